"""The oil-grade study under the thermal modes: a constructed case whose answer follows
by hand from the monotone heat balance; the cold start and the mission energy recomputed
with the model's single-case path; film keeps the limits; outputs; bad input."""

import json
from dataclasses import replace

import pytest

from oilgap.cli import main
from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InputError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import joint_mean_power, operating_temperature
from oilgap.model.oils import get_oil
from oilgap.studies.io.case_write import write_case_toml
from oilgap.studies.oil_grade import study as oil_grade
from oilgap.studies.oil_grade.study import SEED_MISSION
from oilgap.studies.settings import OilGradeSettings, split_keywords


def run(out_dir=None, case=None, mission=None, **keywords):
    """The study from keywords, as the façade builds its records."""
    return oil_grade.run(out_dir, case, mission, *split_keywords(keywords, OilGradeSettings))

GRADES = ("VG15", "VG22", "VG32")
SEA, R = 2.0, 0.5
DEPTHS, SEAS = (0.0, 7000.0), (0.0, 40.0)
LIMIT = 0.99 * get_oil("VG15").kinematic_viscosity_cSt(40.0, 0.0)  # 14.85 cSt
SMALL = dict(grades=GRADES, n_depth=2, n_temp=2, workers=1, iso_tolerance=0.0,
             nu_min_cSt=LIMIT, nu_max_cSt=1000.0, depth_range_m=DEPTHS)


def thermal_case():
    return replace(seed_case(), thermal=ThermalSpec(SEA, R, 5e4))


def with_oil(case, oil, sea=None, depth=None):
    """``case`` with another oil, and optionally sea temperature [degC] and depth [m]."""
    c = replace(case, oil=get_oil(oil))
    if sea is not None:
        c = replace(c, thermal=replace(c.thermal, sea_temp_C=sea))
    if depth is not None:
        c = replace(c, operating=replace(c.operating, depth_m=depth))
    return c


@pytest.fixture(scope="module")
def full():
    return run(case=thermal_case(), thermal="full", sea_temp_range_C=SEAS, **SMALL)


def test_constructed_case_changes_grade_for_the_reason_worked_out_by_hand(full):
    """The answer by hand.

    Limits: lubrication nu >= LIMIT = 0.99 nu_VG15(40 degC, 0 m) = 14.85 cSt, cold start
    nu <= 1000 cSt, no ISO tolerance; envelope 0/7000 m x sea 0/40 degC.

    Isothermal (the oil at the sea temperature): the thinnest point is 40 degC, 0 m, where
    VG15 has 15.0 cSt >= 14.85: VG15 and VG22 pass; VG32 has 1640 cSt at 0 degC, 7000 m >
    1000: fails. The thinner VG15 loses less at every mission row: recommended VG15.

    Full: T_op = T_sea + R P(T_op) with P falling as T rises. As P > 0, T_op > T_sea, so
    P(T_op) < P(T_sea) and T_op < T_hi = T_sea + R P(T_sea); then P(T_op) > P(T_hi) and
    T_op > T_sea + R P(T_hi). VG15 at sea 40 degC, 0 m: this lower bound is about
    42.5 degC, where nu < 14.85: VG15 now fails the lubrication limit. VG22: the upper
    bound T_hi at every envelope point keeps nu far above 14.85; a cold start is the oil
    at the sea temperature before it warms, so the cold check is the isothermal one (VG22
    839 cSt passes, VG32 fails). Only VG22 passes: recommended VG22, changed, because
    VG15 is too thin at its operating temperature.
    """
    c = thermal_case()
    vg15 = with_oil(c, "VG15")
    p_sea = float(joint_mean_power(vg15, 40.0, "full", 0.0))
    t_low = 40.0 + R * float(joint_mean_power(vg15, 40.0 + R * p_sea, "full", 0.0))
    assert 42.0 < t_low < 43.0  # the number quoted above
    assert get_oil("VG15").kinematic_viscosity_cSt(t_low, 0.0) < LIMIT  # premise
    for d in DEPTHS:
        for s in SEAS:
            vg22 = with_oil(c, "VG22")
            t_high = s + R * float(joint_mean_power(vg22, s, "full", d))
            assert get_oil("VG22").kinematic_viscosity_cSt(t_high, d) > LIMIT  # premise
    assert full.recommended_isothermal == "VG15" and full.recommended == "VG22"
    t = full.table.set_index("oil")
    assert not t.loc["VG15", "passes_lubrication"] and t.loc["VG15", "passes_cold"]
    assert t.loc["VG15", "nu_min_at_C"] >= t_low and t.loc["VG15", "nu_min_at_sea_C"] == 40.0
    assert not t.loc["VG32", "passes_cold"]
    cmp = full.comparison
    assert cmp["changed"] and cmp["recommended_isothermal"] == "VG15"
    assert "VG15, the isothermal choice, fails under full: too thin" in cmp["why"]
    assert full.runner_up is None and full.runner_up_isothermal == "VG22"


