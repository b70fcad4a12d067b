"""Stage 4 of the calibration: the structure of a residual.

The white-noise level from successive differences within runs (von Neumann's
mean square successive difference [1]), the share of the residual above it,
binned means and correlation ratios against the operating variables, and the
within-run autocorrelation.

References
----------
.. [1] J. von Neumann, "Distribution of the ratio of the mean square successive
   difference to the variance", Ann. Math. Stat. 12:367-395, 1941.
.. [2] K. Pearson, "On the general theory of skew correlation and non-linear
   regression", Drapers' Company Research Memoirs, Biometric Series II, 1905
   (the correlation ratio eta^2).
.. [3] G. E. P. Box, G. M. Jenkins, G. C. Reinsel, *Time Series Analysis*, 4th
   ed., Wiley 2008, sec. 2.1 (sample autocorrelation).
"""

from __future__ import annotations

import math

import numpy as np

from oilgap.model.measured.data import Samples
from oilgap.model.units import m2_s_to_cst

STRUCTURE_FRACTION = 0.2
"""Residual with more than this share of its variance above the noise is 'structured'."""
RESIDUAL_VARIABLES = ("speed_rpm", "abs_speed_rpm", "accel_rad_s2", "temp_C", "nu_cSt",
                      "time_s")
"""Variables the residual is binned against."""
ACF_LAGS = (1, 2, 5, 10, 25, 50)
"""Lags [samples] of the reported autocorrelation."""


def noise_estimate(res: np.ndarray, run_code: np.ndarray) -> float:
    """White-noise level [W] from successive differences within runs [1].

    ``sigma^2 = sum (r_k+1 - r_k)^2 / (2 (n - runs))``: for white noise each
    difference has variance 2 sigma^2; a slowly varying structure hardly
    contributes.

    Parameters
    ----------
    res : array
        Residual per sample [W], runs contiguous.
    run_code : array of int
        Run of each sample.

    Returns
    -------
    float
        Noise standard deviation [W].
    """
    same = run_code[1:] == run_code[:-1]
    d = np.diff(res)[same]
    return float(np.sqrt(np.sum(d * d) / (2.0 * max(1, len(d)))))


def autocorrelation(res: np.ndarray, run_code: np.ndarray, lag: int) -> float:
    """Pooled within-run autocorrelation of a residual at ``lag`` samples [-] [3].

    Each run's residual is centred on its own mean; lagged products and squares
    are summed over runs.

    Parameters
    ----------
    res : array
        Residual per sample [W].
    run_code : array of int
        Run of each sample.
    lag : int
        Lag [samples] >= 1.

    Returns
    -------
    float
        ``sum r_k r_k+lag / sum r_k^2`` (0 for a zero residual) [-].
    """
    order = np.argsort(run_code, kind="stable")       # each run's samples contiguous, in order
    code = np.asarray(run_code)[order]
    cnt = np.bincount(code)
    r = res[order] - (np.bincount(code, weights=res[order]) / np.maximum(cnt, 1))[code]
    den = float(r @ r)
    same = code[lag:] == code[:-lag]
    num = float(r[lag:][same] @ r[:-lag][same]) if len(r) > lag else 0.0
    return num / den if den > 0 else 0.0


def _binned(res: np.ndarray, v: np.ndarray, vres: float, bins: int) -> dict:
    """Pearson r, eta^2, bin centres and bin means of ``res`` against ``v``."""
    edges = np.unique(np.quantile(v, np.linspace(0, 1, bins + 1)))
    idx = np.clip(np.searchsorted(edges, v, side="right") - 1, 0, len(edges) - 2) \
        if len(edges) > 1 else np.zeros(len(v), int)
    nb = int(idx.max()) + 1
    cnt = np.bincount(idx, minlength=nb)
    mean = np.bincount(idx, weights=res, minlength=nb) / np.maximum(cnt, 1)
    cen = np.bincount(idx, weights=v, minlength=nb) / np.maximum(cnt, 1)
    eta2 = float(np.sum(cnt * (mean - res.mean()) ** 2) / (len(res) * vres)) if vres > 0 \
        else 0.0
    r = float(np.corrcoef(v, res)[0, 1]) if np.std(v) > 0 and np.std(res) > 0 else 0.0
    return {"pearson_r": r, "eta2": eta2, "bin_centres": cen.tolist(),
            "bin_means_W": mean.tolist()}


