"""Choosing the oil grade: ISO VG 10 to 1000 over the operating envelope.

For each grade the study evaluates the joint's mean viscous power over its duty
cycle on a grid over the envelope (sea depth x oil temperature, default
0-7000 m x 0-40 degC) through :func:`oilgap.studies.grid.runner.run_grid`, then:

* **Lubrication limit** (harmonic reducer and bearings): the lowest viscosity in
  the envelope (hottest, shallowest point) must stay at or above ``nu_min_cSt``.
  Default 13 cSt: kappa = nu/nu1 >= 1 with the ISO 281 rated viscosity
  ``nu1 = 4500 n^-0.5 dm^-0.5`` [cSt] (n >= 1000 rpm) of a bearing of pitch
  diameter dm ~ 49 mm (the seed's region 2: 2 (R2 + delta2/2)), which is
  11.6 cSt at the seed's 3000 rpm peak and 14.6 cSt at its 1910 rpm mean |speed|.
* **Cold limit** (start-up torque): the highest viscosity in the envelope
  (coldest, deepest point) must stay at or below ``nu_max_cSt``. Default
  1000 cSt, the usual cold-start ceiling of hydraulic practice; the seed's own
  VG22 reaches about 860 cSt at 2 degC and 7000 m (seed Sec. IV.B) and its rig
  ran the joint with oils up to that range. The viscous torque at peak speed in
  that corner is reported as well.
* Both checks take the ISO 3448 grade tolerance (+-10 % on nu at 40 degC) at its
  worst: ``(1 - tol) nu_min >= nu_min_cSt`` and ``(1 + tol) nu_max <= nu_max_cSt``.
* **Mission energy**: the mean power at each (depth, oil temperature, time
  fraction) row of the mission profile (the case's ``[[mission]]`` rows, or
  :data:`SEED_MISSION`), weighted by the fractions, times the mission duration.
* **Recommendation**: among the grades that pass both limits, the lowest
  mission energy; the runner-up is the next. Every other grade gets the reason
  it fails or loses.

References
----------
.. [1] ISO 3448:1992, Industrial liquid lubricants - ISO viscosity classification.
.. [2] ISO 281:2007, Rolling bearings - Dynamic load ratings and rating life
   (viscosity ratio kappa; the rated viscosity nu1 as in bearing makers' catalogues).
.. [3] Seed paper, Sec. IV.B (``shared/reference/seed-paper.md``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase, MissionSegment, OperatingPoint
from oilgap.model.case_io import seed_case
from oilgap.model.errors import InputError, check_finite, check_positive, check_range
from oilgap.model.evaluation import evaluate_case
from oilgap.model.oils import builtin_oils, get_oil, read_oils_csv
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.reporting import markdown_table, new_figure, save_figure, write_tables

ISO_GRADES = ("VG10", "VG15", "VG22", "VG32", "VG46", "VG68", "VG100", "VG150", "VG220",
              "VG320", "VG460", "VG680", "VG1000")
WHERE = "oil-grade study"
"""Context named by the study's InputErrors."""
DEFAULT_NU_MIN_CST = 13.0
"""Lubrication limit: minimum viscosity at the hottest envelope point [cSt]."""
DEFAULT_NU_MAX_CST = 1000.0
"""Cold limit: maximum viscosity at the coldest envelope point, for start-up [cSt]."""
DEFAULT_ISO_TOLERANCE = 0.10
"""ISO 3448 tolerance on nu at 40 degC, applied at its worst to both limits [-]."""
DEFAULT_DEPTH_RANGE_M = (0.0, 7000.0)
DEFAULT_TEMP_RANGE_C = (0.0, 40.0)
DEFAULT_MISSION_HOURS = 8.0
"""Mission duration for the mission energy [h] (one working dive)."""
SEED_MISSION = (MissionSegment(0.0, 20.0, 0.05), MissionSegment(1500.0, 4.0, 0.10),
                MissionSegment(3000.0, 2.0, 0.85))
