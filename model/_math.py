"""Elementary functions that work on floats, numpy arrays and CasADi symbols.

Every physics function in :mod:`oilgap.model` is written with these, so that the
design NLP (CasADi) differentiates exactly the code the studies evaluate (numpy).
Dispatch is by argument type: if any argument is a CasADi ``SX``, ``MX`` or ``DM``
the CasADi function is used, otherwise the numpy one.
"""

from __future__ import annotations

from typing import Any

import casadi as ca
import numpy as np

_CASADI_TYPES = (ca.SX, ca.MX, ca.DM)


def is_symbolic(*args: Any) -> bool:
    """Return True if any argument is a CasADi matrix (SX, MX or DM)."""
    for a in args:  # a plain loop: this runs in every law's every call
        if isinstance(a, _CASADI_TYPES):
            return True
    return False


def exp(x):
    return ca.exp(x) if is_symbolic(x) else np.exp(x)


def log(x):
    return ca.log(x) if is_symbolic(x) else np.log(x)


def log10(x):
    return ca.log10(x) if is_symbolic(x) else np.log10(x)


def sqrt(x):
    return ca.sqrt(x) if is_symbolic(x) else np.sqrt(x)


def tanh(x):
    return ca.tanh(x) if is_symbolic(x) else np.tanh(x)


def atan(x):
    return ca.atan(x) if is_symbolic(x) else np.arctan(x)


def fabs(x):
    return ca.fabs(x) if is_symbolic(x) else np.abs(x)


def fmax(a, b):
    return ca.fmax(a, b) if is_symbolic(a, b) else np.maximum(a, b)


def fmin(a, b):
    return ca.fmin(a, b) if is_symbolic(a, b) else np.minimum(a, b)


def sign(x):
    return ca.sign(x) if is_symbolic(x) else np.sign(x)


def where(cond, a, b):
    """Elementwise ``a if cond else b`` (``if_else`` for CasADi)."""
    if is_symbolic(cond, a, b):
        return ca.if_else(cond, a, b)
    return np.where(cond, a, b)


def sigmoid(z):
    """Logistic function 1/(1+exp(-z)), written with tanh so it never overflows."""
    return 0.5 * (1.0 + tanh(0.5 * z))


def smooth_relu(z, width: float):
    """Smooth ``max(0, z)``: (z + sqrt(z**2 + width**2))/2.

    Twice differentiable everywhere; the error is width/2 at z = 0 and falls as
    width**2/(4|z|) away from it. No overflow for any z.
    """
    return 0.5 * (z + sqrt(z * z + width * width))
