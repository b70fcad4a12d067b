"""Stage 6 of the calibration: nonlinear refit with the selected effects, held-out errors.

The effects the linearised selection accepts are refitted with the law by
nonlinear least squares (their exact forms where the library has them). Held-out
errors come from the cross-validation folds (:mod:`.folds`: whole runs, one fold
per run up to 10 runs, grouped 10-fold above): one Gauss-Newton step from the
all-runs fit (default) or a full nonlinear refit per fold; a fold that cannot
identify a base parameter holds it at its prior (the published or case value,
:meth:`.spec.BaseSpec.prior_values`) and is always refitted in full from there, so
no information from its held-out group enters its fit. The nonlinear
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

import math
from dataclasses import dataclass, field

import numpy as np

from .candidates import Candidates
from .folds import cv_folds
from .forward import ForwardModel
from .least_squares import BaseSpec, ModelFit, fit_model, one_step_fold, rescale_level
from .selection import Selection
from .spec import LOG_PARAMS, fold_spec
from .steps import SelectionStep

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
        Each sample predicted by the fit without its group [W].
    folds : list of ModelFit
        The fit without each group, in group-code order (parameters in the
        all-data specification).
    held : list of tuple of str
        Per fold, the base parameters it could not identify (held at their
        priors, :meth:`.spec.BaseSpec.prior_values`).
    """

    pred: np.ndarray
    folds: list[ModelFit]
    held: list[tuple[str, ...]] = field(default_factory=list)


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
        self._holds: dict[int, tuple[str, ...]] | None = None
        self._sub: Refitter | bool | None = None

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
        sub = self.subsample() if on is None else None
        if sub is not None:  # start on the subsample: a few full-data iterations remain
            sub.model.taylor_exponent = self.model.taylor_exponent
            f0 = sub.fit(names, x_start, theta_start)
            x_start, theta_start = f0.x, f0.theta
        return fit_model(on or self.model, self.spec, x_start, tuple(names), theta_start, sc,
                         full=self.model)

    def subsample(self) -> Refitter | None:
        """The refitter on the deterministic subsample of :func:`screen_refitter` (cached;
        None at most :data:`SCREEN_ABOVE` samples).

        Returns
        -------
        Refitter or None
        """
        if self._sub is None:
            self._sub = screen_refitter(self) or False
        return self._sub or None

    def fold_holds(self) -> dict[int, tuple[str, ...]]:
        """Per cross-validation group, the base parameters its fold cannot identify.

        Returns
        -------
        dict
            Group code -> parameters held at their priors (cached).
        """
        if self._holds is None:
            s = self.model.samples
            groups = cv_folds(s)
            r1 = self.model.geometry.regions[0].radius_m
            self._holds = {int(c): fold_spec(self.spec, s.subset(groups != c), r1)
                           for c in np.unique(groups)}
        return self._holds

    def _full_fold(self, names, x_all: np.ndarray, theta: np.ndarray | None, train: np.ndarray,
                   hold: tuple[str, ...]) -> ModelFit:
        """Complete nonlinear refit on ``train`` with ``hold`` at their priors (the other
        parameters start at the all-data fit; the converged fold fit depends on ``train``
        only)."""
        spec = self.spec
        prior = spec.prior_values()
        sub = spec.holding({k: prior[k] for k in hold})
        keep = [spec.free.index(k) for k in sub.free]
        sc = np.array([self.feature_scale[n] for n in names])
        on = self.model.subset(train)
        x0 = rescale_level(on, sub, x_all[keep]) if hold else x_all[keep]  # level to the prior
        f = fit_model(on, sub, x0, tuple(names), theta, sc, full=self.model)
        x = x_all.copy()
        x[keep] = f.x
        for k in hold:
            i = spec.free.index(k)
            x[i] = math.log(prior[k]) if k in LOG_PARAMS else prior[k]
        return ModelFit(
            x=x, theta=f.theta, law=spec.law(x), pred=f.pred, jac_base=f.jac_base, jac=None,
            scale=f.scale, names=f.names, lower=f.lower)

    def leave_one_run_out(self, names, x_start: np.ndarray, theta_start: np.ndarray | None,
                          at: ModelFit | None = None) -> HeldOut:
        """Held-out predictions and per-fold fits of the model ``names`` [1].

        One fold per fold code of :func:`.folds.cv_folds` (whole groups, the runs
        unless the data say otherwise; one per group up to
        :data:`.folds.MAX_FOLDS` groups, grouped k-fold above). A fold that
        cannot identify a base parameter holds it at its prior and is refitted in full
        (never at the all-data value: that has seen the held-out group); a one-step
        fold that would move a parameter too far is refitted in full.

        Parameters
        ----------
        names : sequence of str
            Effects.
        x_start, theta_start : arrays
            Start of full refits (the all-data values).
        at : ModelFit, optional
            All-data fit: the folds are one Gauss-Newton step from it unless
            ``cv == "full"`` (without it, full refits).

        Returns
        -------
        HeldOut
        """
        s = self.model.samples
        groups = cv_folds(s)
        holds = self.fold_holds()
        pred = np.empty(s.n)
        folds, held = [], []
        x_all = at.x if at is not None else np.asarray(x_start, float)
        th_all = at.theta if at is not None else theta_start
        for c in np.unique(groups):
            train, hold = groups != c, holds[int(c)]
            f = None
            if at is not None and self.cv != "full" and not hold:
                f = one_step_fold(at, self.model, self.spec, train, hold)
            if f is None:
                f = self._full_fold(names, x_all, th_all, train, hold)
            pred[~train] = f.pred[~train]
            folds.append(f)
            held.append(hold)
        return HeldOut(pred, folds, held)


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
    log : list of SelectionStep
        The nonlinear check's rejection, prunes and additions, if any.
    taylor_exponent : float
        Shape exponent m of the Taylor-vortex excess of the final model [-].
    """

    fit: ModelFit
    accepted: list[str]
    chosen: tuple[int, ...]
    before: HeldOut
    after: HeldOut
    nonlinear_check: dict | None
    log: list[SelectionStep]
    taylor_exponent: float = 2.0


def refit_selected(refitter: Refitter, base: ModelFit, cands: Candidates,
                   selection: Selection, margin: float) -> FinalModel:
    """Nonlinear refit of the selected effects, checked on held-out runs.

    The coefficients start at the linearised amplitudes (times the variant's
    parameter for an exact-form column); a Taylor-vortex shape column sets the
    forward model's shape exponent m. If the nonlinear held-out RMSE does
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
        return FinalModel(
            fit=base, accepted=[], chosen=chosen, before=before, after=before, nonlinear_check=None,
            log=[])
    lin_coef = selection.selector.coef(chosen)
    start = []
    for j in chosen:  # coefficient start: linear amplitude, or amplitude x variant value
        a_j = float(lin_coef[j])
        exact = cands.variant[j] is not None and not cands.is_shape(j)
        start.append(a_j * cands.variant[j] if exact else a_j)
    fit, m = _fit_taylor_shape(refitter, base, cands, chosen, np.array(start))
    after = refitter.leave_one_run_out(accepted, fit.x, fit.theta, fit)
    ha = rmse(y - after.pred)
    check = {"heldout_before_W": hb, "heldout_after_W": ha, "gain_pct": 100 * (1 - ha / hb)}
    if ha > hb * (1.0 - margin):  # the honest held-out check overrules
        log = [SelectionStep(step="nonlinear check", rejected=accepted,
                             gain_pct=100 * (1 - ha / hb))]
        return FinalModel(
            fit=base, accepted=[], chosen=(), before=before, after=before, nonlinear_check=check,
            log=log)
    return _prune_nonlinear(refitter, FinalModel(
        fit=fit, accepted=accepted, chosen=chosen, before=before, after=after,
        nonlinear_check=check, log=[], taylor_exponent=m), margin)


