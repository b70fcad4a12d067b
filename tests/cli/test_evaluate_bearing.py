"""``oilgap evaluate`` with a [bearing]: the bearing is its own row with its model, its
mean power equals bearing_mean_power at the same oil state (computed here), the total is
regions + bearing under every thermal mode, the balance under full takes its heat, the
defaults the tool filled in are shown; bad tables exit 2 with one line; a case without
[bearing] prints what it printed before."""

import json
import math
import re
from dataclasses import replace

import pytest

from oilgap.cli import main
from oilgap.model.bearing import bearing_mean_power, bearing_torque
from oilgap.model.evaluation import oil_state
from oilgap.model.io.case_io import read_case_toml

THERMAL = """
[thermal]
sea_temp_C = 2.0
resistance_K_per_W = 0.5
heat_capacity_J_per_K = 5.0e4
other_heat_W = 3.0
"""

JSON_REL = 1e-5  # JSON numbers carry 6 significant digits (oilgap.model.io.serialize)
JSON_ABS = 1e-4  # [K] or [W]: a temperature or power rounded to 6 digits


def run(capsys, argv):
    code = main(argv)
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.fixture
def cases(seed_toml, write_file):
    """Paths (str) of the test joint with a 6809 (skf, palmgren, with [thermal]) and without."""
    return {
        "skf": str(write_file(seed_toml + '[bearing]\ndesignation = "6809"\n', "skf.toml")),
        "palmgren": str(write_file(seed_toml + '[bearing]\ndesignation = "6809"\n'
                                   'model = "palmgren"\n', "palmgren.toml")),
        "hot": str(write_file(seed_toml + '[bearing]\ndesignation = "6809"\n' + THERMAL,
                              "hot.toml")),
        "plain": str(write_file(seed_toml, "plain.toml")),
        "hot_plain": str(write_file(seed_toml + THERMAL, "hot_plain.toml")),
    }


def evaluate_json(capsys, *argv):
    code, out, err = run(capsys, ["evaluate", *argv, "--json"])
    assert code == 0, err
    return json.loads(out)


@pytest.mark.parametrize("model", ["skf", "palmgren"])
@pytest.mark.parametrize("thermal", ["none", "film"])
def test_json_bearing_row_and_total(capsys, cases, model, thermal):
    d = evaluate_json(capsys, cases[model], "--thermal", thermal)
    plain = evaluate_json(capsys, cases["plain"], "--thermal", thermal)
    case = read_case_toml(cases[model])
    nu, _, _ = oil_state(case, d["oil_temp_C"], d["depth_m"])
    nodes, weights = case.duty_cycle.speed_distribution()
    (b,) = d["bearings"]
    assert (b["name"], b["model"]) == ("61809", model)
    assert b["mean_power_W"] == pytest.approx(
        float(bearing_mean_power(case.bearing, nodes, weights, nu)), rel=JSON_REL)
    assert b["torque_peak_Nm"] == pytest.approx(
        float(bearing_torque(case.bearing, 3000 * 3.141592653589793 / 30, nu)), rel=JSON_REL)
    assert sum(b["terms_W"].values()) == pytest.approx(b["mean_power_W"], rel=1e-5)
    expected_terms = ({"rolling", "sliding", "drag_vm", "drag_rs"} if model == "skf"
                      else {"load_independent", "load_dependent"})
    assert set(b["terms_W"]) == expected_terms
    assert b["defaults"]["outside_mm"] == 58.0 and b["defaults"]["balls"] == 24
    assert "bore_mm" not in b["defaults"]
    # the regions are the case's without the bearing; the total adds the bearing
    assert d["regions"] == plain["regions"]
    regions = sum(r["mean_power_W"] for r in d["regions"])
    assert d["total_mean_power_W"] == pytest.approx(regions + b["mean_power_W"], rel=JSON_REL)
    assert d["viscous_torque_peak_Nm"] == pytest.approx(
        plain["viscous_torque_peak_Nm"] + b["torque_peak_Nm"], rel=JSON_REL)
    assert d["cycle_energy_J"] == pytest.approx(300.0 * d["total_mean_power_W"], rel=JSON_REL)
    if thermal == "none":
        assert d["isothermal_total_mean_power_W"] == d["total_mean_power_W"]
    # no bearings key without a bearing (the document of before)
    assert "bearings" not in plain


