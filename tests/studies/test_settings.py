"""The studies' settings records (studies/settings.py): every value checked once, at
construction, naming the field as the façade spells it; one default each, the same for
the façade and the command line."""

import pytest

from oilgap.cli import build_parser
from oilgap.model.errors import InputError
from oilgap.studies.settings import (
    DEFAULT_STARTS,
    DesignLimits,
    OilGradeSettings,
    ParetoSettings,
    RunOptions,
    SmoothingSettings,
    SweepSettings,
    split_keywords,
)


@pytest.mark.parametrize("make, field", [
    (lambda: OilGradeSettings(nu_min_cSt=100.0, nu_max_cSt=50.0), "nu_max_cSt"),
    (lambda: OilGradeSettings(nu_min_cSt=-1.0), "nu_min_cSt"),
    (lambda: OilGradeSettings(iso_tolerance=0.6), "iso_tolerance"),
    (lambda: OilGradeSettings(depth_range_m=(100.0, 0.0)), "depth_range_m"),
    (lambda: OilGradeSettings(depth_range_m=(0.0,)), "depth_range_m"),
    (lambda: OilGradeSettings(temp_range_C=(0.0, 200.0)), "temp_range_C max"),
    (lambda: OilGradeSettings(n_temp=1), "n_temp"),
    (lambda: OilGradeSettings(n_depth=2.5), "n_depth"),
    (lambda: OilGradeSettings(grades=()), "grades"),
    (lambda: OilGradeSettings(mission_hours=0.0), "mission_hours"),
    (lambda: OilGradeSettings(thermal="warm"), "thermal"),
    (lambda: OilGradeSettings(rated_temps_C=(float("nan"),)), "rated_temps_C"),
    (lambda: SweepSettings(mode="fit"), "mode"),
    (lambda: SweepSettings(thermal="hot"), "thermal"),
    (lambda: SmoothingSettings(method="guess"), "method"),
    (lambda: SmoothingSettings(thermal="bulk"), "thermal"),
    (lambda: SmoothingSettings(plateau_tol=1.0), "plateau_tol"),
    (lambda: ParetoSettings(points=49), "points"),
    (lambda: ParetoSettings(torque_min_Nm=0.0), "torque_min_Nm"),
    (lambda: RunOptions(workers=0), "workers"),
    (lambda: RunOptions(workers=True), "workers"),
    (lambda: RunOptions(chunk_size=0), "chunk_size"),
    (lambda: RunOptions(chunk_seconds=-1.0), "chunk_seconds"),
    (lambda: DesignLimits(starts=0), "starts"),
    (lambda: DesignLimits(inertia_max_ratio=-2.0), "inertia_max_ratio"),
])
def test_a_bad_value_is_refused_at_construction_naming_its_field(make, field):
    with pytest.raises(InputError) as e:
        make()
    assert e.value.field == field


def test_records_are_frozen_and_keyword_only():
    s = OilGradeSettings()
    with pytest.raises(AttributeError):
        s.nu_min_cSt = 1.0
    with pytest.raises(TypeError):
        OilGradeSettings(13.0)  # a positional value could land in the wrong field


def test_values_are_normalised_once():
    s = OilGradeSettings(grades=["VG22"], depth_range_m=[0, 100], n_depth=3)
    assert s.grades == ("VG22",) and s.depth_range_m == (0.0, 100.0)
    assert SmoothingSettings(T_values=[1, 2]).T_values == (1.0, 2.0)


def test_the_command_line_defaults_are_the_records():
    """One default each: what the parser fills in is what the façade's records hold."""
    p = build_parser()
    og = p.parse_args(["study", "oil-grade"])
    s = OilGradeSettings()
    assert (og.nu_min_cst, og.nu_max_cst, og.iso_tolerance, og.mission_hours) == (
        s.nu_min_cSt, s.nu_max_cSt, s.iso_tolerance, s.mission_hours)
    assert (og.depth_min_m, og.depth_max_m) == s.depth_range_m
    assert og.thermal is s.thermal is None
    assert p.parse_args(["study", "pareto"]).points == ParetoSettings().points
    assert p.parse_args(["study", "smoothing"]).plateau_tol == SmoothingSettings().plateau_tol
    sw = p.parse_args(["study", "sweep", "g.csv"])
    assert sw.mode == SweepSettings().mode
    assert sw.chunk_seconds == RunOptions().chunk_seconds
    assert int(p.parse_args(["optimize"]).starts) == DesignLimits().starts == DEFAULT_STARTS == 8


def test_keywords_go_to_their_record():
    s, o = split_keywords({"points": 50, "workers": 2}, ParetoSettings)
    assert s == ParetoSettings(points=50) and o == RunOptions(workers=2)
    whole = ParetoSettings(points=55)
    assert split_keywords({"settings": whole}, ParetoSettings)[0] is whole
    with pytest.raises(TypeError):
        split_keywords({"pionts": 50}, ParetoSettings)
    with pytest.raises(TypeError):
        split_keywords({"settings": whole, "points": 50}, ParetoSettings)
    with pytest.raises(TypeError):
        split_keywords({"workers": 2}, SmoothingSettings, run_options=False)
