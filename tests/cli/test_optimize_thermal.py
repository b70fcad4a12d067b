"""``oilgap optimize --thermal``: the mode named, with and without heating side by side,
``--thermal none`` reproducing the golden (pre-heating) output, bad combinations exit 2."""

import json
import re
from dataclasses import replace
from pathlib import Path

import pytest

from oilgap.cli import main
from oilgap.model.case import ThermalSpec
from oilgap.model.io.case_io import seed_case
from oilgap.studies.io.case_write import write_case_toml

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "data" / "optimize_none.json"

JSON_REL = 1e-5  # JSON numbers carry 6 significant digits (oilgap.model.io.serialize)
JSON_ABS = 1e-4  # [K] or [W]: a temperature or power rounded to 6 digits


@pytest.fixture(scope="module")
def thermal_toml(tmp_path_factory):
    case = replace(seed_case(), name="seed with [thermal]",
                   thermal=ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5,
                                       heat_capacity_J_K=5e4))
    return str(write_case_toml(case, tmp_path_factory.mktemp("cases") / "thermal.toml"))


def run_json(capsys, *argv):
    assert main(["optimize", "--json", "--starts", "1", *argv]) == 0
    return json.loads(capsys.readouterr().out)


def _same_numbers(a, b, path=""):
    """Differences of the keys both documents have (numbers to 1e-12 relative)."""
    if isinstance(a, dict):
        return [d for k in set(a) & set(b) if k != "solve_time_s"
                for d in _same_numbers(a[k], b[k], f"{path}.{k}")]
    if isinstance(a, list):
        return [d for i, (x, y) in enumerate(zip(a, b, strict=True))
                for d in _same_numbers(x, y, f"{path}[{i}]")]
    if isinstance(a, float) and isinstance(b, float):
        return [] if abs(a - b) <= 1e-12 * max(abs(a), abs(b), 1e-300) else [path]
    return [] if a == b else [path]


def test_thermal_none_reproduces_the_golden_numbers(capsys):
    """The golden ``optimize --thermal none --json`` (default 8 starts), checked equal to
    the output recorded before the thermal modes existed."""
    assert main(["optimize", "--json", "--thermal", "none"]) == 0
    d = json.loads(capsys.readouterr().out)
    gold = json.loads(GOLDEN.read_text())
    assert _same_numbers(gold, d) == []
    assert set(gold) <= set(d)
    assert d["thermal_mode"] == "none" and d["oil_temp_C"] == 2.0
    assert d["sea_temp_C"] is None and d["without_heating"] is None


def test_default_on_the_seed_is_none_with_the_film_band(capsys):
    d = run_json(capsys)
    none = run_json(capsys, "--thermal", "none")
    assert d["thermal_mode"] == "none" and d["without_heating"] is None
    assert _same_numbers(d, none) == []
    for k in ("initial", "optimal"):  # the same design with film heating beside it
        band = d[k]["film_band"]
        assert band["mode"] == "film" and band["film_applied"] is True
        assert band["mean_power_W"] < d[k]["mean_power_exact_W"]
        assert "docs/thermal.md#evidence" in band["evidence"]


def test_film_beside_the_isothermal_optimum(capsys):
    d = run_json(capsys, "--thermal", "film")
    none = run_json(capsys, "--thermal", "none")
    assert d["thermal_mode"] == "film" and d["oil_temp_C"] == 2.0
    # its band is the default's number: the initial design without film heating
    assert d["initial"]["film_band"]["mode"] == "none"
    assert d["initial"]["film_band"]["mean_power_W"] == pytest.approx(
        none["initial"]["mean_power_exact_W"], rel=JSON_REL)
    assert d["sea_temp_cost_W_per_K"] is None and d["oil_temp_cost_W_per_K"] < 0
    w = d["without_heating"]
    assert w["optimal"]["mean_power_W"] == none["optimal"]["mean_power_W"]
    assert w["active_constraints"] == none["active_constraints"]
    # the film thins the oil where it is sheared: less loss at the same temperature
    assert d["optimal"]["mean_power_W"] < w["optimal"]["mean_power_W"]
    ch = d["heating_changes"]["mean_power_W"]
    assert ch["change"] == pytest.approx(d["optimal"]["mean_power_W"]
                                         - w["optimal"]["mean_power_W"], rel=JSON_REL)