@pytest.mark.parametrize("mode", ["bulk", "full"])  # bulk: the default with [thermal]
def test_balance_includes_the_bearing_heat(capsys, cases, mode):
    asked = [] if mode == "bulk" else ["--thermal", mode]
    d = evaluate_json(capsys, cases["hot"], *asked)
    assert d["thermal_mode"] == mode
    case = read_case_toml(cases["hot"])
    t = d["oil_temp_C"]
    nu, _, _ = oil_state(case, t, d["depth_m"])
    nodes, weights = case.duty_cycle.speed_distribution()
    p_bearing = float(bearing_mean_power(case.bearing, nodes, weights, nu))
    p_regions = sum(r["mean_power_W"] for r in d["regions"])
    assert d["bearings"][0]["mean_power_W"] == pytest.approx(p_bearing, rel=JSON_REL)
    assert t - 2.0 - 0.5 * (p_regions + p_bearing + 3.0) == pytest.approx(0.0, abs=JSON_ABS)
    # the bearing's heat warms the oil above the balance without it
    without = evaluate_json(capsys, cases["hot_plain"], *asked)
    assert "bearings" not in without and t - without["oil_temp_C"] > 0.1


def test_text_output_has_the_bearing_row_model_and_defaults(capsys, cases):
    code, out, err = run(capsys, ["evaluate", cases["skf"], "--thermal", "none"])
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert any(re.match(r"^rolling brg 61809 \(deep-groove-ball, d_m = 51.5 mm\): SKF", x)
               for x in lines)
    head = next(i for i, x in enumerate(lines) if x.startswith("rolling bearing model"))
    row = lines[head + 1].split()
    assert row[:2] == ["61809", "skf"]
    assert head > next(i for i, x in enumerate(lines) if x.startswith("rotor-stator"))
    regions = [float(x.split()[8]) for x in lines if x.startswith(("rotor-stator", "bearing  "))
               and len(x.split()) > 9]
    total = float(re.search(r"total mean power\s+([\d.]+) W", out).group(1))
    assert total == pytest.approx(sum(regions) + float(row[2]), abs=2e-3)
    assert "rolling bearing 61809" in out and "kappa = nu/nu_1" in out
    assert "outside_mm = 58.0 (catalogue 61809)" in out
    assert re.search(r"balls = 24 \(estimate", out)


def test_without_bearing_the_text_is_unchanged(capsys, cases):
    code, out, _ = run(capsys, ["evaluate", cases["plain"], "--thermal", "none"])
    assert code == 0
    assert "total mean viscous power" in out and "rolling bearing" not in out
    assert not any(x.startswith("rolling brg") for x in out.splitlines())


@pytest.mark.parametrize("table,needle", [
    ('designation = "6809"\nbore_diameter_mm = 45\n', "bore_diameter_mm = 45"),
    ('designation = "6809"\nmodel = "timken"\n', "model = 'timken'"),
    ('designation = "6809"\nradial_load_N = -5.0\n', "radial_load_N = -5.0"),
    ('designation = "6809"\nballs = 2.5\n', "balls = 2.5"),
    ('designation = "6809-2RS"\n', "seal"),
    ('designation = "abc"\n', "designation = 'abc'"),
    ('bore_mm = 45.0\n', "outside_mm"),
])
def test_bad_bearing_tables_exit_2_with_one_line(capsys, seed_toml, write_file, table,
                                                  needle):
    path = write_file(seed_toml + "[bearing]\n" + table, "bad.toml")
    code, out, err = run(capsys, ["evaluate", str(path)])
    assert code == 2 and out == ""
    assert needle in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def _spheres_hand_W(omega, nu, rho, z=24, dw=3.96875e-3, dm=51.5e-3):
    """24 balls as spheres in still oil at the cage's pitch speed, Schiller-Naumann [W]."""
    u = omega / 2 * (1 - dw / dm) * dm / 2
    re_ = u * dw / nu
    return z * 0.5 * rho * 24 / re_ * (1 + 0.15 * re_**0.687) * math.pi / 4 * dw**2 * u**3


