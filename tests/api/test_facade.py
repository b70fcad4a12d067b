"""The façade (``import oilgap as og``) against the module-level API it wraps: the same
numbers, units in the frame's columns, axes from plot, a table in the notebook display,
rounded JSON, a path and a DesignCase alike, bad input named."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from matplotlib.axes import Axes

import oilgap as og
from oilgap.model.errors import InputError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.serialize import round_sig
from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.optim.calibration.model_io import PREDICTED_VISCOUS
from oilgap.optim.design import DesignProblem
from oilgap.optim.multiobjective import hypervolume_2d
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.rigs.synth import SynthConfig, synthesize
from oilgap.studies.settings import INLINE, SweepSettings

THERMAL_CASE = Path(__file__).parents[1] / "golden" / "data" / "seed_thermal.toml"


def _floats(doc):
    if isinstance(doc, dict):
        for v in doc.values():
            yield from _floats(v)
    elif isinstance(doc, list):
        for v in doc:
            yield from _floats(v)
    elif isinstance(doc, float):
        yield doc


def _common(view, columns, exact=()):
    """The views' shared methods: units in the columns, axes, an HTML table, rounded JSON
    (but the blocks in ``exact``: the fitted model keeps its digits), the summary as
    str()."""
    frame = view.to_frame()
    assert set(columns) <= set(frame.columns)
    assert isinstance(view.plot(), Axes)
    assert "<table" in view._repr_html_()
    doc = json.loads(view.to_json())
    rounded = {k: v for k, v in doc.items() if k not in exact}
    assert all(x == round_sig(x) for x in _floats(rounded))
    assert str(view) == view.summary() and view.summary()
    return frame, doc


def test_import_is_light():
    import subprocess
    code = ("import sys, oilgap; print(oilgap.__version__); "
            "print([m for m in ('pandas', 'dask', 'casadi') if m in sys.modules])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=60).stdout.split("\n")
    assert out[1] == "[]" and out[0]
    assert {"evaluate", "optimize", "Loop", "synth", "sweep"} <= set(og.__all__)


def test_evaluate_is_evaluate_case():
    case = seed_case()
    ev = og.evaluate(case, thermal="none", oil="VG22", depth_m=1000.0)
    from dataclasses import replace

    from oilgap.model.case import OperatingPoint
    from oilgap.model.oils import get_oil
    ref = evaluate_case(replace(case, oil=get_oil("VG22"),
                                operating=OperatingPoint(1000.0, case.operating.oil_temp_C)),
                        thermal="none")
    frame, doc = _common(ev, ["mean_power_W", "gap_mm", "radius_mm", "length_mm"])
    for r in ref.regions:
        assert frame.loc[r.name, "mean_power_W"] == r.mean_power_W
        assert frame.loc[r.name, "gap_mm"] == pytest.approx(r.gap_m * 1e3, rel=1e-12)
    assert doc["total_mean_power_W"] == round_sig(ref.total_mean_power_W)
    assert doc["gamma_source"] == case.gamma_source and isinstance(doc["defaults"], list)


def test_path_and_case_give_the_same_result():
    a = og.evaluate(str(THERMAL_CASE), thermal="film")
    b = og.evaluate(og.read_case(THERMAL_CASE), thermal="film")
    assert a.to_dict() == b.to_dict()
    c = og.evaluate(THERMAL_CASE, sea_temp_C=6.0)
    assert c.raw.sea_temp_C == 6.0 and c.raw.thermal_mode == "bulk"  # the default


@pytest.mark.parametrize(("call", "field"), [
    (lambda: og.evaluate(3), "case"),
    (lambda: og.evaluate(oil_temp_C=float("nan")), "oil_temp_C"),
    (lambda: og.evaluate(THERMAL_CASE, oil_temp_C=5.0), "oil_temp_C"),
    (lambda: og.evaluate(sea_temp_C=3.0), "sea_temp_C"),
    (lambda: og.evaluate(laminar_law="laminar"), "laminar_law"),
    (lambda: og.optimize(starts=0), "starts"),
    (lambda: og.optimize(torque_min_Nm=-1.0), "torque_min_Nm"),
    (lambda: og.synth(strength=1.0), "strength"),
    (lambda: og.synth(seed=-1), "seed"),
    (lambda: og.sweep(pd.DataFrame({"oil": ["VG22"]}), oils=3), "oils"),
])
def test_bad_input_names_the_field(call, field):
    with pytest.raises(InputError) as e:
        call()
    assert e.value.field == field


def test_optimize_is_design_problem_solve(tmp_path):
    case = seed_case()
    opt = og.optimize(case, thermal="none", starts=1)
    ref = DesignProblem(case).solve(starts=1)
    frame, doc = _common(opt, ["mean_power_W", "delta_mm", "R_mm", "L_mm", "inertia_ratio"])
    assert frame.loc["optimal", "mean_power_W"] == pytest.approx(ref.optimal.mean_power_W,
                                                                 rel=1e-9)
    assert frame.loc["optimal", "delta_mm"] == pytest.approx(ref.optimal.delta_m * 1e3,
                                                             rel=1e-7)
    assert frame.loc["optimal", "mean_power_exact_W"] == \
        ref.evaluate()[1].total_mean_power_W
    assert doc["thermal_mode"] == "none"
    path = tmp_path / "opt.json"
    opt.to_json(path)
    assert json.loads(path.read_text()) == doc
    with pytest.raises(InputError):  # never overwritten without being asked
        opt.to_json(path)


def test_synth_loop_and_predict():
    df = og.synth(roughness=(4,), viscous=True, seed=2)
    ref = synthesize(SynthConfig(roughness=(4.0,), kind="viscous_power_W"), seed=2)
    pd.testing.assert_frame_equal(df, ref)
    loop = og.Loop(effects="seal_coulomb_friction").fit(df)
    frame, doc = _common(loop, ["measured_mean_W", "model_before_mean_W",
                                "model_after_mean_W", "rmse_with_T_W"], exact=("model",))
    measured = df.groupby("run")["viscous_power_W"].mean()
    for run, row in frame.iterrows():
        assert row["measured_mean_W"] == pytest.approx(measured[run], rel=1e-12)
    rows = df.drop(columns=["viscous_power_W", "time_s"]).iloc[::500]  # steady points
    pred = loop.predict(rows)
    assert list(pred.columns[:len(rows.columns)]) == list(rows.columns)
    np.testing.assert_allclose(pred[PREDICTED_VISCOUS].to_numpy(),
                               LoopEstimator.predict(loop, rows).to_numpy(), rtol=1e-12)
    assert doc["rmse_W"]["with_T"] == round_sig(loop.rmse_["with_T"])


def test_loop_report_refuses_an_existing_report(tmp_path):
    df = og.synth(roughness=(4,), viscous=True, seed=2)
    loop = og.Loop(effects="seal_coulomb_friction").fit(df)
    paths = loop.report(tmp_path / "rep", figures=False)
    assert Path(paths["json"]).exists() and Path(paths["report"]).exists()
    with pytest.raises(InputError):
        loop.report(tmp_path / "rep", figures=False)
    loop.report(tmp_path / "rep", figures=False, force=True)


def test_sweep_is_run_grid(tmp_path):
    grid = pd.DataFrame({"oil": ["VG22", "VG32", "VG46"], "oil_temp_C": [2.0, 10.0, 20.0]})
    sw = og.sweep(grid, thermal="none", workers=1, progress=False, out=tmp_path / "sw")
    ref = run_grid(grid, seed_case(), SweepSettings(thermal="none"), INLINE)
    frame, doc = _common(sw, ["mean_power_W", "oil_temp_C"])
    np.testing.assert_array_equal(frame["mean_power_W"], ref["mean_power_W"])
    assert doc["ok"] == 3 and (tmp_path / "sw" / "results.csv").exists()


def test_pareto_and_oil_grade():
    p = og.pareto(points=50)
    frame, doc = _common(p, ["delta_mm", "mean_power_W", "inertia_ratio"])
    gap = frame[(frame["front"] == "gap") & (frame["status"] == "ok")]
    hv = hypervolume_2d(gap[["delta_mm", "mean_power_W"]].to_numpy(), p.raw.reference_point)
    assert doc["hypervolume_mm_W"] == round_sig(hv)
    g = og.oil_grade(thermal="none", n_depth=2, n_temp=2,
                     mission=[{"depth_m": 3000.0, "oil_temp_C": 2.0, "fraction": 1.0}])
    frame, doc = _common(g, ["oil", "mission_mean_power_W"])
    rec = g.recommended
    assert rec in set(frame["oil"]) and doc["recommended"] == rec
    # the mission is one segment: its mean power is the grade's evaluate at that point
    ev = evaluate_case(seed_case(), oil_temp_C=2.0, depth_m=3000.0, thermal="none")
    seed_oil = seed_case().oil.name
    row = frame[frame["oil"] == seed_oil]
    if len(row):
        assert math.isclose(row["mission_mean_power_W"].iloc[0], ev.total_mean_power_W,
                            rel_tol=1e-9)
