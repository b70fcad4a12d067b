"""The rig's speed profiles at hand-computed points (studies/rigs/profiles.py)."""

import numpy as np
import pytest

from oilgap.studies.rigs.profiles import profile_speed


def test_sine_is_the_seed_rig_s():
    t = np.array([0.0, 5.0, 10.0])  # f = 0.05 Hz: a quarter period is 5 s
    w, a = profile_speed("sine", t, 100.0, 0.05)
    assert w == pytest.approx([0.0, 100.0, 0.0], abs=1e-9)
    assert a[0] == pytest.approx(100.0 * 2 * np.pi * 0.05)


def test_trapezoid_holds_the_peak_and_ramps_linearly():
    # triangle 2.5 x (2/pi) asin(sin(2 pi f t)) clipped at 1: the ramp from 0 to the peak
    # takes 1/2.5 of a quarter period (2 s of 5 s), slope 2.5 x 4 f w0 = 50 rad/s^2
    w, a = profile_speed("trapezoid", np.array([1.0, 2.5, 5.0, 15.0]), 100.0, 0.05)
    assert w == pytest.approx([50.0, 100.0, 100.0, -100.0])
    assert a == pytest.approx([50.0, 0.0, 0.0, 0.0])


def test_steps_climb_four_levels():
    # period 20 s: levels w0/4, w0/2, 3w0/4, w0 for 5 s each, a ramp over 5 % (0.25 s)
    w, a = profile_speed("steps", np.array([2.0, 7.0, 12.0, 17.0, 5.125]), 100.0, 0.05)
    assert w == pytest.approx([25.0, 50.0, 75.0, 100.0, 37.5])
    assert a[:4] == pytest.approx([0.0] * 4)
    assert a[4] == pytest.approx(25.0 / 0.25)
