"""The grid runner: a grid of parameter combinations in, a DataFrame of results out.

:func:`run_grid` evaluates every row (``mode="evaluate"``: the mean viscous
power over the duty cycle and its parts, :mod:`oilgap.studies.grid.evaluate`)
or optimizes it (``mode="optimize"``: one design NLP per row, warm-started from
the previous row of the same chunk, :mod:`oilgap.studies.grid.optimize`) and
returns one result row per grid row.

* Speed: the grid is cut into chunks of a few seconds each
  (:mod:`oilgap.studies.grid.chunking`) that run on all local cores, or on a Dask
  cluster (``scheduler``, :mod:`oilgap.studies.grid.backends`), with the same rows
  and numbers; inside a chunk, evaluation is vectorised.
* Robustness: a point that fails (a geometry the case refuses, a solver
  failure) is a row with ``status = "error"`` and its message in ``error``;
  the sweep goes on.
* Resumable: with ``out_dir``, each finished chunk is stored at once, whole or not
  at all, and folded into ``out_dir/points_<mode>.csv``
  (:mod:`oilgap.studies.grid.store`); a rerun with the same folder checks the
  store (partial rows dropped and counted) and computes only the points not in it.
  The results are ``results.csv`` and ``results.parquet``.
* One run per folder: ``out_dir`` is locked for the run
  (:class:`oilgap.studies.io.result_folder.FolderLock`); a second run is refused.
* Ctrl-C: the workers ignore SIGINT; the pool is stopped and its workers ended, and
  :class:`SweepInterrupted` (a ``KeyboardInterrupt`` saying how many points are
  stored) reaches the caller alone (no worker tracebacks); at most one chunk per
  worker is lost.
"""

from __future__ import annotations

import contextlib
import math
import os
import time
import warnings
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path

import numpy as np
import pandas as pd
from tqdm import tqdm

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import default_thermal_mode, resolve_thermal_mode
from oilgap.model.oils import Oil, get_oil, read_oils_csv, with_builtin
from oilgap.studies.grid.backends import InlineBackend, check_scheduler, make_backend
from oilgap.studies.grid.chunking import ChunkSizer
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
from oilgap.studies.io.files import OutputError, atomic_to_csv, atomic_to_parquet
from oilgap.studies.io.result_folder import FolderLock
from oilgap.studies.progress import progress_bar
from oilgap.studies.settings import DEFAULT_CHUNK_SECONDS, RunOptions, SweepSettings

# --------------------------------------------------------------------------- progress
# the bar is oilgap's one progress display (studies/progress.py), re-exported here

# --------------------------------------------------------------------------- chunks


def chunks(items: list, size: int) -> Iterable[list]:
    """``items`` in consecutive slices of ``size`` (the last one shorter)."""
    for i in range(0, len(items), size):
        yield items[i:i + size]


def run_chunk(mode: str, base: DesignCase, rows: list[dict],
              catalogue: Mapping[str, Oil] | None, thermal: str = "none",
              chain: int | None = None) -> list[dict]:
    """One task: evaluate or optimize a chunk of rows under a thermal mode (OilgapWarnings
    silenced; they are reported per row in ``warning``); in optimize mode each run of
    ``chain`` rows is one warm-started chain (default: the whole chunk)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        if mode == "evaluate":
            return evaluate_chunk(base, rows, catalogue, thermal)
        return optimize_chunk(base, rows, catalogue, thermal, chain=chain)


def timed_chunk(mode: str, base: DesignCase, rows: list[dict],
                catalogue: Mapping[str, Oil] | None, thermal: str = "none",
                chain: int | None = None) -> tuple[list[dict], float]:
    """:func:`run_chunk` and its wall time on the worker [s] (what chunks are sized by)."""
    t0 = time.perf_counter()
    recs = run_chunk(mode, base, rows, catalogue, thermal, chain)
    return recs, time.perf_counter() - t0


def resolve_grid_thermal(base: DesignCase, mode: str, thermal: str | None
                         ) -> tuple[str, bool]:
    """(thermal mode, whether it is the default) of a grid run.

    ``None`` asks for the default: in evaluate mode the case's
    (:func:`~oilgap.model.joint_loss.default_thermal_mode`: ``bulk`` with ``[thermal]``,
    else ``none``); in optimize mode the same when the design NLP carries it
    (:func:`~oilgap.studies.grid.optimize.nlp_thermal_modes`).

    Raises
    ------
    InputError
        An unknown mode, ``bulk``/``full`` without ``[thermal]``, or a mode the design NLP does
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


