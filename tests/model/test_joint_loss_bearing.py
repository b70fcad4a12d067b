"""model.joint_loss with a rolling bearing: the joint's loss is the regions' plus the
bearing's at the bulk viscosity under every thermal mode (no film factor), region 2 keeps
its own term, the bearing's heat closes the balance under ``full``; the Palmgren mean over
the seed's sine cycle written out by hand over the cycle's samples and in closed form."""

import dataclasses
import math

import casadi as ca
import numpy as np
import pytest

from oilgap.model.bearing import bearing_mean_power
from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.case import OperatingPoint, ThermalSpec
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import (
    bearing_mean_power_at,
    joint_mean_power,
    operating_temperature,
    region_mean_powers,
)
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.oils import get_oil
from oilgap.model.regions import joint_regions
from oilgap.model.units import celsius_to_kelvin

SEED = seed_case()
SKF = bearing_spec_from({"designation": "6809"})
PALMGREN = bearing_spec_from({"designation": "6809", "model": "palmgren", "f0": 2.0})


def nu_at(case, temp_C, depth_m=None):
    """Kinematic viscosity [m^2/s] of the case's oil at (T, depth), from the oil's law."""
    d = case.operating.depth_m if depth_m is None else depth_m
    return float(case.oil.properties(celsius_to_kelvin(temp_C), seawater_gauge_pressure(d))[0])


def bearing_by_nodes(case, spec, temp_C):
    nodes, weights = case.duty_cycle.speed_distribution()
    return float(bearing_mean_power(spec, nodes, weights, nu_at(case, temp_C)))


@pytest.mark.parametrize("spec", [SKF, PALMGREN], ids=["skf", "palmgren"])
@pytest.mark.parametrize("mode", ["none", "film"])
def test_the_joint_adds_the_bearing_at_the_bulk_viscosity(spec, mode):
    case = dataclasses.replace(SEED, bearing=spec)
    for t in (2.0, 25.0):
        added = joint_mean_power(case, t, mode) - joint_mean_power(SEED, t, mode)
        assert added == pytest.approx(bearing_by_nodes(case, spec, t), rel=1e-10)
        assert bearing_mean_power_at(case, t) == pytest.approx(added, rel=1e-10)
        # region 2 (the annulus) keeps its term; the bearing is not merged into it
        np.testing.assert_array_equal(region_mean_powers(case, t, mode),
                                      region_mean_powers(SEED, t, mode))
    op = operating_temperature(case, mode)
    assert op.bearing_mean_power_W == pytest.approx(bearing_by_nodes(case, spec, 2.0),
                                                    rel=1e-12)
    assert op.mean_power_W == pytest.approx(sum(op.region_mean_powers_W)
                                            + op.bearing_mean_power_W, rel=1e-12)
    assert bearing_mean_power_at(SEED, 2.0) == 0.0
    assert operating_temperature(SEED, mode).bearing_mean_power_W == 0.0


def test_palmgren_over_the_seed_cycle_by_hand():
    """Palmgren's M0 = 1e-7 f0 (nu n)^(2/3) dm^3 [N mm] (nu n >= 2000; 160e-7 f0 dm^3
    below) and M1 = 0.0005 (P0/C0)^0.55 P1 dm (Harris & Kotzalas), P = M omega, averaged
    over the seed cycle's 1500 samples; and in closed form for n = n_pk |sin|:
    mean = P_peak E|sin|^(5/3), E|sin|^p = Gamma((p+1)/2)/(sqrt(pi) Gamma(p/2+1))."""
    case = dataclasses.replace(SEED, oil=get_oil("VG320"), bearing=PALMGREN,
                               operating=OperatingPoint(0.0, 40.0))
    nu_cst = nu_at(case, 40.0) * 1e6
    assert nu_cst == pytest.approx(320.0, rel=1e-9)  # ISO VG 320 at 40 degC, the surface
    cycle = case.duty_cycle
    w = np.abs(cycle.omega_rad_s)
    n = w * 60.0 / (2.0 * math.pi)
    dm, f0, fr, c0 = 51.5, 2.0, 50.0, 6100.0
    m0 = 1e-7 * f0 * np.maximum((nu_cst * n) ** (2.0 / 3.0), 160.0) * dm**3
    m1 = 0.0005 * (fr / c0) ** 0.55 * fr * dm
    by_samples = float(np.sum((m0 + m1) * 1e-3 * w * cycle.sample_weights())
                       / np.sum(cycle.sample_weights()))
    got = joint_mean_power(case, 40.0, "none") - joint_mean_power(
        dataclasses.replace(case, bearing=None), 40.0, "none")
    assert got == pytest.approx(by_samples, rel=1e-10)
    # closed form: peak power 83.52 W (docs/notes, sec. 4) times E|sin|^(5/3) = 0.5356
    p = 5.0 / 3.0
    e_sin = math.gamma((p + 1) / 2) / (math.sqrt(math.pi) * math.gamma(p / 2 + 1))
    peak = 1e-7 * f0 * (nu_cst * 3000.0) ** (2 / 3) * dm**3 * 1e-3 * 3000 * math.pi / 30
    assert peak == pytest.approx(83.52, abs=0.01) and e_sin == pytest.approx(0.5356, abs=1e-4)
    m1_mean = m1 * 1e-3 * 3000 * math.pi / 30 * 2 / math.pi  # E|sin| = 2/pi
    assert got == pytest.approx(peak * e_sin + m1_mean, rel=2e-4)
    assert got == pytest.approx(44.7, abs=0.05)  # the notes' table (sec. 5), f0 = 2


