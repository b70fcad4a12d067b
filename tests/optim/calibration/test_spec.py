"""Stage 3a, spec: the Eq. 6 base model, its parameters, the numerical box, fold identifiability."""

import math

import numpy as np
import pytest

from oilgap.model.skin_friction import FrictionLaw, moment_coefficient
from oilgap.optim.calibration import (
    BaseSpec,
    ForwardModel,
    check_alpha,
    decide_spec,
    fit_model,
    fold_spec,
    initial_guess,
)
from oilgap.optim.calibration.spec import PARAM_LIMITS

EQ6 = BaseSpec(("scale", "gamma"), {"alpha": 0.3}, "eq6", "couette")


def test_eq6_spec_is_the_design_tools_law_times_a_scale():
    x = EQ6.start({"scale": 1.25, "gamma": 0.4})
    assert x[0] == pytest.approx(math.log(1.25)) and x[1] == 0.4
    law = EQ6.law(x)
    assert (law.form, law.laminar_law, law.alpha) == ("smooth", "couette", 0.3)
    assert law.scale == pytest.approx(1.25) and law.gamma == 0.4
    assert EQ6.params == ("scale", "alpha", "gamma")
    # the scale multiplies the published smooth C_m: at Re = 30, x = 0.039, T = 2 by hand
    pub = moment_coefficient(30.0, 0.039, FrictionLaw(form="smooth"))
    assert moment_coefficient(30.0, 0.039, law, 2.0) == pytest.approx(1.25 * pub * 2 ** 0.4,
                                                                       rel=1e-12)


def test_alpha_of_eq6_is_the_gap_exponent_and_0_3_changes_nothing():
    # Eq. 6 laminar branch 10 x^alpha / Re: with laminar law "bilgen-boulos" the power
    # follows x^alpha exactly; alpha = 0.3 is the published law
    re, x = 30.0, 0.04
    for form in ("bilgen-boulos", "smooth"):
        pub = FrictionLaw(form=form, laminar_law="bilgen-boulos")
        assert moment_coefficient(re, x, pub) == pytest.approx(10 * x ** 0.3 / re, rel=1e-6)
        free = FrictionLaw(form=form, laminar_law="bilgen-boulos", alpha=0.5)
        assert moment_coefficient(re, x, free) == pytest.approx(10 * x ** 0.5 / re, rel=1e-6)


def test_the_box_keeps_every_evaluation_finite():
    spec = BaseSpec(("C", "alpha", "beta"), {"gamma": 0.0})
    v = spec.values(np.array([1e4, -1e4, 50.0]))  # exp(1e4) would overflow
    assert v["C"] == pytest.approx(math.exp(PARAM_LIMITS["C"][1]))
    assert v["alpha"] == PARAM_LIMITS["alpha"][0] and v["beta"] == PARAM_LIMITS["beta"][1]
    law = spec.law(np.array([1e4, -1e4, 50.0]))
    assert np.isfinite(moment_coefficient(1e-3, 0.04, law))
    assert spec.at_limit(np.array([50.0, 0.3, -1.0])) == ["C"]
    assert spec.at_limit(np.array([2.3, 0.3, -1.0])) == []


def test_new_base_recovers_scale_1_on_data_made_with_the_published_law(rig, samples_factory):
    # noise-free power from the published law as `evaluate` computes it (exact piecewise
    # Eq. 6, Couette laminar law, the truth's gamma): the smooth Eq. 6 base gives back
    # scale 1 (the smooth form differs from the exact one only within ~10 % of Re = 64,
    # 500, 1e4, where few samples lie) and gamma
    truth = FrictionLaw(form="bilgen-boulos", laminar_law="couette", gamma=0.45)
    s0 = samples_factory()
    y = ForwardModel(s0, rig.case, rig.oils).power(truth)
    m = ForwardModel(samples_factory(power=y), rig.case, rig.oils)
    spec, stmt = decide_spec(m.samples, m.geometry, rig.case, base="eq6")
    spec, stmt = check_alpha(m, spec, stmt)
    assert spec.free == ("scale", "gamma") and spec.base == "eq6"
    fit = fit_model(m, spec, initial_guess(m, spec))
    got = spec.values(fit.x)
    assert got["scale"] == pytest.approx(1.0, abs=0.005)
    assert got["gamma"] == pytest.approx(0.45, abs=0.01)
    # and exactly with the smooth truth (the model is then the truth's own form)
    y2 = ForwardModel(s0, rig.case, rig.oils).power(truth.smooth())
    m2 = ForwardModel(samples_factory(power=y2), rig.case, rig.oils)
    fit2 = fit_model(m2, spec, initial_guess(m2, spec))
    assert spec.values(fit2.x)["scale"] == pytest.approx(1.0, rel=1e-7)


def test_decide_spec_of_the_eq6_base_has_no_beta(rig, samples_factory):
    s = samples_factory()
    spec, stmt = decide_spec(s, ForwardModel(s, rig.case, rig.oils).geometry, rig.case, "eq6")
    assert spec.free == ("scale", "gamma") and spec.fixed == {"alpha": 0.3}
    assert "beta" not in stmt and stmt["scale"].startswith("identified")


def test_alpha_is_fixed_where_the_couette_bound_governs_region_1(rig, samples_factory):
    # two region-1 gaps, a rig without region 2: laminar data at x ~ 0.03-0.05 lie where
    # Eq. 6's laminar branch is 0.8-0.95 of Couette (physics notes), so
    # max(Couette, Eq. 6) is Couette at every sample and has no alpha in it
    from dataclasses import replace
    case = replace(rig.case, region2=None)
    s = samples_factory(peak_rpm=300.0)
    gaps = np.where(s.run_code < 2, 0.8e-3, 1.2e-3)
    s2 = type(s)(**{**{k: getattr(s, k) for k in s.__dataclass_fields__}, "gap1_m": gaps})
    m = ForwardModel(s2, case, rig.oils)
    spec, stmt = decide_spec(s2, m.geometry, case, "eq6")
    assert "alpha" in spec.free
    spec, stmt = check_alpha(m, spec, stmt)
    assert "alpha" not in spec.free and spec.fixed["alpha"] == 0.3
    assert stmt["alpha"].startswith("not identifiable: region 1 follows the Couette bound")


def test_fold_spec_holds_what_the_training_runs_cannot_identify(rig, samples_factory):
    s = samples_factory()  # runs a, b at T = 4; c, d at T = 2
    gaps = np.where(s.run_code == 3, 1.2e-3, 0.8e-3)  # run d alone at the second gap
    s2 = type(s)(**{**{k: getattr(s, k) for k in s.__dataclass_fields__}, "gap1_m": gaps})
    spec = BaseSpec(("scale", "alpha", "gamma"), {}, "eq6")
    r1 = rig.case.region1.radius
    assert fold_spec(spec, s2.subset(s2.run_code != 0), r1) == ()
    # without run d: one gap left, alpha held; T = 4 and 2 still there
    assert fold_spec(spec, s2.subset(s2.run_code != 3), r1) == ("alpha",)
    # only the T = 4 runs: gamma held too (and alpha: one gap)
    assert fold_spec(spec, s2.subset(s2.run_code < 2), r1) == ("alpha", "gamma")
