"""Issue 20, classes 2 and 8: a resumed store never takes a hand-edited row as a result,
and an interrupted optimize-mode sweep keeps its finished chunks.

Each row of the table is a store edited by hand (as a user, a script or a full disk
would) and the promise it checks. Every case is resumed twice, through the command line
(``oilgap study sweep ... --resume``) and through the façade (``og.sweep(..., resume=
True)``): no traceback, exit 0, the tampered rows computed again (a warning naming the
file, the line and why), and every result equal to the untouched sweep's.
"""

from __future__ import annotations

import csv
import io
import shutil
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import oilgap as og
from oilgap.cli import main
from oilgap.model.errors import OilgapWarning
from oilgap.studies.grid import runner
from oilgap.studies.grid.chunking import PRIOR_S_PER_POINT, WARM_CHAIN, ChunkSizer
from oilgap.studies.grid.runner import SweepInterrupted
from oilgap.studies.settings import SweepSettings, split_keywords

GRID = pd.DataFrame({"oil_temp_C": [4.0, 10.0, 20.0, 30.0], "gap_mm": [0.4, 0.5, 0.6, 0.7]})
OPT_GRID = pd.DataFrame({"oil_temp_C": [4.0, 20.0, 30.0]})
RUN = {"thermal": "none", "workers": 1, "progress": False}


# --------------------------------------------------------------------------- tampering


def _edit(text: str, row: int, column: str, value: str) -> str:
    """The store's text with data row ``row`` (0: the first) holding ``value`` in
    ``column``."""
    rows = list(csv.reader(io.StringIO(text)))
    rows[row + 1][rows[0].index(column)] = value
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows(rows)
    return out.getvalue()


def cell(row: int, column: str, value: str) -> Callable[[str], str]:
    return lambda text: _edit(text, row, column, value)


def lines(f: Callable[[list[str]], list[str]]) -> Callable[[str], str]:
    """An edit of the file's lines (the header first)."""
    return lambda text: "\n".join(f(text.split("\n")))


def _rename(old: str, new: str) -> Callable[[str], str]:
    return lines(lambda ls: [ls[0].replace(old, new), *ls[1:]])


def _dup_different(ls: list[str]) -> list[str]:
    copy = _edit(ls[0] + "\n" + ls[2] + "\n", 0, "mean_power_W", "1.0").split("\n")[1]
    return [*ls[:-1], copy, ls[-1]]


@dataclass(frozen=True)
class Case:
    promise: str
    edit: Callable[[str], str]
    recomputed: int  # grid rows computed again
    why: str  # words of the warning ("" when no row is dropped)
    mode: str = "evaluate"
    in_chunk: bool = False  # the edited row moved to a chunk file of its own


CASES = [
    Case("mean_power_W 'abc' is not a number: recomputed", cell(0, "mean_power_W", "abc"), 1,
         "mean_power_W = 'abc' is not a number"),
    Case("an empty mean_power_W is no result: recomputed", cell(1, "mean_power_W", ""), 1,
         "mean_power_W is empty"),
    Case("a loss of -1e9 W is unphysical: recomputed", cell(2, "mean_power_W", "-1e9"), 1,
         "outside its physical range"),
    Case("a NaN loss is not finite: recomputed", cell(0, "mean_power_W", "nan"), 1,
         "is not finite"),
    Case("an infinite loss is not finite: recomputed", cell(3, "mean_power_W", "inf"), 1,
         "is not finite"),
    Case("1e400 overflows to infinity: recomputed", cell(1, "Re1_peak", "1e400"), 1,
         "is not finite"),
    Case("a negative region-1 loss: recomputed", cell(1, "region1_power_W", "-5"), 1,
         "region1_power_W = -5 is outside"),
    Case("an oil at 1000 degC is no liquid: recomputed", cell(2, "oil_temp_op_C", "1000"), 1,
         "oil_temp_op_C = 1000 is outside"),
    Case("a zero viscosity: recomputed", cell(3, "nu_cSt", "0"), 1, "nu_cSt = 0 is outside"),
    Case("roughness T < 1 is no geometry: recomputed", cell(0, "T_res", "0.5"), 1,
         "T_res = 0.5 is outside"),
    Case("status 'OK' is not a status oilgap writes: recomputed", cell(0, "status", "OK"), 1,
         "status = 'OK'"),
    Case("status ok with an error text: recomputed", cell(1, "error", "solver failed"), 1,
         "status ok with an error message"),
    Case("an unknown thermal mode: recomputed", cell(2, "thermal_mode", "warm"), 1,
         "not a thermal mode"),
    Case("a key oilgap does not write: recomputed", cell(3, "point_key", "../../x"), 1,
         "not a key oilgap writes"),
    Case("a file cut short inside its last row: that row recomputed",
         lambda t: t.rstrip("\n")[:-30], 1, "the row is cut short"),
    Case("a file cut short inside its header: every row recomputed",
         lambda t: t[:40], 4, "the file is cut short"),
    Case("a row with an extra field: recomputed",
         lines(lambda ls: [*ls[:2], ls[2] + ",7", *ls[3:]]), 1, "fields for"),
    Case("a row with a field missing: recomputed",
         lines(lambda ls: [*ls[:3], ls[3].rsplit(",", 1)[0], *ls[4:]]), 1, "fields for"),
    Case("mean_power_W renamed: no result column, every row recomputed",
         _rename("mean_power_W", "mean_power_kW"), 4,
         "the header has no mean_power_W column"),
    Case("a column named twice (region1_power_W renamed mean_power_W): every row recomputed",
         _rename("region1_power_W", "mean_power_W"), 4, "holds mean_power_W twice"),
    Case("an unbalanced quote swallowing the row: recomputed",
         lines(lambda ls: [ls[0], ls[1].replace(",ok,", ',"ok,'), *ls[2:]]), 1,
         "fields for"),
    Case("a key stored twice with different numbers: recomputed",
         lines(_dup_different), 1, "stored twice with different numbers"),
    Case("a key stored twice alike (a crash between fold and cleanup): reused",
         lines(lambda ls: [*ls[:-1], ls[1], ls[-1]]), 0, ""),
    Case("a chunk file holding 'abc': recomputed", cell(0, "mean_power_W", "abc"), 1,
         "points_evaluate.chunks", in_chunk=True),
    Case("a chunk file holding a negative loss: recomputed", cell(0, "mean_power_W", "-1"), 1,
         "outside its physical range", in_chunk=True),
    Case("optimize: iterations 2.5 is not a count: recomputed",
         cell(0, "iterations", "2.5"), 1, "not a whole number", mode="optimize"),
    Case("optimize: a negative optimum loss: recomputed",
         cell(1, "mean_power_W", "-1e9"), 1, "outside its physical range", mode="optimize"),
    Case("optimize: a stator radius 'abc': recomputed",
         cell(2, "T3_mm", "abc"), 1, "T3_mm = 'abc' is not a number", mode="optimize"),
]


