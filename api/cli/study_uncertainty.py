"""``oilgap study uncertainty [CASE]``: the loss's percentiles under uncertain inputs, the
tornado and the Sobol' indices (arguments in :func:`oilgap.cli.parsers.add_study`); a thin
layer over :func:`oilgap._uncertainty.uncertainty` (``og.uncertainty``), printing its
summary (or, with ``--json``, its JSON document)."""

from __future__ import annotations

import argparse

from oilgap._uncertainty import uncertainty
from oilgap.cli.common import show, study_case, study_out
from oilgap.cli.outputs import json_quiet, out_folder
from oilgap.studies.settings import UncertaintySettings


def run(args: argparse.Namespace) -> int:
    """``oilgap study uncertainty``: percentiles, tornado, Sobol' indices; returns the exit
    code."""
    case = study_case(args)
    settings = UncertaintySettings(samples=args.samples, sobol_samples=args.sobol_samples,
                                   seed=args.seed, thermal=args.thermal,
                                   confidence=args.confidence, sobol=not args.no_sobol)
    out = study_out(args, "uncertainty")
    with out_folder(args, out) as folder, json_quiet(args):  # locked before computing
        r = uncertainty(case, model=args.model, out=out, folder=folder, settings=settings)
    show(r, args)
    return 0
