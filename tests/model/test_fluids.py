"""Any fluid: gases (ideal gas + Sutherland), property tables, the common interface, the
case TOML of each kind and the command line on a gas case.

Published values (air, nitrogen) are in ``tests/validation/test_published_fluids.py``."""

import json
import math
import warnings

import casadi as ca
import numpy as np
import pytest

from oilgap.cli import main
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.evaluation import evaluate_case, oil_state
from oilgap.model.fluids import (
    Fluid,
    GasFluid,
    TableFluid,
    builtin_gases,
    read_fluid_table,
    warn_if_untrusted_state,
)
from oilgap.model.io.case_io import read_case_toml
from oilgap.model.io.case_write import case_to_dict
from oilgap.model.oils import builtin_fluids, get_oil, read_oils_csv
from oilgap.model.regions import joint_regions, region_mean_power
from oilgap.studies.io.case_write import write_case_toml

R_U = 8.314462618  # J/(mol K), CODATA 2018

# IAPWS-95 density and IAPWS 2008 viscosity of liquid water at 0.101325 MPa, as tabulated
# in the CRC Handbook of Chemistry and Physics ("Properties of water in the range
# 0-100 degC"): mu = 1.0016, 0.7972, 0.6527, 0.4660 mPa s and rho = 998.21, 995.65,
# 992.22, 983.20 kg/m^3 at 20, 30, 40, 60 degC, so nu = mu/rho = 1.004, 0.801, 0.658,
# 0.474 cSt.
WATER_CSV = """# liquid water at 0.101325 MPa (IAPWS-95, IAPWS 2008)
temp_C,nu_cSt,density_kg_m3
40,0.658,992.2
20,1.004,998.2
60,0.474,983.2
"""

CASE_HEAD = """
name = "fluid joint"
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
[operating]
depth_m = 0.0
oil_temp_C = 20.0
[friction]
gamma = 0.566
"""


@pytest.fixture
def water(tmp_path):
    p = tmp_path / "water.csv"
    p.write_text(WATER_CSV)
    return read_fluid_table(p)


def write_case(tmp_path, oil_table: str, name="case.toml"):
    p = tmp_path / name
    p.write_text(CASE_HEAD + "[oil]\n" + oil_table)
    return p


# --------------------------------------------------------------------------- gas


def test_sutherland_is_exact_at_its_reference_temperature():
    for g in builtin_gases().values():
        assert g.viscosity(g.T_ref_K) == pytest.approx(g.mu_ref_Pa_s, rel=1e-15)
    air = get_oil("air")
    assert (air.mu_ref_Pa_s, air.T_ref_K, air.sutherland_S_K) == (1.716e-5, 273.0, 111.0)
    n2 = get_oil("Nitrogen")
    assert (n2.mu_ref_Pa_s, n2.T_ref_K, n2.sutherland_S_K) == (1.663e-5, 273.0, 107.0)


def test_gas_by_hand_at_400K_and_10_bar():
    # Sutherland: 1.716e-5 (400/273)^1.5 (384/511) = 1.716e-5 * 1.773594 * 0.751468
    #           = 2.28704e-5 Pa s
    # ideal gas: (101325 + 9e5) * 0.02897 / (8.314462618 * 400) = 29008.385 / 3325.785
    #           = 8.72227 kg/m^3
    nu, mu, rho = get_oil("air").properties(400.0, 9.0e5)
    assert mu == pytest.approx(2.28704e-5, rel=2e-5)
    assert rho == pytest.approx(8.72227, rel=2e-5)
    assert nu == pytest.approx(mu / rho, rel=1e-14)


def test_gas_takes_casadi_symbols():
    air = get_oil("air")
    T, p = ca.SX.sym("T"), ca.SX.sym("p")
    f = ca.Function("f", [T, p], list(air.properties(T, p)) + [air.temperature_slope(T, p)])
    for t, pg in ((250.0, 0.0), (330.0, 2e5)):
        got = [float(v) for v in f(t, pg)]
        want = list(air.properties(t, pg)) + [air.temperature_slope(t, pg)]
        assert got == pytest.approx(want, rel=1e-13)


