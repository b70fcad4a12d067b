"""Rig data that are well formed but wrong: unit mistakes named, override text counted,
duplicate headers refused, no rotation refused (issue 12: nothing silent in the data)."""

import math
import warnings

import numpy as np
import pandas as pd
import pytest

from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.io.tables import read_table, text_cells
from oilgap.model.measured.data import load_measured, oil_samples, validate
from oilgap.optim.calibration.uncertainty import jackknife_ci

N = 20
"""Samples per run of the hand-made frames (every run is >= 10 samples long)."""


def _frame(**cols) -> pd.DataFrame:
    """Two runs of viscous-power data at plausible values (rpm, degC, W, s), ``cols``
    replacing columns."""
    t = np.arange(N) * 0.2
    speed = 3000.0 * np.sin(2 * np.pi * 0.05 * t + 0.3)
    df = pd.DataFrame({
        "run": ["a"] * N + ["b"] * N, "time_s": np.r_[t, t], "speed_rpm": np.r_[speed, speed],
        "temp_C": np.full(2 * N, 30.0), "oil": ["VG150"] * N + ["VG320"] * N,
        "roughness_T": [4.0] * N + [2.0] * N,
        "viscous_power_W": 5.0 + np.abs(np.r_[speed, speed]) / 100.0})
    for k, v in cols.items():
        df[k] = v
    return df


def _oilgap_warnings(fn):
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        out = fn()
    return out, [str(w.message) for w in rec if issubclass(w.category, OilgapWarning)]


def test_plausible_data_pass_without_a_warning():
    data, msgs = _oilgap_warnings(lambda: validate(_frame()))
    assert data.n_dropped == 0 and msgs == []


def test_temperature_in_kelvin_is_refused_naming_kelvin():
    df = _frame()
    df["temp_C"] = df["temp_C"] + 273.15
    with pytest.raises(InputError) as e:
        validate(df, source="rig.csv")
    msg = str(e.value)
    assert e.value.field == "temp_C median" and "looks like kelvin (subtract 273.15" in msg
    assert msg.startswith("rig.csv: ") and "\n" not in msg


def test_a_temperature_that_is_no_oil_temperature_is_refused():
    with pytest.raises(InputError, match="not an oil temperature in degC"):
        validate(_frame(temp_C=800.0))


def test_a_hot_median_warns_of_fahrenheit():
    _, msgs = _oilgap_warnings(lambda: validate(_frame(temp_C=120.0)))
    assert any("temp_C median 120.0 degC" in m and "degF" in m for m in msgs)


def test_no_viscous_signal_at_all_is_refused_for_fitting():
    with pytest.raises(InputError, match="no viscous signal") as e:
        validate(_frame(viscous_power_W=0.0))
    assert e.value.field == "viscous_power_W"
    assert validate(_frame(viscous_power_W=0.0), purpose="predict").n_dropped == 0


def test_no_rotation_is_refused_for_fitting_but_not_for_prediction():
    with pytest.raises(InputError, match="no rotation in the data") as e:
        validate(_frame(speed_rpm=0.0))
    assert e.value.field == "speed_rpm"
    data = validate(_frame(speed_rpm=0.0), purpose="predict")  # power 0 at rest: fine
    assert data.n_dropped == 0


def test_speed_scaled_x100_is_refused_and_x10_warns():
    df = _frame()
    with pytest.raises(InputError, match=r"x100\?") as e:
        validate(df.assign(speed_rpm=df["speed_rpm"] * 100))
    assert e.value.field == "speed_rpm peak"
    _, msgs = _oilgap_warnings(lambda: validate(df.assign(speed_rpm=df["speed_rpm"] * 10)))
    assert any("speed_rpm peak" in m and "x10?" in m for m in msgs)


