"""The smoothing study's outputs: Table 4 and loss-vs-T figures, ``summary.md``, the CSVs;
the thermal-mode line and the comparison of the thermal models (shared with the CLI)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.thermal_modes import ThermalMode
from oilgap.studies.reporting import (
    markdown_table,
    new_figure,
    save_figure,
    write_tables,
    write_text,
)
from oilgap.studies.smoothing.fit import T_GROOVED, T_SMOOTHED, SmoothingFit
from oilgap.studies.smoothing.laminar import laminar_share

if TYPE_CHECKING:
    from oilgap.studies.smoothing.study import SmoothingResult

THERMAL_TEXT = {
    "none": "isothermal oil at the fitted run temperatures, the seed paper's model",
    "film": "the film's own shear heating at the fitted run temperatures",
    "full": "film heating at the oil temperature of the rig's heat balance "
            "T_run = T_0 + R_th P(T_run), T_0 and R_th fitted",
}
"""What each thermal mode of the smoothing fit computes."""


def thermal_line(fit: SmoothingFit, default: bool) -> str:
    """The text after ``thermal`` in the header: mode, whether it is the default, what it
    computes and the method."""
    text = f"{fit.thermal_mode} ("
    if default:
        text += "default: the heat balance does not fit Table 4 better, see the comparison; "
    text += THERMAL_TEXT[fit.thermal_mode] + f"; method {fit.method}"
    if fit.thermal_mode != ThermalMode.FULL:
        text += "; --thermal full for the heat-balance fit"
    return text + ")"


COMPARISON_HEADERS = {
    "variant": "fit", "n_params": "free parameters", "rms_W": "powers RMS [W]",
    "max_abs_W": "powers worst [W]", "reduction_rms_W": "reductions RMS [W]",
    "reduction_max_abs_W": "reductions worst [W]", "gamma": "gamma", "gamma_se": "+-",
    "temperatures": "run temperatures"}
"""Columns of the comparison table (in this order) and their headers."""


def comparison_view(checks: pd.DataFrame) -> pd.DataFrame:
    """The comparison table with readable headers (paper first, then the fits)."""
    return checks[list(COMPARISON_HEADERS)].rename(columns=COMPARISON_HEADERS)


def run_temps_view(run_temps: pd.DataFrame) -> pd.DataFrame:
    """Each fit's run temperatures [degC], one column per run (``VG150 T=4`` ...)."""
    t = run_temps.assign(run=run_temps["oil"] + " T=" + run_temps["T"].map("{:g}".format))
    wide = t.pivot(index="variant", columns="run", values="oil_temp_C")
    wide = wide[list(dict.fromkeys(t["run"]))].loc[list(dict.fromkeys(t["variant"]))]
    return wide.reset_index()


def verdict(checks: pd.DataFrame) -> str:
    """What the comparison says: does the heat balance beat the paper's model and the
    per-oil default, with fewer parameters?"""
    by = checks.set_index("variant")
    paper = checks.iloc[0]
    hb = checks[checks["method"] == "heat-balance"].iloc[0]
    po = checks[(checks["method"] == "per-oil") & (checks["thermal_mode"] == "none")
                & (checks["resistance_K_per_W"] == 0.0)].iloc[0]
    pof = by.loc["per-oil/film"] if "per-oil/film" in by.index else None
    beats = (hb["reduction_rms_W"] <= paper["reduction_rms_W"]
             and hb["reduction_max_abs_W"] <= paper["reduction_max_abs_W"])
    text = (f"The heat balance with film heating ({hb['n_params']} free parameters: gamma, "
            f"T_0, R_th) puts the reductions within RMS {hb['reduction_rms_W']:.2f} W, worst "
            f"{hb['reduction_max_abs_W']:.2f} W, and the powers within RMS "
            f"{hb['rms_W']:.2f} W; the paper's model (gamma, with the run temperatures "
            f"measured) {paper['reduction_rms_W']:.2f} W / "
            f"{paper['reduction_max_abs_W']:.2f} W; one effective temperature per oil "
            f"({po['n_params']} parameters) {po['reduction_rms_W']:.2f} W / "
            f"{po['reduction_max_abs_W']:.2f} W (powers {po['rms_W']:.2f} W). ")
    text += ("It beats the paper's model with fewer free parameters." if beats else
             "The data do not allow it to beat the paper's model: ")
    if not beats:
        if hb["resistance_K_per_W"] == 0.0:
            text += ("the fit drives R_th to its bound 0, i.e. every run at one "
                     "temperature. ")
        if pof is not None:
            text += ("With the film-heated loss the per-oil fit needs bulk temperatures "
                     + pof["temperatures"].removeprefix("per oil ")
                     + " (VG150/320/680/1000): the oil with the largest loss would have to "
                     "run coolest, which no heat balance T_0 + R_th P can give. ")
        text += ("Table 4 gives no run temperatures; the paper's model had them (measured "
                 "on the motor coil), the fits must infer them from the powers.")
    return text


