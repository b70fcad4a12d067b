"""Trade-study engine: a grid of parameter combinations in, a DataFrame of results out.

One row of the grid is one design point: columns name what changes with
respect to a base case (by default the seed joint), for example
``oil, oil_temp_C, depth_m, T, gap_mm``. :func:`run_grid` evaluates every row
(``mode="evaluate"``: the mean viscous power over the duty cycle and its parts)
or optimizes it (``mode="optimize"``: one design NLP per row, warm-started from
the previous row of the same chunk) and returns one result row per grid row.

* Speed: the grid is cut into chunks that run on all local cores
  (:mod:`concurrent.futures`); inside a chunk, evaluation is vectorised: the
  rows that share an oil, a friction law and a duty cycle are evaluated in one
  call of :func:`oilgap.model.viscous_loss.clearance_power` over a
  (rows x speed nodes) array.
* Robustness: a point that fails (a geometry the case refuses, a solver
  failure) is a row with ``status = "error"`` and its message in ``error``;
  the sweep goes on.
* Resumable: with ``out_dir``, each finished chunk is appended to
  ``out_dir/points_<mode>.csv`` keyed by a hash of (mode, base case, row
  parameters); a rerun with the same folder computes only the points not in
  that file.

Grid columns (units in their names; an empty cell keeps the base case's value)
are listed in :data:`PARAM_COLUMNS`. Physics is never re-written here: oil
state, geometry and power come from :func:`oilgap.model.evaluation.oil_state`,
:func:`~oilgap.model.regions.joint_regions` and
:func:`~oilgap.model.viscous_loss.clearance_power`.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import sys
import time
import warnings
import weakref
from collections.abc import Callable, Iterable, Mapping
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.case_io import case_to_dict, seed_case
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.errors import InputError, OilgapWarning, check_positive
from oilgap.model.evaluation import oil_state
from oilgap.model.oils import Oil, get_oil, read_oils_csv, warn_if_untrusted_temperature
from oilgap.model.regions import Region, joint_regions, region_mean_power
from oilgap.model.taylor_couette import couette_reynolds
from oilgap.model.units import MM_TO_M, m2_s_to_cst

ENGINE_VERSION = "1"
"""Part of every point key: bump it when a result column changes meaning."""

PARAM_COLUMNS: dict[str, str] = {
    "oil": "oil name (catalogue, e.g. VG22, or the case's/--oils table)",
    "oil_temp_C": "oil temperature [degC]",
    "depth_m": "sea depth [m]",
    "T1_mm": "rotor groove-bottom radius [mm]",
    "T2_mm": "rotor outer radius [mm]",
    "T3_mm": "stator bore radius [mm]",
    "T4_mm": "stator groove-bottom radius [mm]",
    "length_mm": "region-1 length L [mm]",
    "R_mm": "region-1 radius R = T2 [mm]; shifts T1..T4 together (gap and grooves kept)",
    "gap_mm": "region-1 clearance delta = T3 - T2 [mm]; moves the stator (T3, T4)",
    "T": "roughness (T4-T1)/(T3-T2) [-], >= 1; groove depths scaled in their rotor/stator "
         "proportion (even split if the case has none)",
    "gamma": "groove-roughness exponent of Eq. 8 [-]",
    "scale": "multiplier on the Eq. 6 C_m [-]",
    "laminar_law": "couette or bilgen-boulos",
    "form": "bilgen-boulos, smooth or power-law",
    "peak_speed_rpm": "peak speed of the case's sine duty cycle [rpm]",
    "region2_radius_mm": "bearing annulus radius [mm]",
    "region2_length_mm": "bearing annulus length [mm]",
    "region2_gap_mm": "bearing annulus gap [mm]",
    "label": "free text carried through to the results (not a parameter)",
}
"""Columns a grid may hold in ``mode="evaluate"`` (and ``"optimize"``)."""

OPTIMIZE_COLUMNS: dict[str, str] = {
    "torque_min_Nm": "required torque capability of the motor [N m]",
    "delta_min_mm": "lower bound of the magnetic gap delta [mm]",
    "delta_max_mm": "upper bound of the magnetic gap delta [mm]",
    "inertia_max_ratio": "rotor inertia limit as a multiple of the case's rotor [-]",
}
"""Extra columns a grid may hold in ``mode="optimize"`` (passed to the design NLP)."""

STRING_COLUMNS = ("oil", "laminar_law", "form", "label")

EVALUATE_RESULTS = ("status", "error", "warning", "mean_power_W", "region1_power_W",
                    "region2_power_W", "nu_cSt", "density_kg_m3", "Re1_peak", "Re2_peak",
                    "T_res", "delta_mm_res", "R_mm_res", "L_mm_res")
"""Result columns of ``mode="evaluate"``; ``*_res`` are the resolved geometry of the row."""

OPTIMIZE_RESULTS = ("status", "error", "warning", "mean_power_W", "mean_power_exact_W",
                    "initial_mean_power_W", "region1_power_W", "region2_power_W", "delta_mm",
                    "R_mm", "L_mm", "T1_mm", "T2_mm", "T3_mm", "T4_mm", "T",
                    "torque_capability_Nm", "inertia_kgm2", "inertia_ratio",
                    "torque_min_Nm_used", "inertia_max_kgm2_used", "active_constraints",
                    "iterations", "solve_time_s")
"""Result columns of ``mode="optimize"``: the optimal design; ``mean_power_W`` is the
NLP objective (smooth C_m), ``mean_power_exact_W`` the same design with the case's
exact C_m form."""

MODES = ("evaluate", "optimize")

DEFAULT_EVAL_CHUNK = 1000
"""Rows per chunk in evaluate mode (vectorised inside a chunk)."""


# --------------------------------------------------------------------------- grid checks


def _missing(v: Any) -> bool:
    return v is None or (isinstance(v, float) and math.isnan(v)) or (
        isinstance(v, str) and v.strip() == "")


def validate_grid(grid: pd.DataFrame, mode: str = "evaluate") -> pd.DataFrame:
    """Check a grid and return it with numeric columns as float and a clean index.

    Raises
    ------
    InputError
        Not a DataFrame, no rows, an unknown column, a non-numeric or
        non-finite value in a numeric column, ``T < 1``, or both ``T`` and
        ``T1_mm``/``T4_mm`` (conflicting definitions of the grooves).
    """
    if mode not in MODES:
        raise InputError("mode", mode, f"allowed: {', '.join(MODES)}", "trade study")
    if not isinstance(grid, pd.DataFrame):
        raise InputError("grid", type(grid).__name__, "must be a pandas DataFrame",
                         "trade study")
    allowed = dict(PARAM_COLUMNS)
    if mode == "optimize":
        allowed.update(OPTIMIZE_COLUMNS)
    if len(grid) == 0 or len(grid.columns) == 0:
        raise InputError("grid", f"{len(grid)} rows x {len(grid.columns)} columns",
                         "must hold at least one row and one parameter column", "trade study")
    for c in grid.columns:
        if c not in allowed:
            raise InputError("column", c, f"unknown grid column; allowed ({mode} mode): "
                             f"{', '.join(allowed)}", "trade study")
    if len(set(grid.columns)) != len(grid.columns):
        raise InputError("column", list(grid.columns), "column names must be unique",
                         "trade study")
    if "T" in grid.columns and ({"T1_mm", "T4_mm"} & set(grid.columns)):
        raise InputError("column", "T", "give either T or T1_mm/T4_mm, not both",
                         "trade study")
    out = grid.reset_index(drop=True).copy()
    for c in out.columns:
        if c in STRING_COLUMNS:
            out[c] = out[c].astype(object).where(out[c].notna(), None)
            continue
        vals = pd.to_numeric(out[c], errors="coerce")
        bad = vals.isna() & out[c].notna() & ~out[c].astype(str).str.strip().isin(["", "nan"])
        if bad.any():
            i = int(np.flatnonzero(bad.to_numpy())[0])
            raise InputError(c, out[c].iloc[i], f"a number is required (grid row {i})",
                             "trade study")
        arr = vals.to_numpy(dtype=float)
        if np.isinf(arr).any():
            i = int(np.flatnonzero(np.isinf(arr))[0])
            raise InputError(c, arr[i], f"a finite number is required (grid row {i})",
                             "trade study")
        out[c] = arr
    if "T" in out.columns:
        t = out["T"].to_numpy(dtype=float)
        low = np.flatnonzero(t < 1.0)
        if low.size:
            raise InputError("T", float(t[low[0]]), "must be >= 1 (T = 1 is a smooth "
                             f"clearance; grid row {int(low[0])})", "trade study")
    return out


def read_grid_csv(path: str | Path) -> pd.DataFrame:
    """Read a grid CSV (one column per parameter, see :data:`PARAM_COLUMNS`)."""
    p = Path(path)
    if not p.is_file():
        raise InputError("grid", str(p), "must be an existing CSV file", "trade study")
    try:
        df = pd.read_csv(p, dtype={c: str for c in STRING_COLUMNS}, skipinitialspace=True)
    except pd.errors.EmptyDataError:
        raise InputError("grid", str(p), "is empty; it must hold a header and at least one "
                         "row", "trade study") from None
    except (pd.errors.ParserError, UnicodeDecodeError) as e:
        raise InputError("grid", str(p), f"is not a readable CSV ({e})", "trade study") \
            from None
    df.columns = [str(c).strip() for c in df.columns]
    return df


# --------------------------------------------------------------------------- one point's case


_DUTY_CACHE: dict[tuple, DutyCycle] = {}


def _sine_with_peak(case: DesignCase, peak_rpm: float) -> DutyCycle:
    spec = dict(case.duty_cycle.spec)
    if spec.get("kind") != "sine":
        raise InputError("peak_speed_rpm", peak_rpm, "only for a case with a sine duty cycle",
                         "trade study")
    spec.pop("kind")
    spec["peak_speed_rpm"] = float(peak_rpm)
    key = tuple(sorted(spec.items()))
    if key not in _DUTY_CACHE:
        if len(_DUTY_CACHE) > 256:
            _DUTY_CACHE.clear()
        _DUTY_CACHE[key] = DutyCycle.sine(**spec)
    return _DUTY_CACHE[key]


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
    p = {k: v for k, v in params.items() if not _missing(v) and k != "label"}
    for k in ("T1_mm", "T2_mm", "T3_mm", "T4_mm", "length_mm", "R_mm", "gap_mm",
              "region2_radius_mm", "region2_length_mm", "region2_gap_mm", "peak_speed_rpm"):
        if k in p:
            check_positive(k, p[k], "grid row")
    mm = MM_TO_M
    if "oil" in p:
        case = replace(case, oil=get_oil(str(p["oil"]), catalogue))
    if "oil_temp_C" in p or "depth_m" in p:
        op = case.operating
        case = replace(case, operating=type(op)(float(p.get("depth_m", op.depth_m)),
                                                float(p.get("oil_temp_C", op.oil_temp_C))))
    geo_keys = ("T1_mm", "T2_mm", "T3_mm", "T4_mm", "length_mm", "R_mm", "gap_mm", "T")
    if any(k in p for k in geo_keys):
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
                raise InputError("T", t_val, "must be >= 1 (T = 1 is a smooth clearance)",
                                 "trade study")
            rotor, stator = g["T2"] - g["T1"], g["T4"] - g["T3"]
            share = 0.5 if rotor + stator <= 0 else rotor / (rotor + stator)
            depth = (t_val - 1.0) * (g["T3"] - g["T2"])
            g["T1"] = g["T2"] - share * depth
            g["T4"] = g["T3"] + (1.0 - share) * depth
        g["T1_unfilled"] = min(g["T1_unfilled"], g["T1"])
        g["T4_unfilled"] = max(g["T4_unfilled"], g["T4"])
        case = replace(case, region1=replace(r1, **g))
    fkw = {k: p[k] for k in ("gamma", "scale", "laminar_law", "form") if k in p}
    if fkw:
        fkw = {k: (str(v) if k in ("laminar_law", "form") else float(v)) for k, v in fkw.items()}
        case = replace(case, friction=replace(case.friction, **fkw))
    if "peak_speed_rpm" in p:
        case = replace(case, duty_cycle=_sine_with_peak(case, float(p["peak_speed_rpm"])))
    r2kw = {k[len("region2_"):-3]: float(p[k]) * mm
            for k in ("region2_radius_mm", "region2_length_mm", "region2_gap_mm") if k in p}
    if r2kw:
        if case.region2 is None:
            k0 = next(k for k in p if k.startswith("region2_"))
            raise InputError(k0, p[k0], "the base case has no region 2", "trade study")
        case = replace(case, region2=replace(case.region2, **r2kw))
    return case


# --------------------------------------------------------------------------- vectorised evaluation


EVALUATE_NUMBERS = ("mean_power_W", "region1_power_W", "region2_power_W", "nu_cSt",
                    "density_kg_m3", "Re1_peak", "Re2_peak", "T_res", "delta_mm_res",
                    "R_mm_res", "L_mm_res")


def evaluate_arrays(cases: list[DesignCase]) -> tuple[dict[str, np.ndarray], list[str | None]]:
    """The numbers of :func:`evaluate_cases` as a dict of arrays, and the warnings."""
    n = len(cases)
    out = {k: np.full(n, np.nan) for k in EVALUATE_NUMBERS}
    warn_col: list[str | None] = [None] * n
    groups: dict[tuple, list[int]] = {}
    for i, c in enumerate(cases):
        key = (c.oil, c.friction, id(c.duty_cycle), c.region2 is None)
        groups.setdefault(key, []).append(i)
    for idx in groups.values():
        c0 = cases[idx[0]]
        ii = np.asarray(idx)
        temps = np.array([cases[i].operating.oil_temp_C for i in idx])
        depths = np.array([cases[i].operating.depth_m for i in idx])
        with warnings.catch_warnings(record=True) as rec:
            warnings.simplefilter("always", OilgapWarning)
            nu, _, rho = oil_state(c0, temps, depths)
        if rec:
            for i, t in zip(idx, temps, strict=True):
                with warnings.catch_warnings(record=True) as r1:
                    warnings.simplefilter("always", OilgapWarning)
                    warn_if_untrusted_temperature(t)
                if r1:
                    warn_col[i] = str(r1[0].message)
        nu = np.broadcast_to(np.asarray(nu, dtype=float), temps.shape)
        rho = np.broadcast_to(np.asarray(rho, dtype=float), temps.shape)
        nodes, weights = c0.duty_cycle.speed_distribution()
        w_peak = float(nodes.max())
        geos = [joint_regions(cases[i]) for i in idx]
        total = np.zeros(len(idx))
        for r in range(len(geos[0])):
            R, d, L, T = (np.array([getattr(g[r], k) for g in geos])
                          for k in ("radius_m", "gap_m", "length_m", "roughness_T"))
            stacked = Region(geos[0][r].name, R[:, None], d[:, None], L[:, None], T[:, None])
            mean = region_mean_power(stacked, nodes[None, :], weights, nu[:, None],
                                     rho[:, None], c0.friction)
            total += mean
            out[f"region{r + 1}_power_W"][ii] = mean
            out[f"Re{r + 1}_peak"][ii] = couette_reynolds(w_peak, R, d, nu)
            if r == 0:
                out["T_res"][ii] = T
                out["delta_mm_res"][ii] = d / MM_TO_M
                out["R_mm_res"][ii] = R / MM_TO_M
                out["L_mm_res"][ii] = L / MM_TO_M
        out["mean_power_W"][ii] = total
        out["nu_cSt"][ii] = m2_s_to_cst(nu)
        out["density_kg_m3"][ii] = rho
    return out, warn_col


def evaluate_cases(cases: list[DesignCase]) -> pd.DataFrame:
    """Evaluate many cases at their own operating points, vectorised.

    Cases that share an oil, a friction law and a duty cycle are evaluated in
    one call of :func:`~oilgap.model.viscous_loss.clearance_power` on a
    (cases x speed nodes) array; the mean over the duty cycle is the
    speed-distribution quadrature of :meth:`DutyCycle.speed_distribution`, as
    in :func:`oilgap.model.evaluation.mean_viscous_power` (which this equals
    row by row to rounding).

    Returns
    -------
    DataFrame
        One row per case: ``mean_power_W``, ``region1_power_W``,
        ``region2_power_W`` [W], ``nu_cSt``, ``density_kg_m3``, ``Re1_peak``,
        ``Re2_peak`` (at the peak speed) and the resolved ``T_res``,
        ``delta_mm_res``, ``R_mm_res``, ``L_mm_res``; ``warning`` holds any
        OilgapWarning of the row.
    """
    out, warn_col = evaluate_arrays(cases)
    df = pd.DataFrame(out)
    df["warning"] = warn_col
    return df


def _evaluate_chunk(base: DesignCase, rows: list[dict], catalogue) -> list[dict]:
    """Evaluate one chunk of grid rows; a row that fails carries its error."""
    results: list[dict] = [{} for _ in rows]
    cases, where = [], []
    for i, row in enumerate(rows):
        try:
            cases.append(apply_params(base, row, catalogue))
            where.append(i)
        except (InputError, ValueError) as e:
            results[i] = {"status": "error", "error": str(e)}
    if cases:
        try:
            df = evaluate_cases(cases)
            recs = df.to_dict("records")
        except Exception:  # isolate the failing row(s): evaluate one by one
            recs = []
            for c in cases:
                try:
                    recs.append(evaluate_cases([c]).to_dict("records")[0])
                except Exception as e:  # noqa: BLE001 - a failed point is a row, not a crash
                    recs.append({"error": f"{type(e).__name__}: {e}"})
        for i, rec in zip(where, recs, strict=True):
            if "error" in rec:
                results[i] = {"status": "error", "error": rec["error"]}
            elif not np.isfinite(rec["mean_power_W"]):
                results[i] = {"status": "error",
                              "error": "non-finite result (oil state outside the laws' range)"}
            else:
                results[i] = dict(rec, status="ok", error=None)
    return results


# --------------------------------------------------------------------------- optimize mode


OPERATING_COLUMNS = ("oil", "oil_temp_C", "depth_m")
"""In optimize mode these are parameters of the NLP (no rebuild of the problem)."""


def _optimize_chunk(base: DesignCase, rows: list[dict], catalogue) -> list[dict]:
    """Optimize each row (one design NLP each), warm-starting from the previous success.

    The rows' structural parameters give the case (one DesignProblem per distinct
    case, built once); ``oil``, ``oil_temp_C``, ``depth_m`` and the
    :data:`OPTIMIZE_COLUMNS` are parameters of each solve.
    """
    from oilgap.studies.pareto import solve_design_point

    results: list[dict] = []
    x_prev = None
    for row in rows:
        struct = {k: v for k, v in row.items()
                  if k not in OPTIMIZE_COLUMNS and k not in OPERATING_COLUMNS}
        overrides = {k: float(v) for k, v in row.items()
                     if k in OPTIMIZE_COLUMNS and not _missing(v)}
        operating = {k: v for k, v in row.items()
                     if k in OPERATING_COLUMNS and not _missing(v)}
        try:
            case = apply_params(base, struct, catalogue)
            if "oil" in operating:
                operating["oil"] = get_oil(str(operating["oil"]), catalogue).name
                case = replace(case, oil=get_oil(operating.pop("oil"), catalogue))
            rec, x_prev = solve_design_point(case, overrides, x0=x_prev, operating=operating)
            results.append(dict(rec, status="ok", error=None, warning=None))
        except Exception as e:  # noqa: BLE001 - a failed point is a row, not a crash
            results.append({"status": "error", "error": f"{type(e).__name__}: {e}"})
    return results


def _run_chunk(mode: str, base: DesignCase, rows: list[dict], catalogue) -> list[dict]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        if mode == "evaluate":
            return _evaluate_chunk(base, rows, catalogue)
        return _optimize_chunk(base, rows, catalogue)


# --------------------------------------------------------------------------- keys and storage


_FINGERPRINTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def case_fingerprint(case: DesignCase) -> str:
    """Short hash of everything in a case but its name (its TOML document); cached per
    (immutable) case object."""
    try:
        return _FINGERPRINTS[case]
    except KeyError:
        pass
    doc = case_to_dict(case)
    doc.pop("name", None)
    duty = case.duty_cycle  # the samples themselves (a cycle made in Python has no spec)
    doc["duty_cycle_samples"] = hashlib.sha1(np.ascontiguousarray(duty.time_s).tobytes()
                                             + np.ascontiguousarray(duty.omega_rad_s)
                                             .tobytes()).hexdigest()
    fp = hashlib.sha1(json.dumps(doc, sort_keys=True, default=str).encode()).hexdigest()[:16]
    _FINGERPRINTS[case] = fp
    return fp


def _canon(v: Any) -> Any:
    if _missing(v):
        return None
    if isinstance(v, (float, int, np.floating, np.integer)) and not isinstance(v, bool):
        return repr(float(v))
    return str(v)


def point_keys(grid: pd.DataFrame, base: DesignCase, mode: str,
               extra: Mapping[str, Any] | None = None) -> list[str]:
    """Key of each grid row: hash of (engine version, mode, base case, row parameters)."""
    head = json.dumps([ENGINE_VERSION, mode, case_fingerprint(base),
                       sorted((extra or {}).items())], default=str)
    keys = []
    cols = [c for c in grid.columns if c != "label"]
    for rec in grid[cols].itertuples(index=False, name=None):
        body = json.dumps(sorted((c, _canon(v)) for c, v in zip(cols, rec, strict=True)
                                 if not _missing(v)))
        keys.append(hashlib.sha1((head + body).encode()).hexdigest()[:20])
    return keys


def _result_columns(mode: str) -> tuple[str, ...]:
    return EVALUATE_RESULTS if mode == "evaluate" else OPTIMIZE_RESULTS


def _load_points(path: Path, mode: str) -> pd.DataFrame:
    if not path.is_file():
        return pd.DataFrame(columns=["point_key", *_result_columns(mode)])
    try:
        df = pd.read_csv(path, dtype={"point_key": str, "status": str, "error": str,
                                      "warning": str})
    except pd.errors.EmptyDataError:
        return pd.DataFrame(columns=["point_key", *_result_columns(mode)])
    if "point_key" not in df.columns:
        raise InputError("out_dir", str(path), "holds a points file oilgap did not write; "
                         "choose another --out", "trade study")
    return df


def _append_points(path: Path, keys: list[str], recs: list[dict], mode: str) -> None:
    cols = _result_columns(mode)
    df = pd.DataFrame([{c: r.get(c) for c in cols} for r in recs], columns=list(cols))
    df.insert(0, "point_key", keys)
    new = not path.is_file() or path.stat().st_size == 0
    df.to_csv(path, mode="w" if new else "a", header=new, index=False)


# --------------------------------------------------------------------------- progress


class Progress:
    """A one-line progress bar on stderr: bar, percent, count, elapsed time and ETA."""

    def __init__(self, total: int, label: str = "sweep", enabled: bool = True,
                 stream=None, width: int = 30, min_interval_s: float = 0.1):
        self.total = max(int(total), 0)
        self.label = label
        self.enabled = enabled
        self.stream = stream if stream is not None else sys.stderr
        self.width = width
        self.min_interval_s = min_interval_s
        self.done = 0
        self.t0 = time.perf_counter()
        self._last = -1.0

    def line(self) -> str:
        """The current progress line (without carriage return)."""
        frac = 1.0 if self.total == 0 else self.done / self.total
        filled = int(frac * self.width)
        el = time.perf_counter() - self.t0
        eta = el / frac - el if 0 < frac < 1 else 0.0
        return (f"oilgap {self.label} [{'#' * filled}{'-' * (self.width - filled)}] "
                f"{100 * frac:5.1f}% {self.done}/{self.total} points  {el:.1f} s"
                + (f"  ETA {eta:.1f} s" if 0 < frac < 1 else ""))

    def update(self, n: int = 1) -> None:
        """Advance by ``n`` points and redraw (at most every ``min_interval_s``)."""
        self.done += n
        now = time.perf_counter()
        if self.enabled and (now - self._last >= self.min_interval_s or self.done >= self.total):
            self._last = now
            self.stream.write("\r" + self.line())
            self.stream.flush()

    def close(self) -> None:
        """Finish the line."""
        if self.enabled:
            self.stream.write("\r" + self.line() + "\n")
            self.stream.flush()


# --------------------------------------------------------------------------- the engine


def _chunks(items: list, size: int) -> Iterable[list]:
    for i in range(0, len(items), size):
        yield items[i:i + size]


def run_grid(grid: pd.DataFrame, case: DesignCase | None = None, mode: str = "evaluate",
             out_dir: str | Path | None = None, workers: int | None = None,
             chunk_size: int | None = None, progress: bool | None = None,
             catalogue: Mapping[str, Oil] | None = None,
             label: str = "sweep", retry_failed: bool = False,
             on_chunk: Callable[[int], None] | None = None) -> pd.DataFrame:
    """Evaluate or optimize every row of a grid of parameter combinations.

    Parameters
    ----------
    grid : DataFrame
        One row per point; columns from :data:`PARAM_COLUMNS` (and
        :data:`OPTIMIZE_COLUMNS` in optimize mode); an empty cell keeps the
        base case's value.
    case : DesignCase, optional
        Base case (default: the seed joint, grooved).
    mode : {"evaluate", "optimize"}
    out_dir : path, optional
        Folder for ``points_<mode>.csv`` (finished points, appended chunk by
        chunk) and ``results.csv``; a rerun with the same folder skips the
        points already there.
    workers : int, optional
        Processes (default: all local cores; 1 runs in this process).
    chunk_size : int, optional
        Rows per task (default: 1000 in evaluate mode; in optimize mode the
        grid split evenly over the workers so that each chunk is one
        warm-started chain).
    progress : bool, optional
        Progress line on stderr (default: when stderr is a terminal).
    catalogue : mapping, optional
        Oils to look ``oil`` names up in (default: the case's ``oils_csv`` or
        the built-in ISO VG catalogue).
    retry_failed : bool
        Recompute points stored as errors (default: they count as finished).

    Returns
    -------
    DataFrame
        The grid's columns, then ``status`` ("ok"/"error"), ``error``,
        ``warning`` and the result columns (:data:`EVALUATE_RESULTS` or
        :data:`OPTIMIZE_RESULTS`); ``point_key`` identifies the point.

    Raises
    ------
    InputError
        Bad grid (see :func:`validate_grid`), unknown oil, bad ``workers``.
    """
    grid = validate_grid(grid, mode)
    base = case if case is not None else seed_case()
    if catalogue is None and base.oils_csv:
        catalogue = read_oils_csv(base.oils_csv)
    if "oil" in grid.columns:  # unknown oil names are bad study parameters, not failed points
        for name in pd.unique(grid["oil"].dropna()):
            get_oil(str(name), catalogue)
    n_cpu = os.cpu_count() or 1
    if workers is None:
        workers = n_cpu
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise InputError("workers", workers, "must be an integer >= 1", "trade study")
    keys = point_keys(grid, base, mode)
    points_path = None
    done: dict[str, dict] = {}
    if out_dir is not None:
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        points_path = out / f"points_{mode}.csv"
        old = _load_points(points_path, mode)
        for rec in old.to_dict("records"):
            if retry_failed and rec.get("status") != "ok":
                continue
            done[str(rec["point_key"])] = rec
    todo_keys: list[str] = []
    todo_rows: list[dict] = []
    seen = set(done)
    records = grid.to_dict("records")
    for k, rec in zip(keys, records, strict=True):
        if k not in seen:
            seen.add(k)
            todo_keys.append(k)
            todo_rows.append(rec)
    n = len(todo_rows)
    if chunk_size is None:
        chunk_size = DEFAULT_EVAL_CHUNK if mode == "evaluate" else max(
            1, math.ceil(n / max(workers, 1)))
    chunk_size = max(1, int(chunk_size))
    if progress is None:
        progress = bool(getattr(sys.stderr, "isatty", lambda: False)())
    bar = Progress(len(keys), label, progress)
    bar.done = len(keys) - n
    tasks = list(zip(_chunks(todo_keys, chunk_size), _chunks(todo_rows, chunk_size),
                     strict=True))

    def finish(ks: list[str], recs: list[dict]) -> None:
        for k, r in zip(ks, recs, strict=True):
            done[k] = r
        if points_path is not None:
            _append_points(points_path, ks, recs, mode)
        bar.update(len(ks))
        if on_chunk is not None:
            on_chunk(len(ks))

    if tasks:
        if workers == 1 or len(tasks) == 1:
            for ks, rows in tasks:
                finish(ks, _run_chunk(mode, base, rows, catalogue))
        else:
            with ProcessPoolExecutor(max_workers=min(workers, len(tasks))) as ex:
                futs = {ex.submit(_run_chunk, mode, base, rows, catalogue): ks
                        for ks, rows in tasks}
                pending = set(futs)
                while pending:
                    fin, pending = wait(pending, return_when=FIRST_COMPLETED)
                    for f in fin:
                        finish(futs[f], f.result())
    bar.close()
    cols = _result_columns(mode)
    res = pd.DataFrame([{c: done[k].get(c) for c in cols} for k in keys], columns=list(cols))
    for c in ("error", "warning"):
        res[c] = res[c].astype(object).where(res[c].notna(), None)
    res = res.drop(columns=[c for c in res.columns if c in grid.columns and c != "status"])
    result = pd.concat([grid, res], axis=1)
    result["point_key"] = keys
    result.attrs.update(computed=n, reused=len(keys) - n, elapsed_s=time.perf_counter() - bar.t0)
    if out_dir is not None:
        result.to_csv(Path(out_dir) / "results.csv", index=False)
    return result


# --------------------------------------------------------------------------- reporting helpers


def markdown_table(df: pd.DataFrame, digits: int = 2) -> str:
    """A DataFrame as a Markdown pipe table (floats to ``digits`` decimals, NaN blank)."""

    def fmt(v: Any) -> str:
        if v is None or (isinstance(v, float) and math.isnan(v)):
            return ""
        if isinstance(v, (float, np.floating)):
            return f"{v:.{digits}f}"
        return str(v)

    head = "| " + " | ".join(str(c) for c in df.columns) + " |"
    sep = "|" + "|".join("---" for _ in df.columns) + "|"
    body = ["| " + " | ".join(fmt(v) for v in row) + " |"
            for row in df.itertuples(index=False, name=None)]
    return "\n".join([head, sep, *body])


def write_tables(out: Path, tables: dict[str, pd.DataFrame]) -> list[Path]:
    """Write each named DataFrame as ``out/<name>`` CSV (no index); return the paths."""
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, df in tables.items():
        df.to_csv(out / name, index=False)
        paths.append(out / name)
    return paths


def save_figure(fig, path: Path) -> Path:
    """Save a figure made by :func:`new_figure` as PNG."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    return path


def new_figure(width: float = 7.5, height: float = 4.8, ncols: int = 1):
    """A new (figure, axes) drawn by the Agg canvas, outside pyplot (no global backend)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    axes = fig.subplots(1, ncols)
    return fig, axes
