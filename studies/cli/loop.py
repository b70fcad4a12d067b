"""``oilgap loop``: calibrate on measured runs, find the missing effect, report before/after."""

from __future__ import annotations

import argparse
import json


def add_parser(sub) -> None:
    """Register ``oilgap loop``."""
    p = sub.add_parser(
        "loop", help="calibrate on measured data, search a missing effect, report",
        description="Close the loop with measured data: validate DATA (CSV or Parquet), take "
        "away the oil-free baseline, fit the seed's model without and with T (Table 3), "
        "search the residual for a missing effect from the library (sparse regression, "
        "leave-one-run-out cross-validation), refit and report the errors before and after. "
        "Writes DIR/loop.json, DIR/report.md and figures.")
    p.add_argument("data", metavar="DATA.csv", help="measured runs (CSV, or .parquet)")
    p.add_argument("--oils", metavar="OILS.csv", help="oils table oil,nu40_cSt,nu100_cSt,"
                   "density_kg_m3 (default: the built-in ISO VG catalogue)")
    p.add_argument("--case", metavar="RIG.toml", help="rig geometry (default: the seed joint)")
    p.add_argument("--out", metavar="DIR", default="loop_out",
                   help="output directory (default: loop_out)")
    p.add_argument("--json", action="store_true", help="print loop.json instead of the tables")
    from oilgap.studies.cli import finite_float

    p.add_argument("--margin", type=finite_float, default=0.10,
                   help="held-out RMSE fall an effect must bring (default 0.10)")
    p.add_argument("--effects", metavar="NAME,...", help="consider only these library effects")
    p.add_argument("--no-figures", action="store_true", help="skip the figures")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the loop and write the report; returns the exit code."""
    from oilgap.model.case_io import read_case_toml
    from oilgap.model.measured_data import load_measured
    from oilgap.model.oils import read_oils_csv
    from oilgap.optim.calibration.estimator import LoopEstimator
    from oilgap.studies.report_loop import format_summary, loop_json, write_report

    case = read_case_toml(args.case) if args.case else None
    oils = read_oils_csv(args.oils) if args.oils else None
    data = load_measured(args.data, oils)
    effects = [e.strip() for e in args.effects.split(",") if e.strip()] if args.effects \
        else None
    est = LoopEstimator(case=case, margin=args.margin, effects=effects).fit(data)
    paths = write_report(est, args.out, figures=not args.no_figures)
    if args.json:
        print(json.dumps(loop_json(est), indent=2))
    else:
        print(format_summary(est))
        print(f"\nwrote {paths['json']}, {paths['report']}"
              + (f" and {len(paths['figures'])} figures" if paths["figures"] else ""))
    return 0
