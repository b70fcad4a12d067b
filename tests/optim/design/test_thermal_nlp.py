"""The design NLP with the oil's heating (modes film and full), checked independently.

* the NLP's loss and oil temperature at the start design against the model's own
  evaluation (``evaluate_case``, ``operating_temperature``);
* the KKT conditions of the full optimum with gradients by central finite differences
  of the model's functions evaluated in numpy (not CasADi): stationarity of the
  Lagrangian in every variable with the reported multipliers in physical units, signs,
  complementarity, and the heat balance to 1e-8 K;
* what a kelvin of sea temperature costs: the balance's multiplier against a central
  difference of re-solved optima (T_sea +- 0.1 K) and against the envelope theorem
  written out by hand, dP*/dT_sea = P_T / (1 - R P_T) at fixed design;
* a brute-force grid over (R, delta, L) (coarse grid, then two local refinements),
  each point's oil temperature from the model's steady balance
  (:func:`oilgap.model.thermal.joint_steady_temperature`), constraints checked: its best
  point is not better than the NLP's optimum and lies next to it;
* failures are errors, never results; bad combinations are InputErrors.
"""

from dataclasses import replace

import numpy as np
import pytest

import oilgap.optim.design.variables as dv
from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InfeasibleError, InputError, SolverError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import joint_mean_power, operating_temperature
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.regions import Region, joint_regions, rotor_stator_region
from oilgap.model.thermal import joint_steady_temperature
from oilgap.optim.design import DesignProblem, ThermalDesignResult, compare_heating

SPEC = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5e4)
GROOVE_FREE = ("rotor_groove_depth", "stator_groove_depth")


@pytest.fixture(scope="module")
def case():
    return replace(seed_case(), thermal=SPEC)


@pytest.fixture(scope="module")
def smooth(case):
    """The case with the NLP's friction law (smooth C_m): the model evaluated in numpy."""
    return replace(case, friction=case.friction.smooth())


@pytest.fixture(scope="module")
def full(case):
    return DesignProblem(case, thermal="full")


@pytest.fixture(scope="module")
def opt(full):
    return full.solve()


def loss(smooth, x, temp_C):
    """P(x, T) [W] from the model's functions in numpy: region 1 of x plus the bearing."""
    r1 = rotor_stator_region(*x)
    return float(joint_mean_power(smooth, temp_C, "full",
                                  regions=(r1, *joint_regions(smooth)[1:])))


# ----------------------------------------------------------------- start design


def test_film_start_is_the_models_film_evaluation():
    c = seed_case()
    res = DesignProblem(c, thermal="film").solve()
    ev = evaluate_case(replace(c, friction=c.friction.smooth()), thermal="film")
    assert res.initial.mean_power_W == pytest.approx(ev.total_mean_power_W, rel=1e-10)
    assert res.initial_oil_temp_C == res.oil_temp_C == c.operating.oil_temp_C


def test_full_start_is_the_models_operating_temperature(opt, smooth):
    op = operating_temperature(smooth, "full")
    assert opt.initial_oil_temp_C == pytest.approx(op.oil_temp_C, abs=1e-8)
    assert opt.initial.mean_power_W == pytest.approx(op.mean_power_W, rel=1e-9)


def test_bulk_optimum_is_an_isothermal_loss_on_its_balance(case, smooth):
    # bulk: the start is the model's bulk balance; at the optimum the reported loss is
    # the isothermal (no film) loss of the optimal design at its own balance temperature
    res = DesignProblem(case, thermal="bulk").solve()
    op = operating_temperature(smooth, "bulk")
    assert res.thermal_mode == "bulk"
    assert res.initial_oil_temp_C == pytest.approx(op.oil_temp_C, abs=1e-8)
    assert res.initial.mean_power_W == pytest.approx(op.mean_power_W, rel=1e-9)
    o = res.optimal
    x = np.array([o.R_m, o.delta_m, o.rotor_groove_depth_m, o.stator_groove_depth_m, o.L_m])
    r1 = rotor_stator_region(*x)
    p = float(joint_mean_power(smooth, res.oil_temp_C, "none",
                               regions=(r1, *joint_regions(smooth)[1:])))
    assert o.mean_power_W == pytest.approx(p, rel=1e-12)
    assert abs(res.oil_temp_C - SPEC.sea_temp_C - SPEC.resistance_K_W * p) <= 1e-8
    assert res.sea_temp_cost_W_per_K < 0  # a warmer sea thins the oil


