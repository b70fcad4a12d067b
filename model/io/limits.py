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

from ..errors import InputError, check_range
from ..motor import motor_torque
from ..thermal import MAX_OIL_TEMP_C
from ..units import MM_TO_M, ZERO_CELSIUS_K

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


MIN_INPUT_TEMP_C = -60.0
"""Coldest oil or sea temperature of a case [degC]: below the pour point of every
compensating oil (the coldest seas are at -2 degC)."""

MAX_INPUT_TEMP_C = 230.0
"""Hottest oil or sea temperature of a case [degC]: compensating oils are used well below
their flash point (mineral hydraulic oils 180-230 degC); a larger number is most often
a temperature in kelvin written in a degC key (275.15 K is 2 degC)."""


def check_celsius(field: str, value: Any, where: str) -> float:
    """An input temperature [degC] in [:data:`MIN_INPUT_TEMP_C`, :data:`MAX_INPUT_TEMP_C`],
    or an InputError; above the range, with a "kelvin in a degC key?" hint as a length in
    m written in a mm key gets its hint.

    Parameters
    ----------
    field : str
        TOML key (``"oil_temp_C"``, ``"sea_temp_C"``) [-].
    value : Any
        The value as written [degC].
    where : str
        Table it came from [-].

    Returns
    -------
    float
        ``float(value)`` [degC].

    Raises
    ------
    InputError
        Not finite, below or above the range.
    """
    x = check_range(field, value, MIN_INPUT_TEMP_C, None, where)
    if x > MAX_INPUT_TEMP_C:
        as_c = x - ZERO_CELSIUS_K
        hint = (f"; kelvin in a degC key? {x:g} K is {as_c:.4g} degC"
                if MIN_INPUT_TEMP_C <= as_c <= MAX_INPUT_TEMP_C else "")
        raise InputError(field, value, f"allowed range is [{MIN_INPUT_TEMP_C:g}, "
                         f"{MAX_INPUT_TEMP_C:g}] degC: compensating oils are used below their "
                         f"flash point (mineral hydraulic oils 180-230 degC){hint}", where)
    return x


def check_heat_source(sea_temp_C: float, resistance_K_W: float, other_heat_W: float,
                      where: str) -> None:
    """Refuse a ``[thermal]`` table whose other heat alone, before any viscous loss, puts
    the oil at or above the balance's cap :data:`~oilgap.model.thermal.MAX_OIL_TEMP_C`:
    ``T_sea + R Q >= 250 degC``. No balance ``T = T_sea + R (P(T) + Q)`` with a loss
    ``P >= 0`` can hold it, whatever the joint; it is an impossible input (exit 2), not a
    solver failure.

    Parameters
    ----------
    sea_temp_C : float
        Sea temperature [degC].
    resistance_K_W : float
        Thermal resistance to the sea R [K/W].
    other_heat_W : float
        Heat of other sources Q [W].
    where : str
        Table it came from [-].

    Raises
    ------
    InputError
        Naming ``other_heat_W`` (``resistance_K_per_W`` when Q = 0 cannot be the cause),
        the base temperature and the cap.

    References
    ----------
    T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley 2011,
    sec. 3.1 (thermal resistance).
    """
    base = sea_temp_C + resistance_K_W * other_heat_W
    if base < MAX_OIL_TEMP_C:
        return
    raise InputError("other_heat_W", other_heat_W, f"the sea {sea_temp_C:g} degC + "
                     f"resistance_K_per_W {resistance_K_W:g} K/W x other heat alone is "
                     f"{base:.4g} degC >= {MAX_OIL_TEMP_C:g} degC, before any viscous loss: no "
                     "oil temperature balances this heat source (a smaller other_heat_W or "
                     "resistance_K_per_W)", where)


def in_mm(value_m: float) -> float:
    """A length [m] in mm as the user wrote it: ``value_m / MM_TO_M`` rounded to 12
    significant digits, so ``0.035`` mm read as 3.5e-5 m is quoted as ``0.035``, not
    ``0.035000000000000003`` (messages quote the value in the user's units).

    Parameters
    ----------
    value_m : float
        The length [m].

    Returns
    -------
    float
        The length [mm].
    """
    return float(f"{float(value_m) / MM_TO_M:.12g}")


