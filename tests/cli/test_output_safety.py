"""Outputs are safe: checked before any computation, never overwritten unless asked,
written atomically, a result folder complete or marked incomplete, one sweep per
folder, a resumable store that survives a cut-short row and a kill, logs off stdout,
a closed pipe and Ctrl-C ended in one line.

In-process ``main([...])`` calls, except where a real process is the point (a lock
held by another process, SIGKILL in the middle of a chunk, a broken pipe, Ctrl-C).
"""

import errno
import importlib
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pandas as pd
import pytest
from matplotlib.figure import Figure

from oilgap.cli import COMMANDS, main
from oilgap.model.measured.data import load_measured
from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.studies.grid.schema import read_grid_csv
from oilgap.studies.io.files import MARKER, atomic_write_text
from oilgap.studies.io.result_folder import LOCK_NAME, FolderLock, ResultFolder
from oilgap.studies.outputs import OUTPUTS
from oilgap.studies.rigs.synth import SynthConfig, synthesize

PY = sys.executable
ENV = {**os.environ, "PYTHONWARNINGS": "ignore"}


def one_error_line(capsys, *needles: str) -> str:
    """stderr is exactly one ``oilgap: error:`` line holding every needle."""
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert "Traceback" not in err and len(lines) == 1, err
    assert lines[0].startswith("oilgap: error:"), lines[0]
    for n in needles:
        assert n in lines[0], (n, lines[0])
    return lines[0]


def tree(folder: Path) -> dict[str, bytes]:
    """Every file below ``folder`` with its content."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file()}


def boom(*args, **kwargs):
    raise AssertionError("computation started before --out was checked")


def no_compute(monkeypatch, command: str, names: tuple[str, ...]) -> None:
    """Replace the command's first computation (or input reading) by :func:`boom`."""
    mod = importlib.import_module(COMMANDS[command])
    for name in names:
        target = mod
        *path, attr = name.split(".")
        for part in path:
            target = getattr(target, part)
        monkeypatch.setattr(target, attr, boom)


GRID = "T,oil\n1,VG22\n2,VG32\n3,VG46\n4,VG68\n5,VG100\n6,VG150\n"

# command argv (folder/file relative to tmp_path), existing output, computation replaced
EXISTING = [
    (["synth", "--out", "d.csv"], "d.csv", "synth", ("synth",)),
    (["optimize", "--starts", "1", "--out", "o.toml"], "o.toml", "optimize",
     ("optimize_resolved", "load_case")),
    (["predict", "g.csv", "--model", "m.json", "--out", "p.csv"], "p.csv", "predict",
     ("predict",)),
    (["loop", "g.csv", "--out", "o"], "o/report.md", "loop", ("Loop",)),
    (["study", "sweep", "g.csv", "--out", "o"], "o/points_evaluate.csv", "study sweep",
     ("sweep",)),
    (["study", "pareto", "--out", "o"], "o/pareto_gap.png", "study pareto", ("pareto",)),
    (["study", "oil-grade", "--out", "o"], "o/grid/points_evaluate.csv", "study oil-grade",
     ("oil_grade",)),
    (["study", "smoothing", "--out", "o"], "o/summary.md", "study smoothing",
     ("smoothing",)),
    (["study", "uncertainty", "--out", "o"], "o/uncertainty_tornado.png", "study uncertainty",
     ("uncertainty",)),
    (["loop", "g.csv", "--out", "o"], f"o/{MARKER}", "loop", ("Loop",)),
]


@pytest.mark.parametrize("argv,existing,command,compute", EXISTING,
                         ids=[f"{e[2]}:{e[1]}" for e in EXISTING])
