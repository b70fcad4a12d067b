"""Stage 7 of the calibration: confidence intervals of the fitted parameters.

A delete-a-group jackknife [1] over the cross-validation folds (one per run up to
10 runs, grouped 10-fold above: :mod:`.folds`) gives each parameter's variance;
the oil-free baseline's own error, shared by every oil run of its T and so
invisible to the jackknife, is propagated linearly and added [2]; the interval
uses Student's t with (folds - 1) degrees of freedom.
Parameters that must be positive (C, the scale) get their interval in log space
(jackknife of ln C, then exponentiated: the interval never includes zero or
negative values). A parameter some folds could not identify (held at its
prior there) gets its interval from the other folds only, and none
with fewer than 3. A parameter every fold returns at exactly the same value
(pinned on a bound of the solver's box, or nothing in the data moves it) with
no baseline variance gets no interval either: a zero-width "95 % interval"
would claim a certainty the data do not give (it is not identifiable).

References
----------
.. [1] B. Efron, C. Stein, "The jackknife estimate of variance", Ann. Stat.
   9:586-596, 1981 (delete-one-group jackknife).
.. [2] JCGM 100:2008, *Evaluation of measurement data - Guide to the
   expression of uncertainty in measurement*, sec. 5.1 (law of propagation).
"""

from __future__ import annotations

import numpy as np
from scipy import stats

from oilgap.model.measured.data import Samples

from .baseline import BaselineFit
from .least_squares import BaseSpec, ModelFit
from .spec import LOG_PARAMS


def jackknife_ci(full: np.ndarray, folds: np.ndarray, extra_var: np.ndarray | None = None,
                 level: float = 0.95) -> tuple[np.ndarray, np.ndarray]:
    """Delete-one-run jackknife interval [1], variance widened by ``extra_var``.

    ``var = (g - 1)/g sum_i (theta_i - mean)^2`` over the g folds; interval
    ``full -+ t_{(1+level)/2, g-1} sqrt(var + extra_var)``.

    Parameters
    ----------
    full : array, shape (p,)
        All-runs estimate (any unit).
    folds : array, shape (g, p)
        Estimate without each run (same unit).
    extra_var : array, shape (p,), optional
        Variance added (unit squared).
    level : float
        Confidence level [-].

    Returns
    -------
    (lo, hi) : arrays, shape (p,)
        Bounds (NaN with fewer than 3 folds, and where the variance is zero: not
        identifiable, never a zero-width interval).
    """
    g = folds.shape[0]
    if g < 3:
        return np.full_like(full, np.nan), np.full_like(full, np.nan)
    mean = folds.mean(axis=0)
    var = (g - 1) / g * np.sum((folds - mean) ** 2, axis=0)
    if extra_var is not None:
        var = var + extra_var
    t = stats.t.ppf(0.5 + level / 2, g - 1)
    half = np.where(var > 0, t * np.sqrt(np.maximum(var, 0.0)), np.nan)
    return full - half, full + half


def baseline_variance(fit: ModelFit, spec: BaseSpec, s: Samples,
                      baselines: dict[float, BaselineFit]) -> np.ndarray:
    """Variance of (free Eq. 8 parameters, effect coefficients) due to the baseline's error.

    The oil-free baseline is estimated once per T and taken away from every oil
    run of that T, so its error is shared by those runs and a jackknife over
    runs cannot see it. Linear propagation [2]: ``dz = J^+ dy``, ``dy = -X_T dc_T``,
    Cov(dc_T) from the baseline's least squares.

    Parameters
    ----------
    fit : ModelFit
        All-runs fit with its Jacobian.
    spec : BaseSpec
    s : Samples
        Oil-run samples.
    baselines : dict
        T -> BaselineFit (empty for viscous-power data).

    Returns
    -------
    array
        Variances of C or the scale (not their logarithms) [-], the other free
        parameters [-] and the effect coefficients (library unit squared).
    """
    p = fit.jac.shape[1] if fit.jac is not None else 0
    if not baselines or fit.jac is None:
        return np.zeros(p)
    A = np.linalg.pinv(fit.jac)
    cov = np.zeros((p, p))
    for T, b in baselines.items():
        rows = s.roughness_T == T
        if b.cov is None or not rows.any():
            continue
        B = A[:, rows] @ b.design(s.omega[rows], s.domega_dt[rows], s.temp_C[rows])
        cov += B @ b.cov @ B.T
    var = np.diag(cov).copy()
    q = len(spec.free)
    vals = spec.values(fit.x)
    for i, k in enumerate(spec.free):  # ln C -> C, ln scale -> scale
        if k in LOG_PARAMS:
            var[i] *= vals[k] ** 2
    var[q:] /= fit.scale ** 2
    return var


def parameter_ci(spec: BaseSpec, fit: ModelFit, folds: list[ModelFit], s: Samples,
                 baselines: dict[float, BaselineFit],
                 held: list[tuple[str, ...]] | None = None) -> dict:
    """95 % interval of each base parameter ("fixed" if not fitted).

    C and the scale are handled as ln C and ln scale (the solver's unknowns): the
    jackknife and the baseline's variance (``var(C) / C^2``) in log space, the
    bounds exponentiated [1], [2].

    Parameters
    ----------
    spec : BaseSpec
    fit : ModelFit
        All-data fit.
    folds : list of ModelFit
        Fit without each group.
    s : Samples
    baselines : dict
        T -> BaselineFit.
    held : list of tuple of str, optional
        Per fold, the parameters it held at their prior (left out of
        that parameter's jackknife).

    Returns
    -------
    dict
        Parameter -> [lo, hi] [-] (NaN bounds: no interval), or "fixed".
    """
    vals = spec.values(fit.x)
    extra = baseline_variance(fit, spec, s, baselines)[:len(spec.free)]
    held = held or [()] * len(folds)
    out = {}
    for i, k in enumerate(spec.free):
        log = k in LOG_PARAMS
        ev = extra[i] / vals[k] ** 2 if log else extra[i]
        fv = np.array([[f.x[i]] for f, h in zip(folds, held, strict=True) if k not in h])
        full = np.array([fit.x[i]])
        lo, hi = jackknife_ci(full, fv, np.array([ev])) if len(fv) else (full * np.nan,) * 2
        lo, hi = (np.exp(lo), np.exp(hi)) if log else (lo, hi)
        out[k] = [float(lo[0]), float(hi[0])]
    return {k: out.get(k, "fixed") for k in spec.params}


def effect_ci(spec: BaseSpec, fit: ModelFit, folds: list[ModelFit], s: Samples,
              baselines: dict[float, BaselineFit]) -> tuple[np.ndarray, np.ndarray]:
    """95 % interval [unit of each coefficient] of each effect coefficient of ``fit``.

    Parameters
    ----------
    spec : BaseSpec
    fit : ModelFit
        All-runs fit with effects ``fit.names``.
    folds : list of ModelFit
        Fit without each run.
    s : Samples
    baselines : dict
        T -> BaselineFit.

    Returns
    -------
    (lo, hi) : arrays
        Bounds in the library's units, e.g. [N m] or [s] (empty without effects).
    """
    if not fit.names:
        return np.zeros(0), np.zeros(0)
    extra = baseline_variance(fit, spec, s, baselines)[len(spec.free):]
    return jackknife_ci(fit.theta, np.array([f.theta for f in folds]), extra)