# ----------------------------------------------------------------- KKT


def _constraints(case, x):
    """(torque [N m], inertia [kg m^2]) of x [m], numpy."""
    m, r1 = case.motor, case.region1
    return (float(motor_torque(m, x[0], x[1], x[4])[0]),
            float(rotor_inertia(m, x[0], x[2], x[4], r1.T2 - r1.T1_unfilled)))


def _gradient(f, z, steps):
    g = np.zeros(len(z))
    for i, h in enumerate(steps):
        e = np.zeros(len(z))
        e[i] = h
        g[i] = (f(z + e) - f(z - e)) / (2 * h)
    return g


def test_kkt_of_the_full_optimum(opt, smooth, case):
    o = opt.optimal
    x = np.array([o.R_m, o.delta_m, o.rotor_groove_depth_m, o.stator_groove_depth_m, o.L_m])
    T = opt.oil_temp_C
    z = np.append(x, T)
    steps = [1e-7, 1e-8, 1e-8, 1e-8, 1e-7, 1e-4]  # m, m, m, m, m, K
    P = loss(smooth, x, T)
    gP = _gradient(lambda v: loss(smooth, v[:5], v[5]), z, steps)
    gtau = _gradient(lambda v: _constraints(case, v[:5])[0], z, steps)
    gJ = _gradient(lambda v: _constraints(case, v[:5])[1], z, steps)
    # the balance is met at the reported state, to 1e-8 K
    assert abs(T - SPEC.sea_temp_C - SPEC.resistance_K_W * P) <= 1e-8
    assert o.mean_power_W == pytest.approx(P, rel=1e-12)
    # Lagrangian L = P + lam h - sum_k s_k (c_k - b_k), s_k = dP*/db_k (reported),
    # h = T - T_sea - R (P + Q), lam = -dP*/dT_sea (reported)
    mu = opt.multipliers
    lam = -opt.sea_temp_cost_W_per_K
    Rth = SPEC.resistance_K_W
    grad_h = np.append(-Rth * gP[:5], 1.0 - Rth * gP[5])
    bounds = np.zeros(6)
    for i, stem in enumerate(("radius", "gap", "rotor_groove_depth", "stator_groove_depth",
                              "length")):
        bounds[i] = mu[f"{stem}_min"].value_si + mu[f"{stem}_max"].value_si
    resid = (gP + lam * grad_h - mu["torque_min"].value_si * gtau
             - mu["inertia_max"].value_si * gJ - bounds)
    scale = np.array([x[0], x[1], 1e-3, 1e-3, x[4], 1.0])  # W per unit ln x, per mm, per K
    assert np.max(np.abs(resid * scale)) / P < 1e-6, resid * scale
    # signs: lower bounds and torque_min cost (>= 0), upper bounds and inertia_max save
    for name, m in mu.items():
        if m.active:
            assert (m.value_si >= 0) == (name.endswith("_min")), name
    # complementarity with IPOPT's own multipliers (scaled NLP): |lam_g| * slack ~ 0, and
    # primal feasibility to IPOPT's bound relaxation (1e-8 relative)
    tau, J = _constraints(case, x)
    prm = opt.parameters
    lam_g = opt._raw["lam_g"]
    slack = np.array([np.log(tau / prm.torque_min_Nm), np.log(prm.inertia_max_kgm2 / J)])
    assert np.all(slack > -1e-7)
    assert np.all(np.abs(lam_g[:2] * slack) < 1e-7)
    assert set(opt.active_constraints) >= {"torque_min", "length_max"}
    assert "inertia_max" not in opt.active_constraints and slack[1] > 1e-3


