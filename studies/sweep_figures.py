"""The sweep's figure, chosen by the grid's dimensions (``oilgap study sweep``'s ``sweep.png``).

The varied grid columns (the factors) decide the layout (:func:`choose_layout`):

* none: the power of each row;
* one: power against it (line and markers; categories such as ``oil`` on the x axis);
* two: a heatmap of the power (``pcolormesh``) on a regular grid, else a scatter
  coloured by the power; a categorical factor (``oil``) gives one line per level;
* three or four: small multiples, one panel per level of the third (and fourth)
  factor, each panel the two-factor figure, one shared colour scale;
* more, or factors with too many irregular values (a Monte Carlo): the power against
  each factor in its own panel.

Every figure has axis labels with units, a colour bar with units where colour carries
the power, a legend where several lines are drawn and a title naming the grid, the
mode and the thermal mode. :func:`plot_sweep` draws on a given figure or axes (a
notebook's) or a new Agg figure; :func:`write_sweep_figure` writes the PNG.
Small multiples are laid out by :func:`oilgap.studies.loop.figures.panels`.
"""

from __future__ import annotations

import math
import re
import textwrap
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib import colormaps
from matplotlib.axes import Axes
from matplotlib.colors import LogNorm, Normalize
from matplotlib.figure import Figure
from matplotlib.ticker import LogLocator, NullFormatter, StrMethodFormatter

from oilgap.studies.grid.columns import OPTIMIZE_COLUMNS, PARAM_COLUMNS
from oilgap.studies.loop.figures import panels
from oilgap.studies.reporting import save_figure

POWER = "mean_power_W"
MAX_LEVELS = 12
"""A numeric factor with more distinct values than this is continuous (no facet)."""
MAX_FACET_LEVELS = 6
"""At most this many levels of a factor shown one panel each."""
MAX_FACETS = 16
"""At most this many panels of small multiples; beyond, the pairwise layout."""
MAX_HUES = 8
"""At most this many lines (one per level) in one panel; beyond, a heatmap."""
MIN_FILL = 0.5
"""A grid holding fewer of its factors' level combinations is a list of cases."""
MAX_CASES = 24
"""A list of cases up to this many rows is drawn row by row (labelled); beyond, pairwise."""
LOG_RATIO = 30.0
"""A colour scale spanning more than this ratio of powers is logarithmic."""


# --------------------------------------------------------------------------- labels


def param_names() -> set[str]:
    """The columns a grid may hold (both modes)."""
    return set(PARAM_COLUMNS) | set(OPTIMIZE_COLUMNS)


def axis_label(col: str) -> str:
    """Axis label with units from the column's description: "oil temperature [degC]"."""
    desc = {**PARAM_COLUMNS, **OPTIMIZE_COLUMNS}.get(col, col)
    return desc[:desc.index("]") + 1] if "]" in desc else col


def _name_unit(col: str) -> tuple[str, str]:
    """A column's name in words and its unit ("" for none): ("sea depth", "m")."""
    m = re.match(r"(.*) \[(.*)\]$", axis_label(col))
    if not m:
        return col.replace("_", " "), ""
    return m.group(1).split(" = ")[0].split(" (")[0], "" if m.group(2) == "-" else m.group(2)


def value_text(col: str, value) -> str:
    """A level with its unit: "20 degC", "VG22", "4"."""
    if isinstance(value, str):
        return value
    unit = _name_unit(col)[1]
    return f"{value:.4g}" + (f" {unit}" if unit else "")


def level_text(col: str, value) -> str:
    """One level of a factor in words: "oil temperature 20 degC", "oil VG22", "T 4"."""
    return f"{_name_unit(col)[0]} {value_text(col, value)}"


def _natural(value) -> tuple:
    """Sort key putting VG15 before VG100 (digit runs compared as numbers)."""
    return tuple(int(p) if p.isdigit() else p for p in re.split(r"(\d+)", str(value)))


# --------------------------------------------------------------------------- layout


@dataclass(frozen=True)
class Factor:
    """A varied grid column: its sorted distinct values and whether they are numbers."""

    name: str
    levels: tuple
    numeric: bool

    @property
    def continuous(self) -> bool:
        """Too many values for one panel or one line each."""
        return self.numeric and len(self.levels) > MAX_LEVELS


