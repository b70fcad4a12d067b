"""Design cases: TOML in and out, validation naming the key, the seed joint."""

import math

import pytest

from oilgap.model.errors import InputError
from oilgap.model.evaluation import mean_viscous_power
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.studies.io.case_write import write_case_toml

SEED_TOML = """
name = "test joint"
[region1]
T1_mm = 23.9
T2_mm = 25.4
T3_mm = 26.4
T4_mm = 27.9
length_mm = 14.76
[region2]
radius_mm = 22.0
length_mm = 14.24
gap_mm = 5.0
[oil]
name = "VG22"
[operating]
depth_m = 0.0
oil_temp_C = 40.0
[friction]
gamma = 0.5
"""


def write(tmp_path, text, name="case.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def test_toml_round_trip(tmp_path):
    case = seed_case(smoothed=True)
    p = write_case_toml(case, tmp_path / "out.toml")
    back = read_case_toml(p)
    for part in ("region1", "region2"):
        a, b = getattr(back, part), getattr(case, part)
        for f in a.__dataclass_fields__:
            assert getattr(a, f) == pytest.approx(getattr(b, f), rel=1e-14)
    assert back.friction == case.friction and back.oil == case.oil
    assert mean_viscous_power(back) == pytest.approx(mean_viscous_power(case), rel=1e-14)


def test_seed_cases_T():
    assert seed_case().region1.roughness == pytest.approx(4.0)
    assert seed_case(smoothed=True).region1.roughness == pytest.approx(2.0)
    assert seed_case().region1.gap == pytest.approx(1e-3)


def test_duty_cycle_csv(tmp_path):
    p = write(tmp_path, "time_s,speed_rpm\n0,0\n1,1000\n2,-1000\n3,0\n", "cyc.csv")
    toml = SEED_TOML + f'[duty_cycle]\nkind = "csv"\ncsv = "{p.name}"\n'
    case = read_case_toml(write(tmp_path, toml))
    assert case.duty_cycle.peak_omega_rad_s == pytest.approx(1000 * 2 * math.pi / 60)


BAD_CASES = [
    ("T3_mm = 26.4", "T3_mm = 25.4", "T3_mm"),            # gap = 0
    ("T3_mm = 26.4", "T3_mm = 25.0", "T3_mm"),            # gap < 0
    ("T4_mm = 27.9", "T4_mm = 26.0", "T4_mm"),            # T4 < T3
    ("T1_mm = 23.9", "T1_mm = 25.6", "T1_mm"),            # T1 > T2
    ("length_mm = 14.76", "length_mm = 0.0", "length_mm"),
    ("length_mm = 14.24", "length_mm = -1.0", "length_mm"),
    ("gap_mm = 5.0", "gap_mm = 0.0", "gap_mm"),
    ('name = "VG22"', 'name = "VG23"', "oil"),
    ("T1_mm = 23.9", "T1_mm = nan", "T1_mm"),
    ("depth_m = 0.0", "depth_m = inf", "depth_m"),
    ("oil_temp_C = 40.0", "oil_temp_C = nan", "oil_temp_C"),
    ("gamma = 0.5", "gamma = -inf", "gamma"),
    ("gamma = 0.5", "gama = 0.5", "friction.gama"),     # typo is not ignored
    ("[operating]", "[operatin]", "operatin"),
    ("gamma = 0.5", 'form = "spline"', "form"),
    ("T1_mm = 23.9", 'T1_mm = "23.9"', "T1_mm"),
]


@pytest.mark.parametrize("old,new,field", BAD_CASES)
def test_bad_case_refused_naming_field(tmp_path, old, new, field):
    assert old in SEED_TOML
    p = write(tmp_path, SEED_TOML.replace(old, new, 1))
    with pytest.raises(InputError) as e:
        read_case_toml(p)
    assert e.value.field == field


def test_T_below_one_is_refused(tmp_path):
    # T = (T4 - T1)/(T3 - T2) < 1 needs T4 < T3 or T1 > T2: both are refused by name
    toml = SEED_TOML.replace("T1_mm = 23.9", "T1_mm = 25.5").replace("T4_mm = 27.9",
                                                                     "T4_mm = 26.3")
    with pytest.raises(InputError):
        read_case_toml(write(tmp_path, toml))


def test_malformed_toml(tmp_path):
    with pytest.raises(InputError) as e:
        read_case_toml(write(tmp_path, "[region1\nT1_mm = 1"))
    assert "malformed" in str(e.value)


FULL_TOML = (SEED_TOML + """
[motor]
magnet_thickness_mm = 3.0
slot_count = 18
electric_loading_A_per_m = 20000.0
gear_ratio = 120.0
[bounds]
gap_min_mm = 0.6
torque_min_Nm = 1.5
[[mission]]
depth_m = 3000.0
oil_temp_C = 2.0
fraction = 0.25
[[mission]]
depth_m = 0.0
oil_temp_C = 20.0
fraction = 0.75
""").replace('name = "VG22"', 'name = "RigOil"\nnu40_cSt = 46.0\nnu100_cSt = 7.0\n'
                                'density_kg_m3 = 870.0\nbarus_1_GPa = 12.0')


def test_every_table_read_in_si_and_written_back(tmp_path):
    case = read_case_toml(write(tmp_path, FULL_TOML))
    # units in key names -> SI: 3.0 mm -> 3e-3 m, 12 /GPa -> 1.2e-8 /Pa, 0.6 mm -> 6e-4 m
    assert case.motor.magnet_thickness == pytest.approx(3.0e-3, rel=1e-15)
    assert case.motor.slot_count == 18 and case.motor.gear_ratio == 120.0
    assert case.motor.electric_loading_A_m == 20000.0
    assert case.oil.name == "RigOil" and case.oil.barus_1_Pa == pytest.approx(1.2e-8)
    assert case.bounds.gap_min == pytest.approx(6.0e-4, rel=1e-15)
    # bounds not given take the defaults around region 1: gap_max = 2 * 1 mm
    assert case.bounds.gap_max == pytest.approx(2.0e-3, rel=1e-15)
    assert case.bounds.torque_min_Nm == 1.5
    assert [s.fraction for s in case.mission] == [0.25, 0.75]
    back = read_case_toml(write_case_toml(case, tmp_path / "back.toml"))
    assert back.motor == case.motor
    # the Barus coefficient goes 1/Pa -> 1/GPa -> 1/Pa: equal up to rounding
    assert back.oil.barus_1_Pa == pytest.approx(case.oil.barus_1_Pa, rel=1e-15)
    assert back.oil.nu40_cSt == case.oil.nu40_cSt and back.oil.name == case.oil.name
    for f in ("gap_min", "gap_max", "radius_min", "radius_max", "length_min", "length_max",
              "inertia_max_ratio", "torque_min_Nm"):  # m -> mm -> m: equal up to rounding
        assert getattr(back.bounds, f) == pytest.approx(getattr(case.bounds, f), rel=1e-15)
    assert back.mission == case.mission


MORE_BAD_CASES = [
    ("fraction = 0.75", "fraction = 0.5", "mission fractions"),       # sum 0.75, not 1
    ("fraction = 0.75", "fractio = 0.75", "mission[1].fractio"),
    ("slot_count = 18", "slot_count = 1.5", "slot_count"),
    ("gear_ratio = 120.0", "gear_ratio = 0.0", "gear_ratio"),
    ("magnet_thickness_mm = 3.0", "magnet_thickness_mm = -3.0", "magnet_thickness_mm"),
    ("gap_min_mm = 0.6", "gap_min_mm = 3.0", "gap_max_mm"),           # max below min
    ("density_kg_m3 = 870.0", "", "oil.density_kg_m3"),               # custom oil incomplete
    ("[motor]", '[duty_cycle]\nkind = "square"\n[motor]', "duty_cycle.kind"),
    ("[motor]", '[duty_cycle]\ncsv = "c.csv"\nkind = "sine"\n[motor]', "duty_cycle.csv"),
    ("[motor]", '[duty_cycle]\npeak_speed_rpm = -1.0\n[motor]', "peak_speed_rpm"),
]


@pytest.mark.parametrize("old,new,field", MORE_BAD_CASES)
def test_bad_full_case_refused_naming_field(tmp_path, old, new, field):
    assert old in FULL_TOML
    with pytest.raises(InputError) as e:
        read_case_toml(write(tmp_path, FULL_TOML.replace(old, new, 1)))
    assert e.value.field == field


def test_barus_only_with_a_custom_oil(tmp_path):
    toml = SEED_TOML.replace('name = "VG22"', 'name = "VG22"\nbarus_1_GPa = 12.0')
    with pytest.raises(InputError) as e:
        read_case_toml(write(tmp_path, toml))
    assert e.value.field == "oil.barus_1_GPa"