def test_gas_temperature_slope_against_central_difference():
    # b = -d ln(mu)/dT; central difference with h = 0.01 K (truncation ~ h^2 b''' / 6 ~ 1e-9)
    air = get_oil("air")
    for T in (220.0, 293.15, 500.0):
        h = 0.01
        fd = -(math.log(air.properties(T + h)[1]) - math.log(air.properties(T - h)[1])) / (2 * h)
        assert air.temperature_slope(T) == pytest.approx(fd, rel=1e-7)
        # closed form written out: -(3 / (2 T) - 1 / (T + S))
        assert air.temperature_slope(T) == pytest.approx(-(1.5 / T - 1.0 / (T + 111.0)),
                                                         rel=1e-14)
    assert air.temperature_slope(293.15) < 0  # a gas thickens as it warms


def test_gas_refuses_bad_constants_and_vacuum():
    with pytest.raises(InputError) as e:
        GasFluid("x", 0.03, -1e-5, 273.0, 100.0)
    assert e.value.field == "sutherland_mu_ref_Pa_s"
    with pytest.raises(InputError):
        GasFluid("x", 0.03, 1e-5, 273.0, 100.0, (400.0, 300.0))
    with pytest.raises(InputError):
        get_oil("air").properties(300.0, -2.0e5)  # absolute pressure < 0


def test_every_fluid_has_the_common_interface(water):
    for f in (get_oil("VG22"), get_oil("air"), water):
        assert isinstance(f, Fluid)
        assert f.kind in ("mineral", "gas", "table")
        lo, hi = f.trusted_range_C
        assert lo < hi and f.polymer_thickened is False
        nu, mu, rho = f.properties(np.array([300.0, 310.0]), 0.0)
        assert np.allclose(mu, nu * rho, rtol=1e-14)
    assert get_oil("VG22").trusted_range_C == (-20.0, 150.0)
    assert water.trusted_range_C == pytest.approx((20.0, 60.0))
    # White Table 1-2, 2 % range of Sutherland's law for air: 170 ... 1900 K
    assert get_oil("air").trusted_range_C == pytest.approx((170 - 273.15, 1900 - 273.15))


def test_get_oil_finds_gases_also_with_a_user_catalogue(tmp_path):
    p = tmp_path / "oils.csv"
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3\nRigOil,46,7,870\n")
    cat = read_oils_csv(p)
    assert get_oil(" AIR ", cat).kind == "gas" and get_oil("rigoil", cat).kind == "mineral"
    with pytest.raises(InputError) as e:
        get_oil("helium")
    assert "air" in str(e.value) and "VG22" in str(e.value)
    assert {"VG22", "AIR", "NITROGEN"} <= set(builtin_fluids())


# --------------------------------------------------------------------------- table


def test_water_table_at_30C_within_the_expected_band(water):
    nu, mu, rho = water.properties(303.15)
    # ln nu linear in T: at the midpoint nu is the geometric mean sqrt(1.004 * 0.658)
    # = 0.812785 cSt; rho linear: (998.2 + 992.2) / 2 = 995.2 kg/m^3
    assert nu * 1e6 == pytest.approx(math.sqrt(1.004 * 0.658), rel=1e-12)
    assert rho == pytest.approx(995.2, rel=1e-12)
    # IAPWS at 30 degC: 0.7972 mPa s / 995.65 kg/m^3 = 0.8007 cSt; the log-linear
    # interpolant over a 20 K step is 1.5 % high, the density 0.05 % low
    assert nu * 1e6 == pytest.approx(0.8007, rel=0.02)
    assert rho == pytest.approx(995.65, rel=1e-3)
    assert mu == pytest.approx(nu * rho, rel=1e-14)
    # the nodes are reproduced exactly (rows may come in any order)
    assert water.kinematic_viscosity_cSt(40.0) == pytest.approx(0.658, rel=1e-12)


