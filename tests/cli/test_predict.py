"""Prediction with a fitted loop model: the caller's index, rows without power, steady new
conditions, ``oilgap predict`` round trip through loop.json, refusals."""

import json
import os

import numpy as np
import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.fluid_table import TableFluid
from oilgap.model.fluids import GasFluid
from oilgap.model.oils import Oil
from oilgap.optim.calibration import LoopEstimator
from oilgap.optim.calibration.model_io import (
    FittedModel,
    fluid_from_dict,
    fluid_to_dict,
    load_model,
)
from oilgap.studies.reporting import write_data_csv
from oilgap.studies.rigs.synth import SynthConfig, synthesize

CFG = SynthConfig(n_samples=200, effect="seal_coulomb_friction")
"""A small synthetic rig (2 oil-free + 8 oil runs of 200 samples) with a seal torque."""


@pytest.fixture(scope="module")
def rig(tmp_path_factory):
    d = tmp_path_factory.mktemp("rig")
    csv = write_data_csv(synthesize(CFG, seed=1), d / "rig.csv")
    est = LoopEstimator().fit(csv)
    return csv, est


def _fit_rows(est):
    """Input rows (0-based) of the fitted samples, in the samples' order."""
    return est.data_.frame["line"].to_numpy()[est.samples_.index] - 2


def test_predict_keeps_the_callers_index_and_needs_no_power(rig):
    csv, est = rig
    df = pd.read_csv(csv)
    assert [e.name for e in est.effects_] == ["seal_coulomb_friction"]
    ref = est.predict(df)
    assert ref.index.equals(df.index)
    rows = _fit_rows(est)
    assert np.array_equal(ref.to_numpy()[rows], est.pred_["with_effect"])
    free = df["oil"] == "none"
    assert ref[free].isna().all() and ref[~free].notna().all()
    assert (ref.attrs["reason"][free] == "oil-free row (no viscous loss to predict)").all()
    # no power column, no oil-free runs, rows shuffled under a string index
    new = df[~free].drop(columns=["power_W"]).sample(frac=1.0, random_state=4)
    new.index = [f"row-{i}" for i in new.index]
    got = est.predict(new)
    assert got.index.equals(new.index)
    expect = ref.loc[[int(i[4:]) for i in new.index]].to_numpy()
    assert np.allclose(got.to_numpy(), expect, rtol=1e-12, atol=0)


def test_steady_new_conditions_equal_the_fitted_law(rig):
    # a fitted sample's operating point as a steady row (no time_s, no run, no power):
    # the calibrated base model depends on speed, fluid state, gap and T only, so the
    # prediction equals the fit's with_T power at that sample
    csv, est = rig
    s = est.samples_
    pick = np.array([5, 300, 900, 1500])
    rows = pd.DataFrame({"speed_rpm": s.speed_rpm[pick], "temp_C": s.temp_C[pick],
                         "oil": s.oil[pick], "roughness_T": s.roughness_T[pick]},
                        index=["w", "x", "y", "z"])
    got = est.predict(rows, stage="with_T")
    assert list(got.index) == ["w", "x", "y", "z"]
    assert np.allclose(got.to_numpy(), est.pred_["with_T"][pick], rtol=1e-12)


def test_oilgap_predict_round_trip_through_loop_json(rig, tmp_path, capsys):
    csv, est = rig
    out = tmp_path / "o"
    assert main(["loop", str(csv), "--out", str(out), "--no-figures"]) == 0
    model = json.loads((out / "loop.json").read_text())["model"]
    assert model["effects"].keys() == {"seal_coulomb_friction"}
    pred = tmp_path / "pred.csv"
    assert main(["predict", str(csv), "--model", str(out / "loop.json"), "--out",
                 str(pred)]) == 0
    p = pd.read_csv(pred, keep_default_na=False, na_values=[""])
    raw = pd.read_csv(csv)
    assert list(p.columns[:len(raw.columns)]) == list(raw.columns) and len(p) == len(raw)
    rows = _fit_rows(est)
    visc = p["predicted_viscous_power_W"].to_numpy()
    ref = est.pred_["with_effect"]
    assert np.max(np.abs(visc[rows] - ref)) <= 1e-9 * np.max(np.abs(ref))
    # baseline + viscous: the baseline of the row's T, evaluated here on its own
    s = est.samples_
    base = np.empty(s.n)
    for T, b in est.baselines_.items():
        sel = s.roughness_T == T
        base[sel] = b.predict(s.omega[sel], s.domega_dt[sel], s.temp_C[sel])
    total = p["predicted_power_W"].to_numpy()[rows]
    assert np.allclose(total - visc[rows], base, rtol=1e-9, atol=1e-9)
    # the fitted model reproduces the measured electrical power to its noise (1 W)
    resid = raw["power_W"].to_numpy()[rows] - total
    assert np.sqrt(np.mean(resid ** 2)) < 1.2 * CFG.noise_power_W
    # the loaded model is the fitted one
    again = load_model(out / "loop.json").predict(raw)
    assert np.array_equal(again.to_numpy()[rows], visc[rows])


