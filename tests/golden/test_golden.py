"""Every command prints the same numbers as the recorded golden outputs, to the tolerance of
the solver that made each number (``golden.TOLERANCES``: 1e-12 for pure evaluations, 1e-9
for the heat balance, 1e-6 for IPOPT optima and least-squares fits).

Rows of a CSV are matched by their identity, never by position (issue 26).
The golden outputs in ``tests/golden/data`` were recorded before the restructure of
issue 8; see ``golden.py`` for what is compared and how to regenerate them when a
change of output is intended.
"""

import os
import subprocess
import sys
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd

matplotlib.use("Agg")

sys.path.insert(0, str(Path(__file__).resolve().parent))

import golden  # noqa: E402


def test_every_command_reproduces_its_golden_output(tmp_path):
    golden.produce(tmp_path)
    diffs = golden.compare_dirs(golden.DATA, tmp_path)
    assert not diffs, "\n".join(diffs[:40])


def test_tolerances_are_the_solvers_and_strict_elsewhere():
    """The table's rows for a few outputs: a loose tolerance only where a solver stops."""
    assert golden.tolerance("evaluate.json", ".total_mean_power_W") == (1e-12, 1e-12)
    assert golden.tolerance("sweep_eval/results.csv", "mean_power_W") == (1e-12, 1e-12)
    assert golden.tolerance("loop_seal/loop.json", ".model.effects.seal") == (1e-6, 1e-9)
    assert golden.tolerance("loop_seal.json", ".residual_after.autocorrelation.1")[1] == 1e-5
    assert golden.tolerance("optimize_none.json", ".optimal.delta_mm") == (1e-6, 1e-9)
    assert golden.tolerance("evaluate_thermal.json", ".oil_temp_C") == (1e-9, 1e-9)


def test_text_numbers_compare_to_their_printed_digit():
    rel = "evaluate.json"  # strictest row
    assert not golden.compare_text("loss 0.5667 W in 12 runs", "loss 0.5668 W in 12 runs", rel)
    assert golden.compare_text("loss 0.5667 W in 12 runs", "loss 0.5669 W in 12 runs", rel)
    assert golden.compare_text("loss 0.5667 W in 12 runs", "loss 0.5667 W in 13 runs", rel)
    assert golden.compare_text("oil VG15", "oil VG22", rel)


def _store(d, gamma: float, keys: list[str], order: list[int]):
    """A two-point grid store: results.csv (inputs, gamma fitted) and points_evaluate.csv
    (rows in the order chunks finished), keyed by ``keys``."""
    d.mkdir()
    rows = [("VG150", 4.0, 0.0, 36.01262986724199), ("VG150", 2.0, 0.0, 25.618265798308883)]
    (d / "results.csv").write_text("oil,T,gamma,status,mean_power_W,point_key\n" + "".join(
        f"{o},{t},{gamma!r},ok,{p!r},{k}\n" for (o, t, _, p), k in zip(rows, keys, strict=True)))
    (d / "points_evaluate.csv").write_text("point_key,status,mean_power_W\n" + "".join(
        f"{keys[i]},ok,{rows[i][3]!r}\n" for i in order))
    return d / "points_evaluate.csv", d / "results.csv"


def test_store_rows_match_by_the_inputs_their_key_stands_for(tmp_path):
    """Issue 26: gamma (a fit) one ulp apart gives other keys and another row order; the
    rows are the same points. With bit-identical inputs the keys must be equal."""
    g = 0.5658601386063837
    pa, ra = _store(tmp_path / "a", g, ["0b05d7", "2077c2"], [0, 1])
    pb, rb = _store(tmp_path / "b", float(np.nextafter(g, 1.0)), ["22b71c", "3ec496"], [1, 0])
    assert not golden.compare_csv(pa, pb, "smoothing/grid/points_evaluate.csv")
    assert not golden.compare_csv(ra, rb, "smoothing/grid/results.csv")
    pc, rc = _store(tmp_path / "c", g, ["0b05d7", "ffffff"], [1, 0])  # same inputs, new key
    assert any("point_key" in d for d in golden.compare_csv(ra, rc, "sweep_eval/results.csv"))
    assert any("point_key" in d for d in golden.compare_csv(pa, pc, "x/points_evaluate.csv"))
    pd_, _ = _store(tmp_path / "d", g + 1e-3, ["0b05d7", "2077c2"], [0, 1])  # another point
    assert golden.compare_csv(pa, pd_, "smoothing/grid/points_evaluate.csv")


def test_rows_match_by_identity_and_differences_name_the_row(tmp_path):
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    a.write_text("variant,gamma\nper-oil/none,0.5658601386063837\nshared/none,0.97872398\n")
    b.write_text("variant,gamma\nshared/none,0.97872398\nper-oil/none,0.5658601386063837\n")
    assert not golden.compare_csv(a, b, "smoothing/smoothing_fits.csv")
    b.write_text("variant,gamma\nshared/none,0.97872398\nper-oil/none,0.5659\n")
    assert golden.compare_csv(a, b, "smoothing/smoothing_fits.csv") == [
        "a.csv[variant=per-oil/none, gamma]: 0.5658601386063837 != 0.5659"]


def test_every_golden_csv_names_each_row_once():
    """The identity of each golden CSV is a key: no two rows share it (else the match of
    rows would fall back on their order)."""
    for p in sorted(golden.DATA.rglob("*.csv")):
        rel = p.relative_to(golden.DATA).as_posix()
        df = pd.read_csv(p)
        if p.name.startswith("points_"):
            df, bad = golden._with_key_inputs(df, p.parent / "results.csv")
            assert not bad, bad
        ids = golden.identity(rel, df)
        assert set(ids) <= set(df.columns), rel
        assert not df.duplicated(ids).any(), rel


def test_the_cpu_without_avx512_is_asked_of_numpy_and_openblas():
    env = golden.without_avx512_env()
    assert {env[k] for k in golden.THREAD_VARS} == {"1"}
    targets = golden.avx512_targets()
    assert ("NPY_DISABLE_CPU_FEATURES" in env) == bool(targets)
    if targets:  # numpy then reports them off, and OpenBLAS runs its AVX2 kernels
        code = ("from numpy._core._multiarray_umath import __cpu_features__ as f\n"
                f"print(any(f[t] for t in {targets!r}))")
        r = subprocess.run([sys.executable, "-c", code], env={**os.environ, **env,
                           "OPENBLAS_VERBOSE": "2"}, capture_output=True, text=True, check=True)
        assert r.stdout.strip().splitlines()[-1] == "False"
        assert "Core: Haswell" in r.stdout + r.stderr
