"""The oil-grade study's outputs: CSV tables, JSON, figures and ``summary.md``.

Written by :func:`oilgap.studies.oil_grade.run` with an output folder; every file
names the thermal mode (:mod:`oilgap.model.joint_loss`). Under ``bulk``, ``film`` and ``full``
the isothermal answer and the comparison (:mod:`oilgap.studies.oil_grade.thermal`)
are written as well.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from oilgap.model.io.defaults import defaults_block, defaults_markdown
from oilgap.model.io.serialize import dumps
from oilgap.model.thermal_modes import uses_balance
from oilgap.studies.grid.evaluate import thermal_description
from oilgap.studies.reporting import (
    markdown_table,
    new_figure,
    save_figure,
    write_tables,
    write_text,
)

if TYPE_CHECKING:  # pragma: no cover - typing only
    from oilgap.model.case import DesignCase
    from oilgap.studies.oil_grade.study import OilGradeResult


def _axis_words(result: OilGradeResult) -> tuple[str, str]:
    """(grid column, words) of the envelope's temperature axis."""
    if uses_balance(result.thermal_mode):
        return "sea_temp_C", "sea"
    return "oil_temp_C", "oil"


def _whose(result: OilGradeResult) -> str:
    """Whose rated condition: the seed design's on the seed case, else the case's."""
    return "seed design's" if result.is_seed else "the case's"


def draw_heatmap(result: OilGradeResult, base: DesignCase, ax) -> None:
    """The loss of the recommended (else lowest-loss) grade over the envelope on ``ax``
    [W], the mission rows and the rated condition marked (``oil_grade_heatmap.png``)."""
    col, words = _axis_words(result)
    g = result.recommended or result.table.sort_values("mission_energy_Wh")["oil"].iloc[0]
    e = result.envelope[result.envelope["oil"] == g]
    depths = np.unique(e["depth_m"])
    temps = np.unique(e[col])
    P = e.pivot_table(index="depth_m", columns=col, values="mean_power_W",
                      aggfunc="first").loc[depths, temps].to_numpy()
    cs = ax.contourf(temps, depths, P, levels=20, cmap="viridis")
    cl = ax.contour(temps, depths, P, levels=8, colors="white", linewidths=0.6)
    ax.clabel(cl, fmt="%.0f W", fontsize=7)
    ax.figure.colorbar(cs, ax=ax, label="mean viscous power over the duty cycle [W]")
    ax.plot([s.oil_temp_C for s in result.mission], [s.depth_m for s in result.mission],
            "wo", mec="k", ms=7, label="mission profile rows")
    t_case = result.settings.rated_temp_C
    ax.plot(t_case, base.operating.depth_m, "r*", ms=15, mec="k",
            label=f"{_whose(result)} rated condition ({base.operating.depth_m:g} m, "
                  f"{t_case:g} degC)")
    ax.invert_yaxis()
    ax.set_xlabel(f"{words} temperature [degC]")
    ax.set_ylabel("sea depth [m]")
    tag = "recommended" if result.recommended else "lowest-loss (no grade passes)"
    ax.set_title(f"{base.name}: loss with {g} ({tag}) over the envelope, thermal "
                 f"{result.thermal_mode}", fontsize=10)
    ax.legend(fontsize=7.5, loc="lower left")


def _shade_failures(ax, t: pd.DataFrame) -> None:
    for i, row in t.iterrows():
        if not row["passes_lubrication"]:
            ax.axvspan(i - 0.5, i + 0.5, color="#f4cccc", zorder=0)
        if not row["passes_cold"]:
            ax.axvspan(i - 0.5, i + 0.5, color="#cfe2f3", zorder=0)
    ax.axvspan(0, 0, color="#f4cccc", label="fails the lubrication limit")
    ax.axvspan(0, 0, color="#cfe2f3", label="fails the cold-start limit")


def draw_vs_grade(result: OilGradeResult, base: DesignCase, ax) -> None:
    """Loss [W] against grade at the rated depth on ``ax``, a curve per temperature,
    failing grades shaded (``oil_grade_loss_vs_grade.png``, ``og.OilGrade.plot``)."""
    col, words = _axis_words(result)
    t = result.table
    x = np.arange(len(t))
    for k, temp in enumerate(result.settings.rated_temps_C):
        r = result.rated[np.isclose(result.rated[col], temp)]
        r = r.set_index("oil").loc[t["oil"]]
        ax.semilogy(x, r["mean_power_W"], "o-", color=f"C{k}", ms=4,
                    label=f"{'sea ' if col == 'sea_temp_C' else ''}{temp:g} degC at "
                          f"{result.settings.rated_depth_m:g} m")
    _shade_failures(ax, t)
    seed_oil = base.oil.name
    if seed_oil in list(t["oil"]):
        i = list(t["oil"]).index(seed_oil)
        ax.plot(i, t.loc[i, "rated_power_W"], "ks", mfc="none", ms=12, mew=1.5,
                label=f"{'seed design' if result.is_seed else 'this design'} ({seed_oil}, "
                      f"{result.settings.rated_temp_C:g} degC)")
    if result.recommended:
        i = list(t["oil"]).index(result.recommended)
        ax.plot(i, t.loc[i, "rated_power_W"], "r*", ms=16, mec="k",
                label=f"recommended ({result.recommended})")
    ax.set_xticks(x, list(t["oil"]), rotation=45)
    ax.set_xlabel("ISO VG grade (cSt at 40 degC)")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title(f"Loss against oil grade at the rated depth ({result.settings.rated_depth_m:g}"
                 f" m), thermal {result.thermal_mode}; curves by {words} temperature", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7.5, loc="upper left")


