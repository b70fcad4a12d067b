"""Viscous heating of a laminar oil film: the Nahme-Griffith problem, closed form.

Steady, fully developed, laminar plane Couette flow of a film of gap h between a
stator (y = 0, u = 0) and a rotor (y = h, u = U, speed imposed), with a viscosity that
falls exponentially with temperature and a constant conductivity k::

    mu(T) = mu0 exp(-b (T - T0)),      b = -d ln(mu)/dT at the wall temperature T0
    d/dy (mu du/dy) = 0                (momentum: tau = mu du/dy uniform)
    k T'' + tau^2 / mu(T) = 0          (energy: conduction = dissipation)

With theta = b (T - T0), eta = y/h and Phi = tau/tau_iso (tau_iso = mu0 U/h) this is
the Bratu problem theta'' = -Na Phi^2 exp(theta) with the speed constraint
Phi * int_0^1 exp(theta) d eta = 1. It depends on one number, the Nahme-Griffith
number ``Na = b mu0 U^2 / k`` (independent of h) [1]_, [2]_, [4]_. Its exact solution
(derived in docs/thermal.md) is, with ``z = Na/4`` (both walls at T0,
``"isothermal-walls"``) or ``z = Na`` (stator at T0, insulated rotor,
``"adiabatic-rotor"``)::

    Phi      = acosh(1 + z) / sqrt(z (2 + z))     (= 2a/sinh 2a, sinh^2 a = Na/8 or Na/2)
    dT_max   = ln(1 + z/2) / b                    (mid-gap, or at the insulated rotor)

Two calibration parameters (docs/thermal.md#evidence) carry the theory to a real joint:

* the **film strength** s in [0, 1] scales the Nahme number, Na_eff = s Na (s = 1 the
  smooth-film theory, s = 0 no film effect): the seed's Table 4 does not support s = 1;
* the **wall floating** w in [0, 1] sits between isothermal walls (w = 0) and an
  insulated rotor (w = 1) through ``z = Na (1 + 3w)/4`` (:func:`wall_z_factor`). Read
  physically, w = 1/(1 + Bi) with Bi = h_r delta/k the Biot number of a rotor wall that
  loses heat by a film coefficient h_r to the bulk: the first-order term of the Robin
  problem theta'(1) = -Bi theta(1) is 1 - Phi = Na (1 + 3w)/12 exactly, the same as the
  closed form's z/3; at both limits the closed form is exact. In between it is an
  interpolation of the full solution: against a finite-difference solution of the Robin
  problem (scipy's solve_bvp) the factor is within 1 % up to Na = 3 and 3.5 % at
  Na = 10 for w = 0.25-0.75, on the side of more heating (tests/test_film_strength.py).
  The curvature slope (1 + 0.5w) and the time-constant factor (1 + w)^2 between the
  limits are interpolations too.

Phi multiplies the isothermal shear stress, torque and dissipated power alike (the
speed is imposed, P = tau U); 1 - Phi = Na/12 - Na^2/120 + ... (isothermal walls),
Na/3 - 2 Na^2/15 + ... (adiabatic rotor). Under imposed speed there is exactly one
solution for every Na >= 0 (no thermal runaway); the film torque Phi sqrt(Na) peaks at
Na = 18.2 (isothermal walls) or 4.55 (adiabatic rotor) and falls beyond.

Validity
--------
* **Laminar only.** The correction multiplies the laminar (Couette) torque and stops
  at Taylor-vortex onset: above it the core is mixed and the heating sits in the
  wall layers, for which no validated torque correction exists. The two regimes
  barely overlap: Na Re = b rho U^3 delta / k, so at onset (Ta = Re sqrt(delta/R) =
  41.3) Na_c = b rho U^3 delta^1.5 / (41.3 k sqrt(R)). Where the correction is large
  (cold, viscous oil) the film is deep in the laminar regime (seed rated point, VG22
  at 2 degC: Na = 9.2 at 8 m/s, Re = 27, Ta = 5.5); at the seed's 8 m/s the oil
  reaches onset only near 40 degC, where Na = 0.6 and Phi = 0.95, so the laminar-only
  correction errs by at most a few per cent where vortices appear.
* **Quasi-steady film.** The film's slowest thermal mode decays with
  :func:`film_time_constant_s` t1 = h^2/(pi^2 alpha) (isothermal walls) or
  4 h^2/(pi^2 alpha) (adiabatic rotor): 1.3 s and 5 s for h = 1 mm. The steady factor
  at the instantaneous Na holds when the heat source's fundamental (4 pi/P for a
  reversing sine of period P) satisfies omega_h t1 << 1; for omega_h t1 >> 1 the film
  is frozen at the cycle-mean heating and the exact factor is Phi(Na) with Na at the
  cycle's mean-square speed. In between a one-pole lag on Na (time constant t1) is
  within a few per cent of the transient solution.
* Constant k and b (b at the wall temperature). The Walther line's ln(mu) is convex
  in T, so a constant b overstates the heating: by 3 % in Phi at Na = 10 (isothermal
  walls), 11 % with an insulated rotor.
* Plane film; :func:`curvature_corrected_nahme` carries it to a rotating inner
  cylinder (delta/R small).

References
----------
.. [1] R. Nahme, "Beitraege zur hydrodynamischen Theorie der Lagerreibung",
   Ingenieur-Archiv 11:191-209, 1940.
.. [2] J. Gavis, R. L. Laurence, "Viscous heating in plane and circular flow between
   moving surfaces", Ind. Eng. Chem. Fundam. 7(2):232-239, 1968.
.. [3] C. S. Cragoe, "Thermal properties of petroleum products", US Bureau of
   Standards Miscellaneous Publication 97, 1929 (k = 0.1167/d (1 - 0.00054 t)
   W/(m K), c_p = (1.685 + 0.00339 t)/sqrt(d) kJ/(kg K), t in degC, d the specific
   gravity at 15.6 degC).
.. [4] R. B. Bird, R. C. Armstrong, O. Hassager, *Dynamics of Polymeric Liquids*,
   vol. 1, 2nd ed., Wiley 1987, sec. 4.4 (Nahme-Griffith number); R. B. Bird,
   W. E. Stewart, E. N. Lightfoot, *Transport Phenomena*, 2nd ed., Wiley 2002,
   sec. 10.4 (constant-viscosity limit mu U^2/(8k)).
.. [5] D. A. Frank-Kamenetskii, *Diffusion and Heat Transfer in Chemical Kinetics*,
   Plenum 1969, ch. 7 (the slab problem theta'' = -lambda exp(theta)).
.. [6] H. S. Carslaw, J. C. Jaeger, *Conduction of Heat in Solids*, 2nd ed., Oxford
   1959, sec. 3.3 (slab eigenmodes; the slowest decays as exp(-pi^2 alpha t/h^2)).
.. [7] The lumped film of the loop's ``film_heating`` effect, ``T_f = T + c P(T_f)``:
   :func:`film_temperature` and :func:`film_theory_coefficient`.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from . import _math as m
from .errors import InputError
from .thermal import steady_temperature

WALL_CONDITIONS = ("isothermal-walls", "adiabatic-rotor")
"""Thermal conditions of the film's walls: both at the bulk oil temperature (default),
or the stator at the bulk temperature and the rotor insulated [-]."""

MINERAL_OIL_CONDUCTIVITY_W_MK = 0.13
"""Thermal conductivity of a light mineral oil [W/(m K)]: Cragoe's correlation [3]_
0.1167/d (1 - 0.00054 t) gives 0.134 (0 degC) to 0.131 (40 degC) for d = 0.87."""

MINERAL_OIL_DIFFUSIVITY_M2_S = 8.1e-8
"""Thermal diffusivity alpha = k/(rho c_p) of a light mineral oil [m^2/s]: Cragoe [3]_
at 20 degC, d = 0.87: 0.133 / (870 * 1880)."""

_SHIFT = 2.0e-3
"""Step of the shifted evaluation in :func:`_phi_of_z` [-] (error <= 0.61 _SHIFT^4)."""


def wall_floating_of(walls):
    """The wall parameter w [-] of a wall condition: 0 for ``"isothermal-walls"``, 1 for
    ``"adiabatic-rotor"``, a number (float, array or CasADi symbol) in [0, 1] as it is.

    Parameters
    ----------
    walls : str, float, array or CasADi symbol
        A name of :data:`WALL_CONDITIONS` or w [-].

    Returns
    -------
    float, array or CasADi symbol
        w in [0, 1] [-].

    Raises
    ------
    InputError
        An unknown wall name, or a number outside [0, 1].
    """
    if isinstance(walls, str):
        if walls not in WALL_CONDITIONS:
            raise InputError("walls", walls, f"one of {', '.join(WALL_CONDITIONS)} or a "
                             "number in [0, 1] (wall_floating)")
        return 0.0 if walls == "isothermal-walls" else 1.0
    if not m.is_symbolic(walls):
        w = np.asarray(walls, dtype=float)
        if not (np.all(np.isfinite(w)) and np.all(w >= 0.0) and np.all(w <= 1.0)):
            raise InputError("wall_floating", walls, "a number in [0, 1]")
    return walls


def wall_z_factor(walls):
    """z/Na of the closed form [-]: 1/4 (isothermal walls), 1 (adiabatic rotor) and
    ``(1 + 3w)/4`` for a wall parameter w in [0, 1] (module docstring).

    The hottest plane of the first-order (constant viscosity) profile lies at
    eta_max = (1 + w)/2 of the gap from the stator, and the film's first-order loss is
    1 - Phi = Na (1 + 3w)/12 = z/3 for a rotor of Biot number Bi = (1 - w)/w; linear in
    w, smooth for the NLP.

    Parameters
    ----------
    walls : str, float, array or CasADi symbol
        A name of :data:`WALL_CONDITIONS` or w in [0, 1] [-].

    Returns
    -------
    float, array or CasADi expression
        z/Na [-].

    References
    ----------
    R. Nahme, Ingenieur-Archiv 11:191-209, 1940 (the two limits); the Robin wall's
    first-order solution in docs/thermal.md#film-strength-and-wall-floating.
    """
    if isinstance(walls, str):
        return 0.25 if wall_floating_of(walls) == 0.0 else 1.0
    return 0.25 * (1.0 + 3.0 * wall_floating_of(walls))


def _z_of(nahme, walls):
    """Map Na to the unified argument z of the closed form (z = Na/4, Na or Na (1+3w)/4)."""
    if walls == "isothermal-walls":
        return 0.25 * nahme
    if walls == "adiabatic-rotor":
        return 1.0 * nahme
    return wall_z_factor(walls) * nahme


def _phi_closed(z):
    """acosh(1+z)/sqrt(z(2+z)) written with log and sqrt (0/0 at z = 0)."""
    s = m.sqrt(z * (2.0 + z))
    return m.log(1.0 + z + s) / s


def _phi_of_z(z):
    """F(z) = acosh(1+z)/sqrt(z(2+z)), analytic and branch-free down to z = 0.

    Every elementary expression of F has a removable 0/0 at z = 0 (acosh's branch point),
    which breaks automatic differentiation where the speed passes zero. The closed form
    is evaluated only at z + j e (j = 1..4, e = 2e-3), where it is well conditioned, and
    extrapolated back with the 4-point backward Newton formula
    F(z) = 4F(z+e) - 6F(z+2e) + 4F(z+3e) - F(z+4e) + O(e^4 F''''), whose error is at
    most 0.61 e^4 = 1e-11 for every z >= 0 (|F''''| <= 192/315). The result is analytic
    for z > -e, so its first and second derivatives are finite and accurate at z = 0.
    z is floored at -e/2 (only a gas, whose viscosity rises with T, has Na < 0, and
    then |Na| < 1e-3).
    """
    z = m.fmax(z, -0.5 * _SHIFT)
    e = _SHIFT
    return (4.0 * _phi_closed(z + e) - 6.0 * _phi_closed(z + 2.0 * e)
            + 4.0 * _phi_closed(z + 3.0 * e) - _phi_closed(z + 4.0 * e))


def nahme_number(b_1_K, mu_Pa_s, speed_m_s, conductivity_W_mK=MINERAL_OIL_CONDUCTIVITY_W_MK):
    """Nahme-Griffith number ``Na = b mu U^2 / k`` [-] [1]_, [2]_, [4]_.

    The ratio of the viscosity change caused by the film's own shear heating to the
    viscosity: the temperature rise mu U^2/k of a film times b. Independent of the gap.

    Parameters
    ----------
    b_1_K : float, array or CasADi symbol
        Viscosity-temperature slope ``-d ln(mu)/dT`` at the wall temperature [1/K]
        (``Fluid.temperature_slope``).
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity at the wall temperature [Pa s].
    speed_m_s : float, array or CasADi symbol
        Sliding (rotor surface) speed [m/s].
    conductivity_W_mK : float, array or CasADi symbol
        Thermal conductivity of the fluid [W/(m K)] (default
        :data:`MINERAL_OIL_CONDUCTIVITY_W_MK`).

    Returns
    -------
    float, array or CasADi expression
        Na [-].
    """
    return b_1_K * mu_Pa_s * speed_m_s * speed_m_s / conductivity_W_mK


def film_factor(nahme, walls="isothermal-walls", strength=1.0):
    """Heated/isothermal torque (and power) ratio of a laminar film at imposed speed [1]_, [2]_.

    ``Phi = acosh(1 + z)/sqrt(z (2 + z))``, z = Na/4 (isothermal walls) or Na (adiabatic
    rotor); equivalently ``Phi = 2a/sinh(2a)`` with ``sinh^2 a = Na/8`` or ``Na/2``.
    Exact for the exponential viscosity law (evaluation error below 1e-11), smooth and
    branch-free down to Na = 0 (dPhi/dNa = -1/12 or -1/3 there), strictly decreasing,
    ``~ ln(2z)/z`` for large z. Laminar regime only (see the module's Validity).

    Parameters
    ----------
    nahme : float, array or CasADi symbol
        Nahme-Griffith number Na >= 0 [-] (:func:`nahme_number`).
    walls : str, float, array or CasADi symbol
        ``"isothermal-walls"`` (both walls at the bulk temperature),
        ``"adiabatic-rotor"`` (insulated rotor) or the wall parameter w in [0, 1]
        between them (:func:`wall_z_factor`) [-].
    strength : float, array or CasADi symbol
        Film strength s in [0, 1]: Phi is taken at s Na (1 the theory, 0 no heating) [-].

    Returns
    -------
    float, array or CasADi expression
        Phi = tau/tau_iso = P/P_iso [-], in (0, 1].

    Raises
    ------
    InputError
        An unknown ``walls``.
    """
    return _phi_of_z(_z_of(strength * nahme, walls))


def film_temperature_rise(nahme, b_1_K, walls="isothermal-walls"):
    """Peak temperature rise of the film above the wall (bulk) temperature [K] [1]_, [2]_.

    ``dT_max = ln(1 + Na/8)/b`` at mid-gap (isothermal walls) or ``ln(1 + Na/2)/b`` at the
    insulated rotor; for small Na it tends to mu U^2/(8k) or mu U^2/(2k) [4]_.

    Parameters
    ----------
    nahme : float, array or CasADi symbol
        Nahme-Griffith number Na >= 0 [-].
    b_1_K : float, array or CasADi symbol
        Viscosity-temperature slope at the wall temperature [1/K] (the same b as in Na).
    walls : str, float, array or CasADi symbol
        ``"isothermal-walls"``, ``"adiabatic-rotor"`` or w in [0, 1] between them [-].

    Returns
    -------
    float, array or CasADi expression
        dT_max [K].

    Raises
    ------
    InputError
        An unknown ``walls``.
    """
    return m.log(1.0 + 0.5 * _z_of(nahme, walls)) / b_1_K


def curvature_corrected_nahme(nahme, gap_ratio, walls="isothermal-walls"):
    """Effective Nahme number of a film between a rotating inner and a fixed outer cylinder [-].

    The plane solution underestimates the heating of a circular film, whose stress and
    dissipation concentrate at the rotor (tau ~ r^-2). Matching the O(Na) perturbation
    of the circular problem, c1(kappa) Na with kappa = 1 + eps, eps = delta/R, gives
    ``Na_eff = Na c1(kappa)/c1(1) ~ Na (1 + eps)`` (isothermal walls) or
    ``Na (1 + 1.5 eps)`` (adiabatic rotor); use ``film_factor(Na_eff)`` with Na built on
    the rotor surface speed. Against a finite-difference solution of the circular
    problem the isothermal-walls factor is then within 0.03 % up to eps = 0.2 and
    Na = 30 (1.5 % uncorrected at eps = 0.04, Na = 9); the adiabatic-rotor factor within
    0.4 % at eps = 0.04, Na <= 9 (3 % uncorrected) and 2 % at eps = 0.2.

    Parameters
    ----------
    nahme : float, array or CasADi symbol
        Nahme-Griffith number at the rotor surface speed [-].
    gap_ratio : float, array or CasADi symbol
        delta/R, gap over rotor radius [-].
    walls : str, float, array or CasADi symbol
        ``"isothermal-walls"``, ``"adiabatic-rotor"`` or w in [0, 1] between them [-].

    Returns
    -------
    float, array or CasADi expression
        Na_eff [-].

    Raises
    ------
    InputError
        An unknown ``walls``.
    """
    if isinstance(walls, str):
        slope = {"isothermal-walls": 1.0, "adiabatic-rotor": 1.5}.get(walls)
        if slope is None:
            raise InputError("walls", walls, f"one of {', '.join(WALL_CONDITIONS)}")
    else:  # between the limits: linear in w, like z (an interpolation)
        slope = 1.0 + 0.5 * wall_floating_of(walls)
    return nahme * (1.0 + slope * gap_ratio)


def film_time_constant_s(gap_m, diffusivity_m2_s=MINERAL_OIL_DIFFUSIVITY_M2_S,
                         walls="isothermal-walls"):
    """Time constant of the film's slowest thermal mode [s] [6]_.

    ``t1 = h^2/(pi^2 alpha)`` with both walls isothermal (mode sin(pi y/h)) and
    ``4 h^2/(pi^2 alpha)`` with the rotor insulated (mode sin(pi y/(2h))). The steady
    (quasi-steady) film factor holds for speed changes slow against t1; the momentum
    time h^2/nu (milliseconds) is negligible.

    Parameters
    ----------
    gap_m : float, array or CasADi symbol
        Film thickness (clearance) h [m].
    diffusivity_m2_s : float, array or CasADi symbol
        Thermal diffusivity alpha = k/(rho c_p) [m^2/s] (default
        :data:`MINERAL_OIL_DIFFUSIVITY_M2_S`).
    walls : str, float, array or CasADi symbol
        ``"isothermal-walls"``, ``"adiabatic-rotor"`` or w in [0, 1] between them [-].

    Returns
    -------
    float, array or CasADi expression
        t1 [s].

    Raises
    ------
    InputError
        An unknown ``walls``.
    """
    if isinstance(walls, str):
        factor = {"isothermal-walls": 1.0, "adiabatic-rotor": 4.0}.get(walls)
        if factor is None:
            raise InputError("walls", walls, f"one of {', '.join(WALL_CONDITIONS)}")
    else:  # the hottest plane's distance to the stator (1 + w)/2 of the gap, squared
        w = wall_floating_of(walls)
        factor = (1.0 + w) * (1.0 + w)
    return factor * gap_m * gap_m / (math.pi ** 2 * diffusivity_m2_s)


def film_theory_coefficient(gap_m, radius_m, length_m, wall_floating=0.0,
                            conductivity_W_mK=MINERAL_OIL_CONDUCTIVITY_W_MK):
    """The loop's film coefficient c [K/W] that the smooth-film theory gives at strength 1.

    The loop's ``film_heating`` effect lumps the film at ``T_film = T + c P(T_film)``.
    Its first-order loss change ``c P dP/dT = -b c P^2`` (laminar Couette, P ~ mu)
    equals the Nahme-Griffith film's first-order loss ``-(1 - Phi) P = -P Na (1 + 3w)/12``
    (:func:`film_factor`, z/3) when ``c = delta (1 + 3w)/(12 k A)``, A =
    2 pi R L the wetted area: Na = b mu U^2/k and P = mu U^2 A/delta. So a fitted c is the
    film strength ``s = c / film_theory_coefficient(...)`` (:func:`film_strength_of`) of
    the clearance, to first order in Na.

    Parameters
    ----------
    gap_m, radius_m, length_m : float or array
        Clearance delta, rotor radius R and length L [m].
    wall_floating : float
        Wall parameter w in [0, 1] (0 isothermal walls, 1 insulated rotor) [-].
    conductivity_W_mK : float
        Oil thermal conductivity k [W/(m K)] (default 0.13, mineral oil).

    Returns
    -------
    float or array
        c at s = 1 [K/W].

    References
    ----------
    Nahme [1]_; the mean rise of uniform dissipation P delta/(12 k A), Bird, Stewart &
    Lightfoot [4]_.
    """
    area = 2.0 * math.pi * radius_m * length_m
    return gap_m * (1.0 + 3.0 * wall_floating) / (12.0 * conductivity_W_mK * area)


def film_strength_of(coefficient_K_W, theory_K_W):
    """Film strength s [-] of a fitted loop coefficient c: ``c / c_theory``.

    Parameters
    ----------
    coefficient_K_W : float or array
        Fitted ``film_heating`` coefficient c (or an end of its interval) [K/W].
    theory_K_W : float
        :func:`film_theory_coefficient` of the clearance [K/W].

    Returns
    -------
    float or array
        s [-] (1: the smooth-film theory; the seed's Table 4 does not support s = 1,
        docs/thermal.md#evidence).

    References
    ----------
    Nahme [1]_ (first-order equivalence, :func:`film_theory_coefficient`).
    """
    return coefficient_K_W / theory_K_W


def film_temperature(temp_C, power_at: Callable[[np.ndarray], np.ndarray],
                     coefficient_K_W: float) -> np.ndarray:
    """Film temperature of the lumped heated film, ``T_f = T + c P(T_f)`` per sample [7]_.

    The same fixed point as the bulk balance ``T = T_base + R P(T)`` with ``T_base = T``
    and ``R = c``, solved by its one solver,
    :func:`~oilgap.model.thermal.steady_temperature` (safeguarded Newton, vectorised
    over the samples): ``g(T_f) = T_f - T - c P(T_f)`` rises (P falls with the
    temperature), so the root is unique, between ``T`` and ``T + c P(T)``.

    Parameters
    ----------
    temp_C : array
        Measured (or lagged) oil temperature per sample [degC] (any shape).
    power_at : callable
        Temperature [degC] per sample (shape of ``temp_C``) -> the clearance's viscous
        power [W] per sample.
    coefficient_K_W : float
        Film rise per watt of the clearance's loss, c [K/W] (>= 0).

    Returns
    -------
    ndarray
        Film temperature per sample [degC], to 1e-9 K on the residual.

    Raises
    ------
    SolverError
        The fixed point did not converge.
    """
    T = np.asarray(temp_C, dtype=float)
    n = T.size
    if n == 0 or coefficient_K_W == 0:
        return T.copy()

    def stacked(temps):  # k temperatures of every sample, sample index fastest
        return np.concatenate([np.broadcast_to(power_at(part.reshape(T.shape)), T.shape)
                               .ravel() for part in temps.reshape(-1, n)])

    tf, _ = steady_temperature(stacked, T.ravel(), coefficient_K_W, n)
    return tf.reshape(T.shape)
