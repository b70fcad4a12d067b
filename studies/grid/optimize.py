"""Optimize mode: one design NLP per grid row, warm-started along a chunk.

Each distinct case (the row's structural parameters applied to the base case)
gets one :class:`oilgap.optim.design.DesignProblem`, built once per process and
kept in a small cache; ``oil``, ``oil_temp_C``, ``depth_m`` and the
:data:`~oilgap.studies.grid.columns.OPTIMIZE_COLUMNS` are parameters of each
solve (no rebuild).
"""

from __future__ import annotations

import inspect
import time
import warnings
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from oilgap.model.case import DesignCase
from oilgap.model.errors import OilgapWarning, SolverError
from oilgap.model.joint_loss import THERMAL_MODES
from oilgap.model.oils import Oil, get_oil
from oilgap.model.units import MM_TO_M
from oilgap.optim.design import DesignProblem
from oilgap.optim.design.lean import (
    LeanRecord,
    LeanStart,
    add_constant_powers,
    optimal_case,
    solve_lean,
)
from oilgap.optim.progress import report
from oilgap.studies.grid.columns import OPERATING_COLUMNS, OPTIMIZE_COLUMNS
from oilgap.studies.grid.evaluate import evaluate_arrays
from oilgap.studies.grid.schema import apply_params, is_missing
from oilgap.studies.grid.store import case_fingerprint

PROBLEMS: dict[str, DesignProblem] = {}
"""DesignProblems built in this process, by case fingerprint (the NLP is built once)."""
MAX_PROBLEMS = 16

_OVERRIDE_MAP = {"torque_min_Nm": ("torque_min_Nm", 1.0),
                 "delta_min_mm": ("gap_min_m", MM_TO_M),
                 "delta_max_mm": ("gap_max_m", MM_TO_M),
                 "inertia_max_ratio": ("inertia_max_ratio", 1.0)}


def nlp_thermal_modes() -> tuple[str, ...]:
    """The thermal modes the design NLP carries: all of them once
    :class:`~oilgap.optim.design.DesignProblem` takes a ``thermal`` argument, else
    only ``"none"`` (the isothermal NLP)."""
    params = inspect.signature(DesignProblem.__init__).parameters
    return THERMAL_MODES if "thermal" in params else ("none",)


def clear_problems() -> None:
    """Empty this process's cache of DesignProblems (the next solve builds its NLP)."""
    PROBLEMS.clear()


def design_problem(case: DesignCase, problems: dict | None = None, thermal: str = "none"
                   ) -> tuple[str, DesignProblem]:
    """(key, DesignProblem) of ``case`` under a thermal mode, built once and kept in
    ``problems`` (default: :data:`PROBLEMS`, at most :data:`MAX_PROBLEMS`, the oldest
    dropped first)."""
    cache = PROBLEMS if problems is None else problems
    key = case_fingerprint(case) + ("" if thermal == "none" else f":{thermal}")
    if key not in cache:
        if len(cache) >= MAX_PROBLEMS:
            cache.pop(next(iter(cache)))
        cache[key] = (DesignProblem(case) if thermal == "none"
                      else DesignProblem(case, thermal=thermal))
    return key, cache[key]


def _kwargs(overrides: Mapping[str, float], operating: Mapping[str, Any] | None
            ) -> dict[str, Any]:
    """The solve's keyword arguments from grid overrides and operating columns (SI)."""
    kw: dict[str, Any] = {}
    for k, v in overrides.items():
        name, f = _OVERRIDE_MAP[k]
        kw[name] = float(v) * f
    for k, v in (operating or {}).items():
        kw[k] = get_oil(str(v)) if k == "oil" else float(v)
    return kw


