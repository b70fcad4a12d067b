"""The figures an engineer reads: the sweep's layout follows the grid's dimensions, the
loop shows whole runs and windows of a few cycles, legends wherever several lines are."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
import pytest
from matplotlib.collections import QuadMesh
from matplotlib.figure import Figure

from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.studies.io.files import MARKER
from oilgap.studies.loop import figures as lf
from oilgap.studies.loop.report import write_report
from oilgap.studies.rigs.synth import SynthConfig, synthesize
from oilgap.studies.sweep_figures import choose_layout, plot_sweep, write_sweep_figure


def _result(grid: pd.DataFrame) -> pd.DataFrame:
    """A result frame as the grid engine writes it (grid columns, status, power): the
    power is a hand-made function of the factors, so the heatmap's cells can be checked."""
    res = grid.copy()
    res["status"] = "ok"
    power = np.full(len(res), 10.0)
    for c in ("gap_mm", "oil_temp_C", "depth_m"):
        if c in res:
            power += res[c].to_numpy(float)
    res["thermal_mode"] = "none"
    res["mean_power_W"] = power
    return res


def _product(**levels) -> pd.DataFrame:
    return pd.DataFrame(list(itertools.product(*levels.values())), columns=list(levels))


def _legends(axes) -> int:
    return sum(ax.get_legend() is not None for ax in axes)


def test_one_factor_is_a_line_with_a_legend():
    res = _result(_product(gap_mm=[0.5, 1.0, 1.5, 2.0]))
    fig, axes = plot_sweep(res, base_power=12.0, base_name="seed", mode="evaluate",
                           grid_name="g1.csv")
    assert choose_layout(res).kind == "line" and len(axes) == 1
    line = axes[0].get_lines()[0]
    np.testing.assert_allclose(line.get_xdata(), [0.5, 1.0, 1.5, 2.0])
    np.testing.assert_allclose(line.get_ydata(), [10.5, 11.0, 11.5, 12.0])
    assert _legends(axes) == 1  # the power and the base case
    assert "[mm]" in axes[0].get_xlabel() and "[W]" in axes[0].get_ylabel()
    assert all(w in axes[0].get_title() for w in ("g1.csv", "evaluate", "thermal mode none"))


def test_two_factors_on_a_regular_grid_are_a_heatmap_with_a_colour_bar():
    res = _result(_product(gap_mm=[0.5, 1.0, 1.5], oil_temp_C=[10.0, 20.0]))
    fig, axes = plot_sweep(res, base_power=25.0)
    assert choose_layout(res).kind == "heatmap" and len(axes) == 1
    mesh = [c for c in axes[0].collections if isinstance(c, QuadMesh)]
    assert len(mesh) == 1
    # rows: oil temperature 10, 20; columns: gap 0.5, 1.0, 1.5 (power = 10 + gap + temp)
    np.testing.assert_allclose(mesh[0].get_array().reshape(2, 3),
                               [[20.5, 21.0, 21.5], [30.5, 31.0, 31.5]])
    cbar = [a for a in fig.axes if a not in axes]
    assert len(cbar) == 1 and "[W]" in cbar[0].get_ylabel()


def test_irregular_two_factors_are_a_scatter_and_a_category_gives_lines():
    rng = np.random.default_rng(0)
    res = _result(pd.DataFrame({"gap_mm": rng.uniform(0.4, 2, 40),
                                "oil_temp_C": rng.uniform(5, 40, 40)}))
    assert choose_layout(res).kind == "scatter"
    res = _result(_product(oil=["VG100", "VG15", "VG22"], gap_mm=[0.5, 1.0, 1.5]))
    fig, axes = plot_sweep(res, base_power=11.0)
    assert choose_layout(res).kind == "lines" and _legends(axes) == 1
    labels = [t.get_text() for t in axes[0].get_legend().get_texts()]
    assert labels[:3] == ["VG15", "VG22", "VG100"]  # the grades in their natural order


@pytest.mark.parametrize(("levels", "panels"), [
    ({"oil": ["VG22", "VG32", "VG68"], "gap_mm": [0.5, 1.0, 1.5], "oil_temp_C": [10, 20]}, 3),
    ({"oil": ["VG22", "VG32"], "gap_mm": [0.5, 1.0, 1.5], "oil_temp_C": [10, 25, 40],
      "depth_m": [0, 3000, 6000, 9000]}, 6),
])
def test_three_and_four_factors_are_small_multiples_on_one_colour_scale(levels, panels):
    res = _result(_product(**levels))
    layout = choose_layout(res)
    fig, axes = plot_sweep(res, base_power=20.0)
    assert layout.kind == "facets" and layout.panel == "heatmap"
    assert layout.facets[0].name == "oil" and len(axes) == panels == layout.n_panels
    meshes = [c for ax in axes for c in ax.collections if isinstance(c, QuadMesh)]
    assert len(meshes) == panels
    assert len({(m.norm.vmin, m.norm.vmax) for m in meshes}) == 1  # one shared scale
    assert len(fig.axes) == panels + 1  # and one colour bar
    assert fig._suptitle is not None