def test_an_earlier_output_is_refused_before_any_computation(
        tmp_path, monkeypatch, capsys, argv, existing, command, compute):
    monkeypatch.chdir(tmp_path)
    Path("g.csv").write_text(GRID)
    Path(existing).parent.mkdir(parents=True, exist_ok=True)
    Path(existing).write_text("an earlier run's output\n")
    before = tree(tmp_path)
    no_compute(monkeypatch, command, compute)
    assert main(argv) == 2
    option = "--resume" if command == "study sweep" else "--force"
    one_error_line(capsys, "--out", option)
    assert tree(tmp_path) == before  # nothing written, nothing removed, no lock left


BAD_OUT = [
    (["study", "pareto", "--out", "/proc/x"], "study pareto", ("pareto",), "/proc"),
    (["study", "oil-grade", "--out", "/proc/x"], "study oil-grade", ("oil_grade",),
     "/proc"),
    (["study", "sweep", "g.csv", "--out", "/proc/x"], "study sweep", ("sweep",),
     "/proc"),
    (["study", "smoothing", "--out", "FILE"], "study smoothing", ("smoothing",),
     "a folder is required"),
    (["study", "sweep", "g.csv", "--out", "FILE"], "study sweep", ("sweep",),
     "a folder is required"),
    (["loop", "g.csv", "--out", "o"], "loop", ("Loop",), "is a directory"),
    (["synth", "--out", "/proc/x/s.csv"], "synth", ("synth",), "does not exist"),
    (["synth", "--out", "nodir/s.csv"], "synth", ("synth",), "does not exist"),
    (["optimize", "--starts", "1", "--out", "/proc/x.toml"], "optimize",
     ("optimize_resolved", "load_case"), "cannot write"),
    (["optimize", "--starts", "1", "--out", "o"], "optimize", ("optimize_resolved",),
     "is a directory"),
    (["predict", "g.csv", "--model", "m.json", "--out", "nodir/p.csv"], "predict",
     ("predict",), "does not exist"),
]


@pytest.mark.parametrize("argv,command,compute,why", BAD_OUT,
                         ids=[" ".join(b[0][:2] + b[0][-1:]) for b in BAD_OUT])
def test_a_bad_out_is_refused_before_any_computation(tmp_path, monkeypatch, capsys, argv,
                                                     command, compute, why):
    monkeypatch.chdir(tmp_path)
    Path("g.csv").write_text(GRID)
    Path("FILE").write_text("a file\n")
    Path("o/loop.json").mkdir(parents=True)  # a directory where loop.json goes
    before = tree(tmp_path)
    no_compute(monkeypatch, command, compute)
    assert main(argv) == 2
    one_error_line(capsys, "--out", why)
    assert tree(tmp_path) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["FILE", "g.csv", "o"]


def test_every_command_that_writes_has_force():
    from oilgap.cli import build_parser

    parser = build_parser()
    for argv in (["synth"], ["optimize"], ["loop", "d.csv"], ["study", "smoothing"],
                 ["study", "pareto"], ["study", "oil-grade"], ["study", "sweep", "g.csv"],
                 ["predict", "d.csv", "--model", "m", "--out", "p.csv"]):
        assert parser.parse_args(argv + ["--force"]).force is True
    assert parser.parse_args(["study", "sweep", "g.csv", "--resume"]).resume is True


# --------------------------------------------------------------------------- sweeps


def sweep(tmp_path, *extra: str, grid: str = GRID, out: str = "o") -> list[str]:
    g = tmp_path / "g.csv"
    g.write_text(grid)
    return ["study", "sweep", str(g), "--out", str(tmp_path / out), "--workers", "1",
            "--thermal", "none", "--no-progress", *extra]


def test_force_starts_over_and_keeps_what_is_not_an_output(tmp_path, capsys):
    out = tmp_path / "o"
    assert main(sweep(tmp_path)) == 0
    (out / "notes.txt").write_text("mine\n")
    assert main(sweep(tmp_path, "--force", grid="T\n1.5\n2.5\n")) == 0
    assert "(2 computed, 0 reused)" in capsys.readouterr().out
    res = read_grid_csv(out / "results.csv")
    assert list(res["T"]) == [1.5, 2.5]
    points = pd.read_csv(out / "points_evaluate.csv")
    assert len(points) == 2  # the earlier store is gone, not appended to
    assert (out / "notes.txt").read_text() == "mine\n"
    assert sorted(p.name for p in out.iterdir()) == [
        "notes.txt", "points_evaluate.csv", "provenance.json", "results.csv", "results.parquet",
        "summary.md", "sweep.png"]


