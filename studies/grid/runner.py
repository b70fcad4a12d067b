"""The grid runner: a grid of parameter combinations in, a DataFrame of results out.

:func:`run_grid` evaluates every row (``mode="evaluate"``: the mean viscous
power over the duty cycle and its parts, :mod:`oilgap.studies.grid.evaluate`)
or optimizes it (``mode="optimize"``: one design NLP per row, warm-started from
the previous row of the same chunk, :mod:`oilgap.studies.grid.optimize`) and
returns one result row per grid row.

* Speed: the grid is cut into chunks that run on all local cores
  (:mod:`concurrent.futures`); inside a chunk, evaluation is vectorised.
* Robustness: a point that fails (a geometry the case refuses, a solver
  failure) is a row with ``status = "error"`` and its message in ``error``;
  the sweep goes on.
* Resumable: with ``out_dir``, each finished chunk is stored at once, whole or not
  at all, and folded into ``out_dir/points_<mode>.csv``
  (:mod:`oilgap.studies.grid.store`); a rerun with the same folder checks the
  store (partial rows dropped and counted) and computes only the points not in it.
* One run per folder: ``out_dir`` is locked for the run
  (:class:`oilgap.model.result_folder.FolderLock`); a second run is refused.
* Ctrl-C: the workers ignore SIGINT; the pool is stopped and its workers ended, and
  ``KeyboardInterrupt`` reaches the caller alone (no worker tracebacks).
"""

from __future__ import annotations

import contextlib
import math
import os
import signal
import sys
import time
import warnings
from collections.abc import Callable, Iterable, Mapping
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from pathlib import Path
from typing import IO

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.case_io import seed_case
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.files import OutputError, atomic_to_csv
from oilgap.model.joint_loss import default_thermal_mode, resolve_thermal_mode
from oilgap.model.oils import Oil, get_oil, read_oils_csv
from oilgap.model.result_folder import FolderLock
from oilgap.studies.grid.columns import THERMAL_COLUMNS, result_columns
from oilgap.studies.grid.evaluate import evaluate_chunk
from oilgap.studies.grid.optimize import nlp_thermal_modes, optimize_chunk
from oilgap.studies.grid.schema import WHERE, check_thermal_columns, validate_grid
from oilgap.studies.grid.store import (
    append_points,
    chunks_dir,
    finished_points,
    fold_chunks,
    point_keys,
    points_path,
    repair_store,
)

DEFAULT_EVAL_CHUNK = 1000
"""Rows per chunk in evaluate mode (vectorised inside a chunk)."""


# --------------------------------------------------------------------------- progress


class Progress:
    """A one-line progress bar on stderr: bar, percent, count, elapsed time and ETA."""

    def __init__(self, total: int, label: str = "sweep", enabled: bool = True,
                 stream: IO[str] | None = None, width: int = 30, min_interval_s: float = 0.1):
        self.total = max(int(total), 0)
        self.label = label
        self.enabled = enabled
        self.stream = stream if stream is not None else sys.stderr
        self.width = width
        self.min_interval_s = min_interval_s
        self.done = 0
        self.t0 = time.perf_counter()
        self._last = -1.0

    def line(self) -> str:
        """The current progress line (without carriage return)."""
        frac = 1.0 if self.total == 0 else self.done / self.total
        filled = int(frac * self.width)
        el = time.perf_counter() - self.t0
        eta = el / frac - el if 0 < frac < 1 else 0.0
        return (f"oilgap {self.label} [{'#' * filled}{'-' * (self.width - filled)}] "
                f"{100 * frac:5.1f}% {self.done}/{self.total} points  {el:.1f} s"
                + (f"  ETA {eta:.1f} s" if 0 < frac < 1 else ""))

    def update(self, n: int = 1) -> None:
        """Advance by ``n`` points and redraw (at most every ``min_interval_s``)."""
        self.done += n
        now = time.perf_counter()
        if self.enabled and (now - self._last >= self.min_interval_s or self.done >= self.total):
            self._last = now
            self.stream.write("\r" + self.line())
            self.stream.flush()

    def abort(self) -> None:
        """End the line where it stands (a failure or Ctrl-C: the message that follows
        starts on a line of its own)."""
        if self.enabled and self._last >= 0:
            self.stream.write("\n")
            self.stream.flush()

    def close(self) -> None:
        """Finish the line."""
        if self.enabled:
            self.stream.write("\r" + self.line() + "\n")
            self.stream.flush()


