"""The schema of a saved loop model (``loop.json``'s ``model`` block) and the ranges of its
fitted numbers, checked once on load.

A saved model is a file a user can edit or cut short, so prediction never trusts it:
:func:`parse_model_json` reads the text (refusing ``NaN``/``Infinity`` literals and keys
given twice) and :func:`check_model_doc` checks the document before anything is built
from it: its format and version, every required field with its type, the lengths that
must agree (a baseline's coefficients and its basis functions, the branches of a law),
the names that must be known (effects of the library, friction forms, the thermal
mode, the power column), every number finite, and every fitted number inside its range:

* the friction laws' ``gamma``, ``scale``, ``C``, ``alpha``, ``beta`` (and the branches'
  ``C_k``, ``alpha_k``, ``beta_k``) inside the ranges a friction law may have as input
  (:data:`oilgap.model.skin_friction.FRICTION_RANGES`: gamma in [0, 3]);
* each effect's coefficient of the sign the library demands and inside the library's
  plausible range on the saved rig (:data:`oilgap.model.effects.PLAUSIBLE`; the film
  strength s in [0, 1]);
* the shapes (the Taylor-vortex exponent m, one of those the loop fits; the film's wall
  condition w in [0, 1]), the baselines (T >= 1, a positive speed, ordered
  temperatures), the fitted ranges (``[low, high]``, low <= high) and the region-1
  clearance (> 0).

Each failure is one :class:`~oilgap.model.errors.InputError` naming the field by its
JSON path (``model.laws.with_effect.gamma``, ``model.baselines[0].coef``), the value and
what is allowed. The schema is the table of ``docs/loop.md`` ("The saved model").

References
----------
.. [1] ECMA-404, *The JSON data interchange syntax*, 2nd ed., 2017 (numbers are finite:
   ``NaN`` and ``Infinity`` are not JSON).
.. [2] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 6-9 (the friction law and its gamma).
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from oilgap.model.effects import EFFECTS, PLAUSIBLE, RigFacts
from oilgap.model.errors import InputError
from oilgap.model.skin_friction import BRANCH_KEYS, FORMS, FRICTION_RANGES, LAMINAR_LAWS
from oilgap.model.transition import TRANSITIONS

from .baseline import BASELINE_TEMP_TERMS, BASELINE_TERMS
from .forward import TAYLOR_SHAPES

STAGES = ("without_T", "with_T", "with_effect")
"""The models of the report, each with its friction law."""

KINDS = ("power_W", "viscous_power_W")
"""Power column of the fitted data."""

LOOP_THERMAL_MODES = ("none", "film")
"""Thermal modes of a calibrated model (``film`` only with ``film_heating``)."""

RANGE_KEYS = ("abs_speed_rpm", "temp_C", "nu_cSt", "gap_mm", "roughness_T", "reynolds",
              "taylor")
"""Operating variables whose fitted range is recorded."""

REQUIRED = {"format": str, "version": int, "case": dict, "laws": dict, "effects": dict,
            "region1_gap_m": float, "kind": str}
"""Keys a model block must hold, with their JSON type (float: any finite number)."""

OPTIONAL = {"shapes": dict, "baselines": list, "fluids": dict, "pressure_gauge_Pa": float,
            "has_time": bool, "cv_by": str, "thermal_mode": str, "fitted_range": dict}
"""Keys a model block may hold, with their JSON type."""

LAW_KEYS = ("form", "laminar_law", "gamma", "scale", "C", "alpha", "beta") + BRANCH_KEYS + (
    "transition",)
"""Keys of a friction law."""

BRANCH_RANGE = {"branch_C": "C", "branch_alpha": "alpha", "branch_beta": "beta"}
"""The range each branch array takes (that of its single-law counterpart)."""

BASELINE_KEYS = {"roughness_T": float, "terms": list, "coef": list, "temp_ref_C": float,
                 "rmse_W": float, "n_samples": int, "temp_range_C": list,
                 "speed_max_rpm": float}
"""Keys of an oil-free baseline, with their JSON type."""

REL_TOL = 1e-9
"""Relative slack on a range's ends (a coefficient fitted at its bound reads back there)."""

