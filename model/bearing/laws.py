"""The laws of rolling-bearing friction in oil, in catalogue units (N mm, r/min, mm^2/s).

SKF's frictional-moment model of deep-groove ball bearings (the series constants, the
rolling and sliding variables G_rr and G_sl, the inlet-shear, replenishment and
boundary-film factors, the drag terms with the digitised V_M diagram), Palmgren's
load-independent and load-dependent moments, and two ISO relations (the static load
rating C_0 and the rated viscosity nu_1). :mod:`oilgap.model.bearing` composes them for a
:class:`~oilgap.model.bearing.BearingSpec` and converts SI to catalogue units, once.

Functions of speed and viscosity take floats, numpy arrays and CasADi symbols; the
powers of n and nu are taken separately, so a symbolic nu has finite derivatives at n = 0.
Sources and what was verified: docs/bearing.md and docs/notes/bearing-friction-models.md.

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
.. [7] L. Schiller, A. Naumann, "Über die grundlegenden Berechnungen bei der
   Schwerkraftaufbereitung", *Z. Ver. Dtsch. Ing.* 77 (1933) 318-320: the sphere drag
   coefficient ``C_D = 24/Re (1 + 0.15 Re^0.687)``, Re <= 1000, as tabulated with its
   accuracy (within about 5 % of the standard drag curve below Re = 800) by R. Clift,
   J. R. Grace, M. E. Weber, *Bubbles, Drops, and Particles*, Academic Press 1978, ch. 5.
.. [8] T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
   CRC 2006, the chapter on bearing kinematics: the cage (ball-set) speed of a ball
   bearing with a rotating inner ring, ``omega_c = omega/2 (1 - D_w cos(a)/d_m)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _math as m
from .skf_speed import boundary_film_speed, inlet_shear_speed


@dataclass(frozen=True)
class SeriesConstants:
    """SKF geometry constants of a deep-groove ball bearing series [1]_.

    Attributes
    ----------
    r1, r2 : float
        Rolling-moment constants R1 [-] and R2 [-] (catalogue units).
    s1, s2 : float
        Sliding-moment constants S1 [-] and S2 [-] (catalogue units).
    k_z : float
        Bearing-type geometry constant K_Z [-] (3.1 for deep-groove ball bearings).
    ball_rows : int
        Rows of balls i_rw [-] (2 for the 42/43 double-row series).
    """

    r1: float
    r2: float
    s1: float
    s2: float
    k_z: float = 3.1
    ball_rows: int = 1


_SERIES_ROWS = (
    (("2", "3"), SeriesConstants(4.4e-7, 1.7, 2.00e-3, 100.0)),
    (("42", "43"), SeriesConstants(5.4e-7, 0.96, 3.00e-3, 40.0, ball_rows=2)),
    (("60", "630"), SeriesConstants(4.1e-7, 1.7, 3.73e-3, 14.6)),
    (("62", "622"), SeriesConstants(3.9e-7, 1.7, 3.23e-3, 36.5)),
    (("63", "623"), SeriesConstants(3.7e-7, 1.7, 2.84e-3, 92.8)),
    (("64",), SeriesConstants(3.6e-7, 1.7, 2.43e-3, 198.0)),
    (("160", "161"), SeriesConstants(4.3e-7, 1.7, 4.63e-3, 4.25)),
    (("617", "618", "628", "637", "638"), SeriesConstants(4.7e-7, 1.7, 6.50e-3, 0.78)),
    (("619", "639"), SeriesConstants(4.3e-7, 1.7, 4.75e-3, 3.6)),
)
SERIES_CONSTANTS: dict[str, SeriesConstants] = {
    s: c for names, c in _SERIES_ROWS for s in names}
"""R1, R2, S1, S2, K_Z of each deep-groove series [-] [1]_ (the table of
docs/notes/bearing-friction-models.md; one row per series name)."""

V_M_LEVELS = (0.0, 0.05, 0.10, 0.15, 0.20, 0.30, 0.50, 0.80, 1.00, 1.10, 1.20)
"""Oil level H/dm of the digitised V_M diagram [-] (0 added: no oil, no drag)."""
V_M_VALUES = (0.0, 1.9e-5, 7.2e-5, 1.5e-4, 2.4e-4, 3.9e-4, 5.6e-4, 7.9e-4, 9.7e-4,
              1.04e-3, 1.25e-3)
"""Drag loss factor V_M of ball bearings at :data:`V_M_LEVELS` [-]: the mean of two
independent digitisations of the catalogue diagram [1]_; constant above H/dm = 1.2."""
V_M_SUBMERGED = 1.25e-3
"""V_M of a fully submerged ball bearing (H >= 1.2 dm) [-] [1]_."""
K_RS_OIL_BATH = 3.0e-8
"""Replenishment constant K_rs of a low-level oil bath or oil jet [-] [1]_."""
MU_EHL_MINERAL = 0.05
"""Full-film sliding coefficient mu_EHL of a mineral oil [-] [2]_."""
MU_BL_DEFAULT = 0.12
"""Boundary sliding coefficient mu_bl for n > 0 [-] (2013 catalogue [1]_)."""
PALMGREN_MIN_NU_N = 2000.0
"""Below ``nu n = 2000`` [cSt rpm] Palmgren's viscous moment is constant [4]_."""
PALMGREN_Z = 5.0e-4
"""Palmgren's load factor z of deep-groove ball bearings [-] (range 4e-4 to 6e-4) [4]_."""
PALMGREN_Y = 0.55
"""Palmgren's load exponent y of deep-groove ball bearings [-] [4]_."""
F0_OIL_BATH = 2.0
"""Palmgren f_0 of a deep-groove ball bearing in an oil bath (level at the lowest
ball's centre) [-] [4]_ (recalled)."""
F0_SUBMERGED = 4.0
"""Palmgren f_0 of a fully submerged bearing [-]: twice the oil-bath value (the usual
guidance "up to about 2x" for high levels, recalled and not located)."""
F0_OIL_RANGE = (F0_OIL_BATH, F0_SUBMERGED)
"""Published range of Palmgren's f_0 for a deep-groove ball bearing lubricated by oil at
a level (oil bath or submerged) [-] [4]_ (recalled): 2 for an oil bath with a horizontal
shaft, 4 for an oil bath with a vertical shaft or an oil jet, the value the guidance
"up to about 2x the oil-bath value" gives a submerged bearing. The band of models
(:func:`oilgap.model.bearing.band.bearing_model_band`) spans it; grease (0.7-2) and oil
mist (1) do not apply to an oil-filled joint."""
SPHERE_DRAG_RE_NEWTON = 1000.0
"""Reynolds number above which a sphere's drag coefficient is taken constant, 0.44 [-]
(the Newton range; Schiller-Naumann below [7]_)."""
SPHERE_DRAG_CD_NEWTON = 0.44
"""Sphere drag coefficient in the Newton range, 1e3 < Re < 2e5 [-] [7]_."""