# --------------------------------------------------------------------------- chunks


def chunks(items: list, size: int) -> Iterable[list]:
    """``items`` in consecutive slices of ``size`` (the last one shorter)."""
    for i in range(0, len(items), size):
        yield items[i:i + size]


def run_chunk(mode: str, base: DesignCase, rows: list[dict],
              catalogue: Mapping[str, Oil] | None, thermal: str = "none") -> list[dict]:
    """One task: evaluate or optimize a chunk of rows under a thermal mode (OilgapWarnings
    silenced; they are reported per row in ``warning``)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        if mode == "evaluate":
            return evaluate_chunk(base, rows, catalogue, thermal)
        return optimize_chunk(base, rows, catalogue, thermal)


def resolve_grid_thermal(base: DesignCase, mode: str, thermal: str | None
                         ) -> tuple[str, bool]:
    """(thermal mode, whether it is the default) of a grid run.

    ``None`` asks for the best physics: in evaluate mode the case's
    (:func:`~oilgap.model.joint_loss.default_thermal_mode`: ``full`` with ``[thermal]``,
    else ``film``); in optimize mode the best the design NLP carries
    (:func:`~oilgap.studies.grid.optimize.nlp_thermal_modes`).

    Raises
    ------
    InputError
        An unknown mode, ``full`` without ``[thermal]``, or a mode the design NLP does
        not carry (optimize mode).
    """
    if mode == "optimize":
        carried = nlp_thermal_modes()
        if thermal is None:
            best = default_thermal_mode(base)
            return (best if best in carried else "none"), True
        resolved = resolve_thermal_mode(base, thermal)
        if resolved not in carried:
            raise InputError("thermal", thermal, "optimize mode: the design NLP carries only "
                             f"{', '.join(carried)} so far", WHERE)
        return resolved, False
    return resolve_thermal_mode(base, thermal), thermal is None


def _check_workers(workers: int | None) -> int:
    if workers is None:
        workers = os.cpu_count() or 1
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise InputError("workers", workers, "must be an integer >= 1", WHERE)
    return workers


def _catalogue(grid: pd.DataFrame, base: DesignCase,
               catalogue: Mapping[str, Oil] | None) -> Mapping[str, Oil] | None:
    """The oils to look names up in; every ``oil`` of the grid must be there (an unknown
    oil name is a bad study parameter, not a failed point)."""
    if catalogue is None and base.oils_csv:
        catalogue = read_oils_csv(base.oils_csv)
    if "oil" in grid.columns:
        for name in pd.unique(grid["oil"].dropna()):
            get_oil(str(name), catalogue)
    return catalogue


def _chunk_size(chunk_size: int | None, mode: str, n: int, workers: int) -> int:
    """Rows per task: given, else 1000 (evaluate) or ``n`` split evenly over the workers
    (optimize: each chunk one warm-started chain)."""
    if chunk_size is None:
        chunk_size = DEFAULT_EVAL_CHUNK if mode == "evaluate" else max(
            1, math.ceil(n / max(workers, 1)))
    return max(1, int(chunk_size))


def _open_store(out_dir: str | Path | None, mode: str, retry_failed: bool,
                stack: contextlib.ExitStack) -> tuple[Path | None, dict[str, dict]]:
    """The points file in ``out_dir`` (created and locked for the run; the lock is
    released by ``stack``), checked (:func:`repair_store`), and the points already
    finished there; (None, {}) without ``out_dir``."""
    if out_dir is None:
        return None, {}
    store = points_path(out_dir, mode)
    new = [] if Path(out_dir).is_dir() else [Path(out_dir)]
    try:
        Path(out_dir).mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise OutputError(out_dir, e) from None
    for d in (*new, chunks_dir(store)):  # after the lock is released: empty folders go
        stack.callback(_rmdir_if_empty, d)
    stack.enter_context(FolderLock(out_dir, "out_dir"))
    repair_store(store, mode)
    return store, finished_points(store, mode, retry_failed)


def _rmdir_if_empty(d: Path) -> None:
    with contextlib.suppress(OSError):
        d.rmdir()


def _todo(keys: list[str], grid: pd.DataFrame, done: Mapping[str, dict]
          ) -> tuple[list[str], list[dict]]:
    """Keys and rows still to compute: not stored, each distinct key once."""
    todo_keys: list[str] = []
    todo_rows: list[dict] = []
    seen = set(done)
    for k, rec in zip(keys, grid.to_dict("records"), strict=True):
        if k not in seen:
            seen.add(k)
            todo_keys.append(k)
            todo_rows.append(rec)
    return todo_keys, todo_rows


def _execute(tasks: list[tuple[list[str], list[dict]]], mode: str, base: DesignCase,
             catalogue: Mapping[str, Oil] | None, workers: int,
             finish: Callable[[list[str], list[dict]], None], thermal: str = "none",
             on_abort: Callable[[], None] | None = None) -> None:
    """Run the tasks here (one worker or one task) or on a process pool; ``finish`` each
    chunk as it completes; ``on_abort`` when a failure or Ctrl-C stops them."""
    try:
        _run_tasks(tasks, mode, base, catalogue, workers, finish, thermal)
    except BaseException:
        if on_abort is not None:
            on_abort()
        raise


def _run_tasks(tasks, mode, base, catalogue, workers, finish, thermal) -> None:
    if not tasks:
        return
    if workers == 1 or len(tasks) == 1:
        for ks, rows in tasks:
            finish(ks, run_chunk(mode, base, rows, catalogue, thermal))
        return
    ex = ProcessPoolExecutor(max_workers=min(workers, len(tasks)),
                             initializer=_ignore_sigint)
    try:
        futs = {ex.submit(run_chunk, mode, base, rows, catalogue, thermal): ks
                for ks, rows in tasks}
        pending = set(futs)
        while pending:
            fin, pending = wait(pending, return_when=FIRST_COMPLETED)
            for f in fin:
                finish(futs[f], f.result())
    except BaseException:
        _stop_pool(ex)
        raise
    ex.shutdown(wait=True)


def _ignore_sigint() -> None:
    """Worker initializer: Ctrl-C goes to the whole process group; the parent alone
    handles it (no traceback per worker)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _stop_pool(ex: ProcessPoolExecutor) -> None:
    """Stop a pool at once: pending chunks cancelled, running workers ended (their
    chunks are not stored; a rerun computes them)."""
    procs = list((getattr(ex, "_processes", None) or {}).values())
    ex.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        with contextlib.suppress(Exception):
            p.terminate()
    for p in procs:
        with contextlib.suppress(Exception):
            p.join(5)


