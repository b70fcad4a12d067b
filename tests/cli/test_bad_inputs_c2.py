"""Nothing silent in the data and in what the tool assumes (issue 12), as a user meets it:
gamma named in every header with its source, a default gamma announced; unit mistakes,
no rotation, duplicate headers and missing-value words in grids refused with one line;
override text counted, never replaced silently."""

import json

import numpy as np
import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.errors import SolverError
from oilgap.model.io.case_io import seed_case
from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.studies.rigs.synth import SynthConfig, synthesize

SEED_TOML = """name = "seed without gamma"
[region1]
T1_mm = 23.9
T2_mm = 25.4
T3_mm = 26.4
T4_mm = 27.9
length_mm = 14.76
[region2]
radius_mm = 22.0
length_mm = 14.24
gap_mm = 5.0
[oil]
name = "VG22"
[friction]
form = "bilgen-boulos"
"""
"""The seed joint (T = 4) with a [friction] table that gives no gamma."""

SMOOTH_TOML = SEED_TOML.replace("T1_mm = 23.9", "T1_mm = 25.4").replace("T4_mm = 27.9",
                                                                        "T4_mm = 26.4")
"""The same joint without grooves (T = 1): gamma does not matter there."""

GAMMA_DEFAULT = "gamma       0.566 (groove exponent of Eq. 8, T^gamma on region 1; from: " \
                "default (seed rig fit))"


def _run(capsys, argv):
    code = main(argv)
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return code, out, err.splitlines()


@pytest.fixture(scope="module")
def rig(tmp_path_factory):
    """Small viscous-power rig data (8 runs of 200 samples) as the synthetic rig makes it."""
    d = tmp_path_factory.mktemp("rig")
    df = synthesize(SynthConfig(n_samples=200, kind="viscous_power_W"), 0)
    df.to_csv(d / "rig.csv", index=False)
    return d / "rig.csv", df


# --------------------------------------------------------------------------- gamma


def test_a_grooved_case_without_gamma_gets_the_seed_fit_with_one_warning(tmp_path, capsys):
    case = tmp_path / "c.toml"
    case.write_text(SEED_TOML)
    code, out, err = _run(capsys, ["evaluate", str(case), "--thermal", "none"])
    assert code == 0 and len(err) == 1 and err[0].startswith("oilgap: warning: [friction] "
                                                             "gives no gamma")
    assert "0.566" in err[0] and "T = 4" in err[0]
    assert GAMMA_DEFAULT in out.splitlines()
    code, out, _ = _run(capsys, ["evaluate", str(case), "--thermal", "none", "--json"])
    doc = json.loads(out)
    assert (doc["gamma"], doc["gamma_source"]) == (0.566, "default (seed rig fit)")
    # the loss is the seed's (gamma = 0.566 given), not the grooves-free loss of gamma = 0
    _, seed_out, _ = _run(capsys, ["evaluate", "--thermal", "none", "--json"])
    seed = json.loads(seed_out)
    assert seed["gamma_source"] == "case"
    assert doc["total_mean_power_W"] == pytest.approx(seed["total_mean_power_W"], rel=1e-12)


def test_a_smooth_case_without_gamma_is_not_warned_but_still_named(tmp_path, capsys):
    case = tmp_path / "c.toml"
    case.write_text(SMOOTH_TOML)
    code, out, err = _run(capsys, ["evaluate", str(case), "--thermal", "none"])
    assert code == 0 and err == [] and GAMMA_DEFAULT in out.splitlines()


def test_optimize_names_gamma_in_text_and_json(tmp_path, capsys):
    case = tmp_path / "c.toml"
    case.write_text(SEED_TOML)
    code, out, err = _run(capsys, ["optimize", str(case), "--thermal", "none"])
    assert code == 0 and GAMMA_DEFAULT in out.splitlines()
    code, out, _ = _run(capsys, ["optimize", "--thermal", "none", "--json"])
    doc = json.loads(out)
    assert (doc["gamma"], doc["gamma_source"]) == (seed_case().friction.gamma, "case")


