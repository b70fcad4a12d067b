"""The uncertainty study against closed forms: lognormal percentiles of a loss linear in
nu, and the Sobol' indices of the Ishigami function and of a linear model."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy import stats

from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InputError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.uncertain.distributions import Distribution, UncertaintySpec
from oilgap.model.uncertain.inputs import apply_inputs
from oilgap.studies.settings import UncertaintySettings
from oilgap.studies.uncertainty import run
from oilgap.studies.uncertainty.indices import sobol_indices
from oilgap.studies.uncertainty.study import mode_why, study_mode


def _laminar_case():
    """The seed without region 2 and without a bearing: region 1 alone, laminar at every
    speed (Re_peak 27 < 55.9) with the exact Couette C_m, so that its loss is
    mu omega^2 R^3 L ... : linear in the viscosity (tests/model/test_scenario.py)."""
    return replace(seed_case(), region2=None, bearing=None)


def test_percentiles_of_a_loss_linear_in_nu_are_the_lognormal_ones():
    # P = P0 * f with f ~ lognormal(median 1, sigma_ln 0.1): P's p-quantile is
    # P0 exp(0 + 0.1 z_p) (a monotone map keeps quantiles), z_p the normal quantile.
    case = _laminar_case()
    p0 = evaluate_case(case).total_mean_power_W  # the scalar path, not the study's
    sigma = 0.1
    spec = UncertaintySpec(distributions=(Distribution(
        input="nu_factor_all_temperatures", kind="lognormal",
        params=(("median", 1.0), ("sigma_ln", sigma))),))
    r = run(None, case, UncertaintySettings(samples=4096, sobol=False), spec)
    law = stats.lognorm(s=sigma, scale=p0)
    for name, q in (("p5", 0.05), ("p50", 0.5), ("p95", 0.95)):
        # by hand: exp(sigma z_q); a scrambled Sobol' sample puts one point in each
        # 1/4096 of [0, 1], so the empirical quantile is within ~1/4096 of q
        assert law.ppf(q) == pytest.approx(p0 * math.exp(sigma * stats.norm.ppf(q)))
        assert r.statistic(name) == pytest.approx(law.ppf(q), rel=1e-3)
    assert r.statistic("mean") == pytest.approx(p0 * math.exp(sigma**2 / 2), rel=1e-3)
    assert r.nominal_W == pytest.approx(p0, rel=1e-12)
    # the tornado: the loss at the factor's own 5th/95th percentiles, exactly
    t = r.tornado.iloc[0]
    assert t["loss_low_W"] == pytest.approx(law.ppf(0.05), rel=1e-9)
    assert t["loss_high_W"] == pytest.approx(law.ppf(0.95), rel=1e-9)


def _ishigami(u: np.ndarray, a: float = 7.0, b: float = 0.1) -> np.ndarray:
    x = -np.pi + 2.0 * np.pi * u  # x_i ~ U(-pi, pi)
    return np.sin(x[:, 0]) + a * np.sin(x[:, 1]) ** 2 + b * x[:, 2] ** 4 * np.sin(x[:, 0])


def test_sobol_indices_of_the_ishigami_function():
    # Ishigami & Homma (1990); Saltelli et al., Global Sensitivity Analysis. The Primer
    # (2008), sec. 4.x: with x_i ~ U(-pi, pi),
    #   V   = a^2/8 + b pi^4/5 + b^2 pi^8/18 + 1/2
    #   V1  = (1 + b pi^4/5)^2 / 2,   V2 = a^2/8,   V3 = 0
    #   V13 = b^2 pi^8 (1/18 - 1/50) (the only interaction)
    # S_i = V_i/V, ST1 = (V1 + V13)/V, ST2 = S2, ST3 = V13/V.
    a, b, pi = 7.0, 0.1, math.pi
    V = a**2 / 8 + b * pi**4 / 5 + b**2 * pi**8 / 18 + 0.5
    V1, V2, V13 = (1 + b * pi**4 / 5) ** 2 / 2, a**2 / 8, b**2 * pi**8 * (1 / 18 - 1 / 50)
    S1 = [V1 / V, V2 / V, 0.0]
    ST = [(V1 + V13) / V, V2 / V, V13 / V]
    assert np.allclose(S1, [0.3139, 0.4424, 0.0], atol=1e-4)  # the published values
    assert np.allclose(ST, [0.5576, 0.4424, 0.2437], atol=1e-4)
    si = sobol_indices(_ishigami, ["x1", "x2", "x3"], 2**13, seed=1)
    np.testing.assert_allclose(si["S1"], S1, atol=0.03)
    np.testing.assert_allclose(si["ST"], ST, atol=0.03)
    assert (si["S1_low"] < si["S1"]).all() and (si["S1"] < si["S1_high"]).all()
    assert (si["ST_high"] - si["ST_low"] < 0.1).all()
    assert (si["evaluations"] == 2**13 * 5).all()


def test_sobol_indices_of_a_linear_model_through_the_inputs_laws():
    # y = sum a_i x_i, x_i ~ N(mu_i, sigma_i) independent: V = sum a_i^2 sigma_i^2 and
    # S_i = ST_i = a_i^2 sigma_i^2 / V (no interaction). Here (40*0.05)^2 = 4,
    # (1.5*2)^2 = 9, (0.01*100)^2 = 1: S = 4/14, 9/14, 1/14.
    spec = UncertaintySpec(distributions=(
        Distribution(input="gamma", kind="normal", params=(("mean", 0.5), ("sd", 0.05))),
        Distribution(input="oil_temp_C", kind="normal", params=(("mean", 5.0), ("sd", 2.0))),
        Distribution(input="depth_m", kind="normal", params=(("mean", 3000.0), ("sd", 100.0))),
    ))
    a = {"gamma": 40.0, "oil_temp_C": 1.5, "depth_m": 0.01}

    def linear(u):
        x = spec.transform(u)
        return sum(a[k] * x[k] for k in a)

    si = sobol_indices(linear, spec.names, 2**12, seed=2)
    expected = np.array([4.0, 9.0, 1.0]) / 14.0
    np.testing.assert_allclose(si["S1"], expected, atol=0.02)
    np.testing.assert_allclose(si["ST"], expected, atol=0.02)


def test_seed_study_numbers_hold_together():
    r = run(None, seed_case(), UncertaintySettings(samples=256, sobol_samples=64))
    s = r.statistics.set_index("statistic")["loss_W"]
    assert s["p5"] < s["p50"] < s["p95"]
    assert r.samples["loss_W"].min() <= s["p5"] and s["p95"] <= r.samples["loss_W"].max()
    assert set(r.sobol["input"]) == {"nu40_factor", "nu100_factor", "gamma"} and r.failed == 0
    # the sample's inputs follow their laws: uniform 0.9..1.1 mean 1, gamma mean 0.566
    assert r.samples["nu40_factor"].mean() == pytest.approx(1.0, abs=1e-3)
    assert r.samples["gamma"].mean() == pytest.approx(0.566, abs=2e-3)


def test_film_strength_runs_under_the_film_counterpart_of_the_default_mode():
    case = seed_case()
    fs = UncertaintySpec(distributions=(Distribution(
        input="film_strength", kind="uniform", params=(("low", 0.0), ("high", 1.0))),))
    assert study_mode(case, fs, None) == ("film", True)
    with pytest.raises(InputError, match="film or full"):
        study_mode(case, fs, "none")
    no_film = UncertaintySpec(distributions=(Distribution(
        input="gamma", kind="normal", params=(("mean", 0.566), ("sd", 0.041))),))
    assert study_mode(case, no_film, None) == ("none", True)


def test_settings_refuse_what_is_not_a_power_of_two():
    with pytest.raises(InputError, match="samples"):
        UncertaintySettings(samples=1000)
    with pytest.raises(InputError, match="confidence"):
        UncertaintySettings(confidence=1.5)


def test_zero_film_strength_under_the_film_counterpart_is_the_default_mode():
    # the documented reading of "between none and the smooth-film theory": s = 0 under
    # film (full) is the isothermal film at the oil (bulk) temperature, by the scalar path
    th = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5e4)
    case = replace(seed_case(), thermal=th)
    s0 = apply_inputs(case, {"film_strength": 0.0})
    for default, film in (("none", "film"), ("bulk", "full")):
        assert evaluate_case(s0, thermal=film).total_mean_power_W == pytest.approx(
            evaluate_case(case, thermal=default).total_mean_power_W, rel=1e-9)
    spec = UncertaintySpec(distributions=(Distribution(
        input="film_strength", kind="uniform", params=(("low", 0.0), ("high", 1.0))),))
    assert study_mode(case, spec, None) == ("full", True)
    assert "s = 0 gives bulk" in mode_why(case, spec, "full", True)


def test_intervals_repeat_with_the_same_seed():
    # SALib leaves its bootstrap unseeded for seed 0: the study's must not be
    a = sobol_indices(_ishigami, ["x1", "x2", "x3"], 256, seed=0)
    b = sobol_indices(_ishigami, ["x1", "x2", "x3"], 256, seed=0)
    np.testing.assert_array_equal(a[["S1_low", "ST_high"]], b[["S1_low", "ST_high"]])
