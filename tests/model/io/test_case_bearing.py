"""The optional [bearing] table of a case: read into a BearingSpec, written back as the user
gave it (round trip), the designation's catalogue geometry filled in and named as defaults,
bad keys and values refused naming the key; without the table nothing changes."""

import math

import pytest

from oilgap.model.errors import InputError
from oilgap.model.io.case_bearing import bearing_defaults
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.io.case_write import case_to_dict, dumps_toml
from oilgap.studies.io.case_write import write_case_toml


def seed_text():
    return dumps_toml(case_to_dict(seed_case()))


def read(write_file, table: str):
    return read_case_toml(write_file(seed_text() + "\n[bearing]\n" + table))


def test_a_designation_only_table_fills_the_catalogue_geometry_and_names_it(write_file):
    b = read(write_file, 'designation = "6809"\n').bearing
    # 6809 = 61809 (old name of the 618 series): bore code 09 -> 9 x 5 = 45 mm; the SKF
    # table (docs/notes/bearing-friction-models.md, sec. 3): D = 58, B = 7, C0 = 6.10 kN
    assert (b.designation, b.series, b.name) == ("61809", "618", "61809")
    assert b.bore_m == pytest.approx(45e-3, rel=1e-15)
    assert b.outside_m == pytest.approx(58e-3, rel=1e-15)
    assert b.width_m == pytest.approx(7e-3, rel=1e-15)
    assert b.pitch_diameter_m == pytest.approx(51.5e-3, rel=1e-15)
    assert b.static_load_rating_N == pytest.approx(6100.0)
    # the ball set estimate by hand: D_w = 0.3 (58 - 45) = 3.9 mm -> 5/32 in = 3.96875 mm;
    # Z = 0.6 pi 51.5 / 3.96875 = 24.46 -> 24
    dw = round(0.3 * 13.0 / (25.4 / 32)) * 25.4 / 32
    assert dw == pytest.approx(3.96875) and round(0.6 * math.pi * 51.5 / dw) == 24
    assert b.balls == 24 and b.ball_diameter_m == pytest.approx(dw * 1e-3, rel=1e-15)
    # the defaults the tool filled in are named (the bore the designation states is not)
    filled = set(b.defaults_used)
    assert {"outside_mm", "width_mm", "balls", "ball_diameter_mm", "radial_load_N",
            "model", "submerged"} <= filled
    assert "bore_mm" not in filled and "designation" not in filled
    shown = bearing_defaults(b)
    assert set(shown) == filled
    assert shown["outside_mm"] == 58.0 and shown["balls"] == 24
    assert shown["model"] == "skf" and shown["submerged"] is True
    # written back: what the user gave (the designation, canonical), not the defaults
    assert case_to_dict(read_case_toml(write_file(seed_text() + '\n[bearing]\ndesignation = '
                                                  '"6809"\n')))["bearing"] == {
        "designation": "61809"}


def test_round_trip_keeps_the_bearing_and_its_defaults(write_file, tmp_path):
    table = ('name = "main bearing"\ndesignation = "61809"\nmodel = "palmgren"\n'
             "radial_load_N = 80.0\naxial_load_N = 5.0\nf0 = 3.0\nballs = 24\n")
    case = read(write_file, table)
    b = case.bearing
    assert (b.name, b.model, b.f0, b.radial_load_N, b.axial_load_N) == (
        "main bearing", "palmgren", 3.0, 80.0, 5.0)
    assert not {"f0", "radial_load_N", "axial_load_N", "model", "balls"} & set(b.defaults_used)
    doc = case_to_dict(case)
    assert doc["bearing"] == {"name": "main bearing", "designation": "61809",
                              "model": "palmgren", "radial_load_N": 80.0,
                              "axial_load_N": 5.0, "f0": 3.0, "balls": 24}
    back = read_case_toml(write_case_toml(case, tmp_path / "out.toml"))
    assert back.bearing == b and back.bearing.defaults_used == b.defaults_used
    assert case_to_dict(back) == doc


def test_round_trip_of_a_bearing_by_its_dimensions(write_file, tmp_path):
    table = ('series = "618"\nbore_mm = 42.5\noutside_mm = 55.5\nradial_load_N = 50.0\n'
             'drag = "skf-full"\nk_rs = 3e-8\n')
    case = read(write_file, table)
    b = case.bearing
    assert b.designation is None and b.pitch_diameter_m == pytest.approx(49e-3, rel=1e-14)
    assert (b.drag, b.k_rs) == ("skf-full", 3e-8)
    back = read_case_toml(write_case_toml(case, tmp_path / "out.toml"))
    assert back.bearing == b
    assert case_to_dict(back)["bearing"] == {"series": "618", "bore_mm": 42.5,
                                             "outside_mm": 55.5, "radial_load_N": 50.0,
                                             "drag": "skf-full", "k_rs": 3e-8}


def test_without_bearing_nothing_changes(write_file):
    case = seed_case()
    assert case.bearing is None
    assert "bearing" not in case_to_dict(case)
    again = read_case_toml(write_file(seed_text()))
    assert again.bearing is None and case_to_dict(again) == case_to_dict(case)


@pytest.mark.parametrize("table,key", [
    ('designation = "6809"\nbore_diameter_mm = 45\n', "bore_diameter_mm"),
    ('designation = "6809"\nmodel = "timken"\n', "model"),
    ('designation = "6809"\nradial_load_N = -5.0\n', "radial_load_N"),
    ('designation = "6809"\nballs = 2.5\n', "balls"),
    ('designation = "6809"\nsubmerged = "yes"\n', "submerged"),
    ('designation = "6809"\ndrag = "all"\n', "drag"),
    ('designation = "6809"\noutside_mm = 60.0\n', "outside_mm"),
    ('designation = "6809"\nf0 = 0.0\n', "f0"),
    ('designation = "7209"\n', "designation"),
    ('bore_mm = 45.0\n', "outside_mm"),
    ('bore_mm = 45.0\noutside_mm = 40.0\nseries = "618"\n', "outside_mm"),
])
def test_bad_keys_and_values_name_the_key(write_file, table, key):
    with pytest.raises(InputError) as e:
        read(write_file, table)
    assert e.value.field == key
    assert "\n" not in str(e.value)


def test_bearing_must_be_a_table(write_file):
    with pytest.raises(InputError) as e:
        read_case_toml(write_file('bearing = "6809"\n' + seed_text()))
    assert "bearing" in str(e.value)
