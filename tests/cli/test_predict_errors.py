"""``oilgap predict`` scores itself where the input carries measured power (issue 25 item 5):
on the loop's own data its RMSE is the loop's in-sample RMSE, and its bias the mean of
(predicted - measured) computed here from the written table."""

import json
import re
import sys
from pathlib import Path

import pandas as pd
import pytest

from oilgap.cli import main

sys.path.insert(0, str(Path(__file__).parents[1] / "optim" / "calibration"))
from test_honest_cv import AIR_RIG, air_frame, wendt_cm  # noqa: E402


def test_predict_prints_rmse_and_bias_of_measured_rows(tmp_path, capsys):
    data = tmp_path / "air.csv"
    air_frame(wendt_cm, (0.009, 0.02, 0.039)).to_csv(data, index=False)
    rig = tmp_path / "rig.toml"
    rig.write_text(AIR_RIG)
    assert main(["loop", str(data), "--case", str(rig), "--cv-by", "gap_mm", "--base", "eq6",
                 "--effects", "seal_coulomb_friction", "--out", str(tmp_path / "o"),
                 "--no-figures"]) == 0
    capsys.readouterr()
    assert main(["predict", str(data), "--model", str(tmp_path / "o" / "loop.json"), "--out",
                 str(tmp_path / "p.csv")]) == 0
    out = capsys.readouterr().out
    m = re.search(r"error       viscous_power_W: RMSE (\S+) W, bias (\S+) W", out)
    assert m, out
    doc = json.loads((tmp_path / "o" / "loop.json").read_text())
    assert float(m.group(1)) == pytest.approx(doc["rmse_W"]["with_effect"], rel=1e-3)
    t = pd.read_csv(tmp_path / "p.csv")
    bias = float((t.predicted_viscous_power_W - t.viscous_power_W).mean())
    assert float(m.group(2)) == pytest.approx(bias, rel=1e-3, abs=1e-6)
