"""Close the loop with measured data: calibrate, find the missing effect, report.

:class:`LoopEstimator` is a scikit-learn style estimator (``fit(data)``,
``predict(data)``, learned attributes ending in ``_``). ``fit`` calls the
stages of this package in order:

1. Validate and load (:mod:`oilgap.model.measured.data`), fit the oil-free
   baseline of each T and take it away (:mod:`.baseline`; or read
   ``viscous_power_W``), get nu and rho per sample from each oil's Walther line
   and density law.
2. The forward model of the oil runs (:mod:`.forward`).
3. The seed's Table 3 comparison. *Without T*: the case's published friction
   law (Eq. 6) with gamma = 0, nothing fitted. *With T*: the base model
   (:mod:`.spec`; default the design tool's smooth Eq. 6 times one scale and
   T^gamma, alpha where several gaps identify it; option: a free power law)
   fitted by nonlinear least squares on the power in W, the free parameters
   decided from the data and reported with the Jacobian's correlations
   (:mod:`.least_squares`). Each parameter is checked against its physical
   range (:mod:`.ranges`): a value outside it is a *finding*.
4. Residual analysis of the calibrated model: binned structure, autocorrelation,
   the noise level from successive differences (:mod:`.residuals`).
5. Effect search over the library of :mod:`oilgap.model.effects` (:mod:`.search`):
   candidate columns (:mod:`oilgap.optim.calibration.candidates`), the sign-constrained
   lasso path and
   cross-validated forward selection (:mod:`.selection`; folds of whole runs,
   leave-one-run-out up to 10 runs, grouped 10-fold above: :mod:`.folds`): each effect must
   lower the held-out RMSE by the margin (default 10 %), and the effects kept
   must together explain at least half of the held-out structure above the
   noise; otherwise the answer is "no missing effect found", and structure
   left over is reported with what it correlates with. An effect fitted
   outside its plausible range is "implausible" and the search runs without
   it. A parameter outside its range is held at the bound and the search run
   again (evidence for an effect it absorbed).
6. Refit with the accepted effects (nonlinear, all parameters), errors before
   and after in-sample and on held-out groups (:mod:`.refit`); a fold that
   cannot identify a parameter holds it at its prior (the published or case value),
   never at the all-data fit, and is refitted in full: no information from the
   held-out group enters that fold's fit.
7. Each parameter and coefficient with a jackknife-over-folds 95 % confidence
   interval (C and the scale in log space), widened by the baseline's error
   (:mod:`~oilgap.optim.calibration.uncertainty`).
8. Tables and records (:mod:`~oilgap.optim.calibration.results`).

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 5-9 and Table 3
   (``shared/reference/seed-paper.md``).
.. [2] R. Tibshirani, "Regression shrinkage and selection via the lasso",
   J. R. Stat. Soc. B 58:267-288, 1996; relaxed lasso: N. Meinshausen,
   Comput. Stat. Data Anal. 52:374-393, 2007.
.. [3] B. Efron, C. Stein, "The jackknife estimate of variance", Ann. Stat.
   9:586-596, 1981 (delete-one-group jackknife).
.. [4] J. von Neumann, "Distribution of the ratio of the mean square successive
   difference to the variance", Ann. Math. Stat. 12:367-395, 1941.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.effects import CONFOUNDED_FORMS, EFFECTS, RigFacts
from oilgap.model.errors import InputError, NotFittedError
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.tables import read_table
from oilgap.model.linear.report import rod_rows_as_motor_speed
from oilgap.model.measured.data import (
    MeasuredData,
    Samples,
    add_kinematics,
    load_measured,
    oil_samples,
    validate,
)
from oilgap.model.oil_state import oil_state_record
from oilgap.model.oils import Oil, read_oils_csv
from oilgap.model.regions import joint_geometry
from oilgap.optim.progress import report

from .base_choice import AUTO_BASE, fit_base, select_base
from .baseline import BaselineFit, fit_baselines
from .film_wall import case_film_wall, wall_identifiability
from .folds import cv_scheme
from .forward import ForwardModel
from .least_squares import ModelFit, identifiability
from .model_io import FittedModel
from .ranges import (
    PARAM_RANGES,
    Finding,
    below_couette_finding,
    explained_findings,
    held_values,
    no_signal_finding,
    parameter_findings,
)
from .refit import CV_MODES, FinalModel, heldout_gains, rmse
from .residual_story import describe_residual
from .residuals import residual_structure, unexplained_structure
from .results import (
    candidate_statuses,
    effect_results,
    law_dict,
    per_run_rows,
    strip_bins,
    table3_rows,
)
from .search import EffectSearch, SearchOptions, evidence_trial, fluid_facts, search_effects
from .spec import BASES, BaseSpec
from .uncertainty import effect_ci, parameter_ci

DEFAULT_MARGIN = 0.10
"""Relative fall of the held-out RMSE an effect must bring [-]."""
DEFAULT_MIN_EXPLAINED = 0.5
"""Share of the held-out structure above noise an accepted effect must explain [-]."""
STAGES = ("without_T", "with_T", "with_effect")
"""The three models of the report."""


class LoopEstimator:
    """Calibrate the viscous-loss model on measured runs and search for a missing effect.

    Parameters
    ----------
    case : DesignCase, optional
        Rig geometry (default: the seed joint). Its friction law is the
        "without T" model (with gamma = 0).
    oils : dict or path, optional
        Oils table (default: the built-in catalogue).
    margin : float
        Relative fall of the held-out RMSE an effect must bring [-] (default 0.10).
    min_explained : float
        Share of the held-out structure above noise it must explain [-] (default 0.5).
    effects : sequence of str, optional
        Library effects to consider (default: all).
    max_effects : int
        Most effects accepted together (default 3).
    cv : {"one-step", "full"}
        How each cross-validation fold is refitted for the reported held-out
        errors and the jackknife: one Gauss-Newton step from the all-runs fit
        (default, fast) or a complete nonlinear refit. The folds hold whole
        groups: one per group up to :data:`.folds.MAX_FOLDS` groups
        (leave-one-run-out), grouped 10-fold cross-validation above
        (:mod:`.folds`).
    base : {"eq6", "auto", "power-law", "branches"}
        Base model (default ``"auto"``): each candidate of
        :func:`.base_choice.base_candidates` (Eq. 6, ``branches``, Eq. 6 with the
        Taylor transition) is fitted with its own effect search, and the one whose base
        and accepted effects have the least held-out log-RMSE is kept unless a simpler
        one (fewer base parameters and effects) comes within ``margin`` of it
        (:mod:`.base_choice`; the table in ``base_selection_``). Forced: ``"eq6"``, the
        design tool's Eq. 6 regime structure (smooth form, the case's laminar law and
        transition) times one scale and T^gamma, ``"power-law"``, a free
        power law C (delta/R)^alpha Re^beta T^gamma, or ``"branches"``, Eq. 6's branches
        each with its own C_k, alpha_k, beta_k, freed only where the data identify them
        (:func:`.spec.branch_identifiability`).
    cv_by : str
        Column of the data whose values are the groups of the cross-validation
        (default ``"run"``; e.g. ``"gap_mm"``, ``"oil"``).

    Attributes
    ----------
    data_ : MeasuredData
    baselines_ : dict
        T -> BaselineFit (empty for viscous-power data).
    samples_ : Samples
        The oil-run samples.
    law_without_T_, law_with_T_, law_ : FrictionLaw
        Published law (gamma = 0), calibrated Eq. 8, final law.
    calibration_, calibration_after_ : dict
        Eq. 8 parameters without and with the effects [-]; ``*_ci_`` their 95 % intervals.
    cv_scheme_ : dict
        The cross-validation folds (:func:`.folds.cv_scheme`): leave-one-group-out
        or grouped k-fold, groups, folds, the rule; ``cross_validation`` in
        ``loop.json``.
    identifiability_ : dict
        Parameter -> statement.
    effects_ : list of EffectResult
    findings_ : list of Finding
        Parameters outside their range or on their box, effects on their bound, no signal.
    candidates_ : list of dict
        Every library effect considered, with its status.
    rmse_ : dict
        without_T / with_T / with_effect [W].
    heldout_rmse_ : dict
        before / after [W].
    per_run_, table3_ : list of dict
    residual_before_, residual_after_ : dict
    unexplained_ : dict or None
    noise_W_ : float
        Noise level [W].
    oil_state_ : dict
        The oil state the final model's terms read
        (:func:`oilgap.model.oil_state.oil_state_record`): measured, lagged and/or
        film-heated; in ``loop.json`` as ``oil_state`` when not
        the measured one.
    lasso_path_ : list of dict
    pred_ : dict
        Model power per sample of each stage [W].
    """

    def __init__(self, case: DesignCase | None = None, oils: dict[str, Oil] | str | Path |
                 None = None, margin: float = DEFAULT_MARGIN,
                 min_explained: float = DEFAULT_MIN_EXPLAINED, effects=None,
                 max_effects: int = 3, cv: str = "one-step", base: str = "auto",
                 cv_by: str = "run"):
        self.case = case
        self.oils = oils
        self.margin = margin
        self.min_explained = min_explained
        self.effects = effects
        self.max_effects = max_effects
        self.cv = cv
        self.base = base
        self.cv_by = cv_by

    # ------------------------------------------------------------------ fit
    def fit(self, data) -> LoopEstimator:
        """Run the whole loop on measured data.

        Parameters
        ----------
        data : path, DataFrame or MeasuredData
            Measured runs (oil-free and oil runs).

        Returns
        -------
        LoopEstimator
            ``self``, with the learned attributes.
        """
        case, names = self._checked_options()
        task = "loop: read, calibrate, search, evidence, intervals"  # progress, no print
        report(task, 0, 5)
        self.case_, self.geometry_ = case, joint_geometry(case)
        self.data_ = data = self._as_data(data)
        # 1. oil-free baseline; oil-run samples with nu and rho
        self.baselines_, s = self._load_samples(data)
        self.samples_ = s
        self.cv_scheme_ = cv_scheme(s)  # whole groups per fold, at most MAX_FOLDS folds
        # 2. forward model; 3. Table 3: without T (published law, gamma = 0), with T (base)
        model = self.forward_model_ = ForwardModel(s, case, data.oils,
                                                   film_wall=case_film_wall(case))
        self.law_without_T_ = replace(case.friction, gamma=0.0)
        report(task, 1, 5)
        facts = RigFacts.of(model.geometry, fluid_facts(s, data.oils))
        opts = SearchOptions(margin=self.margin, min_explained=self.min_explained,
                             max_effects=self.max_effects, cv=self.cv,
                             has_time=bool(getattr(s, "has_time", True)))
        # 3, 5-6. calibration and its effect search (each candidate base with its own)
        spec, base, stmt, free = self._calibrate(model, case, names, facts, opts)
        report(task, 2, 5)
        # 4. residual structure of the calibration; its parameters against their ranges
        self.residual_before_ = residual_structure(s.viscous_W - base.pred, s)
        self.noise_W_ = sigma = self.residual_before_["noise_W"]
        no_signal = no_signal_finding(s.viscous_W, base.pred, sigma)
        below = (below_couette_finding(s.viscous_W, model.couette_power(), sigma)
                 if case.friction.laminar_law == "couette" and no_signal is None else None)
        # the evidence trial of a range violation
        report(task, 3, 5)
        search, self.findings_ = self._evidence(model, free, no_signal, names, facts, sigma,
                                                opts)
        self.findings_ += [below] if below is not None else []
        self.identifiability_ = self._identifiability(stmt, free)
        final = replace(search.final, before=free.final.before)
        model.taylor_exponent = search.refitter.model.taylor_exponent = final.taylor_exponent
        final, w, self.identifiability_["wall_floating"] = wall_identifiability(
            search.refitter, final, case_film_wall(case), self.margin)
        model.film_wall = search.refitter.model.film_wall = w
        self._store_final(search, final)
        report(task, 4, 5)
        # 7. confidence intervals (jackknife over groups, log space for C and the scale)
        self._intervals(free, search, no_signal is not None)
        ci = effect_ci(search.spec, final.fit, final.after.folds, s, self.baselines_)
        # 8. results
        self.effects_ = effect_results(model, final, ci, heldout_gains(search.refitter, final))
        self.findings_ += [Finding(kind="at bound", parameter=e.name, value=e.coefficient,
                                   message=e.shape["at_bound"])
                           for e in self.effects_ if (e.shape or {}).get("at_bound")]
        self.candidates_ = candidate_statuses(search.cands, search.selection, final, sigma,
                                              self.margin, self.min_explained,
                                              search.implausible)
        self.confounded_forms_ = dict(CONFOUNDED_FORMS)
        self._tables(model, base, final)
        report(task, 5, 5)
        return self

    def _calibrate(self, model: ForwardModel, case: DesignCase, names: list[str],
                   facts: RigFacts, opts: SearchOptions
                   ) -> tuple[BaseSpec, ModelFit, dict, EffectSearch]:
        """Stage 3 and 5-6: the base model's free parameters, its fit to the oil runs and
        its effect search; with ``base="auto"`` each candidate base is fitted with its own
        effect search and the held-out error of base and effects chooses
        (:mod:`.base_choice`)."""
        def search_of(spec: BaseSpec, fit: ModelFit) -> EffectSearch:
            sigma = residual_structure(model.samples.viscous_W - fit.pred,
                                       model.samples)["noise_W"]
            return search_effects(model, spec, fit, names, facts, sigma, opts)

        if self.base == AUTO_BASE:
            trial, self.base_selection_ = select_base(model, case, self.margin, search_of)
            spec, base, stmt, free = trial.spec, trial.fit, trial.stmt, trial.search
            self.base_ = trial.candidate.name
        else:
            spec, base, stmt = fit_base(model, case, self.base)
            free = search_of(spec, base)
            self.base_selection_ = []
            self.base_ = spec.base
        self.spec_, self.law_with_T_ = spec, base.law
        return spec, base, stmt, free

    def _evidence(self, model: ForwardModel, free: EffectSearch, no_signal: Finding | None,
                  names: list[str], facts: RigFacts, sigma: float, opts: SearchOptions
                  ) -> tuple[EffectSearch, list[Finding]]:
        """Findings on the calibration, and the search adopted after the evidence trial."""
        fit = free.final.fit
        after = parameter_findings(free.spec, fit, model)
        if no_signal:  # a level pinned by the noise is no evidence of anything
            return free, [f for f in after if f.kind != "out of range"] + [no_signal]
        before = parameter_findings(free.spec, free.base, model) if free.final.accepted else []
        search, evidence = evidence_trial(model, free, held_values(after), names, facts, sigma,
                                          opts)
        held = held_values(after)
        out = [replace(f, evidence=evidence, tried=True) if f.parameter in held else f
               for f in after]
        return search, out + explained_findings(before, after, free.spec.values(fit.x),
                                                free.final.accepted)

    def _identifiability(self, stmt: dict, free: EffectSearch) -> dict:
        """Per-parameter statements, with the folds that held a parameter at its prior."""
        out = identifiability(stmt, free.spec, free.base)
        held = free.final.before.held
        prior = free.spec.prior_values()
        for k in free.spec.free:
            n = sum(k in h for h in held)
            if n:
                out[k] = (f"{out[k]}; held at its prior {prior[k]:.4g} in {n} of {len(held)} "
                          "cross-validation folds (their training data cannot identify it)")
        return out

    def _store_final(self, search: EffectSearch, final: FinalModel) -> None:
        """The selection's log and the final model's law, coefficients and held-out errors."""
        sel = search.selection
        self.search_ = search
        self.selection_log_ = search.log
        self.lasso_path_ = sel.lasso_path
        self.nonlinear_check_ = final.nonlinear_check
        self.heldout_linear_ = {"before": sel.heldout_before_W,
                                "after": sel.selector.cv(final.chosen)}
        self.final_fit_, self.law_ = final.fit, final.fit.law
        self.effect_coef_ = dict(zip(final.accepted, map(float, final.fit.theta), strict=True))
        self.oil_state_ = oil_state_record(self.effect_coef_,
                                           search.refitter.model.film_theory_K_W)
        self.taylor_exponent_ = final.taylor_exponent
        self.heldout_pred_ = {"before": final.before.pred, "after": final.after.pred}

    def _intervals(self, free: EffectSearch, search: EffectSearch, no_signal: bool) -> None:
        """Base parameters without and with the effects, with their 95 % intervals."""
        s, b = self.samples_, self.baselines_
        out = []
        for srch, fit, ho in ((free, free.base, free.final.before),
                              (search, search.final.fit, search.final.after)):
            vals = srch.spec.values(fit.x)
            ci = parameter_ci(srch.spec, fit, ho.folds, s, b, ho.held)
            for k in srch.spec.at_limit(fit.x) if not no_signal else srch.spec.free:
                ci[k] = [float("nan"), float("nan")]  # not identified: no interval
            out.append(({k: float(vals[k]) for k in srch.spec.params}, ci))
        (self.calibration_, self.calibration_ci_), \
            (self.calibration_after_, self.calibration_after_ci_) = out

    def _tables(self, model: ForwardModel, base: ModelFit, final: FinalModel) -> None:
        """Errors in-sample and held out, per run and per oil and T; the final residual."""
        s = self.samples_
        y = s.viscous_W
        self.pred_ = {"without_T": model.base_power(self.law_without_T_),
                      "with_T": base.pred, "with_effect": final.fit.pred}
        self.rmse_ = {k: rmse(y - p) for k, p in self.pred_.items()}
        self.heldout_rmse_ = {"before": rmse(y - final.before.pred),
                              "after": rmse(y - final.after.pred)}
        self.residual_after_ = residual_structure(y - final.fit.pred, s)
        self.unexplained_ = unexplained_structure(self.residual_after_)
        if self.unexplained_:  # where it sits, how it scales, what it points to (issue 25)
            self.unexplained_["described"] = describe_residual(
                y - final.fit.pred, s, self.residual_after_["noise_W"])
        self.table3_ = table3_rows(s, self.pred_["without_T"], self.pred_["with_T"])
        self.per_run_ = per_run_rows(s, self.pred_, final, self.table3_)

    # ------------------------------------------------------------------ helpers
    def _checked_options(self) -> tuple[DesignCase, list[str]]:
        """The rig and the effects considered, after checking the options."""
        for k, v in (("margin", self.margin), ("min_explained", self.min_explained)):
            if not (isinstance(v, (int, float)) and 0.0 <= v < 1.0):
                raise InputError(k, v, "must be a number in [0, 1)", "loop")
        if self.cv not in CV_MODES:
            raise InputError("cv", self.cv, "allowed: one-step, full", "loop")
        if self.base not in (AUTO_BASE, *BASES):
            raise InputError("base", self.base, f"allowed: {', '.join((AUTO_BASE, *BASES))}",
                             "loop")
        if not (isinstance(self.max_effects, int) and self.max_effects >= 1):
            raise InputError("max_effects", self.max_effects, "must be an integer >= 1", "loop")
        names = list(EFFECTS) if self.effects is None else list(self.effects)
        for n in names:
            if n not in EFFECTS:
                raise InputError("effect", n, f"library effects are {', '.join(EFFECTS)}")
        return self.case or seed_case(), names

    def _as_data(self, data) -> MeasuredData:
        """Validated measured data from a path, a DataFrame or MeasuredData."""
        if isinstance(data, MeasuredData):
            return data
        oils = self.oils
        drive = getattr(self.case, "linear", None)
        if isinstance(data, (str, Path)) and drive is not None:  # rod_velocity_m_s rows
            cat = read_oils_csv(oils) if isinstance(oils, (str, Path)) else oils
            return validate(rod_rows_as_motor_speed(read_table(data), drive), cat, str(data))
        if isinstance(data, (str, Path)):
            return load_measured(data, oils)
        if isinstance(data, pd.DataFrame):
            cat = read_oils_csv(oils) if isinstance(oils, (str, Path)) else oils
            if drive is not None:
                data = rod_rows_as_motor_speed(data, drive)
            return validate(data, cat, "data frame")
        raise InputError("data", type(data).__name__, "a path, a pandas DataFrame or "
                         "MeasuredData is required")

    def _load_samples(self, data: MeasuredData) -> tuple[dict[float, BaselineFit], Samples]:
        """Stage 1: the baselines (power_W data) and the oil-run samples of ``data``."""
        kin = add_kinematics(data.frame, data.has_time)
        baselines: dict[float, BaselineFit] = {}
        if data.kind == "power_W":
            baselines = fit_baselines(kin)
        # cv_by with fewer than 2 groups (e.g. one oil run) is refused by oil_samples
        s = oil_samples(data, self.geometry_.regions[0].gap_m, baselines or None, frame=kin,
                        cv_by=self.cv_by)
        bad = ~(np.isfinite(s.nu_m2_s) & np.isfinite(s.density_kg_m3))
        if bad.any():  # pragma: no cover - validation guarantees properties
            raise InputError("oil", s.oil[bad][0], "no viscosity or density for this row")
        r1 = self.geometry_.regions[0].radius_m
        bad = ~((s.gap1_m > 0) & (s.gap1_m < r1))
        if bad.any():
            raise InputError("gap_mm", float(s.gap1_m[bad][0] * 1e3), "a region-1 clearance "
                             f"must lie between 0 and the rotor radius {r1 * 1e3:g} mm",
                             data.source)
        return baselines, s

    # ------------------------------------------------------------------ predict
    def fitted_model(self) -> FittedModel:
        """The fitted model as a predictor (what ``loop.json``'s ``model`` block holds).

        Returns
        -------
        FittedModel
        """
        self._check_fitted("predict()")
        return FittedModel.from_estimator(self)

    def _check_fitted(self, method: str) -> None:
        """Refuse ``method`` before :meth:`fit` (:class:`~oilgap.model.errors.NotFittedError`)."""
        if not hasattr(self, "law_"):
            raise NotFittedError("loop", method)

    def predict(self, data, stage: str = "with_effect") -> pd.Series:
        """Model viscous power [W] of the rows of ``data``, aligned with the caller's rows.

        Parameters
        ----------
        data : path, DataFrame or MeasuredData
            Rows of the same rig in the loop's data format; no power column and no
            oil-free runs needed (new operating conditions). Without ``time_s`` each
            row is a steady point.
        stage : {"without_T", "with_T", "with_effect"}
            Published law (gamma = 0), calibrated base model, or calibrated with the
            accepted effects.

        Returns
        -------
        pandas.Series
            Power [W] with the caller's index (a path: the file's row numbers from 0);
            NaN where a row cannot be predicted (oil-free, invalid), the reason in
            ``series.attrs["reason"]``.
        """
        cat = self.data_.oils if hasattr(self, "data_") else None
        return self.fitted_model().predict(data, stage, cat)

    # ------------------------------------------------------------------ report
    def to_dict(self) -> dict:
        """The loop.json document.

        Returns
        -------
        dict
            Errors [W], calibration, effects, candidates, selection, residuals,
            data, baselines and the three models' laws.
        """
        self._check_fitted("to_dict()")
        d = self.data_
        return {
            "rmse_W": dict(self.rmse_),
            "heldout_rmse_W": dict(self.heldout_rmse_),
            "per_run": [{k: r[k] for k in ("run", "oil", "roughness_T", "rmse_without_T_W",
                                           "rmse_with_T_W", "rmse_with_effect_W")}
                        for r in self.per_run_],
            "base": self.base_,
            **({"base_selection": {"requested": self.base, "margin": self.margin,
                                   "metric": "held-out log-RMSE", "candidates":
                                   self.base_selection_}} if self.base_selection_ else {}),
            "findings": [f.to_dict() for f in self.findings_],
            "parameter_ranges": {k: v.to_dict() for k, v in PARAM_RANGES.items()},
            "calibration": dict(self.calibration_),
            "effects": [e.to_dict() for e in self.effects_],
            "unexplained": self.unexplained_,
            "calibration_ci95": self.calibration_ci_,
            "calibration_with_effect": self.calibration_after_,
            "calibration_with_effect_ci95": self.calibration_after_ci_,
            "identifiability": self.identifiability_,
            "table3": self.table3_,
            "per_run_detail": self.per_run_,
            "candidates": self.candidates_,
            "cross_validation": dict(self.cv_scheme_),
            "selection": {"margin": self.margin, "min_explained": self.min_explained,
                          "noise_W": self.noise_W_, "heldout_linearised_W": self.heldout_linear_,
                          "steps": [s.to_dict() for s in self.selection_log_],
                          "lasso_path": self.lasso_path_},
            "confounded_forms": self.confounded_forms_,
            "residual_before": strip_bins(self.residual_before_),
            "residual_after": strip_bins(self.residual_after_),
            "data": {"source": d.source, "kind": d.kind, "rows_read": d.n_read,
                     "rows_dropped": d.n_dropped, "dropped": [x.to_dict() for x in d.dropped],
                     "ignored_columns": list(d.ignored_columns),
                     "oil_runs": len(self.samples_.run_names),
                     "oil_samples": int(self.samples_.n)},
            "baseline": [b.to_dict() for b in self.baselines_.values()],
            "models": {s: law_dict(law) for s, law in zip(
                STAGES, (self.law_without_T_, self.law_with_T_, self.law_), strict=True)},
            "model": self.fitted_model().to_dict(),
            **({"oil_state": self.oil_state_} if self.oil_state_["applied"] != "measured"
               else {}),
        }