# ISO 76 factor f_0 of radial ball bearings against D_w cos(a)/D_pw (recalled) [5].
_ISO76_RATIO = np.round(np.arange(0.0, 0.405, 0.01), 2)
_ISO76_F0 = np.array([14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5, 16.4,
                      16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2, 14.0, 13.7,
                      13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8, 11.6, 11.4, 11.2,
                      10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4])


def iso_static_load_rating(balls, ball_diameter_mm, pitch_diameter_mm):
    """Basic static load rating of a radial ball bearing [N] (ISO 76, alpha = 0) [5]_.

    ``C_0 = f_0 Z D_w^2`` with f_0 interpolated in ISO 76's table for radial ball
    bearings against ``D_w/D_pw`` (recalled: checked against the catalogue's 61809 and
    6309 within 1 %).

    Parameters
    ----------
    balls : int
        Number of balls Z [-].
    ball_diameter_mm : float
        Ball diameter D_w [mm].
    pitch_diameter_mm : float
        Pitch diameter D_pw [mm].

    Returns
    -------
    float
        C_0 [N].
    """
    f0 = float(np.interp(ball_diameter_mm / pitch_diameter_mm, _ISO76_RATIO, _ISO76_F0))
    return f0 * balls * ball_diameter_mm**2


def rated_viscosity(speed_rpm, pitch_diameter_mm):
    """Rated viscosity nu_1 [cSt] (ISO 281 form, recalled) [6]_.

    ``nu_1 = 45000 n^-0.83 dm^-0.5`` below 1000 r/min, ``4500 n^-0.5 dm^-0.5`` from
    1000 r/min. The exponents match the SKF diagram as digitised in [1]_'s
    transcription; its level there is about 18 % lower.

    Parameters
    ----------
    speed_rpm : float
        Speed n [rpm] (> 0).
    pitch_diameter_mm : float
        Pitch diameter dm [mm].

    Returns
    -------
    float
        nu_1 [cSt].
    """
    n = abs(float(speed_rpm))
    if n < 1000.0:
        return 45000.0 * n**-0.83 * pitch_diameter_mm**-0.5
    return 4500.0 * n**-0.5 * pitch_diameter_mm**-0.5


