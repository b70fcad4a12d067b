"""The sweep's result as a façade view (``og.sweep``, ``oilgap study sweep``):
:class:`Sweep`, and the files a sweep writes besides its store (:func:`write_sweep_outputs`:
``sweep.png``, ``summary.md``).

``Sweep.summary()`` is the text the command prints, ``Sweep.to_json()`` what ``--json``
prints; ``Sweep.plot()`` draws the figure of ``sweep.png``
(:func:`oilgap.studies.sweep_figures.plot_sweep`: the layout the grid's dimensions call
for) on the caller's axes.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pandas as pd

from oilgap._results import ResultView, new_axes
from oilgap._results_studies import records, wrote_lines
from oilgap.model.case import DesignCase
from oilgap.model.groove_band import GrooveBand, groove_band
from oilgap.model.io.defaults import gamma_fields, gamma_line
from oilgap.model.joint_loss import FilmBand, film_band, operating_temperature, uses_balance
from oilgap.studies.grid.evaluate import thermal_description
from oilgap.studies.reporting import markdown_table, write_text
from oilgap.studies.sweep_figures import plot_sweep, write_sweep_figure


def empty_cells(grid: pd.DataFrame) -> str:
    """Which columns have empty cells (they keep the base case's value), or ""."""
    n = {c: int(grid[c].isna().sum()) for c in grid.columns if c != "label"}
    given = ", ".join(f"{c} {k}" for c, k in n.items() if k)
    return f"empty cells (the base case's value): {given}" if given else ""


class Sweep(ResultView):
    """A grid evaluated or optimized row by row (the DataFrame of
    :func:`oilgap.studies.grid.runner.run_grid`).

    Parameters
    ----------
    raw : DataFrame
    case : DesignCase
        The base case.
    grid : DataFrame
        The grid run.
    mode : str
        ``"evaluate"`` or ``"optimize"``.
    elapsed_s : float
        Wall-clock time of the run [s].
    out : path, optional
        The sweep's folder.
    grid_name : str
        The grid's file name (or ``"the grid"``).
    scheduler : str, optional
        The Dask scheduler it ran on (named in the summary).
    """

    def __init__(self, raw: pd.DataFrame, case: DesignCase, grid: pd.DataFrame, mode: str,
                 elapsed_s: float = float("nan"), out: str | Path | None = None,
                 grid_name: str = "the grid", scheduler: str | None = None):
        self.raw = raw
        self.case = case
        self.grid = grid
        self.mode = mode
        self.elapsed_s = elapsed_s
        self.out = out
        self.grid_name = grid_name
        self.scheduler = scheduler
        self.files: list[Path] = []
        self._base: tuple[float, str] | None = None
        self._band: FilmBand | None = None

    # -------------------------------------------------------------- numbers
    @property
    def thermal_mode(self) -> str:
        """The thermal mode the points were computed under."""
        return self.raw.attrs.get("thermal_mode", "none")

    def thermal_text(self) -> str:
        """The text after ``thermal`` in the header."""
        return thermal_description(self.case, self.thermal_mode,
                                   self.raw.attrs.get("thermal_default", False))

    def base(self) -> tuple[float, str]:
        """The base case's loss under the mode [W] and where it was taken."""
        if self._base is None:
            op = operating_temperature(self.case, self.thermal_mode)
            where = (f"oil {op.oil_temp_C:.2f} degC from the balance with the sea at "
                     f"{op.sea_temp_C:g} degC" if uses_balance(self.thermal_mode)
                     else "its operating point")
            self._base = (op.mean_power_W, where)
        return self._base

    def band(self) -> FilmBand:
        """The base case's film band (:func:`~oilgap.model.joint_loss.film_band`)."""
        if self._band is None:
            self._band = film_band(self.case, self.thermal_mode, mean_power_W=self.base()[0])
        return self._band

    def groove_band(self) -> GrooveBand | None:
        """The base case's groove band where its region 1 is laminar (None elsewhere;
        :func:`~oilgap.model.groove_band.groove_band`).

        Returns
        -------
        GrooveBand or None
            The loss at groove factor 1 beside T^gamma [W].
        """
        if not hasattr(self, "_groove"):
            self._groove = groove_band(self.case, self.thermal_mode,
                                       mean_power_W=self.base()[0])
        return self._groove

    def _counts(self) -> tuple[pd.DataFrame, pd.DataFrame, int, int]:
        r, a = self.raw, self.raw.attrs
        return (r[r["status"] == "ok"], r[r["status"] != "ok"], a.get("computed", len(r)),
                a.get("reused", 0))

    # -------------------------------------------------------------- views
    def to_frame(self) -> pd.DataFrame:
        """The results: the grid's columns, ``status``, ``error`` and the result columns
        (``mean_power_W``...)."""
        return self.raw.copy()

    def to_dict(self) -> dict:
        """Counts, thermal mode, the base case's loss [W], every point, the files written
        and the defaults (``oilgap study sweep --json``)."""
        a = self.raw.attrs
        ok, bad, computed, reused = self._counts()
        return {"case": self.case.name, **gamma_fields(self.case), "mode": self.mode,
                "grid": self.grid_name, "thermal_mode": self.thermal_mode,
                "thermal_default": a.get("thermal_default"), "points": len(self.raw),
                "ok": len(ok), "failed": len(bad), "computed": computed, "reused": reused,
                "elapsed_s": self.elapsed_s, "backend": a.get("backend"),
                "base_mean_power_W": self.base()[0],
                "base_film_band": self.band().to_dict(),
                "base_groove_band": None if self.groove_band() is None
                else self.groove_band().to_dict(), "results": records(self.raw),
                "files": [str(f) for f in self.files], "defaults": self.defaults}

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap study sweep`` prints: thermal mode, gamma (``defaults`` False
        leaves these two lines out, ``-q``), empty cells, points done and failed, the
        range of the mean power (within the first 5 lines), the files written."""
        ok, bad, computed, reused = self._counts()
        lines = [f"thermal     {self.thermal_text()}", gamma_line(self.case)] if defaults \
            else []
        if empty_cells(self.grid):
            lines.append(empty_cells(self.grid))
        lines.append(f"{len(self.raw)} points: {len(ok)} ok, {len(bad)} failed "
                     f"({computed} computed, {reused} reused) in {self.elapsed_s:.2f} s")
        if self.scheduler:
            lines.append(f"ran on {self.raw.attrs['backend']} ({self.raw.attrs['chunks']} "
                         "chunks)")
        if len(ok):
            lines.append(f"mean power {ok['mean_power_W'].min():.3f} .. "
                         f"{ok['mean_power_W'].max():.3f} W (base case {self.base()[0]:.3f} W)")
        lines.append(f"film band of the base case: {self.band().line()}")
        if self.groove_band() is not None:
            lines.append(f"groove band of the base case: {self.groove_band().line()}")
        return "\n".join(lines + wrote_lines(self.out, self.files))

    def summary_markdown(self) -> str:
        """The sweep's ``summary.md``."""
        ok, bad, computed, reused = self._counts()
        base_p, base_where = self.base()
        grid = self.grid
        lines = [f"# Sweep of {self.grid_name} ({self.mode})", "",
                 f"Thermal mode: {self.thermal_text()}.", "",
                 f"Groove exponent: gamma = {self.case.friction.gamma:g} "
                 f"({self.case.gamma_source})"
                 + ("; the grid's gamma column overrides it per row." if "gamma" in grid.columns
                    else "."), "",
                 *([empty_cells(grid) + ".", ""] if empty_cells(grid) else []),
                 f"Base case: {self.case.name} ({base_p:.3f} W at {base_where}). "
                 f"{len(self.raw)} points: {len(ok)} ok, {len(bad)} failed; "
                 f"{computed} computed this run, {reused} taken from "
                 f"{self.out}/points_{self.mode}.csv; {self.elapsed_s:.2f} s.", "",
                 f"Film band of the base case: {self.band().line()}."]
        if self.groove_band() is not None:
            lines += ["", f"Groove band of the base case: {self.groove_band().line()}."]
        if len(ok):
            best = ok.loc[ok["mean_power_W"].idxmin()]
            worst = ok.loc[ok["mean_power_W"].idxmax()]
            cols = list(grid.columns) + ["mean_power_W"] + (
                ["oil_temp_op_C"] if uses_balance(self.thermal_mode)
                and "oil_temp_op_C" in ok.columns else [])
            lines += ["", "Lowest and highest mean power:", "",
                      markdown_table(pd.DataFrame([best[cols], worst[cols]]), 3)]
        if len(bad):
            lines += ["", f"First failure (row {bad.index[0]}): {bad['error'].iloc[0]}"]
        return "\n".join(lines) + "\n"

    def plot(self, ax: Any = None) -> Any:
        """The figure of ``sweep.png`` on ``ax`` (its place subdivided when the grid's
        dimensions call for small multiples): mean power [W] against the grid's factors.
        Returns the (first) panel's axes; every panel is in ``ax.figure.axes``."""
        ax = new_axes(ax)
        _, axes = plot_sweep(self.raw, self.base()[0], self.case.name, self.thermal_mode,
                             self.mode, self.grid_name, ax=ax)
        return axes[0]


def write_sweep_outputs(view: Sweep, out: Path) -> list[Path]:
    """Write ``sweep.png`` and ``summary.md`` into ``out``; return every file of the sweep
    (``results.csv``, ``results.parquet``, the store, the figure, the summary)."""
    fig = write_sweep_figure(view.raw, view.base()[0], view.case.name, out / "sweep.png",
                             view.thermal_mode, view.mode, view.grid_name)
    md = out / "summary.md"
    write_text(md, view.summary_markdown())
    return [out / "results.csv", out / "results.parquet", out / f"points_{view.mode}.csv",
            fig, md]


__all__ = ["Sweep", "empty_cells", "write_sweep_outputs"]
