"""``oilgap study pareto``: the gap-loss and loss-inertia fronts (arguments in
:func:`oilgap.cli.parsers.add_study`); a thin layer over
:func:`oilgap._studies.pareto` (``og.pareto``), printing its summary (or,
with ``--json``, its JSON document)."""

from __future__ import annotations

import argparse

from oilgap._studies import pareto
from oilgap.cli.common import show, study_case, study_out
from oilgap.cli.model_option import apply_model, report_model
from oilgap.cli.outputs import json_quiet, out_folder
from oilgap.studies.settings import ParetoSettings, RunOptions


def run(args: argparse.Namespace) -> int:
    """``oilgap study pareto``: the two fronts; returns the exit code."""
    case = study_case(args)
    case, cal = apply_model(case, args)  # --model loop.json (issue 25)
    out = study_out(args, "pareto")
    settings = ParetoSettings(points=args.points, torque_min_Nm=args.torque_min_nm,
                              thermal=args.thermal)  # refused before the folder is locked
    with out_folder(args, out) as folder, json_quiet(args):  # locked before computing
        r = pareto(case, out=out, folder=folder, settings=settings,
                   options=RunOptions(workers=args.workers, scheduler=args.scheduler,
                                      progress=args.progress))
    show(r, args)
    report_model(cal, getattr(args, "json", False))
    return 0
