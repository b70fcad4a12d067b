"""The laws of an electric linear actuator in oil: rod guide, passages, screw, dashpot.

Every function takes floats, numpy arrays and CasADi symbols alike (SI in, SI out), so
the evaluation, the vectorised rows and the design NLP differentiate the same code.
The screw's load-independent torque is Palmgren's law of :mod:`oilgap.model.bearing.laws`
(reused, in catalogue units there); :func:`screw_viscous_torque` only converts units.

References
----------
.. [1] F. M. White, *Viscous Fluid Flow*, 3rd ed., McGraw-Hill 2006, sec. 3-2 (Couette
   flow between concentric cylinders, axial sliding of the inner one: u(r) =
   v ln(r_o/r)/ln(r_o/r_i)) and sec. 3-3 (Hagen-Poiseuille flow in a tube, and the
   eccentric annulus: the leakage of a fully eccentric thin annulus is 2.5x the
   concentric one, ``Q_e/Q_0 = 1 + 1.5 eps^2``).
.. [2] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., Burbank 1959;
   T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
   CRC 2006, ch. 9 (``M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3``; f_0 by bearing type).
.. [3] Plane Poiseuille flow through a thin annular clearance (White [1]_, sec. 3-2):
   a piston of radius R pushing ``Q = pi R^2 v`` through a clearance c of length L
   without a bypass needs ``dp = 12 mu L Q/(2 pi R c^3)``, so
   ``F = dp pi R^2 = 6 pi mu L R^3 v/c^3`` (the classic dashpot; the Couette drag of
   the clearance, smaller by ``c^2/R^2``, is left out).
"""

from __future__ import annotations

import math

from .. import _math as m
from ..bearing.friction import palmgren_viscous_torque

ECCENTRIC_LEAKAGE_GAIN = 1.5
"""Coefficient of eps^2 in the eccentric-annulus leakage ``1 + 1.5 eps^2`` [-] [1]_."""


def motor_speed(rod_velocity_m_s, lead_m):
    """Motor (screw) angular speed that drives the rod at a velocity [rad/s].

    ``omega = 2 pi v / lead``: one screw turn advances the nut by one lead.

    Parameters
    ----------
    rod_velocity_m_s : float, array or CasADi symbol
        Rod velocity v [m/s] (signed).
    lead_m : float, array or CasADi symbol
        Screw lead [m] (> 0).

    Returns
    -------
    float, array or CasADi expression
        Motor speed omega [rad/s] (sign of v).

    References
    ----------
    Screw kinematics (advance per turn = lead).
    """
    return 2.0 * math.pi * rod_velocity_m_s / lead_m


def rod_velocity(omega_rad_s, lead_m):
    """Rod velocity of a motor speed, the inverse of :func:`motor_speed` [m/s].

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Motor speed [rad/s].
    lead_m : float, array or CasADi symbol
        Screw lead [m].

    Returns
    -------
    float, array or CasADi expression
        ``v = omega lead / (2 pi)`` [m/s].

    References
    ----------
    Screw kinematics (advance per turn = lead).
    """
    return omega_rad_s * lead_m / (2.0 * math.pi)


def rod_force_capability(torque_Nm, lead_m, efficiency):
    """Axial force a screw turns a motor torque into [N].

    ``F = 2 pi eta T / lead`` (work balance over one turn, screw efficiency eta).

    Parameters
    ----------
    torque_Nm : float, array or CasADi symbol
        Motor torque T [N m].
    lead_m : float, array or CasADi symbol
        Screw lead [m].
    efficiency : float
        Forward efficiency eta of the screw [-].

    Returns
    -------
    float, array or CasADi expression
        Rod force [N].

    References
    ----------
    Work balance ``F lead = eta T 2 pi`` of a screw (any machine-design text).
    """
    return 2.0 * math.pi * efficiency * torque_Nm / lead_m


def annular_couette_force(mu_Pa_s, rod_velocity_m_s, length_m, rod_radius_m, bore_radius_m):
    """Viscous drag of a rod sliding axially in a concentric guide bushing [N].

    ``F = 2 pi L mu v / ln(r_o/r_i)``, exact for laminar Couette flow between concentric
    cylinders; its thin-gap limit is ``mu pi d L v / c`` (c = r_o - r_i, d = 2 r_i).

    Parameters
    ----------
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity [Pa s].
    rod_velocity_m_s : float, array or CasADi symbol
        Rod velocity v [m/s] (the force has its sign).
    length_m : float, array or CasADi symbol
        Guide length L [m].
    rod_radius_m : float, array or CasADi symbol
        Rod radius r_i [m].
    bore_radius_m : float, array or CasADi symbol
        Bushing bore radius r_o [m] (> r_i).

    Returns
    -------
    float, array or CasADi expression
        Drag force [N], opposing the motion.

    References
    ----------
    White [1]_, sec. 3-2.
    """
    return 2.0 * math.pi * length_m * mu_Pa_s * rod_velocity_m_s / m.log(
        bore_radius_m / rod_radius_m)


def eccentric_drag_factor(eccentricity):
    """Drag of an eccentric rod relative to a concentric one, thin gap [-].

    ``1/sqrt(1 - eps^2)``: the wall shear ``mu v/h`` integrated over
    ``h = c (1 + eps cos(theta))``; 1 at eps = 0, unbounded as eps -> 1.

    Parameters
    ----------
    eccentricity : float, array or CasADi symbol
        Eccentricity ratio eps = e/c [-], in [0, 1).

    Returns
    -------
    float, array or CasADi expression
        Factor [-].

    References
    ----------
    White [1]_, sec. 3-2 (the thin-gap shear); ``int dtheta/(1 + eps cos theta) =
    2 pi/sqrt(1 - eps^2)``.
    """
    return 1.0 / m.sqrt(1.0 - eccentricity**2)


