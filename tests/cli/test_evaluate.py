"""``oilgap evaluate``: JSON and table output, bad input exits 2 with one line."""

import json
import math
import subprocess
import sys

import pytest

from oilgap.cli import main
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case

BAD_TOML = """
name = "bad joint"
[region1]
T1_mm = 23.9
T2_mm = 25.4
T3_mm = 26.4
T4_mm = 26.0
length_mm = 14.76
"""

JSON_REL = 1e-5  # JSON numbers carry 6 significant digits (oilgap.model.io.serialize)
JSON_ABS = 1e-4  # [K] or [W]: a temperature or power rounded to 6 digits


def test_cli_evaluate_json(capsys):
    assert main(["evaluate", "--json", "--temp-c", "40", "--depth-m", "0"]) == 0
    out = json.loads(capsys.readouterr().out)
    ev = evaluate_case(seed_case(), oil_temp_C=40.0, depth_m=0.0)
    assert out["total_mean_power_W"] == pytest.approx(ev.total_mean_power_W, rel=JSON_REL)
    assert [r["name"] for r in out["regions"]] == ["rotor-stator", "bearing"]
    for r in out["regions"]:
        assert {"name", "Re_peak", "Ta_peak", "Cm_peak", "mean_power_W"} <= set(r)
    # the units at the edge: the seed's 3000 rpm peak, nu in cSt
    assert out["peak_speed_rpm"] == pytest.approx(3000.0, rel=JSON_REL)
    assert math.isclose(out["nu_cSt"], ev.nu_cSt, rel_tol=1e-12)


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
    p = tmp_path / "case.toml"
    p.write_text(BAD_TOML)
    r = subprocess.run([sys.executable, "-m", "oilgap.cli", "evaluate", str(p)],
                       capture_output=True, text=True)
    assert r.returncode == 2
    assert "T4_mm = 26.0" in r.stderr and "Traceback" not in r.stderr
    r = subprocess.run([sys.executable, "-m", "oilgap.cli", "evaluate", "--temp-c",
                        "nan"], capture_output=True, text=True)
    assert r.returncode == 2 and "--temp-c" in r.stderr and "Traceback" not in r.stderr


def test_cli_oils_csv(tmp_path, capsys):
    p = tmp_path / "oils.csv"
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3\nRigOil,46,7,870\n")
    assert main(["evaluate", "--oils", str(p), "--oil", "rigoil", "--json"]) == 0
    assert '"oil": "RigOil"' in capsys.readouterr().out
