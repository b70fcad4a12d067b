"""The one solver session of the design NLP (optim/design/session.py): buffered and plain
calls agree, a warm start keeps the optimum, multi-start finds the better of two minima,
every failure is the same one-line SolverError, and only the session calls nlpsol."""

import re
from dataclasses import replace
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

import oilgap.optim.design.variables as dv
from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InfeasibleError, InputError, SolverError
from oilgap.model.io.case_io import seed_case
from oilgap.optim.design import DesignProblem
from oilgap.optim.design.lean import solve_lean
from oilgap.optim.design.session import (
    SolverSession,
    check_starts,
    run_starts,
    snap_to_bounds,
    solver_failure,
)
from oilgap.optim.design.variables import from_nlp, to_nlp

ROOT = Path(__file__).resolve().parents[3]


def _args(prob):
    q = prob.parameters()
    lbg, ubg = prob.constraint_bounds(q)
    return {"x0": to_nlp(prob.x_case_m), "p": [q.nu_m2_s, q.rho_kg_m3],
            "lbx": to_nlp(np.asarray(q.lower_m)), "ubx": to_nlp(np.asarray(q.upper_m)),
            "lbg": lbg, "ubg": ubg}


def _toy():
    """f(x) = (x^2 - 1)^2 + x / 10 on [-2, 2]: two minima, the one near -1 lower."""
    x = ca.SX.sym("x")
    return SolverSession("toy", {"x": x, "p": ca.SX.sym("p", 0),
                                 "f": (x ** 2 - 1) ** 2 + 0.1 * x, "g": ca.SX(0, 1)})


def _newton_root(x):
    """The stationary point 4 x^3 - 4 x + 0.1 = 0 near x, by Newton's method (by hand)."""
    for _ in range(30):
        x -= (4 * x ** 3 - 4 * x + 0.1) / (12 * x ** 2 - 4)
    return x


def test_buffered_call_equals_the_plain_call(prob):
    args = _args(prob)
    plain = prob.session.solve(**args)
    b = prob.session.buffered()
    for k, v in args.items():
        b.arg[k][:] = v
    b.run()
    assert b.stats()["return_status"] == plain.status == "Solve_Succeeded"
    for k in ("x", "g", "lam_x", "lam_g"):
        np.testing.assert_allclose(b.res[k], getattr(plain, k), rtol=1e-12, atol=1e-12)
    assert b.res["f"][0] == pytest.approx(plain.f, rel=1e-12)


def test_warm_start_from_the_optimum_stays_there_in_fewer_iterations(prob):
    args = _args(prob)
    cold = prob.session.solve(**args)
    warm = prob.session.solve(**dict(args, x0=cold.x), lam=(cold.lam_x, cold.lam_g))
    assert warm.ok and warm.iterations < cold.iterations
    np.testing.assert_allclose(warm.x, cold.x, rtol=0, atol=1e-8)


def test_one_start_finds_the_local_minimum_and_multistart_the_global_one():
    s = _toy()

    def solve_from(x, lam):
        out = s.solve(x, [], [-2.0], [2.0], [], [], lam)
        if not out.ok:
            raise solver_failure(out.status, out.iterations, {"x": float(out.x[0])})
        return out

    local = run_starts(solve_from, np.array([1.5]), None, [-2.0], [2.0], 1, power=lambda r: r.f)
    assert local.x[0] == pytest.approx(_newton_root(1.0), abs=1e-7)
    best = run_starts(solve_from, np.array([1.5]), None, [-2.0], [2.0], 8, seed=0,
                      power=lambda r: r.f)
    xm = _newton_root(-1.0)
    assert best.x[0] == pytest.approx(xm, abs=1e-7)
    assert best.f == pytest.approx((xm ** 2 - 1) ** 2 + 0.1 * xm, abs=1e-12)


