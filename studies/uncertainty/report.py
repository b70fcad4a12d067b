"""The uncertainty study's tables, figures and text (``oilgap study uncertainty``).

One drawing function per figure (:func:`draw_histogram`, :func:`draw_tornado`), used by
the written PNGs and by the façade's ``plot()``; one set of text lines
(:func:`result_lines`) used by the command's summary and by ``summary.md``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from oilgap.model.io.defaults import defaults_markdown
from oilgap.model.uncertain.inputs import INPUTS
from oilgap.studies.io.files import atomic_write_text
from oilgap.studies.reporting import new_figure, save_figure, write_tables

FILES = ("uncertainty_samples.csv", "uncertainty_statistics.csv", "uncertainty_inputs.csv",
         "uncertainty_histogram.png", "uncertainty_tornado.png", "summary.md")
"""The files the study writes into its folder."""


def input_lines(spec) -> list[str]:
    """``uncertain   <input> ~ <law> (<source>)`` per input, the set's source and notes."""
    lines = [f"uncertain   {spec.source}"]
    lines += [f"  {d.input} ~ {d.text()} ({d.source})" for d in spec.distributions]
    if spec.correlation is not None:
        c = np.asarray(spec.correlation)
        lines += ["  correlation (normal copula): " + ", ".join(
            f"{a}-{b} {c[i, j]:+.3f}" for i, a in enumerate(spec.names)
            for j, b in enumerate(spec.names) if j > i)]
    lines += [f"  note: {n}" for n in spec.notes]
    return lines


def statistics_lines(result) -> list[str]:
    """The loss's percentile table: mean, sd, p5, p50, p95 and nominal [W]."""
    s = result.statistics.set_index("statistic")["loss_W"]
    n, f = result.settings.samples, result.failed
    head = (f"mean loss over {n} scrambled Sobol' points (seed {result.settings.seed})"
            + (f", {f} failed" if f else ""))
    return [head, f"  {'p5':>9}{'p50':>10}{'p95':>10}{'mean':>10}{'sd':>9}{'nominal':>10}",
            f"  {s['p5']:>7.3f} W{s['p50']:>8.3f} W{s['p95']:>8.3f} W{s['mean']:>8.3f} W"
            f"{s['sd']:>7.3f} W{s['nominal']:>8.3f} W"]


def inputs_table(result) -> pd.DataFrame:
    """Per input: law, tornado (loss at its 5th/95th percentiles, the others nominal)
    and the Sobol' indices with their intervals, largest swing first."""
    t = result.tornado.copy()
    t.insert(1, "law", [result.spec[n].text() for n in t["input"]])
    if result.sobol is not None:
        t = t.merge(result.sobol.drop(columns=["evaluations"], errors="ignore"), on="input",
                    how="left")
    return t


def sobol_lines(result) -> list[str]:
    """The per-input table: Sobol' S1 and ST with their intervals and the tornado."""
    t = inputs_table(result)
    conf = f"{100 * result.settings.confidence:g} %"
    if result.sobol is not None:
        ev = int(result.sobol["evaluations"].iloc[0])
        head = [f"Sobol' indices (SALib, Saltelli design N = {result.settings.sobol_samples}, "
                f"{ev} evaluations; {conf} bootstrap intervals) and tornado (each input at "
                "its p5 and p95, the others nominal)"]
    else:
        head = ["tornado (each input at its p5 and p95, the others nominal); Sobol' indices "
                "not computed"]
    lines = head + [f"  {'input':<20}{'S1':>7}{'interval':>17}{'ST':>8}{'interval':>17}"
                    f"{'loss at p5':>12}{'at p95':>10}"]
    for _, r in t.iterrows():
        if result.sobol is not None:
            s = (f"{r['S1']:>7.3f}  [{r['S1_low']:>6.3f}, {r['S1_high']:>6.3f}]"
                 f"{r['ST']:>8.3f}  [{r['ST_low']:>6.3f}, {r['ST_high']:>6.3f}]")
        else:
            s = f"{'':>7}{'':>17}{'':>8}{'':>17}"
        lines.append(f"  {r['input']:<20}{s}{r['loss_low_W']:>10.3f} W"
                     f"{r['loss_high_W']:>8.3f} W")
    return lines


