"""The model against calculations written out by hand in the test.

* the seed joint's region powers at 40 degC: Eqs. 4-6 and 8 of the seed paper
  (*Modeling and Optimization of Compensating Oil Viscous Power for a Deep-Sea
  Electric Manipulator*) summed over the 1500 samples of its cycle;
* :func:`~oilgap.model.regions.region_mean_power` against the plain 1500-sample mean;
* the steady heat balance of :mod:`oilgap.model.thermal` for a linear loss
  ``P(T) = a - b T``: ``T* = (T_base + R a) / (1 + R b)``;
* :func:`~oilgap.model.effects.effect_context` and
  :func:`~oilgap.model.effects.cross_region_ratios` on a two-region, three-sample joint.
"""

import math

import numpy as np
import pytest

from oilgap.model.effects import Precomputed, cross_region_ratios, effect_context
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.regions import JointGeometry, Region, joint_regions, region_mean_power
from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.thermal import steady_temperature


def seed_speeds():
    """The seed's 1500 samples: 3000 rpm * sin(0.1 pi t), t = 0, 0.2, ..., 299.8 s."""
    return [2 * math.pi * 3000 / 60 * math.sin(0.1 * math.pi * 0.2 * k) for k in range(1500)]


def hand_cm(re, x, laminar="couette"):
    """Eq. 6 (Bilgen & Boulos), bounded below by 8 (1+x)^2 / ((2+x) Re) if 'couette'."""
    if re < 64:
        cm = 10.0 / re * x**0.3
    elif re < 500:
        cm = 2.0 * re**-0.6 * x**0.3
    elif re < 1e4:
        cm = 1.03 * re**-0.5 * x**0.3
    else:
        cm = 0.065 * re**-0.2 * x**0.3
    if laminar == "couette":
        cm = max(cm, 8 * (1 + x) ** 2 / ((2 + x) * re))
    return cm


def hand_mean_power(R, gap, L, T, gamma, nu, rho, laminar="couette"):
    """Eqs. 4-6 and 8 written out independently, averaged over the seed's 1500 samples."""
    total = 0.0
    for w in map(abs, seed_speeds()):
        if w == 0:
            continue
        re = w * R * gap / nu
        total += 0.5 * math.pi * hand_cm(re, gap / R, laminar) * T**gamma * rho * w**3 \
            * R**4 * L
    return total / 1500


@pytest.mark.parametrize("laminar", ["couette", "bilgen-boulos"])
def test_seed_region_powers_at_40C_against_hand_computation(seed_toml, write_file, laminar):
    ev = evaluate_case(read_case_toml(write_file(seed_toml)), laminar_law=laminar,
                       thermal="none")
    # at 40 degC and the surface the Walther line gives the catalogue 22 cSt exactly;
    # density 860 * exp(-6.5e-4 * 25) = 846.138 kg/m^3
    nu, rho = 22e-6, 860 * math.exp(-6.5e-4 * 25)
    assert ev.nu_cSt == pytest.approx(22.0, rel=1e-10)
    assert ev.density_kg_m3 == pytest.approx(rho, rel=1e-12)
    p1 = hand_mean_power(0.0254, 0.001, 0.01476, 4.0, 0.5, nu, rho, laminar)
    p2 = hand_mean_power(0.022, 0.005, 0.01424, 1.0, 0.5, nu, rho, laminar)
    r1, r2 = ev.regions
    assert r1.mean_power_W == pytest.approx(p1, rel=1e-9)
    assert r2.mean_power_W == pytest.approx(p2, rel=1e-9)
    assert ev.total_mean_power_W == pytest.approx(p1 + p2, rel=1e-9)
    # peak Re of region 1 by hand: 314.159 * 0.0254 * 0.001 / 22e-6 = 362.71
    assert r1.Re_peak == pytest.approx(362.71, rel=1e-4)
    assert r1.regimes == ("laminar", "laminar with vortices")


