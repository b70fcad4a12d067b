"""The lumped heat balance of the oil in a joint (or on a rig).

One law, written once: the oil (with what it is in contact with) is one lumped
heat capacity C_th [J/K] heated by the losses P [W] and cooled through one
thermal resistance R_th [K/W] to its surroundings at T_amb::

    C_th dT/dt = P(T, t) - (T - T_amb) / R_th              (transient)
    T = T_amb + R_th P(T)                                  (steady state)

The rig simulator integrates the transient form; the studies solve the steady
form. A joint with a ``[thermal]`` table (:class:`~oilgap.model.case.ThermalSpec`) adds
its other heat Q (motor losses) and is cooled by the sea at T_sea:
:func:`joint_steady_temperature` and :func:`joint_temperature_transient`.
Because the viscous loss falls as the oil warms (dP/dT < 0), the steady
residual ``g(T) = T - T_amb - R_th P(T)`` rises strictly and has exactly one
root between ``T_amb`` and ``T_amb + R_th P(T_amb)``.

References
----------
.. [1] T. L. Bergman, A. S. Lavine, F. P. Incropera, D. P. DeWitt, *Fundamentals
   of Heat and Mass Transfer*, 7th ed., Wiley 2011, sec. 5.2 (lumped capacitance)
   and sec. 3.1 (thermal resistance).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np
from scipy.integrate import solve_ivp

from .errors import InputError, SolverError

if TYPE_CHECKING:
    from .case import ThermalSpec

MAX_OIL_TEMP_C = 250.0
"""Cap of the steady balance [degC]: a case whose balance has no root below it is held
there (far beyond where mineral oil and the Walther line are meaningful)."""


def lumped_temperature_rate(temp_C, heat_W, ambient_C, resistance_K_W, heat_capacity_J_K):
    """dT/dt [K/s] of a lumped heat capacity: ``(P - (T - T_amb)/R_th) / C_th`` [1].

    Parameters
    ----------
    temp_C : float or array
        Temperature of the lump [degC].
    heat_W : float or array
        Heat released in it [W].
    ambient_C : float or array
        Temperature of the surroundings [degC].
    resistance_K_W : float
        Thermal resistance to the surroundings [K/W], > 0.
    heat_capacity_J_K : float
        Heat capacity of the lump [J/K], > 0.

    Returns
    -------
    float or array
        Rate of change of the temperature [K/s].

    References
    ----------
    Bergman et al. [1], sec. 5.2 (lumped capacitance).
    """
    return (heat_W - (temp_C - ambient_C) / resistance_K_W) / heat_capacity_J_K


def steady_temperature(power_at: Callable[[np.ndarray], np.ndarray], base_temp_C,
                       resistance_K_W: float, n: int, tol_K: float = 1e-9,
                       max_iter: int = 60, max_temp_C: float = MAX_OIL_TEMP_C
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Solve the steady balance ``T = T_base + R_th P(T)`` of ``n`` cases at once [1].

    ``g(T) = T - T_base - R_th P(T)`` rises strictly (P falls as the oil warms),
    with ``g(T_base) <= 0 <= g(T_base + R_th P(T_base))``: exactly one root in
    that bracket. Vectorised safeguarded Newton (forward-difference slope; a step
    that leaves the bracket is replaced by bisection). A case whose root lies
    above ``max_temp_C`` is returned at that cap.

    Parameters
    ----------
    power_at : callable
        Loss of the cases [W] at temperatures [degC]: an array of length ``k n``
        (k = 1 or 2) holds k temperatures of every case, case index fastest.
    base_temp_C : float or array
        ``T_base`` [degC], one for all cases or one per case.
    resistance_K_W : float
        ``R_th`` [K/W], >= 0 (0: the oil is at ``T_base``).
    n : int
        Number of cases.
    tol_K : float
        Tolerance on the residual ``g(T)`` [K].
    max_iter : int
        Largest number of Newton iterations.
    max_temp_C : float
        Cap of the temperature [degC] (:data:`MAX_OIL_TEMP_C`).

    Returns
    -------
    temps_C : ndarray
        Steady temperature of each case [degC].
    power_W : ndarray
        Loss there [W].

    Raises
    ------
    InputError
        ``resistance_K_W`` < 0.
    SolverError
        No convergence to ``tol_K`` in ``max_iter`` iterations.

    References
    ----------
    Bergman et al. [1], sec. 3.1 (thermal resistance).
    """
    tb = np.broadcast_to(np.asarray(base_temp_C, dtype=float), (n,)).copy()
    rth = float(resistance_K_W)
    if not rth >= 0:
        raise InputError("resistance_K_W", rth, "must be >= 0", "heat balance")
    p_lo = power_at(tb)
    if rth == 0.0:
        return tb, p_lo
    lo = tb.copy()
    hi = np.minimum(tb + rth * p_lo, max_temp_C)
    capped = (hi >= max_temp_C) & (max_temp_C - tb - rth * power_at(hi) <= 0)
    t = np.where(capped, max_temp_C, 0.5 * (lo + hi))
    h = 1e-4
    for _ in range(max_iter):
        p = power_at(np.concatenate([t, t + h]))
        p0, p1 = p[:n], p[n:]
        g = np.where(capped, 0.0, t - tb - rth * p0)
        if np.all(np.abs(g) < tol_K):
            return t, p0
        lo = np.where(g < 0, t, lo)
        hi = np.where(g > 0, t, hi)
        t_new = t - g / (1.0 - rth * (p1 - p0) / h)
        t = np.where(capped, t, np.where((t_new > lo) & (t_new < hi), t_new, 0.5 * (lo + hi)))
    raise SolverError(f"steady oil temperature did not converge to {tol_K:g} K "
                      f"in {max_iter} iterations", "max_iter")


