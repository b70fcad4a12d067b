"""The lumped thermal law: edge cases of the steady solver (numbers: tests/validation), and
the joint's bulk balance against hand solutions and its own ODE."""

import numpy as np
import pytest

from oilgap.model.case import ThermalSpec
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
    np.testing.assert_allclose(powers, falling(temps), rtol=1e-12)


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
