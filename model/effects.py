"""Candidate effects the seed's viscous-loss model leaves out.

Each effect is a physically named term with a formula, a reference, a stable
name and the sign its coefficient must have. The measured-data loop
(:mod:`oilgap.studies.calibration`) uses them as regression features: the
effect's power is ``coefficient * feature`` per sample; the synthetic rig
(:mod:`oilgap.studies.synth`) injects them into simulated data.

Physics functions (pure; floats, numpy arrays and, where they are closed-form,
CasADi symbols):

* :func:`disc_reynolds`, :func:`free_disc_moment_coefficient`,
  :func:`end_face_disc_power`: rotor end faces as free discs (laminar boundary
  layer ``C_m = 3.87 Re_r^-0.5``, turbulent ``0.146 Re_r^-0.2`` above 3e5) [1], [2].
* :func:`enclosed_disc_couette_power`: end faces in a narrow axial clearance s
  (laminar Couette disc, torque ``pi mu omega (r_o^4 - r_i^4) / (2 s)`` per face) [1], [3].
  Not a candidate of the loop: it scales as ``mu omega^2`` and does not depend
  on T, exactly like the bearing region's laminar loss, so on any data it is
  absorbed into the fitted C (see :data:`CONFOUNDED_FORMS`).
* :func:`palmgren_viscous_moment`, :func:`ball_churning_power`: load-independent
  (viscous) friction moment of a rolling bearing in oil [4], [5].
* :func:`coulomb_friction_power`: seal (lip or face) Coulomb friction [6].
* :func:`oil_inertia_power`: kinetic-energy rate of entrained oil.
* :func:`first_order_lag`, :func:`thermal_lag_power`: gap oil temperature as a
  first-order lag of the measured temperature [7].
* :func:`taylor_excess_factor`, :func:`taylor_vortex_power`: torque excess above
  the critical Taylor number [8], [9], [10].
* :func:`couette_shear_rate`, :func:`cross_viscosity_ratio`,
  :func:`shear_thinning_power`: Cross/Carreau shear thinning [11], [12].
* :func:`sensor_delay_power`: a power reading that lags the speed reading.

The library (:data:`EFFECTS`) maps each stable name to an :class:`Effect`
carrying its formula, reference, coefficient unit, sign constraint and the
function that turns an :class:`EffectContext` (per-sample arrays of a run set)
into the regression feature.

References
----------
.. [1] J. Pyrhönen, T. Jokinen, V. Hrabovcová, *Design of Rotating Electrical
   Machines*, 2nd ed., Wiley 2014, sec. 9.5 (rotor end-face friction loss,
   ``P = C_M rho Omega^3 (D^5 - D_i^5) / 64``).
.. [2] H. Schlichting, K. Gersten, *Boundary-Layer Theory*, 9th ed., Springer
   2017, sec. 5.3.3 (rotating disc, ``C_M = 3.87 / Re^0.5`` both sides).
.. [3] J. W. Daily, R. E. Nece, "Chamber dimension effects on induced flow and
   frictional resistance of enclosed rotating disks", ASME J. Basic Eng. 82:217,
   1960 (regime I, merged boundary layers: Couette disc).
.. [4] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., Burbank 1959.
.. [5] T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*,
   5th ed., CRC 2006, ch. 9 (``M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3`` [N mm]).
.. [6] H. K. Müller, B. S. Nau, *Fluid Sealing Technology*, Marcel Dekker 1998,
   ch. 5 (lip-seal friction torque, nearly speed-independent).
.. [7] T. L. Bergman, A. S. Lavine, F. P. Incropera, D. P. DeWitt, *Fundamentals
   of Heat and Mass Transfer*, 7th ed., Wiley 2011, sec. 5.2 (lumped capacitance).
.. [8] G. I. Taylor, Phil. Trans. R. Soc. A 223:289-343, 1923.
.. [9] J. T. Stuart, "On the non-linear mechanics of hydrodynamic stability",
   J. Fluid Mech. 4:1-21, 1958 (torque excess proportional to Ta^2 - Ta_c^2
   near onset, Ta^2 being the classical Taylor number).
.. [10] R. J. Donnelly, "Experiments on the stability of viscous flow between
   rotating cylinders I. Torque measurements", Proc. R. Soc. A 246:312, 1958.
.. [11] M. M. Cross, "Rheology of non-Newtonian fluids: a new flow equation for
   pseudoplastic systems", J. Colloid Sci. 20:417-437, 1965.
.. [12] R. B. Bird, R. C. Armstrong, O. Hassager, *Dynamics of Polymeric
   Liquids*, vol. 1, 2nd ed., Wiley 1987, sec. 4.4 (Carreau model).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from . import _math as m
from .errors import InputError
from .regions import JointGeometry, region_power
from .skin_friction import FrictionLaw
from .taylor_couette import CRITICAL_TAYLOR_NUMBER, couette_reynolds, taylor_number
from .units import m2_s_to_cst, m_to_mm, mm_to_m, rad_s_to_rpm

FREE_DISC_TRANSITION_RE = 3.0e5
"""Disc Reynolds number of the laminar-turbulent change of the free-disc law [1]."""

PALMGREN_MIN_NU_N = 2000.0
"""Below ``nu n = 2000`` [cSt rpm] Palmgren's viscous moment is constant [5]."""


