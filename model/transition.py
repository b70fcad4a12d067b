"""Where the Taylor vortices start: the transition of the skin friction as a choice.

Two transitions of the moment coefficient C_m (:class:`Transition`, the ``[friction]
transition`` key):

* ``"reynolds"`` (default): the laminar law ``max(Couette, Eq. 6)``
  (:func:`~oilgap.model.skin_friction.couette_law_cm`): Eq. 6's vortex branch takes over
  where it rises above Couette (Re ~ 74 at the seed's gap ratio, Ta ~ 14.7), the
  switch by Reynolds number that Bilgen & Boulos fitted on short enclosed cylinders,
  where end cells raise the torque before vortices do.
* ``"taylor"``: exact circular Couette flow up to the critical Taylor number of the
  gap's radius ratio (:func:`critical_taylor_number`, Esser & Grossmann [1]_), then
  Donnelly & Simon's supercritical torque law [2]_ ``G = a/Omega + b Omega^1.36``,
  continuous with Couette at onset and with Wendt's correlation [3]_ at ten times the
  critical speed (the upper end of Donnelly & Simon's range), then the larger of
  Wendt's correlation and Eq. 6's turbulent branches (:func:`taylor_cm`). The law of
  long cylinders, where nothing but the vortices raises the torque.

Ta and Re are the code's (seed Eqs. 3-4): ``Re = Omega R1 delta / nu``,
``Ta = Re (delta/R1)^0.5``, x = delta/R1, radius ratio eta = R1/R2 = 1/(1 + x).
Esser & Grossmann give the critical *inner Reynolds number* ``Re_c = Omega R1 d / nu``
(the code's Re); the critical Taylor number is ``Re_c x^0.5``. Every function accepts
floats, numpy arrays and CasADi symbols.

References
----------
.. [1] A. Esser, S. Grossmann, "Analytic expression for Taylor-Couette stability
   boundary", Phys. Fluids 8(7):1814-1819, 1996 (outer cylinder at rest:
   ``Re_c = (1+eta)^2 / (2 eta sqrt((1-eta)(3+eta))) / alpha^2``, alpha = 0.1556).
.. [2] R. J. Donnelly, N. J. Simon, "An empirical torque relation for supercritical flow
   between rotating cylinders", J. Fluid Mech. 7(3):401-418, 1960.
.. [3] F. Wendt, "Turbulente Strömungen zwischen zwei rotierenden konaxialen
   Zylindern", Ingenieur-Archiv 4:577-595, 1933 (outer cylinder at rest,
   ``G / (rho nu^2 L) = 1.45 eta^1.5 (1-eta)^-1.75 Re^1.5`` for 400 < Re < 1e4 and
   ``0.23 eta^1.5 (1-eta)^-1.75 Re^1.7`` for 1e4 < Re < 1e5; as quoted by
   Lathrop, Fineberg & Swinney, Phys. Rev. A 46:6390, 1992).
.. [4] E. Bilgen, R. Boulos, ASME J. Fluids Eng. 95(1):122-126, 1973 (Eq. 6).
.. [5] R. C. DiPrima, H. L. Swinney, "Instabilities and transition in flow between
   concentric rotating cylinders", in *Hydrodynamic Instabilities and the Transition
   to Turbulence*, Springer 1981 (linear-stability Re_c: 68.19 at eta = 0.5,
   184.98 at eta = 0.95).
"""

from __future__ import annotations

import math
from enum import StrEnum

import numpy as np

from . import _math as m
from .errors import InputError
from .taylor_couette import (
    REGIME_BOUNDARIES_RE,
    REGIME_NAMES,
    couette_moment_coefficient,
    flow_regime,
)


class Transition(StrEnum):
    """Where C_m leaves the laminar law (:class:`FrictionLaw` ``transition``).

    Attributes
    ----------
    REYNOLDS, TAYLOR : str
        ``max(Couette, Eq. 6)``, Eq. 6's switch by Reynolds number; exact Couette up to
        the critical Taylor number, then the supercritical law (:func:`taylor_cm`) [-].
    """

    REYNOLDS = "reynolds"
    TAYLOR = "taylor"


TRANSITIONS = tuple(t.value for t in Transition)
"""The allowed ``[friction] transition`` values, default first."""

