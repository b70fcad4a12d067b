"""Physical limits of a case's geometry and motor, each with its reason.

The dataclasses of :mod:`oilgap.model.case` call these checks when they are built, so a
case read from TOML, changed by a sweep row or built in Python is refused in one line
(InputError naming the TOML key) when a radius, gap or motor value is impossible or
absurd: a 1 km gap, a 100 000-slot stator whose slot opening is wider than its slot
pitch (the Carter coefficient turns negative and B_g exceeds B_r). The limits and their
reasons are listed in ``docs/case-file.md``.

References
----------
.. [1] J. F. Gieras, *Permanent Magnet Motor Technology*, 3rd ed., CRC 2010, App. A
   (A.27-A.28, the Carter coefficient) and ch. 2 (air-gap flux density).
.. [2] E. Bilgen, R. Boulos, ASME J. Fluids Eng. 95(1):122-126, 1973 (the clearance law).
"""

from __future__ import annotations

import math
from typing import Any

from .errors import InputError
from .motor import motor_torque
from .units import MM_TO_M

MAX_SLOT_COUNT = 1000
"""Most stator slots [-]: the largest hydro generators have a few hundred."""

SLOT_COUNT_REASON = "the largest hydro generators have a few hundred stator slots"

MOTOR_RANGES = {  # field -> (lowest, highest [in the TOML key's unit], lowest excluded, why)
    "remanence_T": (0.0, 1.6, True, "the strongest magnets (sintered NdFeB) reach B_r ~ "
                    "1.5 T"),
    "magnet_thickness": (0.0, 100.0, True, "surface magnets are a few mm thick; 100 mm is "
                         "beyond any surface-PM rotor"),
    "recoil_permeability": (1.0, 10.0, False, "a permanent magnet recoils at mu_rec >= 1 "
                            "(NdFeB 1.05, ferrite ~1.1, AlNiCo up to ~5)"),
    "slot_opening": (0.0, 100.0, True, "slot openings are a few mm; the opening must also "
                     "be narrower than the slot pitch (checked with the case's radii)"),
    "saturation_factor": (1.0, 5.0, False, "k_sat >= 1: saturated iron only adds "
                          "reluctance; typical 1-1.5"),
    "electric_loading_A_m": (0.0, 3.0e5, True, "liquid-cooled machines reach ~1.5e5 A/m "
                             "rms"),
    "winding_factor": (0.0, 1.0, True, "a winding factor is at most 1 (a full-pitch, "
                       "unskewed winding)"),
    "shaft_bore_radius": (0.0, 2000.0, True, "a rotor bore larger than 2 m is not a "
                          "manipulator's motor"),
    "rotor_density_kg_m3": (0.0, 22_600.0, True, "denser than osmium (22 590 kg/m^3), the "
                            "densest element"),
    "epoxy_density_kg_m3": (0.0, 22_600.0, True, "denser than osmium (22 590 kg/m^3), the "
                            "densest element"),
    "rotor_groove_solid_fraction": (0.0, 1.0, False, "a share of the layer"),
    "gear_ratio": (0.0, 1.0e4, True, "beyond multi-stage reducers (harmonic drives reach "
                   "~300)"),
    "gear_efficiency": (0.0, 1.0, False, "an efficiency is a share of the power"),
}
"""Physical range of each Motor field in the unit of its TOML key (``docs/case-file.md``)."""


MAX_RADIUS_M = 2.0
"""Largest radius or gap of a clearance [m]: 2 m is beyond any manipulator or thruster
motor; a larger number is a unit slip (m written as mm)."""

MAX_LENGTH_M = 5.0
"""Longest clearance [m] (as :data:`MAX_RADIUS_M`)."""

MIN_GAP_M = 1.0e-6
"""Smallest clearance [m]: 1 um is below the roundness and surface roughness of turned
and ground bores, so the clearance laws of smooth cylinders do not hold."""

MAX_GAP_RATIO = 1.0
"""Largest gap over radius delta/R [-]: Eq. 6 and the Couette law describe the annulus
between close cylinders; a gap wider than the rotor's radius is open fluid, not a
clearance."""


def check_size(field: str, value_m: float, limit_m: float, where: str) -> None:
    """Refuse a radius, gap or length above ``limit_m``, naming it in mm.

    Parameters
    ----------
    field : str
        TOML key of the value (``"T3_mm"``) [-].
    value_m : float
        The value [m].
    limit_m : float
        Its largest allowed value [m].
    where : str
        Table it came from [-].

    Raises
    ------
    InputError
        ``value_m > limit_m``.
    """
    if value_m > limit_m:
        raise InputError(field, value_m / MM_TO_M, f"at most {limit_m / MM_TO_M:g} mm: "
                         "larger than any manipulator or thruster motor (a unit slip, m "
                         "written as mm?)", where)


