"""Issue 26, item 4, at the model's edge: the bounds and hints the campaign rows
(``tests/cli/campaign_rows26.py``) see through the command line, checked at their
boundaries here with numbers worked out by hand."""

from __future__ import annotations

import pytest

from oilgap.model.case import MissionSegment, OperatingPoint, ThermalSpec
from oilgap.model.duty_cycle import MIN_PEAK_SPEED_RPM, check_peak_speed
from oilgap.model.errors import InputError
from oilgap.model.fluid_table import MAX_TABLE_NU_CST, TableFluid
from oilgap.model.io.case_io import case_from_dict, seed_case
from oilgap.model.io.case_write import case_to_dict
from oilgap.model.io.inputs import file_kind
from oilgap.model.io.limits import MAX_INPUT_TEMP_C, check_celsius


def test_a_temperature_above_the_flash_point_is_refused_with_the_kelvin_hint():
    assert check_celsius("oil_temp_C", MAX_INPUT_TEMP_C, "operating") == 230.0
    with pytest.raises(InputError, match=r"kelvin in a degC key\? 275.15 K is 2 degC"):
        OperatingPoint(depth_m=0.0, oil_temp_C=275.15)
    with pytest.raises(InputError, match=r"sea_temp_C = 277.15 .* 277.15 K is 4 degC"):
        ThermalSpec(sea_temp_C=277.15, resistance_K_W=0.05, heat_capacity_J_K=4000.0)
    with pytest.raises(InputError) as e:  # 1000 K is 727 degC: no hint, still refused
        check_celsius("oil_temp_C", 1000.0, "operating")
    assert "kelvin" not in str(e.value)
    with pytest.raises(InputError, match="oil_temp_C"):
        check_celsius("oil_temp_C", -60.5, "operating")


def test_peak_speed_bounds_and_their_reasons():
    assert check_peak_speed(MIN_PEAK_SPEED_RPM) == 1e-3
    assert check_peak_speed(100_000.0) == 1e5
    for v, why in ((-2000.0, "must be positive"), (0.0, "must be positive"),
                   (5e-324, "at least 0.001 rpm"), (9.99e-4, "at least 0.001 rpm"),
                   (100_001.0, "faster than any electric machine")):
        with pytest.raises(InputError, match=why):
            check_peak_speed(v)


def test_a_heat_source_alone_above_the_cap_is_an_input_error():
    """T_sea + R Q: 4 + 0.5 x 491.8 = 249.9 degC is held (a root may exist below 250),
    4 + 0.5 x 492 = 250 degC is not (no loss P >= 0 can bring it below)."""
    ThermalSpec(sea_temp_C=4.0, resistance_K_W=0.5, heat_capacity_J_K=4e4, other_heat_W=491.8)
    with pytest.raises(InputError, match=r"other_heat_W = 492.0 .*alone is 250 degC"):
        ThermalSpec(sea_temp_C=4.0, resistance_K_W=0.5, heat_capacity_J_K=4e4,
                    other_heat_W=492.0)


def test_a_table_viscosity_beyond_any_fluid_is_refused():
    def table(top_cst: float) -> TableFluid:
        return TableFluid(name="f", temps_K=(273.15, 373.15), nu_m2_s=((top_cst * 1e-6, 1e-4),),
                          rho_kg_m3=((900.0, 880.0),))

    table(MAX_TABLE_NU_CST)
    with pytest.raises(InputError, match=r"nu_cSt = 1e\+300 .*at most 1e\+08 cSt"):
        table(1e300)


def test_file_kind_by_suffix_then_by_text(tmp_path):
    assert file_kind(tmp_path / "case.toml", "") == "TOML"
    assert file_kind(tmp_path / "rig.CSV", "") == "CSV"
    assert file_kind(tmp_path / "model", '{"model": {}}') == "JSON"
    assert file_kind(tmp_path / "case", 'name = "x"\n[oil]\nname = "VG22"\n') == "TOML"
    assert file_kind(tmp_path / "rig", "speed_rpm,temp_C,oil\n1000,30,VG22\n") == "CSV"
    assert file_kind(tmp_path / "notes", "just words\n") is None


def test_mission_rows_keep_the_key_they_were_written_with():
    doc = case_to_dict(seed_case())
    doc["mission"] = [{"depth_m": 3000.0, "sea_temp_C": 2.0, "fraction": 1.0}]
    case = case_from_dict(doc)
    assert case.mission == (MissionSegment(3000.0, 2.0, 1.0, "sea_temp_C"),)
    assert case_to_dict(case)["mission"] == doc["mission"]  # written back as given
    doc["mission"] = [{"depth_m": 3000.0, "fraction": 1.0}]
    with pytest.raises(InputError, match="oil_temp_C"):
        case_from_dict(doc)