@dataclass(frozen=True)
class Layout:
    """The chosen figure: ``kind`` one of ``rows``, ``cases``, ``line``, ``categories``,
    ``lines``, ``heatmap``, ``scatter``, ``facets``, ``pairwise``; ``x``, ``y`` (heatmap/scatter
    y or the lines' hue), ``facets`` (one panel per level combination) and ``panel``
    (the kind drawn in each facet)."""

    kind: str
    factors: tuple[Factor, ...]
    x: Factor | None = None
    y: Factor | None = None
    facets: tuple[Factor, ...] = ()
    panel: str = ""

    @property
    def n_panels(self) -> int:
        """How many axes the layout draws (the colour bar aside)."""
        if self.kind == "pairwise":
            return len(self.factors)
        return math.prod(len(f.levels) for f in self.facets) if self.facets else 1


def grid_factors(res: pd.DataFrame) -> list[Factor]:
    """The varied grid columns of a result frame: the parameter columns before
    ``status`` (the grid's own columns; ``label`` is no factor) with more than one value
    (empty cells, the base case's value, are not counted)."""
    cols = list(res.columns)
    if "status" in cols:
        cols = cols[:cols.index("status")]
    out = []
    for c in cols:
        if c not in param_names() or c == "label":
            continue
        vals = res[c].dropna()
        numeric = pd.api.types.is_numeric_dtype(vals) and not pd.api.types.is_bool_dtype(vals)
        levels = sorted(vals.unique().tolist(), key=None if numeric else _natural)
        if len(levels) > 1:
            out.append(Factor(c, tuple(levels), numeric))
    return out


def _regular(res: pd.DataFrame, cols: Sequence[str]) -> bool:
    """Each combination of the columns' levels occurs exactly once."""
    keys = res[list(cols)].dropna()
    n = math.prod(keys[c].nunique() for c in cols)
    return len(keys) == n and not keys.duplicated().any()


def _pair(res: pd.DataFrame, a: Factor, b: Factor, facets: Sequence[Factor]) -> tuple:
    """(x, y, kind) of a two-factor panel."""
    if a.numeric != b.numeric:  # a category against a number: one line per category
        x, hue = (a, b) if a.numeric else (b, a)
        if len(hue.levels) <= MAX_HUES:
            return x, hue, "lines"
    x, y = sorted((a, b), key=lambda f: (not f.numeric, -len(f.levels)))
    regular = _regular(res, [f.name for f in (*facets, x, y)])
    return x, y, ("heatmap" if regular else "scatter")


def _fill(res: pd.DataFrame, fs: Sequence[Factor]) -> float:
    """Share of the factors' level combinations the grid holds (1: a full factorial)."""
    keys = res[[f.name for f in fs]].dropna().drop_duplicates()
    return len(keys) / math.prod(len(f.levels) for f in fs)


def choose_layout(res: pd.DataFrame) -> Layout:
    """The figure for a result frame by its grid's dimensions (see the module's text)."""
    fs = tuple(grid_factors(res))
    if not fs:
        return Layout("rows", fs)
    if len(fs) == 1:
        return Layout("line" if fs[0].numeric else "categories", fs, x=fs[0])
    sparse = _fill(res, fs) < MIN_FILL
    if len(fs) == 2 and all(f.numeric for f in fs) and (
            sparse or all(f.continuous for f in fs) or not _regular(res, [f.name for f in fs])):
        x, y = sorted(fs, key=lambda f: -len(f.levels))
        return Layout("scatter", fs, x=x, y=y)
    if sparse or len(fs) > 4:  # a list of cases, not a factorial
        return Layout("cases" if len(res) <= MAX_CASES else "pairwise", fs)
    if len(fs) == 2:
        x, y, kind = _pair(res, *fs, ())
        return Layout(kind, fs, x=x, y=y)
    # categories and numbers with few levels become the facets, the rest the axes
    order = sorted(fs, key=lambda f: (f.numeric, len(f.levels)))
    facets, axes = tuple(order[:len(fs) - 2]), order[len(fs) - 2:]
    n = math.prod(len(f.levels) for f in facets)
    if all(len(f.levels) <= MAX_FACET_LEVELS and not f.continuous for f in facets) \
            and n <= MAX_FACETS:
        x, y, kind = _pair(res, *axes, facets)
        return Layout("facets", fs, x=x, y=y, facets=facets, panel=kind)
    return Layout("pairwise", fs)


