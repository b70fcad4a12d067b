"""Design cases (TOML in and out, validation) and the seed joint's evaluation."""

import math
import subprocess
import sys
import warnings

import numpy as np
import pytest

from oilgap.model.case_io import read_case_toml, seed_case, write_case_toml
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.evaluation import evaluate_case, mean_viscous_power
from oilgap.studies.cli import main

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


def hand_mean_power(R, gap, L, T, gamma, nu, rho, laminar="couette"):
    """Eqs. 4-6 and 8 written out independently, summed over the seed's 1500 samples."""
    total = 0.0
    for k in range(1500):
        w = abs(2 * math.pi * 3000 / 60 * math.sin(0.1 * math.pi * 0.2 * k))
        if w == 0:
            continue
        re = w * R * gap / nu
        x = gap / R
        if re < 64:
            cm = 10.0 / re * x**0.3
        elif re < 500:
            cm = 2.0 * re**-0.6 * x**0.3
        elif re < 1e4:
            cm = 1.03 * re**-0.5 * x**0.3
        else:
            cm = 0.065 * re**-0.2 * x**0.3
        if laminar == "couette":
            cm = max(cm, 8 * (1 + x) ** 2 / ((2 + x) * re))
        total += 0.5 * math.pi * cm * T**gamma * rho * w**3 * R**4 * L
    return total / 1500


@pytest.mark.parametrize("laminar", ["couette", "bilgen-boulos"])
def test_seed_region_powers_at_40C_against_hand_computation(tmp_path, laminar):
    case = read_case_toml(write(tmp_path, SEED_TOML))
    ev = evaluate_case(case, laminar_law=laminar)
    # at 40 degC and the surface the Walther line gives the catalogue 22 cSt exactly;
    # density 860 * exp(-6.5e-4 * 25) = 846.138 kg/m^3
    nu, rho = 22e-6, 860 * math.exp(-6.5e-4 * 25)
    assert ev.nu_cSt == pytest.approx(22.0, rel=1e-10)
    assert ev.density_kg_m3 == pytest.approx(rho, rel=1e-12)
    p1 = hand_mean_power(0.0254, 0.001, 0.01476, 4.0, 0.5, nu, rho, laminar)
    p2 = hand_mean_power(0.022, 0.005, 0.01424, 1.0, 0.5, nu, rho, laminar)
    r1, r2 = ev.regions
    assert r1.mean_power_W == pytest.approx(p1, rel=1e-9)
    assert r2.mean_power_W == pytest.approx(p2, rel=1e-9)
    assert ev.total_mean_power_W == pytest.approx(p1 + p2, rel=1e-9)
    # peak Re of region 1 by hand: 314.159 * 0.0254 * 0.001 / 22e-6 = 362.71
    assert r1.Re_peak == pytest.approx(362.71, rel=1e-4)
    assert r1.regimes == ("laminar", "laminar with vortices")


def test_speed_distribution_equals_sample_mean():
    cyc = DutyCycle.sine()
    nodes, weights = cyc.speed_distribution()
    assert len(cyc.time_s) == 1500 and len(nodes) == 26
    assert weights.sum() == pytest.approx(1.0, abs=1e-15)
    for f in (lambda w: w**3, lambda w: w**2 * np.exp(w / 400)):
        plain = np.mean(f(np.abs(cyc.omega_rad_s)))
        assert f(nodes) @ weights == pytest.approx(plain, rel=1e-13)


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


def test_smoothing_lowers_loss_only_in_region1():
    a = evaluate_case(seed_case())
    b = evaluate_case(seed_case(smoothed=True))
    assert b.regions[0].mean_power_W < a.regions[0].mean_power_W
    assert b.regions[1].mean_power_W == a.regions[1].mean_power_W


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


