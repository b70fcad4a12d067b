"""A rolling bearing running in oil: SKF's frictional-moment model and Palmgren's pair.

A deep-groove ball bearing in an oil-filled joint runs fully submerged. Its friction
moment [N m] is given by one of two published models (``BearingSpec.model``):

``skf`` (SKF catalogue, "Friction" [1]_, [2]_)
    ``M = phi_ish phi_rs M_rr + M_sl + M_drag`` with the rolling moment
    ``M_rr = G_rr (nu n)^0.6``, the sliding moment ``M_sl = G_sl mu_sl``, the
    inlet-shear and replenishment factors and the drag of the balls in the oil
    bath. SKF's drag is ``M_drag = 0.4 V_M K_ball dm^5 n^2 + 1.093e-7 n^2 dm^3
    (n dm^2 f_t/nu)^-1.379 R_s``; the option ``drag`` says which of its terms are
    kept: ``"skf-vm-term"`` (the V_M term only, the default: not SKF's full model,
    see docs/bearing.md), ``"skf-full"`` (both terms, SKF's equation) or ``"none"``
    (no drag: rolling and sliding only). Seal moments are not modelled (an
    oil-filled joint's bearing runs open).
``palmgren`` (Palmgren [3]_, Harris & Kotzalas [4]_)
    ``M = M_0 + M_1``: ``M_0 = 1e-7 f_0 (nu n)^(2/3) dm^3``, ``M_1 = f_1 P_1 dm``.

Both are written in catalogue units (N mm, r/min, mm^2/s, mm, N) in
:mod:`oilgap.model.bearing.laws`;
:func:`bearing_moment_terms` converts SI to catalogue units and back, once, through
:mod:`oilgap.model.units`. Every law takes floats, numpy arrays (duty-cycle nodes along
the last axis) and CasADi symbols in speed and viscosity. The SKF terms are smooth
in nu > 0; Palmgren's floor at ``nu n = 2000`` is a kink (see
:func:`palmgren_viscous_moment`). docs/bearing.md has the physics, the constants with
their sources, the validity ranges and the verification.

References
----------
.. [1] SKF, *Rolling bearings*, catalogue 10000 EN (2013) / 17000 EN (2018), section
   "Friction": the SKF model (phi_ish, phi_rs, K_rs, K_Z, drag terms, V_M diagram,
   R1/R2/S1/S2 table), as transcribed by three independent public implementations.
.. [2] SKF, *General Catalogue* 6000 EN, "Friction", pp. 100-106 (Table 2a: G_rr and
   G_sl of deep-groove ball bearings, mu_sl, phi_bl, mu_bl, mu_EHL), read.
.. [3] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., Burbank 1959.
.. [4] T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th
   ed., CRC 2006, ch. 9 (M_0, M_1, f_0, z, y).
.. [5] ISO 76:2006, *Rolling bearings -- Static load ratings* (C_0 = f_0 Z D_w^2 cos a,
   table of f_0 for radial ball bearings; recalled).
.. [6] ISO 281:2007, *Rolling bearings -- Dynamic load ratings and rating life* (rated
   viscosity nu_1; recalled, exponents checked against the SKF diagram).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import casadi as ca
import numpy as np

from .. import _math as m
from ..errors import InputError, OilgapWarning
from ..units import m2_s_to_cst, m_to_mm, mm_to_m, rad_s_to_rpm
from ..viscous_loss import weighted_mean
from .laws import (
    F0_OIL_BATH,
    F0_SUBMERGED,
    K_RS_OIL_BATH,
    MU_BL_DEFAULT,
    MU_EHL_MINERAL,
    PALMGREN_MIN_NU_N,
    SERIES_CONSTANTS,
    ball_drag_constant,
    drag_loss_factor,
    drag_rs_moment,
    drag_vm_moment,
    inlet_shear_factor,
    iso_static_load_rating,
    palmgren_load_moment,
    palmgren_viscous_moment,
    rated_viscosity,
    replenishment_factor,
    rolling_load_factor,
    sliding_friction_coefficient,
    sliding_load_factor,
)
from .skf_speed import boundary_film_speed, inlet_shear_speed

MODELS = ("skf", "palmgren")
"""Friction models [-]."""
KINDS = ("deep-groove-ball",)
"""Bearing types the models are implemented for [-]."""
DRAG_CHOICES = ("skf-vm-term", "skf-full", "none")
"""Terms of SKF's drag kept [-]: the V_M term alone (the default; not SKF's full model),
both the V_M and R_s terms (SKF's equation), or no drag (rolling and sliding only)."""
DRAG_ALIASES = {"vm": "skf-vm-term", "vm+rs": "skf-full"}
"""Former names of the drag options [-], read with a deprecation OilgapWarning (a saved
case still reads; it is written back under the new name)."""
OMEGA_FLOOR_RAD_S = 1.0e-300
"""Floor of a CasADi |omega| in the moments [rad/s] (finite derivatives at rest)."""


@dataclass(frozen=True, kw_only=True)
class BearingSpec:
    """A rolling bearing of the joint and how its friction is modelled [SI].

    Built by :func:`oilgap.model.bearing.catalogue.bearing_spec_from` from a
    ``[bearing]`` table; validation names the TOML key (``bore_mm``, ...).

    Attributes
    ----------
    name : str
        Label in outputs [-] (the designation by default).
    bore_m, outside_m : float
        Bore d and outside diameter D [m].
    balls : int
        Number of balls Z [-] (not an input of either model).
    ball_diameter_m : float
        Ball diameter D_w [m] (not an input of either model).
    radial_load_N, axial_load_N : float
        Radial load F_r and axial load F_a [N].
    series : str or None
        Key of :data:`SERIES_CONSTANTS` (``"618"``) [-]; required by ``skf``.
    model : str
        ``"skf"`` or ``"palmgren"`` [-].
    kind : str
        Bearing type, ``"deep-groove-ball"`` [-] (TOML ``type``).
    width_m : float or None
        Width B [m] (not an input of either model).
    static_load_rating_N : float or None
        Basic static load rating C_0 [N]; None: the ISO 76 estimate from the balls.
    submerged : bool
        Fully submerged (H >= 1.2 dm) [-]; False needs ``oil_level_m``.
    oil_level_m : float or None
        Oil level H above the lowest point of the outer ring's bore [m] (not submerged).
    f0 : float or None
        Palmgren factor f_0 [-]; None: 4 submerged, 2 in an oil bath.
    drag : str
        Terms of SKF's drag kept [-]: ``"skf-vm-term"``, ``"skf-full"`` or ``"none"``
        (:data:`DRAG_CHOICES`; the former ``"vm"`` and ``"vm+rs"`` are read with a
        deprecation warning, :data:`DRAG_ALIASES`).
    mu_ehl, mu_bl : float
        Full-film and boundary sliding coefficients [-].
    k_rs : float or None
        Replenishment constant K_rs [-]; 0 = flooded; None: 0 submerged, 3e-8 otherwise.
    designation : str or None
        Catalogue designation the spec was built from (``"61809"``) [-].
    drag_scale : float
        Factor on SKF's drag terms [-] (>= 0; 1: SKF's; the loop's
        ``bearing_ball_drag`` calibrates such a factor, and an ``[uncertainty]`` input
        draws it); Palmgren's model has no separate drag term, so it has no effect there.
    defaults_used : tuple of str
        TOML keys the tool filled in [-] (shown in outputs).
    """

    name: str
    bore_m: float
    outside_m: float
    balls: int
    ball_diameter_m: float
    radial_load_N: float
    series: str | None = None
    model: str = "skf"
    kind: str = "deep-groove-ball"
    width_m: float | None = None
    axial_load_N: float = 0.0
    static_load_rating_N: float | None = None
    submerged: bool = True
    oil_level_m: float | None = None
    f0: float | None = None
    drag: str = DRAG_CHOICES[0]
    mu_ehl: float = MU_EHL_MINERAL
    mu_bl: float = MU_BL_DEFAULT
    k_rs: float | None = None
    designation: str | None = None
    drag_scale: float = 1.0
    defaults_used: tuple[str, ...] = ()

    def __post_init__(self):
        where = f"[bearing] {self.name}"
        _choice("model", self.model, MODELS, where)
        _choice("type", self.kind, KINDS, where)
        if self.drag in DRAG_ALIASES:
            new = DRAG_ALIASES[self.drag]
            warnings.warn(OilgapWarning(
                f"{where}: drag = {self.drag!r} is deprecated; it reads as drag = {new!r}, "
                "the name that says what it contains (docs/bearing.md)"), stacklevel=3)
            object.__setattr__(self, "drag", new)
        _choice("drag", self.drag, DRAG_CHOICES, where)
        if self.model == "skf" and self.series not in SERIES_CONSTANTS:
            raise InputError("series", self.series, "a deep-groove series of the SKF "
                             f"constants table: {', '.join(SERIES_CONSTANTS)} (or give "
                             "a designation)", where)
        for key, v in (("bore_mm", self.bore_m), ("outside_mm", self.outside_m),
                       ("ball_diameter_mm", self.ball_diameter_m)):
            _positive(key, m_to_mm(v), where)
        if self.outside_m <= self.bore_m:
            raise InputError("outside_mm", m_to_mm(self.outside_m),
                             f"larger than bore_mm = {m_to_mm(self.bore_m):g}", where)
        if self.width_m is not None:
            _positive("width_mm", m_to_mm(self.width_m), where)
        if isinstance(self.balls, bool) or not isinstance(self.balls, int) or self.balls < 1:
            raise InputError("balls", self.balls, "a whole number >= 1", where)
        for key in ("radial_load_N", "axial_load_N", "mu_ehl", "mu_bl", "drag_scale"):
            _non_negative(key, getattr(self, key), where)
        if self.static_load_rating_N is not None:
            _positive("static_load_rating_N", self.static_load_rating_N, where)
        self._check_lubrication(where)

    def _check_lubrication(self, where: str) -> None:
        if not isinstance(self.submerged, bool):
            raise InputError("submerged", self.submerged, "true or false", where)
        if self.submerged and self.oil_level_m is not None:
            raise InputError("oil_level_mm", m_to_mm(self.oil_level_m), "absent for a "
                             "submerged bearing (set submerged = false)", where)
        if not self.submerged:
            if self.oil_level_m is None:
                raise InputError("oil_level_mm", None, "a level > 0 when submerged = "
                                 "false", where)
            _positive("oil_level_mm", m_to_mm(self.oil_level_m), where)
        if self.f0 is None:
            object.__setattr__(self, "f0", F0_SUBMERGED if self.submerged else F0_OIL_BATH)
        _positive("f0", self.f0, where)
        if self.k_rs is None:
            object.__setattr__(self, "k_rs", 0.0 if self.submerged else K_RS_OIL_BATH)
        _non_negative("k_rs", self.k_rs, where)

    @property
    def pitch_diameter_m(self) -> float:
        """Pitch (mean) diameter ``dm = (d + D)/2`` [m]."""
        return 0.5 * (self.bore_m + self.outside_m)

    @property
    def static_rating_N(self) -> float:
        """C_0 [N]: the given rating, or the ISO 76 estimate from the ball set."""
        if self.static_load_rating_N is not None:
            return float(self.static_load_rating_N)
        return iso_static_load_rating(self.balls, m_to_mm(self.ball_diameter_m),
                                      m_to_mm(self.pitch_diameter_m))

    @property
    def oil_level_ratio(self) -> float:
        """Oil level over pitch diameter H/dm [-] (1.2, the plateau, when submerged)."""
        if self.submerged:
            return 1.2
        return min(float(self.oil_level_m / self.pitch_diameter_m), 1.2)


def _choice(key, value, allowed, where):
    if value not in allowed:
        raise InputError(key, value, f"one of {', '.join(allowed)}", where)


def _positive(key, value, where):
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(value) or value <= 0:
        raise InputError(key, value, "a finite number > 0", where)


def _non_negative(key, value, where):
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(value) or value < 0:
        raise InputError(key, value, "a finite number >= 0", where)


def skf_speed_terms(spec: BearingSpec, speed_rpm) -> dict:
    """The parts of :func:`skf_moments` that depend on the speed alone [1]_, [2]_.

    Parameters
    ----------
    spec : BearingSpec
        The bearing.
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm].

    Returns
    -------
    dict
        ``n^0.6`` [rpm^0.6], ``inlet_shear`` and ``boundary_film`` (:mod:`.skf_speed`)
        [-], ``drag_vm`` [N mm] (before ``drag_scale``).
    """
    c = SERIES_CONSTANTS[spec.series]
    d, D = m_to_mm(spec.bore_m), m_to_mm(spec.outside_m)
    dm = 0.5 * (d + D)
    k_ball = ball_drag_constant(d, D, c.k_z, c.ball_rows)
    vm = (drag_vm_moment(speed_rpm, dm, k_ball, drag_loss_factor(spec.oil_level_ratio))
          if spec.drag != "none" else 0.0 * speed_rpm)
    return {"n^0.6": speed_rpm**0.6, "inlet_shear": inlet_shear_speed(speed_rpm, dm),
            "boundary_film": boundary_film_speed(speed_rpm), "drag_vm": vm}


def skf_moments(spec: BearingSpec, speed_rpm, nu_cSt, speed: dict | None = None) -> dict:
    """Every term of SKF's frictional moment [N mm] [1]_, [2]_ (catalogue units).

    ``rolling = phi_ish phi_rs G_rr nu^0.6 n^0.6``, ``sliding = G_sl mu_sl``,
    ``drag_vm`` (0 when ``spec.drag == "none"``), ``drag_rs`` (0 unless
    ``spec.drag == "skf-full"``). The powers of nu and n are taken separately, so that a
    symbolic nu has finite derivatives at n = 0.

    Parameters
    ----------
    spec : BearingSpec
        The bearing (series constants, d, D, loads, lubrication).
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm].
    nu_cSt : float, array or CasADi symbol
        Kinematic viscosity [cSt].
    speed : dict, optional
        :func:`skf_speed_terms` of ``speed_rpm``, if already evaluated (the same numbers).

    Returns
    -------
    dict
        ``rolling``, ``sliding``, ``drag_vm``, ``drag_rs`` [N mm].
    """
    c = SERIES_CONSTANTS[spec.series]
    d, D = m_to_mm(spec.bore_m), m_to_mm(spec.outside_m)
    dm = 0.5 * (d + D)
    fr, fa, c0 = spec.radial_load_N, spec.axial_load_N, spec.static_rating_N
    g_rr = rolling_load_factor(c, dm, fr, fa, c0)
    g_sl = sliding_load_factor(c, dm, fr, fa, c0)
    sp = skf_speed_terms(spec, speed_rpm) if speed is None else speed
    reduction = (inlet_shear_factor(speed_rpm, nu_cSt, dm, sp["inlet_shear"])
                 * replenishment_factor(speed_rpm, nu_cSt, d, D, spec.k_rs, c.k_z))
    rs = (drag_rs_moment(speed_rpm, nu_cSt, d, D, spec.oil_level_ratio, c.k_z)
          if spec.drag == "skf-full" else 0.0 * speed_rpm)
    vm = sp["drag_vm"]
    if spec.drag_scale != 1.0:  # a scenario's factor (1: SKF's terms, bit for bit)
        rs, vm = spec.drag_scale * rs, spec.drag_scale * vm
    return {
        "rolling": reduction * g_rr * nu_cSt**0.6 * sp["n^0.6"],
        "sliding": g_sl * sliding_friction_coefficient(speed_rpm, nu_cSt, dm, spec.mu_bl,
                                                       spec.mu_ehl, sp["boundary_film"]),
        "drag_vm": vm,
        "drag_rs": rs,
    }


# --------------------------------------------------------------------------- SI interface


def bearing_moment_terms(spec: BearingSpec, omega_rad_s, nu_m2_s, speed: dict | None = None
                         ) -> dict:
    """Friction moment of every term of the bearing's model [N m].

    ``skf``: ``rolling``, ``sliding``, ``drag_vm``, ``drag_rs`` (:func:`skf_moments`);
    ``palmgren``: ``load_independent`` (:func:`palmgren_viscous_moment`),
    ``load_dependent`` (:func:`palmgren_load_moment`). Every term has the broadcast
    shape of omega and nu. A CasADi omega is floored at
    :data:`OMEGA_FLOOR_RAD_S` so that derivatives stay finite at rest (the moments there
    are below 1e-170 N m; numpy input is not floored).

    Parameters
    ----------
    spec : BearingSpec
        The bearing.
    omega_rad_s : float, array or CasADi symbol
        Shaft speed [rad/s] (sign ignored); nodes along the last axis.
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity of the oil [m^2/s].
    speed : dict, optional
        ``skf``: :func:`skf_speed_terms` at ``|omega|`` in rpm, if already evaluated.

    Returns
    -------
    dict
        Term name -> moment [N m].

    References
    ----------
    SKF [1]_, [2]_; Palmgren [3]_; Harris & Kotzalas [4]_.
    """
    w = m.fabs(omega_rad_s)
    if m.is_symbolic(omega_rad_s):  # finite CasADi derivatives at rest (n^0.6 at n = 0)
        w = m.fmax(w, OMEGA_FLOOR_RAD_S)
    n = rad_s_to_rpm(w)
    nu = m2_s_to_cst(nu_m2_s)
    zero = 0.0 * n * nu
    if spec.model == "skf":
        terms = skf_moments(spec, n, nu, speed)
    else:
        dm = m_to_mm(spec.pitch_diameter_m)
        terms = {"load_independent": palmgren_viscous_moment(nu, n, dm, spec.f0),
                 "load_dependent": palmgren_load_moment(
                     dm, spec.radial_load_N, spec.axial_load_N, spec.static_rating_N)}
    return {k: mm_to_m(v) + zero for k, v in terms.items()}


def palmgren_viscous_torque(omega_rad_s, nu_m2_s, pitch_diameter_m, f0=1.0):
    """Palmgren's load-independent moment in SI [N m]: the catalogue-unit law
    :func:`~oilgap.model.bearing.laws.palmgren_viscous_moment` converted once, for the
    loop's ``bearing_ball_churning`` effect and a linear drive's screw [3]_, [4]_.

    Parameters
    ----------
    omega_rad_s : float, array or CasADi symbol
        Speed [rad/s] (sign ignored).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].
    pitch_diameter_m : float
        Pitch diameter d_m [m].
    f0 : float
        Palmgren factor [-].

    Returns
    -------
    float, array or CasADi expression
        Moment M_0 [N m] (>= 0).
    """
    n = rad_s_to_rpm(m.fabs(omega_rad_s))
    moment_Nmm = palmgren_viscous_moment(m2_s_to_cst(nu_m2_s), n, m_to_mm(pitch_diameter_m), f0)
    return mm_to_m(moment_Nmm)


def bearing_torque(spec: BearingSpec, omega_rad_s, nu_m2_s):
    """Friction torque of the bearing [N m], opposing rotation (sign of omega; 0 at rest).

    Parameters
    ----------
    spec : BearingSpec
        The bearing.
    omega_rad_s : float, array or CasADi symbol
        Shaft speed [rad/s].
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].

    Returns
    -------
    float, array or CasADi expression
        Torque [N m].

    References
    ----------
    Sum of :func:`bearing_moment_terms` (SKF [1]_, Palmgren [3]_).
    """
    return sum(bearing_moment_terms(spec, omega_rad_s, nu_m2_s).values()) \
        * m.sign(omega_rad_s)


def bearing_power(spec: BearingSpec, omega_rad_s, nu_m2_s, speed: dict | None = None):
    """Friction power of the bearing ``M |omega|`` [W].

    Parameters
    ----------
    spec : BearingSpec
        The bearing.
    omega_rad_s : float, array or CasADi symbol
        Shaft speed [rad/s] (sign ignored).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s].
    speed : dict, optional
        ``skf``: :func:`skf_speed_terms` at ``|omega|`` in rpm, if already evaluated.

    Returns
    -------
    float, array or CasADi expression
        Power [W] (0 at rest).

    References
    ----------
    Power = moment x angular speed; moments of SKF [1]_ or Palmgren [3]_.
    """
    return sum(bearing_moment_terms(spec, omega_rad_s, nu_m2_s, speed).values()) \
        * m.fabs(omega_rad_s)


def bearing_mean_power(spec: BearingSpec, nodes_rad_s, weights, nu_m2_s,
                       speed: dict | None = None):
    """Mean friction power of the bearing over a duty cycle's speed distribution [W].

    Parameters
    ----------
    spec : BearingSpec
        The bearing.
    nodes_rad_s : array or CasADi DM
        Distinct ``|omega|`` of the cycle [rad/s]
        (:meth:`~oilgap.model.duty_cycle.DutyCycle.speed_distribution`).
    weights : array
        Their time weights [-] (sum 1).
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity [m^2/s]: a scalar, or numpy with a trailing axis of 1
        (shape ``(..., 1)``) to broadcast against the nodes.
    speed : dict, optional
        ``skf``: :func:`skf_speed_terms` at the nodes in rpm, if already evaluated (the
        vectorised rows keep them between temperatures).

    Returns
    -------
    float, array or CasADi expression
        Mean power [W] (shape of nu without its trailing axis).

    References
    ----------
    The cycle mean of :func:`bearing_power` by
    :func:`~oilgap.model.viscous_loss.weighted_mean`.
    """
    if m.is_symbolic(nu_m2_s) and not m.is_symbolic(nodes_rad_s):
        nodes_rad_s = ca.DM(np.asarray(nodes_rad_s, dtype=float))
    return weighted_mean(bearing_power(spec, nodes_rad_s, nu_m2_s, speed), weights)


@dataclass(frozen=True)
class BearingValidity:
    """Where a bearing's operating point lies against its models' ranges.

    Attributes
    ----------
    rated_viscosity_cSt : float
        nu_1 at the speed and pitch diameter (ISO 281 form) [cSt].
    kappa : float
        Viscosity ratio nu/nu_1 [-] (normal bearing practice: 1 to 4).
    speed_factor_mm_rpm : float
        n dm [mm rpm].
    notes : tuple of str
        One sentence per range the point is outside [-].
    """

    rated_viscosity_cSt: float
    kappa: float
    speed_factor_mm_rpm: float
    notes: tuple[str, ...]


def bearing_validity(spec: BearingSpec, omega_rad_s: float, nu_m2_s: float) -> BearingValidity:
    """The viscosity ratio and speed factor of an operating point, with warnings.

    Parameters
    ----------
    spec : BearingSpec
        The bearing.
    omega_rad_s : float
        Representative (peak) speed [rad/s], nonzero.
    nu_m2_s : float
        Operating viscosity [m^2/s].

    Returns
    -------
    BearingValidity
        nu_1 [cSt], kappa [-], n dm [mm rpm] and the notes.

    References
    ----------
    ISO 281 [6]_ (nu_1); SKF [1]_ (drag-term limit as implemented by [1]_'s
    transcriptions); Harris & Kotzalas [4]_.
    """
    n = float(rad_s_to_rpm(abs(omega_rad_s)))
    nu = float(m2_s_to_cst(nu_m2_s))
    dm = float(m_to_mm(spec.pitch_diameter_m))
    nu1 = rated_viscosity(n, dm)
    kappa = nu / nu1
    notes = []
    if not 1.0 <= kappa <= 4.0:
        notes.append(f"viscosity ratio kappa = {kappa:.3g} outside 1-4 (nu_1 = {nu1:.3g} "
                     "cSt): the bearing friction models are extrapolated")
    if spec.model == "skf" and spec.drag == "skf-full":
        limit = 250.0 if spec.oil_level_ratio * dm > 0.5 * m_to_mm(spec.outside_m) else 500.0
        if nu > limit:
            notes.append(f"nu = {nu:.4g} cSt above the SKF R_s drag term's limit "
                         f"{limit:g} cSt")
    if spec.model == "palmgren" and nu * n < PALMGREN_MIN_NU_N:
        notes.append(f"nu n = {nu * n:.4g} < 2000: Palmgren's M_0 is its constant floor")
    return BearingValidity(nu1, kappa, n * dm, tuple(notes))


def bearing_vm_drag_power(spec: BearingSpec, omega_rad_s):
    """Power of SKF's V_M drag term of the bearing, whatever its model [W] [1]_.

    ``0.4 V_M K_ball dm^5 n^2 |omega|`` (N mm to N m), with the series' K_Z and rows of
    balls (3.1 and 1, the deep-groove values, without a series) and V_M at the bearing's
    oil level. The loop's ``bearing_ball_drag`` effect scales it: the drag of the balls
    in the oil, calibrated apart from the rolling and sliding. It does not depend on the
    oil (the V_M term has neither viscosity nor density).

    Parameters
    ----------
    spec : BearingSpec
        The bearing (d, D, oil level; series if known).
    omega_rad_s : float or array
        Shaft speed [rad/s] (sign ignored).

    Returns
    -------
    float or array
        Power [W] (0 at rest).

    References
    ----------
    SKF catalogue, "Friction", drag losses [1]_ (:func:`drag_vm_moment`).
    """
    c = SERIES_CONSTANTS.get(spec.series)
    k_z, rows = (c.k_z, c.ball_rows) if c is not None else (3.1, 1)
    d, D = m_to_mm(spec.bore_m), m_to_mm(spec.outside_m)
    w = m.fabs(omega_rad_s)
    moment = drag_vm_moment(rad_s_to_rpm(w), 0.5 * (d + D), ball_drag_constant(d, D, k_z, rows),
                            drag_loss_factor(spec.oil_level_ratio))
    return mm_to_m(moment) * w


__all__ = ["DRAG_ALIASES", "DRAG_CHOICES", "KINDS", "MODELS", "OMEGA_FLOOR_RAD_S",
           "BearingSpec", "BearingValidity", "bearing_mean_power", "bearing_moment_terms",
           "bearing_power", "bearing_torque", "bearing_validity", "bearing_vm_drag_power",
           "palmgren_viscous_torque", "skf_moments"]
