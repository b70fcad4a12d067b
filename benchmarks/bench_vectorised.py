"""The vectorised joint loss next to today's per-point engine, in one run (issue 21 item 4).

Markdown tables, in one process on this machine:

1. Engines side by side, per thermal mode (``none``, ``bulk``) and joint (the seed joint
   with ``[thermal]``, and the same with a 6809 deep-groove ball bearing), all eight
   uncertain inputs drawn at random per row:

   - *per point*: ``evaluate_case(apply_inputs(case, row), thermal=mode)`` per row, timed
     on ``--point-rows`` rows and extrapolated to 10^6;
   - *grid, per case*: the grid engine's evaluate chunk as before issue 21
     (``evaluate_chunk(..., columnar=False)``: a DesignCase per row, rows grouped by law),
     timed on ``--grid-rows`` rows (oil temperature or sea temperature, depth, gamma,
     scale and peak speed varied) and extrapolated;
   - *grid as on main*: the same rows through another installation's chunk
     (``--main-python``, e.g. the Python whose ``oilgap`` is main's checkout);
   - *grid, columnar*: the same rows through the columnar chunk path;
   - *vectorised*: :func:`~oilgap.model.uncertain.arrays.joint_loss_arrays` on 10^4, 10^5
     and 10^6 rows: wall time, rows per second, peak memory (tracemalloc).

2. A ``--sweep-rows`` evaluate sweep end to end (``oilgap study sweep`` in this process,
   writing its store), with where its time goes (cProfile, cumulative).

3. The vectorised loss against the scalar path on ``--check-rows`` random cases (the rows
   split over both joints and the ``--check-modes``, default the four thermal modes): the
   largest relative difference and the rows above 1e-12 (both paths solve the balance to
   its root, issue 27 item 5).

``--vectorised-only --modes none bulk --sweep-rows 0 --check-rows 0`` times only
:func:`joint_loss_arrays` (wall and CPU time, the load average at each start; the peak
memory with ``--memory``, whose tracing slows the run); ``--threads 2`` evaluates blocks
on both cores.

PASS/FAIL against the issue's 5 s (10^6 vectorised evaluations) and 10 s (the sweep).

    python benchmarks/bench_vectorised.py
"""

from __future__ import annotations

import argparse
import contextlib
import cProfile
import io
import os
import platform
import pstats
import subprocess
import sys
import tempfile
import time
import tracemalloc
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml
from oilgap.model.joint_loss import operating_temperature
from oilgap.model.uncertain.arrays import joint_loss_arrays
from oilgap.model.uncertain.inputs import apply_inputs
from oilgap.studies.grid.evaluate import evaluate_chunk

HERE = Path(__file__).resolve().parent
SEED_THERMAL = HERE.parent / "tests" / "golden" / "data" / "seed_thermal.toml"
MILLION = 1_000_000


def cases() -> dict:
    """The seed joint with [thermal] (R 0.5 K/W), and the same with a 6809 bearing."""
    text = SEED_THERMAL.read_text()
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "bearing.toml"
        p.write_text(text + '\n[bearing]\ndesignation = "6809"\n')
        return {"seed": read_case_toml(SEED_THERMAL), "seed + 6809 bearing": read_case_toml(p)}


