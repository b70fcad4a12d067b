"""``oilgap plan`` and its rehearsal: the plan's intervals against the loop's, beside the
naive plan; the command line as a user runs it.

The rehearsal's numbers are obtained independently of the plan: noisy runs simulated by
the synthetic rig, fitted by the loop (``LoopEstimator``), whose delete-one-run jackknife
gives the intervals. One jackknife over 6 runs scatters by about +-30 %, so the widths are
compared as their root mean square over 4 seeds.

The Couette floor (issue 27 item 4). At the synthetic rig's default scale 1 the smooth
Eq. 6 lies only 0.09 % above exact Couette in a laminar annulus: the floor's kink sits
at scale 0.99911, 1.2 expected sds below the truth, and below it the annulus carries no
information on the scale (only the 14 % of the power in region 2 does): the estimate's
sd below the kink is 7 times the linearised one. The loop's jackknife, symmetric, either
misses the kink (most seeds: 0.28 x the floor-aware width, median over 32 seeds) or
straddles it (3 of 32 seeds above 1.5 x, the largest 3.5 x); 4-seed RMS ratios range
0.27 .. 1.79 over seeds 0..31 and the 32-seed RMS is 0.99. Compared there: where the loop's
estimates fall against the plan's floor-aware interval. A rig's scale off the floor
(1.1: a real rotor runs eccentric and has end flows) is where the widths are compared.
"""

import json

import numpy as np
import pandas as pd
import pytest

import oilgap as og
from oilgap.cli import main
from oilgap.studies.plan.candidates import RUN_COLUMNS
from oilgap.studies.plan.rehearse import rehearse

SMALL = {"oils": ("VG150", "VG1000"), "bath_C": (25.0,), "profiles": ("sine",),
         "duration_s": 40.0, "runs": 6, "effects": ("thermal_lag", "taylor_vortex_onset")}
"""A small campaign: two oils, two rotors, one temperature, 40 s runs."""

OFF_FLOOR = 1.1
"""A rig's scale off the Couette floor [-] (the floor's kink 0.096 in ln scale below it)."""


@pytest.fixture(scope="module")
def small_plan():
    return og.plan(**SMALL)


def test_rehearsal_recovers_the_planned_intervals():
    res = og.plan(**SMALL, scale=OFF_FLOOR)
    # the D-optimal plan: the thick oil on both rotors (the most power per run)
    assert {r.oil for r in res.plan.runs} == {"VG1000"}
    assert {r.roughness_T for r in res.plan.runs} == {4.0, 2.0}
    assert res.plan.floor == {} and res.naive.floor == {}  # the kink is far below
    table = rehearse(res, seeds=(0, 1, 2, 3), effects=["thermal_lag"])
    assert set(table["parameter"]) == {"scale", "gamma"}
    for row in table.itertuples():  # both parameters, both plans
        assert 1 / 1.5 <= row.ratio <= 1.5, row
    w = table.set_index(["plan", "parameter"])["loop_rms_width"]
    assert w["plan", "gamma"] < w["naive", "gamma"]
    assert res.plan.interval["gamma"][1] - res.plan.interval["gamma"][0] < \
        res.naive.interval["gamma"][1] - res.naive.interval["gamma"][0]
    s = table.set_index(["plan", "parameter"])["loop_values"]
    assert np.median(s["plan", "scale"]) == pytest.approx(OFF_FLOOR, rel=2e-3)  # the truth


def test_rehearsal_at_the_couette_floor(small_plan):
    """At scale 1 the plan carries the scale's lower end through the floor's kink: every
    loop estimate over 20 seeds lies inside that interval, where some fall below the
    linearised lower end (the interval at t(5) x the jackknife sd, 2.8 sds: 1 of 20 here
    on each plan, 3 of 32, 8 of 64 on the plan; none above its upper end)."""
    res = small_plan
    f = res.plan.floor["scale"]
    lo, hi = res.plan.interval["scale"]
    assert f["kink"] == pytest.approx(1 / 1.0009, abs=2e-5)  # 0.09 % above Couette
    assert lo < f["linearised_lo"] < f["kink"] < 1.0 < hi
    assert 1.0 - lo > 3 * (hi - 1.0)  # a lower tail several times the upper
    # effects=[]: calibration_ci_ is the base law's, fitted before any effect is searched
    table = rehearse(res, seeds=range(20), effects=[]).set_index(["plan", "parameter"])
    for tag, ev in (("plan", res.plan), ("naive", res.naive)):
        v = np.array(table.loc[(tag, "scale"), "loop_values"])
        assert np.all((v > ev.interval["scale"][0]) & (v < ev.interval["scale"][1])), tag
        assert np.sum(v < ev.floor["scale"]["linearised_lo"]) >= 1, tag  # without the floor
        g = np.array(table.loc[(tag, "gamma"), "loop_values"])
        assert np.all((g > ev.interval["gamma"][0]) & (g < ev.interval["gamma"][1])), tag
        assert 1 / 1.5 <= table.loc[(tag, "gamma"), "ratio"] <= 1.5


