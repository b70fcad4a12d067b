"""The heat balance of stacked rows solved to the exact root: a fast bracketed iteration.

:func:`root_balance` solves ``g(T) = T - T_base - R P(T) = 0`` for every row to full
double precision in T with 3.5-4 evaluations of the loss per row (the seed joint, alone
and with a 6809 bearing), where :func:`~oilgap.model.thermal.steady_temperature` (the
scalar path's solver, replayed row by row by
:func:`~oilgap.model.uncertain.rows.row_balance`) stops at ``|g| < 1e-9 K`` after 10-20.
Each step fits the exponential model ``P = P_k exp(-beta (T - T_k))`` through the last
two points (beta from their secant of ln P) and jumps to its root with Lambert's W, ``T =
T_b + W(beta R P_k exp(beta (T_k - T_b)))/beta`` [1]; a step outside the bracket ``[lo,
hi]`` (g < 0 at lo, g > 0 at hi) is replaced by the Illinois false position [2]. A row
stops when its next step is under eight rounding units of g's terms, ``8 eps (|T| + T_b +
R P)`` (about 5e-14 K), and ``|g|`` at its last point under 16 times that; or when the step
is so short that the model's loss there is exact to about 1e-13 (``|s| (|s| + d) <= 1e-10
K^2``, d the spacing of the model's two points), taken without another evaluation.

The start: a pilot of 64 rows (evenly spaced) is solved from its bracket ``[T_b, T_b + R
P(T_b)]``; with the rows' values (``features``) the others start at the root predicted by
a least-squares fit of ``ln(T - T_b)`` on those values (and their logs) over the pilot,
and their second point is one model step from there with the local beta at the root
fitted the same way. Without features, every row's first point is ``T_b`` and its second
the model root with the pilot's median beta. The start only decides how fast a row
converges, not where.

A row it cannot settle this way is handed back (``ok`` False): a loss that did not fall
between two of its points (where the scalar solver scans for a lower root), a bracket top
at the cap :data:`~oilgap.model.thermal.MAX_OIL_TEMP_C`, a non-finite or non-positive
loss, a bracket closed without g reaching 0 (the root on a downward step of the piecewise
Eq. 6, where a speed node crosses a regime boundary: the scalar solver returns the step
from its side), or no convergence in :data:`MAX_EVALS` evaluations. The caller solves
those rows by the scalar path's iteration. Not reproduced: the scalar solver's scan for a
lower root below T_b's neighbourhood (rows started near their root never evaluate the
loss at T_b): where the loss rises only well below the root, this returns the upper root
(docs/benchmarks.md; the seed's loss falls everywhere from -2 to 150 degC); and where the
scalar solver's bracket collapses on a downward step of Eq. 6 (its answer: the step)
while a genuine root lies just above it, this returns that root (5 rows in 200,000 of
the benchmark's bearing rows, 4e-7 to 5e-6 relative apart).

References
----------
.. [1] R. M. Corless et al., "On the Lambert W function", *Adv. Comput. Math.* 5 (1996)
   329-359 (the root of ``x - a - c exp(-b x)``).
.. [2] M. Dowell and P. Jarratt, "A modified regula falsi method for computing the root
   of an equation", *BIT* 11 (1971) 168-174 (the Illinois method).
.. [3] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 3.1 (the bulk balance).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from scipy.special import lambertw

from ..thermal import MAX_OIL_TEMP_C

MAX_EVALS = 12
"""Evaluations of the loss per row before a row is handed back [-]."""

_ULPS = 8.0
"""A step (or bracket) under this many rounding units of g's terms ends a row [-]."""

_NOISE_K = 1e-9
"""Points closer than this [K]: their losses' order is rounding, not a rising loss."""


def _model_root(tb, rth, t_k, p_k, beta):
    """Root of ``T - T_b - R P_k exp(-beta (T - T_k))`` [degC] (NaN where beta <= 0)."""
    with np.errstate(all="ignore"):
        arg = beta * rth * p_k * np.exp(np.minimum(beta * (t_k - tb), 700.0))
        w = np.real(lambertw(np.where(beta > 0, arg, 0.0)))
        return np.where(beta > 0, tb + w / beta, np.nan)


