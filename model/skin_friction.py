"""Skin-friction (moment) coefficient C_m of a rotating clearance.

Three forms of the Bilgen-Boulos correlation (seed Eq. 6), the general power
law (Eq. 7) and the groove-roughness law (Eq. 8):

* ``bilgen_boulos_cm``: Eq. 6 exactly, piecewise in Re (breaks at 64, 500, 1e4).
* ``bilgen_boulos_cm_smooth``: the same branches blended with logistic weights
  in ln Re (width :data:`SMOOTH_WIDTH`), twice differentiable everywhere, for
  the optimizer. Outside a +-10 % band of Re around each break it is within
  3 % of the exact form (tested in ``tests/model/test_skin_friction.py``).
* ``branches_cm`` (form ``"branches"``): a smooth maximum (log-sum-exp in ln C_m,
  width :data:`BRANCHES_WIDTH`) of power-law branches ``C_k x^alpha_k Re^beta_k``,
  each with its own gap exponent; the regime boundaries are where branches cross.
  Its defaults are the four branches of Eq. 6. Eq. 6's published breaks at 64
  and 500 are not crossings of its branches (the branches cross at Re = 55.9 and
  762; the break at 1e4 is one, at 9996), so between 55.9 and 64 and between 500
  and 762 the default branches form is the larger branch, up to 5.7 % and 4.5 %
  above Eq. 6 (smoothing included); elsewhere it is Eq. 6 within the smoothing (at most
  ``BRANCHES_WIDTH ln 2`` = 1.4 % at a crossing, < 0.1 % where the next branch is
  6 % or more lower: beyond a factor 1.25 in Re from 55.9 and 9996, 1.9 from 762).
* laminar law ``"couette"`` (default): ``C_m = max(C_m,Couette, C_m,Eq.6)`` with
  the exact circular-Couette coefficient ``8 (1+x)^2 / ((2+x) Re)``. No flow
  between the cylinders dissipates less than laminar Couette flow (Helmholtz's
  minimum-dissipation theorem: the circular Couette field is also the Stokes
  flow for these boundary values), so Eq. 6 values below it are unphysical.
  Laminar law ``"bilgen-boulos"`` uses Eq. 6 as it stands. ``transition = "taylor"``
  keeps exact Couette up to Ta_c(eta) instead (:mod:`oilgap.model.transition`).

All functions accept floats, numpy arrays and CasADi symbols.

References
----------
.. [1] E. Bilgen, R. Boulos, ASME J. Fluids Eng. 95(1):122-126, 1973.
.. [2] J. Pyrhönen, T. Jokinen, V. Hrabovcová, *Design of Rotating Electrical
   Machines*, 2nd ed., Wiley 2014, p. 528.
.. [3] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 5-9.
.. [4] H. Helmholtz (1868); D. J. Korteweg, Phil. Mag. 16:112-118, 1883
   (minimum dissipation of Stokes flow).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from enum import StrEnum
from typing import Literal

import numpy as np

from . import _math as m
from .errors import InputError, check_finite, check_positive
from .io.inputs import check_physical
from .taylor_couette import REGIME_BOUNDARIES_RE, couette_moment_coefficient
from .taylor_couette import couette_floor_applies as floored
from .transition import Transition, check_transition, taylor_cm, taylor_cm_smooth

BILGEN_BOULOS_BRANCHES = ((10.0, -1.0), (2.00, -0.6), (1.03, -0.5), (0.065, -0.2))
"""(C, beta) of the four branches of seed Eq. 6; each is multiplied by (delta/R)^0.3 [1]."""

BILGEN_BOULOS_ALPHA = 0.3
"""Gap-ratio exponent alpha of every branch of Eq. 6 [1]."""

BRANCH_C = tuple(c for c, _ in BILGEN_BOULOS_BRANCHES)
"""Default C_k of the ``"branches"`` form: Eq. 6's (10, 2.00, 1.03, 0.065) [1]."""

BRANCH_ALPHA = (BILGEN_BOULOS_ALPHA,) * len(BILGEN_BOULOS_BRANCHES)
"""Default gap exponents alpha_k of the ``"branches"`` form: 0.3 each, as in Eq. 6 [1]."""

BRANCH_BETA = tuple(b for _, b in BILGEN_BOULOS_BRANCHES)
"""Default Reynolds exponents beta_k of the ``"branches"`` form: Eq. 6's (-1, -0.6, -0.5,
-0.2) [1]."""

