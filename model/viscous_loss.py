"""Viscous power and torque of oil-filled clearances (seed Eqs. 1, 5, 10).

``P = 0.5 pi Cm rho |omega|^3 R^4 L`` per region (Eq. 5); the joint loss is the
sum over regions (Eq. 10); the viscous torque is ``P / omega`` with the sign of
omega; the joint output torque is ``i eta (tau_M - tau_V)`` (Eq. 1).

All functions accept floats, numpy arrays and CasADi symbols.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 1, 5, 10.
.. [2] J. Pyrhönen et al., *Design of Rotating Electrical Machines*, 2nd ed.,
   2014, p. 528 (the same power form with Cm).
"""

from __future__ import annotations

import casadi as ca
import numpy as np

from . import _math as m
from .skin_friction import FrictionLaw, moment_coefficient
from .taylor_couette import couette_reynolds


def region_viscous_power(omega_rad_s, density_kg_m3, moment_coeff, radius_m, length_m):
    """Viscous power [W] of one clearance: ``0.5 pi Cm rho |omega|^3 R^4 L`` (Eq. 5).

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (sign ignored).
    density_kg_m3 : float, array or CasADi symbol
        Oil density rho [kg/m^3].
    moment_coeff : float, array or CasADi symbol
        Moment coefficient C_m [-].
    radius_m : float, array or CasADi symbol
        Rotation radius R [m].
    length_m : float, array or CasADi symbol
        Length L [m].

    Returns
    -------
    float, array or CasADi expression
        Viscous power [W].

    References
    ----------
    Seed paper (Eq. 5) [1]; Pyrhönen et al. [2].
    """
    w = m.fabs(omega_rad_s)
    return 0.5 * np.pi * moment_coeff * density_kg_m3 * w * w * w * radius_m**4 * length_m


def clearance_power(omega_rad_s, nu_m2_s, density_kg_m3, radius_m, gap_m, length_m,
                    law: FrictionLaw, roughness_T=1.0):
    """Viscous power [W] of a clearance from its geometry, oil and speed.

    Re (Eq. 4) -> C_m (Eqs. 6-8 under ``law``) -> P (Eq. 5). The single place
    where the chain is written; the optimizer, the studies and the calibration
    all call it.

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s] (sign ignored).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].
    density_kg_m3 : float, array or CasADi symbol
        Oil density [kg/m^3].
    radius_m, gap_m, length_m : float, array or CasADi symbol
        R, delta, L of the clearance [m].
    law : FrictionLaw
        How C_m is computed (form, laminar law, gamma [-], scale [-]).
    roughness_T : float, array or CasADi symbol
        Clearance roughness T [-] (region 1; 1 for a smooth annulus).

    Returns
    -------
    float, array or CasADi expression
        Viscous power [W].

    References
    ----------
    Seed paper (Eqs. 4-9) [1].
    """
    re = couette_reynolds(omega_rad_s, radius_m, gap_m, nu_m2_s)
    cm = moment_coefficient(re, gap_m / radius_m, law, roughness_T)
    return region_viscous_power(omega_rad_s, density_kg_m3, cm, radius_m, length_m)


def viscous_torque(power_W, omega_rad_s):
    """Viscous torque [N m] opposing rotation: ``P / |omega|`` with the sign of omega.

    Zero where omega is zero (the power vanishes faster than omega).

    Parameters
    ----------
    power_W : float, array or CasADi symbol
        Viscous power [W] (>= 0).
    omega_rad_s : float, array or CasADi symbol
        Rotor speed [rad/s].

    Returns
    -------
    float, array or CasADi expression
        Torque [N m], with the sign of omega (it opposes the motor).

    References
    ----------
    Power = torque x angular speed.
    """
    w = m.fabs(omega_rad_s)
    safe = m.fmax(w, 1e-300)
    return m.where(w > 0, power_W / safe * m.sign(omega_rad_s), 0.0 * power_W)


def joint_output_torque(motor_torque_Nm, viscous_torque_Nm, gear_ratio, gear_efficiency):
    """Joint output torque ``tau_J = i eta (tau_M - tau_V)`` [N m] (seed Eq. 1).

    Parameters
    ----------
    motor_torque_Nm : float, array or CasADi symbol
        Motor torque tau_M [N m].
    viscous_torque_Nm : float, array or CasADi symbol
        Viscous torque tau_V [N m].
    gear_ratio : float
        Reduction ratio i [-].
    gear_efficiency : float
        Gear efficiency eta [-].

    Returns
    -------
    float, array or CasADi expression
        Joint output torque [N m].

    References
    ----------
    Seed paper (Eq. 1) [1].
    """
    return gear_ratio * gear_efficiency * (motor_torque_Nm - viscous_torque_Nm)


def weighted_mean(values, weights):
    """Mean of ``values`` [any unit] with weights [-] summing to 1 (duty-cycle quadrature).

    Parameters
    ----------
    values : array or CasADi expression
        Values at the nodes, nodes along the last axis [any unit].
    weights : array
        Weights of the nodes [-], summing to 1.

    Returns
    -------
    float, array or CasADi expression
        ``values @ weights`` [unit of values].
    """
    if m.is_symbolic(values, weights):
        return ca.dot(ca.DM(np.asarray(weights, dtype=float)), values)
    return np.asarray(values) @ np.asarray(weights)
