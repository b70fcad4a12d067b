"""The loop's ``"branches"`` base: which C_k, alpha_k, beta_k the data free, the held ones
at Eq. 6's published values with the reason, and the calibration recovering a known law."""

from dataclasses import replace
from functools import cache

import numpy as np
import pandas as pd
import pytest

from oilgap.model.io.case_io import seed_case
from oilgap.model.regions import joint_geometry
from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration import LoopEstimator, decide_spec
from oilgap.optim.calibration.spec import BRANCH_PARAMS
from oilgap.studies.rigs.synth import SynthConfig, synthesize

PUBLISHED = {"scale": 1.0, "C1": 10.0, "C2": 2.0, "C3": 1.03, "C4": 0.065,
             **{f"alpha{k}": 0.3 for k in range(1, 5)},
             "beta1": -1.0, "beta2": -0.6, "beta3": -0.5, "beta4": -0.2}


def test_one_gap_frees_no_alpha_and_says_why(samples_factory):
    case = seed_case()
    spec, stmt = decide_spec(samples_factory(), joint_geometry(case), case, "branches")
    assert spec.base == "branches" and spec.params == BRANCH_PARAMS
    assert not any(k.startswith("alpha") for k in spec.free)
    # viscous oil at the seed's gap: the Couette bound governs region 1, no branch does,
    # so only the level (scale) and gamma are fitted
    assert spec.free == ("scale", "gamma") and "Couette bound governs" in stmt["scale"]
    for k in BRANCH_PARAMS[:-1]:
        assert k in stmt
        if k not in spec.free:
            assert spec.fixed[k] == PUBLISHED[k] and "held at" in stmt[k]
    law = spec.law(spec.start({**PUBLISHED, "gamma": 0.5}))
    assert law.form == "branches" and law.branch_C == (10.0, 2.0, 1.03, 0.065)
    assert law.laminar_law == case.friction.laminar_law


def _three_gap_data(truth: FrictionLaw) -> pd.DataFrame:
    # the seed rig at 1.0, 1.5 and 2.2 mm with thin, warm oil: region 1 reaches Re ~ 90-1600,
    # Eq. 6's branches 2 and 3; branches 1 and 4 govern no sample
    base = seed_case()
    frames = []
    for gap_mm in (1.0, 1.5, 2.2):
        r1 = base.region1
        d = gap_mm * 1e-3 - r1.gap
        case = replace(base, region1=replace(r1, T3=r1.T3 + d, T4=r1.T4 + d,
                                             T4_unfilled=r1.T4 + d))
        df = synthesize(SynthConfig(case=case, oils=("VG22", "VG32"), kind="viscous_power_W",
                                    n_samples=150, truth=truth, ambient_C=60.0,
                                    noise_power_W=0.02), seed=int(10 * gap_mm))
        df["run"] = df["run"] + f"-g{gap_mm:g}"
        df["gap_mm"] = gap_mm
        frames.append(df)
    return pd.concat(frames, ignore_index=True)


@cache
def _fit_published():
    truth = FrictionLaw(form="branches", gamma=seed_case().friction.gamma)
    return LoopEstimator(base="branches", cv="one-step").fit(_three_gap_data(truth))


def test_three_gaps_recover_the_published_branches_and_hold_the_rest():
    est = _fit_published()
    cal, ident = est.calibration_, est.identifiability_
    for k in ("C2", "C3", "alpha2", "alpha3", "beta2", "beta3"):
        assert ident[k].startswith("identified"), (k, ident[k])
    for k in ("scale", "C1", "alpha1", "beta1", "C4", "alpha4", "beta4"):
        assert "held at" in ident[k] and cal[k] == PUBLISHED[k], k
        assert est.calibration_ci_[k] == "fixed"
    # the data were made with Eq. 6's branches: the fit finds them (noise 0.02 W)
    for k in ("alpha2", "alpha3", "beta2", "beta3"):
        assert cal[k] == pytest.approx(PUBLISHED[k], abs=0.03), k
    assert cal["C2"] == pytest.approx(2.0, rel=0.1)
    assert est.law_with_T_.form == "branches"
    assert est.heldout_rmse_["before"] < 0.05


def test_loop_json_names_the_base_and_the_held_parameters():
    doc = _fit_published().to_dict()
    assert doc["base"] == "branches"
    text = str(doc)
    assert "branch 4 governs 0 sample(s)" in text
    assert np.isfinite(doc["calibration"]["alpha2"])
