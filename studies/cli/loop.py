"""``oilgap loop``: calibrate on measured runs, find the missing effect, report before/after
(arguments in :func:`oilgap.studies.cli.parsers.add_loop`)."""

from __future__ import annotations

import argparse
import json

from oilgap.model.case_io import read_case_toml
from oilgap.model.measured_data import load_measured
from oilgap.model.oils import read_oils_csv
from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.studies.loop_report import format_summary, loop_json, write_report


def run(args: argparse.Namespace) -> int:
    """Run the loop and write the report; returns the exit code."""
    case = read_case_toml(args.case) if args.case else None
    oils = read_oils_csv(args.oils) if args.oils else None
    data = load_measured(args.data, oils)
    effects = [e.strip() for e in args.effects.split(",") if e.strip()] if args.effects \
        else None
    est = LoopEstimator(case=case, margin=args.margin, effects=effects,
                        base=getattr(args, "base", "eq6"), cv_by=args.cv_by).fit(data)
    paths = write_report(est, args.out, figures=not args.no_figures)
    if args.json:
        print(json.dumps(loop_json(est), indent=2))
    else:
        print(format_summary(est))
        print(f"\nwrote {paths['json']}, {paths['report']}"
              + (f" and {len(paths['figures'])} figures" if paths["figures"] else ""))
    return 0