def residual_structure(res: np.ndarray, s: Samples, bins: int = 12) -> dict:
    """Structure of a residual [W]: noise, share above noise, binned means, ACF.

    For each variable in :data:`RESIDUAL_VARIABLES`: Pearson r, the correlation
    ratio eta^2 [2] (share of the residual variance explained by the means of
    ``bins`` quantile bins) and the bin centres and means.

    Parameters
    ----------
    res : array
        Residual per sample [W].
    s : Samples
        The samples (speed [rpm], acceleration [rad/s^2], temperature [degC],
        viscosity [m^2/s], time [s], runs).
    bins : int
        Number of quantile bins.

    Returns
    -------
    dict
        ``rmse_W``, ``noise_W`` (:func:`noise_estimate`), ``structured_rms_W``,
        ``structured_fraction`` [-], ``autocorrelation`` (lag -> [-]) and
        ``variables`` (name -> pearson_r, eta2, bin_centres, bin_means_W).
    """
    mse = float(np.mean(res * res))
    sig = noise_estimate(res, s.run_code)
    var = {"speed_rpm": s.speed_rpm, "abs_speed_rpm": np.abs(s.speed_rpm),
           "accel_rad_s2": s.domega_dt, "temp_C": s.temp_C, "nu_cSt": m2_s_to_cst(s.nu_m2_s),
           "time_s": s.time_s}
    vres = float(np.var(res))
    out_vars = {name: _binned(res, v, vres, bins) for name, v in var.items()}
    frac = max(0.0, 1.0 - sig * sig / mse) if mse > 0 else 0.0
    return {"rmse_W": math.sqrt(mse), "noise_W": sig,
            "structured_rms_W": math.sqrt(max(0.0, mse - sig * sig)),
            "structured_fraction": frac,
            "autocorrelation": {str(k): autocorrelation(res, s.run_code, k) for k in ACF_LAGS},
            "variables": out_vars}


def describe_structure(rs: dict) -> str:
    """One sentence on what a structured residual correlates with.

    Parameters
    ----------
    rs : dict
        From :func:`residual_structure`.

    Returns
    -------
    str
        RMS above the noise [W], its share of the variance [%], lag-1
        autocorrelation [-] and the (up to three) variables with eta^2 >= 0.02.
    """
    vs = sorted(rs["variables"].items(), key=lambda kv: -kv[1]["eta2"])
    parts = [f"{k} (eta^2 = {v['eta2']:.2f}, r = {v['pearson_r']:+.2f})" for k, v in vs[:3]
             if v["eta2"] >= 0.02]
    corr = "; correlates with " + ", ".join(parts) if parts else \
        "; no single variable explains it (eta^2 < 0.02 for all)"
    return (f"{rs['structured_rms_W']:.3g} W RMS above the noise ({rs['noise_W']:.3g} W), "
            f"{100 * rs['structured_fraction']:.0f} % of the residual variance, lag-1 "
            f"autocorrelation {rs['autocorrelation']['1']:.2f}{corr}")


def unexplained_structure(rs: dict, threshold: float = STRUCTURE_FRACTION) -> dict | None:
    """Report of the structure left after the final model, or None below ``threshold``.

    Parameters
    ----------
    rs : dict
        :func:`residual_structure` of the final model's residual.
    threshold : float
        Share of the residual variance above the noise [-] that counts as structure.

    Returns
    -------
    dict or None
        Description, structured RMS [W], noise [W], structured fraction [-],
        variables sorted by eta^2 (with Pearson r) and the lag-1 autocorrelation [-].
    """
    if rs["structured_fraction"] < threshold:
        return None
    return {
        "description": "structure no library effect explains: " + describe_structure(rs),
        "structured_rms_W": rs["structured_rms_W"], "noise_W": rs["noise_W"],
        "structured_fraction": rs["structured_fraction"],
        "correlates_with": sorted(
            ({"variable": k, "eta2": v["eta2"], "pearson_r": v["pearson_r"]}
             for k, v in rs["variables"].items()), key=lambda d: -d["eta2"]),
        "autocorrelation_lag1": rs["autocorrelation"]["1"]}
