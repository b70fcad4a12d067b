"""The design NLP's solve interface: start points (case, warm start with and without
multipliers, several starts), the optimum as a case, its evaluation with the exact C_m,
the parameters of a solve (overrides, fixed variables, bad input) and solver failures."""

from dataclasses import replace

import numpy as np
import pytest

import oilgap.optim.design.variables as dv
from oilgap.model.errors import InfeasibleError, InputError, SolverError
from oilgap.model.evaluation import evaluate_case, oil_state
from oilgap.model.io.case_io import seed_case
from oilgap.model.oils import get_oil
from oilgap.optim.design import DesignProblem


def test_initial_point_equals_evaluate_with_smooth_law(seed_opt):
    """The NLP objective at the seed design equals oilgap's evaluation (smooth C_m)."""
    c = seed_case()
    ev = evaluate_case(replace(c, friction=c.friction.smooth()), thermal="none")
    assert seed_opt.initial.mean_power_W == pytest.approx(ev.total_mean_power_W, rel=1e-12)
    assert seed_opt.initial.region1_power_W == pytest.approx(ev.regions[0].mean_power_W,
                                                             rel=1e-12)


def test_warm_start_reaches_the_cold_optimum(prob, seed_opt):
    cold = prob.solve(torque_min_Nm=0.47)
    warm = prob.solve(x0=seed_opt, torque_min_Nm=0.47)
    assert warm.optimal.mean_power_W == pytest.approx(cold.optimal.mean_power_W, rel=1e-9)
    assert warm.iterations <= cold.iterations


def test_failed_dual_warm_start_falls_back_to_a_primal_start(monkeypatch, seed_opt):
    monkeypatch.setitem(dv.WARM_OPTIONS, "ipopt.max_iter", 1)
    p = DesignProblem(seed_case())
    r = p.solve(x0=seed_opt, torque_min_Nm=0.47)
    assert r.optimal.mean_power_W == pytest.approx(
        p.solve(torque_min_Nm=0.47).optimal.mean_power_W, rel=1e-9)


def test_to_case_round_trip_poses_the_same_problem(seed_opt):
    """Re-optimizing the optimal case gives the same design (same absolute limits)."""
    case = seed_opt.to_case()
    again = DesignProblem(case).solve()
    assert again.optimal.mean_power_W == pytest.approx(seed_opt.optimal.mean_power_W,
                                                       rel=1e-7)
    assert np.allclose(again.optimal.x_mm, seed_opt.optimal.x_mm, rtol=1e-6, atol=1e-7)
    assert case.region1.roughness == pytest.approx(seed_opt.optimal.T)


@pytest.mark.parametrize("kw, field", [
    ({"gap_min_m": 2e-3, "gap_max_m": 1e-3}, "gap_max_mm"),
    ({"torque_min_Nm": -1.0}, "torque_min_Nm"),
    ({"torque_min_Nm": float("nan")}, "torque_min_Nm"),
    ({"inertia_max_ratio": 0.0}, "inertia_max_ratio"),
    ({"fix": ("T5",)}, "fix"),
    ({"fix": {"d_r": 5e-3}}, "fix[d_r]"),
    ({"radius_min_m": 0.005}, "radius_min_mm"),
    ({"oil_temp_C": 400.0}, "oil_temp_C"),
    ({"nu_m2_s": 1e-4, "oil_temp_C": 10.0}, "nu_m2_s/rho_kg_m3"),
    ({"starts": 0}, "starts"),
    ({"x0": [0.02, 0.001]}, "x0"),
])
def test_bad_overrides_raise_input_error(prob, kw, field):
    with pytest.raises(InputError) as e:
        prob.solve(**kw)
    assert e.value.field == field


def test_solver_failure_raises_with_last_iterate(monkeypatch):
    monkeypatch.setitem(dv.SOLVER_OPTIONS, "ipopt.max_iter", 2)
    with pytest.raises(SolverError) as e:
        DesignProblem(seed_case()).solve()
    assert not isinstance(e.value, InfeasibleError)
    assert e.value.status == "Maximum_Iterations_Exceeded"
    assert {"delta_mm", "R_mm", "L_mm", "mean_power_W"} <= set(e.value.last_iterate)
    assert e.value.exit_code == 4


