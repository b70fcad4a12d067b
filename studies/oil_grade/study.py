"""Choosing the oil grade: ISO VG 10 to 1000 over the operating envelope.

For each grade the study evaluates the joint's mean viscous power over its duty
cycle on a grid over the envelope (sea depth x oil temperature, or sea temperature
under the thermal mode ``bulk``/``full``; default 0-7000 m x 0-40 degC) through
:func:`oilgap.studies.grid.runner.run_grid`, then:

* **Lubrication limit** (harmonic reducer and bearings): the lowest viscosity in
  the envelope (hottest, shallowest point) must stay at or above ``nu_min_cSt``.
  Default 13 cSt: kappa = nu/nu1 >= 1 with the ISO 281 rated viscosity
  ``nu1 = 4500 n^-0.5 dm^-0.5`` [cSt] (n >= 1000 rpm) of a bearing of pitch
  diameter dm ~ 49 mm (the seed's region 2: 2 (R2 + delta2/2)), which is
  11.6 cSt at the seed's 3000 rpm peak and 14.6 cSt at its 1910 rpm mean ``|speed|``.
* **Cold limit** (start-up torque): the highest viscosity in the envelope
  (coldest, deepest point) must stay at or below ``nu_max_cSt``. Default
  1000 cSt, the usual cold-start ceiling of hydraulic practice; the seed's own
  VG22 reaches about 860 cSt at 2 degC and 7000 m (seed Sec. IV.B) and its rig
  ran the joint with oils up to that range. The viscous torque at peak speed in
  that corner is reported as well.
* Both checks take the ISO 3448 grade tolerance (+-10 % on nu at 40 degC) at its
  worst: ``(1 - tol) nu_min >= nu_min_cSt`` and ``(1 + tol) nu_max <= nu_max_cSt``.
* **Mission energy**: the mean power at each (depth, oil temperature, time
  fraction) row of the mission profile (the case's ``[[mission]]`` rows; without
  them, one segment at the case's own ``[operating]`` point, or :data:`SEED_MISSION`
  for the seed joint), weighted by the fractions, times the mission duration.
* **Recommendation**: among the grades that pass both limits, the lowest
  mission energy; the runner-up is the next. Every other grade gets the reason
  it fails or loses.

Thermal modes (``thermal``, :mod:`oilgap.model.joint_loss`):

* ``none`` (the Python default): the seed's isothermal model, as above.
* ``film``: the losses (envelope, mission, rated view) carry the film-heating
  correction at the given oil temperatures; the limits are as under ``none`` (the
  bulk oil is at the given temperature).
* ``bulk``/``full`` (the case's ``[thermal]`` table): the temperature axis of the envelope,
  the mission rows' and the rated view's temperatures are the **sea's**; at every
  point each grade's bulk oil temperature is the heat balance's
  ``T = T_sea + R (P(T) + Q)``, a result, and so is its operating viscosity.
  Lubrication: the lowest operating viscosity over the envelope (the hottest
  operating point). Cold start: the oil at the sea temperature before it warms
  (no heating: the isothermal viscosity at the coldest sea, deepest point). Mission
  energy with the balance. The ISO tolerance is applied to the operating viscosity
  as it is (conservative: a thinner batch also heats a little less).

A case's rolling bearing (``[bearing]``) is part of every loss (the grid's
``mean_power_W``): its friction and drag grow with the viscosity, so they favour thinner
grades; the grade table then also lists its share of the rated and mission powers
(``rated_bearing_power_W``, ``mission_bearing_power_W``).

Under ``bulk``, ``film`` and ``full`` the isothermal study over the same temperatures runs as
well: the result names both recommendations, whether the grade changes and why
(:mod:`oilgap.studies.oil_grade.thermal`).

References
----------
.. [1] ISO 3448:1992, Industrial liquid lubricants - ISO viscosity classification.
.. [2] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life
   (viscosity ratio kappa; the rated viscosity nu1 as in bearing makers' catalogues).
.. [3] Seed paper, Sec. IV.B (``shared/reference/seed-paper.md``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, fields, replace
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase, MissionSegment, OperatingPoint
from oilgap.model.errors import InputError, SolverError, check_finite
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.defaults import Default, case_defaults, study_default
from oilgap.model.joint_loss import FilmBand, bearing_mean_power_at, film_band
from oilgap.model.joint_loss import resolve_thermal_mode as resolve_mode
from oilgap.model.oils import builtin_oils, get_oil, read_oils_csv
from oilgap.model.thermal_modes import ThermalMode, uses_balance
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.oil_grade.mission import (  # noqa: F401  (re-exported)
    SEED_MISSION,
    mission_temps,
    parse_mission,
    read_mission_csv,
)
from oilgap.studies.oil_grade.report import summary_markdown, write_outputs
from oilgap.studies.oil_grade.thermal import compare_recommendations
from oilgap.studies.settings import (
    DEFAULT_DEPTH_RANGE_M,
    DEFAULT_ISO_TOLERANCE,
    DEFAULT_MISSION_HOURS,
    DEFAULT_NU_MAX_CST,
    DEFAULT_NU_MIN_CST,
    DEFAULT_TEMP_RANGE_C,
    ISO_GRADES,
    OilGradeSettings,
    RunOptions,
    SweepSettings,
    split_keywords,
)
from oilgap.studies.user_case import is_seed_case

WHERE = "oil-grade study"
"""Context named by the study's InputErrors."""
@dataclass(frozen=True, kw_only=True)
class OilGradeEnvelope:
    """The oil-grade study's settings as applied to its case and thermal mode: the
    limits [cSt], tolerance [-], envelope [m], [degC] (the oil's or, under ``bulk``/
    ``full``, the sea's: ``temp_axis``), grid sizes, mission hours [h] and the rated point
    [m], [degC] of the loss-vs-grade view."""

    nu_min_cSt: float
    nu_max_cSt: float
    iso_tolerance: float
    depth_range_m: tuple[float, float]
    temp_range_C: tuple[float, float]
    n_depth: int
    n_temp: int
    mission_hours: float
    thermal_mode: str
    thermal_default: bool
    temp_axis: str
    rated_depth_m: float
    rated_temp_C: float
    rated_temps_C: list[float]

    def to_dict(self) -> dict:
        """The fields as a dict (``oil_grade.json``'s ``settings``)."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


@dataclass(frozen=True, eq=False, kw_only=True)
class OilGradeResult:
    """Everything the oil-grade study computes.

    Attributes
    ----------
    table : one row per grade (limits, mission energy, rank, verdict, reason) under the
        thermal mode
    envelope : the grid over depth x temperature (the sea's under ``bulk``/``full``) for every grade
    rated : loss against grade at the rated depth for a few temperatures
    recommended, runner_up : grade names (None if no grade passes)
    mission : the mission profile used
    settings : the limits, ranges and thermal mode used
    files : files written
    thermal_mode : "none", "bulk", "film" or "full"
    isothermal_table : the grade table of the isothermal study over the same
        temperatures (the same as ``table`` under ``none``)
    recommended_isothermal, runner_up_isothermal : its answer
    comparison : the two recommendations, whether the grade changes and why
        (:func:`oilgap.studies.oil_grade.thermal.compare_recommendations`); None under
        ``none``
    """

    table: pd.DataFrame
    envelope: pd.DataFrame
    rated: pd.DataFrame
    recommended: str | None
    runner_up: str | None
    mission: tuple[MissionSegment, ...]
    mission_source: str
    settings: OilGradeEnvelope
    files: tuple[Path, ...] = ()
    thermal_mode: str = "none"
    isothermal_table: pd.DataFrame | None = None
    recommended_isothermal: str | None = None
    runner_up_isothermal: str | None = None
    comparison: dict | None = None
    defaults: tuple[Default, ...] = ()
    """What the tool filled in: the case's and the study's (mission, envelope, limits)."""
    is_seed: bool = True
    """Whether the case is the seed joint (labels name "the seed design" only then)."""
    film_band: FilmBand | None = None
    """The case's own oil at its rated point, beside the opposite film choice."""


def run(out_dir: str | Path | None = None, case: DesignCase | None = None, mission=None,
        settings: OilGradeSettings | None = None,
        options: RunOptions | None = None) -> OilGradeResult:
    """Run the oil-grade study; with ``out_dir`` write CSVs, JSON, figures and ``summary.md``.

    Parameters
    ----------
    out_dir : path, optional
    case : DesignCase, optional
        The joint (default: the seed joint); its geometry, friction law, duty
        cycle, rated depth, mission rows and ``[thermal]`` are used; its oil is replaced.
    mission : optional
        Mission profile (see :func:`parse_mission`); default the case's rows; without
        them one segment at the case's ``[operating]`` point (its sea temperature under
        ``bulk``/``full``), or :data:`SEED_MISSION` for the seed joint. Under
        ``bulk``/``full`` each row's temperature is the sea's.
    settings : OilGradeSettings, optional
        Grades, limits [cSt], tolerance, envelope, grid sizes, mission hours, rated
        temperatures and thermal mode (default: :class:`OilGradeSettings()`, whose
        thermal mode None is ``bulk`` with ``[thermal]``, else ``none``).
    options : RunOptions, optional
        Workers, scheduler and progress line of the grid
        (:func:`~oilgap.studies.grid.runner.run_grid`).

    Raises
    ------
    InputError
        Bad mission or grade names; a thermal mode the case does not allow;
        ``temp_range_C`` under ``bulk``/``full`` or ``sea_temp_range_C`` without it.
    """
    s = settings if settings is not None else OilGradeSettings()
    base = case if case is not None else seed_case()
    mode = resolve_mode(base, s.thermal)
    t_lo, t_hi = _temp_axis(mode, s.temp_range_C, s.sea_temp_range_C)
    catalogue, grades = _grades(base, s.grades)
    segs, source = _mission(base, mission, mode)
    rated_temp = _case_temp(base, mode)
    rated = s.rated_temps_C
    if rated is None:
        rated = sorted({t_lo, rated_temp, 20.0, t_hi})
    settings = OilGradeEnvelope(
        nu_min_cSt=s.nu_min_cSt, nu_max_cSt=s.nu_max_cSt, iso_tolerance=s.iso_tolerance,
        depth_range_m=s.depth_range_m, temp_range_C=(float(t_lo), float(t_hi)),
        n_depth=s.n_depth, n_temp=s.n_temp, mission_hours=s.mission_hours, thermal_mode=mode,
        thermal_default=s.thermal is None, temp_axis="sea" if uses_balance(mode) else "oil",
        rated_depth_m=base.operating.depth_m, rated_temp_C=rated_temp,
        rated_temps_C=[check_finite("rated_temps_C", t, WHERE) for t in rated])
    grid = _grid(grades, segs, settings)
    out = Path(out_dir) if out_dir is not None else None
    how = options if options is not None else RunOptions(progress=False)
    frames_iso = _evaluate(grid, base, catalogue, "none", out, mode, how)
    isothermal = mode == ThermalMode.NONE
    frames = frames_iso if isothermal else _evaluate(grid, base, catalogue, mode, out, mode, how)
    table, recommended, runner_up = _decide(base, catalogue, grades, frames,
                                            frames_iso["envelope"], segs, settings, mode)
    t_iso, rec_iso, run_iso = (table, recommended, runner_up) if isothermal else _decide(
        base, catalogue, grades, frames_iso, frames_iso["envelope"], segs, settings, "none")
    comparison = None if isothermal else compare_recommendations(
        table, t_iso, (recommended, rec_iso), (runner_up, run_iso), mode, base, settings)
    result = OilGradeResult(
        table=table, envelope=frames["envelope"], rated=frames["rated"],
        recommended=recommended, runner_up=runner_up, mission=segs, mission_source=source,
        settings=settings, thermal_mode=mode, isothermal_table=t_iso,
        recommended_isothermal=rec_iso, runner_up_isothermal=run_iso, comparison=comparison,
        defaults=_defaults(base, settings, mission is None, source, segs, s.temp_range_C,
                           s.sea_temp_range_C, s.rated_temps_C is not None),
        is_seed=is_seed_case(base), film_band=film_band(base, mode))
    if out is not None:
        result = replace(result, files=write_outputs(out, result, base))
    return result


def _grades(base: DesignCase, grades: Sequence[str]) -> tuple[dict, list[str]]:
    """The oil catalogue (built-in and the case's table) and the grades' names."""
    catalogue = builtin_oils()
    if base.oils_csv:
        catalogue.update(read_oils_csv(base.oils_csv))
    return catalogue, [get_oil(g, catalogue).name for g in grades]


def _temp_axis(mode: str, temp_range_C, sea_temp_range_C) -> Sequence[float]:
    """The envelope's temperature range: the oil's (none, film) or the sea's (bulk, full)."""
    if uses_balance(mode):
        if temp_range_C is not None:
            raise InputError("temp_range_C", tuple(temp_range_C), f"under thermal mode '{mode}' "
                             "the oil temperature is a result; give sea_temp_range_C", WHERE)
        return DEFAULT_TEMP_RANGE_C if sea_temp_range_C is None else sea_temp_range_C
    if sea_temp_range_C is not None:
        raise InputError("sea_temp_range_C", tuple(sea_temp_range_C), "only under thermal "
                         f"mode 'bulk' or 'full' (the heat balance); the mode is '{mode}'", WHERE)
    return DEFAULT_TEMP_RANGE_C if temp_range_C is None else temp_range_C


def _case_temp(base: DesignCase, mode: str) -> float:
    """The case's own temperature on the envelope's axis: its sea's under ``bulk``/``full``."""
    return float(base.thermal.sea_temp_C if uses_balance(mode) else base.operating.oil_temp_C)


def _axis(mode: str) -> str:
    """The grid column of the envelope's temperature axis."""
    return "sea_temp_C" if uses_balance(mode) else "oil_temp_C"


def _evaluate(grid: pd.DataFrame, base: DesignCase, catalogue: dict, mode: str,
              out: Path | None, study_mode: str, how: RunOptions) -> dict[str, pd.DataFrame]:
    """The grid under one thermal mode: the envelope, mission and rated frames. Points
    are stored under ``out/grid`` (the study's mode) or ``out/grid_isothermal``."""
    sub = "grid" if mode == study_mode else "grid_isothermal"
    res = run_grid(grid.rename(columns={"oil_temp_C": _axis(mode)}), base,
                   SweepSettings(thermal=mode), how,
                   out_dir=out / sub if out is not None else None, label="oil-grade",
                   catalogue=catalogue)
    failed = res[res["status"] != "ok"]
    if len(failed):
        where = failed.iloc[0][["oil", "depth_m", _axis(mode)]].to_dict()
        err = failed["error"].iloc[0]
        if str(err).startswith("SolverError"):  # the heat balance: exit 4, not bad input
            raise SolverError(f"{WHERE}: {len(failed)} grid point(s) failed under thermal "
                              f"mode '{mode}', first {where}: {err}", "grid point")
        raise InputError("grid point", where, f"failed: {err}", WHERE)
    return {k: res[res["label"] == lab].reset_index(drop=True)
            for k, lab in (("envelope", "envelope"), ("mission", "mission"), ("rated", "rated"))}


def _decide(base: DesignCase, catalogue: dict, grades: list[str], frames: dict,
            cold_env: pd.DataFrame, segs: Sequence[MissionSegment], settings: OilGradeEnvelope,
            mode: str) -> tuple[pd.DataFrame, str | None, str | None]:
    """The grade table under ``mode``, ranked, with verdicts; (table, recommended,
    runner-up)."""
    table = _grade_table(base, catalogue, grades, frames, cold_env, segs, settings, mode)
    recommended, runner_up, best_e = _rank(table)
    _verdicts(table, recommended, runner_up, best_e, settings, mode)
    return table, recommended, runner_up


def _mission(base: DesignCase, mission, mode: str = "none"
             ) -> tuple[tuple[MissionSegment, ...], str]:
    """The mission profile used and where it comes from: given, the case's rows, the seed
    joint's default mission, or one segment at the case's own operating point."""
    if mission is not None:
        segs = parse_mission(mission)
        if not (isinstance(mission, pd.DataFrame) or any(isinstance(r, MissionSegment)
                                                         for r in mission)):
            return segs, "given"  # bare (depth, temperature, fraction): the mode's temperature
        return mission_temps(segs, mode, f"the mission (a {'sea' if uses_balance(mode) else 'oil'}"
                         "_temp_C column)"), "given"
    if base.mission:
        return (mission_temps(tuple(base.mission), mode, "[[mission]]"),
                "the case's [[mission]] rows")
    if is_seed_case(base):
        return SEED_MISSION, "default seed mission (the case has none)"
    t = _case_temp(base, mode)
    where = "sea " if uses_balance(mode) else ""
    return ((MissionSegment(float(base.operating.depth_m), t, 1.0),),
            f"default: one segment at the case's [operating] point "
            f"({base.operating.depth_m:g} m, {where}{t:g} degC; the case has no [[mission]])")


_STUDY_DEFAULTS = (("nu_min_cSt", DEFAULT_NU_MIN_CST, "cSt"),  # settings key, default, unit
                   ("nu_max_cSt", DEFAULT_NU_MAX_CST, "cSt"),
                   ("iso_tolerance", DEFAULT_ISO_TOLERANCE, "-"),
                   ("depth_range_m", DEFAULT_DEPTH_RANGE_M, "m"),
                   ("mission_hours", DEFAULT_MISSION_HOURS, "h"))


def _defaults(base: DesignCase, settings: OilGradeEnvelope, mission_default: bool, source: str,
              segs, temp_range_C, sea_temp_range_C,
              rated_given: bool) -> tuple[Default, ...]:
    """The case's defaults and the study's: each setting left at its default (by value),
    the envelope's temperatures, the mission when the tool chose it, the rated view."""
    out = list(case_defaults(base))
    for key, default, unit in _STUDY_DEFAULTS:
        v = getattr(settings, key)
        if (tuple(v) if isinstance(v, (tuple, list)) else v) == default:
            out.append(study_default(f"oil_grade.{key}", default, unit))
    if temp_range_C is None and sea_temp_range_C is None:
        out.append(study_default(f"oil_grade.{settings.temp_axis}_temp_range_C",
                                 DEFAULT_TEMP_RANGE_C, "degC"))
    if mission_default and not base.mission:
        seed = source.startswith("default seed")
        out.append(study_default("oil_grade.mission", "; ".join(
            f"{m.depth_m:g} m/{m.oil_temp_C:g} degC/{m.fraction:g}" for m in segs),
            "depth/temp/fraction", "the seed's mission" if seed else
            "one segment at the case's [operating] point; the case has no [[mission]]"))
    if not rated_given:
        out.append(study_default("oil_grade.rated_temps_C", ", ".join(
            f"{t:g}" for t in settings.rated_temps_C), "degC",
            "envelope min, the case's temperature, 20 degC, envelope max"))
    return tuple(out)


def _grid(grades: list[str], segs: Sequence[MissionSegment],
          settings: OilGradeEnvelope) -> pd.DataFrame:
    """One grid for every grade: the envelope, the mission rows and the rated-depth view
    (temperatures in ``oil_temp_C``; renamed to ``sea_temp_C`` under ``bulk``/``full``)."""
    depths = np.linspace(*settings.depth_range_m, settings.n_depth)
    temps = np.linspace(*settings.temp_range_C, settings.n_temp)
    rated_temps = settings.rated_temps_C
    D, Tm = np.meshgrid(depths, temps, indexing="ij")
    env = pd.DataFrame({"depth_m": np.tile(D.ravel(), len(grades)),
                        "oil_temp_C": np.tile(Tm.ravel(), len(grades)),
                        "oil": np.repeat(grades, D.size), "label": "envelope"})
    mis = pd.DataFrame({"depth_m": np.tile([s.depth_m for s in segs], len(grades)),
                        "oil_temp_C": np.tile([s.oil_temp_C for s in segs], len(grades)),
                        "oil": np.repeat(grades, len(segs)), "label": "mission"})
    rat = pd.DataFrame({"depth_m": settings.rated_depth_m,
                        "oil_temp_C": np.tile(rated_temps, len(grades)),
                        "oil": np.repeat(grades, len(rated_temps)), "label": "rated"})
    return pd.concat([env, mis, rat], ignore_index=True)


def _grade_row(base: DesignCase, oil, e: pd.DataFrame, c: pd.DataFrame, m: pd.DataFrame,
               r: pd.DataFrame, fr: np.ndarray, settings: OilGradeEnvelope, mode: str) -> dict:
    """One grade's row: lowest operating viscosity over the envelope ``e``, cold-start
    viscosity over the isothermal envelope ``c``, mission ``m`` and rated ``r`` rows."""
    tol, axis = settings.iso_tolerance, _axis(mode)
    i_lo, i_hi = e["nu_cSt"].idxmin(), c["nu_cSt"].idxmax()
    lo_nu, hi_nu = float(e.loc[i_lo, "nu_cSt"]), float(c.loc[i_hi, "nu_cSt"])
    mean_p = float(m["mean_power_W"].to_numpy() @ fr)
    cold_case = replace(base, oil=oil, operating=OperatingPoint(
        float(c.loc[i_hi, "depth_m"]), float(c.loc[i_hi, "oil_temp_C"])))
    r_case = r[np.isclose(r[axis], settings.rated_temp_C)]

    def rated(k: str) -> float:
        return float(r_case[k].iloc[0]) if len(r_case) else float("nan")

    return {
        "oil": oil.name, "nu40_cSt": oil.nu40_cSt,
        "nu_min_envelope_cSt": lo_nu, "nu_min_at_C": float(e.loc[i_lo, "oil_temp_op_C"]),
        "nu_min_at_m": float(e.loc[i_lo, "depth_m"]),
        "nu_max_envelope_cSt": hi_nu, "nu_max_at_C": float(c.loc[i_hi, "oil_temp_C"]),
        "nu_max_at_m": float(c.loc[i_hi, "depth_m"]),
        "passes_lubrication": bool((1 - tol) * lo_nu >= settings.nu_min_cSt),
        "passes_cold": bool((1 + tol) * hi_nu <= settings.nu_max_cSt),
        "peak_viscous_torque_cold_Nm": evaluate_case(  # a start: not yet heated
            cold_case, thermal="none").viscous_torque_peak_Nm,
        "envelope_min_power_W": float(e["mean_power_W"].min()),
        "envelope_max_power_W": float(e["mean_power_W"].max()),
        "rated_power_W": rated("mean_power_W"),
        "mission_mean_power_W": mean_p,
        "mission_energy_Wh": mean_p * settings.mission_hours,
        "thermal_mode": mode,
        "nu_min_at_sea_C": float(e.loc[i_lo, axis]) if uses_balance(mode) else float("nan"),
        "oil_temp_op_max_C": float(e["oil_temp_op_C"].max()),
        "rated_oil_temp_op_C": rated("oil_temp_op_C"),
        "mission_oil_temp_op_max_C": float(m["oil_temp_op_C"].max())} | _bearing_columns(
            base, oil, m, r_case, fr)


def _bearing_columns(base: DesignCase, oil, m: pd.DataFrame, r: pd.DataFrame,
                     fr: np.ndarray) -> dict:
    """The rolling bearing's share of the rated and mission powers [W] at their operating
    temperatures (none without ``[bearing]``)."""
    if base.bearing is None:
        return {}
    case = replace(base, oil=oil)

    def bearing_w(rows: pd.DataFrame) -> np.ndarray:
        return np.array([bearing_mean_power_at(case, t, d) for t, d in
                         zip(rows["oil_temp_op_C"], rows["depth_m"], strict=True)])

    rated = bearing_w(r)
    return {"rated_bearing_power_W": float(rated[0]) if len(rated) else float("nan"),
            "mission_bearing_power_W": float(bearing_w(m) @ fr)}


def _grade_table(base: DesignCase, catalogue: dict, grades: list[str], frames: dict,
                 cold_env: pd.DataFrame, segs: Sequence[MissionSegment], settings: OilGradeEnvelope,
                 mode: str) -> pd.DataFrame:
    """One row per grade (:func:`_grade_row`): the limits' checks, the cold peak torque,
    the powers and the mission energy under ``mode``."""
    fr = np.array([s.fraction for s in segs])
    env, mres, rated = frames["envelope"], frames["mission"], frames["rated"]
    return pd.DataFrame([_grade_row(base, get_oil(g, catalogue), env[env["oil"] == g],
                                    cold_env[cold_env["oil"] == g], mres[mres["oil"] == g],
                                    rated[rated["oil"] == g], fr, settings, mode)
                         for g in grades])


def _rank(table: pd.DataFrame) -> tuple[str | None, str | None, float]:
    """Add ``feasible`` and ``rank`` (by mission energy among the feasible grades);
    return (recommended, runner-up, the recommended grade's mission energy [Wh])."""
    table["feasible"] = table["passes_lubrication"] & table["passes_cold"]
    order = table[table["feasible"]].sort_values("mission_energy_Wh")
    table["rank"] = pd.Series(dtype="Int64")
    for k, i in enumerate(order.index, start=1):
        table.loc[i, "rank"] = k
    recommended = order["oil"].iloc[0] if len(order) else None
    runner_up = order["oil"].iloc[1] if len(order) > 1 else None
    best_e = float(order["mission_energy_Wh"].iloc[0]) if len(order) else float("nan")
    return recommended, runner_up, best_e


def _why_fails(r: pd.Series, settings: OilGradeEnvelope, mode: str) -> list[str]:
    """The limits a grade fails, each with its numbers."""
    tol, nu_min, nu_max = settings.iso_tolerance, settings.nu_min_cSt, settings.nu_max_cSt
    why = []
    if not r["passes_lubrication"]:
        where = (f"its operating {r['nu_min_at_C']:.1f} degC (sea {r['nu_min_at_sea_C']:g} "
                 f"degC)" if uses_balance(mode) else f"{r['nu_min_at_C']:g} degC")
        why.append(f"too thin: nu = {r['nu_min_envelope_cSt']:.1f} cSt at {where}, "
                   f"{r['nu_min_at_m']:g} m"
                   + (f" ({(1 - tol) * r['nu_min_envelope_cSt']:.1f} at -{100 * tol:g} %"
                      " ISO tolerance)" if tol else "")
                   + f" < lubrication limit {nu_min:g} cSt")
    if not r["passes_cold"]:
        where = (f"a cold start in a {r['nu_max_at_C']:g} degC sea (oil not yet warmed)"
                 if uses_balance(mode) else f"{r['nu_max_at_C']:g} degC")
        why.append(f"too thick when cold: nu = {r['nu_max_envelope_cSt']:.0f} cSt at "
                   f"{where}, {r['nu_max_at_m']:g} m"
                   + (f" ({(1 + tol) * r['nu_max_envelope_cSt']:.0f} at +{100 * tol:g} %)"
                      if tol else "")
                   + f" > cold-start limit {nu_max:g} cSt")
    return why


def _verdicts(table: pd.DataFrame, recommended: str | None, runner_up: str | None,
              best_e: float, settings: OilGradeEnvelope, mode: str = "none") -> None:
    """Add ``verdict`` and ``reason``: why each grade fails, loses or wins."""
    verdicts, reasons = [], []
    for _, r in table.iterrows():
        why = _why_fails(r, settings, mode)
        if why:
            verdicts.append("fails")
            reasons.append("; ".join(why))
        elif r["oil"] == recommended:
            verdicts.append("recommended")
            reasons.append("passes both limits with the lowest mission energy")
        else:
            verdicts.append("runner-up" if r["oil"] == runner_up else "passes")
            reasons.append(f"passes both limits; mission energy "
                           f"{100 * (r['mission_energy_Wh'] / best_e - 1):+.1f} % vs "
                           f"{recommended}")
    table["verdict"] = verdicts
    table["reason"] = reasons


def oil_grade_study(out_dir: str | Path | None = None, case: DesignCase | None = None, mission=None,
                    **keywords) -> pd.DataFrame:
    """The oil-grade study as one call: one row per grade (see :func:`run`); ``attrs``
    carries ``recommended``, ``runner_up``, ``thermal_mode``, ``recommended_isothermal``."""
    settings, options = split_keywords(keywords, OilGradeSettings)
    r = run(out_dir, case, mission, settings, options)
    t = r.table.copy()
    t.attrs.update(recommended=r.recommended, runner_up=r.runner_up,
                   thermal_mode=r.thermal_mode, recommended_isothermal=r.recommended_isothermal)
    return t

__all__ = ["ISO_GRADES", "SEED_MISSION", "OilGradeResult", "oil_grade_study", "parse_mission",
           "read_mission_csv", "run", "summary_markdown", "write_outputs"]
