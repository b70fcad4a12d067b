"""Sweeps that scale out: the Dask backend against the process pool, chunks sized by
time, Ctrl-C's count of stored points, Parquet grids and results, the refusals of a
scheduler that cannot be used."""

from __future__ import annotations

import builtins
import os
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.errors import InfeasibleError, InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.units import MM_TO_M
from oilgap.optim.design import DesignProblem
from oilgap.studies.grid import backends, runner
from oilgap.studies.grid.chunking import WARM_CHAIN, ChunkSizer
from oilgap.studies.grid.columns import OPTIMIZE_RESULTS
from oilgap.studies.grid.evaluate import evaluate_cases
from oilgap.studies.grid.optimize import optimize_chunk
from oilgap.studies.grid.runner import SweepInterrupted
from oilgap.studies.grid.schema import read_grid, read_grid_csv
from oilgap.studies.settings import SweepSettings, split_keywords


def run_grid(grid, case=None, *, out_dir=None, catalogue=None, label="sweep", on_chunk=None,
             **keywords):
    """The engine from keywords, as the façade builds its records."""
    return runner.run_grid(grid, case, *split_keywords(keywords, SweepSettings),
                           out_dir=out_dir, catalogue=catalogue, label=label,
                           on_chunk=on_chunk)

EVAL = pd.DataFrame({"oil_temp_C": np.repeat([4.0, 20.0, 35.0], 4),
                     "gap_mm": np.tile([0.4, 0.5, 0.6, 0.7], 3)})
OPT = pd.DataFrame({"oil_temp_C": [4.0, 10.0, 20.0, 30.0, 4.0, 25.0],
                    "torque_min_Nm": [0.45, 0.45, 0.5, 0.5, 0.4, 0.4]})


def _numbers(df: pd.DataFrame) -> pd.DataFrame:
    return df.drop(columns=["solve_time_s"], errors="ignore")


@pytest.fixture(scope="module")
def dask_address():
    """The LocalCluster of ``--scheduler local`` (2 processes, no dashboard), started once
    for the module: its address (tcp://HOST:PORT, a running cluster to connect to)."""
    pytest.importorskip("dask.distributed")
    backend = backends.DaskBackend("local", 2)
    try:
        yield backend._cluster.scheduler_address
    finally:
        backend.close()


def test_local_cluster_workers_keep_glibc_malloc_threshold(dask_address):
    distributed = pytest.importorskip("dask.distributed")
    with distributed.Client(dask_address) as client:
        env = client.run(os.environ.get, "MALLOC_TRIM_THRESHOLD_")
        threads = client.run(os.environ.get, "OMP_NUM_THREADS")
    assert len(env) == 2 and set(env.values()) == {None}  # not Dask's 65536
    assert set(threads.values()) == {"1"}  # the rest of Dask's worker environment kept


KW = dict(workers=2, progress=False, thermal="none", chunk_size=3)


def test_dask_cluster_evaluates_as_the_process_pool(dask_address):
    pool = run_grid(EVAL, **KW)
    dask = run_grid(EVAL, scheduler=dask_address, **KW)
    assert dask.attrs["backend"] == f"the Dask scheduler at {dask_address}"
    assert pool.attrs["backend"] == "local processes" and dask.attrs["chunks"] == 4
    pd.testing.assert_frame_equal(pool, dask)
    power = dask["mean_power_W"].to_numpy().reshape(3, 4)  # (temperature, gap)
    assert (np.diff(power, axis=0) < 0).all() and (np.diff(power, axis=1) < 0).all()


def test_dask_cluster_optimizes_as_the_process_pool(dask_address):
    pool = run_grid(OPT, mode="optimize", **KW)
    dask = run_grid(OPT, mode="optimize", scheduler=dask_address, **KW)
    assert dask.attrs["worker_s"] > 0 and dask.attrs["chunks"] == 2
    pd.testing.assert_frame_equal(_numbers(pool), _numbers(dask))
    assert (pool["status"] == "ok").all() and pool["point_key"].is_unique
    one = DesignProblem(seed_case()).solve(oil_temp_C=20.0, torque_min_Nm=0.5)
    assert dask["mean_power_W"].iloc[2] == pytest.approx(one.optimal.mean_power_W, rel=1e-6)