def _assemble(grid: pd.DataFrame, keys: list[str], done: Mapping[str, dict],
              mode: str) -> pd.DataFrame:
    """The grid's columns then the result columns, one row per grid row."""
    cols = result_columns(mode)
    res = pd.DataFrame([{c: done[k].get(c) for c in cols} for k in keys], columns=list(cols))
    for c in ("error", "warning"):
        res[c] = res[c].astype(object).where(res[c].notna(), None)
    grid = grid.copy()
    for c in THERMAL_COLUMNS:  # a grid cell left empty shows the base case's value used
        if c in grid.columns and c in res.columns:
            grid[c] = grid[c].where(grid[c].notna(), res[c])
    res = res.drop(columns=[c for c in res.columns if c in grid.columns and c != "status"])
    result = pd.concat([grid, res], axis=1)
    result["point_key"] = keys
    return result


# --------------------------------------------------------------------------- the engine


def _bar(total: int, todo: int, label: str, progress: bool | None) -> Progress:
    """The progress line (default: shown when stderr is a terminal), ``total - todo``
    points already done."""
    if progress is None:
        progress = bool(getattr(sys.stderr, "isatty", lambda: False)())
    bar = Progress(total, label, progress)
    bar.done = total - todo
    return bar


def _finisher(done: dict, store: Path | None, mode: str, bar: Progress,
              on_chunk: Callable[[int], None] | None
              ) -> Callable[[list[str], list[dict]], None]:
    """What happens to each finished chunk: kept, appended to the store, counted."""

    def finish(ks: list[str], recs: list[dict]) -> None:
        for k, r in zip(ks, recs, strict=True):
            done[k] = r
        if store is not None:
            append_points(store, ks, recs, mode)
        bar.update(len(ks))
        if on_chunk is not None:
            on_chunk(len(ks))

    return finish