def joint_steady_temperature(power_at: Callable[[np.ndarray], np.ndarray], spec: ThermalSpec,
                             n: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Steady bulk oil temperature of a joint: ``T = T_sea + R (P(T) + Q)`` [1].

    The balance is :func:`steady_temperature` with the base temperature
    ``T_base = T_sea + R Q`` (Q, the other heat, does not depend on T). The
    residual ``g(T) = T - T_base - R P(T)`` rises strictly because the viscous
    loss P falls as the oil warms (dP/dT < 0, so dg/dT >= 1), and
    ``g(T_base) = -R P(T_base) <= 0 <= g(T_base + R P(T_base))``: the fixed point
    exists and is unique, between ``T_base`` and ``T_base + R P(T_base)``.

    Parameters
    ----------
    power_at : callable
        Viscous loss of the cases [W] at temperatures [degC] (as for
        :func:`steady_temperature`: an array of length ``k n``, case index fastest).
    spec : ThermalSpec
        Sea temperature [degC], resistance R [K/W] and other heat Q [W].
    n : int
        Number of cases.

    Returns
    -------
    temps_C : ndarray
        Steady oil temperature of each case [degC].
    power_W : ndarray
        Viscous loss there [W] (without Q).

    Raises
    ------
    SolverError
        The safeguarded Newton iteration did not converge.

    References
    ----------
    Bergman et al. [1], sec. 3.1 (thermal resistance).
    """
    base = spec.sea_temp_C + spec.resistance_K_W * spec.other_heat_W
    return steady_temperature(power_at, base, spec.resistance_K_W, n)


def joint_temperature_transient(power_at_time_temp: Callable[[float, float], float],
                                spec: ThermalSpec, t_s, start_temp_C: float,
                                rtol: float = 1e-10, atol_K: float = 1e-10) -> np.ndarray:
    """Bulk oil temperature over time: ``C dT/dt = P(t, T) + Q - (T - T_sea)/R`` [1].

    The right-hand side is :func:`lumped_temperature_rate` (one implementation of
    the law), integrated with :func:`scipy.integrate.solve_ivp` (DOP853) from
    ``start_temp_C`` at ``t_s[0]``.

    Parameters
    ----------
    power_at_time_temp : callable
        Viscous loss [W] at time [s] and oil temperature [degC]: ``P(t, T)``.
    spec : ThermalSpec
        Sea temperature [degC], resistance R [K/W], heat capacity C [J/K] and
        other heat Q [W].
    t_s : array_like
        Times [s], strictly increasing, at least one.
    start_temp_C : float
        Oil temperature at ``t_s[0]`` [degC].
    rtol : float
        Relative tolerance of the integrator [-].
    atol_K : float
        Absolute tolerance of the integrator [K].

    Returns
    -------
    ndarray
        Oil temperature at each of ``t_s`` [degC].

    Raises
    ------
    InputError
        ``t_s`` empty, not finite or not strictly increasing.
    SolverError
        The integrator failed.

    References
    ----------
    Bergman et al. [1], sec. 5.2 (lumped capacitance).
    """
    t = np.asarray(t_s, dtype=float).ravel()
    if t.size == 0 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        raise InputError("t_s", f"<{t.size} values>", "finite times [s], strictly "
                         "increasing, at least one", "heat balance")
    if t.size == 1:
        return np.array([float(start_temp_C)])

    def rate(time, y):
        heat = power_at_time_temp(time, y[0]) + spec.other_heat_W
        return [lumped_temperature_rate(y[0], heat, spec.sea_temp_C, spec.resistance_K_W,
                                        spec.heat_capacity_J_K)]

    sol = solve_ivp(rate, (t[0], t[-1]), [float(start_temp_C)], method="DOP853", t_eval=t,
                    rtol=rtol, atol=atol_K)
    if not sol.success:
        raise SolverError(f"oil temperature transient failed: {sol.message}", "solve_ivp")
    return sol.y[0]
