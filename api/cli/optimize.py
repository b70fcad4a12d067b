"""``oilgap optimize``: the region-1 clearance geometry of least mean viscous power.

Thin layer over :func:`oilgap._optimize.optimize` (``og.optimize``, the thermal mode
resolved once, here; the
design NLP of :class:`oilgap.optim.design.DesignProblem`, under ``film``/``full`` its
thermal form): loads the case
(or the seed joint), applies the oil/operating overrides, solves the design NLP
and prints the initial and optimal designs side by side, the active constraints
and what each constraint costs (its multiplier in physical units). Under a thermal
mode the optimum without heating (``none`` at the case's oil temperature) is solved
too and shown beside it, with what heating changed and, under ``full``, what a kelvin
of sea temperature costs. Exit codes: 2 bad input, 3 infeasible problem, 4 solver
failure (from ``oilgap.cli``). Arguments in
:func:`oilgap.cli.parsers.add_optimize`.
"""

from __future__ import annotations

import argparse
import contextlib
from dataclasses import replace
from pathlib import Path

from oilgap._optimize import optimize_resolved, robust_resolved
from oilgap._results_design import Optimization
from oilgap.cli.common import load_case, thermal_case
from oilgap.cli.model_option import apply_model, model_record, report_model
from oilgap.cli.outputs import print_wrote, report_folder, solver_log_to_stderr
from oilgap.model.errors import InputError, check_finite, check_positive
from oilgap.model.io.serialize import dumps
from oilgap.optim.design.session import MAX_STARTS
from oilgap.studies.io.case_write import write_case_toml
from oilgap.studies.io.files import check_out_file
from oilgap.studies.settings import DesignLimits


def _number(args: argparse.Namespace, attr: str, field: str,
            positive: bool = False) -> float | None:
    raw = getattr(args, attr)
    if raw is None:
        return None
    try:
        value = float(raw)
    except ValueError:
        raise InputError(field, raw, "a finite number is required") from None
    return check_positive(field, value) if positive else check_finite(field, value)


def _starts(args: argparse.Namespace) -> int:
    try:
        starts = int(args.starts)
    except ValueError:
        raise InputError("--starts", args.starts, "an integer >= 1 is required") from None
    if not 1 <= starts <= MAX_STARTS:
        raise InputError("--starts", args.starts, f"an integer from 1 to {MAX_STARTS} is "
                         "required (each start is one IPOPT solve)")
    return starts


def _integer(args: argparse.Namespace, attr: str, option: str) -> int | None:
    raw = getattr(args, attr, None)
    if raw is None:
        return None
    try:
        return int(raw)
    except ValueError:
        raise InputError(option, raw, "an integer is required") from None


def _robust_keywords(args: argparse.Namespace) -> dict:
    """``scenarios``, ``seed``, ``pareto`` of ``--robust`` (refused without it)."""
    kw = {k: _integer(args, k, f"--{k}") for k in ("scenarios", "seed", "pareto")}
    given = [f"--{k}" for k, v in kw.items() if v is not None]
    if getattr(args, "figure", None):
        given.append("--figure")
    if args.robust is None and given:
        raise InputError(given[0], getattr(args, given[0][2:]), "only with --robust")
    if args.figure:
        check_out_file(args.figure, args.force)
    return kw


def _write_figure(res, path: str) -> Path:
    import matplotlib
    matplotlib.use("Agg")
    ax = res.plot()
    try:
        ax.figure.savefig(path, dpi=120, bbox_inches="tight")
    except OSError as e:
        raise InputError("--figure", path, f"cannot be written ({e.strerror})") from None
    return Path(path)


def _write(res: Optimization, args: argparse.Namespace, cal=None):
    if not args.out:
        return None
    case = res.to_case()
    if cal is not None:  # the optimum keeps its calibrated model, by reference (every digit)
        case = replace(case, friction=cal.uncalibrated.friction,
                       thermal=cal.uncalibrated.thermal,
                       calibration_model=str(Path(cal.provenance["path"]).resolve()))
    try:
        return write_case_toml(case, args.out, run=getattr(args, "run", None),
                               exact=True)  # every digit: evaluated again, the loss printed
    except OSError as e:
        raise InputError("--out", args.out, f"cannot be written ({e.strerror})") from None


def _solve(args: argparse.Namespace, limits: DesignLimits, robust: dict):
    """The nominal (or ``--robust``) optimum of the case named on the command line
    (``--model`` folded in), and the calibrated model (None without ``--model``)."""
    case, mode = thermal_case(load_case(args), args)  # the one resolution, named as given
    case, cal = apply_model(case, args)
    log = solver_log_to_stderr() if args.verbose else contextlib.nullcontext()
    with log:  # IPOPT's log on stderr: stdout carries the result (--json) alone
        if args.robust is not None:
            return robust_resolved(case, mode, args.robust, robust, limits, args.verbose), cal
        return optimize_resolved(case, mode, args.thermal is None, limits, args.verbose), cal


def run(args: argparse.Namespace) -> int:
    """Solve the design NLP and print (or write) the result; returns the exit code."""
    args.temp_c = _number(args, "temp_c", "--temp-c")
    args.depth_m = _number(args, "depth_m", "--depth-m")
    torque_min = _number(args, "torque_min_nm", "--torque-min-nm", positive=True)
    inertia_ratio = _number(args, "inertia_max_ratio", "--inertia-max-ratio", positive=True)
    limits = DesignLimits(torque_min_Nm=torque_min, inertia_max_ratio=inertia_ratio,
                          starts=_starts(args))
    if args.out:  # before any computation: folder writable, no earlier file unless --force
        check_out_file(args.out, args.force)
    robust = _robust_keywords(args)
    with report_folder(args) as folder:  # checked and locked before computing
        res, cal = _solve(args, limits, robust)
        files = res.report(args.report, folder=folder) if folder is not None else []
    out_path = _write(res, args, cal)
    fig = _write_figure(res, args.figure) if getattr(args, "figure", None) else None
    if args.json:
        print(dumps({**res.to_dict(), "out": str(out_path) if out_path else None,
                     **({"figure": str(fig)} if fig else {}),
                     **({"report": [str(f) for f in files]} if files else {}),
                     **({"model": model_record(cal)} if cal is not None else {})}))
    else:
        print(res.summary(defaults=not args.quiet))
        report_model(cal)  # the model used, the given design's loss with and without it
        for p in (out_path, fig):
            if p:
                print(f"\nwrote {Path(p)}")
        print_wrote(args, files)
    return 0
