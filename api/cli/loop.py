"""``oilgap loop``: calibrate on measured runs, find the missing effect, report before/after
(arguments in :func:`oilgap.cli.parsers.add_loop`); a thin layer over
:class:`oilgap._loop.Loop` (``og.Loop``)."""

from __future__ import annotations

import argparse

from oilgap._loop import Loop
from oilgap.cli.outputs import out_folder
from oilgap.studies.io.result_folder import ResultFolder


def run(args: argparse.Namespace) -> int:
    """Run the loop and write the report; returns the exit code. ``--out`` is checked and
    locked before anything is read or fitted; the folder is marked incomplete while the
    report is written."""
    with out_folder(args, args.out) as folder:
        return _loop(args, folder)


def _loop(args: argparse.Namespace, folder: ResultFolder) -> int:
    """The loop inside its locked result folder."""
    est = Loop(args.case, oils=args.oils, margin=args.margin, effects=args.effects,
               base=getattr(args, "base", "auto"), cv_by=args.cv_by)
    est.fit(args.data)
    paths = est.report(args.out, figures=not args.no_figures, folder=folder)
    if args.json:
        print(est.to_json())
    else:
        print(est.summary())
        print(f"\nwrote {paths['json']}, {paths['report']}"
              + (f" and {len(paths['figures'])} figures" if paths["figures"] else ""))
    return 0