def _catalogue(grid: pd.DataFrame, base: DesignCase,
               catalogue: Mapping[str, Oil] | None) -> Mapping[str, Oil] | None:
    """The oils to look names up in; every ``oil`` of the grid must be there (an unknown
    oil name is a bad study parameter, not a failed point)."""
    if catalogue is None and base.oils_csv:
        catalogue = with_builtin(read_oils_csv(base.oils_csv), "oil.oils_csv")
    if "oil" in grid.columns:
        for name in pd.unique(grid["oil"].dropna()):
            get_oil(str(name), catalogue)
    return catalogue


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
    k = pd.Series(keys, dtype=object)
    new = ~k.duplicated().to_numpy() & ~k.isin(list(done)).to_numpy()
    idx = np.flatnonzero(new)
    return [keys[i] for i in idx.tolist()], grid.iloc[idx].to_dict("records")


def _execute(backend, sizer: ChunkSizer, todo_keys: list[str], todo_rows: list[dict],
             job: tuple, finish: Callable[[list[str], list[dict]], None]) -> None:
    """Submit the rows chunk by chunk (sized by ``sizer``, at most two chunks per worker
    in flight) and ``finish`` each chunk as it completes; on a failure or Ctrl-C the
    backend is stopped at once (the chunks not finished are not stored)."""
    slots = 1 if isinstance(backend, InlineBackend) else 2 * backend.workers
    pos, n, inflight = 0, len(todo_rows), {}
    try:
        while pos < n or inflight:
            while pos < n and len(inflight) < slots:
                size = sizer.next_size(n - pos)
                ks, rows = todo_keys[pos:pos + size], todo_rows[pos:pos + size]
                pos += size
                inflight[backend.submit(timed_chunk, *job[:2], rows, *job[2:],
                                        sizer.chain)] = ks
            for f in backend.wait_any(list(inflight)):
                ks = inflight.pop(f)
                recs, seconds = f.result()
                sizer.observe(len(ks), seconds)
                finish(ks, recs)
    except BaseException:
        backend.close(abort=True, pending=list(inflight))
        raise
    backend.close()


def _assemble(grid: pd.DataFrame, keys: list[str], done: Mapping[str, dict],
              mode: str) -> pd.DataFrame:
    """The grid's columns then the result columns, one row per grid row."""
    cols = result_columns(mode)
    recs = [done[k] for k in keys]
    res = pd.DataFrame({c: [r.get(c) for r in recs] for c in cols}, columns=list(cols))
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


class SweepInterrupted(KeyboardInterrupt):
    """Ctrl-C during a run with an ``out_dir``: how many of the grid's points are stored.

    Attributes
    ----------
    saved, total : int
        Grid rows whose points are stored, and all rows [-].
    out_dir : Path
        The folder [-].
    """

    def __init__(self, saved: int, total: int, out_dir: str | Path):
        self.saved, self.total, self.out_dir = int(saved), int(total), Path(out_dir)
        super().__init__(f"{self.saved} of {self.total} points saved in {self.out_dir}")