def root_balance(power: Callable[[np.ndarray, np.ndarray], np.ndarray], base_temp_C,
                 resistance_K_W: float, max_temp_C: float = MAX_OIL_TEMP_C,
                 features=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Exact root of ``T = T_base + R P(T)`` for every row, or the row handed back [3].

    Parameters
    ----------
    power : callable
        ``power(temps_C, rows)``: the total loss [W] of the rows ``rows`` (int array) at
        temperatures ``temps_C`` [degC], one per entry.
    base_temp_C : ndarray
        ``T_base = T_sea + R Q`` of each row [degC].
    resistance_K_W : float
        R [K/W], > 0.
    max_temp_C : float
        The cap [degC]: a bracket reaching it hands the row back.
    features : ndarray, optional
        Shape (rows, k): the values the rows differ by (their units); the other rows'
        roots are predicted from the pilot rows' on them (fewer losses a row).

    Returns
    -------
    temps_C : ndarray
        The root [degC] (NaN where not ``ok``).
    power_W : ndarray
        The loss there [W] (the loss evaluated at the returned temperature).
    ok : ndarray of bool
        Rows solved; the others are left to the scalar path's iteration.

    References
    ----------
    Corless et al. [1]_ (Lambert W); Dowell and Jarratt [2]_ (Illinois); Bergman et al.
    [3]_, sec. 3.1.
    """
    tb = np.asarray(base_temp_C, dtype=float)
    r = float(resistance_K_W)
    n = tb.size
    out = (np.full(n, np.nan), np.full(n, np.nan), np.zeros(n, bool))
    idx = np.arange(n)
    with np.errstate(all="ignore"):
        pilot = idx[::max(1, n // _PILOT_ROWS)]
        p0 = np.full(n, np.nan)
        p0[pilot] = power(tb[pilot], pilot)
        _from_top(power, pilot, tb, r, p0, out, max_temp_C)
        rest = idx[~np.isin(idx, pilot)]
        done = pilot[out[2][pilot]]
        if features is not None and done.size >= _PILOT_ROWS // 2:
            _from_prediction(power, rest, done, tb, r, np.asarray(features, float), out,
                             max_temp_C)
        elif rest.size:
            p0[rest] = power(tb[rest], rest)
            _from_beta(power, rest, done, tb, r, p0, out, max_temp_C)
    out[2][:] &= out[0] < max_temp_C - 1.0  # near the cap: the scalar path decides
    return out


def _from_beta(power, rest, done, tb, r, p0, out, cap):
    """Rows started at the root of the exponential model through ``(T_b, P(T_b))`` with
    the pilot rows' median beta (from their bracket without a pilot)."""
    if done.size < 4:  # no beta to start from: every row from its bracket
        _from_top(power, rest, tb, r, p0, out, cap)
        return
    t, p = out[0][done], out[1][done]
    beta = float(np.median(np.log(p0[done] / p) / (t - tb[done])))
    hi = tb + r * p0
    t1 = _model_root(tb[rest], r, tb[rest], p0[rest], beta)
    good = (t1 > tb[rest]) & (t1 < hi[rest]) & (hi[rest] < cap)
    _from_top(power, rest[~good], tb, r, p0, out, cap)
    rest, t1 = rest[good], t1[good]
    p1 = power(t1, rest)
    fell = np.isfinite(p1) & (p1 > 0) & (p1 < p0[rest])
    rest, t1, p1 = rest[fell], t1[fell], p1[fell]
    st = _State(rest, tb[rest], r, tb[rest], p0[rest], t1, p1)
    below = st.g_hi < 0  # the pilot's beta put t1 below the root: hi unverified, its
    st.lo, st.g_lo = np.where(below, t1, st.lo), np.where(below, st.g_hi, st.g_lo)
    st.hi = np.where(below, hi[rest], t1)  # g estimated from the loss at t1 (above it)
    st.g_hi = np.where(below, r * (p0[rest] - p1), st.g_hi)
    _iterate(power, st, MAX_EVALS - 2, out)


def _design(x):
    """Regression columns of the rows' values: 1, each value, and the log of each
    positive one, scaled to unit size."""
    cols = [np.ones(len(x))]
    for c in x.T:
        cols.append(c / max(float(np.max(np.abs(c))), 1e-300))
        if np.all(c > 0):
            cols.append(np.log(c / np.max(c)))
    return np.column_stack(cols)


def _from_prediction(power, rest, done, tb, r, features, out, cap):
    """Rows started at their root predicted from the pilot rows: ``ln(T - T_b)`` fitted
    on the rows' values by least squares; the second point one model step from there
    with the local beta at the root fitted the same way. Rows that do not start cleanly go from
    their bracket."""
    x = _design(features)
    t_d, p_d = out[0][done], out[1][done]
    coef = np.linalg.lstsq(x[done], np.log(t_d - tb[done]), rcond=None)[0]
    beta_d = np.log(p_d / power(t_d + _BETA_STEP_K, done)) / _BETA_STEP_K
    beta = x[rest] @ np.linalg.lstsq(x[done], beta_d, rcond=None)[0]
    beta = np.where(beta > 0, beta, float(np.median(beta_d)))
    t1 = tb[rest] + np.exp(x[rest] @ coef)
    p1 = power(t1, rest)
    t2 = _model_root(tb[rest], r, t1, p1, beta)
    good = np.isfinite(p1) & (p1 > 0) & np.isfinite(t2) & (t2 > tb[rest]) & (t2 < cap)
    p2 = np.full(t2.shape, np.nan)
    p2[good] = power(t2[good], rest[good])
    good &= np.isfinite(p2) & (p2 > 0) & ((p2 - p1) * (t2 - t1) < 0)
    bad = rest[~good]
    p0 = np.full(len(tb), np.nan)
    p0[bad] = power(tb[bad], bad)
    _from_top(power, bad, tb, r, p0, out, cap)
    rest, t1, p1, t2, p2 = rest[good], t1[good], p1[good], t2[good], p2[good]
    st = _State(rest, tb[rest], r, t1, p1, t2, p2)
    g1, g2 = st.g(t1, p1), st.g(t2, p2)
    lo1, lo2 = (g1 < 0) & ~((g2 < 0) & (t2 > t1)), (g2 < 0) & ~((g1 < 0) & (t1 > t2))
    hi1, hi2 = (g1 > 0) & ~((g2 > 0) & (t2 < t1)), (g2 > 0) & ~((g1 > 0) & (t1 < t2))
    st.lo = np.select([lo1, lo2], [t1, t2], st.tb)
    st.g_lo = np.select([lo1, lo2], [g1, g2], -r * np.maximum(p1, p2))  # an estimate
    st.hi = np.select([hi1, hi2], [t1, t2], cap)
    st.g_hi = np.select([hi1, hi2], [g1, g2], cap - st.tb - r * np.minimum(p1, p2))
    _iterate(power, st, MAX_EVALS - 2, out)


_MODEL_K2 = 1e-10
"""A last step s [K] is taken on the model, without evaluating the loss again, when
``|s| (|s| + d) <= this`` [K^2] (d: the spacing of the two points the model's beta came
from): beta's error is about ``|d beta/dT| d`` (below 0.01 /K^2 for an oil), so the loss
there is the model's to ``|d beta/dT| d |s|``, about 1e-12 relative."""

_MAX_SLOPE = 10.0
"""Largest slope dg/dT = 1 + R beta P [-] of a last step taken on the model: a steeper
secant spans a step of the piecewise loss (Eq. 6), not its smooth part."""

_BETA_STEP_K = 1e-3
"""Step of the pilot roots' local beta ``-d ln P/dT`` [K]."""

_PILOT_ROWS = 64
"""Rows of a block solved first from ``[T_b, T_b + R P(T_b)]``; their median exponent
beta of the loss between T_b and the root starts the other rows near their root [-]."""


def _from_top(power, idx, tb, r, p0, out, cap):
    """Rows started from their bracket ``[T_b, T_b + R P(T_b)]`` (the top: the
    fixed-point iterate, where ``g = R (P(T_b) - P(top)) > 0``)."""
    hi = tb[idx] + r * p0[idx]
    idx, hi = idx[np.isfinite(hi) & (p0[idx] > 0) & (hi < cap)], hi[np.isfinite(hi)
                                                                  & (p0[idx] > 0) & (hi < cap)]
    if idx.size == 0:
        return
    p1 = power(hi, idx)
    live = np.isfinite(p1) & (p1 > 0) & (p1 < p0[idx])
    idx, hi, p1 = idx[live], hi[live], p1[live]
    _iterate(power, _State(idx, tb[idx], r, tb[idx], p0[idx], hi, p1), MAX_EVALS - 2, out)


def _iterate(power, st, evals, out):
    """Step the rows of ``st`` until solved, handed back or out of ``evals``; the solved
    rows' (T, P, True) into ``out``."""
    t_out, p_out, ok = out
    for _ in range(evals):
        if st.idx.size == 0:
            break
        t_new, p_model = st.propose()
        solved, model, closed = st.stopped(t_new)
        model &= np.isfinite(p_model)
        fin = st.idx[solved]
        t_out[fin], p_out[fin], ok[fin] = st.t_k[solved], st.p_k[solved], True
        fin = st.idx[model]
        t_out[fin], p_out[fin], ok[fin] = t_new[model], p_model[model], True
        st.keep(~(solved | model | closed))
        t_new = t_new[~(solved | model | closed)]
        st.take(t_new, power(t_new, st.idx))


class _State:
    """The rows still iterating: the last two points, the bracket and Illinois' side."""

    def __init__(self, idx, tb, r, t_a, p_a, t_k, p_k):
        self.idx, self.tb, self.r = idx, tb, r
        self.t_a, self.p_a, self.t_k, self.p_k = t_a, p_a, t_k, p_k
        self.lo, self.g_lo = t_a.copy(), t_a - tb - r * p_a
        self.hi, self.g_hi = t_k.copy(), t_k - tb - r * p_k
        self.side = np.zeros(idx.size, np.int8)  # 1: hi kept at the last step, -1: lo

    def g(self, t, p):
        return t - self.tb - self.r * p

    def propose(self):
        """The next temperature of each row: the exponential model's root through the
        last two points, else the Illinois false position in the bracket; and the
        model's loss there, ``P_k exp(-beta (T - T_k))``."""
        beta = np.log(self.p_a / self.p_k) / (self.t_k - self.t_a)
        t_new = _model_root(self.tb, self.r, self.t_k, self.p_k, beta)
        inside = (t_new > self.lo) & (t_new < self.hi)
        falsi = (self.lo * self.g_hi - self.hi * self.g_lo) / (self.g_hi - self.g_lo)
        t_new = np.where(inside, t_new, falsi)
        return t_new, np.where(inside, self.p_k * np.exp(-beta * (t_new - self.t_k)), np.nan)

    def stopped(self, t_new):
        """(rows solved at their last point: a step under the rounding of g with g itself
        at that level; rows solved at ``t_new`` by the model: a short last step; rows to
        hand back: a bracket closed on a step of the loss)."""
        tol = _ULPS * np.finfo(float).eps * (np.abs(self.t_k) + np.abs(self.tb)
                                             + self.r * self.p_k)
        g_k = np.abs(self.t_k - self.tb - self.r * self.p_k)
        step = np.abs(t_new - self.t_k)
        solved = (step <= tol) & (g_k <= 16.0 * tol)
        model = (~solved & (step * (step + np.abs(self.t_k - self.t_a)) <= _MODEL_K2)
                 & (g_k <= _MAX_SLOPE * step + 16.0 * tol))  # not across a step of P
        return solved, model, ~solved & ~model & (self.hi - self.lo <= tol)

    def keep(self, m):
        for k in ("idx", "tb", "t_a", "p_a", "t_k", "p_k", "lo", "g_lo", "hi", "g_hi",
                  "side"):
            setattr(self, k, getattr(self, k)[m])

    def take(self, t, p):
        """A new point: shift the pair, move the bracket; rows whose loss rose (or is not
        finite) leave."""
        g = self.g(t, p)
        fell = np.isfinite(p) & (p > 0) & ((np.abs(t - self.t_k) < _NOISE_K)
                                           | ((p - self.p_k) * (t - self.t_k) < 0))
        below = g < 0
        self.lo = np.where(below, t, self.lo)
        self.g_lo = np.where(below, g, np.where(self.side == -1, 0.5, 1.0) * self.g_lo)
        self.hi = np.where(below, self.hi, t)
        self.g_hi = np.where(below, np.where(self.side == 1, 0.5, 1.0) * self.g_hi, g)
        self.side = np.where(below, 1, -1).astype(np.int8)  # Illinois: an end kept twice
        self.t_a, self.p_a, self.t_k, self.p_k = self.t_k, self.p_k, t, p  # has g halved
        self.keep(fell)


__all__ = ["MAX_EVALS", "root_balance"]