# --------------------------------------------------------------------------- SKF laws


def load_angle_deg(axial_load_N, static_rating_N):
    """SKF's load angle ``alpha_F = 24.6 (F_a/C_0)^0.24`` [deg] [2]_.

    Parameters
    ----------
    axial_load_N : float
        Axial load F_a [N].
    static_rating_N : float
        Basic static load rating C_0 [N].

    Returns
    -------
    float
        alpha_F [deg].
    """
    return 24.6 * (axial_load_N / static_rating_N) ** 0.24


def rolling_load_factor(c: SeriesConstants, dm_mm, fr_N, fa_N, static_rating_N):
    """SKF's rolling variable G_rr of a deep-groove ball bearing [-] (Table 2a [2]_).

    ``G_rr = R1 dm^1.96 F_r^0.54`` (F_a = 0); for F_a > 0
    ``R1 dm^1.96 (F_r + R2/sin(alpha_F) F_a)^0.54``.

    Parameters
    ----------
    c : SeriesConstants
        The series' R1 [-] and R2 [-].
    dm_mm : float
        Pitch diameter [mm].
    fr_N, fa_N : float
        Radial and axial load [N].
    static_rating_N : float
        C_0 [N] (used when F_a > 0).

    Returns
    -------
    float
        G_rr [catalogue units: M_rr = G_rr (nu n)^0.6 in N mm].
    """
    if fa_N > 0.0:
        s = math.sin(math.radians(load_angle_deg(fa_N, static_rating_N)))
        return c.r1 * dm_mm**1.96 * (fr_N + c.r2 / s * fa_N) ** 0.54
    return c.r1 * dm_mm**1.96 * fr_N**0.54


def sliding_load_factor(c: SeriesConstants, dm_mm, fr_N, fa_N, static_rating_N):
    """SKF's sliding variable G_sl of a deep-groove ball bearing [-] (Table 2a [2]_).

    ``G_sl = S1 dm^-0.26 F_r^(5/3)`` (F_a = 0); for F_a > 0
    ``S1 dm^-0.145 (F_r^5 + S2 dm^1.5/sin(alpha_F) F_a^4)^(1/3)`` (the two branches do
    not join at F_a -> 0: the dm exponent changes).

    Parameters
    ----------
    c : SeriesConstants
        The series' S1 [-] and S2 [-].
    dm_mm : float
        Pitch diameter [mm].
    fr_N, fa_N : float
        Radial and axial load [N].
    static_rating_N : float
        C_0 [N] (used when F_a > 0).

    Returns
    -------
    float
        G_sl [catalogue units: M_sl = G_sl mu_sl in N mm].
    """
    if fa_N > 0.0:
        s = math.sin(math.radians(load_angle_deg(fa_N, static_rating_N)))
        return c.s1 * dm_mm**-0.145 * (fr_N**5 + c.s2 * dm_mm**1.5 / s * fa_N**4) ** (1 / 3)
    return c.s1 * dm_mm**-0.26 * fr_N ** (5.0 / 3.0)


def inlet_shear_factor(speed_rpm, nu_cSt, dm_mm, speed_part=None):
    """SKF inlet-shear heating factor ``1/(1 + 1.84e-9 (n dm)^1.28 nu^0.64)`` [-] [1]_.

    Parameters
    ----------
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm] (>= 0).
    nu_cSt : float, array or CasADi symbol
        Kinematic viscosity [cSt].
    dm_mm : float
        Pitch diameter [mm].
    speed_part : float or array, optional
        :func:`~.skf_speed.inlet_shear_speed` of these speeds, if already evaluated [-].

    Returns
    -------
    float, array or CasADi expression
        phi_ish [-].
    """
    a = inlet_shear_speed(speed_rpm, dm_mm) if speed_part is None else speed_part
    return 1.0 / (1.0 + a * nu_cSt**0.64)


