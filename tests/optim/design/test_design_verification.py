"""The design NLP: optimality checked independently of CasADi/IPOPT.

* KKT conditions at the returned point with gradients from central finite
  differences of the numpy path of the objective (tolerance stated below);
* the seed's optimum recomputed from its active set with scipy brentq;
* a closed-form case (only delta free, torque bound active) by brentq;
* a 24-point multi-start that must find nothing better;
* SciPy SLSQP (numpy path, finite differences) reaching the same optimum;
* the multipliers against finite differences of the optimal value;
* the duty-cycle reduction against the plain mean over the samples.
"""

import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.model.evaluation import oil_state
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.oils import get_oil
from oilgap.optim.design import VARIABLE_LABELS, VARIABLES, region1_mean_power
from oilgap.optim.scipy_reference import solve_slsqp

KKT_RTOL = 1e-6
"""Stationarity residual allowed, relative to the objective gradient's norm."""
FEAS_RTOL = 1e-7
"""Constraint violation allowed, relative to the bound (IPOPT tol 1e-9 on ln-scaled g)."""


def np_functions(prob, params):
    """Objective [W], torque [N m], inertia [kg m^2] of x [m]: the numpy path of the
    objective (no CasADi)."""
    objective = prob.objective(params)
    return (lambda x: float(objective.mean_power(x)), lambda x: float(objective.torque(x)),
            lambda x: float(objective.inertia(x)))


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
        stem = VARIABLE_LABELS[v][1]
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


def test_duty_cycle_reduction_is_exact(prob, seed_opt):
    """26 weighted nodes against the plain mean over the 1500 samples."""
    c = prob.case
    x = seed_opt.optimal.x_mm * 1e-3
    nu, _, rho = oil_state(c)
    samples = c.duty_cycle.omega_rad_s
    assert samples.size == 1500 and prob.nodes_rad_s.size == 25  # + the zero node
    plain = float(np.mean(region1_mean_power(x, nu, rho, samples, np.ones(1500) / 1500,
                                             prob.law)))
    reduced = float(region1_mean_power(x, nu, rho, prob.nodes_rad_s, prob.weights, prob.law))
    assert abs(reduced - plain) <= 1e-12 * plain
