"""oilgap.model.joint_loss: the thermal modes against their parts composed by hand, the
bulk balance against its own ODE, and the uniqueness of the balance's root (the residual
g(T) = T - T_base - R P(T) rises) for the seed joint and every catalogue grade."""

import dataclasses

import casadi as ca
import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InputError
from oilgap.model.film_cycle import film_factors
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import (
    THERMAL_MODES,
    case_film,
    default_thermal_mode,
    film_band,
    joint_mean_power,
    operating_temperature,
    resolve_thermal_mode,
)
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.oils import builtin_oils
from oilgap.model.regions import joint_regions, region_mean_power, region_power
from oilgap.model.thermal import joint_temperature_transient
from oilgap.model.units import celsius_to_kelvin

SEED = seed_case()


def with_thermal(case=SEED, walls="isothermal-walls", **kw):
    spec = dict(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5e4,
                other_heat_W=10.0, walls=walls) | kw
    return dataclasses.replace(case, thermal=ThermalSpec(**spec))


def oil_state(case, temp_C, depth_m=None):
    p = seawater_gauge_pressure(case.operating.depth_m if depth_m is None else depth_m)
    nu, _, rho = case.oil.properties(celsius_to_kelvin(temp_C), p)
    return nu, rho, p


# --------------------------------------------------------------------------- modes


def test_modes_and_their_resolution():
    assert THERMAL_MODES == ("none", "bulk", "film", "full")
    hot = with_thermal()
    # the default is the model the seed's Table 4 supports: no film heating; the bulk
    # balance when the case has one
    assert default_thermal_mode(SEED) == "none" and default_thermal_mode(hot) == "bulk"
    assert resolve_thermal_mode(SEED, None) == "none"
    assert resolve_thermal_mode(hot, None) == "bulk"
    for mode in ("none", "film"):
        assert resolve_thermal_mode(SEED, mode) == mode == resolve_thermal_mode(hot, mode)
    for mode in ("bulk", "full"):
        assert resolve_thermal_mode(hot, mode) == mode
        with pytest.raises(InputError) as e:
            resolve_thermal_mode(SEED, mode)       # no [thermal] table
        assert e.value.field == "thermal" and "[thermal]" in str(e.value)
    with pytest.raises(InputError) as e:
        resolve_thermal_mode(hot, "hot")
    assert e.value.field == "thermal" and "none, bulk, film, full" in str(e.value)


@pytest.mark.parametrize("temp_C, depth_m", [(2.0, None), (25.0, 500.0)])
def test_none_is_the_isothermal_sum_of_the_regions(temp_C, depth_m):
    nu, rho, _ = oil_state(SEED, temp_C, depth_m)
    nodes, w = SEED.duty_cycle.speed_distribution()
    hand = sum(region_mean_power(r, nodes, w, nu, rho, SEED.friction)
               for r in joint_regions(SEED))
    assert joint_mean_power(SEED, temp_C, "none", depth_m) == pytest.approx(hand, rel=1e-14)


@pytest.mark.parametrize("walls", ["isothermal-walls", "adiabatic-rotor"])
def test_film_is_the_node_power_times_the_film_factor(walls):
    # b = -d ln(mu)/dT by a central difference of the oil's own mu = nu rho (not the
    # oil's temperature_slope), the factor per node, the isothermal node power
    case = with_thermal(walls=walls)
    t, dt = 2.0, 1e-3
    nu, rho, _ = oil_state(case, t)
    mu_up, mu_dn = (np.prod(oil_state(case, t + s)[:2]) for s in (dt, -dt))
    b = -(np.log(mu_up) - np.log(mu_dn)) / (2.0 * dt)
    nodes, w = case.duty_cycle.speed_distribution()
    hand = sum(region_power(r, nodes, nu, rho, case.friction)
               * film_factors(nodes, w, r.radius_m, r.gap_m, nu, rho, b, case_film(case)) @ w
               for r in joint_regions(case))
    film = joint_mean_power(case, t, "film")
    assert film == pytest.approx(hand, rel=1e-6)     # the difference's truncation error
    assert joint_mean_power(case, t, "full") == pytest.approx(film, rel=1e-15)  # the film at t
    assert film < joint_mean_power(case, t, "none")