BRANCH_KEYS = ("branch_C", "branch_alpha", "branch_beta")
"""The ``[friction]`` keys (arrays, one number per branch) of the ``"branches"`` form."""

BRANCHES_WIDTH = 0.02
"""Width in ln C_m of the log-sum-exp maximum of the ``"branches"`` form [-]: it exceeds the
largest branch by at most ``width ln n`` (1.4 % where two branches cross) and by
``width exp(-d/width)`` at a distance d in ln C_m from the next one."""

SMOOTH_WIDTH = 0.025
"""Width in ln Re of the logistic blends of the smooth form [-]."""

SMOOTH_MAX_WIDTH = 0.02
"""Width in ln C_m of the smooth max between Couette and Eq. 6 [-]."""

RE_FLOOR = 1.0e-12
"""Reynolds numbers below this are evaluated at it (power there is ~0 anyway)."""


class FrictionForm(StrEnum):
    """How C_m is computed (:class:`FrictionLaw` ``form``), equal to its plain string.

    Attributes
    ----------
    BILGEN_BOULOS, SMOOTH, POWER_LAW, BRANCHES : str
        Eq. 6 exactly, its smooth form, one power law (Eq. 7), smooth max of branches [-].
    """

    BILGEN_BOULOS = "bilgen-boulos"
    SMOOTH = "smooth"
    POWER_LAW = "power-law"
    BRANCHES = "branches"


class LaminarLaw(StrEnum):
    """The laminar bound of Eq. 6 (:class:`FrictionLaw` ``laminar_law``), equal to its string.

    Attributes
    ----------
    COUETTE, BILGEN_BOULOS : str
        Eq. 6 bounded below by the exact laminar Couette law; Eq. 6 as published [-].
    """

    COUETTE = "couette"
    BILGEN_BOULOS = "bilgen-boulos"


FORMS = tuple(f.value for f in FrictionForm)
LAMINAR_LAWS = tuple(law.value for law in LaminarLaw)  # the one list of both

FRICTION_RANGES = {
    "gamma": (0.0, 3.0, "T^gamma >= 1: grooves raise a clearance's loss (every smoothed run "
              "of the seed's Table 4 lost less), so gamma >= 0; the seed's fits give "
              "0.57-0.98 and the smoothing study bounds it by 3 (above it, halving T would "
              "cut the loss more than 8-fold)"),
    "scale": (0.01, 100.0, "a calibration factor on the measured Eq. 6; one that moves it "
              "100-fold either way says Eq. 6 does not describe the joint (use form = "
              "\"power-law\")"),
    "C": (1.0e-4, 1.0e4, "the branches of Eq. 6 have C = 0.065-10; 1000-fold outside that "
          "is a slip, not a law"),
    "alpha": (-2.0, 2.0, "Eq. 6 has alpha = 0.3; over the gap ratios of real clearances "
              "(0.001-1) |alpha| > 2 changes C_m more than a million-fold"),
    "beta": (-1.5, 0.5, "laminar Couette flow has beta = -1, fully rough turbulence beta -> "
             "0, the branches of Eq. 6 -1 to -0.2; outside [-1.5, 0.5] no clearance flow "
             "behaves so (the torque would fall as the speed rises, or grow without bound)"),
}
"""Physical range of each number of a friction law given as input (a case's
``[friction]``, a sweep's ``gamma``/``scale`` column): key -> (lowest, highest, reason).
A fit (the loop's calibration) may explore outside them; an input may not
(:func:`check_friction_ranges`)."""


def power_law_cm(reynolds, gap_ratio, C, alpha, beta):
    """General power law ``Cm = C (delta/R)^alpha Re^beta`` (seed Eq. 7) [-].

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R [-].
    C, alpha, beta : float
        Coefficient [-] and exponents [-] of the law.

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient C_m [-].

    References
    ----------
    Seed paper (Eq. 7) [3]; each branch of Bilgen & Boulos [1] is one instance.
    """
    return C * gap_ratio**alpha * reynolds**beta


def groove_roughness_factor(roughness_T, gamma):
    """Groove-roughness factor ``T^gamma`` of seed Eq. 8 [-].

    Parameters
    ----------
    roughness_T : float, array or CasADi symbol
        Clearance roughness T [-] (Eq. 9; 1 for a smooth annulus).
    gamma : float or CasADi symbol
        Roughness exponent [-].

    Returns
    -------
    float, array or CasADi expression
        Factor on C_m [-].

    References
    ----------
    Seed paper (Eq. 8) [3].
    """
    return roughness_T**gamma


