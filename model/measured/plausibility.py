"""Plausibility of measured rig data: unit mistakes named before anything is fitted.

A rig file can be well formed and still wrong: temperatures in kelvin, speeds
scaled or in rad/s, power in kW or mW, time in ms. Each check looks at a whole
column (medians and peaks, never row by row) and says which mistake the numbers
look like. Where the data cannot be right for a joint of this kind (an oil at a
median of 299 degC, a shaft at 10^5 rpm, no rotation at all) the file is refused
with one :class:`~oilgap.model.errors.InputError` naming the column, exit 2; where
they might be right (a slow rig, a small motor) an
:class:`~oilgap.model.errors.OilgapWarning` names the likely mistake and the run
goes on.

A speed in rad/s cannot be told from a slow rig by the speed alone; the loop
compares the fitted level with the published law after the fit
(:func:`oilgap.studies.loop.report.unit_hints`).

References
----------
.. [1] ASTM D341 (Walther's viscosity law; oilgap trusts it over -20 ... 150 degC,
   :data:`oilgap.model.oil_properties.WALTHER_TRUSTED_RANGE_C`).
"""

from __future__ import annotations

import warnings

import numpy as np

from ..errors import InputError, OilgapWarning
from ..oil_properties import WALTHER_TRUSTED_RANGE_C
from ..units import ZERO_CELSIUS_K

TEMP_MEDIAN_MAX_C = WALTHER_TRUSTED_RANGE_C[1]
"""A median oil temperature above this [degC] is refused: no compensating oil runs a
test there, and the viscosity law is not trusted beyond it (150 degC)."""
TEMP_MEDIAN_WARN_C = 100.0
"""A median above this [degC] warns (a hot test, or degF)."""
KELVIN_LIKE_K = (200.0, 450.0)
"""A refused median within this range [K] is named as kelvin (-73 ... 177 degC)."""
SPEED_MAX_RPM = 1.0e5
"""Peak shaft speed above this [rpm] is refused: beyond the fastest high-speed
spindles, let alone a manipulator joint motor (the seed's 3000 rpm); a scaled
column (x100) or a count rate."""
SPEED_WARN_RPM = 2.0e4
"""Peak shaft speed above this [rpm] warns (x10?)."""
POWER_MAX_W = 1.0e5
"""Peak |power| above this [W] is refused (100 kW in a joint: mW or a scaled column)."""
POWER_WARN_W = 1.0e4
"""Peak |power| above this [W] warns."""
ELECTRIC_POWER_MIN_W = 0.5
"""Median electrical input ``power_W`` below this [W] while the shaft turns is refused: a
joint motor's own losses alone are watts (the seed rig's oil-free runs draw about 4 W):
kW instead of W."""
ELECTRIC_POWER_WARN_W = 1.0
"""... and below this [W] warns."""
TIME_STEP_WARN_S = 10.0
"""A median sample step above this [s] within runs warns (ms instead of s?) ..."""
RUN_WARN_S = 3600.0
"""... when a run is also longer than this [s] (a 300 s run in ms spans 83 h)."""
RUN_DURATION_MAX_S = 1.0e7
"""A run longer than this [s] (116 days) is refused: time_s is not in seconds."""


def _median(x: np.ndarray) -> float:
    f = x[np.isfinite(x)]
    return float(np.median(f)) if f.size else float("nan")


def _peak(x: np.ndarray) -> float:
    f = np.abs(x[np.isfinite(x)])
    return float(f.max()) if f.size else float("nan")


def _warn(message: str) -> None:
    warnings.warn(OilgapWarning(message), stacklevel=3)


