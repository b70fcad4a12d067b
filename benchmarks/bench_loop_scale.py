"""Scale of the measured-data loop: few long runs against many short runs, 10^6 samples each.

Targets (issues 9 and 20): 1,000,000 samples end to end (read, validate, fit,
report without figures) in <= 30 s and <= 2 GB peak memory on 2 cores, whether
they come as 10 long runs or as 100 runs of 10,000 samples (a qualification
campaign), the number of cross-validation folds bounded (grouped 10-fold above
10 oil runs, :mod:`oilgap.optim.calibration.folds`). Issue 26: a campaign's shape,
670 runs of 1,500 samples (1,005,000), end to end *with* the report's figures (above 24
runs a summary: the 12 worst runs, the residuals, a grid of small multiples) in <= 60 s.

A shape ``RxM`` is R runs of M samples. The data are the synthetic rig's
experiment (2 oil-free + 8 oil runs of 300 s, ``3000 rpm sin(0.1 pi t)``, four
ISO VG oils, T = 4 and 2), logged every 300 s / M (so the Savitzky-Golay windows,
1 s and 3 s, grow with the rate), repeated R / 10 times with measurement noise of
seeds 0, 1, ... (runs renamed ``<run>_c<seed>``; R = 10 is the rig's experiment
itself). Each shape is written to CSV (not timed) and run in a fresh Python
process of its own, so its peak resident memory (``VmHWM``) is its own: imports,
``load_measured`` (pyarrow), ``LoopEstimator().fit``, ``loop.json`` +
``report.md``. Printed side by side: wall time of the whole process (imports
included) and of the loop alone, the process's CPU time (user + system: what a
loaded, shared machine inflates least), peak RSS, the folds used, what the loop found,
its held-out RMSE before and after, and PASS/FAIL against the targets (10^6
samples only); the load average before and after (the machine may be shared).

    python benchmarks/bench_loop_scale.py   # 10x100000, 100x10000, 670x1500; clean, thermal_lag
    python benchmarks/bench_loop_scale.py --shapes 670x1500 --effects none   # the campaign alone
    python benchmarks/bench_loop_scale.py --shapes 10x1000,10x10000 --effects none
    python benchmarks/bench_loop_scale.py --sizes 10000,100000,1000000   # 10 runs each
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TARGET_S = 30.0
TARGET_MB = 2048.0
TARGET_SAMPLES = 10 ** 6
CAMPAIGN_RUNS = 100
"""Shapes of more runs than this draw the report's figures (a summary) and are held to
:data:`TARGET_FIGURES_S`; the others are timed without figures, against :data:`TARGET_S`."""
TARGET_FIGURES_S = 60.0
RUN_S = 300.0
"""Duration of each synthetic run [s] (the rig's 1500 samples x 0.2 s)."""
RIG_RUNS = 10
"""Runs of one synthetic experiment (2 oil-free + 8 oil runs)."""


def peak_rss_mb() -> float:
    """Peak resident set size of this process [MB] (VmHWM; getrusage where /proc lacks it)."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def load_average() -> str:
    """The 1, 5 and 15 min load averages, or "n/a"."""
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "n/a"


def child(csv: str, out: str, figures: str = "none") -> None:
    """One shape, in its own process: the loop from the file to the report, timed
    (``figures``: what the report draws, ``"none"`` or ``"summary"``)."""
    t0 = time.perf_counter()
    from oilgap.model.measured.data import load_measured
    from oilgap.optim.calibration import LoopEstimator
    from oilgap.studies.loop.report import write_report
    t1 = time.perf_counter()
    data = load_measured(csv)
    t2 = time.perf_counter()
    est = LoopEstimator().fit(data)
    t3 = time.perf_counter()
    write_report(est, out, figures=figures)
    t4 = time.perf_counter()
    cv = est.cv_scheme_
    print(json.dumps({"rows": data.n_read, "import_s": t1 - t0, "read_s": t2 - t1,
                      "fit_s": t3 - t2, "report_s": t4 - t3, "loop_s": t4 - t1,
                      "peak_mb": peak_rss_mb(), "folds": cv["folds"], "groups": cv["groups"],
                      "scheme": cv["scheme"], "figures": figures,
                      "effects": [e.name for e in est.effects_] or ["none"],
                      "heldout": est.heldout_rmse_}))


def make_data(runs: int, per_run: int, effect: str | None, path: Path) -> Path:
    """``runs`` synthetic runs of ``per_run`` samples (``runs / 10`` rig experiments), as CSV."""
    import pandas as pd

    from oilgap.studies.reporting import write_data_csv
    from oilgap.studies.rigs.synth import SynthConfig, synthesize
    cfg = SynthConfig(n_samples=per_run, sample_interval_s=RUN_S / per_run, effect=effect)
    if runs == RIG_RUNS:
        return write_data_csv(synthesize(cfg, seed=0), path)
    frames = []
    for seed in range(runs // RIG_RUNS):
        df = synthesize(cfg, seed=seed)
        df["run"] = df["run"].astype(str) + f"_c{seed:02d}"
        frames.append(df)
    return write_data_csv(pd.concat(frames, ignore_index=True), path)


def run_shape(runs: int, per_run: int, effect: str | None, tmp: Path,
              figures: str = "auto") -> dict:
    """Write the data, run the loop in a child process, return its record (``figures``
    "auto": the report's summary above :data:`CAMPAIGN_RUNS` runs, none below)."""
    csv = make_data(runs, per_run, effect, tmp / f"data_{runs}x{per_run}.csv")
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    if figures == "auto":
        figures = "summary" if runs > CAMPAIGN_RUNS else "none"
    r = subprocess.run([sys.executable, __file__, "--child", str(csv),
                        str(tmp / f"out_{runs}x{per_run}"), figures],
                       capture_output=True, text=True, check=True)
    wall = time.perf_counter() - t0
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (ru1.ru_utime - ru0.ru_utime) + (ru1.ru_stime - ru0.ru_stime)
    res = json.loads(r.stdout.strip().splitlines()[-1])
    csv.unlink()
    return {**res, "wall_s": wall, "cpu_s": cpu}


def parse_shapes(shapes: str | None, sizes: str | None) -> list[tuple[int, int]]:
    """(runs, samples per run) of ``--shapes RxM,...`` and of ``--sizes N,...`` (10 runs)."""
    out = []
    for s in (shapes or "").split(","):
        if s.strip():
            r, m = (int(x) for x in s.lower().split("x"))
            if r % RIG_RUNS or r < RIG_RUNS:
                raise SystemExit(f"--shapes {s}: runs must be a multiple of {RIG_RUNS}")
            out.append((r, m))
    for n in (sizes or "").split(","):
        if n.strip():
            out.append((RIG_RUNS, int(n) // RIG_RUNS))
    return out


def verdict(r: dict) -> str:
    """PASS/FAIL against the time and memory targets (only at 10^6 samples; with the
    figures, the campaign's 60 s)."""
    if r["rows"] < TARGET_SAMPLES:
        return "-"
    target = TARGET_FIGURES_S if r.get("figures", "none") != "none" else TARGET_S
    return "PASS" if r["wall_s"] <= target and r["peak_mb"] <= TARGET_MB else "FAIL"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--shapes", default=None,
                    help="comma-separated RUNSxSAMPLES_PER_RUN (default 10x100000,100x10000)")
    ap.add_argument("--sizes", default=None, help="comma-separated total samples, 10 runs each")
    ap.add_argument("--effects", default="none,thermal_lag",
                    help="comma-separated: none (clean) and/or library effects")
    ap.add_argument("--figures", choices=("auto", "none", "summary", "all"), default="auto",
                    help="the report's figures: auto (summary above 100 runs, else none), "
                    "or as given (all: every run's pages, as before issue 26)")
    ap.add_argument("--child", nargs=3, metavar=("CSV", "OUT", "FIGURES"),
                    help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(*args.child)
        return
    shapes = parse_shapes(args.shapes if args.shapes or args.sizes
                          else "10x100000,100x10000,670x1500",
                          args.sizes)
    effects = [None if e == "none" else e for e in args.effects.split(",")]
    print(f"oilgap loop scale benchmark, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}: "
          f"{os.cpu_count()} CPUs visible; target {TARGET_S:g} s and {TARGET_MB:g} MB at 10^6 "
          f"samples; one process per shape; load average before {load_average()}")
    print(f"{'data':<12}{'runs':>5}{'x samples':>10}{'total':>9}{'folds':>6}{'wall s':>8}"
          f"{'cpu s':>7}{'loop s':>8}{'read s':>7}{'fit s':>7}{'peak MB':>8}  "
          f"{'held-out W before -> after':<27}{'found':<14}{'figures':<9}verdict")
    verdicts = []
    with tempfile.TemporaryDirectory() as d:
        for effect in effects:
            for runs, per_run in shapes:
                r = run_shape(runs, per_run, effect, Path(d), args.figures)
                h, v = r["heldout"], verdict(r)
                folds = f"{r['folds']}" + ("" if r["scheme"] == "grouped k-fold" else "*")
                print(f"{effect or 'clean':<12}{runs:>5}{per_run:>10}{r['rows']:>9}{folds:>6}"
                      f"{r['wall_s']:>8.2f}{r['cpu_s']:>7.1f}{r['loop_s']:>8.2f}"
                      f"{r['read_s']:>7.2f}"
                      f"{r['fit_s']:>7.2f}{r['peak_mb']:>8.0f}  "
                      f"{h['before']:>8.3f} -> {h['after']:<15.3f}"
                      f"{','.join(r['effects']):<14}{r['figures']:<9}{v}", flush=True)
                if v != "-":
                    verdicts.append(v == "PASS")
    print(f"folds: grouped 10-fold over the oil runs; * one fold per oil run (leave-one-run-out, "
          f"10 oil runs or fewer); load average after {load_average()}")
    if verdicts:
        print(f"10^6 samples: {sum(verdicts)} of {len(verdicts)} runs meet the {TARGET_S:g} s / "
              f"{TARGET_MB:g} MB target ({TARGET_FIGURES_S:g} s with the report's figures, "
              "more than 100 runs; wall time of the whole process, imports included)")


if __name__ == "__main__":
    main()
