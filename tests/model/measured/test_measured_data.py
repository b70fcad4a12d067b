"""Measured data: validation with counted drop reasons, file errors, overrides, kinematics."""

import numpy as np
import pandas as pd
import pytest
from scipy.signal import savgol_filter

from oilgap.cli import main
from oilgap.model.errors import InputError
from oilgap.model.io import tables as table_io
from oilgap.model.measured.data import (
    load_measured,
    oil_samples,
    read_table,
    time_derivative,
    validate,
)
from oilgap.model.oils import get_oil


def _run(name, oil, T, n=40, dt=0.2, power="power_W", **extra):
    t = np.arange(n) * dt
    d = {"run": name, "time_s": t, "speed_rpm": 3000 * np.sin(0.1 * np.pi * t),
         "temp_C": 30.0 + 0.01 * t, "oil": oil, "roughness_T": T, power: 20 + t}
    d.update(extra)
    return pd.DataFrame(d)


def _frame():
    return pd.concat([_run("free4", "none", 4.0), _run("a", "VG150", 4.0),
                      _run("b", "VG320", 4.0)], ignore_index=True)


def test_clean_frame_keeps_every_row():
    md = validate(_frame())
    assert md.n_read == 120 and md.n_dropped == 0 and md.kind == "power_W"
    assert md.drop_summary() == "120 rows read, none dropped"


def test_each_bad_row_is_counted_under_its_reason():
    df = _frame().astype(object)
    df.loc[41, "speed_rpm"] = "fast"          # a: non-numeric
    df.loc[42, "temp_C"] = np.nan             # a: missing
    df.loc[43, "roughness_T"] = 0.5           # a: T < 1
    df.loc[44, "temp_C"] = 900.0              # a: not an oil temperature
    df.loc[45, "time_s"] = df.loc[46, "time_s"]  # a: duplicate time (45 kept, 46 dropped)
    df.loc[50, "time_s"] = 0.1                # a: goes back in time
    df.loc[[81, 82], "oil"] = "VG9999"        # b: unknown oil
    df.loc[83, "oil"] = "VG150"               # b: other oil than its run
    df.loc[84, "run"] = ""                    # missing run
    df.loc[85, "nu_cSt"] = -3                 # b: bad override
    extra = _run("short", "VG150", 4.0, n=5)  # too short
    other_T = _run("c", "VG150", 2.0)          # no oil-free run at T = 2
    df = pd.concat([df, extra, other_T], ignore_index=True)
    md = validate(df)
    got = {r.reason: r.count for r in md.dropped}
    assert got == {
        "missing run": 1,
        "speed_rpm missing or not a finite number": 1,
        "temp_C missing or not a finite number": 1,
        "nu_cSt not a positive finite number": 1,
        "roughness_T < 1": 1,
        "temp_C outside [-60, 300] degC": 1,
        "oil 'VG9999' not in the oils table (and no nu_cSt + density_kg_m3)": 2,
        "oil differs from the rest of its run": 1,
        "duplicate time_s within run": 1,
        "time_s does not increase within run": 1,
        "run shorter than 10 samples": 5,
        "no oil-free baseline run with roughness_T = 2": 40,
    }
    assert md.n_dropped == sum(got.values()) == 56
    assert len(md.frame) == len(df) - 56
    lines = {r.reason: r.lines for r in md.dropped}
    assert lines["speed_rpm missing or not a finite number"] == (43,)  # header is line 1


@pytest.mark.parametrize("change, message", [
    (lambda d: d.drop(columns=["temp_C"]), "missing \\['temp_C'\\]"),
    (lambda d: d.assign(viscous_power_W=1.0), "both given"),
    (lambda d: d.drop(columns=["power_W"]), "neither given"),
    (lambda d: d.rename(columns={"power_W": "Power_W"}), "case-sensitive"),
    (lambda d: d[d["oil"] == "none"], "no oil run"),
])
def test_unusable_tables_raise_one_input_error(change, message):
    with pytest.raises(InputError, match=message):
        validate(change(_frame()))


