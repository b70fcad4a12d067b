"""Stage 6, refit: leave-one-run-out folds, the nonlinear check, held-out gains."""

import numpy as np
import pytest

from oilgap.optim.calibration import (
    BaseSpec,
    ForwardModel,
    Refitter,
    Thresholds,
    fit_model,
    heldout_gains,
    refit_selected,
    rmse,
    screen_candidates,
    select_effects,
)

FIXED = BaseSpec((), {"C": 10.0, "alpha": 0.3, "beta": -1.0, "gamma": -0.3})
LINEAR = ("seal_coulomb_friction", "oil_inertia")


def test_rmse_by_hand():
    assert rmse(np.array([3.0, -4.0])) == pytest.approx(np.sqrt(12.5))
    assert np.isnan(rmse(np.zeros(0)))


def _linear_model(rig, samples_factory):
    s0 = samples_factory()
    rng = np.random.default_rng(1)
    p_law = ForwardModel(s0, rig.case, rig.oils).power(FIXED.law(np.zeros(0)))
    y = p_law + 0.05 * np.abs(s0.omega) + rng.normal(0, 0.5, s0.n)
    return ForwardModel(samples_factory(power=y), rig.case, rig.oils), p_law


def test_folds_of_a_linear_model_one_step_full_and_by_hand(rig, samples_factory):
    m, p_law = _linear_model(rig, samples_factory)
    s = m.samples
    scale = {"seal_coulomb_friction": 100.0, "oil_inertia": 1.0}
    one = Refitter(m, FIXED, scale, "one-step")
    fit = one.fit(LINEAR, np.zeros(0), np.array([0.04, 1e-7]))
    a = one.leave_one_run_out(LINEAR, fit.x, fit.theta, fit)
    b = Refitter(m, FIXED, scale, "full").leave_one_run_out(LINEAR, fit.x, fit.theta, fit)
    assert np.allclose(a.pred, b.pred, rtol=1e-8)
    # by hand: least squares of the two features on the other runs, predict the run left out
    X = np.column_stack([np.abs(s.omega), s.density_kg_m3 * s.omega * s.domega_dt])
    for c in range(len(s.run_names)):
        tr = s.run_code != c
        coef = np.linalg.lstsq(X[tr], (s.viscous_W - p_law)[tr], rcond=None)[0]
        assert np.allclose(a.pred[~tr], (p_law + X @ coef)[~tr], rtol=1e-8)
        assert np.allclose(a.folds[c].theta, coef, rtol=1e-6)


def _search(rig, samples_factory, tau=0.05):
    s0 = samples_factory()
    rng = np.random.default_rng(2)
    y = (ForwardModel(s0, rig.case, rig.oils).power(rig.law) + tau * np.abs(s0.omega)
         + rng.normal(0, 0.5, s0.n))
    m = ForwardModel(samples_factory(power=y), rig.case, rig.oils)
    spec = BaseSpec(("C", "gamma"), {"alpha": 0.3, "beta": -1.0})
    base = fit_model(m, spec, spec.start({"C": 10.0, "gamma": 0.0}))
    cands = screen_candidates(m, spec, base, ["seal_coulomb_friction", "oil_inertia"])
    r0 = y - base.pred
    limits = Thresholds(noise_W=0.5, margin=0.1, min_explained=0.5, max_effects=3)
    sel = select_effects(base.jac_base, r0, m.samples.run_code, cands, limits)
    return m, spec, base, cands, sel, Refitter(m, spec, cands.feature_scale())


@pytest.mark.filterwarnings("ignore:Solution may be inaccurate")  # cvxpy, on the lasso path
def test_refit_names_the_effect_and_the_held_out_check_can_overrule(rig, samples_factory):
    m, spec, base, cands, sel, refitter = _search(rig, samples_factory)
    final = refit_selected(refitter, base, cands, sel, 0.1)
    assert final.accepted == ["seal_coulomb_friction"] and final.log == []
    assert final.fit.theta[0] == pytest.approx(0.05, rel=0.05)
    y = m.samples.viscous_W
    hb, ha = rmse(y - final.before.pred), rmse(y - final.after.pred)
    assert final.nonlinear_check == pytest.approx(
        {"heldout_before_W": hb, "heldout_after_W": ha, "gain_pct": 100 * (1 - ha / hb)})
    gains = heldout_gains(refitter, final)
    assert gains == pytest.approx({"seal_coulomb_friction": 100 * (1 - ha / hb)})
    # a margin no effect can reach: rejected, the calibration stays
    strict = refit_selected(refitter, base, cands, sel, 0.999)
    assert strict.accepted == [] and strict.fit is base and strict.chosen == ()
    assert strict.log[0].step == "nonlinear check"
    assert strict.log[0].rejected == ["seal_coulomb_friction"]
    assert np.array_equal(strict.after.pred, strict.before.pred)


def test_nothing_selected_keeps_the_calibration(rig, samples_factory):
    m, spec, base, cands, sel, refitter = _search(rig, samples_factory, tau=0.0)
    assert sel.chosen == ()
    final = refit_selected(refitter, base, cands, sel, 0.1)
    assert final.fit is base and final.nonlinear_check is None
    assert heldout_gains(refitter, final) == {}
