"""The laws of the out-of-family rig (:mod:`oilgap.studies.rigs.outside_rig`), written apart.

Nothing here comes from oilgap's physics (only :mod:`oilgap.model.errors` and
:mod:`oilgap.model.units` are imported): each law is written again, in a form
that differs from the estimator's wherever physics allows. Functions take
floats and numpy arrays (SI unless the name says otherwise).

* Fluids: ISO VG oils by ASTM D341 (Walther) through their 40 and 100 degC
  points [3], density ``rho15 / (1 + a (t - 15))``; silicone oils (PDMS,
  Newtonian) by Andrade's law [10].
* Clearance loss: Eq. 6 piecewise [1], optionally bounded below by the exact
  Couette coefficient [2], times T^gamma; ``P = 0.5 pi C_m rho |w|^3 R^4 L``.
* Effects: enclosed end-face discs (Daily & Nece regimes I and II) [5], Palmgren
  churning [6], Coulomb + Stribeck seal [7], Taylor-vortex excess shaped by
  Wendt's Re^1.5 torque [8], Carreau shear thinning [9]; the exact first-order
  lag [4].
* Rig parts: geometry, the oil-free baseline (gearbox loss ``k |tau w|^p``),
  the lumped thermal node (exact exponential step) [4], speed profiles, AR(1) noise.

References
----------
.. [1] E. Bilgen, R. Boulos, ASME J. Fluids Eng. 95(1):122-126, 1973 (Eq. 6 of the seed paper).
.. [2] F. M. White, *Viscous Fluid Flow*, 3rd ed., 2006, sec. 3-2.3 (Couette torque
   ``4 pi mu L w R1^2 R2^2 / (R2^2 - R1^2)``).
.. [3] ASTM D341-20; ISO 3448:1992 (grade = nu at 40 degC).
.. [4] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed.,
   2011, sec. 5.2 (lumped capacitance).
.. [5] J. W. Daily, R. E. Nece, ASME J. Basic Eng. 82:217-232, 1960 (enclosed
   rotating discs; C_M = 2 M / (rho w^2 r^5), M the torque on both faces).
.. [6] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., 1959.
.. [7] R. Stribeck, Z. VDI 46:1341, 1902; B. Armstrong-Hélouvry, *Control of
   Machines with Friction*, Kluwer 1991 (Coulomb + Stribeck friction).
.. [8] F. Wendt, Ing.-Arch. 4:577-595, 1933 (torque ~ Re^1.5 in vortex flow);
   G. I. Taylor, Phil. Trans. R. Soc. A 223:289, 1923 (onset at Ta = 41.3).
.. [9] P. J. Carreau, Trans. Soc. Rheol. 16:99-127, 1972.
.. [10] Dow, *XIAMETER PMX-200 Silicone Fluid* product information (viscosity-
   temperature coefficient 0.59, density 0.96 g/cm^3 at 50 cSt); E. N. da C.
   Andrade, Nature 125:309, 1930 (``nu = nu_25 exp(B (1/T - 1/T_25))``).
.. [11] J. D. Hamilton, *Time Series Analysis*, Princeton 1994, ch. 3 (AR(1)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.signal import lfilter

from oilgap.model.errors import InputError
from oilgap.model.units import (
    ZERO_CELSIUS_K,
    cst_to_m2_s,
    m2_s_to_cst,
    m_to_mm,
    mm_to_m,
    rad_s_to_rpm,
    rpm_to_rad_s,
)

WHERE = "outside rig"

VG_OILS = {  # name: (nu40 [cSt], nu100 [cSt], density at 15 degC [kg/m^3]), ISO 3448 grades
    "VG10": (10.0, 2.5, 850.0), "VG15": (15.0, 3.5, 855.0), "VG22": (22.0, 4.5, 860.0),
    "VG32": (32.0, 5.5, 865.0), "VG46": (46.0, 6.5, 870.0), "VG68": (68.0, 8.5, 875.0),
    "VG100": (100.0, 11.4, 880.0), "VG150": (150.0, 14.5, 885.0),
    "VG220": (220.0, 19.0, 890.0), "VG320": (320.0, 24.5, 895.0),
    "VG460": (460.0, 32.0, 900.0), "VG680": (680.0, 42.0, 905.0),
    "VG1000": (1000.0, 55.0, 910.0)}
"""ISO VG oils, transcribed from oilgap's catalogue so that the loop looks them up by name."""

