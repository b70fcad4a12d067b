"""Figures of the measured-data loop, drawn on a notebook's axes or on new Agg figures.

* :func:`plot_overview`: per run (one panel each), the whole record: measured, the
  case's law without T, the calibrated base model (with T) and the model with the
  accepted effects; the window of :func:`plot_windows` shaded;
* :func:`plot_windows`: per run, a window of a few cycles at the end of the run, where
  the waveform's shape shows, small multiples on one y scale;
* :func:`plot_residuals`: the residual before and after against time (one line per
  run, a legend naming its oil, roughness and temperatures) or against speed (the
  samples and their bin means).

Each takes a fitted :class:`~oilgap.optim.calibration.estimator.LoopEstimator` or the
:class:`LoopCurves` drawn from one, and optionally the axes to draw on (one axes is
subdivided into panels), and returns the axes. At most :data:`PER_PAGE` runs go in one
figure: :func:`pages` splits the runs, :func:`figure_names` names the files
:mod:`oilgap.studies.loop.report` writes. :func:`panels` lays out small multiples (here and
in :mod:`oilgap.studies.sweep_figures`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from matplotlib import colormaps
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.gridspec import GridSpec

PER_PAGE = 12
"""At most this many runs (panels) in one figure."""
CAP = 2 * PER_PAGE
"""Above this many runs the report summarises (:func:`figure_names` ``every=False``): the
:data:`PER_PAGE` worst runs, and a grid of :data:`GRID_MAX` runs spread over all of them;
every run's pages only on request (``--figures all``)."""
GRID_MAX = 48
"""At most this many small multiples in :data:`GRID`."""
LEGEND_MAX = 40
"""The residual-against-time figure names each run in its legend up to this many runs."""
CYCLES = 2
"""The window of :func:`plot_windows` spans this many speed cycles."""

OVERVIEW = "measured_vs_model.png"
WINDOW = "measured_vs_model_window.png"
SPEED = "residual_vs_speed.png"
TIME = "residual_vs_time.png"
GRID = "measured_vs_model_grid.png"

MODELS = {"without_T": ("case's law without T", "tab:red", "-", 0.7),
          "with_T": ("base model (calibrated, with T)", "tab:blue", "-", 1.0),
          "with_effect": ("with effect (after)", "tab:green", "--", 1.0)}
"""Each prediction's legend entry, colour, line style and width."""


@dataclass(frozen=True, eq=False, kw_only=True)
class LoopCurves:
    """What the loop's figures draw, one entry per oil sample (SI, time in seconds).

    Attributes
    ----------
    run_names : tuple of str
        The runs in order; ``run_code`` indexes it.
    run_code : ndarray of int
        Run of each sample.
    time_s : ndarray
        Time [s], or the operating point's number within its run when ``has_time`` is
        False (steady data).
    has_time : bool
        The data are records in time (else steady operating points).
    speed_rpm, temp_C, measured_W : ndarray
        Speed [rpm], measured temperature [degC], measured viscous power [W].
    oil, roughness_T : ndarray
        Oil name and roughness T [-] of each sample.
    predictions : dict of str to ndarray
        Model predictions [W] by :data:`MODELS` key (``with_effect`` only when an
        effect was accepted).
    """

    run_names: tuple[str, ...]
    run_code: np.ndarray
    time_s: np.ndarray
    has_time: bool
    speed_rpm: np.ndarray
    temp_C: np.ndarray
    measured_W: np.ndarray
    oil: np.ndarray
    roughness_T: np.ndarray
    predictions: dict

    @classmethod
    def of(cls, loop) -> LoopCurves:
        """The curves of a fitted LoopEstimator (a LoopCurves is returned as is)."""
        if isinstance(loop, LoopCurves):
            return loop
        s = loop.samples_
        has_time = bool(getattr(s, "has_time", True))
        t = np.asarray(s.time_s, float)
        if not has_time:  # operating-point number within its run
            t = np.zeros(len(s.run_code))
            for c in np.unique(s.run_code):
                idx = np.nonzero(s.run_code == c)[0]
                t[idx] = np.arange(len(idx))
        keys = ("without_T", "with_T") + (("with_effect",) if loop.effects_ else ())
        return cls(run_names=tuple(s.run_names), run_code=np.asarray(s.run_code), time_s=t,
                   has_time=has_time, speed_rpm=np.asarray(s.speed_rpm, float),
                   temp_C=np.asarray(s.temp_C, float), measured_W=np.asarray(s.viscous_W, float),
                   oil=np.asarray(s.oil), roughness_T=np.asarray(s.roughness_T, float),
                   predictions={k: np.asarray(loop.pred_[k], float) for k in keys})

    def run_label(self, i: int) -> str:
        """A run in words: "VG320-T4: VG320, T = 4, 21..35 degC"."""
        m = self.run_code == i
        temps = self.temp_C[m]
        oils = ", ".join(dict.fromkeys(str(o) for o in self.oil[m]))
        rough = ", ".join(f"{t:g}" for t in dict.fromkeys(self.roughness_T[m]))
        return (f"{self.run_names[i]}: {oils}, T = {rough}, "
                f"{np.nanmin(temps):.0f}..{np.nanmax(temps):.0f} degC")

    @property
    def xlabel(self) -> str:
        """The time axis' label."""
        return "time [s]" if self.has_time else "operating point in its run [-]"


