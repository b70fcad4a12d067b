"""The grid schema: which columns a grid may hold, their checks, and one row applied to a case.

One row of a grid is one design point: its columns name what changes with
respect to a base case (units in the names; an empty cell keeps the base
case's value). The columns are listed in :data:`PARAM_COLUMNS` (and
:data:`OPTIMIZE_COLUMNS` in optimize mode), defined in
:mod:`oilgap.studies.grid.columns`.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Mapping
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq

from oilgap.model.case import DesignCase
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.errors import InputError, check_positive
from oilgap.model.oils import Oil, get_oil
from oilgap.model.skin_friction import check_friction_ranges
from oilgap.model.thermal_modes import ThermalMode
from oilgap.model.units import MM_TO_M
from oilgap.studies.grid.columns import (
    MODES,
    OPTIMIZE_COLUMNS,
    PARAM_COLUMNS,
    STRING_COLUMNS,
    THERMAL_COLUMNS,
)

__all__ = ["MODES", "OPTIMIZE_COLUMNS", "PARAM_COLUMNS", "STRING_COLUMNS", "apply_params",
           "check_thermal_columns", "is_missing", "missing_cells", "read_grid", "read_grid_csv",
           "read_grid_parquet", "validate_grid"]

PARQUET_SUFFIXES = (".parquet", ".pq")
"""Suffixes of a grid read as Parquet (:func:`read_grid`); anything else is CSV."""

WHERE = "trade study"
"""Context named by every InputError of the engine."""


def is_missing(v: Any) -> bool:
    """True for an empty grid cell: None, NaN or a blank string."""
    return v is None or (isinstance(v, float) and math.isnan(v)) or (
        isinstance(v, str) and v.strip() == "")


def missing_cells(s: pd.Series) -> np.ndarray:
    """Which cells of a column are empty (:func:`is_missing`), column by column.

    Parameters
    ----------
    s : Series
        A grid column [-].

    Returns
    -------
    ndarray of bool
        True where the cell is None, NaN or a blank text [-].
    """
    if s.dtype.kind == "f":
        return s.isna().to_numpy(dtype=bool)
    if pd.api.types.infer_dtype(s, skipna=True) not in ("string", "empty"):
        return np.array([is_missing(v) for v in s.tolist()], dtype=bool)
    codes, uniq = pd.factorize(s, use_na_sentinel=True)  # texts: each distinct one once
    flags = np.array([is_missing(u) for u in uniq] + [True], dtype=bool)
    return flags[codes]


# --------------------------------------------------------------------------- grid checks


def _check_columns(grid: pd.DataFrame, mode: str) -> None:
    if mode not in MODES:
        raise InputError("mode", mode, f"allowed: {', '.join(MODES)}", WHERE)
    if not isinstance(grid, pd.DataFrame):
        raise InputError("grid", type(grid).__name__, "must be a pandas DataFrame", WHERE)
    allowed = dict(PARAM_COLUMNS)
    if mode == "optimize":
        allowed.update(OPTIMIZE_COLUMNS)
    if len(grid) == 0 or len(grid.columns) == 0:
        raise InputError("grid", f"{len(grid)} rows x {len(grid.columns)} columns",
                         "must hold at least one row and one parameter column", WHERE)
    for c in grid.columns:
        if c not in allowed:
            raise InputError("column", c, f"unknown grid column; allowed ({mode} mode): "
                             f"{', '.join(allowed)}", WHERE)
    if len(set(grid.columns)) != len(grid.columns):
        raise InputError("column", list(grid.columns), "column names must be unique", WHERE)
    if "T" in grid.columns and ({"T1_mm", "T4_mm"} & set(grid.columns)):
        raise InputError("column", "T", "give either T or T1_mm/T4_mm, not both", WHERE)


def _numeric_column(col: pd.Series, name: str) -> np.ndarray:
    vals = pd.to_numeric(col, errors="coerce")
    bad = vals.isna() & col.notna() & ~col.astype(str).str.strip().isin(["", "nan"])
    if bad.any():
        i = int(np.flatnonzero(bad.to_numpy())[0])
        raise InputError(name, col.iloc[i], f"a number is required (grid row {i})", WHERE)
    arr = vals.to_numpy(dtype=float)
    if np.isinf(arr).any():
        i = int(np.flatnonzero(np.isinf(arr))[0])
        raise InputError(name, arr[i], f"a finite number is required (grid row {i})", WHERE)
    return arr


def validate_grid(grid: pd.DataFrame, mode: str = "evaluate") -> pd.DataFrame:
    """Check a grid and return it with numeric columns as float and a clean index.

    Raises
    ------
    InputError
        Not a DataFrame, no rows, an unknown column, a non-numeric or
        non-finite value in a numeric column, ``T < 1``, or both ``T`` and
        ``T1_mm``/``T4_mm`` (conflicting definitions of the grooves).
    """
    _check_columns(grid, mode)
    out = grid.reset_index(drop=True).copy()
    for c in out.columns:
        if c in STRING_COLUMNS:
            out[c] = out[c].astype(object).where(out[c].notna(), None)
        else:
            out[c] = _numeric_column(out[c], c)
    if "T" in out.columns:
        t = out["T"].to_numpy(dtype=float)
        low = np.flatnonzero(t < 1.0)
        if low.size:
            raise InputError("T", float(t[low[0]]), "must be >= 1 (T = 1 is a smooth "
                             f"clearance; grid row {int(low[0])})", WHERE)
    return out


def check_thermal_columns(grid: pd.DataFrame, thermal: str, case: DesignCase) -> None:
    """Refuse columns that mean nothing under the thermal mode.

    Under ``bulk``/``full`` the oil temperature is a result of the heat balance: a given
    ``oil_temp_C`` is refused (vary ``sea_temp_C``). Under ``none``/``film`` there is
    no balance: ``sea_temp_C`` and ``resistance_K_per_W`` are refused.

    Raises
    ------
    InputError
        Naming the column, the mode and what to do instead.
    """
    given = [c for c in grid.columns if not missing_cells(grid[c]).all()]
    if thermal in (ThermalMode.BULK, ThermalMode.FULL):
        if "oil_temp_C" in given:
            raise InputError("oil_temp_C", "a grid column", f"under thermal mode '{thermal}' "
                             "the oil temperature is a result of the heat balance; vary "
                             "sea_temp_C instead (or choose --thermal none/film)", WHERE)
        if case.thermal is None:
            raise InputError("thermal", thermal, "'none' or 'film': the case has no "
                             "[thermal] table", WHERE)
        return
    for c in THERMAL_COLUMNS:
        if c in given:
            raise InputError(c, "a grid column", "only under thermal mode 'bulk' or 'full' "
                             f"(the heat balance); the mode is '{thermal}'", WHERE)


MISSING_WORDS = frozenset({"nan", "-nan", "na", "n/a", "#n/a", "<na>", "null", "none"})
"""Cell texts (lower case) pandas would read as missing: refused in a grid CSV, where only
an empty cell means "the base case's value"."""


def _raw_header(p: Path) -> list[str]:
    """The header's column names as written (stripped), before pandas renames duplicates."""
    try:
        with open(p, newline="", encoding="utf-8-sig") as fh:
            return [c.strip() for c in next(csv.reader(fh), [])]
    except (UnicodeDecodeError, csv.Error):
        return []


