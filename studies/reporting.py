"""The one report and figure convention of the studies and the loop report.

Tables: :func:`markdown_table` (a DataFrame) or :func:`markdown_rows` (ready-made
cells) as Markdown pipe tables, :func:`write_tables` for the CSVs. Figures:
:func:`new_figure` draws on the Agg canvas outside pyplot (no global backend,
safe in worker processes) and :func:`save_figure` writes the PNG.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from oilgap.model.errors import InputError

DPI = 120
"""Resolution of the studies' PNG figures [dots per inch]."""


def markdown_rows(header: Sequence[Any], rows: Sequence[Sequence[Any]]) -> str:
    """A Markdown pipe table of ready-made cells (each written with ``str``)."""
    out = ["| " + " | ".join(str(c) for c in header) + " |",
           "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(str(x) for x in r) + " |" for r in rows]
    return "\n".join(out)


def markdown_table(df: pd.DataFrame, digits: int = 2) -> str:
    """A DataFrame as a Markdown pipe table (floats to ``digits`` decimals, NaN blank)."""

    def fmt(v: Any) -> str:
        if v is None or (isinstance(v, float) and math.isnan(v)):
            return ""
        if isinstance(v, (float, np.floating)):
            return f"{v:.{digits}f}"
        return str(v)

    return markdown_rows(list(df.columns),
                         [[fmt(v) for v in row] for row in df.itertuples(index=False, name=None)])


def write_tables(out: Path, tables: dict[str, pd.DataFrame]) -> list[Path]:
    """Write each named DataFrame as ``out/<name>`` CSV (no index); return the paths."""
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, df in tables.items():
        df.to_csv(out / name, index=False)
        paths.append(out / name)
    return paths


def write_data_csv(df: pd.DataFrame, path: str | Path) -> Path:
    """Write simulated rig data as CSV (7 significant digits, far below the noise).

    The one writer of both synthetic rigs (:mod:`oilgap.studies.synth`,
    :mod:`oilgap.studies.outside_rig`); refuses a folder that does not exist.
    """
    path = Path(path)
    if not path.parent.is_dir():
        raise InputError("--out", str(path), f"directory {str(path.parent)!r} does not exist")
    df.to_csv(path, index=False, float_format="%.7g")
    return path


def new_figure(width: float = 7.5, height: float = 4.8, ncols: int = 1, nrows: int = 1,
               **subplots_kw: Any) -> tuple[Figure, Any]:
    """A new (figure, axes) drawn by the Agg canvas, outside pyplot (no global backend).

    ``width``, ``height`` in inches; ``nrows`` x ``ncols`` axes and any other
    keyword of :meth:`matplotlib.figure.Figure.subplots` (``squeeze``, ``sharey``...).
    """
    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    axes = fig.subplots(nrows, ncols, **subplots_kw)
    return fig, axes


def save_figure(fig: Figure, path: Path, dpi: int = DPI) -> Path:
    """Save a figure made by :func:`new_figure` as PNG (tight layout); return the path."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    return path
