"""Decision variables of the design NLP, their scaling for IPOPT, and the IPOPT options.

Decision variables (non-redundant)::

    x = (R, delta, d_r, d_s, L)
    R      = T2        rotor outer radius (region 1 radius)
    delta  = T3 - T2   clearance, also the magnetic gap g
    d_r    = T2 - T1   rotor groove depth left open by the epoxy fill
    d_s    = T4 - T3   stator groove depth left open by the epoxy fill
    L                  clearance (stack) length

so that T1 = R - d_r, T3 = R + delta, T4 = R + delta + d_s and
T = (T4 - T1)/(T3 - T2) = 1 + (d_r + d_s)/delta >= 1 by construction (Eq. 9 of
the seed paper [1]).

Scaling: IPOPT sees y = (ln R/mm, ln delta/mm, d_r/mm, d_s/mm, ln L/mm)
(:func:`to_nlp`, :func:`from_nlp`). The laminar loss, a near-monomial in R,
delta and L, is near-linear in these logarithms, which saves IPOPT iterations;
the groove depths may be 0, so they stay linear.

References
----------
.. [1] *Modeling and Optimization of Compensating Oil Viscous Power for a Deep-Sea
   Electric Manipulator* (the seed paper), Eq. 9.
.. [2] A. Wächter, L. T. Biegler, "On the implementation of an interior-point
   filter line-search algorithm for large-scale nonlinear programming",
   Math. Program. 106:25-57, 2006 (IPOPT; the options below).
"""

from __future__ import annotations

import numpy as np

from oilgap.model.units import MM_TO_M

VARIABLES = ("R", "delta", "d_r", "d_s", "L")
"""Decision variables, in the order of the NLP vector."""

VARIABLE_LABELS = {
    "R": ("R_mm", "radius", "rotor outer radius R = T2"),
    "delta": ("delta_mm", "gap", "clearance delta = T3 - T2 (= magnetic gap)"),
    "d_r": ("rotor_groove_depth_mm", "rotor_groove_depth", "rotor groove depth T2 - T1"),
    "d_s": ("stator_groove_depth_mm", "stator_groove_depth", "stator groove depth T4 - T3"),
    "L": ("L_mm", "length", "clearance length L"),
}
"""variable -> (JSON key, bound name stem, description)."""

LOG_VARIABLES = np.array([True, True, False, False, True])
"""Which NLP variables are logarithms of the length in mm (R, delta, L)."""

SUCCESS_STATUSES = ("Solve_Succeeded", "Solved_To_Acceptable_Level")
"""IPOPT return statuses accepted as an optimum."""

IPOPT_TOL = 1e-9
"""IPOPT convergence tolerance on the NLP error (objective ln P1, variables ln mm or mm)."""

ACTIVE_RTOL = 1e-6
"""A bound or constraint is active when its slack is below this fraction of its scale."""

QUIET_OPTIONS = {"ipopt.print_level": 0, "ipopt.sb": "yes", "print_time": False}
"""nlpsol options that silence IPOPT (dropped by ``DesignProblem(verbose=True)``)."""

SOLVER_OPTIONS = {"ipopt.tol": IPOPT_TOL, "ipopt.mu_init": 1e-3,
                  "ipopt.barrier_tol_factor": 100, "ipopt.nlp_scaling_method": "none",
                  "ipopt.constr_mult_init_max": 0.0, "calc_lam_p": False,
                  "error_on_fail": False, "expand": True}
"""nlpsol options (measured on the seed and 120 random cases: 8-9 IPOPT iterations). The
NLP is scaled by construction, so IPOPT's own gradient scaling is off; the constraint
multipliers start at 0 (no least-squares estimate: one factorization less)."""

WARM_OPTIONS = {"ipopt.warm_start_init_point": "yes", "ipopt.warm_start_bound_push": 1e-9,
                "ipopt.warm_start_bound_frac": 1e-9, "ipopt.warm_start_slack_bound_push": 1e-9,
                "ipopt.warm_start_slack_bound_frac": 1e-9,
                "ipopt.warm_start_mult_bound_push": 1e-9, "ipopt.mu_init": 1e-6}
"""nlpsol options added to :data:`SOLVER_OPTIONS` for a start with primal and dual values
(the neighbour's optimum in a sweep): keep the start, begin with a small barrier."""


def to_nlp(x_m: np.ndarray) -> np.ndarray:
    """Design vector -> NLP vector y.

    Parameters
    ----------
    x_m : array of 5 floats
        (R, delta, d_r, d_s, L) [m].

    Returns
    -------
    ndarray of 5 floats
        (ln R/mm, ln delta/mm, d_r/mm, d_s/mm, ln L/mm) [-, -, mm, mm, -].
    """
    y = np.array(x_m, dtype=float) / MM_TO_M
    y[LOG_VARIABLES] = np.log(y[LOG_VARIABLES])
    return y


def from_nlp(y: np.ndarray) -> np.ndarray:
    """NLP vector y -> design vector (the inverse of :func:`to_nlp`).

    Parameters
    ----------
    y : array of 5 floats
        (ln R/mm, ln delta/mm, d_r/mm, d_s/mm, ln L/mm) [-, -, mm, mm, -].

    Returns
    -------
    ndarray of 5 floats
        (R, delta, d_r, d_s, L) [m].
    """
    x = np.array(y, dtype=float)
    x[LOG_VARIABLES] = np.exp(x[LOG_VARIABLES])
    return x * MM_TO_M


__all__ = ["VARIABLES", "VARIABLE_LABELS", "LOG_VARIABLES", "SUCCESS_STATUSES", "IPOPT_TOL",
           "ACTIVE_RTOL", "QUIET_OPTIONS", "SOLVER_OPTIONS", "WARM_OPTIONS", "to_nlp",
           "from_nlp"]
