"""Robust design: the clearance geometry that minimises a statistic of the loss over N
scenarios of the uncertain inputs (a sample-average approximation in the CasADi NLP).

Variables: the design x = (R, delta, d_r, d_s, L) of the nominal NLP (:mod:`.problem`),
scaled alike (:mod:`.variables`). Each scenario i (:mod:`.scenarios`) has its own loss::

    L_i(x) = P1(x; nu_i, rho_i, law_i, nodes_i) + P2_i + P_b,i      [W]

built from the same model function as the nominal objective
(:func:`.objective.region1_mean_power`) with that scenario's oil state, friction law
(gamma, scale) and duty-cycle nodes. With l_i = L_i / L_ref (L_ref: the nominal loss
of the start design) the statistics are::

    mean       f = ln( (1/N) sum l_i )
    mean+2sd   f = ln( m + 2 sqrt(v + eps) ),  m the sample mean, v the sample variance
               (N - 1 divisor), eps = 1e-16 (sqrt smooth at v = 0)
    p95        the CVaR at alpha = 0.95 of Rockafellar and Uryasev [1]:
               f = t + sum s_i / (N (1 - alpha)),  s_i >= l_i - t,  s_i >= 0
               (N + 1 extra variables t, s_i, N linear-in-s rows)

The empirical p95 is an order statistic of the N losses: piecewise smooth, its gradient
jumps whenever two scenarios swap rank, so IPOPT's exact Hessian would be wrong there.
The CVaR (the mean of the worst 5 % of the scenarios) is smooth in the epigraph form,
convex in the losses, and bounds the p95 from above (CVaR >= VaR): minimising it is a
conservative surrogate of minimising p95 [1, 2]. The report gives the empirical p95 of
the result beside it.

Constraints: the torque capability and the rotor inertia depend on the geometry only,
not on any uncertain input (the motor's torque requirement is a case limit), so each
stays one row, as in the nominal NLP. An optional row bounds the nominal loss,
``L_nom(x) <= eps`` (the Pareto of nominal against p95 loss, under ``none``). Under
``bulk`` the oil temperature is a variable per scenario with its own heat-balance row
(:mod:`.robust_bulk`); ``film``/``full`` are refused with the mode named. The expressions
and their exact derivatives under ``none``: :mod:`.robust_nlp`.

Solved through the problem's one solver session (:class:`.session.SolverSession`):
multi-start as the nominal problem, the first start the nominal optimum.

References
----------
.. [1] R. T. Rockafellar, S. Uryasev, "Optimization of conditional value-at-risk",
   J. Risk 2(3):21-41, 2000.
.. [2] A. Shapiro, D. Dentcheva, A. Ruszczynski, *Lectures on Stochastic Programming*,
   2nd ed., SIAM 2014, ch. 5 (sample-average approximation).
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import casadi as ca
import numpy as np

from oilgap.model.errors import InputError
from oilgap.model.units import MM_TO_M

from .problem import DesignProblem
from .results import DesignPoint
from .robust_bulk import TEMP_SCALE_K, build_bulk_nlp, start_temperatures
from .robust_nlp import CVAR_ALPHA, build_robust_nlp
from .scenarios import ScenarioSet, check_scenarios, resolve_scenarios
from .session import SolverSession, check_starts, clamp, run_starts, solver_failure
from .variables import VARIABLE_LABELS, VARIABLES, from_nlp, to_nlp

ROBUST_MODES = ("none", "bulk")
"""Thermal modes the robust NLP supports (``film``/``full``: the film factor per scenario,
not built)."""

STATISTICS = ("mean", "mean+2sd", "p95")
"""Statistics the robust NLP minimises."""

SCENARIOS_RANGE = (8, 4096)
"""Allowed number of scenarios N [-]: fewer than 8 leave no tail for p95; more than 4096
build an NLP of minutes."""

_LIMIT_KEYS = ("torque_min_Nm", "inertia_max_ratio", "gap_min_m", "gap_max_m",
               "radius_min_m", "radius_max_m", "length_min_m", "length_max_m", "fix")


def check_statistic(statistic: Any) -> str:
    """Check a statistic name.

    Parameters
    ----------
    statistic : str
        One of :data:`STATISTICS` [-].

    Returns
    -------
    str

    Raises
    ------
    InputError
        Unknown statistic.
    """
    if statistic not in STATISTICS:
        raise InputError("robust", statistic, f"one of {', '.join(STATISTICS)}", "optimize")
    return statistic


def check_scenario_count(n: Any) -> int:
    """Check a number of scenarios.

    Parameters
    ----------
    n : int
        Scenarios N [-], within :data:`SCENARIOS_RANGE`.

    Returns
    -------
    int

    Raises
    ------
    InputError
        Not an integer in the range.
    """
    lo, hi = SCENARIOS_RANGE
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not lo <= n <= hi:
        raise InputError("scenarios", n, f"an integer from {lo} to {hi}", "optimize")
    return int(n)


def empirical_stats(losses: np.ndarray) -> dict[str, float]:
    """Mean, sample sd, mean + 2 sd, p5, p50, p95 and CVaR95 of a sample of losses.

    Parameters
    ----------
    losses : ndarray
        Losses [W].

    Returns
    -------
    dict
        ``mean_W``, ``sd_W``, ``mean+2sd_W``, ``p5_W``, ``p50_W``, ``p95_W`` (numpy's
        linear interpolation of the order statistics), ``cvar95_W`` [W].
    """
    x = np.asarray(losses, dtype=float)
    sd = float(np.std(x, ddof=1)) if x.size > 1 else 0.0
    return {"mean_W": float(x.mean()), "sd_W": sd, "mean+2sd_W": float(x.mean() + 2 * sd),
            "p5_W": float(np.percentile(x, 5)), "p50_W": float(np.percentile(x, 50)),
            "p95_W": float(np.percentile(x, 95)), "cvar95_W": cvar(x, CVAR_ALPHA)}


def cvar(losses: np.ndarray, alpha: float = CVAR_ALPHA) -> float:
    """The Rockafellar-Uryasev CVaR of a sample: min over t of t + mean((L - t)+)/(1 - a).

    The function of t is convex and piecewise linear with breaks at the sample values, so
    its minimum is at one of them (evaluated at all) [1].

    Parameters
    ----------
    losses : ndarray
        Losses [W].
    alpha : float
        Level [-].

    Returns
    -------
    float
        CVaR [W].
    """
    x = np.asarray(losses, dtype=float)
    t = x[:, None]
    return float(np.min(t[:, 0] + np.mean(np.maximum(x[None, :] - t, 0.0), axis=1)
                        / (1.0 - alpha)))


def statistic_value(losses: np.ndarray, statistic: str) -> float:
    """The robust objective of a sample of losses, as the NLP defines it (numpy).

    Parameters
    ----------
    losses : ndarray of shape (..., N)
        Losses [W] (scenarios on the last axis).
    statistic : str
        ``mean``, ``mean+2sd`` or ``p95`` (the CVaR at 95 %).

    Returns
    -------
    float or ndarray
        [W].
    """
    x = np.asarray(losses, dtype=float)
    if statistic == "mean":
        return x.mean(axis=-1)
    if statistic == "mean+2sd":
        return x.mean(axis=-1) + 2 * x.std(axis=-1, ddof=1)
    if x.ndim == 1:
        return cvar(x)
    return np.array([cvar(r) for r in x.reshape(-1, x.shape[-1])]).reshape(x.shape[:-1])


@dataclass(frozen=True, kw_only=True)
class RobustSolve:
    """One robust optimum (SI).

    Attributes
    ----------
    statistic : str
        The statistic minimised [-].
    status : str
        IPOPT's status.
    iterations : int
        IPOPT iterations (of the best start).
    starts : int
        Start points [-].
    solve_time_s : float
        IPOPT's wall time, all starts [s].
    x_m : ndarray
        The design (R, delta, d_r, d_s, L) [m].
    optimal : DesignPoint
        The design at the nominal inputs (smooth C_m) [W, m].
    losses_W : ndarray
        Its loss in each scenario [W].
    objective_W : float
        The statistic minimised, in watts (CVaR for p95) [W].
    """

    statistic: str
    status: str
    iterations: int
    starts: int
    solve_time_s: float
    x_m: np.ndarray
    optimal: DesignPoint
    losses_W: np.ndarray
    objective_W: float
    raw: dict = field(default_factory=dict, repr=False)


class RobustDesignProblem:
    """The robust design NLP of a case over N scenarios, built once.

    Parameters
    ----------
    problem : DesignProblem
        The nominal problem: its case, scaling, constraints, and its thermal mode, ``none``
        (:mod:`.robust_nlp`) or ``bulk`` (one oil temperature and heat balance per
        scenario, :mod:`.robust_bulk`).
    scenarios : mapping of str -> array, or ScenarioSet
        N values of each uncertain input (:func:`.scenarios.resolve_scenarios`).
    statistic : str
        One of :data:`STATISTICS`.
    """

    def __init__(self, problem: DesignProblem, scenarios: Mapping[str, Any] | ScenarioSet,
                 statistic: str = "p95"):
        t0 = time.perf_counter()
        self.mode = str(problem.thermal_mode)
        if self.mode not in ROBUST_MODES:
            raise InputError("thermal", self.mode, "the robust design NLP supports thermal "
                             f"modes {' and '.join(ROBUST_MODES)}", "optimize")
        self.problem = problem
        self.statistic = check_statistic(statistic)
        if self.mode == "bulk":
            self.scenarios = check_scenarios(scenarios)
            self._n = next(iter(self.scenarios.values())).size if self.scenarios else 0
        else:
            self.scenarios = (scenarios if isinstance(scenarios, ScenarioSet)
                              else resolve_scenarios(problem.case, scenarios))
            self._n = self.scenarios.n
        check_scenario_count(self._n)
        self.loss_ref_W = float(problem.point(problem.x_case_m).mean_power_W)
        self._build()
        self.build_time_s = time.perf_counter() - t0

    @property
    def n(self) -> int:
        """Number of scenarios N [-]."""
        return self._n

    def _build(self) -> None:
        """The scaled NLP with its exact derivatives (:mod:`.robust_nlp`), its solver
        session and the report function (losses, torque, inertia, nominal loss)."""
        name = f"oilgap_robust_{self.mode}_" + self.statistic.replace("+2", "_plus_2")
        if self.mode == "bulk":
            self.bulk = build_bulk_nlp(self.problem, self.scenarios, self.statistic,
                                       self.loss_ref_W)
            self.session = SolverSession(name, self.bulk.nlp, self.problem.verbose,
                                         expand=False)
            return
        built = build_robust_nlp(self.problem, self.scenarios, self.statistic,
                                 self.loss_ref_W)
        self.nlp = built
        self.session = SolverSession(name, built.nlp, self.problem.verbose, expand=False,
                                     **built.options)
        self.report_fn = built.report

    def losses(self, x_m: Sequence[float]) -> np.ndarray:
        """The NLP's per-scenario losses of a design [W] (its own expressions).

        Parameters
        ----------
        x_m : sequence of 5 floats
            (R, delta, d_r, d_s, L) [m].

        Returns
        -------
        ndarray of shape (N,)
        """
        x = np.asarray(x_m, float)
        if self.mode == "bulk":  # at each scenario's own balance (the scalar path's)
            u = self._temperatures(x) / TEMP_SCALE_K
            return np.asarray(self.bulk.report(ca.DM(to_nlp(x)), ca.DM(u))).ravel()
        return np.asarray(self.report_fn(ca.DM(to_nlp(x)))[0]).ravel()

    def _temperatures(self, x_m: np.ndarray) -> np.ndarray:
        """Each scenario's bulk temperature at design ``x_m`` [degC] (``bulk``)."""
        p = self.problem
        return start_temperatures(self.bulk.cases, x_m, (p.machined_rotor_groove_m,
                                                         p.machined_stator_groove_m))

    def _w0(self, x_m: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Start vector and bounds of the auxiliary variables (temperatures under ``bulk``;
        t, s under p95) at design ``x_m``."""
        parts = []
        if self.mode == "bulk":
            u = self._temperatures(x_m) / TEMP_SCALE_K
            lo, hi = self.bulk.u_bounds
            parts.append((np.clip(u, lo, hi), lo, hi))
        if self.statistic == "p95":
            ell = self.losses(x_m) / self.loss_ref_W
            t = float(np.percentile(ell, 100 * CVAR_ALPHA))
            parts.append((np.concatenate([[t], np.maximum(ell - t, 0.0)]),
                          np.concatenate([[-np.inf], np.zeros(self.n)]),
                          np.full(self.n + 1, np.inf)))
        if not parts:
            return np.zeros(0), np.zeros(0), np.zeros(0)
        return tuple(np.concatenate([q[k] for q in parts]) for k in range(3))

    def solve(self, x0: Sequence[float] | None = None, *, starts: int = 1, seed: int = 0,
              nominal_max_W: float | None = None, **limits: Any) -> RobustSolve:
        """Solve the robust NLP; the first start ``x0`` (default: the nominal optimum).

        Parameters
        ----------
        x0 : sequence of 5 floats, optional
            Start design (R, delta, d_r, d_s, L) [m] (default: the nominal optimum).
        starts : int
            ``x0`` and ``starts - 1`` random points in the bounds; the best is kept.
        seed : int
            Seed of the random starts.
        nominal_max_W : float, optional
            Upper bound on the nominal loss [W] (the Pareto's epsilon constraint).
        **limits
            ``torque_min_Nm``, ``inertia_max_ratio``, the bounds (``gap_min_m``...)
            and ``fix``, as :meth:`DesignProblem.solve_isothermal`.

        Returns
        -------
        RobustSolve

        Raises
        ------
        InputError, InfeasibleError, SolverError
            Bad limits; constraints that conflict; IPOPT failing at every start.
        """
        bad = set(limits) - set(_LIMIT_KEYS)
        if bad:
            raise InputError("robust", sorted(bad)[0], "the oil state comes from the "
                             f"scenarios; allowed: {', '.join(_LIMIT_KEYS)}", "optimize")
        check_starts(starts)
        prob = self.problem
        params = prob.parameters(**limits)
        if nominal_max_W is not None and self.mode != "none":
            raise InputError("pareto", nominal_max_W, "under thermal mode none only",
                             "optimize")
        if x0 is None:
            x0 = prob.solve(starts=starts, seed=seed, **limits).optimal
        x_start = np.asarray(x0.x_mm * MM_TO_M if isinstance(x0, DesignPoint) else x0, float)
        x_start = clamp(x_start, params.lower_m, params.upper_m)
        prob.check_feasible(params, x_start)
        lbg, ubg = prob.constraint_bounds(params)
        ub_nom = np.inf if nominal_max_W is None else np.log(nominal_max_W / self.loss_ref_W)
        lbg, ubg = [*lbg, -np.inf], [*ubg, ub_nom]
        if self.mode == "bulk":  # the balance rows (degrees over 1 K)
            lbg, ubg = [*lbg, *[0.0] * self.n], [*ubg, *[0.0] * self.n]
        if self.statistic == "p95":
            lbg, ubg = [*lbg, *[-np.inf] * self.n], [*ubg, *[0.0] * self.n]
        lo, hi = np.asarray(params.lower_m), np.asarray(params.upper_m)
        total = [0.0]

        def solve_from(x: np.ndarray, _lam: Any) -> RobustSolve:
            r = self._solve_from(x, lo, hi, lbg, ubg)
            total[0] += r.solve_time_s
            return r

        best = run_starts(solve_from, x_start, None, lo, hi, starts, seed,
                          power=lambda r: r.objective_W)
        return RobustSolve(**{**best.__dict__, "starts": starts, "solve_time_s": total[0]})

    def _solve_from(self, x_m: np.ndarray, lo: np.ndarray, hi: np.ndarray, lbg: list,
                    ubg: list) -> RobustSolve:
        """One IPOPT solve from design ``x_m`` [m]."""
        aux0, auxlo, auxhi = self._w0(x_m)
        ylo, yhi = to_nlp(lo), to_nlp(hi)
        out = self.session.solve(np.concatenate([to_nlp(x_m), aux0]), [],
            np.concatenate([ylo, auxlo]), np.concatenate([yhi, auxhi]), lbg, ubg)
        y = out.x[:5]
        if not out.ok:
            last = {VARIABLE_LABELS[v][0]: float(xv) for v, xv in
                    zip(VARIABLES, from_nlp(y) / MM_TO_M, strict=True)}
            raise solver_failure(out.status, out.iterations, last,
                                 f"the robust design NLP ({self.statistic})")
        y_in = clamp(y, ylo, yhi)
        x = np.where(y_in == ylo, lo, np.where(y_in == yhi, hi, clamp(from_nlp(y_in), lo, hi)))
        if self.mode == "bulk":  # at the NLP's own temperatures (balanced to IPOPT's tol)
            losses = np.asarray(self.bulk.report(ca.DM(to_nlp(x)),
                                                 ca.DM(out.x[5:5 + self.n]))).ravel()
            optimal = self.problem.heated.point(x)[0]
        else:
            losses, optimal = self.losses(x), self.problem.point(x)
        return RobustSolve(statistic=self.statistic, status=out.status,
                           iterations=out.iterations, starts=1, solve_time_s=out.time_s,
                           x_m=x, optimal=optimal, losses_W=losses,
                           objective_W=float(statistic_value(losses, self.statistic)),
                           raw={"f": out.f, "lam_g": out.lam_g})


__all__ = ["CVAR_ALPHA", "RobustDesignProblem", "RobustSolve", "SCENARIOS_RANGE",
           "STATISTICS", "check_scenario_count", "check_statistic", "cvar", "empirical_stats",
           "statistic_value"]