def test_sweep_names_gamma_and_its_empty_cells(tmp_path, capsys):
    grid = tmp_path / "grid.csv"
    grid.write_text("oil,oil_temp_C,gap_mm\nVG22,2,1.0\nVG32,,0.8\n")
    out_dir = tmp_path / "sw"
    code, out, err = _run(capsys, ["study", "sweep", str(grid), "--out", str(out_dir),
                                   "--workers", "1", "--no-progress", "--thermal", "none"])
    assert code == 0
    lines = out.splitlines()
    assert lines[1].startswith("gamma       0.566 (") and lines[1].endswith("from: case)")
    assert "empty cells (the base case's value): oil_temp_C 1" in lines
    md = (out_dir / "summary.md").read_text()
    assert "Groove exponent: gamma = 0.566 (case)." in md


# --------------------------------------------------------------------------- grid cells


@pytest.mark.parametrize("text, field, value", [
    ("oil,oil_temp_C\nVG22,2\nVG32,NA\n", "oil_temp_C", "NA"),
    ("oil,gap_mm\nVG22,nan\n", "gap_mm", "nan"),
    ("oil,gap_mm\nnull,1.0\n", "oil", "null"),
    ("oil,gap_mm,gap_mm\nVG22,1.0,1.1\n", "column", "gap_mm"),
])
def test_grid_missing_words_and_duplicate_columns_are_refused(tmp_path, capsys, text, field,
                                                              value):
    grid = tmp_path / "grid.csv"
    grid.write_text(text)
    code, out, err = _run(capsys, ["study", "sweep", str(grid), "--out", str(tmp_path / "sw"),
                                   "--workers", "1", "--no-progress"])
    assert code == 2 and out == "" and len(err) == 1
    assert err[0].startswith(f"oilgap: error: trade study: {field} = {value!r} is not allowed")
    assert not list((tmp_path / "sw").glob("*.csv")) and not (tmp_path / "sw" / "summary.md"
                                                                ).exists()


# --------------------------------------------------------------------------- loop data


def _bad(df: pd.DataFrame, how: str) -> pd.DataFrame:
    d = df.copy()
    if how == "kelvin":
        d["temp_C"] = d["temp_C"] + 273.15
    elif how == "no rotation":
        d["speed_rpm"] = 0.0
    elif how == "x100":
        d["speed_rpm"] = d["speed_rpm"] * 100
    elif how == "mW":
        d["viscous_power_W"] = d["viscous_power_W"] * 1e4
    return d


@pytest.mark.parametrize("how, field, words", [
    ("kelvin", "temp_C median", "looks like kelvin (subtract 273.15"),
    ("no rotation", "speed_rpm", "no rotation in the data"),
    ("x100", "speed_rpm peak", "x100?"),
    ("mW", "viscous_power_W peak", "in mW"),
])
def test_loop_refuses_unit_mistakes_with_one_line(tmp_path, capsys, rig, how, field, words):
    data = tmp_path / "bad.csv"
    _bad(rig[1], how).to_csv(data, index=False)
    out_dir = tmp_path / "lo"
    code, out, err = _run(capsys, ["loop", str(data), "--out", str(out_dir), "--no-figures"])
    assert code == 2 and out == "" and len(err) == 1
    assert err[0].startswith(f"oilgap: error: {data}: {field} = ") and words in err[0]
    assert not (out_dir / "loop.json").exists() and not (out_dir / "report.md").exists()


def test_loop_refuses_a_duplicate_header(tmp_path, capsys, rig):
    data = tmp_path / "dup.csv"
    text = rig[0].read_text().splitlines()
    text[0] = text[0].replace("roughness_T", "temp_C")
    data.write_text("\n".join(text + ["x,1"]) + "\n")  # ragged: pandas reads it, not pyarrow
    code, out, err = _run(capsys, ["loop", str(data), "--out", str(tmp_path / "lo")])
    assert code == 2 and len(err) == 1
    assert err[0] == f"oilgap: error: {data}: columns = ['temp_C'] is not allowed; column " \
                     "names must be unique"