def groove_roughness(T1_m, T2_m, T3_m, T4_m):
    """Clearance roughness ``T = (T4 - T1) / (T3 - T2)`` (seed Eq. 9) [-].

    T3 - T2 is the clearance; the groove depths add to it.

    Parameters
    ----------
    T1_m : float, array or CasADi symbol
        Rotor groove-bottom radius [m].
    T2_m : float, array or CasADi symbol
        Rotor outer radius [m].
    T3_m : float, array or CasADi symbol
        Stator bore radius [m].
    T4_m : float, array or CasADi symbol
        Stator groove-bottom radius [m].

    Returns
    -------
    float, array or CasADi expression
        Roughness T [-] (1 for smooth walls).

    References
    ----------
    Seed paper (Eq. 9) [3]; the radii as read from its Fig. 5.
    """
    return (T4_m - T1_m) / (T3_m - T2_m)


def bilgen_boulos_cm(reynolds, gap_ratio, alpha=BILGEN_BOULOS_ALPHA):
    """Seed Eq. 6 exactly: the piecewise Bilgen-Boulos moment coefficient [-].

    ``C_m = C_k x^alpha Re^beta_k`` (alpha = 0.3 as published) with (C, beta) =
    (10, -1) for Re < 64, (2.00, -0.6) for 64 <= Re < 500, (1.03, -0.5) for
    500 <= Re < 1e4 and (0.065, -0.2) above.

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R [-].
    alpha : float
        Gap-ratio exponent [-] (:data:`BILGEN_BOULOS_ALPHA`; a calibration may free it).

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient C_m [-].

    References
    ----------
    Bilgen & Boulos [1]; Pyrhönen et al. [2]; seed paper (Eq. 6) [3].
    """
    if np.ndim(reynolds) and not m.is_symbolic(reynolds, gap_ratio, alpha):
        k = (reynolds >= REGIME_BOUNDARIES_RE[0]).view(np.uint8)  # numpy: each point's
        for re_k in REGIME_BOUNDARIES_RE[1:]:  # branch only (in bytes; NaN: branch 0, NaN
            k += (reynolds >= re_k).view(np.uint8)  # C_m), the form below to 1e-15
        c, beta = np.take(np.array(BILGEN_BOULOS_BRANCHES).T, k.astype(np.intp), axis=1)
        re_beta = np.exp(beta * np.log(reynolds))  # power of an array of exponents: no SIMD
        np.copyto(re_beta, np.divide(1.0, reynolds), where=k == 0)  # as numpy's Re**-1.0
        return power_law_cm(re_beta, gap_ratio, c, alpha, 1.0)
    b = [power_law_cm(reynolds, gap_ratio, C, alpha, beta) for C, beta in BILGEN_BOULOS_BRANCHES]
    r1, r2, r3 = REGIME_BOUNDARIES_RE
    return m.where(reynolds < r1, b[0], m.where(reynolds < r2, b[1],
                                                m.where(reynolds < r3, b[2], b[3])))


def bilgen_boulos_cm_smooth(reynolds, gap_ratio, width=SMOOTH_WIDTH, alpha=BILGEN_BOULOS_ALPHA):
    """Smooth form of Eq. 6: branches blended in log space with logistic weights.

    ``ln Cm = ln Cm_1 + sum_k s_k (ln Cm_{k+1} - ln Cm_k)``,
    ``s_k = sigmoid((ln Re - ln Re_k) / width)`` at the breaks Re_k = 64, 500,
    1e4. Every branch is an instance of Eq. 7, so the blend is Eq. 7 with a
    Reynolds-dependent C and beta.

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R [-].
    width : float
        Width of the logistic blends in ln Re [-] (:data:`SMOOTH_WIDTH`).
    alpha : float
        Gap-ratio exponent [-] (:data:`BILGEN_BOULOS_ALPHA`).

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient C_m [-].

    References
    ----------
    Bilgen & Boulos [1]; seed paper (Eqs. 6-7) [3].
    """
    ln_re = m.log(reynolds)
    ln_x = m.log(gap_ratio)
    lnc = [math.log(C) + alpha * ln_x + beta * ln_re
           for C, beta in BILGEN_BOULOS_BRANCHES]
    out = lnc[0]
    for k, re_k in enumerate(REGIME_BOUNDARIES_RE):
        out = out + m.sigmoid((ln_re - math.log(re_k)) / width) * (lnc[k + 1] - lnc[k])
    return m.exp(out)