def test_many_irregular_factors_are_the_power_against_each(tmp_path):
    rng = np.random.default_rng(1)
    res = _result(pd.DataFrame({c: rng.uniform(1, 2, 100) for c in
                                ("gap_mm", "oil_temp_C", "depth_m", "length_mm")}))
    fig, axes = plot_sweep(res)
    assert choose_layout(res).kind == "pairwise" and len(axes) == 4
    assert _legends(axes) >= 1
    # a short list of cases is drawn row by row, each labelled by its values
    res = _result(pd.DataFrame({"oil": ["VG22", "VG32", "VG15"], "oil_temp_C": [2, 10, None],
                                "gap_mm": [1.0, 0.8, 1.2]}))
    assert choose_layout(res).kind == "cases"
    path = write_sweep_figure(res, 30.0, "seed", tmp_path / "sweep.png")
    assert path.stat().st_size > 10_000 and sorted(p.name for p in tmp_path.iterdir()) == \
        ["sweep.png"]  # written atomically: no temporary file left


def test_sweep_draws_on_a_given_axes():
    fig = Figure()
    ax = fig.add_subplot(1, 2, 2)
    res = _result(_product(oil=["VG22", "VG32"], gap_mm=[0.5, 1.0], oil_temp_C=[10, 20]))
    got, axes = plot_sweep(res, ax=ax)
    assert got is fig and len(axes) == 2 and ax not in fig.axes


# --------------------------------------------------------------------------- the loop


@pytest.fixture(scope="module")
def loop():
    """A small synthetic rig with a seal's Coulomb friction, fitted (about 1 s)."""
    df = synthesize(SynthConfig(kind="viscous_power_W", n_samples=300,
                                effect="seal_coulomb_friction"), seed=3)
    return LoopEstimator(base="eq6", effects=["seal_coulomb_friction"]).fit(df)


def test_the_window_spans_the_last_cycles_of_the_speed():
    t = np.arange(0, 300, 0.2)
    speed = 3000 * np.sin(0.1 * np.pi * t)  # period 20 s
    assert lf.cycle_period_s(t, speed) == pytest.approx(20.0, abs=0.2)
    c = lf.LoopCurves(run_names=("a",), run_code=np.zeros(len(t), int), time_s=t,
                      has_time=True, speed_rpm=speed, temp_C=np.full(len(t), 20.0),
                      measured_W=speed**2 / 1e5, oil=np.array(["VG22"] * len(t)),
                      roughness_T=np.full(len(t), 4.0),
                      predictions={"without_T": speed**2 / 2e5, "with_T": speed**2 / 1e5})
    lo, hi = lf.window_of(c, 0, cycles=2)
    assert hi == pytest.approx(299.8) and hi - lo == pytest.approx(40.0, abs=0.5)
    assert lf.cycle_period_s(t, np.full(len(t), 1000.0)) is None  # no cycle: whole run


def test_loop_overview_and_windows_one_panel_per_run_with_legends(loop):
    n = len(loop.samples_.run_names)
    over = lf.plot_overview(loop)
    win = lf.plot_windows(loop)
    assert len(over) == len(win) == n and _legends(over) == _legends(win) == 1
    labels = [t.get_text() for t in win[0].get_legend().get_texts()]
    assert labels == ["measured", "base model (calibrated, with T)", "with effect (after)"]
    assert len({ax.get_ylim() for ax in win}) == 1  # one y scale
    c = lf.LoopCurves.of(loop)
    for ax, i in zip(win, range(n), strict=True):  # the window holds two speed cycles
        x = ax.get_lines()[0].get_xdata()
        lo, hi = lf.window_of(c, i)
        assert x.min() >= lo and x.max() <= hi and len(x) < np.sum(c.run_code == i)
    res = lf.plot_residuals(loop, "time")
    assert len(res[1].get_legend().get_texts()) == n  # each run named
    assert "VG" in res[1].get_legend().get_texts()[0].get_text()
    assert _legends(lf.plot_residuals(loop, "speed")) == 2


def test_loop_report_writes_every_named_figure(loop, tmp_path, monkeypatch):
    monkeypatch.setattr("oilgap.studies.loop.report_figures.DPI", 20)  # small files, fast
    paths = write_report(loop, tmp_path)
    names = lf.figure_names(len(loop.samples_.run_names))
    assert [p.name for p in paths["figures"]] == names
    assert names[:3] == ["measured_vs_model.png", "residual_vs_speed.png",
                         "residual_vs_time.png"] and "measured_vs_model_window.png" in names
    assert not list(tmp_path.glob("*.tmp*")) and not (tmp_path / MARKER).exists()
    report = (tmp_path / "report.md").read_text()
    assert all(f"![{f}]({f})" in report for f in names)


def test_many_runs_go_on_several_pages():
    assert lf.pages(8) == [list(range(8))]
    assert [len(p) for p in lf.pages(30)] == [10, 10, 10]
    names = lf.figure_names(30, every=True)  # every run's pages (above 24 runs: on request)
    assert names.count("measured_vs_model_window_3.png") == 1 and len(names) == 3 + 2 + 3
