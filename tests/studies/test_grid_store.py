"""The grid's resumable store: what a point key depends on (and what it does not), the
case fingerprint, and the points file written and read back."""

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.studies.grid.columns import EVALUATE_RESULTS
from oilgap.studies.grid.store import (
    append_points,
    case_fingerprint,
    finished_points,
    load_points,
    point_keys,
    points_path,
)


def test_keys_ignore_column_order_labels_and_empty_cells():
    base = seed_case()
    a = pd.DataFrame({"oil": ["VG22", "VG46"], "T": [2.0, 3.0], "gamma": [np.nan, 0.5]})
    b = pd.DataFrame({"gamma": [np.nan, 0.5], "T": [2, 3], "oil": ["VG22", "VG46"],
                      "label": ["x", "y"]})
    c = pd.DataFrame({"oil": ["VG22"], "T": [2.0]})
    ka, kb, kc = (point_keys(g, base, "evaluate") for g in (a, b, c))
    assert ka == kb
    assert ka[0] == kc[0]  # an empty cell is the same point as no column
    assert ka[0] != ka[1]


def test_keys_depend_on_mode_and_base_case_but_not_its_name():
    g = pd.DataFrame({"T": [2.0]})
    base = seed_case()
    renamed = replace(base, name="another name")
    longer = replace(base, region1=replace(base.region1, length=base.region1.length * 1.1))
    k = point_keys(g, base, "evaluate")
    assert point_keys(g, renamed, "evaluate") == k
    assert case_fingerprint(renamed) == case_fingerprint(base)
    assert point_keys(g, longer, "evaluate") != k
    assert point_keys(g, base, "optimize") != k


def test_points_file_round_trip(tmp_path):
    path = points_path(tmp_path, "evaluate")
    assert path == tmp_path / "points_evaluate.csv"
    assert load_points(path, "evaluate").empty
    append_points(path, ["k1"], [{"status": "ok", "mean_power_W": 1.5}], "evaluate")
    append_points(path, ["k2"], [{"status": "error", "error": "bad"}], "evaluate")
    df = load_points(path, "evaluate")
    assert list(df.columns) == ["point_key", *EVALUATE_RESULTS]
    assert list(df["point_key"]) == ["k1", "k2"]
    assert set(finished_points(path, "evaluate")) == {"k1", "k2"}
    assert set(finished_points(path, "evaluate", retry_failed=True)) == {"k1"}
    assert finished_points(path, "evaluate")["k1"]["mean_power_W"] == 1.5


def test_a_foreign_points_file_is_refused(tmp_path):
    path = points_path(tmp_path, "evaluate")
    path.write_text("a,b\n1,2\n")
    with pytest.raises(InputError):
        load_points(path, "evaluate")
