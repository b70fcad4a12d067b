"""Multi-objective helpers for two minimised objectives: the non-dominated filter, the
exact 2-D hypervolume, and epsilon values spread along a front for an
epsilon-constraint sweep.

References
----------
.. [1] Y. Y. Haimes, L. S. Lasdon, D. A. Wismer, "On a bicriterion formulation
   of the problems of integrated system identification and system
   optimization", IEEE Trans. SMC 1(3):296-297, 1971 (epsilon-constraint).
.. [2] E. Zitzler, L. Thiele, "Multiobjective evolutionary algorithms: a
   comparative case study and the strength Pareto approach", IEEE Trans. EC
   3(4):257-271, 1999 (hypervolume).
"""

from __future__ import annotations

import numpy as np


def nondominated(points: np.ndarray) -> np.ndarray:
    """Mask of the points no other point dominates (both objectives minimised).

    Parameters
    ----------
    points : array of shape (n, 2)
        Objective values (f1, f2) [any units].

    Returns
    -------
    ndarray of bool, shape (n,)
        True where no other point is at least as good in both objectives and
        better in one; equal points are all kept.
    """
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    le = (p[None, :, 0] <= p[:, None, 0]) & (p[None, :, 1] <= p[:, None, 1])
    lt = (p[None, :, 0] < p[:, None, 0]) | (p[None, :, 1] < p[:, None, 1])
    return ~np.any(le & lt, axis=1)


def hypervolume_2d(points: np.ndarray, ref: tuple[float, float]) -> float:
    """Hypervolume (area) dominated by a set of 2-D points, both objectives minimised.

    The area of the union of the boxes ``[f1, r1] x [f2, r2]`` over the points
    that dominate the reference point ``r``; exact (sweep over f1) [2].

    Parameters
    ----------
    points : array of shape (n, 2)
        Objective values (f1, f2) [unit1, unit2]; non-finite rows are ignored.
    ref : (float, float)
        Reference point (r1, r2) [unit1, unit2].

    Returns
    -------
    float
        The dominated area [unit1 x unit2]; 0 if no point dominates ``ref``.
    """
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    p = p[np.all(np.isfinite(p), axis=1) & (p[:, 0] < ref[0]) & (p[:, 1] < ref[1])]
    if p.size == 0:
        return 0.0
    p = p[np.lexsort((p[:, 1], p[:, 0]))]
    area, best_f2 = 0.0, float(ref[1])
    for f1, f2 in p:  # f1 ascending: each new best f2 adds a strip of width ref1 - f1
        if f2 < best_f2:
            area += (ref[0] - f1) * (best_f2 - f2)
            best_f2 = f2
    return float(area)


def arc_length_epsilons(x_top: float, y_top: float, x_bot: float, y_bot: float,
                        points: int) -> np.ndarray:
    """Epsilon values from ``x_top`` down to ``x_bot``, equally spaced along the front's
    normalised arc length, the front modelled as ``y = a + b / x`` through its two ends.

    Equal steps in x crowd the flat part of a front shaped like 1/x and leave
    big steps on the steep part; equal arc length in normalised objective space
    spreads the points evenly along the curve (a larger hypervolume for the
    same number of solves of an epsilon-constraint sweep [1]). Falls back to
    equal steps in x if the ends do not describe a falling front.

    Parameters
    ----------
    x_top, y_top : float
        The end with the loosest constraint: epsilon [unit of x] and its optimal
        objective [unit of y].
    x_bot, y_bot : float
        The end with the tightest constraint [unit of x], [unit of y].
    points : int
        Number of epsilon values.

    Returns
    -------
    ndarray of shape (points,)
        Epsilon values [unit of x], from ``x_top`` down to ``x_bot`` (both exact).
    """
    if not (x_top > x_bot > 0 and y_bot > y_top):
        return np.linspace(x_top, x_bot, points)
    b = (y_bot - y_top) / (1.0 / x_bot - 1.0 / x_top)
    x = np.linspace(x_bot, x_top, 4001)
    y = y_top + b * (1.0 / x - 1.0 / x_top)
    xn = (x - x_bot) / (x_top - x_bot)
    yn = (y - y_top) / (y_bot - y_top)
    s = np.r_[0.0, np.cumsum(np.hypot(np.diff(xn), np.diff(yn)))]
    eps = np.interp(np.linspace(0.0, s[-1], points), s, x)[::-1]
    eps[0], eps[-1] = x_top, x_bot
    return eps


__all__ = ["nondominated", "hypervolume_2d", "arc_length_epsilons"]