def test_table_refuses_outside_its_temperatures(water):
    with pytest.raises(InputError) as e:
        water.properties(np.array([300.0, 343.15]))
    assert e.value.field == "oil_temp_C" and e.value.value == pytest.approx(70.0)
    assert "20..60 degC" in str(e.value)
    clamp = TableFluid(water.name, water.temps_K, water.nu_m2_s, water.rho_kg_m3,
                       outside="clamp")
    with pytest.warns(OilgapWarning, match="outside the table"):
        nu, _, rho = clamp.properties(343.15)
    assert nu * 1e6 == pytest.approx(0.474, rel=1e-12) and rho == pytest.approx(983.2)
    with pytest.warns(OilgapWarning):
        assert clamp.temperature_slope(343.15) == 0.0  # flat beyond the edge


def test_table_temperature_slope_by_hand_and_by_difference(water):
    # on [20, 40] degC: d ln nu/dT = ln(0.658/1.004)/20 = -0.422545/20 = -0.0211272 /K;
    # d rho/dT = -6/20 = -0.3 kg/(m^3 K); at 30 degC rho = 995.2:
    # b = 0.0211272 + 0.3/995.2 = 0.0211272 + 0.0003014 = 0.0214287 /K
    b = water.temperature_slope(303.15)
    assert b == pytest.approx(-math.log(0.658 / 1.004) / 20 + 0.3 / 995.2, rel=1e-10)
    assert b == pytest.approx(0.0214287, rel=1e-5)
    h = 0.01
    mu = lambda T: water.properties(T)[1]  # noqa: E731
    fd = -(math.log(mu(308.15 + h)) - math.log(mu(308.15 - h))) / (2 * h)
    assert water.temperature_slope(308.15) == pytest.approx(fd, rel=1e-4)


def test_table_with_pressures_is_bilinear(tmp_path):
    p = tmp_path / "liquid.csv"
    p.write_text("temp_C,pressure_MPa,nu_cSt,density_kg_m3\n"
                 "20,0.101325,4,800\n40,0.101325,2,790\n20,20.101325,8,810\n"
                 "40,20.101325,4,800\n")
    f = read_fluid_table(p, name="hydraulic fluid")
    assert f.name == "hydraulic fluid" and len(f.pressures_Pa) == 2
    # centre (30 degC, 10 MPa gauge): ln nu bilinear, so nu is the geometric mean of the
    # corners (4 * 2 * 8 * 4)^(1/4) = 256^(1/4) = 4.0 cSt; rho = (800 + 790 + 810 + 800) / 4
    # = 800 kg/m^3
    nu, mu, rho = f.properties(303.15, 10.0e6)
    assert nu * 1e6 == pytest.approx(4.0, rel=1e-12) and rho == pytest.approx(800.0)
    # at gauge 0 the first pressure row, at 20 degC its node
    assert f.kinematic_viscosity_cSt(20.0, 0.0) == pytest.approx(4.0, rel=1e-12)
    with pytest.raises(InputError) as e:
        f.properties(303.15, 30.0e6)
    assert e.value.field == "pressure_MPa"


@pytest.mark.parametrize("text,field", [
    ("temp_C,nu_cSt\n20,1\n40,2\n", "columns"),
    ("temp_C,nu_cSt,density_kg_m3,colour\n20,1,1000,red\n", "columns"),
    ("temp_C,nu_cSt,density_kg_m3\n20,1,1000\n", "temp_C"),               # one temperature
    ("temp_C,nu_cSt,density_kg_m3\n20,1,1000\n20,1.1,1000\n", "temp_C"),  # duplicate
    ("temp_C,nu_cSt,density_kg_m3\n20,-1,1000\n40,1,990\n", "nu_cSt"),
    ("temp_C,nu_cSt,density_kg_m3\n20,1,1000\n40,1,nan\n", "density_kg_m3"),
    ("temp_C,pressure_MPa,nu_cSt,density_kg_m3\n20,0.1,1,1000\n40,0.1,1,990\n"
     "20,10,1.1,1005\n", "pressure_MPa"),                                    # incomplete grid
])
def test_bad_fluid_tables_refused_naming_the_field(tmp_path, text, field):
    p = tmp_path / "t.csv"
    p.write_text(text)
    with pytest.raises(InputError) as e:
        read_fluid_table(p)
    assert e.value.field == field


