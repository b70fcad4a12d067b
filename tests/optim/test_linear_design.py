"""The linear actuator's design NLP (issue 29): the optimum meets the force, speed,
passage-velocity and compensator constraints, beats every feasible design of a random
sample evaluated by the evaluation path, and the CLI refuses a dashpot (exit 2) and a
compensator too small (exit 3) with one line."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

import oilgap as og
from oilgap.cli import main
from oilgap.model.linear.laws import rod_force_capability
from oilgap.model.motor import motor_torque
from oilgap.optim.design.linear import (
    linear_bounds,
    linear_design_case,
    solve_linear_design,
)

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "linear_joint.toml"


@pytest.fixture(scope="module")
def case():
    return og.read_case(EXAMPLE)


@pytest.fixture(scope="module")
def optimum(case):
    return solve_linear_design(case, "none")


def _feasible(case, x_mm):
    d, r1 = case.linear, case.region1
    lead, _, dp, delta = (v * 1e-3 for v in x_mm[:4])
    force = rod_force_capability(motor_torque(case.motor, r1.T2, delta, r1.length)[0], lead,
                                 d.screw_efficiency)
    v_max = case.duty_cycle.peak_omega_rad_s * d.lead_m / (2 * math.pi)
    vel = d.rod_area_m2 * v_max / (d.passage_count * math.pi * dp**2 / 4)
    speed = 2 * math.pi * v_max / lead
    return (force >= d.required_force_N * (1 - 1e-6) and speed <= d.max_motor_speed_rad_s
            and vel <= d.passage_velocity_limit_m_s)


def test_the_optimum_meets_every_constraint(case, optimum):
    assert _feasible(case, optimum.x_mm)
    f = optimum.constraints["rod force"]
    assert f[0] >= f[1] * (1 - 1e-6)
    comp = optimum.constraints["compensator volume"]
    # displaced volume pi (10 mm)^2 100 mm = 31.4 mL plus the oil's expansion
    assert comp[0] > math.pi * 0.01**2 * 0.1 and comp[0] <= comp[1]


def test_the_optimum_beats_a_random_feasible_sample(case, optimum):
    lo, hi = linear_bounds(case)
    rng = np.random.default_rng(29)
    best = og.evaluate(linear_design_case(case, optimum.x_mm), thermal="none").raw
    tried = 0
    for x in lo + rng.random((400, 6)) * (hi - lo):
        if not _feasible(case, x):
            continue
        tried += 1
        ev = og.evaluate(linear_design_case(case, x), thermal="none").raw
        assert ev.total_mean_power_W >= best.total_mean_power_W * (1 - 1e-3)
    assert tried >= 5
    given = og.evaluate(case, thermal="none").raw
    assert best.total_mean_power_W < given.total_mean_power_W


def test_the_lead_trades_motor_speed_against_force(case, optimum):
    # the force constraint is active: 2 pi eta T(delta)/lead = F_req at the optimum
    r1 = case.region1
    lead, delta = optimum.x_mm[0] * 1e-3, optimum.x_mm[3] * 1e-3
    tau = motor_torque(case.motor, r1.T2, delta, r1.length)[0]
    assert 2 * math.pi * 0.9 * tau / lead == pytest.approx(800.0, rel=1e-5)


def test_cli_json_and_facade(capsys):
    assert main(["optimize", str(EXAMPLE), "--thermal", "none", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    res = og.optimize(str(EXAMPLE), thermal="none")
    assert d["loss_by_element_W"]["optimum"]["total"] == pytest.approx(
        res.optimum.total_mean_power_W, rel=1e-5)


def _variant(tmp_path, old, new):
    p = tmp_path / "v.toml"
    p.write_text(EXAMPLE.read_text().replace(old, new))
    return str(p)


def test_cli_refuses_a_dashpot_and_a_small_compensator(capsys, tmp_path):
    assert main(["optimize", _variant(tmp_path, "count = 1", "count = 0")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "dashpot" in err[0] and " N at " in err[0]
    assert main(["optimize", _variant(tmp_path, "capacity_mL = 60.0", "capacity_mL = 20.0")]) == 3
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "compensator" in err[0]


@pytest.mark.parametrize("mode", ["none", "bulk"])
def test_robust_p95_runs_and_keeps_the_constraints(case, optimum, mode):
    from oilgap.optim.design.linear_robust import solve_linear_robust
    r = solve_linear_robust(case, "p95", scenarios=4, seed=1, mode=mode)
    assert _feasible(case, r.robust.x_mm)
    if mode == "none":
        assert np.array_equal(r.nominal.x_mm, optimum.x_mm)
    # the CVaR surrogate's optimum is no worse at p95 than the nominal optimum
    assert len(r.losses_W["robust"]) == 4
    assert np.percentile(r.losses_W["robust"], 95) <= np.percentile(
        r.losses_W["nominal"], 95) * (1 + 1e-6)


@pytest.mark.parametrize("mode", ["bulk", "full"])
def test_the_balance_modes_solve_the_balance_in_the_nlp(case, mode):
    d = solve_linear_design(case, mode)
    ev = og.evaluate(linear_design_case(case, d.x_mm), thermal=mode).raw
    # the NLP's oil temperature is the design's balance (the smooth C_m beside the exact)
    assert d.oil_temp_C == pytest.approx(ev.oil_temp_C, abs=0.02)
    assert d.mean_power_W == pytest.approx(ev.total_mean_power_W, rel=5e-3)