# --------------------------------------------------------------------------- physics


def disc_reynolds(omega_rad_s, radius_m, nu_m2_s):
    """Disc Reynolds number ``Re_r = |omega| r^2 / nu`` [-] [1]."""
    return m.fabs(omega_rad_s) * radius_m * radius_m / nu_m2_s


def free_disc_moment_coefficient(disc_re):
    """Moment coefficient of a free disc, both faces [-] [1], [2].

    ``C_M = 3.87 Re_r^-0.5`` (laminar boundary layer, Re_r < 3e5),
    ``0.146 Re_r^-0.2`` above. Re_r is floored at 1e-12.
    """
    re = m.fmax(disc_re, 1.0e-12)
    return m.where(re < FREE_DISC_TRANSITION_RE, 3.87 * re**-0.5, 0.146 * re**-0.2)


def end_face_disc_power(omega_rad_s, nu_m2_s, density_kg_m3, r_outer_m, r_inner_m):
    """Friction power [W] of both rotor end faces turning as free discs in oil.

    ``P = C_M rho |omega|^3 (D^5 - D_i^5) / 64`` with ``C_M`` from
    :func:`free_disc_moment_coefficient` at ``Re_r = |omega| r_o^2 / nu`` [1], [2].
    In the laminar range ``P ∝ rho nu^0.5 |omega|^2.5``.
    """
    cm = free_disc_moment_coefficient(disc_reynolds(omega_rad_s, r_outer_m, nu_m2_s))
    w = m.fabs(omega_rad_s)
    d5 = (2.0 * r_outer_m) ** 5 - (2.0 * r_inner_m) ** 5
    return cm * density_kg_m3 * w * w * w * d5 / 64.0


def enclosed_disc_couette_power(omega_rad_s, mu_Pa_s, r_outer_m, r_inner_m, axial_gap_m,
                                faces=2):
    """Friction power [W] of end faces in a narrow axial clearance (laminar Couette disc).

    Torque per face ``pi mu omega (r_o^4 - r_i^4) / (2 s)`` [3]; power = torque x omega
    x faces, i.e. ``∝ mu omega^2``. Confounded with the laminar clearance law
    (see the module docstring), so not a candidate effect.
    """
    w = m.fabs(omega_rad_s)
    return faces * np.pi * mu_Pa_s * w * w * (r_outer_m**4 - r_inner_m**4) / (2.0 * axial_gap_m)


def palmgren_viscous_moment(nu_cSt, speed_rpm, pitch_diameter_mm, f0=1.0):
    """Palmgren's load-independent bearing friction moment [N mm] [4], [5].

    ``M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3`` for ``nu n >= 2000``; below, the value at
    ``nu n = 2000`` (Palmgren writes 160e-7 f_0 d_m^3; 2000^(2/3) = 158.7 keeps it
    continuous). nu [cSt], n [rpm], d_m [mm]; f_0 the bearing-type and
    lubrication factor (deep-groove ball bearing in an oil bath: about 2).
    """
    nn = m.fmax(nu_cSt * m.fabs(speed_rpm), PALMGREN_MIN_NU_N)
    return 1.0e-7 * f0 * nn ** (2.0 / 3.0) * pitch_diameter_mm**3


