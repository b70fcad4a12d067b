"""Stage 5b, selection: box least squares, the leave-one-run-out selector, lasso, stepwise."""

import itertools
import math
from dataclasses import replace

import cvxpy as cp
import numpy as np
import pytest
from scipy.optimize import lsq_linear

from oilgap.optim.calibration import (
    Candidates,
    LeaveOneRunOutSelector,
    SelectionStep,
    SignConstrainedLasso,
    Thresholds,
    box_lstsq,
    select_effects,
    stepwise_selection,
)

LIMITS = Thresholds(noise_W=0.05, margin=0.1, min_explained=0.5, max_effects=3)
"""Noise 0.05 W, margin 10 %, half the structure explained, at most 3 effects."""


def _problem(seed=3, n=200):
    rng = np.random.default_rng(seed)
    X = rng.normal(size=(n, 7))
    r = X @ np.array([1.0, -2.0, 0.5, -0.7, 0.0, 0.3, -1.5]) + rng.normal(size=n)
    lo = np.array([-np.inf, -np.inf, -np.inf, 0.0, 0.0, 0.0, 0.0])  # sign-constrained tail
    hi = np.full(7, np.inf)
    lo[5] = hi[5] = 0.0  # one column left out of the support
    return X, r, lo, hi


def _brute_force(X, r, lo, hi):
    """Every active set of the sign constraints: unconstrained solve on the rest, best feasible."""
    fixed = lo == hi
    signed = [j for j in range(X.shape[1]) if lo[j] == 0.0 and not fixed[j]]
    best, best_f = None, np.inf
    for k in range(len(signed) + 1):
        for act in itertools.combinations(signed, k):
            free = [j for j in range(X.shape[1]) if not fixed[j] and j not in act]
            x = np.zeros(X.shape[1])
            x[free] = np.linalg.lstsq(X[:, free], r, rcond=None)[0]
            if np.all(x[signed] >= -1e-12):
                f = float(np.sum((X @ x - r) ** 2))
                if f < best_f:
                    best, best_f = x, f
    return best


def test_box_least_squares_against_brute_force_lsq_linear_and_cvxpy():
    X, r, lo, hi = _problem()
    got = box_lstsq(X.T @ X / len(r), X.T @ r / len(r), lo, hi)
    assert np.allclose(got, _brute_force(X, r, lo, hi), atol=1e-8)
    free = lo != hi
    ref = lsq_linear(X[:, free], r, bounds=(lo[free], hi[free]), method="bvls", tol=1e-12)
    assert np.allclose(got[free], ref.x, atol=1e-8) and got[5] == 0.0
    x = cp.Variable(7)
    cp.Problem(cp.Minimize(cp.sum_squares(X @ x - r)),
               [x[3:5] >= 0, x[5] == 0, x[6] >= 0]).solve(solver=cp.CLARABEL)
    assert np.allclose(got, x.value, atol=1e-6)
    assert got[3] == 0.0 and got[6] == 0.0  # the negative-truth coefficients sit on the bound


def test_box_least_squares_without_active_bounds_is_the_normal_equations():
    X, r, _, _ = _problem(seed=4)
    lo, hi = np.full(7, -np.inf), np.full(7, np.inf)
    got = box_lstsq(X.T @ X, X.T @ r, lo, hi)
    assert np.allclose(got, np.linalg.lstsq(X, r, rcond=None)[0], rtol=1e-8)
    assert np.array_equal(box_lstsq(X.T @ X, X.T @ r, np.zeros(7), np.zeros(7)), np.zeros(7))


def _runs_data(seed=0, n_runs=5, n=80, noise=0.05):
    rng = np.random.default_rng(seed)
    code = np.repeat(np.arange(n_runs), n)
    t = np.tile(np.linspace(0, 1, n), n_runs)
    J = np.column_stack([np.ones(code.size)])  # the calibration: one offset direction
    u, v, w = (rng.normal(size=code.size) for _ in range(3))
    F = np.column_stack([u + v + 0.5 * w, u, v, np.sin(7 * t)])
    return code, J, F, u, v, w, rng.normal(0, noise, code.size)


def test_selector_cv_is_leave_one_run_out_least_squares():
    code, J, F, u, v, w, e = _runs_data()
    r = 2.0 * u + 0.3 + e
    sel = LeaveOneRunOutSelector(J, F, r, code, np.zeros(4, bool), np.arange(4))
    X = np.column_stack([J, F[:, [1, 3]]])
    sse = 0.0
    for c in range(5):
        tr = code != c
        b = np.linalg.lstsq(X[tr], r[tr], rcond=None)[0]
        sse += float(np.sum((r[~tr] - X[~tr] @ b) ** 2))
    assert sel.cv((1, 3)) == pytest.approx(math.sqrt(sse / len(r)), rel=1e-8)
    b = np.linalg.lstsq(X, r, rcond=None)[0]
    assert np.allclose(sel.coef((1, 3))[[1, 3]], b[1:], rtol=1e-8)
    assert np.all(sel.coef((1, 3))[[0, 2]] == 0.0)


def test_sign_constrained_lasso_limits():
    rng = np.random.default_rng(5)
    A = rng.normal(size=(50, 3))
    b = A @ np.array([1.0, -0.5, 0.0]) + 0.01 * rng.normal(size=50)
    lasso = SignConstrainedLasso(A, b, np.array([-np.inf, 0.0, -np.inf]), np.full(3, np.inf))
    x0 = lasso.solve(np.zeros(3))  # no penalty: box least squares, x1 on its bound
    assert np.allclose(x0, box_lstsq(A.T @ A, A.T @ b, np.array([-np.inf, 0.0, -np.inf]),
                                     np.full(3, np.inf)), atol=1e-6)
    big = 2.1 * np.abs(A.T @ b).max()  # above lambda_max = max |2 A'b|: all zero
    assert np.allclose(lasso.solve(np.full(3, big)), 0.0, atol=1e-6)


