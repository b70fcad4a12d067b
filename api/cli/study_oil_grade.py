"""``oilgap study oil-grade``: the grade table and the recommendation (arguments in
:func:`oilgap.cli.parsers.add_study`); a thin layer over
:func:`oilgap._studies.oil_grade` (``og.oil_grade``), printing its summary
(or, with ``--json``, its JSON document). Exit 3 if no grade passes both limits."""

from __future__ import annotations

import argparse

from oilgap._studies import oil_grade
from oilgap.cli.common import show, study_case, study_out
from oilgap.cli.model_option import apply_model, report_model
from oilgap.cli.outputs import json_quiet, out_folder
from oilgap.model.errors import InfeasibleError
from oilgap.studies.oil_grade.study import read_mission_csv
from oilgap.studies.settings import DEFAULT_TEMP_RANGE_C, OilGradeSettings, RunOptions


def _temp_range(args: argparse.Namespace) -> tuple[float, float] | None:
    """--temp-min-c/--temp-max-c (None when neither is given; default 0-40 degC)."""
    if args.temp_min_c is None and args.temp_max_c is None:
        return None
    lo, hi = DEFAULT_TEMP_RANGE_C
    return (lo if args.temp_min_c is None else args.temp_min_c,
            hi if args.temp_max_c is None else args.temp_max_c)


def run(args: argparse.Namespace) -> int:
    """``oilgap study oil-grade``: grade table and recommendation; exit 3 if none passes."""
    case = study_case(args)
    case, cal = apply_model(case, args)  # --model loop.json (issue 25)
    mission = read_mission_csv(args.mission) if args.mission else None
    settings = OilGradeSettings(thermal=args.thermal, nu_min_cSt=args.nu_min_cst,
                                nu_max_cSt=args.nu_max_cst, iso_tolerance=args.iso_tolerance,
                                depth_range_m=(args.depth_min_m, args.depth_max_m),
                                temp_range_C=_temp_range(args),
                                sea_temp_range_C=args.sea_temp_range_c,
                                mission_hours=args.mission_hours)
    out = study_out(args, "oil-grade")
    with out_folder(args, out) as folder, json_quiet(args):  # locked before computing
        r = oil_grade(case, mission=mission, out=out, folder=folder, settings=settings,
                      options=RunOptions(workers=args.workers, scheduler=args.scheduler,
                                         progress=args.progress))
    show(r, args)
    report_model(cal, getattr(args, "json", False))
    if r.recommended is None:
        raise InfeasibleError("no oil grade meets both the lubrication limit "
                              f"({args.nu_min_cst:g} cSt) and the cold-start limit "
                              f"({args.nu_max_cst:g} cSt) over the envelope",
                              "no feasible grade")
    return 0