@pytest.mark.parametrize("bearing", [False, True])
def test_lean_sweep_solve_equals_design_problem_solve(bearing):
    case = seed_case()
    if bearing:  # the bearing's power is added to the optimum's and the start's
        case = replace(case, bearing=bearing_spec_from({"designation": "6809"}))
    rows = [{"oil_temp_C": t, "torque_min_Nm": q, **({"delta_max_mm": 0.5} if i % 4 == 1
                                                       else {})}
            for i, (t, q) in enumerate(zip(np.linspace(2, 35, 8), [0.45, 0.5, 0.4] * 3,
                                           strict=False))]
    rows.append({"oil_temp_C": 10.0, "torque_min_Nm": 50.0})  # infeasible
    lean = optimize_chunk(case, rows, None)
    prob, prev = DesignProblem(case), None
    for row, got in zip(rows, lean, strict=True):
        kw = {"oil_temp_C": row["oil_temp_C"], "torque_min_Nm": row["torque_min_Nm"]}
        if "delta_max_mm" in row:
            kw["gap_max_m"] = row["delta_max_mm"] * MM_TO_M
        if row["torque_min_Nm"] > 1:
            with pytest.raises(InfeasibleError):
                prob.solve(x0=prev, **kw)
            assert got["status"] == "error" and got["error"].startswith("InfeasibleError")
            continue
        res = prev = prob.solve(x0=prev, **kw)
        exact = evaluate_cases([res.to_case()], "none")["mean_power_W"].iloc[0]
        want = dict(res.optimal.to_dict(), initial_mean_power_W=res.initial.mean_power_W,
                    mean_power_exact_W=exact, iterations=res.iterations,
                    active_constraints=" ".join(res.active_constraints),
                    torque_min_Nm_used=res.parameters.torque_min_Nm,
                    inertia_max_kgm2_used=res.parameters.inertia_max_kgm2)
        for c in OPTIMIZE_RESULTS:
            if c in want:
                if isinstance(want[c], str):  # active_constraints: the same names
                    assert got[c] == want[c], c
                else:
                    assert got[c] == pytest.approx(want[c], rel=1e-12, abs=0), c
    assert any("gap_max" in r.get("active_constraints", "") for r in lean)


def test_chunks_are_sized_by_time():
    s = ChunkSizer("evaluate", workers=2, chunk_seconds=1.0, prior_s=1e-3)
    first = s.next_size(10_000)
    assert first == 250  # a quarter of 1 s / 1 ms: the probe
    s.observe(first, 0.5)  # 2 ms a point measured
    assert s.next_size(10_000) == 500
    assert s.next_size(300) == 150  # the tail shared by the workers
    o = ChunkSizer("optimize", workers=2, chunk_seconds=3.0, prior_s=5e-3)
    assert o.chain == WARM_CHAIN and o.next_size(10_000) % WARM_CHAIN == 0
    assert ChunkSizer("optimize", 2, chunk_size=7).next_size(100) == 7
    calls = []  # a real run: several chunks, each stored
    res = run_grid(EVAL, workers=1, progress=False, chunk_seconds=1e-9, on_chunk=calls.append)
    assert sum(calls) == len(EVAL) and len(calls) == len(EVAL) == res.attrs["chunks"]


def test_warm_chains_do_not_depend_on_the_chunks():
    grid = pd.DataFrame({"oil_temp_C": np.linspace(2.0, 30.0, 8)})
    a = run_grid(grid, mode="optimize", workers=1, progress=False, thermal="none")
    b = run_grid(grid, mode="optimize", workers=1, progress=False, thermal="none",
                 chunk_seconds=1e-9)  # eight chunks of one row... of one chain
    assert b.attrs["chunks"] == 1  # whole chains: one chain of 8 < WARM_CHAIN rows
    pd.testing.assert_frame_equal(_numbers(a), _numbers(b))


