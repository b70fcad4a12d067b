"""``oilgap study``: the trade studies (smoothing, pareto, oil-grade, sweep).

Each subcommand writes a CSV of its numbers, PNG figures and ``summary.md`` to
``--out DIR`` (default ``out/<study>/``) and prints the key numbers. Each is a
thin layer over one Python call:

* ``smoothing`` -> :func:`oilgap.studies.smoothing.run`
* ``pareto`` -> :func:`oilgap.studies.pareto.run`
* ``oil-grade`` -> :func:`oilgap.studies.oil_grade.run`
* ``sweep GRID.csv`` -> :func:`oilgap.studies.trade.run_grid`

Bad study parameters exit 2 with one line (InputError).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.errors import InputError


def _out(args: argparse.Namespace, study: str) -> Path:
    return Path(args.out) if args.out else Path("out") / study


def _case(path: str | None):
    from oilgap.model.case_io import read_case_toml, seed_case

    return read_case_toml(path) if path else seed_case()


def _positive_int(text: str) -> int:
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if v < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not allowed; an integer >= 1 is "
                                         "required")
    return v


def add_parser(sub) -> None:
    """Register ``oilgap study`` and its four subcommands."""
    from oilgap.studies.cli import finite_float

    p = sub.add_parser("study", help="trade studies: smoothing, pareto, oil-grade, sweep",
                       description="Trade studies. Each writes CSV, PNG figures and "
                       "summary.md to --out DIR (default out/<study>/).")
    ss = p.add_subparsers(dest="study", metavar="STUDY")
    ss.required = True

    s = ss.add_parser("smoothing", help="seed joint T = 4 vs T = 2 against Table 4; loss vs T",
                      description="Reproduce the seed's smoothing experiment (Table 4): "
                      "grooved T = 4 vs smoothed T = 2 with ISO VG150/320/680/1000 at 0 m; fit "
                      "gamma and the runs' effective oil temperatures; then loss against T.")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/smoothing/)")
    s.add_argument("--method", choices=("per-oil", "shared"), default="per-oil",
                   help="effective temperature: one per oil (default) or one shared steady "
                   "heat balance T = T_base + R_th P")
    s.add_argument("--r-th-k-per-w", type=finite_float, default=0.0, metavar="K_PER_W",
                   help="per-oil method: fixed R_th [K/W] making smoothed runs colder "
                   "(default 0)")
    s.add_argument("--t-min", type=finite_float, default=1.0, help="smallest T (>= 1)")
    s.add_argument("--t-max", type=finite_float, default=5.0, help="largest T")
    s.add_argument("--t-step", type=finite_float, default=0.05, help="T step")
    s.add_argument("--plateau-tol", type=finite_float, default=0.05,
                   help="loss counts as levelled off within this fraction of P(T=1) "
                   "(default 0.05)")
    s.set_defaults(func=run_smoothing)

    s = ss.add_parser("pareto", help="epsilon-constraint fronts: gap vs loss, loss vs inertia",
                      description="Pareto fronts of the design NLP by epsilon-constraint "
                      "sweeps (one warm-started IPOPT solve per point): magnetic gap vs loss "
                      "and loss vs rotor inertia; seed and smoothed seed marked.")
    s.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/pareto/)")
    s.add_argument("--points", type=_positive_int, default=60,
                   help="points per front (>= 50, default 60)")
    s.add_argument("--torque-min-nm", type=finite_float,
                   help="required torque capability [N m] (default: the case's own)")
    s.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="progress line on stderr (default: if a terminal)")
    s.set_defaults(func=run_pareto)

    s = ss.add_parser("oil-grade", help="choose the ISO VG grade over the envelope",
                      description="Mean loss of ISO VG10..VG1000 over the envelope, "
                      "lubrication and cold-start limits, mission energy; recommended grade.")
    s.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/oil-grade/)")
    s.add_argument("--mission", metavar="MISSION.csv",
                   help="mission profile depth_m,oil_temp_C,fraction (default: the case's "
                   "[[mission]] rows, else the stated seed mission)")
    s.add_argument("--nu-min-cst", type=finite_float, default=13.0,
                   help="lubrication limit: minimum viscosity at the hottest point [cSt] "
                   "(default 13)")
    s.add_argument("--nu-max-cst", type=finite_float, default=1000.0,
                   help="cold-start limit: maximum viscosity at the coldest point [cSt] "
                   "(default 1000)")
    s.add_argument("--iso-tolerance", type=finite_float, default=0.10,
                   help="ISO 3448 grade tolerance applied at its worst (default 0.10)")
    s.add_argument("--depth-min-m", type=finite_float, default=0.0)
    s.add_argument("--depth-max-m", type=finite_float, default=7000.0)
    s.add_argument("--temp-min-c", type=finite_float, default=0.0)
    s.add_argument("--temp-max-c", type=finite_float, default=40.0)
    s.add_argument("--mission-hours", type=finite_float, default=8.0,
                   help="mission duration for the energy [h] (default 8)")
    s.add_argument("--workers", type=_positive_int, help="processes (default: all cores)")
    s.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="progress line on stderr (default: if a terminal)")
    s.set_defaults(func=run_oil_grade)

    s = ss.add_parser("sweep", help="evaluate or optimize every row of a grid CSV",
                      description="Run any grid of parameter combinations (one row per "
                      "point, columns: " + ", ".join(_columns()) + "). Empty cells keep the "
                      "case's value. A failed point is a row with its error; rerunning with "
                      "the same --out computes only the points not yet done.")
    s.add_argument("grid", metavar="GRID.csv")
    s.add_argument("--case", metavar="CASE.toml", help="base case (default: seed)")
    s.add_argument("--oils", metavar="OILS.csv", help="oils table to look oil names up in")
    s.add_argument("--mode", choices=("evaluate", "optimize"), default="evaluate")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/sweep/)")
    s.add_argument("--workers", type=_positive_int, help="processes (default: all cores)")
    s.add_argument("--chunk-size", type=_positive_int, help="rows per task")
    s.add_argument("--retry-failed", action="store_true",
                   help="recompute points stored as failed")
    s.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="progress line on stderr (default: if a terminal)")
    s.set_defaults(func=run_sweep)


def _columns() -> list[str]:
    from oilgap.studies.trade import OPTIMIZE_COLUMNS, PARAM_COLUMNS

    return list(PARAM_COLUMNS) + [f"{c} (optimize)" for c in OPTIMIZE_COLUMNS]


def _files(files) -> str:
    return "\n".join(f"  {f}" for f in files)


# --------------------------------------------------------------------------- smoothing


def run_smoothing(args: argparse.Namespace) -> int:
    """``oilgap study smoothing``: fit, Table 4, loss vs T; returns the exit code."""
    from oilgap.studies.smoothing import run

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
    T = np.unique(np.r_[T[T <= args.t_max + 1e-12], [2.0, 4.0]
                        if args.t_min <= 2.0 <= args.t_max else []])
    out = _out(args, "smoothing")
    r = run(out, method=args.method, resistance_K_W=args.r_th_k_per_w, T_values=T,
            plateau_tol=args.plateau_tol)
    f = r.fit
    t = r.table[r.table["group"] > 0]
    print(f"fitted gamma = {f.gamma:.3f} +- {f.gamma_se:.3f}   <- candidate calibrated default "
          "for the seed case")
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
    pl = r.plateau
    print(f"loss vs T: within {100 * args.plateau_tol:g} % of P(T=1) only for T <= "
          f"{pl['T_stop'].min():.2f}..{pl['T_stop'].max():.2f}; 4 -> 2 takes "
          f"{100 * pl['share_of_possible_saving_4_to_2'].mean():.0f} % of the possible saving")
    print(f"\nwrote {out}/:\n" + _files(r.files))
    return 0


# --------------------------------------------------------------------------- pareto


def run_pareto(args: argparse.Namespace) -> int:
    """``oilgap study pareto``: the two fronts; returns the exit code."""
    from oilgap.studies.pareto import run

    case = _case(args.case)
    out = _out(args, "pareto")
    r = run(out, case, args.points, args.torque_min_nm, args.progress)
    g, i = r.gap_front, r.inertia_front
    gok = g[g["status"] == "ok"]
    iok = i[i["status"] == "ok"]
    print(f"gap front: {len(gok)}/{len(g)} points, delta {gok['delta_mm'].min():.3f}.."
          f"{gok['delta_mm'].max():.3f} mm, loss {gok['mean_power_W'].max():.2f}.."
          f"{gok['mean_power_W'].min():.2f} W; sweep {r.sweep_time_s:.2f} s "
          f"(median solve {1e3 * gok['solve_time_s'].median():.1f} ms)")
    print(f"  hypervolume {r.hypervolume:.4f} mm W, reference point "
          f"(delta {r.reference_point[0]:g} mm, P {r.reference_point[1]:.3f} W)")
    print(f"inertia front: {len(iok)}/{len(i)} points, inertia "
          f"{iok['inertia_ratio'].min():.3f}..{iok['inertia_ratio'].max():.3f} x the case's "
          f"rotor, loss {iok['mean_power_W'].max():.2f}..{iok['mean_power_W'].min():.2f} W")
    for _, s in r.seeds.iterrows():
        print(f"  {s['design']:<22} delta {s['delta_mm']:.3f} mm  T {s['T']:.2f}  "
              f"P {s['mean_power_W']:.2f} W  inertia {s['inertia_ratio']:.3f} x")
    bad = pd.concat([g[g["status"] != "ok"], i[i["status"] != "ok"]])
    if len(bad):
        print(f"{len(bad)} points failed (rows kept with their error); first: "
              f"{bad['error'].iloc[0]}")
    print(f"\nwrote {out}/:\n" + _files(r.files))
    return 0


# --------------------------------------------------------------------------- oil grade


def run_oil_grade(args: argparse.Namespace) -> int:
    """``oilgap study oil-grade``: grade table and recommendation; exit 3 if none passes."""
    from oilgap.model.errors import InfeasibleError
    from oilgap.studies.oil_grade import read_mission_csv, run

    case = _case(args.case)
    mission = read_mission_csv(args.mission) if args.mission else None
    out = _out(args, "oil-grade")
    r = run(out, case, mission, nu_min_cSt=args.nu_min_cst, nu_max_cSt=args.nu_max_cst,
            iso_tolerance=args.iso_tolerance, depth_range_m=(args.depth_min_m,
                                                            args.depth_max_m),
            temp_range_C=(args.temp_min_c, args.temp_max_c), mission_hours=args.mission_hours,
            workers=args.workers, progress=args.progress)
    t = r.table
    if r.recommended is not None:
        print(f"recommended: {r.recommended}   runner-up: {r.runner_up or 'none'}\n")
    print(f"{'oil':<8}{'nu min':>9}{'nu max':>10}{'mission W':>11}{'energy Wh':>11}  verdict")
    for _, row in t.iterrows():
        print(f"{row['oil']:<8}{row['nu_min_envelope_cSt']:>9.1f}"
              f"{row['nu_max_envelope_cSt']:>10.0f}{row['mission_mean_power_W']:>11.2f}"
              f"{row['mission_energy_Wh']:>11.1f}  {row['verdict']}: {row['reason']}")
    print(f"\nmission: {r.mission_source}; " + ", ".join(
        f"{m.depth_m:g} m/{m.oil_temp_C:g} degC/{m.fraction:g}" for m in r.mission))
    print(f"wrote {out}/:\n" + _files(r.files))
    if r.recommended is None:
        raise InfeasibleError("no oil grade meets both the lubrication limit "
                              f"({args.nu_min_cst:g} cSt) and the cold-start limit "
                              f"({args.nu_max_cst:g} cSt) over the envelope",
                              "no feasible grade")
    return 0


# --------------------------------------------------------------------------- sweep


def _sweep_figure(res: pd.DataFrame, base_power: float, base_name: str, path: Path):
    from oilgap.studies.trade import new_figure, save_figure

    ok = res[res["status"] == "ok"]
    params = [c for c in res.columns if c in _param_names() and c != "label"]
    num = [c for c in params if pd.api.types.is_numeric_dtype(res[c])
           and res[c].nunique() > 1]
    fig, ax = new_figure(7.5, 4.8)
    if num:
        x = num[0]
        if len(num) > 1:
            sc = ax.scatter(ok[x], ok["mean_power_W"], c=ok[num[1]], s=14, cmap="viridis")
            fig.colorbar(sc, ax=ax, label=_axis_label(num[1]))
        else:
            ax.plot(ok[x], ok["mean_power_W"], "o", ms=4)
        ax.set_xlabel(_axis_label(x))
    else:
        ax.plot(np.arange(len(ok)), ok["mean_power_W"], "o", ms=4)
        ax.set_xlabel("grid row [-]")
    ax.axhline(base_power, color="k", ls="--", lw=1,
               label=f"base case ({base_name}): {base_power:.2f} W")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title(f"Sweep: {len(ok)}/{len(res)} points")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, path)


def _axis_label(col: str) -> str:
    """Axis label with units from the column's description: "oil temperature [degC]"."""
    from oilgap.studies.trade import OPTIMIZE_COLUMNS, PARAM_COLUMNS

    desc = {**PARAM_COLUMNS, **OPTIMIZE_COLUMNS}.get(col, col)
    return desc[:desc.index("]") + 1] if "]" in desc else col


