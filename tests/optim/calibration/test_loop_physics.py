"""The loop keeps the physics (issue 9): the Eq. 6 base, ranges and findings, several effects at
once, plausibility, robust folds, errors as one line."""

from dataclasses import replace
from functools import cache

import numpy as np
import pandas as pd
import pytest

from oilgap.model.effects import EFFECTS, FluidFacts, RigFacts
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration import LoopEstimator
from oilgap.studies.loop.report import format_summary
from oilgap.studies.rigs.synth import (
    DEFAULT_STRENGTH,
    SynthConfig,
    fluid_table,
    polymer_thickened,
    power_law_truth,
    synthesize,
)

GAMMA = seed_case().friction.gamma


@cache
def _fit(cfg: SynthConfig, seed: int = 0, **kw) -> LoopEstimator:
    oils = fluid_table(cfg) if cfg.fluids else None
    return LoopEstimator(base="eq6", case=cfg.case, oils=oils, **kw).fit(synthesize(cfg, seed))


def _cut(est):
    h = est.heldout_rmse_
    return 1.0 - h["after"] / h["before"]


TWO = {"seal_coulomb_friction": 0.04, "oil_inertia": 5e-7}
THREE = {**TWO, "taylor_vortex_onset": 1.0}


@pytest.mark.parametrize("effects", [TWO, THREE], ids=["two", "three"])
def test_two_and_three_effects_injected_at_once_are_all_named(effects):
    est = _fit(SynthConfig(effects=effects))
    assert sorted(e.name for e in est.effects_) == sorted(effects)
    for e in est.effects_:  # each coefficient recovered, each inside its interval
        assert e.coefficient == pytest.approx(effects[e.name], rel=0.05), e.name
        assert e.ci_low < e.coefficient < e.ci_high
    # the held-out error falls to the noise (1 W), not to "one effect explained"
    assert est.heldout_rmse_["after"] < 1.15 and _cut(est) > 0.8
    assert est.unexplained_ is None
    # no single effect explains half the structure of three: the old per-step rule stopped
    # there; the set rule accepts them together
    steps = [s for s in est.selection_log_ if s.step in (1, 2, 3) and s.accepted]
    assert len(steps) == len(effects)
    if len(effects) == 3:
        assert steps[0].explained_total < 0.9


def test_data_made_with_the_published_law_give_scale_1_and_no_finding():
    est = _fit(SynthConfig())
    assert est.calibration_["scale"] == pytest.approx(1.0, abs=0.005)
    lo, hi = est.calibration_ci_["scale"]
    assert 0 < lo < 1.0 < hi
    assert est.findings_ == [] and est.to_dict()["findings"] == []
    assert est.to_dict()["base"] == "eq6"


def test_a_scale_outside_its_range_is_a_finding_tried_as_evidence():
    # truth: the published law at 1.6x (a loss that scales exactly like the laminar loss,
    # e.g. an enclosed end disc, absorbed): reported, tried with the scale held at 1.4, and
    # kept since no library effect predicts the held-out runs as well
    est = _fit(SynthConfig(truth=FrictionLaw(form="smooth", scale=1.6, gamma=GAMMA)))
    assert est.calibration_["scale"] == pytest.approx(1.6, rel=0.01)
    (f,) = est.findings_
    assert f.kind == "out of range" and f.parameter == "scale"
    assert f.range == (0.7, 1.4) and f.held_at == 1.4
    assert f.message.startswith("the scale is 1.6x the published law outside its physical "
                                   "range 0.7..1.4")
    assert "an effect that scales like the laminar loss may be absorbed" in f.message
    assert f.evidence.startswith("evidence: with scale = 1.4 held at its range bound")
    assert f.evidence.endswith("the free calibration is kept")
    assert est.effects_ == []
    out = format_summary(est)
    assert "finding     the scale is 1.6x the published law" in out
    d = est.to_dict()["findings"][0]
    assert list(d) == ["kind", "parameter", "value", "range", "basis", "source", "message",
                       "held_at", "evidence"]
    assert d["parameter"] == "scale" and d["range"] == [0.7, 1.4]


