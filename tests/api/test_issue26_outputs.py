"""Issue 26, item 4: what the user sees is not misleading. The optimize and robust tables
show an inertia of a few 1e-3 kg m^2 with its change (5 significant digits below 1), and
``opt.plot()`` keeps its labels and title inside the figure when saved as is."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

import oilgap as og  # noqa: E402
from oilgap._results_design import _fmt  # noqa: E402
from oilgap._results_robust import _f  # noqa: E402


@pytest.mark.parametrize("fmt", [_fmt, _f])
def test_a_small_inertia_keeps_its_change(fmt):
    """0.0012345 -> 0.0012456 kg m^2 (+0.9 %) printed to 4 decimals was 0.0012 twice."""
    assert (fmt(0.0012345), fmt(0.0012456)) == ("0.0012345", "0.0012456")
    assert fmt(0.5032097) == "0.50321"
    assert fmt(6.8410e-05) == "6.8410e-05"
    assert fmt(49.4957) == "49.4957"


def _outside(fig, texts) -> list[str]:
    fig.canvas.draw()
    r, fb = fig.canvas.get_renderer(), fig.bbox
    out = []
    for t in texts:
        b = t.get_window_extent(r)
        if t.get_text() and not (b.x0 >= fb.x0 - 0.5 and b.x1 <= fb.x1 + 0.5
                                 and b.y0 >= fb.y0 - 0.5 and b.y1 <= fb.y1 + 0.5):
            out.append(t.get_text())
    return out


def test_opt_plot_labels_are_not_clipped():
    ax = og.optimize().plot()
    lo, hi = sorted(ax.get_xlim())
    ticks = [t for t, x in zip(ax.get_xticklabels(), ax.get_xticks(), strict=True)
             if lo <= x <= hi]
    try:
        assert ax.figure.get_layout_engine() is not None
        assert not _outside(ax.figure, [ax.title, ax.xaxis.label, *ax.get_yticklabels(),
                                        *ticks])
        # the longest label, clipped on the left without the layout, is among those checked
        assert "torque_capability_Nm" in [t.get_text() for t in ax.get_yticklabels()]
    finally:
        plt.close(ax.figure)
