"""The smoothing study on the user's own joint: what filling its grooves would save.

``oilgap study smoothing CASE`` (:func:`oilgap.studies.smoothing.run` with a case other
than the seed joint) evaluates the case at its own operating point with its own gamma
(and says where that gamma came from) for roughness T from its own value down to 1
(smooth), through the grid engine (``T`` column: groove depths scaled in their
rotor/stator proportion, :func:`oilgap.studies.grid.schema.apply_params`):

* the loss against T and dP/dT,
* the plateau: the largest T whose loss is within ``plateau_tol`` of the smooth wall's,
* the loss at T = 2 (the seed's epoxy fill) against the case's own T, and at T = 1.

The Table 4 comparison and the gamma fit belong to the seed rig's measurements only and
are not run on a case (the output says so).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, SolverError
from oilgap.model.io.defaults import Default, case_defaults, defaults_markdown, study_default
from oilgap.model.joint_loss import resolve_thermal_mode
from oilgap.model.thermal_modes import DEFAULT_MODE_WHY
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.reporting import (
    markdown_table,
    new_figure,
    save_figure,
    write_tables,
    write_text,
)
from oilgap.studies.settings import INLINE, SweepSettings
from oilgap.studies.smoothing.laminar import laminar_share

WHERE = "smoothing study"
T_STEP = 0.05
"""Step of the default T grid (from 1 to the case's T) [-]."""
NO_TABLE4 = ("Table 4 (grooved against smoothed, four oils on the seed rig) is the seed "
             "rig's measurement: it and the gamma fit run only without a case "
             "(`oilgap study smoothing`)")


def case_T_values(case: DesignCase, T_values: np.ndarray | None = None) -> np.ndarray:
    """The T grid of the case view: ``T_values`` (>= 1), else 1 to the case's own T by
    :data:`T_STEP`, with T = 2 and the case's T included."""
    t_case = float(case.region1.roughness)
    if T_values is None:
        n = max(2, int(round((t_case - 1.0) / T_STEP)) + 1)
        T_values = np.linspace(1.0, t_case, n)
    T = np.asarray(T_values, dtype=float)
    if T.size == 0 or not np.all(np.isfinite(T)) or np.any(T < 1.0):
        raise InputError("T", "empty" if T.size == 0 else float(T[~(T >= 1.0)][0])
                         if np.any(~(T >= 1.0)) else "not finite",
                         "roughness values must be finite and >= 1 (T = 1 is smooth)", WHERE)
    extra = [t_case] + ([2.0] if T.min() <= 2.0 <= T.max() else [])
    return np.unique(np.r_[T, extra])


def case_curve(case: DesignCase, T_values: np.ndarray, mode: str) -> pd.DataFrame:
    """The case's mean loss [W] against T at its own operating point under ``mode``:
    ``curve, oil, T, oil_temp_C, depth_m, mean_power_W, dP_dT_W``."""
    res = run_grid(pd.DataFrame({"T": T_values}), case, SweepSettings(thermal=mode), INLINE,
                   label="smoothing")
    bad = res[res["status"] != "ok"]
    if len(bad):
        raise SolverError(f"loss-vs-T point failed: {bad['error'].iloc[0]}", "evaluation")
    op = case.operating
    P = res["mean_power_W"].to_numpy(dtype=float)
    return pd.DataFrame({
        "curve": f"{case.name}: {case.oil.name} at {op.depth_m:g} m, {op.oil_temp_C:g} degC",
        "oil": case.oil.name, "T": T_values, "oil_temp_C": res["oil_temp_op_C"].to_numpy(),
        "depth_m": op.depth_m, "mean_power_W": P,
        "dP_dT_W": np.gradient(P, T_values) if len(P) > 1 else np.nan})


def case_saving(curve: pd.DataFrame, t_case: float, tol: float) -> pd.DataFrame:
    """One row: the case's loss at its T, at T = 2 and at T = 1, the savings, the plateau
    ``T_stop`` (largest T with ``P <= (1 + tol) P(1)``)."""
    T, P = curve["T"].to_numpy(), curve["mean_power_W"].to_numpy()
    p1, pc = float(P[0]), float(np.interp(t_case, T, P))
    p2 = float(np.interp(2.0, T, P)) if t_case >= 2.0 else float("nan")
    return pd.DataFrame([{
        "curve": curve["curve"].iloc[0], "oil": curve["oil"].iloc[0], "T_case": t_case,
        "P_T_case_W": pc, "P_T2_W": p2, "P_T1_W": p1,
        "saving_to_T2_W": pc - p2, "saving_to_T2_pct": 100 * (pc - p2) / pc,
        "saving_to_T1_W": pc - p1, "saving_to_T1_pct": 100 * (pc - p1) / pc,
        "T_stop": float(T[P <= (1.0 + tol) * p1].max()), "tol": tol}])


def run_case(out: Path | None, case: DesignCase, T_values: np.ndarray | None,
             plateau_tol: float, thermal: str | None
             ) -> tuple[pd.DataFrame, pd.DataFrame, str, tuple[Default, ...], tuple]:
    """The case view: (curve, saving row, thermal mode, defaults, files written)."""
    mode = resolve_thermal_mode(case, thermal)
    T = case_T_values(case, T_values)
    curve = case_curve(case, T, mode)
    saving = case_saving(curve, float(case.region1.roughness), plateau_tol)
    defaults = list(case_defaults(case))
    if T_values is None:
        defaults.append(study_default("smoothing.T_values", f"1..{T.max():.4g} by {T_STEP:g}",
                                      "-", "1 to the case's own T"))
    if thermal is None:
        defaults.append(study_default("smoothing.thermal", mode, "", DEFAULT_MODE_WHY))
    files: tuple = ()
    if out is not None:
        files = _write(out, case, curve, saving, mode, tuple(defaults))
    return curve, saving, mode, tuple(defaults), files


def saving_lines(case: DesignCase, saving: pd.DataFrame, mode: str) -> list[str]:
    """The case view in sentences (the CLI's text and the summary's)."""
    s = saving.iloc[0]
    lines = [f"{case.name}: T = {s['T_case']:.3g} with gamma = {case.friction.gamma:g} "
             f"(from: {case.gamma_source}), thermal {mode}: mean loss {s['P_T_case_W']:.2f} W"]
    if s["T_case"] <= 1.0 + 1e-9:
        return lines + ["the clearance is already smooth (T = 1): nothing to fill"]
    if np.isfinite(s["P_T2_W"]):
        lines.append(f"filled to T = 2 (the seed's epoxy fill): {s['P_T2_W']:.2f} W, saves "
                     f"{s['saving_to_T2_W']:.2f} W ({s['saving_to_T2_pct']:.1f} %)")
    else:
        lines.append("its T is below 2: a fill to T = 2 saves nothing")
    lines.append(f"filled flush (T = 1): {s['P_T1_W']:.2f} W, saves {s['saving_to_T1_W']:.2f} W "
                 f"({s['saving_to_T1_pct']:.1f} %); within {100 * s['tol']:g} % of that for "
                 f"T <= {s['T_stop']:.2f}")
    return lines


def draw_case(case: DesignCase, curve: pd.DataFrame, saving: pd.DataFrame, mode: str,
              ax) -> None:
    """The case's mean loss [W] against roughness T [-] on ``ax``, its own T and the fill
    to T = 2 marked (``smoothing_loss_vs_T.png``, ``og.Smoothing.plot``)."""
    s = saving.iloc[0]
    ax.plot(curve["T"], curve["mean_power_W"], "-", color="C0", label=curve["curve"].iloc[0])
    ax.plot(s["T_case"], s["P_T_case_W"], "s", color="C0", mfc="white", ms=8,
            label=f"this design (T = {s['T_case']:.3g})")
    if np.isfinite(s["P_T2_W"]):
        ax.plot(2.0, s["P_T2_W"], "o", color="C0", mfc="white", ms=8, label="filled to T = 2")
    ax.axvspan(1.0, max(s["T_stop"], 1.0), color="0.85", zorder=0,
               label=f"loss within {100 * s['tol']:g} % of its T = 1 value")
    ax.set_xlabel("clearance roughness T = (T4 - T1)/(T3 - T2) [-]")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title(f"{case.name}: mean loss against roughness T (gamma = "
                 f"{case.friction.gamma:g}, thermal {mode})", fontsize=10)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left")


def _write(out: Path, case: DesignCase, curve: pd.DataFrame, saving: pd.DataFrame,
           mode: str, defaults: tuple[Default, ...]) -> tuple[Path, ...]:
    """``smoothing_loss_vs_T.csv``, ``smoothing_plateau.csv``, the figure, ``summary.md``."""
    files = write_tables(out, {"smoothing_loss_vs_T.csv": curve,
                               "smoothing_plateau.csv": saving})
    fig, ax = new_figure(8.0, 5.0)
    draw_case(case, curve, saving, mode, ax)
    files.append(save_figure(fig, out / "smoothing_loss_vs_T.png"))
    pick = np.unique(np.linspace(0, len(curve) - 1, min(9, len(curve))).round().astype(int))
    md = out / "summary.md"
    write_text(md, "\n".join([
        f"# Smoothing the grooves of {case.name}", "",
        *[f"{line}." for line in saving_lines(case, saving, mode)], "",
        "L" + laminar_share(case, None, curve).line()[1:] + ".", "",
        markdown_table(curve.iloc[pick][["T", "oil_temp_C", "mean_power_W", "dP_dT_W"]], 3),
        "", NO_TABLE4 + ".", "", *defaults_markdown(defaults)]) + "\n")
    files.append(md)
    return tuple(files)


__all__ = ["NO_TABLE4", "case_T_values", "draw_case", "case_curve", "case_saving", "run_case",
           "saving_lines"]