"""Default mission of the seed joint (it has none): fractions of the joint's running
time at (depth [m], oil temperature [degC]): deck checks at 0 m and 20 degC (5 %),
work on the way at 1500 m and 4 degC (10 %), work at the rated 3000 m and 2 degC (85 %)."""


def parse_mission(mission) -> tuple[MissionSegment, ...]:
    """Validate a mission profile: MissionSegments, (depth_m, oil_temp_C, fraction)
    tuples, or a DataFrame with those columns. Fractions must sum to 1.

    Raises
    ------
    InputError
        Missing columns, bad values, no rows, fractions not summing to 1 (+-1e-6).
    """
    if isinstance(mission, pd.DataFrame):
        cols = ("depth_m", "oil_temp_C", "fraction")
        missing = [c for c in cols if c not in mission.columns]
        extra = [c for c in mission.columns if c not in cols]
        if missing or extra:
            raise InputError("mission columns", list(mission.columns),
                             "required exactly depth_m, oil_temp_C, fraction", "oil-grade study")
        rows = list(mission[list(cols)].itertuples(index=False, name=None))
    else:
        rows = list(mission)
    if not rows:
        raise InputError("mission", "no rows", "needs at least one (depth_m, oil_temp_C, "
                         "fraction) row", "oil-grade study")
    segs = []
    for i, r in enumerate(rows):
        if isinstance(r, MissionSegment):
            segs.append(r)
            continue
        if len(r) != 3:
            raise InputError(f"mission[{i}]", r, "needs (depth_m, oil_temp_C, fraction)",
                             "oil-grade study")
        segs.append(MissionSegment(*(check_finite(k, v, f"mission row {i}") for k, v in
                                     zip(("depth_m", "oil_temp_C", "fraction"), r,
                                         strict=True))))
    total = sum(s.fraction for s in segs)
    if abs(total - 1.0) > 1e-6:
        raise InputError("mission fractions", round(total, 9), "must sum to 1",
                         "oil-grade study")
    return tuple(segs)


def read_mission_csv(path: str | Path) -> tuple[MissionSegment, ...]:
    """Read a mission CSV ``depth_m,oil_temp_C,fraction`` (see :func:`parse_mission`)."""
    p = Path(path)
    if not p.is_file():
        raise InputError("mission", str(p), "must be an existing CSV file", "oil-grade study")
    try:
        df = pd.read_csv(p, skipinitialspace=True)
    except pd.errors.EmptyDataError:
        raise InputError("mission", str(p), "is empty", "oil-grade study") from None
    df.columns = [str(c).strip() for c in df.columns]
    return parse_mission(df)


def _range(name: str, rng: Sequence[float], lo: float, hi: float) -> tuple[float, float]:
    if len(rng) != 2:
        raise InputError(name, rng, "needs (min, max)", "oil-grade study")
    a = check_range(name + " min", rng[0], lo, hi, "oil-grade study")
    b = check_range(name + " max", rng[1], lo, hi, "oil-grade study")
    if b < a:
        raise InputError(name, (a, b), "max must be >= min", "oil-grade study")
    return a, b


@dataclass(frozen=True, eq=False)
class OilGradeResult:
    """Everything the oil-grade study computes.

    Attributes
    ----------
    table : one row per grade (limits, mission energy, rank, verdict, reason)
    envelope : the grid over depth x temperature for every grade
    rated : loss against grade at the rated depth for a few oil temperatures
    recommended, runner_up : grade names (None if no grade passes)
    mission : the mission profile used
    settings : the limits and ranges used
    files : files written
    """

    table: pd.DataFrame
    envelope: pd.DataFrame
    rated: pd.DataFrame
    recommended: str | None
    runner_up: str | None
    mission: tuple[MissionSegment, ...]
    mission_source: str
    settings: dict
    files: tuple[Path, ...] = ()


