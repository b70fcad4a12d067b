"""The lumped thermal law: edge cases of the steady solver (numbers: tests/validation)."""

import numpy as np
import pytest

from oilgap.model.errors import InputError, SolverError
from oilgap.model.thermal import lumped_temperature_rate, steady_temperature


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
