"""The Reynolds and Taylor ranges of a fitted model (issue 25 item 1): stored in loop.json,
and a case outside them warned with the variable and both ranges; a model file written
before them still loads and says they are unknown.

Hand computations (seed Eqs. 3-4): ``Re = |omega| R delta / nu``, ``Ta = Re (delta/R)^0.5``
with the rig's R = 0.1 m, the runs' gap and viscosity columns, and for the case its peak
speed 3000 rpm, its 0.5 mm gap and its oil's viscosity at the oil temperature.
"""

import json
import math
import sys
import tomllib
from pathlib import Path

import pytest

from oilgap.model.io.case_io import case_from_dict
from oilgap.optim.calibration import LoopEstimator
from oilgap.optim.calibration.calibrated_case import calibrate_case
from oilgap.optim.calibration.model_io import FittedModel

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "model" / "effects"))
from test_domains import RIG, laminar_runs  # noqa: E402

R = 0.1


@pytest.fixture(scope="module")
def slow_fit():
    df = laminar_runs(rpm_max=300.0)   # 100..300 rpm, gaps 0.5 and 1 mm, 100 cSt
    est = LoopEstimator(case=case_from_dict(tomllib.loads(RIG)), base="eq6", cv_by="gap_mm",
                        effects=["seal_coulomb_friction"]).fit(df)
    return df, est


def hand_re(rpm, gap_m, nu_m2_s):
    return rpm * math.pi / 30 * R * gap_m / nu_m2_s


def test_loop_json_stores_the_reynolds_and_taylor_ranges(slow_fit):
    df, est = slow_fit
    rng = json.loads(json.dumps(est.to_dict()["model"]))["fitted_range"]
    lo = hand_re(100.0, 0.5e-3, 100e-6)    # 5.236
    hi = hand_re(300.0, 1e-3, 100e-6)      # 31.42
    assert rng["reynolds"] == pytest.approx([lo, hi], rel=1e-9)
    assert rng["taylor"] == pytest.approx([lo * math.sqrt(0.005), hi * math.sqrt(0.01)],
                                          rel=1e-9)


def test_a_case_outside_them_is_warned_with_both_ranges(slow_fit):
    _, est = slow_fit
    case = case_from_dict(tomllib.loads(RIG))      # seed's duty cycle: 3000 rpm peak
    nu = case.oil.kinematic_viscosity_cSt(case.operating.oil_temp_C,
                                          case.operating.depth_m) * 1e-6
    re = hand_re(3000.0, 0.5e-3, nu)               # 54.1 against the fitted 5.24..31.4
    ta = re * math.sqrt(0.005)
    dom = calibrate_case(case, est.fitted_model()).domain
    assert f"reynolds 0..{re:.4g} outside the fitted 5.236..31.42" in dom
    assert f"taylor 0..{ta:.4g} outside the fitted 0.3702..3.142" in dom


def test_an_old_model_file_without_them_loads_and_says_unknown(slow_fit):
    _, est = slow_fit
    doc = est.to_dict()["model"]
    for k in ("reynolds", "taylor"):
        del doc["fitted_range"][k]
    old = FittedModel.from_dict(json.loads(json.dumps(doc)))
    dom = calibrate_case(case_from_dict(tomllib.loads(RIG)), old).domain
    assert dom[-1] == ("reynolds and taylor ranges unknown: the model file predates them "
                       "(run oilgap loop again to record them)")
    assert not any(d.startswith(("reynolds 0", "taylor 0")) for d in dom)
