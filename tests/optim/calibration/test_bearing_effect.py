"""The loop's ``bearing_ball_churning`` effect expressed with the case's bearing model.

With a ``[bearing]`` the effect's feature is that bearing's power under its model
(:func:`oilgap.model.bearing.bearing_power`), so the fitted coefficient c is a correction
factor on the bearing model (c = 1: the model is right). Without one it stays Palmgren's
M0 |omega| with f0 = 1 at the annulus' pitch diameter 2 R2 + delta2 (today's feature,
checked here against the formula written out). The recovery test is a plumbing test on
synthetic data: the synthetic rig's clean seed power plus 1.3 x the SKF model's power of
a 6809 computed here from the data's own speed and temperature columns.

``bearing_ball_drag`` is SKF's V_M drag term of the case's bearing (checked against the
formula written out), so its k is a drag scale; on synthetic data with the V_M term
2.5 x the loop names both effects and returns c = 1, k = 1.5.
"""

from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.bearing import bearing_power, bearing_vm_drag_power
from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.effects import EFFECTS, FluidFacts, RigFacts, effect_context
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.oils import get_oil
from oilgap.model.regions import joint_geometry
from oilgap.model.units import celsius_to_kelvin, rpm_to_rad_s
from oilgap.optim.calibration import LoopEstimator
from oilgap.studies.rigs.synth import SynthConfig, synthesize

SKF_6809 = {"designation": "6809"}
CHURNING = EFFECTS["bearing_ball_churning"]


def context(case, rpm, nu_m2_s):
    w = rpm_to_rad_s(np.asarray(rpm, dtype=float))
    return effect_context(joint_geometry(case), w, 0.0 * w, nu_m2_s, 870.0 + 0.0 * w,
                          case.friction)


def test_without_bearing_the_feature_is_palmgren_f0_1_at_the_annulus():
    case = seed_case()
    rpm = np.array([300.0, 1500.0, 3000.0])
    nu = 320e-6
    f = CHURNING.feature_values(context(case, rpm, nu))
    dm_mm = 2 * 22.0 + 5.0  # 2 R2 + delta2 of the seed's region 2
    hand = 1e-7 * (320.0 * rpm) ** (2 / 3) * dm_mm**3 * 1e-3 * rpm * 2 * np.pi / 60
    np.testing.assert_allclose(f, hand, rtol=1e-12)


@pytest.mark.parametrize("table", [SKF_6809, {"designation": "6809", "model": "palmgren"}])
def test_with_bearing_the_feature_is_the_bearing_models_power(table):
    spec = bearing_spec_from(table)
    case = replace(seed_case(), bearing=spec)
    rpm = np.array([-3000.0, 0.0, 700.0, 3000.0, 3000.0])
    nu = np.array([320e-6, 320e-6, 150e-6, 320e-6, 1000e-6])
    f = CHURNING.feature_values(context(case, rpm, nu))
    ref = [float(bearing_power(spec, float(rpm_to_rad_s(r)), float(v)))
           for r, v in zip(rpm, nu, strict=True)]
    np.testing.assert_allclose(f, ref, rtol=1e-12)
    assert f[1] == 0.0 and f[0] == pytest.approx(f[3], rel=1e-12)  # at rest, sign of speed
    assert np.all(f[[0, 2, 3]] > 0) and f[4] > f[3]  # thicker oil, more friction


def test_plumbing_the_fitted_coefficient_is_the_correction_factor():
    # synthetic: the clean seed model (noise 1 W) plus 1.3 x SKF's 6809 at each sample
    spec = bearing_spec_from(SKF_6809)
    df = synthesize(SynthConfig(n_samples=200, kind="viscous_power_W"), 0)
    nu = np.array([float(get_oil(o).properties(celsius_to_kelvin(t), 0.0)[0])
                   for o, t in zip(df["oil"], df["temp_C"], strict=True)])
    pb = np.asarray(bearing_power(spec, rpm_to_rad_s(df["speed_rpm"].to_numpy()), nu))
    assert 8.0 < pb.mean() < 15.0  # the SKF rolling + V_M drag of a 61809 at 25-50 degC
    data = df.assign(viscous_power_W=df["viscous_power_W"] + 1.3 * pb)
    est = LoopEstimator(base="eq6", case=replace(seed_case(), bearing=spec),
                        effects=["bearing_ball_churning"]).fit(data)
    (eff,) = est.effects_
    assert eff.name == "bearing_ball_churning"
    assert eff.coefficient == pytest.approx(1.3, abs=0.03)
    assert eff.ci_low < 1.3 < eff.ci_high
    assert eff.ci_high - eff.ci_low < 0.3
    assert est.calibration_after_["scale"] == pytest.approx(1.0, abs=0.02)  # truth's scale