def ball_churning_power(omega_rad_s, nu_m2_s, pitch_diameter_m, f0=1.0):
    """Viscous (churning) loss [W] of a rolling bearing in oil: ``M_0 |omega|`` [4], [5].

    :func:`palmgren_viscous_moment` converted to SI; ``∝ nu^(2/3) |omega|^(5/3)``.
    """
    w = m.fabs(omega_rad_s)
    moment_Nmm = palmgren_viscous_moment(m2_s_to_cst(nu_m2_s), rad_s_to_rpm(w),
                                         m_to_mm(pitch_diameter_m), f0)
    return mm_to_m(moment_Nmm) * w


def coulomb_friction_power(omega_rad_s, torque_Nm):
    """Coulomb (seal) friction loss [W]: ``tau_c |omega|`` [6]."""
    return torque_Nm * m.fabs(omega_rad_s)


def oil_inertia_power(omega_rad_s, domega_dt_rad_s2, density_kg_m3, volume_inertia_m5):
    """Power [W] to accelerate entrained oil: ``rho I_V omega domega/dt``.

    ``I_V = ∫ r^2 dV`` [m^5] of the oil that turns with the rotor, so the
    entrained inertia is ``J = rho I_V`` [kg m^2]; the power is the rate of
    change of its kinetic energy ``J omega^2 / 2`` (zero mean over a cycle).
    """
    return density_kg_m3 * volume_inertia_m5 * omega_rad_s * domega_dt_rad_s2


def first_order_lag(time_s, signal, tau_s, initial=None):
    """Exact response [same unit as signal] of a first-order lag ``tau dy/dt = x - y``.

    The input is taken as piecewise linear between samples, for which the
    discrete update is exact [7]:
    ``y_k+1 = x_k+1 + (y_k - x_k) e^(-h/tau) - s tau (1 - e^(-h/tau))`` with
    ``s = (x_k+1 - x_k)/h``; on a uniform record this is an IIR filter
    (``scipy.signal.lfilter``). Starts from ``initial`` (default: the first
    input, i.e. in equilibrium). numpy only; ``tau_s = 0`` returns the input.
    """
    from scipy.signal import lfilter

    t = np.asarray(time_s, dtype=float)
    x = np.asarray(signal, dtype=float)
    if tau_s == 0.0 or len(x) < 2:
        return x.copy()
    y0 = x[0] if initial is None else float(initial)
    dt = np.diff(t)
    h = float(np.median(dt))
    if np.all(np.abs(dt - h) <= 1e-9 * max(1.0, h)):
        e = np.exp(-h / tau_s)
        g = tau_s / h * (1.0 - e)
        b = np.array([1.0 - g, g - e])
        a = np.array([1.0, -e])
        # state so that y_0 = y0 given x_0: y_1 = e y_0 + b0 x_1 + b1 x_0
        y = np.empty_like(x)
        y[0] = y0
        y[1:], _ = lfilter(b, a, x[1:], zi=np.array([e * y0 + b[1] * x[0]]))
        return y
    y = np.empty_like(x)
    y[0] = y0
    for k in range(len(x) - 1):
        e = np.exp(-dt[k] / tau_s)
        s = (x[k + 1] - x[k]) / dt[k]
        y[k + 1] = x[k + 1] + (y[k] - x[k]) * e - s * tau_s * (1.0 - e)
    return y


def thermal_lag_power(dpower_dtemp_W_K, dtemp_dt_K_s, tau_s):
    """Power change [W] when the gap oil lags the measured temperature by ``tau`` [s].

    ``T_oil ≈ T_meas - tau dT_meas/dt`` (first term of the first-order lag [7]), so
    ``dP ≈ -tau (dP/dT) dT/dt``. tau < 0: the measured temperature lags the oil.
    """
    return -tau_s * dpower_dtemp_W_K * dtemp_dt_K_s


def taylor_excess_factor(taylor, critical=CRITICAL_TAYLOR_NUMBER):
    """Supercriticality ``max(0, (Ta/Ta_c)^2 - 1)`` [-] of Taylor-vortex flow [8], [9].

    Ta is the seed's Eq. 3 (``∝ omega``); its square is the classical Taylor
    number, in which the torque excess grows linearly near onset [9], [10].
    """
    r = taylor / critical
    return m.fmax(r * r - 1.0, 0.0)


def taylor_vortex_power(power_laminar_W, taylor, k, critical=CRITICAL_TAYLOR_NUMBER):
    """Extra loss [W] of Taylor vortices: ``k P_lam max(0, (Ta/Ta_c)^2 - 1)`` [8]-[10].

    k [-] is the torque excess per unit supercriticality.
    """
    return k * power_laminar_W * taylor_excess_factor(taylor, critical)


