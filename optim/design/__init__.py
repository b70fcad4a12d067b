"""The design NLP of the clearance geometry (CasADi/IPOPT) and its results.

One module per responsibility:

* :mod:`.variables`: the decision variables, their scaling for IPOPT, the IPOPT options;
* :mod:`.parameters`: the parameters of one solve, resolved and validated;
* :mod:`.objective`: the one objective (mean power, torque, inertia; CasADi and numpy);
* :mod:`.feasibility`: the feasibility check before IPOPT and its message;
* :mod:`.results`: design points, multipliers (converted to physical units), the optimum;
* :mod:`.session`: the one IPOPT session every solve goes through (the solver, warm start,
  buffered calls), multi-start, bound snapping and the failure message;
* :mod:`.problem`: the isothermal NLP built once per case, and its solves;
* :mod:`.thermal`: the NLP under a thermal mode (film factor; oil temperature and heat
  balance as a variable and an equality);
* :mod:`.lean`: a sweep's solve of the isothermal NLP (buffered, only the sweep's columns);
* :mod:`.heating`: the optimum with and without heating, side by side;
* :mod:`.scenarios`, :mod:`.robust`, :mod:`.robust_nlp`, :mod:`.robust_bulk`: the robust
  design NLP over N scenarios of the uncertain inputs (mean, mean + 2 sd, p95 by its
  CVaR), under thermal ``none`` or ``bulk``.
"""

from .feasibility import check_feasible, infeasibility_message
from .heating import HeatingComparison, compare_heating
from .objective import DesignObjective, region1_mean_power
from .parameters import DesignParameters
from .problem import DesignProblem, solve_design
from .results import (
    DesignPoint,
    DesignResult,
    Multiplier,
    ThermalDesignResult,
    convert_multipliers,
    design_point,
)
from .robust import RobustDesignProblem, RobustSolve
from .session import DEFAULT_STARTS, SolverSession
from .thermal import ThermalDesignProblem
from .variables import VARIABLE_LABELS, VARIABLES, from_nlp, to_nlp

__all__ = [
    "VARIABLES", "VARIABLE_LABELS", "DesignParameters", "DesignPoint", "DesignProblem",
    "DesignResult", "Multiplier", "region1_mean_power", "solve_design", "DesignObjective",
    "check_feasible", "infeasibility_message", "convert_multipliers",
    "design_point", "to_nlp", "from_nlp", "ThermalDesignProblem", "ThermalDesignResult",
    "HeatingComparison", "compare_heating", "DEFAULT_STARTS", "SolverSession",
    "RobustDesignProblem", "RobustSolve",
]
