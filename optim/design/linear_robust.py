"""Robust design of a linear actuator: the linear design NLP over scenarios of the
uncertain inputs (``oilgap optimize --robust`` on a linear case, thermal ``none`` or ``bulk``).

The scenarios are quasi-random draws of the case's ``[uncertainty]`` (or the documented
defaults, :func:`oilgap.model.uncertain.distributions.case_uncertainty`), each applied by
the scalar reference path :func:`~oilgap.model.uncertain.apply_inputs`; scenario i's loss
l_i(x) is the linear design NLP's objective (:func:`.linear.design_expressions`, the one
composition) of its case. The statistic:

* ``mean``: the mean of l_i;
* ``mean+2sd``: mean plus twice the sample standard deviation;
* ``p95``: the CVaR surrogate at 0.95: ``t + sum_i s_i/(N (1 - 0.95))`` with
  ``s_i >= l_i - t``, ``s_i >= 0`` (Rockafellar & Uryasev [1]_), as the rotary robust
  NLP.

The constraints are the nominal case's (force, speed, passage velocity; they do not
depend on the oil). The nominal optimum (:func:`.linear.solve_linear_design`) is solved
too, and both designs' empirical p5/p50/p95 over the scenarios are reported, each
scenario's loss at a design by the evaluation's path (exact C_m, its own balance under
``bulk``).

References
----------
.. [1] R. T. Rockafellar, S. Uryasev, "Optimization of conditional value-at-risk",
   *J. Risk* 2(3):21-41, 2000.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import casadi as ca
import numpy as np

from oilgap.model.case import DesignCase
from oilgap.model.errors import InfeasibleError, InputError
from oilgap.model.joint_loss import operating_temperature, uses_balance
from oilgap.model.linear.report import refuse_dashpot
from oilgap.model.uncertain.distributions import case_uncertainty
from oilgap.model.uncertain.inputs import apply_inputs
from oilgap.model.units import MM_TO_M

from .linear import (
    _LOG,
    LINEAR_VARIABLES,
    TEMP_SCALE_K,
    LinearDesign,
    _to_y,
    check_compensator,
    constraint_rows,
    design_expressions,
    linear_bounds,
    linear_design_case,
    linear_design_vector,
    solve_linear_design,
)
from .session import SolverSession, solver_failure
from .variables import SUCCESS_STATUSES

CVAR_ALPHA = 0.95
"""Level of the CVaR surrogate of p95 [-]."""
DEFAULT_LINEAR_SCENARIOS = 16
"""Scenarios of the linear robust NLP [-] (a power of 2 for the Sobol' points)."""


@dataclass(frozen=True, kw_only=True)
class LinearRobustDesign:
    """The robust optimum beside the nominal one.

    Attributes
    ----------
    statistic : str
        ``p95``, ``mean`` or ``mean+2sd``.
    robust, nominal : LinearDesign
        The two optima [mm].
    losses_W : dict
        ``"robust"``/``"nominal"`` -> each scenario's loss at that design [W].
    scenarios : int
        N [-].
    """

    statistic: str
    robust: LinearDesign
    nominal: LinearDesign
    losses_W: dict
    scenarios: int


def _statistic(stat: str, losses, n: int):
    """(objective, extra variables, their bounds, extra rows) of a statistic."""
    if stat == "mean":
        return sum(losses) / n, [], ([], []), []
    if stat == "mean+2sd":
        mean = sum(losses) / n
        var = sum((v - mean) ** 2 for v in losses) / (n - 1)
        return mean + 2.0 * ca.sqrt(var + 1e-16), [], ([], []), []
    t, s = ca.SX.sym("t"), ca.SX.sym("s", n)
    f = t + ca.sum1(s) / (n * (1.0 - CVAR_ALPHA))
    rows = [s[i] - (losses[i] - t) for i in range(n)]
    return f, [t, s], ([-ca.inf] + [0.0] * n, [ca.inf] * (n + 1)), rows


def _scenario_losses(cases, x, mode: str):
    """Each scenario's loss expression, and under a balance mode its temperature variable
    and the balance row ``T_i - T_sea,i - R (l_i + Q) = 0`` [K]."""
    losses, temps, rows = [], [], []
    for c in cases:
        cs = replace(c, friction=c.friction.smooth())
        if uses_balance(mode):
            q = ca.SX.sym("t")
            loss = design_expressions(cs, x, q * TEMP_SCALE_K, mode)[0]
            th = c.thermal
            rows.append(q * TEMP_SCALE_K - th.sea_temp_C - th.resistance_K_W
                        * (loss + th.other_heat_W))
            temps.append(q)
        else:
            loss = design_expressions(cs, x, float(c.operating.oil_temp_C), mode)[0]
        losses.append(loss)
    return losses, temps, rows


def _exact_losses(cases, x_mm, mode: str) -> np.ndarray:
    """Each scenario's loss at a design, by the evaluation's path (exact C_m) [W]."""
    return np.array([operating_temperature(linear_design_case(c, x_mm), mode).mean_power_W
                     for c in cases])


def _robust_design(case, y, xs, lo, hi, names, comp, mode: str, iterations: int,
                   lr: np.ndarray) -> LinearDesign:
    """The robust optimum as a :class:`~.linear.LinearDesign`, its constraints evaluated."""
    each = ca.Function("each", [y], [ca.vertcat(*[n_[1] for n_ in names])])
    cons_r = np.asarray(each(_to_y(xs))).ravel()
    rpm = 30.0 / np.pi
    cons = {nm[0]: ((float(v) * rpm, float(nm[2]) * rpm, "rpm", nm[4]) if nm[3] == "rad/s"
                    else (float(v), float(nm[2]), nm[3], nm[4]))
            for nm, v in zip(names, cons_r, strict=True)}
    if comp is not None:
        cons["compensator volume"] = (comp[0], comp[1], "m^3", "<=")
    robust = LinearDesign(x_mm=xs, x0_mm=linear_design_vector(case), lower_mm=lo,
                          upper_mm=hi, mean_power_W=float(np.mean(lr)),
                          oil_temp_C=float(case.operating.oil_temp_C), constraints=cons,
                          nlp_mode=mode, iterations=iterations)
    return robust


def solve_linear_robust(case: DesignCase, statistic: str = "p95",
                        scenarios: int | None = None, seed: int | None = None,
                        verbose: bool = False, mode: str = "none") -> LinearRobustDesign:
    """The robust linear design (module docstring), thermal ``none`` or ``bulk``.

    Parameters
    ----------
    case : DesignCase
        A linear case.
    statistic : str
        ``p95``, ``mean`` or ``mean+2sd``.
    scenarios : int, optional
        N (default :data:`DEFAULT_LINEAR_SCENARIOS`).
    seed : int, optional
        Seed of the draws (default 0).
    verbose : bool
        IPOPT's iterations.
    mode : str
        ``"none"`` or ``"bulk"`` (each scenario's own balance as an equality, its
        temperature a variable).

    Returns
    -------
    LinearRobustDesign
        Robust and nominal optima and their scenario losses [W].

    Raises
    ------
    InputError, InfeasibleError, SolverError
        As :func:`.linear.solve_linear_design`.

    References
    ----------
    Rockafellar & Uryasev [1]_.
    """
    n = DEFAULT_LINEAR_SCENARIOS if scenarios is None else int(scenarios)
    if n < 4:
        raise InputError("--scenarios", n, "at least 4", "optimize")
    refuse_dashpot(case)
    comp = check_compensator(case)
    draws = case_uncertainty(case).sample(n, 0 if seed is None else int(seed))
    cases = [apply_inputs(case, {k: float(v[i]) for k, v in draws.items()}) for i in range(n)]
    y = ca.SX.sym("y", 6)
    x = [ca.exp(y[i]) * MM_TO_M if _LOG[i] else y[i] * MM_TO_M for i in range(6)]
    losses, temps, balance = _scenario_losses(cases, x, mode)
    _, force, speed, vel = design_expressions(replace(case, friction=case.friction.smooth()),
                                              x, float(case.operating.oil_temp_C), "none")
    g, names = constraint_rows(case.linear, force, speed, vel)
    f, extra, (elo, ehi), rows = _statistic(statistic, losses, n)
    lo, hi = linear_bounds(case)
    nominal = solve_linear_design(case, mode, verbose)
    z = ca.vertcat(y, *temps, *extra)
    t0 = [operating_temperature(linear_design_case(c, nominal.x_mm), mode).oil_temp_C
          / TEMP_SCALE_K for c in cases] if temps else []
    l0 = _exact_losses(cases, nominal.x_mm, mode)
    z0 = np.concatenate([_to_y(np.clip(nominal.x_mm, lo, hi)), t0,
                         ([float(l0.max())] + [0.0] * n) if extra else []])
    ng = len(g) + len(rows)
    session = SolverSession("oilgap_linear_robust", {"x": z, "p": ca.SX.sym("p", 0), "f": f,
                                                     "g": ca.vertcat(*g, *rows, *balance)},
                            verbose)
    out = session.solve(z0, [], np.concatenate([_to_y(lo), [-6.0] * len(temps), elo]),
                        np.concatenate([_to_y(hi), [30.0] * len(temps), ehi]),
                        [0.0] * (ng + len(balance)), [ca.inf] * ng + [0.0] * len(balance))
    xs = np.clip(np.where(_LOG, np.exp(out.x[:6]), out.x[:6]), lo, hi)
    last = dict(zip(LINEAR_VARIABLES, xs, strict=True))
    if out.status == "Infeasible_Problem_Detected":
        raise InfeasibleError("no design meets the constraints within the bounds",
                              status=out.status, last_iterate=last)
    if out.status not in SUCCESS_STATUSES:
        raise solver_failure(out.status, out.iterations, last, "the linear robust NLP")
    lr = _exact_losses(cases, xs, mode)
    robust = _robust_design(case, y, xs, lo, hi, names, comp, str(mode), out.iterations, lr)
    return LinearRobustDesign(statistic=statistic, robust=robust, nominal=nominal,
                              losses_W={"robust": lr, "nominal": l0}, scenarios=n)
