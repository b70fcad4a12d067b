"""The [uncertainty] table of a case file: read, refused key by key, written back; the
distributions' inverse CDFs against scipy.stats and their samples."""

from __future__ import annotations

import tomllib
from importlib import resources

import numpy as np
import pytest
from scipy import stats

from oilgap.model.errors import InputError
from oilgap.model.io.case_io import case_from_dict, seed_case
from oilgap.model.io.case_write import case_to_dict, dumps_toml
from oilgap.model.io.defaults import uncertainty_defaults
from oilgap.model.uncertain.distributions import (
    Distribution,
    UncertaintySpec,
    case_uncertainty,
)

TABLE = {
    "oil_temp_C": {"dist": "normal", "mean_C": 2.0, "sd_K": 1.5},
    "nu40_factor": {"dist": "uniform", "low": 0.9, "high": 1.1},
    "gamma": {"dist": "lognormal", "median": 0.566, "sigma_ln": 0.07, "source": "my fit"},
    "depth_m": {"dist": "triangular", "low_m": 2500.0, "mode_m": 3000.0, "high_m": 3500.0},
    "peak_speed_rpm": {"dist": "normal", "mean_rpm": 3000.0, "sd_rpm": 100.0},
}


def _doc(uncertainty=None, **tables):
    text = (resources.files("oilgap.model") / "data" / "seed_joint.toml").read_text()
    doc = tomllib.loads(text)
    doc.update(tables)
    if uncertainty is not None:
        doc["uncertainty"] = uncertainty
    return doc


def test_table_is_read_in_order_with_units_in_the_keys_and_written_back():
    case = case_from_dict(_doc(TABLE))
    spec = case.uncertainty
    assert spec.names == tuple(TABLE)
    assert spec["oil_temp_C"].params == (("mean", 2.0), ("sd", 1.5))
    assert spec["gamma"].source == "my fit" and spec["depth_m"]["mode"] == 3000.0
    text = dumps_toml(case_to_dict(case))
    assert "[uncertainty.oil_temp_C]" in text and "sd_K = 1.5" in text
    again = case_from_dict(tomllib.loads(text))
    assert again.uncertainty == spec
    assert case_uncertainty(case) is spec and uncertainty_defaults(case) == ()


def test_without_the_table_the_defaults_apply_with_their_sources():
    case = seed_case()
    assert case.uncertainty is None and "uncertainty" not in case_to_dict(case)
    spec = case_uncertainty(case)
    assert spec.names == ("nu40_factor", "nu100_factor", "gamma")
    assert spec["nu40_factor"].kind == "uniform"
    assert (spec["nu40_factor"]["low"], spec["nu40_factor"]["high"]) == (0.9, 1.1)
    assert "ISO 3448" in spec["nu40_factor"].source
    assert spec["gamma"].params == (("mean", 0.566), ("sd", 0.041))
    assert "smoothing" in spec["gamma"].source
    fields = [d.field for d in uncertainty_defaults(case)]
    assert (spec["nu100_factor"]["low"], spec["nu100_factor"]["high"]) == (0.95, 1.05)
    assert "D2270" in spec["nu100_factor"].source
    assert fields == ["uncertainty.nu40_factor", "uncertainty.nu100_factor",
                      "uncertainty.gamma"]


