"""Robust design of a linear actuator: the linear design NLP over scenarios of the
uncertain inputs (``oilgap optimize --robust`` on a linear case, thermal ``none``).

The scenarios are quasi-random draws of the case's ``[uncertainty]`` (or the documented
defaults, :func:`oilgap.model.uncertain.distributions.case_uncertainty`), each applied by
the scalar reference path :func:`~oilgap.model.uncertain.apply_inputs`; scenario i's loss
l_i(x) is the linear design NLP's objective (:func:`.linear.design_expressions`, the one
composition) of its case. The statistic:

``mean``       the mean of l_i;
``mean+2sd``   mean plus twice the sample standard deviation;
``p95``        the CVaR surrogate at 0.95: ``t + sum_i s_i/(N (1 - 0.95))`` with
               ``s_i >= l_i - t``, ``s_i >= 0`` (Rockafellar & Uryasev [1]_), as the
               rotary robust NLP.

The constraints are the nominal case's (force, speed, passage velocity; they do not
depend on the oil). The nominal optimum (:func:`.linear.solve_linear_design`) is solved
too, and both designs' empirical p5/p50/p95 over the scenarios are reported.

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
from oilgap.model.linear.report import refuse_dashpot
from oilgap.model.uncertain.distributions import case_uncertainty
from oilgap.model.uncertain.inputs import apply_inputs
from oilgap.model.units import MM_TO_M

from .linear import (
    _LOG,
    LINEAR_VARIABLES,
    LinearDesign,
    _to_y,
    check_compensator,
    constraint_rows,
    design_expressions,
    linear_bounds,
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


def solve_linear_robust(case: DesignCase, statistic: str = "p95",
                        scenarios: int | None = None, seed: int | None = None,
                        verbose: bool = False) -> LinearRobustDesign:
    """The robust linear design (module docstring), thermal ``none``.

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
    losses = [design_expressions(replace(c, friction=c.friction.smooth()), x,
                                 float(c.operating.oil_temp_C), "none")[0] for c in cases]
    _, force, speed, vel = design_expressions(replace(case, friction=case.friction.smooth()),
                                              x, float(case.operating.oil_temp_C), "none")
    g, names = constraint_rows(case.linear, force, speed, vel)
    f, extra, (elo, ehi), rows = _statistic(statistic, losses, n)
    lo, hi = linear_bounds(case)
    nominal = solve_linear_design(case, "none", verbose)
    z = ca.vertcat(y, *extra)
    z0 = np.concatenate([_to_y(np.clip(nominal.x_mm, lo, hi)),
                         ([float(np.max(np.asarray(ca.Function("l", [y], [ca.vertcat(*losses)])(
                             _to_y(nominal.x_mm)))))] + [0.0] * n) if extra else []])
    session = SolverSession("oilgap_linear_robust", {"x": z, "p": ca.SX.sym("p", 0), "f": f,
                                                     "g": ca.vertcat(*g, *rows)}, verbose)
    out = session.solve(z0, [], np.concatenate([_to_y(lo), elo]),
                        np.concatenate([_to_y(hi), ehi]), [0.0] * (len(g) + len(rows)),
                        [ca.inf] * (len(g) + len(rows)))
    xs = np.clip(np.where(_LOG, np.exp(out.x[:6]), out.x[:6]), lo, hi)
    last = dict(zip(LINEAR_VARIABLES, xs, strict=True))
    if out.status == "Infeasible_Problem_Detected":
        raise InfeasibleError("no design meets the constraints within the bounds",
                              status=out.status, last_iterate=last)
    if out.status not in SUCCESS_STATUSES:
        raise solver_failure(out.status, out.iterations, last, "the linear robust NLP")
    each = ca.Function("each", [y], [ca.vertcat(*losses), ca.vertcat(*[n_[1] for n_ in names])])
    lr, cons_r = (np.asarray(v).ravel() for v in each(_to_y(xs)))
    ln = np.asarray(each(_to_y(nominal.x_mm))[0]).ravel()
    rpm = 30.0 / np.pi
    cons = {nm[0]: ((float(v) * rpm, float(nm[2]) * rpm, "rpm", nm[4]) if nm[3] == "rad/s"
                    else (float(v), float(nm[2]), nm[3], nm[4]))
            for nm, v in zip(names, cons_r, strict=True)}
    if comp is not None:
        cons["compensator volume"] = (comp[0], comp[1], "m^3", "<=")
    robust = LinearDesign(x_mm=xs, x0_mm=linear_design_vector(case), lower_mm=lo,
                          upper_mm=hi, mean_power_W=float(np.mean(lr)),
                          oil_temp_C=float(case.operating.oil_temp_C), constraints=cons,
                          nlp_mode="none", iterations=out.iterations)
    return LinearRobustDesign(statistic=statistic, robust=robust, nominal=nominal,
                              losses_W={"robust": lr, "nominal": ln}, scenarios=n)