@pytest.mark.parametrize("bad", [["--scheduler", "foo"], ["--thermal", "full"],
                                 ["--chunk-seconds", "-1"]])
def test_force_with_a_refused_input_loses_nothing(tmp_path, capsys, bad):
    """--force replaces the earlier outputs only with new ones: a run refused for its
    input (after the folder was opened) leaves them as they were, byte for byte."""
    out = tmp_path / "o"
    assert main(sweep(tmp_path)) == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    capsys.readouterr()
    assert main(sweep(tmp_path, "--force", *bad)) == 2
    one_error_line(capsys, bad[0].lstrip("-").replace("-", "_"))
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before


def test_a_cut_short_store_row_is_dropped_counted_and_recomputed(tmp_path, capsys):
    out = tmp_path / "o"
    assert main(sweep(tmp_path, "--chunk-size", "2")) == 0
    full = read_grid_csv(out / "results.csv")
    store = out / "points_evaluate.csv"
    text = store.read_text()
    # a full disk cut the last row short; a stray line is not a row either
    store.write_text(text[:-25] .replace("\n", "\nnot,a,row\n", 1))
    capsys.readouterr()
    assert main(sweep(tmp_path, "--resume", "--chunk-size", "2")) == 0
    cap = capsys.readouterr()
    warn = [x for x in cap.err.splitlines() if x.startswith("oilgap: warning:")]
    assert len(warn) == 1 and "2 partial or invalid rows dropped" in warn[0], cap.err
    assert "(1 computed, 5 reused)" in cap.out
    again = read_grid_csv(out / "results.csv")
    pd.testing.assert_frame_equal(again.drop(columns="solve_time_s", errors="ignore"),
                                  full.drop(columns="solve_time_s", errors="ignore"))
    rows = store.read_text().splitlines()
    assert len(rows) == 7 and all(r.count(",") == rows[0].count(",") for r in rows)


KILL_MID_CHUNK = textwrap.dedent("""
    import os, signal, sys
    import oilgap.studies.grid.store as store
    real = store.atomic_to_csv
    calls = []

    def dying(df, path, **kw):
        calls.append(path)
        if len(calls) == 4:  # the 4th chunk: half of it written, then SIGKILL
            text = df.to_csv(index=False)
            with open(path.parent / ("." + path.name + ".x.tmp"), "w") as fh:
                fh.write(text[: len(text) // 2])
                fh.flush()
            os.kill(os.getpid(), signal.SIGKILL)
        return real(df, path, **kw)

    store.atomic_to_csv = dying
    from oilgap.cli import main
    sys.exit(main(sys.argv[1:]))
""")


def test_sigkill_mid_chunk_then_resume_gives_the_same_results(tmp_path, capsys):
    grid = "T\n" + "".join(f"{1 + 0.25 * i}\n" for i in range(12))
    argv = sweep(tmp_path, "--chunk-size", "2", grid=grid)
    p = subprocess.run([PY, "-c", KILL_MID_CHUNK, *argv], capture_output=True, env=ENV,
                       timeout=120)
    assert p.returncode == -signal.SIGKILL
    out = tmp_path / "o"
    assert (out / MARKER).is_file() and (out / LOCK_NAME).is_file()  # killed: marked
    assert len(list((out / "points_evaluate.chunks").glob("*.csv"))) == 3
    assert not (out / "results.csv").exists()
    assert main(argv) == 2  # an unfinished sweep is not silently continued
    one_error_line(capsys, "--resume")
    assert main(argv + ["--resume"]) == 0  # the dead run's lock is taken over
    assert "(6 computed, 6 reused)" in capsys.readouterr().out
    assert sorted(p.name for p in out.iterdir()) == [
        "points_evaluate.csv", "provenance.json", "results.csv", "results.parquet", "summary.md",
        "sweep.png"]
    assert main(sweep(tmp_path, grid=grid, out="fresh")) == 0
    cols = ["T", "status", "mean_power_W", "point_key"]
    pd.testing.assert_frame_equal(read_grid_csv(out / "results.csv")[cols],
                                  read_grid_csv(tmp_path / "fresh" / "results.csv")[cols])


