"""``oilgap study smoothing``: fit, Table 4, loss vs T (arguments in
:func:`oilgap.studies.cli.parsers.add_study`); a thin layer over
:func:`oilgap.studies.smoothing.run`."""

from __future__ import annotations

import argparse

import numpy as np

from oilgap.model.errors import InputError
from oilgap.studies import smoothing
from oilgap.studies.cli.common import case_or_seed, file_list, gamma_line, study_out
from oilgap.studies.cli.outputs import out_folder
from oilgap.studies.smoothing import SmoothingResult
from oilgap.studies.smoothing_report import thermal_line


def _t_values(args: argparse.Namespace) -> np.ndarray:
    """The T grid of --t-min, --t-max, --t-step (with T = 2 and 4 when in range)."""
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


def _print_comparison(r: SmoothingResult) -> None:
    """The thermal models side by side: parameters, errors of powers and reductions."""
    print(f"\n{'fit':<26}{'params':>7}{'powers RMS':>12}{'worst':>7}{'reductions RMS':>16}"
          f"{'worst':>7}{'gamma':>8}  run temperatures")
    for _, c in r.checks.iterrows():
        gamma = "" if np.isnan(c["gamma"]) else f"{c['gamma']:.3f}"
        print(f"{c['variant'][:25]:<26}{c['n_params']:>7d}{c['rms_W']:>12.2f}"
              f"{c['max_abs_W']:>7.2f}{c['reduction_rms_W']:>16.2f}"
              f"{c['reduction_max_abs_W']:>7.2f}{gamma:>8}  {c['temperatures']}")


def _print(r: SmoothingResult, plateau_tol: float) -> None:
    f = r.fit
    t = r.table[r.table["group"] > 0]
    print(f"thermal     {thermal_line(f, r.thermal_default)}")
    print(f"{gamma_line(case_or_seed(None))}; this study fits its own below")
    print(f"fitted gamma = {f.gamma:.3f} +- {f.gamma_se:.3f}"
          + ("   <- candidate calibrated default for the seed case"
             if (f.method, f.thermal_mode, f.resistance_K_W) == ("per-oil", "none", 0.0)
             else ""))
    print(f"effective temperature: {f.describe()}")
    print()
    print(f"{'oil':<8}{'T_oil':>7}{'model T=4':>11}{'T=2':>8}{'change':>9}"
          f"{'measured T=4':>14}{'T=2':>8}{'change':>9}{'paper model':>13}{'diff':>8}")
    for _, row in t.iterrows():
        print(f"{row['oil']:<8}{row['oil_temp_before_C']:>7.1f}{row['model_before_W']:>11.2f}"
              f"{row['model_after_W']:>8.2f}{row['model_change_W']:>9.2f}"
              f"{row['measured_before_W']:>14.2f}{row['measured_after_W']:>8.2f}"
              f"{row['measured_change_W']:>9.2f}{row['paper_model_change_W']:>13.2f}"
              f"{row['model_minus_measured_change_W']:>8.2f}")
    d = t["model_minus_measured_change_W"].abs()
    print(f"\nreductions within {d.max():.2f} W of measured (paper's model: "
          f"{t['paper_model_minus_measured_change_W'].abs().max():.2f} W)")
    _print_comparison(r)
    print()
    pl = r.plateau
    print(f"loss vs T: within {100 * plateau_tol:g} % of P(T=1) only for T <= "
          f"{pl['T_stop'].min():.2f}..{pl['T_stop'].max():.2f}; 4 -> 2 takes "
          f"{100 * pl['share_of_possible_saving_4_to_2'].mean():.0f} % of the possible saving")


def run(args: argparse.Namespace) -> int:
    """``oilgap study smoothing``: fit, Table 4, loss vs T; returns the exit code."""
    T = _t_values(args)
    out = study_out(args, "smoothing")
    with out_folder(args, out) as folder:  # checked and locked before any computation
        folder.begin()
        r = smoothing.run(out, method=args.method, resistance_K_W=args.r_th_k_per_w,
                          T_values=T, plateau_tol=args.plateau_tol, thermal=args.thermal)
    _print(r, args.plateau_tol)
    print(f"\nwrote {out}/:\n" + file_list(r.files))
    return 0
