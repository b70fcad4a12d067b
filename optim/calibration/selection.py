"""Stage 5b of the calibration: sparse selection of the missing effect.

The problem is linearised at the calibration: the residual ``r`` is regressed
on the calibration's Jacobian (free, unpenalised) and the candidate columns
(:mod:`oilgap.optim.calibration.candidates`), each scaled to unit RMS. The
sign-constrained lasso path [1] ranks the effects; cross-validation on per-fold Gram matrices
(folds of
whole runs, :mod:`.folds`: one per run up to 10 runs, grouped 10-fold above)
judges supports exactly and fast (:class:`LeaveOneRunOutSelector`,
inner problems by :func:`box_lstsq` [3]). Forward selection adds the effect
that lowers the held-out RMSE most while each addition lowers it by the margin;
backward pruning then drops any effect that no longer brings the margin in the
final set; the set kept must together explain at least ``min_explained`` of
the held-out structure above the noise, or nothing is accepted
(:func:`stepwise_selection`). Folds are the cross-validation groups (the runs
unless the data say otherwise); a base parameter a fold cannot identify is held
at its prior there (its linearised coefficient held at the step from the all-data
value to the prior), never at the all-data value, which has seen the held-out fold.

References
----------
.. [1] R. Tibshirani, "Regression shrinkage and selection via the lasso",
   J. R. Stat. Soc. B 58:267-288, 1996; relaxed lasso: N. Meinshausen,
   Comput. Stat. Data Anal. 52:374-393, 2007.
.. [2] M. Stone, "Cross-validatory choice and assessment of statistical
   predictions", J. R. Stat. Soc. B 36:111-147, 1974.
.. [3] P. B. Stark, R. L. Parker, "Bounded-variable least-squares: an algorithm
   and applications", Comput. Stat. 10:129-141, 1995.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import cvxpy as cp
import numpy as np
from scipy.linalg import solve_triangular
from scipy.optimize import lsq_linear

from oilgap.model.errors import SolverError

from .candidates import Candidates
from .steps import SelectionStep

CLARABEL_SETTINGS = {"tol_gap_abs": 1e-8, "tol_gap_rel": 1e-8, "tol_feas": 1e-8,
                     "max_iter": 200, "direct_solve_method": "qdldl"}
"""Clarabel's settings, named rather than left to the installed version's defaults (these
are Clarabel 0.11's), with its single-threaded direct solver: the same data give the same
lasso path whatever the version's defaults and the core count (issue 18)."""


class SignConstrainedLasso:
    """Sign-constrained lasso ``min ||A x - b||^2 + pen * |x|, lo <= x <= hi`` (cvxpy) [1].

    A and the data are fixed; ``pen`` (the penalty weights, zero on the
    calibration's own columns) is a parameter, so the path re-solves without
    recompiling. ``|x|`` is written with an epigraph variable t >= ``|x|``.

    Parameters
    ----------
    A : array, shape (m, p)
    b : array, shape (m,)
    lo, hi : arrays, shape (p,)
        Bounds of x (infinite bounds are clipped at +-1e6).
    """

    def __init__(self, A: np.ndarray, b: np.ndarray, lo: np.ndarray, hi: np.ndarray):
        p = A.shape[1]
        self.pen = cp.Parameter(p, nonneg=True)
        self.x = cp.Variable(p)
        t = cp.Variable(p)
        big = 1e6
        cons = [self.x >= np.clip(lo, -big, big), self.x <= np.clip(hi, -big, big),
                t >= self.x, t >= -self.x]
        self.prob = cp.Problem(cp.Minimize(cp.sum_squares(A @ self.x - b) + self.pen @ t), cons)

    def solve(self, pen: np.ndarray) -> np.ndarray:
        """Minimiser at penalty weights ``pen`` (Clarabel, SCS as fallback).

        Parameters
        ----------
        pen : array, shape (p,)
            Penalty weight of each ``|x_j|`` (>= 0).

        Returns
        -------
        array
            x.

        Raises
        ------
        SolverError
            Neither solver reaches an optimal status.
        """
        self.pen.value = pen
        try:
            self.prob.solve(solver=cp.CLARABEL, **CLARABEL_SETTINGS)
        except cp.error.SolverError:
            self.prob.solve(solver=cp.SCS, eps=1e-9, max_iters=100000)
        if self.x.value is None or self.prob.status not in ("optimal", "optimal_inaccurate"):
            raise SolverError(f"sparse regression: cvxpy status {self.prob.status}")
        return np.asarray(self.x.value)


def box_lstsq(G: np.ndarray, h: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """``min x'Gx - 2h'x`` on the box [lo, hi] (entries fixed where lo = hi).

    Unconstrained solve on the free entries first (with a ridge of 1e-10 of
    the mean diagonal); if a bound is violated, the bounded-variable least
    squares of Stark & Parker [3] (``scipy lsq_linear``, method "bvls") on the
    Cholesky factor. Exact for this convex problem.

    Parameters
    ----------
    G : array, shape (p, p)
        Gram matrix (symmetric positive semi-definite).
    h : array, shape (p,)
    lo, hi : arrays, shape (p,)
        Bounds (-inf/inf allowed).

    Returns
    -------
    array
        The minimiser x.
    """
    p = len(h)
    x = np.zeros(p)
    fixed = lo == hi
    x[fixed] = lo[fixed]
    f = ~fixed
    if not f.any():
        return x
    Gf = G[np.ix_(f, f)]
    ridge = 1e-10 * max(1.0, float(np.trace(Gf)) / f.sum())
    Gf = Gf + ridge * np.eye(f.sum())
    hf = h[f] - G[np.ix_(f, fixed)] @ x[fixed]
    xf = np.linalg.solve(Gf, hf)
    lf, uf = lo[f], hi[f]
    if np.all(xf >= lf - 1e-12) and np.all(xf <= uf + 1e-12):
        x[f] = xf
        return x
    L = np.linalg.cholesky(Gf)
    b = solve_triangular(L, hf, lower=True)
    res = lsq_linear(L.T, b, bounds=(lf, uf), method="bvls", tol=1e-12)
    x[f] = res.x
    return x


class LeaveOneRunOutSelector:
    """Linearised sparse selection with leave-one-run-out CV on Gram matrices [2].

    Columns: the calibration's Jacobian (free, unpenalised), then the
    candidate columns, each scaled to unit RMS. Each candidate column belongs
    to one effect (``group``); a support holds at most one column per effect.

    Parameters
    ----------
    J : array, shape (n, q)
        Jacobian of the calibration [W per unit parameter].
    F : array, shape (n, k)
        Candidate columns [W per unit coefficient].
    r : array, shape (n,)
        Residual of the calibration [W].
    run_code : array of int, shape (n,)
        Cross-validation group of each sample (the run by default).
    nonneg : array of bool, shape (k,)
        Column j's coefficient must be >= 0.
    group : array of int, shape (k,)
        Effect of each column.
    hold : dict, optional
        Fold (group code) -> calibration columns held in that fold (the parameters
        its training data cannot identify): a tuple of column indices (held at zero,
        the all-data value) or a dict index -> step held [solver unit] (to the prior).
    """

    def __init__(self, J: np.ndarray, F: np.ndarray, r: np.ndarray, run_code: np.ndarray,
                 nonneg: np.ndarray, group: np.ndarray, hold: dict | None = None):
        self.q = J.shape[1]
        X = np.column_stack([J, F])
        sc = np.sqrt(np.einsum("ij,ij->j", X, X) / max(1, len(X)))  # RMS, no n x p temporary
        self.scale = np.where(sc > 0, sc, 1.0)
        X /= self.scale
        self.k = F.shape[1]
        self.nonneg = np.asarray(nonneg, bool)
        self.group = np.asarray(group)
        self.runs = np.unique(run_code)
        self.hold = {int(c): dict(v) if isinstance(v, dict) else dict.fromkeys(v, 0.0)
                     for c, v in (hold or {}).items()}
        self.G, self.h, self.s, self.n = {}, {}, {}, {}
        code = np.asarray(run_code)
        if np.all(code[1:] >= code[:-1]):  # groups contiguous (runs): slices, no copies
            lo, hi = np.searchsorted(code, self.runs), np.searchsorted(code, self.runs, "right")
            part = {c: slice(a, b) for c, a, b in zip(self.runs, lo, hi, strict=True)}
        else:
            part = {c: code == c for c in self.runs}
        for c in self.runs:
            Xc, rc = X[part[c]], r[part[c]]
            self.G[c] = Xc.T @ Xc
            self.h[c] = Xc.T @ rc
            self.s[c] = float(rc @ rc)
            self.n[c] = len(rc)
        self.Gt = sum(self.G.values())
        self.ht = sum(self.h.values())
        self.nt = sum(self.n.values())
        self._cache: dict = {}

    def _bounds(self, support) -> tuple[np.ndarray, np.ndarray]:
        p = self.q + self.k
        lo = np.full(p, -np.inf)
        hi = np.full(p, np.inf)
        for j in range(self.k):
            if j not in support:
                lo[self.q + j] = hi[self.q + j] = 0.0
            elif self.nonneg[j]:
                lo[self.q + j] = 0.0
        return lo, hi

    def cv(self, support) -> float:
        """Pooled held-out RMSE [W] of calibration + support, leaving one fold out at a time.

        Parameters
        ----------
        support : iterable of int
            Candidate columns in the model.

        Returns
        -------
        float
            ``sqrt(sum over folds of the held-out squared error / n)`` [W] (cached).
        """
        key = frozenset(support)
        if key not in self._cache:
            lo, hi = self._bounds(key)
            sse = 0.0
            for c in self.runs:
                ntr = self.nt - self.n[c]
                lo_c, hi_c = lo, hi
                if self.hold.get(int(c)):
                    lo_c, hi_c = lo.copy(), hi.copy()
                    for i, step in self.hold[int(c)].items():
                        lo_c[i] = hi_c[i] = step * self.scale[i]
                x = box_lstsq((self.Gt - self.G[c]) / ntr, (self.ht - self.h[c]) / ntr, lo_c,
                              hi_c)
                sse += max(0.0, self.s[c] - 2 * x @ self.h[c] + x @ self.G[c] @ x)
            self._cache[key] = math.sqrt(sse / self.nt)
        return self._cache[key]

    def coef(self, support) -> np.ndarray:
        """Full-data coefficients of the candidate columns [unit per column].

        Parameters
        ----------
        support : iterable of int
            Candidate columns in the model.

        Returns
        -------
        array, shape (k,)
            Coefficients in the columns' natural units (zero off the support).
        """
        lo, hi = self._bounds(frozenset(support))
        x = box_lstsq(self.Gt / self.nt, self.ht / self.nt, lo, hi)
        return (x / self.scale)[self.q:]

    def lasso_path(self, n_lambda: int = 12) -> list[tuple[float, tuple[int, ...]]]:
        """Supports along the sign-constrained lasso path [1].

        Parameters
        ----------
        n_lambda : int
            Number of penalties, log-spaced from lambda_max down to 1e-3 lambda_max.

        Returns
        -------
        list of (float, tuple of int)
            lambda / lambda_max [-] and the candidate columns with a coefficient
            above 1e-4 of the residual's RMS [W] (the columns have unit RMS).
        """
        rms = math.sqrt(sum(self.s.values()) / self.nt)
        if self.k == 0 or not rms > 0:
            return []
        G = self.Gt / self.nt
        h = self.ht / self.nt / rms  # the residual at unit RMS: same supports, any scale
        lo0, hi0 = self._bounds(frozenset())
        x0 = box_lstsq(G, h, lo0, hi0)
        grad = 2 * (h - G @ x0)[self.q:]
        g = np.where(self.nonneg, np.maximum(grad, 0.0), np.abs(grad))
        lam_max = float(g.max())
        if lam_max <= 0:
            return []
        p = self.q + self.k
        L = np.linalg.cholesky(G + 1e-10 * max(1.0, float(np.trace(G)) / p) * np.eye(p))
        lo, hi = self._bounds(frozenset(range(self.k)))
        lasso = SignConstrainedLasso(L.T, solve_triangular(L, h, lower=True), lo, hi)
        path = []
        tol = 1e-4
        for lam in lam_max * np.logspace(0, -3, n_lambda):
            x = lasso.solve(np.concatenate([np.zeros(self.q), np.full(self.k, lam)]))
            sup = tuple(int(j) for j in np.nonzero(np.abs(x[self.q:]) > tol)[0])
            path.append((float(lam / lam_max), sup))
        return path


def _explained(e_before: float, e_after: float, noise_W: float) -> float:
    """Share of the held-out structure above the noise that a step removes [-]."""
    st = e_before * e_before - noise_W * noise_W
    return (e_before ** 2 - e_after ** 2) / st if st > 0 else 0.0


@dataclass(frozen=True, kw_only=True)
class Thresholds:
    """The acceptance thresholds of the effect selection.

    Attributes
    ----------
    noise_W : float
        Noise level of the power reading [W].
    margin : float
        Relative fall of the held-out RMSE each effect must bring [-].
    min_explained : float
        Share of the held-out structure above noise the effects must explain [-].
    max_effects : int
        Most effects accepted together.
    """

    noise_W: float
    margin: float
    min_explained: float
    max_effects: int


@dataclass
class StepwiseResult:
    """Outcome of forward selection and backward pruning.

    Attributes
    ----------
    chosen : tuple of int
        Candidate columns kept.
    log : list of SelectionStep
        One record per forward step (held-out RMSE [W], gain [%], share of the
        current and of the initial structure explained [-], accepted, and the
        rule that rejected it), per pruned column, and the structure check.
    """

    chosen: tuple[int, ...]
    log: list[SelectionStep]


def _prune(sel: LeaveOneRunOutSelector, cands: Candidates, chosen: tuple[int, ...],
           margin: float, log: list[SelectionStep]) -> tuple[int, ...]:
    """Backward pruning: drop a column that no longer brings the margin in the set."""
    changed = True
    while changed and len(chosen) > 1:
        changed = False
        for j in chosen:
            rest = tuple(i for i in chosen if i != j)
            if sel.cv(rest) * (1 - margin) < sel.cv(chosen):
                chosen = rest
                changed = True
                log.append(SelectionStep(step="prune", dropped=cands.label(j)))
                break
    return chosen


def _best_pair(sel: LeaveOneRunOutSelector, cands: Candidates, chosen: tuple[int, ...],
               trials: dict[int, float], e_cur: float, margin: float
               ) -> tuple[int, int] | None:
    """Two columns of two new effects that bring the margin together when neither does alone.

    The pair with the lowest held-out RMSE among the columns of ``trials``; it is
    returned only if it lowers the held-out RMSE by ``margin`` and each of its
    two columns brings the margin against the other alone (each is needed).
    """
    name = cands.name
    cols = sorted(trials)
    best, e_best = None, np.inf
    for a in range(len(cols)):
        for b in range(a + 1, len(cols)):
            i, j = cols[a], cols[b]
            if name[i] != name[j]:
                e = sel.cv(chosen + (i, j))
                if e < e_best:
                    best, e_best = (i, j), e
    if best is None or e_best > e_cur * (1.0 - margin):
        return None
    i, j = best
    if e_best > min(trials[i], trials[j]) * (1.0 - margin):
        return None
    return best


def stepwise_selection(sel: LeaveOneRunOutSelector, cands: Candidates, e0: float,
                       entry: dict[str, float], limits: Thresholds,
                       exclude: frozenset[str] | set[str] = frozenset()) -> StepwiseResult:
    """Forward selection on the held-out RMSE, backward pruning, then the structure check.

    Each step adds the column (of an effect not yet in and not excluded) with
    the lowest held-out RMSE; near-ties (0.1 %) go to the effect the lasso path
    takes in first. The step is accepted if it lowers the held-out RMSE by
    ``margin``; if no single column does, the best pair of two new effects is
    taken instead when it brings the margin and each of the two brings it
    against the other (two effects can cancel in the calibration's fit so that
    neither shows alone). Selection goes on while steps are accepted, up to
    ``max_effects``. Then each chosen column must still bring the margin in the
    final set, or it is dropped. Last, the set kept must together explain
    ``min_explained`` of the held-out structure above the noise (measured from
    the calibration alone, so that two or three effects of similar size, none
    of which explains half alone, are all found); otherwise nothing is accepted.

    Parameters
    ----------
    sel : LeaveOneRunOutSelector
    cands : Candidates
    e0 : float
        Held-out RMSE of the calibration alone [W].
    entry : dict
        Effect -> lambda / lambda_max at which it enters the lasso path [-].
    limits : Thresholds
        Noise level [W], required relative fall of the held-out RMSE per step and
        explained share of the set [-], most effects accepted together.
    exclude : set of str
        Effects not to select (implausible, or not applicable to these data).

    Returns
    -------
    StepwiseResult
    """
    noise_W, margin = limits.noise_W, limits.margin
    min_explained, max_effects = limits.min_explained, limits.max_effects
    name = cands.name
    chosen: tuple[int, ...] = ()
    e_cur = e0
    log: list[SelectionStep] = []
    n_max = min(max_effects, len(set(cands.usable) - set(exclude)))
    while len({name[j] for j in chosen}) < n_max:
        taken = {name[j] for j in chosen}
        trials = {j: sel.cv(chosen + (j,)) for j in range(len(name))
                  if name[j] not in taken and name[j] not in exclude}
        best = min(trials, key=lambda j: (round(trials[j] / e_cur, 3), -entry.get(name[j], 0.0)))
        add, e_new = (best,), trials[best]
        ok = 1.0 - e_new / e_cur >= margin
        if not ok and n_max - len(taken) >= 2:  # look ahead: two effects only found together
            pair = _best_pair(sel, cands, chosen, trials, e_cur, margin)
            if pair is not None:
                add, e_new, ok = pair, sel.cv(chosen + pair), True
        gain = 1.0 - e_new / e_cur
        log.append(SelectionStep(
            step=len(chosen) + 1, best=" + ".join(cands.label(j) for j in add),
            heldout_rmse_W=e_new, gain_pct=100 * gain,
            explained_structure=_explained(e_cur, e_new, noise_W),
            explained_total=_explained(e0, e_new, noise_W), accepted=bool(ok),
            rejected_by=None if ok else "margin"))
        if not ok:
            break
        chosen = chosen + add
        e_cur = e_new
    chosen = _prune(sel, cands, chosen, margin, log)
    if chosen:
        total = _explained(e0, sel.cv(chosen), noise_W)
        ok = total >= min_explained
        log.append(SelectionStep(step="structure", effects=[cands.label(j) for j in chosen],
                                 explained_total=total, accepted=bool(ok),
                                 rejected_by=None if ok else "structure"))
        if not ok:
            chosen = ()
    return StepwiseResult(chosen, log)


def score_alone(cands: Candidates, sel: LeaveOneRunOutSelector, e0: float, noise_W: float,
                entry: dict[str, float]) -> list[dict]:
    """Screening records with each candidate's held-out score alone.

    Parameters
    ----------
    cands : Candidates
    sel : LeaveOneRunOutSelector
    e0 : float
        Held-out RMSE of the calibration alone [W].
    noise_W : float
        Noise level [W].
    entry : dict
        Effect -> lambda / lambda_max of its lasso entry [-].

    Returns
    -------
    list of dict
        :attr:`Candidates.info` with, for each candidate, its best column's
        held-out RMSE [W], gain [%], explained share [-], column and lasso entry.
    """
    out = []
    st0 = e0 * e0 - noise_W * noise_W
    for info in cands.info:
        if info["status"] == "candidate":
            best = min(cands.columns_of(info["name"]), key=lambda j: sel.cv((j,)))
            e1 = sel.cv((best,))
            info = {**info, "heldout_rmse_alone_W": e1,
                    "heldout_gain_alone_pct": 100.0 * (1.0 - e1 / e0),
                    "explained_structure_alone": (e0 * e0 - e1 ** 2) / st0 if st0 > 0 else 0.0,
                    "best_column": cands.label(best),
                    "lasso_entry_lambda_rel": entry.get(info["name"])}
        out.append(info)
    return out


@dataclass
class Selection:
    """The effect search's outcome.

    Attributes
    ----------
    selector : LeaveOneRunOutSelector
    heldout_before_W : float
        Held-out RMSE of the calibration alone (linearised) [W].
    lasso_entry : dict
        Effect -> lambda / lambda_max at which it enters the path [-].
    lasso_path : list of dict
        ``lambda_rel`` [-] and ``support`` (effect names) along the path.
    candidates : list of dict
        Screening records with the held-out scores alone.
    chosen : tuple of int
        Columns selected.
    log : list of SelectionStep
        Forward and pruning steps, and the structure check.
    exclude : frozenset of str
        Effects that were not selectable.
    """

    selector: LeaveOneRunOutSelector
    heldout_before_W: float
    lasso_entry: dict[str, float]
    lasso_path: list[dict]
    candidates: list[dict]
    chosen: tuple[int, ...]
    log: list[SelectionStep]
    exclude: frozenset[str] = frozenset()


def select_effects(jac: np.ndarray, residual: np.ndarray, run_code: np.ndarray,
                   cands: Candidates, limits: Thresholds, exclude: frozenset[str] = frozenset(),
                   hold: dict | None = None, selector: LeaveOneRunOutSelector | None = None
                   ) -> Selection:
    """Lasso path, held-out scores and stepwise selection of the candidate columns.

    Parameters
    ----------
    jac : array, shape (n, q)
        Jacobian of the calibration [W per unit parameter].
    residual : array, shape (n,)
        Residual of the calibration [W].
    run_code : array of int
        Cross-validation group of each sample (the run by default).
    cands : Candidates
    limits : Thresholds
        Noise level [W], acceptance thresholds [-] and most effects accepted together.
    exclude : frozenset of str
        Effects not to select.
    hold : dict, optional
        Fold -> calibration columns held at zero (:class:`LeaveOneRunOutSelector`).
    selector : LeaveOneRunOutSelector, optional
        One already built on these data (its cache is reused).

    Returns
    -------
    Selection
    """
    sel = selector or LeaveOneRunOutSelector(
        J=jac, F=cands.columns, r=residual, run_code=run_code, nonneg=np.array(cands.nonneg, bool),
        group=cands.group, hold=hold)
    e0 = sel.cv(())
    path = sel.lasso_path()
    entry: dict[str, float] = {}
    for lam, sup in path:
        for j in sup:
            entry.setdefault(cands.name[j], lam)
    lasso = [{"lambda_rel": lam, "support": sorted({cands.name[j] for j in sup})}
             for lam, sup in path]
    scored = score_alone(cands, sel, e0, limits.noise_W, entry)
    steps = stepwise_selection(sel, cands, e0, entry, limits, exclude)
    return Selection(
        selector=sel, heldout_before_W=e0, lasso_entry=entry, lasso_path=lasso, candidates=scored,
        chosen=steps.chosen, log=steps.log, exclude=frozenset(exclude))
