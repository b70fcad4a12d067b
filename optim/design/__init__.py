"""The design NLP of the clearance geometry (CasADi/IPOPT) and its results."""

from .problem import (
    VARIABLE_LABELS,
    VARIABLES,
    DesignParameters,
    DesignPoint,
    DesignProblem,
    DesignResult,
    Multiplier,
    region1_mean_power,
    solve_design,
)

__all__ = [
    "VARIABLES", "VARIABLE_LABELS", "DesignParameters", "DesignPoint", "DesignProblem",
    "DesignResult", "Multiplier", "region1_mean_power", "solve_design",
]
