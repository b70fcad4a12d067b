"""Taylor-Couette flow in a clearance: Reynolds and Taylor numbers, flow regime,
exact laminar (circular Couette) torque.

Geometry: an inner cylinder of radius R [m] turning at omega [rad/s] inside a
fixed outer cylinder of radius R + delta; x = delta / R.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 2-4 and 6.
.. [2] G. I. Taylor, "Stability of a viscous liquid contained between two
   rotating cylinders", Phil. Trans. R. Soc. A 223:289-343, 1923.
.. [3] F. M. White, *Viscous Fluid Flow*, 3rd ed., McGraw-Hill 2006, sec. 3-2.3
   (flow between rotating concentric cylinders).
.. [4] E. Bilgen, R. Boulos, "Functional dependence of torque coefficient of
   coaxial cylinders on gap width and Reynolds numbers", ASME J. Fluids Eng.
   95(1):122-126, 1973.
"""

from __future__ import annotations

import numpy as np

from . import _math as m

CRITICAL_TAYLOR_NUMBER = 41.3
"""Critical Taylor number Ta = Re (delta/R)^0.5 for the onset of Taylor vortices [1], [2]."""

REGIME_BOUNDARIES_RE = (64.0, 500.0, 1.0e4)
"""Couette Reynolds numbers at which Eq. 6 changes branch [4]."""

REGIME_NAMES = ("laminar", "laminar with vortices", "turbulent with vortices", "turbulent")
"""Bilgen-Boulos flow regimes, in the order of the Eq. 6 branches [4]."""


def couette_reynolds(omega_rad_s, radius_m, gap_m, nu_m2_s):
    """Couette Reynolds number ``Re = |omega| R delta / nu`` [-] (seed Eq. 4).

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Angular speed of the inner cylinder [rad/s] (sign ignored).
    radius_m : float, array or CasADi symbol
        Inner-cylinder radius R [m].
    gap_m : float, array or CasADi symbol
        Radial clearance delta [m].
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].

    Returns
    -------
    float, array or CasADi expression
        Couette Reynolds number [-].

    References
    ----------
    Seed paper (Eq. 4) [1].
    """
    return m.fabs(omega_rad_s) * radius_m * gap_m / nu_m2_s


def taylor_number(reynolds, gap_m, radius_m):
    """Taylor number ``Ta = Re (delta / R)^0.5`` [-] (seed Eq. 3).

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (:func:`couette_reynolds`).
    gap_m : float, array or CasADi symbol
        Radial clearance delta [m].
    radius_m : float, array or CasADi symbol
        Inner-cylinder radius R [m].

    Returns
    -------
    float, array or CasADi expression
        Taylor number [-]; Taylor vortices appear above
        :data:`CRITICAL_TAYLOR_NUMBER` = 41.3.

    References
    ----------
    Seed paper (Eq. 3) [1]; Taylor [2].
    """
    return reynolds * m.sqrt(gap_m / radius_m)


def flow_regime(reynolds) -> np.ndarray:
    """Bilgen-Boulos regime name for each Reynolds number (numpy only).

    Re < 64 laminar, 64-500 laminar with vortices, 500-1e4 turbulent with
    vortices, >= 1e4 turbulent: the branches of the seed's Eq. 6 [4].

    Parameters
    ----------
    reynolds : float or array
        Couette Reynolds number(s) [-].

    Returns
    -------
    ndarray of str
        One name of :data:`REGIME_NAMES` per Reynolds number.

    References
    ----------
    Bilgen & Boulos [4]; seed paper (Eq. 6) [1].
    """
    idx = np.searchsorted(np.asarray(REGIME_BOUNDARIES_RE), np.asarray(reynolds, dtype=float),
                          side="right")
    return np.asarray(REGIME_NAMES, dtype=object)[idx]


def couette_torque(omega_rad_s, mu_Pa_s, inner_radius_m, outer_radius_m, length_m):
    """Exact laminar torque [N m] on the inner cylinder of circular Couette flow.

    ``tau = 4 pi mu L R1^2 R2^2 / (R2^2 - R1^2) * omega`` with the outer cylinder
    at rest (seed Eq. 2 with the dynamic viscosity and times the length).
    Valid below the critical Taylor number.

    Parameters
    ----------
    omega_rad_s : float or array
        Angular speed of the inner cylinder [rad/s] (signed: so is the torque).
    mu_Pa_s : float or array
        Dynamic viscosity [Pa s].
    inner_radius_m, outer_radius_m : float or array
        R1 (rotor) and R2 (bore) [m], R2 > R1.
    length_m : float or array
        Length of the cylinders [m].

    Returns
    -------
    float or array
        Torque the fluid exerts against the rotation, as a magnitude with the sign of
        omega [N m].

    References
    ----------
    White [3], Eq. 3-49; seed paper (Eq. 2) [1].
    """
    r1s = inner_radius_m * inner_radius_m
    r2s = outer_radius_m * outer_radius_m
    return 4.0 * np.pi * mu_Pa_s * length_m * r1s * r2s / (r2s - r1s) * omega_rad_s


def couette_moment_coefficient(reynolds, gap_ratio):
    """Moment coefficient of laminar circular Couette flow in the form of seed Eq. 5.

    ``Cm = 8 (1 + x)^2 / ((2 + x) Re)``, x = delta/R: :func:`couette_torque`
    written as ``P = 0.5 pi Cm rho omega^3 R^4 L``. Derivation: with
    ``(R + delta)^2 - R^2 = R^2 x (2 + x)`` the Couette power is
    ``tau omega = 4 pi mu L R^2 (1 + x)^2 omega^2 / (x (2 + x))``; equating it to
    Eq. 5 and using ``Re = omega R^2 x / nu`` gives the expression.

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-].
    gap_ratio : float, array or CasADi symbol
        x = delta / R [-].

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient [-].

    References
    ----------
    White [3]; seed paper (Eq. 5) [1] for the form.
    """
    x = gap_ratio
    return 8.0 * (1.0 + x) ** 2 / ((2.0 + x) * reynolds)


def couette_floor_form(law) -> bool:
    """Whether a friction law's form can be floored at exact Couette (a scale below 1
    then floors it, :func:`couette_floor_applies`): the Couette laminar law and a form
    with a scale (not the power law).

    Parameters
    ----------
    law : FrictionLaw
        Its ``laminar_law`` and ``form`` [-].

    Returns
    -------
    bool
    """
    return law.laminar_law == "couette" and law.form != "power-law"


def couette_floor_applies(law) -> bool:
    """Whether a friction law is floored at exact Couette by
    :func:`oilgap.model.skin_friction.moment_coefficient`: the Couette laminar law, a form
    with a scale, and a scale below 1 or not a number (an array of scales or a CasADi
    symbol; issue 27 item 4: no calibration takes the laminar loss below Couette, the least
    any flow of the geometry dissipates; at a numeric scale >= 1 nothing changes, bit for
    bit).

    Parameters
    ----------
    law : FrictionLaw
        Its ``laminar_law``, ``form`` and ``scale`` [-].

    Returns
    -------
    bool
    """
    if not couette_floor_form(law):
        return False
    # a number >= 1 cannot take the loss below Couette: nothing to floor, bit for bit; an
    # array or symbol of scales (the vectorised rows, a robust NLP's scenarios) is floored
    # row by row, where max(C_m, Couette) is C_m itself wherever the scale is >= 1
    return not (isinstance(law.scale, (int, float)) and law.scale >= 1.0)
