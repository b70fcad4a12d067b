"""Unit conversions: the one place where non-SI units enter or leave oilgap.

Inside oilgap every quantity is SI (m, s, rad/s, Pa, K, m^2/s, kg/m^3, W, N m).
Names that cross a boundary (TOML, CSV, CLI, JSON) carry their unit
(``gap_mm``, ``speed_rpm``, ``nu_cSt``); they are converted here.
"""

from __future__ import annotations

import math

RPM_TO_RAD_S = 2.0 * math.pi / 60.0
"""[rad/s per rpm]"""
MM_TO_M = 1.0e-3
"""[m per mm]"""
CST_TO_M2_S = 1.0e-6
"""[m^2/s per cSt]"""
BAR_TO_PA = 1.0e5
"""[Pa per bar]"""
MPA_TO_PA = 1.0e6
"""[Pa per MPa]"""
ZERO_CELSIUS_K = 273.15
"""0 degC in [K]."""
STANDARD_ATMOSPHERE_PA = 101_325.0
"""Standard atmosphere [Pa] (ISO 2533)."""
STANDARD_GRAVITY_M_S2 = 9.80665
"""Standard acceleration of gravity [m/s^2] (3rd CGPM, 1901)."""


def rpm_to_rad_s(speed_rpm):
    """Convert a rotational speed from [rpm] to [rad/s]: ``omega = 2 pi n / 60``.

    Parameters
    ----------
    speed_rpm : float or array
        Rotational speed [rpm].

    Returns
    -------
    float or array
        The same speed [rad/s].
    """
    return speed_rpm * RPM_TO_RAD_S


def rad_s_to_rpm(omega_rad_s):
    """Convert a rotational speed from [rad/s] to [rpm].

    Parameters
    ----------
    omega_rad_s : float or array
        Angular speed [rad/s].

    Returns
    -------
    float or array
        The same speed [rpm].
    """
    return omega_rad_s / RPM_TO_RAD_S


def mm_to_m(length_mm):
    """Convert a length from [mm] to [m].

    Parameters
    ----------
    length_mm : float or array
        Length [mm].

    Returns
    -------
    float or array
        The same length [m].
    """
    return length_mm * MM_TO_M


def m_to_mm(length_m):
    """Convert a length from [m] to [mm].

    Parameters
    ----------
    length_m : float or array
        Length [m].

    Returns
    -------
    float or array
        The same length [mm].
    """
    return length_m / MM_TO_M


def cst_to_m2_s(nu_cSt):
    """Convert a kinematic viscosity from [cSt] to [m^2/s].

    Parameters
    ----------
    nu_cSt : float or array
        Kinematic viscosity (1 cSt = 1 mm^2/s) [cSt].

    Returns
    -------
    float or array
        The same viscosity [m^2/s].
    """
    return nu_cSt * CST_TO_M2_S


def m2_s_to_cst(nu_m2_s):
    """Convert a kinematic viscosity from [m^2/s] to [cSt].

    Parameters
    ----------
    nu_m2_s : float or array
        Kinematic viscosity [m^2/s].

    Returns
    -------
    float or array
        The same viscosity [cSt].
    """
    return nu_m2_s / CST_TO_M2_S


def celsius_to_kelvin(temp_C):
    """Convert a temperature from [degC] to [K].

    Parameters
    ----------
    temp_C : float or array
        Temperature [degC].

    Returns
    -------
    float or array
        The same temperature [K].
    """
    return temp_C + ZERO_CELSIUS_K


def kelvin_to_celsius(temp_K):
    """Convert a temperature from [K] to [degC].

    Parameters
    ----------
    temp_K : float or array
        Temperature [K].

    Returns
    -------
    float or array
        The same temperature [degC].
    """
    return temp_K - ZERO_CELSIUS_K


def per_gpa_to_per_pa(coeff_1_GPa):
    """Convert a pressure coefficient from [1/GPa] to [1/Pa].

    Parameters
    ----------
    coeff_1_GPa : float or array
        Pressure coefficient, e.g. a Barus coefficient [1/GPa].

    Returns
    -------
    float or array
        The same coefficient [1/Pa].
    """
    return coeff_1_GPa * 1.0e-9