def check_temperature(temp_C: np.ndarray, source: str) -> None:
    """Refuse a temperature column that is not in degC; warn when it may not be.

    Parameters
    ----------
    temp_C : ndarray
        ``temp_C`` of every row [degC as given] (NaN where missing).
    source : str
        Name used in messages.

    Raises
    ------
    InputError
        Median above :data:`TEMP_MEDIAN_MAX_C` (named as kelvin when it lies in
        :data:`KELVIN_LIKE_K`).
    """
    med = _median(temp_C)
    if not np.isfinite(med):
        return
    if med > TEMP_MEDIAN_MAX_C:
        lo, hi = KELVIN_LIKE_K
        hint = (f"looks like kelvin (subtract {ZERO_CELSIUS_K:g}: "
                f"{med - ZERO_CELSIUS_K:.1f} degC)" if lo <= med <= hi else
                "not an oil temperature in degC")
        raise InputError("temp_C median", round(med, 4), f"{hint}; oil temperatures in degC "
                         f"are required (a median above {TEMP_MEDIAN_MAX_C:g} degC is refused)",
                         source)
    if med > TEMP_MEDIAN_WARN_C:
        _warn(f"{source}: temp_C median {med:.1f} degC: a hot test for a compensating oil; "
              "if the column is in degF, convert it ((F - 32)/1.8)")


def check_speed(speed_rpm: np.ndarray, oil_rows: np.ndarray, purpose: str,
                source: str) -> None:
    """Refuse no rotation at all (fitting) or an impossible speed; warn at a high one.

    Parameters
    ----------
    speed_rpm : ndarray
        ``speed_rpm`` of every row [rpm as given] (NaN where missing).
    oil_rows : ndarray of bool
        Rows in oil (not oil-free), still kept.
    purpose : {"fit", "predict"}
        Fitting needs rotation in the oil rows.
    source : str
        Name used in messages.

    Raises
    ------
    InputError
        Every oil row at speed 0 (fitting), or a peak above :data:`SPEED_MAX_RPM`.
    """
    peak = _peak(speed_rpm)
    if np.isfinite(peak) and peak > SPEED_MAX_RPM:
        raise InputError("speed_rpm peak", float(f"{peak:.6g}"), "faster than any joint "
                         f"motor (at most {SPEED_MAX_RPM:g} rpm): a scaled column (x100?) or "
                         "counts instead of rpm", source)
    oil_speed = speed_rpm[oil_rows]
    oil_speed = oil_speed[np.isfinite(oil_speed)]
    if purpose == "fit" and oil_speed.size and not np.any(oil_speed != 0.0):
        raise InputError("speed_rpm", 0.0, "no rotation in the data: every oil row has speed "
                         "0, so there is no viscous loss to calibrate", source)
    if np.isfinite(peak) and peak > SPEED_WARN_RPM:
        _warn(f"{source}: speed_rpm peak {peak:.4g} rpm: unusually fast for a joint motor (the "
              "seed's 3000 rpm); check the column's unit (x10?)")


def check_power(power: np.ndarray, kind: str, speed_rpm: np.ndarray, oil_rows: np.ndarray,
                purpose: str, source: str) -> None:
    """Refuse an impossible power; warn at one that looks like kW or mW.

    Parameters
    ----------
    power : ndarray
        The power column of every row [W as given].
    kind : {"power_W", "viscous_power_W"}
        Which column it is.
    speed_rpm : ndarray
        ``speed_rpm`` of every row [rpm].
    oil_rows : ndarray of bool
        Rows in oil that are still kept (the electrical input is judged on them).
    purpose : {"fit", "predict"}
        Fitting needs a loss in the oil rows.
    source : str
        Name used in messages.

    Raises
    ------
    InputError
        Peak ``|power|`` above :data:`POWER_MAX_W`; a negative median power of the oil
        rows while the shaft turns (a loss is dissipated heat); a median electrical input below
        :data:`ELECTRIC_POWER_MIN_W` while the shaft turns; (fitting) a viscous power of
        exactly 0 in every oil row.
    """
    peak = _peak(power)
    if not np.isfinite(peak):
        return
    if peak > POWER_MAX_W:
        raise InputError(f"{kind} peak", float(f"{peak:.6g}"), f"above {POWER_MAX_W:g} W "
                         "for a joint: in mW, or a scaled column? give the power in W", source)
    if peak > POWER_WARN_W:
        _warn(f"{source}: {kind} peak {peak:.4g} W: large for a joint; if the column is in "
              "mW, divide by 1000")
    oil_p = power[oil_rows & np.isfinite(power)]
    if purpose == "fit" and kind == "viscous_power_W" and oil_p.size and not oil_p.any():
        raise InputError(kind, 0.0, "no viscous signal: the measured loss is 0 in every oil "
                         "row, so there is nothing to calibrate", source)
    turning = oil_rows & np.isfinite(speed_rpm) & (np.abs(speed_rpm) > 0) & np.isfinite(power)
    if turning.any() and _median(power[turning]) < 0:
        raise InputError(f"{kind} median", float(f"{_median(power[turning]):.6g}"),
                         "must be > 0 over the oil rows while the shaft turns: a viscous loss "
                         "(and a motor's input driving it) is heat dissipated, never negative "
                         "(a sign convention of the rig, power fed back?) give the loss as a "
                         "positive power in W", source)
    if kind == "power_W" and turning.any():
        p = _median(np.abs(power[turning]))
        if np.isfinite(p) and p < ELECTRIC_POWER_MIN_W:
            raise InputError("power_W median", float(f"{p:.6g}"), "the electrical input of "
                             "the oil runs while the shaft turns is below a motor's own losses "
                             f"(at least {ELECTRIC_POWER_MIN_W:g} W): in kW? give the power in "
                             "W (multiply by 1000)", source)
        if np.isfinite(p) and p < ELECTRIC_POWER_WARN_W:
            _warn(f"{source}: power_W median {p:.3g} W while the shaft turns: below a motor's "
                  "own losses; if the column is in kW, multiply by 1000")


