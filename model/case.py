"""Design cases: a typed, validated description of an oil-filled joint.

A :class:`DesignCase` holds region 1 (rotor-stator clearance, radii T1-T4 and
length), region 2 (bearing annulus, optional), the motor data, the oil, the
friction law, the operating condition, the duty cycle, the design bounds and
the mission profile, and optionally a heat balance to the sea and a rolling bearing.
Everything inside is SI; the TOML file carries units in
its key names (``T1_mm``, ``depth_m``, ``peak_speed_rpm``).

Radii of Fig. 5 of the seed paper (not defined in its text), as oilgap reads
them: T1 rotor groove-bottom radius, T2 rotor outer radius, T3 stator bore
radius, T4 stator groove-bottom radius; delta1 = T3 - T2 and
T = (T4 - T1)/(T3 - T2) (Eq. 9); region 1's R is T2.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 1 and 9, Table 1, Figs. 4-5.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields, replace
from typing import Any

from .bearing.friction import BearingSpec
from .duty_cycle import DutyCycle
from .errors import InputError, check_positive, check_range
from .film_heating import WALL_CONDITIONS
from .fluids import Fluid
from .io.inputs import check_physical
from .io.limits import (
    MAX_GAP_RATIO,
    MAX_LENGTH_M,
    MAX_RADIUS_M,
    MAX_SLOT_COUNT,
    MIN_GAP_M,
    MOTOR_RANGES,
    SLOT_COUNT_REASON,
    check_bearing_fits,
    check_celsius,
    check_gap,
    check_heat_source,
    check_motor_fits,
    check_proportions,
    check_size,
    in_mm,
)
from .skin_friction import FrictionLaw, groove_roughness
from .units import MM_TO_M

# --------------------------------------------------------------------------- dataclasses


@dataclass(frozen=True)
class RotorStatorClearance:
    """Region 1: the rotor-stator clearance [m].

    Attributes
    ----------
    T1 : float
        Rotor groove-bottom radius [m] (after any epoxy fill).
    T2 : float
        Rotor outer radius, the rotation radius R1 [m].
    T3 : float
        Stator bore radius [m]; the clearance is T3 - T2.
    T4 : float
        Stator groove-bottom radius [m] (after any epoxy fill).
    length : float
        Length L1 [m].
    T1_unfilled, T4_unfilled : float, optional
        Groove bottoms before any epoxy fill [m] (default: T1, T4, i.e. unfilled).

    Raises
    ------
    InputError
        Non-positive radii, T3 <= T2, T1 > T2, T4 < T3, a fill that deepens a groove.
    """

    T1: float
    T2: float
    T3: float
    T4: float
    length: float
    T1_unfilled: float | None = None
    T4_unfilled: float | None = None

    def __post_init__(self):
        where = "region1"
        for f in ("T1", "T2", "T3", "T4", "length"):
            check_positive(_key(f), in_mm(getattr(self, f)), where)
            check_size(_key(f), getattr(self, f), MAX_LENGTH_M if f == "length"
                        else MAX_RADIUS_M, where)
        if self.T1_unfilled is None:
            object.__setattr__(self, "T1_unfilled", self.T1)
        if self.T4_unfilled is None:
            object.__setattr__(self, "T4_unfilled", self.T4)
        check_positive("T1_unfilled_mm", in_mm(self.T1_unfilled), where)
        check_positive("T4_unfilled_mm", in_mm(self.T4_unfilled), where)
        check_size("T4_unfilled_mm", self.T4_unfilled, MAX_RADIUS_M, where)
        if self.T3 <= self.T2:
            raise InputError("T3_mm", in_mm(self.T3), f"the gap T3 - T2 must be > 0 "
                             f"(T2_mm = {in_mm(self.T2):g})", where)
        if self.T1 > self.T2:
            raise InputError("T1_mm", in_mm(self.T1), f"must be <= T2_mm = {in_mm(self.T2):g} "
                             "(groove bottoms lie inside the rotor surface)", where)
        if self.T4 < self.T3:
            raise InputError("T4_mm", in_mm(self.T4), f"must be >= T3_mm = {in_mm(self.T3):g} "
                             "(groove bottoms lie outside the stator bore)", where)
        if self.T1_unfilled > self.T1:
            raise InputError("T1_unfilled_mm", in_mm(self.T1_unfilled),
                             f"must be <= T1_mm = {in_mm(self.T1):g} (fill only raises it)", where)
        if self.T4_unfilled < self.T4:
            raise InputError("T4_unfilled_mm", in_mm(self.T4_unfilled),
                             f"must be >= T4_mm = {in_mm(self.T4):g} (fill only lowers it)", where)
        if self.roughness < 1.0:
            raise InputError("T", self.roughness, "roughness (T4-T1)/(T3-T2) must be >= 1", where)
        check_gap("T3_mm", in_mm(self.T3), self.gap, self.T2, "T2_mm", where)
        check_proportions(self.length, self.gap, self.T2,
                          ("length_mm", "the gap T3_mm - T2_mm", "T2_mm"), where)

    @property
    def gap(self) -> float:
        """Clearance delta1 = T3 - T2 [m]."""
        return self.T3 - self.T2

    @property
    def radius(self) -> float:
        """Rotation radius R1 = T2 [m]."""
        return self.T2

    @property
    def roughness(self) -> float:
        """Clearance roughness T = (T4 - T1)/(T3 - T2) (Eq. 9 of the seed paper [1]) [-]."""
        return float(groove_roughness(self.T1, self.T2, self.T3, self.T4))


@dataclass(frozen=True)
class BearingClearance:
    """Region 2: the bearing annulus [m].

    Attributes
    ----------
    radius : float
        Rotation radius R2 [m].
    length : float
        Length L2 [m].
    gap : float
        Radial clearance delta2 [m].
    """

    radius: float
    length: float
    gap: float

    def __post_init__(self):
        for f in ("radius", "length", "gap"):
            check_positive(f + "_mm", in_mm(getattr(self, f)), "region2")
            check_size(f + "_mm", getattr(self, f), MAX_LENGTH_M if f == "length"
                        else MAX_RADIUS_M, "region2")
        check_gap("gap_mm", in_mm(self.gap), self.gap, self.radius, "radius_mm", "region2")
        check_proportions(self.length, self.gap, self.radius,
                          ("length_mm", "gap_mm", "radius_mm"), "region2")


@dataclass(frozen=True)
class Motor:
    """Surface-PM motor data the optimizer needs (SI); the defaults stand for the seed's motor.

    Attributes
    ----------
    remanence_T : float
        Magnet remanence B_r [T].
    magnet_thickness : float
        Radial magnet thickness h_M [m].
    recoil_permeability : float
        Relative recoil permeability mu_rec [-].
    slot_count : int
        Number of stator slots Q_s [-].
    slot_opening : float
        Slot opening b [m].
    saturation_factor : float
        Saturation factor k_sat [-].
    electric_loading_A_m : float
        Rms electric loading A [A/m].
    winding_factor : float
        Winding factor k_w [-].
    shaft_bore_radius : float
        Inner radius of the rotor [m].
    rotor_density_kg_m3, epoxy_density_kg_m3 : float
        Densities of the rotor iron and the epoxy fill [kg/m^3].
    rotor_groove_solid_fraction : float
        Share of the grooved layer that is iron [-], in [0, 1].
    gear_ratio : float
        Reduction ratio i of Eq. 1 [-].
    gear_efficiency : float
        Gear efficiency eta of Eq. 1 [-], in [0, 1].
    """

    remanence_T: float = 1.2
    magnet_thickness: float = 2.5e-3
    recoil_permeability: float = 1.05
    slot_count: int = 12
    slot_opening: float = 2.0e-3
    saturation_factor: float = 1.0
    electric_loading_A_m: float = 15_000.0
    winding_factor: float = 0.95
    shaft_bore_radius: float = 10.0e-3
    rotor_density_kg_m3: float = 7600.0
    epoxy_density_kg_m3: float = 1150.0
    rotor_groove_solid_fraction: float = 0.8
    gear_ratio: float = 100.0
    gear_efficiency: float = 0.8

    def __post_init__(self):
        where = "motor"
        v = self.slot_count
        if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= MAX_SLOT_COUNT:
            raise InputError("slot_count", v, f"must be an integer from 1 to {MAX_SLOT_COUNT} "
                             f"({SLOT_COUNT_REASON})", where)
        for f in fields(self):
            if f.name in MOTOR_RANGES:
                lo, hi, lo_open, reason = MOTOR_RANGES[f.name]
                check_physical(MOTOR_FIELD_TO_KEY.get(f.name, f.name),
                               motor_value_in_toml_units(f.name, getattr(self, f.name)),
                               lo, hi, reason, where, lo_open)




@dataclass(frozen=True)
class OperatingPoint:
    """Steady operating condition: sea depth [m] and oil temperature [degC].

    Attributes
    ----------
    depth_m : float
        Sea depth [m], in [0, 11000]; the oil carries the water column's pressure.
    oil_temp_C : float
        Oil temperature [degC], in [-60, 230].
    """

    depth_m: float = 3000.0
    oil_temp_C: float = 2.0

    def __post_init__(self):
        check_range("depth_m", self.depth_m, 0.0, 11_000.0, "operating")
        check_celsius("oil_temp_C", self.oil_temp_C, "operating")


@dataclass(frozen=True)
class DesignBounds:
    """Bounds of the design NLP [m]; ``torque_min_Nm``/``inertia_max_ratio`` of its constraints.

    Attributes
    ----------
    gap_min, gap_max : float
        Bounds of the clearance delta1 [m].
    radius_min, radius_max : float
        Bounds of the rotor radius R1 [m].
    length_min, length_max : float
        Bounds of the length L1 [m].
    inertia_max_ratio : float
        Largest rotor inertia as a multiple of the case's unfilled rotor [-].
    torque_min_Nm : float or None
        Smallest torque capability [N m]; None: the capability of the case as given.
    """

    gap_min: float
    gap_max: float
    radius_min: float
    radius_max: float
    length_min: float
    length_max: float
    inertia_max_ratio: float = 1.05
    torque_min_Nm: float | None = None

    def __post_init__(self):
        where = "bounds"
        for lo, hi in (("gap_min", "gap_max"), ("radius_min", "radius_max"),
                       ("length_min", "length_max")):
            a = check_positive(lo + "_mm", in_mm(getattr(self, lo)), where)
            b = check_positive(hi + "_mm", in_mm(getattr(self, hi)), where)
            if b < a:
                raise InputError(hi + "_mm", b, f"must be >= {lo}_mm = {a:g}", where)
            check_size(hi + "_mm", getattr(self, hi), MAX_LENGTH_M if lo == "length_min"
                        else MAX_RADIUS_M, where)
        check_gap("gap_min_mm", in_mm(self.gap_min), self.gap_min, self.radius_min,
                  "radius_min_mm", where)
        check_gap("gap_max_mm", in_mm(self.gap_max), self.gap_max, self.radius_min,
                  "radius_min_mm", where)
        check_positive("inertia_max_ratio", self.inertia_max_ratio, where)
        if self.torque_min_Nm is not None:
            check_positive("torque_min_Nm", self.torque_min_Nm, where)

    @classmethod
    def around(cls, region1: RotorStatorClearance) -> DesignBounds:
        """Default bounds: gap x[0.5, 2], radius x[0.9, 1.1], length x[0.8, 1.2] of the given,
        within the limits of :mod:`~oilgap.model.io.limits` (the gap from 1 um to the
        smallest radius, the radius at most 2 m, the length at most 5 m).

        Parameters
        ----------
        region1 : RotorStatorClearance
            The clearance as given (SI: [m]).

        Returns
        -------
        DesignBounds
            Bounds [m], inertia ratio 1.05 [-], no torque bound.
        """
        r_min = 0.9 * region1.radius
        return cls(max(0.5 * region1.gap, MIN_GAP_M), min(2.0 * region1.gap,
                                                          MAX_GAP_RATIO * r_min), r_min,
                   min(1.1 * region1.radius, MAX_RADIUS_M), 0.8 * region1.length,
                   min(1.2 * region1.length, MAX_LENGTH_M))


MISSION_TEMP_KEYS = ("oil_temp_C", "sea_temp_C")
"""The keys of a mission row's temperature: the oil's (thermal modes none/film) or the
sea's (bulk/full)."""


