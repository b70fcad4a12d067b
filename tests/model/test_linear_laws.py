"""The linear actuator's laws against hand calculations and second methods (issue 29)."""

import math

import casadi as ca
import numpy as np
import pytest

from oilgap.model.bearing.laws import palmgren_viscous_moment
from oilgap.model.linear.elements import PassagesElement, RodGuideElement, ScrewElement
from oilgap.model.linear.laws import (
    annular_couette_force,
    annulus_leakage,
    dashpot_force,
    eccentric_drag_factor,
    hagen_poiseuille_pressure_drop,
    motor_speed,
    passages_power,
    rod_force_capability,
    rod_velocity,
    screw_viscous_torque,
)

MU, V, L = 0.1, 0.1, 0.03  # Pa s, m/s, m


def _couette_by_finite_differences(r_i, r_o, n=200):
    """Second method: solve (1/r) d/dr (r du/dr) = 0, u(r_i) = V, u(r_o) = 0, by central
    differences, and take the wall shear at r_i by a one-sided second-order difference."""
    r = np.linspace(r_i, r_o, n)
    h = r[1] - r[0]
    a = np.zeros((n, n))
    b = np.zeros(n)
    a[0, 0] = a[-1, -1] = 1.0
    b[0] = V
    for k in range(1, n - 1):
        a[k, k - 1] = (r[k] - 0.5 * h) / h**2
        a[k, k] = -2.0 * r[k] / h**2
        a[k, k + 1] = (r[k] + 0.5 * h) / h**2
    u = np.linalg.solve(a, b)
    dudr = (-3.0 * u[0] + 4.0 * u[1] - u[2]) / (2.0 * h)
    return -MU * dudr * 2.0 * math.pi * r_i * L


def test_annular_couette_force_matches_the_formula_and_a_finite_difference_solution():
    r_i, r_o = 0.010, 0.012
    f = annular_couette_force(MU, V, L, r_i, r_o)
    assert f == pytest.approx(2 * math.pi * L * MU * V / math.log(1.2), rel=1e-15)
    assert f == pytest.approx(_couette_by_finite_differences(r_i, r_o), rel=1e-4)


def test_thin_gap_limit_is_mu_pi_d_L_v_over_c():
    d = 0.020
    for c in (1e-4, 1e-5, 1e-6):
        exact = annular_couette_force(MU, V, L, d / 2, d / 2 + c)
        thin = MU * math.pi * d * L * V / c
        # ln(1 + x) = x - x^2/2 + ...: exact/thin = 1 + c/d + O((c/d)^2), x = 2c/d
        assert exact / thin - 1.0 == pytest.approx(c / d, rel=2 * c / d + 1e-6)


def test_eccentricity_factors():
    assert eccentric_drag_factor(0.0) == 1.0
    assert eccentric_drag_factor(0.6) == pytest.approx(1 / 0.8)
    q0 = annulus_leakage(MU, 1e5, L, 0.02, 5e-5, 0.0)
    assert q0 == pytest.approx(math.pi * 0.02 * (5e-5) ** 3 * 1e5 / (12 * MU * L))
    assert annulus_leakage(MU, 1e5, L, 0.02, 5e-5, 1.0) / q0 == pytest.approx(2.5)


def test_hagen_poiseuille_by_hand_and_by_integrating_the_profile():
    # 20 mm rod at 0.1 m/s: Q = pi (0.01)^2 0.1 = pi 1e-5 m^3/s through one 2 mm, 50 mm
    # passage: dp = 128 0.1 0.05 pi 1e-5 / (pi 1.6e-11) = 4e5 Pa; P = dp Q = 4 pi W
    q = math.pi * 1e-5
    dp = hagen_poiseuille_pressure_drop(MU, 0.05, q, 0.002)
    assert dp == pytest.approx(4.0e5, rel=1e-12)
    assert passages_power(MU, V, 0.02, 1, 0.002, 0.05) == pytest.approx(4 * math.pi, rel=1e-12)
    # two passages: each carries Q/2 at dp/2, the power halves
    assert passages_power(MU, V, 0.02, 2, 0.002, 0.05) == pytest.approx(2 * math.pi, rel=1e-12)
    # second method: the parabolic profile u = dp/(4 mu L) (R^2 - r^2) integrated
    r = np.linspace(0.0, 0.001, 20001)
    u = dp / (4 * MU * 0.05) * (0.001**2 - r**2)
    assert np.trapezoid(2 * math.pi * r * u, r) == pytest.approx(q, rel=1e-7)


