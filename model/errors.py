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
    """Bad input: names the field, the value and what is allowed.

    The message reads ``"{where}: {field} = {value!r} is not allowed; {allowed}"``;
    the command line prints it and exits 2.

    Parameters
    ----------
    field : str
        Name of the offending key, column or argument, with its unit as the user
        wrote it (``"T3_mm"``, ``"depth_m"``).
    value : Any
        The offending value [in the unit of ``field``].
    allowed : str
        What would have been accepted.
    where : str, optional
        Where the value came from (file, table, line).

    Attributes
    ----------
    field, value, allowed, where
        As given.
    """

    def __init__(self, field: str, value: Any, allowed: str, where: str | None = None):
        self.field = field
        self.value = value
        self.allowed = allowed
        self.where = where
        loc = f"{where}: " if where else ""
        super().__init__(f"{loc}{field} = {value!r} is not allowed; {allowed}")


class ArgumentError(InputError, TypeError):
    """A façade argument of a type the function does not take (``og.read_case(None)``):
    an :class:`InputError` (exit 2 on the command line) that is also a ``TypeError``.

    The message reads ``"{field} = {value} is not allowed; {allowed}"`` with the value
    shown as its type, or its value when short (``a list of 2 int [1, 2]``).

    Parameters
    ----------
    field : str
        The argument's name (``"mission"``, ``"model"``).
    value : Any
        The value given (shown by :func:`describe`).
    allowed : str
        What the argument takes.
    """

    def __init__(self, field: str, value: Any, allowed: str):
        super().__init__(field, _Shown(describe(value)), allowed)
        self.value = value


class _Shown(str):
    """A value's description, quoted as is in a message."""

    def __repr__(self) -> str:
        return str(self)


def describe(value: Any) -> str:
    """A value in a few words for a message: short scalars as they are (``None``,
    ``42``, ``'abc'``), containers and arrays by type and size.

    Parameters
    ----------
    value : Any
        Anything [-].

    Returns
    -------
    str
        E.g. ``"None"``, ``"42 (int)"``, ``"a list of 2 int [1, 2]"``,
        ``"a numpy array of shape (2, 2)"``, ``"a dict with keys ['a']"``.
    """
    kind = type(value).__name__
    if value is None:
        return "None"
    if isinstance(value, (bool, int, float, complex, str, bytes)):
        text = repr(value)
        return f"{text[:60]}{'...' if len(text) > 60 else ''} ({kind})"
    shape = getattr(value, "shape", None)
    if isinstance(shape, tuple):
        return f"a {type(value).__module__.split('.')[0]} {kind} of shape {shape}"
    if isinstance(value, dict):
        keys = list(value)[:4]
        return f"a dict with keys {keys!r}{'...' if len(value) > 4 else ''}"
    if isinstance(value, (list, tuple, set, frozenset)):
        kinds = sorted({type(v).__name__ for v in value})
        text = repr(value)
        return (f"a {kind} of {len(value)} {'/'.join(kinds) or 'items'} "
                f"{text[:40]}{'...' if len(text) > 40 else ''}")
    return f"a {kind}"


class NotFittedError(InputError):
    """An estimator used before its ``fit``: names it and what to call first.

    Parameters
    ----------
    estimator : str
        The estimator's name (``"loop"``).
    method : str
        What was called (``"predict"``, ``"summary"``).
    """

    def __init__(self, estimator: str, method: str):
        super().__init__(estimator, "unfitted", f"call fit(data) before {method}")


class SolverError(RuntimeError):
    """A numerical solver did not deliver a trustworthy answer.

    Parameters
    ----------
    message : str
        What failed.
    status : str, optional
        The solver's status word (e.g. IPOPT's ``return_status``).
    last_iterate : dict, optional
        The solver's last iterate, by variable name [SI units of each variable].

    Attributes
    ----------
    status, last_iterate
        As given.
    exit_code : int
        Exit status of the command line: 4.
    """

    exit_code = 4

    def __init__(self, message: str, status: str = "", last_iterate: dict | None = None):
        self.status = status
        self.last_iterate = last_iterate or {}
        super().__init__(message)


class InfeasibleError(SolverError):
    """The constraints of a design problem cannot all hold.

    Parameters
    ----------
    message, status, last_iterate
        As for :class:`SolverError`.

    Attributes
    ----------
    exit_code : int
        Exit status of the command line: 3.
    """

    exit_code = 3


class OilgapWarning(UserWarning):
    """A result that is computed but outside where its law is trustworthy.

    Parameters
    ----------
    message : str
        The quantity, its value [with its unit] and the range where the law holds.
    """


def check_finite(field: str, value: Any, where: str | None = None) -> float:
    """Return ``value`` as float, or raise InputError if it is not a finite number.

    Parameters
    ----------
    field : str
        Name of the value in messages.
    value : Any
        The value to check [in the unit of ``field``]; bools and strings are refused.
    where : str, optional
        Where the value came from, for the message.

    Returns
    -------
    float
        ``float(value)`` [in the unit of ``field``].

    Raises
    ------
    InputError
        Not a number, NaN or infinite.
    """
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
    """Return ``value`` as a finite float > 0, or raise InputError.

    Parameters
    ----------
    field : str
        Name of the value in messages.
    value : Any
        The value to check [in the unit of ``field``].
    where : str, optional
        Where the value came from, for the message.

    Returns
    -------
    float
        ``float(value)`` [in the unit of ``field``].

    Raises
    ------
    InputError
        Not a finite number, or <= 0.
    """
    x = check_finite(field, value, where)
    if x <= 0.0:
        raise InputError(field, value, "must be > 0", where)
    return x


def check_range(field: str, value: Any, lo: float | None = None, hi: float | None = None,
                where: str | None = None) -> float:
    """Return ``value`` as a finite float within [lo, hi], or raise InputError.

    Parameters
    ----------
    field : str
        Name of the value in messages.
    value : Any
        The value to check [in the unit of ``field``].
    lo, hi : float, optional
        Inclusive bounds [in the unit of ``field``]; None: unbounded on that side.
    where : str, optional
        Where the value came from, for the message.

    Returns
    -------
    float
        ``float(value)`` [in the unit of ``field``].

    Raises
    ------
    InputError
        Not a finite number, or outside [lo, hi].
    """
    x = check_finite(field, value, where)
    if (lo is not None and x < lo) or (hi is not None and x > hi):
        lo_s = "-inf" if lo is None else f"{lo:g}"
        hi_s = "inf" if hi is None else f"{hi:g}"
        raise InputError(field, value, f"allowed range is [{lo_s}, {hi_s}]", where)
    return x
