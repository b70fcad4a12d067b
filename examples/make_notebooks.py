"""Write the example notebooks of ``examples/`` (this script is their source).

Each notebook is saved without outputs (small, clean diffs). Edit the cells here,
then run ``python examples/make_notebooks.py`` from the repository root; it
rewrites ``examples/0*.ipynb``. ``tests/examples/test_notebooks.py`` executes them.

Every notebook reads its inputs from the folder it runs in (``my_joint.toml``,
``mission.csv``, ``rig_runs.csv``) and writes its outputs to a temporary folder
(``$OILGAP_EXAMPLES_OUT`` if set, else a fresh ``tempfile.mkdtemp()``), never
into the repository. Its last cell prints the key numbers the test checks.
"""

from __future__ import annotations

import sys
from pathlib import Path

import nbformat
from nbformat.v4 import new_notebook

HERE = Path(__file__).resolve().parent

sys.path.insert(0, str(HERE))  # the notebooks' cells live beside this script
from _cells import code, md, setup  # noqa: E402
from _notebooks_late import NB05, NB06, NB07  # noqa: E402

# --------------------------------------------------------------------------- 01

NB01 = [
    md("""
# 1. My joint: evaluate and optimize

The joint of `my_joint.toml`: rotor radius R = 40 mm, gap δ = 0.8 mm, clearance length
L = 30 mm, grooved rotor and stator (T = 4.75), ISO VG 32, rated at 4000 m with the oil at
4 °C, and a `[thermal]` table (sea at 4 °C, 0.05 K/W from the oil to the sea). Everything
the file leaves out (motor data, the 3000 rpm sine duty cycle, the design bounds) takes a
stated default, and the tool lists it.

What you will see:

1. the mean viscous loss over the duty cycle, region by region, in W;
2. the same joint under the four thermal models side by side (`none`: the seed paper's
   isothermal oil at the given temperature; `bulk`, the default with a `[thermal]` table:
   the oil's temperature comes out of the heat balance with the sea, the film stays
   isothermal at it; `film`: the film heats itself as it is sheared; `full`: both);
3. the optimized clearance (R, δ, L, the epoxy fill of the grooves) and what it saves;
4. the optimized design written as a case file, read back and evaluated again.
"""),
    code(setup("01_my_joint", "import matplotlib.pyplot as plt", "import pandas as pd")),
    md("""
## Read the case

`og.read_case` checks every key against its physical range and refuses a typo or a unit
slip with one line naming the key. Paths work too: every `og` function takes a case, a
path to a case file, or nothing (the seed paper's joint).
"""),
    code('''
case = og.read_case("my_joint.toml")
print(case.name, "| oil", case.oil.name, "| thermal table:", case.thermal is not None)'''),
    md("""
## Evaluate

With a `[thermal]` table the default thermal model is `bulk`: the oil settles where the
loss heats it as fast as the sea cools it, and the clearance's film is isothermal at that
temperature, the model the only measurements in oil (the seed paper's Table 4) support.
What film heating at full strength would give is printed beside the loss as the *film
band*, with its evidence (`docs/thermal.md#evidence`). The table gives the mean power of
each region
over the duty cycle [W], its peak Reynolds number (laminar below ~2000 in these narrow
gaps) and the flow regimes visited.
"""),
    code('''
ev = og.evaluate(case)
ev'''),
    code('''
ev.to_frame()'''),
    md("""
## The four thermal models side by side

The same joint, the same duty cycle: only what the oil's temperature is taken to be
changes. `none` is the seed paper's model (oil at 4 °C throughout); `bulk` (the default
here) adds the joint's heat balance (the bulk oil runs above the sea by R × P); `film` lets
the sheared film heat itself at 4 °C (the Nahme number says how much); `full` does both.
Cold VG 32 is viscous: at the sea's temperature the loss is several times what the heat
balance gives. The film's own heating would lower it further; the seed paper's
measurements do not support it at full strength, so it is an option, not the default.
"""),
    code('''
modes = {m: og.evaluate(case, thermal=m) for m in ("none", "bulk", "film", "full")}
side = pd.DataFrame({m: {"oil temperature [degC]": e.to_dict()["oil_temp_C"],
                         "viscosity at that temperature [cSt]": e.to_dict()["nu_cSt"],
                         "mean viscous loss [W]": e.to_dict()["total_mean_power_W"]}
                     for m, e in modes.items()})
side.round(2)'''),
    code('''
fig, axes = plt.subplots(1, 4, figsize=(15, 3.5), sharey=True)
for ax, (m, e) in zip(axes, modes.items(), strict=True):
    e.plot(ax=ax)
    ax.set_title(f"thermal = {m}")
fig.tight_layout()'''),
    md("""
## Optimize the clearance

`og.optimize` minimises the mean loss over R, δ, L and the epoxy fill of both grooves,
keeping the motor's torque capability and the rotor inertia within 1.05× its own (the
default bounds: gap ×0.5–2, R ×0.9–1.1, L ×0.8–1.2 of the case's, listed in the output).
With a `[thermal]` table the oil temperature is a variable of the problem; the isothermal
optimum is printed beside it.
"""),
    code('''
opt = og.optimize(case)
print(opt)'''),
    md("""
Every value the tool filled in, with where it came from (the motor data of the seed joint,
the bounds around your design, the duty cycle): check these before trusting the optimum.
"""),
    code('''
pd.DataFrame(opt.defaults)'''),
    code('''
opt.to_frame()'''),
    md("""
## Before and after, and the optimized case written out

The optimized design is an ordinary case: write it, read it back, evaluate it like the
original (`oilgap optimize my_joint.toml --out my_joint_opt.toml` does the same from the
command line). `opt.raw` is the module-level result: under `bulk` a comparison whose
`heated` optimum (on the heat balance) is the design. The two evaluations below use the
same model (`bulk`, the default), so the difference is the design alone.
"""),
    code('''
from oilgap.studies.io.case_write import write_case_toml  # the façade has no case writer (yet)

opt_path = write_case_toml(opt.raw.heated.to_case(), OUT / "my_joint_opt.toml")
opt_case = og.read_case(opt_path)
after = og.evaluate(opt_case)


def design(c, e):
    """The clearance of case c (SI inside, shown in mm) and its evaluated loss."""
    r1 = c.region1
    return {"R [mm]": 1e3 * r1.radius, "gap [mm]": 1e3 * r1.gap, "L [mm]": 1e3 * r1.length,
            "roughness T [-]": r1.roughness, "oil temperature [degC]": e.to_dict()["oil_temp_C"],
            "mean loss [W]": e.to_dict()["total_mean_power_W"]}


pd.DataFrame({"before": design(case, ev), "after": design(opt_case, after)}).round(3)'''),
    code('''
loss_before = ev.to_dict()["total_mean_power_W"]
loss_after = after.to_dict()["total_mean_power_W"]
print(f"mean loss as designed: {loss_before:.4f} W")
print(f"mean loss optimized: {loss_after:.4f} W")
print(f"saved: {100 * (1 - loss_after / loss_before):.1f} %")'''),
]