ESSER_GROSSMANN_ALPHA = 0.1556
"""Esser & Grossmann's constant alpha [-]: ``1/alpha^2`` = 41.30 is the narrow-gap Ta_c [1]."""

DONNELLY_SIMON_EXPONENT = 1.36
"""Exponent of Omega in Donnelly & Simon's supercritical torque ``a/Omega + b Omega^1.36`` [2]."""

DONNELLY_SIMON_RANGE = 10.0
"""Upper end of Donnelly & Simon's law, in multiples of the critical speed [-] [2]."""

WENDT_COEFFICIENTS = ((1.45, 1.5), (0.23, 1.7))
"""(c, n) of Wendt's ``G/(rho nu^2 L) = c eta^1.5 (1-eta)^-1.75 Re^n`` [3]; they meet at
Re = 1e4."""

TURBULENT_BRANCHES = ((1.03, -0.5), (0.065, -0.2))
"""(C, beta) of Eq. 6's turbulent branches, each times x^alpha [4]."""

TAYLOR_SMOOTH_WIDTH = 0.025
"""Width in ln Re of the smooth form's blend at ten times the critical speed [-]."""

TAYLOR_MAX_WIDTH = 0.02
"""Width (in C_m / C_m,Couette - 1, and in ln C_m) of the smooth form's maxima [-]."""


def critical_reynolds_number(gap_ratio):
    """Critical Couette Reynolds number of Taylor-vortex onset, outer cylinder at rest [-].

    Esser & Grossmann's ``Re_c = (1+eta)^2 / (2 eta sqrt((1-eta)(3+eta))) / alpha^2``
    with eta = 1/(1+x), written in x = delta/R1:
    ``Re_c = (2+x)^2 / (2 sqrt(x (4+3x)) alpha^2)``. Within 3.1 % of linear stability
    theory for 0.5 <= eta < 1 (68.19 vs 70.2 at eta = 0.5, 184.98 vs 186.0 at 0.95 [5]).

    Parameters
    ----------
    gap_ratio : float, array or CasADi symbol
        x = delta / R1 [-] (> 0).

    Returns
    -------
    float, array or CasADi expression
        Re_c = Omega_c R1 delta / nu [-].

    References
    ----------
    Esser & Grossmann [1]_; DiPrima & Swinney [5]_ (the check).
    """
    x = gap_ratio
    return (2.0 + x) ** 2 / (2.0 * m.sqrt(x * (4.0 + 3.0 * x)) * ESSER_GROSSMANN_ALPHA**2)


def critical_taylor_number(gap_ratio):
    """Critical Taylor number ``Ta_c = Re_c x^0.5`` in the code's Ta (seed Eq. 3) [-].

    ``Ta_c = (2+x)^2 / (2 sqrt(4+3x) alpha^2)``: 41.30 for a narrow gap, 42.3 at the
    seed's region 1 (x = 0.039), 46.6 at x = 0.2 (eta = 0.83).

    Parameters
    ----------
    gap_ratio : float, array or CasADi symbol
        x = delta / R1 [-] (> 0).

    Returns
    -------
    float, array or CasADi expression
        Ta_c [-].

    References
    ----------
    Esser & Grossmann [1]_.
    """
    return critical_reynolds_number(gap_ratio) * m.sqrt(gap_ratio)


def _torque_to_cm(gap_ratio):
    """Factor k with ``C_m = k G* / Re^2``, G* = G / (rho nu^2 L) (seed Eq. 5) [-].

    From ``G = 0.5 pi C_m rho Omega^2 R1^4 L`` and ``Omega R1^2 / nu = Re / x``:
    ``C_m = 2 x^2 G* / (pi Re^2)``.
    """
    return 2.0 * gap_ratio**2 / math.pi


