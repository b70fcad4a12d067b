"""Which branches of Eq. 6 a data set identifies: the rules of the ``"branches"`` base.

A sample belongs to the branch of Bilgen & Boulos's correlation (seed Eq. 6) that is
largest there; a branch's level C_k, gap exponent alpha_k and Reynolds exponent beta_k
are fitted only where its samples can tell them apart (:func:`branch_identifiability`),
the rest held at the published values. Used by :mod:`.spec` (the base's free
parameters) and the validation against Wendt's air data.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 6-7.
.. [2] E. Bilgen, R. Boulos, ASME J. Fluids Eng. 95(1):122-126, 1973.
"""

from __future__ import annotations

import math

import numpy as np

from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.taylor_couette import couette_moment_coefficient

BRANCH_MIN_SAMPLES = 3
"""Samples a branch must govern (be the largest at) for its C_k to be fitted."""

BRANCH_MIN_GAPS = 2
"""Distinct gap ratios among a branch's samples for its alpha_k to be fitted (3 or more
give a check of the power in delta/R; 2 determine it)."""

BRANCH_MIN_LN_GAP_SPAN = 0.1
"""... and their spread ln(x_max / x_min) [-] (10 %): closer gaps cannot separate
alpha_k from the scatter."""

BRANCH_MIN_LN_RE_OVERLAP = 0.2
"""... and they must share a Reynolds range: two gaps count for alpha_k only where their
spans of ln Re inside the regime overlap by this much [-] (a factor 1.22); gaps met at
different Re alone confound alpha_k with beta_k."""

BRANCH_MIN_LN_RE_SPAN = 0.5
"""Span of ln Re [-] (a factor 1.65) a branch's samples must cover at one gap ratio for
its beta_k to be fitted: the speed range inside the regime, not across gaps, where
alpha_k and beta_k would be confounded."""


def branch_regimes(reynolds, gap_ratio, law: FrictionLaw) -> np.ndarray:
    """Index of the branch that governs each sample under ``law`` (form ``"branches"``).

    Parameters
    ----------
    reynolds : array
        Couette Reynolds number [-] (> 0).
    gap_ratio : array
        delta / R [-].
    law : FrictionLaw
        Its branch_C, branch_alpha, branch_beta [-] and laminar law.

    Returns
    -------
    array of int
        k (0-based) of the largest branch ``C_k x^alpha_k Re^beta_k`` [2]; -1 where the
        laminar Couette bound is above every branch (laminar law ``"couette"``).
    """
    re = np.atleast_1d(np.asarray(reynolds, float))
    lnx = np.log(np.broadcast_to(np.asarray(gap_ratio, float), re.shape))
    lnre = np.log(np.maximum(re, 1e-12))
    terms = np.column_stack([math.log(c) + a * lnx + b * lnre for c, a, b in zip(
        law.branch_C, law.branch_alpha, law.branch_beta, strict=True)])
    k = np.argmax(terms, axis=1)
    if law.laminar_law == "couette":
        lnc = np.log(couette_moment_coefficient(np.maximum(re, 1e-12), np.exp(lnx)))
        k = np.where(lnc > terms.max(axis=1), -1, k)
    return k