# --------------------------------------------------------------------------- the stores


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    """An untouched sweep of each mode: its folder (the store and results) and results."""
    root = tmp_path_factory.mktemp("clean")
    out = {}
    for mode, grid in (("evaluate", GRID), ("optimize", OPT_GRID)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OilgapWarning)
            res = og.sweep(grid, out=root / mode, mode=mode, **RUN).raw
        out[mode] = (root / mode, res)
    return out


def _tampered(case: Case, clean, dest: Path) -> Path:
    """A copy of the clean folder of the case's mode with its store edited."""
    src, _ = clean[case.mode]
    shutil.copytree(src, dest)
    store = dest / f"points_{case.mode}.csv"
    text = store.read_text()
    edited = case.edit(text)
    if case.in_chunk:  # the edited first row as a chunk file, the rest in the points file
        head, *rows = text.split("\n")
        store.write_text("\n".join([head, *rows[1:]]))
        chunk = dest / f"points_{case.mode}.chunks"
        chunk.mkdir()
        (chunk / "00000000000000000001-1-000000.csv").write_text(
            "\n".join(edited.split("\n")[:2]) + "\n")
    else:
        store.write_text(edited)
    return dest


def _same_results(got: pd.DataFrame, want: pd.DataFrame) -> None:
    assert list(got["status"]) == ["ok"] * len(want)
    cols = [c for c in want.columns if c.endswith(("_W", "_C", "_mm", "_cSt", "_m3"))
            and c != "initial_mean_power_W"]  # the start of a solve: its chain's row before
    np.testing.assert_allclose(got[cols].to_numpy(float), want[cols].to_numpy(float),
                               rtol=1e-5, atol=0)  # an optimum to the solver's tolerance


def _grid(case: Case) -> pd.DataFrame:
    return GRID if case.mode == "evaluate" else OPT_GRID


@pytest.mark.parametrize("case", CASES, ids=[c.promise for c in CASES])
def test_tampered_store_through_the_cli(case, clean, tmp_path, capsys):
    folder = _tampered(case, clean, tmp_path / "o")
    grid = tmp_path / "g.csv"
    _grid(case).to_csv(grid, index=False)
    argv = ["study", "sweep", str(grid), "--out", str(folder), "--mode", case.mode,
            "--thermal", "none", "--workers", "1", "--no-progress", "--resume"]
    assert main(argv) == 0
    out, err = capsys.readouterr()
    n = len(_grid(case))
    assert f"({case.recomputed} computed, {n - case.recomputed} reused)" in out
    assert "Traceback" not in err
    if case.why:
        assert f"points_{case.mode}" in err and case.why in err
    else:
        assert "dropped" not in err
    _same_results(pd.read_csv(folder / "results.csv"), clean[case.mode][1])


