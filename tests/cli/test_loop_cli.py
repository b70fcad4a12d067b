"""``oilgap synth`` and ``oilgap loop`` end to end, as a user runs them."""

import json

import pandas as pd

from oilgap.studies.cli import main

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
    assert set(doc["calibration"]) == {"C", "alpha", "beta", "gamma"}
    assert [e["name"] for e in doc["effects"]] == ["oil_inertia"]
    assert EFFECT_KEYS <= set(doc["effects"][0])
    assert (res / "report.md").read_text().startswith("# Measured-data loop report")
    for f in ("measured_vs_model.png", "residual_vs_speed.png", "residual_vs_time.png"):
        assert (res / f).stat().st_size > 10_000

    # the table form: error table, effects, before/after
    assert main(["loop", str(data), "--out", str(res), "--no-figures"]) == 0
    text = capsys.readouterr().out
    assert "error table" in text and "oil_inertia" in text and "held-out (LORO)" in text


def test_loop_on_clean_data_says_so(tmp_path, capsys):
    data = tmp_path / "clean.csv"
    assert main(["synth", "--seed", "5", "--out", str(data), "--viscous"]) == 0
    assert main(["loop", str(data), "--out", str(tmp_path / "r"), "--no-figures"]) == 0
    text = capsys.readouterr().out
    assert "no missing effect found" in text
    doc = json.loads((tmp_path / "r" / "loop.json").read_text())
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