def run(out_dir: str | Path | None = None, case: DesignCase | None = None,
        mission=None, grades: Sequence[str] = ISO_GRADES,
        nu_min_cSt: float = DEFAULT_NU_MIN_CST, nu_max_cSt: float = DEFAULT_NU_MAX_CST,
        iso_tolerance: float = DEFAULT_ISO_TOLERANCE,
        depth_range_m: Sequence[float] = DEFAULT_DEPTH_RANGE_M,
        temp_range_C: Sequence[float] = DEFAULT_TEMP_RANGE_C, n_depth: int = 29,
        n_temp: int = 21, mission_hours: float = DEFAULT_MISSION_HOURS,
        rated_temps_C: Sequence[float] | None = None, workers: int | None = None,
        progress: bool | None = False) -> OilGradeResult:
    """Run the oil-grade study; with ``out_dir`` write CSVs, figures and ``summary.md``.

    Parameters
    ----------
    out_dir : path, optional
    case : DesignCase, optional
        The joint (default: the seed joint); its geometry, friction law, duty
        cycle, rated depth and mission rows are used; its oil is replaced.
    mission : optional
        Mission profile (see :func:`parse_mission`); default the case's rows, or
        :data:`SEED_MISSION` if it has none.
    grades : oil names (default ISO VG10..VG1000 of the catalogue)
    nu_min_cSt, nu_max_cSt : lubrication and cold limits [cSt]
    iso_tolerance : grade tolerance applied at its worst [-] (0 to switch off)
    depth_range_m, temp_range_C : the envelope [m], [degC]
    n_depth, n_temp : grid points over the envelope (>= 2 each)
    mission_hours : mission duration [h]
    rated_temps_C : oil temperatures of the loss-vs-grade view at the rated depth
        (default: envelope min, the case's temperature, 20 degC, envelope max)
    workers, progress : passed to :func:`~oilgap.studies.grid.runner.run_grid`

    Raises
    ------
    InputError
        Bad limits, ranges, grid sizes, mission or grade names.
    """
    base = case if case is not None else seed_case()
    settings = _settings(nu_min_cSt, nu_max_cSt, iso_tolerance, depth_range_m, temp_range_C,
                         n_depth, n_temp, mission_hours)
    if not grades:
        raise InputError("grades", list(grades), "needs at least one oil", WHERE)
    catalogue = builtin_oils()
    if base.oils_csv:
        catalogue.update(read_oils_csv(base.oils_csv))
    grades = [get_oil(g, catalogue).name for g in grades]
    segs, source = _mission(base, mission)
    settings["rated_depth_m"] = base.operating.depth_m
    if rated_temps_C is None:
        t_lo, t_hi = settings["temp_range_C"]
        rated_temps_C = sorted({t_lo, base.operating.oil_temp_C, 20.0, t_hi})
    settings["rated_temps_C"] = [check_finite("rated_temps_C", t, WHERE) for t in rated_temps_C]
    grid = _grid(grades, segs, settings)
    res = run_grid(grid, base, out_dir=Path(out_dir) / "grid" if out_dir else None,
                   workers=workers, progress=progress, label="oil-grade", catalogue=catalogue)
    failed = res[res["status"] != "ok"]
    if len(failed):
        raise InputError("grid point", failed.iloc[0][["oil", "depth_m", "oil_temp_C"]].to_dict(),
                         f"failed: {failed['error'].iloc[0]}", WHERE)
    envelope = res[res["label"] == "envelope"].reset_index(drop=True)
    mres = res[res["label"] == "mission"].reset_index(drop=True)
    rated = res[res["label"] == "rated"].reset_index(drop=True)
    table = _grade_table(base, catalogue, grades, envelope, mres, rated, segs, settings)
    recommended, runner_up, best_e = _rank(table)
    _verdicts(table, recommended, runner_up, best_e, settings)
    result = OilGradeResult(table, envelope, rated, recommended, runner_up, segs, source,
                            settings)
    if out_dir is not None:
        files = write_outputs(Path(out_dir), result, base)
        result = replace(result, files=files)
    return result


