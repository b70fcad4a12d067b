"""The store's column-wise paths (issue 21 item 4) against their row-by-row definitions:
CSV text against ``DataFrame.to_csv`` and ``repr``, point keys against the hash of each
row's JSON text written out here, and the column-wise check of a stored file against
:func:`~oilgap.studies.grid.store_check.row_problem` line by line."""

import csv
import hashlib
import json

import numpy as np
import pandas as pd

from oilgap.model.io.case_io import seed_case
from oilgap.studies.grid.columns import ENGINE_VERSION, result_columns
from oilgap.studies.grid.store import _read_rows, append_points, case_fingerprint, point_keys
from oilgap.studies.grid.store_check import row_problem
from oilgap.studies.io.csv_text import csv_text, float_texts


def test_float_texts_are_python_repr():
    rng = np.random.default_rng(1)
    v = np.concatenate([10 ** rng.uniform(-30, 30, 20000), -(10 ** rng.uniform(-6, 12, 5000)),
                        np.round(10 ** rng.uniform(-4, 12, 5000)),
                        np.round(rng.uniform(0, 1e4, 5000), 3),
                        [0.0, -0.0, 1e-4, np.nextafter(1e-4, 0), np.nextafter(1e10, 0), 1e10, 1e16,
                         np.inf, -np.inf, np.nan, 5e-324, 25.4, 3.9999999999999964]])
    want = ["" if x != x else repr(x) for x in v.tolist()]
    assert float_texts(v).to_pylist() == want


def test_csv_text_is_to_csv_byte_for_byte():
    rng = np.random.default_rng(2)
    n = 500
    df = pd.DataFrame({
        "k": [f"k{i}" for i in range(n)], "x": rng.uniform(size=n) * 1e3,
        "msg": np.where(rng.uniform(size=n) < 0.5, None, 'a,b "c"\nd\re ü'),
        "t": np.where(rng.uniform(size=n) < 0.5, "", "ok"), "i": np.arange(n),
        "f": np.where(rng.uniform(size=n) < 0.3, np.nan, rng.uniform(size=n) * 1e12)})
    for cols in (list(df.columns), ["x", "t"], ["msg", "k"], ["t", "i"]):
        assert csv_text(df[cols]) == df[cols].to_csv(index=False).encode()
        assert csv_text(df[cols].iloc[:0]) == df[cols].iloc[:0].to_csv(index=False).encode()
    assert csv_text(df[["x"]]) is None  # one column: left to to_csv
    assert csv_text(pd.DataFrame({"b": [True, False], "x": [1.0, 2.0]})) is None


def test_point_keys_hash_each_rows_json_text():
    base = seed_case()
    grid = pd.DataFrame({"oil_temp_C": [1.5, np.nan, 3.0], "depth_m": [10, 20, 30],
                         "oil": ["VG32", None, 'V"G\u00e9'], "label": ["a", "b", "c"]})
    extra = {"thermal": "none"}
    head = json.dumps([ENGINE_VERSION, "evaluate", case_fingerprint(base),
                       sorted(extra.items())])
    rows = [[["depth_m", "10.0"], ["oil", "VG32"], ["oil_temp_C", "1.5"]],
            [["depth_m", "20.0"]],
            [["depth_m", "30.0"], ["oil", 'V"G\u00e9'], ["oil_temp_C", "3.0"]]]
    want = [hashlib.sha1((head + json.dumps(r)).encode()).hexdigest()[:20] for r in rows]
    assert point_keys(grid, base, "evaluate", extra) == want


def _line_by_line(path, mode):
    """(kept lines, reasons) of a points file checked one line at a time."""
    lines = path.read_text().split("\n")
    header, cols = next(csv.reader([lines[0]])), result_columns(mode)
    kept, why = [], []
    for no, line in enumerate(lines[1:-1], start=2):
        if not line.strip():
            continue
        fields = next(csv.reader([line]))
        reason = (f"{len(fields)} fields for {len(header)} columns" if len(fields) != len(header)
                  else row_problem(dict(zip(header, fields, strict=True)), mode, cols))
        if reason:
            why.append(f"{path}:{no}: {reason}")
        else:
            kept.append(line + "\n")
    return kept, why


def test_columnwise_check_keeps_what_row_problem_keeps(tmp_path):
    mode = "evaluate"
    cols = result_columns(mode)
    recs = [{c: 1.0 + i for c in cols if c not in ("status", "error", "warning",
                                                  "thermal_mode", "sea_temp_C")}
            | {"status": "ok", "thermal_mode": "none"} for i in range(40)]
    recs[3] = {"status": "error", "error": "bad, with a comma"}
    path = append_points(tmp_path / "points_evaluate.csv", [f"k{i}" for i in range(40)],
                         recs, mode)
    lines = path.read_text().split("\n")
    header = lines[0].split(",")
    bad = {"mean_power_W": ["", "nan", "-1", "inf", "abc", "True", "1_0", " 3 ", "0", "1e-400"],
           "T_res": ["0.9999995", "0.5", ""], "oil_temp_op_C": ["300", "-60", "301"],
           "status": ["okay", "error"], "thermal_mode": ["hot", " "], "point_key": ["a b"],
           "error": ["oops"]}
    i = 5
    for col, values in bad.items():
        for v in values:
            f = lines[i].split(",")
            f[header.index(col)] = v
            lines[i] = ",".join(f)
            i += 1
    lines[i] += ",extra"
    lines[i + 1] = "   "
    path.write_text("\n".join(lines) + "cut,short")
    got = _read_rows(path, mode)
    kept, why = _line_by_line(path, mode)
    assert got.lines == kept and len(kept) > 10
    assert got.problems == [*why, f"{path}:{len(lines)}: the row is cut short"]
    assert len(why) >= 12
