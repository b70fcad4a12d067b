"""``oilgap study smoothing [CASE]``: fit, Table 4, loss vs T on the seed rig; on a case,
what smoothing its grooves would save (arguments in
:func:`oilgap.cli.parsers.add_study`); a thin layer over
:func:`oilgap._studies.smoothing` (``og.smoothing``), printing its summary
(or, with ``--json``, its JSON document)."""

from __future__ import annotations

import argparse

import numpy as np

from oilgap._studies import smoothing
from oilgap.cli.common import show, study_case, study_out
from oilgap.cli.model_option import apply_model, report_model
from oilgap.cli.outputs import json_quiet, out_folder
from oilgap.model.errors import InputError
from oilgap.studies.settings import SmoothingSettings
from oilgap.studies.smoothing.fit import check_fixed_resistance
from oilgap.studies.user_case import is_seed_case


def _t_values(args: argparse.Namespace, t_max_default: float = 5.0) -> np.ndarray:
    """The T grid of --t-min, --t-max (default ``t_max_default``), --t-step (with T = 2
    and 4 when in range)."""
    if args.t_max is None:
        args = argparse.Namespace(**{**vars(args), "t_max": t_max_default})
    if args.t_step <= 0:
        raise InputError("--t-step", args.t_step, "must be > 0", "smoothing study")
    if args.t_min < 1.0:
        raise InputError("T", args.t_min, "must be >= 1 (T = 1 is a smooth clearance)",
                         "--t-min")
    if args.t_max < args.t_min:
        raise InputError("--t-max", args.t_max, f"must be >= --t-min = {args.t_min:g}",
                         "smoothing study")
    n = int(round((args.t_max - args.t_min) / args.t_step)) + 1
    if n > 10_000:
        raise InputError("--t-step", args.t_step, "gives more than 10000 T values",
                         "smoothing study")
    T = np.linspace(args.t_min, args.t_min + (n - 1) * args.t_step, n)
    return np.unique(np.r_[T[T <= args.t_max + 1e-12], [2.0, 4.0]
                           if args.t_min <= 2.0 <= args.t_max else []])


def run(args: argparse.Namespace) -> int:
    """``oilgap study smoothing [CASE]``: fit, Table 4, loss vs T on the seed rig; on a
    case, what smoothing its grooves would save. Returns the exit code."""
    case = study_case(args)
    case, cal = apply_model(case, args)  # --model loop.json (issue 25)
    seed = is_seed_case(case)
    T = (_t_values(args) if seed else None if args.t_max is None and args.t_min == 1.0
         and args.t_step == 0.05 else _t_values(args, float(case.region1.roughness)))
    if seed:
        check_fixed_resistance(args.method, args.thermal, args.r_th_k_per_w,
                               ("--r-th-k-per-w", "--method"))
    out = study_out(args, "smoothing")
    with out_folder(args, out) as folder, json_quiet(args):  # locked before computing
        settings = SmoothingSettings(method=args.method, thermal=args.thermal,
                                     resistance_K_W=args.r_th_k_per_w, T_values=T,
                                     plateau_tol=args.plateau_tol,
                                     film_evidence=getattr(args, "film_evidence", False))
        r = smoothing(case, out=out, folder=folder, settings=settings)
    show(r, args)
    report_model(cal, getattr(args, "json", False))
    return 0