def couette_shear_rate(omega_rad_s, radius_m, gap_m):
    """Nominal shear rate ``|omega| R / delta`` [1/s] of a narrow clearance [12]."""
    return m.fabs(omega_rad_s) * radius_m / gap_m


def cross_viscosity_ratio(shear_rate_1_s, lam_s, exponent=2.0):
    """Cross model ``mu/mu_0 = 1 / (1 + (lambda gamma_dot)^m)`` [-] (mu_inf = 0) [11]."""
    return 1.0 / (1.0 + (lam_s * shear_rate_1_s) ** exponent)


def carreau_viscosity_ratio(shear_rate_1_s, lam_s, n):
    """Carreau model ``mu/mu_0 = (1 + (lambda gamma_dot)^2)^((n-1)/2)`` [-] [12]."""
    return (1.0 + (lam_s * shear_rate_1_s) ** 2) ** ((n - 1.0) / 2.0)


def shear_thinning_power(power_laminar_W, shear_rate_1_s, lam2_s2):
    """Power change [W] of a shear-thinning oil at low Weissenberg number [11], [12].

    ``dP ≈ -lambda^2 gamma_dot^2 P_lam``: the first term of the Cross model with
    m = 2 (Carreau: lambda^2 stands for (1-n) lambda^2 / 2). ``lam2_s2`` [s^2] >= 0.
    """
    return -lam2_s2 * shear_rate_1_s * shear_rate_1_s * power_laminar_W


def sensor_delay_power(dpower_dt_W_s, delay_s):
    """Power change [W] when the power reading lags the speed reading by ``d`` [s].

    ``P(t - d) ≈ P(t) - d dP/dt`` (first-order Taylor expansion of the time shift).
    """
    return -delay_s * dpower_dt_W_s


# --------------------------------------------------------------------------- library


@dataclass(frozen=True)
class RegionState:
    """One clearance region over the samples (arrays of length n, or floats) [SI]."""

    name: str
    radius_m: float
    gap_m: np.ndarray
    length_m: float
    power_W: np.ndarray
    reynolds: np.ndarray
    taylor: np.ndarray