THERMAL_EXPANSION_1_K = 7.0e-4
"""Volumetric expansion of the ISO VG oils [1/K] (mineral oil: 6.4e-4 to 7.5e-4)."""

SILICONE_OILS = {"PDMS10": (10.0, 935.0), "PDMS50": (50.0, 960.0), "PDMS100": (100.0, 965.0)}
"""Newtonian silicone oils: nu [cSt] and rho [kg/m^3] at 25 degC [10]. Not in oilgap's
catalogue: the rig writes them with per-row ``nu_cSt`` and ``density_kg_m3``."""

SILICONE_VTC = 0.59
"""Viscosity-temperature coefficient 1 - nu(99 degC)/nu(38 degC) of PDMS [-] [10]."""

SILICONE_EXPANSION_1_K = 9.6e-4
"""Volumetric expansion of PDMS [1/K] [10]."""

EQ6_BRANCHES = ((64.0, 10.0, -1.0), (500.0, 2.00, -0.6), (1.0e4, 1.03, -0.5),
                (math.inf, 0.065, -0.2))
"""(upper Re, coefficient, exponent) of the four branches of Eq. 6 [1]."""

TAYLOR_ONSET = 41.3
"""Critical Taylor number Re (delta/R)^0.5 [-] [8]."""

CARREAU_INDEX = 0.6
"""Power-law index n of the injected Carreau fluid [-] [9]."""

STRIBECK = (1.5, 5.0)
"""Seal: breakaway torque as a multiple of tau_c [-], Stribeck speed [rad/s] [7]."""


# --------------------------------------------------------------------------- fluids


def walther_coefficients(nu40_cSt, nu100_cSt):
    """ASTM D341 line ``log10 log10(nu + 0.7) = A - B log10(T/K)`` through 40 and 100 degC.

    Returns (A, B) [-] [3].
    """
    z40 = math.log10(math.log10(nu40_cSt + 0.7))
    z100 = math.log10(math.log10(nu100_cSt + 0.7))
    x40, x100 = math.log10(ZERO_CELSIUS_K + 40.0), math.log10(ZERO_CELSIUS_K + 100.0)
    B = (z40 - z100) / (x100 - x40)
    return z40 + B * x40, B


def fluid_state(name: str, temp_C):
    """Kinematic viscosity [m^2/s] and density [kg/m^3] of a rig fluid at temp_C [degC].

    ISO VG oils: Walther [3] and a linear expansion; silicone oils: Andrade with B
    such that nu(99)/nu(38) = 1 - VTC [10].
    """
    t = np.asarray(temp_C, dtype=float)
    if name in SILICONE_OILS:
        nu25, rho25 = SILICONE_OILS[name]
        b = -math.log(1.0 - SILICONE_VTC) / (1.0 / (ZERO_CELSIUS_K + 38.0)
                                             - 1.0 / (ZERO_CELSIUS_K + 99.0))
        nu = nu25 * np.exp(b * (1.0 / (t + ZERO_CELSIUS_K) - 1.0 / (ZERO_CELSIUS_K + 25.0)))
        return cst_to_m2_s(nu), rho25 / (1.0 + SILICONE_EXPANSION_1_K * (t - 25.0))
    nu40, nu100, rho15 = VG_OILS[name]
    A, B = walther_coefficients(nu40, nu100)
    nu_cSt = 10.0 ** (10.0 ** (A - B * np.log10(t + ZERO_CELSIUS_K))) - 0.7
    return cst_to_m2_s(nu_cSt), rho15 / (1.0 + THERMAL_EXPANSION_1_K * (t - 15.0))


# --------------------------------------------------------------------------- clearance loss


def eq6_moment_coefficient(re, gap_ratio):
    """Piecewise Eq. 6 [1]: C_m [-] at Couette Re [-] and x = delta/R [-]."""
    re = np.maximum(np.asarray(re, dtype=float), 1e-12)
    conds = [re < upper for upper, _, _ in EQ6_BRANCHES[:-1]]
    vals = [c * re**b for _, c, b in EQ6_BRANCHES]
    return np.select(conds, vals[:-1], vals[-1]) * gap_ratio**0.3