def _settings(nu_min_cSt: float, nu_max_cSt: float, iso_tolerance: float,
              depth_range_m: Sequence[float], temp_range_C: Sequence[float], n_depth: int,
              n_temp: int, mission_hours: float) -> dict:
    """The study's limits, envelope and grid sizes, checked."""
    nu_min = check_positive("nu_min_cSt", nu_min_cSt, WHERE)
    nu_max = check_positive("nu_max_cSt", nu_max_cSt, WHERE)
    if nu_max <= nu_min:
        raise InputError("nu_max_cSt", nu_max, f"must be > nu_min_cSt = {nu_min:g}", WHERE)
    tol = check_range("iso_tolerance", iso_tolerance, 0.0, 0.5, WHERE)
    d_lo, d_hi = _range("depth_range_m", depth_range_m, 0.0, 11_000.0)
    t_lo, t_hi = _range("temp_range_C", temp_range_C, -20.0, 150.0)
    for name, n in (("n_depth", n_depth), ("n_temp", n_temp)):
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2:
            raise InputError(name, n, "must be an integer >= 2", WHERE)
    hours = check_positive("mission_hours", mission_hours, WHERE)
    return {"nu_min_cSt": nu_min, "nu_max_cSt": nu_max, "iso_tolerance": tol,
            "depth_range_m": (d_lo, d_hi), "temp_range_C": (t_lo, t_hi),
            "n_depth": int(n_depth), "n_temp": int(n_temp), "mission_hours": hours}


def _mission(base: DesignCase, mission) -> tuple[tuple[MissionSegment, ...], str]:
    """The mission profile used and where it comes from."""
    if mission is not None:
        return parse_mission(mission), "given"
    if base.mission:
        return tuple(base.mission), "the case's [[mission]] rows"
    return SEED_MISSION, "default seed mission (the case has none)"


def _grid(grades: list[str], segs: Sequence[MissionSegment], settings: dict) -> pd.DataFrame:
    """One grid for every grade: the envelope, the mission rows and the rated-depth view."""
    depths = np.linspace(*settings["depth_range_m"], settings["n_depth"])
    temps = np.linspace(*settings["temp_range_C"], settings["n_temp"])
    rated_temps = settings["rated_temps_C"]
    D, Tm = np.meshgrid(depths, temps, indexing="ij")
    env = pd.DataFrame({"depth_m": np.tile(D.ravel(), len(grades)),
                        "oil_temp_C": np.tile(Tm.ravel(), len(grades)),
                        "oil": np.repeat(grades, D.size), "label": "envelope"})
    mis = pd.DataFrame({"depth_m": np.tile([s.depth_m for s in segs], len(grades)),
                        "oil_temp_C": np.tile([s.oil_temp_C for s in segs], len(grades)),
                        "oil": np.repeat(grades, len(segs)), "label": "mission"})
    rat = pd.DataFrame({"depth_m": settings["rated_depth_m"],
                        "oil_temp_C": np.tile(rated_temps, len(grades)),
                        "oil": np.repeat(grades, len(rated_temps)), "label": "rated"})
    return pd.concat([env, mis, rat], ignore_index=True)


