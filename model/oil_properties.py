"""Oil properties against temperature and pressure; sea-water pressure against depth.

Laws
----
* ASTM D341 (Walther): ``log10(log10(nu + 0.7)) = A - B log10(T)``, nu in [cSt],
  T in [K]. Two points fix A and B.
* Barus: ``mu(p) = mu0 exp(alpha p)`` for the dynamic viscosity, p the gauge
  pressure above atmospheric [Pa]. The coefficient is given at 40 degC
  (default 17 /GPa for mineral oil [3]) and follows temperature as the initial
  slope of Roelands' equation does, ``alpha ∝ ln(mu0 / mu_inf)`` with
  ``mu_inf = 6.31e-5 Pa s`` [4]: it grows as the oil gets colder.
* Density: ``rho = rho15 exp(-beta (T - 288.15 K) + p / K)`` (linear thermal
  expansion beta and bulk modulus K, written as an exponential so it stays
  positive and smooth).
* Hydrostatic sea-water pressure: ``p = p_atm + rho_sw g depth``.

All functions accept floats, numpy arrays and CasADi symbols.

References
----------
.. [1] ASTM D341-20, Standard Practice for Viscosity-Temperature Equations and
   Charts for Liquid Petroleum or Hydrocarbon Products.
.. [2] C. Barus, "Isothermals, isopiestics and isometrics relative to
   viscosity", Am. J. Sci. 45:87-96, 1893.
.. [3] A. Vacca, G. Franzoni, *Hydraulic Fluid Power*, Wiley 2021, sec. 2.4
   (bulk modulus) and 2.6.2 (pressure-viscosity coefficient).
.. [4] C. J. A. Roelands, *Correlational aspects of the viscosity-temperature-
   pressure relationship of lubricating oils*, PhD thesis, TU Delft, 1966.
.. [5] P. M. Saunders, "Practical conversion of pressure to depth", J. Phys.
   Oceanogr. 11:573-574, 1981 (the hydrostatic column with a mean density).
.. [6] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for
   a Deep-Sea Electric Manipulator*, Sec. IV.B (ISO VG 22 at about 857 cSt at
   2 degC and 7000 m: a check of the temperature and pressure laws together).
"""

from __future__ import annotations

from . import _math as m
from .units import (
    STANDARD_ATMOSPHERE_PA,
    STANDARD_GRAVITY_M_S2,
    ZERO_CELSIUS_K,
    cst_to_m2_s,
)

WALTHER_OFFSET_CST = 0.7
"""ASTM D341 offset added to nu [cSt] (the low-viscosity correction below ~2 cSt is omitted)."""

BARUS_MINERAL_OIL_1_PA = 1.7e-8
"""Default pressure-viscosity coefficient of mineral oil [1/Pa] (1.7e-3 /bar, 17 /GPa) [3]."""

THERMAL_EXPANSION_MINERAL_OIL_1_K = 6.5e-4
"""Volumetric thermal expansion coefficient of mineral oil [1/K]."""

BULK_MODULUS_MINERAL_OIL_PA = 1.8e9
"""Isothermal secant bulk modulus of mineral hydraulic oil [Pa] (1.5-2.0 GPa) [3]."""

ROELANDS_MU_INF_PA_S = 6.31e-5
"""Roelands' asymptotic viscosity [Pa s] [4]."""

BARUS_REFERENCE_TEMPERATURE_K = ZERO_CELSIUS_K + 40.0
"""Temperature at which a Barus coefficient is stated [K]."""

SEAWATER_DENSITY_KG_M3 = 1030.0
"""Mean density of the sea-water column [kg/m^3] (1025-1050 with depth)."""

REFERENCE_TEMPERATURE_K = ZERO_CELSIUS_K + 15.0
"""Temperature at which catalogue densities are given [K]."""

WALTHER_TRUSTED_RANGE_C = (-20.0, 150.0)
"""Oil temperatures [degC] over which oilgap trusts a Walther line fitted at 40 and 100 degC."""