def test_dashpot_by_hand_and_from_the_annulus_leakage():
    # 6 pi 0.1 0.03 (0.01)^3 0.1 / (1e-5)^3 = 6 pi 3e5 N = 5.65e6 N
    f = dashpot_force(MU, V, L, 0.01, 1e-5)
    assert f == pytest.approx(6 * math.pi * 3e5, rel=1e-12)
    # second method: dp that drives Q = pi R^2 v through the clearance, on the area pi R^2
    q = math.pi * 0.01**2 * V
    dp = q / annulus_leakage(MU, 1.0, L, 0.02, 1e-5)
    assert dp * math.pi * 0.01**2 == pytest.approx(f, rel=1e-12)


def test_motor_speed_is_2_pi_v_over_lead():
    w = motor_speed(0.1, 0.005)
    assert w == pytest.approx(2 * math.pi * 20.0)  # 20 rev/s = 1200 rpm
    assert rod_velocity(w, 0.005) == pytest.approx(0.1)
    # F = 2 pi eta T / lead: 1 N m, 0.9, 5 mm -> 1131 N
    assert rod_force_capability(1.0, 0.005, 0.9) == pytest.approx(2 * math.pi * 0.9 / 0.005)


def test_screw_reuses_palmgren_in_si():
    nu = 100e-6
    w = motor_speed(0.1, 0.005)
    m0 = screw_viscous_torque(w, nu, 0.016, 4.0)
    hand = 1e-7 * 4.0 * (100.0 * 1200.0) ** (2 / 3) * 16.0**3 * 1e-3  # N mm -> N m
    assert m0 == pytest.approx(hand, rel=1e-12)
    assert m0 == pytest.approx(palmgren_viscous_moment(100.0, 1200.0, 16.0, 4.0) * 1e-3)
    # below nu n = 2000 Palmgren's moment is constant: 10 cSt at 100 rpm and 50 rpm
    slow = [screw_viscous_torque(n * math.pi / 30, 10e-6, 0.016, 4.0) for n in (100, 50)]
    assert slow[0] == pytest.approx(slow[1])


@pytest.mark.parametrize("element", [
    RodGuideElement(0.005, 0.02, 0.03, 5e-5, 0.3),
    PassagesElement(0.005, 0.02, 2, 0.002, 0.05),
    ScrewElement(0.016, 4.0)])
def test_power_is_force_times_speed_for_every_element(element):
    nu, rho = 100e-6, 880.0
    w = motor_speed(0.07, 0.005)
    p = element.power(w, nu, rho)
    v = rod_velocity(w, 0.005)
    if isinstance(element, ScrewElement):
        assert p == pytest.approx(element.torque(w, nu) * w, rel=1e-14)
    elif isinstance(element, RodGuideElement):
        f = annular_couette_force(nu * rho, v, 0.03, 0.01, 0.01 + 5e-5) / math.sqrt(1 - 0.09)
        assert p == pytest.approx(f * v, rel=1e-13)
    else:
        dp = hagen_poiseuille_pressure_drop(nu * rho, 0.05, math.pi * 1e-4 * v / 2, 0.002)
        assert p == pytest.approx(dp * math.pi * 1e-4 * v, rel=1e-13)  # (dp A_rod) v


def test_rod_term_vanishes_as_the_guide_clearance_grows():
    nu, rho, w = 100e-6, 880.0, motor_speed(0.1, 0.005)
    powers = [RodGuideElement(0.005, 0.02, 0.03, c, 0.0).power(w, nu, rho)
              for c in (1e-5, 1e-3, 1e-1, 1e1, 1e3)]
    assert all(a > b for a, b in zip(powers, powers[1:], strict=False))
    # P ln(1 + c/r) is the same for every c: P -> 0 like 1/ln(c/r)
    logs = [math.log(1 + c / 0.01) for c in (1e-5, 1e-3, 1e-1, 1e1, 1e3)]
    prod = [p * g for p, g in zip(powers, logs, strict=True)]
    assert np.allclose(prod, prod[0], rtol=1e-12)
    assert powers[-1] / powers[0] < 1e-3


def test_the_elements_take_casadi_symbols():
    lead, c, d = ca.SX.sym("lead"), ca.SX.sym("c"), ca.SX.sym("d")
    nodes, weights = np.array([10.0, 100.0]), np.array([0.5, 0.5])
    expr = (RodGuideElement(lead, 0.02, 0.03, c).mean_power(nodes, weights, 1e-4, 880.0)
            + PassagesElement(lead, 0.02, 1, d, 0.05).mean_power(nodes, weights, 1e-4, 880.0))
    f = ca.Function("f", [lead, c, d], [expr])
    num = (RodGuideElement(0.005, 0.02, 0.03, 5e-5).mean_power(nodes, weights, 1e-4, 880.0)
           + PassagesElement(0.005, 0.02, 1, 0.002, 0.05).mean_power(nodes, weights, 1e-4,
                                                                      880.0))
    assert float(f(0.005, 5e-5, 0.002)) == pytest.approx(num, rel=1e-14)