@dataclass(frozen=True)
class EffectContext:
    """Per-sample quantities the effect features need (SI arrays of length n).

    ``power_W`` is the clearance model's viscous power (sum of ``regions``);
    ``dpower_dt_W_s`` its time derivative along the record and
    ``dpower_dtemp_W_K`` its derivative with respect to the oil temperature
    (NaN where the viscosity does not follow a temperature law).
    ``disc_radii_m`` are the rotor end-face outer and inner radii;
    ``bearing_pitch_diameter_m`` is None for a rig without a bearing region.
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

    @property
    def power_W(self) -> np.ndarray:
        """Viscous power of all regions [W]."""
        return sum(r.power_W for r in self.regions)


def region_states(geometry: JointGeometry, omega_rad_s, nu_m2_s, powers_W
                  ) -> tuple[RegionState, ...]:
    """Per-region state (geometry, power, Re of Eq. 4, Ta of Eq. 3) over the samples.

    Parameters
    ----------
    geometry : JointGeometry
        The joint's regions (:func:`oilgap.model.regions.joint_geometry`).
    omega_rad_s : rotor speed per sample [rad/s]
    nu_m2_s : kinematic viscosity per sample [m^2/s]
    powers_W : sequence of arrays
        Viscous power of each region per sample [W].

    Returns
    -------
    tuple of RegionState
    """
    ones = np.ones_like(np.asarray(omega_rad_s * nu_m2_s, dtype=float))
    out = []
    for region, p in zip(geometry.regions, powers_W, strict=True):
        R, gap = region.radius_m, region.gap_m
        re = couette_reynolds(omega_rad_s, R, gap, nu_m2_s)
        out.append(RegionState(region.name, R, gap * ones, region.length_m, p, re,
                               taylor_number(re, gap, R)))
    return tuple(out)


def effect_context(geometry: JointGeometry, omega_rad_s, domega_dt_rad_s2, nu_m2_s,
                   density_kg_m3, law: FrictionLaw, *, powers_W=None, dtemp_dt_K_s=None,
                   dpower_dt_W_s=None, dpower_dtemp_W_K=None) -> EffectContext:
    """The one builder of an :class:`EffectContext` (rig simulator and calibration alike).

    Parameters
    ----------
    geometry : JointGeometry
        Regions, end-face radii and bearing pitch diameter of the joint.
    omega_rad_s, domega_dt_rad_s2 : speed [rad/s] and acceleration [rad/s^2] per sample
    nu_m2_s, density_kg_m3 : oil state per sample [m^2/s], [kg/m^3]
    law : FrictionLaw
        Friction law of the clearance model (used unless ``powers_W`` is given).
    powers_W : sequence of arrays, optional
        Region powers already computed [W].
    dtemp_dt_K_s, dpower_dt_W_s, dpower_dtemp_W_K : arrays, optional
        Derivatives along the record (zero where not given).

    Returns
    -------
    EffectContext
    """
    ones = np.ones_like(np.asarray(omega_rad_s * nu_m2_s, dtype=float))
    omega = np.asarray(omega_rad_s, dtype=float) * ones
    if powers_W is None:
        powers_W = [region_power(r, omega, nu_m2_s, density_kg_m3, law)
                    for r in geometry.regions]
    zeros = np.zeros_like(ones)
    return EffectContext(
        omega, np.asarray(domega_dt_rad_s2, dtype=float) * ones, nu_m2_s, density_kg_m3,
        zeros if dtemp_dt_K_s is None else dtemp_dt_K_s,
        zeros if dpower_dt_W_s is None else dpower_dt_W_s,
        zeros if dpower_dtemp_W_K is None else dpower_dtemp_W_K,
        region_states(geometry, omega, nu_m2_s, powers_W), geometry.disc_radii_m,
        geometry.bearing_pitch_diameter_m)


def cross_region_ratios(ctx: EffectContext, lam_s: float) -> list[np.ndarray]:
    """Cross viscosity ratio ``mu/mu_0`` of each region at its nominal shear rate [-] [11].

    ``1 / (1 + (lambda |omega| R_i / delta_i)^2)``: the full (not first-order)
    shear-thinning law, applied to each region's power by the rig simulator and
    by the calibration's exact form.
    """
    return [cross_viscosity_ratio(couette_shear_rate(ctx.omega_rad_s, r.radius_m, r.gap_m),
                                  lam_s) for r in ctx.regions]


def _f_disc(c: EffectContext):
    r_o, r_i = c.disc_radii_m
    return end_face_disc_power(c.omega_rad_s, c.nu_m2_s, c.density_kg_m3, r_o, r_i)


def _f_churning(c: EffectContext):
    if c.bearing_pitch_diameter_m is None:
        return None
    return ball_churning_power(c.omega_rad_s, c.nu_m2_s, c.bearing_pitch_diameter_m, 1.0)


def _f_seal(c: EffectContext):
    return coulomb_friction_power(c.omega_rad_s, 1.0)


def _f_inertia(c: EffectContext):
    return oil_inertia_power(c.omega_rad_s, c.domega_dt_rad_s2, c.density_kg_m3, 1.0)


def _f_thermal(c: EffectContext):
    d = np.nan_to_num(np.asarray(c.dpower_dtemp_W_K, dtype=float), nan=0.0)
    return thermal_lag_power(d, c.dtemp_dt_K_s, 1.0)


def _f_taylor(c: EffectContext):
    return sum(taylor_vortex_power(r.power_W, r.taylor, 1.0) for r in c.regions)


def _f_shear(c: EffectContext):
    return sum(shear_thinning_power(r.power_W, couette_shear_rate(c.omega_rad_s, r.radius_m,
                                                                  r.gap_m), 1.0)
               for r in c.regions)


def _f_delay(c: EffectContext):
    return sensor_delay_power(c.dpower_dt_W_s, 1.0)


@dataclass(frozen=True)
class Effect:
    """A candidate effect of the library.

    Attributes
    ----------
    name : stable identifier (used in JSON, CLI and tests)
    title : human-readable name
    formula : the term as the loop adds it, in plain text
    reference : source of the law
    coefficient : symbol and meaning of the fitted coefficient
    unit : unit of the coefficient
    nonnegative : True if physics demands coefficient >= 0 (dissipation,
        positive inertia, causality); False if either sign is physical
    feature : EffectContext -> per-sample power per unit coefficient [W/unit]
        (None if the effect cannot act on that rig, e.g. no bearing region)
    strength_unit : unit of the synthetic rig's ``--strength``
    coefficient_from_strength : maps the strength to the coefficient
    strength_from_coefficient : inverse
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

    def feature_values(self, ctx: EffectContext) -> np.ndarray | None:
        """The feature column [W per unit coefficient], or None if not applicable."""
        f = self.feature(ctx)
        return None if f is None else np.asarray(f, dtype=float) * np.ones_like(ctx.omega_rad_s)