def inputs(n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """All eight uncertain inputs, uniform around the seed's values."""
    rng = np.random.default_rng(seed)
    return {"nu40_factor": rng.uniform(0.9, 1.1, n), "oil_temp_C": rng.uniform(0.0, 6.0, n),
            "depth_m": rng.uniform(2000.0, 4000.0, n), "gamma": rng.uniform(0.48, 0.65, n),
            "friction_scale": rng.uniform(0.9, 1.1, n), "film_strength": rng.uniform(0, 1, n),
            "bearing_drag_scale": rng.uniform(0.5, 2.0, n),
            "peak_speed_rpm": rng.uniform(2500.0, 3500.0, n)}


def grid_rows(n: int, mode: str, seed: int = 0) -> list[dict]:
    """Grid rows of the columns both grid paths take."""
    x = inputs(n, seed)
    key = "sea_temp_C" if mode in ("bulk", "full") else "oil_temp_C"
    return [{key: float(x["oil_temp_C"][i]), "depth_m": float(x["depth_m"][i]),
             "gamma": float(x["gamma"][i]), "scale": float(x["friction_scale"][i]),
             "peak_speed_rpm": float(x["peak_speed_rpm"][i])} for i in range(n)]


def per_point_s(case, mode: str, n: int) -> float:
    """Seconds per row of evaluate_case on apply_inputs (today's per-point engine)."""
    x = inputs(n, 1)
    t0 = time.perf_counter()
    for i in range(n):
        evaluate_case(apply_inputs(case, {k: float(v[i]) for k, v in x.items()}), thermal=mode)
    return (time.perf_counter() - t0) / n


def grid_s(case, mode: str, n: int, columnar: bool) -> float:
    """Seconds per row of the grid engine's evaluate chunk."""
    rows = grid_rows(n, mode, 2)
    t0 = time.perf_counter()
    recs = evaluate_chunk(case, rows, None, mode, columnar=columnar)
    assert all(r["status"] == "ok" for r in recs)
    return (time.perf_counter() - t0) / n


MAIN_SNIPPET = """
import sys, time, warnings
import numpy as np
from oilgap.model.io.case_io import read_case_toml
from oilgap.studies.grid.evaluate import evaluate_chunk
warnings.simplefilter("ignore")
case, mode, n = read_case_toml(sys.argv[1]), sys.argv[2], int(sys.argv[3])
rng = np.random.default_rng(2)
x = [rng.uniform(0.9, 1.1, n), rng.uniform(0.0, 6.0, n), rng.uniform(2000.0, 4000.0, n),
     rng.uniform(0.48, 0.65, n), rng.uniform(0.9, 1.1, n)]
key = "sea_temp_C" if mode in ("bulk", "full") else "oil_temp_C"
rows = [{key: float(x[1][i]), "depth_m": float(x[2][i]), "gamma": float(x[3][i]),
         "scale": float(x[4][i]), "peak_speed_rpm": float(rng.uniform(2500.0, 3500.0))}
        for i in range(n)]
t0 = time.perf_counter()
recs = evaluate_chunk(case, rows, None, mode)
assert all(r["status"] == "ok" for r in recs)
print((time.perf_counter() - t0) / n)
"""
"""The grid chunk timed by another installation of oilgap (``--main-python``: main's)."""


def main_grid_s(python: str, case, mode: str, n: int) -> float:
    """Seconds per row of another installation's grid evaluate chunk (main's engine)."""
    from oilgap.studies.io.case_write import write_case_toml

    with tempfile.TemporaryDirectory() as d:
        p = write_case_toml(case, Path(d) / "case.toml")
        out = subprocess.run([python, "-c", MAIN_SNIPPET, str(p), mode, str(n)], check=True,
                             capture_output=True, text=True, cwd=d)
    return float(out.stdout.split()[-1])


def vectorised(case, mode: str, n: int, threads: int, memory: bool = False
               ) -> tuple[float, float, float, float]:
    """(wall [s], CPU [s], load average at the start, peak traced memory [MB] or NaN) of
    joint_loss_arrays on n rows."""
    x = inputs(n, 3)
    load = os.getloadavg()[0]
    t0, c0 = time.perf_counter(), time.process_time()
    p = joint_loss_arrays(case, x, mode, threads=threads)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    assert np.isfinite(p).all()
    peak = float("nan")
    if memory:
        tracemalloc.start()
        joint_loss_arrays(case, x, mode, threads=threads)
        peak = tracemalloc.get_traced_memory()[1] / 2**20
        tracemalloc.stop()
    return wall, cpu, load, peak


def engines(a) -> pd.DataFrame:
    rows = []
    for name, case in cases().items():
        for mode in a.modes:
            if a.vectorised_only:
                rows.append(vectorised_row(a, name, case, mode))
                continue
            point = per_point_s(case, mode, a.point_rows)
            old = grid_s(case, mode, a.grid_rows, columnar=False)
            col = grid_s(case, mode, a.grid_rows, columnar=True)
            if a.main_python:
                main_s = main_grid_s(a.main_python, case, mode, a.grid_rows)
                print(f"{name}, {mode}: main's grid {main_s * MILLION:.4g} s per 10^6",
                      file=sys.stderr, flush=True)
            row = {"joint": name, "mode": mode,
                   "per point 10^6 [s] (extrap.)": point * MILLION,
                   "grid as on main 10^6 [s] (extrap.)": main_s * MILLION if a.main_python
                   else float("nan"),
                   "grid per case 10^6 [s] (extrap.)": old * MILLION,
                   "grid columnar 10^6 [s] (extrap.)": col * MILLION}
            row.update(vectorised_row(a, name, case, mode))
            rows.append(row)
    return pd.DataFrame(rows)


def vectorised_row(a, name: str, case, mode: str) -> dict:
    """The vectorised columns of a joint and mode."""
    row = {"joint": name, "mode": mode, "threads": a.threads}
    for n in a.rows:
        wall, cpu, load, peak = vectorised(case, mode, n, a.threads, a.memory)
        row[f"vectorised {n:.0e} [s]"] = wall
        row[f"CPU {n:.0e} [s]"] = cpu
        row[f"load {n:.0e}"] = load
        if a.memory:
            row[f"peak MB {n:.0e}"] = peak
    if MILLION in a.rows:
        row["10^6 <= 5 s"] = "PASS" if row["vectorised 1e+06 [s]"] <= 5 else "FAIL"
    print(f"{name}, {mode}: {row}", file=sys.stderr, flush=True)
    return row


def sweep(n: int) -> tuple[float, str]:
    """Wall time [s] of an n-row evaluate sweep on the command line (store written), and
    its profile's main entries."""
    from oilgap.cli import main

    rng = np.random.default_rng(4)
    grid = pd.DataFrame({"oil_temp_C": np.round(rng.uniform(0, 10, n), 6),
                         "depth_m": np.round(rng.uniform(0, 6000, n), 3),
                         "gamma": np.round(rng.uniform(0.5, 0.6, n), 6),
                         "peak_speed_rpm": np.round(rng.uniform(2500, 3500, n), 3)})
    with tempfile.TemporaryDirectory() as d:
        g = Path(d) / "grid.csv"
        grid.to_csv(g, index=False)
        prof = cProfile.Profile()
        t0 = time.perf_counter()
        with contextlib.redirect_stdout(io.StringIO()):
            prof.enable()
            code = main(["study", "sweep", str(g), "--out", str(Path(d) / "out"),
                         "--workers", "1", "--no-progress"])
            prof.disable()
        wall = time.perf_counter() - t0
        assert code == 0
    buf = io.StringIO()
    pstats.Stats(prof, stream=buf).sort_stats("cumulative").print_stats(
        r"grid/(runner|store|evaluate|columnar)\.py|_results_sweep|files\.py:.*atomic", 14)
    return wall, buf.getvalue()


def accuracy(n: int, modes=("none", "bulk", "film", "full")) -> pd.DataFrame:
    """Largest |vectorised / scalar - 1| over n random cases (both joints, the modes); the
    vectorised rows are the first of a call of at least 20,000 rows (a balance run of that
    size starts its blocks from one pilot's predictor, as 10^6 rows do)."""
    out = []
    per = max(1, n // (2 * len(modes)))
    for name, case in cases().items():
        for k, mode in enumerate(modes):
            x = inputs(max(per, 20_000), 10 + k)
            got = joint_loss_arrays(case, x, mode)[:per]
            x = {key: v[:per] for key, v in x.items()}
            want = np.array([operating_temperature(apply_inputs(
                case, {key: float(v[i]) for key, v in x.items()}), mode).mean_power_W
                for i in range(per)])
            rel = np.abs(got / want - 1.0)
            out.append({"joint": name, "mode": mode, "rows": per,
                        "max rel. difference": float(rel.max()),
                        "rows above 1e-12": int((rel > 1e-12).sum())})
            print(f"{name}, {mode}: {out[-1]}", file=sys.stderr, flush=True)
    return pd.DataFrame(out)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", type=int, nargs="+", default=[10_000, 100_000, MILLION])
    ap.add_argument("--point-rows", type=int, default=500)
    ap.add_argument("--grid-rows", type=int, default=2000)
    ap.add_argument("--sweep-rows", type=int, default=MILLION)
    ap.add_argument("--check-rows", type=int, default=10_000)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--check-modes", nargs="+", default=["none", "bulk", "film", "full"])
    ap.add_argument("--memory", action="store_true",
                    help="also the peak traced memory (a second, traced run)")
    ap.add_argument("--modes", nargs="+", default=["none", "bulk"])
    ap.add_argument("--vectorised-only", action="store_true",
                    help="time joint_loss_arrays only (no per-point or grid engine)")
    ap.add_argument("--main-python", default=None, help="a Python whose oilgap is main's "
                    "(before issue 21): its grid evaluate chunk is timed too")
    a = ap.parse_args()
    warnings.simplefilter("ignore")
    load0 = os.getloadavg()
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, numpy "
          f"{np.__version__}, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, load "
          f"average {load0[0]:.2f} at the start; threads {a.threads}\n")
    print(f"**Engines** (per point: {a.point_rows} rows, grid: {a.grid_rows} rows, both "
          "extrapolated to 10^6)\n")
    t = engines(a)
    print("\n" + t.to_markdown(index=False, floatfmt=".4g"))
    if a.sweep_rows:
        wall, prof = sweep(a.sweep_rows)
        verdict = "PASS" if wall <= 10 else "FAIL"
        print(f"\n**Evaluate sweep of {a.sweep_rows} rows end to end**: {wall:.1f} s "
              f"({a.sweep_rows / wall:.0f} rows/s; <= 10 s: {verdict}; load average "
              f"{os.getloadavg()[0]:.2f})\n\n```\n{prof.strip()}\n```")
    if a.check_rows:
        acc = accuracy(a.check_rows, tuple(a.check_modes))
        print(f"\n**Vectorised against the scalar path, {len(acc) * acc['rows'].iloc[0]} "
              f"random cases**: max relative difference "
              f"{acc['max rel. difference'].max():.2e}"
              "\n\n" + acc.to_markdown(index=False, floatfmt=".3g"))
    print(f"\nload average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
