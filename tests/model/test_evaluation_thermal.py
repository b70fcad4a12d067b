"""``evaluate_case`` under the thermal modes none, film and full, against independent numbers.

* film: Na = b mu U^2/k with b from a finite difference of ln mu, the closed form
  Phi = acosh(1+z)/sqrt(z(2+z)) and the rise ln(1 + z/2)/b written out here, on a
  constant-speed duty cycle (one node, so the cycle's lag gain plays no role);
* full: the reported oil temperature satisfies T = T_sea + R (P(T) + Q) with P
  recomputed at that T, equals the steady state of the transient ODE run long, and
  the generic fixed-point solver of model.thermal;
* none: today's numbers, exactly (the golden ``evaluate --thermal none --json`` outputs,
  checked equal to the outputs recorded before the thermal modes existed).
"""

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InputError
from oilgap.model.evaluation import evaluate_case, oil_state
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.io.serialize import plain
from oilgap.model.joint_loss import joint_mean_power, operating_temperature
from oilgap.model.oils import get_oil
from oilgap.model.thermal import joint_steady_temperature, joint_temperature_transient

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "data"

CONSTANT_SPEED = """
name = "constant-speed film"
[region1]
T1_mm = 25.0
T2_mm = 25.0
T3_mm = 26.0
T4_mm = 26.0
length_mm = 20.0
[oil]
name = "VG46"
[operating]
depth_m = 0.0
oil_temp_C = 5.0
[duty_cycle]
csv = "cycle.csv"
"""
"""A smooth 25 mm rotor, 1 mm gap, in VG46 at 5 degC and the surface, at 1500 rpm."""

THERMAL = """
[thermal]
sea_temp_C = 4.0
resistance_K_per_W = 0.8
heat_capacity_J_per_K = 3.0e4
other_heat_W = 5.0
"""


def constant_speed_case(write_file):
    write_file("time_s,speed_rpm\n0,1500\n10,1500\n20,1500\n", "cycle.csv")
    return read_case_toml(write_file(CONSTANT_SPEED))


def test_film_mode_by_hand(write_file):
    case = constant_speed_case(write_file)
    film = evaluate_case(case, thermal="film")
    none = evaluate_case(case)  # no [thermal]: the default is none (the seed's Table 4)
    assert (film.thermal_mode, film.thermal_mode_default) == ("film", False)
    assert (none.thermal_mode, none.thermal_mode_default) == ("none", True)
    assert (film.film_applied, none.film_applied) == (True, False)
    assert film.sea_temp_C is None and film.oil_temp_C == 5.0
    R, gap, k = 0.025, 0.001, 0.13
    omega = 1500 * 2 * math.pi / 60
    nu, mu, rho = oil_state(case, 5.0, 0.0)
    dT = 1e-3  # b = -d ln(mu)/dT by a central difference of the oil's own law
    b = -(math.log(oil_state(case, 5.0 + dT, 0.0)[1])
          - math.log(oil_state(case, 5.0 - dT, 0.0)[1])) / (2 * dT)
    na = b * mu * (omega * R) ** 2 / k
    na_eff = na * (1 + gap / R)  # curvature of the circular film, isothermal walls
    z = na_eff / 4
    phi = math.acosh(1 + z) / math.sqrt(z * (2 + z))
    ta = omega * R * gap / nu * math.sqrt(gap / R)
    weight = 1 / (1 + (ta / 41.3) ** 10)  # 1 - logistic(10 ln(Ta/Ta_c)): laminar share
    factor = 1 - weight * (1 - phi)
    assert 2.0 < na < 6.0 and ta < 10 and 0.7 < factor < 0.9  # a real correction
    for ev in (film, none):  # none reports the same film, not applied
        r = ev.regions[0]
        assert r.nahme_peak == pytest.approx(na, rel=1e-6)
        # one speed: no lag, so the effective Na is the curvature-corrected one and the
        # steady Phi is the factor before the (here negligible) Taylor fade
        assert r.nahme_effective_peak == pytest.approx(na_eff, rel=1e-6)
        assert r.film_factor_steady_peak == pytest.approx(phi, rel=1e-6)
        assert r.film_factor_effective_peak == pytest.approx(factor, rel=1e-6)
        assert r.film_temp_rise_peak_K == pytest.approx(math.log(1 + z / 2) / b, rel=1e-6)
    assert film.regions[0].film_factor_applied_peak == pytest.approx(factor, rel=1e-6)
    assert none.regions[0].film_factor_applied_peak == 1.0
    assert (film.regions[0].film_applied, none.regions[0].film_applied) == (True, False)
    # each reports the other as its film band
    assert none.film_band.other_mode == "film" and film.film_band.other_mode == "none"
    assert none.film_band.other_mean_power_W == pytest.approx(film.total_mean_power_W,
                                                              rel=1e-12)
    assert film.film_band.other_mean_power_W == pytest.approx(none.total_mean_power_W,
                                                              rel=1e-12)
    assert film.regions[0].mean_power_W == pytest.approx(
        factor * none.regions[0].mean_power_W, rel=1e-6)
    assert film.regions[0].torque_peak_Nm == pytest.approx(
        factor * none.regions[0].torque_peak_Nm, rel=1e-6)
    assert film.isothermal_total_mean_power_W == none.total_mean_power_W
    assert none.isothermal_total_mean_power_W == none.total_mean_power_W
    for key in ("Re_peak", "Ta_peak", "Cm_peak"):  # at the same (operating) temperature
        assert getattr(film.regions[0], key) == getattr(none.regions[0], key)


