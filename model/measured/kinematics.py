"""Speed and temperature rates of measured runs: d(omega)/dt and dT/dt per run.

A uniform record is differentiated by a quadratic Savitzky-Golay filter [1]
(window in seconds, so the same smoothing at any sampling rate), a non-uniform
one by central differences. Long windows (a rig logging at 1 kHz has 1001- and
3001-sample windows) are applied as an FFT convolution with the filter's own
coefficients (overlap-add [2]), the ends by the filter itself: the result is the
filter's to rounding (1e-14 relative) in time linear in the samples.

Steady-point data (no ``time_s``) have no rates: both are zero.

References
----------
.. [1] A. Savitzky, M. J. E. Golay, "Smoothing and differentiation of data by
   simplified least squares procedures", Anal. Chem. 36:1627-1639, 1964.
.. [2] A. V. Oppenheim, R. W. Schafer, *Discrete-Time Signal Processing*, 3rd
   ed., Pearson 2010, sec. 8.7.3 (overlap-add).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from scipy.signal import oaconvolve, savgol_coeffs, savgol_filter

from ..units import rpm_to_rad_s

SPEED_DERIVATIVE_WINDOW_S = 1.0
"""Savitzky-Golay window [s] for d(omega)/dt (quadratic, at least 5 samples)."""
TEMP_DERIVATIVE_WINDOW_S = 3.0
"""Savitzky-Golay window [s] for dT/dt."""
DIRECT_WINDOW_MAX = 64
"""Windows up to this many samples are filtered directly, longer ones by FFT convolution."""


def _savgol_slope(x: np.ndarray, win: int, h: float) -> np.ndarray:
    """Quadratic Savitzky-Golay first derivative, ``mode="interp"`` [1], [2]."""
    if win <= DIRECT_WINDOW_MAX:
        return savgol_filter(x, win, 2, deriv=1, delta=h, mode="interp")
    out = oaconvolve(x, savgol_coeffs(win, 2, deriv=1, delta=h, use="conv"), mode="same")
    m = win // 2  # the ends: the filter's polynomial fit to the first and last window
    out[:m] = savgol_filter(x[:win], win, 2, deriv=1, delta=h, mode="interp")[:m]
    out[-m:] = savgol_filter(x[-win:], win, 2, deriv=1, delta=h, mode="interp")[-m:]
    return out


def time_derivative(time_s: np.ndarray, x: np.ndarray, window_s: float) -> np.ndarray:
    """d x / d t of one run [unit of x per s]: Savitzky-Golay (quadratic) on a uniform
    record, central differences otherwise.

    Parameters
    ----------
    time_s : ndarray
        Sample times of one run [s], increasing.
    x : ndarray
        The signal [any unit].
    window_s : float
        Savitzky-Golay window [s] (odd number of samples, at least 5).

    Returns
    -------
    ndarray
        Derivative [unit of x per s] (zeros for fewer than 3 samples).

    References
    ----------
    A. Savitzky, M. J. E. Golay, Anal. Chem. 36:1627, 1964.
    """
    t = np.asarray(time_s, dtype=float)
    x = np.asarray(x, dtype=float)
    if len(t) < 3:
        return np.zeros_like(x)
    dt = np.diff(t)
    h = float(np.median(dt))
    win = int(round(window_s / h)) // 2 * 2 + 1
    win = max(win, 5)
    if len(t) >= win and np.all(np.abs(dt - h) <= 0.05 * h):
        return _savgol_slope(x, win, h)
    return np.gradient(x, t)


def run_slices(run_code: np.ndarray) -> list[slice]:
    """Contiguous blocks of equal run codes (the runs of a frame sorted by run).

    Parameters
    ----------
    run_code : ndarray of int
        Run of each row [-], each run's rows contiguous.

    Returns
    -------
    list of slice
        One slice per block, in row order.
    """
    rc = np.asarray(run_code)
    if len(rc) == 0:
        return []
    cuts = np.flatnonzero(rc[1:] != rc[:-1]) + 1
    starts = np.concatenate([[0], cuts])
    ends = np.concatenate([cuts, [len(rc)]])
    return [slice(int(a), int(b)) for a, b in zip(starts, ends, strict=True)]


def add_kinematics(frame: pd.DataFrame, has_time: bool = True) -> pd.DataFrame:
    """Columns ``omega`` [rad/s], ``domega_dt`` [rad/s^2], ``dtemp_dt`` [K/s] per run.

    Parameters
    ----------
    frame : pandas.DataFrame
        Validated samples sorted by run (``run``, ``time_s`` [s], ``speed_rpm`` [rpm],
        ``temp_C`` [degC]; ``run_code`` if at hand).
    has_time : bool
        False for steady operating points: both rates are zero.

    Returns
    -------
    pandas.DataFrame
        A shallow copy with the three columns added (:func:`time_derivative` per run).
    """
    f = frame.copy(deep=False)
    f["omega"] = rpm_to_rad_s(f["speed_rpm"].to_numpy(dtype=float))
    a = np.zeros(len(f))
    dT = np.zeros(len(f))
    if has_time and len(f):
        code = f["run_code"].to_numpy() if "run_code" in f.columns else \
            pd.factorize(f["run"].to_numpy())[0]
        t = f["time_s"].to_numpy(dtype=float)
        w = f["omega"].to_numpy()
        temp = f["temp_C"].to_numpy(dtype=float)
        order = np.argsort(code, kind="stable")  # the identity for a frame sorted by run
        for sl in run_slices(code[order]):
            idx = order[sl]
            a[idx] = time_derivative(t[idx], w[idx], SPEED_DERIVATIVE_WINDOW_S)
            dT[idx] = time_derivative(t[idx], temp[idx], TEMP_DERIVATIVE_WINDOW_S)
    f["domega_dt"] = a
    f["dtemp_dt"] = dT
    return f
