"""The figures of the loop's report (:mod:`oilgap.studies.loop.report`): which are drawn
for how many runs, and their files.

Up to :data:`~oilgap.studies.loop.figures.CAP` runs every run's figures (12 runs a page);
above (a campaign) a summary: the :data:`~oilgap.studies.loop.figures.PER_PAGE` runs of
largest held-out error after (overview and windows), the residuals, and a grid of small
multiples spread over all runs; every run's pages on request (``figures="all"``,
``oilgap loop --figures all``). The drawing is :mod:`oilgap.studies.loop.figures`'.
"""

from __future__ import annotations

import math
from pathlib import Path

from oilgap.model.errors import InputError
from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.optim.progress import steps
from oilgap.studies.io.files import atomic_savefig
from oilgap.studies.loop.figures import (
    GRID,
    OVERVIEW,
    PER_PAGE,
    SPEED,
    TIME,
    WINDOW,
    LoopCurves,
    figure_names,
    grid_runs,
    pages,
    plot_grid,
    plot_overview,
    plot_residuals,
    plot_windows,
    summarised,
)
from oilgap.studies.reporting import save_figure

DPI = 110
"""Resolution of the loop's figures [dots per inch]."""


def _figure_runs(curves: LoopCurves, path: Path, runs: list[int], windows: bool) -> Path:
    """The overview (whole runs) or the windows (a few cycles) of ``runs``, written."""
    axs = (plot_windows if windows else plot_overview)(curves, runs)
    return save_figure(axs[0].figure, path, DPI)


def _figure_residuals(curves: LoopCurves, path: Path, against: str) -> Path:
    """The residual before and after against time or speed, written."""
    axs = plot_residuals(curves, against)
    return save_figure(axs[0].figure, path, DPI)


def worst_runs(est: LoopEstimator, n: int = PER_PAGE) -> list[int]:
    """The ``n`` runs of largest held-out RMSE after (in-sample after where not held
    out), worst first, as indices into the run names."""
    names = list(est.samples_.run_names)

    def err(x: dict) -> float:
        v = x.get("heldout_rmse_after_W", math.nan)
        v = v if v is not None and math.isfinite(v) else x.get("rmse_with_effect_W", math.nan)
        return v if v is not None and math.isfinite(v) else -math.inf

    ranked = sorted(est.per_run_, key=lambda x: (-err(x), names.index(x["run"])))
    return [names.index(x["run"]) for x in ranked[:n]]


def write_figures(est: LoopEstimator, out: Path, every: bool = False) -> list[Path]:
    """The figures of :func:`oilgap.studies.loop.figures.figure_names`, written into
    ``out`` in that order (at most 12 runs a figure; above the cap without ``every``,
    the summary)."""
    c = LoopCurves.of(est)
    names = figure_names(len(c.run_names), every)
    if summarised(len(c.run_names), every):
        worst = worst_runs(est)
        grid = plot_grid(c)[0].figure
        return [_figure_runs(c, out / OVERVIEW, worst, False),
                _figure_residuals(c, out / SPEED, "speed"),
                _figure_residuals(c, out / TIME, "time"),
                atomic_savefig(grid, out / GRID, dpi=DPI),
                _figure_runs(c, out / names[-1], worst, True)]
    pg = pages(len(c.run_names))
    paths = [_figure_runs(c, out / names[0], pg[0], False),
             _figure_residuals(c, out / names[1], "speed"),
             _figure_residuals(c, out / names[2], "time")]
    more, windows = names[3:2 + len(pg)], names[2 + len(pg):]
    pages_todo = [(n, p, False) for n, p in zip(more, pg[1:], strict=True)]
    pages_todo += [(n, p, True) for n, p in zip(windows, pg, strict=True)]
    paths += [_figure_runs(c, out / n, p, w) for n, p, w in steps("loop: figures", pages_todo)]
    return paths


FIGURE_CHOICES = ("summary", "all", "none")
"""What the report draws: the figures (a summary above the cap), every run's, none."""


def figure_mode(figures: bool | str) -> str:
    """``figures`` as one of :data:`FIGURE_CHOICES` (True: ``"summary"``, False:
    ``"none"``); anything else is refused (InputError naming ``figures``)."""
    if figures is True or figures is False:
        return "summary" if figures else "none"
    if figures not in FIGURE_CHOICES:
        raise InputError("figures", figures, "allowed: summary, all, none (or True, False)",
                         "loop report")
    return str(figures)


def md_figures(est: LoopEstimator, mode: str) -> list[str]:
    """Report section: the figures, and what a summary shows."""
    n = len(est.samples_.run_names)
    if mode == "none":
        return ["## Figures", "", "Not drawn (`--no-figures`)."]
    every = mode == "all"
    note = ([f"{n} runs: the figures summarise. `{OVERVIEW}` and `{WINDOW}` show the "
             f"{PER_PAGE} runs of largest held-out error after (worst first), `{GRID}` "
             f"{len(grid_runs(n))} runs spread over all {n}; the table above lists every run. "
             "Every run's figures: `oilgap loop --figures all` "
             "(`Loop.report(..., figures=\"all\")`).", ""] if summarised(n, every) else [])
    return ["## Figures", "", *note, *(f"![{f}]({f})" for f in figure_names(n, every))]


__all__ = ["DPI", "FIGURE_CHOICES", "figure_mode", "md_figures", "worst_runs",
           "write_figures"]