HOLD_LOCK = textwrap.dedent("""
    import sys, time
    from oilgap.studies.io.result_folder import FolderLock
    with FolderLock(sys.argv[1]):
        print("locked", flush=True)
        time.sleep(60)
""")


def test_a_second_run_into_a_folder_in_use_is_refused(tmp_path, capsys):
    out = tmp_path / "o"
    out.mkdir()
    holder = subprocess.Popen([PY, "-c", HOLD_LOCK, str(out)], stdout=subprocess.PIPE,
                              env=ENV)
    try:
        assert holder.stdout.readline().strip() == b"locked"
        assert main(sweep(tmp_path)) == 2
        one_error_line(capsys, "in use by another oilgap run", f"pid {holder.pid}")
        assert sorted(p.name for p in out.iterdir()) == [LOCK_NAME]
    finally:
        holder.kill()
        holder.wait()
    assert main(sweep(tmp_path)) == 0  # its process is gone: the stale lock is taken over
    assert not (out / LOCK_NAME).exists()


def test_the_lock_is_reentrant_in_one_process_and_released(tmp_path):
    with FolderLock(tmp_path) as a, FolderLock(tmp_path):
        assert a.path.read_text().split("\n")[0] == str(os.getpid())
    assert not (tmp_path / LOCK_NAME).exists()
    (tmp_path / LOCK_NAME).write_text("")  # a run killed before writing its pid
    os.utime(tmp_path / LOCK_NAME, (time.time() - 60, time.time() - 60))
    with FolderLock(tmp_path):
        pass


# --------------------------------------------------------------------------- the loop


@pytest.fixture(scope="module")
def fitted(tmp_path_factory):
    """Small synthetic viscous data and its fitted loop (fitted once for the module)."""
    d = tmp_path_factory.mktemp("rig")
    df = synthesize(SynthConfig(kind="viscous_power_W", n_samples=300), seed=5)
    csv = d / "rig.csv"
    df.to_csv(csv, index=False)
    return csv, LoopEstimator().fit(load_measured(csv))


@pytest.fixture
def quick_loop(fitted, monkeypatch):
    """``oilgap loop`` with the fit replaced by the module's fitted estimator."""
    csv, est = fitted

    def fit(self, data):
        self.__dict__.update(est.__dict__)
        return self

    monkeypatch.setattr(LoopEstimator, "fit", fit)
    return csv


