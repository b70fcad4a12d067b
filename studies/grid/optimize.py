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
from oilgap.model.errors import OilgapWarning
from oilgap.model.joint_loss import THERMAL_MODES
from oilgap.model.oils import Oil, get_oil
from oilgap.model.units import MM_TO_M
from oilgap.optim.design import DesignProblem
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
        The result columns of :data:`oilgap.studies.grid.columns.OPTIMIZE_RESULTS`.
    warm : tuple
        (problem key, DesignResult), to pass as the next ``x0``.

    Raises
    ------
    InputError, InfeasibleError, SolverError
        As :meth:`DesignProblem.solve`.
    """
    key, prob = design_problem(case, problems, thermal)
    kw: dict[str, Any] = {}
    for k, v in overrides.items():
        name, f = _OVERRIDE_MAP[k]
        kw[name] = float(v) * f
    for k, v in (operating or {}).items():
        kw[k] = get_oil(str(v)) if k == "oil" else float(v)
    start = None
    if x0 is not None:
        k0, r0 = x0
        start = r0 if k0 == key else r0.optimal
    t0 = time.perf_counter()
    res = prob.solve(x0=start, **kw)
    dt = time.perf_counter() - t0
    o = res.optimal
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        arrays = evaluate_arrays([res.to_case()], thermal)[0]
    rec = dict(o.to_dict(), initial_mean_power_W=res.initial.mean_power_W,
               mean_power_exact_W=float(arrays["mean_power_W"][0]), thermal_mode=thermal,
               oil_temp_op_C=float(arrays["oil_temp_op_C"][0]), solve_time_s=dt,
               iterations=res.iterations,
               active_constraints=" ".join(res.active_constraints),
               torque_min_Nm_used=res.parameters.torque_min_Nm,
               inertia_max_kgm2_used=res.parameters.inertia_max_kgm2)
    return rec, (key, res)


def optimize_chunk(base: DesignCase, rows: list[dict],
                   catalogue: Mapping[str, Oil] | None, thermal: str = "none") -> list[dict]:
    """Optimize each row (one design NLP each), warm-starting from the previous success.

    The rows' structural parameters give the case (one DesignProblem per distinct
    case, built once); ``oil``, ``oil_temp_C``, ``depth_m`` and the
    :data:`OPTIMIZE_COLUMNS` are parameters of each solve.
    """
    results: list[dict] = []
    x_prev = None
    for row in rows:
        struct = {k: v for k, v in row.items()
                  if k not in OPTIMIZE_COLUMNS and k not in OPERATING_COLUMNS}
        overrides = {k: float(v) for k, v in row.items()
                     if k in OPTIMIZE_COLUMNS and not is_missing(v)}
        operating = {k: v for k, v in row.items()
                     if k in OPERATING_COLUMNS and not is_missing(v)}
        try:
            case = apply_params(base, struct, catalogue)
            if "oil" in operating:
                operating["oil"] = get_oil(str(operating["oil"]), catalogue).name
                case = replace(case, oil=get_oil(operating.pop("oil"), catalogue))
            rec, x_prev = solve_design_point(case, overrides, x0=x_prev, operating=operating,
                                             thermal=thermal)
            results.append(dict(rec, status="ok", error=None, warning=None))
        except Exception as e:  # noqa: BLE001 - a failed point is a row, not a crash
            results.append({"status": "error", "error": f"{type(e).__name__}: {e}"})
    return results
