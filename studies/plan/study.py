"""Plan a rig campaign: the optimal plan and the naive plan of the same size, compared.

1. Every candidate run (:func:`~.candidates.candidate_runs`) is simulated and its Fisher
   information taken from the loop's forward model (:mod:`oilgap.studies.plan.candidates`).
2. The design's parameters are the base law's free ones and the effects the candidates
   can tell from them (an effect confounded with the base on *every* candidate, e.g. an
   end disc that scales like the annulus, cannot be planned for and is reported).
3. The continuous design (D, A, E or T) is solved with cvxpy and rounded to whole runs
   (:mod:`oilgap.optim.planning.design`).
4. **Costs, by whole plots.** Oil and rotor are hard to change: the chosen runs are
   sequenced rotor by rotor, oil by oil, bath temperature within an oil (whole plots),
   and the plan's rig time is counted on that sequence (each run, each oil, temperature
   and rotor change). A budget in hours sets the number of runs: the largest whose
   sequenced plan fits. The convex problem itself carries no cost term: a change's cost
   is shared by the runs of a plot, which is not a per-run cost.
5. The plan and the naive plan (the full factorial in the order rotor x oil first, at the
   first bath temperature and profile, then the others) are both evaluated: expected sd
   of each base parameter (``A^-1 B A^-1``, the least-squares sandwich) and the interval
   the loop will report (its delete-a-group jackknife's expected sd with its t quantile),
   the smallest detectable size of each effect, confounded pairs and directions
   (:mod:`oilgap.optim.planning.analysis`).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np
from scipy import stats

from oilgap.optim.calibration.folds import MAX_FOLDS, grouped_folds
from oilgap.optim.calibration.spec import LOG_PARAMS
from oilgap.optim.planning.analysis import (
    SINGULAR_TOL,
    base_sd,
    confounding,
    detectable_sizes,
    jackknife_sd,
)
from oilgap.optim.planning.design import (
    ContinuousDesign,
    efficient_rounding,
    equivalence_gap,
    normalise,
    optimal_weights,
)
from oilgap.optim.planning.floor import floored_half_width

from .candidates import Candidate, CandidateSet, candidate_information
from .settings import PlanSettings

DESIGN_TOL = 1e-4
"""Smallest eigenvalue of the candidates' pooled, correlation-scaled information that a
parameter may bring into the design criterion (below: confounded on every candidate)."""


@dataclass
class PlanEvaluation:
    """What one plan identifies (see :mod:`oilgap.optim.planning.analysis`); ``info`` and
    ``meat`` are its information ``A`` and noise meat ``B`` over all parameters
    (``CandidateSet.params.names``) [unit^-2]."""

    runs: list[Candidate]
    counts: np.ndarray
    sd: dict
    jack_sd: dict
    interval: dict
    detectable: dict
    explained: dict
    confounded: dict
    cost_h: float
    changes: dict
    log_det: float
    info: np.ndarray
    meat: np.ndarray
    floor: dict = field(default_factory=dict)


@dataclass
class PlanResult:
    """The plan, the naive plan, and how the design was found."""

    settings: PlanSettings
    candidates: CandidateSet
    design_params: tuple[str, ...]
    design: ContinuousDesign
    plan: PlanEvaluation
    naive: PlanEvaluation
    excluded: dict
    d_efficiency: float

    def summary(self) -> str:
        """The terminal text of ``oilgap plan``: the answer first, then the tables."""
        from .report import summary_lines
        return "\n".join(summary_lines(self))


def design_parameters(cs: CandidateSet) -> tuple[list[int], dict]:
    """Indices of the parameters the design targets, and why the others are left out.

    Base parameters with information come first; an effect is added in the library's
    order if the pooled information stays nonsingular (:data:`DESIGN_TOL`).
    """
    pooled = cs.info.mean(axis=0)
    names = cs.params.names
    keep, why = [], {}
    for i, n in enumerate(names):
        if not pooled[i, i] > 0:
            why[n] = "no information on any candidate run (its column is zero)"
            continue
        trial = keep + [i]
        lam = np.linalg.eigvalsh(_corr(pooled[np.ix_(trial, trial)]))[0]
        if lam > DESIGN_TOL:
            keep = trial
        else:
            why[n] = ("confounded on every candidate run with "
                      + _partner(pooled, i, keep, names))
    return keep, why


def _corr(M):
    d = np.sqrt(np.diag(M))
    return M / d[:, None] / d[None, :]


def _partner(M, i, keep, names) -> str:
    """The kept parameters that explain column i best (their R^2 in the information)."""
    if not keep:
        return "nothing"
    A = M[np.ix_(keep, keep)]
    b = M[keep, i]
    coef = np.linalg.lstsq(A, b, rcond=None)[0]
    r2 = float(b @ coef / M[i, i])
    top = [names[keep[j]] for j in np.argsort(-np.abs(coef * np.sqrt(np.diag(A))))[:2]]
    return f"{' and '.join(top)} (R^2 = {min(r2, 1.0):.6f})"


def sequence(runs: list[Candidate], settings: PlanSettings) -> list[Candidate]:
    """The runs in whole plots: rotor, then oil, then pressure, bath and profile."""
    rank = {f: {v: i for i, v in enumerate(getattr(settings, f))}
            for f in ("roughness", "oils", "pressures_MPa", "bath_C", "profiles")}
    return sorted(runs, key=lambda r: (rank["roughness"].get(r.roughness_T, 99),
                                       rank["oils"].get(r.oil, 99),
                                       rank["pressures_MPa"].get(r.pressure_MPa, 99),
                                       rank["bath_C"].get(r.bath_C, 99),
                                       rank["profiles"].get(r.profile, 99)))


def plan_cost(runs: list[Candidate], settings: PlanSettings) -> tuple[float, dict]:
    """Rig time of the runs in their order [h] and the changes counted."""
    ch = {"rotor": 0, "oil": 0, "temperature": 0}
    for a, b in zip(runs, runs[1:], strict=False):
        ch["rotor"] += a.roughness_T != b.roughness_T
        ch["oil"] += a.oil != b.oil or a.roughness_T != b.roughness_T
        ch["temperature"] += a.bath_C != b.bath_C
    cost = (len(runs) * settings.run_cost_h + ch["rotor"] * settings.rotor_change_h
            + ch["oil"] * settings.oil_change_h + ch["temperature"] * settings.temp_change_h)
    return float(cost), ch


def naive_runs(settings: PlanSettings, n: int) -> list[Candidate]:
    """The full factorial's first n runs, rotor x oil fastest (the seed rig's habit)."""
    full = [Candidate(o, float(T), float(b), pr, float(p)) for pr, b, p, T, o in
            itertools.product(settings.profiles, settings.bath_C, settings.pressures_MPa,
                              settings.roughness, settings.oils)]
    return [full[i % len(full)] for i in range(n)]


def evaluate(cs: CandidateSet, runs: list[Candidate], settings: PlanSettings
             ) -> PlanEvaluation:
    """Expected sds, intervals, detectable sizes and confounding of a plan."""
    index = {r: i for i, r in enumerate(cs.runs)}
    counts = np.zeros(len(cs.runs), dtype=int)
    for r in runs:
        counts[index[r]] += 1
    M = np.einsum("i,ijk->jk", counts, cs.info)
    B = np.einsum("i,ijk->jk", counts, cs.meat)
    q = len(cs.spec.free)
    sd = base_sd(M, q, B)
    idx = [index[r] for r in runs]
    folds = grouped_folds(np.arange(len(runs)), MAX_FOLDS)
    held = _held(cs, runs, folds)
    jsd = jackknife_sd(cs.info[idx][:, :q, :q], cs.meat[idx][:, :q, :q], folds, held)
    g = min(len(runs), MAX_FOLDS)
    t = stats.t.ppf(0.975, g - 1) if g >= 3 else math.inf
    sds = {k: float(sd[i]) for i, k in enumerate(cs.spec.free)}
    jsds = {k: float(jsd[i]) for i, k in enumerate(cs.spec.free)}
    ivs, floor = _intervals(cs, idx, jsd, t, jackknife_sd(
        cs.floor_info[idx], cs.floor_meat[idx], folds, held))
    size, r2 = detectable_sizes(M, q, B)
    eff = cs.params.names[q:]
    ordered = sequence(runs, settings)
    cost, ch = plan_cost(ordered, settings)
    sign, ld = np.linalg.slogdet(normalise(M[None])[0][0]) if M.any() else (0, -math.inf)
    return PlanEvaluation(runs=ordered, counts=counts, sd=sds, jack_sd=jsds, interval=ivs,
                          detectable=dict(zip(eff, map(float, size), strict=True)),
                          explained=dict(zip(eff, map(float, r2), strict=True)),
                          confounded=confounding(M, cs.params.names), cost_h=cost,
                          changes=ch, log_det=float(ld) if sign > 0 else -math.inf,
                          info=M, meat=B, floor=floor)


def _intervals(cs: CandidateSet, idx: list[int], jsd: np.ndarray, t: float,
               jsd_floor: np.ndarray) -> tuple[dict, dict]:
    """The loop's expected 95 % interval of each base parameter (the jackknife's expected
    sd times its t quantile; C and the scale in log space), the scale's lower half
    carried through the Couette floor's kink where it reaches it
    (:func:`~oilgap.optim.planning.floor.floored_half_width`); and, if it does, what the
    floor did (``scale``: the kink's scale, the sd below it, the linearised lower bound)."""
    vals = cs.spec.values(cs.x0)
    ivs, floor = {}, {}
    gap = float(cs.floor_gap[idx].min()) if len(idx) else math.inf
    for i, k in enumerate(cs.spec.free):
        h = t * jsd[i]
        if not math.isfinite(h):
            ivs[k] = [math.nan, math.nan]
            continue
        lo = floored_half_width(h, gap, jsd[i], jsd_floor[i]) if k == "scale" else h
        if k in LOG_PARAMS:
            ivs[k] = [vals[k] * math.exp(-lo), vals[k] * math.exp(h)]
        else:
            ivs[k] = [vals[k] - lo, vals[k] + h]
        if lo != h:
            floor[k] = {"kink": vals[k] * math.exp(-gap), "jack_sd_below": float(jsd_floor[i]),
                        "linearised_lo": vals[k] * math.exp(-h)}
    return ivs, floor


def _held(cs: CandidateSet, runs: list[Candidate], folds: np.ndarray) -> dict:
    """Per fold, the base parameters the loop holds: gamma where the training runs have a
    single roughness T (:func:`~oilgap.optim.calibration.spec.fold_spec`)."""
    if "gamma" not in cs.spec.free:
        return {}
    g = cs.spec.free.index("gamma")
    out = {}
    for c in np.unique(folds):
        if len({r.roughness_T for r, f in zip(runs, folds, strict=True) if f != c}) < 2:
            out[c] = (g,)
    return out


def _runs_for(cs: CandidateSet, w: np.ndarray, n: int) -> list[Candidate]:
    counts = efficient_rounding(w, n)
    return [r for r, c in zip(cs.runs, counts, strict=True) for _ in range(c)]


def make_plan(settings: PlanSettings) -> PlanResult:
    """The optimal plan and the naive plan of the same size, evaluated.

    Parameters
    ----------
    settings : PlanSettings

    Returns
    -------
    PlanResult
    """
    cs = candidate_information(settings)
    keep, excluded = design_parameters(cs)
    if settings.targets == "base" and settings.criterion != "T":
        keep = [i for i in keep if i < len(cs.spec.free)]
    q = sum(1 for i in keep if i < len(cs.spec.free))
    Ms = cs.info[:, keep][:, :, keep]
    names = tuple(cs.params.names[i] for i in keep)
    eff_keep = [i - len(cs.spec.free) for i in keep if i >= len(cs.spec.free)
                and cs.params.names[i] in cs.params.effects]
    scale = None
    if settings.criterion == "T":
        scale = np.concatenate([1.0 / cs.ref[eff_keep] ** 2,
                                np.ones(len(keep) - q - len(eff_keep))])
    design = optimal_weights(Ms, settings.criterion, nuisance=q, effect_scale=scale)
    n = settings.runs
    if n is None:  # the budget in hours: the largest plan whose sequence fits
        n = 1
        while n < 1000:
            trial = sequence(_runs_for(cs, design.weights, n + 1), settings)
            if plan_cost(trial, settings)[0] > settings.budget_h:
                break
            n += 1
    runs = _runs_for(cs, design.weights, n)
    plan = evaluate(cs, runs, settings)
    naive = evaluate(cs, naive_runs(settings, n), settings)
    _, eff_rounded = equivalence_gap(normalise(Ms)[0], plan.counts, settings.criterion, q,
                                     None if scale is None else scale * normalise(Ms)[1][q:] ** 2)
    return PlanResult(settings=settings, candidates=cs, design_params=names, design=design,
                      plan=plan, naive=naive, excluded=excluded,
                      d_efficiency=float(eff_rounded))


__all__ = ["PlanEvaluation", "PlanResult", "SINGULAR_TOL", "evaluate", "make_plan",
           "naive_runs", "plan_cost", "sequence"]
