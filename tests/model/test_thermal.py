"""The lumped thermal law: edge cases of the steady solver (numbers: tests/validation), the
joint's bulk balance against hand solutions and its own ODE, the monotonicity checks, and
the film's fixed point (model.effects.film_temperature) solved by the same solver."""

import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.model.case import ThermalSpec
from oilgap.model.effects import film_temperature
from oilgap.model.errors import InputError, SolverError
from oilgap.model.thermal import (
    joint_steady_temperature,
    joint_temperature_transient,
    lumped_temperature_rate,
    steady_temperature,
)


def falling(temps):
    return 100.0 * np.exp(-0.05 * np.asarray(temps))


def test_zero_resistance_keeps_the_base_temperature():
    temps, powers = steady_temperature(falling, np.array([5.0, 30.0]), 0.0, 2)
    np.testing.assert_array_equal(temps, [5.0, 30.0])
    np.testing.assert_allclose(powers, falling([5.0, 30.0]), rtol=1e-15)


def test_root_lies_in_the_bracket_and_solves_the_balance():
    tb, rth = np.array([0.0, 10.0, 40.0]), 0.3
    temps, powers = steady_temperature(falling, tb, rth, 3)
    assert np.all(temps >= tb) and np.all(temps <= tb + rth * falling(tb))
    np.testing.assert_allclose(temps - tb - rth * falling(temps), 0.0, atol=1e-9)
    # the last step may be taken without another evaluation, the loss carried to it
    # linearly (error P'' s^2/2 with |s| < 1e-4 K)
    np.testing.assert_allclose(powers, falling(temps), rtol=1e-10)


def test_bad_resistance_and_no_convergence():
    with pytest.raises(InputError) as e:
        steady_temperature(falling, 10.0, -1.0, 1)
    assert e.value.field == "resistance_K_W"
    with pytest.raises(SolverError):
        steady_temperature(falling, 10.0, 0.3, 1, max_iter=0)


def test_rate_signs():
    # warmer than the steady point T_amb + R P: cools; colder: warms
    assert lumped_temperature_rate(30.0, 10.0, 0.0, 1.0, 100.0) < 0
    assert lumped_temperature_rate(5.0, 10.0, 0.0, 1.0, 100.0) > 0


# --------------------------------------------------------------------------- joint balance
# (oilgap.model.case.ThermalSpec: T = T_sea + R (P(T) + Q), C dT/dt = P + Q - (T - T_sea)/R)

A_W, C_1_K, T0_C = 80.0, 0.04, 2.0


def exp_law(temps):
    """P(T) = a exp(-c (T - T0)) [W]: falls with T like a viscous loss."""
    return A_W * np.exp(-C_1_K * (np.asarray(temps, dtype=float) - T0_C))


def test_steady_fixed_point_is_the_transient_steady_state():
    spec = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.4, heat_capacity_J_K=200.0,
                       other_heat_W=15.0)
    (t_star,), (p_star,) = joint_steady_temperature(exp_law, spec)
    # tau = R C = 80 s at most (dP/dT < 0 only shortens it); 4000 s = 50 tau
    for start in (spec.sea_temp_C, 60.0):
        temps = joint_temperature_transient(lambda t, temp: exp_law(temp), spec,
                                            np.linspace(0.0, 4000.0, 5), start)
        assert temps[0] == start
        assert abs(temps[-1] - t_star) < 1e-6
    assert t_star - spec.sea_temp_C == pytest.approx(0.4 * (p_star + 15.0), abs=1e-9)