def test_multistart_option_returns_the_best(prob, seed_opt):
    r = prob.solve(starts=4)
    assert r.optimal.mean_power_W == pytest.approx(seed_opt.optimal.mean_power_W, rel=1e-9)
    assert r.initial.T == pytest.approx(4.0)



def test_parameters_default_to_the_case(prob):
    """Without overrides: the case's oil state, bounds (mm in the case file -> m), the
    groove depths as machined and the case's own torque capability."""
    c = prob.case
    prm = prob.parameters()
    nu, _, rho = oil_state(c)
    assert (prm.nu_m2_s, prm.rho_kg_m3) == (float(nu), float(rho))
    b, r1 = c.bounds, c.region1
    assert prm.lower_m == (b.radius_min, b.gap_min, 0.0, 0.0, b.length_min)
    assert prm.upper_m == (b.radius_max, b.gap_max, r1.T2 - r1.T1_unfilled,
                           r1.T4_unfilled - r1.T3, b.length_max)
    assert prm.torque_min_Nm == prob.tau_ref_Nm
    assert prm.inertia_max_ratio == pytest.approx(b.inertia_max_ratio, rel=1e-15)


def test_parameters_to_dict_units(prob):
    """nu in cSt (1 cSt = 1e-6 m^2/s) and bounds in mm, by hand."""
    prm = prob.parameters(nu_m2_s=2.5e-5, rho_kg_m3=870.0, gap_max_m=1.7e-3,
                          inertia_max_ratio=1.1)
    d = prm.to_dict()
    assert d["nu_cSt"] == pytest.approx(25.0, rel=1e-14)
    assert d["density_kg_m3"] == 870.0
    assert d["gap_max_mm"] == pytest.approx(1.7, rel=1e-14)
    assert d["inertia_max_ratio"] == pytest.approx(1.1, rel=1e-14)
    assert d["inertia_max_kgm2"] == pytest.approx(1.1 * prob.inertia_ref_kgm2, rel=1e-14)
    assert prm.raw_oil_state


def test_parameters_with_an_oil_at_a_condition(prob):
    """An oil, temperature and depth give the oil state of the case with that oil there."""
    oil = get_oil("VG46")
    prm = prob.parameters(oil=oil, oil_temp_C=30.0, depth_m=2000.0)
    nu, _, rho = oil_state(replace(prob.case, oil=oil), 30.0, 2000.0)
    assert (prm.oil, prm.nu_m2_s, prm.rho_kg_m3) == ("VG46", float(nu), float(rho))
    assert not prm.raw_oil_state


def test_fix_pins_variables(prob):
    prm = prob.parameters(fix=("R", "L"))
    x = prob.x_case_m
    assert prm.lower_m[0] == prm.upper_m[0] == x[0]
    assert prm.lower_m[4] == prm.upper_m[4] == x[4]
    prm = prob.parameters(fix={"delta": 1.2e-3})
    assert prm.lower_m[1] == prm.upper_m[1] == 1.2e-3
    r = prob.solve(fix={"delta": 1.2e-3}, torque_min_Nm=0.4)
    assert r.optimal.delta_m == 1.2e-3 and "gap_fixed" in r.active_constraints


def test_starts_from_a_design_point_and_a_vector_agree(prob, seed_opt):
    a = prob.solve(x0=seed_opt.optimal)
    b = prob.solve(x0=seed_opt.optimal.x_mm * 1e-3)
    assert a.optimal.mean_power_W == b.optimal.mean_power_W
    assert np.allclose(a.initial.x_mm, seed_opt.optimal.x_mm, rtol=1e-15)


def test_evaluate_gives_the_exact_law_of_both_designs(seed_opt):
    """DesignResult.evaluate equals evaluate_case of the case and of to_case()."""
    start, opt = seed_opt.evaluate()
    assert start.total_mean_power_W == pytest.approx(
        evaluate_case(seed_case(), thermal="none").total_mean_power_W, rel=1e-12)
    assert opt.total_mean_power_W == pytest.approx(
        evaluate_case(seed_opt.to_case(), thermal="none").total_mean_power_W, rel=1e-12)


def test_infeasible_is_a_solver_error_with_its_status(prob):
    with pytest.raises(SolverError) as e:
        prob.solve(inertia_max_ratio=0.3)
    assert isinstance(e.value, InfeasibleError)
    assert e.value.status == "infeasible (checked before solving)"