def couette_moment_coefficient(re, gap_ratio):
    """Exact circular-Couette C_m = 8 (1+x)^2 / ((2+x) Re) [-] [2]."""
    re = np.maximum(np.asarray(re, dtype=float), 1e-12)
    return 8.0 * (1.0 + gap_ratio) ** 2 / ((2.0 + gap_ratio) * re)


def annulus_power(omega, nu, rho, radius_m, gap_m, length_m, *,
                  roughness: tuple[float, float] = (1.0, 0.0), couette_floor=True):
    """Viscous power [W] of one clearance and its Couette Re [-].

    ``Re = |w| R delta / nu``; C_m from Eq. 6 (piecewise), at least the Couette
    value if ``couette_floor``; times T^gamma with ``roughness = (T, gamma)``;
    ``P = 0.5 pi C_m rho |w|^3 R^4 L`` [1], [2].
    """
    roughness_T, gamma = roughness
    w = np.abs(omega)
    re = w * radius_m * gap_m / nu
    x = gap_m / radius_m
    cm = eq6_moment_coefficient(re, x)
    if couette_floor:
        cm = np.maximum(cm, couette_moment_coefficient(re, x))
    cm = cm * np.asarray(roughness_T, dtype=float) ** gamma
    return 0.5 * np.pi * cm * rho * w**3 * radius_m**4 * length_m, re


# --------------------------------------------------------------------------- effect laws


def enclosed_disc_power(omega, nu, rho, r_outer_m, r_inner_m, axial_gap_m, merged=False):
    """Both end faces of the rotor in a housing [W], Daily & Nece [5].

    Regime II (laminar, separate boundary layers): ``C_M = 3.70 G^0.1 Re^-0.5``,
    G = s/r_o, Re = ``|w|`` r_o^2/nu; with ``merged`` the larger of that and regime I
    (Couette disc) ``2 pi / (G Re)``. ``P = 0.5 C_M rho |w|^3 (r_o^5 - r_i^5)``.
    """
    w = np.abs(omega)
    g = axial_gap_m / r_outer_m
    re = np.maximum(w * r_outer_m**2 / nu, 1e-12)
    cm = 3.70 * g**0.1 * re**-0.5
    if merged:
        cm = np.maximum(cm, 2.0 * np.pi / (g * re))
    return 0.5 * cm * rho * w**3 * (r_outer_m**5 - r_inner_m**5)


def palmgren_churning_power(omega, nu, pitch_diameter_m, f0):
    """Load-independent rolling-bearing loss [W]: ``M_0 |w|``, Palmgren [6].

    ``M_0 = 1e-7 f0 (nu n)^(2/3) d_m^3`` N mm (nu [cSt], n [rpm], d_m [mm]) for
    ``nu n >= 2000``, ``160e-7 f0 d_m^3`` below.
    """
    w = np.abs(omega)
    nn = m2_s_to_cst(nu) * rad_s_to_rpm(w)
    m0 = f0 * np.where(nn >= 2000.0, 1e-7 * np.maximum(nn, 2000.0) ** (2.0 / 3.0), 160e-7)
    return mm_to_m(m0 * m_to_mm(pitch_diameter_m) ** 3) * w


def stribeck_seal_power(omega, coulomb_Nm):
    """Seal loss [W]: ``tau |w|``, ``tau = tau_c (1 + (k-1) exp(-(w/w_s)^2))`` [7]."""
    k, ws = STRIBECK
    return coulomb_Nm * (1.0 + (k - 1.0) * np.exp(-(np.asarray(omega) / ws) ** 2)) \
        * np.abs(omega)


def wendt_taylor_excess(re, gap_m, radius_m):
    """Torque excess of Taylor vortices over the laminar torque [-] [8].

    ``max(0, (Re/Re_c)^0.5 - 1)`` with ``Re_c = 41.3 (R/delta)^0.5``: zero below
    onset, growing as Wendt's G ~ Re^1.5 against the laminar G ~ Re above it.
    """
    ratio = np.asarray(re) * np.sqrt(gap_m / radius_m) / TAYLOR_ONSET
    return np.maximum(np.sqrt(ratio) - 1.0, 0.0)


def carreau_ratio(shear_rate_1_s, lam_s, n=CARREAU_INDEX):
    """Carreau viscosity ratio ``(1 + (lambda gamma_dot)^2)^((n-1)/2)`` [-] [9]."""
    return (1.0 + (lam_s * np.asarray(shear_rate_1_s)) ** 2) ** ((n - 1.0) / 2.0)