def test_plan_reports_what_no_run_informs(small_plan):
    # the plan never reaches the Taylor onset (Ta < 41.3 in VG1000 at 25 degC): it cannot
    # detect the vortex; the naive plan's VG150 runs do
    assert small_plan.plan.detectable["taylor_vortex_onset"] == float("inf")
    assert "taylor_vortex_onset" in small_plan.plan.confounded["uninformed"]
    assert small_plan.naive.detectable["taylor_vortex_onset"] < 1.0
    assert small_plan.design.gap < 1e-3


def test_cli_plan_then_synth_plan(tmp_path, capsys):
    out = tmp_path / "p"
    args = ["plan", "--oil-grades", "VG150,VG1000", "--bath-C", "25", "--profiles", "sine",
            "--duration-s", "40", "--runs", "6", "--effects",
            "thermal_lag,taylor_vortex_onset", "--out", str(out)]
    assert main(args) == 0
    text = capsys.readouterr().out
    first = text.splitlines()[:5]
    assert first[0].startswith("plan        6 runs, D-optimal") and "VG1000" in first[0]
    assert any(line.startswith("gamma") and "naive" in line for line in first)
    plan = pd.read_csv(out / "plan.csv")
    naive = pd.read_csv(out / "naive.csv")
    assert list(plan.columns) == list(RUN_COLUMNS) == list(naive.columns)
    assert len(plan) == len(naive) == 6
    doc = json.loads((out / "plan.json").read_text())
    assert doc["plan"]["runs"] and doc["naive"]["runs"] and doc["continuous"]["gap"] < 1e-3
    assert (out / "plan_runs.png").stat().st_size > 10_000
    assert main(args) == 2  # an earlier plan is not overwritten unasked
    assert "--force" in capsys.readouterr().err

    data = tmp_path / "rig.csv"
    assert main(["synth", "--plan", str(out / "plan.csv"), "--seed", "1", "--effects",
                 "taylor_vortex_onset", "--out", str(data)]) == 0
    df = pd.read_csv(data)
    assert df["run"].nunique() == 6 and len(df) == 6 * 200
    assert set(df["oil"]) == {"VG1000"} and "viscous_power_W" in df.columns
    # the rig's true scale 1.1: more loss (less than 10 %: the oil heats up and thins)
    hot = tmp_path / "rig11.csv"
    assert main(["synth", "--plan", str(out / "plan.csv"), "--seed", "1", "--effects",
                 "taylor_vortex_onset", "--truth-scale", "1.1", "--out", str(hot)]) == 0
    ratio = pd.read_csv(hot)["viscous_power_W"].sum() / df["viscous_power_W"].sum()
    assert 1.02 < ratio < 1.1


def test_cli_plan_bad_input_is_one_line(tmp_path, capsys):
    assert main(["plan", "--bath-C", "warm", "--out", str(tmp_path / "x")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--bath-C" in err[0] and "warm" in err[0]
    assert main(["plan", "--profiles", "zigzag", "--out", str(tmp_path / "y")]) == 2
    assert "zigzag" in capsys.readouterr().err
    with pytest.raises(og.InputError, match="criterion"):
        og.plan(criterion="Z")
    assert main(["plan", "--expected-scale", "0", "--out", str(tmp_path / "z")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "scale = 0.0" in err[0] and not (tmp_path / "z").exists()
    assert "--expected-scale = 0.0" in err[0]  # the option typed, not the settings field
    assert main(["plan", "--sample-s", "0", "--out", str(tmp_path / "z")]) == 2
    assert "--sample-s = 0.0" in capsys.readouterr().err and not (tmp_path / "z").exists()
    assert main(["synth", "--truth-scale", "1.1", "--out", str(tmp_path / "s.csv")]) == 2
    assert "--truth-scale" in capsys.readouterr().err
    bad = tmp_path / "bad.csv"
    bad.write_text("run,order,oil,roughness_T,bath_C,profile,peak_speed_rpm,frequency_hz,"
                   "duration_s,sample_interval_s,pressure_MPa\n"
                   "P01,1,VG320,four,25,sine,3000,0.05,40,0.2,0\n")
    assert main(["synth", "--plan", str(bad), "--out", str(tmp_path / "d.csv")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "roughness_T (row 1)" in err[0] and "'four'" in err[0]
    good = tmp_path / "good.csv"
    good.write_text(bad.read_text().replace(",four,", ",4,"))
    assert main(["synth", "--plan", str(good), "--truth-scale", "0",
                 "--out", str(tmp_path / "d.csv")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--truth-scale = 0.0" in err[0]
    assert not (tmp_path / "d.csv").exists()


def test_budget_in_hours_sets_the_number_of_runs():
    from oilgap.studies.plan.study import plan_cost, sequence

    res = og.plan(**{**SMALL, "runs": None}, budget_h=9.0)
    st = res.settings
    n = len(res.plan.runs)
    # by hand: VG1000 on both rotors, (40/3600 + 0.25) h a run, one rotor change (4 h),
    # one oil change with it (2 h): n runs cost 6 + 0.2611 n <= 9 -> n = 11
    assert n == 11
    assert res.plan.cost_h == pytest.approx(6.0 + n * (40 / 3600 + 0.25))
    more = sequence(res.plan.runs + [res.plan.runs[0]], st)
    assert plan_cost(more, st)[0] > 9.0
