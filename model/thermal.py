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

Uniqueness needs only ``dg/dT = 1 - R_th dP/dT > 0``, i.e. ``dP/dT < 1/R_th``. The
isothermal loss always falls with T. With the film-heating factor
(:mod:`.film_cycle`) the loss of a laminar film tends to ``P ~ k ln(Na)/b`` at large
Na, which rises with T wherever b = -d ln(mu)/dT falls fast enough, and the fade of
the correction across Taylor onset raises a region's loss with T. For the seed joint
(VG10 to VG1000) the total loss still falls everywhere from -2 to 150 degC with either
wall condition (isothermal walls: from -30 degC); with an insulated rotor it rises
below -14 degC (VG10) and below -19 to -30 degC (VG320 to VG1000), and the bearing
region alone rises by at most 0.44 W/K across onset: far from 1/R_th. The solver
scans, where the residual fell on the way, for a lower root and returns the lowest it
finds (the bracket always holds a rising sign change of g, a stable balance).

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
from scipy.special import lambertw

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
                       max_iter: int = 60, max_temp_C: float = MAX_OIL_TEMP_C,
                       polish: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """Solve the steady balance ``T = T_base + R_th P(T)`` of ``n`` cases at once [1].

    ``g(T) = T - T_base - R_th P(T)`` rises strictly where P falls as the oil warms,
    with ``g(T_base) <= 0 <= g(T_base + R_th P(T_base))``: exactly one root in
    that bracket; generally, one root while ``dP/dT < 1/R_th``. Where P rose between
    ``T_base`` and the bracket's top (``g < 0`` there) the bracket is extended to
    ``max_temp_C``. Vectorised safeguarded Newton (forward-difference slope; a step
    leaving the bracket, a non-positive slope and every third iteration bisect, so the
    bracket always shrinks). Converged where ``|g| < tol_K`` or the bracket is narrower
    than ``tol_K``: a piecewise friction law (Eq. 6) gives P small steps where a speed
    node crosses a regime boundary, and a root on a downward step is the step itself.
    Where the residual was seen to fall (P rose) on the way, g is scanned at 15
    temperatures between ``T_base`` and the root; a lower sign change is solved in
    turn, so the root returned is the lowest found, where oil warming from ``T_base``
    stops. A case whose root lies above ``max_temp_C`` is returned at that cap.

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
    polish : bool
        Then step each case to the root itself (:func:`polish_roots`).

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
        No convergence in ``max_iter`` iterations.

    References
    ----------
    Bergman et al. [1], sec. 3.1 (thermal resistance).
    """
    tb = np.broadcast_to(np.asarray(base_temp_C, dtype=float), (n,)).copy()
    rth = float(resistance_K_W)
    if not rth >= 0:
        raise InputError("resistance_K_W", rth, "must be >= 0", "heat balance")
    if rth == 0.0:
        return tb, power_at(tb)
    st = _Newton(tb, rth, max_temp_C)
    for _ in range(max_iter):
        p = power_at(np.concatenate([st.t, st.t + _SLOPE_STEP_K]))
        p0, p1 = p[:n], p[n:]
        done, t_out, p_out = st.update(_total(p0), _total(p1), p0, p1, tol_K)
        if np.all(done):
            lower = _lower_sign_change(power_at, tb, rth, t_out, st.suspect & ~st.capped,
                                       tol_K)
            if lower is None:
                return (polish_roots(power_at, tb, rth, t_out, p_out, max_temp_C, tol_K)
                        if polish else (t_out, p_out))
            st.rebracket(*lower)
        st.extend_unverified(power_at, tol_K)
    raise SolverError(f"steady oil temperature did not converge to {tol_K:g} K "
                      f"in {max_iter} iterations", "max_iter")


_SLOPE_STEP_K = 1e-4
"""Forward-difference step of dP/dT in :func:`steady_temperature` [K]."""

_FAST_STEP_K = 1e-4
"""Largest last step taken without another evaluation [K]: a step of the loss (Eq. 6 is
piecewise) hidden inside it can move the root by no more than this."""


