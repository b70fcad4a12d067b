"""Stage 3b of the calibration: the base law chosen by its honest held-out error.

Each candidate base (:data:`BASE_CANDIDATES`: Eq. 6 with one shared gap exponent and
``branches`` with each regime's own C_k, alpha_k, beta_k, freed where identified) is
decided (:func:`.spec.decide_spec`), fitted on all oil runs and cross-validated on
the loop's folds (:mod:`.folds`), each fold refitted with only its training groups
and the parameters it cannot identify at their priors (:mod:`.refit`). They are
compared on the held-out **log**-RMSE, ``sqrt(mean(ln(P_heldout / P_measured)^2))``
over the samples whose measured power stands above :data:`NOISE_FLOOR` noise levels
(the successive-difference noise of the simplest candidate's residual,
:func:`.residuals.residual_structure`; below it the logarithm measures the noise and
the baseline, not the law): a law's job is the shape of C_m across regimes, and the
power of a campaign spans decades (it grows as omega^3), so an RMSE in W would judge
only the fastest points.
The best is kept unless a simpler candidate (fewer free parameters) comes within
the parsimony margin (the effect selection's, default 10 %) of it: the most complex
base must earn its place out of sample, as an effect must [1].

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
from oilgap.model.errors import SolverError

from .forward import ForwardModel
from .least_squares import ModelFit, check_alpha, fit_model, initial_guess
from .refit import Refitter
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
"""The ``base`` that lets the held-out error choose among :data:`BASE_CANDIDATES`."""

BASE_CANDIDATES = (BaseCandidate(name="eq6", base="eq6"),
                   BaseCandidate(name="branches", base="branches"))
"""The candidate bases of ``base = "auto"`` (the default), in order of preference at a tie.
The free power law is not one: the bases are compared before the effect search, and its
free Reynolds slope absorbs a missing effect's share (issue 9: beta went to -0.16 and took
in an effect the data carried; a bearing's drag on the seed rig is taken for a steeper
law), so it would win by hiding the effect. It stays available as ``--base power-law``."""


@dataclass
class BaseTrial:
    """One candidate base fitted and cross-validated.

    Attributes
    ----------
    candidate : BaseCandidate
    spec : BaseSpec or None
    fit : ModelFit or None
    stmt : dict
        Identifiability statements.
    heldout_pred : array or None
        Each sample predicted by the fold without its group [W].
    log_rmse, heldout_log_rmse : float
        In-sample and held-out log-RMSE [-] (NaN if the fit failed), over the
        ``scored`` samples above the noise (all positive ones when ``scored`` is 0).
    rmse_W, heldout_rmse_W : float
        The same in W.
    error : str
        Why the candidate could not be fitted ("" if it was).
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

    @property
    def n_free(self) -> int:
        """Free parameters of the base [-] (its complexity)."""
        return len(self.spec.free) if self.spec is not None else 0

    def row(self, chosen: str) -> dict:
        """The trial as a row of the report's table and of ``loop.json`` ``base_selection``."""
        return {"base": self.candidate.name, "free_parameters": self.n_free,
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


def try_base(model: ForwardModel, case: DesignCase, cand: BaseCandidate, cv: str) -> BaseTrial:
    """Fit one candidate and cross-validate it on the loop's folds.

    Parameters
    ----------
    model : ForwardModel
    case : DesignCase
    cand : BaseCandidate
    cv : {"one-step", "full"}
        Fold refits (as the loop's).

    Returns
    -------
    BaseTrial
        Its fit, held-out predictions [W] and errors (log [-], RMSE [W]).
    """
    y = model.samples.viscous_W
    try:
        spec, fit, stmt = fit_base(model, cand.case_of(case), cand.base)
        ho = Refitter(model, spec, {}, cv).leave_one_run_out((), fit.x, None, fit).pred
    except SolverError as e:
        nan = float("nan")
        return BaseTrial(cand, None, None, {}, None, log_rmse=nan, heldout_log_rmse=nan,
                         rmse_W=nan, heldout_rmse_W=nan, error=str(e))
    return BaseTrial(cand, spec, fit, stmt, ho, log_rmse=log_rmse(y, fit.pred),
                     heldout_log_rmse=log_rmse(y, ho),
                     rmse_W=float(np.sqrt(np.mean((fit.pred - y) ** 2))),
                     heldout_rmse_W=float(np.sqrt(np.mean((ho - y) ** 2))))


def choose(trials: list[BaseTrial], margin: float) -> BaseTrial:
    """The base kept: the least held-out log-RMSE, or a simpler one within ``margin``.

    Parameters
    ----------
    trials : list of BaseTrial
        In order of preference at a tie.
    margin : float
        A more complex base must lower the held-out log-RMSE by this share [-].

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


def select_base(model: ForwardModel, case: DesignCase, margin: float, cv: str,
                candidates: tuple[BaseCandidate, ...] = BASE_CANDIDATES
                ) -> tuple[BaseTrial, list[dict]]:
    """Fit every candidate base, keep the one the held-out error supports.

    Parameters
    ----------
    model : ForwardModel
    case : DesignCase
    margin : float
        Parsimony margin [-].
    cv : {"one-step", "full"}
    candidates : tuple of BaseCandidate

    Returns
    -------
    (BaseTrial, list of dict)
        The chosen trial and the comparison table (one row per candidate).
    """
    trials = [try_base(model, case, c, cv) for c in candidates]
    y = model.samples.viscous_W
    first = next((t for t in trials if t.fit is not None), None)
    if first is not None:  # the log scores on the samples above the noise
        noise = float(residual_structure(y - first.fit.pred, model.samples)["noise_W"])
        sel = y > NOISE_FLOOR * noise
        if sel.sum() >= 3:
            for t in trials:
                if t.fit is not None:
                    t.log_rmse = log_rmse(y[sel], t.fit.pred[sel])
                    t.heldout_log_rmse = log_rmse(y[sel], t.heldout_pred[sel])
                    t.scored = int(sel.sum())
    chosen = choose(trials, margin)
    return chosen, [t.row(chosen.candidate.name) for t in trials]
