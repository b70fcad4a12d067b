"""Evaluation of a case region by region: regions, overrides, warnings."""

import warnings

import pytest

from oilgap.model.errors import OilgapWarning
from oilgap.model.evaluation import (
    evaluate_case,
    mean_viscous_power,
    oil_state,
    region_powers,
)
from oilgap.model.io.case_io import read_case_toml, seed_case


def test_smoothing_lowers_loss_only_in_region1():
    a = evaluate_case(seed_case())
    b = evaluate_case(seed_case(smoothed=True))
    assert b.regions[0].mean_power_W < a.regions[0].mean_power_W
    assert b.regions[1].mean_power_W == a.regions[1].mean_power_W


def test_untrusted_temperature_warns():
    with pytest.warns(OilgapWarning, match="oil_temp_C"):
        evaluate_case(seed_case(), oil_temp_C=-35.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        evaluate_case(seed_case(), oil_temp_C=2.0)


def test_rig_without_region2(seed_toml, write_file):
    toml = seed_toml.replace("[region2]\nradius_mm = 22.0\nlength_mm = 14.24\ngap_mm = 5.0\n",
                             "")
    case = read_case_toml(write_file(toml))
    assert case.region2 is None
    ev = evaluate_case(case)
    full = evaluate_case(read_case_toml(write_file(seed_toml, "full.toml")))
    assert len(ev.regions) == 1
    assert ev.total_mean_power_W == pytest.approx(full.regions[0].mean_power_W, rel=1e-14)


def test_totals_are_consistent():
    case = seed_case()
    ev = evaluate_case(case, thermal="none")
    assert ev.total_mean_power_W == pytest.approx(sum(r.mean_power_W for r in ev.regions),
                                                  rel=1e-14)
    assert ev.total_mean_power_W == pytest.approx(mean_viscous_power(case), rel=1e-14)
    # energy over the 300 s cycle: mean power times duration
    assert ev.cycle_energy_J == pytest.approx(ev.total_mean_power_W * 300.0, rel=1e-14)
    assert ev.viscous_torque_peak_Nm == pytest.approx(
        sum(r.torque_peak_Nm for r in ev.regions), rel=1e-14)
    d = ev.to_dict()
    assert d["regions"][0]["regimes"] == list(ev.regions[0].regimes)


def test_region_powers_and_overrides():
    case = seed_case()
    nu, mu, rho = oil_state(case, 40.0, 0.0)
    assert mu == pytest.approx(nu * rho, rel=1e-14)
    p = region_powers(case, 100.0, nu, rho)
    assert set(p) == {"rotor-stator", "bearing"}
    ev = evaluate_case(case, oil_temp_C=40.0, depth_m=0.0, laminar_law="bilgen-boulos")
    assert (ev.oil_temp_C, ev.depth_m, ev.laminar_law) == (40.0, 0.0, "bilgen-boulos")
    # colder oil, more loss
    assert mean_viscous_power(case, 2.0) > mean_viscous_power(case, 40.0)