_POLISH_STEPS = 6
"""Largest number of chord steps of :func:`polish_roots` [-]."""

_POLISH_SLOPE_K = 1e-7
"""Forward-difference step of the polish's slope [K]: short enough not to straddle a
step of Eq. 6 that lies within _SLOPE_STEP_K of the root (a slope error of about 3e-7
from the loss's rounding)."""

_ROUNDING_ULPS = 64.0
"""A step under this many rounding units of g's terms ends the polish [-]: the loss's
own rounding (a sum over speed nodes and regions) moves g by up to about 30 units near
the root (measured on the seed joint), a K-independent floor of 3e-13 K there."""


def polish_roots(power_at: Callable[[np.ndarray], np.ndarray], base_temp_C, resistance_K_W,
                 temps_C, power_W, max_temp_C: float = MAX_OIL_TEMP_C, tol_K: float = 1e-9
                 ) -> tuple[np.ndarray, np.ndarray]:
    """Step converged roots of ``g(T) = T - T_base - R P(T)`` to the root itself [1].

    A case with ``|g| < 10 tol_K`` below the cap takes chord steps ``s = -g / g'`` with
    ``g'`` the forward-difference slope at its first point (step :data:`_POLISH_SLOPE_K`;
    the error shrinks by ``|1 - g'(root)/g'|``, about 1e-6, a step), within ``2
    _FAST_STEP_K`` of its start (the solver's last step may have been taken without an
    evaluation, its loss extrapolated across a step of Eq. 6), until a step is under 64
    rounding units of g's terms, ``64 eps (|T| + |T_base| + R P)`` (about 4e-13 K; the
    loss's rounding moves g by up to half that); it returns the last point evaluated. A
    case whose step would leave that window, or that does not settle in
    :data:`_POLISH_STEPS` (a downward step of the piecewise loss: no root there, the step
    is the answer), keeps its converged point.

    Parameters
    ----------
    power_at : callable
        As for :func:`steady_temperature` (``k n`` temperatures, case index fastest).
    base_temp_C : ndarray
        ``T_base`` [degC] of each case.
    resistance_K_W : float
        ``R`` [K/W].
    temps_C, power_W : ndarray
        The converged temperatures [degC] and their losses [W] (columns allowed).
    max_temp_C : float
        The cap [degC]: capped cases are left.
    tol_K : float
        The tolerance they converged to [K].

    Returns
    -------
    temps_C, power_W : ndarray
        The roots [degC] and the losses evaluated there [W].

    References
    ----------
    Bergman et al. [1], sec. 3.1 (thermal resistance).
    """
    n = temps_C.size
    t, p = temps_C.copy(), power_W.copy()
    rth = float(resistance_K_W)

    def g_of(tt, pp):
        return tt - base_temp_C - rth * _total(pp)

    live = (t < max_temp_C) & np.isfinite(t) & (np.abs(g_of(t, p)) < 10.0 * tol_K)
    if not live.any():
        return t, p
    start = t.copy()
    pp = power_at(np.concatenate([t, t + _POLISH_SLOPE_K]))
    p0, p1 = pp[:n], pp[n:]
    slope = 1.0 - rth * (_total(p1) - _total(p0)) / _POLISH_SLOPE_K
    live &= slope > 0
    cur_t, cur_p = t.copy(), p0
    for _ in range(_POLISH_STEPS):
        g = g_of(cur_t, cur_p)
        step = -g / np.where(live, slope, 1.0)
        tol = _ROUNDING_ULPS * np.finfo(float).eps * (np.abs(cur_t) + np.abs(base_temp_C)
                                                       + rth * np.abs(_total(cur_p)))
        done = live & (np.abs(step) <= tol)
        t = np.where(done, cur_t, t)
        p = np.where(done[:, None] if p.ndim == 2 else done, cur_p, p)
        live &= ~done & (np.abs(cur_t + step - start) <= 2.0 * _FAST_STEP_K)
        if not live.any():
            break
        cur_t = np.where(live, cur_t + step, cur_t)
        cur_p = power_at(cur_t)
    return t, p