def test_predict_refuses_to_overwrite_and_bad_input(rig, tmp_path, capsys):
    csv, est = rig
    model = tmp_path / "loop.json"
    model.write_text(json.dumps({"rmse_W": {}, "model": FittedModel.from_estimator(est)
                                 .to_dict()}))
    pred = tmp_path / "p.csv"
    pred.write_text("keep me\n")
    args = ["predict", str(csv), "--model", str(model), "--out", str(pred)]
    assert main(args) == 2
    assert pred.read_text() == "keep me\n"
    assert main(args + ["--force"]) == 0
    assert pd.read_csv(pred)["predicted_viscous_power_W"].notna().sum() == 1600
    assert sorted(f.name for f in tmp_path.iterdir()) == ["loop.json", "p.csv"]  # no temp file
    umask = os.umask(0)
    os.umask(umask)
    assert pred.stat().st_mode & 0o777 == 0o666 & ~umask
    capsys.readouterr()
    old = tmp_path / "old.json"
    old.write_text(json.dumps({"rmse_W": {}}))                 # loop.json without a model
    free = tmp_path / "free.csv"
    pd.read_csv(csv).query("oil == 'none'").to_csv(free, index=False)
    for bad in (["predict", str(csv), "--model", str(old), "--out", str(tmp_path / "a.csv")],
                ["predict", str(csv), "--model", str(tmp_path / "no.json"), "--out",
                 str(tmp_path / "b.csv")],
                ["predict", str(free), "--model", str(model), "--out", str(tmp_path / "c.csv")],
                ["predict", str(csv), "--model", str(model), "--out", str(tmp_path / "d.txt")]):
        assert main(bad) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 4 and all(e.startswith("oilgap: error:") for e in err)
    assert "no 'model' block" in err[0] and "no row can be predicted" in err[2]


@pytest.mark.parametrize("fluid", [
    GasFluid("my gas", 0.028, 1.7e-5, 273.0, 110.0),           # trusted range up to inf
    Oil("my oil", 46.0, 6.8, 870.0, polymer_thickened=True),
    TableFluid("my table", (280.0, 300.0, 320.0), ((2e-5, 1e-5, 6e-6),), ((880.0, 870.0,
                                                                            860.0),)),
])
def test_fluids_survive_the_json_model_document(fluid):
    doc = json.loads(json.dumps(fluid_to_dict(fluid)))
    assert fluid_from_dict(doc) == fluid


def test_the_saved_model_records_its_thermal_mode_and_predict_uses_it(rig, tmp_path, capsys):
    """Issue 18: a calibrated model predicts under the thermal mode recorded in loop.json
    (the loop's, not the design tool's default), says so, and refuses a record its
    effects contradict."""
    csv, est = rig
    out = tmp_path / "o"
    assert main(["loop", str(csv), "--out", str(out), "--no-figures"]) == 0
    doc = json.loads((out / "loop.json").read_text())
    # no film_heating among the accepted effects: every term at the measured oil
    assert "film_heating" not in doc["model"]["effects"]
    assert doc["model"]["thermal_mode"] == "none"
    capsys.readouterr()
    assert main(["predict", str(csv), "--model", str(out / "loop.json"), "--out",
                 str(tmp_path / "p.csv")]) == 0
    assert "thermal     none (the mode recorded in" in capsys.readouterr().out
    # a model with a calibrated film records film; a hand edit that disagrees is refused
    film = dict(doc["model"], effects={**doc["model"]["effects"], "film_heating": 0.3},
                shapes={"film_heating": {"coefficient": "film_strength", "wall_floating": 0.0}},
                thermal_mode="film")
    assert FittedModel.from_dict(film).thermal_mode == "film"
    (tmp_path / "film.json").write_text(json.dumps({**doc, "model": film}))
    capsys.readouterr()
    assert main(["predict", str(csv), "--model", str(tmp_path / "film.json"), "--out",
                 str(tmp_path / "f.csv")]) == 0
    assert "film strength s = 0.3 of the smooth-film theory, wall condition w = 0" in \
        capsys.readouterr().out
    # an older loop.json's film_heating was a c in K/W, not the strength s: refused
    older = dict(film)
    del older["shapes"]
    with pytest.raises(Exception, match="film strength s"):
        FittedModel.from_dict(older)
    bad = dict(doc["model"], thermal_mode="film")
    with pytest.raises(Exception, match="model.thermal_mode"):
        FittedModel.from_dict(bad)
    # a file written before the record existed still reads (derived from its effects)
    old = {k: v for k, v in doc["model"].items() if k != "thermal_mode"}
    assert FittedModel.from_dict(old).thermal_mode == "none"