def draw_table4(table: pd.DataFrame, ax) -> None:
    """Table 4 on ``ax``: measured and modelled loss [W] per oil, grooved and smoothed
    (``smoothing_table4.png``)."""
    rows = table[table["group"] > 0]
    x = np.arange(len(rows))
    w = 0.38
    ax.bar(x - w / 2, rows["measured_before_W"], w, color="#b0b0b0",
           label="measured, grooved seed (T = 4)")
    ax.bar(x + w / 2, rows["measured_after_W"], w, color="#7fb3d5",
           label="measured, smoothed seed (T = 2)")
    ax.plot(x - w / 2, rows["model_before_W"], "kD", ms=7, label="oilgap model, T = 4")
    ax.plot(x + w / 2, rows["model_after_W"], "D", color="#1f4e79", ms=7,
            label="oilgap model, T = 2")
    ax.plot(x - w / 2, rows["paper_model_before_W"], "r_", ms=16, mew=2,
            label="paper's model (Table 4 brackets)")
    ax.plot(x + w / 2, rows["paper_model_after_W"], "r_", ms=16, mew=2)
    ax.set_xticks(x, [f"{o}\n{t:.1f}/{a:.1f} degC" for o, t, a in zip(
        rows["oil"], rows["oil_temp_before_C"], rows["oil_temp_after_C"], strict=True)])
    ax.set_xlabel("oil (ISO VG = cSt at 40 degC); effective oil temperature T=4 / T=2 runs")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title("Seed joint on the rig (0 m): Table 4 measured vs model, before/after smoothing")
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(axis="y", alpha=0.3)


def draw_loss_vs_T(curves: pd.DataFrame, plateau: pd.DataFrame, fit: SmoothingFit,
                   ax) -> None:
    """Mean loss [W] against roughness T [-] on ``ax``, a curve per oil, the plateau
    shaded (``smoothing_loss_vs_T.png``, ``og.Smoothing.plot``)."""
    for k, (curve, sub) in enumerate(curves.groupby("curve", sort=False)):
        color = f"C{k}"
        ls = "--" if "rated" in curve else "-"
        ax.plot(sub["T"], sub["mean_power_W"], ls, color=color, label=curve)
        for t_mark, mk in ((T_GROOVED, "s"), (T_SMOOTHED, "o")):
            ax.plot(t_mark, np.interp(t_mark, sub["T"], sub["mean_power_W"]), mk, color=color,
                    mfc="white", ms=7)
    ax.plot([], [], "ks", mfc="white", label="seed design, grooved (T = 4)")
    ax.plot([], [], "ko", mfc="white", label="seed design, smoothed (T = 2)")
    t_stop = float(plateau["T_stop"].max())
    tol = float(plateau["tol"].iloc[0])
    ax.axvspan(1.0, t_stop, color="0.85", zorder=0,
               label=f"loss within {100 * tol:g} % of its T = 1 value (T <= {t_stop:.2f})")
    ax.set_xlabel("clearance roughness T = (T4 - T1)/(T3 - T2) [-]")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title(f"Mean loss against roughness T (gamma = {fit.gamma:.3f}, {fit.method} "
                 f"temperatures, thermal {fit.thermal_mode})")
    ax.set_xlim(curves["T"].min(), curves["T"].max())
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left")


def _pct_range(x: pd.Series) -> str:
    lo, hi = f"{100 * x.min():.0f}", f"{100 * x.max():.0f}"
    return f"{lo} %" if lo == hi else f"{lo}-{hi} %"


_TABLE4_HEADERS = {
    "oil_temp_before_C": "T_oil T=4 [degC]", "oil_temp_after_C": "T_oil T=2 [degC]",
    "model_before_W": "model before [W]", "model_after_W": "model after [W]",
    "model_change_W": "model change [W]", "measured_before_W": "measured before [W]",
    "measured_after_W": "measured after [W]", "measured_change_W": "measured change [W]",
    "paper_model_before_W": "paper model before [W]",
    "paper_model_after_W": "paper model after [W]",
    "paper_model_change_W": "paper model change [W]",
    "model_minus_measured_before_W": "diff before [W]",
    "model_minus_measured_after_W": "diff after [W]",
    "model_minus_measured_change_W": "diff change [W]"}
"""Columns of the summary's Table 4 (in this order) and their headers."""


