"""The calibration engine: measured runs -> calibrated Eq. 8 -> the missing effect.

Stages (each its own module, called in this order by :class:`LoopEstimator`):

* :mod:`.baseline`: the oil-free baseline of each roughness T.
* :mod:`.forward`: the forward model (Eq. 8 per region plus effect terms).
* :mod:`.least_squares`: which Eq. 8 parameters the data identify, nonlinear
  least squares, one-step leave-one-run-out folds.
* :mod:`.residuals`: noise level and structure of a residual.
* :mod:`.candidates`: library effects as candidate regression columns.
* :mod:`.selection`: sign-constrained lasso, box least squares, leave-one-run-out
  selector, forward selection with backward pruning.
* :mod:`.refit`: nonlinear refit of the selected effects, held-out errors.
* :mod:`.uncertainty`: jackknife intervals, baseline variance propagation.
* :mod:`.results`: effect records, candidate statuses, per-run and Table 3 rows.
* :mod:`.estimator`: :class:`LoopEstimator`.
"""

from .baseline import BaselineFit, fit_baselines
from .candidates import Candidates, exact_form_variants, screen_candidates
from .estimator import LoopEstimator
from .forward import EXACT_FORMS, ForwardModel, sample_geometry
from .least_squares import (
    BASE_PARAMS,
    BaseSpec,
    ModelFit,
    decide_spec,
    fit_model,
    identifiability,
    initial_guess,
    one_step_fold,
)
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
from .selection import (
    LeaveOneRunOutSelector,
    Selection,
    SignConstrainedLasso,
    StepwiseResult,
    box_lstsq,
    score_alone,
    select_effects,
    stepwise_selection,
)
from .uncertainty import baseline_variance, effect_ci, jackknife_ci, parameter_ci

__all__ = [
    "BASE_PARAMS", "EXACT_FORMS", "BaseSpec", "BaselineFit", "Candidates", "EffectResult",
    "FinalModel", "ForwardModel", "HeldOut", "LeaveOneRunOutSelector", "LoopEstimator",
    "ModelFit", "Refitter", "Selection", "SignConstrainedLasso", "StepwiseResult",
    "autocorrelation", "baseline_variance", "box_lstsq", "candidate_statuses", "decide_spec",
    "describe_structure", "effect_ci", "effect_results", "exact_form_variants", "fit_baselines",
    "fit_model", "heldout_gains", "identifiability", "initial_guess", "jackknife_ci",
    "noise_estimate", "one_step_fold", "parameter_ci", "per_run_rows", "refit_selected",
    "residual_structure", "rmse", "sample_geometry", "score_alone", "screen_candidates",
    "select_effects", "stepwise_selection", "table3_rows", "unexplained_structure",
]