def _grade_table(base: DesignCase, catalogue: dict, grades: list[str], envelope: pd.DataFrame,
                 mres: pd.DataFrame, rated: pd.DataFrame, segs: Sequence[MissionSegment],
                 settings: dict) -> pd.DataFrame:
    """One row per grade: the envelope's extreme viscosities, the limits' checks, the
    cold peak torque, the powers and the mission energy."""
    tol = settings["iso_tolerance"]
    fr = np.array([s.fraction for s in segs])
    rows = []
    for g in grades:
        e = envelope[envelope["oil"] == g]
        i_lo, i_hi = e["nu_cSt"].idxmin(), e["nu_cSt"].idxmax()
        lo_nu, hi_nu = float(e.loc[i_lo, "nu_cSt"]), float(e.loc[i_hi, "nu_cSt"])
        m = mres[mres["oil"] == g]["mean_power_W"].to_numpy()
        mean_p = float(m @ fr)
        cold_case = replace(base, oil=get_oil(g, catalogue),
                            operating=OperatingPoint(float(e.loc[i_hi, "depth_m"]),
                                                     float(e.loc[i_hi, "oil_temp_C"])))
        r_at_case = rated[(rated["oil"] == g)
                          & np.isclose(rated["oil_temp_C"], base.operating.oil_temp_C)]
        rows.append({
            "oil": g, "nu40_cSt": get_oil(g, catalogue).nu40_cSt,
            "nu_min_envelope_cSt": lo_nu, "nu_min_at_C": float(e.loc[i_lo, "oil_temp_C"]),
            "nu_min_at_m": float(e.loc[i_lo, "depth_m"]),
            "nu_max_envelope_cSt": hi_nu, "nu_max_at_C": float(e.loc[i_hi, "oil_temp_C"]),
            "nu_max_at_m": float(e.loc[i_hi, "depth_m"]),
            "passes_lubrication": bool((1 - tol) * lo_nu >= settings["nu_min_cSt"]),
            "passes_cold": bool((1 + tol) * hi_nu <= settings["nu_max_cSt"]),
            "peak_viscous_torque_cold_Nm": evaluate_case(cold_case).viscous_torque_peak_Nm,
            "envelope_min_power_W": float(e["mean_power_W"].min()),
            "envelope_max_power_W": float(e["mean_power_W"].max()),
            "rated_power_W": (float(r_at_case["mean_power_W"].iloc[0]) if len(r_at_case)
                              else float("nan")),
            "mission_mean_power_W": mean_p,
            "mission_energy_Wh": mean_p * settings["mission_hours"]})
    return pd.DataFrame(rows)


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


def _verdicts(table: pd.DataFrame, recommended: str | None, runner_up: str | None,
              best_e: float, settings: dict) -> None:
    """Add ``verdict`` and ``reason``: why each grade fails, loses or wins."""
    tol, nu_min, nu_max = (settings[k] for k in ("iso_tolerance", "nu_min_cSt", "nu_max_cSt"))
    verdicts, reasons = [], []
    for _, r in table.iterrows():
        why = []
        if not r["passes_lubrication"]:
            why.append(f"too thin: nu = {r['nu_min_envelope_cSt']:.1f} cSt at "
                       f"{r['nu_min_at_C']:g} degC, {r['nu_min_at_m']:g} m"
                       + (f" ({(1 - tol) * r['nu_min_envelope_cSt']:.1f} at -{100 * tol:g} %"
                          " ISO tolerance)" if tol else "")
                       + f" < lubrication limit {nu_min:g} cSt")
        if not r["passes_cold"]:
            why.append(f"too thick when cold: nu = {r['nu_max_envelope_cSt']:.0f} cSt at "
                       f"{r['nu_max_at_C']:g} degC, {r['nu_max_at_m']:g} m"
                       + (f" ({(1 + tol) * r['nu_max_envelope_cSt']:.0f} at +{100 * tol:g} %)"
                          if tol else "")
                       + f" > cold-start limit {nu_max:g} cSt")
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


def oil_grade_study(out_dir: str | Path | None = None, **kwargs) -> pd.DataFrame:
    """The oil-grade study as one call: one row per grade (see :func:`run`).

    ``attrs`` carries ``recommended`` and ``runner_up``.
    """
    r = run(out_dir, **kwargs)
    t = r.table.copy()
    t.attrs.update(recommended=r.recommended, runner_up=r.runner_up)
    return t


# --------------------------------------------------------------------------- outputs