def _signed_sqrt(x: float) -> float:
    return float(np.sign(x) * np.sqrt(abs(x)))


EFFECTS: dict[str, Effect] = {e.name: e for e in (
    Effect("end_face_disc", "rotor end-face disc friction",
           "k * C_M rho |w|^3 (D^5 - D_i^5)/64, C_M = 3.87 Re_r^-0.5 (0.146 Re_r^-0.2 > 3e5), "
           "Re_r = |w| r_o^2/nu",
           "Pyrhönen et al. 2014 sec. 9.5; Schlichting & Gersten 2017 sec. 5.3.3",
           "k (multiple of the free-disc value, both faces)", "-", True, _f_disc, "-"),
    Effect("bearing_ball_churning", "bearing ball churning",
           "M_0 |w|, M_0 = 1e-7 f0 (nu[cSt] n[rpm])^(2/3) d_m[mm]^3 N mm, "
           "d_m = 2 R2 + delta2",
           "Palmgren 1959; Harris & Kotzalas 2006 ch. 9",
           "f0 (Palmgren factor)", "-", True, _f_churning, "-"),
    Effect("seal_coulomb_friction", "seal / Coulomb friction", "tau_c |w|",
           "Coulomb friction; Müller & Nau 1998 ch. 5 (lip-seal torque)",
           "tau_c (friction torque)", "N m", True, _f_seal, "N m"),
    Effect("oil_inertia", "entrained oil inertia", "rho I_V w dw/dt",
           "kinetic energy of oil turning with the rotor, d/dt(J w^2/2), J = rho I_V",
           "I_V (second moment of the entrained oil volume)", "m^5", True, _f_inertia, "m^5"),
    Effect("thermal_lag", "thermal lag of the gap oil",
           "-tau (dP/dT) dT/dt  (T_oil = T_meas/(1 + tau s), first order)",
           "lumped-capacitance first-order response, Bergman et al. 2011 sec. 5.2",
           "tau (lag of the gap oil behind the measured temperature; < 0: it leads)", "s",
           False, _f_thermal, "s"),
    Effect("taylor_vortex_onset", "Taylor-vortex onset",
           "k * sum_i P_i max(0, (Ta_i/41.3)^2 - 1)",
           "Taylor 1923; Stuart 1958 (JFM 4:1); Donnelly 1958",
           "k (torque excess per unit supercriticality)", "-", True, _f_taylor, "-"),
    Effect("shear_thinning", "shear thinning of the oil",
           "-lambda^2 * sum_i (|w| R_i/delta_i)^2 P_i  (Cross mu/mu0 = 1/(1+(lambda g)^2), "
           "first order)",
           "Cross 1965; Bird, Armstrong & Hassager 1987 sec. 4.4 (Carreau)",
           "lambda^2 (Cross time constant squared)", "s^2", True, _f_shear, "s",
           coefficient_from_strength=lambda s: float(s) ** 2,
           strength_from_coefficient=_signed_sqrt),
    Effect("sensor_delay", "power-sensor delay", "-d dP/dt  (P_meas(t) = P(t - d))",
           "first-order expansion of a time shift (dead time)",
           "d (delay of the power reading behind the speed reading)", "s", True, _f_delay,
           "s"),
)}
"""The candidate-effect library, by stable name."""

CONFOUNDED_FORMS = {
    "enclosed_disc_couette": (
        "pi mu w^2 (r_o^4 - r_i^4)/s per face (Daily & Nece 1960 regime I): scales as "
        "mu w^2 and does not depend on T, exactly like the bearing region's laminar loss; "
        "on any data it is absorbed into the fitted C and cannot be named"),
}
"""Physical terms deliberately left out of the candidates, with the reason."""


def get_effect(name: str) -> Effect:
    """The library effect of that stable name.

    Raises
    ------
    InputError
        Unknown name; the message lists the library.
    """
    if name not in EFFECTS:
        raise InputError("effect", name, f"library effects are {', '.join(EFFECTS)}")
    return EFFECTS[name]