def test_a_range_violation_the_effects_explain_is_reported_so():
    # a large seal torque: without effects the scale absorbs it (about 1.5x); with the seal
    # accepted the refitted scale is back near 1
    est = _fit(SynthConfig(effect="seal_coulomb_friction", strength=0.15))
    assert [e.name for e in est.effects_] == ["seal_coulomb_friction"]
    assert est.calibration_["scale"] > 1.4
    assert est.calibration_after_["scale"] == pytest.approx(1.0, abs=0.02)
    (f,) = est.findings_
    assert f.kind == "out of range without effects"
    assert "refitted with seal_coulomb_friction it is 1, within its range" in f.message


def test_shear_thinning_on_a_newtonian_oil_is_not_a_candidate():
    # outside its physical domain (no polymer-thickened liquid): not a candidate at all
    est = _fit(SynthConfig(effect="shear_thinning"))  # straight mineral oils
    assert est.effects_ == []
    st = {c["name"]: c["status"] for c in est.candidates_}
    assert st["shear_thinning"] == ("not a candidate: no polymer-thickened liquid among the "
                                    "fluids of the oil runs (VG1000, VG150, VG320, VG680: "
                                    "Newtonian)")
    # a fit on such a fluid would still be implausible (the rule for a mixed set of fluids)
    facts = RigFacts.of(est.forward_model_.geometry, [FluidFacts("VG150", "mineral", False)])
    why = EFFECTS["shear_thinning"].implausibility(1e-8, facts)
    assert "the effect needs a polymer-thickened liquid: " in why
    assert "VG150 is a straight mineral oil" in why
    # the same rig with the oils marked polymer-thickened: named, lambda recovered
    est = _fit(SynthConfig(effect="shear_thinning", fluids=polymer_thickened()))
    (e,) = est.effects_
    assert e.name == "shear_thinning"
    assert e.strength == pytest.approx(DEFAULT_STRENGTH["shear_thinning"], rel=0.03)


def test_plausible_ranges_hold_every_test_strength_of_the_synthetic_rig():
    # the rig's default strengths are meant to be physical: each inside its range
    from oilgap.model.regions import joint_geometry
    facts = RigFacts.of(joint_geometry(seed_case()), [FluidFacts("VG320", "mineral", True)])
    for name, s in DEFAULT_STRENGTH.items():
        eff = EFFECTS[name]
        assert eff.implausibility(eff.coefficient_from_strength(s), facts) is None, name


def _one_gap_fold_data():
    # eight runs at the seed's 1 mm gap and one run (VG320, T = 4) at 1.4 mm: leaving that
    # run out leaves one gap ratio, which cannot identify alpha
    base = seed_case()
    frames = []
    for gap_mm, oils in ((1.0, ("VG150", "VG320", "VG680", "VG1000")), (1.4, ("VG320",))):
        r1 = base.region1
        d = gap_mm * 1e-3 - r1.gap
        case = replace(base, region1=replace(r1, T3=r1.T3 + d, T4=r1.T4 + d,
                                             T4_unfilled=r1.T4 + d))
        df = synthesize(SynthConfig(case=case, oils=oils, kind="viscous_power_W", n_samples=300,
                                    truth=power_law_truth(base)), seed=int(10 * gap_mm))
        if gap_mm == 1.4:
            df = df[df["run"] == "VG320-T4"]
        df["run"] = df["run"] + f"-g{gap_mm:g}"
        df["gap_mm"] = gap_mm
        frames.append(df)
    return pd.concat(frames, ignore_index=True)


