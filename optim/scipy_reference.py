"""Independent solve of the design NLP with SciPy SLSQP on the numpy path of the model.

Same problem as :class:`oilgap.optim.design.DesignProblem` (same variables in
mm, same scaling, same bounds and parameters, same model functions), but the
objective and constraints are evaluated with numpy (vectorised over the
duty-cycle nodes) and SLSQP differentiates them by finite differences. No
CasADi, no IPOPT: it is the cross-check of the CasADi/IPOPT optimum and the
baseline of the speed benchmark.

References
----------
.. [1] D. Kraft, "A software package for sequential quadratic programming",
   DFVLR-FB 88-28, 1988 (SLSQP).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import Bounds, minimize

from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.units import MM_TO_M

from .design import DesignParameters, DesignProblem, region1_mean_power


@dataclass(frozen=True)
class ReferenceResult:
    """Outcome of :func:`solve_slsqp` (SI)."""

    x_m: np.ndarray
    """(R, delta, d_r, d_s, L) [m]."""
    region1_power_W: float
    mean_power_W: float
    """Region 1 plus region 2, smooth C_m (the NLP's objective) [W]."""
    torque_capability_Nm: float
    inertia_kgm2: float
    success: bool
    message: str
    iterations: int
    evaluations: int
    solve_time_s: float


def numpy_functions(problem: DesignProblem, params: DesignParameters):
    """(objective P1(x_mm) [W], torque(x_mm) [N m], inertia(x_mm) [kg m^2]) on the numpy path."""
    nodes, weights, law, motor = (problem.nodes_rad_s, problem.weights, problem.law,
                                  problem.case.motor)
    nu, rho = params.nu_m2_s, params.rho_kg_m3
    d_r0 = problem.machined_rotor_groove_m

    def power(x_mm):
        R, d, a, b, L = np.asarray(x_mm, dtype=float) * MM_TO_M
        return float(region1_mean_power(R, d, a, b, L, nu, rho, nodes, weights, law))

    def torque(x_mm):
        R, d, _, _, L = np.asarray(x_mm, dtype=float) * MM_TO_M
        return float(motor_torque(motor, R, d, L)[0])

    def inertia(x_mm):
        R, _, a, _, L = np.asarray(x_mm, dtype=float) * MM_TO_M
        return float(rotor_inertia(motor, R, a, L, d_r0))

    return power, torque, inertia


def solve_slsqp(problem: DesignProblem, x0: Sequence[float] | None = None, *,
                ftol: float = 1e-12, maxiter: int = 500, **overrides: Any) -> ReferenceResult:
    """Solve the design NLP with SLSQP and finite-difference gradients (numpy path).

    Parameters
    ----------
    problem : DesignProblem
        Supplies the case, nodes/weights, law and the parameter resolution.
    x0 : (R, delta, d_r, d_s, L) [m]; default the case's design
    ftol : SLSQP tolerance on the scaled objective (~1 at the start) [-]
    **overrides : as :meth:`DesignProblem.solve`
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
    return ReferenceResult(x_mm * MM_TO_M, p1,
                           p1 + problem.region2_power(params.nu_m2_s, params.rho_kg_m3),
                           torque(x_mm), inertia(x_mm), bool(res.success), str(res.message),
                           int(res.nit), int(res.nfev), dt)