def branch_identifiability(reynolds, gap_ratio, law: FrictionLaw) -> dict[str, tuple]:
    """Which C_k, alpha_k, beta_k of a ``"branches"`` law samples identify, and why.

    A sample belongs to the branch that is largest there under ``law`` (the
    published branches of Eq. 6 by default). C_k needs
    :data:`BRANCH_MIN_SAMPLES` samples of branch k; alpha_k needs
    :data:`BRANCH_MIN_GAPS` distinct gap ratios among them spread by
    :data:`BRANCH_MIN_LN_GAP_SPAN` whose Re ranges in the regime overlap by
    :data:`BRANCH_MIN_LN_RE_OVERLAP`; beta_k needs a span of ln Re of
    :data:`BRANCH_MIN_LN_RE_SPAN` inside the regime at one gap ratio. The others
    stay at their values in ``law``.

    Parameters
    ----------
    reynolds : array
        Couette Reynolds number of each sample [-].
    gap_ratio : array
        delta / R of each sample [-].
    law : FrictionLaw
        The law whose branches the samples are assigned to [-].

    Returns
    -------
    dict
        ``"C1"``, ``"alpha1"``, ``"beta1"``, ... (1-based) -> (free, statement).

    References
    ----------
    Bilgen & Boulos [2] (the branches); seed paper [1] (Eq. 7).
    """
    re = np.atleast_1d(np.asarray(reynolds, float))
    x = np.broadcast_to(np.asarray(gap_ratio, float), re.shape)
    ok = np.isfinite(re) & (re > 0) & np.isfinite(x) & (x > 0)
    k_of = np.where(ok, branch_regimes(np.where(ok, re, 1.0), np.where(ok, x, 1.0), law), -2)
    out = {}
    for k, (c, a, b) in enumerate(zip(law.branch_C, law.branch_alpha, law.branch_beta,
                                      strict=True)):
        n = k + 1
        sel = k_of == k
        xs, rs = x[sel], re[sel]
        gaps = distinct_values(xs, 6)
        if sel.sum() < BRANCH_MIN_SAMPLES:
            why = (f"branch {n} governs {int(sel.sum())} sample(s) (< {BRANCH_MIN_SAMPLES})")
            for name, v in (("C", c), ("alpha", a), ("beta", b)):
                out[f"{name}{n}"] = (False, f"not identifiable: {why}; held at {v:g}")
            continue
        out[f"C{n}"] = (True, f"identified: the level of branch {n} ({int(sel.sum())} samples, "
                              f"Re {rs.min():.3g}..{rs.max():.3g})")
        lnre = {g: np.log(rs[np.round(xs, 6) == g]) for g in gaps}
        shared = _overlapping_gaps(lnre)
        span_x = math.log(max(shared) / min(shared)) if shared else 0.0
        if len(shared) >= BRANCH_MIN_GAPS and span_x >= BRANCH_MIN_LN_GAP_SPAN:
            out[f"alpha{n}"] = (True, f"identified from {len(shared)} gap ratios "
                                      f"{min(shared):.4g}..{max(shared):.4g} at a shared Re "
                                      f"range in branch {n}" + (
                                          " (only 2: no check of the power law in delta/R)"
                                          if len(shared) == 2 else ""))
        else:
            out[f"alpha{n}"] = (False, f"not identifiable: branch {n}'s samples have "
                                       f"{len(gaps)} gap ratio(s), {len(shared)} of them at a "
                                       f"shared Re range (overlap >= "
                                       f"{BRANCH_MIN_LN_RE_OVERLAP:g} in ln Re), spanning "
                                       f"{span_x:.2f} in ln(delta/R) (needs {BRANCH_MIN_GAPS} "
                                       f"spanning {BRANCH_MIN_LN_GAP_SPAN:g}); held at {a:g}")
        span_re = max(float(np.ptp(v)) for v in lnre.values())
        if span_re >= BRANCH_MIN_LN_RE_SPAN:
            out[f"beta{n}"] = (True, f"identified from a span of {span_re:.2f} in ln Re inside "
                                     f"branch {n} at one gap ratio")
        else:
            out[f"beta{n}"] = (False, f"not identifiable: branch {n}'s samples span {span_re:.2f}"
                                      f" in ln Re at any one gap ratio (needs "
                                      f"{BRANCH_MIN_LN_RE_SPAN:g}); held at {b:g}")
    return out



def distinct_values(a: np.ndarray, digits: int) -> list[float]:
    """The distinct values of ``a`` rounded to ``digits`` decimals, sorted.

    Parameters
    ----------
    a : array
        Values [any unit].
    digits : int
        Decimals kept before the values are compared [-].

    Returns
    -------
    list of float
        The distinct rounded values, ascending [the unit of ``a``].
    """
    return np.unique(np.round(np.asarray(a, float), digits)).tolist()


def _overlapping_gaps(lnre: dict) -> list[float]:
    """Gap ratios whose ln Re range overlaps another gap's by BRANCH_MIN_LN_RE_OVERLAP."""
    keep = set()
    gaps = list(lnre)
    for i, g in enumerate(gaps):
        for h in gaps[i + 1:]:
            lo = max(lnre[g].min(), lnre[h].min())
            hi = min(lnre[g].max(), lnre[h].max())
            if hi - lo >= BRANCH_MIN_LN_RE_OVERLAP:
                keep |= {g, h}
    return sorted(keep)