@pytest.mark.parametrize("nu_cSt", [30.0, 300.0, 3000.0])
def test_region_mean_power_is_the_1500_sample_mean(nu_cSt):
    """region_mean_power over the cycle's speed distribution (26 nodes) equals the plain
    mean over the 1500 samples of Eq. 5 with Eq. 6 (Couette-bounded) and T^0.5."""
    nu, rho = nu_cSt * 1e-6, 880.0
    law = FrictionLaw(gamma=0.5)
    nodes, weights = seed_case().duty_cycle.speed_distribution()
    for region, T in zip(joint_regions(seed_case()), (4.0, 1.0), strict=True):
        R, gap, L = region.radius_m, region.gap_m, region.length_m
        got = region_mean_power(region, nodes, weights, nu, rho, law)
        assert got == pytest.approx(hand_mean_power(R, gap, L, T, 0.5, nu, rho), rel=1e-12)


def test_steady_temperature_of_a_linear_loss():
    """P(T) = a - b T heats the oil through R: T = T_base + R (a - b T), so
    T* = (T_base + R a) / (1 + R b). Case 1: (20 + 0.4 * 120) / (1 + 0.4 * 1.5) = 68 / 1.6
    = 42.5 degC, P = 120 - 1.5 * 42.5 = 56.25 W. Case 2: (2 + 0.1 * 300) / (1 + 0.1 * 2)
    = 32 / 1.2 = 26.667 degC, P = 300 - 53.333 = 246.667 W."""
    a = np.array([120.0, 300.0])
    b = np.array([1.5, 2.0])
    t_base = np.array([20.0, 2.0])
    r = np.array([0.4, 0.1])

    def power_at(temps):  # k temperatures of every case, case index fastest
        k = len(temps) // 2
        return np.tile(a, k) - np.tile(b, k) * temps

    for i in range(2):  # one thermal resistance per call
        temps, powers = steady_temperature(lambda t, i=i: a[i] - b[i] * t, t_base[i], r[i], 1)
        assert temps[0] == pytest.approx((t_base[i] + r[i] * a[i]) / (1 + r[i] * b[i]),
                                         abs=1e-9)
        assert powers[0] == pytest.approx(a[i] - b[i] * temps[0], rel=1e-12)
    temps, powers = steady_temperature(power_at, t_base, 0.4, 2)  # both cases at once
    np.testing.assert_allclose(temps, (t_base + 0.4 * a) / (1 + 0.4 * b), atol=1e-9)
    assert temps[0] == pytest.approx(42.5, abs=1e-9)
    np.testing.assert_allclose(powers, a - b * temps, rtol=1e-12)


def test_steady_temperature_held_at_the_cap():
    """a = 1e5 W, b = 1 W/K, R = 1 K/W: T* = (20 + 1e5) / 2 = 50010 degC, far above the
    250 degC cap; the case is returned at the cap with P(250) = 1e5 - 250."""
    temps, powers = steady_temperature(lambda t: 1e5 - t, 20.0, 1.0, 1)
    assert temps[0] == 250.0 and powers[0] == pytest.approx(1e5 - 250.0, rel=1e-15)


# --------------------------------------------------------------------------- effects

# Two regions, three samples. Region 1: R 20 mm, delta 1 mm (x = 0.05), L 10 mm;
# region 2: R 15 mm, delta 4 mm (x = 0.2667), L 8 mm. nu = 1e-4 m^2/s, rho = 900 kg/m^3
# (mu = 0.09 Pa s); omega = 100, -50, 0 rad/s.
GEOMETRY = JointGeometry((Region("rotor-stator", 0.020, 0.001, 0.010, 1.0),
                          Region("bearing", 0.015, 0.004, 0.008, 1.0)), (0.020, 0.005), 0.034)
OMEGA = np.array([100.0, -50.0, 0.0])
NU, RHO = 1e-4, 900.0


