"""Plausible ranges of the candidate effects' coefficients, with their basis and source.

A fitted coefficient outside its range is reported by the measured-data loop as
"implausible" and the effect is not accepted. Some ranges depend on the rig
(:class:`RigFacts`: its size and fluids): a seal's torque is bounded by the
seal's size, the entrained oil's inertia by the joint's, and shear thinning
needs a polymer-thickened liquid.

References
----------
.. [1] J. W. Daily, R. E. Nece, "Chamber dimension effects on induced flow and
   frictional resistance of enclosed rotating disks", ASME J. Basic Eng. 82:217,
   1960.
.. [2] T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*,
   5th ed., CRC 2006, ch. 9; A. Palmgren, *Ball and Roller Bearing Engineering*,
   3rd ed., Burbank 1959.
.. [3] H. K. Müller, B. S. Nau, *Fluid Sealing Technology*, Marcel Dekker 1998, ch. 5.
.. [4] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed.,
   Wiley 2011, sec. 5.2.
.. [5] J. T. Stuart, J. Fluid Mech. 4:1-21, 1958; R. J. Donnelly, Proc. R. Soc. A
   246:312, 1958.
.. [6] R. B. Bird, R. C. Armstrong, O. Hassager, *Dynamics of Polymeric Liquids*,
   vol. 1, 2nd ed., Wiley 1987, sec. 4.4; M. M. Cross, J. Colloid Sci. 20:417, 1965.
.. [7] IEC 61000-4-30:2015, *Power quality measurement methods*, sec. 5.2
   (10/12-cycle measurement interval).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..film_heating import film_strength_of, film_theory_coefficient
from ..regions import JointGeometry

FILM_CONDUCTIVITY_MIN_W_MK = 0.1
"""Lowest thermal conductivity of a liquid lubricant [W/(m K)] (mineral oils 0.12-0.15,
silicone oils 0.10-0.16; VDI Heat Atlas 2010 D3.1), for the film-heating bound."""


@dataclass(frozen=True)
class FluidFacts:
    """What the plausibility rules need to know of a fluid of the data.

    Attributes
    ----------
    name : str
        Fluid name as written in the data.
    kind : str
        ``"mineral"``, ``"gas"``, ``"table"``, ... (``getattr(fluid, "kind", "mineral")``;
        ``"unknown"`` for a per-row fluid the catalogue does not hold).
    polymer_thickened : bool
        True for a polymer-thickened (VI-improved, non-Newtonian) liquid [-];
        unknown fluids count as Newtonian.
    """

    name: str
    kind: str
    polymer_thickened: bool


@dataclass(frozen=True)
class RigFacts:
    """The rig's size and fluids, for the plausibility rules of the effects.

    Attributes
    ----------
    fluids : tuple of FluidFacts
        The fluids of the oil runs.
    radius_max_m : float
        Largest wetted radius of the joint (rotor radius plus clearance) [m].
    wetted_length_m : float
        Summed length of the clearance regions [m].
    film_resistance_K_W : float
        Largest conduction resistance ``delta/(k A)`` of a clearance's film, A = 2 pi R L
        its wetted area, k = :data:`FILM_CONDUCTIVITY_MIN_W_MK` [K/W] (inf: unknown).
    bearing : BearingSpec or None
        The case's rolling bearing (``[bearing]``), if any: the churning coefficient is
        then a correction factor on its model.
    film_theory_K_W : float
        The ``film_heating`` coefficient of the smooth-film theory (strength 1,
        isothermal walls, k = 0.13 W/(m K)) on the rotor-stator clearance [K/W]
        (:func:`~oilgap.model.film_heating.film_theory_coefficient`; nan: unknown): a
        film coefficient c is the film strength ``s = c / film_theory_K_W`` (the loop's
        ``film_heating`` fits s itself since issue 18).
    """

    fluids: tuple[FluidFacts, ...]
    radius_max_m: float
    wetted_length_m: float
    film_resistance_K_W: float = np.inf
    bearing: object = None
    film_theory_K_W: float = np.nan

    def film_strength(self, coefficient_K_W: float) -> float:
        """Film strength s [-] of a fitted ``film_heating`` coefficient c [K/W].

        Parameters
        ----------
        coefficient_K_W : float
            c (or an end of its interval) [K/W].

        Returns
        -------
        float
            ``c / film_theory_K_W`` [-] (nan when the rig's clearance is unknown).
        """
        return film_strength_of(coefficient_K_W, self.film_theory_K_W)

    @classmethod
    def of(cls, geometry: JointGeometry, fluids) -> RigFacts:
        """Facts of a joint and its fluids.

        Parameters
        ----------
        geometry : JointGeometry
            Regions (R, delta, L [m]) and end-face radii [m].
        fluids : iterable of FluidFacts

        Returns
        -------
        RigFacts
            Largest wetted radius [m] and summed region length [m].
        """
        regions = geometry.regions
        r = max([float(np.max(g.radius_m + np.asarray(g.gap_m))) for g in regions]
                + [geometry.disc_radii_m[0]])
        film = max(float(np.max(g.gap_m)) / (FILM_CONDUCTIVITY_MIN_W_MK * 2.0 * np.pi
                                            * g.radius_m * g.length_m) for g in regions)
        g0 = regions[0]
        theory = float(np.max(film_theory_coefficient(np.asarray(g0.gap_m), g0.radius_m,
                                                      g0.length_m)))
        return cls(tuple(fluids), r, float(sum(g.length_m for g in regions)), film,
                   getattr(geometry, "bearing", None), theory)


@dataclass(frozen=True)
class Plausibility:
    """The physically plausible range of an effect's coefficient.

    Attributes
    ----------
    low, high : float
        Range of the coefficient [unit of the effect] (used unless ``bounds`` is given).
    basis : str
        Why (the physics and numbers behind the range).
    reference : str
        Source of the numbers.
    bounds : callable, optional
        RigFacts -> (low, high) for a range that depends on the rig's size.
    needs_polymer : bool
        The effect needs a polymer-thickened liquid: on any other fluid a fitted
        coefficient is implausible.
    """

    low: float
    high: float
    basis: str
    reference: str
    bounds: Callable[[RigFacts], tuple[float, float]] | None = None
    needs_polymer: bool = False

    def range(self, facts: RigFacts | None = None) -> tuple[float, float]:
        """The plausible range on a rig [unit of the effect].

        Parameters
        ----------
        facts : RigFacts, optional
            The rig (needed where the range depends on its size).

        Returns
        -------
        (float, float)
            Low and high bound [unit of the effect].
        """
        if self.bounds is not None and facts is not None:
            return self.bounds(facts)
        return self.low, self.high

    def check(self, symbol: str, value: float, unit: str, facts: RigFacts) -> str | None:
        """Reason a value is implausible, or None.

        Parameters
        ----------
        symbol : str
            Coefficient symbol (for the message).
        value : float
            Fitted coefficient [unit].
        unit : str
            Its unit.
        facts : RigFacts
            The rig and its fluids.

        Returns
        -------
        str or None
            ``"<symbol> = <value> <unit> outside <low>..<high> (<basis>; <reference>)"``,
            or the fluid that rules the effect out, or None.
        """
        u = "" if unit == "-" else f" {unit}"
        if self.needs_polymer:
            plain = [f for f in facts.fluids if not f.polymer_thickened]
            if plain:
                kinds = dict.fromkeys(f.kind for f in plain)
                what = "; ".join(_kind_text([f.name for f in plain if f.kind == k], k)
                                 for k in kinds)
                return (f"{symbol} = {value:.3g}{u} fitted, but the effect needs a "
                        f"polymer-thickened liquid: {what} ({self.reference})")
        lo, hi = self.range(facts)
        if lo <= value <= hi:
            return None
        return (f"{symbol} = {value:.3g}{u} outside the plausible {lo:.3g}..{hi:.3g}{u} "
                f"({self.basis}; {self.reference})")


def _kind_text(names: list[str], kind: str) -> str:
    """``"VG150, VG320 are straight mineral oils"``: fluids of one kind, as a clause."""
    one = len(names) == 1
    what = {"gas": ("a gas", "gases"), "mineral": ("a straight mineral oil",
                                                   "straight mineral oils"),
            "unknown": ("a per-row fluid of unknown kind (taken as Newtonian)",
                        "per-row fluids of unknown kind (taken as Newtonian)")}.get(
        kind, (f"a {kind} fluid, not polymer-thickened", f"{kind} fluids, not polymer-thickened"))
    return f"{', '.join(names)} {'is' if one else 'are'} {what[0] if one else what[1]}"


SEAL_TANGENTIAL_FORCE_N_M = 500.0
"""Largest lip-seal friction force per unit circumference [N/m]: a radial lip load of
0.05-0.3 N/mm times a friction coefficient of at most ~1, rounded up (Müller & Nau 1998,
ch. 5)."""


def _seal_bounds(f: RigFacts) -> tuple[float, float]:
    # a lip seal on a shaft no larger than the rotor: tau <= f_t 2 pi r^2
    return 0.0, SEAL_TANGENTIAL_FORCE_N_M * 2.0 * np.pi * f.radius_max_m ** 2


def _inertia_bounds(f: RigFacts) -> tuple[float, float]:
    # oil turning rigidly in a housing of twice the wetted radius and three times the
    # wetted length: I_V = pi/2 (2 R)^4 (3 L) = 24 pi R^4 L
    return 0.0, 24.0 * np.pi * f.radius_max_m ** 4 * f.wetted_length_m


PALMGREN_F0_MAX = 12.0
"""Largest plausible Palmgren factor f0 [-]: about 0.7-4 for ball bearings (grease to oil
bath), up to 8 submerged, about 12 for full-complement roller bearings (Harris &
Kotzalas 2006 ch. 9)."""

SKF_CORRECTION_MAX = 30.0
"""Largest plausible correction factor on SKF's model of a submerged deep-groove ball
bearing [-]: the published models of one bearing differ by this much at the viscosity
ratios of an oil-filled joint (kappa 10-120, outside both models' range). Palmgren's M_0
with f0 = 8 is 13-29x SKF's rolling + V_M drag for a 61809 at 3000 rpm and 150-1000 cSt
(docs/notes/bearing-friction-models.md sec. 5; docs/bearing.md)."""


def _churning_bounds(f: RigFacts) -> tuple[float, float]:
    # without [bearing] the coefficient is Palmgren's f0; with one it multiplies the
    # bearing's model: c f0 <= 12 for Palmgren's, c <= 30 for SKF's
    b = f.bearing
    if b is None:
        return 0.0, PALMGREN_F0_MAX
    if b.model == "palmgren":
        return 0.0, PALMGREN_F0_MAX / b.f0
    return 0.0, SKF_CORRECTION_MAX


PLAUSIBLE = {
    "end_face_disc": Plausibility(
        0.0, 50.0, "k = 1 is the free disc on both faces; an enclosed face in laminar "
        "regime I has C_M = 2 pi/((s/a) Re_r), 1.6/((s/a) Re_r^0.5) times the free disc, "
        "below 50 for s/a >= 0.01 and Re_r >= 10", "Daily & Nece 1960, J. Basic Eng. 82:217"),
    "bearing_ball_churning": Plausibility(
        0.0, PALMGREN_F0_MAX, "Palmgren's f0 is about 0.7-4 for ball bearings (grease to "
        "oil bath) and up to about 12 for full-complement roller bearings; with [bearing] "
        "the coefficient multiplies the case's bearing model: c f0 <= 12 for Palmgren's, "
        f"c <= {SKF_CORRECTION_MAX:g} for SKF's (the published models of one submerged "
        "bearing differ this much)",
        "Harris & Kotzalas 2006 ch. 9; Palmgren 1959; SKF catalogue 'Friction'",
        bounds=_churning_bounds),
    "bearing_ball_drag": Plausibility(
        0.0, SKF_CORRECTION_MAX, "k = 1 is SKF's V_M drag term and the balls as spheres in "
        "still oil give about 0.9 of it; SKF's R_s term, outside its validity in a "
        "submerged bearing, would add 10-130x at 150-1000 cSt; the bound is that of the "
        "correction factor on SKF's model", "SKF catalogue 'Friction'; Schiller & Naumann "
        "1933; docs/bearing.md"),
    "seal_coulomb_friction": Plausibility(
        0.0, np.inf, "a lip seal's torque is bounded by its size: at most "
        f"{SEAL_TANGENTIAL_FORCE_N_M / 1000:g} N/mm of circumference (radial lip load "
        "0.05-0.3 N/mm, friction coefficient <= 1) on a shaft no larger than the rotor",
        "Müller & Nau 1998 ch. 5", bounds=_seal_bounds),
    "oil_inertia": Plausibility(
        0.0, np.inf, "the entrained oil's I_V = int r^2 dV is at most that of oil turning "
        "rigidly in a housing twice the wetted radius and three times the wetted length, "
        "24 pi R^4 L", "rigid-body second moment of a cylinder", bounds=_inertia_bounds),
    "thermal_lag": Plausibility(
        -600.0, 600.0, "lumped time constants rho c V/(h A) of joint-sized oil volumes and "
        "sensor housings (rho c = 1.7e6 J/(m^3 K), V/A ~ 5 mm, h >= 15 W/(m^2 K)) stay below "
        "10 min either way", "Bergman et al. 2011 sec. 5.2"),
    "taylor_vortex_onset": Plausibility(
        0.0, 3.0, "the torque excess just above onset is of order one per unit "
        "(Ta/Ta_c)^2 - 1 in weakly nonlinear theory and in the measured torques",
        "Stuart 1958, JFM 4:1; Donnelly 1958, Proc. R. Soc. A 246:312"),
    "shear_thinning": Plausibility(
        0.0, 1e-6, "shear thinning needs a polymer-thickened liquid (straight mineral oils "
        "and gases are Newtonian at these shear rates); Cross time constants of "
        "VI-improved oils are below 1 ms (lambda^2 <= 1e-6 s^2)",
        "Bird, Armstrong & Hassager 1987 sec. 4.4; Cross 1965", needs_polymer=True),
    "sensor_delay": Plausibility(
        0.0, 2.0, "a power reading lags the speed by its averaging window and link latency: "
        "0.2 s for the IEC 61000-4-30 10/12-cycle interval, about 1 s for slow power "
        "analysers; 2 s is the bound", "IEC 61000-4-30:2015 sec. 5.2"),
    "film_heating": Plausibility(
        0.0, 1.0, "the film strength s scales the Nahme number of the smooth laminar film, "
        "c = s delta (1 + 3w)/(12 k A) with A = 2 pi R L (s = 1: the smooth-film theory, "
        "the mean rise of uniform dissipation with the walls held by w); the fit bounds s "
        "to [0, 1], and s at 1 is at the smooth-film theory's bound: a film hotter than "
        "the theory allows (walls above the sensor, w > 0, or another heating) is "
        "absorbed there", "Bird, Stewart & Lightfoot 2002 sec. 10.4; Nahme 1940"),
}
"""Plausible range of each library effect's coefficient, with its basis and reference."""

TIME_DEPENDENT = ("oil_inertia", "thermal_lag", "sensor_delay")
"""Effects that need a time record (rates of speed and temperature, lags, delays)."""