PROPORTION_RANGES = {  # ratio -> (lowest, highest, why too low, why too high)
    "length/gap": (1.0, 1.0e5, "an annulus shorter than its gap is no clearance: the "
                   "clearance laws (Eq. 6, Couette) hold for L >> gap",
                   "longer than 10^5 gaps is beyond any turned joint"),
    "length/radius": (0.01, 100.0, "a clearance shorter than 1 % of its radius is a "
                      "face, not an annulus", "a joint 100 radii long is a shaft, not a "
                      "joint"),
}
"""Plausible proportions [-] of a clearance (region 1 and region 2), lowest and highest
included, with the reason of each bound; outside them a length in m typed into a mm key
(``length_mm = 0.035``) or the reverse is the likely cause."""


def check_proportions(length_m: float, gap_m: float, radius_m: float, keys: tuple[str, str,
                      str], where: str) -> None:
    """Refuse a clearance whose L/gap or L/R lies outside :data:`PROPORTION_RANGES`.

    Parameters
    ----------
    length_m, gap_m, radius_m : float
        Length, gap and rotor radius of the clearance [m].
    keys : tuple of str
        TOML keys of the length, gap and radius (``"length_mm"``, ...) [-].
    where : str
        Table it came from [-].

    Raises
    ------
    InputError
        Naming the length as written [mm], the ratio, its range and the reason, with a
        "mm written as m?" hint.

    References
    ----------
    Bilgen & Boulos [2] (the clearance law of a long annulus).
    """
    lk, gk, rk = keys
    for name, other, key in (("length/gap", gap_m, gk), ("length/radius", radius_m, rk)):
        lo, hi, why_lo, why_hi = PROPORTION_RANGES[name]
        ratio = length_m / other
        if lo <= ratio <= hi:
            continue
        why, hint = ((why_lo, "a length in m written in a mm key?") if ratio < lo else
                     (why_hi, f"{key} in m written in a mm key?"))
        raise InputError(lk, in_mm(length_m), f"gives {name} = {ratio:.4g} with {key} = "
                         f"{in_mm(other):g}; allowed {lo:g} to {hi:g} ({why}; {hint})", where)


def check_bearing_fits(case: Any) -> None:
    """Refuse a rolling bearing whose bore is wider than the joint around it.

    The bearing carries the joint's shaft, so its bore radius ``d/2`` lies inside the
    joint: below the largest radius the case knows (the stator groove bottoms ``T4`` or
    the outer wall of region 2, radius + gap).

    Parameters
    ----------
    case : DesignCase
        The case (its ``bearing``, ``region1`` and ``region2``) [m].

    Raises
    ------
    InputError
        Naming ``bore_mm`` as written, the joint's radius and the reason.

    References
    ----------
    SKF, *Rolling bearings*, catalogue 10000 EN (2013) (the bore d of a bearing).
    """
    b = case.bearing
    if b is None:
        return
    r2 = case.region2
    outer, key = case.region1.T4, "T4_mm"
    if r2 is not None and r2.radius + r2.gap > outer:
        outer, key = r2.radius + r2.gap, "region2 radius_mm + gap_mm"
    if b.bore_m / 2.0 > outer:
        raise InputError("bore_mm", in_mm(b.bore_m), f"the bearing's bore radius "
                         f"{in_mm(b.bore_m / 2.0):g} mm must lie inside the joint ({key} = "
                         f"{in_mm(outer):g}): the bearing carries the joint's shaft; a bore "
                         "wider than the joint is another machine", "bearing")


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
        raise InputError(field, in_mm(value_m), f"at most {limit_m / MM_TO_M:g} mm: "
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
    if m.shaft_bore_radius >= r1.T1_unfilled:
        raise InputError("shaft_bore_radius_mm", in_mm(m.shaft_bore_radius), "must be less than "
                         f"the rotor's groove bottoms (T1_unfilled_mm = {in_mm(r1.T1_unfilled):g})"
                         ": the rotor needs material", "motor")
    check_slot_pitch(m, r1.T3, "slot_opening_mm", in_mm(m.slot_opening),
                     f"the stator bore T3_mm = {in_mm(r1.T3):g}", "motor")
    _, bg, kc = motor_torque(m, r1.T2, r1.gap, r1.length)
    if not (math.isfinite(kc) and kc >= 1.0 and 0.0 < bg <= m.remanence_T):
        raise InputError("motor", f"k_C = {kc:.4g}, B_g = {bg:.4g} T", "a Carter coefficient "
                         f">= 1 and an air-gap flux density in (0, B_r = {m.remanence_T:g} T] "
                         "(slot_count, slot_opening_mm, the magnet and the gap)", "motor")
