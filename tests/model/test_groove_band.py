"""The groove band (model/groove_band.py), the smoothing study's laminar share and the
``groove_exponent_scale`` uncertain input."""

from __future__ import annotations

import json
from dataclasses import replace

import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.errors import InputError
from oilgap.model.groove_band import groove_band
from oilgap.model.io.case_io import seed_case
from oilgap.model.uncertain import apply_inputs, nominal_inputs
from oilgap.studies.smoothing.laminar import laminar_share


def _evaluate_json(capsys, *argv):
    assert main(["evaluate", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_groove_band_in_evaluate_json_where_laminar(capsys):
    doc = _evaluate_json(capsys)  # the seed's rated point: Re 27, Ta 5.5
    band = doc["groove_band"]
    assert band["Ta_peak"] < band["Ta_critical"]
    # laminar Couette in region 1: its loss is proportional to T^gamma, so removing the
    # factor divides region 1 by 4^0.566 = 2.1916 (by hand) and leaves region 2 alone
    r1, r2 = (r["mean_power_W"] for r in doc["regions"])
    assert band["groove_factor"] == pytest.approx(4.0**0.566, rel=1e-5)  # JSON: 6 digits
    assert band["theory_mean_power_W"] == pytest.approx(r1 / 4.0**0.566 + r2, rel=1e-4)
    assert band["theory_mean_power_W"] < doc["total_mean_power_W"]
    hot = _evaluate_json(capsys, "--temp-c", "60")  # VG22 at 60 degC: Ta ~ 150 > Ta_c
    assert hot["groove_band"] is None


def test_no_band_without_grooves_or_gamma():
    case = seed_case()
    assert groove_band(replace(case, friction=replace(case.friction, gamma=0.0))) is None
    assert groove_band(case).change_pct == pytest.approx(-49.0, abs=0.5)


def test_laminar_share_of_savings():
    case = seed_case()
    table = pd.DataFrame({"group": [0, 1, 2], "oil": ["none", "VG150", "VG22"],
                          "oil_temp_before_C": [float("nan"), 34.2, 90.0],
                          "oil_temp_after_C": [float("nan"), 30.0, 80.0],
                          "model_change_W": [float("nan"), -10.0, -2.0]})
    curves = pd.DataFrame(columns=["curve", "oil", "T", "oil_temp_C", "depth_m",
                                   "mean_power_W"])
    share = laminar_share(case, table, curves)
    assert list(share.rows["laminar"]) == [True, False]  # VG22 at 90 degC has vortices
    assert share.share_pct == pytest.approx(100 * 10 / 12, rel=1e-12)
    assert "83 %" in share.line()


def test_groove_exponent_scale_input():
    case = seed_case()
    assert nominal_inputs(case)["groove_exponent_scale"] == 1.0
    assert apply_inputs(case, {"groove_exponent_scale": 0.0}).friction.gamma == 0.0
    both = apply_inputs(case, {"gamma": 0.8, "groove_exponent_scale": 0.5})
    assert both.friction.gamma == pytest.approx(0.4, rel=1e-15)
    with pytest.raises(InputError, match="groove_exponent_scale"):
        apply_inputs(case, {"groove_exponent_scale": 1.5})