def _checked(grid: pd.DataFrame, case: DesignCase | None, mode: str, thermal: str | None
             ) -> tuple[pd.DataFrame, DesignCase, str, bool]:
    """(grid checked, base case, thermal mode, whether it is the default)."""
    grid = validate_grid(grid, mode)
    base = case if case is not None else seed_case()
    thermal, by_default = resolve_grid_thermal(base, mode, thermal)
    check_thermal_columns(grid, thermal, base)
    return grid, base, thermal, by_default


def run_grid(grid: pd.DataFrame, case: DesignCase | None = None, mode: str = "evaluate",
             out_dir: str | Path | None = None, workers: int | None = None,
             chunk_size: int | None = None, progress: bool | None = None,
             catalogue: Mapping[str, Oil] | None = None,
             label: str = "sweep", retry_failed: bool = False,
             on_chunk: Callable[[int], None] | None = None,
             thermal: str | None = "none") -> pd.DataFrame:
    """Evaluate or optimize every row of a grid of parameter combinations.

    Parameters
    ----------
    grid : DataFrame
        One row per point; columns from :data:`PARAM_COLUMNS` (and
        :data:`OPTIMIZE_COLUMNS` in optimize mode); an empty cell keeps the
        base case's value.
    case : DesignCase, optional
        Base case (default: the seed joint, grooved).
    mode : {"evaluate", "optimize"}
    out_dir : path, optional
        Folder for ``points_<mode>.csv`` (finished points, appended chunk by
        chunk) and ``results.csv``; a rerun with the same folder skips the
        points already there.
    workers : int, optional
        Processes (default: all local cores; 1 runs in this process).
    chunk_size : int, optional
        Rows per task (default: 1000 in evaluate mode; in optimize mode the
        grid split evenly over the workers so that each chunk is one
        warm-started chain).
    progress : bool, optional
        Progress line on stderr (default: when stderr is a terminal).
    catalogue : mapping, optional
        Oils to look ``oil`` names up in (default: the case's ``oils_csv`` or
        the built-in ISO VG catalogue).
    retry_failed : bool
        Recompute points stored as errors (default: they count as finished).
    thermal : {"none", "film", "full"} or None
        Thermal mode (:mod:`oilgap.model.joint_loss`; default ``"none"``, the
        isothermal model; None: the best physics, :func:`resolve_grid_thermal`).
        Under ``full`` the grid may hold ``sea_temp_C``, ``resistance_K_per_W``
        and not ``oil_temp_C`` (a result: ``oil_temp_op_C``).

    Returns
    -------
    DataFrame
        The grid's columns, then ``status`` ("ok"/"error"), ``error``,
        ``warning``, ``thermal_mode`` and the result columns
        (:data:`EVALUATE_RESULTS` or :data:`OPTIMIZE_RESULTS`); ``point_key``
        identifies the point. ``attrs``: ``thermal_mode``, ``thermal_default``,
        ``computed``, ``reused``, ``elapsed_s``.

    Raises
    ------
    InputError
        Bad grid (:func:`validate_grid`), unknown oil, bad ``workers``, a thermal
        mode or column the case refuses (:func:`check_thermal_columns`).
    """
    grid, base, thermal, by_default = _checked(grid, case, mode, thermal)
    catalogue = _catalogue(grid, base, catalogue)
    workers = _check_workers(workers)
    keys = point_keys(grid, base, mode, {"thermal": thermal})
    with contextlib.ExitStack() as stack:
        store, done = _open_store(out_dir, mode, retry_failed, stack)
        todo_keys, todo_rows = _todo(keys, grid, done)
        n = len(todo_rows)
        chunk_size = _chunk_size(chunk_size, mode, n, workers)
        bar = _bar(len(keys), n, label, progress)
        finish = _finisher(done, store, mode, bar, on_chunk)
        tasks = list(zip(chunks(todo_keys, chunk_size), chunks(todo_rows, chunk_size),
                         strict=True))
        _execute(tasks, mode, base, catalogue, workers, finish, thermal, bar.abort)
        bar.close()
        result = _assemble(grid, keys, done, mode)
        result.attrs.update(thermal_mode=thermal, thermal_default=by_default, computed=n,
                            reused=len(keys) - n, elapsed_s=time.perf_counter() - bar.t0)
        if store is not None:
            fold_chunks(store, mode)
            atomic_to_csv(result, Path(out_dir) / "results.csv", index=False)
    return result