def test_effect_context_by_hand():
    ctx = effect_context(GEOMETRY, OMEGA, np.array([3.0, -1.0, 0.5]), NU, RHO, FrictionLaw())
    # Re = |w| R delta / nu: region 1 100 * 0.02 * 0.001 / 1e-4 = 20, 10, 0;
    # region 2 100 * 0.015 * 0.004 / 1e-4 = 60, 30, 0 (all laminar)
    r1, r2 = ctx.regions
    np.testing.assert_allclose(r1.reynolds, [20.0, 10.0, 0.0], rtol=1e-14)
    np.testing.assert_allclose(r2.reynolds, [60.0, 30.0, 0.0], rtol=1e-14)
    np.testing.assert_allclose(r1.taylor, [20.0 * 0.05**0.5, 10.0 * 0.05**0.5, 0.0],
                               rtol=1e-14)
    # Region 1 at x = 0.05: Eq. 6 laminar 10/Re x^0.3 = 0.2035 at Re = 20 is below the
    # Couette 8 (1.05)^2 / (2.05 * 20) = 0.2151, so the Couette law holds: the exact
    # torque 4 pi mu L R1^2 R2^2 / (R2^2 - R1^2) w with R2 = 21 mm:
    # 4e-4 * 4.41e-4 / 4.1e-5 = 4.302439e-3 m^2; P = 4 pi 0.09 0.01 4.302439e-3 w^2
    # = 4.865944e-5 w^2: 0.4865944 W at 100 rad/s, 0.1216486 W at 50 rad/s
    np.testing.assert_allclose(r1.power_W, [0.4865944, 0.1216486, 0.0], rtol=1e-6)
    # Region 2 at x = 0.2667: Eq. 6 laminar is above Couette (0.0944 at Re = 60);
    # Cm = 10/60 * 0.266667^0.3 = 0.166667 * 0.672652 = 0.112109;
    # P = 0.5 pi Cm rho w^3 R^4 L = 0.5 pi 0.112109 * 900 * 1e6 * 5.0625e-8 * 0.008
    # = 0.0641884 W; at 50 rad/s Re = 30 doubles Cm: 0.0641884 * 2 / 8 = 0.0160471 W
    np.testing.assert_allclose(r2.power_W, [0.0641884, 0.0160471, 0.0], rtol=2e-6)
    np.testing.assert_allclose(ctx.power_W, r1.power_W + r2.power_W, rtol=1e-15)
    # the record's derivatives default to zero; geometry passes through
    assert np.all(ctx.dtemp_dt_K_s == 0) and np.all(ctx.dpower_dt_W_s == 0)
    np.testing.assert_allclose(ctx.domega_dt_rad_s2, [3.0, -1.0, 0.5])
    assert ctx.disc_radii_m == (0.020, 0.005) and ctx.bearing_pitch_diameter_m == 0.034


def test_effect_context_takes_given_powers():
    given = [np.array([1.0, 2.0, 3.0]), np.array([0.5, 0.5, 0.5])]
    ctx = effect_context(GEOMETRY, OMEGA, 0.0, NU, RHO, FrictionLaw(),
                         given=Precomputed(powers_W=given))
    np.testing.assert_allclose(ctx.power_W, [1.5, 2.5, 3.5])


def test_cross_region_ratios_by_hand():
    """mu/mu_0 = 1 / (1 + (lambda |w| R / delta)^2), lambda = 1e-4 s. Shear rates:
    region 1 100 * 20 = 2000 /s, 1000 /s, 0; region 2 100 * 3.75 = 375 /s, 187.5 /s, 0.
    (0.2)^2 = 0.04 -> 0.961538; 0.01 -> 0.990099; (0.0375)^2 -> 0.998596;
    (0.01875)^2 -> 0.999649."""
    ctx = effect_context(GEOMETRY, OMEGA, 0.0, NU, RHO, FrictionLaw())
    ratios = cross_region_ratios(ctx, 1e-4)
    np.testing.assert_allclose(ratios[0], [1 / 1.04, 1 / 1.01, 1.0], rtol=1e-14)
    np.testing.assert_allclose(ratios[1], [1 / (1 + 0.0375**2), 1 / (1 + 0.01875**2), 1.0],
                               rtol=1e-14)
    np.testing.assert_allclose(ratios[1], [0.998596, 0.999649, 1.0], rtol=1e-6)
