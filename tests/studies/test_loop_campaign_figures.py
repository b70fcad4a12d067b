"""Issue 26: a campaign's loop report summarises its figures (the worst runs, a capped grid
of small multiples) instead of drawing every run's pages; every run's on request."""

from types import SimpleNamespace

import numpy as np
import pytest

import oilgap.studies.loop.figures as lf
from oilgap.model.errors import InputError
from oilgap.studies.loop.report_figures import figure_mode, worst_runs


def test_up_to_the_cap_every_run_above_it_a_summary():
    assert lf.figure_names(24) == lf.figure_names(24, every=True)  # golden loops: unchanged
    assert len(lf.figure_names(24)) == 3 + 1 + 2
    assert lf.figure_names(670) == [lf.OVERVIEW, lf.SPEED, lf.TIME, lf.GRID, lf.WINDOW]
    every = lf.figure_names(670, every=True)
    assert len(every) == 3 + 2 * len(lf.pages(670)) - 1 and len(lf.pages(670)) == 56


def test_grid_spreads_its_runs_over_all_of_them():
    runs = lf.grid_runs(670)
    assert len(runs) == lf.GRID_MAX and runs[0] == 0 and runs[-1] == 669
    gaps = np.diff(runs)
    assert gaps.min() >= 13 and gaps.max() <= 15  # 669 / 47 = 14.2 runs apart
    assert lf.grid_runs(10) == list(range(10))


def test_worst_runs_by_held_out_error_after():
    per_run = [{"run": f"r{i}", "heldout_rmse_after_W": e, "rmse_with_effect_W": 0.5}
               for i, e in enumerate([1.0, 3.0, float("nan"), 2.0])]
    est = SimpleNamespace(per_run_=per_run,
                          samples_=SimpleNamespace(run_names=[f"r{i}" for i in range(4)]))
    assert worst_runs(est, 3) == [1, 3, 0]  # the run not held out ranks by its in-sample 0.5


@pytest.mark.parametrize("given, mode", [(True, "summary"), (False, "none"), ("all", "all")])
def test_figure_mode(given, mode):
    assert figure_mode(given) == mode


def test_figure_mode_refuses_other_words():
    with pytest.raises(InputError, match="figures"):
        figure_mode("every")


def test_grid_draws_one_panel_per_run_on_one_scale():
    n, m = 60, 50
    t = np.tile(np.arange(m, dtype=float), n)
    code = np.repeat(np.arange(n), m)
    meas = np.sin(t / 5.0) + code
    c = lf.LoopCurves(run_names=tuple(f"run{i}" for i in range(n)), run_code=code, time_s=t,
                      has_time=True, speed_rpm=np.sin(t), temp_C=np.full(n * m, 20.0),
                      measured_W=meas, oil=np.full(n * m, "VG22"),
                      roughness_T=np.full(n * m, 4.0),
                      predictions={"with_T": meas + 0.1})
    axs = lf.plot_grid(c)
    assert len(axs) == lf.GRID_MAX
    assert [a.get_title() for a in axs[:2]] == ["run0", "run1"]
    assert axs[0].get_ylim() == axs[-1].get_ylim()  # shared y: runs compare at a glance
