"""Pareto study: the fronts'
optimality properties (constraints hold, nested feasible sets give a monotone
front, the seeds are feasible hence dominated), warm-started points against cold
solves, the numpy problem against the NLP, bad input."""

import json

import numpy as np
import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.errors import InfeasibleError, InputError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.units import MM_TO_M
from oilgap.optim.design import DesignProblem
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.pareto import (
    draw_gap_front,
    gap_front,
    gap_problem_numpy,
    hypervolume_2d,
    inertia_front,
    min_feasible_inertia_ratio,
    run,
    seed_points,
)
from oilgap.studies.reporting import new_figure
from oilgap.studies.settings import INLINE, ParetoSettings, SweepSettings


@pytest.fixture(scope="module")
def fronts():
    case = seed_case()
    return case, gap_front(case, 50), inertia_front(case, 50), seed_points()


def test_gap_front_points_are_feasible_and_monotone(fronts):
    case, g, _, _ = fronts
    assert len(g) == 50 and (g["status"] == "ok").all()
    assert (g["delta_mm"] <= g["epsilon"] * (1 + 1e-9)).all()
    assert (g["torque_capability_Nm"] >= g["torque_min_Nm_used"] * (1 - 1e-6)).all()
    assert (g["inertia_kgm2"] <= g["inertia_max_kgm2_used"] * (1 + 1e-6)).all()
    # eps falls along the sweep: nested feasible sets, the optimum can only get worse
    assert (np.diff(g["mean_power_W"].to_numpy()) >= -1e-9).all()
    assert g["epsilon"].min() == pytest.approx(case.bounds.gap_min / MM_TO_M)


def test_seed_designs_are_feasible_so_the_front_dominates_them(fronts):
    _, g, _, seeds = fronts
    at = g[g["epsilon"] >= 1.0 - 1e-12]  # the seed's gap is 1 mm: it is feasible there
    for _, s in seeds.iterrows():
        assert s["inertia_ratio"] <= 1.05 and s["delta_mm"] == pytest.approx(1.0)
        assert (at["mean_power_W"] <= s["mean_power_W"] + 1e-9).all()


def test_warm_started_points_match_cold_solves(fronts):
    case, g, _, _ = fronts
    prob = DesignProblem(case)
    for k in (5, 25, 45):
        cold = prob.solve(gap_max_m=g["epsilon"].iloc[k] * MM_TO_M)
        assert g["mean_power_W"].iloc[k] == pytest.approx(cold.optimal.mean_power_W,
                                                          rel=1e-6)


def test_inertia_front(fronts):
    case, _, i, _ = fronts
    assert len(i) == 50 and (i["status"] == "ok").all()
    assert (i["inertia_ratio"] <= i["epsilon"] * (1 + 1e-6)).all()
    assert (np.diff(i["mean_power_W"].to_numpy()) >= -1e-9).all()


def test_min_feasible_inertia_ratio_is_the_boundary():
    case = seed_case()
    r = min_feasible_inertia_ratio(case)
    prob = DesignProblem(case)
    with pytest.raises(InfeasibleError):
        prob.solve(inertia_max_ratio=r * (1 - 1e-3))
    assert prob.solve(inertia_max_ratio=r * (1 + 1e-3)).success


def test_numpy_problem_matches_the_nlp(fronts):
    case, g, _, _ = fronts
    lo, hi, evaluate = gap_problem_numpy(case)
    row = g.iloc[10]
    x = np.array([row["R_mm"], row["delta_mm"], row["R_mm"] - row["T1_mm"],
                  row["T4_mm"] - row["T3_mm"], row["L_mm"]]) * MM_TO_M
    F, G = evaluate(x[None, :])
    assert F[0, 0] == pytest.approx(row["delta_mm"], rel=1e-12)
    assert F[0, 1] == pytest.approx(row["mean_power_W"], rel=1e-9)
    assert (G <= 1e-6).all()
    assert (x >= lo - 1e-12).all() and (x <= hi + 1e-12).all()


def test_infeasible_points_are_rows_with_their_error():
    res = run_grid(pd.DataFrame({"inertia_max_ratio": [1.05, 0.2]}), None,
                   SweepSettings(mode="optimize"), INLINE)
    assert list(res["status"]) == ["ok", "error"]
    assert "InfeasibleError" in res["error"].iloc[1]


def test_too_few_points_refused():
    with pytest.raises(InputError):
        gap_front(seed_case(), 10)


def test_outputs_written(tmp_path):
    r = run(tmp_path, settings=ParetoSettings(points=50))
    for f in ("pareto_gap.csv", "pareto_inertia.csv", "pareto_gap.png", "pareto_inertia.png",
              "summary.md"):
        assert (tmp_path / f).stat().st_size > 0
    ok = r.gap_front[r.gap_front["status"] == "ok"]
    assert r.hypervolume == pytest.approx(
        hypervolume_2d(ok[["delta_mm", "mean_power_W"]].to_numpy(), r.reference_point))


def test_pareto_takes_the_thermal_modes(tmp_path, capsys):
    """``study pareto --thermal``: the fronts and the marked designs under the mode asked
    (here film on the seed), named in the header, the summary, both figure titles and
    provenance.json; a balance mode without [thermal] exits 2."""
    out = tmp_path / "film"
    assert main(["study", "pareto", "--points", "50", "--thermal", "film", "--out", str(out),
                 "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["thermal_mode"] == "film" and doc["thermal_default"] is False
    seed = next(d for d in doc["designs"] if d["design"] == "seed (T = 4)")
    # the marked seed: film-heated at 2 degC as `oilgap evaluate --thermal film`, and its
    # band the default's isothermal number
    film = evaluate_case(seed_case(), thermal="film")
    assert seed["mean_power_exact_W"] == pytest.approx(film.total_mean_power_W, rel=1e-5)
    assert seed["film_band_mode"] == "none"
    assert seed["film_band_power_W"] == pytest.approx(
        evaluate_case(seed_case(), thermal="none").total_mean_power_W, rel=1e-5)
    # the front is the film NLP's: its optimum is film's (below the isothermal 19.52 W)
    ok = [r for r in doc["gap_front"] if r["status"] == "ok"]
    assert all(r["thermal_mode"] == "film" for r in ok)
    assert min(r["mean_power_W"] for r in ok) < 19.0
    md = (out / "summary.md").read_text()
    assert "Thermal mode: film (" in md and "Film band of seed (T = 4)" in md
    prov = json.loads((out / "provenance.json").read_text())
    assert (prov["thermal_mode"], prov["thermal_mode_default"]) == ("film", False)
    r = run(None, settings=ParetoSettings(points=50, thermal="film"))
    fig, ax = new_figure(7.8, 5.0)
    draw_gap_front(r, ax)
    assert ax.get_title().endswith("thermal film)")
    assert main(["study", "pareto", "--points", "50", "--thermal", "bulk", "--out",
                 str(tmp_path / "bulk")]) == 2
    assert "[thermal]" in capsys.readouterr().err
