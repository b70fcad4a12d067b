"""The grid's columnar evaluate path against its per-case path (one DesignCase per row).

Both paths compose the same laws (:mod:`oilgap.model.uncertain.rows`); the per-case path is
the engine as it was before issue 21 (``apply_params`` per row, rows grouped by law), whose
numbers the golden sweep pins. Here the columnar path must give every row the same record:
status, error text, warning, and every number to 1e-12 relative.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.io.case_io import seed_case
from oilgap.studies.grid.columnar import columnar_chunk
from oilgap.studies.grid.columns import EVALUATE_NUMBERS
from oilgap.studies.grid.evaluate import evaluate_chunk
from oilgap.studies.grid.schema import apply_params

REL = 1e-12


@pytest.fixture(scope="module")
def thermal_case():
    from oilgap.model.case import ThermalSpec

    return replace(seed_case(), thermal=ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5,
                                                    heat_capacity_J_K=5e4))


def grid_rows(n, seed, balance=False):
    rng = np.random.default_rng(seed)
    rows = []
    for i in range(n):
        r = {"oil": ["VG22", "VG32", None][i % 3],
             "depth_m": float(rng.uniform(0, 6000)),
             "gamma": None if i % 5 == 0 else float(rng.uniform(0.3, 0.8)),
             "scale": float(rng.uniform(0.7, 1.3)),
             "peak_speed_rpm": None if i % 7 == 0 else float(rng.uniform(500, 6000)),
             "label": f"row {i}"}
        key = "sea_temp_C" if balance else "oil_temp_C"
        r[key] = None if i % 4 == 0 else float(rng.uniform(-1, 40))
        rows.append(r)
    return rows


def same_records(a, b):
    assert len(a) == len(b)
    for ra, rb in zip(a, b, strict=True):
        assert ra["status"] == rb["status"] and ra.get("error") == rb.get("error")
        if ra["status"] != "ok":
            continue
        assert ra["warning"] == rb["warning"] and ra["thermal_mode"] == rb["thermal_mode"]
        for k in EVALUATE_NUMBERS:
            x, y = ra[k], rb[k]
            assert (math.isnan(x) and math.isnan(y)) or x == pytest.approx(y, rel=REL), k


@pytest.mark.parametrize("mode", ["none", "film"])
def test_columnar_equals_per_case_rows(mode):
    base, rows = seed_case(), grid_rows(90, 1)
    got = columnar_chunk(base, rows, None, mode)
    assert got is not None
    same_records(got, evaluate_chunk(base, rows, None, mode, columnar=False))


@pytest.mark.parametrize("mode", ["bulk", "full"])
def test_columnar_equals_per_case_rows_under_the_balance(thermal_case, mode):
    rows = grid_rows(40, 2, balance=True)
    got = columnar_chunk(thermal_case, rows, None, mode)
    assert got is not None
    same_records(got, evaluate_chunk(thermal_case, rows, None, mode, columnar=False))


def test_rows_without_a_balance_root_fail_alone(thermal_case):
    hot = replace(thermal_case, thermal=replace(thermal_case.thermal, resistance_K_W=40.0))
    rows = [{"peak_speed_rpm": 300.0}, {"peak_speed_rpm": 6000.0}, {"peak_speed_rpm": 400.0}]
    got = columnar_chunk(hot, rows, None, "bulk")
    assert [r["status"] for r in got] == ["ok", "error", "ok"]
    assert "no oil temperature below 250 degC" in got[1]["error"]
    same_records(got, evaluate_chunk(hot, rows, None, "bulk", columnar=False))


def test_bad_rows_go_the_per_case_path_with_their_own_errors():
    base = seed_case()
    rows = [{"depth_m": 100.0}, {"depth_m": -5.0}, {"oil": "VG9999"}, {"gamma": 0.4}]
    assert columnar_chunk(base, rows[:2], None, "none") is None  # a value out of range
    got = evaluate_chunk(base, rows, None, "none")
    assert [r["status"] for r in got] == ["ok", "error", "error", "ok"]
    assert "depth_m" in got[1]["error"] and "VG9999" in got[2]["error"]
    same_records(got, evaluate_chunk(base, rows, None, "none", columnar=False))
    assert got[3]["mean_power_W"] == pytest.approx(evaluate_chunk(
        apply_params(base, {"gamma": 0.4}), [{}], None, "none")[0]["mean_power_W"], rel=REL)


def test_an_unknown_oil_is_an_error_row_in_the_columnar_path():
    rows = [{"oil": "VG9999", "depth_m": 10.0}, {"oil": "VG46", "depth_m": 20.0}]
    got = columnar_chunk(seed_case(), rows, None, "none")
    assert got[0]["status"] == "error" and got[1]["status"] == "ok"
    same_records(got, evaluate_chunk(seed_case(), rows, None, "none", columnar=False))


def test_geometry_columns_take_the_per_case_path():
    assert columnar_chunk(seed_case(), [{"gap_mm": 1.0}], None, "none") is None
