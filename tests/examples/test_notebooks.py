"""The example notebooks of ``examples/`` executed as a user would run them (issue 13).

Each notebook runs in a fresh ``python3`` kernel (ipykernel's own kernelspec, no
``ipykernel install`` needed) in a temporary folder holding a copy of it and of the
example inputs, with matplotlib on Agg and its outputs sent to that folder
(``OILGAP_EXAMPLES_OUT``). No cell may raise. The numbers its last cell prints are
then checked against the module-level API (``oilgap.model``, ``oilgap.optim``,
``oilgap.studies``) computed here, not against values copied from a run.
"""

from __future__ import annotations

import importlib.util
import re
import shutil
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import nbformat
import numpy as np
import pandas as pd
import pytest
from nbclient import NotebookClient

from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml
from oilgap.optim.calibration import LoopEstimator
from oilgap.optim.design import DesignProblem
from oilgap.optim.design.heating import compare_heating
from oilgap.studies import pareto
from oilgap.studies.oil_grade import study as oil_grade
from oilgap.studies.settings import OilGradeSettings, ParetoSettings, UncertaintySettings
from oilgap.studies.uncertainty import run as uncertainty_run

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
INPUTS = ("my_joint.toml", "mission.csv", "rig_runs.csv", "rig_new_points.csv",
          "linear_joint.toml")
CELL_TIMEOUT_S = 120
LINE = re.compile(r"^(?P<key>[^:\n]+): (?P<value>[-+]?\d[\d.eE+-]*|[A-Za-z]\w*)\b", re.M)


def execute(name: str, folder: Path, monkeypatch) -> dict[str, str]:
    """Run notebook ``name`` in ``folder``; the ``key: value`` lines of its last cell."""
    for f in (name, *INPUTS):
        shutil.copy(EXAMPLES / f, folder / f)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    monkeypatch.setenv("OILGAP_EXAMPLES_OUT", str(folder / "out"))
    nb = nbformat.read(folder / name, as_version=4)
    t0 = time.perf_counter()
    NotebookClient(nb, timeout=CELL_TIMEOUT_S, kernel_name="python3",
                   resources={"metadata": {"path": str(folder)}}).execute()
    print(f"{name}: {time.perf_counter() - t0:.1f} s")
    text = "".join(o.get("text", "") for o in nb.cells[-1].outputs if o["output_type"] == "stream")
    return {m["key"].strip(): m["value"] for m in LINE.finditer(text)}


def number(found: dict[str, str], key: str) -> float:
    assert key in found, f"{key!r} not printed by the last cell: {found}"
    return float(found[key])


def printed(found: dict[str, str], key: str, value: float, rel: float = 1e-6):
    """The printed number equals ``value`` to its printed digits (4 decimals) or ``rel``."""
    assert number(found, key) == pytest.approx(value, rel=rel, abs=1e-4), key


def case():
    return read_case_toml(EXAMPLES / "my_joint.toml")


def test_notebooks_are_saved_without_outputs():
    names = sorted(p.name for p in EXAMPLES.glob("*.ipynb"))
    assert names == ["01_my_joint_evaluate_optimize.ipynb", "02_pareto_gap_inertia.ipynb",
                     "03_oil_grade_for_a_mission.ipynb", "04_rig_data_loop_predict.ipynb",
                     "05_uncertainty.ipynb", "06_plan_rig.ipynb",
                     "07_linear_actuator.ipynb"]
    for name in names:
        nb = nbformat.read(EXAMPLES / name, as_version=4)
        nbformat.validate(nb)
        assert nb.metadata["kernelspec"]["name"] == "python3"
        for cell in nb.cells:
            if cell.cell_type == "code":
                assert cell.outputs == [] and cell.execution_count is None, name


def test_notebooks_are_what_their_generator_writes():
    # examples/make_notebooks.py is the source: a notebook edited by hand would drift from it
    spec = importlib.util.spec_from_file_location("make_notebooks", EXAMPLES / "make_notebooks.py")
    gen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(gen)
    for name, cells in gen.NOTEBOOKS.items():
        written = (EXAMPLES / name).read_text(encoding="utf-8")
        assert written == nbformat.writes(gen.build(cells)) + "\n", name


def test_python3_kernelspec_comes_with_ipykernel():
    # a fresh interpreter finds the kernel without `python -m ipykernel install --user`
    out = subprocess.run([sys.executable, "-c", "from jupyter_client.kernelspec import "
                          "KernelSpecManager as K; print(K().get_kernel_spec('python3')"
                          ".resource_dir)"], capture_output=True, text=True, check=True)
    assert out.stdout.strip()


def test_01_evaluate_and_optimize(tmp_path, monkeypatch):
    found = execute("01_my_joint_evaluate_optimize.ipynb", tmp_path, monkeypatch)
    c = case()
    before = evaluate_case(c, thermal=None).total_mean_power_W  # bulk: the case's default
    heated = compare_heating(DesignProblem(c, thermal=None)).heated
    after = evaluate_case(heated.to_case(), thermal=None).total_mean_power_W
    printed(found, "mean loss as designed", before)
    # the notebook's optimum went through a TOML file (6 significant digits)
    printed(found, "mean loss optimized", after, rel=1e-4)
    assert after < 0.6 * before
    assert (tmp_path / "out" / "01_my_joint" / "my_joint_opt.toml").is_file()