def _fit_taylor_shape(refitter: Refitter, base: ModelFit, cands: Candidates,
                      chosen: tuple[int, ...], start: np.ndarray) -> tuple[ModelFit, float]:
    """Nonlinear fit of the chosen columns; with Taylor-vortex onset among them, at each
    screened shape exponent m, the one of least squared error kept (all other effects in).

    The linearised selection picks a shape column before the other effects are in, so a
    shape can stand in for an effect added later; the nonlinear refit with every
    chosen effect present decides m (same number of coefficients at every m). The
    forward model keeps the chosen m (its folds copy it).
    """
    accepted = [cands.name[j] for j in chosen]
    j0 = next((j for j in chosen if cands.name[j] == "taylor_vortex_onset"), None)
    if j0 is None:
        refitter.model.taylor_exponent = 2.0
        return refitter.fit(accepted, base.x, start), 2.0
    i0 = chosen.index(j0)
    y = refitter.model.samples.viscous_W
    rms0 = float(np.sqrt(np.mean(cands.columns[:, j0] ** 2)))
    best = None
    for j in cands.columns_of("taylor_vortex_onset"):
        m = cands.taylor_exponent((j,))
        th = start.copy()  # the same rms Taylor power at this shape
        th[i0] = start[i0] * rms0 / max(float(np.sqrt(np.mean(cands.columns[:, j] ** 2))),
                                        1e-300)
        refitter.model.taylor_exponent = m
        f = refitter.fit(accepted, base.x, th)
        sse = float(np.sum((y - f.pred) ** 2))
        if best is None or sse < best[0]:
            best = (sse, f, m)
    refitter.model.taylor_exponent = best[2]
    return best[1], best[2]