def test_arrays_and_casadi_agree_with_floats():
    temps = np.array([0.0, 2.0, 10.0, 40.0])
    for mode in THERMAL_MODES[:2]:
        got = joint_mean_power(SEED, temps, mode)
        assert np.shape(got) == (4,)
        np.testing.assert_allclose(got, [joint_mean_power(SEED, float(t), mode)
                                         for t in temps], rtol=1e-14)
    # depths broadcast against temperatures
    both = joint_mean_power(SEED, temps[:, None], "film", np.array([0.0, 3000.0]))
    assert np.shape(both) == (4, 2)
    assert both[1, 1] == pytest.approx(joint_mean_power(SEED, 2.0, "film", 3000.0),
                                       rel=1e-14)
    # CasADi: value and dP/dT against a central difference
    x = ca.SX.sym("T")
    p = joint_mean_power(SEED, x, "film")
    f = ca.Function("f", [x], [p, ca.gradient(p, x)])
    val, grad = (float(v) for v in f(2.0))
    assert val == pytest.approx(joint_mean_power(SEED, 2.0, "film"), rel=1e-12)
    h = 1e-4
    fd = (joint_mean_power(SEED, 2.0 + h, "film") - joint_mean_power(SEED, 2.0 - h, "film"))
    assert grad == pytest.approx(fd / (2.0 * h), rel=1e-6)
    assert grad < 0


# --------------------------------------------------------------------------- balance


def test_operating_temperature_without_balance_is_the_case_temperature():
    for mode in ("none", "film"):
        op = operating_temperature(with_thermal(), mode)
        assert op.mode == mode and op.sea_temp_C is None
        assert op.oil_temp_C == SEED.operating.oil_temp_C
        assert op.mean_power_W == pytest.approx(
            joint_mean_power(SEED, SEED.operating.oil_temp_C, mode), rel=1e-12)
    assert operating_temperature(SEED).mode == "none"  # the default without [thermal]


@pytest.mark.parametrize("walls", ["isothermal-walls", "adiabatic-rotor"])
def test_full_is_the_steady_state_of_the_lumped_ode(walls):
    case = with_thermal(walls=walls)
    spec = case.thermal
    op = operating_temperature(case, "full")
    assert op.mode == "full" and op.sea_temp_C == 2.0
    # C dT/dt = P(T) + Q - (T - T_sea)/R from the sea temperature: tau <= R C = 25000 s,
    # 6e5 s = 24 R C
    temps = joint_temperature_transient(
        lambda time, temp: float(joint_mean_power(case, temp, "full")), spec,
        [0.0, 6e5], spec.sea_temp_C, rtol=1e-8, atol_K=1e-9)
    assert op.oil_temp_C == pytest.approx(temps[-1], abs=1e-6)
    # the balance with P recomputed at the result
    p = float(joint_mean_power(case, op.oil_temp_C, "full"))
    assert op.mean_power_W == pytest.approx(p, rel=1e-9)
    residual = op.oil_temp_C - spec.sea_temp_C - spec.resistance_K_W * (p + spec.other_heat_W)
    assert abs(residual) < 1e-8
    assert op.oil_temp_C > spec.sea_temp_C + spec.resistance_K_W * spec.other_heat_W


@pytest.mark.parametrize("oil, sea, resistance, other", [
    ("VG22", 2.0, 0.5, 10.0), ("VG22", -1.0, 5.0, 0.0), ("VG1000", 4.0, 0.05, 0.0),
    ("VG10", 20.0, 2.0, 30.0)])
