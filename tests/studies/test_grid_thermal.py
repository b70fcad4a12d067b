"""The grid engine under the thermal modes: a row under film/full against the model's own
single-case path (model.joint_loss) and against the heat balance written out by hand with
P recomputed region by region; none = the isothermal model exactly; the columns each mode
refuses; the sweep command names the mode and keeps one store per mode."""

import json
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InputError
from oilgap.model.evaluation import evaluate_case, mean_viscous_power
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import case_film, joint_mean_power, operating_temperature
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.oils import get_oil
from oilgap.model.regions import joint_regions, region_mean_power
from oilgap.model.units import celsius_to_kelvin
from oilgap.studies.grid import runner
from oilgap.studies.grid.evaluate import evaluate_cases
from oilgap.studies.grid.schema import apply_params, read_grid_csv
from oilgap.studies.io.case_write import write_case_toml
from oilgap.studies.settings import SweepSettings, split_keywords


def run_grid(grid, case=None, *, out_dir=None, catalogue=None, label="sweep", on_chunk=None,
             **keywords):
    """The engine from keywords, as the façade builds its records."""
    return runner.run_grid(grid, case, *split_keywords(keywords, SweepSettings),
                           out_dir=out_dir, catalogue=catalogue, label=label,
                           on_chunk=on_chunk)

SEA, R, C, Q = 2.0, 0.5, 5e4, 3.0


def thermal_case(other_heat_W=Q):
    return replace(seed_case(), thermal=ThermalSpec(SEA, R, C, other_heat_W))


def film_power_by_hand(case, temp_C, depth_m):
    """P(T) [W] composed region by region from region_mean_power with the film factor
    (not through joint_mean_power): nu, rho and b = -d ln mu/dT from the oil's law."""
    p = seawater_gauge_pressure(depth_m)
    t_k = celsius_to_kelvin(temp_C)
    nu, _, rho = case.oil.properties(t_k, p)
    b = case.oil.temperature_slope(t_k, p)
    nodes, weights = case.duty_cycle.speed_distribution()
    return sum(float(region_mean_power(r, nodes, weights, nu, rho, case.friction,
                                       case_film(case), b)) for r in joint_regions(case))


ROWS = [{"oil": "VG22", "depth_m": 3000.0},
        {"oil": "VG46", "depth_m": 1000.0, "sea_temp_C": 10.0},
        {"oil": "VG15", "depth_m": 0.0, "sea_temp_C": 20.0, "T": 2.0}]


def test_full_rows_equal_the_single_case_balance_and_the_hand_balance():
    base = thermal_case()
    res = run_grid(pd.DataFrame(ROWS), base, thermal="full", workers=1)
    assert (res["status"] == "ok").all() and (res["thermal_mode"] == "full").all()
    for row, got in zip(ROWS, res.to_dict("records"), strict=True):
        case = apply_params(base, row)
        ref = operating_temperature(case, "full")
        assert got["oil_temp_op_C"] == pytest.approx(ref.oil_temp_C, abs=1e-8)
        assert got["mean_power_W"] == pytest.approx(ref.mean_power_W, rel=1e-9)
        sea = row.get("sea_temp_C", SEA)
        assert got["sea_temp_C"] == sea
        # the balance written out: T - T_sea - R (P(T) + Q) = 0 with P recomputed
        t = got["oil_temp_op_C"]
        p = film_power_by_hand(case, t, row["depth_m"])
        assert p == pytest.approx(got["mean_power_W"], rel=1e-12)
        assert abs(t - sea - R * (p + Q)) < 1e-8
        assert t > sea + R * Q  # the oil is warmer than the sea by more than Q's share
        # nu at the operating temperature; the isothermal reference at the sea's
        nu = get_oil(row["oil"]).kinematic_viscosity_cSt(t, row["depth_m"])
        assert got["nu_cSt"] == pytest.approx(nu, rel=1e-12)
        assert got["isothermal_power_W"] == pytest.approx(
            mean_viscous_power(case, sea, row["depth_m"]), rel=1e-12)


