"""Residuals described when no effect fits (issue 25 item 4): where the residual sits (oil,
run, roughness) and how it scales (a power law in |omega|, nu, rho with intervals), checked
on residuals whose answer is known by construction, and the loop's report on a rig whose
oil is off its grade."""

import warnings

import numpy as np
import pytest

from oilgap.model.errors import OilgapWarning
from oilgap.model.units import rpm_to_rad_s
from oilgap.optim.calibration import LoopEstimator
from oilgap.optim.calibration.residual_story import (
    describe_residual,
    how_it_scales,
    where_it_sits,
)
from oilgap.studies.loop.report import format_summary
from oilgap.studies.rigs.synth import SynthConfig, synthesize


@pytest.fixture(scope="module")
def rig():
    return synthesize(SynthConfig(n_samples=200, kind="viscous_power_W"), 0)


@pytest.fixture(scope="module")
def samples(rig):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        return LoopEstimator(base="eq6", effects=[]).fit(rig).samples_


def test_an_omega_cubed_residual_is_named_inertial(samples):
    w = np.abs(samples.omega)
    rng = np.random.default_rng(1)
    res = 4e-7 * w**3 + 0.05 * rng.standard_normal(w.size)
    sc = how_it_scales(res, samples)
    a, b = sc["exponents"]["omega"], sc["exponents"]["nu"]
    assert a["ci95"][0] < 3.0 < a["ci95"][1] and abs(a["value"] - 3.0) < 0.05
    assert b["ci95"][0] < 0.0 < b["ci95"][1]
    assert sc["exponents"]["rho"]["value"] is None    # mineral oils: rho hardly varies
    d = describe_residual(res, samples, 0.05)
    assert d["mechanism"].endswith("an inertial loss (churning, windage): grows as omega^3 "
                                   "and does not depend on nu")


def test_a_viscous_residual_is_named_laminar_shear(samples):
    w, nu = np.abs(samples.omega), samples.nu_m2_s
    res = 30.0 * w**2 * nu
    d = describe_residual(res, samples, 1e-3)
    assert "laminar viscous shear" in d["mechanism"]


def test_one_oil_carries_the_residual(samples):
    oil = np.asarray(samples.oil)
    res = np.where(oil == "VG320", 5.0, 0.0) + 0.01 * np.sin(np.arange(oil.size))
    wh = where_it_sits(res, samples, 0.01)
    top = wh["by"]["oil"]["groups"][0]
    assert top["group"] == "VG320" and top["share"] == pytest.approx(1.0, abs=0.01)
    # hand check: the share is n_g m_g^2 / sum r^2
    n = int((oil == "VG320").sum())
    assert top["share"] == pytest.approx(n * np.mean(res[oil == "VG320"]) ** 2
                                         / np.sum(res**2), rel=1e-12)
    assert set(wh["standout_runs"]) == set(np.asarray(samples.run_names)[
        np.unique(samples.run_code[oil == "VG320"])])
    assert "VG320" in describe_residual(res, samples, 0.01)["mechanism"]
    assert "off its grade" in describe_residual(res, samples, 0.01)["mechanism"]


def test_the_loop_reports_where_and_how_when_no_effect_fits(rig):
    w = rpm_to_rad_s(rig["speed_rpm"].to_numpy())
    data = rig.assign(viscous_power_W=rig["viscous_power_W"] + 4e-7 * np.abs(w) ** 3)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        est = LoopEstimator(base="eq6", effects=[]).fit(data)
    d = est.unexplained_["described"]
    assert set(d["where"]["by"]) == {"oil", "run", "roughness_T"}
    assert d["scaling"]["exponents"]["omega"]["ci95"] is not None
    assert any(t.startswith("points to:") for t in d["text"])
    assert "            points to: " in format_summary(est)
