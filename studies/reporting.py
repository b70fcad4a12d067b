"""The one report and figure convention of the studies and the loop report.

Tables: :func:`markdown_table` (a DataFrame) or :func:`markdown_rows` (ready-made
cells) as Markdown pipe tables written by pandas' ``DataFrame.to_markdown``
(tabulate: columns padded, numbers right-aligned), :func:`write_tables` for the CSVs. Figures:
:func:`new_figure` draws on the Agg canvas outside pyplot (no global backend,
safe in worker processes) and :func:`save_figure` writes the PNG. Every file is
written atomically (:mod:`oilgap.studies.io.files`: a temporary file, then a rename), so
a failure never leaves half a file; :func:`write_text` is the form for Markdown and
JSON.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.text import Text

from oilgap.model.errors import InputError
from oilgap.studies.io.files import atomic_savefig, atomic_to_csv, atomic_write_text, is_number

DPI = 120
"""Resolution of the studies' PNG figures [dots per inch]."""


_TAG_OPEN = re.compile(r"<(?=[A-Za-z/!?])")
"""A ``<`` that opens raw HTML in Markdown (a tag, a comment, a declaration)."""


def markdown_cell(x: Any) -> str:
    """One table cell as text that cannot break its table or inject HTML: on one line,
    ``|`` escaped (GitHub splits cells on it even inside code spans), a ``<`` that would
    open an HTML tag written as ``&lt;`` outside a code span (``nu < 13`` stays as is)."""
    text = " ".join(str(x).splitlines())
    if not (len(text) >= 2 and text[0] == "`" and text[-1] == "`"):
        text = _TAG_OPEN.sub("&lt;", text)
    return text.replace("|", "\\|")


def _pipe_table(header: Sequence[Any], cells: list[list[str]], right: Sequence[bool]) -> str:
    """The pipe table of escaped text cells by ``DataFrame.to_markdown`` (tabulate; the
    text written as given, not parsed again), ``right`` columns right-aligned."""
    names = [markdown_cell(c) for c in header]
    frame = pd.DataFrame(cells, columns=range(len(names)), dtype=object) if cells else \
        pd.DataFrame(columns=range(len(names)), dtype=object)
    frame.columns = names
    return frame.to_markdown(index=False, tablefmt="pipe", disable_numparse=True,
                             colalign=["right" if r else "left" for r in right])


def markdown_rows(header: Sequence[Any], rows: Sequence[Sequence[Any]]) -> str:
    """A Markdown pipe table of ready-made cells (each written with ``str``, escaped by
    :func:`markdown_cell`); a column whose cells are all numbers (or blank) is
    right-aligned."""
    cells = [[markdown_cell(x) for x in r] for r in rows]
    right = [bool(col) and all(c == "" or is_number(c) for c in col)
             and any(c != "" for c in col) for col in zip(*cells, strict=True)] \
        if cells else [False] * len(header)
    return _pipe_table(header, cells, right)


def markdown_table(df: pd.DataFrame, digits: int = 2) -> str:
    """A DataFrame as a Markdown pipe table (floats to ``digits`` decimals, NaN blank,
    numeric columns right-aligned)."""

    def fmt(v: Any) -> str:
        if v is None or (isinstance(v, float) and math.isnan(v)):
            return ""
        if isinstance(v, (float, np.floating)):
            return f"{v:.{digits}f}"
        return markdown_cell(v)

    cells = [[fmt(v) for v in row] for row in df.itertuples(index=False, name=None)]
    right = [pd.api.types.is_numeric_dtype(t) and not pd.api.types.is_bool_dtype(t)
             for t in df.dtypes]
    return _pipe_table(list(df.columns), cells, right)


def write_tables(out: Path, tables: dict[str, pd.DataFrame]) -> list[Path]:
    """Write each named DataFrame as ``out/<name>`` CSV (no index), atomically; return
    the paths."""
    out.mkdir(parents=True, exist_ok=True)
    return [atomic_to_csv(df, out / name, index=False) for name, df in tables.items()]


def write_text(path: Path, text: str) -> Path:
    """Write a text output (Markdown, JSON) atomically, UTF-8; return the path."""
    return atomic_write_text(path, text)


def write_data_csv(df: pd.DataFrame, path: str | Path) -> Path:
    """Write simulated rig data as CSV (7 significant digits, far below the noise).

    The one writer of both synthetic rigs (:mod:`oilgap.studies.rigs.synth`,
    :mod:`oilgap.studies.rigs.outside_rig`); refuses a folder that does not exist.
    """
    path = Path(path)
    if not path.parent.is_dir():
        raise InputError("--out", str(path), f"directory {str(path.parent)!r} does not exist")
    return atomic_to_csv(df, path, index=False, float_format="%.7g")


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


def _named_texts(fig: Figure) -> list[Text]:
    """The texts a study writes (titles, axis labels, legends, annotations), not the
    tick labels the axes' formatters make."""
    out = list(fig.texts) + [t for leg in fig.legends for t in (*leg.get_texts(),
                                                                 leg.get_title())]
    if getattr(fig, "_suptitle", None) is not None:
        out.append(fig._suptitle)
    for ax in fig.axes:
        out += [ax.title, ax.xaxis.label, ax.yaxis.label, *ax.texts]
        out += [t for t in ax.get_children() if isinstance(t, Text) and t not in out
                and t.get_text() and t is not ax.xaxis.offsetText
                and t is not ax.yaxis.offsetText]
        leg = ax.get_legend()
        if leg is not None:
            out += [*leg.get_texts(), leg.get_title()]
    return out


def save_figure(fig: Figure, path: Path, dpi: int = DPI) -> Path:
    """Save a figure made by :func:`new_figure` as PNG (tight layout), atomically; return
    the path."""
    path.parent.mkdir(parents=True, exist_ok=True)
    for text in _named_texts(fig):  # names are drawn as written: "$" is no mathtext
        text.set_parse_math(False)  # (tick labels keep it: a log axis writes 10^2 so)
    fig.tight_layout()
    return atomic_savefig(fig, path, dpi=dpi)