def _total(p):
    """Total loss of each case: ``power_at`` may give one column per region."""
    return p.sum(axis=-1) if p.ndim == 2 else p


class _Newton:
    """State of the vectorised safeguarded iteration of :func:`steady_temperature`.

    Each step jumps to the root of an exponential model of P through (T, P, dP/dT),
    ``P = P0 exp(-beta (T - T0))``, whose root is ``T_b + W(beta R P0 exp(beta (T0 -
    T_b)))/beta`` (W: Lambert's function; near-exact for a Walther oil); where P does not
    fall, a Newton step; outside the bracket, or where the bracket did not halve in two
    steps, bisection. The bracket starts at ``[T_b, T_b + R P(T_b)]``; its top is
    verified (g > 0 seen) before a collapsed bracket counts as converged, else it is
    extended to the cap. A step s is taken without another evaluation when its a
    posteriori error ``R |P''| (s^2 + h |s|)/2`` (P'' from the last two slopes) is
    below tol/10.
    """

    def __init__(self, tb, rth, max_temp_C):
        self.tb, self.rth, self.cap = tb, rth, max_temp_C
        self.t = tb.copy()
        self.lo, self.hi = tb.copy(), np.full(tb.shape, np.nan)
        self.hi_ok = np.zeros(tb.shape, bool)
        self.capped = np.zeros(tb.shape, bool)
        self.suspect = np.zeros(tb.shape, bool)
        self.width = [np.full(tb.shape, np.inf)] * 2
        self.last = None
        self.done = np.zeros(tb.shape, bool)
        self.t_out = np.full(tb.shape, np.nan)
        self.p_out = None

    def update(self, P0, P1, p0, p1, tol_K):
        """One step from the losses at t and t + h; returns (done, T, P) of all cases."""
        t, r, h = self.t, self.rth, _SLOPE_STEP_K
        if self.p_out is None:
            self.p_out = np.full(p0.shape, np.nan)
            self.hi = np.minimum(self.tb + r * P0, self.cap)
        g = t - self.tb - r * P0
        dP = (P1 - P0) / h
        self.lo = np.where(g < 0, t, self.lo)
        self.hi_ok |= g > 0
        self.hi = np.where(g > 0, t, self.hi)
        slope = 1.0 - r * dP
        self.suspect |= slope <= 0
        step = -g / np.where(slope > 0, slope, np.inf)
        collapsed = (self.hi - self.lo <= tol_K) & self.hi_ok
        conv = (np.abs(g) < tol_K) | collapsed
        fast = self.capped & False
        if self.last is not None:
            t_l, dP_l = self.last
            curv = np.abs((dP - dP_l) / np.where(t != t_l, t - t_l, np.inf))
            fast = (~conv & (slope > 0) & (np.abs(step) < _FAST_STEP_K)
                    & (t + step > self.lo) & (t + step < self.hi)
                    & (10.0 * r * curv * (step * step + h * np.abs(step)) < 2.0 * tol_K))
        self.last = (t, dP)
        new = ~self.done & (conv | fast | self.capped)
        if new.any():
            ext = np.where(fast, step / h, 0.0)
            ext = ext[:, None] if p0.ndim == 2 else ext
            self.t_out = np.where(new, np.where(fast, t + step, t), self.t_out)
            self.p_out = np.where(new[:, None] if p0.ndim == 2 else new,
                                  p0 + (p1 - p0) * ext, self.p_out)
            self.done |= new
        if not self.done.all():
            self._next(t, P0, dP, step, slope)
        return self.done, self.t_out, self.p_out

    def _next(self, t, P0, dP, step, slope):
        """The next iterate of every case not yet done."""
        with np.errstate(all="ignore"):
            beta = -dP / P0
            falls = (dP < 0) & (P0 > 0)
            arg = beta * self.rth * P0 * np.exp(np.minimum(beta * (t - self.tb), 700.0))
            model = self.tb + np.real(lambertw(np.where(falls, arg, 0.0))) / beta
        t_new = np.where(falls & np.isfinite(model), model, t + step)
        inside = (t_new > self.lo) & (t_new < self.hi) & (slope > 0)
        width = self.hi - self.lo
        slow = width > 0.5 * self.width[0]
        self.width = [self.width[1], width]
        mid = 0.5 * (self.lo + self.hi)
        self.t = np.where(self.done, t, np.where(inside & ~slow, t_new, mid))

    def rebracket(self, mask, lo, hi):
        """Restart the cases of ``mask`` in the verified bracket [lo, hi] (g(lo) < 0 <
        g(hi)) below the root they had found."""
        self.done &= ~mask
        self.suspect &= ~mask
        self.lo = np.where(mask, lo, self.lo)
        self.hi = np.where(mask, hi, self.hi)
        self.hi_ok |= mask
        self.t = np.where(mask, 0.5 * (lo + hi), self.t)
        self.last = None
        self.width = [np.where(mask, np.inf, w) for w in self.width]

    def extend_unverified(self, power_at, tol_K):
        """Where the bracket collapsed onto an unverified top, check g there: a top
        with g <= 0 at the cap is the capped answer; below the cap the bracket is
        extended to the cap (P rose on the way)."""
        todo = ~self.done & ~self.hi_ok & (self.hi - self.lo <= tol_K)
        if not np.any(todo):
            return
        p_hi = power_at(self.hi)
        g_hi = self.hi - self.tb - self.rth * _total(p_hi)
        at_cap = todo & (g_hi <= 0) & (self.hi >= self.cap)
        self.capped |= at_cap
        self.done |= at_cap
        self.t_out = np.where(at_cap, self.cap, self.t_out)
        self.p_out = np.where(at_cap[:, None] if p_hi.ndim == 2 else at_cap, p_hi,
                              self.p_out)
        grow = todo & (g_hi <= 0) & ~at_cap
        self.suspect |= grow
        self.lo = np.where(grow, self.hi, self.lo)
        self.hi = np.where(grow, self.cap, self.hi)
        self.hi_ok |= todo & (g_hi > 0)
        self.t = np.where(grow, 0.5 * (self.lo + self.hi), self.t)
        self.width = [np.where(grow, np.inf, w) for w in self.width]


