"""oilgap.model.bearing.catalogue: designations (ISO 15 bore codes, aliases, /d,
miniatures, refused seals), the product rows against the research notes, the ball-set
estimate checked with ISO 76, the [bearing] table with its defaults named and its round
trip."""

import pytest

from oilgap.model.bearing.catalogue import (
    PRODUCTS,
    SERIES_CONSTANTS,
    ball_set_estimate,
    bearing_spec_from,
    bearing_table,
    describe_defaults,
    parse_designation,
)
from oilgap.model.bearing.laws import iso_static_load_rating
from oilgap.model.errors import InputError


@pytest.mark.parametrize("text, canonical, series, bore", [
    ("61809", "61809", "618", 45.0),
    ("6809", "61809", "618", 45.0),      # old name of 61809
    ("6909", "61909", "619", 45.0),
    ("16009", "16009", "160", 45.0),
    ("6009", "6009", "60", 45.0),
    ("6205", "6205", "62", 25.0),
    ("6200", "6200", "62", 10.0),       # bore codes 00-03: 10, 12, 15, 17 mm
    ("6201", "6201", "62", 12.0),
    ("6202", "6202", "62", 15.0),
    ("6203", "6203", "62", 17.0),
    ("6204", "6204", "62", 20.0),
    ("62/22", "62/22", "62", 22.0),     # /d: the bore in mm
    ("618/500", "618/500", "618", 500.0),
    ("608", "608", "60", 8.0),          # miniature: the last digit is the bore
    ("4205", "4205", "42", 25.0),       # double row
    ("63009", "63009", "630", 45.0),
    ("6309 C3", "6309", "63", 45.0),    # clearance suffix ignored
    ("6309/C3", "6309", "63", 45.0),
])
def test_parse_designation(text, canonical, series, bore):
    p = parse_designation(text)
    assert (p.designation, p.series, p.bore_mm) == (canonical, series, bore)
    assert p.series in SERIES_CONSTANTS


@pytest.mark.parametrize("text, words", [
    ("6809-2RS1", "seal"), ("6205-2Z", "seal"), ("6205 ZZ", "seal"), ("6205-RS", "seal"),
    ("NU205", "digits"), ("22205", "series"), ("6205-XYZ", "suffix"), ("61", "series"),
    (6809, "string"),
])
def test_parse_designation_refusals(text, words):
    with pytest.raises(InputError) as e:
        parse_designation(text)
    assert e.value.field == "designation" and words in str(e.value)


def test_products_of_the_notes():
    # docs/notes/bearing-friction-models.md, section 3 (SKF 10000 EN via [JR])
    for des, row in {"61808": (40, 52, 7, 4.49, 3.75), "61809": (45, 58, 7, 6.63, 6.10),
                     "61810": (50, 65, 7, 6.76, 6.80)}.items():
        p = PRODUCTS[des]
        assert (p.bore_mm, p.outside_mm, p.width_mm, p.dynamic_rating_kN,
                p.static_rating_kN) == row
    assert PRODUCTS["61809"].limiting_speed_rpm == 14000
    for des, p in PRODUCTS.items():
        assert parse_designation(des).bore_mm == p.bore_mm


def test_ball_set_estimate():
    # 61809: 24 balls of 5/32 in (the notes' estimate); ISO 76 C0 within 1 % of the catalogue
    z, dw = ball_set_estimate(45, 58)
    assert (z, dw) == (24, pytest.approx(25.4 * 5 / 32))
    assert iso_static_load_rating(z, dw, 51.5) == pytest.approx(6100, rel=0.01)
    # 6205 (recalled: 9 x 7.938 mm) and 6309 (8 balls)
    assert ball_set_estimate(25, 52) == (9, pytest.approx(25.4 * 10 / 32))
    assert ball_set_estimate(45, 100)[0] == 8