def test_include_bearing_follows_the_regions_argument():
    case = dataclasses.replace(SEED, bearing=SKF)
    regions = joint_regions(case)
    whole = joint_mean_power(case, 2.0, "film")
    assert joint_mean_power(case, 2.0, "film", regions=regions) == pytest.approx(
        joint_mean_power(SEED, 2.0, "film"), rel=1e-14)
    assert joint_mean_power(case, 2.0, "film", regions=regions,
                            include_bearing=True) == pytest.approx(whole, rel=1e-14)
    assert joint_mean_power(case, 2.0, "film", include_bearing=False) == pytest.approx(
        joint_mean_power(SEED, 2.0, "film"), rel=1e-14)


def test_arrays_and_casadi_agree_with_floats():
    case = dataclasses.replace(SEED, bearing=SKF)
    temps = np.array([0.0, 2.0, 10.0, 40.0])
    got = joint_mean_power(case, temps, "film")
    np.testing.assert_allclose(got, [joint_mean_power(case, float(t), "film") for t in temps],
                               rtol=1e-13)
    both = joint_mean_power(case, temps[:, None], "none", np.array([0.0, 3000.0]))
    assert both.shape == (4, 2)
    assert both[1, 1] == pytest.approx(joint_mean_power(case, 2.0, "none", 3000.0), rel=1e-13)
    np.testing.assert_allclose(bearing_mean_power_at(case, temps),
                               [bearing_by_nodes(case, SKF, t) for t in temps], rtol=1e-12)
    x = ca.SX.sym("T")
    p = joint_mean_power(case, x, "film")
    f = ca.Function("f", [x], [p, ca.gradient(p, x)])
    val, grad = (float(v) for v in f(2.0))
    assert val == pytest.approx(joint_mean_power(case, 2.0, "film"), rel=1e-12)
    h = 1e-4
    fd = (joint_mean_power(case, 2.0 + h, "film") - joint_mean_power(case, 2.0 - h, "film"))
    assert grad == pytest.approx(fd / (2 * h), rel=1e-6) and grad < 0


@pytest.mark.parametrize("spec", [SKF, PALMGREN], ids=["skf", "palmgren"])
def test_the_balance_takes_the_bearing_heat(spec):
    thermal = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5e4,
                          other_heat_W=5.0)
    plain = dataclasses.replace(SEED, thermal=thermal)
    case = dataclasses.replace(plain, bearing=spec)
    op = operating_temperature(case, "full")
    t = op.oil_temp_C
    p_regions = float(joint_mean_power(plain, t, "full"))  # recomputed at the root
    p_bearing = bearing_by_nodes(case, spec, t)
    residual = t - 2.0 - 0.5 * (p_regions + p_bearing + 5.0)
    assert abs(residual) < 1e-7
    assert op.bearing_mean_power_W == pytest.approx(p_bearing, rel=1e-9)
    assert sum(op.region_mean_powers_W) == pytest.approx(p_regions, rel=1e-9)
    assert op.mean_power_W == pytest.approx(p_regions + p_bearing, rel=1e-9)
    assert len(op.region_mean_powers_W) == 2
    # the bearing's heat warms the oil, by less than R P_bearing at the warmer oil without
    # it (every loss falls as the oil warms)
    t_plain = operating_temperature(plain, "full").oil_temp_C
    assert 0.0 < t - t_plain <= 0.5 * bearing_by_nodes(case, spec, t_plain)
