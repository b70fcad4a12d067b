"""``oilgap study uncertainty`` and ``og.uncertainty``: the seed case with small samples,
the JSON document, the files, the defaults with their sources, bad input in one line."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

import oilgap as og
from oilgap.cli import main
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.case_write import case_to_dict, dumps_toml

SMALL = ["--samples", "64", "--sobol-samples", "32"]


def test_seed_case_prints_percentiles_sobol_table_and_default_sources(tmp_path, capsys):
    out = tmp_path / "u"
    assert main(["study", "uncertainty", *SMALL, "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "p5" in text and "p50" in text and "p95" in text
    head = text.splitlines()[:5]  # the percentiles first (issue 26), as statistics.csv
    stats = dict(line.split(",") for line in
                 (out / "uncertainty_statistics.csv").read_text().splitlines()[1:])
    assert head[0].startswith("mean loss over") and "p95" in head[1]
    assert f"{float(stats['p95']):.3f} W" in head[2]
    assert "Sobol' indices (SALib" in text and "nu40_factor" in text and "gamma" in text
    assert "uncertainty.nu40_factor = uniform(low = 0.9, high = 1.1) (ISO 3448" in text
    assert "oilgap study smoothing" in text  # gamma's source
    for name in ("uncertainty_samples.csv", "uncertainty_statistics.csv",
                 "uncertainty_inputs.csv", "uncertainty_histogram.png",
                 "uncertainty_tornado.png", "summary.md", "provenance.json"):
        assert (out / name).is_file(), name


def test_json_document_matches_the_facade(tmp_path, capsys):
    assert main(["study", "uncertainty", *SMALL, "--no-sobol", "--json",
                 "--out", str(tmp_path / "j")]) == 0
    doc = json.loads(capsys.readouterr().out)
    r = og.uncertainty(samples=64, sobol=False)
    st = doc["statistics_W"]
    assert st["p95"] == pytest.approx(r.statistic("p95"), rel=1e-5)
    assert st["p5"] < st["p50"] < st["p95"]
    assert doc["uncertainty"]["source"].startswith("defaults")
    assert {d["field"] for d in doc["defaults"]} >= {"uncertainty.nu40_factor",
                                                     "uncertainty.gamma"}
    assert [i["input"] for i in doc["inputs"]] == list(r.to_frame()["input"])
    assert "S1" not in r.to_frame() and r.sobol is None
    # ISO 3448's band on nu40 carried to the seed's 2 degC (test_uncertain_grade.py)
    assert doc["viscosity_carried"][0] == "nu40 x0.9..1.1 (nu100 held) -> nu(2 degC) -26 %/+31 %"


def test_case_table_replaces_the_defaults(tmp_path, capsys):
    doc = case_to_dict(seed_case())
    doc["uncertainty"] = {"oil_temp_C": {"dist": "normal", "mean_C": 2.0, "sd_K": 1.5}}
    p = tmp_path / "c.toml"
    p.write_text(dumps_toml(doc))
    r = og.uncertainty(p, samples=64, sobol_samples=32)
    assert r.spec.names == ("oil_temp_C",)
    assert not any(d["field"].startswith("uncertainty.gamma") for d in r.defaults)
    # colder oil is thicker: the loss at the temperature's p5 exceeds that at its p95
    t = r.tornado.iloc[0]
    assert t["loss_low_W"] > r.nominal_W > t["loss_high_W"]
    assert math.isclose(r.sobol["ST"].iloc[0], 1.0, abs_tol=0.1)  # the only input


@pytest.mark.parametrize("argv, needle", [
    (["--samples", "1000"], "samples = 1000 is not allowed; a power of 2"),
    (["--thermal", "bulk"], "[thermal]"),
    (["--model", "missing.json"], "--model"),
    (["--confidence", "2"], "confidence"),
])
def test_bad_input_is_one_line_exit_2(argv, needle, capsys, tmp_path):
    assert main(["study", "uncertainty", *argv, "--out", str(tmp_path / "b")]) == 2
    err = capsys.readouterr().err
    assert needle in err and "Traceback" not in err and len(err.strip().split("\n")) == 1


def test_a_loop_json_supplies_gamma_and_scale_correlated(capsys, tmp_path):
    # the golden loop's fit: gamma and the friction scale with jackknife intervals and
    # corr(scale, gamma) of the Jacobian columns +0.912 -> parameters' -0.912
    path = Path(__file__).parents[1] / "golden" / "data" / "loop_clean" / "loop.json"
    r = og.uncertainty(model=path, samples=64, sobol=False)
    assert set(r.spec.names) == {"gamma", "friction_scale"}
    c = r.spec.correlation
    assert c[0][1] == pytest.approx(-0.912, abs=1e-3)
    assert any("alpha" in n for n in r.spec.notes)
    lo, hi = 0.563818, 0.567228  # loop.json's calibration_with_effect_ci95 of gamma
    assert r.spec["gamma"].sd == pytest.approx((hi - lo) / 2 / 2.365, rel=1e-3)  # t(.975, 7)
