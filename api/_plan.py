"""The façade's rig-planning functions: ``og.plan`` (``oilgap plan``: which runs identify
the law and detect the effects) and ``og.synth_plan`` (``oilgap synth --plan``: the
planned runs simulated, in the loop's data format)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import pandas as pd

from oilgap._checks import (
    CASE,
    EFFECT_NAMES,
    FLAG,
    INT,
    NUMBER,
    OUT,
    PATH_KINDS,
    Arg,
    checked,
    choice,
)
from oilgap._evaluate import as_case
from oilgap.model.case import DesignCase
from oilgap.model.effects import EFFECTS
from oilgap.model.errors import InputError
from oilgap.studies.outputs import result_folder

LIST = Arg((tuple, list), "a tuple or list of values, e.g. (25, 40)", optional=True)
PLAN = Arg((*PATH_KINDS, "DataFrame"), "a path to a plan.csv or its DataFrame")


def _effect_names(effects: Any) -> tuple[str, ...] | None:
    if effects is None:
        return None
    names = [e.strip() for e in effects.split(",")] if isinstance(effects, str) else \
        list(effects)
    for e in names:
        if e not in EFFECTS:
            raise InputError("effects", e, f"allowed: {', '.join(EFFECTS)}")
    return tuple(names)


@checked(case=CASE, settings=Arg(("PlanSettings", dict), "a PlanSettings or a dict of its "
                                  "fields", optional=True),
         oils=LIST, bath_C=LIST, roughness=LIST, profiles=LIST, pressures_MPa=LIST,
         effects=EFFECT_NAMES, criterion=choice("D", "A", "E", "T"),
         targets=choice("base", "all"), base=choice("eq6", "power-law"), runs=INT,
         budget_h=NUMBER, noise_W=NUMBER, duration_s=NUMBER, sample_interval_s=NUMBER,
         out=OUT, force=FLAG)
def plan(case: DesignCase | str | Path | None = None, settings: Any = None, *,
         out: str | Path | None = None, force: bool = False, **keywords: Any):
    """Plan a rig campaign (``oilgap plan``): the runs that identify the base law and
    detect the effects, beside the naive full-factorial plan of the same size.

    Parameters
    ----------
    case : DesignCase, path or None
        The rig (None: the seed joint).
    settings : PlanSettings or dict, optional
        The campaign (:class:`oilgap.studies.plan.settings.PlanSettings`); keywords in
        ``keywords`` override its fields.
    out : str or Path, optional
        Folder for plan.csv, naive.csv, parameters.csv, effects.csv, plan.json,
        plan_runs.png and summary.md (None: no file).
    force : bool
        Replace an earlier plan in ``out``.
    **keywords
        Fields of PlanSettings: ``oils``, ``bath_C`` [degC], ``roughness`` [-],
        ``profiles`` (sine, trapezoid, steps), ``pressures_MPa``, ``effects`` (library
        names to detect), ``criterion`` (D, A, E, T), ``targets`` (base, all), ``base``
        (eq6, power-law), ``runs`` or ``budget_h`` [h], ``noise_W`` [W],
        ``noise_speed_rpm``, ``noise_temp_K``, ``duration_s``, ``sample_interval_s`` [s],
        ``peak_speed_rpm``, ``frequency_hz``, ``run_h``, ``oil_change_h``,
        ``temp_change_h``, ``rotor_change_h`` [h], ``scale`` (the expected friction scale,
        the plan's expansion point) [-].

    Returns
    -------
    PlanResult
        ``plan`` and ``naive`` (runs, expected sd and interval, detectable sizes,
        confounding, cost), the continuous design and its gap; ``summary()``.
    """
    from oilgap.studies.plan.settings import PlanSettings
    from oilgap.studies.plan.study import make_plan

    fields = PlanSettings.__dataclass_fields__
    base = {} if settings is None else (dict(settings) if isinstance(settings, dict)
                                        else {k: getattr(settings, k) for k in fields})
    if case is None:
        case = base.get("case")
    base.pop("case", None)
    for k, v in {**base, **keywords}.items():
        if k not in fields or k == "case":
            raise InputError(k, v, "not a plan setting; allowed: "
                             + ", ".join(f for f in fields if f != "case"))
    kw = {**base, **{k: v for k, v in keywords.items() if v is not None}}
    if "effects" in kw:
        kw["effects"] = _effect_names(kw["effects"])
    if keywords.get("budget_h") is not None and keywords.get("runs") is None:
        kw["runs"] = None
    with result_folder("plan", out, force) as folder:
        st = PlanSettings(case=None if case is None else as_case(case), **kw)
        res = make_plan(st)
        if folder is not None:
            from oilgap.studies.plan.report import write_plan
            folder.begin()
            write_plan(res, Path(out))
            folder.complete()
    return res


@checked(plan=PLAN, case=CASE, effects=EFFECT_NAMES, seed=INT)
def synth_plan(plan: str | Path | pd.DataFrame, *, case: DesignCase | str | Path | None = None,
               effects: Any = None, seed: int = 0, scale: float = 1.0) -> pd.DataFrame:
    """The runs of a plan simulated by the synthetic rig (``oilgap synth --plan``).

    Parameters
    ----------
    plan : path or DataFrame
        plan.csv (or naive.csv) of ``oilgap plan``.
    case : DesignCase, path or None
        Rig geometry (None: the seed joint).
    effects : str or list of str, optional
        Library effects injected at their test strengths (``name`` or ``name=strength``).
    seed : int
        Noise seed (>= 0).
    scale : float
        True friction scale of the simulated rig [-] (the plan's ``scale``; default 1).

    Returns
    -------
    DataFrame
        ``run, time_s, speed_rpm, temp_C, oil, roughness_T, viscous_power_W``.
    """
    from oilgap.studies.plan.candidates import plan_data, runs_from_table

    if isinstance(seed, bool) or seed is None or seed < 0:
        raise InputError("seed", seed, "an integer >= 0 is required (the noise seed)")
    if isinstance(plan, (str, Path)):
        try:
            table = pd.read_csv(plan)
        except (OSError, pd.errors.ParserError, UnicodeDecodeError) as e:
            raise InputError("plan", str(plan), f"cannot read the plan CSV ({e})") from None
    else:
        table = plan
    settings, runs = runs_from_table(table, str(plan) if isinstance(plan, (str, Path))
                                     else "plan")
    settings = replace(settings, scale=scale)
    return plan_data(settings, runs, None if case is None else as_case(case),
                     _strengths(effects), seed=int(seed))


def _strengths(effects: Any) -> dict | None:
    """``name`` or ``name=strength`` items -> {name: strength or None}."""
    if effects is None:
        return None
    items = [e.strip() for e in effects.split(",")] if isinstance(effects, str) else \
        list(effects)
    out = {}
    for it in items:
        name, _, val = str(it).partition("=")
        _effect_names([name])
        try:
            out[name] = float(val) if val else None
        except ValueError:
            raise InputError("effects", it, "name or name=strength (a number)") from None
    return out


__all__ = ["plan", "synth_plan"]
