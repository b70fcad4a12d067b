"""``oilgap optimize``: output against the API, --out round trip, exit codes 2/3/4."""

import json
import subprocess
import sys

import pytest

import oilgap.optim.design.variables as dv
from oilgap.cli import main
from oilgap.model.io.case_io import seed_case
from oilgap.optim.design import DesignProblem

POINT_KEYS = {"mean_power_W", "T", "delta_mm", "R_mm", "L_mm", "T1_mm", "T2_mm", "T3_mm",
              "T4_mm", "torque_capability_Nm", "inertia_kgm2"}

JSON_REL = 1e-5  # JSON numbers carry 6 significant digits (oilgap.model.io.serialize)
JSON_ABS = 1e-4  # [K] or [W]: a temperature or power rounded to 6 digits


@pytest.fixture(scope="module")
def api_result():
    return DesignProblem(seed_case()).solve()


def run_json(capsys, *argv):
    assert main(["optimize", "--json", *argv]) == 0
    return json.loads(capsys.readouterr().out)


def test_json_has_the_issue_keys_and_the_api_numbers(capsys, api_result):
    d = run_json(capsys, "--thermal", "none")
    assert {"status", "initial", "optimal", "active_constraints", "multipliers"} <= set(d)
    for k in ("initial", "optimal"):
        assert POINT_KEYS <= set(d[k])
    assert d["status"] == "Solve_Succeeded"
    o = api_result.optimal
    assert d["optimal"]["mean_power_W"] == pytest.approx(o.mean_power_W, rel=JSON_REL)
    assert d["optimal"]["delta_mm"] == pytest.approx(o.delta_m * 1e3, rel=JSON_REL)
    # lengths in mm are the SI values times 1000, T is (T4 - T1)/(T3 - T2)
    oo = d["optimal"]
    assert oo["T"] == pytest.approx((oo["T4_mm"] - oo["T1_mm"]) / (oo["T3_mm"] - oo["T2_mm"]))
    assert d["initial"]["T1_mm"] == pytest.approx(23.9) and d["initial"]["T"] == pytest.approx(4)
    tq = d["multipliers"]["torque_min"]
    assert tq["unit"] == "W per N m" and tq["active"] and tq["value"] > 0
    assert d["multipliers"]["inertia_max"]["unit"] == "W per % of the reference inertia"
    assert set(d["active_constraints"]) == set(api_result.active_constraints)


def test_table_shows_both_designs_and_costs(capsys, api_result):
    assert main(["optimize", "--starts", "1", "--thermal", "none"]) == 0
    out = capsys.readouterr().out
    for needle in ("initial", "optimal", "delta_mm", "T4_mm", "region2_power_W",
                   "torque_capability_Nm", "inertia_kgm2", "active constraints",
                   "W per N m", "W per mm"):
        assert needle in out
    line = next(s for s in out.splitlines() if s.startswith("mean_power_W "))
    assert float(line.split()[2]) == pytest.approx(api_result.optimal.mean_power_W, abs=1e-4)


def test_out_is_a_case_that_evaluate_accepts(tmp_path, capsys):
    path = tmp_path / "opt.toml"
    d = run_json(capsys, "--out", str(path))
    assert path.is_file() and d["out"] == str(path)
    assert main(["evaluate", str(path), "--json"]) == 0
    ev = json.loads(capsys.readouterr().out)
    # the case file and the JSON carry 6 significant digits (radii to 0.1 um): the gap
    # T3 - T2 of the file is within 1e-4 mm of the optimum's, the loss within 1e-4
    assert ev["total_mean_power_W"] == pytest.approx(d["optimal"]["mean_power_exact_W"],
                                                     rel=1e-4)
    r1 = ev["regions"][0]
    assert r1["gap_mm"] == pytest.approx(d["optimal"]["delta_mm"], abs=1e-4)
    assert r1["roughness_T"] == pytest.approx(d["optimal"]["T"], rel=1e-4)


def test_overrides_reach_the_problem(capsys):
    d = run_json(capsys, "--oil", "VG46", "--temp-c", "10", "--depth-m", "500",
                 "--torque-min-nm", "0.45", "--inertia-max-ratio", "1.1", "--starts", "1")
    p = d["parameters"]
    assert p["oil"] == "VG46" and p["oil_temp_C"] == 10 and p["depth_m"] == 500
    assert p["torque_min_Nm"] == 0.45 and p["inertia_max_ratio"] == pytest.approx(1.1)
    assert d["optimal"]["torque_capability_Nm"] >= 0.45 * (1 - 1e-7)


def test_infeasible_exits_3_with_one_line(capsys):
    assert main(["optimize", "--torque-min-nm", "5"]) == 3
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "torque >= 5 N m" in err[0] and "delta_min" in err[0]


def test_solver_failure_exits_4(capsys, monkeypatch):
    monkeypatch.setitem(dv.SOLVER_OPTIONS, "ipopt.max_iter", 2)
    assert main(["optimize", "--starts", "1"]) == 4
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "Maximum_Iterations_Exceeded" in err[0]
    assert "last iterate" in err[0]


@pytest.mark.parametrize("argv, needle", [
    (["missing.toml"], "case"),
    (["--oil", "VG7"], "VG7"),
    (["--oils", "nope.csv", "--oil", "x"], "nope.csv"),
    (["--temp-c", "warm"], "--temp-c"),
    (["--temp-c", "400"], "oil_temp_C"),
    (["--depth-m", "nan"], "--depth-m"),
    (["--depth-m", "-5"], "depth_m"),
    (["--torque-min-nm", "-1"], "--torque-min-nm"),
    (["--torque-min-nm", "inf"], "--torque-min-nm"),
    (["--inertia-max-ratio", "0"], "--inertia-max-ratio"),
    (["--starts", "0"], "--starts"),
    (["--starts", "two"], "--starts"),
])
def test_bad_input_exits_2_with_one_line(capsys, argv, needle):
    assert main(["optimize", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and needle in err[0]


def test_bad_out_path_exits_2(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert main(["optimize", "--starts", "1", "--out", str(blocker / "opt.toml")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--out" in err[0]


def test_bad_case_bounds_exit_2(tmp_path, capsys):
    """radius_min 11 mm leaves the 1.5 mm deep rotor grooves inside the 10 mm shaft bore."""
    from oilgap.model.io.case_write import case_to_dict, dumps_toml

    doc = case_to_dict(seed_case())
    doc["bounds"]["radius_min_mm"] = 11.0
    p = tmp_path / "bad.toml"
    p.write_text(dumps_toml(doc))
    assert main(["optimize", str(p)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "radius_min_mm" in err[0]


def test_subprocess_infeasible_no_traceback():
    r = subprocess.run([sys.executable, "-m", "oilgap.cli", "optimize",
                        "--torque-min-nm", "5"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 3
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1
