"""One calibrated model, every command (issue 25 item 1): ``oilgap loop --write-case`` writes
the rig case with ``[calibration] model`` and evaluating it equals ``evaluate --model`` on the
rig case to 1e-12; what the model carries and what it names as not carried; the domain
warning; ``--model`` on optimize and the studies' parsers."""

import json
import sys
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from oilgap._calibrated import with_model
from oilgap._evaluate import as_case, evaluate, with_operating
from oilgap._loop import predict
from oilgap.cli import main
from oilgap.cli.parsers import build_parser
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.errors import OilgapWarning
from oilgap.optim.calibration.calibrated_case import calibrate_case
from oilgap.optim.calibration.model_io import load_model

sys.path.insert(0, str(Path(__file__).parents[1] / "optim" / "calibration"))
from test_honest_cv import AIR_RIG, air_frame, wendt_cm  # noqa: E402


@pytest.fixture(scope="module")
def looped(tmp_path_factory):
    d = tmp_path_factory.mktemp("calibrated")
    data = d / "air.csv"
    air_frame(wendt_cm, (0.009, 0.02, 0.039)).to_csv(data, index=False)
    rig = d / "rig.toml"
    rig.write_text(AIR_RIG)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        assert main(["loop", str(data), "--case", str(rig), "--cv-by", "gap_mm", "--base",
                     "branches", "--out", str(d / "o"), "--no-figures", "--write-case",
                     str(d / "cal.toml")]) == 0
    return d


def test_written_case_equals_evaluate_with_model(looped, capsys):
    d = looped
    text = (d / "cal.toml").read_text()
    assert '[calibration]\nmodel = "o/loop.json"' in text
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        direct = evaluate(with_model(as_case(d / "rig.toml"), d / "o" / "loop.json")[0])
        written = evaluate(as_case(d / "cal.toml"))
        plain = evaluate(as_case(d / "rig.toml"))
    a, b = direct.total_mean_power_W, written.total_mean_power_W
    assert abs(a - b) <= 1e-12 * abs(a)
    assert abs(a - plain.total_mean_power_W) > 1e-3 * abs(a)  # the model changes the loss
    # the law evaluated is the model's final law, every digit
    law = load_model(d / "o" / "loop.json").laws["with_effect"]
    assert as_case(d / "cal.toml").friction == law


def test_evaluate_model_names_it_and_prints_both_losses(looped, capsys):
    d = looped
    capsys.readouterr()
    assert main(["evaluate", str(d / "rig.toml"), "--model", str(d / "o" / "loop.json"),
                 "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    m = doc["model"]
    assert m["path"].endswith("loop.json") and "air.csv" in m["data"] and m["fitted"]
    assert m["base"] == "branches" and m["carried"][0].startswith("friction law branches")
    assert m["loss_calibrated_W"] == pytest.approx(doc["total_mean_power_W"], rel=1e-6)
    assert m["loss_uncalibrated_W"] != pytest.approx(m["loss_calibrated_W"], rel=1e-3)
    # the rig case's oil (VG22 at 2 degC by default) lies far outside the fitted air
    assert any(x.startswith("nu_cSt") for x in m["outside_domain"])


def test_rig_only_and_design_effects_are_named(looped):
    fitted = load_model(looped / "o" / "loop.json")
    fitted.effects = {"sensor_delay": 0.3, "seal_coulomb_friction": 0.04}
    cal = calibrate_case(as_case(looped / "rig.toml"), fitted)
    why = dict(cal.not_carried)
    assert "rig's power sensor" in why["sensor_delay (0.3)"]
    assert "no seal term" in why["seal_coulomb_friction (0.04)"]


@pytest.mark.parametrize("argv", [["evaluate"], ["optimize"], ["study", "pareto"],
                                  ["study", "oil-grade"], ["study", "smoothing"],
                                  ["study", "sweep", "grid.csv"]])
def test_model_option_on_every_design_command(argv):
    args = build_parser().parse_args([*argv, "--model", "m/loop.json"])
    assert args.model == "m/loop.json"


def test_predict_at_a_rig_point_equals_evaluate_with_model(looped):
    # one steady rig point: air at 20 degC, 1 atm, smooth walls, the rig's own gap, 6000 rpm
    model = looped / "o" / "loop.json"
    row = pd.DataFrame({"speed_rpm": [6000.0], "temp_C": [20.0], "oil": ["air"],
                        "roughness_T": [1.0]})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        p = float(predict(model, row)["predicted_viscous_power_W"].iloc[0])
        rig = as_case(looped / "rig.toml")
        case = with_operating(rig, "air", None, 20.0, 0.0)   # the rig point: sea level
        w = 6000.0 * np.pi / 30.0
        case = replace(case, duty_cycle=DutyCycle(np.arange(8.0), np.full(8, w), "constant"))
        e = evaluate(with_model(case, model)[0]).total_mean_power_W
    assert abs(p - e) <= 1e-12 * abs(p)


def test_facade_model_keyword_is_the_same_fold(looped):
    import oilgap as og

    d = looped
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        a = og.evaluate(d / "rig.toml", model=d / "o" / "loop.json").total_mean_power_W
        b = og.evaluate(d / "cal.toml").total_mean_power_W
    assert abs(a - b) <= 1e-12 * abs(a)


def test_a_case_carrying_its_model_prints_the_model_lines_of_model(looped, capsys):
    # evaluate cal.toml ([calibration] model = "o/loop.json") prints the same model lines
    # as evaluate rig.toml --model o/loop.json, numbers equal; only the path is as resolved
    d = looped
    out = {}
    for key, argv in (("model", ["evaluate", str(d / "rig.toml"), "--model",
                                 str(d / "o" / "loop.json")]),
                      ("case", ["evaluate", str(d / "cal.toml")])):
        capsys.readouterr()
        assert main(argv) == 0
        cap = capsys.readouterr()
        i = cap.out.index("\nmodel       ")
        out[key] = (cap.out[i:].splitlines()[2:],
                    [x for x in cap.err.splitlines() if "outside the model's domain" in x])
    lines, warned = out["case"]
    assert lines == out["model"][0] and any("W calibrated, " in x for x in lines)
    assert any("carried: friction law branches" in x for x in lines)
    # the domain warning names where the model came from
    assert warned and all("warning: [calibration] model " in x for x in warned)
    assert out["model"][1] and all("warning: --model " in x for x in out["model"][1])