@pytest.mark.parametrize("table, field", [
    ({"gamma": {"dist": "normal", "mean": 0.5, "sd": 0.0}}, "uncertainty.gamma.sd"),
    ({"gamma": {"dist": "normal", "mean": 0.5, "sd": -1.0}}, "uncertainty.gamma.sd"),
    ({"nu40_factor": {"dist": "uniform", "low": 1.1, "high": 0.9}},
     "uncertainty.nu40_factor.low"),
    ({"depth_m": {"dist": "triangular", "low_m": 1.0, "mode_m": 5.0, "high_m": 3.0}},
     "uncertainty.depth_m.mode_m"),
    ({"gamma": {"dist": "lognormal", "median": -1.0, "sigma_ln": 0.1}},
     "uncertainty.gamma.median"),
    ({"viscosity": {"dist": "normal", "mean": 1.0, "sd": 0.1}}, "uncertainty"),
    ({"gamma": {"dist": "weibull"}}, "uncertainty.gamma.dist"),
    ({"oil_temp_C": {"dist": "normal", "mean": 2.0, "sd": 1.0}}, "uncertainty.oil_temp_C.mean"),
    ({"oil_temp_C": {"dist": "normal", "mean_C": 2.0}}, "uncertainty.oil_temp_C.sd_K"),
    ({"gamma": {"dist": "normal", "mean": 0.5, "sd": "x"}}, "uncertainty.gamma.sd"),
    ({"gamma": 3}, "uncertainty.gamma"),
    ({}, "uncertainty"),
    ({"film_strength": {"dist": "uniform", "low": 0.0, "high": 1.0}},
     "uncertainty.film_strength"),  # no [thermal]
    ({"bearing_drag_scale": {"dist": "uniform", "low": 0.5, "high": 2.0}},
     "uncertainty.bearing_drag_scale"),  # no [bearing]
    ({"gamma": {"dist": "normal", "mean": 0.1, "sd": 0.05}}, "uncertainty.gamma"),  # < 0
    ({"depth_m": {"dist": "uniform", "low_m": 9000.0, "high_m": 12000.0}}, "uncertainty.depth_m"),
])
def test_refusals_name_the_key(table, field):
    with pytest.raises(InputError) as e:
        case_from_dict(_doc(table))
    assert e.value.field == field


def test_film_strength_with_a_thermal_table_is_read():
    th = {"sea_temp_C": 2.0, "resistance_K_per_W": 0.5, "heat_capacity_J_per_K": 2000.0}
    case = case_from_dict(_doc({"film_strength": {"dist": "uniform", "low": 0.0,
                                                  "high": 1.0}}, thermal=th))
    assert case.uncertainty.names == ("film_strength",)


@pytest.mark.parametrize("d, ref", [
    (Distribution(input="gamma", kind="normal", params=(("mean", 0.5), ("sd", 0.05))),
     stats.norm(0.5, 0.05)),
    (Distribution(input="gamma", kind="lognormal", params=(("median", 0.5), ("sigma_ln", 0.1))),
     stats.lognorm(s=0.1, scale=0.5)),
    (Distribution(input="nu40_factor", kind="uniform", params=(("low", 0.9), ("high", 1.1))),
     stats.uniform(0.9, 0.2)),
    (Distribution(input="depth_m", kind="triangular",
                  params=(("low", 100.0), ("mode", 300.0), ("high", 1000.0))),
     stats.triang(c=200.0 / 900.0, loc=100.0, scale=900.0)),
])
def test_inverse_cdf_mean_and_sd_equal_scipy_stats(d, ref):
    u = np.linspace(0.001, 0.999, 101)
    np.testing.assert_allclose(d.ppf(u), ref.ppf(u), rtol=1e-12)
    assert d.mean == pytest.approx(ref.mean(), rel=1e-12)
    assert d.sd == pytest.approx(ref.std(), rel=1e-12)


def test_sample_is_balanced_and_a_correlation_is_kept():
    spec = UncertaintySpec(distributions=(
        Distribution(input="gamma", kind="normal", params=(("mean", 0.5), ("sd", 0.05))),
        Distribution(input="friction_scale", kind="lognormal",
                     params=(("median", 1.0), ("sigma_ln", 0.1)))),
        correlation=((1.0, -0.8), (-0.8, 1.0)))
    x = spec.sample(4096, seed=3)
    assert x["gamma"].mean() == pytest.approx(0.5, abs=1e-4)
    # the normal scores of the two inputs: gamma itself and ln(scale)
    r = np.corrcoef(x["gamma"], np.log(x["friction_scale"]))[0, 1]
    assert r == pytest.approx(-0.8, abs=0.01)
    a, b = spec.sample(64, seed=3), spec.sample(64, seed=3)
    np.testing.assert_array_equal(a["gamma"], b["gamma"])
    with pytest.raises(InputError, match="positive definite"):
        UncertaintySpec(distributions=spec.distributions,
                        correlation=((1.0, 1.2), (1.2, 1.0)))