def test_sea_temperature_cost_is_the_derivative_of_the_optimum(full, opt, smooth):
    """The balance's multiplier against re-solved optima and against the envelope theorem
    (dP*/dT_sea = P_T dT/dT_sea at the fixed optimal design, dT/dT_sea = 1/(1 - R P_T))."""
    up = full.solve(x0=opt, sea_temp_C=SPEC.sea_temp_C + 0.1).optimal.mean_power_W
    down = full.solve(x0=opt, sea_temp_C=SPEC.sea_temp_C - 0.1).optimal.mean_power_W
    fd = (up - down) / 0.2
    assert opt.sea_temp_cost_W_per_K == pytest.approx(fd, rel=1e-4)
    o = opt.optimal
    x = [o.R_m, o.delta_m, o.rotor_groove_depth_m, o.stator_groove_depth_m, o.L_m]
    h = 1e-3
    p_t = (loss(smooth, x, opt.oil_temp_C + h) - loss(smooth, x, opt.oil_temp_C - h)) / (2 * h)
    assert opt.sea_temp_cost_W_per_K == pytest.approx(
        p_t / (1.0 - SPEC.resistance_K_W * p_t), rel=1e-6)
    assert opt.sea_temp_cost_W_per_K < 0  # a warmer sea thins the oil


def test_film_oil_temperature_cost_is_the_derivative_of_the_optimum():
    prob = DesignProblem(seed_case(), thermal="film")
    r = prob.solve()
    up = prob.solve(x0=r, oil_temp_C=2.1).optimal.mean_power_W
    down = prob.solve(x0=r, oil_temp_C=1.9).optimal.mean_power_W
    assert r.oil_temp_cost_W_per_K == pytest.approx((up - down) / 0.2, rel=1e-4)


# ----------------------------------------------------------------- brute force


def _grid_losses(smooth, R, d, L, mode="full"):
    """Loss [W] and oil temperature [degC] of designs (R, delta, L) [m], grooves filled,
    each at its own steady balance (the model's fixed point)."""
    n = R.size

    def power_at(ts):
        k = ts.size // n
        r1 = Region("rotor-stator", np.tile(R, k)[:, None], np.tile(d, k)[:, None],
                    np.tile(L, k)[:, None], 1.0)
        return np.asarray(joint_mean_power(smooth, ts, mode,
                                           regions=(r1, *joint_regions(smooth)[1:])))

    temps, power = joint_steady_temperature(power_at, SPEC, n)
    return power, temps


def _best(smooth, case, tmin, jmax, R, d, L, mode="full"):
    Rg, dg, Lg = (a.ravel() for a in np.meshgrid(R, d, L, indexing="ij"))
    power, temps = _grid_losses(smooth, Rg, dg, Lg, mode)
    x = np.stack([Rg, dg, 0 * Rg, 0 * Rg, Lg])
    ok = ((motor_torque(case.motor, x[0], x[1], x[4])[0] >= tmin) &
          (rotor_inertia(case.motor, x[0], x[2], x[4], case.region1.T2
                         - case.region1.T1_unfilled) <= jmax))
    k = int(np.argmin(np.where(ok, power, np.inf)))
    return power[k], temps[k], (Rg[k], dg[k], Lg[k])