def walther_coefficients(nu1_cSt, temp1_K, nu2_cSt, temp2_K):
    """Coefficients A, B of the ASTM D341 (Walther) line through two points.

    Parameters
    ----------
    nu1_cSt, nu2_cSt : float
        Kinematic viscosities [cSt] at the two temperatures.
    temp1_K, temp2_K : float
        The two temperatures [K], different.

    Returns
    -------
    A, B : float
        ``log10(log10(nu + 0.7)) = A - B log10(T)`` with nu in [cSt] and T in [K];
        A [-], B [-].

    References
    ----------
    ASTM D341 [1].
    """
    z1 = m.log10(m.log10(nu1_cSt + WALTHER_OFFSET_CST))
    z2 = m.log10(m.log10(nu2_cSt + WALTHER_OFFSET_CST))
    x1 = m.log10(temp1_K)
    x2 = m.log10(temp2_K)
    B = (z1 - z2) / (x2 - x1)
    A = z1 + B * x1
    return A, B


def walther_viscosity_cSt(temp_K, A, B):
    """Kinematic viscosity [cSt] at ``temp_K`` [K] on the Walther line (A, B).

    ``nu = 10^(10^(A - B log10 T)) - 0.7``.

    Parameters
    ----------
    temp_K : float, array or CasADi symbol
        Temperature [K].
    A, B : float
        Walther coefficients [-] (:func:`walther_coefficients`).

    Returns
    -------
    float, array or CasADi expression
        Kinematic viscosity at atmospheric pressure [cSt].

    References
    ----------
    ASTM D341 [1].
    """
    return 10.0 ** (10.0 ** (A - B * m.log10(temp_K))) - WALTHER_OFFSET_CST


def walther_temperature_K(nu_cSt, A, B):
    """Inverse of :func:`walther_viscosity_cSt`: temperature [K] at which nu [cSt] is reached.

    Parameters
    ----------
    nu_cSt : float or array
        Kinematic viscosity [cSt].
    A, B : float
        Walther coefficients [-] (:func:`walther_coefficients`).

    Returns
    -------
    float or array
        Temperature [K].

    References
    ----------
    ASTM D341 [1].
    """
    return 10.0 ** ((A - m.log10(m.log10(nu_cSt + WALTHER_OFFSET_CST))) / B)


def barus_factor(pressure_gauge_Pa, alpha_1_Pa=BARUS_MINERAL_OIL_1_PA):
    """Barus pressure-viscosity factor ``mu(p)/mu(0) = exp(alpha p)`` [-].

    Parameters
    ----------
    pressure_gauge_Pa : float or array
        Pressure above atmospheric [Pa].
    alpha_1_Pa : float
        Pressure-viscosity coefficient [1/Pa].

    Returns
    -------
    float or array
        ``mu(p) / mu(0)`` [-].

    References
    ----------
    Barus [2]; default coefficient from Vacca [3].
    """
    return m.exp(alpha_1_Pa * pressure_gauge_Pa)


def barus_coefficient(alpha_ref_1_Pa, mu0_Pa_s, mu_ref_Pa_s):
    """Pressure-viscosity coefficient [1/Pa] at a temperature where mu(p=0) = mu0.

    ``alpha = alpha_ref ln(mu0 / mu_inf) / ln(mu_ref / mu_inf)``: the temperature
    dependence of the initial slope of Roelands' equation, scaled so that
    ``alpha = alpha_ref`` where the oil has its reference viscosity ``mu_ref``.

    Parameters
    ----------
    alpha_ref_1_Pa : float
        Barus coefficient at the reference temperature (40 degC) [1/Pa].
    mu0_Pa_s : float or array
        Dynamic viscosity at atmospheric pressure and the temperature of interest [Pa s].
    mu_ref_Pa_s : float
        Dynamic viscosity at atmospheric pressure and the reference temperature [Pa s].

    Returns
    -------
    float or array
        Barus coefficient at the temperature of interest [1/Pa].

    References
    ----------
    Roelands [4]; Vacca & Franzoni [3] for alpha_ref.
    """
    return alpha_ref_1_Pa * m.log(mu0_Pa_s / ROELANDS_MU_INF_PA_S) / m.log(
        mu_ref_Pa_s / ROELANDS_MU_INF_PA_S)


