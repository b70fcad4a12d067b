"""Feasibility of the design NLP, decided before IPOPT is called, and why it fails.

The torque capability falls with delta and rises with R and L; the rotor
inertia rises with R, L and the epoxy fill (Gieras [1] for both laws, as
:mod:`oilgap.model.motor` composes them). So the problem is feasible iff some R
admits an L with ``tau(R, delta_min, L) >= tau_min`` and
``J(R, d_r,max, L) <= J_max``; both are linear in L, which leaves a 1-D search
over R (grid, then refined with a bounded scalar minimization).

References
----------
.. [1] J. F. Gieras, *Permanent Magnet Motor Technology*, 3rd ed., 2010, A.27-A.28.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from oilgap.model.case import Motor
from oilgap.model.errors import InfeasibleError
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.units import MM_TO_M

from .parameters import DesignParameters


def check_feasible(motor: Motor, machined_rotor_groove_m: float, params: DesignParameters,
                   x_hint_m: np.ndarray | None = None) -> None:
    """Raise InfeasibleError, naming the conflicting constraints, if no design meets
    ``torque >= torque_min`` and ``inertia <= inertia_max`` within the bounds.

    Parameters
    ----------
    motor : Motor
        The case's motor (torque and inertia laws).
    machined_rotor_groove_m : float
        Rotor groove depth as machined, d_r0 [m].
    params : DesignParameters
        Bounds [m], ``torque_min_Nm`` [N m] and ``inertia_max_kgm2`` [kg m^2].
    x_hint_m : array of 5 floats, optional
        A design (R, delta, d_r, d_s, L) [m] tried first (clipped to the bounds):
        if it is feasible, nothing more is checked.

    Returns
    -------
    None

    Raises
    ------
    InfeasibleError
        With :func:`infeasibility_message` and status ``"infeasible (checked before
        solving)"``.
    """
    m = motor
    lo, hi = np.asarray(params.lower_m), np.asarray(params.upper_m)
    tmin, jmax = params.torque_min_Nm, params.inertia_max_kgm2
    if x_hint_m is not None:
        x = np.clip(x_hint_m, lo, hi)
        if (float(motor_torque(m, x[0], x[1], x[4])[0]) >= tmin and
                float(rotor_inertia(m, x[0], x[2], x[4], machined_rotor_groove_m))
                <= jmax):
            return
    d_lo, dr_hi, L_lo, L_hi = lo[1], hi[2], lo[4], hi[4]

    def slack(R):
        R = np.asarray(R, dtype=float)
        t1 = motor_torque(m, R, d_lo, 1.0)[0]
        j1 = rotor_inertia(m, R, dr_hi, 1.0, machined_rotor_groove_m)
        need = np.maximum(L_lo, tmin / t1)
        allow = np.minimum(L_hi, jmax / j1)
        return (allow - need) / L_hi, need, allow

    grid = np.linspace(lo[0], hi[0], 401) if hi[0] > lo[0] else np.array([lo[0]])
    s, _, _ = slack(grid)
    if np.max(s) >= -1e-12:
        return
    k = int(np.argmax(s))
    R_best = grid[k]
    if grid.size > 1:
        a, bnd = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
        r = minimize_scalar(lambda R: -slack(R)[0], bounds=(a, bnd), method="bounded",
                            options={"xatol": 1e-12})
        if -r.fun >= -1e-12:
            return
        R_best = float(r.x)
    raise InfeasibleError(infeasibility_message(motor, machined_rotor_groove_m, params,
                                                R_best),
                          status="infeasible (checked before solving)")


def infeasibility_message(motor: Motor, machined_rotor_groove_m: float,
                          params: DesignParameters, R_best: float) -> str:
    """Why no design meets the torque and inertia constraints within the bounds.

    Parameters
    ----------
    motor : Motor
        The case's motor.
    machined_rotor_groove_m : float
        Rotor groove depth as machined, d_r0 [m].
    params : DesignParameters
        Bounds [m], ``torque_min_Nm`` [N m] and ``inertia_max_kgm2`` [kg m^2].
    R_best : float
        The radius [m] where the two constraints come closest to agreeing.

    Returns
    -------
    str
        The torque requirement against the smallest gap (with the gap it would
        need), the inertia limit against the lightest rotor, or, if each alone
        is feasible, their conflict at ``R_best``; lengths in mm.
    """
    m = motor
    lo, hi = params.lower_m, params.upper_m
    tmin, jmax = params.torque_min_Nm, params.inertia_max_kgm2
    mm = 1.0 / MM_TO_M
    parts = []
    t_max = float(motor_torque(m, hi[0], lo[1], hi[4])[0])
    if t_max < tmin:
        where = f"R = R_max = {hi[0] * mm:.4g} mm, L = L_max = {hi[4] * mm:.4g} mm"
        tiny = 1e-9
        if float(motor_torque(m, hi[0], tiny, hi[4])[0]) >= tmin:
            d_need = brentq(lambda d: float(motor_torque(m, hi[0], d, hi[4])[0]) - tmin,
                            tiny, lo[1], xtol=1e-15)
            parts.append(f"torque >= {tmin:.6g} N m needs delta <= {d_need * mm:.4g} mm "
                         f"(at {where}), but delta_min = {lo[1] * mm:.4g} mm")
        else:
            parts.append(f"torque >= {tmin:.6g} N m exceeds the motor's capability at any "
                         f"gap ({t_max:.4g} N m at delta_min, {where})")
    j_min = float(rotor_inertia(m, lo[0], hi[2], lo[4], machined_rotor_groove_m))
    if j_min > jmax:
        parts.append(f"inertia <= {jmax:.4g} kg m^2 ({params.inertia_max_ratio:.4g} x the "
                     f"reference {params.inertia_ref_kgm2:.4g}) is below the lightest "
                     f"rotor within the bounds, {j_min:.4g} kg m^2 (R = R_min = "
                     f"{lo[0] * mm:.4g} mm, L = L_min = {lo[4] * mm:.4g} mm, grooves "
                     "as open as allowed)")
    if not parts:
        t1 = float(motor_torque(m, R_best, lo[1], 1.0)[0])
        j1 = float(rotor_inertia(m, R_best, hi[2], 1.0, machined_rotor_groove_m))
        parts.append(f"torque >= {tmin:.6g} N m and inertia <= {jmax:.4g} kg m^2 "
                     f"({params.inertia_max_ratio:.4g} x reference) conflict: at the best "
                     f"radius R = {R_best * mm:.4g} mm with delta = delta_min = "
                     f"{lo[1] * mm:.4g} mm the torque needs L >= "
                     f"{max(lo[4], tmin / t1) * mm:.4g} mm but the inertia allows L <= "
                     f"{min(hi[4], jmax / j1) * mm:.4g} mm")
    return "; ".join(parts)


__all__ = ["check_feasible", "infeasibility_message"]