# --------------------------------------------------------------------------- drawing


@dataclass(frozen=True)
class _Style:
    """What every panel of one figure shares: colour scale, base case, power label."""

    norm: Normalize
    base_power: float | None
    base_name: str
    power_label: str

    def base_line(self, ax: Axes) -> None:
        if self.base_power is not None and math.isfinite(self.base_power):
            ax.axhline(self.base_power, color="k", ls="--", lw=1,
                       label=f"base case ({self.base_name}): {self.base_power:.2f} W")


def _positions(values: pd.Series, f: Factor) -> np.ndarray:
    """Where the values sit on an axis: the numbers, or the index of the category."""
    if f.numeric:
        return values.to_numpy(float)
    index = {v: i for i, v in enumerate(f.levels)}
    return np.array([index[v] for v in values], float)


def _set_axis(ax: Axes, f: Factor, which: str) -> None:
    """Label (with units) and, for categories or few levels, ticks at the levels."""
    getattr(ax, f"set_{which}label")(axis_label(f.name))
    if not f.numeric:
        turn = {"rotation": 45, "ha": "right"} if which == "x" and len(f.levels) > 5 else {}
        getattr(ax, f"set_{which}ticks")(range(len(f.levels)), [str(v) for v in f.levels],
                                         **turn)
    elif len(f.levels) <= 5:
        getattr(ax, f"set_{which}ticks")(list(f.levels), [f"{v:.4g}" for v in f.levels])


def _edges(f: Factor) -> np.ndarray:
    """Cell edges around each level (midpoints; categories at integer positions)."""
    if not f.numeric:
        return np.arange(len(f.levels) + 1) - 0.5
    c = np.asarray(f.levels, float)
    mid = (c[1:] + c[:-1]) / 2
    return np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])


def _draw_heatmap(ax: Axes, ok: pd.DataFrame, x: Factor, y: Factor, st: _Style):
    """Power on the regular (x, y) grid; blank cells: no converged point."""
    z = np.full((len(y.levels), len(x.levels)), np.nan)
    ix = _positions(ok[x.name], x) if not x.numeric else \
        np.searchsorted(np.asarray(x.levels, float), ok[x.name].to_numpy(float))
    iy = _positions(ok[y.name], y) if not y.numeric else \
        np.searchsorted(np.asarray(y.levels, float), ok[y.name].to_numpy(float))
    z[iy.astype(int), ix.astype(int)] = ok[POWER].to_numpy(float)
    mesh = ax.pcolormesh(_edges(x), _edges(y), np.ma.masked_invalid(z), cmap="viridis",
                         norm=st.norm, shading="flat")
    if len(x.levels) * len(y.levels) <= 40:  # few cells: the numbers too
        for (j, i), v in np.ndenumerate(z):
            if math.isfinite(v):
                cx = x.levels[i] if x.numeric else i
                cy = y.levels[j] if y.numeric else j
                ax.text(cx, cy, f"{v:.3g}", ha="center", va="center", fontsize=6,
                        color="w" if st.norm(v) < 0.6 else "k")
    if st.base_power is not None and x.numeric and y.numeric and \
            np.nanmin(z) < st.base_power < np.nanmax(z):
        ax.contour(np.asarray(x.levels, float), np.asarray(y.levels, float),
                   np.ma.masked_invalid(z), levels=[st.base_power], colors="w",
                   linestyles="--", linewidths=1)
    _set_axis(ax, x, "x")
    _set_axis(ax, y, "y")
    return mesh


def _draw_scatter(ax: Axes, ok: pd.DataFrame, x: Factor, y: Factor, st: _Style):
    """Points at (x, y) coloured by the power (an irregular grid)."""
    sc = ax.scatter(_positions(ok[x.name], x), _positions(ok[y.name], y), c=ok[POWER],
                    s=14, cmap="viridis", norm=st.norm)
    _set_axis(ax, x, "x")
    _set_axis(ax, y, "y")
    return sc


