"""Stage 3b of the calibration: the base law chosen by its honest held-out error, after
each candidate's own effect search.

Each candidate base (:func:`base_candidates`: Eq. 6 with one shared gap exponent,
``branches`` with each regime's own C_k, alpha_k, beta_k, freed where identified, and
Eq. 6 with the Taylor transition) is decided (:func:`.spec.decide_spec`), fitted on all
oil runs and given the loop's effect search (:func:`.search.search_effects`); its base
and accepted effects are cross-validated on the loop's folds (:mod:`.folds`), each fold
refitted with only its training groups and the parameters it cannot identify at their
priors (:mod:`.refit`). Compared before the search, a flexible base takes in an effect's
share and wins by hiding it (on the out-of-family rig ``branches`` won and the vortex
effect's held-out cut fell from 83 % to 42 %); after it, each base has its effects. They
are compared on the held-out **log**-RMSE, ``sqrt(mean(ln(P_heldout / P_measured)^2))``
over the samples whose measured power stands above :data:`NOISE_FLOOR` noise levels
(the successive-difference noise of the first candidate's base residual,
:func:`.residuals.residual_structure`; below it the logarithm measures the noise and
the baseline, not the law): a law's job is the shape of C_m across regimes, and the
power of a campaign spans decades (it grows as omega^3), so an RMSE in W would judge
only the fastest points.
The best is kept unless a simpler candidate (fewer free parameters of base and accepted
effects) comes within the parsimony margin (the effect selection's, default 10 %) of it:
the most complex model must earn its place out of sample, as an effect must [1].

A candidate is a :class:`BaseCandidate`: a base form and a hook on the rig case
(:attr:`BaseCandidate.case_of`), so a law option of the case (a transition rule of
the friction law, say) enters as one more candidate without changing this stage.

References
----------
.. [1] M. Stone, "Cross-validatory choice and assessment of statistical
   predictions", J. R. Stat. Soc. B 36:111-147, 1974.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace

import numpy as np

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, SolverError

from .forward import ForwardModel
from .least_squares import ModelFit, check_alpha, fit_model, initial_guess
from .residuals import residual_structure
from .spec import BaseSpec, decide_spec


def _same_case(case: DesignCase) -> DesignCase:
    return case


@dataclass(frozen=True, kw_only=True)
class BaseCandidate:
    """One base law the loop may choose.

    Parameters
    ----------
    name : str
        Name in the report and in ``loop.json`` (``"eq6"``, ``"branches"``, ...).
    base : {"eq6", "branches", "power-law"}
        The base form (:data:`.spec.BASES`).
    case_of : callable
        Rig case -> the case this candidate is fitted on (default: as it is); the hook
        for a law option of the case's ``[friction]``.
    """

    name: str
    base: str
    case_of: Callable[[DesignCase], DesignCase] = field(default=_same_case)


NOISE_FLOOR = 3.0
"""Noise levels a measured power must exceed to enter the log score [-]."""

AUTO_BASE = "auto"
"""The ``base`` that lets the held-out error choose among :func:`base_candidates` (the
default)."""


def _taylor_transition(case: DesignCase) -> DesignCase:
    return replace(case, friction=replace(case.friction, transition="taylor"))


BASE_CANDIDATES = (BaseCandidate(name="eq6", base="eq6"),
                   BaseCandidate(name="branches", base="branches"),
                   BaseCandidate(name="eq6-taylor", base="eq6", case_of=_taylor_transition))
"""The candidate bases of ``base = "auto"`` (the default), in order of preference at a tie:
Eq. 6 with the case's transition, ``branches``, and Eq. 6 exact Couette up to Ta_c
(``[friction] transition = "taylor"``, issue 27) where the case's law allows it
(:func:`base_candidates`). Each is compared after its own effect search. The free power
law is not one: its free Reynolds slope absorbs a missing effect's share before the search
sees it (issue 9: beta went to -0.16 and took in an effect the data carried; a bearing's
drag on the seed rig is taken for a steeper law). It stays available as
``--base power-law``."""


def base_candidates(case: DesignCase) -> tuple[BaseCandidate, ...]:
    """The candidates of ``base = "auto"`` for a rig case: :data:`BASE_CANDIDATES`, the
    Taylor transition only where it is a different law the case's friction allows (an
    Eq. 6 form with the Couette laminar law, the transition not already ``taylor``).

    Parameters
    ----------
    case : DesignCase
        The rig case (its friction law's form [-], laminar law [-] and transition [-]).

    Returns
    -------
    tuple of BaseCandidate
        In order of preference at a tie [-].
    """
    f = case.friction
    taylor_ok = (f.transition == "reynolds" and f.laminar_law == "couette"
                 and f.form in ("bilgen-boulos", "smooth"))
    return tuple(c for c in BASE_CANDIDATES if c.case_of is not _taylor_transition or taylor_ok)


@dataclass
class BaseTrial:
    """One candidate base fitted, its effects searched, and cross-validated.

    Attributes
    ----------
    candidate : BaseCandidate
    spec : BaseSpec or None
    fit : ModelFit or None
        The base alone.
    stmt : dict
        Identifiability statements.
    heldout_pred : array or None
        Each sample predicted by the fold without its group, base with its accepted
        effects [W].
    log_rmse, heldout_log_rmse : float
        In-sample and held-out log-RMSE of base and effects [-] (NaN if the fit failed),
        over the ``scored`` samples above the noise (all positive ones when ``scored`` is 0).
    rmse_W, heldout_rmse_W : float
        The same in W.
    error : str
        Why the candidate could not be fitted ("" if it was).
    search : EffectSearch or None
        The candidate's own effect search (:func:`.search.search_effects`).
    base_heldout_log_rmse : float
        Held-out log-RMSE of the base alone [-] (what a comparison before the effect
        search would have seen).
    taylor_exponent : float
        The forward model's Taylor shape after this candidate's search [-].
    """

    candidate: BaseCandidate
    spec: BaseSpec | None
    fit: ModelFit | None
    stmt: dict
    heldout_pred: np.ndarray | None
    log_rmse: float
    heldout_log_rmse: float
    rmse_W: float
    heldout_rmse_W: float
    error: str = ""
    scored: int = 0
    search: object = None
    base_heldout_log_rmse: float = float("nan")
    taylor_exponent: float = 2.0

    @property
    def effects(self) -> list[str]:
        """The effects its search accepted."""
        return list(self.search.final.accepted) if self.search is not None else []

    @property
    def n_free(self) -> int:
        """Free parameters of the base and its accepted effects [-] (its complexity)."""
        return (len(self.spec.free) if self.spec is not None else 0) + len(self.effects)

    def row(self, chosen: str) -> dict:
        """The trial as a row of the report's table and of ``loop.json`` ``base_selection``."""
        return {"base": self.candidate.name, "free_parameters": self.n_free,
                "effects": self.effects, "base_heldout_log_rmse": self.base_heldout_log_rmse,
                "log_rmse": self.log_rmse, "heldout_log_rmse": self.heldout_log_rmse,
                "rmse_W": self.rmse_W, "heldout_rmse_W": self.heldout_rmse_W,
                "scored_samples": self.scored,
                "chosen": self.candidate.name == chosen, **({"error": self.error}
                                                            if self.error else {})}


def log_rmse(y: np.ndarray, pred: np.ndarray) -> float:
    """Root mean square of ``ln(pred / y)`` over the samples where both are positive [-].

    Parameters
    ----------
    y, pred : arrays
        Measured and model power [W].

    Returns
    -------
    float
        Log-RMSE [-] (NaN if no sample qualifies).
    """
    ok = (y > 0) & (pred > 0) & np.isfinite(pred)
    return float(np.sqrt(np.mean(np.log(pred[ok] / y[ok]) ** 2))) if ok.any() else float("nan")


LAMINAR_SHARE = 0.5
"""Power-weighted share of the samples at the Couette floor above which a fitted scale below
where the floor starts is bounded there [-]: a smaller scale cannot lower the loss (the
floor holds it), and a fit left free would run the scale to nothing (issue 27 item 4)."""


FLOOR_WITHIN = 0.9
"""A sample is at the Couette floor when its Couette loss is at least this share of the
law's at scale 1 [-] (the smooth form's max lies up to a few % above Couette)."""


def laminar_share(model: ForwardModel, spec: BaseSpec) -> tuple[float, float]:
    """Power-weighted share of the samples whose loss at the published level (scale 1) is
    exact Couette flow [-] (0 without the Couette laminar law), and the least scale that
    keeps every one of them at or above Couette [-].

    Parameters
    ----------
    model : ForwardModel
    spec : BaseSpec

    Returns
    -------
    (float, float)
        ``sum(P at the floor) / sum(P)`` [-] and ``max(P_Couette / P)`` over those samples.
    """
    if spec.laminar_law != "couette" or "scale" not in spec.free:
        return 0.0, 0.0
    law = spec.law(spec.start({**spec.prior_values(), **spec.fixed, "scale": 1.0}))
    p = model.base_power(replace(law, gamma=0.0))
    cc = model.couette_power()
    tot = float(np.sum(np.abs(p)))
    at_floor = (cc >= FLOOR_WITHIN * p) & (p > 0)  # the smooth max: a few % above Couette
    if tot <= 0 or not at_floor.any():
        return 0.0, 0.0
    return (float(np.sum(np.abs(p)[at_floor]) / tot),
            min(1.0, float(np.max(cc[at_floor] / p[at_floor]))))


def fit_base(model: ForwardModel, case: DesignCase, base: str) -> tuple[BaseSpec, ModelFit, dict]:
    """Decide and fit one base on all oil runs (the loop's stage 3).

    Parameters
    ----------
    model : ForwardModel
    case : DesignCase
        Rig case (its friction law: laminar law, gamma).
    base : str
        Base form.

    Returns
    -------
    (BaseSpec, ModelFit, dict)
        Specification, fit (its prediction in W [W]) and identifiability statements.
    """
    spec, stmt = decide_spec(model.samples, model.geometry, case, base)
    spec, stmt = check_alpha(model, spec, stmt)
    fit = fit_model(model, spec, initial_guess(model, spec))
    share, floor = laminar_share(model, spec)
    if share >= LAMINAR_SHARE and spec.values(fit.x).get("scale", 1.0) < floor:
        # the fit wants to go below the Couette floor, which governs the data: bounded there
        spec = replace(spec, scale_min=floor)
        stmt = {**stmt, "scale": f"{stmt.get('scale', 'identified')}; bounded below by "
                f"{floor:.4g}: {100 * share:.0f} % of the power is at the exact Couette "
                "floor, which no calibration goes below"}
        fit = fit_model(model, spec, initial_guess(model, spec))
    return spec, fit, stmt


def try_base(model: ForwardModel, case: DesignCase, cand: BaseCandidate,
             search_of: Callable) -> BaseTrial:
    """Fit one candidate, search its effects, and keep its held-out predictions.

    Parameters
    ----------
    model : ForwardModel
    case : DesignCase
    cand : BaseCandidate
    search_of : callable
        ``(spec, fit) -> EffectSearch``: the loop's effect search on this calibration
        (:func:`.search.search_effects` with the loop's options); its folds give both
        held-out errors, of the base alone and of the base with its accepted effects.

    Returns
    -------
    BaseTrial
        Its fit, search, held-out predictions [W] and errors (log [-], RMSE [W]).
    """
    y = model.samples.viscous_W
    te = model.taylor_exponent
    try:
        spec, fit, stmt = fit_base(model, cand.case_of(case), cand.base)
        search = search_of(spec, fit)
    except (SolverError, InputError) as e:
        nan = float("nan")
        return BaseTrial(cand, None, None, {}, None, log_rmse=nan, heldout_log_rmse=nan,
                         rmse_W=nan, heldout_rmse_W=nan, error=str(e))
    finally:
        state, model.taylor_exponent = model.taylor_exponent, te
    final = search.final
    ho = final.after.pred
    return BaseTrial(cand, spec, fit, stmt, ho, log_rmse=log_rmse(y, final.fit.pred),
                     heldout_log_rmse=log_rmse(y, ho),
                     rmse_W=float(np.sqrt(np.mean((final.fit.pred - y) ** 2))),
                     heldout_rmse_W=float(np.sqrt(np.mean((ho - y) ** 2))),
                     search=search, base_heldout_log_rmse=log_rmse(y, final.before.pred),
                     taylor_exponent=state)


def choose(trials: list[BaseTrial], margin: float) -> BaseTrial:
    """The base kept: the least held-out log-RMSE, or a simpler one within ``margin``.

    Parameters
    ----------
    trials : list of BaseTrial
        In order of preference at a tie.
    margin : float
        A more complex model (base and its effects) must lower the held-out log-RMSE by
        this share [-].

    Returns
    -------
    BaseTrial
    """
    ok = [t for t in trials if np.isfinite(t.heldout_log_rmse)]
    if not ok:
        raise SolverError("no candidate base law could be fitted: "
                          + "; ".join(f"{t.candidate.name}: {t.error}" for t in trials))
    best = min(t.heldout_log_rmse for t in ok)
    near = [t for t in ok if t.heldout_log_rmse * (1.0 - margin) <= best]
    return min(near, key=lambda t: (t.n_free, ok.index(t)))


def _score_above_noise(trials: list[BaseTrial], model: ForwardModel) -> None:
    """Log scores over the samples above :data:`NOISE_FLOOR` noise levels (of the first
    fitted candidate's base residual), when at least 3 qualify."""
    y = model.samples.viscous_W
    first = next((t for t in trials if t.fit is not None), None)
    if first is None:
        return
    noise = float(residual_structure(y - first.fit.pred, model.samples)["noise_W"])
    sel = y > NOISE_FLOOR * noise
    if sel.sum() < 3:
        return
    for t in trials:
        if t.fit is not None:
            final = t.search.final
            t.log_rmse = log_rmse(y[sel], final.fit.pred[sel])
            t.heldout_log_rmse = log_rmse(y[sel], t.heldout_pred[sel])
            t.base_heldout_log_rmse = log_rmse(y[sel], final.before.pred[sel])
            t.scored = int(sel.sum())


def select_base(model: ForwardModel, case: DesignCase, margin: float, search_of: Callable,
                candidates: tuple[BaseCandidate, ...] | None = None
                ) -> tuple[BaseTrial, list[dict]]:
    """Fit every candidate base with its own effect search, keep the one the held-out
    error of base and accepted effects supports.

    Parameters
    ----------
    model : ForwardModel
    case : DesignCase
    margin : float
        Parsimony margin [-].
    search_of : callable
        ``(spec, fit) -> EffectSearch`` (:func:`try_base`).
    candidates : tuple of BaseCandidate, optional
        Default: :func:`base_candidates` of ``case``.

    Returns
    -------
    (BaseTrial, list of dict)
        The chosen trial (the forward model left at its Taylor shape) and the comparison
        table (one row per candidate).
    """
    cands = base_candidates(case) if candidates is None else candidates
    trials = [try_base(model, case, c, search_of) for c in cands]
    _score_above_noise(trials, model)
    chosen = choose(trials, margin)
    model.taylor_exponent = chosen.taylor_exponent
    return chosen, [t.row(chosen.candidate.name) for t in trials]
