"""Optimal designs over candidate runs: the convex relaxation, its gap, and rounding.

A design puts weight ``w_i >= 0`` (sum 1) on candidate run i; its information is
``M(w) = sum_i w_i M_i``. The continuous problem is convex [1]:

* D-optimal: maximise ``log det M(w)``;
* A-optimal: minimise ``tr M(w)^-1``;
* E-optimal: maximise ``lambda_min M(w)``;
* T-optimal (linearised model discrimination): maximise the smallest, over the effects
  k, of ``S_k(w) / s_k`` with ``S_k = m_kk - m_kb^T M_bb^-1 m_kb`` the information on
  effect k left after the nuisance (base) parameters are fitted, written as the LMI
  ``[[M_bb, m_kb], [m_kb^T, m_kk - t s_k]] >= 0`` (Schur complement) [1], [3].

Its optimality gap follows from the general equivalence theorem (Kiefer-Wolfowitz) [2]:
for D, ``log det M* - log det M(w) <= max_i tr(M^-1 M_i) - p``, so the D-efficiency is at
least ``p / max_i tr(M^-1 M_i)``; for A, ``max_i tr(M^-2 M_i) - tr M^-1`` bounds
``tr M^-1 - tr M*^-1``. A design is rounded to whole runs by efficient rounding [4].

References
----------
.. [1] S. Boyd, L. Vandenberghe, *Convex Optimization*, Cambridge 2004, sec. 7.5.
.. [2] J. Kiefer, J. Wolfowitz, "The equivalence of two extremum problems", Canad. J.
   Math. 12:363-366, 1960; Pukelsheim, *Optimal Design of Experiments*, 1993, ch. 7.
.. [3] A. C. Atkinson, V. V. Fedorov, "The design of experiments for discriminating
   between two rival models", Biometrika 62:57-70, 1975 (T-optimality).
.. [4] F. Pukelsheim, S. Rieder, "Efficient rounding of approximate designs",
   Biometrika 79:763-770, 1992.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import cvxpy as cp
import numpy as np
from scipy.optimize import linprog

from oilgap.model.errors import InputError, SolverError

CRITERIA = ("D", "A", "E", "T")
"""Design criteria offered."""

SUPPORT_TOL = 1e-4
"""Weights below this share of the largest are taken as zero (solver round-off)."""


@dataclass(frozen=True)
class ContinuousDesign:
    """A continuous design and its certificate.

    Attributes
    ----------
    weights : array
        Weight of each candidate [-] (sum 1).
    criterion : str
        D, A, E or T.
    gap : float
        Bound on the criterion's distance to the optimum from the equivalence theorem
        (D: in log det; A: in tr M^-1; E, T: the solver's duality gap) [-].
    efficiency : float
        Lower bound on the efficiency relative to the optimum [-] (D: p / max d_i).
    status : str
        The solver's status.
    """

    weights: np.ndarray
    criterion: str
    gap: float
    efficiency: float
    status: str


def _solve(problem: cp.Problem) -> str:
    for solver in ("CLARABEL", "SCS"):
        try:
            problem.solve(solver=solver)
        except (cp.error.SolverError, ValueError):
            continue
        if problem.status in ("optimal", "optimal_inaccurate"):
            return problem.status
    raise SolverError(f"the design problem was not solved (status {problem.status})")


def normalise(Ms: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Information matrices scaled to unit mean diagonal (a D-optimal design is invariant;
    A and E are then taken over the standardised parameters).

    Parameters
    ----------
    Ms : array, shape (m, p, p)
        Information of each candidate [unit^-2].

    Returns
    -------
    (Ms, d)
        ``D M_i D`` [-] with ``D = diag(d)``, ``d = 1/sqrt(mean_i diag M_i)`` [unit].
    """
    diag = np.mean(np.diagonal(Ms, axis1=1, axis2=2), axis=0)
    d = 1.0 / np.sqrt(np.where(diag > 0, diag, 1.0))
    return Ms * d[None, :, None] * d[None, None, :], d


def optimal_weights(Ms: np.ndarray, criterion: str = "D", nuisance: int = 0,
                    effect_scale: np.ndarray | None = None) -> ContinuousDesign:
    """Continuous optimal design over candidates with information ``Ms`` [1].

    Parameters
    ----------
    Ms : array, shape (m, p, p)
        Information of one run of each candidate [unit^-2]; the pooled matrix must be
        nonsingular (D, A, E).
    criterion : {"D", "A", "E", "T"}
        Design criterion.
    nuisance : int
        T only: the first ``nuisance`` parameters are nuisance (the base law); the rest
        are the effects to discriminate.
    effect_scale : array, optional
        T only: s_k, the information each effect needs (1/size^2 of interest, in the
        units of ``Ms``) [unit^-2].

    Returns
    -------
    ContinuousDesign
    """
    if criterion not in CRITERIA:
        raise InputError("criterion", criterion, f"allowed: {', '.join(CRITERIA)}", "plan")
    Ms, d = normalise(np.asarray(Ms, float))
    m, p, _ = Ms.shape
    if effect_scale is not None:  # s_k in the normalised parameters
        effect_scale = np.asarray(effect_scale, float) * d[nuisance:] ** 2
    w = cp.Variable(m, nonneg=True)
    M = sum(w[i] * Ms[i] for i in range(m))
    M = (M + M.T) / 2
    cons = [cp.sum(w) == 1]
    if criterion == "D":
        obj = cp.Maximize(cp.log_det(M))
    elif criterion == "A":
        obj = cp.Minimize(cp.tr_inv(M))
    elif criterion == "E":
        obj = cp.Maximize(cp.lambda_min(M))
    else:
        t = cp.Variable()
        b = nuisance
        sc = np.ones(p - b) if effect_scale is None else effect_scale / np.mean(effect_scale)
        for k in range(b, p):
            idx = list(range(b)) + [k]
            sub = M[idx][:, idx]
            e = np.zeros((b + 1, b + 1))
            e[b, b] = sc[k - b]
            cons.append(sub - t * e >> 0)
        obj = cp.Maximize(t)
    prob = cp.Problem(obj, cons)
    status = _solve(prob)
    wv = np.clip(np.asarray(w.value, float), 0.0, None)
    wv[wv < SUPPORT_TOL * wv.max()] = 0.0
    wv /= wv.sum()
    gap, eff = equivalence_gap(Ms, wv, criterion, nuisance, effect_scale)
    return ContinuousDesign(weights=wv, criterion=criterion, gap=gap, efficiency=eff,
                            status=status)


def equivalence_gap(Ms: np.ndarray, w: np.ndarray, criterion: str = "D", nuisance: int = 0,
                    effect_scale: np.ndarray | None = None) -> tuple[float, float]:
    """Optimality gap of design ``w`` from the general equivalence theorem [2].

    Parameters
    ----------
    Ms : array, shape (m, p, p)
        Candidate information matrices.
    w : array, shape (m,)
        Weights (sum 1) or run counts (normalised here).
    criterion : str
        D gives ``max_i tr(M^-1 M_i) - p`` (a bound on the log det lost) and the
        efficiency bound ``p / max_i tr(M^-1 M_i)``; A gives ``max_i tr(M^-2 M_i) -
        tr M^-1`` and ``tr M^-1 / max_i tr(M^-2 M_i)``; E gives ``max_i v^T M_i v -
        lambda_min`` (v its eigenvector: a supergradient of the concave lambda_min) and
        ``lambda_min / (lambda_min + gap)``; T the same with the hull of the active
        effects' supergradients ``a^T M_i a``, ``a = (-M_bb^-1 m_kb, 1)``.
    nuisance, effect_scale : int, array
        T only, as in :func:`optimal_weights`.

    Returns
    -------
    (gap, efficiency) : floats [-]
    """
    w = np.asarray(w, float) / np.sum(w)
    M = np.einsum("i,ijk->jk", w, Ms)
    p = M.shape[0]
    try:
        Minv = np.linalg.inv(M)
    except np.linalg.LinAlgError:
        return math.inf, 0.0
    if criterion == "D":
        d = np.einsum("jk,ikj->i", Minv, Ms)
        return float(d.max() - p), float(p / d.max())
    if criterion == "A":
        M2 = Minv @ Minv
        d = np.einsum("jk,ikj->i", M2, Ms)
        return float(d.max() - np.trace(Minv)), float(np.trace(Minv) / d.max())
    if criterion == "E":
        lam, vec = np.linalg.eigh(M)
        a, value = vec[:, 0], lam[0]
        d = np.einsum("j,ijk,k->i", a, Ms, a)
        gap = float(max(d.max() - value, 0.0))
    else:
        value, gap = _t_gap(Ms, M, nuisance, effect_scale)
    return gap, float(value / (value + gap)) if value > 0 else 0.0


ACTIVE_TOL = 1e-3
"""Relative distance to the smallest S_k / s_k within which an effect is active (T)."""


def _t_gap(Ms: np.ndarray, M: np.ndarray, b: int, effect_scale) -> tuple[float, float]:
    """The T criterion at M and its gap: ``min over lambda in the simplex of the active
    effects of max_i sum_k lambda_k a_k^T M_i a_k / s_k - value`` (the superdifferential
    of a minimum of concave functions is the hull of the active ones' gradients), an LP."""
    p = M.shape[0]
    sc = np.ones(p - b) if effect_scale is None else np.asarray(effect_scale, float)
    sc = sc / np.mean(sc)
    vals, grads = [], []
    for k in range(b, p):
        a = np.zeros(p)
        a[k] = 1.0
        if b:
            a[:b] = -np.linalg.solve(M[:b, :b], M[:b, k])
        vals.append(float(a @ M @ a) / sc[k - b])
        grads.append(np.einsum("j,ijk,k->i", a, Ms, a) / sc[k - b])
    vals = np.array(vals)
    value = float(vals.min())
    act = np.nonzero(vals <= value * (1 + ACTIVE_TOL))[0]
    G = np.array(grads)[act]  # (active, m)
    n = len(act)
    res = linprog(np.r_[np.zeros(n), 1.0], A_ub=np.c_[G.T, -np.ones(G.shape[1])],
                  b_ub=np.zeros(G.shape[1]), A_eq=np.r_[np.ones(n), 0.0][None, :], b_eq=[1.0],
                  bounds=[(0, None)] * n + [(None, None)], method="highs")
    best = float(res.fun) if res.success else float(G.max(axis=1).min())
    return value, max(best - value, 0.0)


def efficient_rounding(w: np.ndarray, n: int) -> np.ndarray:
    """Whole runs from a continuous design by efficient rounding [4].

    ``n_i = ceil((n - l/2) w_i)`` on the l support points, then a run is added where
    ``n_i / w_i`` is smallest (or taken where ``(n_i - 1)/w_i`` is largest) until the
    sum is ``n``. With fewer runs than support points, the ``n`` largest weights are
    kept first.

    Parameters
    ----------
    w : array
        Weights [-] (sum 1).
    n : int
        Number of runs (>= 1).

    Returns
    -------
    array of int
        Runs of each candidate (sum n).
    """
    if n < 1:
        raise InputError("runs", n, "at least one run", "plan")
    w = np.asarray(w, float).copy()
    support = np.nonzero(w > 0)[0]
    if len(support) > n:
        keep = support[np.argsort(-w[support], kind="stable")[:n]]
        w2 = np.zeros_like(w)
        w2[keep] = w[keep]
        w = w2 / w2.sum()
        support = np.sort(keep)
    ell = len(support)
    counts = np.zeros(len(w), dtype=int)
    counts[support] = np.ceil((n - ell / 2.0) * w[support]).astype(int)
    while counts.sum() < n:
        j = support[np.argmin(counts[support] / w[support])]
        counts[j] += 1
    while counts.sum() > n:
        j = support[np.argmax((counts[support] - 1) / w[support])]
        counts[j] -= 1
    return counts