def replenishment_factor(speed_rpm, nu_cSt, d_mm, D_mm, k_rs, k_z=3.1):
    """SKF kinematic replenishment factor
    ``exp(-K_rs nu n (d + D) sqrt(K_Z/(2 (D - d))))`` [-] [1]_ (1 when K_rs = 0).

    Parameters
    ----------
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm].
    nu_cSt : float, array or CasADi symbol
        Kinematic viscosity [cSt].
    d_mm, D_mm : float
        Bore and outside diameter [mm].
    k_rs : float
        Replenishment constant K_rs [-] (0: flooded).
    k_z : float
        Geometry constant K_Z [-].

    Returns
    -------
    float, array or CasADi expression
        phi_rs [-].
    """
    if isinstance(k_rs, (int, float)) and k_rs == 0.0:  # flooded: exp(0), exactly 1
        return 1.0
    return m.exp(-k_rs * nu_cSt * speed_rpm * (d_mm + D_mm)
                 * math.sqrt(k_z / (2.0 * (D_mm - d_mm))))


def sliding_friction_coefficient(speed_rpm, nu_cSt, dm_mm, mu_bl=MU_BL_DEFAULT,
                                 mu_ehl=MU_EHL_MINERAL, speed_part=None):
    """SKF ``mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL``,
    ``phi_bl = exp(-2.6e-8 (n nu)^1.4 dm)`` [-] [2]_.

    Parameters
    ----------
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm].
    nu_cSt : float, array or CasADi symbol
        Kinematic viscosity [cSt].
    dm_mm : float
        Pitch diameter [mm].
    mu_bl, mu_ehl : float
        Boundary and full-film coefficients [-].
    speed_part : float or array, optional
        :func:`~.skf_speed.boundary_film_speed` of these speeds, if already evaluated [-].

    Returns
    -------
    float, array or CasADi expression
        mu_sl [-].
    """
    a = boundary_film_speed(speed_rpm) if speed_part is None else speed_part
    phi_bl = m.exp(a * nu_cSt**1.4 * dm_mm)
    return phi_bl * mu_bl + (1.0 - phi_bl) * mu_ehl


def drag_loss_factor(level_ratio):
    """Drag loss factor V_M of ball bearings at oil level H/dm [-] [1]_.

    Linear interpolation in the digitised diagram (:data:`V_M_VALUES`); 1.25e-3 from
    H/dm = 1.2 (fully submerged).

    Parameters
    ----------
    level_ratio : float
        H/dm [-].

    Returns
    -------
    float
        V_M [-].
    """
    return float(np.interp(level_ratio, V_M_LEVELS, V_M_VALUES))


def ball_drag_constant(d_mm, D_mm, k_z=3.1, ball_rows=1):
    """SKF ``K_ball = i_rw K_Z (d + D)/(D - d) 1e-12`` [catalogue units] [1]_.

    Parameters
    ----------
    d_mm, D_mm : float
        Bore and outside diameter [mm].
    k_z : float
        Geometry constant K_Z [-].
    ball_rows : int
        Rows of balls i_rw [-].

    Returns
    -------
    float
        K_ball [-].
    """
    return ball_rows * k_z * (d_mm + D_mm) / (D_mm - d_mm) * 1.0e-12


def drag_vm_moment(speed_rpm, dm_mm, k_ball, v_m):
    """SKF ball drag ``0.4 V_M K_ball dm^5 n^2`` [N mm] [1]_.

    Parameters
    ----------
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm].
    dm_mm : float
        Pitch diameter [mm].
    k_ball : float
        :func:`ball_drag_constant` [-].
    v_m : float
        :func:`drag_loss_factor` [-].

    Returns
    -------
    float, array or CasADi expression
        Moment [N mm].
    """
    return 0.4 * v_m * k_ball * dm_mm**5 * speed_rpm * speed_rpm


