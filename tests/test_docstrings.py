"""Docstrings are part of the interface (numpydoc, units in brackets).

Every public function and class of ``oilgap.model`` and ``oilgap.optim`` (every module
of both packages, walked with :mod:`pkgutil`; public = name without a leading
underscore, defined in that module) documents itself:

* functions: a docstring; a ``Parameters`` section naming every parameter (other
  than ``self``/``cls``); a ``Returns`` (or ``Yields``) section unless the function
  is annotated ``-> None``; at least one unit in brackets (``[W]``, ``[m^2/s]``, ``[-]``);
* classes: a docstring with an ``Attributes`` or ``Parameters`` section.

The test lists every offender at once. Modules that implement a physical law cite
their references; the dataclasses of ``oilgap.model`` list every field with a unit.
"""

from __future__ import annotations

import dataclasses
import importlib
import inspect
import pkgutil
import re

import pytest

import oilgap.model
import oilgap.optim

PACKAGES = (oilgap.model, oilgap.optim)

LAW_MODULES = ["oil_properties", "taylor_couette", "skin_friction", "viscous_loss", "motor",
               "regions", "thermal", "effects.library", "effects.laws", "film_heating",
               "film_cycle", "joint_loss", "bearing.friction", "bearing.laws",
               "bearing.catalogue"]

UNIT_RE = re.compile(r"\[(-|[^\[\]\n]*[A-Za-z%][^\[\]\n]*)\]")
"""A unit in brackets: ``[-]`` or bracketed text with a letter (not a citation ``[1]``)."""

SECTION_RE = re.compile(r"^([ \t]*)([A-Z][A-Za-z ]*)\n\1-{3,}[ \t]*$", re.MULTILINE)


# --------------------------------------------------------------------------- helpers


def _is_private(modname: str) -> bool:
    return any(part.startswith("_") for part in modname.split("."))


def walk_modules(pkg) -> tuple[list, list[str]]:
    """All public modules of a package, recursively; import failures as offenders."""
    mods, errors = [pkg], []
    for info in pkgutil.walk_packages(pkg.__path__, pkg.__name__ + ".",
                                      onerror=lambda name: errors.append(
                                          f"{name}: cannot be imported")):
        if _is_private(info.name):
            continue
        try:
            mods.append(importlib.import_module(info.name))
        except Exception as e:  # noqa: BLE001 - reported as an offender
            errors.append(f"{info.name}: cannot be imported ({type(e).__name__}: {e})")
    return mods, errors


def public_members(mod):
    """Public functions and classes defined in ``mod`` (re-exports excluded)."""
    for name, obj in sorted(vars(mod).items()):
        if name.startswith("_"):
            continue
        if not (inspect.isfunction(obj) or inspect.isclass(obj)):
            continue
        if getattr(obj, "__module__", None) == mod.__name__:
            yield name, obj


def sections(doc: str) -> dict[str, str]:
    """numpydoc sections of a docstring: title -> body (up to the next title)."""
    doc = inspect.cleandoc(doc)
    found = list(SECTION_RE.finditer(doc))
    out = {}
    for i, mt in enumerate(found):
        end = found[i + 1].start() if i + 1 < len(found) else len(doc)
        out[mt.group(2).strip()] = doc[mt.end():end]
    return out


def listed_names(body: str) -> set[str]:
    """Names of the entries of a Parameters/Attributes section (``a, b : type`` lines)."""
    lines = [ln for ln in body.splitlines() if ln.strip()]
    if not lines:
        return set()
    indent = min(len(ln) - len(ln.lstrip()) for ln in lines)
    names = set()
    for ln in lines:
        if len(ln) - len(ln.lstrip()) != indent:
            continue
        head = ln.strip().split(" : ")[0].rstrip(":")
        names |= {n.strip().lstrip("*") for n in head.split(",") if n.strip()}
    return names


def _returns_none(fn) -> bool:
    try:
        ann = inspect.signature(fn).return_annotation
    except (TypeError, ValueError):
        return False
    return ann is None or ann == "None"


