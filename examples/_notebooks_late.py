"""Notebooks 05-07 of ``examples/`` (uncertainty, rig planning, linear actuator).

Part of the notebooks' source, :mod:`make_notebooks`, which writes them.
"""

from __future__ import annotations

from _cells import code, md, setup

# --------------------------------------------------------------------------- 05

NB05 = [
    md("""
# 5. How sure is the loss? Percentiles and what drives them

The joint of `my_joint.toml` again. Its mean loss is one number; its inputs are not: the
oil's viscosity at 40 °C may be ±10 % off its grade (ISO 3448), the groove exponent γ
comes from one rig (0.566 ± 0.041), the sea temperature at depth is known to a few
kelvin, the film heating lies between none and the smooth-film theory.
`og.uncertainty` draws scrambled Sobol' points of the uncertain inputs, evaluates the
joint's loss at each (the same number as `og.evaluate` of that scenario) and reports the
loss's percentiles [W], a tornado and the Sobol' indices (SALib). The samples are small
here so that the notebook runs in seconds; the command's defaults are 8192 and 2048
([uncertainty](../docs/uncertainty.md)).
"""),
    code(setup("05_uncertainty", "import matplotlib.pyplot as plt")),
    md("""
## The defaults: ISO 3448 on ν40 and γ from the seed fit

Without an `[uncertainty]` table the study takes two inputs, each listed with its source:
the grade's viscosity factor uniform on 0.9–1.1 and γ normal with sd 0.041. The thermal
mode is the case's default (`bulk`: the oil at its heat balance's temperature).
"""),
    code("""
u = og.uncertainty("my_joint.toml", samples=1024, sobol_samples=256, out=OUT / "defaults")
print(u)"""),
    md("""
`statistics` holds the loss's mean, sd and percentiles [W]; `to_frame()` one row per
input: its law, the loss with that input at its own 5th and 95th percentiles (the others
nominal: the tornado) and its first-order and total Sobol' indices with 95 % intervals.
"""),
    code("""
u.statistics"""),
    code("""
u.to_frame()"""),
    code("""
fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4))
u.plot(ax=left)
u.plot(ax=right, kind="tornado")
fig.tight_layout()"""),
    md("""
## Say what you know: the sea temperature and the film

The laws can be given in the case file (`[uncertainty.oil_temp_C] dist = "normal"`,
`mean_C = 4.0`, `sd_K = 1.5`, ...) or in Python as an `UncertaintySpec`. Here the sea
temperature (with `[thermal]`, `oil_temp_C` moves the sea by the same amount) and the film
strength s, uniform on 0–1, join the two defaults. With s uncertain the study runs under
`full`, the film counterpart of `bulk` (s = 0 is `bulk` exactly).
"""),
    code("""
from oilgap.model.uncertain import Distribution, UncertaintySpec, case_uncertainty

case = og.read_case("my_joint.toml")
laws = case_uncertainty(case).distributions + (
    Distribution(input="oil_temp_C", kind="normal", params=(("mean", 4.0), ("sd", 1.5)),
                 source="the sea at 4000 m, known to a few kelvin"),
    Distribution(input="film_strength", kind="uniform", params=(("low", 0.0), ("high", 1.0)),
                 source="between none and the smooth-film theory"),
)
more = og.uncertainty(case, spec=UncertaintySpec(distributions=laws, source="this notebook"),
                      samples=1024, sobol_samples=256)
print(more.thermal_mode)
more.to_frame()[["input", "S1", "ST", "loss_low_W", "loss_high_W"]]"""),
    md("""
## The numbers to remember

The motor must be sized for the 95th percentile of the loss, not its nominal value; the
input with the largest total index is the one worth measuring first.
"""),
    code("""
top = u.to_frame().sort_values("ST", ascending=False).iloc[0]
print(f"nominal loss: {u.nominal_W:.4f} W")
print(f"p95 of the loss: {u.statistic('p95'):.4f} W")
print(f"largest total index: {top['input']}")
print(f"p95 with the sea and the film uncertain: {more.statistic('p95'):.4f} W")"""),
]

# --------------------------------------------------------------------------- 06