def wendt_cm(reynolds, gap_ratio):
    """Wendt's turbulent-vortex correlation as a moment coefficient [-].

    ``C_m = 2 x^2 / (pi Re^2) max_k c_k eta^1.5 (1-eta)^-1.75 Re^n_k`` with eta = 1/(1+x)
    (:data:`WENDT_COEFFICIENTS`; the two ranges meet at Re = 1e4, where the larger is
    the one that applies).

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R1 [-].

    Returns
    -------
    float, array or CasADi expression
        C_m [-].

    References
    ----------
    Wendt [3]_.
    """
    x = gap_ratio
    geo = (1.0 + x) ** 0.25 * x ** (-1.75)  # eta^1.5 (1 - eta)^-1.75
    g = [c * geo * reynolds**n for c, n in WENDT_COEFFICIENTS]
    return _torque_to_cm(x) * m.fmax(g[0], g[1]) / reynolds**2


def _upper_cm(reynolds, gap_ratio, alpha):
    """The law above Donnelly & Simon's range: max(Wendt, Eq. 6's turbulent branches)."""
    out = wendt_cm(reynolds, gap_ratio)
    for c, beta in TURBULENT_BRANCHES:
        out = m.fmax(out, c * gap_ratio**alpha * reynolds**beta)
    return out


def donnelly_simon_coefficients(gap_ratio, alpha=0.3):
    """(A, B) of ``G/G_Couette = A r^-2 + B r^0.36``, r = Re/Re_c [-].

    Donnelly & Simon's ``G = a/Omega + b Omega^1.36`` divided by the Couette torque
    (proportional to Omega), fixed by continuity: 1 at onset (r = 1) and the upper law
    (:func:`wendt_cm`, Eq. 6's turbulent branches) at r = 10, the upper end of their range:
    ``A + B = 1``, ``A / 100 + B 10^0.36 = Phi``.

    Parameters
    ----------
    gap_ratio : float, array or CasADi symbol
        x = delta / R1 [-].
    alpha : float
        Gap exponent of Eq. 6's turbulent branches [-].

    Returns
    -------
    tuple
        (A, B) [-].

    References
    ----------
    Donnelly & Simon [2]_; Wendt [3]_.
    """
    rb = DONNELLY_SIMON_RANGE
    re_b = rb * critical_reynolds_number(gap_ratio)
    phi = _upper_cm(re_b, gap_ratio, alpha) / couette_moment_coefficient(re_b, gap_ratio)
    b = (phi - rb**-2) / (rb ** (DONNELLY_SIMON_EXPONENT - 1.0) - rb**-2)
    return 1.0 - b, b


def _ratios(reynolds, gap_ratio, alpha):
    """r = Re/Re_c, Donnelly & Simon's ratio and the upper law's ratio to Couette."""
    r = reynolds / critical_reynolds_number(gap_ratio)
    a, b = donnelly_simon_coefficients(gap_ratio, alpha)
    ds = a * r**-2.0 + b * r ** (DONNELLY_SIMON_EXPONENT - 1.0)
    up = _upper_cm(reynolds, gap_ratio, alpha) / couette_moment_coefficient(reynolds, gap_ratio)
    return r, ds, up


def taylor_cm(reynolds, gap_ratio, alpha=0.3):
    """C_m under the ``"taylor"`` transition, exact (piecewise) form [-].

    ``C_m = C_Couette * max(1, phi)``: phi = 1 below Re_c (exact Couette, no vortices),
    Donnelly & Simon's ``A r^-2 + B r^0.36`` for 1 <= r < 10
    (:func:`donnelly_simon_coefficients`) and ``max(Wendt, Eq. 6 turbulent) / C_Couette``
    above. Continuous at Re_c (phi = 1 there) and at 10 Re_c (by construction).

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R1 [-].
    alpha : float
        Gap exponent of Eq. 6's turbulent branches [-] (0.3 as published).

    Returns
    -------
    float, array or CasADi expression
        C_m [-].

    References
    ----------
    Esser & Grossmann [1]_; Donnelly & Simon [2]_; Wendt [3]_; Bilgen & Boulos [4]_.
    """
    r, ds, up = _ratios(reynolds, gap_ratio, alpha)
    phi = m.where(r < 1.0, 1.0, m.where(r < DONNELLY_SIMON_RANGE, ds, up))
    return couette_moment_coefficient(reynolds, gap_ratio) * m.fmax(1.0, phi)


