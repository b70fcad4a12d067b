"""``oilgap evaluate``: the viscous loss of a joint, region by region, under a thermal mode
(arguments in :func:`oilgap.cli.parsers.add_evaluate`); a thin layer over
:func:`oilgap._evaluate.evaluate` (``og.evaluate``; the thermal mode resolved once,
here): the text is the result's ``summary()``, ``--json`` its ``to_json()``."""

from __future__ import annotations

import argparse

from oilgap._evaluate import evaluate_resolved
from oilgap.cli.common import load_case, show, thermal_case
from oilgap.cli.outputs import print_wrote, report_folder


def run(args: argparse.Namespace) -> int:
    """Evaluate the case and print the table (or JSON; ``--report DIR``: also the report
    folder, checked and locked before computing); returns the exit code."""
    with report_folder(args) as folder:
        case, mode = thermal_case(load_case(args), args)  # the one resolution, as given
        res = evaluate_resolved(case, mode, args.thermal is None, args.laminar_law)
        files = res.report(args.report, folder=folder) if folder is not None else []
    show(res, args)
    print_wrote(args, files)
    return 0
