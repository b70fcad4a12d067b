"""Robust design against nominal design, side by side, checked by an independent Monte Carlo.

:func:`robust_design` solves the nominal design NLP (:class:`~oilgap.optim.design.
DesignProblem`) and the robust one (:class:`~oilgap.optim.design.robust.
RobustDesignProblem`) over N scenarios drawn from the case's uncertain inputs
(:func:`~oilgap.model.uncertain.case_uncertainty`, scrambled Sobol' points, ``seed``),
warm-started from the nominal optimum, and then:

* evaluates both designs at the nominal inputs with the case's own (exact) C_m
  (:func:`~oilgap.model.evaluation.evaluate_case`, what ``oilgap evaluate`` prints);
* evaluates both over an independent Monte Carlo sample of the same inputs (a different
  scramble seed, ``mc_samples`` > 2N draws) through the vectorised loss
  (:func:`~oilgap.model.uncertain.arrays.joint_loss_arrays`, the case's exact C_m), not
  through the NLP's expressions: the mean, p5, p50, p95 and CVaR95 of each;
* solves again with 2N scenarios (same seed) and reports the change of the design and of
  its statistic on the independent Monte Carlo: stable when every design variable moves by
  at most :data:`STABILITY_DESIGN_TOL` of its bound range and the statistic by at most
  :data:`STABILITY_STAT_TOL` of its value (the in-sample objective is shown too: it moves
  with the scenarios drawn even when the design does not);
* optionally, the Pareto front of nominal loss against the statistic
  (:func:`robust_pareto`: minimise the statistic subject to nominal loss <= eps).

Sample-average approximation: Shapiro, Dentcheva & Ruszczynski [1]; the CVaR surrogate of
p95: Rockafellar & Uryasev [2].

References
----------
.. [1] A. Shapiro, D. Dentcheva, A. Ruszczynski, *Lectures on Stochastic Programming*,
   2nd ed., SIAM 2014, ch. 5.
.. [2] R. T. Rockafellar, S. Uryasev, "Optimization of conditional value-at-risk",
   J. Risk 2(3):21-41, 2000.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning, SolverError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.uncertain import UncertaintySpec, case_uncertainty
from oilgap.model.uncertain.arrays import joint_loss_arrays
from oilgap.model.units import MM_TO_M
from oilgap.optim.design import DesignProblem, DesignResult
from oilgap.optim.design.robust import (
    RobustDesignProblem,
    RobustSolve,
    check_scenario_count,
    check_statistic,
    empirical_stats,
)
from oilgap.optim.design.scenarios import design_case
from oilgap.optim.design.session import check_starts
from oilgap.optim.design.variables import VARIABLE_LABELS, VARIABLES
from oilgap.optim.progress import report
from oilgap.studies.settings import DEFAULT_STARTS

DEFAULT_SCENARIOS = 64
"""Scenarios N of the robust NLP unless told otherwise [-]."""

MC_SAMPLES = 4096
"""Draws of the independent Monte Carlo check [-] (a power of 2: balanced Sobol' points)."""

MC_SEED_OFFSET = 7919
"""The Monte Carlo's scramble seed is the NLP's seed plus this: another sample [-]."""

STABILITY_DESIGN_TOL = 0.01
"""Stable: each design variable moves by at most this fraction of its bound range [-]."""

STABILITY_STAT_TOL = 0.01
"""Stable: the statistic changes by at most this fraction of its value [-]."""


@dataclass(frozen=True, kw_only=True)
class RobustSettings:
    """What a robust design run does.

    Attributes
    ----------
    statistic : str
        ``p95`` (CVaR 95 % surrogate), ``mean`` or ``mean+2sd`` [-].
    scenarios : int
        Scenarios N of the NLP [-] (8 ... 4096).
    seed : int
        Scramble seed of the scenarios' Sobol' points [-].
    starts : int
        Start points of each solve [-].
    mc_samples : int
        Draws of the independent Monte Carlo check [-] (> 2 N).
    pareto_points : int
        Points of the nominal-vs-statistic front (0: none) [-].
    """

    statistic: str = "p95"
    scenarios: int = DEFAULT_SCENARIOS
    seed: int = 0
    starts: int = DEFAULT_STARTS
    mc_samples: int = MC_SAMPLES
    pareto_points: int = 0

    def __post_init__(self):
        check_statistic(self.statistic)
        check_scenario_count(self.scenarios)
        check_starts(self.starts)
        if isinstance(self.seed, bool) or not isinstance(self.seed, (int, np.integer)) \
                or self.seed < 0:
            raise InputError("seed", self.seed, "an integer >= 0", "optimize")
        mc = self.mc_samples
        if isinstance(mc, bool) or not isinstance(mc, (int, np.integer)) \
                or not 2 * self.scenarios < mc <= 2 ** 22:
            raise InputError("mc_samples", mc, f"an integer above 2 x scenarios "
                             f"({2 * self.scenarios}) and at most {2 ** 22}", "optimize")
        p = self.pareto_points
        if isinstance(p, bool) or not isinstance(p, (int, np.integer)) or not (
                p == 0 or 3 <= p <= 50):
            raise InputError("pareto", p, "0 (none) or an integer from 3 to 50", "optimize")


@dataclass(frozen=True, eq=False, kw_only=True)
class RobustDesign:
    """The nominal and the robust optimum side by side (SI; powers [W]).

    Attributes
    ----------
    case : DesignCase
        The case solved.
    mode : str
        Thermal mode (``none`` or ``bulk``).
    settings : RobustSettings
        What was done.
    spec : UncertaintySpec
        The uncertain inputs' joint law and its source.
    nominal : DesignResult
        The nominal optimum.
    robust, doubled : RobustSolve
        The robust optimum over N scenarios, and over 2N (the stability check).
    at_nominal_W : dict
        ``nominal``, ``robust`` -> loss at the nominal inputs, exact C_m [W].
    mc : dict
        ``nominal``, ``robust`` -> :func:`~oilgap.optim.design.robust.empirical_stats` of
        the independent Monte Carlo [W].
    mc_losses_W : dict
        ``nominal``, ``robust`` -> the Monte Carlo's losses [W].
    build_time_s : float
        Time to build the robust NLP over N scenarios [s].
    pareto : list of dict
        The front's points (empty unless asked).
    """

    case: DesignCase
    mode: str
    settings: RobustSettings
    spec: UncertaintySpec
    nominal: DesignResult
    robust: RobustSolve
    doubled: RobustSolve
    at_nominal_W: dict
    mc: dict
    mc_losses_W: dict = field(repr=False)
    build_time_s: float
    pareto: list = field(default_factory=list)

    @property
    def mc_seed(self) -> int:
        """Scramble seed of the independent Monte Carlo [-]."""
        return self.settings.seed + MC_SEED_OFFSET

    @property
    def price_W(self) -> float:
        """Price of robustness: the robust design's nominal loss minus the nominal
        design's (exact C_m) [W]."""
        return self.at_nominal_W["robust"] - self.at_nominal_W["nominal"]

    @property
    def p95_gain_W(self) -> float:
        """Independent Monte Carlo p95 of the nominal design minus the robust one's [W]."""
        return self.mc["nominal"]["p95_W"] - self.mc["robust"]["p95_W"]

    @property
    def design_change_mm(self) -> dict[str, float]:
        """The 2N design minus the N design, each variable [mm]."""
        d = (self.doubled.x_m - self.robust.x_m) / MM_TO_M
        return {VARIABLE_LABELS[v][0]: float(x) for v, x in zip(VARIABLES, d, strict=True)}

    @property
    def statistic_change(self) -> float:
        """Relative change of the statistic on the independent Monte Carlo from the N
        design to the 2N design [-] (the answer's change; the in-sample value also moves
        with the scenarios drawn: :attr:`in_sample_change`)."""
        key = f"{self.settings.statistic}_W"
        a, b = self.mc["robust"][key], self.mc["doubled"][key]
        return (b - a) / a

    @property
    def in_sample_change(self) -> float:
        """Relative change of the in-sample objective from N to 2N scenarios [-] (a
        different set of scenarios: sampling noise of the SAA, not of the design)."""
        return (self.doubled.objective_W - self.robust.objective_W) / self.robust.objective_W

    @property
    def same_design(self) -> bool:
        """The robust design is the nominal one to 1e-6 of each bound range."""
        lo = np.asarray(self.nominal.parameters.lower_m)
        hi = np.asarray(self.nominal.parameters.upper_m)
        span = np.where(hi > lo, hi - lo, 1.0)
        return bool(np.all(np.abs(self.robust.x_m - design_x(self.nominal)) <= 1e-6 * span))

    @property
    def stable(self) -> bool:
        """Both changes within :data:`STABILITY_DESIGN_TOL`, :data:`STABILITY_STAT_TOL`."""
        lo = np.asarray(self.nominal.parameters.lower_m)
        hi = np.asarray(self.nominal.parameters.upper_m)
        span = np.where(hi > lo, hi - lo, 1.0)
        dx = np.abs(self.doubled.x_m - self.robust.x_m) / span
        return bool(np.all(dx <= STABILITY_DESIGN_TOL)
                    and abs(self.statistic_change) <= STABILITY_STAT_TOL)

    def to_dict(self) -> dict[str, Any]:
        """Plain dict, units in the keys (the ``--json`` document without ``defaults``)."""
        s = self.settings

        def design(x_m: np.ndarray, sol_stats: dict) -> dict:
            d = {VARIABLE_LABELS[v][0]: float(x) / MM_TO_M
                 for v, x in zip(VARIABLES, x_m, strict=True)}
            return {**d, **sol_stats}

        nom_x = np.array([self.nominal.optimal.R_m, self.nominal.optimal.delta_m,
                          self.nominal.optimal.rotor_groove_depth_m,
                          self.nominal.optimal.stator_groove_depth_m, self.nominal.optimal.L_m])
        return {
            "statistic": s.statistic, "scenarios": s.scenarios, "seed": s.seed,
            "starts": s.starts, "uncertainty": self.spec.to_dict(),
            "objective": "cvar95" if s.statistic == "p95" else s.statistic,
            "nominal": design(nom_x, {
                "nominal_loss_W": self.at_nominal_W["nominal"],
                "torque_capability_Nm": self.nominal.optimal.torque_capability_Nm,
                "inertia_kgm2": self.nominal.optimal.inertia_kgm2,
                "mc": self.mc["nominal"]}),
            "robust": design(self.robust.x_m, {
                "nominal_loss_W": self.at_nominal_W["robust"],
                "torque_capability_Nm": self.robust.optimal.torque_capability_Nm,
                "inertia_kgm2": self.robust.optimal.inertia_kgm2,
                "objective_W": self.robust.objective_W,
                "in_sample": empirical_stats(self.robust.losses_W),
                "status": self.robust.status, "iterations": self.robust.iterations,
                "solve_time_s": self.robust.solve_time_s, "mc": self.mc["robust"]}),
            "price_of_robustness_W": self.price_W, "p95_gain_W": self.p95_gain_W,
            "same_design": self.same_design,
            "monte_carlo": {"samples": s.mc_samples, "seed": self.mc_seed, "mode": self.mode,
                            "path": "joint_loss_arrays (vectorised, case's C_m)"},
            "stability": {"scenarios": 2 * s.scenarios,
                          "design_change_mm": self.design_change_mm,
                          "objective_W": self.doubled.objective_W,
                          "statistic_change": self.statistic_change,
                          "in_sample_change": self.in_sample_change,
                          "design_tol_of_range": STABILITY_DESIGN_TOL,
                          "statistic_tol": STABILITY_STAT_TOL, "stable": self.stable},
            "build_time_s": self.build_time_s, "pareto": list(self.pareto),
        }


def design_x(res: DesignResult) -> np.ndarray:
    """(R, delta, d_r, d_s, L) [m] of a DesignResult's optimum.

    Parameters
    ----------
    res : DesignResult
        A nominal optimum.

    Returns
    -------
    ndarray of 5 floats
        [m].
    """
    o = res.optimal
    return np.array([o.R_m, o.delta_m, o.rotor_groove_depth_m, o.stator_groove_depth_m, o.L_m])


def monte_carlo(case: DesignCase, x_m: np.ndarray, machined_m: tuple[float, float],
                sample: dict, mode: str = "none") -> np.ndarray:
    """Loss of design ``x_m`` over a sample of the uncertain inputs (vectorised path).

    Parameters
    ----------
    case : DesignCase
        The nominal case.
    x_m : ndarray of 5 floats
        (R, delta, d_r, d_s, L) [m].
    machined_m : (float, float)
        Machined groove depths d_r0, d_s0 [m].
    sample : dict of str -> ndarray
        The inputs' values [their units].
    mode : str
        Thermal mode (``none`` or ``bulk``).

    Returns
    -------
    ndarray
        Loss of each draw under ``mode``, the case's C_m [W].

    Raises
    ------
    SolverError
        A draw without a loss.
    """
    dc = design_case(case, x_m, machined_m)
    return np.asarray(joint_loss_arrays(dc, sample, mode=mode, strict=True), dtype=float)


def _at_nominal(case: DesignCase, x_m: np.ndarray, machined_m: tuple[float, float],
                mode: str) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        return float(evaluate_case(design_case(case, x_m, machined_m),
                                   thermal=mode).total_mean_power_W)


def robust_design(case: DesignCase, settings: RobustSettings | None = None,
                  spec: UncertaintySpec | None = None, verbose: bool = False,
                  mode: str = "none", **limits: Any) -> RobustDesign:
    """Nominal and robust optimum, the independent Monte Carlo and the 2N stability check.

    Parameters
    ----------
    case : DesignCase
        The joint.
    settings : RobustSettings, optional
        Statistic, N, seed, starts, Monte Carlo draws, Pareto points (default: p95, 64, 0).
    spec : UncertaintySpec, optional
        The uncertain inputs (default: :func:`~oilgap.model.uncertain.case_uncertainty`).
    verbose : bool
        Let IPOPT print its iterations.
    mode : str
        Thermal mode: ``none`` (isothermal oil at each scenario's temperature) or ``bulk``
        (each scenario at its own heat balance; needs ``[thermal]``; no Pareto).
    **limits
        ``torque_min_Nm`` [N m], ``inertia_max_ratio`` [-] (None: the case's).

    Returns
    -------
    RobustDesign

    Raises
    ------
    InputError, InfeasibleError, SolverError
        Bad input; constraints that conflict; IPOPT failing.
    """
    s = settings or RobustSettings()
    spec = spec or case_uncertainty(case)
    lim = {k: v for k, v in limits.items() if v is not None}
    if mode == "bulk" and s.pareto_points:
        raise InputError("--pareto", s.pareto_points, "under thermal mode none only",
                         "optimize")
    task = "robust optimize: nominal, N, 2N, Monte Carlo"
    report(task, 0, 4)
    prob = DesignProblem(case, verbose=verbose, thermal=mode)
    nominal = prob.solve(starts=s.starts, seed=s.seed, **lim)
    x_nom = design_x(nominal)
    report(task, 1, 4)
    t0 = time.perf_counter()
    rp = RobustDesignProblem(prob, spec.sample(s.scenarios, s.seed), s.statistic)
    build = time.perf_counter() - t0
    robust = rp.solve(x_nom, starts=s.starts, seed=s.seed, **lim)
    report(task, 2, 4)
    rp2 = RobustDesignProblem(prob, spec.sample(2 * s.scenarios, s.seed), s.statistic)
    doubled = rp2.solve(robust.x_m, starts=s.starts, seed=s.seed, **lim)
    report(task, 3, 4)
    machined = (prob.machined_rotor_groove_m, prob.machined_stator_groove_m)
    sample = spec.sample(s.mc_samples, s.seed + MC_SEED_OFFSET)
    mc_l = {k: monte_carlo(case, x, machined, sample, mode)
            for k, x in (("nominal", x_nom), ("robust", robust.x_m), ("doubled", doubled.x_m))}
    at_nom = {k: _at_nominal(case, x, machined, mode)
              for k, x in (("nominal", x_nom), ("robust", robust.x_m))}
    front = robust_pareto(rp, x_nom, robust, s.pareto_points, lim) if s.pareto_points else []
    for row in front:  # each front point's p95 on the independent Monte Carlo too
        x = np.array([row[VARIABLE_LABELS[v][0]] for v in VARIABLES]) * MM_TO_M
        row["mc_p95_W"] = float(np.percentile(monte_carlo(case, x, machined, sample, mode), 95))
    report(task, 4, 4)
    return RobustDesign(case=case, mode=mode, settings=s, spec=spec, nominal=nominal,
                        robust=robust,
                        doubled=doubled, at_nominal_W=at_nom,
                        mc={k: empirical_stats(v) for k, v in mc_l.items()}, mc_losses_W=mc_l,
                        build_time_s=build, pareto=front)


def _pareto_row(eps_W: float, r: RobustSolve) -> dict:
    row = {"eps_W": float(eps_W), "nominal_loss_W": r.optimal.mean_power_W,
           "objective_W": r.objective_W, "p95_W": empirical_stats(r.losses_W)["p95_W"]}
    row.update({VARIABLE_LABELS[v][0]: float(xv) / MM_TO_M
                for v, xv in zip(VARIABLES, r.x_m, strict=True)})
    return row


def robust_pareto(rp: RobustDesignProblem, x_nom: np.ndarray, robust: RobustSolve,
                  points: int, limits: dict) -> list[dict]:
    """The front of nominal loss against the statistic (epsilon constraint).

    Minimise the statistic subject to nominal loss <= eps, eps spread evenly from the
    nominal optimum's nominal loss to the robust optimum's (smooth C_m, the NLP's), each
    solve warm-started from its neighbour.

    Parameters
    ----------
    rp : RobustDesignProblem
        The robust NLP.
    x_nom : ndarray
        The nominal optimum [m].
    robust : RobustSolve
        The robust optimum (the front's other end).
    points : int
        Points of the front [-].
    limits : dict
        The solves' limits (``torque_min_Nm``, ``inertia_max_ratio``).

    Returns
    -------
    list of dict
        ``eps_W``, ``nominal_loss_W`` (smooth C_m), ``objective_W``, ``p95_W`` (in
        sample) and the design [mm] of each point; one point when the two optima
        coincide.
    """
    lo_w = rp.problem.point(x_nom).mean_power_W
    hi_w = robust.optimal.mean_power_W
    rows = [_pareto_row(hi_w, robust)]  # the robust optimum: its own eps
    if hi_w - lo_w > 1e-6 * abs(hi_w):
        x = robust.x_m
        for e in np.linspace(hi_w, lo_w * (1 + 1e-7), points)[1:]:
            try:
                r = rp.solve(x, starts=1, nominal_max_W=float(e), **limits)
            except SolverError:
                continue
            x = r.x_m
            rows.append(_pareto_row(float(e), r))
    return rows[::-1]


__all__ = ["DEFAULT_SCENARIOS", "MC_SAMPLES", "MC_SEED_OFFSET", "RobustDesign",
           "RobustSettings", "STABILITY_DESIGN_TOL", "STABILITY_STAT_TOL", "design_x",
           "monte_carlo", "robust_design", "robust_pareto"]
