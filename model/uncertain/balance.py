"""The heat balance of stacked rows solved to the exact root: a fast bracketed iteration.

:func:`root_balance` solves ``g(T) = T - T_base - R P(T) = 0`` for every row to full
double precision in T with 3.1 evaluations of the loss per row on a large run (the seed
joint, alone and with a 6809 bearing; 3.5-4 with a pilot per block), where the scalar
path's solver, :func:`~oilgap.model.thermal.steady_temperature`, takes 10-20 to ``|g| <
1e-9 K`` and its polish (:func:`~oilgap.model.thermal.polish_roots`) 2-3 more to the root:
the two agree to rounding (1e-13 relative in the loss). Each step fits the exponential
model ``P = P_k exp(-beta (T - T_k))`` through the last two points (beta from their secant
of ln P) and jumps to its root with Lambert's W, ``T = T_b + W(beta R P_k exp(beta (T_k -
T_b)))/beta`` [1]; a step outside the bracket ``[lo, hi]`` (g < 0 at lo, g > 0 at hi) is
replaced by the Illinois false position [2]. A row stops when its next step is under eight
rounding units of g's terms, ``8 eps (|T| + T_b + R P)`` (about 5e-14 K), and ``|g|`` at its
last point under 16 times that; or when the step is so short that the model's loss there
is exact to about 1e-13 (``|s| (|s| + d) <= 1e-10 K^2``, d the spacing of the model's two
points), taken without another evaluation.

The start: a pilot of rows is solved from its bracket ``[T_b, T_b + R P(T_b)]``; with the
rows' values (``features``) the others start at the root predicted by a least-squares fit
of ``ln(T - T_b)`` on those values (and their logs) over the pilot, and their second point
is one model step from there with the local beta at the root fitted the same way. A large
run fits one :class:`Predictor` (a quadratic surface) on 512 rows once
(:func:`fit_predictor`) and passes it to every block; otherwise each call's own 64 rows
fit a linear one. Without features, every row's first point is ``T_b`` and its second
the model root with the pilot's median beta. The start only decides how fast a row
converges, not where.

A row it cannot settle this way is handed back (``ok`` False): a loss that did not fall
between two of its points (where the scalar solver scans for a lower root), a bracket top
at the cap :data:`~oilgap.model.thermal.MAX_OIL_TEMP_C`, a non-finite or non-positive
loss, a bracket closed without g reaching 0 (the root on a downward step of the piecewise
Eq. 6, where a speed node crosses a regime boundary: the scalar solver returns the step
from its side), or no convergence in :data:`MAX_EVALS` evaluations. The caller solves
those rows by the scalar path's solver (about 6 rows in 10,000 with the bearing). Not
reproduced: the scalar solver's scan for a lower root below T_b's neighbourhood (rows
started near their root never evaluate the loss at T_b): where the loss rises only well
below the root, this returns the upper root (docs/benchmarks.md; the seed's loss falls
everywhere from -2 to 150 degC); and where the scalar solver's bracket collapses on a
downward step of Eq. 6 (its answer: the step) while a genuine root lies just above it,
this returns that root (5 rows in 200,000 of the benchmark's bearing rows, 4e-7 to 5e-6
relative apart).

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

from ..thermal import MAX_OIL_TEMP_C

MAX_EVALS = 12
"""Evaluations of the loss per row before a row is handed back [-]."""

_ULPS = 8.0
"""A step (or bracket) under this many rounding units of g's terms ends a row [-]."""

_NOISE_K = 1e-9
"""Points closer than this [K]: their losses' order is rounding, not a rising loss."""


def lambert_w0(x):
    """Principal branch of Lambert's W for real ``x >= 0``: ``w exp(w) = x`` [1]_ [-].

    Halley's iteration from ``log1p(x)`` (x < e) or ``log x - log log x``, vectorised, to
    a relative step under 4 rounding units (four or five iterations); NaN where x < 0
    or x is not finite. Replaces SciPy's complex ``lambertw`` here (about twice as fast
    on arrays; equal to it within 5e-16 relative from 1e-12 to 1e12).

    Parameters
    ----------
    x : ndarray
        Argument [-], >= 0.

    Returns
    -------
    ndarray
        W0(x) [-].

    References
    ----------
    Corless et al. [1]_, eq. 5.9 (Halley's iteration for W).
    """
    x = np.asarray(x, dtype=float)
    with np.errstate(all="ignore"):
        big = x > np.e
        lx = np.log(np.where(big, x, np.e))
        w = np.where(big, lx - np.log(lx), np.log1p(np.where(big, 0.0, x)))
        for _ in range(8):
            ew = np.exp(w)
            f = w * ew - x
            step = f / (ew * (w + 1.0) - (w + 2.0) * f / (2.0 * w + 2.0))
            w = w - step
            if not np.any(np.abs(step) > 4.0 * np.finfo(float).eps * np.maximum(w, 1e-300)):
                break
        return np.where((x >= 0) & np.isfinite(x), np.where(x == 0, 0.0, w), np.nan)


