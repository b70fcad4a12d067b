"""Gap-loss front: epsilon-constraint sweep (warm-started IPOPT) against pymoo's NSGA-II.

The same two-objective problem for both: minimise (magnetic gap delta [mm], mean
viscous power [W]) over (R, delta, d_r, d_s, L) within the seed case's bounds,
subject to torque capability >= the seed's and rotor inertia <= 1.05 x the
seed's (smooth C_m, the seed's duty cycle, VG22 at 3000 m and 2 degC). NSGA-II
evaluates the numpy path of the same functions, vectorised over its population
(:func:`oilgap.studies.pareto.gap_problem_numpy`).

Front quality: hypervolume (HV) with the reference point (delta = 2 mm = the
case's gap_max, P = the seed's mean power), computed by
:func:`oilgap.optim.multiobjective.hypervolume_2d` and cross-checked with pymoo's HV.

Comparison (time to target, at equal front size): for N = 50 and 100 points, the
sweep's wall time ``t_eps`` (the first call in the process, including building the
NLP) and its HV; NSGA-II with population N records, generation by generation, the
HV of its feasible non-dominated set and stops once it reaches the sweep's HV or
after ``BUDGET_FACTOR x t_eps``. Target: no NSGA-II run reaches the sweep's HV in
less than 20 x t_eps. For information, NSGA-II with 100 points is also raced against
the 50-point sweep (more points alone raise the HV).

Run: ``python benchmarks/bench_pareto_nsga2.py`` (needs pymoo: ``pip install
'oilgap[bench]'``).
"""

from __future__ import annotations

import sys
import time

import numpy as np

from oilgap.model.io.case_io import seed_case
from oilgap.optim.multiobjective import hypervolume_2d, nondominated
from oilgap.studies.grid.optimize import clear_problems
from oilgap.studies.pareto import (
    default_reference_point,
    gap_front,
    gap_problem_numpy,
    seed_points,
)

SIZES = (50, 100)
"""Front sizes compared: the sweep's points = NSGA-II's population."""
SEEDS = (1, 2, 3)
TARGET_FACTOR = 20.0
BUDGET_FACTOR = 30.0
"""Each NSGA-II run stops at the sweep's HV or after this many times t_eps."""


def _sweeps(case, ref, evaluate, HV) -> dict:
    """The epsilon-constraint sweeps at each size: time (first and warm), HV, and their
    optima checked on NSGA-II's numpy path."""
    sweeps = {}
    for n in SIZES:
        clear_problems()  # cold: the first call builds the NLP
        t0 = time.perf_counter()
        front = gap_front(case, n)
        t_first = time.perf_counter() - t0
        warm = []
        for _ in range(5):
            t0 = time.perf_counter()
            gap_front(case, n)
            warm.append(time.perf_counter() - t0)
        ok = front[front["status"] == "ok"]
        F = ok[["delta_mm", "mean_power_W"]].to_numpy()
        X = np.column_stack([ok["R_mm"], ok["delta_mm"], ok["R_mm"] - ok["T1_mm"],
                             ok["T4_mm"] - ok["T3_mm"], ok["L_mm"]]) * 1e-3
        F_np, G_np = evaluate(X)
        sweeps[n] = dict(points=len(ok), t=max(t_first, float(np.median(warm))),
                         t_first=t_first, t_warm=float(np.median(warm)),
                         hv=hypervolume_2d(F, ref), hv_pymoo=float(HV(ref_point=np.array(ref))(F)),
                         viol=max(0.0, float(G_np.max())),
                         agree=float(np.max(np.abs(F_np[:, 1] / F[:, 1] - 1))))
    return sweeps


def _print_sweeps(ref, sweeps: dict) -> None:
    """The reference point and the sweeps' table."""
    print("Gap-loss front of the seed joint (VG22, 3000 m, 2 degC), both objectives minimised")
    print(f"reference point: delta = {ref[0]:g} mm, P = {ref[1]:.4f} W "
          "(the case's gap_max, the seed's mean power)")
    print()
    print("epsilon-constraint sweeps (t_eps = first call in the process, incl. building the NLP):")
    print(f"{'points':>7}{'HV mm W':>10}{'pymoo HV':>10}{'t_eps s':>9}{'warm s':>8}"
          f"{'max viol.':>10}{'obj. agree':>11}")
    for sw in sweeps.values():
        print(f"{sw['points']:>7}{sw['hv']:>10.4f}{sw['hv_pymoo']:>10.4f}{sw['t']:>9.3f}"
              f"{sw['t_warm']:>8.3f}{sw['viol']:>10.1e}{sw['agree']:>11.1e}")
    print("  (viol./agree: the sweep's optima on NSGA-II's numpy path: max scaled constraint "
          "violation, max relative objective difference)")


