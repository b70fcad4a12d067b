"""The loop on a linear actuator's rig data (issue 29): rows carry ``rod_velocity_m_s``,
the motor's speed follows from the lead, and the loop's forward model adds the screw, the
rod guide and the passages to the clearance. Data made from those laws (per sample, at
the oils table's state) is fitted to its rounding; the same rows fitted as a rotary joint
(the elements missing) are not."""

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import oilgap as og
from oilgap.model.elements import BearingElement, joint_elements
from oilgap.model.errors import InputError
from oilgap.model.oils import get_oil
from oilgap.model.regions import joint_regions, region_power
from oilgap.model.units import celsius_to_kelvin
from oilgap.optim.calibration import LoopEstimator

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "linear_joint.toml"


@pytest.fixture(scope="module")
def rig():
    case = og.read_case(EXAMPLE)
    rows = []
    for oil in ("VG10", "VG15"):
        for t in (5.0, 20.0, 35.0):
            nu, _, rho = get_oil(oil).properties(celsius_to_kelvin(t), 0.0)
            for v in np.linspace(0.01, 0.12, 12):
                w = 2 * math.pi * v / case.linear.lead_m
                p = region_power(joint_regions(case)[0], w, nu, rho, case.friction)
                p += sum(e.power(w, nu, rho) for e in joint_elements(case)
                         if not isinstance(e, BearingElement))
                rows.append({"rod_velocity_m_s": v, "temp_C": t, "oil": oil,
                             "roughness_T": 5.0, "viscous_power_W": round(float(p), 6)})
    return case, pd.DataFrame(rows)


@pytest.fixture(scope="module")
def fitted(rig):
    case, df = rig
    return LoopEstimator(base="eq6", case=case, effects=["seal_coulomb_friction"]).fit(df)


def test_the_loop_fits_rod_velocity_data_through_the_elements(rig, fitted):
    case, df = rig
    est = fitted
    assert est.heldout_rmse_["before"] < 2e-3 * df["viscous_power_W"].mean()
    # the motor's speed is 60 v/lead: 0.12 m/s on a 5 mm lead is 1440 rpm
    assert est.samples_.speed_rpm.max() == pytest.approx(1440.0)
    rotary = replace(case, linear=None)
    as_rotary = df.rename(columns={"rod_velocity_m_s": "speed_rpm"}).assign(
        speed_rpm=lambda d: 60 * d["speed_rpm"] / case.linear.lead_m)
    bad = LoopEstimator(base="eq6", case=rotary, effects=["seal_coulomb_friction"]).fit(as_rotary)
    # the laminar passages and the laminar gap both go as mu omega^2: the friction scale
    # takes most of the missing terms, the screw's (nu n)^(2/3) and the rest stay
    assert bad.heldout_rmse_["before"] > 20 * est.heldout_rmse_["before"]


def test_speed_and_rod_velocity_together_are_refused(rig):
    case, df = rig
    with pytest.raises(InputError, match="speed_rpm and rod_velocity_m_s"):
        LoopEstimator(base="eq6", case=case).fit(df.assign(speed_rpm=1.0))


def test_predict_takes_rod_velocity_rows(rig, fitted):
    _, df = rig
    est = fitted
    new = df.drop(columns="viscous_power_W").iloc[:5]
    pred = og.predict(est, new, stage="with_T")
    col = "predicted_viscous_power_W"
    assert pred[col].to_numpy() == pytest.approx(df["viscous_power_W"].iloc[:5], rel=2e-3)