AGAIN = ("a model as oilgap loop writes it; a fit outside a range is a finding of the "
         "loop's report, not a model to predict with")
"""What to do about a saved model that fails its schema."""

_TYPE_TEXT = {str: "a string", int: "an integer", float: "a finite number", dict: "an object",
              list: "an array", bool: "true or false"}


_TEXT_KEYS = ("name", "source", "outside", "kind", "form", "laminar_law", "transition")


def encode(x: Any) -> Any:
    """JSON-safe value: non-finite floats as strings, tuples and arrays as lists [1].

    Parameters
    ----------
    x : Any
        A value of a model block (numbers in the unit of their key).

    Returns
    -------
    Any
        The same with ``nan``/``inf``/``-inf`` as strings [-].
    """
    if isinstance(x, dict):
        return {str(k): encode(v) for k, v in x.items()}
    if isinstance(x, (list, tuple, np.ndarray)):
        return [encode(v) for v in x]
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (int, np.integer)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        v = float(x)
        return v if math.isfinite(v) else ("nan" if math.isnan(v) else
                                           ("inf" if v > 0 else "-inf"))
    return x


def decode(x: Any, key: str = "") -> Any:
    """Inverse of :func:`encode` (lists become tuples).

    Parameters
    ----------
    x : Any
        A value of a model block as read.
    key : str
        Its key (text keys keep the strings ``"inf"``, ``"nan"``).

    Returns
    -------
    Any
        The value with non-finite strings as floats [-].
    """
    if isinstance(x, dict):
        return {k: decode(v, k) for k, v in x.items()}
    if isinstance(x, list):
        return tuple(decode(v, key) for v in x)
    if isinstance(x, str) and key not in _TEXT_KEYS and x in ("inf", "-inf", "nan"):
        return float(x)
    return x


class _Literal(str):
    """A ``NaN``/``Infinity``/``-Infinity`` literal met while parsing (refused by path)."""


class _Duplicate(dict):
    """An object whose key ``key`` was given twice."""


def _pairs(pairs: list) -> dict:
    out: dict = {}
    for k, v in pairs:
        if k in out:
            d = _Duplicate(out)
            d.duplicate = k
            return d
        out[k] = v
    return out


def parse_model_json(text: str) -> Any:
    """Parse a saved model's JSON text, keeping what JSON forbids for :func:`check_model_doc`.

    Parameters
    ----------
    text : str
        The file's text.

    Returns
    -------
    Any
        The document; a ``NaN``/``Infinity`` literal is kept as a marker and a key given
        twice marks its object, so the check names the field [-].

    Raises
    ------
    json.JSONDecodeError
        Not JSON (cut short, a syntax error).
    """
    return json.loads(text, parse_constant=_Literal, object_pairs_hook=_pairs)


def _bad(path: str, value: Any, allowed: str) -> InputError:
    shown = value if not isinstance(value, (dict, list)) else type(value).__name__
    return InputError(path, shown, f"{allowed} ({AGAIN})")


def nested(path: str, build, doc: Any) -> Any:
    """``build(doc)`` with its refusal named under ``path`` (the JSON path of ``doc``).

    Parameters
    ----------
    path : str
        JSON path of ``doc`` (``model.case``).
    build : callable
        Reader of the block (e.g. :func:`~oilgap.model.io.case_io.case_from_dict`).
    doc : Any
        The block.

    Returns
    -------
    Any
        What ``build`` returns [-].

    Raises
    ------
    InputError
        ``build``'s refusal with its field under ``path``, or its Python error as one.
    """
    try:
        return build(doc)
    except InputError as e:
        name = e.field if e.field.startswith(path) else f"{path}.{e.field}"
        raise InputError(name, e.value, e.allowed) from None
    except (KeyError, TypeError, ValueError, AttributeError) as e:
        raise InputError(path, f"{type(e).__name__}: {e}", f"the block oilgap loop writes "
                         f"({AGAIN})") from None