def panels(n: int, ncols: int, target=None, panel_size: tuple[float, float] = (4.0, 2.8),
           colorbar: bool = False, sharey: bool = False
           ) -> tuple[Figure, np.ndarray, Axes | None]:
    """``n`` axes in rows of ``ncols`` (and a colour-bar axes spanning the rows).

    Parameters
    ----------
    n, ncols : int
        Number of panels and of columns [-].
    target : None, Figure, Axes or sequence of Axes
        None: a new Agg figure (outside pyplot) sized ``panel_size`` [in] per panel; a
        figure: its whole area; one axes: its place in its figure, subdivided (the axes
        itself when one panel without colour bar is asked); several axes: the first ``n``
        of them as given (the colour bar then takes room from them).
    colorbar : bool
        Add a narrow axes for a colour bar at the right [-].
    sharey : bool
        Panels share their y axis (inner tick labels hidden) [-].

    Returns
    -------
    fig : Figure
    axes : ndarray of Axes
        The ``n`` panels, row by row.
    cax : Axes or None
        The colour bar's axes (None for given axes: use ``fig.colorbar(..., ax=axes)``).
    """
    nrows = math.ceil(n / ncols)
    if target is not None and not isinstance(target, (Figure, Axes)):
        axes = np.asarray(target, dtype=object).ravel()
        if len(axes) < n:
            raise ValueError(f"{n} axes needed, {len(axes)} given")
        return axes[0].figure, axes[:n], None
    if isinstance(target, Axes) and n == 1 and not colorbar:
        return target.figure, np.array([target], dtype=object), None
    ratios = [1.0] * ncols + ([0.05 * ncols] if colorbar else [])
    if target is None:
        fig = Figure(figsize=(panel_size[0] * ncols + (1.0 if colorbar else 0.0),
                              panel_size[1] * nrows + 0.5))
        FigureCanvasAgg(fig)
        gs = fig.add_gridspec(nrows, len(ratios), width_ratios=ratios)
    elif isinstance(target, Figure):
        fig = target
        gs = fig.add_gridspec(nrows, len(ratios), width_ratios=ratios)
    else:
        fig, spec = target.figure, target.get_subplotspec()
        if spec is None:  # an axes placed by hand: a grid over its rectangle
            p = target.get_position()
            gs = GridSpec(nrows, len(ratios), figure=fig, width_ratios=ratios, left=p.x0,
                          right=p.x1, bottom=p.y0, top=p.y1)
        else:
            gs = spec.subgridspec(nrows, len(ratios), width_ratios=ratios)
        target.remove()
    axes = []
    for i in range(n):
        share = axes[0] if sharey and axes else None
        ax = fig.add_subplot(gs[i // ncols, i % ncols], sharey=share)
        if share is not None and i % ncols:
            ax.tick_params(labelleft=False)
        axes.append(ax)
    cax = fig.add_subplot(gs[:, -1]) if colorbar else None
    return fig, np.array(axes, dtype=object), cax


def pages(n_runs: int, per_page: int = PER_PAGE) -> list[list[int]]:
    """The runs split into figures of at most ``per_page`` panels (equal sizes)."""
    if n_runs <= 0:
        return [[]]
    k = math.ceil(n_runs / per_page)
    size = math.ceil(n_runs / k)
    return [list(range(i, min(i + size, n_runs))) for i in range(0, n_runs, size)]


def summarised(n_runs: int, every: bool = False) -> bool:
    """Whether the report draws the summary (more than :data:`CAP` runs, not ``every``)."""
    return n_runs > CAP and not every


def figure_names(n_runs: int, every: bool = False) -> list[str]:
    """The files of the loop's figures for ``n_runs`` runs, in the order they are
    written: overview (page 1), the two residual figures, the overview's further pages,
    the windows (``_2``, ``_3``... for further pages). Above :data:`CAP` runs and without
    ``every``: overview and windows of the :data:`PER_PAGE` worst runs, the two residual
    figures and the grid of small multiples (:data:`GRID`)."""
    if summarised(n_runs, every):
        return [OVERVIEW, SPEED, TIME, GRID, WINDOW]
    n = len(pages(n_runs))
    paged = [f"{WINDOW[:-4]}{'' if p == 0 else f'_{p + 1}'}.png" for p in range(n)]
    return [OVERVIEW, SPEED, TIME, *(f"{OVERVIEW[:-4]}_{p + 1}.png" for p in range(1, n)),
            *paged]


def cycle_period_s(t: np.ndarray, speed: np.ndarray) -> float | None:
    """The speed's period [s] (median time between upward crossings of its mean, with a
    dead band of 0.2 standard deviations against noise); None without two cycles."""
    x = speed - np.mean(speed)
    band = 0.2 * np.std(x)
    if not band > 0:
        return None
    state = np.where(x > band, 1, np.where(x < -band, -1, 0))
    nz = np.nonzero(state)[0]
    s = state[nz]
    up = nz[1:][(s[1:] > 0) & (s[:-1] < 0)]
    if len(up) < 2:
        return None
    return float(np.median(np.diff(t[up])))


def window_of(curves: LoopCurves, i: int, cycles: int = CYCLES) -> tuple[float, float]:
    """The time window [s] of run ``i`` shown by :func:`plot_windows`: the last
    ``cycles`` speed cycles, or the whole run when it holds fewer (or no time)."""
    m = curves.run_code == i
    t = curves.time_s[m]
    if not len(t):
        return 0.0, 0.0
    period = cycle_period_s(t, curves.speed_rpm[m]) if curves.has_time else None
    if period is None or cycles * period >= t.max() - t.min():
        return float(t.min()), float(t.max())
    return float(t.max() - cycles * period), float(t.max())


def _draw_run(ax, c: LoopCurves, i: int, keys: Sequence[str], window=None) -> None:
    """Measured and model of run ``i`` (within ``window``)."""
    m = c.run_code == i
    if window is not None:
        m &= (c.time_s >= window[0]) & (c.time_s <= window[1])
    t = c.time_s[m]
    style = ".-" if not c.has_time else "."
    ax.plot(t, c.measured_W[m], style, ms=2 if window else 1.2, lw=0.3, color="0.45",
            label="measured")
    for k in keys:
        if k in c.predictions:
            label, color, ls, lw = MODELS[k]
            ax.plot(t, c.predictions[k][m], ls=ls, lw=lw, color=color, label=label,
                    marker="o" if not c.has_time else None, ms=2)
    ax.set_title(c.run_label(i), fontsize=8)
    ax.tick_params(labelsize=7)
    ax.grid(alpha=0.25)


def _runs(c: LoopCurves, runs: Sequence[int] | None) -> list[int]:
    return list(range(len(c.run_names))) if runs is None else list(runs)


def plot_overview(loop, runs: Sequence[int] | None = None, axes=None) -> np.ndarray:
    """Per run, its whole record: measured, without T, with T, with effect; the window
    of :func:`plot_windows` shaded.

    Parameters
    ----------
    loop : LoopEstimator or LoopCurves
        A fitted loop [-].
    runs : sequence of int, optional
        Indices into ``run_names`` (default all; keep to :data:`PER_PAGE`) [-].
    axes : Axes, Figure or sequence of Axes, optional
        Where to draw (see :func:`panels`); default a new
        Agg figure [-].

    Returns
    -------
    ndarray of Axes
        One panel per run.
    """
    c = LoopCurves.of(loop)
    runs = _runs(c, runs)
    ncols = 1 if len(runs) <= 3 else 2
    fig, axs, _ = panels(len(runs), ncols, axes, (7.0, 2.2))
    for k, (ax, i) in enumerate(zip(axs, runs, strict=True)):
        _draw_run(ax, c, i, tuple(MODELS))
        w = window_of(c, i)
        m = c.run_code == i
        if c.has_time and (w[0], w[1]) != (c.time_s[m].min(), c.time_s[m].max()):
            ax.axvspan(*w, color="gold", alpha=0.25, lw=0, label="window (detail figure)")
        if k % ncols == 0:
            ax.set_ylabel("viscous power [W]", fontsize=8)
        if k + ncols >= len(runs):
            ax.set_xlabel(c.xlabel, fontsize=8)
    if len(axs):
        lo, hi = axs[0].get_ylim()
        axs[0].set_ylim(lo, hi + 0.4 * (hi - lo))  # room above the curves for the legend
        axs[0].legend(fontsize=7, loc="upper right", ncol=3)
        fig.suptitle(f"Measured and modelled viscous power, whole runs ({_which(c, runs)})",
                     fontsize=10)
    return axs


def plot_windows(loop, runs: Sequence[int] | None = None, axes=None,
                 cycles: int = CYCLES) -> np.ndarray:
    """Per run, the last ``cycles`` speed cycles (the waveform's shape): measured, the
    base model and the model with the accepted effects, on one y scale.

    Parameters
    ----------
    loop : LoopEstimator or LoopCurves
        A fitted loop [-].
    runs : sequence of int, optional
        Indices into ``run_names`` (default all; keep to :data:`PER_PAGE`) [-].
    axes : Axes, Figure or sequence of Axes, optional
        Where to draw; default a new Agg figure [-].
    cycles : int
        Speed cycles per window [-].

    Returns
    -------
    ndarray of Axes
        One panel per run.
    """
    c = LoopCurves.of(loop)
    runs = _runs(c, runs)
    ncols = min(4, max(1, len(runs)))
    fig, axs, _ = panels(len(runs), ncols, axes, (3.6, 2.6), sharey=axes is None)
    lo, hi = math.inf, -math.inf
    for k, (ax, i) in enumerate(zip(axs, runs, strict=True)):
        w = window_of(c, i, cycles)
        _draw_run(ax, c, i, ("with_T", "with_effect"), w)
        m = (c.run_code == i) & (c.time_s >= w[0]) & (c.time_s <= w[1])
        for y in (c.measured_W[m], *(p[m] for p in c.predictions.values())):
            if len(y):
                lo, hi = min(lo, np.nanmin(y)), max(hi, np.nanmax(y))
        if k % ncols == 0:
            ax.set_ylabel("viscous power [W]", fontsize=8)
        if k + ncols >= len(runs):
            ax.set_xlabel(c.xlabel, fontsize=8)
    if len(axs) and math.isfinite(lo):
        pad = 0.05 * (hi - lo or 1.0)
        for ax in axs:  # one scale, room above the curves for the legend
            ax.set_ylim(lo - pad, hi + 7 * pad)
        axs[0].legend(fontsize=7, loc="upper left")
        span = f"the last {cycles} speed cycles" if c.has_time else "all operating points"
        note = "" if "with_effect" in c.predictions else "; no effect accepted"
        fig.suptitle(f"Measured and modelled viscous power over {span} of each run "
                     f"({_which(c, runs)}{note})", fontsize=10)
    return axs


def _which(c: LoopCurves, runs: Sequence[int]) -> str:
    n = len(c.run_names)
    if len(runs) == n:
        return f"all {n} runs"
    return f"runs {runs[0] + 1}..{runs[-1] + 1} of {n}" if runs else f"none of {n} runs"


def _bin_means(xv: np.ndarray, res: np.ndarray, bins: int = 24
               ) -> tuple[np.ndarray, np.ndarray]:
    """Centres and means of ``res`` in ``bins`` equal-count bins of ``xv``."""
    edges = np.quantile(xv, np.linspace(0, 1, bins + 1))
    idx = np.clip(np.searchsorted(edges, xv, side="right") - 1, 0, bins - 1)
    count = np.maximum(np.bincount(idx, None, bins), 1)
    return np.bincount(idx, xv, bins) / count, np.bincount(idx, res, bins) / count


def plot_residuals(loop, against: str = "time", axes=None) -> np.ndarray:
    """The residual (measured - model) before (calibrated, with T) and after (with the
    accepted effects), two panels.

    Parameters
    ----------
    loop : LoopEstimator or LoopCurves
        A fitted loop [-].
    against : {"time", "speed"}
        Time: one line per run, a legend naming each (oil, T, temperatures); speed: the
        samples and their means in 24 equal-count bins [-].
    axes : Axes, Figure or sequence of Axes, optional
        Where to draw; default a new Agg figure [-].

    Returns
    -------
    ndarray of Axes
        Before, after.
    """
    c = LoopCurves.of(loop)
    fig, axs, _ = panels(2, 2, axes, (5.5, 3.8), sharey=axes is None)
    after = c.predictions.get("with_effect", c.predictions["with_T"])
    colors = _run_colors(len(c.run_names))
    for ax, pred, title in ((axs[0], c.predictions["with_T"], "before (calibrated, with T)"),
                            (axs[1], after, "after (with accepted effects)"
                             if "with_effect" in c.predictions else
                             "after (no effect accepted: as before)")):
        res = c.measured_W - pred
        if against == "time":
            for i in range(len(c.run_names)):
                m = c.run_code == i
                ax.plot(c.time_s[m], res[m], lw=0.5, alpha=0.8, color=colors[i],
                        label=c.run_label(i) if len(c.run_names) <= LEGEND_MAX else None)
            ax.set_xlabel(c.xlabel)
        else:
            ax.plot(c.speed_rpm, res, ".", ms=1, alpha=0.3, color="0.4")
            ax.plot([], [], ".", ms=5, color="0.4", label="samples")  # a visible key
            cen, mean = _bin_means(c.speed_rpm, res)
            ax.plot(cen, mean, "o-", ms=3, color="tab:red", label="means of 24 speed bins")
            ax.legend(fontsize=8)
            ax.set_xlabel("speed [rpm]")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_title(f"residual {title}: RMSE {math.sqrt(np.nanmean(res * res)):.3g} W",
                     fontsize=9)
        ax.grid(alpha=0.25)
    axs[0].set_ylabel("measured - model [W]")
    if against == "time" and len(c.run_names) <= LEGEND_MAX:  # one legend, at the right
        axs[1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5),
                      ncol=1 + len(c.run_names) // 25, title="run: oil, roughness, temperatures",
                      title_fontsize=7)
    return axs


def grid_runs(n_runs: int, most: int = GRID_MAX) -> list[int]:
    """Up to ``most`` runs spread evenly over ``n_runs`` (first and last included)."""
    if n_runs <= most:
        return list(range(n_runs))
    return sorted({round(i * (n_runs - 1) / (most - 1)) for i in range(most)})


def plot_grid(loop, runs: Sequence[int] | None = None) -> np.ndarray:
    """Small multiples: per run (default :func:`grid_runs` of all), the measured viscous
    power [W] and the model after (with the accepted effects, else the base model)
    against time [s], one y scale, no tick labels; each panel titled by its run.

    Parameters
    ----------
    loop : LoopEstimator or LoopCurves
        A fitted loop [-].
    runs : sequence of int, optional
        Indices into ``run_names`` [-].

    Returns
    -------
    ndarray of Axes
        One panel per run, on a new Agg figure laid out by hand (no tight layout: a
        campaign's grid draws in a fraction of the time).
    """
    c = LoopCurves.of(loop)
    runs = grid_runs(len(c.run_names)) if runs is None else list(runs)
    ncols = min(8, max(1, len(runs)))
    fig, axs, _ = panels(len(runs), ncols, None, (1.6, 1.1), sharey=True)
    key = "with_effect" if "with_effect" in c.predictions else "with_T"
    for ax, i in zip(axs, runs, strict=True):
        m = c.run_code == i
        ax.plot(c.time_s[m], c.measured_W[m], lw=0.4, color="0.5")
        ax.plot(c.time_s[m], c.predictions[key][m], lw=0.6, color=MODELS[key][1])
        ax.set_title(c.run_names[i], fontsize=6, pad=2)
        ax.tick_params(labelleft=False, labelbottom=False, length=0)
    fig.subplots_adjust(left=0.02, right=0.98, bottom=0.02, top=0.9, wspace=0.08,
                        hspace=0.35)
    fig.suptitle(f"Measured (grey) and {MODELS[key][0]} ({MODELS[key][1][4:]}) of "
                 f"{len(runs)} of {len(c.run_names)} runs, evenly spread; one y scale",
                 fontsize=9)
    return axs


def _run_colors(n: int) -> list:
    """A colour per run (tab10, tab20 beyond ten runs, cycled beyond twenty)."""
    cmap = colormaps["tab10" if n <= 10 else "tab20"]
    return [cmap(i % cmap.N) for i in range(n)]
