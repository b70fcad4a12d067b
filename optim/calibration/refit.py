"""Stage 6 of the calibration: nonlinear refit with the selected effects, held-out errors.

The effects the linearised selection accepts are refitted with the law by
nonlinear least squares (their exact forms where the library has them). Held-out
errors come from leave-one-run-out folds: one Gauss-Newton step from the
all-runs fit (default) or a full nonlinear refit per fold. The nonlinear
held-out error overrules the linearised one: if the accepted effects do not
lower it by the margin, they are rejected.

References
----------
.. [1] M. Stone, "Cross-validatory choice and assessment of statistical
   predictions", J. R. Stat. Soc. B 36:111-147, 1974.
.. [2] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eq. 8.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .candidates import Candidates
from .forward import ForwardModel
from .least_squares import BaseSpec, ModelFit, fit_model, one_step_fold
from .selection import Selection

CV_MODES = ("one-step", "full")
"""How each leave-one-run-out fold is refitted."""


def rmse(a: np.ndarray) -> float:
    """Root mean square of ``a`` (NaN if empty).

    Parameters
    ----------
    a : array
        Residual [W].

    Returns
    -------
    float
        RMS [W].
    """
    return float(np.sqrt(np.mean(a * a))) if len(a) else float("nan")


@dataclass
class HeldOut:
    """Leave-one-run-out predictions of one model.

    Attributes
    ----------
    pred : array
        Each sample predicted by the fit without its run [W].
    folds : list of ModelFit
        The fit without each run, in run-code order.
    """

    pred: np.ndarray
    folds: list[ModelFit]


class Refitter:
    """Nonlinear fits of the law with named effects, on all runs or leaving runs out.

    Parameters
    ----------
    model : ForwardModel
        All oil runs.
    spec : BaseSpec
        Free Eq. 8 parameters.
    feature_scale : dict
        Effect -> RMS of its feature [W/unit] (conditioning of the solver).
    cv : {"one-step", "full"}
        Fold refits: one Gauss-Newton step from the all-runs fit, or complete.
    """

    def __init__(self, model: ForwardModel, spec: BaseSpec, feature_scale: dict[str, float],
                 cv: str = "one-step"):
        self.model = model
        self.spec = spec
        self.feature_scale = feature_scale
        self.cv = cv

    def fit(self, names, x_start: np.ndarray, theta_start: np.ndarray | None,
            on: ForwardModel | None = None) -> ModelFit:
        """Fit law + effects ``names`` on ``on`` (default all runs), predicting all runs.

        Parameters
        ----------
        names : sequence of str
            Effects.
        x_start : array
            Start of the free Eq. 8 parameters (C as ln C) [-].
        theta_start : array or None
            Start of the effect coefficients (library units).
        on : ForwardModel, optional
            Samples fitted.

        Returns
        -------
        ModelFit
        """
        sc = np.array([self.feature_scale[n] for n in names])
        return fit_model(on or self.model, self.spec, x_start, tuple(names), theta_start, sc,
                         full=self.model)

    def leave_one_run_out(self, names, x_start: np.ndarray, theta_start: np.ndarray | None,
                          at: ModelFit | None = None) -> HeldOut:
        """Held-out predictions and per-fold fits of the model ``names`` [1].

        Parameters
        ----------
        names : sequence of str
            Effects.
        x_start, theta_start : arrays
            Start of full refits.
        at : ModelFit, optional
            All-runs fit: the folds are one Gauss-Newton step from it unless
            ``cv == "full"`` (without it, full refits).

        Returns
        -------
        HeldOut
        """
        s = self.model.samples
        runs = np.unique(s.run_code)
        pred = np.empty(s.n)
        folds = []
        full = at is None or self.cv == "full"
        if full:
            subs = {c: self.model.subset(s.run_code != c) for c in runs}
        for c in runs:
            if full:
                f = self.fit(names, x_start, theta_start, subs[c])
            else:
                f = one_step_fold(at, self.model, self.spec, s.run_code != c)
            pred[s.run_code == c] = f.pred[s.run_code == c]
            folds.append(f)
        return HeldOut(pred, folds)


@dataclass
class FinalModel:
    """The calibrated model after the effect search.

    Attributes
    ----------
    fit : ModelFit
        With the accepted effects (the calibration itself if none).
    accepted : list of str
        Effects in the final model.
    chosen : tuple of int
        Their candidate columns.
    before, after : HeldOut
        Leave-one-run-out predictions without effect and of the final model.
    nonlinear_check : dict or None
        Held-out RMSE before and after [W] and gain [%] of the nonlinear refit.
    log : list of dict
        The rejection by the nonlinear check, if any.
    """

    fit: ModelFit
    accepted: list[str]
    chosen: tuple[int, ...]
    before: HeldOut
    after: HeldOut
    nonlinear_check: dict | None
    log: list[dict]


def refit_selected(refitter: Refitter, base: ModelFit, cands: Candidates,
                   selection: Selection, margin: float) -> FinalModel:
    """Nonlinear refit of the selected effects, checked on held-out runs.

    The coefficients start at the linearised amplitudes (times the variant's
    parameter for an exact-form column). If the nonlinear held-out RMSE does
    not fall by ``margin``, the effects are rejected [1], [2].

    Parameters
    ----------
    refitter : Refitter
    base : ModelFit
        Calibration without effect.
    cands : Candidates
    selection : Selection
    margin : float
        Required relative fall of the held-out RMSE [-].

    Returns
    -------
    FinalModel
    """
    y = refitter.model.samples.viscous_W
    before = refitter.leave_one_run_out((), base.x, None, base)
    hb = rmse(y - before.pred)
    chosen = selection.chosen
    accepted = [cands.name[j] for j in chosen]
    if not accepted:
        return FinalModel(base, [], chosen, before, before, None, [])
    lin_coef = selection.selector.coef(chosen)
    start = []
    for j in chosen:  # coefficient start: linear amplitude, or amplitude x variant value
        a_j = float(lin_coef[j])
        start.append(a_j if cands.variant[j] is None else a_j * cands.variant[j])
    fit = refitter.fit(accepted, base.x, np.array(start))
    after = refitter.leave_one_run_out(accepted, fit.x, fit.theta, fit)
    ha = rmse(y - after.pred)
    check = {"heldout_before_W": hb, "heldout_after_W": ha, "gain_pct": 100 * (1 - ha / hb)}
    if ha > hb * (1.0 - margin):  # the honest held-out check overrules
        log = [{"step": "nonlinear check", "rejected": accepted,
                "gain_pct": 100 * (1 - ha / hb)}]
        return FinalModel(base, [], (), before, before, check, log)
    return FinalModel(fit, accepted, chosen, before, after, check, [])


def heldout_gains(refitter: Refitter, final: FinalModel) -> dict[str, float]:
    """Held-out gain of each accepted effect: the final model against it left out.

    Parameters
    ----------
    refitter : Refitter
    final : FinalModel

    Returns
    -------
    dict
        Effect -> ``100 (1 - RMSE_ho(final) / RMSE_ho(without it))`` [%].
    """
    y = refitter.model.samples.viscous_W
    fit, accepted = final.fit, final.accepted
    gains = {}
    for n in accepted:
        rest = [m for m in accepted if m != n]
        if rest:
            keep = [accepted.index(m) for m in rest]
            f_rest = refitter.fit(rest, fit.x, fit.theta[keep])
            pr = refitter.leave_one_run_out(rest, fit.x, fit.theta[keep], f_rest).pred
            e_rest = rmse(y - pr)
        else:
            e_rest = rmse(y - final.before.pred)
        gains[n] = 100.0 * (1.0 - rmse(y - final.after.pred) / e_rest)
    return gains