def check_gap(field: str, shown: float, gap_m: float, radius_m: float, radius_key: str,
               where: str) -> None:
    """Refuse a gap below :data:`MIN_GAP_M` or wider than :data:`MAX_GAP_RATIO` radii.

    Parameters
    ----------
    field : str
        TOML key to name (``"T3_mm"``, ``"gap_mm"``) [-].
    shown : float
        Its value as the user wrote it [mm].
    gap_m, radius_m : float
        The gap and the rotor radius [m].
    radius_key : str
        TOML key of the radius, for the message [-].
    where : str
        Table it came from [-].

    Raises
    ------
    InputError
        The gap outside [:data:`MIN_GAP_M`, :data:`MAX_GAP_RATIO` x radius].

    References
    ----------
    Bilgen & Boulos [2] (the clearance law of close cylinders).
    """
    if gap_m < MIN_GAP_M * (1.0 - 1e-9):  # rounding of radii in mm aside
        raise InputError(field, shown, f"gives a gap of {gap_m / MM_TO_M:.6g} mm; at least "
                         f"{MIN_GAP_M / MM_TO_M:g} mm (below the roundness and roughness of a "
                         "machined bore the clearance laws do not hold)", where)
    if gap_m > MAX_GAP_RATIO * radius_m:
        raise InputError(field, shown, f"gives a gap of {gap_m / MM_TO_M:g} mm, wider than "
                         f"the radius {radius_key} = {radius_m / MM_TO_M:g}: the clearance "
                         "laws (Eq. 6, Couette) describe an annulus between close cylinders, "
                         "gap/radius <= 1", where)


def check_slot_pitch(motor: Any, bore_m: float, field: str, value: Any, bore_text: str,
                     where: str) -> None:
    """Refuse a slot opening at least as wide as the slot pitch ``2 pi bore / Q_s``.

    Parameters
    ----------
    motor : Motor
        Slot count Q_s [-] and slot opening b [m].
    bore_m : float
        Stator bore radius [m].
    field : str
        Key to name in the message (``"slot_opening_mm"``, ``"bounds.radius_min_mm"``) [-].
    value : Any
        Its value as the user wrote it [unit of ``field``].
    bore_text : str
        Which bore this is, for the message [-].
    where : str
        Table it came from [-].

    Raises
    ------
    InputError
        ``b >= 2 pi bore / Q_s``: no teeth between the slots, the Carter coefficient
        negative or infinite.

    References
    ----------
    Gieras [1], Eqs. A.27-A.28.
    """
    pitch = 2.0 * math.pi * bore_m / motor.slot_count
    if motor.slot_opening >= pitch:
        raise InputError(field, value, f"the slot opening {motor.slot_opening / MM_TO_M:g} mm "
                         f"must be narrower than the slot pitch 2 pi bore/slot_count = "
                         f"{pitch / MM_TO_M:.4g} mm at {bore_text} (slot_count = "
                         f"{motor.slot_count}): the teeth between the slots need width", where)


def check_motor_fits(case: Any) -> None:
    """Refuse a motor that does not fit the case's rotor and stator.

    The shaft bore must lie inside the rotor's groove bottoms; the slot opening must be
    narrower than the slot pitch at the stator bore (else the Carter coefficient is
    negative or infinite; the optimizer checks the bounds' smallest bore); then the
    Carter coefficient must be >= 1 and B_g <= B_r at the case's design.

    Parameters
    ----------
    case : DesignCase
        The case (its ``motor``, ``region1`` and ``bounds``) [SI: m, T].

    Raises
    ------
    InputError
        Naming ``shaft_bore_radius_mm``, ``slot_opening_mm`` or the motor.

    References
    ----------
    Gieras [1], Eqs. A.27-A.28 and ch. 2.
    """
    m, r1 = case.motor, case.region1
    mm = 1.0 / MM_TO_M
    if m.shaft_bore_radius >= r1.T1_unfilled:
        raise InputError("shaft_bore_radius_mm", m.shaft_bore_radius * mm, "must be less than "
                         f"the rotor's groove bottoms (T1_unfilled_mm = {r1.T1_unfilled * mm:g})"
                         ": the rotor needs material", "motor")
    check_slot_pitch(m, r1.T3, "slot_opening_mm", m.slot_opening * mm,
                     f"the stator bore T3_mm = {r1.T3 * mm:g}", "motor")
    _, bg, kc = motor_torque(m, r1.T2, r1.gap, r1.length)
    if not (math.isfinite(kc) and kc >= 1.0 and 0.0 < bg <= m.remanence_T):
        raise InputError("motor", f"k_C = {kc:.4g}, B_g = {bg:.4g} T", "a Carter coefficient "
                         f">= 1 and an air-gap flux density in (0, B_r = {m.remanence_T:g} T] "
                         "(slot_count, slot_opening_mm, the magnet and the gap)", "motor")