def _pymoo_classes(Problem, Callback, lo, hi, evaluate, ref):
    """The gap-loss problem on NSGA-II's numpy path and the HV tracker (pymoo's base
    classes passed in: pymoo is imported only when the benchmark runs)."""
    class GapLoss(Problem):
        def __init__(self):
            super().__init__(n_var=5, n_obj=2, n_ieq_constr=2, xl=lo, xu=hi)

        def _evaluate(self, X, out, *args, **kwargs):
            F, G = evaluate(X)
            out["F"] = F
            out["G"] = G

    class Tracker(Callback):
        """HV per generation; its own time is excluded from NSGA-II's clock."""

        def __init__(self, budget_s: float, target_hv: float, t_ref: float):
            super().__init__()
            self.target_hv = target_hv
            self.t_ref = t_ref
            self.t0 = time.perf_counter()
            self.own = 0.0
            self.budget_s = budget_s
            self.hit = None
            self.hv_at_target = None
            self.hv = 0.0
            self.evals = 0

        def notify(self, algorithm):
            c0 = time.perf_counter()
            opt = algorithm.opt
            F = opt.get("F")[opt.get("CV").ravel() <= 0]
            F = F[nondominated(F)] if len(F) else F
            self.hv = hypervolume_2d(F, ref) if len(F) else 0.0
            self.evals = algorithm.evaluator.n_eval
            self.own += time.perf_counter() - c0
            t = time.perf_counter() - self.t0 - self.own
            if self.hv_at_target is None and t >= TARGET_FACTOR * self.t_ref:
                self.hv_at_target = self.hv
            if self.hit is None and self.hv >= self.target_hv:
                self.hit = (algorithm.n_gen, t)
            if self.hit is not None or t >= self.budget_s:
                algorithm.termination.force_termination = True
            self.t = t

    return GapLoss, Tracker


def main() -> int:
    try:
        from pymoo.algorithms.moo.nsga2 import NSGA2
        from pymoo.core.callback import Callback
        from pymoo.core.problem import Problem
        from pymoo.indicators.hv import HV
        from pymoo.optimize import minimize
    except ImportError:
        print("pymoo is not installed: pip install 'oilgap[bench]' (or pip install pymoo)")
        return 1

    case = seed_case()
    seeds = seed_points()
    ref = default_reference_point(case, seeds)
    lo, hi, evaluate = gap_problem_numpy(case)
    sweeps = _sweeps(case, ref, evaluate, HV)

    GapLoss, Tracker = _pymoo_classes(Problem, Callback, lo, hi, evaluate, ref)
    _print_sweeps(ref, sweeps)

    def race(pop: int, seed: int, target_hv: float, t_ref: float):
        cb = Tracker(BUDGET_FACTOR * t_ref, target_hv, t_ref)
        minimize(GapLoss(), NSGA2(pop_size=pop), ("n_gen", 100_000), seed=seed,
                 callback=cb, verbose=False)
        return cb

    def show(pop, seed, cb, t_ref):
        hv20 = cb.hv_at_target if cb.hv_at_target is not None else cb.hv
        reached = f"{cb.hit[1]:.2f} s" if cb.hit else "never"
        ratio = f"{cb.hit[1] / t_ref:.1f}" if cb.hit else f">{cb.t / t_ref:.0f}"
        print(f"{pop:>5}{seed:>6}{cb.hit[0] if cb.hit else '-':>7}{cb.evals:>8}"
              f"{hv20:>17.4f}{cb.hv:>10.4f}{reached:>12}{ratio:>9}")

    head = (f"{'pop':>5}{'seed':>6}{'gens':>7}{'evals':>8}{'HV at 20x t_eps':>17}"
            f"{'final HV':>10}{'reached at':>12}{'t/t_eps':>9}")
    passed = True
    for n, sw in sweeps.items():
        print()
        print(f"NSGA-II, population {n} (= the sweep's points), until HV >= {sw['hv']:.4f} "
              f"or {BUDGET_FACTOR:g} x t_eps = {BUDGET_FACTOR * sw['t']:.1f} s:")
        print(head)
        for seed in SEEDS:
            cb = race(n, seed, sw["hv"], sw["t"])
            show(n, seed, cb, sw["t"])
            passed &= cb.hit is None or cb.hit[1] >= TARGET_FACTOR * sw["t"]
    n_small, n_big = min(SIZES), max(SIZES)
    sw = sweeps[n_small]
    print()
    print(f"for information, NSGA-II with twice the points (population {n_big}) against the "
          f"{n_small}-point sweep's HV {sw['hv']:.4f}:")
    print(head)
    for seed in SEEDS:
        show(n_big, seed, race(n_big, seed, sw["hv"], sw["t"]), sw["t"])
    print()
    print(f"target: at equal front size, no NSGA-II run reaches the sweep's HV in less than "
          f"{TARGET_FACTOR:g} x t_eps: {'PASS' if passed else 'FAIL'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
