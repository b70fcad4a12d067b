"""``oilgap optimize --robust`` and ``og.optimize(robust=...)``: small-N smoke runs, the
report's numbers against a recomputation here, the written case, bad input (exit 2, one
line)."""

import json

import numpy as np
import pytest

import oilgap as og
from oilgap.cli import main
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml


def test_cli_json_report(capsys, tmp_path):
    out = tmp_path / "robust.toml"
    fig = tmp_path / "robust.png"
    argv = ["optimize", "--robust", "mean", "--scenarios", "8", "--starts", "1", "--temp-c",
            "20", "--pareto", "3", "--json", "--out", str(out), "--figure", str(fig)]
    assert main(argv) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["statistic"] == "mean" and d["scenarios"] == 8 and d["seed"] == 0
    assert d["uncertainty"]["source"].startswith("defaults")
    assert {x["field"] for x in d["defaults"]} >= {"seed", "uncertainty.nu40_factor",
                                                   "uncertainty.gamma"}
    assert d["price_of_robustness_W"] == pytest.approx(
        d["robust"]["nominal_loss_W"] - d["nominal"]["nominal_loss_W"], abs=1e-5)
    assert d["p95_gain_W"] == pytest.approx(
        d["nominal"]["mc"]["p95_W"] - d["robust"]["mc"]["p95_W"], abs=1e-5)
    assert d["stability"]["scenarios"] == 16
    assert len(d["pareto"]) >= 1 and fig.stat().st_size > 0
    # the written case is the robust design (radii written to 0.1 um); oilgap evaluate
    # gives its nominal loss
    case = read_case_toml(out)
    assert case.region1.gap * 1e3 == pytest.approx(d["robust"]["delta_mm"], abs=2e-4)
    ev = evaluate_case(case, thermal="none")
    assert ev.total_mean_power_W == pytest.approx(d["robust"]["nominal_loss_W"], rel=5e-4)


def test_cli_text_names_defaults_and_stability(capsys):
    assert main(["optimize", "--robust", "p95", "--scenarios", "8", "--starts", "1"]) == 0
    text = capsys.readouterr().out
    head = text.splitlines()[:5]  # the answer first (issue 26): p95 gain, price, design
    assert head[0].startswith("p95 gain ") and any(x.startswith("price of robustness") for x
                                                     in head)
    for s in ("N = 8, Sobol' seed 0 (default)", "uncertainty from: defaults", "nu40_factor",
              "price of robustness", "p95 gain", "stability            2N = 16", "CVaR",
              "same design"):  # the seed's vertex optimum: documented in optimizer.md
        assert s in text


def test_facade_frame_and_plot():
    import matplotlib
    matplotlib.use("Agg")
    r = og.optimize(robust="p95", scenarios=8, seed=3, starts=1)
    f = r.to_frame()
    assert list(f.index) == ["nominal", "robust"]
    assert {"delta_mm", "loss_at_nominal_W", "mc_p95_W"} <= set(f.columns)
    lo = r.raw.mc_losses_W["robust"]
    assert f.loc["robust", "mc_p95_W"] == pytest.approx(np.percentile(lo, 95))
    assert r.raw.settings.seed == 3 and r.plot() is not None
    assert "seed" not in {x["field"] for x in r.defaults}


@pytest.mark.parametrize("argv, field", [
    (["--robust", "p99"], "robust"),
    (["--robust", "p95", "--scenarios", "4"], "scenarios"),
    (["--robust", "p95", "--scenarios", "100000"], "scenarios"),
    (["--robust", "p95", "--scenarios", "8.5"], "--scenarios"),
    (["--scenarios", "16"], "--scenarios"),
    (["--robust", "p95", "--thermal", "film"], "--robust"),
    (["--robust", "mean", "--pareto", "2"], "pareto"),
    (["--robust", "mean", "--seed", "-1"], "seed"),
])
def test_bad_input_exits_2_with_one_line(capsys, argv, field):
    assert main(["optimize", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and field in err