def test_cold_start_is_the_oil_at_the_sea_temperature_before_it_warms(full):
    t = full.table.set_index("oil")
    for g in GRADES:
        assert t.loc[g, "nu_max_envelope_cSt"] == pytest.approx(
            get_oil(g).kinematic_viscosity_cSt(0.0, 7000.0), rel=1e-12)
        cold = replace(with_oil(seed_case(), g),
                       operating=replace(seed_case().operating, depth_m=7000.0, oil_temp_C=0.0))
        assert t.loc[g, "peak_viscous_torque_cold_Nm"] == pytest.approx(
            evaluate_case(cold, thermal="none").viscous_torque_peak_Nm, rel=1e-12)


def test_mission_energy_with_the_balance_recomputed_case_by_case(full):
    t = full.table.set_index("oil")
    for g in ("VG15", "VG22"):
        mean = sum(s.fraction * operating_temperature(
            with_oil(thermal_case(), g, s.oil_temp_C, s.depth_m), "full").mean_power_W
            for s in SEED_MISSION)
        assert t.loc[g, "mission_mean_power_W"] == pytest.approx(mean, rel=1e-9)
        rated = operating_temperature(with_oil(thermal_case(), g), "full")
        assert t.loc[g, "rated_oil_temp_op_C"] == pytest.approx(rated.oil_temp_C, abs=1e-8)
    per = full.comparison["grades"].set_index("oil")
    assert (per["mission_energy_Wh"] < per["mission_energy_isothermal_Wh"]).all()
    # a thicker grade runs hotter at the rated point
    assert t["rated_oil_temp_op_C"].is_monotonic_increasing


def test_film_keeps_the_limits_and_lowers_every_loss():
    film = run(thermal="film", **SMALL)
    iso = film.isothermal_table.set_index("oil")
    t = film.table.set_index("oil")
    for col in ("nu_min_envelope_cSt", "nu_max_envelope_cSt", "feasible"):
        assert (t[col] == iso[col]).all()
    assert (t["mission_energy_Wh"] < iso["mission_energy_Wh"]).all()
    assert film.recommended == film.recommended_isothermal == "VG15"
    assert not film.comparison["changed"] and "does not change" in film.comparison["why"]
    none = run(**SMALL)  # the Python default: isothermal, no comparison
    assert none.thermal_mode == "none" and none.comparison is None
    assert (none.table["mission_energy_Wh"] == film.isothermal_table["mission_energy_Wh"]).all()


def test_outputs_name_the_mode(tmp_path):
    r = run(tmp_path, case=thermal_case(), thermal=None, **SMALL)
    assert r.thermal_mode == "bulk"  # the default with [thermal]
    doc = json.loads((tmp_path / "oil_grade.json").read_text())
    assert doc["thermal_mode"] == "bulk" and doc["thermal_default"]
    band = doc["film_band"]  # the case's own oil at its rated point, under full beside
    assert band["mode"] == "full" and band["rated_mean_power_W"] > band["mean_power_W"]
    assert band["rated_mean_power_W"] == pytest.approx(
        operating_temperature(thermal_case()).mean_power_W, rel=1e-5)
    assert doc["sea_temp_C"] == SEA and doc["recommended"] == r.recommended
    assert doc["recommended_isothermal"] == r.recommended_isothermal
    assert doc["settings"]["temp_range_C"] == [0.0, 40.0]  # the default sea range
    md = (tmp_path / "summary.md").read_text()
    assert "Thermal mode: bulk (default" in md and "## With and without heating" in md
    assert "film band: film heating at full strength (full)" in md
    for f in ("oil_grade_thermal_comparison.csv", "oil_grade_isothermal_table.csv",
              "oil_grade_thermal.png", "oil_grade_heatmap.png"):
        assert (tmp_path / f).stat().st_size > 0


@pytest.mark.parametrize("kw", [dict(thermal="full"),  # the seed has no [thermal]
                                dict(thermal="none", sea_temp_range_C=(0.0, 30.0))])
def test_bad_thermal_parameters(kw):
    with pytest.raises(InputError):
        run(**{**SMALL, **kw})


def test_cli_refuses_an_oil_temperature_range_under_full(tmp_path, capsys):
    case = write_case_toml(thermal_case(), tmp_path / "case.toml")
    assert main(["study", "oil-grade", str(case), "--temp-max-c", "30", "--out",
                 str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "sea_temp_range_C" in err[0]
