"""An electric linear actuator in oil: the screw, the rod, its guide and the passages.

A motor turns a ball or roller screw; the nut drives a rod that slides in a guide bushing;
the oil the rod displaces flows through compensation passages. The motor (region 1 and
its rolling bearing) runs at ``omega = 2 pi v / lead``; :class:`LinearDrive` holds what
the linear elements (:mod:`oilgap.model.linear.elements`) need besides the oil state
and that speed. SI inside; the case file's keys carry units (``lead_mm``),
:mod:`oilgap.model.io.case_linear`
reads them.

References
----------
.. [1] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., Burbank 1959;
   T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
   CRC 2006, ch. 9: f_0 of an angular-contact or thrust ball set in an oil bath about 2
   (recalled); oilgap's submerged deep-groove bearing takes twice the oil-bath value
   (:data:`oilgap.model.bearing.laws.F0_SUBMERGED`), and the screw's nut likewise.
.. [2] Hydraulic line sizing practice: return lines 2-4 m/s, pressure lines 3-6 m/s
   (e.g. Parker, *Industrial Hydraulic Technology*; recalled, not located).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..bearing.laws import F0_SUBMERGED
from ..errors import InputError, check_positive, check_range

SCREW_TYPES = ("ball", "roller")
"""Screw types [-]: a recirculating ball screw or a planetary roller screw."""

SCREW_F0 = {"ball": F0_SUBMERGED, "roller": 2.0 * F0_SUBMERGED}
"""Default Palmgren f_0 of a fully submerged screw nut [-] [1]_: a ball nut as a submerged
ball bearing (4), a roller nut (line contacts, many rollers) twice that. Recalled
bearing values carried over to screws, not validated on screws: the ``[screw] f0`` key
sets it, and docs/linear-joint.md shows the band."""

SCREW_EFFICIENCY = {"ball": 0.9, "roller": 0.85}
"""Default forward efficiency of a screw [-] (catalogue ranges 0.85-0.95 for ball
screws, 0.75-0.9 for roller screws; recalled)."""

PASSAGE_VELOCITY_LIMIT_M_S = 3.0
"""Default largest mean oil velocity in a compensation passage [m/s] [2]_ (return-line
practice; a design limit, not a law)."""


@dataclass(frozen=True, kw_only=True)
class Compensator:
    """The pressure compensator the rod's displaced volume and the oil's expansion fill.

    Attributes
    ----------
    capacity_m3 : float
        Volume the compensator can take up [m^3].
    oil_volume_m3 : float
        Oil volume of the actuator [m^3].
    temp_min_C, temp_max_C : float
        Oil temperature range over the mission [degC].
    """

    capacity_m3: float
    oil_volume_m3: float
    temp_min_C: float
    temp_max_C: float

    def __post_init__(self):
        where = "compensator"
        check_positive("capacity_mL", self.capacity_m3 * 1e6, where)
        check_positive("oil_volume_mL", self.oil_volume_m3 * 1e6, where)
        check_range("temp_min_C", self.temp_min_C, -60.0, 300.0, where)
        check_range("temp_max_C", self.temp_max_C, self.temp_min_C, 300.0, where)


@dataclass(frozen=True, kw_only=True)
class LinearDrive:
    """The screw, rod, guide, passages and stroke of a linear actuator [SI].

    Attributes
    ----------
    lead_m : float
        Screw lead [m].
    screw_pitch_diameter_m : float
        Screw pitch diameter d_m [m].
    screw_type : str
        One of :data:`SCREW_TYPES` [-].
    screw_f0 : float
        Palmgren factor of the nut [-] (default :data:`SCREW_F0` of the type).
    screw_efficiency : float
        Forward efficiency eta [-] (default :data:`SCREW_EFFICIENCY` of the type).
    rod_diameter_m : float
        Rod diameter [m].
    guide_length_m : float
        Guide bushing length [m].
    guide_clearance_m : float
        Radial clearance of the guide [m].
    eccentricity : float
        Eccentricity ratio of the rod in the guide [-], in [0, 1).
    passage_count : int
        Number of compensation passages [-]; 0: no bypass (a dashpot, refused).
    passage_diameter_m, passage_length_m : float
        Passage diameter and length [m].
    passage_velocity_limit_m_s : float
        Largest mean velocity in a passage [m/s] (a design constraint).
    stroke_m : float
        Rod stroke [m].
    required_force_N : float or None
        Rod force the joint needs [N] (optimize's constraint); None: none.
    max_motor_speed_rad_s : float or None
        The motor's top speed [rad/s] (optimize's constraint); None: none.
    compensator : Compensator or None
        The compensator's volume check; None: none.
    design_bounds : tuple or None
        (lo, hi) [m] of the lead, the guide clearance and the passage diameter, the
        design NLP's bounds; None: x[0.5, 2] of the values given.
    """

    lead_m: float
    screw_pitch_diameter_m: float
    screw_type: str = "ball"
    screw_f0: float | None = None
    screw_efficiency: float | None = None
    rod_diameter_m: float
    guide_length_m: float
    guide_clearance_m: float
    eccentricity: float = 0.0
    passage_count: int = 1
    passage_diameter_m: float
    passage_length_m: float
    passage_velocity_limit_m_s: float = PASSAGE_VELOCITY_LIMIT_M_S
    stroke_m: float
    required_force_N: float | None = None
    max_motor_speed_rad_s: float | None = None
    compensator: Compensator | None = None
    design_bounds: tuple | None = None

    def __post_init__(self):
        if self.screw_type not in SCREW_TYPES:
            raise InputError("type", self.screw_type, f"one of {', '.join(SCREW_TYPES)}",
                             "screw")
        if self.screw_f0 is None:
            object.__setattr__(self, "screw_f0", SCREW_F0[self.screw_type])
        if self.screw_efficiency is None:
            object.__setattr__(self, "screw_efficiency", SCREW_EFFICIENCY[self.screw_type])
        for key, v, where in (("lead_mm", self.lead_m, "screw"),
                              ("pitch_diameter_mm", self.screw_pitch_diameter_m, "screw"),
                              ("diameter_mm", self.rod_diameter_m, "rod"),
                              ("guide_length_mm", self.guide_length_m, "rod"),
                              ("guide_clearance_mm", self.guide_clearance_m, "rod"),
                              ("diameter_mm", self.passage_diameter_m, "passages"),
                              ("length_mm", self.passage_length_m, "passages"),
                              ("stroke_mm", self.stroke_m, "drive")):
            check_positive(key, v * 1e3, where)
        check_positive("f0", self.screw_f0, "screw")
        check_range("efficiency", self.screw_efficiency, 0.0, 1.0, "screw")
        if not 0.0 <= self.eccentricity < 1.0:
            raise InputError("eccentricity", self.eccentricity, "in [0, 1): e/c of the rod "
                             "in its guide (1: the rod touches the bushing)", "rod")
        c = self.passage_count
        if isinstance(c, bool) or not isinstance(c, int) or c < 0:
            raise InputError("count", c, "an integer >= 0", "passages")
        check_positive("max_velocity_m_s", self.passage_velocity_limit_m_s, "passages")
        if self.guide_clearance_m >= 0.5 * self.rod_diameter_m:
            raise InputError("guide_clearance_mm", self.guide_clearance_m * 1e3,
                             f"below half the rod diameter ({self.rod_diameter_m * 5e2:g} mm)",
                             "rod")
        if self.required_force_N is not None:
            check_positive("required_force_N", self.required_force_N, "drive")
        if self.max_motor_speed_rad_s is not None:
            check_positive("max_motor_speed_rpm", self.max_motor_speed_rad_s, "drive")

    @property
    def rod_area_m2(self) -> float:
        """Rod cross-section ``pi d^2/4`` [m^2]."""
        return 0.25 * math.pi * self.rod_diameter_m**2

    @property
    def has_bypass(self) -> bool:
        """Whether the displaced oil has passages to flow through (else: a dashpot)."""
        return self.passage_count > 0