def couette_law_cm(reynolds, gap_ratio, alpha=BILGEN_BOULOS_ALPHA):
    """Eq. 6 bounded below by the exact laminar law: ``max(Couette, Eq. 6)`` [-].

    No flow between the cylinders dissipates less than circular Couette flow
    (minimum dissipation of Stokes flow), so Eq. 6 values below it are unphysical.

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R [-].
    alpha : float
        Gap-ratio exponent of Eq. 6 [-] (:data:`BILGEN_BOULOS_ALPHA`).

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient C_m [-].

    References
    ----------
    White, *Viscous Fluid Flow*, sec. 3-2.3 (circular Couette flow); Helmholtz and
    Korteweg [4]; Bilgen & Boulos [1]; seed paper (Eq. 6) [3].
    """
    return m.fmax(couette_moment_coefficient(reynolds, gap_ratio),
                  bilgen_boulos_cm(reynolds, gap_ratio, alpha))


def couette_law_cm_smooth(reynolds, gap_ratio, width=SMOOTH_WIDTH,
                          max_width=SMOOTH_MAX_WIDTH, alpha=BILGEN_BOULOS_ALPHA):
    """Smooth form of :func:`couette_law_cm`: a smooth max in log space of the
    Couette coefficient and :func:`bilgen_boulos_cm_smooth` [-].

    ``ln C_m = ln C_c + smooth_relu(ln C_bb - ln C_c, max_width)``.

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R [-].
    width : float
        Width of the branch blends in ln Re [-] (:data:`SMOOTH_WIDTH`).
    max_width : float
        Width of the smooth max in ln C_m [-] (:data:`SMOOTH_MAX_WIDTH`).
    alpha : float
        Gap-ratio exponent of Eq. 6 [-] (:data:`BILGEN_BOULOS_ALPHA`).

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient C_m [-].

    References
    ----------
    As :func:`couette_law_cm` (Helmholtz, Korteweg [4], Bilgen & Boulos [1], Eq. 6 [3]).
    """
    ln_cc = m.log(couette_moment_coefficient(reynolds, gap_ratio))
    ln_bb = m.log(bilgen_boulos_cm_smooth(reynolds, gap_ratio, width, alpha))
    return m.exp(ln_cc + m.smooth_relu(ln_bb - ln_cc, max_width))


def log_sum_exp_max(terms, width):
    """Smooth maximum ``width ln sum_k exp(t_k / width)`` of a list of terms [-].

    Evaluated shifted by the largest term so that it never overflows; the shift
    cancels exactly, so the value and its derivatives (CasADi's too) are those of
    the unshifted expression. It exceeds ``max_k t_k`` by at most ``width ln n``.

    Parameters
    ----------
    terms : list of float, array or CasADi symbol
        The terms t_k (here ln C_m of each branch) [-].
    width : float
        Smoothing width, in the unit of the terms [-].

    Returns
    -------
    float, array or CasADi expression
        The smooth maximum [-].

    References
    ----------
    S. Boyd, L. Vandenberghe, *Convex Optimization*, Cambridge 2004, sec. 3.1.5
    (log-sum-exp as a smooth maximum).
    """
    top = terms[0]
    for t in terms[1:]:
        top = m.fmax(top, t)
    total = 0.0
    for t in terms:
        total = total + m.exp((t - top) / width)
    return top + width * m.log(total)