def test_unreadable_files(tmp_path):
    (tmp_path / "empty.csv").write_text("")
    (tmp_path / "bin.csv").write_bytes(bytes(range(256)) * 4)
    (tmp_path / "x.parquet").write_text("not parquet")
    for name in ("missing.csv", "empty.csv", "bin.csv", "x.parquet"):
        with pytest.raises(InputError):
            read_table(tmp_path / name)


def test_cli_bad_file_exits_2_with_one_line(tmp_path, capsys):
    p = tmp_path / "d.csv"
    _frame().drop(columns=["oil"]).to_csv(p, index=False)
    assert main(["loop", str(p), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("oilgap: error:") and "oil" in err[0]
    assert main(["loop", str(tmp_path / "nope.csv")]) == 2


def test_property_overrides_and_gap(tmp_path):
    a = _run("a", "MyFluid", 4.0, power="viscous_power_W", nu_cSt=55.0, density_kg_m3=812.0,
             gap_mm=0.8)
    b = _run("b", "VG150", 4.0, power="viscous_power_W")
    df = pd.concat([a, b], ignore_index=True)
    df.loc[len(a):, ["nu_cSt", "density_kg_m3", "gap_mm"]] = np.nan
    p = tmp_path / "d.parquet"
    df.to_parquet(p)
    md = load_measured(p)
    assert md.n_dropped == 0 and md.kind == "viscous_power_W"
    s = oil_samples(md, region1_gap_m=1.0e-3)
    fluid = s.oil == "MyFluid"
    assert np.allclose(s.nu_m2_s[fluid], 55e-6) and np.allclose(s.density_kg_m3[fluid], 812)
    assert np.allclose(s.gap1_m[fluid], 0.8e-3) and np.allclose(s.gap1_m[~fluid], 1e-3)
    assert np.all(np.isnan(s.nu_pm[0][fluid]))  # no temperature law for the override
    nu, _, _ = get_oil("VG150").properties(s.temp_C[~fluid] + 273.15, 0.0)
    assert np.allclose(s.nu_m2_s[~fluid], nu)


def test_time_derivative_of_a_sine():
    t = np.arange(0, 60, 0.2)
    w = 314.16 * np.sin(0.1 * np.pi * t)
    d = time_derivative(t, w, 1.0)
    exact = 314.16 * 0.1 * np.pi * np.cos(0.1 * np.pi * t)
    # quadratic Savitzky-Golay over 5 samples: error ~ w''' h^2 (N^2 - ...) / 20 << 1 %
    assert np.max(np.abs(d - exact)[2:-2]) < 0.005 * np.max(np.abs(exact))


# --------------------------------------------------------------------------- steady points


def _steady(n=4, **extra):
    """Steady operating points, no time_s and no run: two oils x two T, n speeds each."""
    rows = []
    for oil in ("VG150", "VG320"):
        for T in (4.0, 2.0):
            for k in range(n):
                rows.append({"speed_rpm": 500.0 * (k + 1), "temp_C": 30.0 + k, "oil": oil,
                             "roughness_T": T, "viscous_power_W": 10.0 + k})
    return pd.DataFrame(rows).assign(**extra)


def test_steady_points_need_no_time_and_no_run():
    md = validate(_steady())
    assert not md.has_time and md.n_dropped == 0
    f = md.frame
    # one group per (oil, T): 4 groups of 4 rows, each a "run" though shorter than a
    # time-series run may be (MIN_RUN_SAMPLES = 10 applies to time series only)
    assert sorted(set(f["run"])) == ["VG150 T=2", "VG150 T=4", "VG320 T=2", "VG320 T=4"]
    assert (f.groupby("run", observed=True).size() == 4).all()
    assert (f["time_s"] == 0).all()
    s = oil_samples(md, region1_gap_m=1.0e-3)
    assert not s.has_time and np.all(s.domega_dt == 0) and np.all(s.dtemp_dt == 0)
    assert s.cv_by == "run" and np.array_equal(s.cv_group, s.run_code)
    # file order is kept within a group (no time to sort by): speeds 500, 1000, ...
    assert f.loc[f["run"] == "VG320 T=4", "speed_rpm"].tolist() == [500, 1000, 1500, 2000]


def test_steady_groups_include_the_gap_and_time_needs_a_run():
    df = _steady(gap_mm=np.tile([0.5, 0.8], 8))
    assert len(set(validate(df).frame["run"])) == 8  # (oil, T, gap)
    with pytest.raises(InputError, match="with run when time_s"):
        validate(_steady().assign(time_s=0.0))


def test_cv_groups_by_any_column_and_refusals():
    md = validate(_steady(gap_mm=np.tile([0.5, 0.8], 8), rig=np.repeat(["A", "B"], 8)))
    s = oil_samples(md, 1.0e-3, cv_by="gap_mm")
    assert s.cv_names == ("0.5", "0.8") and s.cv_by == "gap_mm"
    assert np.array_equal(s.cv_group, np.round(s.gap1_m * 1e3, 6) == 0.8)
    s = oil_samples(md, 1.0e-3, cv_by="rig")           # a column outside the format
    assert s.cv_names == ("A", "B") and np.bincount(s.cv_group).tolist() == [8, 8]
    s = oil_samples(md, 1.0e-3, cv_by="oil")
    assert s.cv_names == ("VG150", "VG320")
    with pytest.raises(InputError, match="not a column of the data"):
        oil_samples(md, 1.0e-3, cv_by="gap")
    with pytest.raises(InputError, match="has 1 group"):
        oil_samples(validate(_steady()), 1.0e-3, cv_by="gap_mm")  # every row at the case gap
    with pytest.raises(InputError, match="has 1 group"):
        oil_samples(validate(_steady().assign(oil="VG150")), 1.0e-3, cv_by="oil")


# --------------------------------------------------------------------------- reading


def test_pyarrow_and_pandas_readers_give_the_same_validated_data(tmp_path, monkeypatch):
    df = _frame().astype(object)
    df.loc[41, "speed_rpm"] = "fast"
    df.loc[42, "temp_C"] = ""
    df.loc[43, "run"] = " a "                 # stripped: still run a
    df.loc[44, "oil"] = "nan"
    df["note"] = "x"
    p = tmp_path / "d.csv"
    df.to_csv(p, index=False)
    fast = load_measured(p)
    monkeypatch.setattr(table_io, "_read_csv_arrow", lambda path: None)   # pandas' parser
    slow = load_measured(p)
    assert [r.to_dict() for r in fast.dropped] == [r.to_dict() for r in slow.dropped]
    assert {r.reason: r.count for r in fast.dropped} == {
        "missing oil": 1, "speed_rpm missing or not a finite number": 1,
        "temp_C missing or not a finite number": 1}
    for c in ("run", "oil", "time_s", "speed_rpm", "temp_C", "power_W", "line"):
        assert fast.frame[c].astype(str).tolist() == slow.frame[c].astype(str).tolist()
    reasons = fast.row_reasons()
    assert reasons[41] == "speed_rpm missing or not a finite number" and reasons[0] == ""


def test_predict_validation_needs_no_power_and_takes_any_row_order():
    df = _frame().drop(columns=["power_W"]).sample(frac=1.0, random_state=3)
    md = validate(df, purpose="predict")
    assert md.kind == "none"
    assert {r.reason: r.count for r in md.dropped} == {
        "oil-free row (no viscous loss to predict)": 40}
    f = md.frame
    assert f["run"].tolist() == ["a"] * 40 + ["b"] * 40   # sorted by run, then time
    assert np.all(np.diff(f["time_s"].to_numpy()[:40]) > 0)
    with pytest.raises(InputError, match="exactly one of"):
        validate(df)                            # fitting needs a power column


def test_long_savitzky_golay_window_by_fft_equals_the_filter():
    # 1 kHz logging: the 1 s window has 1001 samples; the FFT convolution with the
    # filter's coefficients must equal scipy's direct filter (a second method) to rounding
    rng = np.random.default_rng(1)
    t = np.arange(20000) * 1e-3
    x = np.cumsum(rng.normal(size=t.size)) + 300 * np.sin(0.3 * t)
    direct = savgol_filter(x, 1001, 2, deriv=1, delta=1e-3, mode="interp")
    fast = time_derivative(t, x, 1.0)
    assert np.max(np.abs(fast - direct)) < 1e-10 * np.max(np.abs(direct))