@pytest.mark.parametrize("case", CASES, ids=[c.promise for c in CASES])
def test_tampered_store_through_the_facade(case, clean, tmp_path):
    folder = _tampered(case, clean, tmp_path / "o")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = og.sweep(_grid(case), out=folder, resume=True, mode=case.mode, **RUN).raw
    said = " ".join(str(w.message) for w in caught if issubclass(w.category, OilgapWarning))
    assert res.attrs["computed"] == case.recomputed
    assert (case.why in said and str(folder) in said) if case.why else "dropped" not in said
    _same_results(res, clean[case.mode][1])


def test_the_table_holds_at_least_fifteen_stores():
    assert len(CASES) >= 15 and len({c.promise for c in CASES}) == len(CASES)


# --------------------------------------------------------------------------- class 8


def test_optimize_chunks_follow_the_measured_time():
    """Timing-independent: the sizer is told the times. A chunk is 3 s of work in whole
    chains, rounded down; one chain when a chain takes longer; the probe is one chain
    whatever the prior (the prior is the seed case's cost; a film solve or a long duty
    cycle costs many times more)."""
    c = WARM_CHAIN
    s = ChunkSizer("optimize", workers=2, chunk_seconds=3.0)
    assert s.next_size(600) == c  # the probe: one chain
    s.observe(c, c * 0.02)  # 20 ms a point: 3 / 0.02 = 150 rows
    assert s.next_size(10_000) == (150 // c) * c
    slow = ChunkSizer("optimize", workers=2, chunk_seconds=3.0)
    slow.observe(c, c * 0.5)  # 0.5 s a point: 6 rows < one chain
    assert slow.next_size(600) == c
    mid = ChunkSizer("optimize", workers=1, chunk_seconds=3.0)
    mid.observe(c, c * 0.04)  # 40 ms: 75 rows, whole chains rounded down
    assert mid.next_size(600) == (75 // c) * c <= 75
    fast = ChunkSizer("optimize", workers=1, chunk_seconds=3.0)
    fast.observe(c, c * 0.001)  # 1 ms: 3000 rows
    assert fast.next_size(10_000) == (3000 // c) * c
    # one chain of the costly case (0.5 s a solve) is about the target
    assert c * 0.5 <= 2 * 3.0
    # the old first chunk: a quarter of 3 s at the prior, in chains of 50: 150 rows (75 s
    # at 0.5 s a solve, the 77 s of the report)
    assert round(0.25 * 3.0 / PRIOR_S_PER_POINT["optimize"] / 50) * 50 == 150


def test_interrupted_optimize_sweep_keeps_its_chunks(tmp_path):
    """Ctrl-C after the first finished chunk of a three-chain optimize sweep (default
    chunk sizing): that chunk (one chain) is stored, the folder stays, and a resumed run
    computes only the other two chains."""
    grid = pd.DataFrame({"oil_temp_C": np.linspace(2.0, 30.0, 3 * WARM_CHAIN)})
    calls = []

    def stop(n):
        calls.append(n)
        raise KeyboardInterrupt

    def run(on_chunk=None):
        return runner.run_grid(grid, None, *split_keywords({"mode": "optimize", **RUN},
                                                           SweepSettings),
                               out_dir=tmp_path / "o", on_chunk=on_chunk)

    with pytest.raises(SweepInterrupted) as e:
        run(stop)
    assert calls == [WARM_CHAIN] and (e.value.saved, e.value.total) == (WARM_CHAIN, 3 * WARM_CHAIN)
    assert (tmp_path / "o" / "points_optimize.chunks").is_dir()
    again = run()
    assert (again.attrs["computed"], again.attrs["reused"]) == (2 * WARM_CHAIN, WARM_CHAIN)
    assert (again["status"] == "ok").all()


def test_interrupted_optimize_sweep_on_the_command_line(tmp_path, monkeypatch, capsys):
    """The same through ``oilgap study sweep --mode optimize``: Ctrl-C after the first
    chunk says one chain is saved (exit 130), the folder stays marked INCOMPLETE, and
    ``--resume`` computes only the rest."""
    grid = tmp_path / "g.csv"
    pd.DataFrame({"oil_temp_C": np.linspace(2.0, 30.0, 3 * WARM_CHAIN)}).to_csv(grid,
                                                                                index=False)
    out = tmp_path / "c"
    argv = ["study", "sweep", str(grid), "--out", str(out), "--mode", "optimize",
            "--thermal", "none", "--workers", "1", "--no-progress"]
    real = runner._finisher

    def interrupting(*a):
        finish = real(*a)

        def f(ks, recs):
            finish(ks, recs)
            raise KeyboardInterrupt
        return f

    monkeypatch.setattr(runner, "_finisher", interrupting)
    assert main(argv) == 130
    err = capsys.readouterr().err
    assert f"interrupted: {WARM_CHAIN} of {3 * WARM_CHAIN} points saved" in err
    assert (out / "INCOMPLETE").is_file()
    monkeypatch.setattr(runner, "_finisher", real)
    assert main(argv + ["--resume"]) == 0
    assert f"({2 * WARM_CHAIN} computed, {WARM_CHAIN} reused)" in capsys.readouterr().out
    assert not (out / "INCOMPLETE").exists()
