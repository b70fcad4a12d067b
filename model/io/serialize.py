"""The one writer of oilgap's JSON and TOML text: floats rounded to what the model can
claim, NaN and infinities as ``null``, numpy scalars and arrays as plain numbers.

Every JSON document oilgap prints or writes (``--json``, ``loop.json``,
``oil_grade.json``, a fitted model, the ``defaults`` and provenance blocks) goes
through :func:`dumps`; every TOML file through :func:`toml_dumps` (tomli-w). The
numbers are rounded to :data:`SIGNIFICANT_DIGITS` significant digits, so that
``3000.0000000000005`` is written ``3000.0`` and ``37.713312256684894`` is
written ``37.7133``: the physics behind them (empirical friction laws, viscosity
correlations) is good to a few per cent, never to 17 digits.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import tomli_w

SIGNIFICANT_DIGITS = 6
"""Significant digits of every float oilgap writes to JSON or TOML."""

FULL_DIGITS = 17
"""Digits that write a float so that it reads back to the same float (IEEE double)."""


class Exact(dict):
    """A block of a document written with every digit (:data:`FULL_DIGITS`), not rounded:
    machine state that must read back to the same numbers (the fitted model of
    ``loop.json``, which ``oilgap predict`` uses to reproduce the fit's predictions).
    A ``dict``, so :func:`json.dumps` writes it as well.

    Parameters
    ----------
    *args, **kwargs
        As for ``dict`` (keys -> values in the units of their names) [-].
    """


def round_sig(x: float, digits: int = SIGNIFICANT_DIGITS) -> float:
    """``x`` rounded to ``digits`` significant digits (0, NaN and infinities unchanged).

    Parameters
    ----------
    x : float
        The number [any unit].
    digits : int
        Significant digits kept (>= 1) [-].

    Returns
    -------
    float
        The rounded number [the unit of x], e.g. ``round_sig(37.713312256684894) == 37.7133``.
    """
    if x == 0.0 or not math.isfinite(x):
        return x
    return float(f"{x:.{digits}g}")


def plain(obj: Any, digits: int = SIGNIFICANT_DIGITS) -> Any:
    """``obj`` with every float rounded (:func:`round_sig`), NaN/inf as None, numpy
    scalars and arrays as Python numbers and lists, tuples as lists and mapping keys as
    strings: what JSON and TOML can hold.

    Parameters
    ----------
    obj : Any
        A document of dicts, lists, tuples, numbers, strings, booleans, None and numpy
        values.
    digits : int
        Significant digits of the floats [-].

    Returns
    -------
    Any
        The same document in plain Python types.
    """
    if isinstance(obj, bool | np.bool_):
        return bool(obj)
    if isinstance(obj, int | np.integer):
        return int(obj)
    if isinstance(obj, float | np.floating):
        x = float(obj)
        return None if not math.isfinite(x) else round_sig(x, digits)
    if isinstance(obj, Exact):
        digits = FULL_DIGITS
    if isinstance(obj, Mapping):
        return {str(k): plain(v, digits) for k, v in obj.items()}
    if isinstance(obj, np.ndarray):
        return [plain(v, digits) for v in obj.tolist()]
    if isinstance(obj, list | tuple | set | frozenset):
        return [plain(v, digits) for v in obj]
    if hasattr(obj, "to_dict") and callable(obj.to_dict):
        return plain(obj.to_dict(), digits)
    if hasattr(obj, "__fspath__"):
        return str(obj)
    return obj


def dumps(obj: Any, digits: int = SIGNIFICANT_DIGITS, indent: int | None = 2) -> str:
    """The JSON text of ``obj`` (:func:`plain` first: rounded floats, NaN as null).

    Parameters
    ----------
    obj : Any
        The document.
    digits : int
        Significant digits of the floats [-].
    indent : int or None
        JSON indentation (None: one line).

    Returns
    -------
    str
        Strict JSON (no ``NaN`` or ``Infinity`` tokens).
    """
    return json.dumps(plain(obj, digits), indent=indent, allow_nan=False)


def toml_dumps(doc: Mapping[str, Any], digits: int = SIGNIFICANT_DIGITS) -> str:
    """The TOML text of ``doc`` written by tomli-w, floats rounded (:func:`plain`; None
    values are left out, TOML has no null).

    Parameters
    ----------
    doc : Mapping
        Tables (dicts) and values.
    digits : int
        Significant digits of the floats [-].

    Returns
    -------
    str
        TOML text.
    """
    def drop_none(v: Any) -> Any:
        if isinstance(v, dict):
            return {k: drop_none(x) for k, x in v.items() if x is not None}
        if isinstance(v, list):
            return [drop_none(x) for x in v]
        return v

    return tomli_w.dumps(drop_none(plain(doc, digits)))
