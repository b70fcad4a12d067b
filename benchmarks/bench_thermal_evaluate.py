"""Speed of ``evaluate_case`` under the thermal modes none, film and full (issue 10).

Side by side in one run, on the seed joint and on the seed joint with a ``[thermal]``
table (sea 2 degC, R 0.5 K/W, C 5e4 J/K):

* :func:`oilgap.model.evaluation.evaluate_case` under ``none``, ``film`` and ``full``:
  median and fastest wall time of repeated calls on one case (the duty cycle's speed
  distribution and heating spectrum are cached on it, as in every command), the modes
  measured in turn so that load on the machine hits them alike; the ratio to ``none``;
  and the first call on a freshly read case (nothing cached).
* the heat balance alone: :func:`oilgap.model.joint_loss.operating_temperature`
  against the generic solver :func:`oilgap.model.thermal.joint_steady_temperature` on
  the same loss (the path ``full`` took before), with the number of loss evaluations
  and the difference of the two temperatures.

Target: ``full`` within 3x the isothermal (``none``) time.

Run: ``python benchmarks/bench_thermal_evaluate.py``
"""

from __future__ import annotations

import os
import sys
import time
from dataclasses import replace

import numpy as np

from oilgap.model import joint_loss
from oilgap.model.case import ThermalSpec
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.thermal import joint_steady_temperature

REPEATS = 400
FRESH = 20
THERMAL = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5.0e4)


def with_thermal(case):
    """The case with the benchmark's [thermal] table."""
    return replace(case, name=f"{case.name} + [thermal]", thermal=THERMAL)


def timed(fn) -> float:
    """Wall time of one call [s]."""
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def interleaved(calls: dict, repeats: int) -> dict[str, np.ndarray]:
    """Wall times [s] of each call, measured in turn ``repeats`` times (after a warm-up)."""
    for fn in calls.values():
        fn()
    times = {k: [] for k in calls}
    for _ in range(repeats):
        for k, fn in calls.items():
            times[k].append(timed(fn))
    return {k: np.array(v) for k, v in times.items()}


def counted_steady(case) -> tuple[float, int]:
    """The balance by the generic solver, and its number of loss evaluations."""
    n = [0]

    def power(ts):
        n[0] += 1
        return np.asarray(joint_loss.joint_mean_power(case, ts, "full"), dtype=float)

    temps, _ = joint_steady_temperature(power, case.thermal, 1)
    return float(temps[0]), n[0]


def counted_fast(case) -> tuple[float, int]:
    """The balance by operating_temperature, and its number of loss evaluations."""
    n = [0]
    inner = joint_loss._stacked_powers

    def counting(*args, **kwargs):
        n[0] += 1
        return inner(*args, **kwargs)

    joint_loss._stacked_powers = counting
    try:
        t = joint_loss.operating_temperature(case, "full").oil_temp_C
    finally:
        joint_loss._stacked_powers = inner
    return t, n[0]


def main() -> int:
    print(f"machine: {os.cpu_count()} logical cores; {REPEATS} calls per mode, interleaved")
    seed, hot = seed_case(), with_thermal(seed_case())
    calls = {
        ("seed", "none"): lambda: evaluate_case(seed, thermal="none"),
        ("seed", "film"): lambda: evaluate_case(seed, thermal="film"),
        ("seed + [thermal]", "none"): lambda: evaluate_case(hot, thermal="none"),
        ("seed + [thermal]", "film"): lambda: evaluate_case(hot, thermal="film"),
        ("seed + [thermal]", "full"): lambda: evaluate_case(hot, thermal="full"),
    }
    times = interleaved(calls, REPEATS)
    fresh = {k: np.median([timed(lambda k=k: evaluate_case(
        seed_case() if k[0] == "seed" else with_thermal(seed_case()), thermal=k[1]))
        for _ in range(FRESH)]) for k in calls}
    print("\nevaluate_case, wall time per call [ms]:")
    print(f"  {'case':<18}{'mode':<6}{'median':>8}{'fastest':>9}{'x none':>8}"
          f"{'first call':>12}   result")
    for (name, mode), t in times.items():
        ref = times[(name, "none")]
        ev = calls[(name, mode)]()
        print(f"  {name:<18}{mode:<6}{1e3 * np.median(t):>8.3f}{1e3 * t.min():>9.3f}"
              f"{np.median(t) / np.median(ref):>8.2f}{1e3 * fresh[(name, mode)]:>12.3f}   "
              f"{ev.total_mean_power_W:.3f} W at {ev.oil_temp_C:.3f} degC")
    ratio = np.median(times[("seed + [thermal]", "full")]) / np.median(
        times[("seed + [thermal]", "none")])
    best = times[("seed + [thermal]", "full")].min() / times[("seed + [thermal]", "none")].min()
    print(f"  target full <= 3x none: {'PASS' if ratio <= 3.0 else 'FAIL'} "
          f"({ratio:.2f}x by the medians, {best:.2f}x by the fastest calls)")

    (t_generic, n_generic), (t_fast, n_fast) = counted_steady(hot), counted_fast(hot)
    solver = interleaved({"generic": lambda: counted_steady(hot),
                          "fast": lambda: joint_loss.operating_temperature(hot, "full")},
                         REPEATS // 4)
    print("\nheat balance of seed + [thermal] alone:")
    print(f"  thermal.joint_steady_temperature (generic)  {1e3 * np.median(solver['generic']):7.3f}"
          f" ms  {n_generic} loss evaluations  T = {t_generic:.9f} degC")
    print(f"  joint_loss.operating_temperature            {1e3 * np.median(solver['fast']):7.3f}"
          f" ms  {n_fast} loss evaluations  T = {t_fast:.9f} degC "
          f"(differs by {abs(t_fast - t_generic):.1e} K)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