def hot_case(seed_toml, write_file):
    return read_case_toml(write_file(seed_toml + THERMAL, "hot.toml"))


def test_full_mode_solves_the_heat_balance(seed_toml, write_file):
    case = hot_case(seed_toml, write_file)
    ev = evaluate_case(case, thermal="full")
    spec = case.thermal
    assert (ev.thermal_mode, ev.thermal_mode_default, ev.sea_temp_C) == ("full", False, 4.0)
    assert (ev.resistance_K_per_W, ev.other_heat_W) == (0.8, 5.0)
    t = ev.oil_temp_C
    p = float(joint_mean_power(case, t, "film"))  # the loss recomputed at that T
    assert t - spec.sea_temp_C - spec.resistance_K_W * (p + spec.other_heat_W) == \
        pytest.approx(0.0, abs=1e-8)
    assert ev.total_mean_power_W == pytest.approx(p, rel=1e-10)
    # the reported oil state and film are those at the operating temperature
    at_t = evaluate_case(case, oil_temp_C=t, thermal="film")
    assert ev.nu_cSt == at_t.nu_cSt
    for a, c in zip(ev.regions, at_t.regions, strict=True):
        assert a.mean_power_W == pytest.approx(c.mean_power_W, rel=1e-10)
        assert (a.nahme_peak, a.film_factor_applied_peak, a.Re_peak) == \
            (c.nahme_peak, c.film_factor_applied_peak, c.Re_peak)
    # the isothermal model at the case's own 40 degC
    assert ev.isothermal_total_mean_power_W == \
        evaluate_case(case, thermal="none").total_mean_power_W
    # the steady state of C dT/dt = P(T) + Q - (T - T_sea)/R, run 40 time constants
    tau = spec.resistance_K_W * spec.heat_capacity_J_K
    traj = joint_temperature_transient(
        lambda _s, temp: float(joint_mean_power(case, temp, "film")), spec,
        [0.0, 40 * tau], spec.sea_temp_C)
    assert traj[-1] == pytest.approx(t, abs=1e-6)
    # and the generic safeguarded Newton of model.thermal
    temps, _ = joint_steady_temperature(
        lambda ts: np.asarray(joint_mean_power(case, ts, "film"), dtype=float), spec, 1)
    assert temps[0] == pytest.approx(t, abs=1e-9)


