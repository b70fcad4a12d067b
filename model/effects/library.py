"""Candidate effects the seed's viscous-loss model leaves out: the library.

Each effect is a physically named term with a formula, a reference, a stable
name and the sign its coefficient must have. The measured-data loop
(:mod:`oilgap.optim.calibration`) uses them as regression features: the
effect's power is ``coefficient * feature`` per sample; the synthetic rig
(:mod:`oilgap.studies.rigs.synth`) injects them into simulated data.

The physical laws live in :mod:`oilgap.model.effects.laws` (end-face discs,
bearing churning, seal friction, oil inertia, first-order lags, Taylor
vortices, shear thinning, sensor delay) and are re-exported here.

``bearing_ball_churning`` is the rolling bearing's friction and drag. For a case with a
``[bearing]`` its feature is that bearing's power under the case's model
(:func:`oilgap.model.bearing.bearing_power`, SKF's or Palmgren's [5]_), so the fitted
coefficient c is a correction factor on the bearing model: c = 1 means the model is
right. For a case without one it is Palmgren's load-independent loss with f0 = 1 at
the annulus' pitch diameter, and the coefficient is f0.

``bearing_ball_drag`` is the drag of the balls in the oil alone: SKF's V_M drag term of
the case's ``[bearing]`` (:func:`oilgap.model.bearing.bearing_vm_drag_power`), so the
fitted k is a drag scale (k = 1: the V_M term; balls as spheres in still oil give about
0.9). With ``bearing_ball_churning`` beside it the bearing's loss is
``c P_model + k P_V_M``: the rolling and sliding scale by c, the drag by about c + k.
Without a ``[bearing]`` it does not apply.

The library (:data:`EFFECTS`) maps each stable name to an :class:`Effect`
carrying its formula, reference, coefficient unit, sign constraint and the
function that turns an :class:`EffectContext` (per-sample arrays of a run set)
into the regression feature.

References
----------
.. [1] M. M. Cross, "Rheology of non-Newtonian fluids: a new flow equation for
   pseudoplastic systems", J. Colloid Sci. 20:417-437, 1965.
.. [2] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for
   a Deep-Sea Electric Manipulator*, Eqs. 3 and 4.
.. [3] The laws' own references: :mod:`oilgap.model.effects.laws`.
.. [4] H. Nahme, "Beiträge zur hydrodynamischen Theorie der Lagerreibung",
   Ing.-Arch. 11:191-209, 1940; the exact heated film: :mod:`oilgap.model.film_heating`.
.. [5] SKF's frictional-moment model; Palmgren's load-independent/load-dependent pair:
   :mod:`oilgap.model.bearing` and its references.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from ..bearing.friction import bearing_power, bearing_vm_drag_power
from ..errors import InputError
from ..film_heating import film_temperature, film_theory_coefficient
from ..regions import JointGeometry, region_power
from ..skin_friction import FrictionLaw
from ..taylor_couette import couette_reynolds, taylor_number
from .domains import DOMAINS, Domain
from .laws import (
    CRITICAL_TAYLOR_NUMBER,
    FREE_DISC_TRANSITION_RE,
    PALMGREN_MIN_NU_N,
    ball_churning_power,
    carreau_viscosity_ratio,
    couette_shear_rate,
    coulomb_friction_power,
    cross_viscosity_ratio,
    disc_reynolds,
    enclosed_disc_couette_power,
    end_face_disc_power,
    first_order_lag,
    free_disc_moment_coefficient,
    oil_inertia_power,
    palmgren_viscous_moment,
    sensor_delay_power,
    shear_thinning_power,
    taylor_excess_factor,
    taylor_vortex_power,
    thermal_lag_power,
)
from .plausibility import (
    PLAUSIBLE,
    SEAL_TANGENTIAL_FORCE_N_M,
    TIME_DEPENDENT,
    FluidFacts,
    Plausibility,
    RigFacts,
)

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..bearing.friction import BearingSpec
    from ..oil_state import OilState

__all__ = [
    "RegionState", "EffectContext", "Precomputed", "region_states", "effect_context",
    "cross_region_ratios", "Effect", "EFFECTS", "CONFOUNDED_FORMS", "get_effect",
    "FREE_DISC_TRANSITION_RE", "PALMGREN_MIN_NU_N", "CRITICAL_TAYLOR_NUMBER", "disc_reynolds",
    "free_disc_moment_coefficient", "end_face_disc_power", "enclosed_disc_couette_power",
    "palmgren_viscous_moment", "ball_churning_power", "coulomb_friction_power",
    "oil_inertia_power", "first_order_lag", "thermal_lag_power", "taylor_excess_factor",
    "film_temperature", "taylor_vortex_power", "couette_shear_rate", "cross_viscosity_ratio",
    "carreau_viscosity_ratio", "shear_thinning_power", "sensor_delay_power", "FluidFacts",
    "RigFacts", "Plausibility", "PLAUSIBLE", "TIME_DEPENDENT", "SEAL_TANGENTIAL_FORCE_N_M",
]


@dataclass(frozen=True, kw_only=True)
class RegionState:
    """One clearance region over the samples (arrays of length n, or floats).

    Attributes
    ----------
    name : str
        ``"rotor-stator"`` or ``"bearing"``.
    radius_m : float
        Rotation radius R [m].
    gap_m : ndarray
        Radial clearance per sample [m].
    length_m : float
        Length L [m].
    power_W : ndarray
        Viscous power of the region per sample [W].
    reynolds : ndarray
        Couette Reynolds number per sample [-] (seed Eq. 4).
    taylor : ndarray
        Taylor number per sample [-] (seed Eq. 3).
    """

    name: str
    radius_m: float
    gap_m: np.ndarray
    length_m: float
    power_W: np.ndarray
    reynolds: np.ndarray
    taylor: np.ndarray


@dataclass(frozen=True, kw_only=True)
class EffectContext:
    """Per-sample quantities the effect features need (SI arrays of length n).

    Build it with :func:`effect_context`. ``power_W`` is the clearance model's
    viscous power (the sum over ``regions``).

    Attributes
    ----------
    omega_rad_s : ndarray
        Rotor speed [rad/s].
    domega_dt_rad_s2 : ndarray
        Angular acceleration [rad/s^2].
    nu_m2_s : ndarray
        Kinematic viscosity [m^2/s].
    density_kg_m3 : ndarray
        Oil density [kg/m^3].
    dtemp_dt_K_s : ndarray
        Rate of change of the oil temperature [K/s].
    dpower_dt_W_s : ndarray
        Time derivative of the viscous power along the record [W/s].
    dpower_dtemp_W_K : ndarray
        Derivative of the viscous power with respect to the oil temperature [W/K]
        (NaN where the viscosity does not follow a temperature law).
    regions : tuple of RegionState
        The clearance regions over the samples.
    disc_radii_m : (float, float)
        Rotor end-face outer and inner radius [m].
    bearing_pitch_diameter_m : float or None
        Pitch diameter of the bearing [m]; None for a rig without a bearing region.
    bearing : BearingSpec or None
        The case's rolling bearing (``[bearing]``), if any: the ``bearing_ball_churning``
        feature is its power under its model.
    oil : OilState or None
        The oil state ``nu_m2_s`` and ``density_kg_m3`` were read from (measured,
        lagged or film-heated temperatures: :mod:`oilgap.model.oil_state`), if known.
    """

    omega_rad_s: np.ndarray
    domega_dt_rad_s2: np.ndarray
    nu_m2_s: np.ndarray
    density_kg_m3: np.ndarray
    dtemp_dt_K_s: np.ndarray
    dpower_dt_W_s: np.ndarray
    dpower_dtemp_W_K: np.ndarray
    regions: tuple[RegionState, ...]
    disc_radii_m: tuple[float, float]
    bearing_pitch_diameter_m: float | None
    bearing: BearingSpec | None = None
    oil: OilState | None = None

    @property
    def power_W(self) -> np.ndarray:
        """Viscous power of all regions [W] (sum over ``regions``)."""
        return sum(r.power_W for r in self.regions)


def region_states(geometry: JointGeometry, omega_rad_s, nu_m2_s, powers_W
                  ) -> tuple[RegionState, ...]:
    """Per-region state (geometry, power, Re of Eq. 4, Ta of Eq. 3) over the samples.

    Parameters
    ----------
    geometry : JointGeometry
        The joint's regions (:func:`oilgap.model.regions.joint_geometry`).
    omega_rad_s : float or array
        Rotor speed per sample [rad/s].
    nu_m2_s : float or array
        Kinematic viscosity per sample [m^2/s].
    powers_W : sequence of arrays
        Viscous power of each region per sample [W].

    Returns
    -------
    tuple of RegionState
        One per region: R, delta, L [m], power [W], Re [-], Ta [-].

    References
    ----------
    Seed paper (Eqs. 3-4) [2].
    """
    ones = np.ones_like(np.asarray(omega_rad_s * nu_m2_s, dtype=float))
    out = []
    for region, p in zip(geometry.regions, powers_W, strict=True):
        R, gap = region.radius_m, region.gap_m
        re = couette_reynolds(omega_rad_s, R, gap, nu_m2_s)
        out.append(RegionState(name=region.name, radius_m=R, gap_m=gap * ones,
                               length_m=region.length_m, power_W=p, reynolds=re,
                               taylor=taylor_number(re, gap, R)))
    return tuple(out)


@dataclass(frozen=True, kw_only=True)
class Precomputed:
    """What the caller of :func:`effect_context` already has (None: computed, or zero).

    Attributes
    ----------
    powers_W : sequence of arrays or None
        Viscous power of each region [W].
    dtemp_dt_K_s, dpower_dt_W_s, dpower_dtemp_W_K : array or None
        Oil temperature rate [K/s], viscous power's time and temperature slopes [W/s], [W/K].
    """

    powers_W: list | tuple | None = None
    dtemp_dt_K_s: np.ndarray | None = None
    dpower_dt_W_s: np.ndarray | None = None
    dpower_dtemp_W_K: np.ndarray | None = None


def effect_context(geometry: JointGeometry, omega_rad_s, domega_dt_rad_s2, nu_m2_s,
                   density_kg_m3, law: FrictionLaw | None, *, given: Precomputed | None = None,
                   oil: OilState | None = None) -> EffectContext:
    """The one builder of an :class:`EffectContext` (rig simulator and calibration alike).

    Parameters
    ----------
    geometry : JointGeometry
        Regions, end-face radii, bearing pitch diameter and rolling bearing (if any) of
        the joint.
    omega_rad_s : float or array
        Rotor speed per sample [rad/s].
    domega_dt_rad_s2 : float or array
        Angular acceleration per sample [rad/s^2].
    nu_m2_s : float or array
        Kinematic viscosity per sample [m^2/s].
    density_kg_m3 : float or array
        Oil density per sample [kg/m^3].
    law : FrictionLaw or None
        Friction law of the clearance model (used unless ``given.powers_W`` is given).
    given : Precomputed, optional
        Region powers [W] and derivatives along the record already computed.
    oil : OilState, optional
        The oil state ``nu_m2_s`` and ``density_kg_m3`` come from (kept for the record).

    Returns
    -------
    EffectContext
        All per-sample arrays broadcast to the samples' shape (SI).
    """
    g = Precomputed() if given is None else given
    powers_W = g.powers_W
    ones = np.ones_like(np.asarray(omega_rad_s * nu_m2_s, dtype=float))
    omega = np.asarray(omega_rad_s, dtype=float) * ones
    if powers_W is None:
        powers_W = [region_power(r, omega, nu_m2_s, density_kg_m3, law)
                    for r in geometry.regions]
    zeros = np.zeros_like(ones)
    return EffectContext(
        omega_rad_s=omega, domega_dt_rad_s2=np.asarray(domega_dt_rad_s2, dtype=float) * ones,
        nu_m2_s=nu_m2_s, density_kg_m3=density_kg_m3,
        dtemp_dt_K_s=zeros if g.dtemp_dt_K_s is None else g.dtemp_dt_K_s,
        dpower_dt_W_s=zeros if g.dpower_dt_W_s is None else g.dpower_dt_W_s,
        dpower_dtemp_W_K=zeros if g.dpower_dtemp_W_K is None else g.dpower_dtemp_W_K,
        regions=region_states(geometry, omega, nu_m2_s, powers_W),
        disc_radii_m=geometry.disc_radii_m,
        bearing_pitch_diameter_m=geometry.bearing_pitch_diameter_m,
        bearing=getattr(geometry, "bearing", None), oil=oil)


def cross_region_ratios(ctx: EffectContext, lam_s: float) -> list[np.ndarray]:
    """Cross viscosity ratio ``mu/mu_0`` of each region at its nominal shear rate [-] [1].

    ``1 / (1 + (lambda |omega| R_i / delta_i)^2)``: the full (not first-order)
    shear-thinning law, applied to each region's power by the rig simulator and
    by the calibration's exact form.

    Parameters
    ----------
    ctx : EffectContext
        Speeds [rad/s] and regions (R, delta [m]) of the samples.
    lam_s : float
        Cross time constant lambda [s].

    Returns
    -------
    list of ndarray
        ``mu / mu_0`` [-] of each region per sample, in the order of ``ctx.regions``.

    References
    ----------
    Cross [1].
    """
    return [cross_viscosity_ratio(couette_shear_rate(ctx.omega_rad_s, r.radius_m, r.gap_m),
                                  lam_s) for r in ctx.regions]


def _f_disc(c: EffectContext):
    r_o, r_i = c.disc_radii_m
    return end_face_disc_power(c.omega_rad_s, c.nu_m2_s, c.density_kg_m3, r_o, r_i)


def _f_churning(c: EffectContext):
    if c.bearing is not None:  # the case's bearing model: the coefficient corrects it
        return bearing_power(c.bearing, c.omega_rad_s, c.nu_m2_s)
    if c.bearing_pitch_diameter_m is None:
        return None
    return ball_churning_power(c.omega_rad_s, c.nu_m2_s, c.bearing_pitch_diameter_m, 1.0)


def _f_ball_drag(c: EffectContext):
    if c.bearing is None:  # the drag term needs the bearing's rings (d, D)
        return None
    return bearing_vm_drag_power(c.bearing, c.omega_rad_s)


def _f_seal(c: EffectContext):
    return coulomb_friction_power(c.omega_rad_s, 1.0)


def _f_inertia(c: EffectContext):
    return oil_inertia_power(c.omega_rad_s, c.domega_dt_rad_s2, c.density_kg_m3, 1.0)


def _f_thermal(c: EffectContext):
    d = np.nan_to_num(np.asarray(c.dpower_dtemp_W_K, dtype=float), nan=0.0)
    return thermal_lag_power(d, c.dtemp_dt_K_s, 1.0)


def _f_film(c: EffectContext):  # per unit strength s: c_theory P dP/dT, isothermal walls
    d = np.nan_to_num(np.asarray(c.dpower_dtemp_W_K, dtype=float), nan=0.0)
    g = c.regions[0]
    return d * c.power_W * film_theory_coefficient(float(np.max(g.gap_m)), g.radius_m,
                                                   g.length_m)


def taylor_feature(c: EffectContext, exponent: float = 2.0):
    """Taylor-vortex power per unit k [W]: ``sum_i P_i max(0, (Ta_i/41.3)^m - 1)``.

    Parameters
    ----------
    c : EffectContext
        Regions' power [W] and Taylor number [-] per sample.
    exponent : float
        Shape exponent m [-] (2: Stuart 1958 near onset; 0.5: Wendt 1933).

    Returns
    -------
    array
        Feature [W per unit k].

    References
    ----------
    Stuart, J. Fluid Mech. 4:1, 1958; Wendt, Ing.-Arch. 4:577, 1933 (through
    :func:`~oilgap.model.effects.laws.taylor_vortex_power`).
    """
    return sum(taylor_vortex_power(r.power_W, r.taylor, 1.0, exponent=exponent)
               for r in c.regions)


def _f_taylor(c: EffectContext):
    return taylor_feature(c)


def _f_shear(c: EffectContext):
    return sum(shear_thinning_power(r.power_W, couette_shear_rate(c.omega_rad_s, r.radius_m,
                                                                  r.gap_m), 1.0)
               for r in c.regions)


def _f_delay(c: EffectContext):
    return sensor_delay_power(c.dpower_dt_W_s, 1.0)


@dataclass(frozen=True, kw_only=True)
class Effect:
    """A candidate effect of the library.

    Attributes
    ----------
    name : str
        Stable identifier (used in JSON, CLI and tests).
    title : str
        Human-readable name.
    formula : str
        The term as the loop adds it, in plain text.
    reference : str
        Source of the law.
    coefficient : str
        Symbol and meaning of the fitted coefficient.
    unit : str
        Unit of the coefficient ("-", "N m", "m^5", "s", "s^2", "K/W").
    nonnegative : bool
        True if physics demands coefficient >= 0 (dissipation, positive inertia,
        causality); False if either sign is physical.
    feature : callable
        EffectContext -> per-sample power per unit coefficient [W/unit] (None if
        the effect cannot act on that rig, e.g. no bearing region).
    strength_unit : str
        Unit of the synthetic rig's ``--strength``.
    coefficient_from_strength : callable
        Maps the strength [strength_unit] to the coefficient [unit].
    strength_from_coefficient : callable
        The inverse.
    plausible : Plausibility or None
        Physically plausible range of the coefficient [unit], with its basis and
        reference; a fit outside it is "implausible" and not accepted.
    time_dependent : bool
        True if the effect needs a time record (rates or lags): not a candidate
        on steady-point data.
    upper : float
        Upper bound of the coefficient in the fit [unit] (inf: none; 1 for the film
        strength, the smooth-film theory's bound).
    domain : Domain or None
        Where the mechanism can act (:mod:`.domains`): data outside it, not a candidate.
    """

    name: str
    title: str
    formula: str
    reference: str
    coefficient: str
    unit: str
    nonnegative: bool
    feature: Callable[[EffectContext], np.ndarray | None]
    strength_unit: str
    coefficient_from_strength: Callable[[float], float] = float
    strength_from_coefficient: Callable[[float], float] = float
    plausible: Plausibility | None = None
    time_dependent: bool = False
    upper: float = np.inf
    domain: Domain | None = None

    def implausibility(self, coefficient: float, facts: RigFacts) -> str | None:
        """Why a fitted coefficient is implausible on this rig, or None if it is plausible.

        Parameters
        ----------
        coefficient : float
            Fitted coefficient [``unit``].
        facts : RigFacts
            The rig's size and fluids.

        Returns
        -------
        str or None
            The reason (the range, its basis and reference), or None.
        """
        return None if self.plausible is None else self.plausible.check(
            self.coefficient.split(" (")[0], coefficient, self.unit, facts)

    def feature_values(self, ctx: EffectContext) -> np.ndarray | None:
        """The feature column [W per unit coefficient], or None if not applicable.

        Parameters
        ----------
        ctx : EffectContext
            Per-sample quantities (SI).

        Returns
        -------
        ndarray or None
            Power per unit coefficient at each sample [W/unit].
        """
        f = self.feature(ctx)
        return None if f is None else np.asarray(f, dtype=float) * np.ones_like(ctx.omega_rad_s)


def _signed_sqrt(x: float) -> float:
    return float(np.sign(x) * np.sqrt(abs(x)))


EFFECTS: dict[str, Effect] = {e.name: e for e in (
    Effect(name="end_face_disc", title="rotor end-face disc friction",
           formula="k * C_M rho |w|^3 (D^5 - D_i^5)/64, C_M = 3.87 Re_r^-0.5 (0.146 Re_r^-0.2 > "
                   "3e5), Re_r = |w| r_o^2/nu",
           reference="Pyrhönen et al. 2014 sec. 9.5; Schlichting & Gersten 2017 sec. 5.3.3",
           coefficient="k (multiple of the free-disc value, both faces)", unit="-",
           nonnegative=True, feature=_f_disc, strength_unit="-"),
    Effect(name="bearing_ball_churning", title="bearing ball churning",
           formula="M_0 |w|, M_0 = 1e-7 f0 (nu[cSt] n[rpm])^(2/3) d_m[mm]^3 N mm, "
           "d_m = 2 R2 + delta2",
           reference="Palmgren 1959; Harris & Kotzalas 2006 ch. 9; with [bearing]: SKF catalogue "
           "'Friction' (10000 EN) or Palmgren",
           coefficient="f0 or c (Palmgren factor; with [bearing]: c multiplies the case's bearing "
           "model P_bearing(w, nu) of oilgap.model.bearing, 1 = the model is right)", unit="-",
           nonnegative=True, feature=_f_churning, strength_unit="-"),
    Effect(name="bearing_ball_drag", title="drag of the bearing's balls in the oil",
           formula="k * 0.4 V_M K_ball d_m[mm]^5 n[rpm]^2 |w| N mm (SKF's V_M drag term of the "
           "case's [bearing])",
           reference="SKF catalogue 'Friction' (10000 EN), drag losses; balls as spheres in still "
           "oil: Schiller & Naumann 1933 (docs/bearing.md#the-bearing-model-band)",
           coefficient="k (drag scale: multiple of SKF's V_M drag term; with "
                       "bearing_ball_churning the drag is scaled by about c + k)", unit="-",
                       nonnegative=True, feature=_f_ball_drag,
           strength_unit="-"),
    Effect(name="seal_coulomb_friction", title="seal / Coulomb friction", formula="tau_c |w|",
           reference="Coulomb friction; Müller & Nau 1998 ch. 5 (lip-seal torque)",
           coefficient="tau_c (friction torque)", unit="N m", nonnegative=True, feature=_f_seal,
           strength_unit="N m"),
    Effect(name="oil_inertia", title="entrained oil inertia", formula="rho I_V w dw/dt",
           reference="kinetic energy of oil turning with the rotor, d/dt(J w^2/2), J = rho I_V",
           coefficient="I_V (second moment of the entrained oil volume)", unit="m^5",
           nonnegative=True, feature=_f_inertia, strength_unit="m^5"),
    Effect(name="thermal_lag", title="thermal lag of the gap oil",
           formula="-tau (dP/dT) dT/dt  (T_oil = T_meas/(1 + tau s), first order)",
           reference="lumped-capacitance first-order response, Bergman et al. 2011 sec. 5.2",
           coefficient="tau (lag of the gap oil behind the measured temperature; < 0: it leads)",
           unit="s", nonnegative=False, feature=_f_thermal, strength_unit="s"),
    Effect(name="taylor_vortex_onset", title="Taylor-vortex onset",
           formula="k * sum_i P_i max(0, (Ta_i/41.3)^2 - 1)",
           reference="Taylor 1923; Stuart 1958 (JFM 4:1); Donnelly 1958",
           coefficient="k (torque excess per unit supercriticality)", unit="-", nonnegative=True,
           feature=_f_taylor, strength_unit="-"),
    Effect(name="shear_thinning", title="shear thinning of the oil",
           formula="-lambda^2 * sum_i (|w| R_i/delta_i)^2 P_i  (Cross mu/mu0 = 1/(1+(lambda g)^2), "
           "first order)",
           reference="Cross 1965; Bird, Armstrong & Hassager 1987 sec. 4.4 (Carreau)",
           coefficient="lambda^2 (Cross time constant squared)", unit="s^2", nonnegative=True,
           feature=_f_shear, strength_unit="s",
           coefficient_from_strength=lambda s: float(s) ** 2,
           strength_from_coefficient=_signed_sqrt),
    Effect(name="sensor_delay", title="power-sensor delay",
           formula="-d dP/dt  (P_meas(t) = P(t - d))",
           reference="first-order expansion of a time shift (dead time)",
           coefficient="d (delay of the power reading behind the speed reading)", unit="s",
           nonnegative=True, feature=_f_delay, strength_unit="s"),
    Effect(name="film_heating", title="viscous heating of the film",
           formula="c P dP/dT, c = s delta (1 + 3w)/(12 k 2 pi R L)  (T_film = T_meas + c "
                   "P(T_film), first order)",
           reference="Nahme 1940 (Ing.-Arch. 11:191), the lumped film of "
                     "oilgap.model.film_heating",
           coefficient="s (film strength: 1 = the smooth-film theory; wall "
                       "condition w held unless identified)", unit="-", nonnegative=True,
                       feature=_f_film,
           strength_unit="-", upper=1.0),
)}
"""The candidate-effect library, by stable name."""

EFFECTS = {n: replace(e, plausible=PLAUSIBLE[n], time_dependent=n in TIME_DEPENDENT,
                      domain=DOMAINS[n]) for n, e in EFFECTS.items()}  # ranges, time, domain

CONFOUNDED_FORMS = {
    "enclosed_disc_couette": (
        "pi mu w^2 (r_o^4 - r_i^4)/s per face (Daily & Nece 1960 regime I): scales as "
        "mu w^2 and does not depend on T, exactly like the bearing region's laminar loss; "
        "on any data it is absorbed into the fitted C and cannot be named"),
}
"""Physical terms deliberately left out of the candidates, with the reason."""


def get_effect(name: str) -> Effect:
    """The library effect of that stable name.

    Parameters
    ----------
    name : str
        Stable name, e.g. ``"seal_coulomb_friction"`` [-].

    Returns
    -------
    Effect
        Formula, reference, coefficient unit and feature of the effect.

    Raises
    ------
    InputError
        Unknown name; the message lists the library.
    """
    if name not in EFFECTS:
        raise InputError("effect", name, f"library effects are {', '.join(EFFECTS)}")
    return EFFECTS[name]