@pytest.mark.parametrize("base", ["power-law", "eq6"])
def test_a_fold_with_one_gap_holds_alpha_and_says_so(base):
    est = LoopEstimator(base=base, cv="one-step").fit(_one_gap_fold_data())
    stmt = est.identifiability_["alpha"]
    if base == "power-law":  # the Eq. 6 base fixes alpha anyway (Couette governs region 1)
        assert stmt.startswith("identified from 2 region-1 gap ratios")
        # held at its prior (Eq. 6's 0.3), never at the all-data fit (issue 25)
        assert stmt.endswith("held at its prior 0.3 in 1 of 9 cross-validation folds "
                             "(their training data cannot identify it)")
        assert np.all(np.isfinite(est.calibration_ci_["alpha"]))
    level = "C" if base == "power-law" else "scale"
    lo, hi = est.calibration_ci_[level]
    if "bounded below" in est.identifiability_.get(level, ""):
        # the fit went below the Couette floor and is held there (issue 27): pinned by the
        # floor, not identified by the data, so no interval
        assert np.isnan(lo) and np.isnan(hi)
    else:
        assert 0 < lo < est.calibration_[level] < hi  # log space: never below zero
    assert np.all(np.isfinite(est.heldout_pred_["before"]))


def test_data_without_a_viscous_signal_report_it_without_pinned_intervals():
    df = synthesize(SynthConfig(kind="viscous_power_W", n_samples=300), 0)
    df["viscous_power_W"] = np.random.default_rng(3).normal(0.0, 1.0, len(df))  # noise only
    est = LoopEstimator(base="eq6").fit(df)
    kinds = [f.kind for f in est.findings_]
    assert "no viscous signal" in kinds and "out of range" not in kinds
    assert all(np.isnan(est.calibration_ci_[k]).all() for k in ("scale", "gamma"))
    assert est.effects_ == []


def test_steady_point_data_drop_the_time_dependent_effects():
    # rows without time_s are steady operating points: no time-dependent candidate
    df = synthesize(SynthConfig(kind="viscous_power_W", n_samples=300), 0)
    est = LoopEstimator(base="eq6").fit(df.iloc[::10].drop(columns=["time_s"]))
    assert est.samples_.has_time is False
    st = {c["name"]: c["status"] for c in est.candidates_}
    for name in ("oil_inertia", "thermal_lag", "sensor_delay"):
        assert st[name] == ("not a candidate: steady-point data (no time_s); a "
                            "time-dependent effect needs a time record"), name
    assert st["seal_coulomb_friction"].startswith("rejected")
    assert "sensor_delay: not a candidate: steady-point data" in format_summary(est)


@pytest.mark.parametrize("kw, field", [({"base": "spline"}, "base"),
                                       ({"max_effects": 0}, "max_effects")])
def test_bad_options_are_input_errors(kw, field):
    with pytest.raises(InputError) as e:
        LoopEstimator(**kw).fit(synthesize(SynthConfig(n_samples=100), 0))
    assert e.value.field == field


def test_an_absurd_gap_is_an_input_error_naming_it():
    df = synthesize(SynthConfig(kind="viscous_power_W", n_samples=100), 0)
    df["gap_mm"] = 300.0
    with pytest.raises(InputError) as e:
        LoopEstimator(base="eq6").fit(df)
    assert e.value.field == "gap_mm" and "rotor radius" in str(e.value)


def test_an_implausible_partner_is_dropped_and_its_share_left_unexplained():
    # thermal lag 4 s + shear thinning in straight mineral oils: shear thinning is outside
    # its domain (no polymer-thickened liquid); the search without it may take in a delay
    # column the nonlinear refit sets to nothing, which the per-effect nonlinear margin then
    # drops. The thinning's share stays as unexplained structure instead of being forced
    # onto a name.
    est = _fit(SynthConfig(effects={"thermal_lag": 4.0, "shear_thinning": 7.5e-5}))
    assert [e.name for e in est.effects_] == ["thermal_lag"]
    # the thinning lowers the loss below Couette at the measured viscosity; with the Couette
    # floor (issue 27) no scale below it can take that share, so the scale is held at the
    # floor and the lag takes part of it: 3.55 s against 4 s (within 3 % before the floor)
    assert "bounded below" in est.identifiability_["scale"]
    assert est.effects_[0].coefficient == pytest.approx(4.0, rel=0.15)
    st = {c["name"]: c["status"] for c in est.candidates_}
    assert st["shear_thinning"].startswith("not a candidate: no polymer-thickened liquid")
    assert est.unexplained_ is not None
    for s in est.selection_log_:
        if s.step == "nonlinear prune":
            assert s.gain_pct < 10.0
