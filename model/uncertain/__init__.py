"""Uncertain inputs of a joint's loss: what they are and how a set of values makes a case.

:mod:`.inputs` names the inputs and applies one set of values to a case (the scalar
reference path).
"""

from .inputs import INPUTS, InputInfo, apply_inputs, nominal_inputs

__all__ = ["INPUTS", "InputInfo", "apply_inputs", "nominal_inputs"]
