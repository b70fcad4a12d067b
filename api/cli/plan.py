"""``oilgap plan``: the rig runs that identify the law and detect the effects, beside the
naive plan (arguments in :func:`oilgap.cli.plan_args.add_plan`); a thin layer over
:func:`oilgap._plan.plan` (``og.plan``)."""

from __future__ import annotations

import argparse

from oilgap.cli.outputs import out_folder
from oilgap.model.errors import InputError

OPTIONS = {"oil_grades": ("--oil-grades", str), "bath_C": ("--bath-C", float),
           "roughness": ("--roughness", float), "profiles": ("--profiles", str),
           "pressures_MPa": ("--pressures-MPa", float)}
"""List options: argparse dest -> (option, item type) (``oil_grades`` is the field
``oils``: ``--oils`` names an oils CSV in the other commands)."""

NUMBERS = {"runs": "runs", "budget_h": "budget_h", "noise_W": "noise_W",
           "duration_s": "duration_s", "sample_s": "sample_interval_s",
           "peak_rpm": "peak_speed_rpm", "cost_run_h": "run_h", "cost_oil_h": "oil_change_h",
           "cost_temp_h": "temp_change_h", "cost_rotor_h": "rotor_change_h",
           "expected_scale": "scale"}
"""Number options: argparse dest -> settings field."""

FLAGS = {field: "--" + dest.replace("_", "-") for dest, field in NUMBERS.items() if dest != field}
"""Settings field -> the option that sets it, where the two names differ: a refusal of the
settings names the option the user typed."""


def named_by_option(e: InputError, flags: dict[str, str]) -> InputError:
    """A refusal of the plan's settings naming the option the user typed (``flags``: field
    -> option, e.g. ``scale`` -> ``--expected-scale``); any other error as it is."""
    from oilgap.studies.plan.settings import WHERE

    if e.where != WHERE or e.field not in flags:
        return e
    return InputError(flags[e.field], e.value, e.allowed, e.where)


def _items(option: str, text: str, kind: type) -> tuple:
    try:
        vals = tuple(kind(x.strip()) for x in text.split(",") if x.strip())
    except ValueError:
        raise InputError(option, text, "comma-separated numbers, e.g. 25,40") from None
    if not vals:
        raise InputError(option, text, "at least one value")
    return vals


def settings_from_args(args: argparse.Namespace) -> dict:
    """The keyword arguments of ``og.plan`` given on the command line."""
    kw = {f: _items(opt, getattr(args, f), kind) for f, (opt, kind) in OPTIONS.items()
          if getattr(args, f) is not None}
    if "oil_grades" in kw:
        kw["oils"] = kw.pop("oil_grades")
    kw.update({field: getattr(args, dest) for dest, field in NUMBERS.items()
               if getattr(args, dest) is not None})
    for k in ("criterion", "targets", "base", "effects"):
        if getattr(args, k) is not None:
            kw[k] = getattr(args, k)
    if args.runs is not None and args.budget_h is not None:
        raise InputError("--budget-h", args.budget_h, "give --runs or --budget-h, not both")
    return kw


def run(args: argparse.Namespace) -> int:
    """Plan, print the answer first, write the folder; returns the exit code."""
    from oilgap._plan import plan
    from oilgap.model.io.serialize import dumps
    from oilgap.studies.plan.report import plan_json, write_plan

    kw = settings_from_args(args)
    with out_folder(args, args.out) as folder:
        try:
            res = plan(args.case, **kw)
        except InputError as e:
            raise named_by_option(e, FLAGS) from None
        folder.begin()
        write_plan(res, folder.path)
        folder.complete()
    if args.json:
        print(dumps(plan_json(res)))
    else:
        print(res.summary())
        print(f"\nwrote {args.out}/plan.csv, naive.csv, parameters.csv, effects.csv, "
              "plan.json, plan_runs.png, summary.md")
    return 0
