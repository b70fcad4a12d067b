"""The calibration engine: measured runs -> calibrated Eq. 8 -> the missing effect.

Stages (each its own module, called in this order by :class:`LoopEstimator`):

* :mod:`.baseline`: the oil-free baseline of each roughness T.
* :mod:`.forward`: the forward model (Eq. 8 per region plus effect terms).
* :mod:`.spec`: the base model (Eq. 6 x scale x T^gamma, or a free power law) and
  which of its parameters the data, and each cross-validation fold, identify.
* :mod:`.least_squares`: nonlinear least squares, one-step folds.
* :mod:`.ranges`: the physical range of each calibrated parameter; findings.
* :mod:`.residuals`: noise level and structure of a residual.
* :mod:`oilgap.optim.calibration.candidates`: library effects as candidate regression columns.
* :mod:`.folds`: the cross-validation folds (whole groups; one per group up to 10,
  grouped 10-fold above) and the scheme stated in the report.
* :mod:`.selection`: sign-constrained lasso, box least squares, cross-validation
  selector, forward selection with backward pruning.
* :mod:`.steps`: the log of the effect search, one record per decision.
* :mod:`.search`: screening, selection and refit, repeated without implausible
  fits; the evidence trial of a parameter outside its range.
* :mod:`.refit`: nonlinear refit of the selected effects, held-out errors.
* :mod:`.uncertainty`: jackknife intervals, baseline variance propagation.
* :mod:`.results`: effect records, candidate statuses, per-run and Table 3 rows.
* :mod:`.estimator`: :class:`LoopEstimator`.
"""

from .baseline import BaselineFit, fit_baselines
from .candidates import Candidates, exact_form_variants, screen_candidates
from .estimator import LoopEstimator
from .folds import MAX_FOLDS, cv_folds, cv_scheme, grouped_folds
from .forward import EXACT_FORMS, ForwardModel, sample_geometry
from .least_squares import (
    ModelFit,
    check_alpha,
    fit_model,
    identifiability,
    initial_guess,
    one_step_fold,
)
from .ranges import PARAM_RANGES, Finding, ParamRange, held_values, parameter_findings
from .refit import FinalModel, HeldOut, Refitter, heldout_gains, refit_selected, rmse
from .residuals import (
    autocorrelation,
    describe_structure,
    noise_estimate,
    residual_structure,
    unexplained_structure,
)
from .results import (
    EffectResult,
    candidate_statuses,
    effect_results,
    per_run_rows,
    table3_rows,
)
from .search import EffectSearch, SearchOptions, evidence_trial, fluid_facts, search_effects
from .selection import (
    LeaveOneRunOutSelector,
    Selection,
    SignConstrainedLasso,
    StepwiseResult,
    Thresholds,
    box_lstsq,
    score_alone,
    select_effects,
    stepwise_selection,
)
from .spec import (
    BASE_PARAMS,
    BASES,
    EQ6_PARAMS,
    LOG_PARAMS,
    PARAM_LIMITS,
    BaseSpec,
    cv_groups,
    decide_spec,
    fold_spec,
)
from .steps import SelectionStep
from .uncertainty import baseline_variance, effect_ci, jackknife_ci, parameter_ci

__all__ = [
    "MAX_FOLDS", "cv_folds", "cv_scheme", "grouped_folds",
    "BASES", "EQ6_PARAMS", "LOG_PARAMS", "PARAM_LIMITS", "PARAM_RANGES", "ParamRange",
    "Finding", "EffectSearch", "SearchOptions", "check_alpha", "cv_groups", "evidence_trial",
    "fluid_facts", "fold_spec", "held_values", "parameter_findings", "search_effects",
    "BASE_PARAMS", "EXACT_FORMS", "BaseSpec", "BaselineFit", "Candidates", "EffectResult",
    "FinalModel", "ForwardModel", "HeldOut", "LeaveOneRunOutSelector", "LoopEstimator",
    "ModelFit", "Refitter", "Selection", "SelectionStep", "SignConstrainedLasso", "StepwiseResult",
    "Thresholds",
    "autocorrelation", "baseline_variance", "box_lstsq", "candidate_statuses", "decide_spec",
    "describe_structure", "effect_ci", "effect_results", "exact_form_variants", "fit_baselines",
    "fit_model", "heldout_gains", "identifiability", "initial_guess", "jackknife_ci",
    "noise_estimate", "one_step_fold", "parameter_ci", "per_run_rows", "refit_selected",
    "residual_structure", "rmse", "sample_geometry", "score_alone", "screen_candidates",
    "select_effects", "stepwise_selection", "table3_rows", "unexplained_structure",
]