def _figure(draw, result: OilGradeResult, base: DesignCase, size: tuple, path: Path) -> Path:
    """``draw`` on a new Agg figure of ``size`` [in], written as PNG."""
    fig, ax = new_figure(*size)
    draw(result, base, ax)
    return save_figure(fig, path)


def _figure_thermal(result: OilGradeResult, path: Path) -> Path:
    """Mission energy and lowest operating viscosity per grade, with and without heating."""
    per = result.comparison["grades"]
    s = result.settings
    x = np.arange(len(per))
    fig, (a1, a2) = new_figure(11.0, 4.6, ncols=2)
    a1.semilogy(x, per["mission_energy_isothermal_Wh"], "o--", color="C0", label="isothermal")
    a1.semilogy(x, per["mission_energy_Wh"], "o-", color="C3",
                label=f"thermal {result.thermal_mode}")
    a1.set_ylabel(f"mission energy ({s.mission_hours:g} h) [Wh]")
    a2.semilogy(x, per["nu_min_isothermal_cSt"], "o--", color="C0", label="isothermal")
    a2.semilogy(x, per["nu_min_cSt"], "o-", color="C3", label=f"thermal {result.thermal_mode}"
                " (at the operating temperature)")
    a2.axhline(s.nu_min_cSt / (1 - s.iso_tolerance), color="k", ls=":",
               label=f"lubrication limit {s.nu_min_cSt:g} cSt / (1 - "
                     f"{s.iso_tolerance:g})")
    a2.set_ylabel("lowest viscosity over the envelope [cSt]")
    for ax in (a1, a2):
        ax.set_xticks(x, list(per["oil"]), rotation=45)
        ax.set_xlabel("ISO VG grade")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7.5)
    a1.set_title(f"recommended under thermal {result.thermal_mode}: "
                 f"{result.recommended or 'none'} (isothermal: "
                 f"{result.recommended_isothermal or 'none'})", fontsize=10)
    a2.set_title(f"lubrication check, thermal {result.thermal_mode}", fontsize=10)
    return save_figure(fig, path)


def _headline(result: OilGradeResult, base: DesignCase) -> str:
    t = result.table
    if not result.recommended:
        return "**No grade passes both limits**: see the reasons below."
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
    return head


def _thermal_section(result: OilGradeResult) -> list[str]:
    """With and without heating: both recommendations, why, the grade-by-grade table."""
    c = result.comparison
    if c is None:
        return []
    per = c["grades"][["oil", "verdict_isothermal", "verdict", "nu_min_isothermal_cSt",
                       "nu_min_cSt", "nu_min_at_C", "rated_oil_temp_op_C",
                       "mission_energy_isothermal_Wh", "mission_energy_Wh",
                       "mission_energy_change_pct"]]
    return ["", "## With and without heating", "",
            f"Recommended under {c['thermal_mode']}: **{c['recommended'] or 'none'}**; "
            f"isothermal: **{c['recommended_isothermal'] or 'none'}** "
            f"({'changed' if c['changed'] else 'unchanged'}).", "", c["why"], "",
            markdown_table(per, 1)]