def refuse_literals(x: Any, path: str = "model") -> None:
    """Refuse ``NaN``/``Infinity`` literals and keys given twice anywhere in a document
    parsed by :func:`parse_model_json`.

    Parameters
    ----------
    x : Any
        The document (or a part of it).
    path : str
        JSON path of ``x`` (``""`` for a whole loop.json).

    Raises
    ------
    InputError
        The first such field, by its JSON path [-].
    """
    def sub(k: object) -> str:
        return f"{path}.{k}" if path else str(k)
    if isinstance(x, _Duplicate):
        raise _bad(sub(x.duplicate), "given twice", "each key once in an object")
    if isinstance(x, _Literal):
        raise _bad(path, str(x), "a finite number (NaN and Infinity are not JSON)")
    if isinstance(x, dict):
        for k, v in x.items():
            refuse_literals(v, sub(k))
    elif isinstance(x, list):
        for i, v in enumerate(x):
            refuse_literals(v, f"{path}[{i}]")


def _typed(path: str, value: Any, kind: type) -> Any:
    """``value`` if it is of JSON type ``kind`` (a number: finite, never a bool)."""
    if kind is float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise _bad(path, value, "a finite number")
        try:
            number = float(value)
        except OverflowError:  # an integer of hundreds of digits
            raise _bad(path, f"an integer of {len(str(value))} digits", "a finite number") \
                from None
        if not math.isfinite(number):
            raise _bad(path, value, "a finite number")
        return number
    if kind is int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise _bad(path, value, "an integer")
        return value
    if not isinstance(value, kind) or (kind is not bool and isinstance(value, bool)):
        raise _bad(path, value, _TYPE_TEXT[kind])
    return value


def _in_range(path: str, value: float, lo: float, hi: float, why: str) -> float:
    tol = REL_TOL * max(abs(lo) if math.isfinite(lo) else 0.0,
                        abs(hi) if math.isfinite(hi) else 0.0, 1.0)
    if not lo - tol <= value <= hi + tol:
        raise _bad(path, value, f"in [{lo:g}, {hi:g}] ({why})")
    return value


def _keys(path: str, doc: dict, required: dict, optional: dict | None = None) -> None:
    """Every required key present with its type, no key unknown."""
    optional = optional or {}
    for k, kind in required.items():
        if k not in doc:
            raise InputError(f"{path}.{k}", "missing", f"{_TYPE_TEXT[kind]} is required "
                             f"({AGAIN})")
        _typed(f"{path}.{k}", doc[k], kind)
    for k, v in doc.items():
        if k in optional:
            _typed(f"{path}.{k}", v, optional[k])
        elif k not in required:
            raise _bad(f"{path}.{k}", v, "not a key of a saved model; allowed: "
                       + ", ".join([*required, *optional]))


def _check_law(path: str, law: Any) -> None:
    law = _typed(path, law, dict)
    for k, v in law.items():
        if k not in LAW_KEYS:
            raise _bad(f"{path}.{k}", v, f"not a key of a friction law; allowed: "
                       f"{', '.join(LAW_KEYS)}")
    for k, allowed in (("form", FORMS), ("laminar_law", LAMINAR_LAWS),
                       ("transition", TRANSITIONS)):
        if law.get(k, allowed[0] if k == "transition" else None) not in allowed:
            raise _bad(f"{path}.{k}", law.get(k, "missing"), f"one of {', '.join(allowed)}")
    for k in ("gamma", "scale", "C", "alpha", "beta"):
        if k not in law:
            raise InputError(f"{path}.{k}", "missing", f"a finite number is required ({AGAIN})")
        lo, hi, why = FRICTION_RANGES[k]
        _in_range(f"{path}.{k}", _typed(f"{path}.{k}", law[k], float), lo, hi, why)
    branches = [k for k in BRANCH_KEYS if k in law]
    if branches and law["form"] != "branches":
        raise _bad(f"{path}.{branches[0]}", law[branches[0]], "only with form = \"branches\"")
    if law["form"] == "branches":
        n = None
        for k in BRANCH_KEYS:
            arr = _typed(f"{path}.{k}", law.get(k, "missing"), list)
            if not arr or (n is not None and len(arr) != n):
                raise _bad(f"{path}.{k}", f"{len(arr)} numbers", f"{n or 'one or more'} "
                           "numbers (branch_C, branch_alpha and branch_beta have one per "
                           "branch)")
            n = len(arr)
            lo, hi, why = FRICTION_RANGES[BRANCH_RANGE[k]]
            for i, v in enumerate(arr):
                _in_range(f"{path}.{k}[{i}]", _typed(f"{path}.{k}[{i}]", v, float), lo, hi,
                          why)


