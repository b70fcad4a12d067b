"""The worked example of robust design (issue 21's Done-when): ``oilgap optimize
examples/warm_oil_robust.toml --robust p95`` returns a design whose p95 loss is below the
nominal optimum's, checked here on a Monte Carlo the command never saw.

The check does not reuse the command's sample or its Monte Carlo: 8192 plain
pseudo-random draws (numpy's PCG64, seed 2026, not Sobol' points) of the laws written out
below from the example's ``[uncertainty]`` table, each design's loss through the
vectorised joint loss (``joint_loss_arrays``, the case's exact C_m; equal to the scalar
``oilgap evaluate`` path, tests/model/test_uncertain_arrays.py), and the noise of the p95
difference estimated by a paired bootstrap over the draws. The margin asked is four
bootstrap standard deviations (measured: gain ~0.5 W, sd ~0.04 W; docs/uncertainty.md).
"""

import json
from pathlib import Path

import numpy as np
import pytest

from oilgap.cli import main
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml
from oilgap.model.uncertain import apply_inputs
from oilgap.model.uncertain.arrays import joint_loss_arrays
from oilgap.optim.design import DesignProblem
from oilgap.optim.design.scenarios import design_case

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "warm_oil_robust.toml"
KEYS = ("R_mm", "delta_mm", "rotor_groove_depth_mm", "stator_groove_depth_mm", "L_mm")


def independent_draws(n: int, seed: int) -> dict:
    """The example's laws, written out by hand (not read from its table)."""
    rng = np.random.default_rng(seed)
    return {"nu40_factor": rng.uniform(0.9, 1.1, n),         # ISO 3448 +-10 %
            "gamma": rng.normal(0.566, 0.041, n),            # the seed rig fit
            "oil_temp_C": rng.normal(12.0, 4.0, n),          # 12 degC +- 4 K
            "peak_speed_rpm": rng.normal(3000.0, 150.0, n)}  # +-5 %


@pytest.fixture(scope="module")
def report():
    import contextlib
    import io
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        code = main(["optimize", str(EXAMPLE), "--robust", "p95", "--scenarios", "32",
                     "--starts", "1", "--json"])
    assert code == 0
    return json.loads(buf.getvalue())


def test_robust_p95_beats_nominal_on_an_independent_monte_carlo(report):
    case = read_case_toml(EXAMPLE)
    prob = DesignProblem(case)
    machined = (prob.machined_rotor_groove_m, prob.machined_stator_groove_m)
    draws = independent_draws(8192, 2026)
    loss = {}
    for k in ("nominal", "robust"):
        x_m = np.array([report[k][key] for key in KEYS]) * 1e-3
        dc = design_case(case, x_m, machined)
        loss[k] = np.asarray(joint_loss_arrays(dc, draws, mode="none", strict=True))
        for i in (0, 1):  # the scalar path (oilgap evaluate of the scenario's case) agrees
            ci = apply_inputs(dc, {n: float(v[i]) for n, v in draws.items()})
            ref = evaluate_case(ci, thermal="none").total_mean_power_W
            assert loss[k][i] == pytest.approx(ref, rel=1e-9)
    gain = np.percentile(loss["nominal"], 95) - np.percentile(loss["robust"], 95)
    rng = np.random.default_rng(7)
    idx = rng.integers(0, loss["nominal"].size, (200, loss["nominal"].size))
    boot = np.percentile(loss["nominal"][idx], 95, axis=1) - np.percentile(
        loss["robust"][idx], 95, axis=1)
    noise = float(np.std(boot))
    assert gain > 4.0 * noise, (gain, noise)
    # the command's own Monte Carlo (Sobol', another seed) agrees within the noise
    assert report["p95_gain_W"] == pytest.approx(gain, abs=4.0 * noise)
    # what robustness costs: a little more loss at the nominal inputs, a wider gap
    assert report["price_of_robustness_W"] > 0
    assert report["robust"]["delta_mm"] > report["nominal"]["delta_mm"]
    assert np.median(loss["robust"]) > np.median(loss["nominal"])
