"""The rows' heat balance to the exact root (model/uncertain/balance.py).

What is compared: :func:`root_balance` against the closed-form root of an exponential loss
(Lambert W, written out here), against SciPy's ``brentq`` run row by row on the same
losses to 1e-15 K (a second method), and :func:`joint_loss_arrays` against the scalar
path, whose solver is polished to the root (:func:`~oilgap.model.thermal.polish_roots`):
the two agree to 1e-12 on random rows (10^4 in docs/benchmarks.md). Rows the fast
iteration hands back (a loss that rises, no root below the cap) get the scalar solver's
answer.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.model.errors import SolverError
from oilgap.model.io.case_io import read_case_toml
from oilgap.model.joint_loss import operating_temperature
from oilgap.model.uncertain.arrays import _features, _row_values, joint_loss_arrays
from oilgap.model.uncertain.balance import root_balance
from oilgap.model.uncertain.inputs import apply_inputs
from oilgap.model.uncertain.rows import row_model, row_total

SEED_THERMAL = Path(__file__).resolve().parents[1] / "golden" / "data" / "seed_thermal.toml"


@pytest.fixture(scope="module")
def cases(tmp_path_factory):
    text = SEED_THERMAL.read_text()
    p = tmp_path_factory.mktemp("bal") / "bearing.toml"
    p.write_text(text + '\n[bearing]\ndesignation = "6809"\n')
    return {"seed": read_case_toml(SEED_THERMAL), "bearing": read_case_toml(p)}


def rows_of(n, seed):
    rng = np.random.default_rng(seed)
    return {"nu40_factor": rng.uniform(0.9, 1.1, n), "oil_temp_C": rng.uniform(0, 6, n),
            "depth_m": rng.uniform(2000, 4000, n), "gamma": rng.uniform(0.48, 0.65, n),
            "friction_scale": rng.uniform(0.9, 1.1, n), "film_strength": rng.uniform(0, 1, n),
            "bearing_drag_scale": rng.uniform(0.5, 2.0, n),
            "peak_speed_rpm": rng.uniform(2500, 3500, n)}


def test_exponential_loss_has_its_closed_form_root():
    # P = c exp(-b T): T = T_b + R c exp(-b T) has the root T_b + W(b R c exp(-b T_b))/b
    # (Lambert W); W(x) for x = w exp(w) is taken from w = 1.3, 0.4, 2.0 (no solver here).
    w = np.array([1.3, 0.4, 2.0])
    b, r, tb = np.array([0.05, 0.03, 0.08]), 0.5, np.array([3.0, 5.0, 1.0])
    c = w * np.exp(w) / (b * r) * np.exp(b * tb)  # so that b R c exp(-b T_b) = w e^w
    calls = []

    def power(t, i):
        calls.append(len(t))
        return c[i] * np.exp(-b[i] * t)

    temps, p, ok = root_balance(power, tb, r)
    assert ok.all()
    np.testing.assert_allclose(temps, tb + w / b, rtol=1e-14)
    np.testing.assert_allclose(p, c * np.exp(-b * (tb + w / b)), rtol=1e-13)
    assert len(calls) <= 4  # the model is exact: T_b, the top, one step, at most one more


@pytest.mark.parametrize("name", ["seed", "bearing"])
@pytest.mark.parametrize("mode", ["bulk", "full"])
def test_root_equals_brentq_on_the_same_losses(cases, name, mode):
    case = cases[name]
    x = rows_of(300, 11)
    model = row_model(case, mode, True, True)
    rows = _row_values(case, x, model)
    r = case.thermal.resistance_K_W
    base = rows.sea_temp_C + r * case.thermal.other_heat_W
    evals = []

    def power(t, i):
        evals.append(len(t))
        return row_total(model, rows, t, i)

    temps, p, ok = root_balance(power, base, r, features=_features(rows))
    assert ok.mean() > 0.99 and sum(evals) / rows.n < 6  # 3.5-4.0 on the benchmark's rows
    for j in np.flatnonzero(ok)[::15]:
        def g(t, j=j):
            return t - base[j] - r * row_total(model, rows, np.array([t]), np.array([j]))[0]
        top = base[j] + r * row_total(model, rows, base[j:j + 1], np.array([j]))[0]
        t_ref = brentq(g, base[j], top, xtol=1e-15, rtol=8.9e-16)
        p_ref = row_total(model, rows, np.array([t_ref]), np.array([j]))[0]
        assert temps[j] == pytest.approx(t_ref, abs=1e-11)
        assert p[j] == pytest.approx(p_ref, rel=1e-12)


@pytest.mark.parametrize(("name", "mode", "n"), [("seed", "bulk", 150), ("bearing", "bulk", 150),
                                                 ("bearing", "full", 40)])
def test_vector_balance_equals_the_scalar_path_to_1e_12(cases, name, mode, n):
    case = cases[name]
    x = rows_of(n, 5 + n)
    if mode == "bulk":
        x.pop("film_strength")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        got = joint_loss_arrays(case, x, mode)
        want = np.array([operating_temperature(apply_inputs(
            case, {k: float(v[i]) for k, v in x.items()}), mode).mean_power_W
            for i in range(n)])
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=0)


def test_rows_handed_back_and_rows_without_a_root(cases):
    case = cases["bearing"]
    hot = case.__class__(**{**case.__dict__, "thermal": type(case.thermal)(
        **{**case.thermal.__dict__, "resistance_K_W": 40.0})})
    speeds = np.array([300.0, 6000.0])  # 6000 rpm: no balance below 250 degC
    got = joint_loss_arrays(hot, {"peak_speed_rpm": speeds}, "bulk")
    low = operating_temperature(apply_inputs(hot, {"peak_speed_rpm": 300.0}), "bulk")
    assert got[0] == pytest.approx(low.mean_power_W, rel=1e-10) and np.isnan(got[1])
    with pytest.raises(SolverError, match="row 1"):
        joint_loss_arrays(hot, {"peak_speed_rpm": speeds}, "bulk", strict=True)

    # a loss that rises between two points (two roots of g): handed back, not solved
    def bump(t, i):
        return 20.0 * np.exp(-0.05 * t) + 30.0 * np.exp(-((t - 12.0) / 1.5) ** 2)

    _, _, ok = root_balance(bump, np.array([3.0, 3.0]), 0.5)
    assert not ok.any()


def test_threads_do_not_change_the_numbers(cases):
    case = cases["bearing"]
    x = rows_of(200, 7)
    one = joint_loss_arrays(case, x, "bulk", block_rows=64)
    two = joint_loss_arrays(case, x, "bulk", block_rows=64, threads=2)
    assert np.array_equal(one, two)  # bit for bit: each block's numbers are its own
    whole = joint_loss_arrays(case, x, "bulk")  # another pilot per block
    np.testing.assert_allclose(whole, one, rtol=1e-13, atol=0)
    assert math.isfinite(float(one.sum()))


def test_a_large_run_starts_every_block_from_one_pilot_and_equals_the_scalar_path(
        cases, monkeypatch):
    # above 16 pilot sizes, joint_loss_arrays solves PILOT_ROWS rows from their brackets
    # once and starts every block at the fitted predictor's root (here 40 pilot rows of
    # 640, three inputs: a quadratic surface of 36 columns)
    from oilgap.model.uncertain import arrays

    monkeypatch.setattr(arrays, "PILOT_ROWS", 40)
    case = cases["bearing"]
    rng = np.random.default_rng(12)
    n = 640
    x = {"nu40_factor": rng.uniform(0.9, 1.1, n), "oil_temp_C": rng.uniform(0, 6, n),
         "peak_speed_rpm": rng.uniform(2500, 3500, n)}
    calls = []
    real = arrays.fit_predictor
    monkeypatch.setattr(arrays, "fit_predictor",
                        lambda *a, **k: calls.append(1) or real(*a, **k))
    got = joint_loss_arrays(case, x, "bulk", block_rows=128)
    assert calls == [1]
    pick = np.arange(0, n, 16)
    want = np.array([operating_temperature(apply_inputs(
        case, {k: float(v[i]) for k, v in x.items()}), "bulk").mean_power_W for i in pick])
    np.testing.assert_allclose(got[pick], want, rtol=1e-12, atol=0)
    monkeypatch.setattr(arrays, "PILOT_ROWS", 10_000)  # no pilot: each block its own
    np.testing.assert_allclose(joint_loss_arrays(case, x, "bulk", block_rows=128), got,
                               rtol=1e-13, atol=0)
