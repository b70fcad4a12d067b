"""The façade's argument checks: every public ``og.*`` function and method checks the types
of its arguments at the entry, with one decorator (:func:`checked`) and one table of kinds
(:class:`Arg` and the specs below), and refuses a wrong one with
:class:`~oilgap.model.errors.ArgumentError` (an ``InputError``, exit 2 on the command line;
also a ``TypeError``): one line naming the argument, the value's type or value, and what
is allowed. Values (ranges, NaN, files that do not exist) are then checked by the code the
function calls, with the same error class.

A kind is a type, or the name of a class (``"DataFrame"``, ``"MeasuredData"``) matched
against the value's class and its bases, so that this module loads no pandas.
"""

from __future__ import annotations

import functools
import inspect
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from oilgap.model.errors import ArgumentError


@dataclass(frozen=True)
class Arg:
    """What one argument takes: its kinds, in words, whether None is allowed, and a
    further check of the value (``check(name, value)``, raising ArgumentError)."""

    kinds: tuple
    allowed: str
    optional: bool = False
    check: Callable[[str, Any], None] | None = None

    def accepts(self, value: Any) -> bool:
        """Whether ``value`` is of one of the kinds (None when optional)."""
        if value is None:
            return self.optional
        names = {c.__name__ for c in type(value).__mro__}
        return any(k in names if isinstance(k, str) else
                   (isinstance(value, k) and not (k in (int, float) and isinstance(value, bool)))
                   for k in self.kinds)


def check_arg(name: str, value: Any, spec: Arg) -> Any:
    """``value`` checked against ``spec`` (returned as given).

    Raises
    ------
    ArgumentError
        A value of another kind; or the spec's own check failing.
    """
    if not spec.accepts(value):
        raise ArgumentError(name, value, spec.allowed + (" (or None)" if spec.optional
                                                         and "None" not in spec.allowed
                                                         else ""))
    if spec.check is not None and value is not None:
        spec.check(name, value)
    return value


def checked(**specs: Arg) -> Callable:
    """Decorator: the function's arguments named in ``specs`` (or given through its
    ``**keywords``) are checked by :func:`check_arg` before it runs; arguments that do not
    bind to its signature are refused the same way (never Python's TypeError)."""
    def decorate(fn: Callable) -> Callable:
        sig = inspect.signature(fn)
        varkw = next((p.name for p in sig.parameters.values()
                      if p.kind is inspect.Parameter.VAR_KEYWORD), None)

        @functools.wraps(fn)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            try:
                bound = sig.bind(*args, **kwargs)
            except TypeError as e:
                raise ArgumentError(fn.__name__ + "()", _Call(args, kwargs),
                                    f"{e}; the signature is {fn.__name__}{sig}") from None
            given = {**bound.arguments.get(varkw, {}), **bound.arguments}
            for name, spec in specs.items():
                if name in given:
                    check_arg(name, given[name], spec)
            return fn(*args, **kwargs)

        wrapper.__checks__ = specs
        return wrapper
    return decorate


class _Call:
    """The arguments of a call that did not bind, shown by their names."""

    def __init__(self, args: tuple, kwargs: dict):
        self.text = ", ".join([f"<{type(a).__name__}>" for a in args] + list(kwargs))

    def __repr__(self) -> str:
        return f"({self.text})"


def _finite(name: str, value: Any) -> None:
    if not math.isfinite(float(value)):
        raise ArgumentError(name, value, "a finite number is required (no NaN or infinity)")


def _path_text(name: str, value: Any) -> None:
    if not str(value).strip():
        raise ArgumentError(name, value, "a non-empty path is required")


def _all_dicts(name: str, value: Any) -> None:
    """A mission given as a list: every item a dict (a row) or a 3-tuple."""
    if isinstance(value, (list, tuple)):
        bad = [i for i, v in enumerate(value) if not isinstance(v, (dict, tuple, list))
               and type(v).__name__ != "MissionSegment"]
        if bad:
            raise ArgumentError(f"{name}[{bad[0]}]", value[bad[0]], "a row: a dict "
                                "{depth_m, oil_temp_C, fraction}, a (depth_m, oil_temp_C, "
                                "fraction) tuple or a MissionSegment")