def test_film_rows_equal_joint_mean_power_and_the_hand_composition():
    rows = pd.DataFrame([{"oil": "VG22", "oil_temp_C": 2.0, "depth_m": 3000.0},
                         {"oil": "VG100", "oil_temp_C": 30.0, "depth_m": 500.0, "gap_mm": 0.7}])
    res = run_grid(rows, seed_case(), thermal="film", workers=1)
    for row, got in zip(rows.to_dict("records"), res.to_dict("records"), strict=True):
        case = apply_params(seed_case(), row)
        ref = float(joint_mean_power(case, row["oil_temp_C"], "film", row["depth_m"]))
        assert got["mean_power_W"] == pytest.approx(ref, rel=1e-12)
        assert got["mean_power_W"] == pytest.approx(
            film_power_by_hand(case, row["oil_temp_C"], row["depth_m"]), rel=1e-12)
        assert got["oil_temp_op_C"] == row["oil_temp_C"] and np.isnan(got["sea_temp_C"])
        assert got["mean_power_W"] < got["isothermal_power_W"]  # the film heats, mu falls


def test_none_is_the_isothermal_model_exactly():
    # the golden sweep grid: the numbers are today's isothermal ones, to the last bit
    rows = pd.DataFrame({"oil": ["VG22", "VG32", "VG15"], "oil_temp_C": [2.0, 10.0, None],
                         "depth_m": [3000.0, 1000.0, None], "gap_mm": [1.0, 0.8, 1.2],
                         "T": [4.0, 2.0, None]})
    res = run_grid(rows, workers=1, thermal="none")
    assert res.attrs["thermal_mode"] == "none" and not res.attrs["thermal_default"]
    default = run_grid(rows, workers=1)  # one default with the CLI: none on the seed joint
    assert default.attrs["thermal_mode"] == "none" and default.attrs["thermal_default"]
    assert default["mean_power_W"].equals(res["mean_power_W"])
    for row, got in zip(rows.to_dict("records"), res.to_dict("records"), strict=True):
        case = apply_params(seed_case(), row)
        assert got["mean_power_W"] == mean_viscous_power(case)
        assert got["mean_power_W"] == evaluate_case(case, thermal="none").total_mean_power_W
        assert got["isothermal_power_W"] == got["mean_power_W"]
    assert res["mean_power_W"].iloc[0] == pytest.approx(49.453, abs=5e-4)  # seed, Sec. IV


def test_default_is_the_one_the_evidence_supports():
    g = pd.DataFrame({"oil": ["VG22"]})
    assert run_grid(g, seed_case(), thermal=None, workers=1).attrs["thermal_mode"] == "none"
    r = run_grid(g, thermal_case(0.0), thermal=None, workers=1)
    assert r.attrs["thermal_mode"] == "bulk" and r.attrs["thermal_default"]
    assert r["oil_temp_op_C"].iloc[0] == pytest.approx(
        operating_temperature(thermal_case(0.0)).oil_temp_C, abs=1e-8)


def test_bulk_rows_balance_the_isothermal_loss():
    # T = T_sea + R (P_none(T) + Q), P_none the row's isothermal loss at its own T
    base = thermal_case()
    res = run_grid(pd.DataFrame({"sea_temp_C": [0.0, 10.0], "oil": ["VG22", "VG68"]}), base,
                   thermal="bulk", workers=1)
    for got in res.to_dict("records"):
        case = apply_params(base, {"sea_temp_C": got["sea_temp_C"], "oil": got["oil"]})
        t = got["oil_temp_op_C"]
        p = mean_viscous_power(case, oil_temp_C=t)
        assert abs(t - got["sea_temp_C"] - R * (p + Q)) < 1e-8
        assert got["mean_power_W"] == pytest.approx(p, rel=1e-10)
        assert got["thermal_mode"] == "bulk"


