"""The robust design NLP's expressions and their exact derivatives, built per scenario.

One scenario's scaled loss l(y; theta) (:func:`.objective.region1_mean_power` with the
scenario's data theta = (nu, rho, gamma, scale, constant loss, speed nodes), over the
reference loss) is an SX function of the five scaled design variables y. CasADi
differentiates it once, symbolically: its gradient (5) and its Hessian (5 x 5). The NLP
maps these small functions over the N columns of scenario data and assembles its
derivatives from them by the chain rule (:func:`derivative_functions`)::

    f = Phi(l_1 .. l_N)            (mean, mean+2sd; p95: f linear in t, s)
    grad_y f = G dPhi,             G = [grad l_1 .. grad l_N] (5 x N)
    hess_yy(sigma f + lam' g) = sum_i c_i hess l_i + sigma G HPhi G' + sum_k lam_k hess g_k
    c_i = sigma dPhi_i (mean, mean+2sd)   or   lam_(3+i) (p95's rows l_i - t - s_i)

with Phi's gradient dPhi and Hessian HPhi (N x N) by CasADi's AD of Phi alone, and g_k the
three geometry rows (torque, inertia, nominal loss). These are the exact first and second
derivatives CasADi's own AD would give (tests compare them), at a cost linear in N: a
symbolic Hessian of the N-copy expression takes seconds to build for N = 64, and MX AD
through the map costs ~10 ms per Hessian (the benchmark, docs/benchmarks.md). The custom
functions go to IPOPT [1] through the nlpsol options ``grad_f``, ``jac_g`` and
``hess_lag`` of CasADi [2].

References
----------
.. [1] A. Wächter, L. T. Biegler, "On the implementation of an interior-point
   filter line-search algorithm for large-scale nonlinear programming",
   Math. Program. 106:25-57, 2006 (IPOPT).
.. [2] J. A. E. Andersson et al., "CasADi: a software framework for nonlinear
   optimization and optimal control", Math. Prog. Comp. 11:1-36, 2019.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace
from typing import Any

import casadi as ca
import numpy as np

from oilgap.model.errors import InputError
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.units import MM_TO_M

from .objective import region1_mean_power
from .scenarios import ScenarioSet
from .variables import LOG_VARIABLES

CVAR_ALPHA = 0.95
"""Level of the CVaR surrogate of p95 [-]."""

EPS_VAR = 1e-16
"""Added to the sample variance of the scaled losses under the square root of mean+2sd
[-]: sqrt is not differentiable at 0 (N identical scenarios)."""


@dataclass(frozen=True, kw_only=True)
class RobustNLP:
    """The robust NLP (MX) with its derivative functions and a report function.

    Attributes
    ----------
    nlp : dict
        ``x``, ``p``, ``f``, ``g`` (MX) [-].
    options : dict
        ``grad_f``, ``jac_g``, ``hess_lag``: the exact derivative functions [-].
    report : casadi.Function
        y -> (losses [W] (N x 1), torque [N m], inertia [kg m^2], nominal loss [W]).
    """

    nlp: dict
    options: dict
    report: ca.Function


def scenario_columns(sc: ScenarioSet) -> tuple[np.ndarray, np.ndarray, Any]:
    """The scenarios as columns (nu, rho, gamma, scale, constant, nodes...), their common
    weights and their common friction law (gamma and the scale aside).

    Parameters
    ----------
    sc : ScenarioSet
        Resolved scenarios (SI).

    Returns
    -------
    data : ndarray of shape (5 + K, N)
        nu [m^2/s], rho [kg/m^3], gamma [-], scale (C of the power law) [-], the
        design-independent loss [W], the K speed nodes [rad/s] of each scenario.
    weights : ndarray of shape (K,)
        The nodes' weights [-].
    law : FrictionLaw
        The first scenario's law [-].

    Raises
    ------
    InputError
        Scenarios whose duty cycles have different node counts or weights, or whose
        laws differ in more than gamma and the scale (cannot happen with the inputs of
        :data:`~oilgap.model.uncertain.INPUTS`; checked all the same).
    """
    law0 = sc.laws[0]
    key = "C" if law0.form == "power-law" else "scale"
    cols = []
    for i in range(sc.n):
        law, nodes, w = sc.laws[i], sc.nodes_rad_s[i], sc.weights[i]
        same = replace(law, gamma=law0.gamma, **{key: getattr(law0, key)}) == law0
        if not same or nodes.shape != sc.nodes_rad_s[0].shape \
                or not np.array_equal(w, sc.weights[0]):
            raise InputError("scenarios", i, "scenarios that differ in the inputs' "
                             "effects only (one friction form, one duty-cycle shape)", "robust")
        cols.append(np.concatenate([[sc.nu_m2_s[i], sc.rho_kg_m3[i], law.gamma,
                                     getattr(law, key), sc.constant_W[i]], nodes]))
    return np.column_stack(cols), sc.weights[0], law0


def _symbolic_law(law: Any, gamma: Any, scale: Any) -> Any:
    """A copy of ``law`` with CasADi symbols for gamma and the scale (``C`` of the power
    law): FrictionLaw validates numbers when built, so the two fields are set on the copy
    (:func:`~oilgap.model.skin_friction.moment_coefficient` takes symbols for both)."""
    out = copy.copy(law)
    object.__setattr__(out, "gamma", gamma)
    object.__setattr__(out, "C" if law.form == "power-law" else "scale", scale)
    return out


def _design(ys: ca.SX) -> tuple:
    """(R, delta, d_r, d_s, L) [m] of the scaled variables y."""
    return tuple((ca.exp(ys[i]) if LOG_VARIABLES[i] else ys[i]) * MM_TO_M for i in range(5))


def _scenario_functions(sc: ScenarioSet, loss_ref_W: float
                        ) -> tuple[ca.Function, ca.Function, ca.Function, np.ndarray]:
    """One scenario's (l, grad l), its c * hess l, its (loss [W], l), and the data."""
    data, weights, law = scenario_columns(sc)
    ys, th, c = ca.SX.sym("y", 5), ca.SX.sym("theta", data.shape[0]), ca.SX.sym("c")
    loss = region1_mean_power(_design(ys), th[0], th[1], th[5:], weights,
                              _symbolic_law(law, th[2], th[3])) + th[4]
    ell = loss / loss_ref_W
    hess, grad = ca.hessian(ell, ys)
    cse = {"cse": True}
    one = ca.Function("scenario_l", [ys, th], [ell, grad], cse)
    h = ca.Function("scenario_h", [ys, th, c], [c * hess], cse)
    raw = ca.Function("scenario_loss", [ys, th], [loss, ell], cse)
    return one, h, raw, data