@pytest.mark.parametrize("csv,field", [
    ("time_s,rpm\n0,1\n1,2\n", "columns"),
    ("time_s,speed_rpm\n0,1\n1,fast\n", "speed_rpm"),
    ("time_s,speed_rpm\n0,1\n1,2\n1,3\n", "time_s"),
    ("time_s,speed_rpm\n0,1\n2,2\n1,3\n", "time_s"),
    ("time_s,speed_rpm\n0,1\n1,nan\n", "speed_rpm"),
])
def test_bad_duty_cycle_csv(tmp_path, csv, field):
    p = write(tmp_path, csv, "cyc.csv")
    with pytest.raises(InputError) as e:
        DutyCycle.from_csv(p)
    assert e.value.field == field


def test_untrusted_temperature_warns():
    with pytest.warns(OilgapWarning, match="oil_temp_C"):
        evaluate_case(seed_case(), oil_temp_C=-35.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        evaluate_case(seed_case(), oil_temp_C=2.0)


# ---------------------------------------------------------------- command line


def test_cli_evaluate_json(capsys):
    import json

    assert main(["evaluate", "--json", "--temp-c", "40", "--depth-m", "0"]) == 0
    out = json.loads(capsys.readouterr().out)
    ev = evaluate_case(seed_case(), oil_temp_C=40.0, depth_m=0.0)
    assert out["total_mean_power_W"] == pytest.approx(ev.total_mean_power_W, rel=1e-12)
    assert [r["name"] for r in out["regions"]] == ["rotor-stator", "bearing"]
    for r in out["regions"]:
        assert {"name", "Re_peak", "Ta_peak", "Cm_peak", "mean_power_W"} <= set(r)


def test_cli_evaluate_table(capsys):
    assert main(["evaluate", "--oil", "VG1000", "--laminar-law", "bilgen-boulos"]) == 0
    out = capsys.readouterr().out
    assert "rotor-stator" in out and "bearing" in out and "total mean viscous power" in out


@pytest.mark.parametrize("argv,needle", [
    (["evaluate", "--oil", "VG23"], "oil = 'VG23'"),
    (["evaluate", "nonexistent.toml"], "case = 'nonexistent.toml'"),
    (["evaluate", "--depth-m", "-5"], "depth_m = -5"),
])
def test_cli_bad_input_exit_2(capsys, argv, needle):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert needle in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_cli_bad_input_subprocess_no_traceback(tmp_path):
    p = write(tmp_path, SEED_TOML.replace("T4_mm = 27.9", "T4_mm = 26.0"))
    r = subprocess.run([sys.executable, "-m", "oilgap.studies.cli", "evaluate", str(p)],
                       capture_output=True, text=True)
    assert r.returncode == 2
    assert "T4_mm = 26.0" in r.stderr and "Traceback" not in r.stderr
    r = subprocess.run([sys.executable, "-m", "oilgap.studies.cli", "evaluate", "--temp-c",
                        "nan"], capture_output=True, text=True)
    assert r.returncode == 2 and "--temp-c" in r.stderr and "Traceback" not in r.stderr


def test_rig_without_region2(tmp_path):
    toml = SEED_TOML.replace("[region2]\nradius_mm = 22.0\nlength_mm = 14.24\ngap_mm = 5.0\n",
                             "")
    case = read_case_toml(write(tmp_path, toml))
    assert case.region2 is None
    ev = evaluate_case(case)
    full = evaluate_case(read_case_toml(write(tmp_path, SEED_TOML, "full.toml")))
    assert len(ev.regions) == 1
    assert ev.total_mean_power_W == pytest.approx(full.regions[0].mean_power_W, rel=1e-14)


def test_cli_oils_csv(tmp_path, capsys):
    p = write(tmp_path, "oil,nu40_cSt,nu100_cSt,density_kg_m3\nRigOil,46,7,870\n", "oils.csv")
    assert main(["evaluate", "--oils", str(p), "--oil", "rigoil", "--json"]) == 0
    assert '"oil": "RigOil"' in capsys.readouterr().out