@pytest.mark.parametrize("grid, case, thermal, field", [
    ({"oil_temp_C": [10.0]}, "thermal", "full", "oil_temp_C"),
    ({"sea_temp_C": [10.0]}, "thermal", "film", "sea_temp_C"),
    ({"resistance_K_per_W": [1.0]}, "thermal", "none", "resistance_K_per_W"),
    ({"oil": ["VG22"]}, "seed", "full", "thermal"),
    ({"oil": ["VG22"]}, "seed", "bulk", "thermal"),
    ({"oil_temp_C": [10.0]}, "thermal", "bulk", "oil_temp_C"),
    ({"oil": ["VG22"]}, "seed", "warm", "thermal"),
])
def test_columns_and_modes_refused(grid, case, thermal, field):
    base = thermal_case() if case == "thermal" else seed_case()
    with pytest.raises(InputError) as e:
        run_grid(pd.DataFrame(grid), base, thermal=thermal, workers=1)
    assert e.value.field == field


def test_bad_sea_temperature_is_a_failed_row():
    res = run_grid(pd.DataFrame({"sea_temp_C": [4.0, 900.0]}), thermal_case(),
                   thermal="full", workers=1)
    assert list(res["status"]) == ["ok", "error"] and "sea_temp_C" in res["error"].iloc[1]


def test_rows_with_another_resistance_balance_with_their_own():
    res = run_grid(pd.DataFrame({"resistance_K_per_W": [0.25, 2.0]}), thermal_case(),
                   thermal="full", workers=1)
    for r_th, got in zip((0.25, 2.0), res.to_dict("records"), strict=True):
        p = film_power_by_hand(seed_case(), got["oil_temp_op_C"], 3000.0)
        assert abs(got["oil_temp_op_C"] - SEA - r_th * (p + Q)) < 1e-8
    assert res["oil_temp_op_C"].iloc[1] > res["oil_temp_op_C"].iloc[0]


def test_cli_sweep_names_the_mode_and_keeps_a_store_per_mode(tmp_path, capsys):
    case = write_case_toml(thermal_case(), tmp_path / "case.toml")
    g = tmp_path / "grid.csv"
    pd.DataFrame({"oil": ["VG22", "VG32"], "sea_temp_C": [2.0, 6.0]}).to_csv(g, index=False)
    out = tmp_path / "out"
    assert main(["study", "sweep", str(g), "--case", str(case), "--out", str(out),
                 "--workers", "1"]) == 0
    text = capsys.readouterr().out
    assert text.startswith("thermal     bulk (default: ")
    assert "film band of the base case: film heating at full strength (full)" in text
    res = read_grid_csv(out / "results.csv")
    assert (res["thermal_mode"] == "bulk").all() and (res["oil_temp_op_C"] > 2.0).all()
    md = (out / "summary.md").read_text()
    assert "Thermal mode: bulk (default" in md and "Film band of the base case" in md
    prov = json.loads((out / "provenance.json").read_text())
    assert (prov["thermal_mode"], prov["thermal_mode_default"]) == ("bulk", True)
    g.write_text("oil\nVG22\nVG32\n")
    for mode in ("film", "none"):
        assert main(["study", "sweep", str(g), "--case", str(case), "--out", str(out),
                     "--workers", "1", "--thermal", mode, "--resume"]) == 0
        assert "(2 computed, 0 reused)" in capsys.readouterr().out
    res = read_grid_csv(out / "results.csv")
    assert (res["thermal_mode"] == "none").all()
    assert res["mean_power_W"].iloc[0] == mean_viscous_power(thermal_case())


def test_vectorised_full_equals_one_by_one():
    base = thermal_case()
    rng = np.random.default_rng(3)
    rows = [{"oil": o, "depth_m": d, "sea_temp_C": s} for o, d, s in
            zip(rng.choice(["VG15", "VG22", "VG68"], 12), rng.uniform(0, 6000, 12),
                rng.uniform(0, 30, 12), strict=True)]
    cases = [apply_params(base, r) for r in rows]
    together = evaluate_cases(cases, "full")
    for i, c in enumerate(cases):
        one = evaluate_cases([c], "full")
        assert together["oil_temp_op_C"].iloc[i] == pytest.approx(
            one["oil_temp_op_C"].iloc[0], abs=1e-8)
