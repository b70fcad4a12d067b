"""Duty cycles: the seed's sine, CSV cycles, and the exact reduction to a speed distribution."""

import math

import numpy as np
import pytest

from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.errors import InputError


def write(tmp_path, text, name="cyc.csv"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_seed_sine_samples():
    cyc = DutyCycle.sine()
    # 300 s every 0.2 s: 1500 samples; 3000 rpm = 314.159 rad/s peak at t = 5 s (k = 25)
    assert len(cyc.time_s) == 1500 and cyc.time_s[-1] == pytest.approx(299.8)
    assert cyc.omega_rad_s[25] == pytest.approx(100 * math.pi, rel=1e-14)
    assert cyc.peak_omega_rad_s == pytest.approx(100 * math.pi, rel=1e-14)
    assert cyc.duration_s == pytest.approx(300.0, rel=1e-14)


def test_speed_distribution_equals_sample_mean():
    cyc = DutyCycle.sine()
    nodes, weights = cyc.speed_distribution()
    assert len(nodes) == 26
    assert weights.sum() == pytest.approx(1.0, abs=1e-15)
    for f in (lambda w: w**3, lambda w: w**2 * np.exp(w / 400)):
        plain = np.mean(f(np.abs(cyc.omega_rad_s)))
        assert f(nodes) @ weights == pytest.approx(plain, rel=1e-13)


def test_nonuniform_csv_weights_are_time_slots(tmp_path):
    # intervals 1, 3 s; the last sample takes the interval before it: weights 1, 3, 3 / 7
    cyc = DutyCycle.from_csv(write(tmp_path, "time_s,speed_rpm\n0,60\n1,-120\n4,60\n"))
    np.testing.assert_allclose(cyc.sample_weights(), [1 / 7, 3 / 7, 3 / 7], rtol=1e-15)
    nodes, weights = cyc.speed_distribution()
    # |omega| 2 pi (60 rpm = 1 rev/s) with weight 4/7 and 4 pi with 3/7
    np.testing.assert_allclose(sorted(nodes), [2 * math.pi, 4 * math.pi], rtol=1e-14)
    assert weights[np.argmin(nodes)] == pytest.approx(4 / 7, rel=1e-14)


@pytest.mark.parametrize("csv,field", [
    ("time_s,rpm\n0,1\n1,2\n", "columns"),
    ("time_s,speed_rpm\n0,1\n1,fast\n", "speed_rpm"),
    ("time_s,speed_rpm\n0,1\n1,2\n1,3\n", "time_s"),
    ("time_s,speed_rpm\n0,1\n2,2\n1,3\n", "time_s"),
    ("time_s,speed_rpm\n0,1\n1,nan\n", "speed_rpm"),
    ("time_s,speed_rpm\n0,1\n", "rows"),
])
def test_bad_duty_cycle_csv(tmp_path, csv, field):
    with pytest.raises(InputError) as e:
        DutyCycle.from_csv(write(tmp_path, csv))
    assert e.value.field == field


@pytest.mark.parametrize("kw,field", [
    ({"peak_speed_rpm": 0.0}, "peak_speed_rpm"),
    ({"frequency_hz": -1.0}, "frequency_hz"),
    ({"duration_s": 0.2, "sample_interval_s": 0.2}, "duration_s"),
])
def test_bad_sine_refused(kw, field):
    with pytest.raises(InputError) as e:
        DutyCycle.sine(**kw)
    assert e.value.field == field