def summary_markdown(table: pd.DataFrame, fit: SmoothingFit, checks: pd.DataFrame,
                     plateau: pd.DataFrame, base: DesignCase,
                     run_temps: pd.DataFrame | None = None, default: bool = True) -> str:
    """The study's short Markdown summary."""
    rows = table[table["group"] > 0]
    dchg = rows["model_minus_measured_change_W"].abs()
    worst = rows.loc[dchg.idxmax()]
    paper = rows["paper_model_minus_measured_change_W"].abs()
    show = table[["group", "oil", *_TABLE4_HEADERS]].rename(columns=_TABLE4_HEADERS)
    ck = comparison_view(checks)
    pl = plateau[["curve", "P_T1_W", "P_T2_W", "P_T4_W", "P_T5_W",
                  "saving_per_unit_T_at_T4_W", "saving_per_unit_T_at_T2_W",
                  "share_of_possible_saving_4_to_2", "T_stop"]]
    f = fit
    t_stop = plateau["T_stop"].max()
    if f.gamma < 1.0:
        shape = ("With gamma < 1 the region-1 loss, proportional to T^gamma, is concave in T: "
                 "the saving per unit of T grows as T falls, so the loss keeps falling all "
                 f"the way to T = 1 and levels off (within the tolerance) only below T = "
                 f"{t_stop:.2f}.")
    else:
        shape = (f"With gamma >= 1 the saving per unit of T shrinks as T falls; the loss is "
                 f"within the tolerance of its floor below T = {t_stop:.2f}.")
    lines = [
        "# Smoothing study: seed joint grooved (T = 4) vs smoothed (T = 2)",
        "",
        f"Thermal mode: {thermal_line(fit, default)}",
        "",
        f"**Fitted gamma = {f.gamma:.3f} +- {f.gamma_se:.3f}** (Eq. 8 exponent; one value "
        f"for all four oils; friction form `{base.friction.form}`, laminar law "
        f"`{base.friction.laminar_law}`). Candidate calibrated default for the seed case "
        f"(the seed case file still says gamma = {base.friction.gamma:g}).",
        "",
        "Rig: seed joint at 0 m (tank at the surface, atmospheric pressure), sine duty cycle "
        f"({base.duty_cycle.description}); oils ISO VG150/320/680/1000 from the catalogue. "
        "Table 4 rows 1-4 are mean viscous power (the dry run, row 0, is already subtracted).",
        "",
        "Effective oil temperature: " + f.describe() + ".",
        "",
        markdown_table(show, 2),
        "",
        f"Reductions: the model's change is within {dchg.max():.2f} W of the measured change "
        f"(worst: {worst['oil']}, {worst['model_change_W']:.2f} W vs "
        f"{worst['measured_change_W']:.2f} W); the paper's own model was within "
        f"{paper.max():.2f} W. Without the worst oil the model is within "
        f"{dchg.drop(dchg.idxmax()).max():.2f} W. Table 4's VG680 row is inconsistent as "
        "printed (53.27 - 75.08 = -21.81, the table says -22.25).",
        "",
        "## Thermal models compared",
        "",
        "Errors over the eight measured powers and over the four reductions (model "
        "after - before against Table 4's printed change); the paper's row is Table 4's "
        "brackets. `per-oil`: one effective temperature per oil (with R_th > 0 each oil's "
        "smoothed run is colder by R_th x its lower power); `shared`: one T_base and one "
        "R_th for all runs, isothermal loss; `heat-balance`: the rig's balance "
        "T_run = T_0 + R_th P(T_run) with the film-heated loss (thermal mode `full`). "
        "gamma is tied to how much colder the smoothed runs were than the grooved ones "
        "(no temperatures are published): larger R_th needs a larger gamma.",
        "",
        markdown_table(ck, 3),
        "",
        *([] if run_temps is None else
          ["Run temperatures [degC] each fit implies:", "",
           markdown_table(run_temps_view(run_temps), 1), ""]),
        verdict(checks),
        "",
        "## Loss against T (design-space view)",
        "",
        markdown_table(pl, 3),
        "",
        "Criterion: the loss has stopped falling once it is within "
        f"{100 * plateau['tol'].iloc[0]:g} % of its smooth-wall value P(T = 1); T_stop is "
        "the largest such T. " + shape + " Smoothing 4 -> 2 takes "
        + _pct_range(plateau["share_of_possible_saving_4_to_2"]) + " of the saving "
        "a perfectly smooth clearance (T = 1) would give.",
    ]
    return "\n".join(lines) + "\n"


def write_outputs(out: Path, result: SmoothingResult, base: DesignCase) -> tuple[Path, ...]:
    """Write the study's CSVs, PNG figures and ``summary.md`` into ``out`` (the seed rig's
    fit: ``result.table``, ``fit``, ``checks``, ``loss_vs_T``, ``plateau``, ``run_temps``)."""
    r = result
    table, fit, checks, curves, plateau = r.table, r.fit, r.checks, r.loss_vs_T, r.plateau
    run_temps, default = r.run_temps, r.thermal_default
    tables = {"smoothing_table4.csv": table, "smoothing_fits.csv": checks,
              "smoothing_loss_vs_T.csv": curves, "smoothing_plateau.csv": plateau}
    if run_temps is not None:
        tables["smoothing_run_temps.csv"] = run_temps
    files = write_tables(out, tables)
    fig, ax = new_figure(8.0, 4.8)
    draw_table4(table, ax)
    files.append(save_figure(fig, out / "smoothing_table4.png"))
    fig, ax = new_figure(8.0, 5.0)
    draw_loss_vs_T(curves, plateau, fit, ax)
    files.append(save_figure(fig, out / "smoothing_loss_vs_T.png"))
    md = out / "summary.md"
    share = laminar_share(base, table, curves).line()
    write_text(md, summary_markdown(table, fit, checks, plateau, base, run_temps, default)
               .rstrip("\n") + f"\n\n{share[0].upper()}{share[1:]}.\n")
    files.append(md)
    return tuple(files)
