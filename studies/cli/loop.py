"""``oilgap loop``: calibrate on measured runs, find the missing effect, report before/after
(arguments in :func:`oilgap.studies.cli.parsers.add_loop`)."""

from __future__ import annotations

import argparse
import json

import numpy as np

from oilgap.model.case_io import read_case_toml
from oilgap.model.errors import SolverError
from oilgap.model.measured_data import load_measured
from oilgap.model.oils import read_oils_csv
from oilgap.model.result_folder import ResultFolder
from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.studies.cli.outputs import out_folder
from oilgap.studies.loop_report import (
    format_summary,
    loop_json,
    unit_mistake,
    warn_unit_hints,
    write_report,
)


def run(args: argparse.Namespace) -> int:
    """Run the loop and write the report; returns the exit code. ``--out`` is checked and
    locked before anything is read or fitted; the folder is marked incomplete while the
    report is written."""
    with out_folder(args, args.out) as folder:
        return _loop(args, folder)


def _loop(args: argparse.Namespace, folder: ResultFolder) -> int:
    """The loop inside its locked result folder."""
    case = read_case_toml(args.case) if args.case else None
    oils = read_oils_csv(args.oils) if args.oils else None
    data = load_measured(args.data, oils)
    effects = [e.strip() for e in args.effects.split(",") if e.strip()] if args.effects \
        else None
    est = LoopEstimator(case=case, margin=args.margin, effects=effects,
                        base=getattr(args, "base", "eq6"), cv_by=args.cv_by)
    try:
        with np.errstate(all="ignore"):  # trial fits at extreme values: not user news
            est.fit(data)
    except SolverError as e:  # on data in the wrong unit: name the unit, not the solver
        refusal = unit_mistake(est, str(args.data), e)
        if refusal is None:
            raise
        raise refusal from None
    warn_unit_hints(est)
    folder.begin()
    paths = write_report(est, args.out, figures=not args.no_figures)
    folder.complete()
    if args.json:
        print(json.dumps(loop_json(est), indent=2))
    else:
        print(format_summary(est))
        print(f"\nwrote {paths['json']}, {paths['report']}"
              + (f" and {len(paths['figures'])} figures" if paths["figures"] else ""))
    return 0
