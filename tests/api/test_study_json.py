"""``--json`` on every study (one JSON document on stdout: the numbers with units in the
keys, gamma, the thermal mode, the defaults, the files written), the CLI printing the
façade's own summary, and the views' figures drawn on a notebook's axes."""

import json
import shutil
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
import pytest

matplotlib.use("Agg")

import oilgap as og  # noqa: E402
from oilgap.cli import main  # noqa: E402
from oilgap.model.errors import InputError  # noqa: E402
from oilgap.model.io.serialize import round_sig  # noqa: E402

MY_JOINT = Path(__file__).parents[2] / "examples" / "my_joint.toml"
GRID = "oil,oil_temp_C,gap_mm\nVG22,2,1.0\nVG32,10,0.8\n"


def _json(capsys, argv):
    """Run the command in-process; its stdout must be one JSON document."""
    assert main(argv) == 0
    doc = json.loads(capsys.readouterr().out)
    assert {"gamma", "gamma_source", "thermal_mode", "files", "defaults"} <= set(doc)
    for d in doc["defaults"]:
        assert set(d) == {"field", "value", "unit", "source"}
    assert doc["files"] and all(Path(f).exists() for f in doc["files"])
    return doc


@pytest.fixture
def joint(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    shutil.copy(MY_JOINT, tmp_path / "my.toml")
    return og.read_case(tmp_path / "my.toml")


def test_pareto_json_is_the_facades_document(capsys, joint):
    doc = _json(capsys, ["study", "pareto", "my.toml", "--points", "50", "--out", "p",
                         "--json"])
    # my_joint has [thermal]: the fronts under its default, bulk, as evaluate's
    assert doc["case"] == joint.name and doc["thermal_mode"] == "bulk"
    assert doc["thermal_default"] is True
    gap = [r for r in doc["gap_front"] if r["status"] == "ok"]
    assert doc["points"] == 50 and {"delta_mm", "mean_power_W", "inertia_ratio"} <= set(gap[0])
    # the hypervolume of the printed front against its reference point, by hand
    pts = sorted((r["delta_mm"], r["mean_power_W"]) for r in gap)
    ref = doc["reference_point"]
    hv, best = 0.0, ref["mean_power_W"]
    for (x, y), nxt in zip(pts, [p[0] for p in pts[1:]] + [ref["delta_mm"]], strict=True):
        best = min(best, y)
        hv += (nxt - x) * (ref["mean_power_W"] - best)
    assert doc["hypervolume_mm_W"] == pytest.approx(hv, rel=1e-4)
    assert any(d["field"] == "pareto.reference_point" for d in doc["defaults"])


def test_oil_grade_json_and_scheduler_reaches_the_grid(capsys, joint):
    doc = _json(capsys, ["study", "oil-grade", "my.toml", "--thermal", "none", "--out", "o",
                         "--json"])
    names = [g["oil"] for g in doc["grades"]]
    assert doc["recommended"] in names and "mission_mean_power_W" in doc["grades"][0]
    assert doc["gamma"] == round_sig(joint.friction.gamma)
    with pytest.raises(InputError, match="scheduler"):  # passed on to run_grid, checked there
        og.oil_grade(joint, thermal="none", scheduler="bogus", n_depth=2, n_temp=2)


def test_smoothing_json_on_a_case(capsys, joint):
    doc = _json(capsys, ["study", "smoothing", "my.toml", "--out", "s", "--json"])
    assert doc["seed_rig"] is False and doc["fit"] is None and doc["table4"] is None
    saving = doc["plateau"][0]
    assert saving["saving_to_T1_W"] == pytest.approx(saving["P_T_case_W"] - saving["P_T1_W"],
                                                     rel=1e-5)


def test_sweep_json_and_text_are_the_views(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "grid.csv").write_text(GRID)
    doc = _json(capsys, ["study", "sweep", "grid.csv", "--workers", "1", "--no-progress",
                         "--thermal", "none", "--out", "w", "--json"])
    seed = og.evaluate(thermal="none").total_mean_power_W
    assert doc["base_mean_power_W"] == round_sig(seed)
    assert doc["ok"] == 2 and [r["oil"] for r in doc["results"]] == ["VG22", "VG32"]
    assert main(["study", "sweep", "grid.csv", "--workers", "1", "--no-progress",
                 "--thermal", "none", "--out", "w", "--resume"]) == 0
    text = capsys.readouterr().out
    view = og.sweep("grid.csv", thermal="none", workers=1, progress=False, out="w",
                    resume=True)
    strip = [ln for ln in view.summary().splitlines() if " in " not in ln]  # the timing
    assert strip == [ln for ln in text.splitlines() if " in " not in ln]
    assert "2 reused" in text and "mean power" in text


def test_plots_are_the_studies_figures_on_given_axes(joint):
    import matplotlib.pyplot as plt

    sm = og.smoothing(joint)
    ax = sm.plot()
    assert ax.get_title().startswith(joint.name) and ax.get_legend() is not None
    df = og.synth(roughness=(4,), viscous=True, seed=2)
    loop = og.Loop(effects="seal_coulomb_friction").fit(df)
    n_runs = df["run"].nunique()
    for kind, panels in (("windows", n_runs), ("overview", n_runs), ("residuals", 2)):
        fig = plt.figure()
        ax = loop.plot(fig.add_subplot(), kind=kind)
        assert ax.figure is fig and len(fig.axes) == panels
        plt.close(fig)
    with pytest.raises(InputError, match="kind"):
        loop.plot(kind="nope")
    grid = og.sweep(pd.DataFrame({"oil": ["VG22", "VG32"], "gap_mm": [1.0, 0.8]}),
                    thermal="none", workers=1, progress=False)
    ax = grid.plot()
    assert "Sweep of the grid" in ax.get_title() + ax.figure.get_suptitle()
    assert np.isfinite(grid.to_dict()["base_mean_power_W"])
    plt.close("all")
