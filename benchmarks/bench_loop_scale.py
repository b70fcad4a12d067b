"""Scale of the measured-data loop: 10^4, 10^5 and 10^6 samples end to end.

Target (issue 9): 1,000,000 samples end to end (read, validate, fit, report
without figures) in <= 30 s and <= 2 GB peak memory on 2 cores, the time
growing at most linearly with the samples.

The data are the synthetic rig's experiment (2 oil-free + 8 oil runs of 300 s,
``3000 rpm sin(0.1 pi t)``, four ISO VG oils, T = 4 and 2), logged at the rate
that gives N samples in all: 0.3 s for 10^4, 30 ms for 10^5, 3 ms for 10^6 (so
the Savitzky-Golay windows, 1 s and 3 s, grow with the rate). Each size is
written to CSV (not timed) and run in a fresh Python process of its own, so
its peak resident memory (``VmHWM``) is its own: imports, ``load_measured``
(pyarrow), ``LoopEstimator().fit``, ``loop.json`` + ``report.md``. Printed side
by side: wall time of the whole process (imports included) and of the loop
alone, peak RSS, microseconds per sample, what the loop found and its held-out
RMSE before and after.

    python benchmarks/bench_loop_scale.py                       # clean and thermal_lag
    python benchmarks/bench_loop_scale.py --sizes 10000,100000 --effects none
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
RUN_S = 300.0
"""Duration of each synthetic run [s] (the rig's 1500 samples x 0.2 s)."""
RUNS = 10


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


def child(csv: str, out: str) -> None:
    """One size, in its own process: the loop from the file to the report, timed."""
    t0 = time.perf_counter()
    from oilgap.model.measured.data import load_measured
    from oilgap.optim.calibration import LoopEstimator
    from oilgap.studies.loop.report import write_report
    t1 = time.perf_counter()
    data = load_measured(csv)
    t2 = time.perf_counter()
    est = LoopEstimator().fit(data)
    t3 = time.perf_counter()
    write_report(est, out, figures=False)
    t4 = time.perf_counter()
    print(json.dumps({"rows": data.n_read, "import_s": t1 - t0, "read_s": t2 - t1,
                      "fit_s": t3 - t2, "report_s": t4 - t3, "loop_s": t4 - t1,
                      "peak_mb": peak_rss_mb(),
                      "effects": [e.name for e in est.effects_] or ["none"],
                      "heldout": est.heldout_rmse_}))


def make_data(n: int, effect: str | None, path: Path) -> Path:
    """The synthetic rig's experiment with ``n`` samples in all, as CSV."""
    from oilgap.studies.reporting import write_data_csv
    from oilgap.studies.rigs.synth import SynthConfig, synthesize
    per_run = n // RUNS
    cfg = SynthConfig(n_samples=per_run, sample_interval_s=RUN_S / per_run, effect=effect)
    return write_data_csv(synthesize(cfg, seed=0), path)


def run_size(n: int, effect: str | None, tmp: Path) -> dict:
    csv = make_data(n, effect, tmp / f"data_{n}.csv")
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, __file__, "--child", str(csv), str(tmp / f"out_{n}")],
                       capture_output=True, text=True, check=True)
    wall = time.perf_counter() - t0
    res = json.loads(r.stdout.strip().splitlines()[-1])
    csv.unlink()
    return {**res, "wall_s": wall}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="10000,100000,1000000")
    ap.add_argument("--effects", default="none,thermal_lag",
                    help="comma-separated: none (clean) and/or library effects")
    ap.add_argument("--child", nargs=2, metavar=("CSV", "OUT"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(*args.child)
        return
    sizes = [int(x) for x in args.sizes.split(",")]
    effects = [None if e == "none" else e for e in args.effects.split(",")]
    print(f"oilgap loop scale benchmark: {os.cpu_count()} CPUs visible; target {TARGET_S:g} s "
          f"and {TARGET_MB:g} MB at 10^6 samples; one process per size")
    print(f"{'data':<13}{'samples':>9}{'dt ms':>7}{'wall s':>8}{'loop s':>8}{'read s':>8}"
          f"{'fit s':>7}{'us/sample':>10}{'peak MB':>9}  {'held-out W before -> after':<27}found")
    verdict = []
    with tempfile.TemporaryDirectory() as d:
        for effect in effects:
            for n in sizes:
                r = run_size(n, effect, Path(d))
                h = r["heldout"]
                dt_ms = 1e3 * RUN_S / (n // RUNS)
                print(f"{effect or 'clean':<13}{r['rows']:>9}{dt_ms:>7.3g}{r['wall_s']:>8.2f}"
                      f"{r['loop_s']:>8.2f}{r['read_s']:>8.2f}{r['fit_s']:>7.2f}"
                      f"{1e6 * r['loop_s'] / r['rows']:>10.1f}{r['peak_mb']:>9.0f}  "
                      f"{h['before']:>8.3f} -> {h['after']:<15.3f}{','.join(r['effects'])}",
                      flush=True)
                if n == 10 ** 6:
                    verdict.append(r["wall_s"] <= TARGET_S and r["peak_mb"] <= TARGET_MB)
    if verdict:
        print(f"10^6 samples: {'meets' if all(verdict) else 'MISSES'} the {TARGET_S:g} s / "
              f"{TARGET_MB:g} MB target (wall time of the whole process, imports included)")


if __name__ == "__main__":
    main()