def summary_markdown(result: OilGradeResult, base: DesignCase) -> str:
    """The study's short Markdown summary."""
    s = result.settings
    t = result.table
    _, words = _axis_words(result)
    show = t[["oil", "nu_min_envelope_cSt", "nu_max_envelope_cSt", "rated_power_W",
              "mission_mean_power_W", "mission_energy_Wh", "verdict", "reason"]].rename(
        columns={"nu_min_envelope_cSt": "nu min [cSt]", "nu_max_envelope_cSt": "nu max [cSt]",
                 "rated_power_W": f"P at {s.rated_depth_m:g} m, "
                                  f"{'sea ' if s.temp_axis == 'sea' else ''}"
                                  f"{s.rated_temp_C:g} degC [W]",
                 "mission_mean_power_W": "mission mean P [W]",
                 "mission_energy_Wh": f"mission energy ({s.mission_hours:g} h) [Wh]"})
    if uses_balance(result.thermal_mode):
        show.insert(2, "T oil max [degC]", t["oil_temp_op_max_C"])
    mis = pd.DataFrame([{"depth_m": m.depth_m, _axis_words(result)[0]: m.oil_temp_C,
                         "fraction": m.fraction} for m in result.mission])
    lines = [
        f"# Oil grade for {base.name}", "",
        f"Thermal mode: {thermal_description(base, result.thermal_mode, s.thermal_default)}.",
        "", _headline(result, base), "", *band_markdown(result, base),
        f"Envelope: depth {s.depth_range_m[0]:g}-{s.depth_range_m[1]:g} m, {words} "
        f"{s.temp_range_C[0]:g}-{s.temp_range_C[1]:g} degC ({s.n_depth} x "
        f"{s.n_temp} grid). Lubrication limit: nu >= {s.nu_min_cSt:g} cSt at the "
        "thinnest point" + (" (the viscosity at each grade's operating temperature from "
                            "the heat balance)" if uses_balance(result.thermal_mode) else "")
        + f"; cold-start limit: nu <= {s.nu_max_cSt:g} cSt at the thickest"
        + (" (the oil at the sea temperature before it warms)"
           if uses_balance(result.thermal_mode) else "")
        + f"; both with the ISO 3448 +-{100 * s.iso_tolerance:g} % grade tolerance at its "
        "worst. Loss: mean viscous power over the case's duty cycle "
        f"({base.duty_cycle.description}), friction form `{base.friction.form}`, laminar law "
        f"`{base.friction.laminar_law}`, gamma = {base.friction.gamma:g} "
        f"({base.gamma_source}).", "",
        f"Mission profile ({result.mission_source}), {s.mission_hours:g} h:", "",
        markdown_table(mis, 2), "",
        markdown_table(show, 1),
        *_thermal_section(result), "",
        *defaults_markdown(result.defaults),
    ]
    return "\n".join(lines) + "\n"


def band_markdown(result: OilGradeResult, base: DesignCase) -> list[str]:
    """The film band of the case's own oil at its rated point (a paragraph, or nothing)."""
    b = result.film_band
    if b is None:
        return []
    return [f"The case's own oil ({base.oil.name}) at its rated point: {b.mean_power_W:.4g} W "
            f"under {b.mode}; film band: {b.line()}.", ""]


def result_json(result: OilGradeResult, base: DesignCase) -> dict:
    """The study's answer as one JSON document (top-level ``thermal_mode``; under
    ``bulk``/``full`` ``sea_temp_C``; the comparison under ``bulk``/``film``/``full``)."""
    s = result.settings
    doc = {"thermal_mode": result.thermal_mode, "thermal_default": s.thermal_default,
           "case": base.name, "recommended": result.recommended,
           "runner_up": result.runner_up,
           "recommended_isothermal": result.recommended_isothermal,
           "runner_up_isothermal": result.runner_up_isothermal,
           "settings": {k: (list(v) if isinstance(v, tuple) else v)
                        for k, v in s.to_dict().items()},
           "mission": [{"depth_m": m.depth_m, "temp_C": m.oil_temp_C, "fraction": m.fraction}
                       for m in result.mission],
           "grades": json.loads(result.table.to_json(orient="records")),
           "defaults": defaults_block(result.defaults)}
    if result.film_band is not None:
        doc["film_band"] = dict(result.film_band.to_dict(), oil=base.oil.name,
                                rated_mean_power_W=result.film_band.mean_power_W)
    if result.comparison is not None:
        c = dict(result.comparison)
        c["grades"] = json.loads(c["grades"].to_json(orient="records"))
        doc["comparison"] = c
        doc["changed"] = c["changed"]
        doc["why"] = c["why"]
        if "sea_temp_C" in c:
            doc["sea_temp_C"] = c["sea_temp_C"]
    return doc


def write_outputs(out: Path, result: OilGradeResult, base: DesignCase) -> tuple[Path, ...]:
    """Write ``oil_grade_table.csv``, ``oil_grade_envelope.csv``, ``oil_grade_rated.csv``,
    ``oil_grade.json``, the PNG figures and ``summary.md`` into ``out``; under
    ``bulk``/``film``/``full`` also ``oil_grade_isothermal_table.csv``,
    ``oil_grade_thermal_comparison.csv`` and ``oil_grade_thermal.png``."""
    tables = {"oil_grade_table.csv": result.table,
              "oil_grade_envelope.csv": result.envelope,
              "oil_grade_rated.csv": result.rated}
    if result.comparison is not None:
        tables["oil_grade_isothermal_table.csv"] = result.isothermal_table
        tables["oil_grade_thermal_comparison.csv"] = result.comparison["grades"]
    files = write_tables(out, tables)
    js = out / "oil_grade.json"
    write_text(js, dumps(result_json(result, base)) + "\n")  # 6 significant digits
    files.append(js)
    files.append(_figure(draw_heatmap, result, base, (7.5, 5.2),
                         out / "oil_grade_heatmap.png"))
    files.append(_figure(draw_vs_grade, result, base, (8.5, 5.0),
                         out / "oil_grade_loss_vs_grade.png"))
    if result.comparison is not None:
        files.append(_figure_thermal(result, out / "oil_grade_thermal.png"))
    md = out / "summary.md"
    write_text(md, summary_markdown(result, base))
    files.append(md)
    return tuple(files)


__all__ = ["draw_heatmap", "draw_vs_grade", "result_json", "summary_markdown",
           "write_outputs"]