def _model_root(tb, rth, t_k, p_k, beta):
    """Root of ``T - T_b - R P_k exp(-beta (T - T_k))`` [degC] (NaN where beta <= 0)."""
    with np.errstate(all="ignore"):
        arg = beta * rth * p_k * np.exp(np.minimum(beta * (t_k - tb), 700.0))
        w = lambert_w0(np.where(beta > 0, arg, 0.0))
        return np.where(beta > 0, tb + w / beta, np.nan)


def root_balance(power: Callable[[np.ndarray, np.ndarray], np.ndarray], base_temp_C,
                 resistance_K_W: float, max_temp_C: float = MAX_OIL_TEMP_C,
                 features=None, predictor: Predictor | None = None
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
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
    predictor : Predictor, optional
        A predictor fitted beforehand (:func:`fit_predictor`, on other rows of the same
        case): every row starts at its prediction from ``features``, without a pilot.

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
        if predictor is not None and features is not None:
            _from_predicted(power, idx, tb, r, *predictor(np.asarray(features, float), tb),
                            out, max_temp_C)
            out[2][:] &= out[0] < max_temp_C - 1.0
            return out
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


def _standard(x, center=None, scale=None):
    """The rows' values ``x`` (rows, k) and the logs of the positive ones, standardised
    (by the given centre and scale, or the rows' own) [-]."""
    cols = []
    for c in np.asarray(x, float).T:
        cols.append(c)
        if np.all(c > 0):
            cols.append(np.log(c))
    z = np.column_stack(cols)
    if center is None:
        center, scale = z.mean(axis=0), z.std(axis=0)
        scale = np.where(scale > 0, scale, 1.0)
    return (z - center) / scale, center, scale


def _columns(z):
    """Regression columns of standardised values ``z``: 1, each, and the product of every
    pair (a quadratic response surface)."""
    k = z.shape[1]
    quad = [z[:, i] * z[:, j] for i in range(k) for j in range(i, k)]
    return np.column_stack([np.ones(len(z)), z, *quad])


class Predictor:
    """A root's predictor fitted on solved rows: ``ln(T - T_b)`` and the local exponent
    beta at the root, least squares on a quadratic surface of the rows' values and their
    logs (standardised).

    Parameters
    ----------
    features : ndarray
        The solved rows' values, one row each, one column per feature.
    tb : ndarray
        Each row's base temperature T_b of the balance [degC].
    temps : ndarray
        Each row's root, the steady oil temperature [degC].
    beta : ndarray
        Each row's local exponent of the loss at its root, -d ln P / dT [1/K].
    """

    def __init__(self, features, tb, temps, beta):
        z, self.center, self.scale = _standard(features)
        x = _columns(z)
        self.coef = [self._unpack(_ridge(x, y), z.shape[1])
                     for y in (np.log(temps - tb), beta)]
        self.beta_median = float(np.median(beta))

    @staticmethod
    def _unpack(c, k):
        """(constant, linear, upper-triangular quadratic matrix) of the coefficients."""
        q = np.zeros((k, k))
        q[np.triu_indices(k)] = c[1 + k:]
        return float(c[0]), c[1:1 + k], q

    def __call__(self, features, tb):
        """(predicted root [degC], predicted beta [1/K]) of rows."""
        zt = np.ascontiguousarray(_standard(features, self.center, self.scale)[0].T)
        out = [_surface(zt, c0, c1, q) for c0, c1, q in self.coef]
        beta = out[1]
        return tb + np.exp(out[0]), np.where(beta > 0, beta, self.beta_median)


def _surface(zt, c0, c1, q):
    """``c0 + z c1 + z q z`` of each row (``zt``: the values z by column, q upper
    triangular), summed column by column in one fixed order without BLAS: the same numbers
    on any CPU and core count (three times faster than ``einsum``'s matrix product)."""
    total = np.full(zt.shape[1], c0)
    tmp = np.empty(zt.shape[1])
    for i in range(len(zt)):
        inner = q[i, i] * zt[i]
        inner += c1[i]
        for j in range(i + 1, len(zt)):
            inner += np.multiply(q[i, j], zt[j], out=tmp)
        total += np.multiply(zt[i], inner, out=inner)
    return total


def _ridge(x, y):
    """Least squares of ``x c = y`` by its normal equations with a 1e-10 ridge (columns
    may repeat an input: A and B of one nu40 factor) and a Cholesky factorisation written
    out, without threaded BLAS or LAPACK: the same coefficients on any core count and
    load (``einsum`` sums in order)."""
    a = np.einsum("ki,kj->ij", x, x)
    a[np.diag_indices_from(a)] += 1e-10 * max(float(np.trace(a)) / len(a), 1e-300)
    b = np.einsum("ki,k->i", x, y)
    n = len(a)
    lo = np.zeros_like(a)
    for j in range(n):  # a = L L^T, column by column
        d = a[j, j] - np.einsum("k,k->", lo[j, :j], lo[j, :j])
        lo[j, j] = np.sqrt(max(d, 1e-300))
        lo[j + 1:, j] = (a[j + 1:, j] - np.einsum("ik,k->i", lo[j + 1:, :j], lo[j, :j])
                         ) / lo[j, j]
    u = np.zeros(n)
    for i in range(n):  # L u = b
        u[i] = (b[i] - np.einsum("k,k->", lo[i, :i], u[:i])) / lo[i, i]
    c = np.zeros(n)
    for i in range(n - 1, -1, -1):  # L^T c = u
        c[i] = (u[i] - np.einsum("k,k->", lo[i + 1:, i], c[i + 1:])) / lo[i, i]
    return c


def fit_predictor(power, base_temp_C, resistance_K_W: float, features, rows,
                  max_temp_C: float = MAX_OIL_TEMP_C) -> Predictor | None:
    """Solve ``rows`` from their brackets (their values ``features[rows]``) and fit the
    :class:`Predictor` of the others' roots on them (None: too few solved).

    Parameters
    ----------
    power : callable
        As for :func:`root_balance` (row numbers index ``base_temp_C`` and ``features``).
    base_temp_C : ndarray
        ``T_base`` of every row [degC].
    resistance_K_W : float
        R [K/W].
    features : ndarray
        Shape (rows, k): the rows' values.
    rows : ndarray of int
        The pilot rows.
    max_temp_C : float
        The cap [degC].

    Returns
    -------
    Predictor or None
        The fitted predictor [degC, 1/K].
    """
    tb = np.asarray(base_temp_C, dtype=float)
    n = tb.size
    out = (np.full(n, np.nan), np.full(n, np.nan), np.zeros(n, bool))
    with np.errstate(all="ignore"):
        p0 = np.full(n, np.nan)
        p0[rows] = power(tb[rows], rows)
        _from_top(power, rows, tb, float(resistance_K_W), p0, out, max_temp_C)
        done = rows[out[2][rows] & (out[0][rows] > tb[rows])]
        x = np.asarray(features, float)
        if done.size < 2 * _columns(_standard(x[done[:2]])[0]).shape[1]:
            return None
        t_d, p_d = out[0][done], out[1][done]
        beta = np.log(p_d / power(t_d + _BETA_STEP_K, done)) / _BETA_STEP_K
        good = np.isfinite(beta) & (beta > 0)
        return Predictor(x[done[good]], tb[done[good]], t_d[good], beta[good])


def _from_prediction(power, rest, done, tb, r, features, out, cap):
    """Rows started at their root predicted by a :class:`Predictor` fitted on the pilot
    rows ``done``."""
    x = np.asarray(features, float)
    t_d, p_d = out[0][done], out[1][done]
    beta_d = np.log(p_d / power(t_d + _BETA_STEP_K, done)) / _BETA_STEP_K
    good = np.isfinite(beta_d) & (beta_d > 0)
    if good.sum() > 2 * _columns(_standard(x[:2])[0]).shape[1]:
        pred = Predictor(x[done[good]], tb[done[good]], t_d[good], beta_d[good])
    else:
        pred = _LinearPredictor(x[done], tb[done], t_d, beta_d)
    _from_predicted(power, rest, tb, r, *pred(x[rest], tb[rest]), out, cap)


class _LinearPredictor:
    """The predictor of few pilot rows: 1, each value and its log (unit-scaled)."""

    def __init__(self, x, tb, temps, beta):
        self.scale = np.maximum(np.max(np.abs(x), axis=0), 1e-300)
        self.logs = np.all(x > 0, axis=0)
        d = self._design(x)
        self.coef_t = np.linalg.lstsq(d, np.log(temps - tb), rcond=None)[0]
        self.coef_b = np.linalg.lstsq(d, beta, rcond=None)[0]
        self.beta_median = float(np.median(beta))

    def _design(self, x):
        cols = [np.ones(len(x))]
        for c, s, lg in zip(x.T, self.scale, self.logs, strict=True):
            cols.append(c / s)
            if lg:
                cols.append(np.log(np.maximum(c, 1e-300) / s))
        return np.column_stack(cols)

    def __call__(self, x, tb):
        d = self._design(x)
        beta = d @ self.coef_b
        return tb + np.exp(d @ self.coef_t), np.where(beta > 0, beta, self.beta_median)


def _from_predicted(power, rest, tb, r, t1, beta, out, cap):
    """Rows started at their predicted root ``t1``; the second point one model step from
    there with the predicted local beta. Rows that do not start cleanly go from their
    bracket."""
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


__all__ = ["MAX_EVALS", "Predictor", "fit_predictor", "root_balance"]