@dataclass(frozen=True)
class MissionSegment:
    """One row of a mission profile: a steady condition held for a fraction of the time.

    Attributes
    ----------
    depth_m : float
        Sea depth [m].
    oil_temp_C : float
        The segment's temperature [degC]: the oil's, or the sea's when ``temp_key`` is
        ``"sea_temp_C"`` (under the thermal modes ``bulk``/``full``, where the oil's is the
        balance's result).
    fraction : float
        Share of the mission time [-]; the fractions of a mission sum to 1.
    temp_key : str
        The key the temperature was written under: ``"oil_temp_C"`` (default) or
        ``"sea_temp_C"`` [-]; the oil-grade study refuses an oil temperature under
        ``bulk``/``full`` and a sea temperature under ``none``/``film`` (issue 26).
    """

    depth_m: float
    oil_temp_C: float
    fraction: float
    temp_key: str = "oil_temp_C"

    def __post_init__(self):
        if self.temp_key not in MISSION_TEMP_KEYS:
            raise InputError("temp_key", self.temp_key, f"one of {', '.join(MISSION_TEMP_KEYS)}",
                             "mission")
        check_range("depth_m", self.depth_m, 0.0, 11_000.0, "mission")
        check_celsius(self.temp_key, self.oil_temp_C, "mission")
        check_range("fraction", self.fraction, 0.0, 1.0, "mission")