def lag_update(y, x0, x1, h_s, tau_s):
    """Exact step of ``|tau| dy/dt = x - y`` over h_s [s], x linear from x0 to x1 [4]."""
    e = math.exp(-h_s / abs(tau_s))
    return x1 + (y - x0) * e - (x1 - x0) / h_s * abs(tau_s) * (1.0 - e)


def ar1_noise(rng: np.random.Generator, n: int, sigma: float, phi: float) -> np.ndarray:
    """Stationary AR(1) noise: variance sigma^2, lag-1 autocorrelation phi [11]."""
    w = rng.standard_normal(n)
    e0 = sigma * w[0]
    if n == 1:
        return np.array([e0])
    rest, _ = lfilter([sigma * math.sqrt(1.0 - phi * phi)], [1.0, -phi], w[1:],
                      zi=[phi * e0])
    return np.concatenate([[e0], rest])


# --------------------------------------------------------------------------- rig parts


@dataclass(frozen=True)
class Annulus:
    """A clearance region: rotation radius, radial gap, length [m]."""

    radius_m: float
    gap_m: float
    length_m: float


@dataclass(frozen=True)
class RigGeometry:
    """The joint: region 1 (grooved, per-run T), optional region 2 (bearing), end faces.

    The end faces turn between ``shaft_bore_m`` and region 1's radius, with an
    axial clearance ``disc_axial_gap_m`` to the housing; the bearing's pitch
    diameter is ``2 R2 + delta2``.
    """

    name: str
    region1: Annulus
    region2: Annulus | None = None
    shaft_bore_m: float = 10.0e-3
    disc_axial_gap_m: float = 5.0e-3

    @property
    def bearing_pitch_m(self) -> float | None:
        """Bearing pitch diameter d_m [m] (None without region 2)."""
        r2 = self.region2
        return None if r2 is None else 2.0 * r2.radius_m + r2.gap_m

    def case_document(self, groove_depth_m: float = 1.5e-3) -> dict:
        """The geometry as an oilgap case TOML document (``case_from_dict``), units in keys."""
        r1, mm = self.region1, m_to_mm
        doc = {"name": self.name,
               "region1": {"T1_mm": mm(r1.radius_m - groove_depth_m), "T2_mm": mm(r1.radius_m),
                           "T3_mm": mm(r1.radius_m + r1.gap_m),
                           "T4_mm": mm(r1.radius_m + r1.gap_m + groove_depth_m),
                           "length_mm": mm(r1.length_m)},
               "motor": {"shaft_bore_radius_mm": mm(self.shaft_bore_m)},
               # stated, not the seed-fit default: the loop is given no groove law for this rig
               "friction": {"gamma": 0.0}}
        if self.region2 is not None:
            r2 = self.region2
            doc["region2"] = {"radius_mm": mm(r2.radius_m), "length_mm": mm(r2.length_m),
                              "gap_mm": mm(r2.gap_m)}
        return doc


SEED_GEOMETRY = RigGeometry("seed joint (outside rig)", Annulus(25.4e-3, 1.0e-3, 14.76e-3),
                            Annulus(22.0e-3, 5.0e-3, 14.24e-3))
"""The seed joint: region 1 R 25.4 mm, delta 1 mm, L 14.76 mm; region 2 R 22, delta 5, L 14.24."""

OPEN_GEOMETRY = RigGeometry("rig without a bearing region (outside rig)",
                            Annulus(40.0e-3, 0.6e-3, 30.0e-3), None, 15.0e-3, 3.0e-3)
"""A larger motor, no bearing annulus in the oil (as tests/data/rig_no_bearing.toml)."""