def _draw_lines(ax: Axes, ok: pd.DataFrame, x: Factor, hue: Factor | None, st: _Style,
                legend: bool = True) -> None:
    """Power against x, one line per level of ``hue`` (legend), the base case dashed."""
    groups = [(None, ok)] if hue is None else [
        (v, ok[ok[hue.name] == v]) for v in hue.levels]
    colors = _colors(len(groups))
    for (v, g), color in zip(groups, colors, strict=True):
        pos = _positions(g[x.name], x)
        order = np.argsort(pos, kind="stable")
        label = "mean power" if v is None else value_text(hue.name, v)
        ax.plot(pos[order], g[POWER].to_numpy(float)[order], "o-", ms=3.5, lw=1.2,
                color=color, label=label)
    st.base_line(ax)
    _set_axis(ax, x, "x")
    ax.set_ylabel(st.power_label)
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(fontsize=7, title=None if hue is None else _name_unit(hue.name)[0],
                  title_fontsize=7)


def _colors(n: int) -> list:
    """``n`` distinguishable colours (tab10, tab20 beyond ten)."""
    cmap = colormaps["tab10" if n <= 10 else "tab20"]
    return [cmap(i % cmap.N) for i in range(n)]


def _norm(power: pd.Series) -> Normalize:
    """One colour scale for every panel: linear, logarithmic over a wide span."""
    p = power.to_numpy(float)
    p = p[np.isfinite(p)]
    if not len(p):
        return Normalize(0.0, 1.0)
    lo, hi = float(p.min()), float(p.max())
    if lo > 0 and hi / lo > LOG_RATIO:
        return LogNorm(lo, hi)
    return Normalize(lo, hi) if hi > lo else Normalize(lo - 0.5, hi + 0.5)


def _colorbar(fig: Figure, mappable, cax: Axes | None, axes: np.ndarray, st: _Style) -> None:
    """The colour bar of the power, the base case marked on it."""
    label = st.power_label.replace(" over the duty cycle", "")
    inside = st.base_power is not None and st.norm.vmin < st.base_power < st.norm.vmax
    if inside:
        label += f"\n(dashed: base case {st.base_power:.2f} W)"
    cb = (fig.colorbar(mappable, cax=cax) if cax is not None
          else fig.colorbar(mappable, ax=list(axes)))
    cb.set_label(label, fontsize=8)
    if isinstance(st.norm, LogNorm):  # plain numbers: figure text is drawn without mathtext
        cb.ax.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        cb.ax.yaxis.set_major_formatter(StrMethodFormatter("{x:g}"))
        cb.ax.yaxis.set_minor_formatter(NullFormatter())
    if inside:
        cb.ax.axhline(st.base_power, color="k", ls="--", lw=1.2)


