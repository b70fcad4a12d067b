"""Helpers shared by the command modules: the case named on the command line, the
output folder of a study, and a result printed as text or (``--json``) as JSON."""

from __future__ import annotations

import argparse
from pathlib import Path

from oilgap._evaluate import as_case, with_operating, with_transition
from oilgap._evaluate import thermal_case as api_thermal_case
from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.thermal_modes import ThermalMode


def load_case(args: argparse.Namespace) -> DesignCase:
    """The case named on the command line (or the seed), with --oil/--oils, --temp-c and
    --depth-m (:func:`oilgap._evaluate.with_operating`) and --transition applied. Shared by the
    subcommands that take a CASE."""
    if args.case and getattr(args, "smoothed", False):
        raise InputError("--smoothed", True, f"not with CASE {args.case!r}: --smoothed picks "
                         "the seed joint smoothed with epoxy (T = 2) when no CASE is given; "
                         "drop one (a case's roughness is its [region1] T1_mm..T4_mm)")
    case = read_case_toml(args.case) if args.case else seed_case(getattr(args, "smoothed",
                                                                         False))
    case = with_operating(case, getattr(args, "oil", None), getattr(args, "oils", None),
                          getattr(args, "temp_c", None), getattr(args, "depth_m", None))
    return with_transition(case, getattr(args, "transition", None), "--transition")


def study_case(args: argparse.Namespace) -> DesignCase:
    """The case of a study command (CASE or the seed) with ``--transition`` applied."""
    return with_transition(as_case(getattr(args, "case", None)),
                           getattr(args, "transition", None), "--transition")


def study_out(args: argparse.Namespace, study: str) -> Path:
    """The study's output folder: ``--out``, else ``out/<study>``."""
    return Path(args.out) if args.out else Path("out") / study


def show(view, args: argparse.Namespace) -> None:
    """Print a result view: its JSON document with ``--json``, else its summary (the
    text the command prints: the answer first; ``-q`` leaves out the assumptions and
    the defaults filled in)."""
    print(view.to_json() if getattr(args, "json", False)
          else view.summary(defaults=not getattr(args, "quiet", False)))


def thermal_case(case: DesignCase, args: argparse.Namespace
                 ) -> tuple[DesignCase, ThermalMode]:
    """The thermal mode of ``--thermal`` checked against the case and ``--temp-c``, and the
    case with ``--sea-temp-c`` applied (evaluate and optimize share these options): the
    façade's :func:`oilgap._evaluate.thermal_case`, its messages naming the options."""
    raw = getattr(args, "sea_temp_c", None)
    try:
        sea = None if raw is None else float(raw)
    except ValueError:
        raise InputError("--sea-temp-c", raw, "a finite number is required") from None
    balance = ("--thermal {mode}" if args.thermal
               else "--thermal {mode} (the default with [thermal])")
    return api_thermal_case(case, args.thermal, args.temp_c, sea, names={
        "thermal": "--thermal", "oil_temp_C": "--temp-c", "sea_temp_C": "--sea-temp-c",
        "balance": balance, "given": "choose --thermal none or film"})
