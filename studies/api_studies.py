"""The façade's studies: ``og.pareto``, ``og.oil_grade``, ``og.smoothing``, ``og.sweep``
(``oilgap study pareto|oil-grade|smoothing|sweep``).

Each runs the study's module-level ``run`` and wraps its result in a view
(:mod:`oilgap.studies.results_studies`). With ``out`` the study writes its files into
that folder as the command does: the folder is checked and locked before any computation
(:class:`~oilgap.studies.io.result_folder.ResultFolder`), earlier outputs are refused unless
``force`` (a sweep continues with ``resume``); ``folder`` is a result folder the caller
(the command line) already opened.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.io.defaults import gamma_fields
from oilgap.model.oils import Oil
from oilgap.studies import oil_grade as oil_grade_study
from oilgap.studies import pareto as pareto_study
from oilgap.studies import smoothing as smoothing_study
from oilgap.studies.api import as_case, oil_catalogue
from oilgap.studies.grid.chunking import DEFAULT_CHUNK_SECONDS
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.grid.schema import read_grid
from oilgap.studies.io.result_folder import ResultFolder
from oilgap.studies.oil_grade import (
    DEFAULT_DEPTH_RANGE_M,
    DEFAULT_MISSION_HOURS,
    DEFAULT_NU_MAX_CST,
    DEFAULT_NU_MIN_CST,
    read_mission_csv,
)
from oilgap.studies.outputs import result_folder
from oilgap.studies.results_studies import OilGrade, Pareto, Smoothing
from oilgap.studies.results_sweep import Sweep, write_sweep_outputs


def _begin(folder: ResultFolder | None, case: DesignCase) -> None:
    """Writing starts; the case's gamma (as read) into the folder's ``provenance.json``."""
    if folder is not None:
        folder.note(**gamma_fields(case))
        folder.begin()


def _passed(**kwargs: Any) -> dict:
    """The options given (not None): passed on only when the caller chose them."""
    return {k: v for k, v in kwargs.items() if v is not None}


def _out(out: str | Path | None) -> Path | None:
    return None if out is None else Path(out)


def _note(folder: ResultFolder | None, mode: str, default: bool) -> None:
    """The study's thermal mode into its folder's ``provenance.json``."""
    if folder is not None:
        folder.note(thermal_mode=mode, thermal_mode_default=bool(default))


def pareto(case: DesignCase | str | Path | None = None, *,
           points: int = pareto_study.DEFAULT_POINTS, torque_min_Nm: float | None = None,
           out: str | Path | None = None, force: bool = False, workers: int | None = None,
           scheduler: str | None = None, progress: bool | None = False,
           folder: ResultFolder | None = None, thermal: str | None = None) -> Pareto:
    """The gap-loss and loss-inertia Pareto fronts by epsilon-constraint sweeps
    (``oilgap study pareto``; :func:`oilgap.studies.pareto.run`).

    Parameters
    ----------
    case : DesignCase, path or None
        The joint (None: the seed joint).
    points : int
        Points per front (>= 50).
    torque_min_Nm : float, optional
        Required torque capability [N m] (default: the case's own).
    out : path, optional
        Folder for the CSVs, figures and ``summary.md``.
    force : bool
        Replace earlier outputs in ``out``.
    workers, scheduler : optional
        Processes, and a Dask scheduler (``"local"``, ``"tcp://HOST:PORT"``), where the
        study takes them.
    progress : bool, optional
        Progress bar on stderr.
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode of the fronts and the marked designs (default: ``bulk`` with
        ``[thermal]``, else ``none``, as ``og.evaluate`` and ``og.optimize``).

    Returns
    -------
    Pareto
    """
    base = as_case(case)
    extra = _passed(workers=workers, scheduler=scheduler)
    with result_folder("study pareto", out, force, folder=folder) as f:
        _begin(f, base)
        r = pareto_study.run(out, base, points, torque_min_Nm, progress, thermal=thermal,
                             **extra)
        _note(f, r.thermal_mode, r.thermal_default)
    return Pareto(r, base, _out(out))


def _mission(mission: Any) -> Any:
    """A mission as :func:`oilgap.studies.oil_grade.parse_mission` takes it: a CSV path
    read, a list of dicts made a DataFrame."""
    if isinstance(mission, (str, Path)):
        return read_mission_csv(mission)
    if isinstance(mission, list) and mission and isinstance(mission[0], dict):
        return pd.DataFrame(mission)
    return mission


def oil_grade(case: DesignCase | str | Path | None = None, *, mission: Any = None,
              thermal: str | None = None, nu_min_cSt: float = DEFAULT_NU_MIN_CST,
              nu_max_cSt: float = DEFAULT_NU_MAX_CST,
              depth_range_m: Sequence[float] = DEFAULT_DEPTH_RANGE_M,
              temp_range_C: Sequence[float] | None = None,
              sea_temp_range_C: Sequence[float] | None = None,
              mission_hours: float = DEFAULT_MISSION_HOURS, out: str | Path | None = None,
              force: bool = False, workers: int | None = None,
              scheduler: str | None = None, progress: bool | None = False,
              folder: ResultFolder | None = None, **options: Any) -> OilGrade:
    """The ISO VG grade for a joint over its envelope and mission (``oilgap study
    oil-grade``; :func:`oilgap.studies.oil_grade.run`).

    Parameters
    ----------
    case : DesignCase, path or None
        The joint (None: the seed joint).
    mission : list of dicts, DataFrame, CSV path or None
        Rows ``depth_m`` [m], ``oil_temp_C`` [degC], ``fraction`` [-] (default: the
        case's ``[[mission]]`` rows, else the study's default mission).
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode (default: ``bulk`` with ``[thermal]``, else ``none``).
    nu_min_cSt, nu_max_cSt : float
        Lubrication and cold-start limits [cSt].
    depth_range_m, temp_range_C, sea_temp_range_C : pairs of float
        The envelope [m], [degC] (oil's under none/film, sea's under bulk/full).
    mission_hours : float
        Mission duration [h].
    out, force, workers, scheduler, progress
        As :func:`pareto` (the grid of grades and envelope runs on the scheduler).
    **options
        Other options of :func:`oilgap.studies.oil_grade.run` (``grades``,
        ``iso_tolerance``, ``n_depth``, ``n_temp``, ``rated_temps_C``).

    Returns
    -------
    OilGrade
    """
    base = as_case(case)
    m = _mission(mission)
    with result_folder("study oil-grade", out, force, folder=folder) as f:
        _begin(f, base)
        r = oil_grade_study.run(out, base, m, nu_min_cSt=nu_min_cSt, nu_max_cSt=nu_max_cSt,
                                depth_range_m=depth_range_m, temp_range_C=temp_range_C,
                                sea_temp_range_C=sea_temp_range_C,
                                mission_hours=mission_hours, workers=workers,
                                progress=progress, thermal=thermal, scheduler=scheduler,
                                **options)
        _note(f, r.thermal_mode, r.settings["thermal_default"])
    return OilGrade(r, base, _out(out))


def smoothing(case: DesignCase | str | Path | None = None, *, method: str | None = None,
              thermal: str | None = None, resistance_K_W: float = 0.0,
              T_values: Sequence[float] | None = None,
              plateau_tol: float = smoothing_study.PLATEAU_TOL,
              out: str | Path | None = None, force: bool = False,
              folder: ResultFolder | None = None, film_evidence: bool = False) -> Smoothing:
    """What smoothing the grooves saves (``oilgap study smoothing``;
    :func:`oilgap.studies.smoothing.run`): the fit on the seed's Table 4 and the loss
    against the roughness T.

    Parameters
    ----------
    case : DesignCase, path or None
        Base joint (None: the seed joint).
    method : {"per-oil", "shared", "heat-balance"}, optional
        How the runs' temperatures are fitted (default per-oil).
    thermal : {"none", "film", "full"}, optional
        The loss at the runs' temperatures (default none).
    resistance_K_W : float
        Per-oil method: fixed R_th [K/W].
    T_values : sequence of float, optional
        Roughness values of the loss-vs-T view [-] (default 1 to 5 by 0.05).
    plateau_tol : float
        Where the loss counts as levelled off [-] (fraction of P(T = 1)).
    out, force
        As :func:`pareto`.
    film_evidence : bool
        Also fit the film strength s with the rig's heat balance (seed rig only):
        ``result.film_evidence`` (docs/thermal.md#evidence).

    Returns
    -------
    Smoothing
    """
    base = as_case(case)
    T = None if T_values is None else np.asarray(T_values, dtype=float)
    with result_folder("study smoothing", out, force, folder=folder) as f:
        _begin(f, base)
        r = smoothing_study.run(out, case=base, method=method, resistance_K_W=resistance_K_W,
                                T_values=T, plateau_tol=plateau_tol, thermal=thermal,
                                film_evidence=film_evidence)
        _note(f, r.thermal_mode, r.thermal_default)
    return Smoothing(r, base, plateau_tol, _out(out))


def sweep(grid: pd.DataFrame | str | Path, case: DesignCase | str | Path | None = None, *,
          mode: str = "evaluate", thermal: str | None = None, out: str | Path | None = None,
          resume: bool = False, force: bool = False, workers: int | None = None,
          scheduler: str | None = None, progress: bool | None = None,
          oils: dict[str, Oil] | str | Path | None = None, chunk_size: int | None = None,
          chunk_seconds: float = DEFAULT_CHUNK_SECONDS, retry_failed: bool = False,
          folder: ResultFolder | None = None) -> Sweep:
    """Evaluate or optimize every row of a grid (``oilgap study sweep``;
    :func:`oilgap.studies.grid.runner.run_grid`), resumable in ``out``.

    Parameters
    ----------
    grid : DataFrame or path (CSV, Parquet)
        One row per point (columns: :data:`oilgap.studies.grid.columns.PARAM_COLUMNS`).
    case : DesignCase, path or None
        Base case (None: the seed joint).
    mode : {"evaluate", "optimize"}
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode (default: ``bulk`` with ``[thermal]``, else ``none``).
    out : path, optional
        Folder of the resumable store, ``results.csv``/``.parquet``, ``sweep.png`` and
        ``summary.md``.
    resume, force : bool
        Continue the sweep stored in ``out``, or discard it.
    workers, scheduler, progress, chunk_size, chunk_seconds, retry_failed
        As :func:`~oilgap.studies.grid.runner.run_grid`.
    oils : path or dict, optional
        Oils to look ``oil`` names up in.

    Returns
    -------
    Sweep
    """
    extra = _passed(scheduler=scheduler)
    resume = resume or retry_failed
    name = Path(grid).name if isinstance(grid, (str, Path)) else "the grid"
    with result_folder("study sweep", out, force, resume, folder) as f:  # before reading
        g = read_grid(grid) if isinstance(grid, (str, Path)) else grid
        base = as_case(case)
        cat = oil_catalogue(oils)
        _begin(f, base)
        t0 = time.perf_counter()
        res = run_grid(g, base, mode=mode, out_dir=out, workers=workers,
                       chunk_size=chunk_size, progress=progress, catalogue=cat,
                       retry_failed=retry_failed, thermal=thermal,
                       chunk_seconds=chunk_seconds, **extra)
        view = Sweep(res, base, g, mode, time.perf_counter() - t0, _out(out), name, scheduler)
        _note(f, view.thermal_mode, res.attrs.get("thermal_default", False))
        if out is not None:
            view.files = write_sweep_outputs(view, Path(out))
    return view


__all__ = ["oil_grade", "pareto", "result_folder", "smoothing", "sweep"]