def function_problems(fn) -> list[str]:
    """What the docstring of a function lacks (empty list: nothing)."""
    doc = fn.__doc__ or ""
    if not doc.strip():
        return ["no docstring"]
    problems = []
    secs = sections(doc)
    try:
        params = [p for p in inspect.signature(fn).parameters if p not in ("self", "cls")]
    except (TypeError, ValueError):
        params = []
    if params:
        if "Parameters" not in secs:
            problems.append("no Parameters section")
        else:
            missing = [p for p in params if p not in listed_names(secs["Parameters"])]
            if missing:
                problems.append(f"Parameters does not list {missing}")
    if not _returns_none(fn) and "Returns" not in secs and "Yields" not in secs:
        problems.append("no Returns section (annotate '-> None' if it returns nothing)")
    if not UNIT_RE.search(doc):
        problems.append("no unit in brackets (e.g. [W], [m^2/s], [-])")
    return problems


def class_problems(cls) -> list[str]:
    """What the docstring of a class lacks (empty list: nothing)."""
    doc = cls.__doc__ or ""
    if not doc.strip():
        return ["no docstring"]
    secs = sections(doc)
    if "Attributes" not in secs and "Parameters" not in secs:
        return ["no Attributes or Parameters section"]
    return []


def offenders(packages=PACKAGES) -> list[str]:
    """One line per public function or class whose docstring falls short."""
    out = []
    for pkg in packages:
        mods, errors = walk_modules(pkg)
        out += errors
        for mod in mods:
            if not (mod.__doc__ or "").strip():
                out.append(f"{mod.__name__}: no module docstring")
            for name, obj in public_members(mod):
                probs = class_problems(obj) if inspect.isclass(obj) else function_problems(obj)
                out += [f"{mod.__name__}.{name}: {p}" for p in probs]
    return out


# --------------------------------------------------------------------------- tests


def test_every_public_function_and_class_is_documented():
    bad = offenders()
    assert not bad, f"{len(bad)} docstring offenders:\n" + "\n".join(bad)


@pytest.mark.parametrize("modname", LAW_MODULES)
def test_law_modules_cite_references(modname):
    mod = importlib.import_module(f"oilgap.model.{modname}")
    assert "References" in sections(mod.__doc__), f"{modname}: no References section"


def test_model_dataclasses_list_every_field_with_a_unit():
    bad = []
    for mod in walk_modules(oilgap.model)[0]:
        for name, cls in public_members(mod):
            if not (inspect.isclass(cls) and dataclasses.is_dataclass(cls)):
                continue
            secs = sections(cls.__doc__ or "")
            listed = listed_names(secs.get("Attributes", "") + "\n"
                                  + secs.get("Parameters", ""))
            missing = [f.name for f in dataclasses.fields(cls) if f.name not in listed]
            if missing:
                bad.append(f"{mod.__name__}.{name}: Attributes does not list {missing}")
            if not UNIT_RE.search(cls.__doc__ or ""):
                bad.append(f"{mod.__name__}.{name}: no unit in brackets")
    assert not bad, "\n".join(bad)


# --------------------------------------------------------------------------- the checker


def _good(omega_rad_s, *, scale=1.0):
    """Power.

    Parameters
    ----------
    omega_rad_s : float
        Speed [rad/s].
    scale : float
        Factor [-].

    Returns
    -------
    float
        Power [W].
    """
    return omega_rad_s


def _no_units(a):
    """Thing.

    Parameters
    ----------
    a : float
        A number.

    Returns
    -------
    float
    """
    return a


def _missing_param(a, b) -> float:
    """Thing [W].

    Parameters
    ----------
    a : float
        A number [m].

    Returns
    -------
    float
    """
    return a + b


def _no_returns(a):
    """Thing [W].

    Parameters
    ----------
    a : float
        A number [m]; the citation [1] alone is not a unit.
    """
    return a


def _returns_nothing(a) -> None:
    """Prints [m].

    Parameters
    ----------
    a, b : float
        Numbers [m].
    """


def test_checker_accepts_a_complete_docstring_and_names_each_gap():
    assert function_problems(_good) == []
    assert function_problems(_returns_nothing) == []
    assert function_problems(_no_units) == ["no unit in brackets (e.g. [W], [m^2/s], [-])"]
    assert function_problems(_missing_param) == ["Parameters does not list ['b']"]
    assert function_problems(_no_returns) == [
        "no Returns section (annotate '-> None' if it returns nothing)"]
    assert function_problems(lambda x: x) == ["no docstring"]
    assert not UNIT_RE.search("see [1] and [2]") and UNIT_RE.search("[-]")