def check_time(time_s: np.ndarray, run: np.ndarray, source: str) -> None:
    """Refuse runs that cannot be in seconds; warn at a slow sample step (ms?).

    Parameters
    ----------
    time_s : ndarray
        ``time_s`` of every row [s as given].
    run : ndarray of int
        Run code of every row.
    source : str
        Name used in messages.

    Raises
    ------
    InputError
        A run longer than :data:`RUN_DURATION_MAX_S`.
    """
    ok = np.isfinite(time_s)
    if ok.sum() < 2:
        return
    t, r = time_s[ok], run[ok]
    lo = np.full(int(r.max()) + 1, np.inf)
    hi = np.full(int(r.max()) + 1, -np.inf)
    np.minimum.at(lo, r, t)
    np.maximum.at(hi, r, t)
    dur = hi - lo
    longest = float(np.max(dur[np.isfinite(dur)])) if np.isfinite(dur).any() else 0.0
    if longest > RUN_DURATION_MAX_S:
        raise InputError("time_s", float(f"{longest:.6g}"), f"a run spans {longest:.4g} s "
                         f"({longest / 86400:.3g} days): time_s is not in seconds (at most "
                         f"{RUN_DURATION_MAX_S:g} s per run)", source)
    same = r[1:] == r[:-1]
    step = np.diff(t)[same]
    step = step[step > 0]
    if step.size and float(np.median(step)) > TIME_STEP_WARN_S and longest > RUN_WARN_S:
        _warn(f"{source}: time_s median step {float(np.median(step)):.4g} s between samples "
              f"(runs up to {longest / 3600:.3g} h): if time_s is in ms, divide by 1000")


def check_units(num: dict, kind: str, has_time: bool, run: np.ndarray | None,
                oil_rows: np.ndarray, purpose: str, source: str) -> None:
    """Every plausibility check of a rig table's numeric columns (before fitting).

    Parameters
    ----------
    num : dict of str to ndarray
        The numeric columns as float64 (``temp_C`` [degC], ``speed_rpm`` [rpm], the
        power column [W], ``time_s`` [s]), one entry per row read.
    kind : str
        The power column (``"power_W"``, ``"viscous_power_W"``) or ``"none"``.
    has_time : bool
        Whether the table has ``time_s`` (then ``run`` too).
    run : ndarray of int or None
        Run code of every row (with time).
    oil_rows : ndarray of bool
        Rows in oil that are still kept.
    purpose : {"fit", "predict"}
        What the data are validated for.
    source : str
        Name used in messages.

    Raises
    ------
    InputError
        One line naming the column and the likely mistake where the data cannot be
        right (see the module docstring); warnings where they might be.
    """
    check_temperature(num["temp_C"], source)
    check_speed(num["speed_rpm"], oil_rows, purpose, source)
    if kind in num:
        check_power(num[kind], kind, num["speed_rpm"], oil_rows, purpose, source)
    if has_time and run is not None:
        check_time(num["time_s"], run, source)
