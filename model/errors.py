"""Exceptions and warnings of oilgap.

Every refusal of bad input is an :class:`InputError` that names the field, the
value and what is allowed; the command line prints its message and exits 2.
Solver failures are :class:`SolverError` (exit 3 for infeasible, 4 otherwise),
never results.
"""

from __future__ import annotations

import math
from typing import Any


class InputError(ValueError):
    """Bad input: names the field, the value and what is allowed."""

    def __init__(self, field: str, value: Any, allowed: str, where: str | None = None):
        self.field = field
        self.value = value
        self.allowed = allowed
        self.where = where
        loc = f"{where}: " if where else ""
        super().__init__(f"{loc}{field} = {value!r} is not allowed; {allowed}")


class SolverError(RuntimeError):
    """A numerical solver did not deliver a trustworthy answer."""

    exit_code = 4

    def __init__(self, message: str, status: str = "", last_iterate: dict | None = None):
        self.status = status
        self.last_iterate = last_iterate or {}
        super().__init__(message)


class InfeasibleError(SolverError):
    """The constraints of a design problem cannot all hold."""

    exit_code = 3


class OilgapWarning(UserWarning):
    """A result that is computed but outside where its law is trustworthy."""


def check_finite(field: str, value: Any, where: str | None = None) -> float:
    """Return ``value`` as float, or raise InputError if it is not a finite number."""
    if isinstance(value, (bool, str, bytes)):
        raise InputError(field, value, "a finite number is required", where)
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InputError(field, value, "a finite number is required", where) from None
    if not math.isfinite(x):
        raise InputError(field, value, "a finite number is required (no NaN or infinity)", where)
    return x


def check_positive(field: str, value: Any, where: str | None = None) -> float:
    """Return ``value`` as a finite float > 0, or raise InputError."""
    x = check_finite(field, value, where)
    if x <= 0.0:
        raise InputError(field, value, "must be > 0", where)
    return x


def check_range(field: str, value: Any, lo: float | None = None, hi: float | None = None,
                where: str | None = None) -> float:
    """Return ``value`` as a finite float within [lo, hi], or raise InputError."""
    x = check_finite(field, value, where)
    if (lo is not None and x < lo) or (hi is not None and x > hi):
        lo_s = "-inf" if lo is None else f"{lo:g}"
        hi_s = "inf" if hi is None else f"{hi:g}"
        raise InputError(field, value, f"allowed range is [{lo_s}, {hi_s}]", where)
    return x
