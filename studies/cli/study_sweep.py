"""``oilgap study sweep GRID.csv``: evaluate or optimize every row of a grid (arguments in
:func:`oilgap.studies.cli.parsers.add_study`); a thin layer over
:func:`oilgap.studies.grid.runner.run_grid`, resumable with the same ``--out``."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.joint_loss import operating_temperature
from oilgap.model.oils import read_oils_csv
from oilgap.model.result_folder import ResultFolder
from oilgap.studies.cli.common import case_or_seed, file_list, gamma_line, study_out
from oilgap.studies.cli.outputs import out_folder
from oilgap.studies.grid.columns import OPTIMIZE_COLUMNS, PARAM_COLUMNS
from oilgap.studies.grid.evaluate import thermal_description
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.grid.schema import read_grid_csv
from oilgap.studies.reporting import markdown_table, new_figure, save_figure, write_text


def _sweep_figure(res: pd.DataFrame, base_power: float, base_name: str, path: Path,
                  thermal: str = "none"):
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
    ax.set_title(f"Sweep: {len(ok)}/{len(res)} points (thermal mode {thermal})")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, path)


def _axis_label(col: str) -> str:
    """Axis label with units from the column's description: "oil temperature [degC]"."""
    desc = {**PARAM_COLUMNS, **OPTIMIZE_COLUMNS}.get(col, col)
    return desc[:desc.index("]") + 1] if "]" in desc else col


def _param_names() -> set[str]:
    return set(PARAM_COLUMNS) | set(OPTIMIZE_COLUMNS)


def _empty_cells(grid: pd.DataFrame) -> str:
    """Which columns have empty cells (they keep the base case's value), or ""."""
    n = {c: int(grid[c].isna().sum()) for c in grid.columns if c != "label"}
    given = ", ".join(f"{c} {k}" for c, k in n.items() if k)
    return f"empty cells (the base case's value): {given}" if given else ""


def _base_line(case, thermal: str) -> tuple[float, str]:
    """The base case's loss under the mode [W] and where it was taken."""
    op = operating_temperature(case, thermal)
    where = (f"oil {op.oil_temp_C:.2f} degC from the balance with the sea at "
             f"{op.sea_temp_C:g} degC" if thermal == "full" else "its operating point")
    return op.mean_power_W, where


def run(args: argparse.Namespace) -> int:
    """``oilgap study sweep GRID.csv``: run a grid (resumable with --resume); returns the
    exit code. ``--out`` is checked and locked before anything is read or computed."""
    out = study_out(args, "sweep")
    with out_folder(args, out, resume=args.resume or args.retry_failed) as folder:
        return _sweep(args, out, folder)


def _sweep(args: argparse.Namespace, out: Path, folder: ResultFolder) -> int:
    """The sweep inside its locked result folder."""
    grid = read_grid_csv(args.grid)
    case = case_or_seed(args.case)
    cat = read_oils_csv(args.oils) if args.oils else None
    folder.begin()
    t0 = time.perf_counter()
    res = run_grid(grid, case, mode=args.mode, out_dir=out, workers=args.workers,
                   chunk_size=args.chunk_size, progress=args.progress, catalogue=cat,
                   retry_failed=args.retry_failed, thermal=args.thermal)
    dt = time.perf_counter() - t0
    thermal = res.attrs["thermal_mode"]
    why = ("the design NLP is isothermal so far" if args.mode == "optimize"
           and thermal == "none" and case.thermal is not None else None)
    header = thermal_description(case, thermal, res.attrs["thermal_default"], why)
    ok = res[res["status"] == "ok"]
    bad = res[res["status"] != "ok"]
    base_p, base_where = _base_line(case, thermal)
    fig = _sweep_figure(res, base_p, case.name, out / "sweep.png", thermal)
    lines = [f"# Sweep of {Path(args.grid).name} ({args.mode})", "",
             f"Thermal mode: {header}.", "",
             f"Groove exponent: gamma = {case.friction.gamma:g} ({case.gamma_source})"
             + ("; the grid's gamma column overrides it per row." if "gamma" in grid.columns
                else "."), "",
             *([_empty_cells(grid) + ".", ""] if _empty_cells(grid) else []),
             f"Base case: {case.name} ({base_p:.3f} W at {base_where}). "
             f"{len(res)} points: {len(ok)} ok, {len(bad)} failed; "
             f"{res.attrs.get('computed', len(res))} computed this run, "
             f"{res.attrs.get('reused', 0)} taken from {out}/points_{args.mode}.csv; "
             f"{dt:.2f} s."]
    if len(ok):
        best = ok.loc[ok["mean_power_W"].idxmin()]
        worst = ok.loc[ok["mean_power_W"].idxmax()]
        cols = [c for c in grid.columns] + ["mean_power_W"] + (
            ["oil_temp_op_C"] if thermal == "full" and "oil_temp_op_C" in ok.columns else [])
        lines += ["", "Lowest and highest mean power:", "",
                  markdown_table(pd.DataFrame([best[cols], worst[cols]]), 3)]
    if len(bad):
        lines += ["", f"First failure (row {bad.index[0]}): {bad['error'].iloc[0]}"]
    md = out / "summary.md"
    write_text(md, "\n".join(lines) + "\n")
    folder.complete()
    print(f"thermal     {header}")
    print(gamma_line(case))
    if _empty_cells(grid):
        print(_empty_cells(grid))
    print(f"{len(res)} points: {len(ok)} ok, {len(bad)} failed "
          f"({res.attrs.get('computed', len(res))} computed, {res.attrs.get('reused', 0)} "
          f"reused) in {dt:.2f} s")
    if len(ok):
        print(f"mean power {ok['mean_power_W'].min():.3f} .. {ok['mean_power_W'].max():.3f} W "
              f"(base case {base_p:.3f} W)")
    if len(bad):
        print(f"first failure (row {bad.index[0]}): {bad['error'].iloc[0]}", file=sys.stderr)
    print(f"wrote {out}/:\n" + file_list([out / "results.csv", out / f"points_{args.mode}.csv",
                                       fig, md]))
    return 0