def annulus_leakage(mu_Pa_s, pressure_drop_Pa, length_m, diameter_m, clearance_m,
                    eccentricity=0.0):
    """Pressure-driven flow through a thin annular clearance [m^3/s].

    ``Q = pi d c^3 dp / (12 mu L) (1 + 1.5 eps^2)``: the concentric thin-gap result
    times the eccentric-annulus factor (2.5 at full eccentricity).

    Parameters
    ----------
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity [Pa s].
    pressure_drop_Pa : float, array or CasADi symbol
        Pressure difference along the clearance [Pa].
    length_m : float, array or CasADi symbol
        Clearance length L [m].
    diameter_m : float, array or CasADi symbol
        Rod diameter d [m].
    clearance_m : float, array or CasADi symbol
        Radial clearance c [m].
    eccentricity : float, array or CasADi symbol
        Eccentricity ratio eps [-], in [0, 1].

    Returns
    -------
    float, array or CasADi expression
        Leakage [m^3/s].

    References
    ----------
    White [1]_, sec. 3-3.
    """
    factor = 1.0 + ECCENTRIC_LEAKAGE_GAIN * eccentricity**2
    return math.pi * diameter_m * clearance_m**3 * pressure_drop_Pa / (
        12.0 * mu_Pa_s * length_m) * factor


def hagen_poiseuille_pressure_drop(mu_Pa_s, length_m, flow_m3_s, diameter_m):
    """Pressure drop of laminar flow through a round passage [Pa].

    ``dp = 128 mu L Q / (pi d^4)``.

    Parameters
    ----------
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity [Pa s].
    length_m : float, array or CasADi symbol
        Passage length L [m].
    flow_m3_s : float, array or CasADi symbol
        Volume flow Q through the passage [m^3/s].
    diameter_m : float, array or CasADi symbol
        Passage diameter d [m].

    Returns
    -------
    float, array or CasADi expression
        Pressure drop [Pa] (sign of Q).

    References
    ----------
    White [1]_, sec. 3-3.
    """
    return 128.0 * mu_Pa_s * length_m * flow_m3_s / (math.pi * diameter_m**4)


def passages_power(mu_Pa_s, rod_velocity_m_s, rod_diameter_m, count, diameter_m, length_m):
    """Power to push the oil the rod displaces through parallel passages [W].

    ``Q = (pi d_rod^2/4) v`` split evenly over ``count`` passages; each costs
    ``dp q`` with ``dp`` by :func:`hagen_poiseuille_pressure_drop`, so the total is
    ``dp Q`` (= the force ``dp A_rod`` on the rod times v).

    Parameters
    ----------
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity [Pa s].
    rod_velocity_m_s : float, array or CasADi symbol
        Rod velocity v [m/s].
    rod_diameter_m : float
        Rod diameter [m].
    count : int
        Number of passages [-] (>= 1).
    diameter_m, length_m : float, array or CasADi symbol
        Passage diameter and length [m].

    Returns
    -------
    float, array or CasADi expression
        Power [W] (>= 0).

    References
    ----------
    White [1]_, sec. 3-3.
    """
    q = 0.25 * math.pi * rod_diameter_m**2 * rod_velocity_m_s
    dp = hagen_poiseuille_pressure_drop(mu_Pa_s, length_m, q / count, diameter_m)
    return dp * q


def dashpot_force(mu_Pa_s, rod_velocity_m_s, length_m, radius_m, clearance_m):
    """Force on a piston that must push the oil it displaces through its own clearance [N].

    ``F = 6 pi mu L R^3 v / c^3``: a piston (or rod end) with no bypass is a dashpot.

    Parameters
    ----------
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity [Pa s].
    rod_velocity_m_s : float, array or CasADi symbol
        Piston velocity v [m/s].
    length_m : float, array or CasADi symbol
        Clearance length L [m].
    radius_m : float, array or CasADi symbol
        Piston radius R [m].
    clearance_m : float, array or CasADi symbol
        Radial clearance c [m] (<< R).

    Returns
    -------
    float, array or CasADi expression
        Force [N], opposing the motion.

    References
    ----------
    The annular-clearance dashpot [3]_.
    """
    return 6.0 * math.pi * mu_Pa_s * length_m * radius_m**3 * rod_velocity_m_s \
        / clearance_m**3


def screw_viscous_torque(omega_rad_s, nu_m2_s, pitch_diameter_m, f0):
    """Load-independent (churning) torque of a screw's nut in oil [N m].

    Palmgren's ``M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3`` [N mm] (nu [cSt], n [rpm], d_m
    [mm]; constant below ``nu n = 2000``) applied to the nut's rolling set, as to a
    bearing: :func:`oilgap.model.bearing.friction.palmgren_viscous_torque`.

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Screw speed [rad/s] (sign ignored).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].
    pitch_diameter_m : float
        Screw pitch diameter d_m [m].
    f0 : float
        Palmgren factor of the screw [-].

    Returns
    -------
    float, array or CasADi expression
        Torque [N m] (>= 0).

    References
    ----------
    Palmgren; Harris & Kotzalas [2]_.
    """
    return palmgren_viscous_torque(omega_rad_s, nu_m2_s, pitch_diameter_m, f0)
