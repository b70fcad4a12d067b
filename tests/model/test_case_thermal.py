"""The optional [thermal] table of a case: read, validated, written back only when given."""

import dataclasses

import pytest

from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.io.case_write import case_to_dict, dumps_toml
from oilgap.studies.io.case_write import write_case_toml

THERMAL = """
[thermal]
sea_temp_C = 2.0
resistance_K_per_W = 0.35
heat_capacity_J_per_K = 1800.0
other_heat_W = 12.5
walls = "adiabatic-rotor"
conductivity_W_per_mK = 0.14
"""


def seed_text():
    return dumps_toml(case_to_dict(seed_case()))


def write(tmp_path, text):
    p = tmp_path / "case.toml"
    p.write_text(text)
    return p


def test_thermal_is_read_in_si_and_written_back(tmp_path):
    case = read_case_toml(write(tmp_path, seed_text() + THERMAL))
    assert case.thermal == ThermalSpec(2.0, 0.35, 1800.0, 12.5, "adiabatic-rotor", 0.14)
    back = read_case_toml(write_case_toml(case, tmp_path / "out.toml"))
    assert back.thermal == case.thermal
    assert case_to_dict(back) == case_to_dict(case)


def test_thermal_defaults_and_round_trip_without_optional_keys(tmp_path):
    text = seed_text() + ("\n[thermal]\nsea_temp_C = 4\nresistance_K_per_W = 0.5\n"
                          "heat_capacity_J_per_K = 900\n")
    case = read_case_toml(write(tmp_path, text))
    assert case.thermal == ThermalSpec(4.0, 0.5, 900.0)
    assert case.thermal.other_heat_W == 0.0 and case.thermal.walls == "isothermal-walls"
    assert case.thermal.conductivity_W_mK is None
    doc = case_to_dict(case)
    assert "conductivity_W_per_mK" not in doc["thermal"]
    assert read_case_toml(write_case_toml(case, tmp_path / "o.toml")).thermal == case.thermal


def test_a_case_without_thermal_writes_the_same_document(tmp_path):
    case = seed_case()
    assert case.thermal is None
    doc = case_to_dict(case)
    assert "thermal" not in doc
    back = read_case_toml(write_case_toml(case, tmp_path / "out.toml"))
    assert back.thermal is None and case_to_dict(back) == doc
    with_thermal = dataclasses.replace(case, thermal=ThermalSpec(2.0, 0.3, 100.0))
    assert case_to_dict(with_thermal) != doc  # the table is what differs
    assert {k: v for k, v in case_to_dict(with_thermal).items() if k != "thermal"} == doc


@pytest.mark.parametrize("line, key", [
    ("resistance_K_per_W = -0.35", "resistance_K_per_W"),
    ("heat_capacity_J_per_K = 0", "heat_capacity_J_per_K"),
    ("other_heat_W = -1", "other_heat_W"),
    ('walls = "insulated"', "walls"),
    ("conductivity_W_per_mK = 0", "conductivity_W_per_mK"),
    ("sea_temp_C = nan", "sea_temp_C"),
    ("fouling_K_per_W = 0.1", "thermal.fouling_K_per_W"),
])
def test_refusals_name_the_key_on_one_line(tmp_path, line, key):
    base = {ln.split(" = ")[0]: ln for ln in THERMAL.strip().splitlines()[1:]}
    base[line.split(" = ")[0]] = line
    text = seed_text() + "\n[thermal]\n" + "\n".join(base.values()) + "\n"
    with pytest.raises(InputError) as e:
        read_case_toml(write(tmp_path, text))
    assert e.value.field == key
    assert "\n" not in str(e.value)


def test_required_thermal_keys(tmp_path):
    text = seed_text() + "\n[thermal]\nsea_temp_C = 4\nresistance_K_per_W = 0.5\n"
    with pytest.raises(InputError) as e:
        read_case_toml(write(tmp_path, text))
    assert e.value.field == "thermal.heat_capacity_J_per_K"
