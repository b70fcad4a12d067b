"""The design NLP: optimality checked independently of CasADi/IPOPT.

* KKT conditions at the returned point with gradients from central finite
  differences of the numpy path of the model (tolerance stated below);
* the seed's optimum recomputed from its active set with scipy brentq;
* a closed-form case (only delta free, torque bound active) by brentq;
* a 24-point multi-start that must find nothing better;
* SciPy SLSQP (numpy path, finite differences) reaching the same optimum;
* the multipliers against finite differences of the optimal value;
* infeasible problems, bad overrides and solver failures raising.
"""

import numpy as np
import pytest
from scipy.optimize import brentq

import oilgap.optim.design.problem as dn
from oilgap.model.case_io import seed_case
from oilgap.model.errors import InfeasibleError, InputError, SolverError
from oilgap.model.evaluation import oil_state
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.oils import get_oil
from oilgap.optim.design import VARIABLES, DesignProblem, region1_mean_power
from oilgap.optim.scipy_reference import solve_slsqp

KKT_RTOL = 1e-6
"""Stationarity residual allowed, relative to the objective gradient's norm."""
FEAS_RTOL = 1e-7
"""Constraint violation allowed, relative to the bound (IPOPT tol 1e-9 on ln-scaled g)."""


@pytest.fixture(scope="module")
def prob():
    return DesignProblem(seed_case())


@pytest.fixture(scope="module")
def seed_opt(prob):
    return prob.solve()


def np_functions(prob, params):
    """Objective [W], torque [N m], inertia [kg m^2] of x [m], numpy path of the model."""
    nodes, w, law, m = prob.nodes_rad_s, prob.weights, prob.law, prob.case.motor

    def power(x):
        return float(region1_mean_power(*x, params.nu_m2_s, params.rho_kg_m3, nodes, w, law))

    def torque(x):
        return float(motor_torque(m, x[0], x[1], x[4])[0])

    def inertia(x):
        return float(rotor_inertia(m, x[0], x[2], x[4], prob.machined_rotor_groove_m))

    return power, torque, inertia


def fd_grad(f, x, rel=1e-6):
    g = np.zeros(5)
    for i in range(5):
        h = rel * max(abs(x[i]), 1e-3)
        e = np.zeros(5)
        e[i] = h
        g[i] = (f(x + e) - f(x - e)) / (2 * h)
    return g


def check_kkt(prob, res):
    """KKT at res.optimal with the reported multipliers (physical units).

    min P(x) s.t. tau(x) >= tau_min, J(x) <= J_max, lo <= x <= hi has, with the
    reported sensitivities s = dP*/d(bound): grad P = s_tau grad tau
    + s_J grad J + sum_i s_i e_i, s_tau >= 0, s_J <= 0, s_i >= 0 at a lower and
    <= 0 at an upper bound, and s = 0 for every inactive constraint.
    """
    prm = res.parameters
    power, torque, inertia = np_functions(prob, prm)
    x = res.optimal.x_mm * 1e-3
    mu = res.multipliers
    gp = fd_grad(power, x)
    rhs = mu["torque_min"].value_si * fd_grad(torque, x) + \
        mu["inertia_max"].value_si * fd_grad(inertia, x)
    for i, v in enumerate(VARIABLES):
        stem = dn.VARIABLE_LABELS[v][1]
        for side in ("min", "max", "fixed"):
            if f"{stem}_{side}" in mu:
                rhs[i] += mu[f"{stem}_{side}"].value_si
    assert np.linalg.norm(gp - rhs) <= KKT_RTOL * np.linalg.norm(gp)
    # primal feasibility
    lo, hi = np.array(prm.lower_m), np.array(prm.upper_m)
    assert np.all(x >= lo) and np.all(x <= hi)
    assert torque(x) >= prm.torque_min_Nm * (1 - FEAS_RTOL)
    assert inertia(x) <= prm.inertia_max_kgm2 * (1 + FEAS_RTOL)
    # dual signs and complementarity
    for name, m in mu.items():
        if not m.active:
            assert m.value == 0.0
        elif name.endswith("_min") and name != "inertia_max":
            assert m.value >= -1e-9, name
        elif name.endswith("_max"):
            assert m.value <= 1e-9, name