def drag_rs_moment(speed_rpm, nu_cSt, d_mm, D_mm, level_ratio=1.2, k_z=3.1):
    """SKF oil-bath drag term ``1.093e-7 n^2 dm^3 (n dm^2 f_t/nu)^-1.379 R_s`` [N mm] [1]_.

    Written ``1.093e-7 n^0.621 dm^0.242 nu^1.379 f_t^-1.379 R_s`` (finite at n = 0), with
    ``R_s = 0.36 dm^2 (t - sin t) f_A``, ``f_A = 0.05 K_Z (D + d)/(D - d)``,
    ``t = 2 acos((0.6 dm - H)/(0.6 dm))`` (H <= 1.2 dm), ``f_t = sin(t/2)`` for t <= pi,
    else 1. Fully submerged: t = 2 pi, ``R_s = 0.72 pi dm^2 f_A``. Outside its stated
    validity above nu = 250 mm^2/s when H > 0.5 D (docs/bearing.md).

    Parameters
    ----------
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm].
    nu_cSt : float, array or CasADi symbol
        Kinematic viscosity [cSt].
    d_mm, D_mm : float
        Bore and outside diameter [mm].
    level_ratio : float
        Oil level H/dm [-] (1.2 or more: submerged).
    k_z : float
        Geometry constant K_Z [-].

    Returns
    -------
    float, array or CasADi expression
        Moment [N mm].
    """
    dm = 0.5 * (d_mm + D_mm)
    h = min(level_ratio, 1.2) * dm
    t = 2.0 * math.acos((0.6 * dm - h) / (0.6 * dm))
    f_t = math.sin(0.5 * t) if t <= math.pi else 1.0
    f_a = 0.05 * k_z * (D_mm + d_mm) / (D_mm - d_mm)
    r_s = 0.36 * dm * dm * (t - math.sin(t)) * f_a
    return 1.093e-7 * speed_rpm**0.621 * dm**0.242 * nu_cSt**1.379 * f_t**-1.379 * r_s


# --------------------------------------------------------------------------- Palmgren


def palmgren_viscous_moment(nu_cSt, speed_rpm, pitch_diameter_mm, f0=1.0):
    """Palmgren's load-independent bearing friction moment [N mm] [3]_, [4]_.

    ``M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3`` for ``nu n >= 2000``; below, the value at
    ``nu n = 2000`` (Palmgren writes 160e-7 f_0 d_m^3; 2000^(2/3) = 158.7 keeps it
    continuous, 0.8 % lower). f_0 is the bearing-type and lubrication factor
    (deep-groove ball bearing in an oil bath: about 2). The one Palmgren law of oilgap:
    the loop's ``bearing_ball_churning`` effect and the ``palmgren`` bearing model
    both call it. The floor is a kink in nu at ``nu = 2000/n``; it only touches nodes
    slower than 2000/nu rpm, whose power is small (docs/bearing.md).

    Parameters
    ----------
    nu_cSt : float, array or CasADi symbol
        Kinematic viscosity [cSt].
    speed_rpm : float, array or CasADi symbol
        Bearing speed n [rpm] (sign ignored).
    pitch_diameter_mm : float
        Pitch diameter d_m [mm].
    f0 : float
        Palmgren factor [-].

    Returns
    -------
    float, array or CasADi expression
        Friction moment M_0 [N mm].
    """
    nn = m.fmax(nu_cSt * m.fabs(speed_rpm), PALMGREN_MIN_NU_N)
    return 1.0e-7 * f0 * nn ** (2.0 / 3.0) * pitch_diameter_mm**3


def palmgren_load_moment(pitch_diameter_mm, fr_N, fa_N, static_rating_N, z=PALMGREN_Z,
                         y=PALMGREN_Y):
    """Palmgren's load-dependent moment ``M_1 = f_1 P_1 dm`` [N mm] [4]_.

    ``f_1 = z (P_0/C_0)^y``, ``P_1 = max(3 F_a - 0.1 F_r, F_r)``,
    ``P_0 = max(0.6 F_r + 0.5 F_a, F_r)`` (ISO 76 equivalent static load).

    Parameters
    ----------
    pitch_diameter_mm : float
        Pitch diameter [mm].
    fr_N, fa_N : float
        Radial and axial load [N].
    static_rating_N : float
        C_0 [N].
    z, y : float
        Load factor [-] and exponent [-] of the bearing type.

    Returns
    -------
    float
        M_1 [N mm].
    """
    p1 = max(3.0 * fa_N - 0.1 * fr_N, fr_N)
    p0 = max(0.6 * fr_N + 0.5 * fa_N, fr_N)
    return z * (p0 / static_rating_N) ** y * p1 * pitch_diameter_mm