def test_table_is_numeric_only(water):
    with pytest.raises(TypeError):
        water.properties(ca.SX.sym("T"))


# --------------------------------------------------------------------------- mineral


def test_walther_slope_against_the_closed_form_and_a_difference():
    """b = -d ln mu/dT of the mineral laws. Written out: with z = nu0 + 0.7 (nu0 [cSt] on
    the Walther line at atmospheric pressure), -d ln nu0/dT = B z ln z / (nu0 T); the
    density adds beta = 6.5e-4 /K; Barus-Roelands multiplies by 1 + alpha_ref p /
    ln(mu_ref / 6.31e-5 Pa s), mu_ref the viscosity at 40 degC."""
    oil = get_oil("VG22")
    A, B = oil.walther
    for T, p in ((275.15, 0.0), (313.15, 0.0), (275.15, 30.0e6), (350.0, 70.0e6)):
        nu0 = 10 ** (10 ** (A - B * math.log10(T))) - 0.7
        z = nu0 + 0.7
        rho40 = 860.0 * math.exp(-6.5e-4 * 25.0)
        mu_ref = 22.0e-6 * rho40
        hand = (1 + 1.7e-8 * p / math.log(mu_ref / 6.31e-5)) * (B * z * math.log(z) / (nu0 * T)
                                                               + 6.5e-4)
        assert oil.temperature_slope(T, p) == pytest.approx(hand, rel=1e-12)
        h = 0.01
        fd = -(math.log(oil.properties(T + h, p)[1]) - math.log(oil.properties(T - h, p)[1]))
        assert oil.temperature_slope(T, p) == pytest.approx(fd / (2 * h), rel=1e-6)
    # VG22 at 40 degC: B = 3.643 (see test_oil_properties), 3.643 * 22.7 ln 22.7 / (22 *
    # 313.15) = 0.03748 /K, + 0.00065 = 0.0381 /K: about 3.8 % per kelvin
    assert oil.temperature_slope(313.15) == pytest.approx(0.0381, rel=2e-3)


def test_mineral_oil_flags_and_the_oils_csv_column(tmp_path):
    vg = get_oil("VG46")
    assert vg.kind == "mineral" and vg.polymer_thickened is False and vg.newtonian
    p = tmp_path / "oils.csv"
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3,polymer_thickened\n"
                 "HV46,46,8.2,870,yes\nHM46,46,6.8,870,\n")
    cat = read_oils_csv(p)
    assert cat["HV46"].polymer_thickened and not cat["HM46"].polymer_thickened
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3,polymer_thickened\nX,46,8,870,maybe\n")
    with pytest.raises(InputError) as e:
        read_oils_csv(p)
    assert e.value.field == "polymer_thickened"


# --------------------------------------------------------------------------- warnings


def test_warnings_use_the_fluids_own_range():
    with warnings.catch_warnings():
        warnings.simplefilter("error", OilgapWarning)
        warn_if_untrusted_state(get_oil("air"), -50.0, 0.0)   # within 170..1900 K
    with pytest.warns(OilgapWarning, match="Walther"):
        warn_if_untrusted_state(get_oil("VG22"), -50.0, 0.0)
    custom = GasFluid("lab gas", 0.03, 1.8e-5, 293.15, 120.0, (273.15, 373.15))
    with pytest.warns(OilgapWarning, match="Sutherland law of 'lab gas'"):
        warn_if_untrusted_state(custom, 150.0, 0.0)
    with pytest.warns(OilgapWarning, match="real-gas"):  # 3000 m: 30 MPa of nitrogen
        warn_if_untrusted_state(get_oil("nitrogen"), 2.0, 30.3e6)