# --------------------------------------------------------------------------- 02

NB02 = [
    md("""
# 2. What a smaller gap costs: the Pareto fronts of my joint

A smaller gap δ strengthens the motor (its magnetic gap shrinks, so the torque
capability rises) but shears the oil harder. The **gap front** answers: for each gap, what
is the least mean loss any design (R, L, groove fill) reaches with the torque the motor
needs? The **inertia front** answers the same for the allowed rotor inertia: how much loss
does each extra per cent of inertia buy back?

Each point is one IPOPT solve, warm-started from its neighbour (ε-constraint method). The
study takes the same thermal model as `og.evaluate` and `og.optimize`: with the case's
`[thermal]` table the default `bulk`, the oil temperature a variable of each solve and the
heat balance an equality (`thermal="none"` for the isothermal fronts at 4 °C). Its mode is
named in the header and the figure titles. 50 points per front (the minimum the study
accepts) take about a second.
"""),
    code(setup("02_pareto", "import matplotlib.pyplot as plt")),
    code('''
case = og.read_case("my_joint.toml")
par = og.pareto(case, points=50, out=OUT / "pareto")
print(par)'''),
    md("""
## The table

`to_frame()` holds both fronts, one row per point (`front` = `gap` or `inertia`): the
bound of the sweep (`delta_max_mm` or `inertia_max_ratio`, the ε), the optimal design
(R, δ, L in mm, the roughness T), its mean loss [W], torque capability [N m], inertia
ratio to the case's rotor, and the solver's status. Only points whose solve succeeded
(`ok`) are on a front. The full table has every column the CSVs have; a few are shown.
"""),
    code('''
fronts = par.to_frame()
shown = ["front", "delta_mm", "R_mm", "L_mm", "T", "mean_power_W", "torque_capability_Nm",
         "inertia_ratio", "status"]
fronts.loc[fronts["front"] == "gap", shown].iloc[::7].round(3)'''),
    code('''
fronts.loc[fronts["front"] == "inertia", shown].iloc[::7].round(3)'''),
    code('''
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
par.plot(ax=left, front="gap")
par.plot(ax=right, front="inertia")
fig.tight_layout()'''),
    md("""
## Reading the front

The marker is your design as drawn, under the same model (far above the front: its
grooves and gap are not the loss-optimal ones; its film band is printed under the fronts).
Going from the loss-optimal gap down to the smallest
allowed gap (half the case's) raises the loss by about half; on the inertia front, a rotor
lighter than the case's costs loss steeply, a heavier one buys little. The hypervolume
(mm W) summarises the gap front in one number (larger is better, measured from the
reference point in the header above). The files written (CSV, PNG, `summary.md`,
`provenance.json`) are what `oilgap study pareto my_joint.toml --out DIR` writes.
"""),
    code('''
raw = par.raw
gap = raw.gap_front[raw.gap_front["status"] == "ok"]
print(sorted(p.name for p in (OUT / "pareto").iterdir()))
print(f"gap front points: {len(gap)}")
print(f"gap range: {gap['delta_mm'].min():.3f} .. {gap['delta_mm'].max():.3f} mm")
print(f"least loss on the gap front: {gap['mean_power_W'].min():.4f} W")
print(f"hypervolume: {raw.hypervolume:.4f} mm W")'''),
]

