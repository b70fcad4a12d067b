"""Uncertain inputs of a joint's loss: what they are and how a set of values makes a case.

:mod:`.inputs` names the inputs and applies one set of values to a case (the scalar
reference path); :mod:`.distributions` gives them laws (the ``[uncertainty]`` table and its
defaults) and quasi-Monte Carlo samples.
"""

from .distributions import Distribution, UncertaintySpec, case_uncertainty
from .inputs import INPUTS, InputInfo, apply_inputs, nominal_inputs

__all__ = ["INPUTS", "Distribution", "InputInfo", "UncertaintySpec", "apply_inputs",
           "case_uncertainty", "nominal_inputs"]
