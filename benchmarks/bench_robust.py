"""Benchmark of the robust design NLP (issue 21 item 4): its solve time against the nominal.

Run: ``python benchmarks/bench_robust.py [--repeats N] [--temp-c X]``

On the seed joint (at its oil temperature, or ``--temp-c``), with N scenarios of the
case's uncertain inputs (``case_uncertainty(case).sample(N, seed=0)``: ISO 3448's band on
nu40 and gamma's seed-fit spread), the statistic p95 (the CVaR epigraph: N + 1 extra
variables and N extra rows), for N = 16, 32, 64:

* build: ``RobustDesignProblem(problem, scenarios, "p95")`` (scenarios resolved through
  ``apply_inputs``, one scenario's SX loss mapped over N, the IPOPT instance);
* solve: ``RobustDesignProblem.solve`` from the case's own design (the nominal solve's
  start too: like for like) and from the nominal optimum (the CLI's warm start), one
  start each; whole public calls timed;
* the nominal NLP: ``DesignProblem.solve_isothermal`` from the case's design.

Calls are interleaved in rounds (nominal, then each N) so that the machine's load hits all
alike; medians of wall and CPU time (this process's: on a shared machine the wall time of a
call of 100 ms includes other processes' time slices, that of a 3 ms call mostly not, so
the CPU ratio is the like-for-like one). Target: the robust NLP with N = 64 solves in <= 20x
the nominal NLP's time. Prints a Markdown table with the date and the load average.
"""

from __future__ import annotations

import argparse
import datetime as dt
import os
import time
from dataclasses import replace

import numpy as np

from oilgap.model.case import OperatingPoint
from oilgap.model.io.case_io import seed_case
from oilgap.model.uncertain import case_uncertainty
from oilgap.optim.design import DesignProblem
from oilgap.optim.design.robust import RobustDesignProblem

SIZES = (16, 32, 64)
TARGET_RATIO = 20.0


def timed(f):
    """(wall, CPU of this process, result) [s]."""
    t, c = time.perf_counter(), time.process_time()
    out = f()
    return time.perf_counter() - t, time.process_time() - c, out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=15)
    ap.add_argument("--temp-c", type=float, default=None)
    args = ap.parse_args()
    case = seed_case()
    if args.temp_c is not None:
        case = replace(case, operating=OperatingPoint(case.operating.depth_m, args.temp_c))
    load0 = os.getloadavg()
    prob = DesignProblem(case)
    nominal = prob.solve_isothermal()
    spec = case_uncertainty(case)
    builds, problems = {}, {}
    for n in SIZES:
        w, c, rp = timed(lambda n=n: RobustDesignProblem(prob, spec.sample(n, 0), "p95"))
        builds[n], problems[n] = (w, c), rp
    t_nom, t_cold, t_warm, its = [], {n: [] for n in SIZES}, {n: [] for n in SIZES}, {}
    for _ in range(args.repeats):
        t_nom.append(timed(prob.solve_isothermal)[:2])
        for n in SIZES:
            w, c, r = timed(lambda n=n: problems[n].solve(prob.x_case_m, starts=1))
            t_cold[n].append((w, c))
            its[n] = r.iterations
            t_warm[n].append(timed(lambda n=n: problems[n].solve(nominal.optimal,
                                                                 starts=1))[:2])
    load1 = os.getloadavg()
    med = lambda xs, k: float(np.median([x[k] for x in xs]))  # noqa: E731
    nw, nc = med(t_nom, 0), med(t_nom, 1)
    print(f"date {dt.datetime.now(dt.UTC):%Y-%m-%d %H:%M} UTC, load average "
          f"{load0[0]:.2f} -> {load1[0]:.2f} (1 min), {os.cpu_count()} cores, "
          f"{args.repeats} rounds, case {case.name} at {case.operating.oil_temp_C:g} degC, "
          f"uncertainty from {spec.source}")
    print()
    print("| NLP | build [s] | solve wall [ms] | solve CPU [ms] | ratio wall | ratio CPU | "
          "IPOPT iterations | from the nominal optimum, wall / CPU [ms] |")
    print("|---|---|---|---|---|---|---|---|")
    print(f"| nominal (5 variables, 2 rows) | {prob.build_time_s:.3f} | {nw * 1e3:.1f} | "
          f"{nc * 1e3:.1f} | 1 | 1 | {nominal.iterations} | |")
    for n in SIZES:
        w, c = med(t_cold[n], 0), med(t_cold[n], 1)
        ww, wc = med(t_warm[n], 0), med(t_warm[n], 1)
        print(f"| robust p95, N = {n} ({5 + 1 + n} variables, {3 + n} rows) | "
              f"{builds[n][0]:.3f} | {w * 1e3:.1f} | {c * 1e3:.1f} | {w / nw:.1f} | "
              f"{c / nc:.1f} | {its[n]} | {ww * 1e3:.1f} / {wc * 1e3:.1f} |")
    r64w, r64c = med(t_cold[64], 0) / nw, med(t_cold[64], 1) / nc
    print()
    print(f"N = 64, same start: {r64c:.1f}x the nominal solve's CPU time "
          f"({'met' if r64c <= TARGET_RATIO else 'NOT met'}), {r64w:.1f}x its wall time "
          f"({'met' if r64w <= TARGET_RATIO else 'NOT met'}); target <= {TARGET_RATIO:g}x; "
          f"the robust calls' wall/CPU = {med(t_cold[64], 0) / med(t_cold[64], 1):.1f} "
          f"at load {load1[0]:.1f} on {os.cpu_count()} cores")

if __name__ == "__main__":
    main()
