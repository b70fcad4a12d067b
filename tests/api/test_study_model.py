"""``model=`` on the façade's studies folds a calibrated loop model into the case as
``--model`` does (issue 25 item 1): a one-row evaluate sweep of the seed joint with the
golden seal-friction loop model gives ``og.evaluate(model=...)``'s loss, and differs from
the uncalibrated one by the calibration's own change."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

import oilgap as og
from oilgap.model.errors import InputError

MODEL = Path(__file__).resolve().parents[1] / "golden" / "data" / "loop_seal" / "loop.json"


@pytest.fixture(scope="module")
def grid():
    return pd.DataFrame({"oil_temp_C": [20.0]})


def test_sweep_with_model_equals_evaluate_with_model(grid):
    calibrated = og.evaluate(model=MODEL, thermal="none").total_mean_power_W
    plain = og.evaluate(thermal="none").total_mean_power_W
    with_model = og.sweep(grid, thermal="none", workers=1, progress=False, model=MODEL)
    without = og.sweep(grid, thermal="none", workers=1, progress=False)
    at_20 = og.evaluate(model=MODEL, thermal="none", oil_temp_C=20.0).total_mean_power_W
    got = with_model.to_frame()["mean_power_W"].iloc[0]
    assert got == pytest.approx(at_20, rel=1e-12)
    assert without.to_frame()["mean_power_W"].iloc[0] != pytest.approx(got, rel=1e-6)
    assert calibrated != pytest.approx(plain, rel=1e-6)  # the model moves the loss


def test_a_bad_model_is_refused_by_name(grid, tmp_path):
    bad = tmp_path / "case.toml"
    bad.write_text('name = "x"\n')
    with pytest.raises(InputError):
        og.sweep(grid, thermal="none", workers=1, progress=False, model=bad)