def _cands(F, names=("mix", "u", "v", "sine")):
    return Candidates(info=[{"name": n, "status": "candidate"} for n in names],
                      usable=list(names), columns=F, name=list(names),
                      variant=[None] * len(names), nonneg=[False] * len(names))


def test_lasso_path_takes_the_true_column_in_first():
    code, J, F, u, v, w, e = _runs_data(seed=1)
    r = 2.0 * F[:, 3] + e
    sel = LeaveOneRunOutSelector(J, F, r, code, np.zeros(4, bool), np.arange(4))
    path = sel.lasso_path()
    assert path[0][0] == 1.0 and path[-1][0] == pytest.approx(1e-3)
    first = next(sup for _, sup in path if sup)
    assert first == (3,)


def test_forward_selection_stops_at_the_margin():
    code, J, F, u, v, w, e = _runs_data(seed=2)
    r = 2.0 * u + e
    c = _cands(F)
    sel = LeaveOneRunOutSelector(J, F, r, code, np.zeros(4, bool), np.arange(4))
    out = stepwise_selection(sel, c, sel.cv(()), {}, LIMITS)
    assert out.chosen == (1,)
    assert [s.accepted for s in out.log] == [True, False, True]
    assert out.log[1].rejected_by == "margin"
    # in loop.json: the keys a forward step carries, unset ones left out
    assert list(out.log[1].to_dict()) == ["step", "best", "heldout_rmse_W", "gain_pct",
                                          "explained_structure", "explained_total", "accepted",
                                          "rejected_by"]
    assert list(out.log[0].to_dict())[-1] == "accepted"
    # the set kept explains the structure above the noise: the last record says so
    assert out.log[2].step == "structure" and out.log[2].effects == ["u"]
    assert out.log[0].best == "u"
    assert out.log[0].gain_pct == pytest.approx(100 * (1 - sel.cv((1,)) / sel.cv(())))


def test_backward_pruning_drops_a_column_made_redundant():
    # r = u + v: the mixture u + v + w/2 is best alone, then u and v together make it useless
    code, J, F, u, v, w, e = _runs_data(seed=3, noise=0.01)
    r = u + v + e
    c = _cands(F)
    sel = LeaveOneRunOutSelector(J, F, r, code, np.zeros(4, bool), np.arange(4))
    out = stepwise_selection(sel, c, sel.cv(()), {}, Thresholds(noise_W=0.01, margin=0.01,
                                                                min_explained=0.0, max_effects=3))
    steps = [s.best for s in out.log if s.step in (1, 2, 3)]
    assert steps[0] == "mix" and set(steps[1:3]) == {"u", "v"}
    assert SelectionStep(step="prune", dropped="mix") in out.log
    assert sorted(out.chosen) == [1, 2]


def test_select_effects_records_the_path_and_the_scores_alone():
    code, J, F, u, v, w, e = _runs_data(seed=4)
    r = 2.0 * F[:, 3] + e
    c = _cands(F)
    res = select_effects(J, r, code, c, LIMITS)
    assert [c.name[j] for j in res.chosen] == ["sine"]
    assert res.lasso_entry["sine"] == max(res.lasso_entry.values())  # enters first
    assert res.lasso_path[0]["lambda_rel"] == 1.0
    rec = {d["name"]: d for d in res.candidates}
    e0, e1 = res.heldout_before_W, res.selector.cv((3,))
    assert rec["sine"]["heldout_rmse_alone_W"] == e1
    assert rec["sine"]["explained_structure_alone"] == pytest.approx(
        (e0 ** 2 - e1 ** 2) / (e0 ** 2 - 0.05 ** 2))
    assert rec["sine"]["best_column"] == "sine"


def test_two_effects_that_only_show_together_are_taken_as_a_pair():
    # a = u + 3s and b = v - 3s share a large part s that cancels in a + b: alone, each
    # fits mostly s, which the data do not hold, and gains little; together they are exact
    rng = np.random.default_rng(7)
    code = np.repeat(np.arange(5), 80)
    u, v, s, w = (rng.normal(size=code.size) for _ in range(4))
    J = np.ones((code.size, 1))
    F = np.column_stack([u + 3 * s, v - 3 * s, w])
    r = F[:, 0] + F[:, 1] + 0.05 * rng.normal(size=code.size)
    c = _cands(F, names=("a", "b", "c"))
    sel = LeaveOneRunOutSelector(J, F, r, code, np.zeros(3, bool), np.arange(3))
    e0 = sel.cv(())
    # by hand: each alone gains less than the 10 % margin, the pair nearly all of it
    assert 1 - sel.cv((0,)) / e0 < 0.1 and 1 - sel.cv((1,)) / e0 < 0.1
    assert 1 - sel.cv((0, 1)) / e0 > 0.9
    out = stepwise_selection(sel, c, e0, {}, LIMITS)
    assert sorted(out.chosen) == [0, 1]
    assert out.log[0].best == "a + b" and out.log[0].accepted
    assert out.log[1].rejected_by == "margin"  # c adds nothing
    # with room for one effect only, no pair is tried: nothing is accepted
    one = stepwise_selection(sel, c, e0, {}, replace(LIMITS, max_effects=1))
    assert one.chosen == () and one.log[0].rejected_by == "margin"