def test_ctrl_c_says_how_many_points_are_saved(tmp_path, monkeypatch, capsys):
    calls = []

    def stop_after_two(n):
        calls.append(n)
        if len(calls) == 2:
            raise KeyboardInterrupt

    with pytest.raises(SweepInterrupted) as e:
        run_grid(EVAL, out_dir=tmp_path / "o", workers=1, chunk_size=5, progress=False,
                 on_chunk=stop_after_two)
    assert (e.value.saved, e.value.total) == (10, 12)
    again = run_grid(EVAL, out_dir=tmp_path / "o", workers=1, chunk_size=5, progress=False)
    assert (again.attrs["computed"], again.attrs["reused"]) == (2, 10)
    # the command line: one line, exit 130, and the same command with --resume continues
    g = tmp_path / "g.csv"
    EVAL.to_csv(g, index=False)
    argv = ["study", "sweep", str(g), "--out", str(tmp_path / "c"), "--workers", "1",
            "--chunk-size", "5", "--thermal", "none", "--no-progress"]
    real = runner._finisher

    def interrupting(*a):
        finish = real(*a)
        count = []

        def f(ks, recs):
            finish(ks, recs)
            count.append(1)
            if len(count) == 1:
                raise KeyboardInterrupt
        return f

    monkeypatch.setattr(runner, "_finisher", interrupting)
    assert main(argv) == 130
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"oilgap: interrupted: 5 of 12 points saved in {tmp_path / 'c'}; rerun "
                   "the same command with --resume to continue"]
    monkeypatch.setattr(runner, "_finisher", real)
    assert main(argv) == 2  # an unfinished sweep is never continued silently
    capsys.readouterr()
    assert main(argv + ["--resume"]) == 0
    assert "7 computed, 5 reused" in capsys.readouterr().out
    assert (tmp_path / "c" / "results.parquet").is_file()


def test_parquet_grid_equals_csv_grid_and_results_in_both(tmp_path):
    grid = pd.DataFrame({"oil": ["VG32", None, "VG46"], "oil_temp_C": [4.0, np.nan, 20.0],
                         "label": ["a", "b", None]})
    grid.to_parquet(tmp_path / "g.parquet", index=False)
    grid.to_csv(tmp_path / "g.csv", index=False)
    pq, csv = read_grid(tmp_path / "g.parquet"), read_grid(tmp_path / "g.csv")
    pd.testing.assert_frame_equal(pq, read_grid_csv(tmp_path / "g.csv"))
    a = run_grid(pq, out_dir=tmp_path / "a", workers=1, progress=False)
    b = run_grid(csv, workers=1, progress=False)
    pd.testing.assert_frame_equal(a, b)
    back = pd.read_parquet(tmp_path / "a" / "results.parquet")
    assert list(back.columns) == list(a.columns)
    assert np.allclose(back["mean_power_W"], a["mean_power_W"], rtol=0, atol=0)
    (tmp_path / "bad.parquet").write_text("not parquet")
    with pytest.raises(InputError, match="not a readable Parquet file"):
        read_grid(tmp_path / "bad.parquet")


def test_scheduler_without_dask_and_a_bad_address(monkeypatch, capsys, tmp_path):
    g = tmp_path / "g.csv"
    EVAL.head(2).to_csv(g, index=False)
    real_import = builtins.__import__

    def no_dask(name, *a, **k):
        if name == "dask" or name.startswith("dask."):
            raise ImportError(name)
        return real_import(name, *a, **k)

    monkeypatch.setattr(builtins, "__import__", no_dask)
    assert main(["study", "sweep", str(g), "--out", str(tmp_path / "a"), "--scheduler",
                 "local"]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        "oilgap: error: --scheduler local needs dask[distributed]: pip install "
        "'oilgap[dask]'"]
    monkeypatch.setattr(builtins, "__import__", real_import)
    pytest.importorskip("dask.distributed")
    monkeypatch.setattr(backends, "CONNECT_TIMEOUT_S", 0.5)
    assert main(["study", "sweep", str(g), "--out", str(tmp_path / "b"), "--scheduler",
                 "tcp://127.0.0.1:9"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(
        "oilgap: error: --scheduler tcp://127.0.0.1:9: no Dask scheduler answered within 0.5 s")
    assert main(["study", "sweep", str(g), "--out", str(tmp_path / "c"), "--scheduler",
                 "nowhere"]) == 2
    assert "scheduler = 'nowhere' is not allowed" in capsys.readouterr().err
