"""Planning rig tests: which runs identify the law and detect the effects.

* :mod:`.fisher`: the Fisher information of candidate runs from the loop's forward model
  (CasADi AD of its region composition; the effects' library features).
* :mod:`.design`: continuous D-, A-, E- and T-optimal designs over the candidates
  (cvxpy), their optimality gap (general equivalence theorem), efficient rounding.
* :mod:`.analysis`: expected sds (least-squares sandwich, the loop's jackknife),
  smallest detectable effects (linearised T-criterion), confounded directions.
"""

from .analysis import base_sd, confounding, detectable_sizes, jackknife_sd, sandwich
from .design import CRITERIA, ContinuousDesign, efficient_rounding, equivalence_gap, optimal_weights
from .fisher import Parameters, base_jacobian, effect_columns, run_information, symbolic_law

__all__ = ["CRITERIA", "ContinuousDesign", "Parameters", "base_jacobian", "base_sd",
           "confounding", "detectable_sizes", "effect_columns", "efficient_rounding",
           "equivalence_gap", "jackknife_sd", "optimal_weights", "run_information",
           "sandwich", "symbolic_law"]