@pytest.mark.parametrize("thermal", ["none", "film"])
def test_json_band_of_bearing_models_beside_the_chosen(capsys, cases, thermal):
    d = evaluate_json(capsys, cases["skf"], "--thermal", thermal)
    palm = evaluate_json(capsys, cases["palmgren"], "--thermal", thermal)
    (b,) = d["bearings"]
    band = b["model_band_W"]
    assert band["chosen"] == "skf, drag skf-vm-term"
    assert band["chosen_W"] == pytest.approx(b["mean_power_W"], rel=JSON_REL)
    members = band["members_W"]
    # the chosen model is a member; Palmgren at f0 4 is the palmgren case's own row
    assert members["skf_vm_term"] == pytest.approx(b["mean_power_W"], rel=JSON_REL)
    assert members["palmgren_f0_4"] == pytest.approx(palm["bearings"][0]["mean_power_W"],
                                                     rel=JSON_REL)
    assert members["palmgren_f0_2"] == pytest.approx(  # M_0 linear in f0, M_1 ~ 0.02 W
        0.5 * members["palmgren_f0_4"], abs=0.02)
    case = read_case_toml(cases["skf"])
    nu, _, rho = oil_state(case, d["oil_temp_C"], d["depth_m"])
    nodes, weights = case.duty_cycle.speed_distribution()
    full = bearing_mean_power(replace(case.bearing, drag="skf-full"), nodes, weights, nu)
    assert members["skf_full"] == pytest.approx(float(full), rel=JSON_REL)
    spheres = sum(w * _spheres_hand_W(x, nu, rho) for x, w in zip(nodes, weights, strict=True)
                  if x > 0)
    assert band["parts_W"]["drag_spheres_still_oil"] == pytest.approx(spheres, rel=JSON_REL)
    assert band["parts_W"]["drag_vm_term"] == pytest.approx(b["terms_W"]["drag_vm"],
                                                            rel=JSON_REL)
    assert band["min_W"] == pytest.approx(min(members.values()), rel=JSON_REL)
    assert band["max_W"] == pytest.approx(max(members.values()), rel=JSON_REL)


def test_text_shows_the_band_line(capsys, cases):
    d = evaluate_json(capsys, cases["skf"], "--thermal", "none")
    band = d["bearings"][0]["model_band_W"]
    code, out, err = run(capsys, ["evaluate", cases["skf"], "--thermal", "none"])
    assert code == 0 and err == ""
    line = next(x for x in out.splitlines() if x.startswith("  bearing models "))
    lo, hi, chosen = re.match(r"  bearing models ([\d.]+)-([\d.]+) W at this oil beside the "
                              r"chosen ([\d.]+) W \(skf, drag skf-vm-term\); see "
                              r"docs/bearing.md#the-bearing-model-band$", line).groups()
    assert (float(lo), float(hi), float(chosen)) == pytest.approx(
        (band["min_W"], band["max_W"], band["chosen_W"]), rel=5e-3)  # 3 digits
    assert "SKF full drag" in out and "Palmgren f0 2" in out and "still oil" in out
    _, plain, _ = run(capsys, ["evaluate", cases["plain"], "--thermal", "none"])
    assert "bearing models" not in plain


def test_a_saved_case_with_a_former_drag_name_reads_with_a_warning(capsys, cases, seed_toml,
                                                                   write_file):
    old = str(write_file(seed_toml + '[bearing]\ndesignation = "6809"\ndrag = "vm"\n',
                         "old.toml"))
    code, out, err = run(capsys, ["evaluate", old, "--thermal", "none", "--json"])
    assert code == 0 and "drag = 'vm' is deprecated" in err and "skf-vm-term" in err
    new = evaluate_json(capsys, cases["skf"], "--thermal", "none")
    assert json.loads(out)["total_mean_power_W"] == new["total_mean_power_W"]