@pytest.mark.parametrize("mode", ["full", "bulk"])
def test_brute_force_grid_finds_nothing_better(full, opt, smooth, case, mode):
    """Both balance modes: ``bulk`` (the default with [thermal]: the balance without the
    film factor) against the same grid with the isothermal loss at each point's own
    steady temperature."""
    if mode == "full":
        res = full.solve(fix={"d_r": 0.0, "d_s": 0.0})
        assert res.optimal.mean_power_W == pytest.approx(opt.optimal.mean_power_W, rel=1e-9)
    else:
        res = DesignProblem(case, thermal="bulk").solve(fix={"d_r": 0.0, "d_s": 0.0})
    prm = res.parameters
    lo, hi = np.array(prm.lower_m), np.array(prm.upper_m)
    tmin, jmax = prm.torque_min_Nm, prm.inertia_max_kgm2
    axes = [np.linspace(lo[i], hi[i], 13) for i in (0, 1, 4)]
    for _ in range(4):  # coarse grid, then three local refinements around the best point
        p_best, t_best, x_best = _best(smooth, case, tmin, jmax, *axes, mode=mode)
        widths = [2 * (a[1] - a[0]) for a in axes]
        axes = [np.linspace(max(lo[i], c - w), min(hi[i], c + w), 13)
                for i, c, w in zip((0, 1, 4), x_best, widths, strict=True)]
    o = res.optimal
    assert p_best >= o.mean_power_W * (1 - 1e-9)  # nothing better than the NLP
    assert p_best <= o.mean_power_W * 1.002  # and the grid's best comes within 0.2 %
    assert abs(t_best - res.oil_temp_C) < 0.01
    assert abs(x_best[0] - o.R_m) < 0.1e-3 and abs(x_best[1] - o.delta_m) < 0.02e-3
    assert abs(x_best[2] - o.L_m) < 0.1e-3


# ----------------------------------------------------------------- interface


def test_comparison_without_heating_is_the_isothermal_optimum(full, opt):
    cmp = compare_heating(full)
    iso = DesignProblem(seed_case()).solve()
    assert cmp.isothermal.optimal.mean_power_W == pytest.approx(iso.optimal.mean_power_W,
                                                                rel=1e-12)
    assert cmp.heated.optimal.mean_power_W == pytest.approx(opt.optimal.mean_power_W,
                                                            rel=1e-9)
    ch = cmp.changes()
    assert ch["oil_temp_C"]["without_heating"] == 2.0
    assert ch["oil_temp_C"]["with_heating"] == pytest.approx(opt.oil_temp_C, abs=1e-9)
    d = cmp.to_dict()
    assert d["thermal_mode"] == "full" and d["sea_temp_C"] == 2.0
    assert d["without_heating"]["optimal"]["mean_power_W"] == iso.optimal.mean_power_W


def test_warm_start_from_a_thermal_optimum(full, opt):
    cold = full.solve(torque_min_Nm=0.47)
    warm = full.solve(x0=opt, torque_min_Nm=0.47)
    assert isinstance(warm, ThermalDesignResult)
    assert warm.optimal.mean_power_W == pytest.approx(cold.optimal.mean_power_W, rel=1e-9)
    assert warm.iterations <= cold.iterations


def test_default_mode_is_the_one_the_evidence_supports(case):
    assert DesignProblem(case, thermal=None).thermal_mode == "bulk"
    assert DesignProblem(seed_case(), thermal=None).thermal_mode == "none"
    assert DesignProblem(seed_case()).heated is None  # the isothermal NLP stays the default


@pytest.mark.parametrize("mode, kw, field", [
    ("film", {"nu_m2_s": 1e-4}, "nu_m2_s"),
    ("film", {"sea_temp_C": 4.0}, "sea_temp_C"),
    ("full", {"oil_temp_C": 20.0}, "oil_temp_C"),
    ("full", {"sea_temp_C": 400.0}, "sea_temp_C"),
])
def test_bad_overrides_are_input_errors(case, mode, kw, field):
    with pytest.raises(InputError) as e:
        DesignProblem(case, thermal=mode).solve(**kw)
    assert e.value.field == field


def test_full_without_a_thermal_table_is_an_input_error():
    with pytest.raises(InputError) as e:
        DesignProblem(seed_case(), thermal="full")
    assert e.value.field == "thermal"


def test_infeasible_limits_are_caught_before_ipopt(full):
    with pytest.raises(InfeasibleError) as e:
        full.solve(torque_min_Nm=5.0)
    assert e.value.status == "infeasible (checked before solving)"


def test_solver_failure_is_an_error_not_a_result(monkeypatch, case):
    monkeypatch.setitem(dv.SOLVER_OPTIONS, "ipopt.max_iter", 2)
    with pytest.raises(SolverError) as e:
        DesignProblem(case, thermal="full").solve()
    assert "Maximum_Iterations_Exceeded" in str(e.value)
    assert "oil_temp_C" in e.value.last_iterate
