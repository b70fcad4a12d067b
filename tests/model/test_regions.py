"""The one list of a joint's regions and the one duty-cycle mean (numpy and CasADi)."""

import casadi as ca
import numpy as np
import pytest

from oilgap.model.io.case_io import seed_case
from oilgap.model.regions import (
    Region,
    joint_geometry,
    joint_regions,
    region_mean_power,
    region_power,
    rotor_stator_radii,
    rotor_stator_region,
)
from oilgap.model.skin_friction import FrictionLaw


def test_geometry_overrides_touch_region1_only():
    case = seed_case()
    T = np.array([4.0, 2.0, 3.0])
    geo = joint_geometry(case, roughness_T=T, gap1_m=0.8e-3)
    r1, r2 = geo.regions
    assert r1.roughness_T is T and r1.gap_m == 0.8e-3
    assert r1.radius_m == case.region1.radius and r2 == joint_regions(case)[1]
    assert geo.disc_radii_m == (case.region1.radius, case.motor.shaft_bore_radius)


def test_no_bearing_region():
    case = seed_case().with_changes(region2=None)
    assert [r.name for r in joint_regions(case)] == ["rotor-stator"]
    assert joint_geometry(case).bearing_pitch_diameter_m is None


def test_rotor_stator_region_from_design_variables():
    # the seed's grooved region 1: R 25.4 mm, delta 1 mm, 1.5 mm grooves on both sides:
    # T1 = 23.9, T2 = 25.4, T3 = 26.4, T4 = 27.9 mm, T = (27.9 - 23.9)/(26.4 - 25.4) = 4
    radii = rotor_stator_radii(25.4e-3, 1e-3, 1.5e-3, 1.5e-3)
    np.testing.assert_allclose(radii, [23.9e-3, 25.4e-3, 26.4e-3, 27.9e-3], rtol=1e-14)
    reg = rotor_stator_region(25.4e-3, 1e-3, 1.5e-3, 1.5e-3, 14.76e-3)
    assert reg.roughness_T == pytest.approx(4.0, rel=1e-12)
    assert reg == Region("rotor-stator", 25.4e-3, 1e-3, 14.76e-3, reg.roughness_T)


def test_mean_power_numpy_casadi_and_batched_agree():
    region = joint_regions(seed_case())[0]
    nodes, weights = seed_case().duty_cycle.speed_distribution()
    law = FrictionLaw(form="smooth", gamma=0.5)
    ref = region_mean_power(region, nodes, weights, 2e-4, 880.0, law)
    nu = ca.SX.sym("nu")
    f = ca.Function("p", [nu], [region_mean_power(region, ca.DM(nodes), weights, nu, 880.0,
                                                  law)])
    assert float(f(2e-4)) == pytest.approx(ref, rel=1e-12)
    # nodes along the last axis: one mean per leading index
    nus = np.array([[1e-4], [2e-4], [4e-4]])
    batch = region_mean_power(region, nodes[None, :], weights, nus, 880.0, law)
    assert batch.shape == (3,) and batch[1] == pytest.approx(ref, rel=1e-13)
    singles = [region_mean_power(region, nodes, weights, n, 880.0, law) for n in (1e-4, 4e-4)]
    np.testing.assert_allclose(batch[[0, 2]], singles, rtol=1e-13)


def test_region_power_is_even_in_speed():
    region = joint_regions(seed_case())[1]
    w = np.array([-200.0, 200.0])
    p = region_power(region, w, 3e-4, 870.0, FrictionLaw())
    assert p[0] == p[1] > 0