def _check_baseline(path: str, b: Any) -> float:
    b = _typed(path, b, dict)
    _keys(path, b, BASELINE_KEYS)
    T = _in_range(f"{path}.roughness_T", float(b["roughness_T"]), 1.0, math.inf,
                  "T = 1 is a smooth annulus, grooves make it larger")
    terms = tuple(b["terms"])
    allowed = (BASELINE_TERMS, BASELINE_TERMS + BASELINE_TEMP_TERMS)
    if terms not in allowed:
        raise _bad(f"{path}.terms", list(terms), "the oil-free basis "
                   f"{list(BASELINE_TERMS)}, with or without {list(BASELINE_TEMP_TERMS)}")
    coef = b["coef"]
    if len(coef) != len(terms):
        raise _bad(f"{path}.coef", f"{len(coef)} numbers", f"one per basis function in "
                   f"{path}.terms ({len(terms)})")
    for i, c in enumerate(coef):
        _typed(f"{path}.coef[{i}]", c, float)
    for k in ("rmse_W", "speed_max_rpm"):
        v = float(b[k])
        if not v > 0 and not (k == "rmse_W" and v == 0):
            raise _bad(f"{path}.{k}", v, "> 0" if k == "speed_max_rpm" else ">= 0")
    if b["n_samples"] < 1:
        raise _bad(f"{path}.n_samples", b["n_samples"], "an integer >= 1")
    _pair(f"{path}.temp_range_C", b["temp_range_C"])
    return T


def _pair(path: str, v: Any) -> None:
    v = _typed(path, v, list)
    if len(v) != 2:
        raise _bad(path, f"{len(v)} numbers", "[low, high]: two numbers")
    lo, hi = (_typed(f"{path}[{i}]", x, float) for i, x in enumerate(v))
    if lo > hi:
        raise _bad(path, v, "[low, high] with low <= high")


def _check_effects(doc: dict, facts: RigFacts | None) -> None:
    for name, v in doc["effects"].items():
        path = f"model.effects.{name}"
        if name not in EFFECTS:
            raise _bad(path, name, f"an effect of the library: {', '.join(EFFECTS)}")
        c = _typed(path, v, float)
        eff = EFFECTS[name]
        if eff.nonnegative and c < 0:
            raise _bad(path, c, ">= 0 (the library's sign for this effect)")
        if c > eff.upper * (1 + REL_TOL):
            raise _bad(path, c, f"<= {eff.upper:g} (the fit's bound)")
        lo, hi = PLAUSIBLE[name].range(facts)
        _in_range(path, c, lo, hi, f"plausible range: {PLAUSIBLE[name].reference}")


def _check_shapes(doc: dict) -> None:
    shapes = doc.get("shapes", {})
    for name, shape in shapes.items():
        path = f"model.shapes.{name}"
        if name not in ("taylor_vortex_onset", "film_heating"):
            raise _bad(path, name, "taylor_vortex_onset or film_heating")
        if name not in doc["effects"]:
            raise _bad(path, name, "only for an effect of model.effects")
        _typed(path, shape, dict)
    tv = shapes.get("taylor_vortex_onset", {})
    if "exponent" in tv:
        m = _typed("model.shapes.taylor_vortex_onset.exponent", tv["exponent"], float)
        if m not in TAYLOR_SHAPES:
            raise _bad("model.shapes.taylor_vortex_onset.exponent", m,
                       f"one of the exponents the loop fits: "
                       f"{', '.join(f'{x:g}' for x in TAYLOR_SHAPES)}")
    film = shapes.get("film_heating", {})
    if "wall_floating" in film:
        _in_range("model.shapes.film_heating.wall_floating",
                  _typed("model.shapes.film_heating.wall_floating", film["wall_floating"],
                         float), 0.0, 1.0, "the wall condition w: 0 held walls, 1 floating")


