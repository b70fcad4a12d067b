"""Stage 4, residual structure: noise level, correlation ratio, autocorrelation."""

import math

import numpy as np
import pytest

from oilgap.optim.calibration import (
    autocorrelation,
    describe_structure,
    noise_estimate,
    residual_structure,
    unexplained_structure,
)


def test_noise_estimate_of_white_noise_of_known_sigma():
    rng = np.random.default_rng(1)
    code = np.repeat(np.arange(4), 5000)
    res = rng.normal(0.0, 0.7, code.size)
    # the estimate's relative standard error is about sqrt(3/2 / n) < 1 %
    assert noise_estimate(res, code) == pytest.approx(0.7, rel=0.03)


def test_noise_estimate_ignores_slow_structure_and_jumps_between_runs():
    # a constant offset per run: no within-run difference, no noise
    code = np.repeat([0, 1, 2], 4)
    res = np.repeat([1.0, 10.0, -3.0], 4)
    assert noise_estimate(res, code) == 0.0
    # hand computation: differences (1, -1) in run 0, (2) in run 1 -> (1 + 1 + 4) / (2 * 3)
    assert noise_estimate(np.array([0.0, 1.0, 0.0, 5.0, 7.0]), np.array([0, 0, 0, 1, 1])) \
        == pytest.approx(1.0)


def test_autocorrelation_by_hand():
    # one run (1, -1, 1, -1): mean 0, lag-1 products sum -3, squares sum 4
    assert autocorrelation(np.array([1.0, -1, 1, -1]), np.zeros(4, int), 1) == -0.75
    # two runs, each centred on its own mean: (0, 2) -> (-1, 1); (5, 5, 8) -> (-1, -1, 2)
    r = np.array([0.0, 2.0, 5.0, 5.0, 8.0])
    c = np.array([0, 0, 1, 1, 1])
    assert autocorrelation(r, c, 1) == pytest.approx((-1 + 1 - 2) / (2 + 6))
    assert autocorrelation(np.zeros(4), np.zeros(4, int), 1) == 0.0


def test_autocorrelation_of_an_ar1_process():
    rng = np.random.default_rng(2)
    e = rng.normal(size=20000)
    r = np.empty_like(e)
    r[0] = e[0]
    for k in range(1, len(e)):
        r[k] = 0.8 * r[k - 1] + e[k]
    code = np.zeros(len(r), int)
    assert autocorrelation(r, code, 1) == pytest.approx(0.8, abs=0.02)
    assert autocorrelation(r, code, 2) == pytest.approx(0.64, abs=0.03)


def test_step_residual_has_eta2_one_against_the_speed_sign(samples_factory):
    s = samples_factory()
    # 5/12 of the samples run backwards, so the sign change is an edge of the 12 quantile
    # bins: the bin means reproduce the step and explain all of its variance
    assert np.mean(s.speed_rpm < 0) == 5 / 12
    res = np.where(s.speed_rpm > 0, 2.0, -1.0)
    rs = residual_structure(res, s)
    v = rs["variables"]["speed_rpm"]
    assert v["eta2"] == pytest.approx(1.0, abs=1e-12)
    assert v["pearson_r"] > 0.5
    assert set(np.round(v["bin_means_W"], 12)) <= {2.0, -1.0}
    assert rs["rmse_W"] == pytest.approx(math.sqrt(np.mean(res ** 2)))


def test_eta2_by_hand_on_two_levels(samples_factory):
    s = samples_factory(runs=(("a", "VG150", 4.0),), n=6)
    t = np.array([0.0, 0, 0, 1, 1, 1])
    s = type(s)(**{**{k: getattr(s, k) for k in s.__dataclass_fields__}, "time_s": t})
    res = np.array([1.0, 2, 3, 7, 8, 9])
    v = residual_structure(res, s, bins=2)["variables"]["time_s"]
    # group means 2 and 8 around 5: between 3*9 + 3*9 = 54 of a total 16+9+4+4+9+16 = 58
    assert v["eta2"] == pytest.approx(54 / 58, rel=1e-12)
    assert v["bin_means_W"] == pytest.approx([2.0, 8.0]) and v["bin_centres"] == [0.0, 1.0]


def test_structured_fraction_and_unexplained_report(samples_factory):
    s = samples_factory()
    rng = np.random.default_rng(3)
    noise = rng.normal(0, 1.0, s.n)
    white = residual_structure(noise, s)
    assert white["structured_fraction"] < 0.1
    assert unexplained_structure(white) is None
    drift = noise + 3.0 * s.time_s / s.time_s.max()
    rs = residual_structure(drift, s)
    assert rs["structured_fraction"] > 0.5
    u = unexplained_structure(rs)
    assert u["correlates_with"][0]["variable"] == "time_s"
    assert [d["eta2"] for d in u["correlates_with"]] == sorted(
        (d["eta2"] for d in u["correlates_with"]), reverse=True)
    assert u["description"].endswith(describe_structure(rs))
    assert "time_s (eta^2 = " in describe_structure(rs)