def _refuse_missing_words(df: pd.DataFrame) -> None:
    """Refuse cells such as ``nan`` or ``NA`` in parameter columns: never computed silently
    at the base value."""
    for c in (c for c in df.columns if c in PARAM_COLUMNS or c in OPTIMIZE_COLUMNS):
        low = df[c].str.strip().str.lower()
        bad = np.flatnonzero(low.isin(MISSING_WORDS).to_numpy())
        if bad.size:
            i = int(bad[0])
            more = f"; {bad.size} such cells in the column" if bad.size > 1 else ""
            raise InputError(c, df[c].iloc[i], "a value is required, or an empty cell for the "
                             f"base case's value (grid row {i}, file line {i + 2}{more})", WHERE)


def read_grid_csv(path: str | Path) -> pd.DataFrame:
    """Read a grid CSV (one column per parameter, see :data:`PARAM_COLUMNS`).

    An empty cell keeps the base case's value; a cell that only names a missing value
    (``nan``, ``NA``, ``null``, ...) and a column name given twice are refused.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("grid", str(p), "must be an existing CSV file", WHERE)
    names = _raw_header(p)
    dup = [c for c in dict.fromkeys(names) if c and names.count(c) > 1]
    if dup:
        raise InputError("column", dup[0], f"appears {names.count(dup[0])} times in the "
                         "header; column names must be unique", WHERE)
    try:
        df = pd.read_csv(p, dtype=str, keep_default_na=False, na_values=[],
                         skipinitialspace=True)
    except pd.errors.EmptyDataError:
        raise InputError("grid", str(p), "is empty; it must hold a header and at least one "
                         "row", WHERE) from None
    except (pd.errors.ParserError, UnicodeDecodeError) as e:
        first = (str(e).strip().splitlines() or [type(e).__name__])[0]  # one line, no content
        raise InputError("grid", str(p), f"is not a readable CSV ({first})", WHERE) from None
    df.columns = [str(c).strip() for c in df.columns]
    _refuse_missing_words(df)
    for c in df.columns:
        col = df[c].where(df[c].str.strip() != "", np.nan)
        num = pd.to_numeric(col, errors="coerce")
        df[c] = num if c not in STRING_COLUMNS and num.notna().sum() == col.notna().sum() \
            else col
    return df


def read_grid_parquet(path: str | Path) -> pd.DataFrame:
    """Read a grid stored as Parquet: the same columns and rules as a CSV grid
    (:func:`read_grid_csv`); a missing value (null) is an empty cell, the base case's
    value.

    Raises
    ------
    InputError
        Not a readable Parquet file, no rows, a column name given twice.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("grid", str(p), "must be an existing CSV or Parquet file", WHERE)
    try:
        schema = pq.read_schema(p)
        names = [str(c).strip() for c in schema.names]
        dup = [c for c in dict.fromkeys(names) if names.count(c) > 1]
        if dup:
            raise InputError("column", dup[0], f"appears {names.count(dup[0])} times in the "
                             "header; column names must be unique", WHERE)
        df = pq.read_table(p).to_pandas()
    except (pa.ArrowException, OSError) as e:
        first = (str(e).strip().splitlines() or [type(e).__name__])[0][:160]
        raise InputError("grid", str(p), f"is not a readable Parquet file ({first})",
                         WHERE) from None
    df.columns = names
    if len(df) == 0:
        raise InputError("grid", str(p), "holds no rows; it must hold at least one", WHERE)
    for c in df.columns:
        if c in STRING_COLUMNS or df[c].dtype == object:
            col = df[c].astype(object)
            df[c] = col.where(col.notna() & (col.astype(str).str.strip() != ""), np.nan)
        if c in STRING_COLUMNS:
            df[c] = df[c].map(lambda v: v if is_missing(v) else str(v))
    return df


