"""Stage 8, results: Table 3 rows, per-run rows, candidate statuses, effect records."""

import numpy as np
import pytest

from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration import (
    Candidates,
    EffectResult,
    FinalModel,
    ForwardModel,
    HeldOut,
    ModelFit,
    Selection,
    SelectionStep,
    candidate_statuses,
    effect_results,
    per_run_rows,
    table3_rows,
)
from oilgap.optim.calibration.results import law_dict, strip_bins

LAW = FrictionLaw(form="power-law", C=9.0)


def _fit(n, names=(), theta=()):
    return ModelFit(np.zeros(1), np.array(theta, float), LAW, np.zeros(n), np.zeros((n, 1)),
                    names=tuple(names))


def _final(n, names=(), theta=(), chosen=(), before=None, after=None):
    b = HeldOut(np.zeros(n) if before is None else before, [])
    a = b if after is None else HeldOut(after, [])
    return FinalModel(_fit(n, names, theta), list(names), tuple(chosen), b, a, None, [])


def test_table3_rows_by_hand(samples_factory):
    s = samples_factory()  # runs a VG150 T4, b VG320 T4, c VG150 T2, d VG680 T2
    code = s.run_code
    p_wo = s.viscous_W + 2.0
    p_wt = s.viscous_W + np.array([1.0, 0.5, 0.0, -1.0])[code]
    rows = table3_rows(s, p_wo, p_wt)
    # one row per (oil, T), ordered by the oil's viscosity, then T
    assert [(r["oil"], r["roughness_T"]) for r in rows] == [
        ("VG150", 2.0), ("VG150", 4.0), ("VG320", 4.0), ("VG680", 2.0)]
    assert [r["rmse_with_T_W"] for r in rows] == [0.0, 1.0, 0.5, 1.0]
    assert all(r["rmse_without_T_W"] == 2.0 for r in rows)
    assert [r["reduction_pct"] for r in rows] == [100.0, 50.0, 75.0, 50.0]


def test_per_run_rows_follow_table3(samples_factory):
    s = samples_factory()
    y = s.viscous_W
    pred = {"without_T": y + 2.0, "with_T": y + 1.0, "with_effect": y - 0.5}
    before = y + np.where(s.run_code == 1, 3.0, 0.0)
    table3 = table3_rows(s, pred["without_T"], pred["with_T"])
    rows = per_run_rows(s, pred, _final(s.n, before=before, after=y), table3)
    assert [r["run"] for r in rows] == ["c", "a", "b", "d"]
    b = rows[2]
    assert b == {"run": "b", "oil": "VG320", "roughness_T": 4.0, "n_samples": 120,
                 "rmse_without_T_W": 2.0, "rmse_with_T_W": 1.0, "rmse_with_effect_W": 0.5,
                 "heldout_rmse_before_W": 3.0, "heldout_rmse_after_W": 0.0}


class _Selector:
    """Held-out RMSE [W] of each support, given."""

    def __init__(self, table):
        self.table = {frozenset(k): v for k, v in table.items()}

    def cv(self, support):
        return self.table[frozenset(support)]


def _selection(cv, scored):
    return Selection(_Selector(cv), cv[()], {}, [], scored, (), [])


def test_candidate_statuses():
    names = ["a", "b", "c"]
    c = Candidates(info=[], usable=names, columns=np.zeros((2, 3)), name=names,
                   variant=[None] * 3, nonneg=[True] * 3)
    scored = [{"name": "a", "status": "candidate"}, {"name": "b", "status": "candidate"},
              {"name": "c", "status": "candidate", "heldout_gain_alone_pct": 4.0,
               "explained_structure_alone": 0.1},
              {"name": "x", "status": "inactive on these data"}]
    cv = {(): 10.0, (0,): 5.0, (0, 1): 4.0, (0, 2): 4.9}
    out = candidate_statuses(c, _selection(cv, scored), _final(2, ["a"], [1.0], (0,)), 1.0,
                             0.1, 0.5)
    st = {d["name"]: d for d in out}
    assert st["a"]["status"] == "accepted"
    assert st["b"]["heldout_gain_added_pct"] == pytest.approx(20.0)
    assert st["b"]["status"] == "rejected: adds 20.0 % to a (margin 10 %)"
    assert st["x"]["status"] == "inactive on these data"
    assert scored[0]["status"] == "candidate"  # the records handed in are not changed
    # nothing accepted: the reasons alone
    scored[1].update(heldout_gain_alone_pct=30.0, explained_structure_alone=0.2)
    out = {d["name"]: d["status"] for d in candidate_statuses(
        c, _selection(cv, scored[1:]), _final(2), 1.0, 0.1, 0.5)}
    assert out["b"] == "rejected: held-out gain 30.0 % but explains only 20 % of the " \
                       "structure (< 50 %)"
    assert out["c"] == "rejected: held-out gain 4.0 % < margin 10 %"
    out = candidate_statuses(c, _selection({(): 0.5}, scored[1:]), _final(2), 1.0, 0.1, 0.5)
    assert out[0]["status"] == "rejected: no structure above the noise"