def test_bulk_is_the_default_with_thermal(seed_toml, write_file):
    case = hot_case(seed_toml, write_file)
    ev = evaluate_case(case)
    spec = case.thermal
    assert (ev.thermal_mode, ev.thermal_mode_default, ev.sea_temp_C) == ("bulk", True, 4.0)
    assert not ev.film_applied and all(r.film_factor_applied_peak == 1.0 for r in ev.regions)
    t = ev.oil_temp_C
    p = float(joint_mean_power(case, t, "none"))  # the isothermal loss at that T
    assert t - spec.sea_temp_C - spec.resistance_K_W * (p + spec.other_heat_W) == \
        pytest.approx(0.0, abs=1e-8)
    assert ev.total_mean_power_W == pytest.approx(p, rel=1e-10)
    # its band is full, the same design with the film correction on the same balance
    full = evaluate_case(case, thermal="full")
    assert ev.film_band.other_mode == "full"
    assert ev.film_band.other_mean_power_W == pytest.approx(full.total_mean_power_W, rel=1e-12)
    assert ev.film_band.other_oil_temp_C == pytest.approx(full.oil_temp_C, abs=1e-12)
    assert full.film_band.other_mean_power_W == pytest.approx(ev.total_mean_power_W, rel=1e-12)


@pytest.mark.parametrize("oil,sea,resistance,other,walls", [
    ("VG22", 2.0, 2.0, 0.0, "isothermal-walls"), ("VG1000", -1.0, 5.0, 20.0, "isothermal-walls"),
    ("VG1000", 2.0, 50.0, 0.0, "isothermal-walls"), ("VG10", 2.0, 1e-3, 0.0, "isothermal-walls"),
    ("VG22", 2.0, 0.5, 0.0, "adiabatic-rotor"), ("VG10", -30.0, 0.05, 0.0, "adiabatic-rotor"),
    ("VG1000", -30.0, 0.02, 0.0, "adiabatic-rotor")])
def test_balance_agrees_with_the_generic_solver(oil, sea, resistance, other, walls):
    """Far from the seed: hot balances, a root beyond the fast path's bracket (R = 50 K/W),
    a balance barely above the sea (R = 1e-3 K/W), insulated rotors in cold oil (where the
    film-corrected loss can rise with T; the last case leaves the fast path)."""
    case = replace(seed_case(), oil=get_oil(oil),
                   thermal=ThermalSpec(sea, resistance, 5e4, other, walls))
    op = operating_temperature(case, "full")
    temps, _ = joint_steady_temperature(
        lambda ts: np.asarray(joint_mean_power(case, ts, "full"), dtype=float),
        case.thermal, 1)
    p = float(joint_mean_power(case, op.oil_temp_C, "full"))
    assert op.oil_temp_C - sea - resistance * (p + other) == pytest.approx(0.0, abs=1e-9)
    assert op.oil_temp_C == pytest.approx(temps[0], abs=2e-9)  # both to |g| < 1e-9 K
    assert op.mean_power_W == pytest.approx(p, rel=1e-10)
    assert sum(op.region_mean_powers_W) == pytest.approx(op.mean_power_W, rel=1e-14)


@pytest.mark.parametrize("name,kwargs", [
    ("evaluate_none.json", {}),
    ("evaluate_smoothed_bb_none.json", {"laminar_law": "bilgen-boulos"})])
def test_none_reproduces_the_golden_numbers(name, kwargs):
    old = json.loads((GOLDEN / name).read_text())
    case = seed_case(smoothed="smoothed" in name)
    new = plain(evaluate_case(case, thermal="none", **kwargs).to_dict())  # as written
    for key, value in old.items():
        if key not in ("regions", "gamma", "gamma_source", "defaults",
                       "groove_band"):  # the CLI adds these
            assert new[key] == value, key
    renamed = {"film_factor_peak": "film_factor_effective_peak"}  # issue 18: honest labels
    for r_old, r_new in zip(old["regions"], new["regions"], strict=True):
        assert {k: r_new[k if k in r_new else renamed[k]] for k in r_old} == r_old


def test_refusals(seed_toml, write_file):
    with pytest.raises(InputError, match="thermal = 'full'"):
        evaluate_case(seed_case(), thermal="full")
    with pytest.raises(InputError, match="thermal = 'hot'"):
        evaluate_case(seed_case(), thermal="hot")
    with pytest.raises(InputError, match="oil_temp_C = 20"):
        evaluate_case(hot_case(seed_toml, write_file), oil_temp_C=20.0)