def taylor_cm_smooth(reynolds, gap_ratio, alpha=0.3, width=TAYLOR_SMOOTH_WIDTH,
                     max_width=TAYLOR_MAX_WIDTH):
    """Smooth form of :func:`taylor_cm` for the optimizer [-].

    ``phi = 1 + smooth_relu(psi - 1)`` with psi Donnelly & Simon's ratio blended into the
    upper law's by a logistic weight in ln(r / 10) (width :data:`TAYLOR_SMOOTH_WIDTH`).
    Below Re_c, psi < 1 and phi = 1 within ``max_width^2 / (4 (1 - psi))``; at onset it is
    ``1 + max_width / 2`` (1 % above Couette).

    Parameters
    ----------
    reynolds : float, array or CasADi symbol
        Couette Reynolds number [-] (> 0).
    gap_ratio : float, array or CasADi symbol
        x = delta / R1 [-].
    alpha : float
        Gap exponent of Eq. 6's turbulent branches [-].
    width, max_width : float
        Widths of the blend (ln Re) and of the maximum [-].

    Returns
    -------
    float, array or CasADi expression
        C_m [-].

    References
    ----------
    As :func:`taylor_cm`.
    """
    r, ds, up = _ratios(reynolds, gap_ratio, alpha)
    s = m.sigmoid(m.log(r / DONNELLY_SIMON_RANGE) / width)
    psi = ds + s * (up - ds)
    return couette_moment_coefficient(reynolds, gap_ratio) * (
        1.0 + m.smooth_relu(psi - 1.0, max_width))


def check_transition(transition: str, form: str, laminar_law: str,
                     where: str = "friction") -> str:
    """Refuse an unknown transition, or ``"taylor"`` with a law it does not apply to.

    Parameters
    ----------
    transition : str
        The ``[friction] transition`` value [-].
    form, laminar_law : str
        The law's form and laminar law [-]: ``"taylor"`` applies to the Eq. 6 forms
        (``"bilgen-boulos"``, ``"smooth"``) with the Couette laminar law, which it replaces
        below Ta_c.
    where : str
        Where the value came from, for the message [-].

    Returns
    -------
    str
        ``transition`` itself.

    Raises
    ------
    InputError
        Unknown value, or ``"taylor"`` with another form or laminar law.

    References
    ----------
    Esser & Grossmann [1]_; Bilgen & Boulos [4]_.
    """
    if transition not in TRANSITIONS:
        raise InputError("transition", transition, f"allowed: {', '.join(TRANSITIONS)}", where)
    if transition == Transition.TAYLOR and form not in ("bilgen-boulos", "smooth"):
        raise InputError("transition", transition, "\"taylor\" applies to form = "
                         f"\"bilgen-boulos\" or \"smooth\" (form is \"{form}\"); use "
                         "transition = \"reynolds\"", where)
    if transition == Transition.TAYLOR and laminar_law != "couette":
        raise InputError("transition", transition, "\"taylor\" is exact Couette below Ta_c: "
                         f"it needs laminar_law = \"couette\" (not \"{laminar_law}\")", where)
    return transition


def transition_regime(reynolds, gap_ratio, transition: str = "reynolds"):
    """Regime name of each Reynolds number under a transition (numpy only).

    ``"reynolds"``: Eq. 6's breaks (:func:`~oilgap.model.taylor_couette.flow_regime`).
    ``"taylor"``: ``"laminar"`` below Re_c (:func:`critical_reynolds_number`), ``"laminar
    with vortices"`` from Re_c to the larger of Re_c and Eq. 6's break at 500, Eq. 6's names
    above.

    Parameters
    ----------
    reynolds : float or array
        Couette Reynolds number(s) [-].
    gap_ratio : float
        x = delta / R1 [-].
    transition : {"reynolds", "taylor"}
        The transition [-].

    Returns
    -------
    ndarray of str
        One regime name per Reynolds number.

    References
    ----------
    Bilgen & Boulos [4]_; Esser & Grossmann [1]_.
    """
    names = flow_regime(reynolds)
    if transition != Transition.TAYLOR:
        return names
    re = np.asarray(reynolds, dtype=float)
    re_c = float(critical_reynolds_number(gap_ratio))
    vortex = (re >= re_c) & (re < max(re_c, REGIME_BOUNDARIES_RE[1]))
    return np.where(re < re_c, REGIME_NAMES[0], np.where(vortex, REGIME_NAMES[1], names))