def test_power_in_mw_or_kw_is_refused_and_a_small_one_warns():
    df = _frame()
    with pytest.raises(InputError, match="in mW"):
        validate(df.assign(viscous_power_W=df["viscous_power_W"] * 1e4))
    kw = df.rename(columns={"viscous_power_W": "power_W"})
    kw = pd.concat([kw, kw.assign(run=kw["run"] + "-free", oil="none")], ignore_index=True)
    kw["power_W"] = kw["power_W"] / 1000.0  # oil runs at a median 0.03 W: refused
    with pytest.raises(InputError, match=r"in kW\?") as e:
        validate(kw)
    assert e.value.field == "power_W median"
    kw["power_W"] = kw["power_W"] * 25.0  # 0.7 W: a small motor, perhaps: warned
    _, msgs = _oilgap_warnings(lambda: validate(kw))
    assert any("power_W median" in m and "multiply by 1000" in m for m in msgs)


def test_time_in_ms_warns_and_in_microseconds_is_refused():
    df = _frame()
    t = np.arange(N) * 0.2
    long = pd.concat([df] * 2, ignore_index=True)  # 40-sample runs: a 7.8 s run
    tt = np.r_[t, t + N * 0.2]
    long["time_s"] = np.r_[tt, tt]
    long["run"] = ["a"] * 2 * N + ["b"] * 2 * N
    _, msgs = _oilgap_warnings(lambda: validate(long.assign(time_s=long["time_s"] * 1e3 * 600)))
    assert any("time_s median step" in m and "divide by 1000" in m for m in msgs)
    with pytest.raises(InputError, match="time_s is not in seconds"):
        validate(long.assign(time_s=long["time_s"] * 1e7))


def test_override_text_is_dropped_and_counted_empty_cells_are_noted():
    df = _frame()
    gap = np.full(len(df), "", dtype=object)
    gap[[3, 4, 25]] = "abc"
    gap[5] = "1.2"
    df["gap_mm"] = gap
    data = validate(df, source="rig.csv")
    rec = {d.reason: d for d in data.dropped}
    reason = next(r for r in rec if r.startswith("gap_mm is text"))
    assert rec[reason].count == 3 and rec[reason].lines == (5, 6, 27)  # header = line 1
    assert data.n_read - data.n_dropped == 37
    assert data.notes == ("gap_mm empty in 36 of 37 oil rows: the case's region-1 clearance "
                          "used there",)
    assert "none dropped" not in data.drop_summary()


def test_override_missing_words_are_empty_cells_not_text():
    s = pd.Series(["1.0", "", "NA", "nan", "abc", " 2 ", "None"], dtype=object)
    assert text_cells(s).tolist() == [False, False, False, False, True, False, False]
    assert not text_cells(pd.Series([1.0, np.nan])).any()


def test_duplicate_header_is_refused_on_the_raw_header(tmp_path):
    # a ragged row makes pyarrow refuse the file: pandas, which would rename the second
    # temp_C to temp_C.1, reads it; the raw header is checked first
    p = tmp_path / "dup.csv"
    p.write_text("speed_rpm,temp_C,oil,roughness_T,temp_C,viscous_power_W\n"
                 "100,30,VG150,4,30,1.0\n100,30,VG150,4\n")
    with pytest.raises(InputError) as e:
        read_table(p)
    assert e.value.field == "columns" and e.value.value == ["temp_C"]
    with pytest.raises(InputError, match="column names must be unique"):
        load_measured(p)


def test_temperature_beyond_the_trusted_range_warns_when_used():
    df = _frame()
    df.loc[:4, "temp_C"] = 160.0  # median stays 30 degC; five rows beyond Walther's range
    data = validate(df)
    _, msgs = _oilgap_warnings(lambda: oil_samples(data, 1e-3))
    assert any(m.startswith("temp_C = 30..160 degC lies outside [-20, 150] degC") for m in msgs)


def test_jackknife_of_identical_folds_gives_no_interval():
    # every fold at the same value (a parameter pinned on a bound): no zero-width interval
    lo, hi = jackknife_ci(np.array([2.0, 1.0]), np.array([[2.0, 0.5], [2.0, 1.0],
                                                          [2.0, 1.5]]))
    assert math.isnan(lo[0]) and math.isnan(hi[0])
    assert hi[1] - lo[1] > 0  # the parameter the folds move keeps its interval
    lo, hi = jackknife_ci(np.array([2.0]), np.full((3, 1), 2.0), np.array([0.25]))
    assert hi[0] - lo[0] > 0  # the baseline's variance alone still gives one