def _param_names() -> set[str]:
    from oilgap.studies.trade import OPTIMIZE_COLUMNS, PARAM_COLUMNS

    return set(PARAM_COLUMNS) | set(OPTIMIZE_COLUMNS)


def run_sweep(args: argparse.Namespace) -> int:
    """``oilgap study sweep GRID.csv``: run a grid (resumable); returns the exit code."""
    from oilgap.model.evaluation import mean_viscous_power
    from oilgap.model.oils import read_oils_csv
    from oilgap.studies.trade import markdown_table, read_grid_csv, run_grid

    grid = read_grid_csv(args.grid)
    case = _case(args.case)
    cat = read_oils_csv(args.oils) if args.oils else None
    out = _out(args, "sweep")
    t0 = time.perf_counter()
    res = run_grid(grid, case, mode=args.mode, out_dir=out, workers=args.workers,
                   chunk_size=args.chunk_size, progress=args.progress, catalogue=cat,
                   retry_failed=args.retry_failed)
    dt = time.perf_counter() - t0
    ok = res[res["status"] == "ok"]
    bad = res[res["status"] != "ok"]
    base_p = mean_viscous_power(case)
    fig = _sweep_figure(res, base_p, case.name, out / "sweep.png")
    lines = [f"# Sweep of {Path(args.grid).name} ({args.mode})", "",
             f"Base case: {case.name} ({base_p:.3f} W at its operating point). "
             f"{len(res)} points: {len(ok)} ok, {len(bad)} failed; "
             f"{res.attrs.get('computed', len(res))} computed this run, "
             f"{res.attrs.get('reused', 0)} taken from {out}/points_{args.mode}.csv; "
             f"{dt:.2f} s."]
    if len(ok):
        best = ok.loc[ok["mean_power_W"].idxmin()]
        worst = ok.loc[ok["mean_power_W"].idxmax()]
        cols = [c for c in grid.columns] + ["mean_power_W"]
        lines += ["", "Lowest and highest mean power:", "",
                  markdown_table(pd.DataFrame([best[cols], worst[cols]]), 3)]
    if len(bad):
        lines += ["", f"First failure (row {bad.index[0]}): {bad['error'].iloc[0]}"]
    md = out / "summary.md"
    md.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"{len(res)} points: {len(ok)} ok, {len(bad)} failed "
          f"({res.attrs.get('computed', len(res))} computed, {res.attrs.get('reused', 0)} "
          f"reused) in {dt:.2f} s")
    if len(ok):
        print(f"mean power {ok['mean_power_W'].min():.3f} .. {ok['mean_power_W'].max():.3f} W "
              f"(base case {base_p:.3f} W)")
    if len(bad):
        print(f"first failure (row {bad.index[0]}): {bad['error'].iloc[0]}", file=sys.stderr)
    print(f"wrote {out}/:\n" + _files([out / "results.csv", out / f"points_{args.mode}.csv",
                                       fig, md]))
    return 0