def _finisher(done: dict, store: Path | None, mode: str, bar: tqdm,
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


def run_grid(grid: pd.DataFrame, case: DesignCase | None = None,
             settings: SweepSettings | None = None, options: RunOptions | None = None, *,
             out_dir: str | Path | None = None, catalogue: Mapping[str, Oil] | None = None,
             label: str = "sweep",
             on_chunk: Callable[[int], None] | None = None) -> pd.DataFrame:
    """Evaluate or optimize every row of a grid of parameter combinations.

    Parameters
    ----------
    grid : DataFrame
        One row per point; columns from :data:`PARAM_COLUMNS` (and
        :data:`OPTIMIZE_COLUMNS` in optimize mode); an empty cell keeps the
        base case's value.
    case : DesignCase, optional
        Base case (default: the seed joint, grooved).
    settings : SweepSettings, optional
        ``mode`` (``"evaluate"`` or ``"optimize"``), ``thermal`` (None: the default,
        :func:`resolve_grid_thermal`; under ``bulk``/``full`` the grid may hold
        ``sea_temp_C``, ``resistance_K_per_W`` and not ``oil_temp_C``, a result:
        ``oil_temp_op_C``) and ``retry_failed`` (recompute points stored as errors;
        default: they count as finished). Default ``SweepSettings()``.
    options : RunOptions, optional
        ``workers`` (processes; default all local cores; 1 runs in this process; with
        ``scheduler="local"`` the processes of the LocalCluster), ``scheduler`` (None:
        local processes, ``"local"``: a Dask LocalCluster, ``"tcp://HOST:PORT"``: a
        running Dask scheduler, :mod:`oilgap.studies.grid.backends`; the same rows and
        numbers), ``progress`` (progress line on stderr; default: when stderr is a
        terminal), ``chunk_size`` (fixed rows per task; in optimize mode each chunk is
        then one warm-started chain; default: chunks sized by time, with fixed chains of
        :data:`~oilgap.studies.grid.chunking.WARM_CHAIN` rows in optimize mode) and
        ``chunk_seconds`` (target wall time of a chunk on its worker [s], default 3,
        :mod:`oilgap.studies.grid.chunking`).
    out_dir : path, optional
        Folder for ``points_<mode>.csv`` (finished points, stored chunk by chunk)
        and ``results.csv``/``results.parquet``; a rerun with the same folder skips
        the points already there.
    catalogue : mapping, optional
        Oils to look ``oil`` names up in (default: the case's ``oils_csv`` or
        the built-in ISO VG catalogue).
    label : str
        The progress line's label.
    on_chunk : callable, optional
        Called with the rows of each finished chunk.

    Returns
    -------
    DataFrame
        The grid's columns, then ``status`` ("ok"/"error"), ``error``,
        ``warning``, ``thermal_mode`` and the result columns
        (:data:`EVALUATE_RESULTS` or :data:`OPTIMIZE_RESULTS`); ``point_key``
        identifies the point. ``attrs``: ``thermal_mode``, ``thermal_default``,
        ``computed``, ``reused``, ``elapsed_s`` [s], ``backend``, ``chunks``,
        ``worker_s`` (the chunks' wall time on their workers, summed) [s],
        ``backend_start_s`` (starting the pool or cluster, or connecting) [s].

    Raises
    ------
    InputError
        Bad grid (:func:`validate_grid`), unknown oil, bad ``workers``, a thermal
        mode or column the case refuses (:func:`check_thermal_columns`), a bad
        ``scheduler`` (no dask, nobody answering at the address).
    SweepInterrupted
        Ctrl-C with an ``out_dir``: the points finished so far are stored (a
        ``KeyboardInterrupt`` saying how many).
    """
    s = settings if settings is not None else SweepSettings()
    o = options if options is not None else RunOptions()
    mode, progress = s.mode, o.progress
    grid, base, thermal, by_default = _checked(grid, case, mode, s.thermal)
    catalogue = _catalogue(grid, base, catalogue)
    workers = o.workers if o.workers is not None else (os.cpu_count() or 1)
    scheduler = check_scheduler(o.scheduler)
    sizer = ChunkSizer(mode, workers, DEFAULT_CHUNK_SECONDS if o.chunk_seconds is None
                       else o.chunk_seconds, o.chunk_size)
    keys = point_keys(grid, base, mode, {"thermal": thermal})
    t0 = time.perf_counter()
    with contextlib.ExitStack() as stack:
        store, done = _open_store(out_dir, mode, s.retry_failed, stack)
        todo_keys, todo_rows = _todo(keys, grid, done)
        n = len(todo_rows)
        t_start = time.perf_counter()
        backend = make_backend(scheduler, workers, _tasks(sizer, n)) if n else None
        started_s = time.perf_counter() - t_start
        bar = stack.enter_context(progress_bar(len(keys), label, progress,
                                               initial=len(keys) - n))
        finish = _finisher(done, store, mode, bar, on_chunk)
        try:
            if backend is not None:
                _execute(backend, sizer, todo_keys, todo_rows,
                         (mode, base, catalogue, thermal), finish)
        except KeyboardInterrupt:
            if store is None:
                raise
            saved = sum(k in done for k in keys)
            raise SweepInterrupted(saved, len(keys), out_dir) from None
        result = _assemble(grid, keys, done, mode)
        result.attrs.update(thermal_mode=thermal, thermal_default=by_default, computed=n,
                            reused=len(keys) - n, elapsed_s=time.perf_counter() - t0,
                            backend=backend.name if backend is not None else "none",
                            chunks=sizer.chunks, worker_s=sizer.seconds,
                            backend_start_s=started_s)
        if store is not None:
            fold_chunks(store, mode)
            write_results(result, Path(out_dir))
    return result


def _tasks(sizer: ChunkSizer, n: int) -> int:
    """Chunks a run of ``n`` rows takes at least (1 or more) [-]."""
    first = sizer.next_size(n)
    return math.ceil(n / first) if first else 0


def write_results(result: pd.DataFrame, out_dir: Path) -> tuple[Path, Path]:
    """``results.csv`` and ``results.parquet`` in ``out_dir``, each written atomically."""
    csv = atomic_to_csv(result, out_dir / "results.csv", index=False)
    pq = atomic_to_parquet(_for_parquet(result), out_dir / "results.parquet", index=False)
    return csv, pq


def _for_parquet(result: pd.DataFrame) -> pd.DataFrame:
    """Text columns as text (None kept), the rest as they are: Arrow needs one type per
    column."""
    out = result.copy()
    out.attrs = {}
    for c in out.columns:
        if out[c].dtype == object:
            out[c] = out[c].map(lambda v: None if v is None or (isinstance(v, float)
                                                                and math.isnan(v)) else str(v))
    return out
