"""The user's case first (issue 13): studies on a case other than the seed show that
case only, the oil-grade default mission comes from the case, every default the tool
fills in is listed, and smoothing takes a case."""

from __future__ import annotations

import json

import matplotlib
import pytest

from oilgap.cli import main
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.io.defaults import case_defaults, defaults_block, defaults_lines
from oilgap.optim.design import DesignProblem
from oilgap.studies import pareto
from oilgap.studies.oil_grade import study as oil_grade
from oilgap.studies.settings import OilGradeSettings, ParetoSettings, SmoothingSettings
from oilgap.studies.smoothing import study as smoothing

matplotlib.use("Agg")

JOINT = """name = "my joint"
[region1]
T1_mm = 38.5
T2_mm = 40.0
T3_mm = 40.8
T4_mm = 42.3
length_mm = 30.0
[region2]
radius_mm = 26.0
length_mm = 15.0
gap_mm = 4.0
[oil]
name = "VG32"
[operating]
depth_m = 4000.0
oil_temp_C = 4.0
[friction]
gamma = 0.566
"""
SEED_WORDS = ("seed (T = 4)", "smoothed seed", "seed's", "seed design")


@pytest.fixture(scope="module")
def case(tmp_path_factory):
    p = tmp_path_factory.mktemp("case") / "my.toml"
    p.write_text(JOINT)
    return read_case_toml(p), p


def test_reader_records_every_default(case):
    c, _ = case
    fields = {d.field: d for d in case_defaults(c)}
    # left out of the TOML: motor, bounds, duty cycle, friction form; given: oil, operating
    assert fields["motor.remanence_T"].value == 1.2
    assert fields["bounds.gap_min_mm"].value == pytest.approx(0.4)  # 0.5 x 0.8 mm
    assert fields["bounds.gap_max_mm"].value == pytest.approx(1.6)
    assert fields["bounds.radius_min_mm"].value == pytest.approx(36.0)  # 0.9 x 40 mm
    assert fields["bounds.length_max_mm"].value == pytest.approx(36.0)  # 1.2 x 30 mm
    assert fields["duty_cycle.peak_speed_rpm"].value == 3000.0
    # the torque bound left out: the NLP keeps the case's own torque capability
    assert fields["bounds.torque_min_Nm"].value == pytest.approx(
        DesignProblem(c).parameters().torque_min_Nm, rel=1e-12)
    assert "oil.name" not in fields and "operating.depth_m" not in fields
    assert "friction.gamma" not in fields  # given
    lines = "\n".join(defaults_lines(case_defaults(c)))
    for d in case_defaults(c):
        assert d.field in lines
    # a value changed after reading is no longer a default
    seed = seed_case()
    assert not any(d.field.startswith("operating") for d in case_defaults(seed))


def test_pareto_on_a_user_case_shows_that_case_only(case, tmp_path):
    c, _ = case
    r = pareto.run(tmp_path / "p", c, ParetoSettings(points=50))
    assert list(r.seeds["design"]) == ["this design (my joint)"]
    assert not r.is_seed
    # the reference point is this design's own power and the case's gap_max
    assert r.reference_point[0] == pytest.approx(1.6)
    assert r.reference_point[1] == pytest.approx(float(r.seeds["mean_power_W"].iloc[0]))
    text = "".join(f.read_text() for f in r.files if f.suffix in (".csv", ".md"))
    for w in SEED_WORDS:
        assert w not in text, w
    assert not (tmp_path / "p" / "pareto_seeds.csv").exists()
    assert "pareto.reference_point" in text and "bounds.gap_max_mm" in text
    assert pareto._whose(r) == "my joint's"


def test_oil_grade_default_mission_comes_from_the_case(case, tmp_path):
    c, _ = case
    r = oil_grade.run(tmp_path / "og", c, settings=OilGradeSettings(
        grades=("VG15", "VG32"), n_depth=2, n_temp=2, thermal="none"))
    assert [(m.depth_m, m.oil_temp_C, m.fraction) for m in r.mission] == [(4000.0, 4.0, 1.0)]
    assert "case's [operating]" in r.mission_source and not r.is_seed
    doc = json.loads((tmp_path / "og" / "oil_grade.json").read_text())
    got = {d["field"] for d in doc["defaults"]}
    assert {d["field"] for d in defaults_block(r.defaults)} == got
    assert {"oil_grade.mission", "oil_grade.nu_min_cSt", "bounds.gap_min_mm",
            "motor.gear_ratio"} <= got
    md = (tmp_path / "og" / "summary.md").read_text()
    head = md.split("## Defaults")[0]
    assert "seed design" not in head and "seed mission" not in head
    assert "4000 m, 4 degC" in head
    # the seed keeps its own mission
    assert oil_grade._mission(seed_case(), None)[0] == oil_grade.SEED_MISSION


def test_cli_headers_list_every_default(case, tmp_path, capsys):
    c, p = case
    assert main(["study", "oil-grade", str(p), "--thermal", "none", "--out",
                 str(tmp_path / "og")]) in (0, 3)
    out = capsys.readouterr().out
    for d in case_defaults(c):
        assert d.field in out, d.field
    assert "mission: default: one segment at the case's [operating] point (4000 m, 4 degC" \
        in out


def test_smoothing_on_a_case_matches_evaluate(case, tmp_path, capsys):
    c, p = case
    r = smoothing.run(tmp_path / "s", c)
    assert not r.seed_rig and r.table is None and r.fit is None
    s = r.plateau.iloc[0]
    # independent path: fill the grooves to T = 2 by hand (even split, as the grid does)
    # and evaluate the case directly under the same thermal mode
    two = c.with_region1(T1=39.6e-3, T4=41.2e-3)
    assert two.region1.roughness == pytest.approx(2.0)
    assert s["P_T2_W"] == pytest.approx(evaluate_case(two, thermal=r.thermal_mode)
                                        .total_mean_power_W, rel=1e-9)
    assert s["P_T_case_W"] == pytest.approx(evaluate_case(c, thermal=r.thermal_mode)
                                            .total_mean_power_W, rel=1e-9)
    assert r.loss_vs_T["T"].max() == pytest.approx(4.75)
    assert main(["study", "smoothing", str(p), "--out", str(tmp_path / "s2")]) == 0
    out = capsys.readouterr().out
    assert "filled to T = 2" in out and "seed rig" in out and "gamma       0.566" in out
    with pytest.raises(Exception, match="seed rig"):
        smoothing.run(None, c, SmoothingSettings(method="shared"))
