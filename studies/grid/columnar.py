"""Columnar evaluation of a chunk: grid rows as arrays, no case object per row.

When the rows of a chunk vary only what the stacked rows of
:mod:`oilgap.model.uncertain.rows` take as arrays (:data:`COLUMNAR`: oil temperature,
depth, gamma, scale, peak speed, sea temperature; the oil by name, one group per oil), the
chunk is evaluated from its columns by :func:`oilgap.studies.grid.evaluate.evaluate_rows`,
the same composition the per-case path uses, without building a
:class:`~oilgap.model.case.DesignCase` per row (the cost of a sweep of 10^5-10^6 points).

The rows are checked as the per-case path checks them: each column's lowest and highest
value go through :func:`~oilgap.studies.grid.schema.apply_params` (every one of these
columns is checked on its own, against an interval), each oil name once. A chunk with a
value out of range, another column, or a failure other than a balance without a root goes
the per-case path (:func:`oilgap.studies.grid.evaluate.evaluate_chunk`), where each bad
row gets its own error. Numbers equal the per-case path's (bit for bit without gamma and
scale columns; with them to rounding, C_m being taken at gamma 0 and scale 1 and times
``scale T^gamma`` after the cycle mean).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from dataclasses import replace

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError
from oilgap.model.oils import Oil
from oilgap.model.uncertain.rows import RowValues
from oilgap.studies.grid.columns import EVALUATE_NUMBERS
from oilgap.studies.grid.schema import apply_params, missing_cells

COLUMNAR = frozenset({"oil", "oil_temp_C", "depth_m", "gamma", "scale", "peak_speed_rpm",
                      "sea_temp_C", "label"})
"""Grid columns the columnar path takes (anything else: one case per row)."""

NON_FINITE = "non-finite result (oil state outside the laws' range)"
"""The error of a row whose loss is not a finite number (as the per-case path's)."""


class NotColumnar(Exception):
    """The chunk goes the per-case path."""


def _columns(rows: list[dict]) -> tuple[dict[str, np.ndarray], list]:
    """Numeric columns (NaN: the base case's value) and the oil names (None: the case's),
    column by column."""
    df = pd.DataFrame.from_records(rows) if rows else pd.DataFrame()
    missing = {c: missing_cells(df[c]) for c in df.columns}
    given = {c for c, m in missing.items() if not m.all()} - {"label"}
    if not given <= COLUMNAR:
        raise NotColumnar
    num = {c: df[c].to_numpy(dtype=float) if df[c].dtype.kind == "f" else
           df[c].astype(object).where(~missing[c], math.nan).to_numpy(dtype=float)
           for c in given - {"oil"}}
    if "oil" not in given:
        return num, [None] * len(rows)
    oil = df["oil"].to_numpy(dtype=object)
    return num, [None if m else str(v) for v, m in zip(oil, missing["oil"], strict=True)]


def _check(base: DesignCase, num: Mapping[str, np.ndarray],
           catalogue: Mapping[str, Oil] | None) -> None:
    """Each column's extremes through :func:`apply_params` (intervals): NotColumnar on a
    value the case refuses."""
    try:
        for c, a in num.items():
            ok = a[~np.isnan(a)]
            for v in {float(ok.min()), float(ok.max())} if ok.size else ():
                apply_params(base, {c: v}, catalogue)
    except (InputError, ValueError):
        raise NotColumnar from None


def _rows(case: DesignCase, base: DesignCase, num: Mapping[str, np.ndarray], sel: np.ndarray
          ) -> tuple[DesignCase, RowValues]:
    """The case (its law at gamma 0 and scale 1 when rows carry them) and the rows ``sel``."""
    def col(name, default):  # a column at sel, the case's value where a cell is empty
        a = num.get(name)
        return None if a is None else np.where(np.isnan(a[sel]), default, a[sel])

    op, th, law = case.operating, case.thermal, case.friction
    peak = col("peak_speed_rpm", math.nan)
    gamma = col("gamma", law.gamma) if "gamma" in num or "scale" in num else None
    scale = col("scale", law.scale) if "scale" in num else (
        None if gamma is None else np.full(len(sel), law.scale))
    if law.form == "power-law":
        scale = None  # the power law has no scale
    if gamma is not None:
        case = replace(case, friction=replace(law, gamma=0.0,
                                              scale=law.scale if scale is None else 1.0))
    temp = col("oil_temp_C", op.oil_temp_C)
    rows = RowValues(
        n=len(sel), oil_temp_C=np.full(len(sel), float(op.oil_temp_C)) if temp is None
        else temp, depth_m=float(op.depth_m) if "depth_m" not in num
        else col("depth_m", op.depth_m), gamma=gamma, friction_scale=scale,
        speed_factor=None if peak is None else np.where(  # the sine's amplitude, as
            np.isnan(peak), 1.0, peak / float(base.duty_cycle.spec["peak_speed_rpm"])),
        sea_temp_C=None if th is None else (col("sea_temp_C", th.sea_temp_C)
                                            if "sea_temp_C" in num
                                            else np.full(len(sel), float(th.sea_temp_C))))
    return case, rows


def _evaluate(case, rows, sel, mode, out, warn_col, errors) -> None:
    """:func:`evaluate_rows` of ``sel``; rows without a balance root get their error and
    the others are evaluated again."""
    from oilgap.studies.grid.evaluate import RowsFailed, evaluate_rows

    try:
        evaluate_rows(case, rows, mode, list(sel), out, warn_col)
    except RowsFailed as e:
        errors.update(e.messages)
        keep = np.array([i not in e.messages for i in sel])
        if keep.any():
            _evaluate(case, _subset(rows, keep), sel[keep], mode, out, warn_col, errors)


def _subset(rows: RowValues, keep: np.ndarray) -> RowValues:
    """The rows where ``keep``."""
    def part(v):
        return v if v is None or np.ndim(v) == 0 else np.asarray(v)[keep]
    return RowValues(n=int(keep.sum()), oil_temp_C=part(rows.oil_temp_C),
                     depth_m=part(rows.depth_m), gamma=part(rows.gamma),
                     friction_scale=part(rows.friction_scale),
                     speed_factor=part(rows.speed_factor), sea_temp_C=part(rows.sea_temp_C))


def columnar_chunk(base: DesignCase, rows: list[dict], catalogue: Mapping[str, Oil] | None,
                   thermal: str) -> list[dict] | None:
    """The records of :func:`~oilgap.studies.grid.evaluate.evaluate_chunk` from the chunk's
    columns, or None when the chunk goes the per-case path (module docstring).

    Parameters
    ----------
    base : DesignCase
        The base case.
    rows : list of dict
        The chunk's grid rows.
    catalogue : mapping or None
        Oils looked up by name.
    thermal : str
        Thermal mode.

    Returns
    -------
    list of dict or None
        One record per row (``status``, ``error``, the numbers, ``thermal_mode``,
        ``warning``).
    """
    try:
        num, oils = _columns(rows)
        if "peak_speed_rpm" in num and (base.duty_cycle.spec.get("kind") != "sine"
                                        or "peak_speed_rpm" not in base.duty_cycle.spec):
            raise NotColumnar
        _check(base, num, catalogue)
        n = len(rows)
        out = {k: np.full(n, np.nan) for k in EVALUATE_NUMBERS}
        warn_col: list[str | None] = [None] * n
        errors: dict[int, str] = {}
        names = np.array(oils, dtype=object)
        for name in dict.fromkeys(oils):
            sel = np.flatnonzero(names == name) if name is not None else np.flatnonzero(
                np.array([o is None for o in oils]))
            try:
                case = base if name is None else apply_params(base, {"oil": name}, catalogue)
            except (InputError, ValueError) as e:
                errors.update({int(i): str(e) for i in sel})
                continue
            case, sub = _rows(case, base, num, sel)
            _evaluate(case, sub, sel, thermal, out, warn_col, errors)
    except NotColumnar:
        return None
    except Exception:  # noqa: BLE001 - the per-case path isolates the failing rows
        return None
    return _records(out, warn_col, errors, thermal)


def _records(out: dict[str, np.ndarray], warn_col: list, errors: Mapping[int, str],
             thermal: str) -> list[dict]:
    """One record per row, as the per-case path makes them."""
    n = len(warn_col)
    keys = [*out, "thermal_mode", "warning", "status", "error"]
    cols = [v.tolist() for v in out.values()]
    cols += [itertools.repeat(thermal, n), warn_col, itertools.repeat("ok", n),
             itertools.repeat(None, n)]
    recs = [dict(zip(keys, vals)) for vals in zip(*cols)]  # noqa: B905 - repeat is endless
    for i in np.flatnonzero(~np.isfinite(out["mean_power_W"])).tolist():
        recs[i] = {"status": "error", "error": NON_FINITE}
    for i, message in errors.items():
        recs[i] = {"status": "error", "error": message}
    return recs
