"""The Couette floor in the plan: where it binds, and the scale's interval across it.

The loop's forward model never takes a region's laminar loss below exact Couette flow
(issue 27 item 4; :func:`oilgap.model.taylor_couette.couette_floor_applies`): region r
of a sample gives ``max(s P_r, P_c,r) T^gamma`` with ``P_r`` its power at scale 1 and
``P_c,r`` the exact Couette power. In ln s the floor binds below the *kink*
``ln(P_c,r / P_r)``; there ``dP/d ln s = 0`` for that region. The plan's information
(:func:`~.fisher.base_jacobian`) is CasADi's derivative of that same ``fmax``, so it is
exact at the expansion point; but where the point sits just above a kink (the smooth
Eq. 6 lies only 0.09 % above Couette in a laminar annulus), the linearised interval
reaches past it, and below the kink the same data inform the scale much less.

:func:`floor_gaps` finds, per run, the distance in ln s from the expansion point down to
the first kink; the information below it is taken at ``ln s - gap - FLOOR_STEP`` (the
floored rows' scale column zero there, by the same AD). :func:`floored_half_width` then
carries the interval's quantile through the kink: the estimate is a monotone,
piecewise-linear function of the data's score in the scale direction, moving with sd
``sd_a`` above the kink and ``sd_b`` below it, so the quantile ``h = t sd_a`` below the
estimate maps to ``k + (h - k) sd_b / sd_a`` if it passes the kink at distance k [1].

References
----------
.. [1] F. Pukelsheim, *Optimal Design of Experiments*, Wiley 1993, ch. 3 (the linearised
   model); the quantile of a monotone transform of a normal estimate is the transform of
   its quantile (e.g. E. L. Lehmann, G. Casella, *Theory of Point Estimation*, 2nd ed.,
   Springer 1998, sec. 1.5).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from oilgap.model.taylor_couette import couette_floor_form
from oilgap.optim.calibration.forward import COUETTE_ONLY, ForwardModel
from oilgap.optim.calibration.spec import BaseSpec

FLOOR_STEP = 1e-4
"""How far below a kink [ln scale] the information below the floor is taken (clear of
the ``fmax`` tie at the kink itself) [-]."""


def floor_gaps(model: ForwardModel, spec: BaseSpec, x: np.ndarray) -> np.ndarray:
    """Per run, the distance in ln scale from ``x`` down to the first kink of the floor.

    Parameters
    ----------
    model : ForwardModel
        The runs' samples.
    spec : BaseSpec
        The base law (floored only for a scale form with the Couette laminar law).
    x : array
        Expansion point in the solver's unknowns (ln scale, gamma, ...) [-].

    Returns
    -------
    array, shape (runs,)
        ``ln s - max{kink < ln s}`` over the run's samples and regions [-]; inf where no
        region of the run has a kink below the point (or the law has no floor).
    """
    runs = len(model.runs)
    law = spec.law(x)
    if "scale" not in spec.free or not couette_floor_form(law):
        return np.full(runs, math.inf)
    ln_s = float(x[spec.free.index("scale")])
    n = model.samples.n
    unit = replace(law, scale=1.0, gamma=0.0)  # a numeric scale of 1: nothing floored
    below = np.full(n, -math.inf)
    # the forward model's own (kept) region powers: the law at scale 1, exact Couette
    for p, c in zip(model.region_powers(unit), model.region_powers(COUETTE_ONLY), strict=True):
        ok = (p > 0) & (c > 0)
        kink = np.full(n, -math.inf)
        kink[ok] = np.log(c[ok] / p[ok])
        below = np.maximum(below, np.where(kink < ln_s, kink, -math.inf))
    return np.array([ln_s - below[idx].max() for idx in model.runs])


def below_floor(x: np.ndarray, spec: BaseSpec, gaps: np.ndarray, run_code: np.ndarray
                ) -> np.ndarray:
    """Per sample, the expansion point moved just below its run's first kink.

    Parameters
    ----------
    x : array
        Expansion point (ln scale, gamma, ...) [-].
    spec : BaseSpec
    gaps : array, shape (runs,)
        :func:`floor_gaps` [-].
    run_code : array of int, shape (n,)
        Run index of each sample.

    Returns
    -------
    array, shape (n, q)
        The point per sample; runs without a kink keep ``x`` [-].
    """
    out = np.repeat(np.asarray(x, float)[None, :], len(run_code), axis=0)
    if "scale" in spec.free:
        g = gaps[run_code]
        step = np.where(np.isfinite(g), g + FLOOR_STEP, 0.0)
        out[:, spec.free.index("scale")] -= step
    return out


def floored_half_width(h: float, gap: float, sd_above: float, sd_below: float) -> float:
    """Lower half-width of the scale's interval [ln scale] carried through the floor.

    Parameters
    ----------
    h : float
        Half-width of the linearised interval, ``t sd_above`` [-].
    gap : float
        Distance from the estimate down to the first kink [-] (inf: none).
    sd_above, sd_below : float
        Sd of the estimate with the information above and below the kink [-].

    Returns
    -------
    float
        ``h`` if the interval stays above the kink, else ``gap + (h - gap) sd_below /
        sd_above`` [-] (inf where the data cannot tell the scale below the kink).
    """
    if not (math.isfinite(h) and h > gap):
        return h
    if not math.isfinite(sd_below) or not sd_above > 0:
        return math.inf
    return gap + (h - gap) * sd_below / sd_above
