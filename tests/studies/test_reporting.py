"""The report and figure convention: Markdown tables written out by hand, figures drawn
on the Agg canvas with the requested size."""

import math

import numpy as np
import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg

from oilgap.studies.reporting import (
    markdown_rows,
    markdown_table,
    new_figure,
    save_figure,
    write_tables,
)


def test_markdown_table_by_hand():
    df = pd.DataFrame({"oil": ["VG22", "VG46"], "P_W": [1.23456, math.nan], "n": [3, 4]})
    # pandas' to_markdown (tabulate): padded columns, numbers right-aligned, NaN blank
    assert markdown_table(df, 2) == ("| oil   |   P_W |   n |\n"
                                     "|:------|------:|----:|\n"
                                     "| VG22  |  1.23 |   3 |\n"
                                     "| VG46  |       |   4 |")


def test_markdown_rows_writes_cells_as_given():
    assert markdown_rows(["a", "b"], [["x", 1], [None, "2.50"]]) == (
        "| a    |    b |\n|:-----|-----:|\n| x    |    1 |\n| None | 2.50 |")


def test_markdown_cells_stay_escaped_and_unparsed():
    # a pipe in a cell cannot split it; "1e3" and "007" are written as given, not parsed
    text = markdown_rows(["k|ey", "v"], [["a|b", "007"], ["<b>x</b>", "1e3"]])
    assert text.splitlines() == ["| k\\|ey          |   v |",
                                 "|:---------------|----:|",
                                 "| a\\|b           | 007 |",
                                 "| &lt;b>x&lt;/b> | 1e3 |"]


def test_write_tables(tmp_path):
    paths = write_tables(tmp_path / "t", {"a.csv": pd.DataFrame({"x": [1, 2]})})
    assert paths == [tmp_path / "t" / "a.csv"]
    assert paths[0].read_text().splitlines() == ["x", "1", "2"]


def test_new_figure_is_on_the_agg_canvas_and_saves_at_its_size(tmp_path):
    fig, axes = new_figure(4.0, 2.5, ncols=3, nrows=2, squeeze=False)
    assert isinstance(fig.canvas, FigureCanvasAgg)
    assert np.shape(axes) == (2, 3)
    path = save_figure(fig, tmp_path / "sub" / "f.png", dpi=50)
    head = path.read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    assert (width, height) == (200, 125)  # 4 in x 50 dpi, 2.5 in x 50 dpi


def test_save_figure_draws_names_as_written_and_log_ticks_as_powers(tmp_path):
    """A "$" in a title or legend is text, not mathtext; a log axis keeps its 10^k ticks
    (the formatter writes them as mathtext: turned off they printed ``$\\mathdefault``)."""
    fig, ax = new_figure()
    ax.semilogy([1, 2, 3], [10, 100, 1000], label="oil $VG15$")
    ax.set_title("cost $5")
    ax.legend()
    save_figure(fig, tmp_path / "f.png")
    assert not ax.title.get_parse_math()
    assert not ax.get_legend().get_texts()[0].get_parse_math()
    assert all(t.get_parse_math() for t in ax.get_yticklabels())
