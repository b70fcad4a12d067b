"""A large optimize sweep on the local process pool and on a Dask LocalCluster.

One run, two Markdown tables:

1. Backends: the same grid (``--points`` rows of oil temperature and depth, the seed
   case, thermal mode ``none``) on the process pool and on a LocalCluster of the same
   ``--workers``: points per second, chunks, and the overhead per task: the run's wall
   time x workers minus the time the chunks took on their workers, per chunk (start-up
   of the pool or cluster, transfer, scheduling and the idle tail included); then the
   same without the start-up (``startup_s``: the runner's wait for the backend: the
   LocalCluster's processes started; a process pool starts its processes at the first
   task, so its start-up stays in the overhead).
2. Per point, in this process (``--lean-points`` rows, one warm-started chain of 50 rows
   after another, as a worker runs them): the chunk loop's wall time per point and the
   sweep's solve per point (``solve_time_s``) next to the IPOPT call the solve makes (the
   wall time of CasADi's buffered call: IPOPT and nothing else; mean and median). A
   calibration row gives, for the seed NLP, that call's wall time over CasADi's own
   ``t_wall_total`` of the same solve through the ordinary call (``record_time``).

    python benchmarks/bench_sweep_scale.py --points 100000 --workers 2
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import casadi as ca
import numpy as np
import pandas as pd

from oilgap.model.io.case_io import seed_case
from oilgap.optim.design import lean
from oilgap.optim.design.variables import to_nlp
from oilgap.studies.grid import optimize as grid_optimize
from oilgap.studies.grid import runner
from oilgap.studies.settings import RunOptions, SweepSettings

CHAIN = 50


def grid(n: int) -> pd.DataFrame:
    """``n`` rows: oil temperature 0-40 degC (slow) by depth 0-6000 m (fast)."""
    depths = np.linspace(0.0, 6000.0, 50)
    temps = np.linspace(0.0, 40.0, max(1, -(-n // len(depths))))
    t, d = np.meshgrid(temps, depths, indexing="ij")
    return pd.DataFrame({"oil_temp_C": t.ravel()[:n], "depth_m": d.ravel()[:n]})


def backend_run(g: pd.DataFrame, workers: int, scheduler: str | None) -> dict:
    """Points per second and overhead per task of one run."""
    t0 = time.perf_counter()
    res = runner.run_grid(g, None, SweepSettings(mode="optimize", thermal="none"),
                          RunOptions(workers=workers, progress=False, scheduler=scheduler))
    wall = time.perf_counter() - t0
    chunks, busy, start = (res.attrs[k] for k in ("chunks", "worker_s", "backend_start_s"))
    return {"backend": res.attrs["backend"], "points": len(res),
            "ok": int((res["status"] == "ok").sum()), "wall_s": wall,
            "points_per_s": len(res) / wall, "chunks": chunks,
            "worker_busy_s": busy, "startup_s": start,
            "overhead_per_task_ms": 1e3 * (wall * workers - busy) / max(chunks, 1),
            "without_startup_ms": 1e3 * ((wall - start) * workers - busy) / max(chunks, 1)}


def per_point(n: int) -> dict:
    """Per-point cost of the sweep (one process) and of its IPOPT calls alone [ms]."""
    rows = grid(n).to_dict("records")
    base = seed_case()
    grid_optimize.optimize_chunk(base, rows[:3], None)  # the NLP built, solvers warm
    _, prob = grid_optimize.design_problem(base)
    solver = lean.lean_solver(prob)
    solver.timings = []
    t0 = time.perf_counter()
    recs = grid_optimize.optimize_chunk(base, rows, None, chain=CHAIN)
    loop = (time.perf_counter() - t0) / n
    solver.timings, ipopt = None, np.asarray(solver.timings)
    solve = np.asarray([r["solve_time_s"] for r in recs if r["status"] == "ok"])
    return {"points": n, "ok": len(solve), "ipopt_calls": len(ipopt),
            "loop_mean": 1e3 * loop, "solve_mean": 1e3 * solve.mean(),
            "solve_median": 1e3 * np.median(solve), "ipopt_mean": 1e3 * ipopt.sum() / n,
            "ipopt_median": 1e3 * np.median(ipopt)}


def calibration(k: int = 200) -> float:
    """Median over ``k`` solves of the seed NLP of (buffered call's wall time) /
    (CasADi's ``t_wall_total`` of the ordinary call), the two interleaved."""
    prob = grid_optimize.design_problem(seed_case())[1]
    q = prob.parameters()
    timed = prob.session.with_options(record_time=True).solver()
    lbg, ubg = prob.constraint_bounds(q)
    args = {"x0": to_nlp(prob.x_case_m), "p": [q.nu_m2_s, q.rho_kg_m3],
            "lbx": to_nlp(np.asarray(q.lower_m)), "ubx": to_nlp(np.asarray(q.upper_m)),
            "lbg": lbg, "ubg": ubg}
    solver = lean.lean_solver(prob)
    solver.timings = []
    ratios = []
    for _ in range(k):
        solver.ipopt(q, prob.x_case_m, None)
        timed(**args)
        ratios.append(solver.timings[-1] / timed.stats()["t_wall_total"])
    solver.timings = None
    return float(np.median(ratios))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--lean-points", type=int, default=2000)
    a = ap.parse_args()
    load0 = os.getloadavg()
    g = grid(a.points)
    rows = [backend_run(g, a.workers, None), backend_run(g, a.workers, "local")]
    c = per_point(a.lean_points)
    cal = calibration()
    load1 = os.getloadavg()
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, load "
          f"average {load0[0]:.2f} before, {load1[0]:.2f} after; casadi {ca.__version__}\n")
    print(f"**{a.points} optimize points, {a.workers} workers**\n")
    print(pd.DataFrame(rows).to_markdown(index=False, floatfmt=".4g"))
    print(f"\n**Per point, one process, {c['points']} points ({c['ok']} solved, "
          f"{c['ipopt_calls']} IPOPT calls)** [ms]\n")
    def f(v: float | None) -> str:
        return "-" if v is None else f"{v:.3g}"

    table = pd.DataFrame([
        {"": "mean", "IPOPT call": f(c["ipopt_mean"]), "sweep solve": f(c["solve_mean"]),
         "chunk loop": f(c["loop_mean"]), "solve / IPOPT": f(c["solve_mean"] / c["ipopt_mean"]),
         "loop / IPOPT": f(c["loop_mean"] / c["ipopt_mean"])},
        {"": "median", "IPOPT call": f(c["ipopt_median"]), "sweep solve": f(c["solve_median"]),
         "chunk loop": "-", "solve / IPOPT": f(c["solve_median"] / c["ipopt_median"]),
         "loop / IPOPT": "-"}])
    print(table.to_markdown(index=False, disable_numparse=True,
                            colalign=("left",) + ("right",) * 5))
    print(f"\nIPOPT call (buffered) / CasADi t_wall_total of the same solve: {cal:.3f} "
          "(median, seed NLP)")


if __name__ == "__main__":
    main()