@dataclass(frozen=True)
class ThermalSpec:
    """Bulk heat balance of the oil: a lumped heat capacity cooled through one resistance
    to the sea (the ``[thermal]`` table of a case).

    Attributes
    ----------
    sea_temp_C : float
        Sea temperature [degC], in [-60, 230].
    resistance_K_W : float
        Thermal resistance oil to sea [K/W], > 0.
    heat_capacity_J_K : float
        Heat capacity of the oil and what it is in contact with [J/K], > 0.
    other_heat_W : float
        Other heat deposited in the oil (motor losses) [W], >= 0.
    walls : str
        Thermal condition of the film's walls, one of ``WALL_CONDITIONS`` of
        :mod:`oilgap.model.film_heating` [-].
    conductivity_W_mK : float or None
        Oil thermal conductivity [W/(m K)], > 0; None: the film model's default.
    film_strength : float or None
        Film strength s in [0, 1] on the Nahme number (``film``/``full`` modes) [-];
        None: 1, the smooth-film theory (docs/thermal.md#evidence).
    wall_floating : float or None
        Wall parameter w in [0, 1]: 0 isothermal walls, 1 an insulated rotor [-];
        None: from ``walls``. Given with ``walls = "adiabatic-rotor"`` it must be 1.

    Raises
    ------
    InputError
        A value out of range; the message names the TOML key.
    """

    sea_temp_C: float
    resistance_K_W: float
    heat_capacity_J_K: float
    other_heat_W: float = 0.0
    walls: str = "isothermal-walls"
    conductivity_W_mK: float | None = None
    film_strength: float | None = None
    wall_floating: float | None = None

    def __post_init__(self):
        where = "thermal"
        check_celsius("sea_temp_C", self.sea_temp_C, where)
        check_positive("resistance_K_per_W", self.resistance_K_W, where)
        check_positive("heat_capacity_J_per_K", self.heat_capacity_J_K, where)
        check_range("other_heat_W", self.other_heat_W, 0.0, None, where)
        check_heat_source(self.sea_temp_C, self.resistance_K_W, self.other_heat_W, where)
        if self.walls not in WALL_CONDITIONS:
            raise InputError("walls", self.walls, f"one of {', '.join(WALL_CONDITIONS)}", where)
        if self.conductivity_W_mK is not None:
            check_positive("conductivity_W_per_mK", self.conductivity_W_mK, where)
        for key in ("film_strength", "wall_floating"):
            if getattr(self, key) is not None:
                check_range(key, getattr(self, key), 0.0, 1.0, where)
        if (self.wall_floating is not None and self.walls == "adiabatic-rotor"
                and self.wall_floating != 1.0):
            raise InputError("wall_floating", self.wall_floating, "1 (or leave it out) with "
                             "walls = 'adiabatic-rotor'; give walls = 'isothermal-walls' "
                             "or leave walls out to set w in [0, 1]", where)