def test_seed_optimum_satisfies_kkt(prob, seed_opt):
    assert seed_opt.success and seed_opt.status == "Solve_Succeeded"
    check_kkt(prob, seed_opt)
    # the optimum is a real improvement and the initial point is the seed design
    assert seed_opt.initial.T == pytest.approx(4.0)
    assert seed_opt.optimal.mean_power_W < 0.9 * seed_opt.initial.mean_power_W


def test_initial_point_equals_evaluate_with_smooth_law(seed_opt):
    """The NLP objective at the seed design equals oilgap's evaluation (smooth C_m)."""
    from dataclasses import replace

    from oilgap.model.evaluation import evaluate_case

    c = seed_case()
    ev = evaluate_case(replace(c, friction=c.friction.smooth()))
    assert seed_opt.initial.mean_power_W == pytest.approx(ev.total_mean_power_W, rel=1e-12)
    assert seed_opt.initial.region1_power_W == pytest.approx(ev.regions[0].mean_power_W,
                                                             rel=1e-12)


def test_seed_optimum_from_its_active_set_by_brentq(prob, seed_opt):
    """At the seed optimum five constraints are active (a vertex): grooves filled flush,
    L = L_max, inertia = J_max, torque = tau_min. J does not depend on delta, so
    J(R, 0, L_max) = J_max gives R and then tau(R, delta, L_max) = tau_min gives delta."""
    assert set(seed_opt.active_constraints) == {
        "torque_min", "inertia_max", "rotor_groove_depth_min", "stator_groove_depth_min",
        "length_max"}
    prm = seed_opt.parameters
    m = prob.case.motor
    L = prm.upper_m[4]
    R = brentq(lambda R: rotor_inertia(m, R, 0.0, L, prob.machined_rotor_groove_m)
               - prm.inertia_max_kgm2, 0.015, 0.04, xtol=1e-15)
    d = brentq(lambda d: motor_torque(m, R, d, L)[0] - prm.torque_min_Nm, 1e-5, 5e-3,
               xtol=1e-16)
    o = seed_opt.optimal
    assert o.R_m == pytest.approx(R, rel=1e-7)
    assert o.delta_m == pytest.approx(d, rel=1e-6)
    assert o.L_m == L and o.T == 1.0


def test_only_delta_free_closed_form(prob):
    """R, groove depths and L fixed at the seed's; torque_min = 0.9 of the seed's.
    The loss falls monotonically with delta (checked on a grid), so the optimum is the
    largest delta the torque allows: tau(delta) = tau_min, solved by brentq."""
    tmin = 0.9 * prob.tau_ref_Nm
    res = prob.solve(fix=("R", "d_r", "d_s", "L"), torque_min_Nm=tmin)
    power, torque, _ = np_functions(prob, res.parameters)
    x = prob.x_case_m.copy()
    deltas = np.linspace(prob.case.bounds.gap_min, prob.case.bounds.gap_max, 301)
    losses = [power(np.r_[x[0], d, x[2:]]) for d in deltas]
    assert np.all(np.diff(losses) < 0)
    d_star = brentq(lambda d: torque(np.r_[x[0], d, x[2:]]) - tmin, 1e-4, 3e-3, xtol=1e-16)
    assert res.optimal.delta_m == pytest.approx(d_star, rel=1e-7)
    assert "torque_min" in res.active_constraints
    # its multiplier: dP*/dtau_min = (dP/ddelta) / (dtau/ddelta) at delta*
    h = 1e-9
    xs = np.r_[x[0], d_star, x[2:]]
    e = np.array([0, h, 0, 0, 0])
    dp = (power(xs + e) - power(xs - e)) / (2 * h)
    dt = (torque(xs + e) - torque(xs - e)) / (2 * h)
    assert res.multipliers["torque_min"].value == pytest.approx(dp / dt, rel=1e-5)
    check_kkt(prob, res)


