"""Grid engine speed: a 10,000-point evaluation grid and a 50-point Pareto sweep.

Side by side in one run:

* the 10,000-point evaluation grid (oil, oil temperature, depth, roughness T, gap)
  through :func:`oilgap.studies.grid.runner.run_grid` on 1 and on 2 worker processes,
  against the plain loop over the same points (``apply_params`` then
  :func:`oilgap.model.evaluation.mean_viscous_power`, one case at a time), with
  the largest relative difference; then the rerun with the same output folder
  (nothing recomputed). Target: under 10 s on 2 cores.
* the 50-point gap-loss Pareto sweep (:func:`oilgap.studies.pareto.gap_front`,
  one warm-started IPOPT solve per point) cold (first call, NLP built) and warm
  (median of 5), against the same 50 epsilon values solved cold (each from the
  case's own design, no warm start). Target: under 3 s.

Run: ``python benchmarks/bench_trade.py``
"""

from __future__ import annotations

import os
import sys
import tempfile
import time

import numpy as np
import pandas as pd

from oilgap.model.evaluation import mean_viscous_power
from oilgap.model.io.case_io import seed_case
from oilgap.model.units import MM_TO_M
from oilgap.optim.design import DesignProblem
from oilgap.studies.grid.optimize import clear_problems
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.grid.schema import apply_params
from oilgap.studies.pareto import gap_front
from oilgap.studies.settings import RunOptions

N_GRID = 10_000
N_FRONT = 50


def grid(n: int, seed: int = 0) -> pd.DataFrame:
    """A random grid over the operating envelope and the clearance geometry."""
    rng = np.random.default_rng(seed)
    return pd.DataFrame({"oil": rng.choice(["VG15", "VG22", "VG32", "VG46"], n),
                         "oil_temp_C": rng.uniform(0.0, 40.0, n),
                         "depth_m": rng.uniform(0.0, 7000.0, n),
                         "T": rng.uniform(1.0, 5.0, n), "gap_mm": rng.uniform(0.5, 2.0, n)})


def main() -> int:
    print(f"machine: {os.cpu_count()} logical cores")
    g = grid(N_GRID)
    base = seed_case()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        r1 = run_grid(g, base, options=RunOptions(workers=1, progress=False))
        rows.append(("engine, 1 process", time.perf_counter() - t0))
        t0 = time.perf_counter()
        run_grid(g, base, options=RunOptions(workers=2, progress=False))
        rows.append(("engine, 2 processes", time.perf_counter() - t0))
        t0 = time.perf_counter()
        r2 = run_grid(g, base, options=RunOptions(workers=2, progress=False), out_dir=tmp)
        t_two = time.perf_counter() - t0
        rows.append(("engine, 2 processes, writing points/results CSV", t_two))
        t0 = time.perf_counter()
        r3 = run_grid(g, base, options=RunOptions(workers=2, progress=False), out_dir=tmp)
        rows.append((f"rerun, same folder ({r3.attrs['computed']} recomputed)",
                     time.perf_counter() - t0))
    t0 = time.perf_counter()
    plain = np.array([mean_viscous_power(apply_params(base, r)) for r in g.to_dict("records")])
    t_plain = time.perf_counter() - t0
    rows.append(("plain loop: apply_params + mean_viscous_power", t_plain))
    diff = max(float(np.max(np.abs(r1["mean_power_W"] / plain - 1))),
               float(np.max(np.abs(r2["mean_power_W"] / plain - 1))))
    print(f"\n{N_GRID}-point evaluation grid ({(r2['status'] == 'ok').sum()} ok):")
    for name, t in rows:
        print(f"  {name:<55}{t:8.3f} s  ({t_plain / t:5.1f}x the plain loop)")
    print(f"  largest relative difference engine vs plain loop: {diff:.1e}")
    print(f"  target < 10 s on 2 cores: {'PASS' if t_two < 10.0 else 'FAIL'} ({t_two:.2f} s)")

    case = seed_case()
    clear_problems()
    t0 = time.perf_counter()
    front = gap_front(case, N_FRONT)
    t_cold = time.perf_counter() - t0
    warm = []
    for _ in range(5):
        t0 = time.perf_counter()
        gap_front(case, N_FRONT)
        warm.append(time.perf_counter() - t0)
    ok = front[front["status"] == "ok"]
    prob = DesignProblem(case)
    t0 = time.perf_counter()
    cold = [prob.solve(gap_max_m=e * MM_TO_M).optimal.mean_power_W for e in front["epsilon"]]
    t_nowarm = time.perf_counter() - t0
    agree = float(np.max(np.abs(np.array(cold) / ok["mean_power_W"].to_numpy() - 1)))
    print(f"\n{N_FRONT}-point Pareto sweep (gap vs loss), {len(ok)} solved:")
    print(f"  warm-started sweep, first call (builds the NLP)        {t_cold:8.3f} s")
    print(f"  warm-started sweep, median of {len(warm)}                        "
          f"{np.median(warm):8.3f} s  (median IPOPT solve "
          f"{1e3 * ok['solve_time_s'].median():.1f} ms, {ok['iterations'].median():.0f} "
          "iterations)")
    print(f"  same epsilons, each solved cold from the case's design {t_nowarm:8.3f} s  "
          f"(objectives agree to {agree:.1e} relative)")
    print(f"  target < 3 s: {'PASS' if t_cold < 3.0 else 'FAIL'} ({t_cold:.2f} s cold)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
