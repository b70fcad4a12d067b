"""``oilgap loop``: calibrate on measured runs, find the missing effect, report before/after
(arguments in :func:`oilgap.cli.parsers.add_loop`); a thin layer over
:class:`oilgap._loop.Loop` (``og.Loop``)."""

from __future__ import annotations

import argparse
import os
from dataclasses import replace
from pathlib import Path

from oilgap._loop import Loop
from oilgap.cli.outputs import out_folder
from oilgap.model.case import DesignCase
from oilgap.studies.io.case_write import write_case_toml
from oilgap.studies.io.files import check_out_file
from oilgap.studies.io.result_folder import ResultFolder


def run(args: argparse.Namespace) -> int:
    """Run the loop and write the report; returns the exit code. ``--out`` is checked and
    locked before anything is read or fitted; the folder is marked incomplete while the
    report is written."""
    case_out = (check_out_file(args.write_case, args.force, suffixes=(".toml",))
                if getattr(args, "write_case", None) else None)  # refused before any fit
    with out_folder(args, args.out) as folder:
        code, case = _loop(args, folder)
    if case_out is not None:
        print(f"wrote {write_calibrated_case(case, args.out, case_out)} (the rig case with "
              "[calibration] model = the loop.json)")
    return code


def write_calibrated_case(case: DesignCase, out_dir: str | Path, path: Path) -> Path:
    """Write the loop's rig case to ``path`` with ``[calibration] model`` naming the
    ``loop.json`` in ``out_dir`` relative to ``path`` (the one representation of a
    calibrated case: by reference, every digit of the model kept)."""
    model = (Path(out_dir) / "loop.json").resolve()
    rel = os.path.relpath(model, path.resolve().parent)
    return write_case_toml(replace(case, calibration_model=rel), path)


def _loop(args: argparse.Namespace, folder: ResultFolder) -> tuple[int, DesignCase]:
    """The loop inside its locked result folder."""
    est = Loop(args.case, oils=args.oils, margin=args.margin, effects=args.effects,
               base=getattr(args, "base", "auto"), cv_by=args.cv_by)
    est.fit(args.data)
    paths = est.report(args.out, figures="none" if args.no_figures else args.figures,
                       folder=folder)
    if args.json:
        print(est.to_json())
    else:
        print(est.summary(defaults=not args.quiet))
        print(f"\nwrote {paths['json']}, {paths['report']}"
              + (f" and {len(paths['figures'])} figures" if paths["figures"] else ""))
    return 0, est.case_