def _geometry_functions(problem: Any, loss_ref_W: float) -> tuple[ca.Function, ca.Function]:
    """The three geometry rows g (ln tau/tau_ref, ln J/J_ref, ln L_nom/L_ref), their
    Jacobian, the raw (tau, J, L_nom), and lam' hess g."""
    ys, lam = ca.SX.sym("y", 5), ca.SX.sym("lam", 3)
    x = _design(ys)
    m = problem.case.motor
    p_nom = (region1_mean_power(x, problem.nu_m2_s, problem.rho_kg_m3,
                                ca.DM(problem.nodes_rad_s), problem.weights, problem.law)
             + problem.constant_power(problem.nu_m2_s, problem.rho_kg_m3))
    tau = motor_torque(m, x[0], x[1], x[4])[0]
    J = rotor_inertia(m, x[0], x[2], x[4], problem.machined_rotor_groove_m)
    g = ca.vertcat(ca.log(tau / problem.tau_ref_Nm), ca.log(J / problem.inertia_ref_kgm2),
                   ca.log(p_nom / loss_ref_W))
    geo = ca.Function("geometry", [ys], [g, ca.jacobian(g, ys), tau, J, p_nom])
    geo_h = ca.Function("geometry_h", [ys, lam], [ca.hessian(ca.dot(lam, g), ys)[0]])
    return geo, geo_h


