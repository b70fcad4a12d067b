"""``oilgap evaluate --thermal none|bulk|film|full``: the header names the mode, the JSON
carries it and the film band, contradictory options exit 2 with one line and no
traceback."""

import json
import re

import pytest

from oilgap.cli import main

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
    """Exit code, stdout with its wrapped prose lines joined again (a continuation line is
    indented under its label), stderr."""
    code = main(argv)
    out = capsys.readouterr()
    return code, re.sub(r"\n {6,}(?=\S)", " ", out.out), out.err


@pytest.mark.parametrize("argv,header", [
    (["evaluate"], "thermal     none (default: the model the evidence supports"),
    (["evaluate", "--thermal", "film"], "thermal     film (the film's own shear heating at "),
    (["evaluate", "--thermal", "none"], "thermal     none (isothermal oil, the seed paper's"),
])
def test_header_names_the_mode(capsys, argv, header):
    code, out, _ = run(capsys, argv)
    lines = out.splitlines()
    assert code == 0 and lines[0].startswith("total mean viscous power")  # the answer first
    assert any(x.startswith(header) for x in lines)
    for col in ("Na_peak", "Na_eff", "Phi_st", "Phi_app", "rise K"):
        assert col in out
    total = float(re.search(r"total mean viscous power\s+([\d.]+) W", out).group(1))
    band = re.search(r"^film band\s+(.*): ([\d.]+) W \(([-+\d]+) %\); (.*)$", out, re.M)
    other, change = float(band.group(2)), float(band.group(3))
    assert change == pytest.approx(100 * (other / total - 1), abs=0.6)  # as printed
    assert band.group(4).endswith(
        "not supported by Table 4 of the seed paper, see docs/thermal.md#evidence")
    if "film" in argv:  # the film applied; the band is the default's (none) number
        assert "film_applied: true" in out and band.group(1).startswith("without film")
        assert other > total
    else:  # not applied; the band is the film at full strength
        assert "film_applied: false" in out and "not applied" in out
        assert band.group(1) == "film heating at full strength (film)" and other < total


def test_bulk_is_the_default_with_thermal(capsys, hot):
    code, out, _ = run(capsys, ["evaluate", hot])
    assert code == 0
    assert re.search(r"^thermal     bulk \(default:", out, re.M)
    assert "film heating at full strength (full)" in out
    assert re.search(r"^balance     sea 2 degC, R_th = 0.5 K/W, Q = 0 W: oil at [\d.]+ degC",
                     out, re.M)
    assert "(heat balance)" in out
    code, out, _ = run(capsys, ["evaluate", hot, "--thermal", "film"])
    assert code == 0 and re.search(r"^thermal     film \(the film's own", out, re.M)
    assert "balance" not in out


def test_json_gains_the_thermal_fields(capsys, hot):
    code, out, _ = run(capsys, ["evaluate", hot, "--json", "--sea-temp-c", "6"])
    d = json.loads(out)
    assert code == 0 and d["thermal_mode"] == "bulk" and d["thermal_mode_default"] is True
    assert d["film_applied"] is False
    band = d["film_band"]
    assert band["mode"] == "full" and band["film_applied"] is True
    assert band["mean_power_W"] < d["total_mean_power_W"]
    assert band["change_pct"] == pytest.approx(
        100 * (band["mean_power_W"] / d["total_mean_power_W"] - 1), rel=1e-5)
    assert "docs/thermal.md#evidence" in band["evidence"]
    assert d["sea_temp_C"] == 6.0 and d["resistance_K_per_W"] == 0.5
    assert d["oil_temp_C"] > 6.0 and d["other_heat_W"] == 0.0
    # the balance: T = T_sea + R P (Q = 0)
    assert d["oil_temp_C"] == pytest.approx(6.0 + 0.5 * d["total_mean_power_W"], rel=1e-5)
    assert d["isothermal_total_mean_power_W"] > 0
    for r in d["regions"]:
        assert {"nahme_peak", "nahme_effective_peak", "film_factor_steady_peak",
                "film_factor_effective_peak", "film_factor_applied_peak", "film_applied",
                "film_temp_rise_peak_K"} <= set(r)
        assert r["film_applied"] is False and r["film_factor_applied_peak"] == 1.0
        assert "film_factor_peak" not in r  # the old, mislabelled key
    code, out, _ = run(capsys, ["evaluate", "--json", "--thermal", "none"])
    d = json.loads(out)
    assert d["thermal_mode"] == "none" and d["thermal_mode_default"] is False
    assert d["sea_temp_C"] is None and d["oil_temp_C"] == 2.0
    assert d["isothermal_total_mean_power_W"] == d["total_mean_power_W"]
    code, out, _ = run(capsys, ["evaluate", hot, "--json", "--thermal", "full"])
    d = json.loads(out)
    assert d["thermal_mode"] == "full" and d["film_applied"] is True
    assert d["film_band"]["mode"] == "bulk" and d["film_band"]["film_applied"] is False
    for r in d["regions"]:  # region 2 has Taylor vortices at the peak: faded out
        assert r["film_factor_applied_peak"] == r["film_factor_effective_peak"] <= 1.0
    assert d["regions"][0]["film_factor_applied_peak"] < 1.0


def test_bulk_is_a_choice(capsys, hot):
    code, out, _ = run(capsys, ["evaluate", hot, "--thermal", "bulk", "--json"])
    asked = json.loads(out)
    code2, out, _ = run(capsys, ["evaluate", hot, "--json"])
    default = json.loads(out)
    assert code == code2 == 0
    assert asked["thermal_mode"] == "bulk" and asked["thermal_mode_default"] is False
    assert asked["total_mean_power_W"] == default["total_mean_power_W"]
    assert asked["oil_temp_C"] == pytest.approx(
        2.0 + 0.5 * asked["total_mean_power_W"], abs=1e-8)  # T = T_sea + R P


@pytest.mark.parametrize("argv,needle", [
    (["evaluate", "--thermal", "full"], "--thermal = 'full' is not allowed"),
    (["evaluate", "--thermal", "bulk"], "--thermal = 'bulk' is not allowed"),
    (["evaluate", "HOT", "--thermal", "bulk", "--temp-c", "5"], "--temp-c = 5.0"),
    (["evaluate", "HOT", "--thermal", "none", "--sea-temp-c", "3"], "--sea-temp-c = 3.0"),
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