# --------------------------------------------------------------------------- balls in still oil


def sphere_drag_force(speed_m_s, diameter_m, nu_m2_s, rho_kg_m3):
    """Drag of a sphere moving steadily through still fluid [N] (Schiller-Naumann) [7]_.

    ``F = 1/2 rho C_D (pi D^2/4) U^2`` with ``C_D = 24/Re (1 + 0.15 Re^0.687)``,
    ``Re = U D/nu`` <= 1000, and ``C_D = 0.44`` above. Written as
    ``F = 3 pi mu D U (1 + 0.15 Re^0.687)`` below Re = 1000, which is Stokes' drag at
    Re -> 0 and finite at U = 0. The two branches meet within 0.5 % at Re = 1000.

    Parameters
    ----------
    speed_m_s : float or array
        ``|U|``, the sphere's speed through the fluid [m/s] (sign ignored).
    diameter_m : float
        Sphere diameter D [m].
    nu_m2_s : float or array
        Kinematic viscosity of the fluid [m^2/s].
    rho_kg_m3 : float or array
        Density of the fluid [kg/m^3].

    Returns
    -------
    float or array
        Drag force [N], opposing the motion (a magnitude here).
    """
    u = np.abs(np.asarray(speed_m_s, dtype=float))
    re = u * diameter_m / nu_m2_s
    viscous = 3.0 * math.pi * rho_kg_m3 * nu_m2_s * diameter_m * u * (1.0 + 0.15 * re**0.687)
    newton = 0.5 * rho_kg_m3 * SPHERE_DRAG_CD_NEWTON * 0.25 * math.pi * diameter_m**2 * u * u
    return np.where(re <= SPHERE_DRAG_RE_NEWTON, viscous, newton)


def cage_pitch_speed(omega_rad_s, pitch_diameter_m, ball_diameter_m):
    """Speed of the balls' centres on the pitch circle, inner ring rotating [m/s] [8]_.

    ``U = omega_c d_m/2`` with the cage speed ``omega_c = |omega|/2 (1 - D_w/d_m)``
    (contact angle 0, outer ring fixed, no skidding).

    Parameters
    ----------
    omega_rad_s : float or array
        Speed of the rotating ring relative to the fixed one [rad/s] (sign ignored).
    pitch_diameter_m : float
        Pitch diameter d_m [m].
    ball_diameter_m : float
        Ball diameter D_w [m].

    Returns
    -------
    float or array
        U [m/s].
    """
    omega_cage = 0.5 * np.abs(omega_rad_s) * (1.0 - ball_diameter_m / pitch_diameter_m)
    return omega_cage * 0.5 * pitch_diameter_m


def balls_in_still_oil_power(omega_rad_s, balls, ball_diameter_m, pitch_diameter_m,
                             nu_m2_s, rho_kg_m3):
    """First-principles drag power of a bearing's balls moving through still oil [W].

    ``P = Z F(U) U``: each of the Z balls an isolated sphere moving at the cage's pitch
    speed U (:func:`cage_pitch_speed` [8]_) through oil at rest, with the
    Schiller-Naumann drag :func:`sphere_drag_force` [7]_. An estimate, not a bearing
    model: it leaves out the cage, the rings' walls (confinement raises the drag), the
    wakes of the balls ahead (shielding lowers it), the balls' spin and the oil the
    cage drags along (which lowers the relative speed). docs/bearing.md compares it with
    SKF's V_M drag term.

    Parameters
    ----------
    omega_rad_s : float or array
        Shaft speed [rad/s] (sign ignored).
    balls : int
        Number of balls Z [-].
    ball_diameter_m : float
        Ball diameter D_w [m].
    pitch_diameter_m : float
        Pitch diameter d_m [m].
    nu_m2_s : float or array
        Kinematic viscosity of the oil [m^2/s].
    rho_kg_m3 : float or array
        Density of the oil [kg/m^3].

    Returns
    -------
    float or array
        Drag power [W] (0 at rest).
    """
    u = cage_pitch_speed(omega_rad_s, pitch_diameter_m, ball_diameter_m)
    return balls * sphere_drag_force(u, ball_diameter_m, nu_m2_s, rho_kg_m3) * u