def _statistic_function(statistic: str, n: int) -> ca.Function | None:
    """Phi(l) -> (Phi, dPhi, HPhi) of the smooth statistics (None for p95's epigraph)."""
    if statistic == "p95":
        return None
    ell = ca.SX.sym("l", n)
    m = ca.sum1(ell) / n
    if statistic == "mean":
        phi = ca.log(m)
    else:
        v = ca.sumsqr(ell - m) / (n - 1)
        phi = ca.log(m + 2 * ca.sqrt(v + EPS_VAR))
    hphi, dphi = ca.hessian(phi, ell)
    return ca.Function("statistic", [ell], [phi, dphi, hphi])


def build_robust_nlp(problem: Any, sc: ScenarioSet, statistic: str,
                     loss_ref_W: float) -> RobustNLP:
    """The scaled robust NLP of ``sc`` and its exact derivative functions.

    Parameters
    ----------
    problem : DesignProblem
        The nominal problem (motor, references, nominal oil state and law).
    sc : ScenarioSet
        The N scenarios.
    statistic : str
        ``mean``, ``mean+2sd`` or ``p95``.
    loss_ref_W : float
        Reference loss the losses are scaled by [W].

    Returns
    -------
    RobustNLP
        Variables w = (y, [t, s]) [-]; rows (torque, inertia, nominal loss[, l_i - t -
        s_i]) [-].
    """
    n = sc.n
    one, h, raw, data = _scenario_functions(sc, loss_ref_W)
    geo, geo_h = _geometry_functions(problem, loss_ref_W)
    phi = _statistic_function(statistic, n)
    one_m = one.map(n)
    h_sum = h.map("scenario_h_sum", "serial", n, [0], [0])
    D = ca.DM(data)
    nw = 5 if phi is not None else 6 + n
    w, p = ca.MX.sym("x", nw), ca.MX.sym("p", 0)
    y = w[:5]
    raw_m = raw.map(n)
    ell = raw_m(y, D)[1].T  # values alone for f and g (no gradient)
    ell_j, grad = one_m(y, D)  # (1 x N), (5 x N): for the derivatives
    g_geo, jac_geo, tau, J, p_nom = geo(y)
    if phi is None:
        t, s = w[5], w[6:]
        f = t + ca.sum1(s) / (n * (1.0 - CVAR_ALPHA))
        g = ca.vertcat(g_geo, ell - t - s)
        g_j = ca.vertcat(g_geo, ell_j.T - t - s)  # the same rows, from the gradients' map
        grad_f = ca.DM([0.0] * 5 + [1.0] + [1.0 / (n * (1.0 - CVAR_ALPHA))] * n)
        jac = ca.vertcat(ca.horzcat(jac_geo, ca.MX(3, 1 + n)),
                         ca.horzcat(grad.T, -ca.DM.ones(n, 1), -ca.DM.eye(n)))
    else:
        f = phi(ell)[0]
        g = g_j = g_geo
        grad_f = ca.mtimes(grad, phi(ell_j.T)[1])
        jac = jac_geo
    lam_f, lam_g = ca.MX.sym("lam_f"), ca.MX.sym("lam_g", g.shape[0])
    if phi is None:
        hy = h_sum(y, D, lam_g[3:].T)
    else:
        _, dphi, hphi = phi(one_m(y, D)[0].T)
        hy = h_sum(y, D, (lam_f * dphi).T) + lam_f * ca.mtimes([grad, hphi, grad.T])
    hy = hy + geo_h(y, lam_g[:3])
    hess = ca.triu(hy if phi is not None else ca.diagcat(hy, ca.MX(1 + n, 1 + n)))
    f_j = f if phi is None else phi(ell_j.T)[0]
    opts = {"grad_f": ca.Function("nlp_grad_f", [w, p], [f_j, grad_f]),
            "jac_g": ca.Function("nlp_jac_g", [w, p], [g_j, jac]),
            "hess_lag": ca.Function("nlp_hess_l", [w, p, lam_f, lam_g], [hess])}
    yr = ca.MX.sym("y", 5)
    report = ca.Function("robust_report", [yr], [raw_m(yr, D)[0].T, *geo(yr)[2:]])
    return RobustNLP(nlp={"x": w, "p": p, "f": f, "g": g}, options=opts, report=report)


__all__ = ["CVAR_ALPHA", "EPS_VAR", "RobustNLP", "build_robust_nlp", "scenario_columns"]