def branches_cm(reynolds, gap_ratio, C=BRANCH_C, alpha=BRANCH_ALPHA, beta=BRANCH_BETA,
                width=BRANCHES_WIDTH, floor=None):
    """Smooth maximum of power-law branches ``C_k x^alpha_k Re^beta_k`` [-].

    ``ln C_m = LSE_width(ln C_k + alpha_k ln x + beta_k ln Re [, ln floor])``: each
    branch (seed Eq. 7) has its own gap exponent, and a regime ends where the next
    branch overtakes it, so the boundaries follow from the branches (no fixed Re
    breaks). With the defaults it is Eq. 6 except between Re 55.9 and 64 (up to
    +5.7 %) and 500 and 762 (up to +4.5 %), where Eq. 6's breaks are not crossings
    of its branches, and within ``width ln 2`` at the crossings.

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R [-].
    C, alpha, beta : sequence of float
        Coefficients C_k [-] (> 0), gap exponents alpha_k [-] and Reynolds
        exponents beta_k [-], one per branch (defaults: the four of Eq. 6).
    width : float
        Width of the maximum in ln C_m [-] (:data:`BRANCHES_WIDTH`).
    floor : float, array or CasADi symbol, optional
        A lower bound taken into the maximum as one more term (the laminar Couette
        coefficient) [-].

    Returns
    -------
    float, array or CasADi expression
        Moment coefficient C_m [-].

    References
    ----------
    Bilgen & Boulos [1] (the default branches); seed paper (Eqs. 6-7) [3].
    """
    ln_re = m.log(reynolds)
    ln_x = m.log(gap_ratio)
    terms = [math.log(c) + a * ln_x + b * ln_re for c, a, b in zip(C, alpha, beta, strict=True)]
    if floor is not None:
        terms.append(m.log(floor))
    return m.exp(log_sum_exp_max(terms, width))


@dataclass(frozen=True)
class FrictionLaw:
    """How C_m is computed.

    Attributes
    ----------
    form : {"bilgen-boulos", "smooth", "power-law", "branches"}
        Eq. 6 exactly, its smooth form, one power law (Eq. 7) with C, alpha, beta
        (equations of the seed paper [3]), or the smooth maximum of
        branches with their own C_k, alpha_k, beta_k (:func:`branches_cm`).
    laminar_law : {"couette", "bilgen-boulos"}
        ``"couette"``: Eq. 6 bounded below by the exact laminar Couette law;
        ``"bilgen-boulos"``: Eq. 6 as published (both Eq. 6 forms).
    gamma : float
        Groove-roughness exponent of Eq. 8 [-] (applies to region 1 only, via T).
    scale : float
        Multiplier on the Eq. 6 forms [-] (a calibration constant; 1 = as published).
    C, alpha, beta : float
        Coefficient [-] and exponents [-] of the power-law form (default: the Eq. 6
        laminar branch); alpha is also the gap-ratio exponent of the Eq. 6 forms
        (0.3 as published).
    branch_C, branch_alpha, branch_beta : tuple of float
        C_k [-], alpha_k [-] and beta_k [-] of the ``"branches"`` form, one per branch,
        of equal length (default: the four branches of Eq. 6, alpha_k = 0.3); the
        scale and T^gamma apply to it as to Eq. 6.
    transition : {"reynolds", "taylor"}
        Where C_m leaves the laminar law: Eq. 6's switch by Re (default) or exact Couette
        up to Ta_c (:func:`~oilgap.model.transition.taylor_cm`; Eq. 6 forms only).

    Raises
    ------
    InputError
        Unknown form or laminar law, non-finite exponents, C, C_k or scale <= 0,
        branch arrays empty or of different lengths.
    """

    form: Literal["bilgen-boulos", "smooth", "power-law", "branches"] = "bilgen-boulos"
    laminar_law: Literal["couette", "bilgen-boulos"] = "couette"
    gamma: float = 0.0
    scale: float = 1.0
    C: float = 10.0
    alpha: float = 0.3
    beta: float = -1.0
    branch_C: tuple[float, ...] = BRANCH_C
    branch_alpha: tuple[float, ...] = BRANCH_ALPHA
    branch_beta: tuple[float, ...] = BRANCH_BETA
    transition: Literal["reynolds", "taylor"] = "reynolds"

    def __post_init__(self):
        where = "friction"
        check_transition(self.transition, self.form, self.laminar_law, where)
        if self.form not in FORMS:
            raise InputError("form", self.form, f"allowed: {', '.join(FORMS)}", where)
        if self.laminar_law not in LAMINAR_LAWS:
            raise InputError("laminar_law", self.laminar_law,
                             f"allowed: {', '.join(LAMINAR_LAWS)}", where)
        for f in ("gamma", "alpha", "beta"):
            check_finite(f, getattr(self, f), where)
        check_positive("scale", self.scale, where)
        check_positive("C", self.C, where)
        self._check_branches(where)

    def _check_branches(self, where: str) -> None:
        n = len(self.branch_C)
        for key in BRANCH_KEYS:
            vals = getattr(self, key)
            if isinstance(vals, (str, bytes)) or not hasattr(vals, "__len__"):
                raise InputError(key, vals, "an array of numbers, one per branch", where)
            if len(vals) == 0 or len(vals) != n:
                raise InputError(key, list(vals), f"{n or 'one or more'} numbers (branch_C, "
                                 "branch_alpha and branch_beta have one per branch)", where)
            object.__setattr__(self, key, tuple(float(check_finite(key, v, where))
                                                for v in vals))
        for c in self.branch_C:
            check_positive("branch_C", c, where)

    def smooth(self) -> FrictionLaw:
        """The same law with the smooth form of Eq. 6 (power law stays as it is).

        Returns
        -------
        FrictionLaw
            ``form = "smooth"`` unless the form is ``"power-law"`` or ``"branches"``
            (smooth already); C_m stays [-].
        """
        smooth_already = self.form in (FrictionForm.POWER_LAW, FrictionForm.BRANCHES)
        return self if smooth_already else replace(self, form=FrictionForm.SMOOTH.value)