@pytest.mark.parametrize("mode", ["full", "bulk"])
def test_balance_json_has_the_balance_and_the_sea_temperature_cost(capsys, thermal_toml,
                                                                   mode):
    d = run_json(capsys, thermal_toml, *(["--thermal", "full"] if mode == "full" else []))
    assert d["thermal_mode"] == mode and d["sea_temp_C"] == 2.0
    w = d["without_heating"]
    assert w["oil_temp_C"] == 2.0
    # the balance holds at the optimum (R = 0.5 K/W, Q = 0)
    assert d["oil_temp_C"] - 2.0 == pytest.approx(0.5 * d["optimal"]["mean_power_W"],
                                                  abs=JSON_ABS)
    assert d["initial_oil_temp_C"] > d["oil_temp_C"]  # a design that loses less runs colder
    assert d["sea_temp_cost_W_per_K"] < 0
    assert d["initial"]["film_band"]["mode"] == {"full": "bulk", "bulk": "full"}[mode]
    warm = run_json(capsys, thermal_toml, "--sea-temp-c", "2.1", "--thermal", mode)
    cold = run_json(capsys, thermal_toml, "--sea-temp-c", "1.9", "--thermal", mode)
    assert warm["sea_temp_C"] == 2.1
    slope = (warm["optimal"]["mean_power_W"] - cold["optimal"]["mean_power_W"]) / 0.2
    # central difference over +-0.1 K; the powers carry 6 digits (1e-4 W over 0.2 K)
    assert slope == pytest.approx(d["sea_temp_cost_W_per_K"], rel=0.01)


def test_text_names_the_mode_and_shows_both_optima(capsys, thermal_toml):
    assert main(["optimize", thermal_toml, "--starts", "1"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("optimum     ")  # the answer first, the header after the tables
    assert re.search(r"^thermal     bulk \(default", out, re.M)
    assert main(["optimize", thermal_toml, "--starts", "1", "--thermal", "full"]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    at = next(i for i, x in enumerate(lines) if x.startswith("thermal     full (film heating"))
    assert "film band, initial design: without film heating (bulk" in out
    assert lines[next(i for i in range(at + 1, len(lines))
                      if not lines[i].startswith(" "))].startswith("balance     sea 2 degC")
    for needle in ("no heating", "vs none", "oil_temp_C", "dP*/dT_sea", "W/K",
                   "active constraints with heating (full)", "mean_power_exact_W"):
        assert needle in out
    assert main(["optimize", "--starts", "1", "--thermal", "none"]) == 0
    assert re.search(r"^thermal     none \(isothermal", capsys.readouterr().out, re.M)


@pytest.mark.parametrize("argv, needle", [
    (["--thermal", "full"], "--thermal"),
    (["--sea-temp-c", "5"], "--sea-temp-c"),
    (["--thermal", "none", "--sea-temp-c", "5"], "--sea-temp-c"),
])
def test_bad_combinations_exit_2_with_one_line(capsys, argv, needle):
    assert main(["optimize", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and needle in err[0]


@pytest.mark.parametrize("argv, needle", [
    (["--temp-c", "10"], "--temp-c"),
    (["--sea-temp-c", "warm"], "--sea-temp-c"),
    (["--sea-temp-c", "400"], "--sea-temp-c"),
])
def test_bad_balance_input_exits_2(capsys, thermal_toml, argv, needle):
    assert main(["optimize", thermal_toml, *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and needle in err[0]