def test_02_pareto(tmp_path, monkeypatch):
    found = execute("02_pareto_gap_inertia.ipynb", tmp_path, monkeypatch)
    r = pareto.run(case=case(), settings=ParetoSettings(points=50))
    gap = r.gap_front[r.gap_front["status"] == "ok"]
    assert number(found, "gap front points") == len(gap)
    printed(found, "least loss on the gap front", gap["mean_power_W"].min())
    printed(found, "hypervolume", r.hypervolume)


def test_03_oil_grade(tmp_path, monkeypatch):
    found = execute("03_oil_grade_for_a_mission.ipynb", tmp_path, monkeypatch)
    r = oil_grade.run(case=case(), mission=oil_grade.read_mission_csv(EXAMPLES / "mission.csv"),
                      settings=OilGradeSettings(thermal=None, depth_range_m=(0.0, 4500.0),
                                                sea_temp_range_C=(0.0, 30.0), n_depth=10,
                                                n_temp=7))
    assert found["recommended"] == r.recommended
    energy = r.table.set_index("oil").loc[r.recommended, "mission_energy_Wh"]
    printed(found, "mission energy of the recommended grade", energy)


def test_04_loop_and_predict(tmp_path, monkeypatch):
    found = execute("04_rig_data_loop_predict.ipynb", tmp_path, monkeypatch)
    est = LoopEstimator(case=case()).fit(EXAMPLES / "rig_runs.csv")
    h = est.heldout_rmse_
    printed(found, "held-out RMSE before", h["before"])
    printed(found, "held-out RMSE after", h["after"])
    assert h["after"] < 0.5 * h["before"]  # the loop found what the rig hid
    assert [e.name for e in est.effects_] == ["seal_coulomb_friction"]
    new = pd.read_csv(EXAMPLES / "rig_new_points.csv")
    table = est.fitted_model().predict_table(new)
    rmse = float(np.sqrt(np.mean((table["predicted_power_W"] - new["power_W"]) ** 2)))
    printed(found, "RMSE on the new points", rmse)
    assert rmse < 2.0  # the rig's noise is 1 W: VG46, never run, is predicted to the noise
    # the calibrated law folded into the joint: the model's final law in the case
    joint = replace(case(), friction=est.fitted_model().laws["with_effect"])
    printed(found, "calibrated loss", evaluate_case(joint).total_mean_power_W)
    printed(found, "uncalibrated loss", evaluate_case(case()).total_mean_power_W)


def test_05_uncertainty(tmp_path, monkeypatch):
    found = execute("05_uncertainty.ipynb", tmp_path, monkeypatch)
    c = case()
    # the nominal loss by the scalar path (bulk: the case's default), not the study's
    printed(found, "nominal loss", evaluate_case(c, thermal=None).total_mean_power_W)
    r = uncertainty_run(case=c, settings=UncertaintySettings(samples=1024, sobol_samples=256))
    printed(found, "p95 of the loss", r.statistic("p95"))
    assert found["largest total index"] == r.sobol.sort_values("ST").iloc[-1]["input"]
    assert number(found, "p95 of the loss") > number(found, "nominal loss")
    assert (tmp_path / "out" / "05_uncertainty" / "defaults" / "summary.md").is_file()


def test_06_plan_rig(tmp_path, monkeypatch):
    from oilgap.studies.plan.settings import PlanSettings
    from oilgap.studies.plan.study import make_plan

    found = execute("06_plan_rig.ipynb", tmp_path, monkeypatch)
    r = make_plan(PlanSettings(oils=("VG150", "VG1000"), bath_C=(25.0,), profiles=("sine",),
                               duration_s=40.0, runs=6,
                               effects=("thermal_lag", "taylor_vortex_onset")))
    assert number(found, "plan runs") == 6
    printed(found, "expected gamma sd plan", r.plan.sd["gamma"], rel=1e-5)
    printed(found, "expected gamma sd naive", r.naive.sd["gamma"], rel=1e-5)
    assert (tmp_path / "out" / "06_plan_rig" / "plan" / "plan.csv").is_file()
    # one rehearsal each: the loop's widths within 1.5x of the plan's (one seed scatters)
    for tag, ev in (("plan", r.plan), ("naive", r.naive)):
        width = ev.interval["gamma"][1] - ev.interval["gamma"][0]
        assert number(found, f"loop gamma width {tag}") < 2.5 * width


def test_07_linear_actuator(tmp_path, monkeypatch):
    from oilgap.optim.design.linear import linear_design_case, solve_linear_design
    found = execute("07_linear_actuator.ipynb", tmp_path, monkeypatch)
    c = read_case_toml(EXAMPLES / "linear_joint.toml")
    d = solve_linear_design(c, "none")
    printed(found, "mean loss as designed", evaluate_case(c, thermal="none").total_mean_power_W)
    printed(found, "mean loss optimized",
            evaluate_case(linear_design_case(c, d.x_mm), thermal="none").total_mean_power_W)
    printed(found, "lead optimized", d.x_mm[0])
