"""``oilgap evaluate``: the viscous loss of a joint, region by region, under a thermal mode
(arguments in :func:`oilgap.cli.parsers.add_evaluate`); a thin layer over
:func:`oilgap._evaluate.evaluate` (``og.evaluate``; the thermal mode resolved once,
here): the text is the result's ``summary()``, ``--json`` its ``to_json()``."""

from __future__ import annotations

import argparse

from oilgap._evaluate import evaluate_resolved
from oilgap.cli.common import load_case, thermal_case
from oilgap.cli.model_option import apply_model, model_record, report_model
from oilgap.model.io.serialize import dumps


def run(args: argparse.Namespace) -> int:
    """Evaluate the case and print the table (or JSON); returns the exit code."""
    case, mode = thermal_case(load_case(args), args)  # the one resolution, named as given
    case, cal = apply_model(case, args)
    res = evaluate_resolved(case, mode, args.thermal is None, args.laminar_law)
    if cal is None:
        print(res.to_json() if args.json else res.summary())
        return 0
    raw = evaluate_resolved(cal.uncalibrated, mode, args.thermal is None, args.laminar_law)
    losses = float(res.total_mean_power_W), float(raw.total_mean_power_W)
    if args.json:
        print(dumps({**res.to_dict(), "model": model_record(cal, *losses)}))
    else:
        print(res.summary())
        report_model(cal, False, *losses)
    return 0
