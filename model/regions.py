"""The clearance regions of a joint and their loss over a duty cycle.

The one place that lists a joint's regions with their geometry: region 1, the
rotor-stator clearance (radius T2, gap T3 - T2, length, roughness T of Eq. 9),
and region 2, the bearing annulus (smooth, T = 1) when the case has one
(:func:`joint_regions`); the effects of the measured-data loop also need the
bearing's pitch diameter and the rotor's end-face radii (:class:`JointGeometry`).
Every caller (evaluation, sweeps, the design NLP, the rig simulator, the
calibration) builds its regions here and takes their power and their mean over
a duty cycle from :func:`region_power` and :func:`region_mean_power`.

All functions accept floats, numpy arrays and CasADi symbols.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 5, 9 and 10, Table 1.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from .film_cycle import FilmHeating, film_factors
from .skin_friction import FrictionLaw, groove_roughness
from .viscous_loss import clearance_power, weighted_mean

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .case import DesignCase

REGION_NAMES = ("rotor-stator", "bearing")
"""Names of region 1 and region 2, in this order."""


@dataclass(frozen=True)
class Region:
    """One clearance region (SI; floats, arrays or CasADi symbols).

    Attributes
    ----------
    name : str
        ``"rotor-stator"`` (region 1) or ``"bearing"`` (region 2).
    radius_m : float or array
        Rotation radius R [m].
    gap_m : float or array
        Radial clearance delta [m].
    length_m : float or array
        Length L [m].
    roughness_T : float or array
        Clearance roughness T [-] (Eq. 9; 1 for a smooth annulus).
    """

    name: str
    radius_m: Any
    gap_m: Any
    length_m: Any
    roughness_T: Any = 1.0


@dataclass(frozen=True)
class JointGeometry:
    """A joint's regions and the dimensions its other loss sources need [m].

    Attributes
    ----------
    regions : tuple of Region
        Region 1, then region 2 if the joint has one.
    disc_radii_m : (float, float)
        Outer and inner radius of the rotor's end faces (rotor radius, shaft bore).
    bearing_pitch_diameter_m : float or None
        ``2 R2 + delta2`` of the bearing region; None without region 2.
    bearing : BearingSpec or None
        The case's rolling bearing (``[bearing]``), if any.
    """

    regions: tuple[Region, ...]
    disc_radii_m: tuple[float, float]
    bearing_pitch_diameter_m: float | None
    bearing: Any = None


def joint_regions(case: DesignCase) -> tuple[Region, ...]:
    """The clearance regions of a design case (region 1, then region 2 if any).

    Parameters
    ----------
    case : DesignCase
        The joint (radii T1-T4 and lengths in [m], SI inside).

    Returns
    -------
    tuple of Region
        Region 1 with R = T2, delta = T3 - T2, its length [m] and T [-] (Eq. 9);
        region 2 with its radius, gap and length [m] and T = 1.

    References
    ----------
    Seed paper (Eq. 9, Table 1, Fig. 4) [1].
    """
    r1 = case.region1
    out = [Region(REGION_NAMES[0], r1.radius, r1.gap, r1.length, r1.roughness)]
    if case.region2 is not None:
        r2 = case.region2
        out.append(Region(REGION_NAMES[1], r2.radius, r2.gap, r2.length, 1.0))
    return tuple(out)


def joint_geometry(case: DesignCase, roughness_T: Any = None, gap1_m: Any = None
                   ) -> JointGeometry:
    """The joint's regions, end-face radii and bearing pitch diameter.

    Parameters
    ----------
    case : DesignCase
        The joint (SI inside: radii and lengths [m]).
    roughness_T : float or array, optional
        Region-1 roughness per sample or run [-] (default: the case's T).
    gap1_m : float or array, optional
        Region-1 gap per sample or run [m] (default: the case's T3 - T2).

    Returns
    -------
    JointGeometry
        Regions (:func:`joint_regions`, region 1 with the given T and gap), end-face
        radii (rotor radius T2, shaft bore) [m], bearing pitch diameter
        ``2 R2 + delta2`` [m] (None without region 2) and the case's rolling bearing.
    """
    regions = list(joint_regions(case))
    changes = {}
    if roughness_T is not None:
        changes["roughness_T"] = roughness_T
    if gap1_m is not None:
        changes["gap_m"] = gap1_m
    regions[0] = replace(regions[0], **changes)
    r2 = case.region2
    pitch = None if r2 is None else 2.0 * r2.radius + r2.gap
    return JointGeometry(tuple(regions), (case.region1.radius, case.motor.shaft_bore_radius),
                         pitch, case.bearing)


def region_power(region: Region, omega_rad_s, nu_m2_s, density_kg_m3, law: FrictionLaw):
    """Viscous power [W] of one region at speed(s) ``omega_rad_s`` [rad/s].

    :func:`~oilgap.model.viscous_loss.clearance_power` with the region's R,
    delta, L and T.

    Parameters
    ----------
    region : Region
        R, delta, L [m] and T [-] of the clearance.
    omega_rad_s : float, array or CasADi symbol
        Rotor speed(s) [rad/s] (sign ignored).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].
    density_kg_m3 : float, array or CasADi symbol
        Oil density [kg/m^3].
    law : FrictionLaw
        How C_m is computed.

    Returns
    -------
    float, array or CasADi expression
        Power [W].

    References
    ----------
    Seed paper (Eqs. 4-9) [1].
    """
    return clearance_power(omega_rad_s, nu_m2_s, density_kg_m3, region.radius_m,
                           region.gap_m, region.length_m, law, region.roughness_T)


def region_mean_power(region: Region, nodes_rad_s, weights, nu_m2_s, density_kg_m3,
                      law: FrictionLaw, film: FilmHeating | None = None, b_1_K=None):
    """Mean viscous power [W] of one region over a duty cycle's speed distribution.

    ``sum_i w_i P(omega_i)`` over the nodes and weights of
    :meth:`~oilgap.model.duty_cycle.DutyCycle.speed_distribution` (the exact
    reduction of the cycle's samples); with CasADi symbols pass ``nodes_rad_s``
    as a ``casadi.DM``. Nodes along the last axis (arrays of shape (..., n)
    give one mean per leading index).

    Parameters
    ----------
    region : Region
        R, delta, L [m] and T [-] of the clearance.
    nodes_rad_s : array or casadi.DM
        Distinct ``|omega|`` of the cycle [rad/s].
    weights : array
        Time fraction of each node [-] (sum 1).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s] (steady over the cycle).
    density_kg_m3 : float, array or CasADi symbol
        Oil density [kg/m^3].
    law : FrictionLaw
        How C_m is computed.
    film : FilmHeating, optional
        Apply the film-heating correction (:func:`~oilgap.model.film_cycle.film_factors`)
        node by node; None (default): the isothermal film.
    b_1_K : float, array or CasADi symbol, optional
        ``-d ln(mu)/dT`` at the bulk temperature [1/K]; required with ``film``.

    Returns
    -------
    float, array or CasADi expression
        Mean power [W].

    References
    ----------
    Seed paper (Eqs. 5 and 10) [1]: the
    mean over the cycle's 1500 samples, reduced exactly to its speed distribution.
    Film heating: Nahme (1940), Gavis & Laurence (1968) (:mod:`.film_cycle`).
    """
    power = region_power(region, nodes_rad_s, nu_m2_s, density_kg_m3, law)
    if film is not None:
        power = power * film_factors(nodes_rad_s, weights, region.radius_m, region.gap_m,
                                     nu_m2_s, density_kg_m3, b_1_K, film)
    return weighted_mean(power, weights)


def rotor_stator_radii(R_m, delta_m, rotor_groove_m, stator_groove_m):
    """Radii (T1, T2, T3, T4) [m] of region 1 from its design variables.

    ``T1 = R - d_r``, ``T2 = R``, ``T3 = R + delta``, ``T4 = R + delta + d_s``,
    so that ``T = (T4 - T1)/(T3 - T2) = 1 + (d_r + d_s)/delta`` (Eq. 9) [1].

    Parameters
    ----------
    R_m : float, array or CasADi symbol
        Rotor outer radius [m].
    delta_m : float, array or CasADi symbol
        Clearance [m].
    rotor_groove_m, stator_groove_m : float, array or CasADi symbol
        Groove depths left open (after any epoxy fill) [m].

    Returns
    -------
    T1, T2, T3, T4 : float, array or CasADi expression
        The four radii [m].

    References
    ----------
    Seed paper (Eq. 9, Fig. 5) [1].
    """
    T3 = R_m + delta_m
    return R_m - rotor_groove_m, R_m, T3, T3 + stator_groove_m


def rotor_stator_region(R_m, delta_m, rotor_groove_m, stator_groove_m, L_m) -> Region:
    """Region 1 from its design variables (R, delta, d_r, d_s, L) [m]; T from Eq. 9.

    Parameters
    ----------
    R_m : float, array or CasADi symbol
        Rotor outer radius [m].
    delta_m : float, array or CasADi symbol
        Clearance [m].
    rotor_groove_m, stator_groove_m : float, array or CasADi symbol
        Groove depths left open [m].
    L_m : float, array or CasADi symbol
        Length [m].

    Returns
    -------
    Region
        ``"rotor-stator"`` with R, delta, L [m] and ``T = 1 + (d_r + d_s)/delta`` [-].

    References
    ----------
    Seed paper (Eq. 9) [1].
    """
    T = groove_roughness(*rotor_stator_radii(R_m, delta_m, rotor_groove_m, stator_groove_m))
    return Region(REGION_NAMES[0], R_m, delta_m, L_m, T)
