"""The lead-loss front of a linear actuator (issue 29): each feasible lead's loss is the
evaluation of its optimum, no feasible lead beats the free-lead optimum, a lead too long
for the rod force is a row marked infeasible; the files are written."""

from pathlib import Path

import pytest

import oilgap as og
from oilgap.optim.design.linear import solve_linear_design
from oilgap.studies.linear_lead import OUTPUTS, lead_front, write_lead_front

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "linear_joint.toml"


def test_lead_front(tmp_path):
    case = og.read_case(EXAMPLE)
    df = lead_front(case, points=3, mode="none")  # 2.5, 5, 10 mm
    # at 10 mm even the smallest motor gap (0.25 mm, the most torque) gives under 800 N
    assert list(df["status"]) == ["ok", "ok", "infeasible"]
    best = og.evaluate(case, thermal="none").raw  # the free optimum, evaluated
    free = solve_linear_design(case, "none")
    ok = df[df["status"] == "ok"]
    assert (ok["mean_power_W"] > free.mean_power_W * 0.99).all()
    parts = ok[["motor_gap_W", "motor_bearing_W", "screw_W", "rod_guide_W", "passages_W"]]
    assert parts.sum(axis=1).to_numpy() == pytest.approx(ok["mean_power_W"].to_numpy())
    assert best.total_mean_power_W > ok["mean_power_W"].min()
    paths = write_lead_front(df, tmp_path, case.name)
    assert sorted(p.name for p in paths) == sorted(OUTPUTS)