def test_multistart_finds_nothing_better(prob, seed_opt):
    rng = np.random.default_rng(20261122)
    prm = seed_opt.parameters
    lo, hi = np.array(prm.lower_m), np.array(prm.upper_m)
    best = seed_opt.optimal.mean_power_W
    n = 0
    while n < 24:
        x0 = rng.uniform(lo, hi)
        r = prob.solve(x0=x0)
        n += 1
        assert r.optimal.mean_power_W >= best * (1 - 1e-9)
        assert np.allclose(r.optimal.x_mm, seed_opt.optimal.x_mm, rtol=1e-6, atol=1e-7)


@pytest.mark.parametrize("overrides", [
    {},
    {"oil": get_oil("VG100"), "oil_temp_C": 5.0, "depth_m": 6000.0, "torque_min_Nm": 0.45},
    {"oil": get_oil("VG46"), "oil_temp_C": 30.0, "depth_m": 0.0, "inertia_max_ratio": 1.2},
    {"torque_min_Nm": 0.55, "gap_min_m": 0.8e-3},
])
def test_scipy_slsqp_reaches_the_same_optimum(prob, overrides):
    res = prob.solve(**overrides)
    ref = solve_slsqp(prob, **overrides)
    assert ref.success
    assert ref.mean_power_W == pytest.approx(res.optimal.mean_power_W, rel=1e-4)
    assert np.allclose(ref.x_m, res.optimal.x_mm * 1e-3, rtol=1e-4, atol=1e-8)
    check_kkt(prob, res)


@pytest.mark.parametrize("name, key, rel_step", [
    ("torque_min", "torque_min_Nm", 1e-4),
    ("inertia_max", "inertia_max_ratio", 1e-4),
    ("length_max", "length_max_m", 1e-4),
])
def test_multipliers_are_derivatives_of_the_optimal_power(prob, seed_opt, name, key,
                                                          rel_step):
    """Central difference of the optimal mean power against the reported multiplier."""
    prm = seed_opt.parameters
    base = {"torque_min_Nm": prm.torque_min_Nm, "inertia_max_ratio": prm.inertia_max_ratio,
            "length_max_m": prm.upper_m[4]}[key]
    h = rel_step * base
    p_plus = prob.solve(**{key: base + h}).optimal.mean_power_W
    p_minus = prob.solve(**{key: base - h}).optimal.mean_power_W
    slope = (p_plus - p_minus) / (2 * h)  # W per unit of the override
    mu = seed_opt.multipliers[name]
    if name == "inertia_max":  # W per % of the reference inertia = W per 0.01 of the ratio
        assert mu.value == pytest.approx(slope * 0.01, rel=1e-4)
    elif name == "length_max":  # W per mm
        assert mu.value == pytest.approx(slope * 1e-3, rel=1e-4)
    else:
        assert mu.value == pytest.approx(slope, rel=1e-4)


def test_warm_start_reaches_the_cold_optimum(prob, seed_opt):
    cold = prob.solve(torque_min_Nm=0.47)
    warm = prob.solve(x0=seed_opt, torque_min_Nm=0.47)
    assert warm.optimal.mean_power_W == pytest.approx(cold.optimal.mean_power_W, rel=1e-9)
    assert warm.iterations <= cold.iterations


def test_failed_dual_warm_start_falls_back_to_a_primal_start(monkeypatch, seed_opt):
    monkeypatch.setitem(dn._WARM_OPTIONS, "ipopt.max_iter", 1)
    p = DesignProblem(seed_case())
    r = p.solve(x0=seed_opt, torque_min_Nm=0.47)
    assert r.optimal.mean_power_W == pytest.approx(
        p.solve(torque_min_Nm=0.47).optimal.mean_power_W, rel=1e-9)