def _prune_nonlinear(refitter: Refitter, final: FinalModel, margin: float) -> FinalModel:
    """Drop, one at a time, an effect that brings less than the margin in the nonlinear refit.

    The linearised selection can take in a column the nonlinear refit then
    sets to nothing (e.g. an exact-form variant next to a stronger effect):
    each accepted effect must keep its held-out margin against the final model
    without it, as in the linearised backward pruning.
    """
    log = list(final.log)
    while len(final.accepted) > 1:
        gains = heldout_gains(refitter, final)
        weakest = min(gains, key=gains.get)
        if gains[weakest] >= 100.0 * margin:
            break
        log.append(SelectionStep(step="nonlinear prune", dropped=weakest,
                                 gain_pct=gains[weakest]))
        keep = [i for i, n in enumerate(final.accepted) if n != weakest]
        names = [final.accepted[i] for i in keep]
        fit = refitter.fit(names, final.fit.x, final.fit.theta[keep])
        after = refitter.leave_one_run_out(names, fit.x, fit.theta, fit)
        y = refitter.model.samples.viscous_W
        ha, hb = rmse(y - after.pred), rmse(y - final.before.pred)
        check = {"heldout_before_W": hb, "heldout_after_W": ha,
                 "gain_pct": 100 * (1 - ha / hb)}
        final = FinalModel(
            fit=fit, accepted=names, chosen=tuple(final.chosen[i] for i in keep),
            before=final.before, after=after, nonlinear_check=check, log=log,
            taylor_exponent=final.taylor_exponent)
    return final


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


STATE_EFFECTS = ("thermal_lag", "film_heating")
"""Effects that move the oil state (the temperature the oil's viscosity is read at)."""

STATE_READERS = ("bearing_ball_churning", "end_face_disc", "shear_thinning",
                 "taylor_vortex_onset", "oil_inertia")
"""Effects whose term reads the oil state (viscosity or density) beside the regions'."""