def _solve(case: DesignCase, overrides: Mapping[str, float], x0, problems: dict | None,
           operating: Mapping[str, Any] | None, thermal: str, constant: bool = True
           ) -> tuple[dict, Any, DesignCase, tuple | None]:
    """(row without the exact columns, warm start, the optimum's case to evaluate,
    (problem, parameters, lean record) of a row whose constant powers are still to add).

    Isothermal: the lean solve (:func:`oilgap.optim.design.lean.solve_lean`, only the
    sweep's columns; ``constant=False``: region 2 and the bearing left to
    :func:`~oilgap.optim.design.lean.add_constant_powers`); film/full:
    :meth:`DesignProblem.solve` and its result."""
    key, prob = design_problem(case, problems, thermal)
    kw = _kwargs(overrides, operating)
    t0 = time.perf_counter()
    if thermal == "none":
        start = x0[1] if x0 is not None and isinstance(x0[1], LeanStart) else None
        if start is not None and x0[0] != key:  # another problem's multipliers: primal only
            start = LeanStart(start.x_m, None, None)
        lean, nxt, params = solve_lean(prob, start, constant=constant, **kw)
        rec = lean.to_dict()
        rec.update(solve_time_s=time.perf_counter() - t0, thermal_mode=thermal)
        return (rec, (key, nxt), optimal_case(prob, params, nxt.x_m),
                None if constant else (prob, params, lean))
    start = None
    if x0 is not None:
        k0, r0 = x0
        start = r0 if k0 == key else r0.optimal
    res = prob.solve(x0=start, **kw)
    dt = time.perf_counter() - t0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        opt_case = res.to_case()
    rec = dict(res.optimal.to_dict(), initial_mean_power_W=res.initial.mean_power_W,
               thermal_mode=thermal, solve_time_s=dt, iterations=res.iterations,
               active_constraints=" ".join(res.active_constraints),
               torque_min_Nm_used=res.parameters.torque_min_Nm,
               inertia_max_kgm2_used=res.parameters.inertia_max_kgm2)
    return rec, (key, res), opt_case, None


def _exact(recs: list[dict], cases: list[DesignCase], thermal: str) -> None:
    """``mean_power_exact_W`` and ``oil_temp_op_C`` of each optimum (the case's exact C_m
    under the thermal mode), evaluated together (:func:`evaluate_arrays`); should that
    fail, one by one, a failing point becoming an error row."""
    if not recs:
        return
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        try:
            arrays = evaluate_arrays(cases, thermal)[0]
        except Exception:  # noqa: BLE001 - find the point that fails
            if len(recs) == 1:
                raise
            for i, (rec, c) in enumerate(zip(recs, cases, strict=True)):
                try:
                    _exact([rec], [c], thermal)
                except Exception as e:  # noqa: BLE001 - a failed point is a row
                    recs[i] = _error_row(e)
            return
    for i, rec in enumerate(recs):
        rec.update(mean_power_exact_W=float(arrays["mean_power_W"][i]),
                   oil_temp_op_C=float(arrays["oil_temp_op_C"][i]))


def _error_row(e: Exception) -> dict:
    """The row of a point that failed."""
    return {"status": "error", "error": f"{type(e).__name__}: {e}"}


def _constant(recs: list[dict], pending: list[tuple]) -> None:
    """Region 2 and the bearing of the lean rows (``pending``: (problem, parameters, lean
    record) of each), one call per problem (:func:`add_constant_powers`), written into
    the rows; should that fail, one by one, a failing point becoming an error row."""
    groups: dict[int, list[int]] = {}
    for i, (prob, _, _) in enumerate(pending):
        groups.setdefault(id(prob), []).append(i)
    for idx in groups.values():
        prob = pending[idx[0]][0]
        try:
            done = add_constant_powers(prob, [pending[i][2] for i in idx],
                                       [pending[i][1] for i in idx])
        except Exception:  # noqa: BLE001 - find the point that fails
            for i in idx:
                try:
                    _complete(recs[i], add_constant_powers(prob, [pending[i][2]],
                                                           [pending[i][1]])[0])
                except Exception as e:  # noqa: BLE001 - a failed point is a row
                    recs[i] = _error_row(e)
            continue
        for i, lean in zip(idx, done, strict=True):
            _complete(recs[i], lean)


def _complete(rec: dict, lean: LeanRecord) -> None:
    """Write a completed lean record's constant powers into its row."""
    rec.update(mean_power_W=lean.mean_power_W, region2_power_W=lean.region2_power_W,
               initial_mean_power_W=lean.initial_mean_power_W)


