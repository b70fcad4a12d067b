"""Stage 5-6 of the calibration: the effect search, with the plausibility of each fit.

Candidate columns (:mod:`oilgap.optim.calibration.candidates`), the linearised selection
(:mod:`.selection`) and the nonlinear refit (:mod:`.refit`), repeated while an
accepted effect's fitted coefficient is outside its plausible range
(:attr:`oilgap.model.effects.Effect.plausible`): such an effect is reported as
"implausible", excluded, and the search runs again without it. The rig's
facts (its size, its fluids and whether each is polymer-thickened, a gas or a
straight mineral oil) come from the data's fluid table.

References
----------
.. [1] The plausible ranges and their sources: :mod:`oilgap.model.effects.plausibility`.
.. [2] M. Stone, "Cross-validatory choice and assessment of statistical
   predictions", J. R. Stat. Soc. B 36:111-147, 1974.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from oilgap.model.effects import EFFECTS, FluidFacts, RigFacts
from oilgap.model.measured.data import Samples
from oilgap.model.oils import normalize_oil_name

from .candidates import Candidates, screen_candidates
from .folds import cv_folds
from .forward import ForwardModel
from .least_squares import ModelFit, fit_model, rescale_level
from .refit import FinalModel, Refitter, add_state_readers, refit_selected
from .selection import Selection, Thresholds, select_effects
from .spec import BaseSpec
from .steps import SelectionStep


def fluid_facts(s: Samples, fluids: dict) -> tuple[FluidFacts, ...]:
    """The fluids of the oil runs, with their kind and whether they are polymer-thickened.

    Parameters
    ----------
    s : Samples
        Oil-run samples (fluid names).
    fluids : dict
        Normalised name -> fluid of the data's table (``kind`` and
        ``polymer_thickened`` attributes where the fluid has them; a mineral
        oil, not thickened, otherwise).

    Returns
    -------
    tuple of FluidFacts
        One per fluid name (kind, polymer-thickened [-]); a name the table does
        not hold (a per-row fluid) is of kind "unknown" and counts as Newtonian.
    """
    out = []
    for name in dict.fromkeys(np.asarray(s.oil).astype(str).tolist()):
        f = fluids.get(normalize_oil_name(name))
        if f is None:
            out.append(FluidFacts(name, "unknown", False))
        else:
            out.append(FluidFacts(name, str(getattr(f, "kind", "mineral")),
                                  bool(getattr(f, "polymer_thickened", False))))
    return tuple(out)


@dataclass(frozen=True, kw_only=True)
class SearchOptions:
    """Thresholds of the effect search (with the noise level, the selection's
    :class:`~oilgap.optim.calibration.selection.Thresholds`: :meth:`thresholds`).

    Attributes
    ----------
    margin : float
        Relative fall of the held-out RMSE each effect must bring [-].
    min_explained : float
        Share of the held-out structure above noise the effects must explain [-].
    max_effects : int
        Most effects accepted together.
    cv : str
        Fold refits: "one-step" or "full".
    has_time : bool
        False for steady-point data (no time-dependent candidates).
    """

    margin: float
    min_explained: float
    max_effects: int
    cv: str = "one-step"
    has_time: bool = True

    def thresholds(self, noise_W: float) -> Thresholds:
        """The selection's acceptance thresholds at a noise level.

        Parameters
        ----------
        noise_W : float
            Noise level of the power reading [W].

        Returns
        -------
        Thresholds
            ``margin``, ``min_explained`` and ``max_effects`` of these options.
        """
        return Thresholds(noise_W=noise_W, margin=self.margin,
                          min_explained=self.min_explained, max_effects=self.max_effects)


@dataclass(kw_only=True)
class EffectSearch:
    """The outcome of the effect search on one calibration.

    Attributes
    ----------
    spec : BaseSpec
        The calibration's specification.
    base : ModelFit
        The calibration without effect.
    cands : Candidates
    selection : Selection
        The last selection (without the implausible effects).
    final : FinalModel
    refitter : Refitter
    implausible : dict
        Effect -> why its fitted coefficient is implausible.
    log : list of SelectionStep
        Selection steps of every round, and each implausible fit.
    """

    spec: BaseSpec
    base: ModelFit
    cands: Candidates
    selection: Selection
    final: FinalModel
    refitter: Refitter
    implausible: dict[str, str]
    log: list[SelectionStep]

    @property
    def heldout_after_W(self) -> float:
        """Held-out RMSE of the final model [W]."""
        y = self.refitter.model.samples.viscous_W
        r = y - self.final.after.pred
        return float(np.sqrt(np.mean(r * r)))


def search_effects(model: ForwardModel, spec: BaseSpec, base: ModelFit, names: list[str],
                   facts: RigFacts, noise_W: float, opts: SearchOptions) -> EffectSearch:
    """Screen, select and refit library effects; exclude implausible fits and search again.

    Parameters
    ----------
    model : ForwardModel
        All oil runs.
    spec : BaseSpec
    base : ModelFit
        Calibration without effect (with its Jacobian).
    names : list of str
        Library effects considered.
    facts : RigFacts
        The rig's size and fluids (plausibility).
    noise_W : float
        Noise level [W].
    opts : SearchOptions

    Returns
    -------
    EffectSearch
    """
    s = model.samples
    cands = screen_candidates(model, spec, base, names, opts.has_time, facts)
    refitter = Refitter(model, spec, cands.feature_scale(), opts.cv)
    prior = spec.start(spec.prior_values())  # a fold holds what it cannot identify there
    hold = {c: {spec.free.index(k): float(prior[spec.free.index(k)] - base.x[spec.free.index(k)])
                for k in h} for c, h in refitter.fold_holds().items()}
    r0 = s.viscous_W - base.pred
    implausible: dict[str, str] = {}
    log: list[SelectionStep] = []
    selector = None
    limits = opts.thresholds(noise_W)
    for _ in range(len(cands.usable) + 1):
        sel = select_effects(base.jac_base, r0, cv_folds(s), cands, limits,
                             frozenset(implausible), hold, selector)
        selector = sel.selector
        final = refit_selected(refitter, base, cands, sel, opts.margin)
        final = add_state_readers(refitter, final, cands, opts.margin, opts.max_effects,
                                  frozenset(implausible))
        log += sel.log + final.log
        bad = {}
        for n, c in zip(final.accepted, final.fit.theta, strict=True):
            why = EFFECTS[n].implausibility(float(c), facts)
            if why:
                bad[n] = why
        if not bad:
            break
        for n, why in bad.items():
            log.append(SelectionStep(step="plausibility", rejected=n, reason=why))
        implausible.update(bad)
    return EffectSearch(spec=spec, base=base, cands=cands, selection=sel, final=final,
                        refitter=refitter, implausible=implausible, log=log)


def evidence_trial(model: ForwardModel, search: EffectSearch, held: dict[str, float],
                   names: list[str], facts: RigFacts, noise_W: float, opts: SearchOptions
                   ) -> tuple[EffectSearch, str | None]:
    """Search again with out-of-range parameters held at their range bound.

    A calibrated parameter outside its physical range (e.g. a scale 1.6x the
    published law) may have absorbed an effect that scales the same way. With
    the parameter held at its bound the effect search gets that share of the
    loss to explain; its result is adopted if it accepts an effect and
    predicts the held-out groups at least as well as the free calibration (with
    its own effects, if any) [2].

    Parameters
    ----------
    model : ForwardModel
    search : EffectSearch
        The search on the free calibration.
    held : dict
        Parameter -> bound it is held at [-] (:func:`.ranges.held_values`).
    names : list of str
        Library effects considered.
    facts : RigFacts
    noise_W : float
        Noise level [W].
    opts : SearchOptions

    Returns
    -------
    (EffectSearch, str or None)
        The search adopted and a sentence on the trial (None without a trial).
    """
    if not held:
        return search, None
    spec = search.spec
    hspec = spec.holding(held)
    vals = spec.values(search.base.x)
    base = fit_model(model, hspec, rescale_level(model, hspec, hspec.start({**vals, **held})))
    trial = search_effects(model, hspec, base, names, facts, noise_W, opts)
    what = ", ".join(f"{k} = {v:.3g}" for k, v in held.items())
    ha, hf = trial.heldout_after_W, search.heldout_after_W
    acc = ", ".join(trial.final.accepted)
    if trial.final.accepted and ha <= hf:
        return trial, (f"evidence: with {what} held at its range bound, {acc} explains what the "
                       f"free calibration absorbed (held-out RMSE {ha:.3g} W against {hf:.3g} "
                       "W): adopted")
    why = (f"{acc} would be accepted but predicts the held-out groups worse ({ha:.3g} W "
           f"against {hf:.3g} W)" if acc else "no library effect explains the difference")
    return search, (f"evidence: with {what} held at its range bound, {why}; the free "
                    "calibration is kept")
