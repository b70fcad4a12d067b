"""Multi-objective helpers: the hypervolume against a hand calculation and grid counting,
the non-dominated mask by hand, the arc-length spacing of epsilon values against the arc
length of the model front computed on its own."""

import numpy as np
import pytest
from scipy.integrate import quad

from oilgap.optim.multiobjective import arc_length_epsilons, hypervolume_2d, nondominated


def test_hypervolume_hand_calculation():
    # boxes [1,4]x[3,4], [2,4]x[2,4], [3,4]x[1,4]: union = 3 + 2 + 1 = 6
    pts = np.array([[3.0, 1.0], [1.0, 3.0], [2.0, 2.0]])
    assert hypervolume_2d(pts, (4.0, 4.0)) == pytest.approx(6.0)
    # a dominated point and points outside the reference box add nothing
    more = np.vstack([pts, [[3.5, 3.5], [5.0, 0.0], [0.5, 4.5]]])
    assert hypervolume_2d(more, (4.0, 4.0)) == pytest.approx(6.0)
    assert hypervolume_2d(np.empty((0, 2)), (1.0, 1.0)) == 0.0


def test_hypervolume_against_grid_counting():
    rng = np.random.default_rng(0)
    pts = rng.uniform(0, 1, (15, 2))
    n = 1000
    xs = (np.arange(n) + 0.5) / n
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    dom = np.zeros_like(X, dtype=bool)
    for a, b in pts:
        dom |= (X >= a) & (Y >= b)
    assert hypervolume_2d(pts, (1.0, 1.0)) == pytest.approx(dom.mean(), abs=3e-3)


def test_nondominated_mask():
    pts = np.array([[1, 3], [2, 2], [3, 1], [2.5, 2.5], [1, 3.5]])
    assert list(nondominated(pts)) == [True, True, True, False, False]



def test_nondominated_keeps_ties_and_accepts_flat_input():
    pts = np.array([1.0, 2.0, 1.0, 2.0, 2.0, 1.0])
    assert list(nondominated(pts)) == [True, True, True]


def test_arc_length_epsilons_are_equally_spaced_along_the_model_front():
    """Ends exact and decreasing; between consecutive values the normalised arc length of
    y = y_top + b (1/x - 1/x_top), integrated with quad, is the same."""
    x_top, y_top, x_bot, y_bot, n = 2.0, 10.0, 0.5, 40.0, 12
    eps = arc_length_epsilons(x_top, y_top, x_bot, y_bot, n)
    assert eps[0] == x_top and eps[-1] == x_bot and len(eps) == n
    assert np.all(np.diff(eps) < 0)
    b = (y_bot - y_top) / (1 / x_bot - 1 / x_top)

    def speed(x):  # |d(xn, yn)/dx| with xn, yn normalised by the ranges
        return np.hypot(1 / (x_top - x_bot), b / x**2 / (y_bot - y_top))

    seg = [quad(speed, lo, hi)[0] for hi, lo in zip(eps[:-1], eps[1:], strict=True)]
    assert np.ptp(seg) <= 1e-3 * np.mean(seg)


def test_arc_length_epsilons_fall_back_to_equal_steps():
    """A front that does not fall (y_bot <= y_top) gives equal steps in x."""
    assert arc_length_epsilons(2.0, 10.0, 0.5, 5.0, 4) == pytest.approx([2.0, 1.5, 1.0, 0.5])
