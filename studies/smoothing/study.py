"""Smoothing study: the seed joint grooved (T = 4) against smoothed (T = 2), four oils.

Reproduces Table 4 of the seed paper (Sec. IV.C.2) with oilgap's model and
then looks at the design space: mean loss against T from 1 to 5.

The rig
-------
The experiment ran at the surface in a tank (atmospheric pressure, depth 0 m)
with the seed's sine duty cycle (3000 rpm peak, 0.05 Hz) and ISO VG 150, 320,
680 and 1000 oils. Rows 1-4 of Table 4 are mean *viscous* power: the dry run
(row 0) is already subtracted (row 1 after smoothing, 25.35 W, is below the
dry 25.36 W, so it cannot include it).

Effective oil temperature
-------------------------
The oil was not at 40 degC: the paper says it heated up quickly and then held
a steady temperature. Each run's oil temperature is one steady heat balance::

    T_run = T_base[oil] + R_th * P_visc(T_run)

solved exactly (one root: P_visc falls as the oil warms). Two ways to set it:

* ``"per-oil"`` (default): one effective temperature ``T_base`` per oil, fitted,
  shared by that oil's grooved and smoothed runs (``R_th`` = 0 by default; a
  fixed ``R_th`` > 0 makes the smoothed run colder by ``R_th`` times its lower
  power). The sensitivity fits with ``R_th`` = 0.05, 0.1 and 0.2 K/W show how
  gamma depends on that choice.
* ``"shared"``: one ``T_base`` and one ``R_th`` for all eight runs, fitted
  (a single steady temperature-rise model for the rig).
* ``"heat-balance"`` (thermal mode ``full``): ``"shared"`` with the film-heated loss,
  ``T_run = T_0 + R_th P_film(T_run)``; gamma, T_0 and R_th are the only parameters.

:func:`fit_comparison` sets these side by side with the paper's own model (Table 4's
brackets: reductions within RMS 2.02 W, worst 2.73 W): free parameters, RMS and worst
error of the eight powers and of the four reductions, run temperatures. The default
stays ``per-oil`` with the isothermal loss: the heat balance, with or without film
heating, fits worse (docs/studies.md).

``gamma`` (Eq. 8) is ONE model parameter for all oils; it and the temperature
parameters are fitted by nonlinear least squares
(:func:`scipy.optimize.least_squares`) to the eight measured mean powers.

The physics is the model's: each run is a :class:`~oilgap.model.case.DesignCase`
evaluated through the grid engine (Eq. 10 over the duty cycle through
:func:`~oilgap.model.viscous_loss.clearance_power`). The fit lives in
:mod:`oilgap.studies.smoothing.fit`, the tables, figures and summary in
:mod:`oilgap.studies.smoothing.report`.

References
----------
.. [1] Seed paper, Sec. IV and Tables 2-4 (``shared/reference/seed-paper.md``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, SolverError
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.defaults import case_defaults
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.settings import INLINE, SmoothingSettings, SweepSettings, split_keywords
from oilgap.studies.smoothing.case import NO_TABLE4, run_case
from oilgap.studies.smoothing.evidence import FilmEvidence
from oilgap.studies.smoothing.evidence import film_evidence as film_evidence_of
from oilgap.studies.smoothing.fit import (
    PLATEAU_TOL,
    RIG_DEPTH_M,
    T_GROOVED,
    T_SMOOTHED,
    SmoothingFit,
    check_fixed_resistance,
    fit_smoothing,
    load_table4,
    measured_runs,
    resolve_fit_mode,
    rig_case,
    run_base_temps,
    steady_temperatures,
)
from oilgap.studies.smoothing.report import write_outputs
from oilgap.studies.user_case import is_seed_case

# --------------------------------------------------------------------------- the study


@dataclass(frozen=True, eq=False, kw_only=True)
class SmoothingResult:
    """Everything the smoothing study computes.

    Attributes
    ----------
    table : Table 4 with the model next to the paper (one row per group)
    fit : the fit used (method and thermal mode chosen by the caller)
    checks : the comparison (:func:`fit_comparison`): the paper's model and every fit
    run_temps : each fit's run temperatures and powers (one row per fit and run)
    thermal_default : whether the thermal mode is the default (not chosen by the caller)
    loss_vs_T : mean loss against T for each oil (and the case at its rated point)
    plateau : per curve, where the loss stops falling (criterion in the summary)
    files : files written (empty without ``out_dir``)
    """

    table: pd.DataFrame | None
    fit: SmoothingFit | None
    checks: pd.DataFrame | None
    loss_vs_T: pd.DataFrame
    plateau: pd.DataFrame
    files: tuple[Path, ...] = ()
    run_temps: pd.DataFrame | None = None
    thermal_default: bool = True
    seed_rig: bool = True
    """False on a case other than the seed joint: then ``table``, ``fit``, ``checks`` and
    ``run_temps`` are None (Table 4 is the seed rig's) and ``loss_vs_T``/``plateau`` are
    the case's own (:mod:`oilgap.studies.smoothing.case`)."""
    defaults: tuple = ()
    """What the tool filled in (:class:`oilgap.model.io.defaults.Default`)."""
    case_name: str = ""
    thermal_mode: str = ""
    """The thermal mode of the loss (the fit's on the seed rig, the case's otherwise)."""
    film_evidence: FilmEvidence | None = None
    """Table 4's evidence on the film strength (``film_evidence=True`` on the seed rig;
    :mod:`oilgap.studies.smoothing.evidence`)."""


def _table(fit: SmoothingFit, base: DesignCase, table4: pd.DataFrame,
           out_dir: Path | None) -> pd.DataFrame:
    runs = [(o, t) for o in table4.loc[table4["group"] > 0, "oil"] for t in (T_GROOVED,
                                                                             T_SMOOTHED)]
    grid = pd.DataFrame({"oil": [o for o, _ in runs], "T": [t for _, t in runs],
                         "oil_temp_C": [fit.temps_C[r] for r in runs],
                         "depth_m": RIG_DEPTH_M, "gamma": fit.gamma})
    res = run_grid(grid, base, SweepSettings(thermal=fit.loss_mode), INLINE, out_dir=out_dir,
                   label="smoothing")
    bad = res[res["status"] != "ok"]
    if len(bad):
        raise SolverError(f"smoothing run failed: {bad['error'].iloc[0]}", "evaluation")
    p = {(r["oil"], r["T"]): r for r in res.to_dict("records")}
    rows = []
    for _, t4 in table4.iterrows():
        row = {"group": int(t4["group"]), "oil": t4["oil"],
               "oil_nu40_cSt": t4["oil_nu40_cSt"], "thermal_mode": fit.thermal_mode}
        if t4["group"] == 0:
            row.update(measured_before_W=t4["measured_before_W"],
                       measured_after_W=t4["measured_after_W"],
                       measured_change_W=t4["measured_change_W"])
            rows.append(row)
            continue
        a, b = p[(t4["oil"], T_GROOVED)], p[(t4["oil"], T_SMOOTHED)]
        row.update(
            oil_temp_before_C=a["oil_temp_C"], oil_temp_after_C=b["oil_temp_C"],
            nu_before_cSt=a["nu_cSt"], nu_after_cSt=b["nu_cSt"],
            model_before_W=a["mean_power_W"], model_after_W=b["mean_power_W"],
            model_change_W=b["mean_power_W"] - a["mean_power_W"],
            measured_before_W=t4["measured_before_W"], measured_after_W=t4["measured_after_W"],
            measured_change_W=t4["measured_change_W"],
            paper_model_before_W=t4["paper_model_before_W"],
            paper_model_after_W=t4["paper_model_after_W"],
            paper_model_change_W=t4["paper_model_change_W"])
        for k in ("before", "after", "change"):
            row[f"model_minus_measured_{k}_W"] = row[f"model_{k}_W"] - row[f"measured_{k}_W"]
            row[f"paper_model_minus_measured_{k}_W"] = (row[f"paper_model_{k}_W"]
                                                        - row[f"measured_{k}_W"])
        rows.append(row)
    return pd.DataFrame(rows)


PAPER_LABEL = "paper's model"
"""The comparison's row of the seed's own model: Table 4's brackets."""


def paper_row(table4: pd.DataFrame) -> dict:
    """The paper's own model as Table 4 prints it (its brackets): its errors."""
    t = table4[table4["group"] > 0]
    res = np.r_[t["paper_model_before_W"] - t["measured_before_W"],
                t["paper_model_after_W"] - t["measured_after_W"]]
    red = (t["paper_model_change_W"] - t["measured_change_W"]).to_numpy(dtype=float)
    return {"variant": PAPER_LABEL, "method": "paper", "thermal_mode": "none",
            "resistance_K_per_W": np.nan, "resistance_fitted": False, "gamma": np.nan,
            "gamma_se": np.nan, "temperatures": "measured on the motor coil (not published)",
            "rms_W": float(np.sqrt(np.mean(res ** 2))), "max_abs_W": float(np.abs(res).max()),
            "reduction_rms_W": float(np.sqrt(np.mean(red ** 2))),
            "reduction_max_abs_W": float(np.abs(red).max()), "n_params": 1,
            "used": False, "aic": np.nan,
            "description": "gamma fitted (value not published); each run at the viscosity "
                           "of its measured coil temperature (Sec. IV.B, Fig. 9)"}


def _temperatures(f: SmoothingFit) -> str:
    if f.method == "per-oil":
        s = "per oil " + "/".join(f"{v:.1f}" for v in f.base_temp_C.values()) + " degC"
        return s + (f" + {f.resistance_K_W:g} K/W x P" if f.resistance_K_W else "")
    return (f"T_0 {f.base_temp_C['all']:.2f} degC + R_th {f.resistance_K_W:.4f} K/W x P"
            + (" (R_th at its bound 0)" if f.resistance_K_W == 0.0 else ""))


def fit_comparison(base: DesignCase, table4: pd.DataFrame, main: SmoothingFit,
                   resistances: tuple[float, ...] = ()) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The paper's model and the fits side by side, and each fit's run temperatures.

    Fits: the one used (``main``); per-oil effective temperatures with the isothermal and
    with the film-heated loss (5 parameters); the shared isothermal balance and the
    heat balance with film heating (3 parameters); per-oil with each fixed R_th of
    ``resistances`` (sensitivity of gamma). The paper's row is Table 4's brackets.

    Returns
    -------
    comparison : DataFrame
        ``variant, method, thermal_mode, resistance_K_per_W, resistance_fitted, gamma,
        gamma_se, temperatures, rms_W, max_abs_W`` (eight powers),
        ``reduction_rms_W, reduction_max_abs_W`` (four reductions), ``n_params, used,
        aic`` (over the powers), ``description``.
    run_temps : DataFrame
        ``variant, oil, T, oil_temp_C, model_W, measured_W`` (one row per fit and run).
    """
    wanted = [("per-oil", "none", 0.0), ("per-oil", "film", 0.0), ("shared", "none", 0.0),
              ("heat-balance", "full", 0.0)] + [("per-oil", "none", r) for r in resistances]
    fits = [main]
    for method, thermal, r in wanted:
        if any(f.method == method and f.thermal_mode == thermal
               and (method != "per-oil" or f.resistance_K_W == r) for f in fits):
            continue
        fits.append(fit_smoothing(method, r, base, table4, thermal))
    rows, temps = [paper_row(table4)], []
    runs, meas = measured_runs(table4)
    for f in fits:
        variant = f.label + (f" R_th {f.resistance_K_W:g}" if f.method == "per-oil"
                             and f.resistance_K_W else "")
        rows.append({"variant": variant, "method": f.method, "thermal_mode": f.thermal_mode,
                     "resistance_K_per_W": f.resistance_K_W,
                     "resistance_fitted": f.method != "per-oil", "gamma": f.gamma,
                     "gamma_se": f.gamma_se, "temperatures": _temperatures(f),
                     "rms_W": f.rms_W, "max_abs_W": f.max_abs_W,
                     "reduction_rms_W": f.reduction_rms_W,
                     "reduction_max_abs_W": f.reduction_max_abs_W, "n_params": f.n_params,
                     "used": f is main,
                     "aic": f.n_data * np.log(f.rms_W ** 2) + 2 * f.n_params,
                     "description": f.describe()})
        temps += [{"variant": variant, "oil": o, "T": t, "oil_temp_C": f.temps_C[(o, t)],
                   "model_W": f.powers_W[(o, t)], "measured_W": m}
                  for (o, t), m in zip(runs, meas, strict=True)]
    return pd.DataFrame(rows), pd.DataFrame(temps)


def loss_vs_T(fit: SmoothingFit, base: DesignCase | None = None,
              T_values: np.ndarray | None = None, include_rated: bool = True,
              table4: pd.DataFrame | None = None) -> pd.DataFrame:
    """Mean loss against roughness T for each rig oil (at its fitted run temperature
    model) and, with ``include_rated``, the base case at its own operating point; the
    loss isothermal or film-heated as in the fit (:attr:`SmoothingFit.loss_mode`).

    Returns
    -------
    DataFrame
        ``curve, oil, T, oil_temp_C, depth_m, mean_power_W, dP_dT_W`` (dP/dT by
        central differences on the T grid [W per unit T]).
    """
    base = base if base is not None else seed_case()
    table4 = table4 if table4 is not None else load_table4()
    T_values = np.linspace(1.0, 5.0, 81) if T_values is None else np.asarray(T_values, float)
    if T_values.size == 0 or np.any(T_values < 1.0) or not np.all(np.isfinite(T_values)):
        bad = T_values[~(T_values >= 1.0)] if T_values.size else "empty"
        raise InputError("T", bad if isinstance(bad, str) else float(bad[0]),
                         "roughness values must be finite and >= 1 (T = 1 is smooth)",
                         "smoothing study")
    T_values = np.unique(T_values)
    oils = [str(o) for o in table4.loc[table4["group"] > 0, "oil"]]
    frames = []
    for oil, tb in zip(oils, run_base_temps(fit, oils), strict=True):
        cases = [rig_case(oil, t, fit.gamma, base) for t in T_values]
        temps, _ = steady_temperatures(cases, tb, fit.resistance_K_W, thermal=fit.thermal_mode)
        frames.append(pd.DataFrame({"curve": f"{oil} on the rig (0 m)", "oil": oil,
                                    "T": T_values, "oil_temp_C": temps,
                                    "depth_m": RIG_DEPTH_M}))
    if include_rated:
        op = base.operating
        frames.append(pd.DataFrame({
            "curve": f"{base.oil.name} at {op.depth_m:g} m, {op.oil_temp_C:g} degC (rated)",
            "oil": base.oil.name, "T": T_values, "oil_temp_C": op.oil_temp_C,
            "depth_m": op.depth_m}))
    grid = pd.concat(frames, ignore_index=True)
    res = run_grid(grid[["oil", "T", "oil_temp_C", "depth_m"]].assign(gamma=fit.gamma), base,
                   SweepSettings(thermal=fit.loss_mode), INLINE, label="smoothing")
    bad = res[res["status"] != "ok"]
    if len(bad):
        raise SolverError(f"loss-vs-T point failed: {bad['error'].iloc[0]}", "evaluation")
    grid["mean_power_W"] = res["mean_power_W"].to_numpy()
    grid["dP_dT_W"] = np.nan
    for _, idx in grid.groupby("curve", sort=False).groups.items():
        sub = grid.loc[idx]
        if len(sub) > 1:
            grid.loc[idx, "dP_dT_W"] = np.gradient(sub["mean_power_W"].to_numpy(),
                                                   sub["T"].to_numpy())
    return grid


def plateau_table(curves: pd.DataFrame, tol: float = PLATEAU_TOL) -> pd.DataFrame:
    """Where the loss stops falling, per curve.

    Criterion: going from rough to smooth, the loss has stopped falling once it
    is within ``tol`` of its smooth-wall value P(T = 1); ``T_stop`` is the
    largest T with ``P(T) <= (1 + tol) P(1)`` (linear interpolation on the T
    grid where P rises monotonically, else the largest grid T). Also reported: the
    marginal saving -dP/dT at T = 4 and T = 2 [W per unit T] and the share of
    the possible saving P(4) - P(1) that smoothing 4 -> 2 takes.
    """
    if not (0.0 < tol < 1.0):
        raise InputError("plateau_tol", tol, "must lie in (0, 1)", "smoothing study")
    rows = []
    for curve, sub in curves.groupby("curve", sort=False):
        T = sub["T"].to_numpy()
        P = sub["mean_power_W"].to_numpy()
        dP = sub["dP_dT_W"].to_numpy()
        p1 = P[0]
        target = (1.0 + tol) * p1
        rising = bool(np.all(np.diff(P) > 0))
        rows.append({
            "curve": curve, "oil": sub["oil"].iloc[0], "P_T1_W": p1,
            "P_T2_W": float(np.interp(2.0, T, P)), "P_T4_W": float(np.interp(4.0, T, P)),
            "P_T5_W": P[-1],
            "saving_per_unit_T_at_T4_W": float(np.interp(4.0, T, dP)),
            "saving_per_unit_T_at_T2_W": float(np.interp(2.0, T, dP)),
            "share_of_possible_saving_4_to_2": float(
                (np.interp(4.0, T, P) - np.interp(2.0, T, P))
                / (np.interp(4.0, T, P) - p1)),
            "T_stop": (float(np.interp(target, P, T)) if rising and P[-1] >= target
                       else float(T[P <= target].max())),
            "tol": tol})
    return pd.DataFrame(rows)


def run(out_dir: str | Path | None = None, case: DesignCase | None = None,
        settings: SmoothingSettings | None = None) -> SmoothingResult:
    """Run the smoothing study; with ``out_dir`` write its CSVs, figures and summary.

    Parameters
    ----------
    out_dir : path, optional
    case : DesignCase, optional
        Default: the seed joint, whose T = 4 and T = 2 are compared with Table 4. Any
        other case: what smoothing its grooves would save at its own operating point
        with its own gamma, T from its own value down to 1
        (:func:`oilgap.studies.smoothing.case.run_case`); no fit, no Table 4 (the seed
        rig's measurement); ``method``, ``resistance_K_W`` and ``film_evidence`` are
        refused.
    settings : SmoothingSettings, optional
        ``method``, ``resistance_K_W``, ``thermal`` (see :func:`fit_smoothing`; method
        None and thermal None: ``per-oil`` with the isothermal loss, the default;
        ``thermal="full"`` is the heat-balance fit); ``T_values``, the roughness values
        of the design-space view (default 1 to 5 by 0.05; all >= 1); ``plateau_tol``,
        the criterion of :func:`plateau_table` (default 0.05); ``sensitivity_K_W``, the
        ``R_th`` values [K/W] of the per-oil sensitivity fits (gamma against how much
        colder the smoothed runs were); ``film_evidence``: also fit the film strength
        with the rig's heat balance
        (:func:`oilgap.studies.smoothing.evidence.film_evidence`; seed rig only; writes
        ``smoothing_film_evidence.csv``).
    """
    s = settings if settings is not None else SmoothingSettings()
    base = case if case is not None else seed_case()
    T_values = None if s.T_values is None else np.asarray(s.T_values, dtype=float)
    if not is_seed_case(base):
        if s.film_evidence:
            raise InputError("film_evidence", True, "the seed rig only (Table 4 is its "
                             "measurement)", "smoothing study")
        return _run_case(out_dir, base, s, T_values)
    method, thermal, default = resolve_fit_mode(s.method, s.thermal)
    check_fixed_resistance(s.method, s.thermal, s.resistance_K_W)
    table4 = load_table4()
    fit = fit_smoothing(method, s.resistance_K_W, base, table4, thermal)
    out = Path(out_dir) if out_dir is not None else None
    table = _table(fit, base, table4, out / "grid" if out else None)
    checks, run_temps = fit_comparison(base, table4, fit, s.sensitivity_K_W)
    curves = loss_vs_T(fit, base, T_values, True, table4)
    plateau = plateau_table(curves, s.plateau_tol)
    evidence = film_evidence_of(base, table4) if s.film_evidence else None
    result = SmoothingResult(table=table, fit=fit, checks=checks, loss_vs_T=curves,
                             plateau=plateau, run_temps=run_temps, thermal_default=default,
                             seed_rig=True, defaults=case_defaults(base), case_name=base.name,
                             thermal_mode=fit.thermal_mode, film_evidence=evidence)
    if out is None:
        return result
    files = write_outputs(out, result, base)
    if evidence is not None:
        path = out / "smoothing_film_evidence.csv"
        evidence.profile.to_csv(path, index=False)
        files = (*files, path)
    return replace(result, files=files)


def _run_case(out_dir, base: DesignCase, s: SmoothingSettings,
              T_values: np.ndarray | None) -> SmoothingResult:
    """The smoothing study on a case other than the seed joint."""
    for name, v, unset in (("method", s.method, None), ("resistance_K_W", s.resistance_K_W,
                                                          0.0)):
        if v != unset:
            raise InputError(name, v, "applies to the seed rig's Table 4 fit only; " + NO_TABLE4,
                             "smoothing study")
    out = Path(out_dir) if out_dir is not None else None
    curve, saving, mode, defaults, files = run_case(out, base, T_values, s.plateau_tol,
                                                    s.thermal)
    return SmoothingResult(table=None, fit=None, checks=None, loss_vs_T=curve, plateau=saving,
                           files=files, run_temps=None, thermal_default=s.thermal is None,
                           seed_rig=False, defaults=defaults, case_name=base.name,
                           thermal_mode=mode)


def smoothing_study(out_dir: str | Path | None = None, case: DesignCase | None = None,
                    **keywords) -> pd.DataFrame:
    """The smoothing study as one call: the Table-4-shaped DataFrame (see :func:`run`).

    ``attrs`` carries the fitted ``gamma``, its standard error, the method, the thermal
    mode and the RMS of the powers and of the reductions.
    """
    settings, _ = split_keywords(keywords, SmoothingSettings, run_options=False)
    r = run(out_dir, case, settings)
    t = r.table.copy()
    t.attrs.update(gamma=r.fit.gamma, gamma_se=r.fit.gamma_se, method=r.fit.method,
                   thermal_mode=r.fit.thermal_mode, rms_W=r.fit.rms_W,
                   reduction_rms_W=r.fit.reduction_rms_W)
    return t
