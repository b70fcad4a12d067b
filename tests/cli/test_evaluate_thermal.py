"""``oilgap evaluate --thermal none|film|full``: the header names the mode, the JSON carries
it, contradictory options exit 2 with one line and no traceback."""

import json
import re

import pytest

from oilgap.studies.cli import main

THERMAL = """
[thermal]
sea_temp_C = 2.0
resistance_K_per_W = 0.5
heat_capacity_J_per_K = 5.0e4
"""


@pytest.fixture
def hot(seed_toml, write_file):
    """The test joint with a [thermal] table (path as str)."""
    return str(write_file(seed_toml + THERMAL, "hot.toml"))


def run(capsys, argv):
    code = main(argv)
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.parametrize("argv,header", [
    (["evaluate"], "thermal     film (default: the best physics this case allows;"),
    (["evaluate", "--thermal", "film"], "thermal     film (film heating at the given oil "),
    (["evaluate", "--thermal", "none"], "thermal     none (isothermal oil: the seed paper's"),
])
def test_header_names_the_mode(capsys, argv, header):
    code, out, _ = run(capsys, argv)
    lines = out.splitlines()
    assert code == 0 and lines[1].startswith(header)
    assert "Na_peak" in out and "rise K" in out
    if "none" in argv:
        assert "not applied" in out and "isothermal (seed model)" not in out
    else:  # the isothermal total and the change, as printed, agree with each other
        total = float(re.search(r"total mean viscous power\s+([\d.]+) W", out).group(1))
        iso = float(re.search(r"isothermal \(seed model\)\s+([\d.]+) W", out).group(1))
        change = float(re.search(r"changes the loss by ([-+\d.]+) %", out).group(1))
        assert change == pytest.approx(100 * (total / iso - 1), abs=0.06)


def test_full_is_the_default_with_thermal(capsys, hot):
    code, out, _ = run(capsys, ["evaluate", hot])
    assert code == 0
    assert out.splitlines()[1].startswith("thermal     full (default:")
    assert re.search(r"^balance     sea 2 degC, R_th = 0.5 K/W, Q = 0 W: oil at [\d.]+ degC",
                     out, re.M)
    assert "(heat balance)" in out
    code, out, _ = run(capsys, ["evaluate", hot, "--thermal", "film"])
    assert code == 0 and out.splitlines()[1].startswith("thermal     film (film heating")
    assert "balance" not in out


def test_json_gains_the_thermal_fields(capsys, hot):
    code, out, _ = run(capsys, ["evaluate", hot, "--json", "--sea-temp-c", "6"])
    d = json.loads(out)
    assert code == 0 and d["thermal_mode"] == "full" and d["thermal_mode_default"] is True
    assert d["sea_temp_C"] == 6.0 and d["resistance_K_per_W"] == 0.5
    assert d["oil_temp_C"] > 6.0 and d["other_heat_W"] == 0.0
    # the balance: T = T_sea + R P (Q = 0)
    assert d["oil_temp_C"] == pytest.approx(6.0 + 0.5 * d["total_mean_power_W"], abs=1e-8)
    assert d["isothermal_total_mean_power_W"] > 0
    for r in d["regions"]:
        assert {"nahme_peak", "film_factor_peak", "film_temp_rise_peak_K"} <= set(r)
    code, out, _ = run(capsys, ["evaluate", "--json", "--thermal", "none"])
    d = json.loads(out)
    assert d["thermal_mode"] == "none" and d["thermal_mode_default"] is False
    assert d["sea_temp_C"] is None and d["oil_temp_C"] == 2.0
    assert d["isothermal_total_mean_power_W"] == d["total_mean_power_W"]


@pytest.mark.parametrize("argv,needle", [
    (["evaluate", "--thermal", "full"], "--thermal = 'full' is not allowed"),
    (["evaluate", "HOT", "--temp-c", "5"], "--temp-c = 5.0 is not allowed"),
    (["evaluate", "HOT", "--thermal", "full", "--temp-c", "5"], "--temp-c = 5.0"),
    (["evaluate", "HOT", "--thermal", "film", "--sea-temp-c", "3"], "--sea-temp-c = 3.0"),
    (["evaluate", "--sea-temp-c", "3"], "needs the case's [thermal] table"),
    (["evaluate", "HOT", "--sea-temp-c", "400"], "--sea-temp-c = 400.0"),
])
def test_contradictions_exit_2_with_one_line(capsys, hot, argv, needle):
    code, out, err = run(capsys, [hot if a == "HOT" else a for a in argv])
    assert code == 2 and out == ""
    assert needle in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