def test_designation_alone_fills_and_names_the_defaults():
    s = bearing_spec_from({"designation": "6809"})
    assert (s.name, s.designation, s.series) == ("61809", "61809", "618")
    assert (s.bore_m, s.outside_m, s.width_m) == pytest.approx((0.045, 0.058, 0.007))
    assert s.static_load_rating_N == 6100.0
    assert (s.model, s.drag, s.submerged, s.f0, s.k_rs) == ("skf", "skf-vm-term", True, 4.0, 0.0)
    assert (s.radial_load_N, s.axial_load_N, s.mu_ehl, s.mu_bl) == (50.0, 0.0, 0.05, 0.12)
    assert set(s.defaults_used) == {
        "model", "type", "outside_mm", "width_mm", "balls", "ball_diameter_mm",
        "radial_load_N", "axial_load_N", "static_load_rating_N", "submerged", "f0", "drag",
        "mu_ehl", "mu_bl", "k_rs"}
    lines = describe_defaults(s)
    assert len(lines) == len(s.defaults_used)
    assert any(line.startswith("outside_mm = 58") and "61809" in line for line in lines)


def test_given_values_are_not_defaults():
    s = bearing_spec_from({"bore_mm": 42.5, "outside_mm": 55.5, "series": "68",
                           "radial_load_N": 80, "model": "palmgren", "f0": 2.5,
                           "oil_level_mm": 10})
    assert s.series == "618" and s.designation is None and s.name == "bearing"
    assert not s.submerged and s.k_rs == 3e-8
    assert {"bore_mm", "outside_mm", "radial_load_N", "model", "f0",
            "oil_level_mm"}.isdisjoint(s.defaults_used)
    # submerged = false is inferred from the level: a default, named
    assert {"balls", "static_load_rating_N", "k_rs", "submerged"} <= set(s.defaults_used)
    # no catalogue row: C0 is the ISO 76 estimate from the estimated balls
    z, dw = ball_set_estimate(42.5, 55.5)
    assert s.static_load_rating_N == pytest.approx(iso_static_load_rating(z, dw, 49.0))


@pytest.mark.parametrize("table", [
    {"designation": "6809"},
    {"designation": "6809", "drag": "skf-full", "radial_load_N": 120.0, "name": "output"},
    {"bore_mm": 42.5, "outside_mm": 55.5, "series": "618", "balls": 22,
     "ball_diameter_mm": 3.969, "model": "palmgren", "submerged": False,
     "oil_level_mm": 12.0, "f0": 2.0, "axial_load_N": 10.0},
])
def test_table_round_trip(table):
    s = bearing_spec_from(table)
    t = bearing_table(s)
    assert bearing_spec_from(t) == s
    assert set(t) <= set(table) | {"designation"}


@pytest.mark.parametrize("table, key", [
    ({"designation": "6809", "colour": "red"}, "colour"),
    ({"designation": "6809", "seals": "2RS1"}, "seals"),
    ({"designation": "6809-2Z"}, "designation"),
    ({"designation": "61813"}, "outside_mm"),   # not in the built-in catalogue
    ({"designation": "6809", "bore_mm": 40}, "bore_mm"),
    ({"designation": "6809", "outside_mm": 60}, "outside_mm"),
    ({"designation": "6809", "series": "619"}, "series"),
    ({"outside_mm": 58}, "bore_mm"),
    ({"bore_mm": 45, "outside_mm": 58}, "series"),    # skf needs the series constants
    ({"designation": "6809", "radial_load_N": "50"}, "radial_load_N"),
    ({"designation": "6809", "radial_load_N": -5}, "radial_load_N"),
    ({"designation": "6809", "f0": 0}, "f0"),
    ({"designation": "6809", "model": "harris"}, "model"),
    ({"designation": "6809", "type": "tapered-roller"}, "type"),
    ({"designation": "6809", "drag": "all"}, "drag"),
    ({"designation": "6809", "submerged": True, "oil_level_mm": 20}, "oil_level_mm"),
    ({"designation": "6809", "balls": 2.5}, "balls"),
])
def test_bad_tables_name_the_key(table, key):
    with pytest.raises(InputError) as e:
        bearing_spec_from(table)
    assert e.value.field == key


def test_open_bearing_accepted_explicitly():
    assert bearing_spec_from({"designation": "6809", "seals": "none"}).designation == "61809"