def add_state_readers(refitter: Refitter, final: FinalModel, cands: Candidates, margin: float,
                      max_effects: int, excluded=frozenset()) -> FinalModel:
    """Nonlinear forward steps for effects read at a moved oil state.

    The linearised screening evaluates every column at the measured oil state of the
    calibration without effect. Once a thermal lag or film heating is in the model, an
    effect that reads the oil's viscosity or density (bearing, discs, thinning, Taylor
    excess, oil inertia) acts at the lagged or heated state: its cross term with the
    state effect is in no linear column, and a large exact-form column of the state
    effect can absorb it in the screening. Each such candidate is therefore refitted
    nonlinearly with the accepted effects (one oil state, :meth:`ForwardModel.oil_state`);
    the best is added if it lowers the held-out RMSE by ``margin`` [1], and so on up to
    ``max_effects``.

    Parameters
    ----------
    refitter : Refitter
    final : FinalModel
        After :func:`refit_selected`.
    cands : Candidates
    margin : float
        Required relative fall of the held-out RMSE [-].
    max_effects : int
        Most effects in the model.
    excluded : set of str
        Effects not to add (implausible fits).

    Returns
    -------
    FinalModel
        ``final``, or with the added effects (logged as "nonlinear add").
    """
    y = refitter.model.samples.viscous_W
    added = False
    screen = refitter.subsample()
    while (set(final.accepted) & set(STATE_EFFECTS)) and len(final.accepted) < max_effects:
        e_now = rmse(y - final.after.pred)
        tried = [n for n in cands.usable if n not in final.accepted and n not in excluded
                 and n in STATE_READERS + STATE_EFFECTS]
        if screen is not None:
            tried = screened_readers(screen, final, tried, margin)
        best = None
        for n in tried:
            names = [*final.accepted, n]
            fit = refitter.fit(names, final.fit.x, np.append(final.fit.theta, 0.0))
            ho = refitter.leave_one_run_out(names, fit.x, fit.theta, fit)
            e = rmse(y - ho.pred)
            if best is None or e < best[0]:
                best = (e, n, fit, ho)
        if best is None or best[0] > e_now * (1.0 - margin):
            break
        e, n, fit, ho = best
        hb = rmse(y - final.before.pred)
        check = {"heldout_before_W": hb, "heldout_after_W": e, "gain_pct": 100 * (1 - e / hb)}
        log = [*final.log, SelectionStep(step="nonlinear add", added=n,
                                         gain_pct=100.0 * (1.0 - e / e_now))]
        final = FinalModel(
            fit=fit, accepted=[*final.accepted, n], chosen=(*final.chosen, cands.columns_of(n)[0]),
            before=final.before, after=ho, nonlinear_check=check, log=log,
            taylor_exponent=final.taylor_exponent)
        added = True
    return _prune_nonlinear(refitter, final, margin) if added else final


SCREEN_ABOVE = 50_000
"""Above this many samples the oil-state readers are screened on a subsample of about
:data:`SCREEN_SAMPLES` (every k-th sample of every run) before any is refitted on all
samples, and every nonlinear fit on all samples starts from the subsample's."""

SCREEN_SAMPLES = 10_000
"""Size of the screening subsample (about; whole strides of every run)."""

SCREEN_SLACK = 0.5
"""Share of the margin a reader must gain on the subsample to be refitted on all samples."""


def screen_refitter(refitter: Refitter) -> Refitter | None:
    """A refitter on a deterministic subsample of a large data set (None at most
    :data:`SCREEN_ABOVE` samples): every k-th sample of every run from its first,
    ``k = ceil(n / SCREEN_SAMPLES)``, the same runs and folds.

    Parameters
    ----------
    refitter : Refitter
        On all samples.

    Returns
    -------
    Refitter or None
        On the subsample (its forward model a subset of the full one: the derivatives
        and features computed on all samples), with the same specification, feature
        scales [W/unit] and fold refits.
    """
    model = refitter.model
    n = model.samples.n
    if n <= SCREEN_ABOVE:
        return None
    k = -(-n // SCREEN_SAMPLES)
    mask = np.zeros(n, bool)
    for idx in model.runs:
        mask[idx[::k]] = True
    return Refitter(model.subset(mask), refitter.spec, refitter.feature_scale, refitter.cv)


def screened_readers(screen: Refitter, final: FinalModel, tried: list[str],
                     margin: float) -> list[str]:
    """The readers worth a nonlinear refit on all samples, by a screen on the subsample.

    On the subsample, the accepted model and each reader with it are refitted
    nonlinearly (from the all-samples fit) and cross-validated as on all samples; a
    reader passes if its held-out RMSE falls below the accepted model's by
    :data:`SCREEN_SLACK` of ``margin`` (the all-samples check then asks the whole
    margin).

    Parameters
    ----------
    screen : Refitter
        On the subsample (:func:`screen_refitter`).
    final : FinalModel
        The model so far (all samples).
    tried : list of str
        Candidate readers.
    margin : float
        Required relative fall of the held-out RMSE [-].

    Returns
    -------
    list of str
        The readers that pass, in the order of ``tried``.
    """
    if not tried:
        return []
    y = screen.model.samples.viscous_W
    screen.model.taylor_exponent = final.taylor_exponent

    def heldout(names, theta):
        fit = screen.fit(names, final.fit.x, theta)
        return rmse(y - screen.leave_one_run_out(names, fit.x, fit.theta, fit).pred)

    e_now = heldout(final.accepted, final.fit.theta)
    errs = {n: heldout([*final.accepted, n], np.append(final.fit.theta, 0.0)) for n in tried}
    return [n for n in tried if errs[n] <= e_now * (1.0 - SCREEN_SLACK * margin)]