def test_bulk_is_the_root_of_the_isothermal_balance(oil, sea, resistance, other):
    # bulk (the default with [thermal]): T = T_sea + R (P_none(T) + Q), P_none the seed
    # paper's isothermal loss summed over the regions by hand at each T, the root by
    # Brent's method on [T_sea + R Q, T_sea + R (P_none(T_sea + R Q) + Q)] (P falls with T)
    case = with_thermal(dataclasses.replace(SEED, oil=builtin_oils()[oil]),
                        sea_temp_C=sea, resistance_K_W=resistance, other_heat_W=other)
    nodes, w = case.duty_cycle.speed_distribution()

    def p_none(temp_C):
        nu, rho, _ = oil_state(case, temp_C)
        return sum(float(region_mean_power(r, nodes, w, nu, rho, case.friction))
                   for r in joint_regions(case))

    lo = sea + resistance * other
    hi = lo + resistance * p_none(lo)
    root = brentq(lambda t: t - sea - resistance * (p_none(t) + other), lo, hi, xtol=1e-13,
                  rtol=1e-15)
    op = operating_temperature(case)
    assert op.mode == "bulk" and op.sea_temp_C == sea
    assert op.oil_temp_C == pytest.approx(root, abs=1e-8)
    assert op.mean_power_W == pytest.approx(p_none(root), rel=1e-9)
    # no film factor: the same as none at the balance's temperature, below full's loss
    assert op.mean_power_W == pytest.approx(
        operating_temperature(dataclasses.replace(
            case, operating=dataclasses.replace(case.operating, oil_temp_C=op.oil_temp_C)),
            "none").mean_power_W, rel=1e-9)
    assert operating_temperature(case, "full").mean_power_W < op.mean_power_W


@pytest.mark.parametrize("walls", ["isothermal-walls", "adiabatic-rotor"])
def test_the_residual_rises_so_the_root_is_unique(walls):
    # g(T) = T - T_base - R P(T) on a fine grid over its bracket [T_base, T_base + R P]
    case = with_thermal(walls=walls)
    spec = case.thermal
    base = spec.sea_temp_C + spec.resistance_K_W * spec.other_heat_W
    top = base + spec.resistance_K_W * float(joint_mean_power(case, base, "full"))
    t = np.linspace(base, top, 2001)
    g = t - base - spec.resistance_K_W * joint_mean_power(case, t, "full")
    assert g[0] < 0 < g[-1]
    assert np.all(np.diff(g) > 0)


def test_film_loss_falls_with_temperature_for_every_grade():
    # the condition of the balance's uniqueness (dP/dT < 1/R) holds with room to spare:
    # on the seed joint the film-corrected loss falls from -2 to 150 degC for every
    # catalogue grade and both wall conditions (model.thermal's module docstring)
    t = np.linspace(-2.0, 150.0, 1521)
    for walls in ("isothermal-walls", "adiabatic-rotor"):
        for name, oil in builtin_oils().items():
            case = with_thermal(dataclasses.replace(SEED, oil=oil), walls=walls)
            p = joint_mean_power(case, t, "film")
            assert np.all(np.diff(p) < 0), (walls, name)


def test_the_film_band_is_the_film_at_full_strength():
    # the band beside none/bulk is the opposite film choice on the same design: film
    # (no [thermal]) or full, at full strength s = 1 whatever [thermal] film_strength says
    band = film_band(SEED)
    assert (band.mode, band.other_mode) == ("none", "film")
    assert band.mean_power_W == operating_temperature(SEED, "none").mean_power_W
    assert band.other_mean_power_W == operating_temperature(SEED, "film").mean_power_W
    hot = with_thermal()
    weak = with_thermal(film_strength=0.3)
    for case in (hot, weak):
        b = film_band(case)
        assert (b.mode, b.other_mode) == ("bulk", "full")
        assert b.other_mean_power_W == pytest.approx(
            operating_temperature(hot, "full").mean_power_W, rel=1e-12)
        assert b.change_pct == pytest.approx(
            100 * (b.other_mean_power_W / b.mean_power_W - 1), rel=1e-12)
    assert operating_temperature(weak, "full").mean_power_W != pytest.approx(
        operating_temperature(hot, "full").mean_power_W, rel=1e-3)
    back = film_band(hot, "full")  # under full, the default's number beside it
    assert back.other_mode == "bulk"
    assert back.other_mean_power_W == operating_temperature(hot, "bulk").mean_power_W
