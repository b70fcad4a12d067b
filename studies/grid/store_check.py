"""The checks of a stored row before a resumed run reuses it as a result.

A points file or chunk file may have been cut short, edited by hand or written by
something else. A row is reused only when it reads as a fresh row would have been
written: a key, a status ``ok`` or ``error``, an ``ok`` row with no error text and
every number of its mode a finite number in its physical range, an ``error`` row with
its message. Any other row is dropped and computed again (the rule of
``docs/studies.md``, "Resuming"): :func:`row_problem` says why, so the warning of
:func:`oilgap.studies.grid.store.repair_store` names the file, the line and the reason.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.compute as pc

from oilgap.model.joint_loss import THERMAL_MODES

_KEY = re.compile(r"[0-9A-Za-z_-]+")
_INF = math.inf

# (low, high, low included) of each stored number; a bound is physical, not a guess
# at the design: a loss is never negative, a radius never zero, a liquid oil neither
# frozen nor boiling (-60..300 degC covers every catalogue oil's table and more).
_POWER = (0.0, _INF, True)
_POSITIVE = (0.0, _INF, False)
_NON_NEGATIVE = (0.0, _INF, True)
_TEMP_C = (-60.0, 300.0, True)
_ROUGHNESS = (1.0 - 1e-6, _INF, True)  # T >= 1; IPOPT may relax its bound by 1e-8
RANGES: dict[str, tuple[float, float, bool]] = {
    "mean_power_W": _POWER, "mean_power_exact_W": _POWER, "initial_mean_power_W": _POWER,
    "region1_power_W": _POWER, "region2_power_W": _POWER, "isothermal_power_W": _POWER,
    "oil_temp_op_C": _TEMP_C, "sea_temp_C": _TEMP_C, "nu_cSt": _POSITIVE,
    "density_kg_m3": _POSITIVE, "Re1_peak": _NON_NEGATIVE, "Re2_peak": _NON_NEGATIVE,
    "T_res": _ROUGHNESS, "T": _ROUGHNESS, "delta_mm_res": _POSITIVE, "R_mm_res": _POSITIVE,
    "L_mm_res": _POSITIVE, "delta_mm": _POSITIVE, "R_mm": _POSITIVE, "L_mm": _POSITIVE,
    "T1_mm": _POSITIVE, "T2_mm": _POSITIVE, "T3_mm": _POSITIVE, "T4_mm": _POSITIVE,
    "torque_capability_Nm": _NON_NEGATIVE, "inertia_kgm2": _POSITIVE,
    "inertia_ratio": _POSITIVE, "torque_min_Nm_used": _NON_NEGATIVE,
    "inertia_max_kgm2_used": _POSITIVE, "iterations": _NON_NEGATIVE,
    "solve_time_s": _NON_NEGATIVE,
}
"""Physical range of each stored number: (low, high, whether low is allowed)."""

REQUIRED = {"evaluate": ("mean_power_W",), "optimize": ("mean_power_W",)}
"""Numbers an ``ok`` row of each mode always holds: its result (the others may be empty,
e.g. ``sea_temp_C`` outside the ``full`` mode; when present they are checked)."""

INTEGERS = ("iterations",)


def _number_problem(name: str, text: str, required: bool) -> str | None:
    """Why the stored text of number ``name`` is not a result (None: it is)."""
    if not text.strip():
        return f"{name} is empty" if required else None
    try:
        v = float(text)
    except ValueError:
        return f"{name} = {text!r} is not a number"
    if not math.isfinite(v):
        return f"{name} = {text} is not finite"
    lo, hi, closed = RANGES[name]
    if v < lo or (v == lo and not closed) or v > hi:
        low = f"{'>=' if closed else '>'} {lo:g}"
        return f"{name} = {text} is outside its physical range ({low}" + (
            f", <= {hi:g})" if math.isfinite(hi) else ")")
    if name in INTEGERS and v != int(v):
        return f"{name} = {text} is not a whole number"
    return None


def row_problem(cells: dict[str, str], mode: str, columns: tuple[str, ...]) -> str | None:
    """Why a stored row (its cells by column) cannot be reused as a result; None if it can.

    Parameters
    ----------
    cells : dict
        The row's text by header column [-].
    mode : {"evaluate", "optimize"}
        The store's mode [-].
    columns : tuple of str
        The mode's result columns (:func:`oilgap.studies.grid.columns.result_columns`) [-].

    Returns
    -------
    str or None
        The first reason found, in words: a bad key or status, an ``ok`` row with an error
        text or a missing, non-numeric, non-finite or unphysical number (:data:`RANGES`),
        an ``error`` row without its message, an unknown thermal mode.
    """
    if not _KEY.fullmatch(cells.get("point_key", "")):
        return "its point_key is not a key oilgap writes"
    status = cells.get("status")
    if status not in ("ok", "error"):
        return f"status = {status!r} (ok or error)"
    thermal = cells.get("thermal_mode", "")
    if thermal.strip() and thermal not in THERMAL_MODES:
        return f"thermal_mode = {thermal!r} is not a thermal mode"
    if status == "error":
        return None if cells.get("error", "").strip() else "an error row without its message"
    if cells.get("error", "").strip():
        return "status ok with an error message"
    for name in columns:
        if name not in RANGES:
            continue
        required = name in REQUIRED.get(mode, ())
        if name not in cells:
            if required:
                return f"no {name} column"
            continue
        why = _number_problem(name, cells[name], required)
        if why:
            return why
    return None



def _numbers_clean(cells, name: str, required: bool) -> np.ndarray:
    """Cells of number ``name`` that :func:`_number_problem` passes for certain: finite,
    clear of its range's bounds by 1e-9 (a value at a bound is checked row by row), a
    whole number where one is due; empty where the number may be (the reader leaves only
    an empty cell as NaN)."""
    col = cells[name]
    blank = col.isna().to_numpy()
    if col.dtype.kind not in "fiu":  # text (True/False too: float() refuses them)
        col = col.astype(str)
    v = pd.to_numeric(col, errors="coerce").to_numpy(dtype=float)
    lo, hi, _ = RANGES[name]
    with np.errstate(invalid="ignore"):
        good = np.isfinite(v) & (v > lo + 1e-9 * max(1.0, abs(lo)))
        if math.isfinite(hi):
            good &= v < hi - 1e-9 * max(1.0, abs(hi))
        if name in INTEGERS:
            good &= np.floor(v) == v
    return good if required else good | blank


def clean_rows(cells, mode: str, columns: tuple[str, ...]) -> np.ndarray:
    """The rows of a table of stored cells that :func:`row_problem` certainly passes,
    checked column by column (the check of a resumed store, :mod:`oilgap.studies.grid.store`).

    Parameters
    ----------
    cells : DataFrame
        One row per stored line, read with the header's columns: the text columns
        (``point_key``, ``status``, ``error``, ``thermal_mode``) as text, an empty cell
        ``""``; the numbers as read by ``pandas.read_csv``, an empty cell (only) NaN [-].
    mode : {"evaluate", "optimize"}
        The store's mode [-].
    columns : tuple of str
        The mode's result columns, all in ``cells`` [-].

    Returns
    -------
    ndarray of bool
        True: a valid ``ok`` row (a key, status ``ok``, no error text, a known or empty
        thermal mode, every number finite and inside its range, away from its bounds).
        False: a row to check with :func:`row_problem` (an ``error`` row, a doubtful
        cell), which says whether it is valid and, if not, why [-].
    """
    key = pa.array(cells["point_key"].astype(object).tolist(), pa.string())
    ok = np.asarray(pc.fill_null(pc.match_substring_regex(key, "^[0-9A-Za-z_-]+$"), False))
    ok &= (cells["status"] == "ok").to_numpy(dtype=bool)
    ok &= (cells["error"] == "").to_numpy(dtype=bool)
    thermal = cells["thermal_mode"]
    ok &= (thermal.isin(THERMAL_MODES) | (thermal == "")).to_numpy(dtype=bool)
    for name in columns:
        if name in RANGES:
            ok &= _numbers_clean(cells, name, name in REQUIRED.get(mode, ()))
    return ok


__all__ = ["INTEGERS", "RANGES", "REQUIRED", "clean_rows", "row_problem"]