# --------------------------------------------------------------------------- 03

NB03 = [
    md("""
# 3. Which oil grade for my mission?

The grade is a compromise: thin oil loses less, but must stay thick enough to lubricate at
the hottest, shallowest point (ν ≥ 13 cSt), and thin enough to start cold at the coldest,
deepest point (ν ≤ 1000 cSt). The study checks every ISO VG grade against both limits
over the joint's envelope and ranks those that pass by the energy they lose over the
mission (Wh over 8 h).

The mission is in `mission.csv` (depth, temperature and the fraction of the running time
of each segment): a few minutes of deck checks at 15 °C, the descent, most of the time at
the rated 4000 m. With the case's `[thermal]` table the study runs under its default,
`bulk`: each segment's temperature is the **sea's**, and every grade's operating
temperature comes out of its own heat balance (a thicker grade loses more and runs
hotter). The envelope below is
this joint's: 0–4500 m, sea 0–30 °C, on a coarse grid (500 m × 5 K: `n_depth=10`,
`n_temp=7`; the default grid is finer and takes a few seconds more). Add
`out="some/folder"` to write the CSVs, figures and `summary.md` that
`oilgap study oil-grade` writes.
"""),
    code(setup("03_oil_grade", "import matplotlib.pyplot as plt", "import pandas as pd")),
    code('''
mission = pd.read_csv("mission.csv")
mission'''),
    code('''
case = og.read_case("my_joint.toml")
grade = og.oil_grade(case, mission="mission.csv", depth_range_m=(0.0, 4500.0),
                     sea_temp_range_C=(0.0, 30.0), n_depth=10, n_temp=7)
print(grade)'''),
    md("""
## The grade table

One row per grade: the lowest viscosity over the envelope (lubrication check) and the
highest (cold start) in cSt, the operating temperature at the rated point [°C], the
mission energy [Wh] and the verdict with its reason in words. VG 32, the grade the joint
was drawn with, is too thick for a cold start in a 0 °C sea at 4500 m once its ±10 % ISO
tolerance is allowed for (917 cSt nominal, 1009 cSt at +10 %, limit 1000 cSt).
"""),
    code('''
table = grade.to_frame()
table'''),
    code('''
fig, ax = plt.subplots(figsize=(10, 4))
grade.plot(ax=ax)
fig.tight_layout()'''),
    md("""
With the heat balance each grade runs warmer than the sea; the isothermal
study (the seed paper's model, the oil at the sea's temperature) is run beside it, and the
header says whether the recommendation changes and why. The last lines are the answer.
"""),
    code('''
raw = grade.raw
row = raw.table.set_index("oil").loc[raw.recommended]
print(f"thermal model: {raw.thermal_mode}")
print(f"recommended: {raw.recommended}   runner-up: {raw.runner_up}")
print(f"mission energy of the recommended grade: {row['mission_energy_Wh']:.4f} Wh")'''),
]