def read_grid(path: str | Path) -> pd.DataFrame:
    """Read a grid by its suffix: Parquet (``.parquet``, ``.pq``,
    :func:`read_grid_parquet`) or CSV (anything else, :func:`read_grid_csv`).

    Raises
    ------
    InputError
        As the reader of the format.
    """
    if Path(path).suffix.lower() in PARQUET_SUFFIXES:
        return read_grid_parquet(path)
    return read_grid_csv(path)


# --------------------------------------------------------------------------- one point's case


_DUTY_CACHE: dict[tuple, DutyCycle] = {}
_POSITIVE = ("T1_mm", "T2_mm", "T3_mm", "T4_mm", "length_mm", "R_mm", "gap_mm",
             "region2_radius_mm", "region2_length_mm", "region2_gap_mm", "peak_speed_rpm",
             "resistance_K_per_W")
_GEOMETRY = ("T1_mm", "T2_mm", "T3_mm", "T4_mm", "length_mm", "R_mm", "gap_mm", "T")


def _sine_with_peak(case: DesignCase, peak_rpm: float) -> DutyCycle:
    spec = dict(case.duty_cycle.spec)
    if spec.get("kind") != "sine":
        raise InputError("peak_speed_rpm", peak_rpm, "only for a case with a sine duty cycle",
                         WHERE)
    spec.pop("kind")
    spec["peak_speed_rpm"] = float(peak_rpm)
    key = tuple(sorted(spec.items()))
    if key not in _DUTY_CACHE:
        if len(_DUTY_CACHE) > 256:
            _DUTY_CACHE.clear()
        _DUTY_CACHE[key] = DutyCycle.sine(**spec)
    return _DUTY_CACHE[key]


