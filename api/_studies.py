"""The façade's studies: ``og.pareto``, ``og.oil_grade``, ``og.smoothing``, ``og.sweep``
(``oilgap study pareto|oil-grade|smoothing|sweep``).

Each runs the study's module-level ``run`` and wraps its result in a view
(:mod:`oilgap._results_studies`). With ``out`` the study writes its files into
that folder as the command does: the folder is checked and locked before any computation
(:class:`~oilgap.studies.io.result_folder.ResultFolder`), earlier outputs are refused unless
``force`` (a sweep continues with ``resume``); ``folder`` is a result folder the caller
(the command line) already opened. ``model=`` (a ``loop.json`` path, a FittedModel or a
fitted og.Loop) folds a calibrated loop model into the case first, as the command line's
``--model`` does.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import pandas as pd

from oilgap._checks import CASE, FLAG, GRID, MISSION, MODEL, OILS, OUT, Arg, checked
from oilgap._evaluate import as_case, oil_catalogue
from oilgap._results_linear import LeadFront
from oilgap._results_studies import OilGrade, Pareto, Smoothing
from oilgap._results_sweep import Sweep, write_sweep_outputs
from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError
from oilgap.model.io.defaults import gamma_fields
from oilgap.model.oils import Oil
from oilgap.studies import pareto as pareto_study
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.grid.schema import read_grid
from oilgap.studies.io.result_folder import ResultFolder
from oilgap.studies.oil_grade import study as oil_grade_study
from oilgap.studies.oil_grade.study import read_mission_csv
from oilgap.studies.outputs import result_folder
from oilgap.studies.settings import (
    OilGradeSettings,
    ParetoSettings,
    SmoothingSettings,
    SweepSettings,
    split_keywords,
)
from oilgap.studies.smoothing import study as smoothing_study


def _begin(folder: ResultFolder | None, case: DesignCase) -> None:
    """Writing starts; the case's gamma (as read) into the folder's ``provenance.json``."""
    if folder is not None:
        folder.note(**gamma_fields(case))
        folder.begin()


def _out(out: str | Path | None) -> Path | None:
    return None if out is None else Path(out)


def _note(folder: ResultFolder | None, mode: str, default: bool) -> None:
    """The study's thermal mode into its folder's ``provenance.json``."""
    if folder is not None:
        folder.note(thermal_mode=mode, thermal_mode_default=bool(default))


FOLDER = Arg(("ResultFolder",), "a ResultFolder the caller opened, or None", optional=True)
"""The ``folder`` argument (the command line's)."""
STUDY = dict(case=CASE, out=OUT, force=FLAG, folder=FOLDER)
"""The arguments every study takes."""


def _study_case(case: DesignCase | str | Path | None, model: Any) -> DesignCase:
    """The study's case, with ``model`` (a ``loop.json`` path, a FittedModel or a fitted
    og.Loop; None: the case's own ``[calibration] model``, if any) folded in as ``--model``
    does (:func:`oilgap._calibrated.with_model`, the one place)."""
    base = as_case(case)
    if model is None and base.calibration_model is None:
        return base
    from oilgap._calibrated import with_model
    return with_model(base, model)[0]


def resume_conflict(resume: bool, force: bool, retry_failed: bool = False,
                    names: tuple[str, str, str] = ("resume", "force", "retry_failed")) -> None:
    """Refuse continuing a stored sweep (``resume``, or ``retry_failed`` which implies it)
    together with discarding it (``force``), naming both (the façade's and the command
    line's spellings, ``names``).

    Raises
    ------
    InputError
        Both given.
    """
    if force and (resume or retry_failed):
        other = names[0] if resume else names[2]
        raise InputError(names[1], True, f"not with {other}: {other} continues the sweep "
                         f"stored in the folder, {names[1]} discards it; choose one")


@checked(**STUDY, model=MODEL)
def pareto(case: DesignCase | str | Path | None = None, *, out: str | Path | None = None,
           force: bool = False, folder: ResultFolder | None = None, **keywords: Any) -> Pareto:
    """The gap-loss and loss-inertia Pareto fronts by epsilon-constraint sweeps
    (``oilgap study pareto``; :func:`oilgap.studies.pareto.run`).

    Parameters
    ----------
    case : DesignCase, path or None
        The joint (None: the seed joint).
    out : path, optional
        Folder for the CSVs, figures and ``summary.md``.
    force : bool
        Replace earlier outputs in ``out``.
    folder : ResultFolder, optional
        A result folder the caller already opened.
    **keywords
        The fields of :class:`~oilgap.studies.settings.ParetoSettings` (``points``: per
        front, >= 50; ``torque_min_Nm``: required torque capability [N m], default the
        case's own; ``thermal``: ``"none"``, ``"bulk"``, ``"film"``, ``"full"``, default
        ``bulk`` with ``[thermal]``, else ``none``) and of
        :class:`~oilgap.studies.settings.RunOptions` (``workers``, ``scheduler``,
        ``progress``), or ``settings=`` / ``options=``, the records whole.

    Returns
    -------
    Pareto
    """
    base = _study_case(case, keywords.pop("model", None))
    settings, options = split_keywords(keywords, ParetoSettings)
    if base.linear is not None:  # a linear actuator: the lead-loss front
        return _lead_front(base, settings, out, force, folder)
    with result_folder("study pareto", out, force, folder=folder) as f:
        _begin(f, base)
        r = pareto_study.run(out, base, settings, options)
        _note(f, r.thermal_mode, r.thermal_default)
    return Pareto(r, base, _out(out))


def _lead_front(base: DesignCase, settings: ParetoSettings, out, force: bool,
                folder: ResultFolder | None) -> LeadFront:
    """``study pareto`` of a linear actuator: :mod:`oilgap.studies.linear_lead`."""
    from oilgap.model.joint_loss import resolved_mode
    from oilgap.studies.linear_lead import lead_front, write_lead_front
    mode = resolved_mode(base, settings.thermal)
    with result_folder("study pareto", out, force, folder=folder) as f:
        _begin(f, base)
        df = lead_front(base, settings.points, str(mode))
        if out is not None:
            write_lead_front(df, out, base.name)
        _note(f, str(mode), settings.thermal is None)
    return LeadFront(df, base.name, str(mode), _out(out))


def _mission(mission: Any) -> Any:
    """A mission as :func:`oilgap.studies.oil_grade.parse_mission` takes it: a CSV path
    read, a list of dicts made a DataFrame."""
    if isinstance(mission, (str, Path)):
        return read_mission_csv(mission)
    if isinstance(mission, list) and mission and isinstance(mission[0], dict):
        return pd.DataFrame(mission)
    return mission


@checked(**STUDY, mission=MISSION, model=MODEL)
def oil_grade(case: DesignCase | str | Path | None = None, *, mission: Any = None,
              out: str | Path | None = None, force: bool = False,
              folder: ResultFolder | None = None, **keywords: Any) -> OilGrade:
    """The ISO VG grade for a joint over its envelope and mission (``oilgap study
    oil-grade``; :func:`oilgap.studies.oil_grade.run`).

    Parameters
    ----------
    case : DesignCase, path or None
        The joint (None: the seed joint).
    mission : list of dicts, DataFrame, CSV path or None
        Rows ``depth_m`` [m], ``oil_temp_C`` [degC], ``fraction`` [-] (default: the
        case's ``[[mission]]`` rows, else the study's default mission).
    out, force, folder
        As :func:`pareto`.
    **keywords
        The fields of :class:`~oilgap.studies.settings.OilGradeSettings` (``thermal``;
        ``nu_min_cSt``, ``nu_max_cSt``: lubrication and cold-start limits [cSt];
        ``depth_range_m``, ``temp_range_C``, ``sea_temp_range_C``: the envelope [m],
        [degC], the oil's under none/film, the sea's under bulk/full; ``mission_hours``
        [h]; ``grades``, ``iso_tolerance``, ``n_depth``, ``n_temp``, ``rated_temps_C``)
        and of :class:`~oilgap.studies.settings.RunOptions` (``workers``, ``scheduler``,
        ``progress``: the grid of grades and envelope runs on the scheduler), or
        ``settings=`` / ``options=``, the records whole.

    Returns
    -------
    OilGrade
    """
    base = _study_case(case, keywords.pop("model", None))
    m = _mission(mission)
    settings, options = split_keywords(keywords, OilGradeSettings)
    with result_folder("study oil-grade", out, force, folder=folder) as f:
        _begin(f, base)
        r = oil_grade_study.run(out, base, m, settings, options)
        _note(f, r.thermal_mode, r.settings.thermal_default)
    return OilGrade(r, base, _out(out))


@checked(**STUDY, model=MODEL)
def smoothing(case: DesignCase | str | Path | None = None, *, out: str | Path | None = None,
              force: bool = False, folder: ResultFolder | None = None,
              **keywords: Any) -> Smoothing:
    """What smoothing the grooves saves (``oilgap study smoothing``;
    :func:`oilgap.studies.smoothing.run`): the fit on the seed's Table 4 and the loss
    against the roughness T.

    Parameters
    ----------
    case : DesignCase, path or None
        Base joint (None: the seed joint).
    out, force, folder
        As :func:`pareto`.
    **keywords
        The fields of :class:`~oilgap.studies.settings.SmoothingSettings`, or
        ``settings=``: ``method`` (``"per-oil"``, ``"shared"``, ``"heat-balance"``; how
        the runs' temperatures are fitted, default per-oil), ``thermal`` (``"none"``,
        ``"film"``, ``"full"``: the loss at the runs' temperatures, default none),
        ``resistance_K_W`` (per-oil method: fixed R_th [K/W]), ``T_values`` (roughness
        values of the loss-vs-T view [-], default 1 to 5 by 0.05), ``plateau_tol``
        (where the loss counts as levelled off [-], fraction of P(T = 1)),
        ``film_evidence`` (also fit the film strength s with the rig's heat balance,
        seed rig only: ``result.film_evidence``, docs/thermal.md#evidence).

    Returns
    -------
    Smoothing
    """
    base = _study_case(case, keywords.pop("model", None))
    settings, _ = split_keywords(keywords, SmoothingSettings, run_options=False)
    with result_folder("study smoothing", out, force, folder=folder) as f:
        _begin(f, base)
        r = smoothing_study.run(out, base, settings)
        _note(f, r.thermal_mode, r.thermal_default)
    return Smoothing(r, base, settings.plateau_tol, _out(out))


@checked(grid=GRID, **STUDY, resume=FLAG, oils=OILS, retry_failed=FLAG, model=MODEL)
def sweep(grid: pd.DataFrame | str | Path, case: DesignCase | str | Path | None = None, *,
          out: str | Path | None = None, resume: bool = False, force: bool = False,
          oils: dict[str, Oil] | str | Path | None = None,
          folder: ResultFolder | None = None, **keywords: Any) -> Sweep:
    """Evaluate or optimize every row of a grid (``oilgap study sweep``;
    :func:`oilgap.studies.grid.runner.run_grid`), resumable in ``out``.

    Parameters
    ----------
    grid : DataFrame or path (CSV, Parquet)
        One row per point (columns: :data:`oilgap.studies.grid.columns.PARAM_COLUMNS`).
    case : DesignCase, path or None
        Base case (None: the seed joint).
    out : path, optional
        Folder of the resumable store, ``results.csv``/``.parquet``, ``sweep.png`` and
        ``summary.md``.
    resume, force : bool
        Continue the sweep stored in ``out``, or discard it (not both: refused naming
        both, as ``--resume``/``--retry-failed`` with ``--force``).
    oils : path or dict, optional
        Oils to look ``oil`` names up in, added to the built-in catalogue
        (:func:`oilgap._evaluate.read_oils`).
    folder : ResultFolder, optional
        A result folder the caller already opened.
    **keywords
        The fields of :class:`~oilgap.studies.settings.SweepSettings` (``mode``:
        ``"evaluate"`` or ``"optimize"``; ``thermal``: default ``bulk`` with
        ``[thermal]``, else ``none``; ``retry_failed``) and of
        :class:`~oilgap.studies.settings.RunOptions` (``workers``, ``scheduler``,
        ``progress``, ``chunk_size``, ``chunk_seconds``), as
        :func:`~oilgap.studies.grid.runner.run_grid` takes them, or ``settings=`` /
        ``options=``, the records whole.

    Returns
    -------
    Sweep
    """
    model = keywords.pop("model", None)
    settings, options = split_keywords(keywords, SweepSettings)
    resume_conflict(resume, force, settings.retry_failed)
    resume = resume or settings.retry_failed
    name = Path(grid).name if isinstance(grid, (str, Path)) else "the grid"
    with result_folder("study sweep", out, force, resume, folder) as f:  # before reading
        g = read_grid(grid) if isinstance(grid, (str, Path)) else grid
        base = _study_case(case, model)
        cat = oil_catalogue(oils)
        _begin(f, base)
        t0 = time.perf_counter()
        res = run_grid(g, base, settings, options, out_dir=out, catalogue=cat)
        view = Sweep(res, base, g, settings.mode, elapsed_s=time.perf_counter() - t0,
                     out=_out(out), grid_name=name, scheduler=options.scheduler)
        _note(f, view.thermal_mode, res.attrs.get("thermal_default", False))
        if out is not None:
            view.files = write_sweep_outputs(view, Path(out))
    return view


__all__ = ["oil_grade", "pareto", "result_folder", "resume_conflict", "smoothing", "sweep"]