def _figure_heatmap(result: OilGradeResult, base: DesignCase, path: Path) -> Path:
    g = result.recommended or result.table.sort_values("mission_energy_Wh")["oil"].iloc[0]
    e = result.envelope[result.envelope["oil"] == g]
    depths = np.unique(e["depth_m"])
    temps = np.unique(e["oil_temp_C"])
    P = e.pivot_table(index="depth_m", columns="oil_temp_C", values="mean_power_W",
                      aggfunc="first").loc[depths, temps].to_numpy()
    fig, ax = new_figure(7.5, 5.2)
    cs = ax.contourf(temps, depths, P, levels=20, cmap="viridis")
    cl = ax.contour(temps, depths, P, levels=8, colors="white", linewidths=0.6)
    ax.clabel(cl, fmt="%.0f W", fontsize=7)
    fig.colorbar(cs, ax=ax, label="mean viscous power over the duty cycle [W]")
    ax.plot([s.oil_temp_C for s in result.mission], [s.depth_m for s in result.mission],
            "wo", mec="k", ms=7, label="mission profile rows")
    ax.plot(base.operating.oil_temp_C, base.operating.depth_m, "r*", ms=15, mec="k",
            label=f"seed design's rated condition ({base.operating.depth_m:g} m, "
                  f"{base.operating.oil_temp_C:g} degC)")
    ax.invert_yaxis()
    ax.set_xlabel("oil temperature [degC]")
    ax.set_ylabel("sea depth [m]")
    tag = "recommended" if result.recommended else "lowest-loss (no grade passes)"
    ax.set_title(f"{base.name}: loss with {g} ({tag}) over the envelope", fontsize=10)
    ax.legend(fontsize=7.5, loc="lower left")
    return save_figure(fig, path)