def solve_design_point(case: DesignCase, overrides: Mapping[str, float], x0=None,
                       problems: dict | None = None, operating: Mapping[str, Any] | None = None,
                       thermal: str = "none") -> tuple[dict, Any]:
    """Solve the design NLP of ``case`` with grid overrides; return (record, warm start).

    Parameters
    ----------
    case : DesignCase
        The structure (geometry, friction, duty cycle, motor, bounds); its
        DesignProblem is built once per distinct case (cached in ``problems``,
        default a per-process cache).
    overrides : mapping
        Grid columns ``torque_min_Nm`` [N m], ``delta_min_mm``, ``delta_max_mm``
        [mm], ``inertia_max_ratio`` [-].
    x0 : optional
        The warm start returned by a previous call (primal and dual if it came
        from the same problem, primal only otherwise).
    operating : mapping, optional
        ``oil`` (name), ``oil_temp_C``, ``depth_m``: NLP parameters, no rebuild.
    thermal : str
        Thermal mode of the NLP and of ``mean_power_exact_W`` (default ``"none"``;
        others need a design NLP that carries them, :func:`nlp_thermal_modes`).

    Returns
    -------
    record : dict
        The result columns of :data:`oilgap.studies.grid.columns.OPTIMIZE_RESULTS`
        (powers [W], lengths [mm], ``solve_time_s`` [s]).
    warm : tuple
        (problem key, start), to pass as the next ``x0``.

    Raises
    ------
    InputError, InfeasibleError, SolverError
        As :meth:`DesignProblem.solve`.
    """
    rec, warm, opt_case, _ = _solve(case, overrides, x0, problems, operating, thermal)
    recs = [rec]
    _exact(recs, [opt_case], thermal)
    if recs[0].get("status") == "error":
        raise SolverError(recs[0]["error"])
    return recs[0], warm


def optimize_chunk(base: DesignCase, rows: list[dict],
                   catalogue: Mapping[str, Oil] | None, thermal: str = "none",
                   chain: int | None = None) -> list[dict]:
    """Optimize each row (one design NLP each), warm-starting from the previous success
    of its chain (``chain`` rows each, from the chunk's start; default: the chunk).

    The rows' structural parameters give the case (one DesignProblem per distinct
    case, built once); ``oil``, ``oil_temp_C``, ``depth_m`` and the
    :data:`OPTIMIZE_COLUMNS` are parameters of each solve. Each row done is reported
    (:func:`oilgap.optim.progress.report`; drawn when the caller installed a reporter in
    this process, as the command line does for a Pareto front's chain).
    """
    memo: dict = {}
    results: list[dict] = []
    solved: list[int] = []
    cases: list[DesignCase] = []
    pending: list[tuple] = []
    x_prev = None
    for i, row in enumerate(rows):
        if chain and i % chain == 0:
            x_prev = None  # a new chain starts cold, as the chunk's first row
        try:
            case, overrides, operating = _row_case(base, row, catalogue, memo)
            rec, x_prev, opt_case, todo = _solve(case, overrides, x_prev, None, operating,
                                                 thermal, constant=False)
            results.append(dict(rec, status="ok", error=None, warning=None))
            solved.append(len(results) - 1)
            cases.append(opt_case)
            pending.append(todo)
        except Exception as e:  # noqa: BLE001 - a failed point is a row, not a crash
            results.append(_error_row(e))
        report("optimize: rows", i + 1, len(rows))  # in this process only (the fronts)
    lean = [k for k, todo in enumerate(pending) if todo is not None]
    recs = [results[solved[k]] for k in lean]
    _constant(recs, [pending[k] for k in lean])  # region 2 of every lean optimum at once
    for k, rec in zip(lean, recs, strict=True):
        results[solved[k]] = rec
    keep = [k for k in range(len(solved)) if results[solved[k]]["status"] == "ok"]
    recs = [results[solved[k]] for k in keep]
    _exact(recs, [cases[k] for k in keep], thermal)  # the exact C_m of every optimum at once
    for k, rec in zip(keep, recs, strict=True):
        results[solved[k]] = rec
    return results


def _row_case(base: DesignCase, row: Mapping[str, Any], catalogue: Mapping[str, Oil] | None,
              memo: dict) -> tuple[DesignCase, dict, dict]:
    """(case, optimize overrides, operating parameters) of a grid row; the case is built
    once per distinct structure and oil (``memo``)."""
    struct = {k: v for k, v in row.items()
              if k not in OPTIMIZE_COLUMNS and k not in OPERATING_COLUMNS}
    overrides = {k: float(v) for k, v in row.items()
                 if k in OPTIMIZE_COLUMNS and not is_missing(v)}
    operating = {k: v for k, v in row.items()
                 if k in OPERATING_COLUMNS and not is_missing(v)}
    oil = operating.pop("oil", None)
    key = (tuple((k, _hashable(v)) for k, v in struct.items()), oil)
    case = memo.get(key)
    if case is None:
        case = apply_params(base, struct, catalogue)
        if oil is not None:
            case = replace(case, oil=get_oil(str(oil), catalogue))
        memo[key] = case
    return case, overrides, operating


def _hashable(v: Any) -> Any:
    """A memo key of a grid value (NaN and None are one missing value)."""
    return None if is_missing(v) else v