def _single(target, ok: pd.DataFrame, layout: Layout, st: _Style):
    """The one-panel layouts."""
    colour = layout.kind in ("heatmap", "scatter")
    fig, axes, cax = panels(1, 1, target, (6.5, 4.8), colorbar=colour)
    ax = axes[0]
    if layout.kind in ("rows", "cases"):
        ax.plot(np.arange(len(ok)), ok[POWER], "o", ms=4, label="grid rows")
        st.base_line(ax)
        ax.set_xlabel("grid row [-]")
        if layout.kind == "cases":
            ax.set_xticks(range(len(ok)), [_case_text(r, layout.factors)
                                           for _, r in ok.iterrows()],
                          rotation=30, ha="right", fontsize=7)
            ax.set_xlabel("grid row (its values; base: the base case's)")
        ax.set_ylabel(st.power_label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    elif layout.kind in ("line", "categories", "lines"):
        _draw_lines(ax, ok, layout.x, layout.y, st)
    else:
        draw = _draw_heatmap if layout.kind == "heatmap" else _draw_scatter
        _colorbar(fig, draw(ax, ok, layout.x, layout.y, st), cax, axes, st)
    return fig, axes


def _case_text(row: pd.Series, fs: Sequence[Factor]) -> str:
    """One row's factor values: "VG22, 2 degC, 0.5 N m" (an empty cell: "base")."""
    return ", ".join("base" if pd.isna(row[f.name]) else value_text(f.name, row[f.name])
                     for f in fs)


def _facet_combos(facets: tuple[Factor, ...]) -> tuple[list[tuple], int]:
    """The level combinations, one panel each (row by row), and the number of columns:
    the first facet's levels across, the second's down."""
    first = facets[0].levels
    if len(facets) == 1:
        return [(a,) for a in first], min(4, len(first))
    return [(a, b) for b in facets[1].levels for a in first], len(first)


def _facets(target, ok: pd.DataFrame, layout: Layout, st: _Style):
    """Small multiples: one panel per level combination of the facets."""
    combos, ncols = _facet_combos(layout.facets)
    colour = layout.panel in ("heatmap", "scatter")
    fig, axes, cax = panels(len(combos), ncols, target, (3.6, 2.9), colorbar=colour,
                            sharey=layout.panel == "lines")
    mappable = None
    for i, (ax, combo) in enumerate(zip(axes, combos, strict=True)):
        mask = np.ones(len(ok), bool)
        for f, v in zip(layout.facets, combo, strict=True):
            mask &= (ok[f.name] == v).to_numpy()
        sub = ok[mask]
        if layout.panel == "lines":
            _draw_lines(ax, sub, layout.x, layout.y, st, legend=i == 0)
        elif len(sub):
            draw = _draw_heatmap if layout.panel == "heatmap" else _draw_scatter
            mappable = draw(ax, sub, layout.x, layout.y, st)
        else:
            _set_axis(ax, layout.x, "x")
            _set_axis(ax, layout.y, "y")
        ax.set_title(", ".join(level_text(f.name, v) for f, v in
                               zip(layout.facets, combo, strict=True))
                     + ("" if len(sub) else ": no converged point"), fontsize=8)
        ax.tick_params(labelsize=7)
        ax.xaxis.label.set_size(8)
        ax.yaxis.label.set_size(8)
        if i % ncols:
            ax.set_ylabel("")
        if i + ncols < len(combos):
            ax.set_xlabel("")
    if colour and mappable is not None:
        _colorbar(fig, mappable, cax, axes, st)
    elif cax is not None:
        cax.axis("off")
    return fig, axes


def _pairwise(target, ok: pd.DataFrame, layout: Layout, st: _Style):
    """The power against each factor, one panel each (shared y)."""
    fs = layout.factors
    ncols = min(4, len(fs))
    fig, axes, _ = panels(len(fs), ncols, target, (3.6, 2.9), sharey=True)
    for i, (ax, f) in enumerate(zip(axes, fs, strict=True)):
        sub = ok.dropna(subset=[f.name])
        pos = _positions(sub[f.name], f)
        ax.plot(pos, sub[POWER], ".", ms=3, alpha=0.4, color="tab:blue", label="grid points")
        cx, med, what = _medians(pos, sub[POWER].to_numpy(float))
        ax.plot(cx, med, "o-", ms=3, lw=1.2, color="tab:red", label=what)
        st.base_line(ax)
        _set_axis(ax, f, "x")
        ax.grid(alpha=0.3)
        ax.tick_params(labelsize=7)
        ax.xaxis.label.set_size(8)
        if i % ncols == 0:
            ax.set_ylabel(st.power_label.replace(" over the duty cycle", ""), fontsize=8)
        if i == 0:
            ax.legend(fontsize=7)
    return fig, axes


def _medians(x: np.ndarray, y: np.ndarray, bins: int = MAX_LEVELS
             ) -> tuple[np.ndarray, np.ndarray, str]:
    """The median of ``y`` per distinct ``x`` (few levels) or per equal-count bin of
    ``x``: the trend of one factor over all the others."""
    levels = np.unique(x)
    if len(levels) <= 3 * MAX_LEVELS:
        return levels, np.array([np.median(y[x == v]) for v in levels]), "median per level"
    edges = np.quantile(x, np.linspace(0, 1, bins + 1))
    idx = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, bins - 1)
    keep = [k for k in range(bins) if np.any(idx == k)]
    return (np.array([np.median(x[idx == k]) for k in keep]),
            np.array([np.median(y[idx == k]) for k in keep]), f"median of {bins} bins")


