"""``oilgap study sweep GRID``: evaluate or optimize every row of a grid (arguments in
:func:`oilgap.cli.parsers.add_study`); a thin layer over
:func:`oilgap._studies.sweep` (``og.sweep``), printing its summary (or, with
``--json``, its JSON document); resumable with the same ``--out``."""

from __future__ import annotations

import argparse
import logging
import sys

from oilgap._evaluate import as_case
from oilgap._studies import resume_conflict, sweep
from oilgap.cli.common import show, study_case, study_out
from oilgap.cli.model_option import apply_model, report_model
from oilgap.cli.outputs import json_quiet, out_folder
from oilgap.model.errors import InputError
from oilgap.studies.grid.runner import SweepInterrupted
from oilgap.studies.io.result_folder import ResultFolder
from oilgap.studies.settings import RunOptions, SweepSettings

RESUME_HINT = "rerun the same command with --resume to continue"
"""What Ctrl-C's line tells the user (the folder stays marked incomplete)."""


def run(args: argparse.Namespace) -> int:
    """``oilgap study sweep GRID``: run a grid (resumable with --resume); returns the exit
    code. ``--out`` is checked and locked before anything is read or computed. Ctrl-C
    says how many points are stored and how to continue (exit 130); an unfinished sweep
    is never continued without ``--resume``."""
    out = study_out(args, "sweep")
    case = study_case(args) if getattr(args, "transition", None) else args.case
    case, cal = (case, None) if getattr(args, "model", None) is None else \
        apply_model(as_case(case), args)  # --model loop.json (issue 25)
    resume_conflict(args.resume, args.force, args.retry_failed,
                    ("--resume", "--force", "--retry-failed"))
    if args.chunk_size is not None and args.chunk_seconds is not None:
        raise InputError("--chunk-size", args.chunk_size, "not with --chunk-seconds: a fixed "
                         "number of rows per task, or chunks sized by time; choose one")
    try:
        with out_folder(args, out, resume=args.resume or args.retry_failed) as folder:
            return _sweep(args, out, folder, case, cal)
    except SweepInterrupted as e:
        print(interrupted_line(e), file=sys.stderr)
        return 130


def interrupted_line(e: SweepInterrupted) -> str:
    """Ctrl-C's one line: how many points are stored and how to continue; plainly
    "nothing was saved" when no point had finished."""
    if e.saved == 0:
        return (f"oilgap: interrupted: nothing was saved (none of the {e.total} points had "
                f"finished); {e.out_dir} is as it was before the run: rerun the same command "
                "to start again")
    return f"oilgap: interrupted: {e.saved} of {e.total} points saved in {e.out_dir}; " \
        f"{RESUME_HINT}"


def _sweep(args: argparse.Namespace, out, folder: ResultFolder, case, cal) -> int:
    """The sweep inside its locked result folder."""
    with json_quiet(args):
        r = sweep(args.grid, case, out=out, oils=args.oils, folder=folder,
                  settings=SweepSettings(mode=args.mode, thermal=args.thermal,
                                         retry_failed=args.retry_failed),
                  options=RunOptions(workers=args.workers, scheduler=args.scheduler,
                                     progress=args.progress, chunk_size=args.chunk_size,
                                     chunk_seconds=args.chunk_seconds))
    folder.complete()
    show(r, args)
    report_model(cal, getattr(args, "json", False))
    bad = r.raw[r.raw["status"] != "ok"]
    if len(bad):
        logging.getLogger("oilgap").warning(  # a failed point changes the result: kept by -q
            f"first failure (row {bad.index[0]}): {bad['error'].iloc[0]}")
    return 0
