"""``oilgap evaluate``: the viscous loss of a joint, region by region, under a thermal mode
(arguments in :func:`oilgap.cli.parsers.add_evaluate`); a thin layer over
:func:`oilgap._evaluate.evaluate` (``og.evaluate``; the thermal mode resolved once,
here): the text is the result's ``summary()``, ``--json`` its ``to_json()``."""

from __future__ import annotations

import argparse
import importlib

from oilgap._evaluate import evaluate_resolved
from oilgap.cli.common import load_case, show, thermal_case
from oilgap.cli.model_option import apply_model, model_record, report_model
from oilgap.model.io.serialize import dumps


def run(args: argparse.Namespace) -> int:
    """Evaluate the case and print the table (or JSON; ``--report DIR``: also the report
    folder, checked and locked before computing; ``--model``: the calibrated model folded
    in, named with its loss beside the uncalibrated one); returns the exit code."""
    if args.report:  # the report's writers load pandas and matplotlib: only when asked
        outputs = importlib.import_module("oilgap.cli.outputs")
        with outputs.report_folder(args) as folder:
            res, cal, losses = _evaluate(args)
            files = res.report(args.report, folder=folder)
        _show(res, args, cal, losses)
        outputs.print_wrote(args, files)
        return 0
    res, cal, losses = _evaluate(args)
    _show(res, args, cal, losses)
    return 0


def _evaluate(args: argparse.Namespace):
    """The case named on the command line (``--model`` folded in), evaluated under its
    thermal mode; with a model also the (calibrated, uncalibrated) losses [W]."""
    case, mode = thermal_case(load_case(args), args)  # the one resolution, named as given
    case, cal = apply_model(case, args)
    res = evaluate_resolved(case, mode, args.thermal is None, args.laminar_law)
    if cal is None:
        return res, None, None
    raw = evaluate_resolved(cal.uncalibrated, mode, args.thermal is None, args.laminar_law)
    return res, cal, (float(res.total_mean_power_W), float(raw.total_mean_power_W))


def _show(res, args: argparse.Namespace, cal, losses) -> None:
    """Print the result as every command does; with a model, its record (JSON) or its
    lines after the answer (text)."""
    if cal is not None and args.json:
        print(dumps({**res.to_dict(), "model": model_record(cal, *losses)}))
        return
    show(res, args)
    if cal is not None:
        report_model(cal, False, *losses)