def check_friction_ranges(law: FrictionLaw, where: str = "friction") -> FrictionLaw:
    """Refuse a friction law whose numbers lie outside :data:`FRICTION_RANGES`.

    Parameters
    ----------
    law : FrictionLaw
        The law as given (gamma, scale, C, alpha, beta [-]).
    where : str
        Where it came from, for the message [-].

    Returns
    -------
    FrictionLaw
        ``law`` itself.

    Raises
    ------
    InputError
        A number outside its range; the message gives the range and why.

    References
    ----------
    Seed paper (Eqs. 6-8 and Table 4) [3]; Bilgen & Boulos [1].
    """
    for name, (lo, hi, reason) in FRICTION_RANGES.items():
        check_physical(name, getattr(law, name), lo, hi, reason, where)
    if law.form == FrictionForm.BRANCHES:
        for key, name in zip(BRANCH_KEYS, ("C", "alpha", "beta"), strict=True):
            lo, hi, reason = FRICTION_RANGES[name]
            for k, v in enumerate(getattr(law, key)):
                check_physical(f"{key}[{k + 1}]", v, lo, hi, reason, where)
    return law


def moment_coefficient(reynolds, gap_ratio, law: FrictionLaw, roughness_T=1.0):
    """Moment coefficient C_m [-] of a clearance under ``law`` (seed Eqs. 6-8).

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (floored at :data:`RE_FLOOR`).
    gap_ratio : float, array or CasADi symbol
        delta / R [-].
    law : FrictionLaw
        Form, laminar law, roughness exponent gamma [-], scale [-].
    roughness_T : float, array or CasADi symbol
        Clearance roughness T [-] (1 = smooth; Eq. 9).

    Returns
    -------
    float, array or CasADi expression
        ``scale * C_m,form(Re, x) * T^gamma`` [-] (no scale for the power law; the
        ``"branches"`` form takes the Couette law into its smooth maximum).

    References
    ----------
    Seed paper (Eqs. 6-8) [3]; Bilgen & Boulos [1].
    """
    re = m.fmax(reynolds, RE_FLOOR)
    if law.form == FrictionForm.POWER_LAW:
        base = power_law_cm(re, gap_ratio, law.C, law.alpha, law.beta)
    elif law.form == FrictionForm.BRANCHES:
        floor = (couette_moment_coefficient(re, gap_ratio)
                 if law.laminar_law == LaminarLaw.COUETTE else None)
        base = law.scale * branches_cm(re, gap_ratio, law.branch_C, law.branch_alpha,
                                       law.branch_beta, floor=floor)
    else:
        couette, smooth = law.laminar_law == LaminarLaw.COUETTE, law.form == FrictionForm.SMOOTH
        cm = ((couette_law_cm_smooth if smooth else couette_law_cm) if couette
              else (bilgen_boulos_cm_smooth if smooth else bilgen_boulos_cm))
        if law.transition == Transition.TAYLOR:
            cm = taylor_cm_smooth if smooth else taylor_cm
        base = law.scale * cm(re, gap_ratio, alpha=law.alpha)
    base = m.fmax(base, couette_moment_coefficient(re, gap_ratio)) if floored(law) else base
    if isinstance(law.gamma, (int, float)) and law.gamma == 0.0:
        return base
    return base * groove_roughness_factor(roughness_T, law.gamma)