def result_lines(result) -> list[str]:
    """The body of the summary: the inputs, the percentiles and the per-input table."""
    carried = [f"  carried: {t}" for t in getattr(result, "carried", ())]
    return [*input_lines(result.spec), *carried, "", *statistics_lines(result), "",
            *sobol_lines(result), "", f"wall time {result.elapsed_s:.1f} s"]


def draw_histogram(result, ax: Any) -> None:
    """Histogram of the mean loss [W] over the sample, p5/p50/p95 and nominal marked."""
    y = result.samples["loss_W"].to_numpy()
    y = y[np.isfinite(y)]
    ax.hist(y, bins=min(60, max(10, len(y) // 40)), color="0.7", edgecolor="0.4")
    s = result.statistics.set_index("statistic")["loss_W"]
    for key, style in (("p5", ":"), ("p50", "--"), ("p95", ":")):
        ax.axvline(s[key], color="C0", ls=style, label=f"{key} {s[key]:.3f} W")
    ax.axvline(result.nominal_W, color="C3", label=f"nominal {result.nominal_W:.3f} W")
    ax.set_xlabel("cycle-mean loss of the joint [W]")
    ax.set_ylabel("scenarios")
    ax.set_title(f"{result.case_name}\nloss under {len(result.spec.names)} uncertain "
                 f"input(s), thermal {result.thermal_mode}", fontsize=9)
    ax.legend(fontsize=8)


def draw_tornado(result, ax: Any) -> None:
    """Tornado: the loss [W] with each input at its 5th and 95th percentiles, the others
    nominal, largest swing on top."""
    t = result.tornado.iloc[::-1]
    pos = np.arange(len(t))
    base = result.nominal_W
    ax.barh(pos, t["loss_low_W"] - base, left=base, color="C0", label="input at its p5")
    ax.barh(pos, t["loss_high_W"] - base, left=base, color="C1", label="input at its p95")
    ax.axvline(base, color="k", lw=0.8)
    labels = [f"{n} ({INPUTS[n].unit})" if INPUTS[n].unit != "-" else n for n in t["input"]]
    ax.set_yticks(pos, labels)
    ax.set_xlabel("cycle-mean loss of the joint [W] (others nominal)")
    ax.set_title(f"{result.case_name}\ntornado, nominal {base:.3f} W", fontsize=9)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncol=2)


def _figure(draw, result, path: Path, height: float = 4.8) -> Path:
    fig, ax = new_figure(7.5, height)
    draw(result, ax)
    return save_figure(fig, path)


def summary_markdown(result) -> str:
    """``summary.md``: the settings, the inputs, the percentiles and the per-input table
    (as printed) and the defaults the tool filled in."""
    body = "\n".join(result_lines(result))
    return "\n".join([f"# Uncertainty study: {result.case_name}", "",
                      f"Thermal mode: {result.thermal_mode}"
                      + (" (default)" if result.thermal_default else ""), "",
                      "```text", body, "```", "",
                      *defaults_markdown(result.defaults)]) + "\n"


def write_outputs(out: Path, result) -> tuple[Path, ...]:
    """Write :data:`FILES` into ``out``: the sample, the statistics, the per-input
    table (CSV), the histogram and tornado (PNG) and ``summary.md``."""
    files = write_tables(out, {"uncertainty_samples.csv": result.samples,
                               "uncertainty_statistics.csv": result.statistics,
                               # without its unit column: a "-" cell is quoted against
                               # formula injection; the law's keys name the units
                               "uncertainty_inputs.csv": inputs_table(result).drop(
                                   columns="unit")})
    files.append(_figure(draw_histogram, result, out / "uncertainty_histogram.png"))
    files.append(_figure(draw_tornado, result, out / "uncertainty_tornado.png",
                         2.4 + 0.45 * len(result.tornado)))
    files.append(atomic_write_text(out / "summary.md", summary_markdown(result)))
    return tuple(files)


__all__ = ["FILES", "draw_histogram", "draw_tornado", "input_lines", "inputs_table",
           "result_lines", "sobol_lines", "statistics_lines", "summary_markdown",
           "write_outputs"]
