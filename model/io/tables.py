"""Read a measured-data table (CSV or Parquet) fast, and code its text columns.

:func:`read_table` reads with pyarrow where it is installed (multi-threaded C++
CSV parser; numbers parsed once into float64/int64 arrays; the text columns
``run`` and ``oil`` dictionary-encoded, so a million rows of a few run names cost
a few megabytes), and with pandas' C parser otherwise or when pyarrow refuses a
file pandas can read (ragged rows, quoted line breaks). Either way the columns
come back with their names stripped; values that do not parse as numbers stay
text, and the validation (:mod:`oilgap.model.measured.data`) counts them.

:func:`text_codes` turns a text column into integer codes into its sorted,
stripped distinct values; :func:`numeric_column` turns any column into float64
(text that is not a number becomes NaN). Both work on the distinct values, never
per row in Python.

References
----------
.. [1] Apache Arrow, *pyarrow.csv.read_csv* and *pyarrow.parquet.read_table*
   (https://arrow.apache.org/docs/python/csv.html).
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.csv as pcsv
import pyarrow.parquet as pq

from ..errors import InputError

TEXT_COLUMNS = ("run", "oil")
"""Columns read as text (dictionary-encoded), never as numbers."""
MISSING_TEXT = frozenset({"", "nan", "-nan", "na", "n/a", "#n/a", "<na>", "null", "none"})
"""Cell texts (lower case, stripped) that mean "no value", as pyarrow and pandas read them."""


def _first_line_names(path: Path) -> list[str]:
    """The header's column names as written (for pyarrow's per-column types)."""
    try:
        with open(path, newline="", encoding="utf-8-sig") as fh:
            return next(csv.reader(fh), [])
    except (UnicodeDecodeError, csv.Error, OSError):
        return []


def _read_csv_arrow(path: Path) -> pd.DataFrame | None:
    """CSV through pyarrow; None if pyarrow cannot parse the file (pandas then tries)."""
    text = pa.dictionary(pa.int32(), pa.string())
    types = {c: text for c in _first_line_names(path) if c.strip() in TEXT_COLUMNS}
    try:
        table = pcsv.read_csv(path, convert_options=pcsv.ConvertOptions(column_types=types))
    except (pa.ArrowInvalid, pa.ArrowNotImplementedError, UnicodeDecodeError, OSError):
        return None
    return _arrow_to_frame(table, str(path))


def _arrow_to_frame(table, source: str) -> pd.DataFrame:
    names = [str(c).strip() for c in table.column_names]
    dup = sorted({c for c in names if names.count(c) > 1})
    if dup:
        raise InputError("columns", dup, "column names must be unique", source)
    df = table.to_pandas(split_blocks=True, self_destruct=True)
    df.columns = names
    return df


def _check_header(path: Path) -> None:
    """Refuse duplicate column names on the raw header (pandas would rename them x, x.1)."""
    names = [c.strip() for c in _first_line_names(path)]
    dup = sorted({c for c in names if c and names.count(c) > 1})
    if dup:
        raise InputError("columns", dup, "column names must be unique", str(path))


def _read_parquet(path: Path) -> pd.DataFrame:
    schema = pq.read_schema(path)
    text = [c for c in schema.names if c.strip() in TEXT_COLUMNS]
    return _arrow_to_frame(pq.read_table(path, read_dictionary=text), str(path))


def read_table(path: str | Path) -> pd.DataFrame:
    """Read a CSV or Parquet file; numbers as float64/int64, other values as text.

    Parameters
    ----------
    path : str or Path
        ``.csv``, or ``.parquet``/``.pq`` (needs pyarrow); units in column names.

    Returns
    -------
    pandas.DataFrame
        The raw table, column names stripped [units as named]; ``run`` and ``oil``
        as text (categorical with pyarrow), numeric columns as float64/int64 when
        every value parses, text otherwise.

    Raises
    ------
    InputError
        Missing file, unreadable content, no rows, duplicate column names.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("data", str(path), "must be an existing CSV or Parquet file")
    suffix = path.suffix.lower()
    try:
        if suffix in (".parquet", ".pq"):
            df = _read_parquet(path)
        else:
            _check_header(path)
            df = _read_csv_arrow(path)
            if df is None:
                df = pd.read_csv(path, dtype=str, keep_default_na=False, skipinitialspace=True)
                df.columns = [str(c).strip() for c in df.columns]
    except InputError:
        raise
    except Exception as e:  # any reader failure (pyarrow's own error types too) is a bad file
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        raise InputError("data", str(path), f"is not a readable CSV/Parquet table ({first})") \
            from None
    if df.shape[0] == 0:
        raise InputError("data", str(path), "holds no data rows")
    return df


def text_codes(s: pd.Series) -> tuple[np.ndarray, np.ndarray]:
    """Integer codes of a text column into its sorted, stripped distinct values.

    Parameters
    ----------
    s : pandas.Series
        Any column (text, categorical, numbers); missing values become ``""``.

    Returns
    -------
    (codes, names)
        ``codes`` (int32, one per row [-]) index ``names`` (sorted object array of
        str); ``names[codes]`` is the column as stripped text.
    """
    if isinstance(s.dtype, pd.CategoricalDtype):
        codes = s.cat.codes.to_numpy()
        uniques = list(s.cat.categories)
    else:
        codes, uniques = pd.factorize(s, use_na_sentinel=True)
        uniques = list(uniques)
    raw = ["" if (u is None or (isinstance(u, float) and np.isnan(u))) else str(u).strip()
           for u in uniques] + [""]
    names = np.array(sorted(set(raw)), dtype=object)
    remap = np.searchsorted(names, np.array(raw, dtype=object)).astype(np.int32)
    codes = np.where(codes < 0, len(raw) - 1, codes)
    return remap[codes], names


def text_cells(s: pd.Series) -> np.ndarray:
    """Where a column holds text that is neither a number nor a missing value.

    Parameters
    ----------
    s : pandas.Series
        Any column.

    Returns
    -------
    ndarray of bool
        One entry per row [-]: True where the cell is text such as ``"abc"`` (empty
        cells and :data:`MISSING_TEXT` are missing values, not text).
    """
    dt = s.dtype
    if pd.api.types.is_numeric_dtype(dt) and not pd.api.types.is_bool_dtype(dt):
        return np.zeros(len(s), bool)
    codes, names = text_codes(s)
    vals = pd.to_numeric(pd.Series(names, dtype=object), errors="coerce").to_numpy(
        dtype=float, na_value=np.nan)
    bad = np.array([n.lower() not in MISSING_TEXT and np.isnan(v)
                    for n, v in zip(names, vals, strict=True)], bool)
    return bad[codes]


def numeric_column(s: pd.Series) -> np.ndarray:
    """A column as float64 [its unit]: numbers as they are, text parsed (NaN if not a number).

    Parameters
    ----------
    s : pandas.Series
        Any column.

    Returns
    -------
    ndarray
        float64 values [unit of the column] (NaN where missing or not a number).
    """
    dt = s.dtype
    if pd.api.types.is_numeric_dtype(dt) and not pd.api.types.is_bool_dtype(dt):
        return s.to_numpy(dtype=float, na_value=np.nan)
    codes, names = text_codes(s)
    vals = pd.to_numeric(pd.Series(names, dtype=object).replace({"": np.nan}),
                         errors="coerce").to_numpy(dtype=float, na_value=np.nan)
    return vals[codes]