def test_linear_law_against_hand_solution():
    # P = a - b T: T = T_sea + R (a - b T + Q)  =>  T* = (T_sea + R (a + Q)) / (1 + R b)
    a, b, sea, r, q = 50.0, 0.3, 4.0, 0.8, 10.0
    spec = ThermalSpec(sea_temp_C=sea, resistance_K_W=r, heat_capacity_J_K=1.0,
                       other_heat_W=q)
    temps, powers = joint_steady_temperature(lambda t: a - b * np.asarray(t), spec)
    hand = (sea + r * (a + q)) / (1.0 + r * b)  # = 52/1.24 = 41.935483870967744
    assert hand == pytest.approx(41.935483870967744, rel=1e-15)
    assert temps[0] == pytest.approx(hand, abs=1e-9)
    assert powers[0] == pytest.approx(a - b * hand, abs=1e-9)


def test_other_heat_raises_the_temperature_by_R_times_Q_at_constant_power():
    base = ThermalSpec(sea_temp_C=3.0, resistance_K_W=0.25, heat_capacity_J_K=500.0)
    more = ThermalSpec(sea_temp_C=3.0, resistance_K_W=0.25, heat_capacity_J_K=500.0,
                       other_heat_W=40.0)
    const = lambda temps: np.full(np.shape(temps), 20.0)  # noqa: E731
    (t0,), _ = joint_steady_temperature(const, base)
    (t1,), _ = joint_steady_temperature(const, more)
    # the solver's tolerance on the residual is 1e-9 K
    assert t0 == pytest.approx(3.0 + 0.25 * 20.0, abs=1e-9)
    assert t1 - t0 == pytest.approx(0.25 * 40.0, abs=2e-9)


def test_transient_of_constant_power_is_the_exponential():
    # C dT/dt = P + Q - (T - T_sea)/R: T = T_inf + (T_0 - T_inf) exp(-t / (R C))
    spec = ThermalSpec(sea_temp_C=1.0, resistance_K_W=0.5, heat_capacity_J_K=100.0,
                       other_heat_W=4.0)
    t = np.array([0.0, 10.0, 50.0, 200.0])
    temps = joint_temperature_transient(lambda time, temp: 16.0, spec, t, 1.0)
    t_inf = 1.0 + 0.5 * 20.0
    np.testing.assert_allclose(temps, t_inf + (1.0 - t_inf) * np.exp(-t / 50.0), atol=1e-8)


def test_transient_refuses_bad_times():
    spec = ThermalSpec(sea_temp_C=1.0, resistance_K_W=0.5, heat_capacity_J_K=100.0)
    with pytest.raises(InputError) as e:
        joint_temperature_transient(lambda time, temp: 1.0, spec, [0.0, 0.0], 1.0)
    assert e.value.field == "t_s" and "\n" not in str(e.value)


# --------------------------------------------------------------------------- monotonicity
# g(T) = T - T_base - R P(T) has one root while dP/dT < 1/R; the solver checks it


def test_loss_rising_slower_than_one_over_R_is_solved_above_the_first_bracket():
    # P = a + s T (a gas: the loss rises with T), R s = 0.2 < 1:
    # T* = T_b + R (a + s T*)  =>  T* = (T_b + R a)/(1 - R s) = (5 + 0.5*20)/(1 - 0.2) = 18.75,
    # above T_b + R P(T_b) = 5 + 0.5*21 = 15.5, the top of the falling-loss bracket
    a, s, r, tb = 20.0, 0.4, 0.5, 5.0
    temps, powers = steady_temperature(lambda t: a + s * np.asarray(t), tb, r, 1)
    # residual tolerance 1e-9 K over dg/dT = 1 - R s = 0.8
    assert temps[0] == pytest.approx(18.75, abs=1.25e-9)
    assert powers[0] == pytest.approx(a + s * 18.75, abs=1e-9)


def sigmoid(x):
    return 1.0 / (1.0 + np.exp(-np.asarray(x, dtype=float)))