THERMAL_TOML_KEYS = {  # TOML key of [thermal] -> ThermalSpec field (same unit, SI)
    "sea_temp_C": "sea_temp_C", "resistance_K_per_W": "resistance_K_W",
    "heat_capacity_J_per_K": "heat_capacity_J_K", "other_heat_W": "other_heat_W",
    "walls": "walls", "conductivity_W_per_mK": "conductivity_W_mK",
    "film_strength": "film_strength", "wall_floating": "wall_floating"}
"""``[thermal]`` key -> :class:`ThermalSpec` field."""


@dataclass(frozen=True, eq=False, kw_only=True)
class DesignCase:
    """A joint to evaluate or optimize (all SI inside).

    Attributes
    ----------
    name : str
        Name in reports.
    region1 : RotorStatorClearance
        The rotor-stator clearance (radii and length [m]).
    region2 : BearingClearance or None
        The bearing annulus [m], if the joint has one.
    oil : Fluid
        The compensating fluid: a mineral Oil (nu [cSt] at 40 and 100 degC, density
        [kg/m^3]), a TableFluid or a GasFluid (:mod:`oilgap.model.fluids`).
    operating : OperatingPoint
        Depth [m] and oil temperature [degC].
    duty_cycle : DutyCycle
        Speed [rad/s] against time [s] (default: the seed's sine).
    friction : FrictionLaw
        How C_m [-] is computed.
    motor : Motor
        Motor and gear data (SI).
    bounds : DesignBounds
        Bounds of the design NLP [m] (default: :meth:`DesignBounds.around`).
    mission : tuple of MissionSegment
        Mission profile (depth [m], temperature [degC], fraction [-]); may be empty.
    oils_csv : str or None
        Path of the oils table a mineral oil came from, if any.
    thermal : ThermalSpec or None
        Bulk heat balance to the sea (``[thermal]``), if given.
    bearing : BearingSpec or None
        The rolling bearing (``[bearing]``, :mod:`oilgap.model.bearing`), if given: its
        friction and drag are added to the regions' loss (region 2, the annulus, keeps
        its own term).
    gamma_source : str
        Where ``friction.gamma`` came from, for output headers: ``"case"`` (the
        case's ``[friction]``), :data:`GAMMA_DEFAULT_SOURCE` (filled in by the reader)
        or ``"given"`` (set in Python).
    defaults : tuple of oilgap.model.io.defaults.Default
        The values the case reader filled in [each in its unit]
        (``oilgap.model.io.defaults.case_defaults`` lists them with the ones that follow
        from the case); empty for a case made in Python.
    uncertainty : oilgap.model.uncertain.distributions.UncertaintySpec or None
        The uncertain inputs' joint law (``[uncertainty]``), if given; None: the documented
        defaults (:func:`oilgap.model.uncertain.distributions.case_uncertainty`). It
        enters no nominal number.
    linear : oilgap.model.linear.drive.LinearDrive or None
        The linear actuator's screw, rod, guide and passages (``[drive] kind =
        "linear"``, docs/linear-joint.md); None: a rotary joint. The duty cycle is then
        the motor's speed ``2 pi v/lead`` of the rod's velocity.
    calibration_model : str or None
        A calibrated loop model (``[calibration] model``: the path of a ``loop.json``)
        the commands fold into the case before computing (``oilgap.api``'s
        ``with_model``); None: the case's own laws.
    """

    name: str
    region1: RotorStatorClearance
    region2: BearingClearance | None
    oil: Fluid
    operating: OperatingPoint = field(default_factory=OperatingPoint)
    duty_cycle: DutyCycle = field(default_factory=DutyCycle.sine)
    friction: FrictionLaw = field(default_factory=FrictionLaw)
    motor: Motor = field(default_factory=Motor)
    bounds: DesignBounds | None = None
    mission: tuple[MissionSegment, ...] = ()
    oils_csv: str | None = None
    thermal: ThermalSpec | None = None
    bearing: BearingSpec | None = None
    gamma_source: str = field(default="given", compare=False)
    defaults: tuple = field(default=(), compare=False)
    uncertainty: Any = field(default=None, compare=False)
    linear: Any = None
    calibration_model: str | None = field(default=None, compare=False)

    def __post_init__(self):
        if self.bounds is None:
            object.__setattr__(self, "bounds", DesignBounds.around(self.region1))
        check_motor_fits(self)
        check_bearing_fits(self)
        if self.linear is not None:  # no bypass: a dashpot, refused with its force
            from .linear.report import refuse_dashpot
            refuse_dashpot(self)
        if self.mission:
            total = sum(s.fraction for s in self.mission)
            if abs(total - 1.0) > 1e-6:
                raise InputError("mission fractions", round(total, 9), "must sum to 1", "mission")

    def with_changes(self, **changes: Any) -> DesignCase:
        """A copy with fields replaced (dataclasses.replace).

        Parameters
        ----------
        **changes : Any
            Field name -> new value [SI].

        Returns
        -------
        DesignCase
            The copy, validated again.
        """
        return replace(self, **changes)

    def with_region1(self, **radii_m: float) -> DesignCase:
        """A copy with region-1 radii/length replaced [m].

        Parameters
        ----------
        **radii_m : float
            ``T1``, ``T2``, ``T3``, ``T4``, ``length`` ... -> new value [m].

        Returns
        -------
        DesignCase
            The copy, validated again.
        """
        return replace(self, region1=replace(self.region1, **radii_m))


