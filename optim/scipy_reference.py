"""Independent solve of the design NLP with SciPy SLSQP on the numpy path of the model.

Same problem as :class:`oilgap.optim.design.DesignProblem` (same variables in
mm, same scaling, same bounds and parameters, the same objective), but the
objective and constraints are evaluated on the numpy path of
:class:`oilgap.optim.design.DesignObjective` (vectorised over the duty-cycle
nodes) and SLSQP differentiates them by finite differences. No
CasADi, no IPOPT: it is the cross-check of the CasADi/IPOPT optimum and the
baseline of the speed benchmark.

References
----------
.. [1] D. Kraft, "A software package for sequential quadratic programming",
   DFVLR-FB 88-28, 1988 (SLSQP).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import Bounds, minimize

from oilgap.model.units import MM_TO_M

from .design import DesignParameters, DesignProblem


@dataclass(frozen=True)
class ReferenceResult:
    """Outcome of :func:`solve_slsqp` (SI).

    Parameters
    ----------
    x_m : ndarray of 5 floats
        The optimum (R, delta, d_r, d_s, L) [m].
    region1_power_W : float
        Region-1 mean power [W].
    mean_power_W : float
        Region 1 plus region 2 (and a rolling bearing), smooth C_m (the NLP's total) [W].
    torque_capability_Nm : float
        Torque capability [N m].
    inertia_kgm2 : float
        Rotor inertia [kg m^2].
    success : bool
        SLSQP's success flag.
    message : str
        SLSQP's message.
    iterations, evaluations : int
        SLSQP iterations and objective evaluations.
    solve_time_s : float
        Wall time [s].
    """

    x_m: np.ndarray
    """(R, delta, d_r, d_s, L) [m]."""
    region1_power_W: float
    mean_power_W: float
    """Region 1 plus region 2 (and a rolling bearing), smooth C_m [W]."""
    torque_capability_Nm: float
    inertia_kgm2: float
    success: bool
    message: str
    iterations: int
    evaluations: int
    solve_time_s: float


def numpy_functions(problem: DesignProblem, params: DesignParameters
                    ) -> tuple[Callable, Callable, Callable]:
    """The objective and constraints of a solve as functions of x in mm (numpy path).

    Parameters
    ----------
    problem : DesignProblem
        Supplies the objective (:meth:`DesignProblem.objective`).
    params : DesignParameters
        The solve's parameters (its oil state).

    Returns
    -------
    power, torque, inertia : callable
        Of x = (R, delta, d_r, d_s, L) [mm]: region-1 mean power P1 [W], torque
        capability [N m], rotor inertia [kg m^2], as floats.
    """
    objective = problem.objective(params)

    def power(x_mm):
        return float(objective.mean_power(np.asarray(x_mm, dtype=float) * MM_TO_M))

    def torque(x_mm):
        return float(objective.torque(np.asarray(x_mm, dtype=float) * MM_TO_M))

    def inertia(x_mm):
        return float(objective.inertia(np.asarray(x_mm, dtype=float) * MM_TO_M))

    return power, torque, inertia


def solve_slsqp(problem: DesignProblem, x0: Sequence[float] | None = None, *,
                ftol: float = 1e-12, maxiter: int = 500, **overrides: Any) -> ReferenceResult:
    """Solve the design NLP with SLSQP and finite-difference gradients (numpy path).

    Parameters
    ----------
    problem : DesignProblem
        Supplies the case, the objective (:func:`numpy_functions`) and the
        parameter resolution.
    x0 : sequence of 5 floats, optional
        Start (R, delta, d_r, d_s, L) [m]; default the case's design.
    ftol : float
        SLSQP tolerance on the scaled objective (~1 at the start) [-].
    maxiter : int
        SLSQP's iteration limit.
    **overrides
        As :meth:`DesignProblem.solve`.

    Returns
    -------
    ReferenceResult
        The optimum [m] with its powers [W], torque [N m] and inertia [kg m^2].
    """
    params = problem.parameters(**overrides)
    lo_mm = np.asarray(params.lower_m) / MM_TO_M
    hi_mm = np.asarray(params.upper_m) / MM_TO_M
    start = problem.x_case_m if x0 is None else np.asarray(x0, dtype=float)
    x_start = np.clip(start / MM_TO_M, lo_mm, hi_mm)
    power, torque, inertia = numpy_functions(problem, params)
    t0 = time.perf_counter()
    scale = power(x_start)
    t_ref, j_ref = problem.tau_ref_Nm, problem.inertia_ref_kgm2
    cons = [
        {"type": "ineq", "fun": lambda x: (torque(x) - params.torque_min_Nm) / t_ref},
        {"type": "ineq", "fun": lambda x: (params.inertia_max_kgm2 - inertia(x)) / j_ref},
    ]
    fixed = lo_mm == hi_mm
    res = minimize(lambda x: power(x) / scale, x_start, method="SLSQP",
                   bounds=Bounds(lo_mm, hi_mm, keep_feasible=~fixed), constraints=cons,
                   options={"ftol": ftol, "maxiter": maxiter})
    dt = time.perf_counter() - t0
    x_mm = np.clip(res.x, lo_mm, hi_mm)
    p1 = power(x_mm)
    return ReferenceResult(
        x_m=x_mm * MM_TO_M, region1_power_W=p1,
        mean_power_W=p1 + problem.constant_power(params.nu_m2_s, params.rho_kg_m3),
        torque_capability_Nm=torque(x_mm), inertia_kgm2=inertia(x_mm), success=bool(res.success),
        message=str(res.message), iterations=int(res.nit), evaluations=int(res.nfev),
        solve_time_s=dt)