def oil_density(density15_kg_m3, temp_K, pressure_gauge_Pa=0.0,
                expansion_1_K=THERMAL_EXPANSION_MINERAL_OIL_1_K,
                bulk_modulus_Pa=BULK_MODULUS_MINERAL_OIL_PA):
    """Oil density [kg/m^3] at temperature and gauge pressure.

    ``rho = rho15 exp(-beta (T - 288.15) + p / K)``.

    Parameters
    ----------
    density15_kg_m3 : float
        Density at 15 degC and atmospheric pressure [kg/m^3].
    temp_K : float or array
        Temperature [K].
    pressure_gauge_Pa : float or array
        Pressure above atmospheric [Pa].
    expansion_1_K : float
        Volumetric thermal expansion coefficient beta [1/K].
    bulk_modulus_Pa : float
        Isothermal bulk modulus K [Pa].

    Returns
    -------
    float or array
        Density [kg/m^3].

    References
    ----------
    Vacca & Franzoni [3], sec. 2.3-2.4.
    """
    return density15_kg_m3 * m.exp(
        -expansion_1_K * (temp_K - REFERENCE_TEMPERATURE_K) + pressure_gauge_Pa / bulk_modulus_Pa
    )


def seawater_gauge_pressure(depth_m, seawater_density_kg_m3=SEAWATER_DENSITY_KG_M3):
    """Hydrostatic gauge pressure [Pa] at ``depth_m`` [m] of sea water: ``rho_sw g depth``.

    A constant column density overstates the pressure at 11 km by about 1.6 %
    (compressibility and latitude are left out) [5].

    Parameters
    ----------
    depth_m : float or array
        Depth below the sea surface [m].
    seawater_density_kg_m3 : float
        Mean density of the water column rho_sw [kg/m^3].

    Returns
    -------
    float or array
        Pressure above atmospheric [Pa].

    References
    ----------
    Hydrostatics with a mean column density; Saunders [5].
    """
    return seawater_density_kg_m3 * STANDARD_GRAVITY_M_S2 * depth_m


def seawater_absolute_pressure(depth_m, seawater_density_kg_m3=SEAWATER_DENSITY_KG_M3):
    """Absolute pressure [Pa] at ``depth_m`` [m]: atmosphere plus the water column.

    Parameters
    ----------
    depth_m : float or array
        Depth below the sea surface [m].
    seawater_density_kg_m3 : float
        Mean density of the water column [kg/m^3].

    Returns
    -------
    float or array
        Absolute pressure [Pa].

    References
    ----------
    Saunders [5] (see :func:`seawater_gauge_pressure`).
    """
    return STANDARD_ATMOSPHERE_PA + seawater_gauge_pressure(depth_m, seawater_density_kg_m3)


def oil_viscosities(walther_A, walther_B, density15_kg_m3, temp_K, pressure_gauge_Pa,
                    alpha_1_Pa=BARUS_MINERAL_OIL_1_PA,
                    expansion_1_K=THERMAL_EXPANSION_MINERAL_OIL_1_K,
                    bulk_modulus_Pa=BULK_MODULUS_MINERAL_OIL_PA):
    """Kinematic viscosity, dynamic viscosity and density of an oil at (T, p).

    The Walther line gives nu at atmospheric pressure; rho(T, 0) * nu gives the
    dynamic viscosity, Barus raises it with pressure, and the kinematic
    viscosity at pressure is mu(T, p) / rho(T, p). ``alpha_1_Pa`` is the Barus
    coefficient at 40 degC; :func:`barus_coefficient` carries it to ``temp_K``.

    Parameters
    ----------
    walther_A, walther_B : float
        Walther coefficients of the oil [-] (:func:`walther_coefficients`).
    density15_kg_m3 : float
        Density at 15 degC and atmospheric pressure [kg/m^3].
    temp_K : float, array or CasADi symbol
        Oil temperature [K].
    pressure_gauge_Pa : float, array or CasADi symbol
        Pressure above atmospheric [Pa].
    alpha_1_Pa : float
        Barus coefficient at 40 degC [1/Pa].
    expansion_1_K : float
        Volumetric thermal expansion coefficient [1/K].
    bulk_modulus_Pa : float
        Bulk modulus [Pa].

    Returns
    -------
    nu_m2_s : float, array or CasADi expression
        Kinematic viscosity [m^2/s].
    mu_Pa_s : float, array or CasADi expression
        Dynamic viscosity [Pa s].
    rho_kg_m3 : float, array or CasADi expression
        Density [kg/m^3].

    References
    ----------
    ASTM D341 [1]; Barus [2] with Roelands' temperature dependence [4]; density
    after Vacca & Franzoni [3]. Checked against the seed's 857 cSt [6].
    """
    nu0_m2_s = cst_to_m2_s(walther_viscosity_cSt(temp_K, walther_A, walther_B))
    rho0 = oil_density(density15_kg_m3, temp_K, 0.0, expansion_1_K, bulk_modulus_Pa)
    rho = oil_density(density15_kg_m3, temp_K, pressure_gauge_Pa, expansion_1_K, bulk_modulus_Pa)
    mu0 = nu0_m2_s * rho0
    t_ref = BARUS_REFERENCE_TEMPERATURE_K
    mu_ref = cst_to_m2_s(walther_viscosity_cSt(t_ref, walther_A, walther_B)) * oil_density(
        density15_kg_m3, t_ref, 0.0, expansion_1_K, bulk_modulus_Pa)
    alpha = barus_coefficient(alpha_1_Pa, mu0, mu_ref)
    mu = mu0 * barus_factor(pressure_gauge_Pa, alpha)
    return mu / rho, mu, rho