def test_loop_force_clears_the_earlier_figures(tmp_path, quick_loop, capsys):
    out = tmp_path / "o"
    assert main(["loop", str(quick_loop), "--out", str(out)]) == 0
    assert len(list(out.glob("*.png"))) == 4  # overview, window, 2 residual figures
    assert main(["loop", str(quick_loop), "--out", str(out), "--no-figures"]) == 2
    one_error_line(capsys, "--force")
    assert main(["loop", str(quick_loop), "--out", str(out), "--no-figures", "--force"]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["loop.json", "provenance.json", "report.md"]
    assert "![" not in (out / "report.md").read_text()  # links no figure


def test_a_failure_while_drawing_leaves_the_folder_marked_incomplete(tmp_path, quick_loop,
                                                                     monkeypatch, capsys):
    out = tmp_path / "o"
    assert main(["loop", str(quick_loop), "--out", str(out), "--no-figures"]) == 0
    real = Figure.savefig
    calls = []

    def disk_full(self, *args, **kwargs):
        calls.append(1)
        if len(calls) == 2:
            raise OSError(errno.ENOSPC, "No space left on device")
        return real(self, *args, **kwargs)

    monkeypatch.setattr(Figure, "savefig", disk_full)
    capsys.readouterr()
    assert main(["loop", str(quick_loop), "--out", str(out), "--force"]) == 2
    one_error_line(capsys, "cannot write", "residual_vs_speed.png", "No space left")
    names = sorted(p.name for p in out.iterdir())
    # the earlier run's outputs are gone (no new loop.json beside old figures, no old
    # loop.json beside new ones), the folder is marked, no temporary file is left
    assert names == [MARKER, "measured_vs_model.png", "provenance.json"]
    assert "incomplete" in (out / MARKER).read_text()


def test_a_crash_while_drawing_leaves_no_report_linking_missing_figures(tmp_path, quick_loop,
                                                                         monkeypatch):
    def crash(*args, **kwargs):
        raise ValueError("a bug while drawing")

    monkeypatch.setattr("oilgap.studies.loop.report_figures._figure_residuals", crash)
    out = tmp_path / "o"
    with pytest.raises(ValueError):  # a bug keeps its traceback; the folder is marked
        main(["loop", str(quick_loop), "--out", str(out)])
    assert sorted(p.name for p in out.iterdir()) == [MARKER, "measured_vs_model.png",
                                                     "provenance.json"]


def test_result_folder_leaves_nothing_when_nothing_was_written(tmp_path):
    out = tmp_path / "new" / "o"
    with pytest.raises(RuntimeError), ResultFolder(out, ("a.csv",)) as folder:
        folder.begin()
        raise RuntimeError("failed before writing")
    assert not (tmp_path / "new").exists()  # provenance.json of nothing removed too
    with pytest.raises(RuntimeError), ResultFolder(out, ("a.csv",)) as folder:
        folder.begin()
        atomic_write_text(out / "a.csv", "x\n")
        raise RuntimeError("failed after writing")
    assert sorted(p.name for p in out.iterdir()) == [MARKER, "a.csv", "provenance.json"]


def test_force_puts_the_earlier_outputs_back_when_nothing_new_was_written(tmp_path):
    out = tmp_path / "o"
    out.mkdir()
    (out / "a.csv").write_text("old\n")
    (out / "sub").mkdir()
    (out / "sub" / "b.csv").write_text("old b\n")
    outputs = ("a.csv", "sub/b.csv")
    with pytest.raises(RuntimeError), ResultFolder(out, outputs, force=True) as folder:
        folder.begin()
        assert not (out / "a.csv").exists()  # moved aside while the run writes
        raise RuntimeError("refused before writing")
    assert (out / "a.csv").read_text() == "old\n"
    assert (out / "sub" / "b.csv").read_text() == "old b\n"
    assert sorted(p.name for p in out.iterdir()) == ["a.csv", "sub"]
    with pytest.raises(RuntimeError), ResultFolder(out, outputs, force=True) as folder:
        folder.begin()
        atomic_write_text(out / "a.csv", "new\n")
        raise RuntimeError("failed after writing")
    # old and new never side by side: the old b.csv is gone, the folder marked
    assert (out / "a.csv").read_text() == "new\n" and not (out / "sub").exists()
    assert sorted(p.name for p in out.iterdir()) == [MARKER, "a.csv", "provenance.json"]
    with ResultFolder(out, outputs, force=True) as folder:
        folder.begin()
        atomic_write_text(out / "a.csv", "newer\n")
    assert sorted(p.name for p in out.iterdir()) == ["a.csv", "provenance.json"]


def test_outputs_list_every_file_the_loop_writes():
    from oilgap.studies.loop.report import FIGURES

    assert set(OUTPUTS["loop"]) == {"loop.json", "report.md", "provenance.json", *FIGURES}


# --------------------------------------------------------------------------- streams


def test_optimize_json_verbose_keeps_ipopt_off_stdout(capfd):
    assert main(["optimize", "--json", "--verbose", "--starts", "1", "--thermal",
                 "none"]) == 0
    cap = capfd.readouterr()
    doc = json.loads(cap.out)  # stdout is the JSON document alone
    assert doc["success"] is True
    assert "Ipopt" in cap.err and "iter" in cap.err


def _cli(*argv: str) -> list[str]:
    return [PY, "-m", "oilgap.cli", *argv]


def test_a_closed_stdout_ends_quietly():
    p = subprocess.Popen(_cli("evaluate", "--json"), stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, env=ENV)
    p.stdout.close()  # the reader is gone before anything is written
    err = p.stderr.read().decode()
    assert p.wait(timeout=60) == 141 and err == ""


def test_evaluate_piped_into_head():
    cmd = " ".join(_cli("evaluate")) + " | head -1"
    p = subprocess.run(["bash", "-o", "pipefail", "-c", cmd], capture_output=True,
                       env=ENV, timeout=60)
    assert p.returncode in (0, 141)
    assert len(p.stdout.decode().splitlines()) == 1
    assert "Traceback" not in p.stderr.decode() and "BrokenPipe" not in p.stderr.decode()


def test_ctrl_c_in_a_parallel_sweep_is_one_line(tmp_path):
    grid = "oil_temp_C,depth_m\n" + "".join(f"{t},{d}\n" for t in range(0, 40, 2)
                                             for d in range(0, 6000, 500))
    argv = sweep(tmp_path, "--mode", "optimize", "--chunk-size", "4", grid=grid)
    argv[argv.index("--workers") + 1] = "2"
    p = subprocess.Popen(_cli(*argv), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         env=ENV, start_new_session=True)
    chunks = tmp_path / "o" / "points_optimize.chunks"
    t0 = time.time()
    while not (chunks.is_dir() and any(chunks.glob("*.csv"))) and time.time() - t0 < 60:
        time.sleep(0.05)
    os.killpg(p.pid, signal.SIGINT)  # Ctrl-C goes to the whole process group
    out, err = p.communicate(timeout=60)
    assert p.returncode == 130, err.decode()
    lines = err.decode().strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("oilgap: interrupted: ")
    assert lines[0].endswith("; rerun the same command with --resume to continue")
    assert (tmp_path / "o" / MARKER).is_file()


def test_an_interrupt_casadi_swallowed_is_raised_after_the_solve(monkeypatch):
    # CasADi turns Ctrl-C during IPOPT into a failed solve and returns; the handler the
    # command line installs notes it, and the solve raises it again
    from oilgap.model.io.case_io import seed_case
    from oilgap.optim import interrupts
    from oilgap.optim.design import DesignProblem

    problem = DesignProblem(seed_case())
    monkeypatch.setitem(interrupts._PENDING, "interrupt", True)
    with pytest.raises(KeyboardInterrupt):
        problem.solve(starts=1)
    assert not interrupts.interrupt_pending()


def test_casadis_own_interrupt_warning_is_not_printed(monkeypatch):
    import io

    from oilgap.cli import _QuietSolverInterrupt
    from oilgap.optim import interrupts

    buf = io.StringIO()
    err = _QuietSolverInterrupt(buf)
    err.write("CasADi - 2026-01-01 WARNING(\"KeyboardInterruptException\") [x.cpp:95]\n")
    monkeypatch.setitem(interrupts._PENDING, "interrupt", True)
    for piece in ("CasADi - ", "2026-01-01 WARNING(\"\") [x.cpp:132]", "\n"):
        err.write(piece)
    err.write("oilgap: interrupted\n")
    assert buf.getvalue() == "oilgap: interrupted\n"