def test_a_failed_warm_start_is_retried_from_the_primal_point():
    calls = []

    def solve_from(x, lam):
        calls.append(lam)
        if lam is not None:
            raise SolverError("stale multipliers")
        return "primal"

    assert run_starts(solve_from, np.zeros(5), ("lam",), np.zeros(5), np.ones(5)) == "primal"
    assert calls == [("lam",), None]


def test_every_start_failing_raises_the_first_error():
    errors = iter([SolverError("first"), SolverError("second"), SolverError("third")])

    def solve_from(x, lam):
        raise next(errors)

    with pytest.raises(SolverError, match="first"):
        run_starts(solve_from, np.zeros(5), None, np.zeros(5), np.ones(5), 3)


@pytest.mark.parametrize("bad", [0, -1, 1.5, True, "2"])
def test_starts_must_be_a_positive_integer(bad):
    with pytest.raises(InputError) as e:
        check_starts(bad)
    assert e.value.field == "starts"


def test_snapping_reports_a_variable_on_its_bound_at_the_bound():
    lo = np.array([0.02, 1e-4, 0.0, 0.0, 0.01])
    hi = np.array([0.05, 2e-3, 1e-3, 1e-3, 0.08])
    ylo, yhi = to_nlp(lo), to_nlp(hi)
    y = np.array([ylo[0] - 1e-3, yhi[1] + 1.0, 0.5, 0.5, 0.5 * (ylo[4] + yhi[4])])
    y_in, x = snap_to_bounds(y, ylo, yhi, lo, hi, from_nlp)
    assert x[0] == lo[0] and x[1] == hi[1]  # exactly, no exp/log round-off
    assert np.all((y_in >= ylo) & (y_in <= yhi))
    assert x[4] == pytest.approx(np.sqrt(lo[4] * hi[4]), rel=1e-12)  # mid-way in ln L


def _failure_of(fn):
    with pytest.raises(SolverError) as e:
        fn()
    assert not isinstance(e.value, InfeasibleError)
    return e.value


def test_every_solve_fails_with_the_same_one_line_message(monkeypatch):
    monkeypatch.setitem(dv.SOLVER_OPTIONS, "ipopt.max_iter", 2)
    prob = DesignProblem(seed_case())
    full = _failure_of(prob.solve)
    lean = _failure_of(lambda: solve_lean(prob))
    assert str(full) == str(lean)  # the sweep's solve and the full one: one message
    assert full.last_iterate == lean.last_iterate
    msg = str(full)
    assert "\n" not in msg
    assert msg.startswith("IPOPT did not converge on the design NLP (status "
                          "Maximum_Iterations_Exceeded after 2 iterations); last iterate: ")


@pytest.mark.parametrize("mode", ["bulk", "film", "full"])
def test_a_thermal_solve_fails_with_the_same_message(monkeypatch, mode):
    monkeypatch.setitem(dv.SOLVER_OPTIONS, "ipopt.max_iter", 2)
    spec = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5e4)
    err = _failure_of(DesignProblem(replace(seed_case(), thermal=spec), thermal=mode).solve)
    assert "\n" not in str(err) and err.status == "Maximum_Iterations_Exceeded"
    assert str(err).startswith(f"IPOPT did not converge on the design NLP under thermal {mode} "
                               "(status Maximum_Iterations_Exceeded after 2 iterations); "
                               "last iterate: R_mm = ")
    assert {"delta_mm", "R_mm", "L_mm", "oil_temp_C", "mean_power_W"} <= set(err.last_iterate)


def test_only_the_session_calls_nlpsol():
    calls = []
    for pkg in ("api", "model", "optim", "studies"):
        for f in sorted((ROOT / pkg).rglob("*.py")):
            for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1):
                if re.search(r"\bnlpsol\s*\(", line):
                    calls.append(f"{f.relative_to(ROOT)}:{n}")
    assert len(calls) == 1 and calls[0].startswith("optim/design/session.py:"), calls