def _apply_geometry(case: DesignCase, p: Mapping[str, Any]) -> DesignCase:
    """Region-1 radii and length of a row, in the order of :func:`apply_params`."""
    mm = MM_TO_M
    r1 = case.region1
    g = {"T1": r1.T1, "T2": r1.T2, "T3": r1.T3, "T4": r1.T4, "length": r1.length,
         "T1_unfilled": r1.T1_unfilled, "T4_unfilled": r1.T4_unfilled}
    for k in ("T1", "T2", "T3", "T4", "length"):
        if k + "_mm" in p:
            g[k] = float(p[k + "_mm"]) * mm
    if "R_mm" in p:
        s = float(p["R_mm"]) * mm - g["T2"]
        for k in ("T1", "T2", "T3", "T4", "T1_unfilled", "T4_unfilled"):
            g[k] += s
    if "gap_mm" in p:
        s = float(p["gap_mm"]) * mm - (g["T3"] - g["T2"])
        for k in ("T3", "T4", "T4_unfilled"):
            g[k] += s
    if "T" in p:
        t_val = float(p["T"])
        if t_val < 1.0:
            raise InputError("T", t_val, "must be >= 1 (T = 1 is a smooth clearance)", WHERE)
        rotor, stator = g["T2"] - g["T1"], g["T4"] - g["T3"]
        share = 0.5 if rotor + stator <= 0 else rotor / (rotor + stator)
        depth = (t_val - 1.0) * (g["T3"] - g["T2"])
        g["T1"] = g["T2"] - share * depth
        g["T4"] = g["T3"] + (1.0 - share) * depth
    g["T1_unfilled"] = min(g["T1_unfilled"], g["T1"])
    g["T4_unfilled"] = max(g["T4_unfilled"], g["T4"])
    return replace(case, region1=replace(r1, **g))


def _apply_thermal(case: DesignCase, p: Mapping[str, Any]) -> DesignCase:
    """A row's ``sea_temp_C`` and ``resistance_K_per_W`` in the case's ``[thermal]``."""
    tkw = {f: float(p[k]) for k, f in (("sea_temp_C", "sea_temp_C"),
                                       ("resistance_K_per_W", "resistance_K_W")) if k in p}
    if not tkw:
        return case
    if case.thermal is None:
        k0 = next(k for k in THERMAL_COLUMNS if k in p)
        raise InputError(k0, p[k0], "the base case has no [thermal] table", WHERE)
    return replace(case, thermal=replace(case.thermal, **tkw))


def apply_params(case: DesignCase, params: Mapping[str, Any],
                 catalogue: Mapping[str, Oil] | None = None) -> DesignCase:
    """The base case with one grid row's parameters applied (validated by the case).

    Geometry is applied in this order: explicit ``T1_mm..T4_mm``/``length_mm``,
    then ``R_mm`` (shifts all four radii), then ``gap_mm`` (moves the stator:
    T3 and T4), then ``T`` (sets the total groove depth ``(T - 1) delta``,
    split between rotor and stator in the case's proportion). Groove bottoms
    before filling follow so that filling never has to remove material.

    Raises
    ------
    InputError
        A value the case refuses (the message names the field).
    """
    p = {k: v for k, v in params.items() if not is_missing(v) and k != "label"}
    for k in _POSITIVE:
        if k in p:
            check_positive(k, p[k], "grid row")
    if "oil" in p:
        case = replace(case, oil=get_oil(str(p["oil"]), catalogue))
    if "oil_temp_C" in p or "depth_m" in p:
        op = case.operating
        case = replace(case, operating=type(op)(float(p.get("depth_m", op.depth_m)),
                                                float(p.get("oil_temp_C", op.oil_temp_C))))
    if any(k in p for k in _GEOMETRY):
        case = _apply_geometry(case, p)
    fkw = {k: p[k] for k in ("gamma", "scale", "laminar_law", "form") if k in p}
    if fkw:
        fkw = {k: (str(v) if k in ("laminar_law", "form") else float(v)) for k, v in fkw.items()}
        case = replace(case, friction=check_friction_ranges(replace(case.friction, **fkw),
                                                             WHERE))
    if "peak_speed_rpm" in p:
        case = replace(case, duty_cycle=_sine_with_peak(case, float(p["peak_speed_rpm"])))
    case = _apply_thermal(case, p)
    r2kw = {k[len("region2_"):-3]: float(p[k]) * MM_TO_M
            for k in ("region2_radius_mm", "region2_length_mm", "region2_gap_mm") if k in p}
    if r2kw:
        if case.region2 is None:
            k0 = next(k for k in p if k.startswith("region2_"))
            raise InputError(k0, p[k0], "the base case has no region 2", WHERE)
        case = replace(case, region2=replace(case.region2, **r2kw))
    return case