def test_plausible_range_of_the_coefficient_follows_the_bearing_model():
    oil = [FluidFacts("VG320", "mineral", False)]
    plain = RigFacts.of(joint_geometry(seed_case()), oil)
    assert CHURNING.plausible.range(plain) == (0.0, 12.0)  # f0, as before
    skf = RigFacts.of(joint_geometry(replace(seed_case(), bearing=bearing_spec_from(
        SKF_6809))), oil)
    assert CHURNING.plausible.range(skf) == (0.0, 30.0)
    assert CHURNING.implausibility(1.3, skf) is None
    assert "outside the plausible" in CHURNING.implausibility(40.0, skf)
    palm = RigFacts.of(joint_geometry(replace(seed_case(), bearing=bearing_spec_from(
        {"designation": "6809", "model": "palmgren"}))), oil)
    assert CHURNING.plausible.range(palm) == (0.0, 3.0)  # c f0 <= 12 with f0 = 4
    assert CHURNING.implausibility(3.5, palm) is not None


# --------------------------------------------------------------------------- drag scale

DRAG = EFFECTS["bearing_ball_drag"]


@pytest.mark.parametrize("table", [SKF_6809, {"designation": "6809", "model": "palmgren"},
                                   {"bore_mm": 45.0, "outside_mm": 58.0,
                                    "model": "palmgren"}])
def test_drag_feature_is_skf_vm_term_by_hand(table):
    # 61809 submerged: K_ball = 3.1 (45 + 58)/(58 - 45) 1e-12, V_M = 1.25e-3, dm = 51.5 mm;
    # at 3000 rpm M = 0.4 V_M K_ball dm^5 n^2 = 40.041 N mm (docs/bearing.md), 12.579 W;
    # the same for a Palmgren bearing and one without a series (K_Z = 3.1 of every
    # deep-groove series); independent of the oil
    case = replace(seed_case(), bearing=bearing_spec_from(table))
    rpm = np.array([3000.0, -1500.0, 0.0])
    f = DRAG.feature_values(context(case, rpm, np.array([320e-6, 1000e-6, 320e-6])))
    k_ball = 3.1 * (45.0 + 58.0) / (58.0 - 45.0) * 1e-12
    hand = 0.4 * 1.25e-3 * k_ball * 51.5**5 * rpm**2 * 1e-3 * np.abs(rpm) * np.pi / 30
    assert hand[0] == pytest.approx(12.579, rel=1e-4)
    np.testing.assert_allclose(f, hand, rtol=1e-12)


def test_drag_feature_does_not_apply_without_a_bearing():
    assert DRAG.feature_values(context(seed_case(), np.array([3000.0]), 320e-6)) is None


def test_plumbing_the_loop_separates_the_drag_scale_from_the_correction_factor():
    # synthetic: the clean seed model plus SKF's 6809 with its V_M drag 2.5 x: c = 1 on
    # the whole model and k = 1.5 on the V_M term; the default library names both
    spec = bearing_spec_from(SKF_6809)
    df = synthesize(SynthConfig(n_samples=200, kind="viscous_power_W"), 0)
    nu = np.array([float(get_oil(o).properties(celsius_to_kelvin(t), 0.0)[0])
                   for o, t in zip(df["oil"], df["temp_C"], strict=True)])
    w = rpm_to_rad_s(df["speed_rpm"].to_numpy())
    pb = np.asarray(bearing_power(spec, w, nu))
    pv = np.asarray(bearing_vm_drag_power(spec, w))
    assert 5.0 < pv.mean() < 0.6 * pb.mean()  # the V_M term, about half the model
    data = df.assign(viscous_power_W=df["viscous_power_W"] + pb + 1.5 * pv)
    est = LoopEstimator(base="eq6", case=replace(seed_case(), bearing=spec)).fit(data)
    got = {e.name: e for e in est.effects_}
    assert set(got) == {"bearing_ball_churning", "bearing_ball_drag"}
    assert got["bearing_ball_churning"].coefficient == pytest.approx(1.0, abs=0.05)
    assert got["bearing_ball_drag"].coefficient == pytest.approx(1.5, abs=0.1)
    assert got["bearing_ball_drag"].ci_low < 1.5 < got["bearing_ball_drag"].ci_high


def test_plumbing_drag_alone_is_the_drag_scale():
    spec = bearing_spec_from(SKF_6809)
    df = synthesize(SynthConfig(n_samples=200, kind="viscous_power_W"), 0)
    pv = np.asarray(bearing_vm_drag_power(spec, rpm_to_rad_s(df["speed_rpm"].to_numpy())))
    est = LoopEstimator(base="eq6", case=replace(seed_case(), bearing=spec),
                        effects=["bearing_ball_drag"]).fit(
        df.assign(viscous_power_W=df["viscous_power_W"] + 2.5 * pv))
    (eff,) = est.effects_
    assert eff.coefficient == pytest.approx(2.5, abs=0.05)


def test_plausible_range_of_the_drag_scale():
    oil = [FluidFacts("VG320", "mineral", False)]
    skf = RigFacts.of(joint_geometry(replace(seed_case(), bearing=bearing_spec_from(
        SKF_6809))), oil)
    assert DRAG.plausible.range(skf) == (0.0, 30.0)
    assert DRAG.implausibility(0.9, skf) is None  # the spheres in still oil
    assert "outside the plausible" in DRAG.implausibility(40.0, skf)


def test_synthetic_rig_refuses_the_drag_without_a_bearing():
    with pytest.raises(InputError, match=r"bearing_ball_drag.*\[bearing\]"):
        synthesize(SynthConfig(n_samples=40, effect="bearing_ball_drag"), 0)
