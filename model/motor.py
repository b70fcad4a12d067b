"""The motor: surface-PM magnetics and rotor inertia (the magnetic-gap and inertia limits).

* Carter coefficient of the stator slot openings (Gieras A.27-A.28).
* Air-gap flux density of a surface-PM machine, leakage neglected:
  ``B_g = B_r h_M / (h_M + mu_rec k_C k_sat g)``.
* Torque capability at a given electric loading: ``tau = 2 pi R^2 L sigma``,
  shear stress ``sigma = k_w B_g A / sqrt(2)`` (so tau ∝ B_g R^2 L).
* Rotor inertia: hollow cylinders ``J = (pi/2) rho L (R_o^4 - R_i^4)``; the
  grooved layer counts with its solid fraction, the epoxy fill with its density.

Epoxy is non-magnetic: filling grooves changes the hydraulic clearance (T), not
the magnetic gap g = T3 - T2.

All functions accept floats, numpy arrays and CasADi symbols.

References
----------
.. [1] J. F. Gieras, *Permanent Magnet Motor Technology*, 3rd ed., CRC 2010,
   App. A (A.27-A.28) and ch. 2 (air-gap flux density).
.. [2] J. Pyrhönen et al., *Design of Rotating Electrical Machines*, 2nd ed.,
   2014, sec. 1.4 (tangential stress) and sec. 3.2 (Carter coefficient).
.. [3] J. L. Meriam, L. G. Kraige, *Engineering Mechanics: Dynamics*, 7th ed.,
   Wiley 2012, App. B (mass moment of inertia of a hollow circular cylinder).
.. [4] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Sec. IV.C.2 (the epoxy's weight is negligible
   against the rotor's inertia: dry runs differ by under 1 W).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from . import _math as m

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .case import Motor


def carter_coefficient(slot_pitch_m, slot_opening_m, gap_m):
    """Carter coefficient ``k_C = t / (t - gamma g)`` [-].

    ``gamma = (4/pi) [ (b/2g) atan(b/2g) - ln sqrt(1 + (b/2g)^2) ]``.

    Parameters
    ----------
    slot_pitch_m : float, array or CasADi symbol
        Slot pitch t at the bore [m].
    slot_opening_m : float, array or CasADi symbol
        Slot opening b [m].
    gap_m : float, array or CasADi symbol
        Mechanical (magnetic) gap g [m].

    Returns
    -------
    float, array or CasADi expression
        Carter coefficient k_C [-] (>= 1).

    References
    ----------
    Gieras [1], Eqs. A.27-A.28.
    """
    u = slot_opening_m / (2.0 * gap_m)
    gam = 4.0 / np.pi * (u * m.atan(u) - 0.5 * m.log(1.0 + u * u))
    return slot_pitch_m / (slot_pitch_m - gam * gap_m)


def airgap_flux_density(remanence_T, magnet_thickness_m, recoil_permeability, carter, gap_m,
                        saturation_factor=1.0):
    """Air-gap flux density of a surface-PM machine [T], leakage neglected.

    ``B_g = B_r h_M / (h_M + mu_rec k_C k_sat g)``.

    Parameters
    ----------
    remanence_T : float
        Magnet remanence B_r [T].
    magnet_thickness_m : float
        Radial magnet thickness h_M [m].
    recoil_permeability : float
        Relative recoil permeability mu_rec [-].
    carter : float, array or CasADi symbol
        Carter coefficient k_C [-].
    gap_m : float, array or CasADi symbol
        Magnetic gap g [m].
    saturation_factor : float
        Saturation factor k_sat [-] (1: unsaturated iron).

    Returns
    -------
    float, array or CasADi expression
        Air-gap flux density B_g [T].

    References
    ----------
    Gieras [1], ch. 2.
    """
    return remanence_T * magnet_thickness_m / (
        magnet_thickness_m + recoil_permeability * carter * saturation_factor * gap_m)


def torque_capability(flux_density_T, electric_loading_A_m, winding_factor, radius_m, length_m):
    """Electromagnetic torque capability [N m] at an rms electric loading A [A/m].

    ``tau = 2 pi R^2 L sigma``, ``sigma = k_w B_g A / sqrt(2)``.

    Parameters
    ----------
    flux_density_T : float, array or CasADi symbol
        Air-gap flux density B_g [T].
    electric_loading_A_m : float
        Rms linear current density A [A/m].
    winding_factor : float
        Winding factor k_w [-].
    radius_m : float, array or CasADi symbol
        Rotor radius R [m].
    length_m : float, array or CasADi symbol
        Stack length L [m].

    Returns
    -------
    float, array or CasADi expression
        Torque [N m].

    References
    ----------
    Pyrhönen et al. [2], sec. 1.4.
    """
    sigma = winding_factor * flux_density_T * electric_loading_A_m / np.sqrt(2.0)
    return 2.0 * np.pi * radius_m * radius_m * length_m * sigma


def hollow_cylinder_inertia(density_kg_m3, length_m, outer_radius_m, inner_radius_m):
    """Polar moment of inertia [kg m^2] of a hollow cylinder: ``(pi/2) rho L (Ro^4 - Ri^4)``.

    Parameters
    ----------
    density_kg_m3 : float
        Density [kg/m^3].
    length_m : float, array or CasADi symbol
        Axial length [m].
    outer_radius_m, inner_radius_m : float, array or CasADi symbol
        Radii [m].

    Returns
    -------
    float, array or CasADi expression
        Moment of inertia about the axis [kg m^2].

    References
    ----------
    Meriam & Kraige [3].
    """
    return 0.5 * np.pi * density_kg_m3 * length_m * (outer_radius_m**4 - inner_radius_m**4)


def grooved_rotor_inertia(length_m, shaft_bore_radius_m, groove_bottom_unfilled_m,
                          groove_bottom_m, outer_radius_m, rotor_density_kg_m3,
                          groove_solid_fraction, epoxy_density_kg_m3):
    """Inertia [kg m^2] of a rotor with a grooved outer layer, grooves partly filled with epoxy.

    Solid core from the shaft bore to the unfilled groove bottoms; the grooved
    layer (unfilled groove bottom to outer radius) counts with its solid
    fraction; the epoxy fills the grooves from the unfilled bottom up to
    ``groove_bottom_m`` (= T1 after filling).

    Parameters
    ----------
    length_m : float, array or CasADi symbol
        Stack length [m].
    shaft_bore_radius_m : float
        Inner radius of the rotor [m].
    groove_bottom_unfilled_m : float, array or CasADi symbol
        Groove-bottom radius as machined [m].
    groove_bottom_m : float, array or CasADi symbol
        Groove-bottom radius after the epoxy fill (T1) [m].
    outer_radius_m : float, array or CasADi symbol
        Rotor outer radius (T2) [m].
    rotor_density_kg_m3 : float
        Density of the rotor iron [kg/m^3].
    groove_solid_fraction : float
        Share of the grooved layer that is iron [-].
    epoxy_density_kg_m3 : float
        Density of the epoxy fill [kg/m^3].

    Returns
    -------
    float, array or CasADi expression
        Moment of inertia [kg m^2].

    References
    ----------
    Hollow cylinders (Meriam & Kraige [3]); epoxy fill after the seed paper [4].
    """
    core = hollow_cylinder_inertia(rotor_density_kg_m3, length_m, groove_bottom_unfilled_m,
                                   shaft_bore_radius_m)
    teeth = groove_solid_fraction * hollow_cylinder_inertia(
        rotor_density_kg_m3, length_m, outer_radius_m, groove_bottom_unfilled_m)
    fill = (1.0 - groove_solid_fraction) * hollow_cylinder_inertia(
        epoxy_density_kg_m3, length_m, groove_bottom_m, groove_bottom_unfilled_m)
    return core + teeth + fill


def motor_torque(motor: Motor, R_m, delta_m, L_m) -> tuple[Any, Any, Any]:
    """Torque capability [N m], air-gap flux density [T] and Carter coefficient [-].

    Carter coefficient with the slot pitch at the bore ``2 pi T3 / Q_s`` and the
    magnetic gap ``g = delta`` (epoxy is non-magnetic) [1]; ``B_g`` and
    ``tau = 2 pi R^2 L k_w B_g A / sqrt 2`` [2].

    Parameters
    ----------
    motor : Motor
        Magnet, slot and winding data of the case (SI).
    R_m : float, array or CasADi symbol
        Rotor outer radius T2 [m].
    delta_m : float, array or CasADi symbol
        Clearance T3 - T2, the magnetic gap [m].
    L_m : float, array or CasADi symbol
        Stack length [m].

    Returns
    -------
    torque_Nm : float, array or CasADi expression
        Torque capability [N m].
    flux_density_T : float, array or CasADi expression
        Air-gap flux density [T].
    carter : float, array or CasADi expression
        Carter coefficient [-].

    References
    ----------
    Gieras [1], Eqs. A.27-A.28 and ch. 2; Pyrhönen et al. [2], sec. 1.4.
    """
    pitch = 2.0 * np.pi * (R_m + delta_m) / motor.slot_count
    kc = carter_coefficient(pitch, motor.slot_opening, delta_m)
    bg = airgap_flux_density(motor.remanence_T, motor.magnet_thickness,
                             motor.recoil_permeability, kc, delta_m, motor.saturation_factor)
    tau = torque_capability(bg, motor.electric_loading_A_m, motor.winding_factor, R_m, L_m)
    return tau, bg, kc


def rotor_inertia(motor: Motor, R_m, rotor_groove_m, L_m, machined_groove_m) -> Any:
    """Rotor inertia [kg m^2] with grooves machined ``machined_groove_m`` deep and filled
    with epoxy up to ``rotor_groove_m`` below the surface (``T1_unfilled = R - d_r0``).

    Parameters
    ----------
    motor : Motor
        Shaft bore [m], densities [kg/m^3] and groove solid fraction [-] of the case.
    R_m : float, array or CasADi symbol
        Rotor outer radius [m].
    rotor_groove_m : float, array or CasADi symbol
        Groove depth left open by the fill, d_r [m].
    L_m : float, array or CasADi symbol
        Stack length [m].
    machined_groove_m : float, array or CasADi symbol
        Groove depth as machined, d_r0 [m].

    Returns
    -------
    float, array or CasADi expression
        Polar moment of inertia [kg m^2] (:func:`grooved_rotor_inertia`).

    References
    ----------
    Meriam & Kraige [3]; seed paper [4].
    """
    return grooved_rotor_inertia(L_m, motor.shaft_bore_radius, R_m - machined_groove_m,
                                 R_m - rotor_groove_m, R_m, motor.rotor_density_kg_m3,
                                 motor.rotor_groove_solid_fraction, motor.epoxy_density_kg_m3)