@dataclass(frozen=True, kw_only=True)
class RigBaseline:
    """Electrical input without oil and the heat it leaves in the joint.

    ``P = P_e + tau_L |w| + k_g |tau_L w|^p + J w dw/dt + k_cu (1 + a (t_coil - 20)) tau_m^2``
    with ``tau_m = tau_L sign(w) + J dw/dt`` (plus the oil's torque if
    ``copper_carries_viscous``). Heat: copper + ``gear_heat_share`` of the gear loss.
    """

    electronics_W: float = 4.0
    load_torque_Nm: float = 0.08
    gear_coeff: float = 0.1
    gear_exponent: float = 1.3
    rotor_inertia_kg_m2: float = 2.0e-4
    copper_W_Nm2: float = 40.0
    copper_tempco_1_K: float = 0.00393
    gear_heat_share: float = 0.5
    copper_carries_viscous: bool = False

    def power(self, omega, accel, coil_C, oil_W=0.0):
        """(electrical input [W], heat into the joint [W]) at speed, acceleration, coil temp."""
        w = np.asarray(omega, dtype=float)
        load = self.load_torque_Nm * np.abs(w)
        gear = self.gear_coeff * load**self.gear_exponent
        tau_m = self.load_torque_Nm * np.sign(w) + self.rotor_inertia_kg_m2 * accel
        if self.copper_carries_viscous:
            tau_m = tau_m + np.sign(w) * oil_W / np.maximum(np.abs(w), 1e-9)
        copper = self.copper_W_Nm2 * (1.0 + self.copper_tempco_1_K * (coil_C - 20.0)) * tau_m**2
        elec = self.electronics_W + load + gear + self.rotor_inertia_kg_m2 * w * accel + copper
        return elec, copper + self.gear_heat_share * gear


@dataclass(frozen=True)
class ThermalNode:
    """Lumped joint: ``C dT/dt = Q - (T - T_amb)/R`` [4], starting at ambient."""

    ambient_C: float = 25.0
    resistance_K_W: float = 0.25
    capacity_J_K: float = 240.0

    def step(self, temp_C, heat_W, h_s):
        """Temperature [degC] after h_s [s] with the heat held: the exact exponential solution."""
        steady = self.ambient_C + self.resistance_K_W * heat_W
        tau = self.resistance_K_W * self.capacity_J_K
        return steady + (temp_C - steady) * math.exp(-h_s / tau)


PROFILES = ("sine", "trapezoid", "step")


@dataclass(frozen=True)
class SpeedProfile:
    """Motor speed against time, periodic; at rest before t = 0.

    * ``sine``: ``w0 sin(2 pi t / period)``;
    * ``trapezoid``: ramp to +w0 in ``ramp_s``, hold, ramp to 0, the same reversed;
    * ``step``: the ``levels`` (fractions of w0) in turn, each reached by a ramp
      of ``ramp_s``, back to 0 at the end of the period.
    """

    kind: str = "trapezoid"
    peak_rpm: float = 3000.0
    period_s: float = 20.0
    ramp_s: float = 3.0
    levels: tuple[float, ...] = (0.3, 1.0, -0.6, -1.0, 0.6)

    def knots(self) -> tuple[np.ndarray, np.ndarray]:
        """Times [s] and speeds [rad/s] of one period of a piecewise-linear profile."""
        w0, r, P = rpm_to_rad_s(self.peak_rpm), self.ramp_s, self.period_s
        if self.kind == "trapezoid":
            h = P / 2.0 - 2.0 * r
            if h < 0:
                raise InputError("ramp_s", r, f"at most period_s/4 = {P / 4:g}", WHERE)
            return np.cumsum([0.0, r, h, r, r, h, r]), w0 * np.array([0.0, 1, 1, 0, -1, -1, 0])
        n = len(self.levels)
        H = (P - r) / max(n, 1)
        if n == 0 or H <= r:
            raise InputError("levels", self.levels, "need period_s > (len(levels)+1) ramp_s",
                             WHERE)
        t, v = [0.0], [0.0]
        for i, lev in enumerate(self.levels):
            t += [i * H + r, (i + 1) * H]
            v += [lev * w0, lev * w0]
        return np.array(t + [P]), np.array(v + [0.0])

    def __call__(self, t):
        """Speed [rad/s] and acceleration [rad/s^2] at times t [s]."""
        t = np.asarray(t, dtype=float)
        before = t < 0
        if self.kind == "sine":
            w0, f = rpm_to_rad_s(self.peak_rpm), 2.0 * np.pi / self.period_s
            w, a = w0 * np.sin(f * t), w0 * f * np.cos(f * t)
        else:
            kt, kv = self.knots()
            tau = np.mod(t, self.period_s)
            w = np.interp(tau, kt, kv)
            dt = np.diff(kt)
            slope = np.divide(np.diff(kv), dt, out=np.zeros_like(dt), where=dt > 0)
            a = slope[np.clip(np.searchsorted(kt, tau, side="right") - 1, 0, len(dt) - 1)]
        return np.where(before, 0.0, w), np.where(before, 0.0, a)
