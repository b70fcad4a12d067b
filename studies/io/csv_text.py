"""A table's CSV text built column by column, byte for byte what ``DataFrame.to_csv``
writes (``index=False``, the defaults otherwise), at a fraction of its time.

``to_csv`` formats each number through NumPy (about 1 us a cell) and writes the rows
through the :mod:`csv` module. Here a float column's texts are Arrow's shortest
round-trip texts where they read as Python's ``repr`` (a non-integral value with
1e-4 <= ``|x|`` < 1e10), ``repr`` elsewhere; a text column's cells are quoted once per
distinct value, as the :mod:`csv` module quotes them (QUOTE_MINIMAL); then each row's
fields are joined. A table with a column of another kind (bool, dates, mixed objects)
is left to ``to_csv`` (:func:`csv_text` returns None).
"""

from __future__ import annotations

import csv
import io

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.compute as pc

_ARROW_LOW, _ARROW_HIGH = 1e-4, 1e10
"""|x| range where Arrow's float text equals ``repr`` (integral values aside)."""


def float_texts(values: np.ndarray) -> pa.Array:
    """The CSV text of each float as ``to_csv`` writes it: ``repr(x)``, NaN empty.

    Parameters
    ----------
    values : ndarray
        Floats [-].

    Returns
    -------
    pyarrow.Array
        ``repr(float(x))`` of each value, ``""`` for NaN (Arrow strings) [-].
    """
    v = np.asarray(values, dtype=float)
    out = pc.cast(pa.array(v), pa.string())
    a = np.abs(v)
    with np.errstate(invalid="ignore"):
        own = ~((a >= _ARROW_LOW) & (a < _ARROW_HIGH) & (np.floor(v) != v))
    idx = np.flatnonzero(own)
    if idx.size == len(v):
        return pa.array([("" if x != x else repr(x)) for x in v.tolist()], pa.string())
    if idx.size:
        fixed = pa.array([("" if x != x else repr(x)) for x in v[idx].tolist()], pa.string())
        out = pc.replace_with_mask(out, pa.array(own), fixed)
    return out


def text_field(v: str) -> str:
    """One text cell as the :mod:`csv` module writes it (QUOTE_MINIMAL, ``"`` doubled)."""
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerow([v, ""])
    return buf.getvalue()[:-2]


def _column_texts(s: pd.Series) -> pa.Array | None:
    """The CSV texts of a column's cells (Arrow strings), None for a kind
    :func:`csv_text` leaves to pandas."""
    kind = s.dtype.kind
    if kind == "f":
        return float_texts(s.to_numpy())
    if kind in "iu":
        return pa.array([str(x) for x in s.tolist()], pa.string())
    if kind != "O" or pd.api.types.infer_dtype(s, skipna=True) not in ("string", "empty"):
        return None
    arr = pa.array(s.astype(object).to_numpy(), pa.string(), from_pandas=True)  # NaN: null
    quote = pc.fill_null(pc.match_substring_regex(arr, '[,"\\r\\n]'), False)
    idx = np.flatnonzero(np.asarray(quote.to_numpy(zero_copy_only=False), dtype=bool))
    if idx.size:
        fixed = pa.array([text_field(v) for v in arr.take(pa.array(idx)).to_pylist()],
                         pa.string())
        arr = pc.replace_with_mask(arr, quote, fixed)
    return pc.fill_null(arr, "")


def csv_text(df: pd.DataFrame) -> bytes | None:
    """``df.to_csv(index=False)``'s text (UTF-8), or None when a column is of a kind this
    does not format (bool, dates, mixed objects: the caller uses ``to_csv``).

    Parameters
    ----------
    df : DataFrame
        The table [-].

    Returns
    -------
    bytes or None
        The CSV text: header line, one line per row, each ending in ``\\n`` [-].
    """
    if df.shape[1] < 2 or not all(isinstance(c, str) for c in df.columns):
        return None  # (csv writes a lone empty field as '""')
    cols = []
    for i in range(df.shape[1]):
        texts = _column_texts(df.iloc[:, i])
        if texts is None:
            return None
        cols.append(texts.cast(pa.large_string()))  # 64-bit offsets: no 2 GB limit
    head = (",".join(text_field(c) for c in df.columns) + "\n").encode()
    if not len(df):
        return head
    lines = pc.binary_join_element_wise(*cols, pa.scalar(",", pa.large_string()))
    lines = pc.binary_join_element_wise(lines, pa.scalar("\n", pa.large_string()),
                                           pa.scalar("", pa.large_string()))
    return head + _joined_bytes(lines)


def _joined_bytes(arr: pa.Array) -> bytes:
    """The bytes of all the strings of an Arrow string array, end to end."""
    arr = arr.combine_chunks() if isinstance(arr, pa.ChunkedArray) else arr
    offsets = np.frombuffer(arr.buffers()[1], dtype=np.int64)[arr.offset:arr.offset
                                                                 + len(arr) + 1]
    return arr.buffers()[2].to_pybytes()[offsets[0]:offsets[-1]]


__all__ = ["csv_text", "float_texts", "text_field"]