# --------------------------------------------------------------------------- 04

NB04 = [
    md("""
# 4. My rig's data through the loop, then predict

`rig_runs.csv` holds 400 rows of rig data: 8 runs of 50 samples (every 0.4 s over one
20 s trapezoid speed cycle up to 3000 rpm): ISO VG 15, 32 and 68, each with the grooved
rotor (T = 4.75) and with the grooves filled (T = 2), and one oil-free run per T, which
measures the motor's own losses (the baseline). `power_W` is the electrical input power,
`temp_C` the measured oil temperature.

**Where the data come from.** Not from oilgap's model: they were made once by
`examples/make_rig_runs.py` with oilgap's *out-of-family rig*
(`oilgap.studies.rigs.outside_rig`), an independent simulation with laws of its own (Eq. 6
piecewise with a Couette floor, groove factor T^0.5, a gearbox loss ∝ |τω|^1.3, a lumped
thermal node, 1 W of AR(1) noise on the power). The rig also carries **an effect the loop
is not told of**: a shaft seal with Coulomb + Stribeck friction of 0.04 N m. A good loop
finds it, names it and estimates its size.

What you will see: the calibrated law (scale, exponent, groove exponent γ), the effects
found with their coefficients and intervals, the error on held-out runs before and after
(each run left out in turn), and predictions for new operating points.
"""),
    code(setup("04_loop", "import matplotlib.pyplot as plt", "import pandas as pd")),
    code('''
data = pd.read_csv("rig_runs.csv")
print(data.groupby("run").size().to_dict())
data.head()'''),
    md("""
## Fit

`og.Loop` is an estimator: `fit` runs the whole loop (baseline from the oil-free runs,
calibration of the design tool's law, plausibility of each parameter, the search of the
residual for missing physical effects, leave-one-run-out validation).
"""),
    code('''
loop = og.Loop("my_joint.toml").fit(data)
print(loop)'''),
    md("""
## Measured against model, run by run

One row per oil run: the mean measured viscous power [W] (electrical input minus the
fitted oil-free baseline) beside three models, and their RMS errors [W]: `without_T`, the
published law as the case states it (no groove factor, nothing fitted); `with_T`, the
calibrated law (scale × T^γ); `with_effect`, calibrated with the effects the loop found.
The last two columns are the errors on each run when it was left out of the fit
(`heldout_rmse_before_W`: calibrated law only; `..._after_W`: with the effects): the
honest measure of what the loop gained.
"""),
    code('''
loop.to_frame()'''),
    code('''
fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4))
loop.plot(ax=left)
runs = loop.to_frame()[["heldout_rmse_before_W", "heldout_rmse_after_W"]]
runs.plot.bar(ax=right, rot=0)
right.set_ylabel("held-out RMS error [W]")
right.set_title("each run left out of the fit in turn")
right.legend(["before: calibrated law, no effect", "after: with the effect found"])
fig.tight_layout()'''),
    md("""
## Predict new operating points

`predict` applies the fitted model to new rows without refitting. `rig_new_points.csv`
holds steady points measured later on the same rig (made by the same script, another
noise draw): VG 32 and **VG 46, a grade the runs never used**, on both rotors, at five
speeds and 25 °C. Rows without `time_s` are steady points. The result is the input rows
with the model's viscous power and total electrical power [W] added (the total needs an
oil-free baseline for that roughness; a row outside the fitted range of speed,
temperature, viscosity or T is predicted with a warning, never silently).
"""),
    code('''
new = pd.read_csv("rig_new_points.csv")
pred = loop.predict(new)
pred["error_W"] = pred["predicted_power_W"] - pred["power_W"]
pred'''),
    code('''
pred.groupby(["oil", "roughness_T"])["error_W"].agg(lambda e: (e**2).mean() ** 0.5).rename(
    "prediction RMSE [W]").to_frame()'''),
    md("""
## Design with what the rig taught

The fitted model goes into any design command: `model=` on `og.evaluate` and
`og.optimize` (`--model loop.json` on the command line) folds the calibrated law into the
case, and names what it does not carry (the seal: the design model has no seal term).
The joint evaluated with the calibrated law; the last cell prints its loss beside the
loss under the case's own law.
"""),
    code('''
calibrated = og.evaluate("my_joint.toml", model=loop)
plain = og.evaluate("my_joint.toml")
calibrated'''),
    md("""
## The numbers to remember

The held-out error is the RMS error [W] on runs left out of the fit, averaged over the
runs; the noise of the rig's power reading is about 1 W. The effect's coefficient is in
its own unit (for the seal, its Coulomb torque in N m; the rig has 0.04 N m).
"""),
    code('''
h = loop.heldout_rmse_
print(f"held-out RMSE before: {h['before']:.4f} W")
print(f"held-out RMSE after: {h['after']:.4f} W")
for e in loop.effects_:
    print(f"effect found: {e.name} = {e.coefficient:.5f}")
print(f"RMSE on the new points: {(pred['error_W'] ** 2).mean() ** 0.5:.4f} W")
print(f"calibrated loss: {calibrated.total_mean_power_W:.4f} W")
print(f"uncalibrated loss: {plain.total_mean_power_W:.4f} W")'''),
]

NOTEBOOKS = {
    "01_my_joint_evaluate_optimize.ipynb": NB01,
    "02_pareto_gap_inertia.ipynb": NB02,
    "03_oil_grade_for_a_mission.ipynb": NB03,
    "04_rig_data_loop_predict.ipynb": NB04,
    "05_uncertainty.ipynb": NB05,
    "06_plan_rig.ipynb": NB06,
    "07_linear_actuator.ipynb": NB07,
}


def build(cells) -> nbformat.NotebookNode:
    """A notebook of these cells, kernel python3, no outputs."""
    nb = new_notebook(cells=cells)
    nb.metadata["kernelspec"] = {"display_name": "Python 3", "language": "python",
                                 "name": "python3"}
    nb.metadata["language_info"] = {"name": "python"}
    for i, cell in enumerate(nb.cells):  # stable ids: no churn in the diffs
        cell["id"] = f"cell-{i:02d}"
    return nb


def main(argv: list[str]) -> int:
    """Write every notebook next to this script."""
    for name, cells in NOTEBOOKS.items():
        nb = build(cells)
        nbformat.validate(nb)
        (HERE / name).write_text(nbformat.writes(nb) + "\n", encoding="utf-8")
        print(f"wrote examples/{name} ({len(cells)} cells)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