DEFAULT_GAMMA = 0.566
"""Groove exponent gamma of Eq. 8 [-] for a case whose ``[friction]`` gives none: the seed
rig's fit (``oilgap study smoothing``: 0.566 +- 0.041 on the seed's Table 4), the only
evidence the tool has of what grooves cost; 0 would drop the grooves' loss (about 1.9x too
low on the seed joint). A grooved case (T > 1) without gamma gets a warning."""
GAMMA_DEFAULT_SOURCE = "default (seed rig fit)"
"""``DesignCase.gamma_source`` of a case whose gamma is :data:`DEFAULT_GAMMA`."""


# --------------------------------------------------------------------------- TOML key names
# (the motor's SI fields and the TOML keys that carry their units)

MOTOR_TOML_KEYS = {  # TOML key -> (field, factor to SI)
    "magnet_thickness_mm": ("magnet_thickness", MM_TO_M),
    "slot_opening_mm": ("slot_opening", MM_TO_M),
    "shaft_bore_radius_mm": ("shaft_bore_radius", MM_TO_M),
    "electric_loading_A_per_m": ("electric_loading_A_m", 1.0),
}
MOTOR_FIELD_TO_KEY = {v[0]: k for k, v in MOTOR_TOML_KEYS.items()}
"""Motor field -> TOML key, for the fields whose key carries a unit."""


def motor_value_in_toml_units(name: str, value: float) -> float:
    """The value of Motor field ``name`` [SI] in the unit of its TOML key.

    Parameters
    ----------
    name : str
        Field of :class:`Motor` (``"magnet_thickness"``, ``"gear_ratio"``).
    value : float
        Its value [SI].

    Returns
    -------
    float
        The value in the unit of the TOML key (``magnet_thickness_mm``: [mm]).
    """
    key = MOTOR_FIELD_TO_KEY.get(name)
    return value / MOTOR_TOML_KEYS[key][1] if key else value


def _key(attr: str) -> str:
    return attr + "_mm"
