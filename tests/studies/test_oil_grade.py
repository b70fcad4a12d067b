"""Oil-grade study: envelope extremes and mission energy recomputed independently
with the model, the limit logic, the recommendation rule, bad input."""

from dataclasses import replace

import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.case import MissionSegment, OperatingPoint
from oilgap.model.errors import InputError
from oilgap.model.evaluation import mean_viscous_power
from oilgap.model.io.case_io import seed_case
from oilgap.model.oils import get_oil
from oilgap.studies.oil_grade import study as oil_grade
from oilgap.studies.oil_grade.study import SEED_MISSION, parse_mission
from oilgap.studies.settings import OilGradeSettings, split_keywords


def run(out_dir=None, case=None, mission=None, **keywords):
    """The study from keywords, as the façade builds its records."""
    return oil_grade.run(out_dir, case, mission, *split_keywords(keywords, OilGradeSettings))

GRADES = ("VG10", "VG15", "VG22", "VG32", "VG46")
SMALL = dict(grades=GRADES, n_depth=3, n_temp=3, workers=1)


@pytest.fixture(scope="module")
def result():
    return run(**SMALL)


def power(oil, depth_m, temp_C):
    c = seed_case()
    return mean_viscous_power(replace(c, oil=get_oil(oil),
                                      operating=OperatingPoint(depth_m, temp_C)))


def test_envelope_extremes_are_the_hot_shallow_and_cold_deep_corners(result):
    t = result.table.set_index("oil")
    for g in GRADES:
        oil = get_oil(g)
        assert t.loc[g, "nu_min_envelope_cSt"] == pytest.approx(
            oil.kinematic_viscosity_cSt(40.0, 0.0), rel=1e-12)
        assert t.loc[g, "nu_max_envelope_cSt"] == pytest.approx(
            oil.kinematic_viscosity_cSt(0.0, 7000.0), rel=1e-12)
        assert (t.loc[g, "nu_min_at_C"], t.loc[g, "nu_min_at_m"]) == (40.0, 0.0)
        assert (t.loc[g, "nu_max_at_C"], t.loc[g, "nu_max_at_m"]) == (0.0, 7000.0)


def test_mission_energy_recomputed_by_hand(result):
    t = result.table.set_index("oil")
    for g in ("VG15", "VG32"):
        mean = sum(s.fraction * power(g, s.depth_m, s.oil_temp_C) for s in SEED_MISSION)
        assert t.loc[g, "mission_mean_power_W"] == pytest.approx(mean, rel=1e-12)
        assert t.loc[g, "mission_energy_Wh"] == pytest.approx(mean * 8.0, rel=1e-12)
    assert t.loc["VG22", "rated_power_W"] == pytest.approx(power("VG22", 3000.0, 2.0),
                                                          rel=1e-12)


def test_limits_and_recommendation_rule(result):
    t = result.table.set_index("oil")
    tol = 0.10
    for g in GRADES:
        lo = get_oil(g).kinematic_viscosity_cSt(40.0, 0.0)
        hi = get_oil(g).kinematic_viscosity_cSt(0.0, 7000.0)
        assert t.loc[g, "passes_lubrication"] == ((1 - tol) * lo >= 13.0)
        assert t.loc[g, "passes_cold"] == ((1 + tol) * hi <= 1000.0)
    feas = t[t["feasible"]]
    assert result.recommended == feas["mission_energy_Wh"].idxmin()
    assert result.runner_up == feas["mission_energy_Wh"].drop(result.recommended).idxmin()
    for _, row in t.iterrows():
        if not row["feasible"]:
            assert row["verdict"] == "fails" and "limit" in row["reason"]


def test_tighter_limits_change_the_answer_and_none_can_pass():
    lo22 = get_oil("VG22").kinematic_viscosity_cSt(40.0, 0.0)
    r = run(nu_min_cSt=0.95 * lo22, iso_tolerance=0.0, nu_max_cSt=5000.0, **SMALL)
    assert r.recommended == "VG22"  # VG10/VG15 too thin now; VG22 the thinnest that passes
    r = run(nu_min_cSt=500.0, nu_max_cSt=600.0, **SMALL)
    assert r.recommended is None and (r.table["verdict"] == "fails").all()


def test_case_mission_rows_are_used():
    case = replace(seed_case(), mission=(MissionSegment(1000.0, 10.0, 0.5),
                                         MissionSegment(6000.0, 1.0, 0.5)))
    r = run(case=case, **SMALL)
    assert r.mission == case.mission
    t = r.table.set_index("oil")
    mean = 0.5 * power("VG22", 1000.0, 10.0) + 0.5 * power("VG22", 6000.0, 1.0)
    assert t.loc["VG22", "mission_mean_power_W"] == pytest.approx(mean, rel=1e-12)


@pytest.mark.parametrize("mission", [
    [(0.0, 20.0, 0.5), (3000.0, 2.0, 0.4)],
    pd.DataFrame({"depth_m": [0.0], "temp": [2.0], "fraction": [1.0]}),
    [],
    [(0.0, 20.0, 1.2)],
])
def test_bad_missions(mission):
    with pytest.raises(InputError):
        parse_mission(mission)


def test_parse_mission_accepts_rows_summing_to_one():
    m = parse_mission([(0.0, 20.0, 0.25), (3000.0, 2.0, 0.75)])
    assert [s.fraction for s in m] == [0.25, 0.75]


@pytest.mark.parametrize("kw", [dict(nu_min_cSt=100.0, nu_max_cSt=50.0),
                                dict(depth_range_m=(100.0, 0.0)), dict(n_temp=1),
                                dict(grades=("VG7",)), dict(mission_hours=0.0)])
def test_bad_parameters(kw):
    with pytest.raises(InputError):
        run(**{**SMALL, **kw})


def test_cli_bad_mission_exits_2(tmp_path, capsys):
    p = tmp_path / "m.csv"
    p.write_text("depth_m,oil_temp_C,fraction\n0,20,0.5\n3000,2,0.4\n")
    assert main(["study", "oil-grade", "--mission", str(p), "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "must sum to 1" in err[0]


def test_outputs_written(tmp_path):
    r = run(tmp_path, **SMALL)
    for f in ("oil_grade_table.csv", "oil_grade_heatmap.png", "oil_grade_loss_vs_grade.png",
              "summary.md"):
        assert (tmp_path / f).stat().st_size > 0
    assert f"Recommended: {r.recommended}" in (tmp_path / "summary.md").read_text()