def test_loop_counts_override_text_names_gamma_and_predict_too(tmp_path, capsys, rig):
    df = rig[1].copy()
    gap = np.full(len(df), "", dtype=object)
    gap[[10, 11, 12]] = "n/a mm"
    df["gap_mm"] = gap
    data = tmp_path / "gap.csv"
    df.to_csv(data, index=False)
    out_dir = tmp_path / "lo"
    code, out, err = _run(capsys, ["loop", str(data), "--out", str(out_dir), "--no-figures",
                                   "--base", "eq6"])
    assert code == 0
    lines = out.splitlines()
    at = next(i for i, x in enumerate(lines) if x.startswith("data "))  # after the answer
    data_line = " ".join(x.strip() for x in lines[at:at + 3])  # wrapped at 100 characters
    assert f"{len(df) - 3} oil samples" in data_line and "3 dropped" in data_line
    assert any(x.strip().startswith("dropped 3 x gap_mm is text") for x in lines)
    assert any(x.strip() == f"gap_mm empty in {len(df) - 3} of {len(df) - 3} oil rows: the "
               "case's region-1 clearance used there" for x in lines)
    assert any(x.startswith("gamma       0.566 (the rig case's, from: case;") for x in lines)
    doc = json.loads((out_dir / "loop.json").read_text())
    assert (doc["gamma"], doc["gamma_source"]) == (0.566, "case")
    assert doc["data"]["dropped"][0]["count"] == 3 and doc["not_identifiable"] == []
    assert "Rig case: seed joint" in (out_dir / "report.md").read_text()
    code, out, _ = _run(capsys, ["predict", str(rig[0]), "--model", str(out_dir / "loop.json"),
                                 "--out", str(tmp_path / "p.csv")])
    assert code == 0 and out.splitlines()[-1].startswith("gamma       0.56")


def test_speed_in_rad_s_is_named_after_the_fit(tmp_path, capsys, rig):
    data = tmp_path / "rads.csv"
    rig[1].assign(speed_rpm=rig[1]["speed_rpm"] * np.pi / 30).to_csv(data, index=False)
    code, out, err = _run(capsys, ["loop", str(data), "--out", str(tmp_path / "lo"),
                                   "--no-figures", "--base", "eq6"])
    assert code == 0 and len(err) == 1
    assert err[0].startswith(f"oilgap: warning: {data}: the calibrated viscous loss is 9")
    assert "if speed_rpm is in rad/s, multiply it by 9.549" in err[0]
    doc = json.loads((tmp_path / "lo" / "loop.json").read_text())
    assert len(doc["unit_hints"]) == 1 and "rad/s" in doc["unit_hints"][0]


def test_a_solver_failure_on_data_in_the_wrong_unit_names_the_unit(tmp_path, capsys, rig,
                                                                   monkeypatch):
    def fail(self, *a, **k):  # a failure after the calibration (stage 7)
        raise SolverError("did not converge")

    monkeypatch.setattr(LoopEstimator, "_intervals", fail)
    data = tmp_path / "rads.csv"
    rig[1].assign(speed_rpm=rig[1]["speed_rpm"] * np.pi / 30).to_csv(data, index=False)
    code, out, err = _run(capsys, ["loop", str(data), "--out", str(tmp_path / "lo"), "--base",
                                   "eq6"])
    assert code == 2 and out == "" and len(err) == 1
    assert err[0].startswith(f"oilgap: error: data = '{data}' is not allowed; the calibrated")
    assert "rad/s" in err[0] and err[0].endswith("the fit then failed (did not converge)")
    code, out, err = _run(capsys, ["loop", str(rig[0]), "--out", str(tmp_path / "lo2"),
                                   "--base", "eq6"])
    assert code == 4 and err == ["oilgap: solver failure: did not converge"]
