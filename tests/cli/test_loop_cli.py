"""``oilgap synth`` and ``oilgap loop`` end to end, as a user runs them."""

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.effects import TIME_DEPENDENT
from oilgap.model.io.case_io import read_case_toml
from oilgap.model.regions import joint_geometry, region_power
from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration.candidates import STEADY_POINT_STATUS

ISSUE_KEYS = {"rmse_W": {"without_T", "with_T", "with_effect"},
              "heldout_rmse_W": {"before", "after"}}
PER_RUN_KEYS = {"run", "oil", "roughness_T", "rmse_without_T_W", "rmse_with_T_W",
                "rmse_with_effect_W"}
EFFECT_KEYS = {"name", "formula", "coefficient", "ci_low", "ci_high", "heldout_gain_pct"}


def test_synth_then_loop(tmp_path, capsys):
    data = tmp_path / "rig.csv"
    assert main(["synth", "--effect", "oil_inertia", "--seed", "2", "--out", str(data)]) == 0
    out = capsys.readouterr()
    assert "wrote" in out.out and "oil_inertia" in out.err
    df = pd.read_csv(data)
    assert len(df) == 15000 and "oil_inertia" not in data.read_text()

    res = tmp_path / "res"
    assert main(["loop", str(data), "--out", str(res), "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    doc = json.loads((res / "loop.json").read_text())
    assert printed == doc
    for k, sub in ISSUE_KEYS.items():
        assert set(doc[k]) == sub
    assert all(PER_RUN_KEYS <= set(r) for r in doc["per_run"]) and len(doc["per_run"]) == 8
    assert set(doc["calibration"]) == {"scale", "alpha", "gamma"}  # Eq. 6 chosen
    # the default base "auto": each candidate after its own effect search
    rows = doc["base_selection"]["candidates"]
    assert [r["base"] for r in rows] == ["eq6", "branches", "eq6-taylor"]
    assert doc["base"] == "eq6" and [r["base"] for r in rows if r["chosen"]] == ["eq6"]
    assert [e["name"] for e in doc["effects"]] == ["oil_inertia"]
    assert EFFECT_KEYS <= set(doc["effects"][0])
    assert (res / "report.md").read_text().startswith("# Measured-data loop report")
    # what the loop filled in: no --case (the seed rig), the library, the options left out;
    # the seed rig's motor and design bounds are not the loop's business
    fields = {d["field"]: d for d in doc["defaults"]}
    assert {"loop.case", "loop.effects", "loop.margin", "loop.cv_by", "loop.base"} <= set(fields)
    assert fields["loop.margin"]["value"] == 0.1 and fields["loop.cv_by"]["value"] == "run"
    assert not any(f.startswith(("motor.", "bounds.")) for f in fields)
    for f in ("measured_vs_model.png", "residual_vs_speed.png", "residual_vs_time.png"):
        assert (res / f).stat().st_size > 10_000

    # the table form: error table, effects, before/after
    assert main(["loop", str(data), "--out", str(res), "--no-figures", "--force", "--base",
                 "eq6"]) == 0
    text = capsys.readouterr().out
    assert "error table" in text and "oil_inertia" in text and "held-out (by run)" in text


def test_loop_on_clean_data_says_so(tmp_path, capsys):
    data = tmp_path / "clean.csv"
    assert main(["synth", "--seed", "5", "--out", str(data), "--viscous"]) == 0
    capsys.readouterr()  # the loop's stdout alone below
    assert main(["loop", str(data), "--out", str(tmp_path / "r"), "--no-figures"]) == 0
    text = capsys.readouterr().out
    assert "no missing effect found" in text
    # the answer first (issue 26): the held-out error before -> after
    held = json.loads((tmp_path / "r" / "loop.json").read_text())["heldout_rmse_W"]
    assert text.startswith(f"held-out RMSE {held['before']:.4g} W before -> "
                           f"{held['after']:.4g} W after")
    assert text.splitlines()[1].startswith("effects     none")
    doc = json.loads((tmp_path / "r" / "loop.json").read_text())
    assert "loop.case" in text and "loop.margin = 0.1" in text  # the defaults header line
    assert doc["effects"] == [] and doc["heldout_rmse_W"]["before"] == \
        doc["heldout_rmse_W"]["after"]


def test_cli_refusals_exit_2(tmp_path, capsys):
    assert main(["synth", "--strength", "2"]) == 2
    assert main(["synth", "--roughness", "4,x"]) == 2
    assert main(["synth", "--out", str(tmp_path / "no" / "x.csv")]) == 2
    bad = tmp_path / "bad.csv"
    bad.write_text("run,time_s\n1,2\n")
    assert main(["loop", str(bad)]) == 2
    assert main(["loop", str(bad), "--case", str(bad)]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and err.count("oilgap: error:") == 5


def test_list_effects(capsys):
    assert main(["synth", "--list-effects"]) == 0
    out = capsys.readouterr().out
    assert "thermal_lag" in out and "shear_thinning" in out


# --------------------------------------------------------------------------- steady points


RIG_NO_BEARING = Path(__file__).parents[1] / "data" / "rig_no_bearing.toml"


def _air_like(path, with_run=True):
    """Steady points like the issue's air data: a smooth cylinder (T = 1) in air at three
    gaps, one run per gap, per-row nu_cSt, density_kg_m3 and gap_mm, viscous_power_W, a
    rig without region 2. The power is the model's own (smooth Eq. 6, scale 1, alpha 0.3)
    with 2 % noise, so the fit must find scale ~ 1, alpha ~ 0.3 and no effect."""
    case = read_case_toml(RIG_NO_BEARING)
    law = FrictionLaw(form="smooth", laminar_law=case.friction.laminar_law)
    rng = np.random.default_rng(0)
    rows = []
    for gap_mm in (0.3, 0.6, 1.2):
        rpm = np.linspace(300.0, 6000.0, 15)
        region = joint_geometry(case, roughness_T=1.0, gap1_m=gap_mm * 1e-3).regions[0]
        p = region_power(region, rpm * np.pi / 30.0, 15.06e-6, 1.204, law)
        p = p * (1.0 + 0.02 * rng.standard_normal(p.size))
        rows.append(pd.DataFrame({"run": f"gap {gap_mm}", "speed_rpm": rpm, "temp_C": 20.0,
                                  "oil": "air", "roughness_T": 1.0, "viscous_power_W": p,
                                  "nu_cSt": 15.06, "density_kg_m3": 1.204, "gap_mm": gap_mm}))
    df = pd.concat(rows, ignore_index=True)
    (df if with_run else df.drop(columns=["run"])).to_csv(path, index=False)
    return path


def test_steady_air_data_one_run_per_gap_leave_one_gap_out(tmp_path, capsys):
    data = _air_like(tmp_path / "air.csv")
    out = tmp_path / "o"
    # --base eq6: the data are Eq. 6's own, and this checks that its scale and alpha come
    # back (the default compares eq6 with branches by held-out error: tests/optim/
    # calibration/test_honest_cv.py)
    assert main(["loop", str(data), "--case", str(RIG_NO_BEARING), "--cv-by", "gap_mm",
                 "--base", "eq6", "--out", str(out), "--no-figures"]) == 0
    captured = capsys.readouterr()
    assert "Traceback" not in captured.err
    doc = json.loads((out / "loop.json").read_text())
    assert doc["effects"] == []
    assert doc["model"]["has_time"] is False and doc["model"]["cv_by"] == "gap_mm"
    cal = doc["calibration"]
    assert abs(cal["alpha"] - 0.3) < 0.05 and abs(cal["scale"] - 1.0) < 0.15
    assert np.isfinite(doc["heldout_rmse_W"]["after"])
    status = {c["name"]: c["status"] for c in doc["candidates"]}
    for name in TIME_DEPENDENT:                       # no time: not candidates, and said so
        assert status[name] == STEADY_POINT_STATUS
    assert "steady-point data" in captured.out
    # without a run column the default groups are the setups (fluid, T, gap): the same
    # three groups, so the same held-out errors
    bare = _air_like(tmp_path / "air_norun.csv", with_run=False)
    assert main(["loop", str(bare), "--case", str(RIG_NO_BEARING), "--base", "eq6", "--out",
                 str(tmp_path / "o2"), "--no-figures"]) == 0
    doc2 = json.loads((tmp_path / "o2" / "loop.json").read_text())
    assert doc2["heldout_rmse_W"] == pytest.approx(doc["heldout_rmse_W"], rel=1e-9)


def test_cv_by_refuses_a_missing_column_or_one_group(tmp_path, capsys):
    data = _air_like(tmp_path / "air.csv")
    base = ["loop", str(data), "--case", str(RIG_NO_BEARING), "--no-figures", "--out",
            str(tmp_path / "o")]
    assert main(base + ["--cv-by", "gap"]) == 2
    assert main(base + ["--cv-by", "oil"]) == 2        # one fluid: one group
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all(e.startswith("oilgap: error:") for e in err)
    assert "not a column of the data" in err[0] and "has 1 group" in err[1]