def _lower_sign_change(power_at, tb, rth, t, suspect, tol_K, points=16):
    """Where the residual was seen to fall on the way (``suspect``: P rose), scan g on
    ``points`` - 1 temperatures between T_base and the root found; return (mask, lo, hi)
    of the cases with a lower rise of g through 0 (a lower root, where oil warming from
    T_base stops first), or None."""
    if not np.any(suspect):
        return None
    found = np.zeros(t.shape, bool)
    lo, hi = tb.copy(), t.copy()
    for f in np.arange(1, points) / points:
        tt = np.where(suspect, tb + f * (t - tb), t)  # others held (a caching power_at
        # evaluates them once; their g is not used)
        g = tt - tb - rth * _total(power_at(tt))
        first = suspect & ~found & (g > tol_K)
        hi = np.where(first, tt, hi)
        found |= first
        lo = np.where(suspect & ~found & (g < 0), tt, lo)
    return (found, lo, hi) if np.any(found) else None


def joint_steady_temperature(power_at: Callable[[np.ndarray], np.ndarray], spec: ThermalSpec,
                             n: int = 1, trusted_range_C: tuple[float, float] | None = None
                             ) -> tuple[np.ndarray, np.ndarray]:
    """Steady bulk oil temperature of a joint: ``T = T_sea + R (P(T) + Q)`` [1].

    The balance is :func:`steady_temperature` with the base temperature
    ``T_base = T_sea + R Q`` (Q, the other heat, does not depend on T), polished to the
    root (:func:`polish_roots`: the vectorised rows of
    :mod:`oilgap.model.uncertain.balance` reach the same root, to rounding). The
    residual ``g(T) = T - T_base - R P(T)`` rises strictly because the viscous
    loss P falls as the oil warms (dP/dT < 0, so dg/dT >= 1), and
    ``g(T_base) = -R P(T_base) <= 0 <= g(T_base + R P(T_base))``: the fixed point
    exists and is unique, between ``T_base`` and ``T_base + R P(T_base)``. The
    condition is ``dP/dT < 1/R`` (module docstring: where the film-corrected loss can
    rise with T); an iterate that breaks it raises :class:`SolverError`.

    Parameters
    ----------
    power_at : callable
        Viscous loss of the cases [W] at temperatures [degC] (as for
        :func:`steady_temperature`: an array of length ``k n``, case index fastest).
    spec : ThermalSpec
        Sea temperature [degC], resistance R [K/W] and other heat Q [W].
    n : int
        Number of cases.
    trusted_range_C : tuple of float, optional
        Temperatures [degC] over which the fluid's law is trusted, quoted in the
        message of a balance without a root.

    Returns
    -------
    temps_C : ndarray
        Steady oil temperature of each case [degC].
    power_W : ndarray
        Viscous loss there [W] (without Q).

    Raises
    ------
    SolverError
        The safeguarded Newton iteration did not converge, the residual is not
        monotone (``dP/dT >= 1/R`` at an iterate: the root may not be unique), or the
        balance has no root below :data:`MAX_OIL_TEMP_C` (the solver's cap is never
        returned as an operating temperature; :func:`require_balanced`).

    References
    ----------
    Bergman et al. [1], sec. 3.1 (thermal resistance).
    """
    base = spec.sea_temp_C + spec.resistance_K_W * spec.other_heat_W
    if n == 1:
        require_balanced(np.array([base]), spec, trusted_range_C)
    temps, powers = steady_temperature(power_at, base, spec.resistance_K_W, n, polish=True)
    require_balanced(temps, spec, trusted_range_C, powers)
    return temps, powers