def choice(*names: str, optional: bool = True) -> Arg:
    """An argument that takes one of ``names`` (str), or None (the default) when
    ``optional``."""
    allowed = f"one of {', '.join(names)}" + (" or None (the default)" if optional else "")

    def check(name: str, value: Any) -> None:
        if value not in names:
            raise ArgumentError(name, value, allowed)
    return Arg((str,), allowed, optional, check)


PATH_KINDS = (str, Path)
CASE = Arg((*PATH_KINDS, "DesignCase"), "a DesignCase, a path to a case TOML (str or "
           "pathlib.Path) or None (the seed joint)", optional=True, check=_path_text)
"""The joint: a case, its TOML file, or None for the seed joint."""
PATH = Arg(PATH_KINDS, "a path (str or pathlib.Path)", check=_path_text)
"""An input or output file."""
OUT = Arg(PATH_KINDS, "a folder path (str or pathlib.Path) or None (no files written)",
          optional=True, check=_path_text)
"""An output folder."""
OILS = Arg((*PATH_KINDS, dict), "a path to an oils CSV, a dict {name: Oil or {nu40_cSt, "
           "nu100_cSt, density_kg_m3}}, og.read_oils(...) or None (the built-in ISO VG "
           "catalogue)", optional=True)
"""An oils table (added to the built-in catalogue; ``og.read_oils(..., only=True)``
alone)."""
FLAG = Arg((bool, "bool_"), "True or False")
"""A switch (``force``, ``resume``, ``smoothed``)."""
NAME = Arg((str,), "a name (str) or None", optional=True)
"""A name such as an oil's (``"VG22"``) or a mode (``"bulk"``)."""
NUMBER = Arg((int, float, "number"), "a finite number or None", optional=True, check=_finite)
"""A scalar in the unit of the argument's name."""
DATA = Arg((*PATH_KINDS, "DataFrame", "MeasuredData"), "a path to a CSV/Parquet file, a "
           "pandas DataFrame or MeasuredData", check=_path_text)
"""Rig data (measured runs, or rows to predict)."""
GRID = Arg((*PATH_KINDS, "DataFrame"), "a pandas DataFrame or a path to a CSV/Parquet grid",
           check=_path_text)
"""A sweep's grid."""
MISSION = Arg((*PATH_KINDS, list, tuple, "DataFrame"), "a list of rows ({depth_m, "
              "oil_temp_C, fraction} dicts or tuples), a DataFrame with those columns or a "
              "CSV path", optional=True, check=_all_dicts)
"""An oil-grade mission."""
MODEL = Arg((*PATH_KINDS, "FittedModel", "LoopEstimator"), "a path to loop.json, a "
            "FittedModel or a fitted og.Loop (a dict read from loop.json: pass the file's "
            "path instead)", check=_path_text)
"""A model the loop fitted."""
EFFECT_NAMES = Arg((str, list, tuple), "effect names: 'a,b' or a list of str", optional=True)
"""The loop's library effects."""
NAMES = Arg((tuple, list), "a tuple of numbers, e.g. (4, 2)")
"""A sequence of values."""
INT = Arg((int, "integer"), "an integer", optional=True)
"""A whole number (a seed, a count)."""
AX = Arg(("Axes",), "a matplotlib Axes or None (a new figure)", optional=True)
"""The axes a result draws on."""


__all__ = ["AX", "CASE", "DATA", "EFFECT_NAMES", "FLAG", "GRID", "INT", "MISSION", "MODEL", "NAME",
           "NAMES", "NUMBER", "OILS", "OUT", "PATH", "Arg", "check_arg", "checked", "choice"]
