"""The model against exact solutions of the same physical problem.

* circular Couette flow (White, *Viscous Fluid Flow*, Eq. 3-49): torque, and the
  same through the seed's Eq. 5 with the Couette law;
* the lumped heat balance with a constant heat: ``T(t) = T_amb + P R + (T0 - T_amb -
  P R) exp(-t / (R C))`` (Bergman et al., *Fundamentals of Heat and Mass Transfer*,
  sec. 5.2);
* the first-order lag: exact responses to a ramp, a step and a sine;
* the enclosed Couette disc against the integrated wall shear stress, the oil-inertia
  power against the change of kinetic energy.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from oilgap.model.effects import laws as fx
from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.taylor_couette import couette_reynolds, couette_torque, taylor_number
from oilgap.model.thermal import lumped_temperature_rate
from oilgap.model.viscous_loss import clearance_power, viscous_torque


def test_exact_couette_torque_by_hand():
    # mu 0.1 Pa s, R1 25 mm, R2 26 mm, L 15 mm, omega 100 rad/s:
    # R1^2 R2^2/(R2^2 - R1^2) = 6.25e-4*6.76e-4/5.1e-5 = 8.28431e-3 m^2
    # tau = 4 pi * 0.1 * 0.015 * 8.28431e-3 * 100 = 0.0156155 N m
    tau = couette_torque(100.0, 0.1, 0.025, 0.026, 0.015)
    assert tau == pytest.approx(0.0156155, rel=1e-5)
    # The same through Eq. 5 with the Couette law (Ta far below critical):
    rho = 900.0
    nu = 0.1 / rho
    re = couette_reynolds(100.0, 0.025, 0.001, nu)
    assert taylor_number(re, 0.001, 0.025) < 41.3
    law = FrictionLaw(laminar_law="couette")
    p = clearance_power(100.0, nu, rho, 0.025, 0.001, 0.015, law)
    assert p == pytest.approx(0.0156155 * 100.0, rel=1e-5)
    assert viscous_torque(p, -100.0) == pytest.approx(-0.0156155, rel=1e-5)


def test_couette_torque_equals_integrated_wall_shear_stress():
    """Second method: the velocity field u(r) = A r + B/r with u(R1) = omega R1,
    u(R2) = 0; wall shear stress mu r d(u/r)/dr = -2 mu B / r^2 at r = R1, times the
    wall area 2 pi R1 L and the arm R1."""
    mu, w, r1, r2, length = 0.25, 80.0, 0.02, 0.0215, 0.012
    B = w * r1**2 * r2**2 / (r2**2 - r1**2)
    tau_wall = 2 * mu * B / r1**2
    assert couette_torque(w, mu, r1, r2, length) == pytest.approx(
        tau_wall * 2 * math.pi * r1 * length * r1, rel=1e-13)


def lumped_exact(t, t0, heat, amb, r, c):
    return amb + heat * r + (t0 - amb - heat * r) * np.exp(-t / (r * c))


def test_lumped_rate_is_the_derivative_of_the_exact_exponential():
    # P = 40 W into C = 2000 J/K through R = 0.5 K/W from 5 degC in 2 degC water:
    # T(t) = 2 + 20 + (5 - 22) exp(-t / 1000 s); dT/dt = 17/1000 exp(-t/1000) K/s
    t = np.array([0.0, 100.0, 1000.0, 5000.0])
    temp = lumped_exact(t, 5.0, 40.0, 2.0, 0.5, 2000.0)
    rate = lumped_temperature_rate(temp, 40.0, 2.0, 0.5, 2000.0)
    np.testing.assert_allclose(rate, 0.017 * np.exp(-t / 1000.0), rtol=1e-12)
    assert lumped_temperature_rate(22.0, 40.0, 2.0, 0.5, 2000.0) == pytest.approx(0.0,
                                                                                   abs=1e-15)


def test_lumped_rate_integrates_to_the_exact_exponential():
    sol = solve_ivp(lambda t, y: lumped_temperature_rate(y, 40.0, 2.0, 0.5, 2000.0),
                    (0.0, 4000.0), [5.0], t_eval=np.linspace(0, 4000, 9), rtol=1e-11,
                    atol=1e-12)
    np.testing.assert_allclose(sol.y[0], lumped_exact(sol.t, 5.0, 40.0, 2.0, 0.5, 2000.0),
                               rtol=1e-9)


def test_enclosed_couette_disc_equals_integrated_shear_stress():
    mu, w, ro, ri, s = 0.3, 200.0, 0.025, 0.01, 0.5e-3
    # torque of one face: int r * (mu w r / s) * 2 pi r dr
    torque, _ = quad(lambda r: r * mu * w * r / s * 2 * math.pi * r, ri, ro)
    assert fx.enclosed_disc_couette_power(w, mu, ro, ri, s, faces=1) == \
        pytest.approx(torque * w, rel=1e-10)
    assert fx.enclosed_disc_couette_power(w, mu, ro, ri, s) == \
        pytest.approx(2 * torque * w, rel=1e-10)


def test_oil_inertia_power_integrates_to_kinetic_energy():
    # w(t) = 50 + 20 t^2 on [0, 3]: int P dt = J (w1^2 - w0^2) / 2, J = rho I_V
    rho, iv = 870.0, 3.0e-7
    energy, _ = quad(lambda t: fx.oil_inertia_power(50 + 20 * t * t, 40 * t, rho, iv), 0, 3)
    assert energy == pytest.approx(0.5 * rho * iv * ((50 + 180) ** 2 - 50**2), rel=1e-10)


@pytest.mark.parametrize("uniform", [True, False])
def test_first_order_lag_exact_for_ramps_and_steps(uniform):
    tau = 4.0
    t = np.linspace(0.0, 30.0, 151)
    if not uniform:
        t = np.sort(np.concatenate([t, [0.33, 7.77, 12.1]]))
    ramp = 2.0 * t
    # ramp from rest: y = 2 (t - tau (1 - e^{-t/tau})), exact for piecewise-linear input
    y = fx.first_order_lag(t, ramp, tau)
    assert np.allclose(y, 2 * (t - tau * (1 - np.exp(-t / tau))), atol=1e-12)
    # unit step held from t = 0 (input 1 from the start, output starting at 0)
    y = fx.first_order_lag(t, np.ones_like(t), tau, initial=0.0)
    assert np.allclose(y, 1 - np.exp(-t / tau), atol=1e-12)


def test_first_order_lag_sine_amplitude_and_phase():
    tau, f = 2.0, 0.05
    t = np.arange(0, 400, 0.05)
    y = fx.first_order_lag(t, np.sin(2 * np.pi * f * t), tau)
    wt = 2 * np.pi * f * tau
    late = t > 300
    expected = np.sin(2 * np.pi * f * t - math.atan(wt)) / math.sqrt(1 + wt * wt)
    # the update is exact for piecewise-linear input; a sine sampled every h differs from
    # its chords by O((w h)^2 / 12) = 2e-5 here
    assert np.max(np.abs(y[late] - expected[late])) < 5e-5