def test_effect_results_by_hand(rig):
    s = rig.samples
    m = ForwardModel(s, rig.case, rig.oils)
    final = _final(s.n, ["seal_coulomb_friction", "shear_thinning"], [0.03, 4e-10], (0, 1))
    lo, hi = np.array([0.02, 1e-10]), np.array([0.04, 9e-10])
    out = effect_results(m, final, (lo, hi), {"seal_coulomb_friction": 40.0,
                                               "shear_thinning": 12.0})
    seal, thin = out
    assert seal.coefficient == 0.03 and (seal.ci_low, seal.ci_high) == (0.02, 0.04)
    assert seal.strength == 0.03 and seal.heldout_gain_pct == 40.0
    # the seal's own power is tau |w| (shear thinning scales the clearance power only)
    assert seal.rms_power_W == pytest.approx(np.sqrt(np.mean((0.03 * s.omega) ** 2)), rel=1e-9)
    assert thin.strength == pytest.approx(2e-5)  # lambda = sqrt(lambda^2) [s]
    assert seal.coefficient_label() == "tau_c"
    d = seal.to_dict()
    assert list(d)[:6] == ["name", "formula", "coefficient", "ci_low", "ci_high",
                           "heldout_gain_pct"]
    assert isinstance(seal, EffectResult)


def test_json_pieces():
    rs = {"rmse_W": 1.0, "variables": {"t": {"pearson_r": 0.1, "eta2": 0.2,
                                             "bin_centres": [1], "bin_means_W": [2]}}}
    assert strip_bins(rs) == {"rmse_W": 1.0, "variables": {"t": {"pearson_r": 0.1,
                                                                 "eta2": 0.2}}}
    assert law_dict(LAW) == {"form": "power-law", "laminar_law": "couette", "gamma": 0.0,
                             "scale": 1.0, "C": 9.0, "alpha": 0.3, "beta": -1.0}


def test_the_status_names_the_rule_that_rejected():
    # issue 9: "held-out gain 16.4 % < margin 10 %" when the structure rule rejected
    names = ["a", "b"]
    c = Candidates(info=[], usable=names, columns=np.zeros((2, 2)), name=names,
                   variant=[None] * 2, nonneg=[True] * 2)
    scored = [{"name": "a", "status": "candidate", "heldout_gain_alone_pct": 16.4,
               "explained_structure_alone": 0.3},
              {"name": "b", "status": "candidate", "heldout_gain_alone_pct": 4.0,
               "explained_structure_alone": 0.05}]
    cv = {(): 10.0, (0,): 8.36}
    log = [SelectionStep(step=1, best="a", accepted=True),
           SelectionStep(step="structure", effects=["a"], explained_total=0.3, accepted=False,
                         rejected_by="structure")]
    sel = Selection(_Selector(cv), 10.0, {}, [], scored, (), log)
    st = {d["name"]: d["status"] for d in candidate_statuses(c, sel, _final(2), 1.0, 0.1, 0.5)}
    assert st["a"] == ("rejected: held-out gain 16.4 % alone, but the effects selected together "
                       "(a) explain only 30 % of the held-out structure above the noise (< 50 %)")
    assert st["b"] == "rejected: held-out gain 4.0 % < margin 10 %"
    # the nonlinear refit's check
    fin = _final(2)
    fin.log.append(SelectionStep(step="nonlinear check", rejected=["a"], gain_pct=6.0))
    sel = Selection(_Selector(cv), 10.0, {}, [], scored, (), log[:1])
    st = {d["name"]: d["status"] for d in candidate_statuses(c, sel, fin, 1.0, 0.1, 0.5)}
    assert st["a"] == ("rejected: held-out gain 16.4 % alone, but the nonlinear refit of a "
                       "lowers the held-out RMSE by only 6.0 % (< margin 10 %)")
    # an implausible fit
    st = {d["name"]: d["status"] for d in candidate_statuses(
        c, sel, _final(2), 1.0, 0.1, 0.5, {"a": "k = 99 outside the plausible 0..3"})}
    assert st["a"] == "implausible: k = 99 outside the plausible 0..3"