def require_balanced(temps_C, spec: ThermalSpec,
                     trusted_range_C: tuple[float, float] | None = None,
                     power_W=None, max_temp_C: float = MAX_OIL_TEMP_C) -> None:
    """Refuse a steady balance ``T = T_sea + R (P(T) + Q)`` without a root below the cap.

    :func:`steady_temperature` holds a case whose balance has no root below
    ``max_temp_C`` at the cap; that is a failure, never an operating temperature [1].

    Parameters
    ----------
    temps_C : array_like
        Steady temperatures [degC] (or the base ``T_sea + R Q`` before solving).
    spec : ThermalSpec
        Sea temperature [degC], resistance R [K/W] and other heat Q [W].
    trusted_range_C : tuple of float, optional
        Temperatures [degC] over which the fluid's law is trusted.
    power_W : array_like, optional
        Viscous loss at ``temps_C`` [W] (one row per case; columns summed).
    max_temp_C : float
        The bound [degC] (:data:`MAX_OIL_TEMP_C`).

    Raises
    ------
    SolverError
        A temperature at or above ``max_temp_C``, or not finite: one line naming the
        bound, the heat that overshoots it and the fluid's trusted range.

    References
    ----------
    Bergman et al. [1], sec. 3.1 (thermal resistance).
    """
    t = np.atleast_1d(np.asarray(temps_C, dtype=float))
    bad = ~(t < max_temp_C)
    if not bad.any():
        return
    j = int(np.flatnonzero(bad)[0])
    r, q, sea = spec.resistance_K_W, spec.other_heat_W, spec.sea_temp_C
    if power_W is None:
        why = (f"the sea {sea:g} degC + R {r:g} K/W x other heat {q:g} W alone is "
               f"{sea + r * q:.4g} degC")
    else:
        p = float(_total(np.atleast_1d(np.asarray(power_W, dtype=float))
                         .reshape(t.size, -1))[j])
        why = (f"at {max_temp_C:g} degC the loss {p:.3g} W + other heat {q:g} W times "
               f"R {r:g} K/W + sea {sea:g} degC = {sea + r * (p + q):.4g} degC")
    trust = ("" if trusted_range_C is None else
             f"; the fluid's law is trusted to {trusted_range_C[1]:g} degC")
    raise SolverError(f"no oil temperature below {max_temp_C:g} degC balances the heat "
                      f"(resistance_K_per_W = {r:g}, other_heat_W = {q:g}): {why} > "
                      f"{max_temp_C:g}{trust}", "no_root")


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