NB06 = [
    md("""
# 6. Plan the next rig test

Before the oil is poured: which runs identify the law (the scale and the groove exponent
γ of Eq. 6 × T^γ) and which would let the loop detect an effect? `og.plan` simulates
every candidate run (oil, rotor, bath temperature, speed profile) with the synthetic rig,
takes its Fisher information from the loop's own forward model, solves the D-optimal
design with cvxpy and rounds it to whole runs, beside the naive full factorial of the
same size ([planning](../docs/planning.md)). Small here (two oils, 40 s runs) so that it
runs in seconds.
"""),
    code(setup("06_plan_rig")),
    code("""
res = og.plan(oils=("VG150", "VG1000"), bath_C=(25.0,), profiles=("sine",),
              duration_s=40.0, runs=6, effects=("thermal_lag", "taylor_vortex_onset"),
              out=OUT / "plan")
print(res.summary())"""),
    md("""
The plan puts every run on the thick oil (the most power per run: the most information on
the scale and γ) and splits them between the two rotors. It never reaches the Taylor
onset, so it cannot detect a vortex; the naive plan's VG150 runs do. `plan.csv` is the
table the rig follows; `oilgap synth --plan plan.csv` (here `og.synth_plan`) rehearses
it, and the loop's intervals come out near the plan's.
"""),
    code("""
import pandas as pd

from oilgap.optim.calibration import LoopEstimator

plan_csv = pd.read_csv(OUT / "plan" / "plan.csv")
widths = {}
for tag in ("plan", "naive"):
    data = og.synth_plan(OUT / "plan" / f"{tag}.csv", seed=0)
    est = LoopEstimator(effects=["thermal_lag"]).fit(data)
    lo, hi = est.calibration_ci_["gamma"]
    widths[tag] = hi - lo
widths"""),
    code("""
print(f"plan runs: {len(plan_csv)}")
print(f"expected gamma sd plan: {res.plan.sd['gamma']:.6g}")
print(f"expected gamma sd naive: {res.naive.sd['gamma']:.6g}")
print(f"loop gamma width plan: {widths['plan']:.6g}")
print(f"loop gamma width naive: {widths['naive']:.6g}")"""),
]

NB07 = [
    md("""
# 7. A linear actuator in oil

`linear_joint.toml`: a motor turns a 16 x 5 ball screw, the nut drives a 20 mm rod through
a 30 mm guide bushing (0.05 mm radial clearance), one 2 mm, 50 mm passage carries the oil
the rod displaces; VG10 at 2 °C and 6000 m; the rod follows 0.1 m/s sin(π t), so the motor
turns at 2πv/lead, 1200 rpm at the peak ([the linear-cylinder joint](../docs/linear-joint.md)).

What you will see: the loss by element (motor gap, motor bearing, screw, rod guide,
passages), the passage diameter as the strongest lever (d⁻⁴), and the design the optimizer
chooses under the rod force, motor speed, passage velocity and compensator constraints.
"""),
    code(setup("07_linear_actuator")),
    code("""
case = og.read_case("linear_joint.toml")
ev = og.evaluate(case, thermal="none")
print(ev.summary().split("linear drive")[1].split("total mean power")[0])
"""),
    md("""
## The passage diameter

Hagen-Poiseuille: the pressure drop goes as d⁻⁴ at the same flow, so the passages' power
does too. The rest of the joint does not change.
"""),
    code("""
from dataclasses import replace

for d_mm in (2.0, 3.0, 4.0):
    c = replace(case, linear=replace(case.linear, passage_diameter_m=d_mm * 1e-3))
    rows = {e.name: e.mean_power_W for e in og.evaluate(c, thermal="none").raw.linear_elements}
    print(f"passage {d_mm:g} mm: {rows['passages']:.3f} W")
"""),
    md("""
## Optimize

The lead, the guide clearance, the passage diameter and the motor's gap and grooves, under
the rod force 2πηT/lead ≥ 800 N, the motor's 3000 rpm, 3 m/s in the passage and the
compensator's 60 mL. The optimum is evaluated exactly under the same thermal mode.
"""),
    code("""
opt = og.optimize(case, thermal="none")
print(opt.summary())
print()
print(f"mean loss as designed: {opt.initial.total_mean_power_W:.4f}")
print(f"mean loss optimized: {opt.optimum.total_mean_power_W:.4f}")
print(f"lead optimized: {opt.design.x_mm[0]:.4f}")
"""),
]