def oil_viscosity_temperature_slope(walther_A, walther_B, density15_kg_m3, temp_K,
                                    pressure_gauge_Pa=0.0, alpha_1_Pa=BARUS_MINERAL_OIL_1_PA,
                                    expansion_1_K=THERMAL_EXPANSION_MINERAL_OIL_1_K,
                                    bulk_modulus_Pa=BULK_MODULUS_MINERAL_OIL_PA):
    """Viscosity-temperature slope ``b = -d ln(mu)/dT`` [1/K] of :func:`oil_viscosities`.

    With ``mu = nu0(T) rho(T, 0) exp(alpha(T) p)`` and Roelands' ``alpha(T) = alpha_ref
    ln(mu0/mu_inf) / ln(mu_ref/mu_inf)``, ``ln mu = ln mu0 (1 + alpha_ref p / ln(mu_ref/
    mu_inf)) + const``, so

    ``b = (1 + alpha_ref p / ln(mu_ref/mu_inf)) (B (nu0 + 0.7) ln(nu0 + 0.7) / (nu0 T)
    + beta)``,

    where ``B (nu0 + 0.7) ln(nu0 + 0.7) / (nu0 T) = -d ln nu0/dT`` follows from
    differentiating the Walther line ``log10 log10(nu0 + 0.7) = A - B log10 T``
    (nu0 [cSt] at atmospheric pressure) and ``beta = -d ln rho/dT``.

    Parameters
    ----------
    walther_A, walther_B : float
        Walther coefficients of the oil [-].
    density15_kg_m3 : float
        Density at 15 degC and atmospheric pressure [kg/m^3].
    temp_K : float, array or CasADi symbol
        Oil temperature [K].
    pressure_gauge_Pa : float, array or CasADi symbol
        Pressure above atmospheric [Pa].
    alpha_1_Pa : float
        Barus coefficient at 40 degC [1/Pa].
    expansion_1_K : float
        Volumetric thermal expansion coefficient [1/K].
    bulk_modulus_Pa : float
        Bulk modulus [Pa] (does not enter: mu does not depend on rho(p)).

    Returns
    -------
    float, array or CasADi expression
        b [1/K] (positive: the oil thins as it warms).

    References
    ----------
    ASTM D341 [1]; Barus [2] with Roelands [4]; density after Vacca & Franzoni [3].
    """
    nu0 = walther_viscosity_cSt(temp_K, walther_A, walther_B)
    z = nu0 + WALTHER_OFFSET_CST
    walther_term = walther_B * z * m.log(z) / (nu0 * temp_K)
    t_ref = BARUS_REFERENCE_TEMPERATURE_K
    mu_ref = cst_to_m2_s(walther_viscosity_cSt(t_ref, walther_A, walther_B)) * oil_density(
        density15_kg_m3, t_ref, 0.0, expansion_1_K, bulk_modulus_Pa)
    barus_term = 1.0 + alpha_1_Pa * pressure_gauge_Pa / m.log(mu_ref / ROELANDS_MU_INF_PA_S)
    return barus_term * (walther_term + expansion_1_K)
