"""Stage 3, least squares: parameter recovery, one-step folds, identifiability decisions."""

import math

import numpy as np
import pytest

from oilgap.model.skin_friction import BILGEN_BOULOS_ALPHA, FrictionLaw
from oilgap.optim.calibration import (
    BaseSpec,
    ForwardModel,
    decide_spec,
    fit_model,
    identifiability,
    initial_guess,
    one_step_fold,
)

FIXED = {"C": 10.0, "alpha": 0.3, "beta": -1.0, "gamma": -0.3}
LINEAR = ("seal_coulomb_friction", "oil_inertia")


def _model(rig, samples_factory, power):
    s = samples_factory(power=power)
    return ForwardModel(s, rig.case, rig.oils)


def test_spec_round_trip_and_law():
    spec = BaseSpec(("C", "gamma"), {"alpha": 0.3, "beta": -1.0})
    x = spec.start({"C": 12.5, "gamma": -0.4})
    assert x[0] == pytest.approx(math.log(12.5)) and x[1] == -0.4
    law = spec.law(x)
    assert law.form == "power-law" and law.C == pytest.approx(12.5) and law.gamma == -0.4
    assert spec.values(x) == pytest.approx({"C": 12.5, "alpha": 0.3, "beta": -1.0,
                                            "gamma": -0.4})


def test_noiseless_data_give_back_the_true_parameters(rig, samples_factory):
    truth = FrictionLaw(form="power-law", C=7.0, alpha=0.3, beta=-0.8, gamma=-0.25)
    s0 = samples_factory()
    y = ForwardModel(s0, rig.case, rig.oils).power(truth)
    m = _model(rig, samples_factory, y)
    spec = BaseSpec(("C", "beta", "gamma"), {"alpha": 0.3})
    fit = fit_model(m, spec, spec.start({"C": 10.0, "beta": -1.0, "gamma": 0.0}))
    got = spec.values(fit.x)
    for k in ("C", "beta", "gamma"):
        assert got[k] == pytest.approx(getattr(truth, k), rel=1e-6), k
    assert np.sqrt(np.mean((fit.pred - y) ** 2)) < 1e-8 * np.abs(y).max()
    assert fit.jac_base.shape == (m.samples.n, 3)


def test_initial_guess_scales_C_onto_the_data(rig, samples_factory):
    # with C the only free parameter the power is proportional to C: the start fits exactly
    s0 = samples_factory()
    y = 3.7 * ForwardModel(s0, rig.case, rig.oils).power(
        FrictionLaw(form="power-law", C=10.0, alpha=BILGEN_BOULOS_ALPHA, beta=-1.0, gamma=0.0))
    m = _model(rig, samples_factory, y)
    spec = BaseSpec(("C",), {"alpha": BILGEN_BOULOS_ALPHA, "beta": -1.0, "gamma": 0.0})
    x0 = initial_guess(m, spec)
    assert math.exp(x0[0]) == pytest.approx(37.0, rel=1e-12)
    assert np.allclose(m.base_power(spec.law(x0)), y, rtol=1e-12)


def test_one_step_fold_is_exact_for_a_model_linear_in_its_parameters(rig, samples_factory):
    # Eq. 8 fixed, two additive effects: the power is linear in (tau_c, I_V)
    rng = np.random.default_rng(0)
    s0 = samples_factory()
    law = BaseSpec((), FIXED).law(np.zeros(0))
    p_law = ForwardModel(s0, rig.case, rig.oils).power(law)
    y = (p_law + 0.05 * np.abs(s0.omega) + 1e-6 * s0.density_kg_m3 * s0.omega * s0.domega_dt
         + rng.normal(0, 0.5, s0.n))
    m = _model(rig, samples_factory, y)
    spec = BaseSpec((), FIXED)
    fit = fit_model(m, spec, np.zeros(0), LINEAR, np.array([0.01, 1e-7]))
    train = m.samples.run_code != 2
    one = one_step_fold(fit, m, spec, train)
    # second method: ordinary least squares of the two feature columns on the training rows
    X = np.column_stack([np.abs(s0.omega), s0.density_kg_m3 * s0.omega * s0.domega_dt])
    coef, *_ = np.linalg.lstsq(X[train], (y - p_law)[train], rcond=None)
    assert np.allclose(one.theta, coef, rtol=1e-6)
    full = fit_model(m.subset(train), spec, np.zeros(0), LINEAR, fit.theta, fit.scale, full=m)
    assert np.allclose(one.theta, full.theta, rtol=1e-6)
    assert np.allclose(one.pred, full.pred, rtol=1e-9)


def test_decide_spec_follows_the_data(rig, samples_factory):
    two_T = samples_factory()
    spec, stmt = decide_spec(two_T, ForwardModel(two_T, rig.case, rig.oils).geometry, rig.case)
    assert spec.free == ("C", "beta", "gamma")
    assert stmt["alpha"].startswith("not identifiable")
    assert spec.fixed == {"alpha": BILGEN_BOULOS_ALPHA}
    one_T = samples_factory(runs=(("a", "VG150", 1.0), ("b", "VG320", 1.0)))
    spec, stmt = decide_spec(one_T, ForwardModel(one_T, rig.case, rig.oils).geometry, rig.case)
    assert "gamma" not in spec.free and spec.fixed["gamma"] == 0.0
    assert stmt["gamma"].startswith("not identifiable: every oil run has T = 1")


def test_alpha_needs_two_gap_ratios_and_beta_a_spread_of_re(rig, samples_factory):
    s = samples_factory()
    gaps = np.where(s.run_code < 2, 0.8e-3, 1.2e-3)
    s2 = type(s)(**{**{k: getattr(s, k) for k in s.__dataclass_fields__}, "gap1_m": gaps})
    m = ForwardModel(s2, rig.case, rig.oils)
    spec, stmt = decide_spec(s2, m.geometry, rig.case)
    assert "alpha" in spec.free and stmt["alpha"].startswith("identified from 2")
    # one speed, one oil: Re varies only with the 3 K between the two runs
    flat = samples_factory(runs=(("a", "VG150", 4.0), ("b", "VG150", 2.0)), peak_rpm=0.0,
                           offset_rpm=1000.0, temp_rate_K_s=0.0)
    spec, stmt = decide_spec(flat, ForwardModel(flat, rig.case, rig.oils).geometry, rig.case)
    assert "beta" not in spec.free and stmt["beta"].startswith("not identifiable")


def test_identifiability_reports_the_jacobian_correlation(rig, samples_factory):
    s0 = samples_factory()
    y = ForwardModel(s0, rig.case, rig.oils).power(rig.law)
    m = _model(rig, samples_factory, y)
    spec = BaseSpec(("C", "gamma"), {"alpha": 0.3, "beta": -1.0})
    fit = fit_model(m, spec, spec.start({"C": 10.0, "gamma": 0.0}))
    a, b = fit.jac_base.T
    r = np.sum((a - a.mean()) * (b - b.mean())) / np.sqrt(
        np.sum((a - a.mean()) ** 2) * np.sum((b - b.mean()) ** 2))
    out = identifiability({"C": "x", "gamma": "y"}, spec, fit)
    assert out["correlations"] == f"corr(C, gamma) = {r:+.3f} (Jacobian columns at the fit)"
    one = BaseSpec(("C",), {"alpha": 0.3, "beta": -1.0, "gamma": -0.3})
    fit1 = fit_model(m, one, one.start({"C": 10.0}))
    assert "correlations" not in identifiability({"C": "x"}, one, fit1)