def check_model_doc(doc: Any) -> None:
    """Check a model block against the schema (structure, types, names, lengths, finite
    numbers) before anything is built from it.

    Parameters
    ----------
    doc : Any
        The ``model`` block as parsed (:func:`parse_model_json` or :func:`json.loads`).

    Raises
    ------
    InputError
        The first field that fails, by its JSON path, with its value and what is allowed
        [-].
    """
    refuse_literals(doc, "model")
    if not isinstance(doc, dict):
        raise InputError("model", type(doc).__name__, "a JSON object (the 'model' block of "
                         "loop.json) is required")
    _keys("model", doc, REQUIRED, OPTIONAL)
    laws = doc["laws"]
    for stage in STAGES:
        if stage not in laws:
            raise InputError(f"model.laws.{stage}", "missing", f"the laws of "
                             f"{', '.join(STAGES)} are required ({AGAIN})")
        _check_law(f"model.laws.{stage}", laws[stage])
    for k in laws:
        if k not in STAGES:
            raise _bad(f"model.laws.{k}", k, f"one of {', '.join(STAGES)}")
    if doc["kind"] not in KINDS:
        raise _bad("model.kind", doc["kind"], f"one of {', '.join(KINDS)}")
    if doc.get("thermal_mode", "none") not in LOOP_THERMAL_MODES:
        raise _bad("model.thermal_mode", doc["thermal_mode"],
                   f"one of {', '.join(LOOP_THERMAL_MODES)}")
    if not doc["region1_gap_m"] > 0:
        raise _bad("model.region1_gap_m", doc["region1_gap_m"], "> 0 (a clearance) [m]")
    if not doc.get("pressure_gauge_Pa", 0.0) >= 0:
        raise _bad("model.pressure_gauge_Pa", doc["pressure_gauge_Pa"], ">= 0 [Pa]")
    for name, f in doc.get("fluids", {}).items():
        _typed(f"model.fluids.{name}", f, dict)
    Ts = [_check_baseline(f"model.baselines[{i}]", b)
          for i, b in enumerate(doc.get("baselines", []))]
    if len(set(Ts)) != len(Ts):
        raise _bad("model.baselines", ", ".join(f"{t:g}" for t in Ts),
                   "one baseline per roughness T")
    for k, v in doc.get("fitted_range", {}).items():
        if k not in RANGE_KEYS:
            raise _bad(f"model.fitted_range.{k}", k, f"one of {', '.join(RANGE_KEYS)}")
        _pair(f"model.fitted_range.{k}", v)
    for name, v in doc["effects"].items():
        if name not in EFFECTS:
            raise _bad(f"model.effects.{name}", name,
                       f"an effect of the library: {', '.join(EFFECTS)}")
        _typed(f"model.effects.{name}", v, float)
    _check_shapes(doc)


def check_model_ranges(doc: dict, facts: RigFacts | None) -> None:
    """Check the effect coefficients of a model block that passed :func:`check_model_doc`
    against the library's sign and plausible ranges on the saved rig.

    Parameters
    ----------
    doc : dict
        The ``model`` block.
    facts : RigFacts or None
        The saved rig (its size and fluids) for the ranges that depend on it.

    Raises
    ------
    InputError
        A coefficient of the wrong sign or outside its plausible range, named
        ``model.effects.<name>`` [unit of the effect].
    """
    _check_effects(doc, facts)


__all__ = ["KINDS", "LOOP_THERMAL_MODES", "RANGE_KEYS", "STAGES", "check_model_doc",
           "check_model_ranges", "decode", "encode", "nested",
           "parse_model_json", "refuse_literals"]
