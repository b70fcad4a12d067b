"""The loop's ``film_heating`` effect: the film hotter than the measured temperature by
c P, c = s c_theory (issue 10, issue 18), its exact refit, its plausible range, both rigs
and the CLI."""

import math

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import brentq

from oilgap.cli import main
from oilgap.model.effects import EFFECTS, FluidFacts, RigFacts, film_temperature
from oilgap.model.io.case_io import seed_case
from oilgap.model.regions import joint_geometry
from oilgap.optim.calibration import LoopEstimator
from oilgap.studies.rigs.outside_rig import (
    TEST_STRENGTH,
    OutsideConfig,
    effect_size_W,
    inject,
    simulate,
)
from oilgap.studies.rigs.synth import DEFAULT_STRENGTH, SynthConfig, synthesize


def test_film_temperature_solves_the_fixed_point_like_a_bracketing_root_finder():
    # P(T) = P0 exp(-b (T - 20)): a Walther-like fall of 6 %/K; second method: brentq
    P0, b = np.array([50.0, 300.0, 600.0]), 0.06
    T = np.array([20.0, 25.0, 10.0])

    def power(t):
        return P0 * np.exp(-b * (t - 20.0))

    c = 0.05
    got = film_temperature(T, power, c)
    for k in range(3):
        ref = brentq(lambda x, k=k: x - T[k] - c * P0[k] * math.exp(-b * (x - 20.0)),
                     T[k], T[k] + c * P0[k] * 2 + 1)
        assert got[k] == pytest.approx(ref, abs=1e-8)
    assert np.all(got > T)
    assert np.array_equal(film_temperature(T, power, 0.0), T)


def test_feature_is_the_slope_of_the_exact_form_at_zero():
    # first order: P(T + c P) = P + c P dP/dT; the exact refit's power at a small c, by
    # difference, against the library feature
    df = synthesize(SynthConfig(n_samples=200), 0)
    est = LoopEstimator(base="eq6").fit(df)
    model = est.forward_model_
    law = est.law_with_T_
    ctx = model.context(law)
    f = EFFECTS["film_heating"].feature_values(ctx)
    c = 1e-6
    slope = (model.power(law, {"film_heating": c}) - model.power(law)) / c
    oil = np.abs(f) > 1e-3 * np.max(np.abs(f))
    # the feature's dP/dT is the data's own +-TEMP_STEP_K difference of the oil table: the
    # two agree to its truncation error (about 5e-4, at most 1 % where dP/dT is smallest)
    err = np.abs(slope[oil] / f[oil] - 1.0)
    assert np.median(err) < 1e-3 and np.max(err) < 2e-2
    assert np.all(f <= 0.0)  # a hotter film thins the oil: less loss


def test_plausible_range_is_the_film_strength_zero_to_one():
    # the coefficient is the film strength s: 1 is the smooth-film theory (the fit's bound)
    facts = RigFacts.of(joint_geometry(seed_case()), [FluidFacts("VG320", "mineral", False)])
    eff = EFFECTS["film_heating"]
    assert eff.upper == 1.0 and eff.unit == "-"
    assert eff.implausibility(DEFAULT_STRENGTH["film_heating"], facts) is None
    assert eff.implausibility(1.0, facts) is None
    assert eff.implausibility(1.01, facts) is not None
    assert eff.implausibility(-1e-3, facts) is not None
    assert eff.nonnegative and not eff.time_dependent  # a steady-point candidate too


def test_outside_rig_injects_film_heating_as_a_library_effect():
    cfg = inject(OutsideConfig(), film_heating=TEST_STRENGTH["film_heating"])
    # the same injection through the rig's older field
    old = OutsideConfig(film_heating_K_W=TEST_STRENGTH["film_heating"])
    size = effect_size_W(cfg)
    assert 4.0 < size < 7.0
    assert np.allclose(simulate(cfg)["measured_W"], simulate(old)["measured_W"])


def test_synth_cli_injects_film_heating(tmp_path, capsys):
    data = tmp_path / "rig.csv"
    assert main(["synth", "--effect", "film_heating", "--seed", "3", "--out", str(data)]) == 0
    assert "film_heating" in capsys.readouterr().err
    df = pd.read_csv(data)
    clean = synthesize(SynthConfig(), 3)
    assert len(df) == len(clean)
    # the heated film thins the oil: less power in every oil run, most in the heaviest
    diff = (df["power_W"] - clean["power_W"]).groupby(df["run"]).mean()
    assert diff["VG1000-T4"] < diff["VG150-T4"] < 0.0