def test_a_residual_falling_between_base_and_its_one_root_is_solved():
    # P = 100 - T + 30 s(T - 50), R = 1, T_b = 0: g = 2T - 100 - 30 s(T - 50) falls near
    # T = 50 (dP/dT = 6.5 W/K there) but keeps g < 0 below its one root near 65:
    # 2T - 100 - 30 (1 - e^-15) = 0  =>  T = 65 - 15 e^-15 = 64.99999541
    t, _ = steady_temperature(lambda t: 100.0 - np.asarray(t) + 30.0 * sigmoid(
        np.asarray(t) - 50.0), 0.0, 1.0, 1)
    assert t[0] == pytest.approx(65.0 - 15.0 * np.exp(-15.0), abs=1e-8)


def test_a_downward_step_of_the_loss_at_the_root_is_the_root():
    # Eq. 6 is piecewise in Re, so P(T) has small steps where a speed node changes
    # regime. P = 10 - 0.5 T below T = 6.66 and 9.97 - 0.5 T above, R = 1, T_b = 0:
    # g = 1.5 T - 10 -> g(6.66-) = -0.01 K; g = 1.5 T - 9.97 -> g(6.66+) = +0.02 K.
    # g never vanishes: the balance sits on the step, T = 6.66.
    def power(t):
        t = np.asarray(t, dtype=float)
        return np.where(t < 6.66, 10.0, 9.97) - 0.5 * t
    t, p = steady_temperature(power, 0.0, 1.0, 1)
    assert t[0] == pytest.approx(6.66, abs=2e-9)
    assert p[0] == pytest.approx(power(t)[0])


def test_the_lowest_of_several_roots_is_the_one_returned():
    # P = 10 + 40 s((T - 30)/2), R = 1, T_b = 0: g = T - 10 - 40 s has a stable root just
    # above 10, an unstable one near 30 and a stable one near 50. Oil warming from T_b
    # stops at the first: brentq on [5, 20], where g changes sign once.
    def power(t):
        return 10.0 + 40.0 * sigmoid((np.asarray(t) - 30.0) / 2.0)
    root = brentq(lambda x: x - float(power(x)), 5.0, 20.0, xtol=1e-13)
    t, _ = steady_temperature(power, 0.0, 1.0, 1)
    assert t[0] == pytest.approx(root, abs=1e-8)


def test_a_root_above_a_lower_one_raises():
    # the same loss from a bracket that only holds the upper root: T_b chosen so that
    # the first bracket's top lies between the roots: not possible for a loss that
    # starts at 10 W; instead shift the middle root below T_b + R P(T_b): with P as
    # above but T_b = 12, g(12) = 2 - 40 s(-9) > 0 ... the balance is then found at the
    # lower root, so the scan must be exercised on the rising branch: P = 20 + 0.5 T
    # below 10 and 30 above (a jump up of 5 W at T = 10), T_b = 0, R = 1:
    # g = 0.5 T - 20 < 0 up to 10, then T - 30: root 30, and no lower root
    def power(t):
        t = np.asarray(t, dtype=float)
        return np.where(t < 10.0, 20.0 + 0.5 * t, 30.0)
    t, _ = steady_temperature(power, 0.0, 1.0, 1)
    assert t[0] == pytest.approx(30.0, abs=1e-8)


def test_film_temperature_is_the_same_fixed_point_per_sample():
    # T_f = T + c P(T_f) with P depending on the sample (2-D samples), against brentq
    T = np.array([[2.0, 20.0, 40.0], [5.0, 10.0, 60.0]])
    scale = np.array([[50.0, 80.0, 300.0], [10.0, 0.0, 600.0]])

    def power(t):
        return scale * np.exp(-0.06 * (np.asarray(t) - 20.0))

    c = 0.08
    got = film_temperature(T, power, c)
    assert got.shape == T.shape
    for t0, a, tf in zip(T.ravel(), scale.ravel(), got.ravel(), strict=True):
        ref = brentq(lambda x, t0=t0, a=a: x - t0 - c * a * np.exp(-0.06 * (x - 20.0)),
                     t0, t0 + c * a * 10.0 + 1.0, xtol=1e-13)
        assert tf == pytest.approx(ref, abs=1e-9)
    assert got[1, 1] == T[1, 1]  # no loss, no rise