# --------------------------------------------------------------------------- case TOML


def test_toml_round_trip_of_each_kind(tmp_path, water):
    (tmp_path / "water.csv").write_text(WATER_CSV)
    tables = {
        "mineral": 'name = "VG46"\npolymer_thickened = true\n',
        "table": 'kind = "table"\ntable_csv = "water.csv"\noutside_table = "clamp"\n',
        "gas": 'kind = "gas"\nname = "air"\n',
        "custom gas": 'kind = "gas"\nname = "argon"\nmolar_mass_kg_per_mol = 0.039948\n'
                      'sutherland_mu_ref_Pa_s = 2.125e-5\nsutherland_T_ref_K = 273.0\n'
                      'sutherland_S_K = 144.0\ntrusted_min_C = -50.0\ntrusted_max_C = 500.0\n',
    }
    for label, text in tables.items():
        case = read_case_toml(write_case(tmp_path, text))
        back = read_case_toml(write_case_toml(case, tmp_path / f"back_{label}.toml"))
        assert back.oil == case.oil, label
        assert oil_state(back) == pytest.approx(oil_state(case), rel=1e-14)
    case = read_case_toml(write_case(tmp_path, tables["mineral"]))
    assert case.oil.polymer_thickened and case.oil.nu40_cSt == 46.0
    case = read_case_toml(write_case(tmp_path, tables["table"]))
    assert case.oil.kind == "table" and case.oil.name == "water" and case.oil.outside == "clamp"
    case = read_case_toml(write_case(tmp_path, tables["custom gas"]))
    assert case.oil.trusted_range_C == pytest.approx((-50.0, 500.0))


def test_mineral_case_dict_is_unchanged_by_fluid_kinds(tmp_path):
    # no "kind" key for mineral oils: case files and grid fingerprints read as before
    case = read_case_toml(write_case(tmp_path, 'name = "VG22"\n'))
    assert case_to_dict(case)["oil"] == {"name": "VG22"}
    gas = read_case_toml(write_case(tmp_path, 'kind = "gas"\nname = "Nitrogen"\n'))
    assert case_to_dict(gas)["oil"] == {"kind": "gas", "name": "nitrogen"}


BAD_OIL_TABLES = [
    ('kind = "liquid"\n', "oil.kind"),
    ('kind = "table"\n', "oil.table_csv"),
    ('kind = "table"\ntable_csv = "missing.csv"\n', "table_csv"),
    ('kind = "table"\ntable_csv = "water.csv"\nnu40_cSt = 10.0\n', "oil.nu40_cSt"),
    ('kind = "table"\ntable_csv = "water.csv"\noutside_table = "extrapolate"\n',
     "outside_table"),
    ('kind = "gas"\nname = "helium"\n', "oil.name"),
    ('kind = "gas"\n', "oil.name"),
    ('kind = "gas"\nname = "air"\npolymer_thickened = true\n', "oil.polymer_thickened"),
    ('kind = "gas"\nsutherland_S_K = 100.0\n', "oil.molar_mass_kg_per_mol"),
    ('kind = "gas"\nname = "x"\nmolar_mass_kg_per_mol = 0.03\nsutherland_mu_ref_Pa_s = 0.0\n'
     'sutherland_T_ref_K = 273.0\nsutherland_S_K = 100.0\n', "sutherland_mu_ref_Pa_s"),
    ('name = "air"\n', "oil.name"),                 # a gas needs kind = "gas"
    ('name = "VG22"\npolymer_thickened = "yes"\n', "oil.polymer_thickened"),
    ('name = "VG22"\ntable_csv = "water.csv"\n', "oil.table_csv"),
    ('name = "X"\nnu40_cSt = 10.0\nnu100_cSt = 12.0\ndensity_kg_m3 = 870.0\n', "nu100_cSt"),
]


@pytest.mark.parametrize("text,field", BAD_OIL_TABLES)
def test_bad_oil_tables_refused_naming_the_key(tmp_path, text, field):
    (tmp_path / "water.csv").write_text(WATER_CSV)
    with pytest.raises(InputError) as e:
        read_case_toml(write_case(tmp_path, text))
    assert e.value.field == field