def test_feasibility_check_premises(prob):
    """check_feasible assumes: torque falls with delta and rises with R (and is linear in
    L); inertia rises with R and L and falls as the rotor grooves open (less epoxy)."""
    m, b = prob.case.motor, prob.case.bounds
    d = np.linspace(1e-5, 3 * b.gap_max, 400)
    R = np.linspace(0.8 * b.radius_min, 1.2 * b.radius_max, 400)
    assert np.all(np.diff(motor_torque(m, b.radius_min, d, b.length_min)[0]) < 0)
    assert np.all(np.diff(motor_torque(m, R, b.gap_max, b.length_min)[0]) > 0)
    d0 = prob.machined_rotor_groove_m
    assert np.all(np.diff(rotor_inertia(m, R, 0.0, b.length_min, d0)) > 0)
    assert np.all(np.diff(rotor_inertia(m, b.radius_min, np.linspace(0, d0, 50),
                                        b.length_min, d0)) < 0)


def test_duty_cycle_reduction_is_exact(prob, seed_opt):
    """26 weighted nodes against the plain mean over the 1500 samples."""
    c = prob.case
    x = seed_opt.optimal.x_mm * 1e-3
    nu, _, rho = oil_state(c)
    samples = c.duty_cycle.omega_rad_s
    assert samples.size == 1500 and prob.nodes_rad_s.size == 25  # + the zero node
    plain = float(np.mean(region1_mean_power(*x, nu, rho, samples, np.ones(1500) / 1500,
                                             prob.law)))
    reduced = float(region1_mean_power(*x, nu, rho, prob.nodes_rad_s, prob.weights, prob.law))
    assert abs(reduced - plain) <= 1e-12 * plain


def test_to_case_round_trip_poses_the_same_problem(seed_opt):
    """Re-optimizing the optimal case gives the same design (same absolute limits)."""
    case = seed_opt.to_case()
    again = DesignProblem(case).solve()
    assert again.optimal.mean_power_W == pytest.approx(seed_opt.optimal.mean_power_W,
                                                       rel=1e-7)
    assert np.allclose(again.optimal.x_mm, seed_opt.optimal.x_mm, rtol=1e-6, atol=1e-7)
    assert case.region1.roughness == pytest.approx(seed_opt.optimal.T)


def test_infeasible_torque_names_delta(prob):
    with pytest.raises(InfeasibleError) as e:
        prob.solve(torque_min_Nm=0.9, gap_min_m=1.5e-3)
    msg = str(e.value)
    assert "torque >= 0.9 N m needs delta <=" in msg and "delta_min = 1.5 mm" in msg
    # the delta it names gives exactly tau_min at R_max, L_max (independent check)
    d_need = float(msg.split("needs delta <= ")[1].split(" mm")[0]) * 1e-3
    b = prob.case.bounds
    tau = motor_torque(prob.case.motor, b.radius_max, d_need, b.length_max)[0]
    assert tau == pytest.approx(0.9, rel=1e-3)
    assert e.value.exit_code == 3


def test_infeasible_inertia_and_joint_conflict(prob):
    with pytest.raises(InfeasibleError, match="inertia <= .* is below the lightest rotor"):
        prob.solve(inertia_max_ratio=0.3)
    # each constraint alone is feasible, together they are not
    with pytest.raises(InfeasibleError, match="conflict") as e:
        prob.solve(torque_min_Nm=0.5, inertia_max_ratio=0.6)
    assert "torque >=" in str(e.value) and "inertia <=" in str(e.value)
    prob.solve(torque_min_Nm=0.5)  # feasible alone
    prob.solve(torque_min_Nm=0.3, inertia_max_ratio=0.6)
    # just inside the limit the check lets IPOPT solve it, and IPOPT finds both active
    r = prob.solve(torque_min_Nm=0.48, inertia_max_ratio=0.6)
    assert {"torque_min", "inertia_max"} <= set(r.active_constraints)


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
    monkeypatch.setitem(dn._SOLVER_OPTIONS, "ipopt.max_iter", 2)
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
