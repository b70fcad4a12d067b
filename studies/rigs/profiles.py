"""Speed profiles of a rig run: sine (the seed's), trapezoid and steps.

Each profile gives the rotor speed [rad/s] and its rate [rad/s^2] at times ``t`` [s] for a
peak speed ``w0`` [rad/s] and a repetition frequency ``f`` [Hz]:

* ``"sine"``: ``w0 sin(2 pi f t)`` (the seed paper's rig, both directions);
* ``"trapezoid"``: both directions, ramps of a fifth of a half period between holds at
  +-w0 (a triangle wave of amplitude 2.5 w0 clipped at +-w0);
* ``"steps"``: one direction, four steady levels w0/4, w0/2, 3w0/4, w0 per period, each
  reached by a linear ramp over 5 % of its step (steady points for the steady law).

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator* (the sine run of its rig).
"""

from __future__ import annotations

import numpy as np

PROFILES = ("sine", "trapezoid", "steps")
"""Speed profiles a planned run may follow."""

TRAPEZOID_GAIN = 2.5
"""Triangle amplitude over the hold speed of the trapezoid [-] (ramps take 1/2.5 of a
quarter period each)."""

STEP_LEVELS = 4
"""Steady levels of the steps profile per period [-]."""

STEP_RAMP = 0.05
"""Share of a step spent ramping from the previous level [-]."""


def profile_speed(profile: str, t, w0: float, f: float) -> tuple[np.ndarray, np.ndarray]:
    """Speed [rad/s] and acceleration [rad/s^2] of a profile at times ``t`` [s].

    Parameters
    ----------
    profile : {"sine", "trapezoid", "steps"}
        Speed profile (:data:`PROFILES`).
    t : float or array
        Times [s].
    w0 : float
        Peak speed [rad/s].
    f : float
        Repetition frequency [Hz].

    Returns
    -------
    (omega, domega_dt) : arrays
        Speed [rad/s] and its rate [rad/s^2].
    """
    t = np.asarray(t, dtype=float)
    two_pi_f = 2.0 * np.pi * f
    if profile == "sine":
        return w0 * np.sin(two_pi_f * t), w0 * two_pi_f * np.cos(two_pi_f * t)
    if profile == "trapezoid":
        tri = (2.0 / np.pi) * np.arcsin(np.clip(np.sin(two_pi_f * t), -1.0, 1.0))
        x = TRAPEZOID_GAIN * tri
        slope = TRAPEZOID_GAIN * 4.0 * f * np.sign(np.cos(two_pi_f * t))
        inside = np.abs(x) < 1.0
        return w0 * np.clip(x, -1.0, 1.0), np.where(inside, w0 * slope, 0.0)
    if profile == "steps":
        u = np.mod(t * f, 1.0) * STEP_LEVELS  # 0 .. 4 over a period
        k = np.floor(u)
        frac = u - k
        level = (k + 1.0) / STEP_LEVELS
        prev = np.where(k == 0, 1.0, k / STEP_LEVELS)
        ramp = frac < STEP_RAMP
        w = np.where(ramp, prev + (level - prev) * frac / STEP_RAMP, level)
        rate = np.where(ramp, (level - prev) / STEP_RAMP * STEP_LEVELS * f, 0.0)
        return w0 * w, w0 * rate
    raise ValueError(f"unknown speed profile {profile!r}; allowed: {', '.join(PROFILES)}")
