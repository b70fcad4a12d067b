"""What a plan identifies: expected sds, detectable effect sizes, confounded directions.

For a plan with information ``M = sum_i n_i M_i`` (runs n_i of candidate i):

* the base parameters' expected covariance is ``M_bb^-1`` (the base model alone, as the
  loop fits it when no effect is accepted) [1];
* an effect k is told from its absence by the linearised T-criterion [2]: the smallest,
  over the nuisance (base) parameters, noise-normalised squared difference between the
  predictions with the effect at coefficient c and without it is
  ``c^2 S_k``, ``S_k = m_kk - m_kb^T M_bb^-1 m_kb`` (the residual of its column after
  the base columns, in the information metric). A two-sided test at level 5 % has
  power 80 % when that noncentrality reaches ``(z_0.975 + z_0.8)^2 = 7.85``: the smallest
  detectable coefficient is ``sqrt(7.85 / S_k)``;
* near-singular directions of ``M`` (condition index of the correlation-scaled matrix
  above :data:`CONDITION_INDEX`) are named by the parameters that load them, and pairs of
  parameters whose columns are nearly parallel (cosine above :data:`CONFOUNDED_COS`) are
  listed as confounded.

References
----------
.. [1] F. Pukelsheim, *Optimal Design of Experiments*, Wiley 1993, ch. 3.
.. [2] A. C. Atkinson, V. V. Fedorov, Biometrika 62:57-70, 1975 (T-optimality); its
   linearisation: D. Ucinski, B. Bogacka, J. R. Stat. Soc. B 67:3-18, 2005.
.. [3] B. Efron, C. Stein, "The jackknife estimate of variance", Ann. Stat. 9:586-596,
   1981 (the jackknife variance is biased upward).
.. [4] D. A. Belsley, E. Kuh, R. E. Welsch, *Regression Diagnostics*, Wiley 1980, ch. 3
   (condition indexes).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import stats

DETECT_LEVEL = 0.05
"""Level of the test that an effect is present [-]."""

DETECT_POWER = 0.80
"""Power at which an effect counts as detected [-]."""

SINGULAR_TOL = 1e-6
"""Eigenvalue of the correlation-scaled information below which a direction is not
identified [-] (a relative sd above 1000 times the parameters' own scale)."""

CONFOUNDED_COS = 0.99
"""``|cosine|`` between two parameters' Jacobian columns above which they are confounded."""

CONDITION_INDEX = 30.0
"""Condition index ``sqrt(lambda_max / lambda)`` of the correlation-scaled information above
which a direction is reported as confounded: Belsley, Kuh & Welsch's "strong" collinearity
[4] (the combination's variance inflated about 900-fold)."""


def noncentrality() -> float:
    """The noncentrality an effect must reach to be detected.

    Returns
    -------
    float
        ``(z_{1-level/2} + z_power)^2`` [-] (7.85 at 5 % and 80 %).
    """
    return (stats.norm.ppf(1 - DETECT_LEVEL / 2) + stats.norm.ppf(DETECT_POWER)) ** 2


def sandwich(A: np.ndarray, B: np.ndarray | None = None) -> np.ndarray | None:
    """Covariance of the least-squares estimate, ``A^-1 B A^-1`` [1].

    Parameters
    ----------
    A : array, shape (p, p)
        Information ``J^T J / sigma^2`` [unit^-2].
    B : array, shape (p, p), optional
        Noise meat ``J^T diag(v) J / sigma^4`` [unit^-2] (None: ``A^-1`` alone).

    Returns
    -------
    array or None
        Covariance [unit^2]; None if ``A`` is near-singular (:data:`SINGULAR_TOL` on its
        correlation scaling).
    """
    if not np.all(np.diag(A) > 0) or np.linalg.eigvalsh(_corr(A))[0] < SINGULAR_TOL:
        return None
    Ai = np.linalg.inv(A)
    return Ai if B is None else Ai @ B @ Ai


def base_sd(M: np.ndarray, q: int, B: np.ndarray | None = None) -> np.ndarray:
    """Expected sd of the q base parameters (the base model alone) [unit].

    Parameters
    ----------
    M : array, shape (p, p)
        Information of the plan (base parameters first).
    q : int
        Number of base parameters.
    B : array, shape (p, p), optional
        The noise "meat" of the least-squares sandwich (default: ``M``, white noise).

    Returns
    -------
    array
        sqrt of the diagonal of ``M_bb^-1 B_bb M_bb^-1`` over the base parameters with
        information; inf where not identified (all inf if they are confounded).
    """
    out = np.full(q, math.inf)
    ok = np.nonzero(np.diag(M[:q, :q]) > 0)[0]
    if not len(ok):
        return out
    cov = sandwich(M[np.ix_(ok, ok)], None if B is None else B[np.ix_(ok, ok)])
    if cov is not None:
        out[ok] = np.sqrt(np.diag(cov))
    return out


def _corr(M: np.ndarray) -> np.ndarray:
    d = np.sqrt(np.diag(M))
    d = np.where(d > 0, d, 1.0)
    return M / d[:, None] / d[None, :]


def jackknife_sd(As: np.ndarray, Bs: np.ndarray, folds: np.ndarray,
                 held: dict | None = None) -> np.ndarray:
    """Expected sd of the delete-a-group jackknife the loop reports, linearised [3].

    With ``u_j`` the score of fold j (covariance ``B_j``) the all-data estimate moves by
    ``A^-1 sum u``, the estimate without fold i by ``d_i = (A - A_i)^-1 sum_{j != i} u_j``
    (over the parameters that fold fits); the jackknife variance ``(g - 1)/g sum_i (d_i -
    mean d)^2`` has the expectation ``(g - 1)/g sum_i sum_j (K_ij - Kbar_j) B_j (K_ij -
    Kbar_j)^T`` with ``K_ij = (A - A_i)^-1`` (0 for j = i). Unlike ``A^-1 B A^-1`` it grows
    when the folds differ in leverage: the jackknife is conservative there [3]. A fold that
    holds a parameter (the loop's rule: its training runs cannot identify it) fits the
    others with it fixed and is left out of that parameter's jackknife, as in the loop.

    Parameters
    ----------
    As, Bs : arrays, shape (m, q, q)
        Information and noise meat of each run (base parameters only) [unit^-2].
    folds : array of int, shape (m,)
        Fold of each run (the loop's: the run itself up to 10 runs) [-].
    held : dict, optional
        Fold code -> indices of the parameters that fold holds [-].

    Returns
    -------
    array, shape (q,)
        sqrt of the expected jackknife variance [unit of each parameter]; inf with fewer
        than 3 usable folds.
    """
    held = held or {}
    codes = np.unique(folds)
    Af = np.array([As[folds == c].sum(axis=0) for c in codes])
    Bf = np.array([Bs[folds == c].sum(axis=0) for c in codes])
    A = Af.sum(axis=0)
    q = A.shape[0]
    K, used = [], []
    for i, c in enumerate(codes):
        free = [k for k in range(q) if k not in held.get(c, ())]
        cov = sandwich((A - Af[i])[np.ix_(free, free)])
        Ci = np.zeros((len(codes), q, q))
        if cov is None:
            continue
        Ci[:, np.ix_(free, free)[0], np.ix_(free, free)[1]] = cov
        Ci[i] = 0.0
        K.append(Ci)
        used.append(set(free))
    out = np.full(q, math.inf)
    for k in range(q):
        rows = [a for a, f in enumerate(used) if k in f]
        g = len(rows)
        if g < 3:
            continue
        Kk = np.array([K[a][:, k, :] for a in rows])  # (g, folds, q): row k of each K_ij
        D = Kk - Kk.mean(axis=0)
        var = np.einsum("ajb,jbc,ajc->", D, Bf, D)
        out[k] = math.sqrt(var * (g - 1) / g)
    return out


def detectable_sizes(M: np.ndarray, q: int, B: np.ndarray | None = None
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Smallest detectable coefficient of each effect (base parameters as nuisance).

    Parameters
    ----------
    M : array, shape (p, p)
        Information of the plan; the first q parameters are the base law's, the next
        ones effects.
    q : int
        Number of base parameters.
    B : array, shape (p, p), optional
        The noise "meat" (default ``M``): with it the effect's variance is the sandwich's
        of the fit of (base, effect), and the size ``sqrt(7.85 var_k)``.

    Returns
    -------
    (size, r2) : arrays, one per non-base parameter
        ``sqrt(7.85 / S_k)`` [unit of the coefficient] (inf when ``S_k`` = 0), and the
        share of the column the base parameters explain, ``1 - S_k / m_kk`` [-].
    """
    p = M.shape[0]
    lam0 = noncentrality()
    size, r2 = np.full(p - q, math.inf), np.ones(p - q)
    Mb = M[:q, :q]
    inv = np.linalg.pinv(Mb) if q else np.zeros((0, 0))
    for k in range(q, p):
        mkk = M[k, k]
        if not mkk > 0:
            continue
        S = mkk - M[:q, k] @ inv @ M[:q, k] if q else mkk
        share = 1.0 - S / mkk
        r2[k - q] = min(1.0, max(0.0, share))
        if S > SINGULAR_TOL * mkk:
            size[k - q] = math.sqrt(lam0 / S)
            if B is not None:
                idx = [*range(q), k]
                cov = sandwich(M[np.ix_(idx, idx)], B[np.ix_(idx, idx)])
                size[k - q] = math.inf if cov is None else math.sqrt(lam0 * cov[-1, -1])
    return size, r2


def confounding(M: np.ndarray, names: tuple[str, ...]) -> dict:
    """Confounded pairs, unidentified parameters and near-singular directions of ``M``.

    Parameters
    ----------
    M : array, shape (p, p)
        Information of the plan [unit^-2].
    names : tuple of str
        Parameter names [-].

    Returns
    -------
    dict
        ``uninformed``: parameters with zero information (their column vanishes on every
        run); ``pairs``: (a, b, cosine) with ``|cosine|`` > :data:`CONFOUNDED_COS`;
        ``directions``: per eigenvalue of the correlation-scaled matrix whose condition
        index exceeds :data:`CONDITION_INDEX`, the eigenvalue [-], the condition index
        [-] and the loadings above 0.3 [-].
    """
    d = np.diag(M)
    uninformed = [n for n, v in zip(names, d, strict=True) if not v > 0]
    keep = [i for i, n in enumerate(names) if n not in uninformed]
    C = _corr(M[np.ix_(keep, keep)])
    pairs = []
    for a in range(len(keep)):
        for b in range(a + 1, len(keep)):
            if abs(C[a, b]) > CONFOUNDED_COS:
                pairs.append((names[keep[a]], names[keep[b]], float(C[a, b])))
    directions = []
    if keep:
        lam, vec = np.linalg.eigh(C)
        lam = np.maximum(lam, 0.0)
        for j in np.nonzero(lam * CONDITION_INDEX ** 2 < lam[-1])[0]:
            load = {names[keep[i]]: float(vec[i, j]) for i in np.argsort(-np.abs(vec[:, j]))
                    if abs(vec[i, j]) > 0.3}
            ci = math.sqrt(lam[-1] / lam[j]) if lam[j] > 0 else math.inf
            directions.append({"eigenvalue": float(lam[j]), "condition_index": ci,
                               "loadings": load})
    return {"uninformed": uninformed, "pairs": pairs, "directions": directions}