def _figure_vs_grade(result: OilGradeResult, base: DesignCase, path: Path) -> Path:
    t = result.table
    x = np.arange(len(t))
    fig, ax = new_figure(8.5, 5.0)
    for k, temp in enumerate(result.settings["rated_temps_C"]):
        r = result.rated[np.isclose(result.rated["oil_temp_C"], temp)]
        r = r.set_index("oil").loc[t["oil"]]
        ax.semilogy(x, r["mean_power_W"], "o-", color=f"C{k}", ms=4,
                    label=f"{temp:g} degC at {result.settings['rated_depth_m']:g} m")
    for i, row in t.iterrows():
        if not row["passes_lubrication"]:
            ax.axvspan(i - 0.5, i + 0.5, color="#f4cccc", zorder=0)
        if not row["passes_cold"]:
            ax.axvspan(i - 0.5, i + 0.5, color="#cfe2f3", zorder=0)
    ax.axvspan(0, 0, color="#f4cccc", label="fails the lubrication limit")
    ax.axvspan(0, 0, color="#cfe2f3", label="fails the cold-start limit")
    seed_oil = base.oil.name
    if seed_oil in list(t["oil"]):
        i = list(t["oil"]).index(seed_oil)
        ax.plot(i, t.loc[i, "rated_power_W"], "ks", mfc="none", ms=12, mew=1.5,
                label=f"seed design ({seed_oil}, {base.operating.oil_temp_C:g} degC)")
    if result.recommended:
        i = list(t["oil"]).index(result.recommended)
        ax.plot(i, t.loc[i, "rated_power_W"], "r*", ms=16, mec="k",
                label=f"recommended ({result.recommended})")
    ax.set_xticks(x, list(t["oil"]), rotation=45)
    ax.set_xlabel("ISO VG grade (cSt at 40 degC)")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title(f"Loss against oil grade at the rated depth ({result.settings['rated_depth_m']:g}"
                 " m)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7.5, loc="upper left")
    return save_figure(fig, path)


def summary_markdown(result: OilGradeResult, base: DesignCase) -> str:
    """The study's short Markdown summary."""
    s = result.settings
    t = result.table
    show = t[["oil", "nu_min_envelope_cSt", "nu_max_envelope_cSt", "rated_power_W",
              "mission_mean_power_W", "mission_energy_Wh", "verdict", "reason"]].rename(
        columns={"nu_min_envelope_cSt": "nu min [cSt]", "nu_max_envelope_cSt": "nu max [cSt]",
                 "rated_power_W": f"P at {s['rated_depth_m']:g} m, "
                                  f"{base.operating.oil_temp_C:g} degC [W]",
                 "mission_mean_power_W": "mission mean P [W]",
                 "mission_energy_Wh": f"mission energy ({s['mission_hours']:g} h) [Wh]"})
    mis = pd.DataFrame([{"depth_m": m.depth_m, "oil_temp_C": m.oil_temp_C,
                         "fraction": m.fraction} for m in result.mission])
    if result.recommended:
        r = t.set_index("oil")
        rec = r.loc[result.recommended]
        head = (f"**Recommended: {result.recommended}** (mission energy "
                f"{rec['mission_energy_Wh']:.0f} Wh, mean {rec['mission_mean_power_W']:.2f} W)"
                + (f"; runner-up **{result.runner_up}** ("
                   f"{r.loc[result.runner_up, 'mission_energy_Wh']:.0f} Wh)"
                   if result.runner_up else "; no runner-up passes both limits") + ".")
        if base.oil.name in r.index and base.oil.name != result.recommended:
            so = r.loc[base.oil.name]
            head += (f" The case's own {base.oil.name}: {so['mission_energy_Wh']:.0f} Wh "
                     f"({so['verdict']}).")
    else:
        head = "**No grade passes both limits**: see the reasons below."
    lines = [
        f"# Oil grade for {base.name}",
        "",
        head,
        "",
        f"Envelope: depth {s['depth_range_m'][0]:g}-{s['depth_range_m'][1]:g} m, oil "
        f"{s['temp_range_C'][0]:g}-{s['temp_range_C'][1]:g} degC ({s['n_depth']} x "
        f"{s['n_temp']} grid). Lubrication limit: nu >= {s['nu_min_cSt']:g} cSt at the "
        f"thinnest point; cold-start limit: nu <= {s['nu_max_cSt']:g} cSt at the thickest; "
        f"both with the ISO 3448 +-{100 * s['iso_tolerance']:g} % grade tolerance at its "
        "worst. Loss: mean viscous power over the case's duty cycle "
        f"({base.duty_cycle.description}), friction form `{base.friction.form}`, laminar law "
        f"`{base.friction.laminar_law}`, gamma = {base.friction.gamma:g}.",
        "",
        f"Mission profile ({result.mission_source}), {s['mission_hours']:g} h:",
        "",
        markdown_table(mis, 2),
        "",
        markdown_table(show, 1),
    ]
    return "\n".join(lines) + "\n"


def write_outputs(out: Path, result: OilGradeResult, base: DesignCase) -> tuple[Path, ...]:
    """Write ``oil_grade_table.csv``, ``oil_grade_envelope.csv``, ``oil_grade_rated.csv``,
    the two PNG figures and ``summary.md`` into ``out``."""
    files = write_tables(out, {
        "oil_grade_table.csv": result.table,
        "oil_grade_envelope.csv": result.envelope,
        "oil_grade_rated.csv": result.rated,
    })
    files.append(_figure_heatmap(result, base, out / "oil_grade_heatmap.png"))
    files.append(_figure_vs_grade(result, base, out / "oil_grade_loss_vs_grade.png"))
    md = out / "summary.md"
    md.write_text(summary_markdown(result, base), encoding="utf-8")
    files.append(md)
    return tuple(files)


__all__ = ["ISO_GRADES", "SEED_MISSION", "OilGradeResult", "oil_grade_study", "parse_mission",
           "read_mission_csv", "run"]
