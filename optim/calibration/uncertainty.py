"""Stage 7 of the calibration: confidence intervals of the fitted parameters.

A delete-one-run jackknife [1] over the leave-one-run-out folds gives each
parameter's variance; the oil-free baseline's own error, shared by every oil
run of its T and so invisible to the jackknife, is propagated linearly and
added [2]; the interval uses Student's t with (runs - 1) degrees of freedom.

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

from oilgap.model.measured_data import Samples

from .baseline import BaselineFit
from .least_squares import BASE_PARAMS, BaseSpec, ModelFit


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
        Bounds (NaN with fewer than 3 folds).
    """
    g = folds.shape[0]
    if g < 3:
        return np.full_like(full, np.nan), np.full_like(full, np.nan)
    mean = folds.mean(axis=0)
    var = (g - 1) / g * np.sum((folds - mean) ** 2, axis=0)
    if extra_var is not None:
        var = var + extra_var
    t = stats.t.ppf(0.5 + level / 2, g - 1)
    return full - t * np.sqrt(var), full + t * np.sqrt(var)


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
        Variances of C (not ln C) [-], the other free parameters [-] and the
        effect coefficients (library unit squared).
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
    if "C" in spec.free:  # ln C -> C
        i = spec.free.index("C")
        var[i] *= spec.law(fit.x).C ** 2
    var[q:] /= fit.scale ** 2
    return var


def parameter_ci(spec: BaseSpec, fit: ModelFit, folds: list[ModelFit], s: Samples,
                 baselines: dict[float, BaselineFit]) -> dict:
    """95 % interval of each Eq. 8 parameter ("fixed" if not fitted).

    Parameters
    ----------
    spec : BaseSpec
    fit : ModelFit
        All-runs fit.
    folds : list of ModelFit
        Fit without each run.
    s : Samples
    baselines : dict
        T -> BaselineFit.

    Returns
    -------
    dict
        C, alpha, beta, gamma -> [lo, hi] [-] or "fixed".
    """
    vals = spec.values(fit.x)
    full = np.array([vals[k] for k in spec.free])
    fv = np.array([[spec.values(f.x)[k] for k in spec.free] for f in folds])
    extra = baseline_variance(fit, spec, s, baselines)[:len(spec.free)]
    lo, hi = jackknife_ci(full, fv, extra)
    return {k: ([float(lo[spec.free.index(k)]), float(hi[spec.free.index(k)])]
                if k in spec.free else "fixed") for k in BASE_PARAMS}


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