def _describe(layout: Layout) -> str:
    """The layout in words (the title's second line)."""
    names = [f.name for f in layout.factors]
    if layout.kind == "rows":
        return "no varied column: power of each row"
    if layout.kind == "cases":
        return f"power of each row (a list of cases in {', '.join(names)}, not a factorial)"
    if layout.kind == "pairwise":
        return f"power against each of {', '.join(names)}"
    text = f"power against {layout.x.name}"
    if layout.y is not None:
        text += (f", one line per {layout.y.name}" if "lines" in (layout.kind, layout.panel)
                 else f" and {layout.y.name}")
    if layout.facets:
        text += ", one panel per " + " x ".join(f.name for f in layout.facets)
    return text


def plot_sweep(res: pd.DataFrame, base_power: float | None = None,
               base_name: str = "base case", thermal: str | None = None,
               mode: str | None = None, grid_name: str | None = None,
               ax: Axes | Figure | None = None, layout: Layout | None = None
               ) -> tuple[Figure, np.ndarray]:
    """Draw a sweep's result frame in the layout its grid's dimensions call for.

    Parameters
    ----------
    res : DataFrame
        :func:`oilgap.studies.grid.runner.run_grid`'s result (the grid's columns,
        ``status``, ``mean_power_W`` [W]...).
    base_power : float, optional
        The base case's mean power, drawn dashed [W].
    base_name : str
        The base case's name [-].
    thermal, mode, grid_name : str, optional
        For the title (default: the frame's ``thermal_mode``; ``optimize`` when the frame
        holds optimize results; "the grid") [-].
    ax : Axes or Figure, optional
        Where to draw: an axes' place (subdivided for several panels) or a whole
        figure; default a new Agg figure [-].
    layout : Layout, optional
        Default :func:`choose_layout` [-].

    Returns
    -------
    fig : Figure
    axes : ndarray of Axes
        The panels (colour bar aside).
    """
    layout = layout or choose_layout(res)
    mode = mode or ("optimize" if "iterations" in res.columns else "evaluate")
    if thermal is None:
        thermal = res.attrs.get("thermal_mode") or (
            str(res["thermal_mode"].dropna().iloc[0]) if "thermal_mode" in res.columns
            and res["thermal_mode"].notna().any() else "none")
    ok = res[res["status"] == "ok"] if "status" in res.columns else res
    notes = [f"{len(res) - len(ok)} failed, not drawn"] if len(ok) < len(res) else []
    if layout.kind not in ("pairwise", "cases", "rows"):
        drawn = ok.dropna(subset=[f.name for f in layout.factors])
        if len(drawn) < len(ok):
            notes.append(f"{len(ok) - len(drawn)} rows with empty cells (the base case's "
                         "value) not drawn")
        ok = drawn
    power = ("optimal design's " if mode == "optimize" else "") + \
        "mean viscous power over the duty cycle [W]"
    st = _Style(_norm(ok[POWER]), base_power, base_name, power)
    draw = {"facets": _facets, "pairwise": _pairwise}.get(layout.kind, _single)
    fig, axes = draw(ax, ok, layout, st)
    title = (f"Sweep of {grid_name or 'the grid'} ({mode}, thermal mode {thermal}): "
             f"{len(ok)}/{len(res)} points\n"
             + textwrap.fill(_describe(layout) + (f"; {'; '.join(notes)}" if notes else ""),
                             70 if len(axes) == 1 else 110))
    if len(axes) == 1:
        axes[0].set_title(title, fontsize=9)
    else:
        fig.suptitle(title, fontsize=10)
    return fig, axes


def write_sweep_figure(res: pd.DataFrame, base_power: float, base_name: str, path: Path,
                       thermal: str = "none", mode: str | None = None,
                       grid_name: str | None = None) -> Path:
    """Draw :func:`plot_sweep` on a new Agg figure and write it as PNG, atomically;
    return the path."""
    fig, _ = plot_sweep(res, base_power, base_name, thermal, mode, grid_name)
    return save_figure(fig, Path(path))
