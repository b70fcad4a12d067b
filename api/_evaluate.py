"""The façade's functions (``import oilgap as og``): one job each, the same as the command
line's: coerce the case argument, apply the overrides, call the module-level API, wrap the
result in a view (:mod:`oilgap._results`).

This module is light (``og.evaluate`` and ``oilgap evaluate`` load no pandas, matplotlib
or :mod:`oilgap.optim`): the case, its overrides and :func:`evaluate`. The other
functions are in :mod:`oilgap._optimize` (``optimize``),
:mod:`oilgap._studies` (``pareto``, ``oil_grade``, ``smoothing``, ``sweep``)
and :mod:`oilgap._loop` (``Loop``, ``predict``, ``synth``); ``oilgap``
(``api/__init__.py``) re-exports them all.

A ``case`` argument is a :class:`~oilgap.model.case.DesignCase`, a path to a case TOML
(str or Path) or None (the seed joint). Bad input raises
:class:`~oilgap.model.errors.InputError` naming the argument.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

from oilgap._checks import (
    CASE,
    FLAG,
    MODEL,
    NAME,
    NUMBER,
    OILS,
    PATH,
    Arg,
    check_arg,
    checked,
    choice,
)
from oilgap._results import Evaluation
from oilgap.model.case import DesignCase, OperatingPoint
from oilgap.model.errors import ArgumentError, InputError, check_finite
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml
from oilgap.model.io.case_io import seed_case as _seed_case
from oilgap.model.joint_loss import resolve_thermal_mode, uses_balance
from oilgap.model.oils import Oil, get_oil, oils_from_dict, read_oils_csv, with_builtin
from oilgap.model.skin_friction import LAMINAR_LAWS
from oilgap.model.thermal_modes import ThermalMode
from oilgap.model.transition import TRANSITIONS
from oilgap.studies.io.case_write import write_case_toml
from oilgap.studies.io.files import check_out_file


@checked(path=PATH)
def read_case(path: str | Path) -> DesignCase:
    """The case TOML at ``path`` (:func:`oilgap.model.io.case_io.read_case_toml`).

    Parameters
    ----------
    path : str or Path
        A case TOML file.

    Returns
    -------
    DesignCase
    """
    return read_case_toml(path)


@checked(case=Arg(("DesignCase",), "a DesignCase (og.read_case(...), "
                   "og.optimize(...).to_case())"), path=PATH, force=FLAG)
def write_case(case: DesignCase, path: str | Path, force: bool = False) -> Path:
    """Write ``case`` as a case TOML that :func:`read_case` reads back (floats to 6
    significant digits; :func:`oilgap.studies.io.case_write.write_case_toml`), atomically; an
    existing file is replaced only with ``force`` (as ``oilgap optimize --out``).

    Parameters
    ----------
    case : DesignCase
        The case, e.g. ``og.optimize(...).to_case()``.
    path : str or Path
        The TOML file to write.
    force : bool
        Replace an existing file.

    Returns
    -------
    Path
        The file written.
    """
    return write_case_toml(case, check_out_file(path, force, field="path", option="force=True"))


@checked(smoothed=FLAG)
def seed_case(smoothed: bool = False) -> DesignCase:
    """The seed joint (Table 1 of the seed paper): grooved (T = 4) or smoothed (T = 2).

    Parameters
    ----------
    smoothed : bool
        The joint smoothed with epoxy (T = 2) instead of grooved.

    Returns
    -------
    DesignCase
    """
    return _seed_case(smoothed)


def as_case(case: DesignCase | str | Path | None = None) -> DesignCase:
    """A DesignCase from what a façade function was given: the case itself, a path to its
    TOML, or None for the seed joint (grooved).

    Raises
    ------
    InputError
        Anything else (``case`` named).
    """
    if case is None:
        return _seed_case()
    if isinstance(case, DesignCase):
        return case
    check_arg("case", case, CASE)
    read = read_case_toml(case)
    if read.calibration_model is None:
        return read
    from oilgap._calibrated import with_model  # a [calibration] model, folded in once
    return with_model(read, None)[0]


class OilTable(dict):
    """Oils resolved for a look-up (:func:`read_oils`): taken as they are, never added to
    the built-in catalogue again."""


@checked(table=Arg((str, Path, dict), "a path to an oils CSV or a dict {name: Oil or "
                   "{nu40_cSt, nu100_cSt, density_kg_m3}}"), only=FLAG, field=NAME)
def read_oils(table: dict | str | Path, only: bool = False, field: str = "oils"
              ) -> dict[str, Oil]:
    """The oils to look names up in: a user's table (a CSV, or a dict of Oil or of the
    CSV's columns) added to the built-in ISO VG catalogue, the user's row winning a name
    clash with a warning, or with ``only`` the user's oils alone (``--oils-only``).

    Parameters
    ----------
    table : str, Path or dict
        ``oil,nu40_cSt,nu100_cSt,density_kg_m3[,barus_1_GPa][,polymer_thickened]`` as a
        CSV, or ``{name: Oil}`` / ``{name: {"nu40_cSt": ..., "nu100_cSt": ...,
        "density_kg_m3": ...}}``: nu [cSt], density [kg/m^3], Barus [1/GPa].
    only : bool
        The user's oils alone, not added to the catalogue.
    field : str
        How the messages name the table (``"--oils"`` on the command line).

    Returns
    -------
    dict
        Name (normalized) -> Oil; pass it as ``oils=`` to any façade function.
    """
    if isinstance(table, OilTable):
        return table
    user = oils_from_dict(table, field) if isinstance(table, dict) \
        else read_oils_csv(table, field)
    return OilTable(user if only else with_builtin(user, field))


def oil_catalogue(oils: dict[str, Oil] | str | Path | None) -> dict[str, Oil] | None:
    """An oils argument resolved (:func:`read_oils`: added to the catalogue); None kept."""
    if oils is None:
        return None
    check_arg("oils", oils, OILS)
    return read_oils(oils)


def with_operating(case: DesignCase, oil: str | None = None,
                   oils: dict[str, Oil] | str | Path | None = None,
                   oil_temp_C: float | None = None, depth_m: float | None = None
                   ) -> DesignCase:
    """``case`` with the oil (looked up in ``oils``, else the catalogue), the oil
    temperature [degC] and the depth [m] replaced where given (the command line's
    ``--oil``, ``--oils``, ``--temp-c``, ``--depth-m``).

    Raises
    ------
    InputError
        An unknown oil, a temperature or depth that is not a finite number.
    """
    cat = oil_catalogue(oils)
    if oil is not None or cat is not None:
        case = replace(case, oil=get_oil(case.oil.name if oil is None else oil, cat))
    if oil_temp_C is not None or depth_m is not None:
        op = case.operating
        op = OperatingPoint(op.depth_m if depth_m is None else check_finite("depth_m", depth_m),
                            op.oil_temp_C if oil_temp_C is None
                            else check_finite("oil_temp_C", oil_temp_C))
        case = replace(case, operating=op)
    return case


def with_transition(case: DesignCase, transition: str | None = None,
                    name: str = "transition") -> DesignCase:
    """``case`` with its ``[friction] transition`` replaced where given (``--transition``,
    ``transition=``): ``"reynolds"`` (Eq. 6's switch by Re) or ``"taylor"`` (exact Couette
    up to Ta_c, :mod:`oilgap.model.transition`).

    Raises
    ------
    InputError
        An unknown value, or ``"taylor"`` with a law it does not apply to; the message
        names ``name``.
    """
    if transition is None:
        return case
    if transition not in TRANSITIONS:
        raise InputError(name, transition, f"one of {', '.join(TRANSITIONS)} (None: the case's)")
    try:
        return replace(case, friction=replace(case.friction, transition=str(transition)))
    except InputError as e:
        raise InputError(name, transition, e.allowed) from None


API_NAMES = {"thermal": "thermal", "oil_temp_C": "oil_temp_C", "sea_temp_C": "sea_temp_C",
             "balance": "thermal '{mode}'", "given": "thermal='none' or 'film'"}
"""How :func:`thermal_case` names the arguments in its messages (the command line passes
its own spellings: ``--thermal``, ``--temp-c``, ``--sea-temp-c``)."""


def thermal_case(case: DesignCase, thermal: str | None = None,
                 oil_temp_C: float | None = None, sea_temp_C: float | None = None,
                 names: dict[str, str] | None = None) -> tuple[DesignCase, ThermalMode]:
    """The thermal mode checked against the case and a given oil temperature, and the case
    with the sea temperature [degC] applied (``bulk``/``full`` only).

    Parameters
    ----------
    case : DesignCase
        The case (its ``[thermal]`` table decides what is allowed).
    thermal : {"none", "bulk", "film", "full"} or None
        The mode asked for (None: the default,
        :func:`~oilgap.model.joint_loss.default_thermal_mode`).
    oil_temp_C : float, optional
        A given oil temperature [degC] (refused under ``bulk``/``full``).
    sea_temp_C : float, optional
        A given sea temperature [degC] (``bulk``/``full`` only).
    names : dict, optional
        The spellings of the arguments in the messages (:data:`API_NAMES`).

    Returns
    -------
    case : DesignCase
    mode : ThermalMode
        ``"none"``, ``"bulk"``, ``"film"`` or ``"full"``, resolved
        (:func:`~oilgap.model.joint_loss.resolve_thermal_mode`: the one resolution of
        a command, passed down).

    Raises
    ------
    InputError
        ``bulk``/``full`` without ``[thermal]``, ``oil_temp_C`` under them (the balance
        sets it), ``sea_temp_C`` without ``[thermal]`` or outside them.
    """
    n = {**API_NAMES, **(names or {})}
    try:
        mode = resolve_thermal_mode(case, thermal)
    except InputError as e:
        raise InputError(n["thermal"], e.value, e.allowed) from None
    balance = n["balance"].format(mode=mode)
    if uses_balance(mode) and oil_temp_C is not None:
        raise InputError(n["oil_temp_C"], oil_temp_C, f"not with {balance}: the heat "
                         f"balance sets the oil temperature; give {n['sea_temp_C']}, or "
                         f"{n['given']}")
    if sea_temp_C is None:
        return case, mode
    sea = check_finite(n["sea_temp_C"], sea_temp_C)
    if case.thermal is None:
        raise InputError(n["sea_temp_C"], sea, "needs the case's [thermal] table (the heat "
                         "balance to the sea)")
    if not uses_balance(mode):
        raise InputError(n["sea_temp_C"], sea, "only under thermal 'bulk' or 'full' (the "
                         f"heat balance to the sea); the mode is '{mode}'")
    try:
        return replace(case, thermal=replace(case.thermal, sea_temp_C=sea)), mode
    except InputError as e:
        raise InputError(n["sea_temp_C"], sea, e.allowed) from None


THERMAL = choice("none", "bulk", "film", "full")
"""The ``thermal`` argument of evaluate and optimize."""


@checked(case=CASE, oil=NAME, oils=OILS, oil_temp_C=NUMBER, depth_m=NUMBER, thermal=THERMAL,
         sea_temp_C=NUMBER, laminar_law=choice(*LAMINAR_LAWS), transition=choice(*TRANSITIONS),
         model=MODEL)
def evaluate(case: DesignCase | str | Path | None = None, *, oil: str | None = None,
             oils: dict[str, Oil] | str | Path | None = None,
             oil_temp_C: float | None = None, depth_m: float | None = None,
             thermal: str | None = None, sea_temp_C: float | None = None,
             **keywords: Any) -> Evaluation:
    """Evaluate a joint region by region over its duty cycle (``oilgap evaluate``).

    Parameters
    ----------
    case : DesignCase, path or None
        The joint (None: the seed joint).
    oil : str, optional
        Oil name replacing the case's (e.g. ``"VG22"``).
    oils : path or dict, optional
        Oils table to look ``oil`` up in, added to the built-in catalogue
        (:func:`read_oils`; ``read_oils(..., only=True)``: alone).
    oil_temp_C : float, optional
        Oil temperature [degC] (refused under ``bulk``/``full``).
    depth_m : float, optional
        Sea depth [m].
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode (default: ``bulk`` with ``[thermal]``, else ``none``: the model
        the evidence supports, :func:`~oilgap.model.joint_loss.default_thermal_mode`).
    sea_temp_C : float, optional
        Sea temperature of the heat balance [degC] (``bulk``/``full`` only).
    **keywords
        The friction's: ``laminar_law`` ({"couette", "bilgen-boulos"}: the law below the
        critical Taylor number) and ``transition`` ({"reynolds", "taylor"}: where C_m leaves
        the laminar law, :func:`with_transition`); default: the case's. ``model`` (a
        ``loop.json`` path, a FittedModel or a fitted og.Loop): a calibrated loop model
        folded into the case (``--model``; :func:`oilgap._calibrated.with_model`).

    Returns
    -------
    Evaluation
        ``.raw`` is the :class:`~oilgap.model.evaluation.CaseEvaluation`; powers [W].
    """
    unknown = set(keywords) - {"laminar_law", "transition", "model"}
    if unknown:
        raise ArgumentError(", ".join(sorted(unknown)), keywords[min(unknown)],
                            "evaluate's keywords are case, "
                            "oil, oils, oil_temp_C, depth_m, thermal, sea_temp_C, laminar_law, "
                            "transition and model")
    laminar_law, transition = keywords.get("laminar_law"), keywords.get("transition")
    model = keywords.get("model")
    if laminar_law is not None and laminar_law not in LAMINAR_LAWS:
        raise InputError("laminar_law", laminar_law, f"one of {', '.join(LAMINAR_LAWS)} "
                         "(None: the case's)")
    c = with_transition(with_operating(as_case(case), oil, oils, oil_temp_C, depth_m),
                        transition)
    c, mode = thermal_case(c, thermal, oil_temp_C, sea_temp_C)  # the one resolution
    if model is not None:
        from oilgap._calibrated import with_model
        c = with_model(c, model)[0]
    return evaluate_resolved(c, mode, thermal is None, laminar_law)


def evaluate_resolved(case: DesignCase, mode: ThermalMode, by_default: bool,
                      laminar_law: str | None = None) -> Evaluation:
    """:func:`evaluate` of a case whose thermal mode is resolved (:func:`thermal_case`;
    ``oilgap evaluate`` resolves it with its options' names): the mode is passed down,
    not resolved again.

    Parameters
    ----------
    case : DesignCase
        The joint, its oil state and sea temperature applied.
    mode : ThermalMode
        The resolved mode.
    by_default : bool
        Whether it is the default (no mode asked for; the header says so).
    laminar_law : {"couette", "bilgen-boulos"}, optional
        Law below the critical Taylor number (default: the case's).

    Returns
    -------
    Evaluation
        As :func:`evaluate`.
    """
    return Evaluation(evaluate_case(case, laminar_law=laminar_law, thermal=mode,
                                    thermal_default=by_default), case)


__all__ = ["THERMAL", "OilTable", "as_case", "evaluate", "evaluate_resolved", "oil_catalogue",
           "read_case", "read_oils", "seed_case", "thermal_case", "with_operating",
           "with_transition"]