# --------------------------------------------------------------------------- commands


def test_evaluate_json_on_a_gas_case(tmp_path, capsys):
    p = write_case(tmp_path, 'kind = "gas"\nname = "air"\n')
    assert main(["evaluate", str(p), "--json", "--thermal", "none"]) == 0
    out = json.loads(capsys.readouterr().out)
    # air at 20 degC, 1 atm by hand: mu = 1.716e-5 (293.15/273)^1.5 (384/404.15)
    # = 1.81425e-5 Pa s; rho = 101325 * 0.02897 / (8.314462618 * 293.15) = 1.204318
    mu = 1.716e-5 * (293.15 / 273.0) ** 1.5 * 384.0 / 404.15
    rho = 101325.0 * 0.02897 / (R_U * 293.15)
    # the JSON carries 6 significant digits: half a unit of the 6th is 5e-6 relative
    assert out["oil"] == "air" and out["density_kg_m3"] == pytest.approx(rho, rel=5e-6)
    assert out["nu_cSt"] == pytest.approx(mu / rho * 1e6, rel=5e-6)
    case = read_case_toml(p)
    nodes, weights = case.duty_cycle.speed_distribution()
    want = sum(region_mean_power(r, nodes, weights, mu / rho, rho, case.friction)
               for r in joint_regions(case))
    assert out["total_mean_power_W"] == pytest.approx(want, rel=5e-6)
    # the same joint in VG22 at 20 degC loses about three orders of magnitude more
    assert evaluate_case(case.with_changes(oil=get_oil("VG22"))).total_mean_power_W > \
        300 * out["total_mean_power_W"]


def test_evaluate_oil_option_takes_a_gas(capsys):
    assert main(["evaluate", "--oil", "nitrogen", "--depth-m", "0", "--temp-c", "25",
                 "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["oil"] == "nitrogen"
    # 101325 * 0.0280134 / (8.314462618 * 298.15) = 1.14503 kg/m^3
    assert out["density_kg_m3"] == pytest.approx(1.14503, rel=1e-5)


def test_optimize_a_gas_case_and_evaluate_its_output(tmp_path, capsys):
    p = write_case(tmp_path, 'kind = "gas"\nname = "air"\n')
    out_case = tmp_path / "opt.toml"
    rc = main(["optimize", str(p), "--json", "--starts", "2", "--out", str(out_case)])
    assert rc == 0  # an IPOPT failure would be exit 4, never a traceback
    d = json.loads(capsys.readouterr().out)
    assert d["status"] == "Solve_Succeeded"
    assert d["optimal"]["mean_power_W"] <= d["initial"]["mean_power_W"] * (1 + 1e-9)
    back = read_case_toml(out_case)
    assert back.oil == get_oil("air")
    assert evaluate_case(back).total_mean_power_W == pytest.approx(
        d["optimal"]["mean_power_W"], rel=0.05)


def test_table_case_outside_its_table_exits_2_with_one_line(tmp_path, capsys):
    (tmp_path / "water.csv").write_text(WATER_CSV)
    p = write_case(tmp_path, 'kind = "table"\ntable_csv = "water.csv"\n')
    assert main(["evaluate", str(p), "--temp-c", "80"]) == 2
    err = capsys.readouterr().err
    assert "oil_temp_C = 80.0" in err and "20..60 degC" in err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert main(["evaluate", str(p), "--temp-c", "30", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["nu_cSt"] == pytest.approx(math.sqrt(1.004 * 0.658), rel=5e-6)  # 6 digits


def test_bad_fluid_case_exits_2_with_one_line(tmp_path, capsys):
    p = write_case(tmp_path, 'kind = "gas"\nname = "helium"\n')
    assert main(["evaluate", str(p)]) == 2
    err = capsys.readouterr().err
    assert "oil.name = 'helium'" in err and len(err.strip().splitlines()) == 1
