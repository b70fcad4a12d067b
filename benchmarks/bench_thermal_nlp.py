"""Benchmark of the thermal design NLP (issue 10): its solve beside the isothermal one.

Run: ``python benchmarks/bench_thermal_nlp.py [--repeats N]``

The seed case with a ``[thermal]`` table (sea 2 degC, R 0.5 K/W, C 5e4 J/K):

1. Build time of each NLP (isothermal, film, full).
2. Solves from the seed design (cold: no multipliers; the CLI's and a first solve's
   case) and warm-started from the optimum with its multipliers and a 1 % different
   required torque (how sweeps and the finite-difference checks re-solve), interleaved
   in rounds: median IPOPT time (``solve_time_s``, the IPOPT call), median wall time
   of the whole public call (start and polish of the oil temperature included),
   iterations and optimum. Target: median IPOPT solve of the full NLP <= 10 ms.
3. The optima side by side and the sea-temperature multiplier against a central
   difference of re-solved optima.
"""

from __future__ import annotations

import argparse
import time
from dataclasses import replace

import numpy as np

from oilgap.model.case import ThermalSpec
from oilgap.model.io.case_io import seed_case
from oilgap.optim.design import DesignProblem

SPEC = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5e4)


def load_average() -> str:
    try:
        with open("/proc/loadavg") as fh:
            return " ".join(fh.read().split()[:3])
    except OSError:
        return "n/a"


def timed(f):
    t = time.perf_counter()
    out = f()
    return time.perf_counter() - t, out


def build_section(case) -> dict[str, DesignProblem]:
    print("1. Build (CasADi SX, expand, IPOPT/MUMPS), median of 3")
    probs = {}
    for mode in ("none", "film", "full"):
        times = []
        for _ in range(3):
            t, probs[mode] = timed(lambda m=mode: DesignProblem(case, thermal=m))
            times.append(t)
        print(f"   {mode:<6}{np.median(times) * 1e3:>8.1f} ms")
    return probs


def solve_section(probs: dict[str, DesignProblem], repeats: int) -> dict:
    opts = {m: p.solve() for m, p in probs.items()}
    stats = {(m, k): {"ipopt": [], "wall": [], "iters": []}
             for m in probs for k in ("cold", "warm")}
    for _ in range(repeats):  # interleaved rounds
        for m, p in probs.items():
            tq = 0.99 * p.default_torque_min_Nm
            for kind, call in (("cold", p.solve),
                               ("warm", lambda p=p, m=m, tq=tq: p.solve(x0=opts[m],
                                                                       torque_min_Nm=tq))):
                t, r = timed(call)
                s = stats[(m, kind)]
                s["wall"].append(t)
                s["ipopt"].append(r.solve_time_s)
                s["iters"].append(r.iterations)
    print(f"\n2. Solves ({repeats} of each, interleaved; load average {load_average()})")
    print(f"   {'NLP':<7}{'start':<7}{'IPOPT median ms':>16}{'p90 ms':>8}{'wall median ms':>16}"
          f"{'iters':>7}")
    for (m, kind), s in stats.items():
        print(f"   {m:<7}{kind:<7}{np.median(s['ipopt']) * 1e3:>16.2f}"
              f"{np.percentile(s['ipopt'], 90) * 1e3:>8.2f}{np.median(s['wall']) * 1e3:>16.2f}"
              f"{int(np.median(s['iters'])):>7}")
    full = np.median(stats[("full", "cold")]["ipopt"]) * 1e3
    print(f"   full NLP, cold: median IPOPT solve {full:.2f} ms (target <= 10 ms: "
          f"{'met' if full <= 10 else 'NOT met'}); ratio to the isothermal NLP "
          f"{full / (np.median(stats[('none', 'cold')]['ipopt']) * 1e3):.2f}")
    return opts


def optima_section(probs: dict[str, DesignProblem], opts: dict) -> None:
    print("\n3. Optima (smooth C_m)")
    print(f"   {'NLP':<7}{'P* W':>10}{'T_oil C':>9}{'delta mm':>10}{'R mm':>9}{'L mm':>8}"
          "  active")
    for m, r in opts.items():
        o = r.optimal
        t = getattr(r, "oil_temp_C", r.parameters.oil_temp_C)
        print(f"   {m:<7}{o.mean_power_W:>10.4f}{t:>9.3f}{o.delta_m * 1e3:>10.4f}"
              f"{o.R_m * 1e3:>9.4f}{o.L_m * 1e3:>8.3f}  {', '.join(r.active_constraints)}")
    r = opts["full"]
    up = probs["full"].solve(x0=r, sea_temp_C=SPEC.sea_temp_C + 0.1).optimal.mean_power_W
    down = probs["full"].solve(x0=r, sea_temp_C=SPEC.sea_temp_C - 0.1).optimal.mean_power_W
    fd = (up - down) / 0.2
    print(f"   dP*/dT_sea: multiplier {r.sea_temp_cost_W_per_K:+.6f} W/K, central difference "
          f"of re-solved optima (+-0.1 K) {fd:+.6f} W/K (rel. diff "
          f"{abs(fd / r.sea_temp_cost_W_per_K - 1):.1e})")
    print(f"   balance residual at IPOPT's solution {r.balance_residual_K:.1e} K (polished "
          "on the optimal design to 1e-11 K)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=30)
    args = ap.parse_args()
    case = replace(seed_case(), thermal=SPEC)
    probs = build_section(case)
    opts = solve_section(probs, args.repeats)
    optima_section(probs, opts)


if __name__ == "__main__":
    main()
