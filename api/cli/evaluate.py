"""``oilgap evaluate``: the viscous loss of a joint, region by region, under a thermal mode
(arguments in :func:`oilgap.cli.parsers.add_evaluate`); a thin layer over
:func:`oilgap._evaluate.evaluate` (``og.evaluate``; the thermal mode resolved once,
here): the text is the result's ``summary()``, ``--json`` its ``to_json()``."""

from __future__ import annotations

import argparse
import importlib

from oilgap._evaluate import evaluate_resolved
from oilgap.cli.common import load_case, show, thermal_case


def run(args: argparse.Namespace) -> int:
    """Evaluate the case and print the table (or JSON; ``--report DIR``: also the report
    folder, checked and locked before computing); returns the exit code."""
    if args.report:  # the report's writers load pandas and matplotlib: only when asked
        outputs = importlib.import_module("oilgap.cli.outputs")
        with outputs.report_folder(args) as folder:
            res = _evaluate(args)
            files = res.report(args.report, folder=folder)
        show(res, args)
        outputs.print_wrote(args, files)
        return 0
    show(_evaluate(args), args)
    return 0


def _evaluate(args: argparse.Namespace):
    """The case named on the command line, evaluated under its thermal mode."""
    case, mode = thermal_case(load_case(args), args)  # the one resolution, named as given
    return evaluate_resolved(case, mode, args.thermal is None, args.laminar_law)
