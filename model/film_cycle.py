"""The film-heating correction of a clearance over a duty cycle.

:mod:`.film_heating` gives the steady factor Phi(Na) of a laminar film at one speed.
Over a duty cycle the film's temperature cannot follow the speed instantly: its
slowest thermal mode has the time constant t1 = delta^2/(pi^2 alpha) (1.3 s for a
1 mm film of mineral oil; 4x with an insulated rotor). Treating the heating as a
first-order lag and keeping its first-order effect on the cycle-mean power, each node
of the cycle's speed distribution sees the effective Nahme number ::

    Na_eff,i = <Na> + g (Na_i - <Na>),     g = sum_k p_k / (1 + (w_k t1)^2)

where <Na> is the cycle mean (Na at the mean-square speed), and (w_k, p_k) are the
angular frequencies and variance fractions of the fluctuation of omega^2 over the cycle
(its heating spectrum, :func:`heating_spectrum`). ``g`` is the in-phase gain of the lag
on that spectrum: g = 1 is the quasi-steady film (Phi at every instant's Na, t1 -> 0),
g = 0 the frozen film (Phi at the mean Na, t1 -> oo). Against a transient
finite-difference solution of the film over 20 s cycles (sine and offset sine, Na_peak 1
and 8, both wall conditions; tests/validation/test_film_cycle_transient.py) the
cycle-mean factor is within 0.9 % (0.2 % with isothermal walls), where the quasi-steady
factor errs by up to 14 % and the frozen one by up to 13 % (docs/thermal.md).

The correction multiplies the laminar torque only. Above Taylor-vortex onset the core
is mixed and the heating sits in thin wall layers, for which no validated torque
correction exists; the factor is faded out across Ta_c = 41.3 (logistic in ln Ta, width
:data:`LAMINAR_FADE_WIDTH`) and is 1 in vortex flow.

All functions accept floats, numpy arrays and CasADi symbols unless noted.

References
----------
.. [1] R. Nahme, Ingenieur-Archiv 11:191-209, 1940; J. Gavis, R. L. Laurence, Ind. Eng.
   Chem. Fundam. 7(2):232-239, 1968 (the steady film, :mod:`.film_heating`).
.. [2] H. S. Carslaw, J. C. Jaeger, *Conduction of Heat in Solids*, 2nd ed., Oxford
   1959, sec. 3.3 (slab eigenmodes; slowest decay exp(-pi^2 alpha t/h^2)).
.. [3] G. I. Taylor, "Stability of a viscous liquid contained between two rotating
   cylinders", Phil. Trans. R. Soc. A 223:289-343, 1923 (onset Ta_c = 41.3).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import _math as m
from .errors import InputError
from .film_heating import (
    MINERAL_OIL_CONDUCTIVITY_W_MK,
    MINERAL_OIL_DIFFUSIVITY_M2_S,
    WALL_CONDITIONS,
    curvature_corrected_nahme,
    film_factor,
    film_temperature_rise,
    film_time_constant_s,
    nahme_number,
)
from .taylor_couette import CRITICAL_TAYLOR_NUMBER, couette_reynolds, taylor_number
from .viscous_loss import weighted_mean

LAMINAR_FADE_WIDTH = 0.1
"""Width in ln Ta of the logistic that fades the film correction out at Taylor onset [-]
(the factor is 99 % applied at Ta = 0.63 Ta_c and 1 % at 1.58 Ta_c)."""

SPECTRUM_ENERGY = 0.99999
"""Fraction of the variance of omega^2 kept by :func:`heating_spectrum` [-]."""


@dataclass(frozen=True)
class FilmHeating:
    """How the film correction is applied: wall condition, oil transport properties and the
    duty cycle's heating spectrum.

    Attributes
    ----------
    walls : str
        ``"isothermal-walls"`` or ``"adiabatic-rotor"`` [-].
    conductivity_W_mK : float
        Oil thermal conductivity k [W/(m K)].
    diffusivity_m2_s : float
        Oil thermal diffusivity alpha [m^2/s] (sets the film time constant).
    frequencies_rad_s : tuple of float
        Angular frequencies of the heating spectrum [rad/s] (empty: quasi-steady).
    spectral_weights : tuple of float
        Variance fraction of each frequency [-] (sum 1, or empty).
    strength : float or CasADi symbol
        Film strength s in [0, 1]: the Nahme number is s Na (1: the smooth-film theory,
        0: no film effect; docs/thermal.md#evidence) [-].
    wall_floating : float, CasADi symbol or None
        Wall parameter w in [0, 1] between isothermal walls (0) and an insulated rotor
        (1), :func:`~oilgap.model.film_heating.wall_z_factor`; None: ``walls`` decides
        [-].
    """

    walls: str = "isothermal-walls"
    conductivity_W_mK: float = MINERAL_OIL_CONDUCTIVITY_W_MK
    diffusivity_m2_s: float = MINERAL_OIL_DIFFUSIVITY_M2_S
    frequencies_rad_s: tuple[float, ...] = ()
    spectral_weights: tuple[float, ...] = ()
    strength: float = 1.0
    wall_floating: float | None = None

    def __post_init__(self):
        if self.walls not in WALL_CONDITIONS:
            raise InputError("walls", self.walls, f"one of {', '.join(WALL_CONDITIONS)}")
        for name in ("strength", "wall_floating"):
            v = getattr(self, name)
            if v is None or m.is_symbolic(v):
                continue
            if not (isinstance(v, (int, float)) and 0.0 <= v <= 1.0):
                raise InputError(name, v, "a number in [0, 1]")
        for name in ("conductivity_W_mK", "diffusivity_m2_s"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and np.isfinite(v) and v > 0):
                raise InputError(name, v, "a finite number > 0")
        if len(self.frequencies_rad_s) != len(self.spectral_weights):
            raise InputError("spectral_weights", len(self.spectral_weights),
                             f"as many as the frequencies ({len(self.frequencies_rad_s)})")

    @property
    def wall_setting(self):
        """What the film laws take as ``walls``: the wall parameter w if given, else the
        name (the exact closed forms of the two limits) [-]."""
        return self.walls if self.wall_floating is None else self.wall_floating


def heating_spectrum(time_s, omega_rad_s, energy: float = SPECTRUM_ENERGY
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Heating spectrum of a duty cycle: frequencies and variance fractions of omega^2.

    The record is resampled on a uniform grid at its median interval and taken as one
    period (a periodic discrete Fourier transform); the strongest harmonics holding
    ``energy`` of the variance are kept and renormalised. numpy only.

    Parameters
    ----------
    time_s : array
        Sample times [s], increasing.
    omega_rad_s : array
        Rotor speed at each sample [rad/s] (sign ignored).
    energy : float
        Fraction of the variance to keep [-], in (0, 1].

    Returns
    -------
    frequencies_rad_s : ndarray
        Angular frequencies w_k [rad/s] (empty for a constant speed).
    weights : ndarray
        Variance fractions p_k [-], summing to 1 (empty for a constant speed).

    References
    ----------
    Parseval's theorem for the discrete Fourier transform (the variance of omega^2 is
    the sum of its harmonics' powers).
    """
    t = np.asarray(time_s, dtype=float)
    w = np.abs(np.asarray(omega_rad_s, dtype=float))
    if t.size < 3:
        return np.empty(0), np.empty(0)
    dt = float(np.median(np.diff(t)))
    n = int(round((t[-1] - t[0]) / dt)) + 1
    grid = t[0] + dt * np.arange(n)
    s = np.interp(grid, t, w) ** 2
    spec = np.abs(np.fft.rfft(s - s.mean())) ** 2
    spec[0] = 0.0
    if n % 2 == 0:
        spec[-1] *= 0.5  # the Nyquist term appears once in the two-sided sum
    total = spec.sum()
    if not total > 0:
        return np.empty(0), np.empty(0)
    order = np.argsort(spec)[::-1]
    keep = order[: int(np.searchsorted(np.cumsum(spec[order]) / total, energy) + 1)]
    keep = np.sort(keep)
    period = n * dt
    return 2.0 * np.pi * keep / period, spec[keep] / spec[keep].sum()


def cycle_gain(time_constant_s, frequencies_rad_s, weights):
    """In-phase gain of a first-order lag of time constant t1 on a heating spectrum [-].

    ``g = sum_k p_k / (1 + (w_k t1)^2)``: 1 for a film that follows the speed
    (quasi-steady), 0 for one frozen at the cycle-mean heating.

    Parameters
    ----------
    time_constant_s : float, array or CasADi symbol
        Film time constant t1 [s] (:func:`~oilgap.model.film_heating.film_time_constant_s`).
    frequencies_rad_s : sequence of float
        w_k [rad/s] (:func:`heating_spectrum`).
    weights : sequence of float
        p_k [-] (sum 1); empty: g = 1.

    Returns
    -------
    float, array or CasADi expression
        g [-], in [0, 1].

    References
    ----------
    The real part of the frequency response 1/(1 + i w t1) of a first-order lag; the
    film's slowest mode from Carslaw & Jaeger [2]_.
    """
    if len(weights) == 0:
        return 1.0
    return sum(float(p) / (1.0 + (float(wk) * time_constant_s) ** 2)
               for wk, p in zip(frequencies_rad_s, weights, strict=True))


def laminar_weight(taylor):
    """Share of the film correction applied at Taylor number Ta [-]: 1 laminar, 0 vortices.

    ``1 - sigmoid(ln(Ta/Ta_c)/width)`` with Ta_c = 41.3 [3]_ and
    :data:`LAMINAR_FADE_WIDTH`; smooth for the NLP.

    Parameters
    ----------
    taylor : float, array or CasADi symbol
        Taylor number [-] (>= 0).

    Returns
    -------
    float, array or CasADi expression
        Weight [-] in [0, 1].
    """
    ln_ratio = m.log(m.fmax(taylor, 1e-300) / CRITICAL_TAYLOR_NUMBER)
    return 1.0 - m.sigmoid(ln_ratio / LAMINAR_FADE_WIDTH)


def _expand(mean, like):
    """Broadcast a mean over the node axis back along it."""
    if m.is_symbolic(mean, like):
        return mean
    return np.asarray(mean)[..., None]


def effective_nahme(omega_rad_s, weights, radius_m, gap_m, mu_Pa_s, b_1_K,
                    film: FilmHeating):
    """Effective Nahme number of a clearance at each node of a duty cycle [-].

    Na_i = b mu (omega_i R)^2 / k, times the film strength s, corrected for the film's
    curvature, then lagged:
    ``Na_eff,i = <Na> + g (Na_i - <Na>)`` (module docstring).

    Parameters
    ----------
    omega_rad_s : array or casadi.DM
        Node speeds [rad/s], nodes along the last axis.
    weights : array
        Node weights [-] (sum 1).
    radius_m, gap_m : float, array or CasADi symbol
        Rotor radius R and clearance delta [m].
    mu_Pa_s : float, array or CasADi symbol
        Dynamic viscosity at the bulk oil temperature [Pa s].
    b_1_K : float, array or CasADi symbol
        ``-d ln(mu)/dT`` there [1/K].
    film : FilmHeating
        Walls, k, alpha and heating spectrum.

    Returns
    -------
    na_raw : array or CasADi expression
        Na at each node, plane film, rotor surface speed [-].
    na_eff : array or CasADi expression
        Effective Na at each node (with the strength s) [-].

    References
    ----------
    Nahme; Gavis & Laurence [1]_; Carslaw & Jaeger [2]_.
    """
    speed = m.fabs(omega_rad_s) * radius_m
    na = nahme_number(b_1_K, mu_Pa_s, speed, film.conductivity_W_mK)
    na_c = curvature_corrected_nahme(film.strength * na, gap_m / radius_m, film.wall_setting)
    g = cycle_gain(film_time_constant_s(gap_m, film.diffusivity_m2_s, film.wall_setting),
                   film.frequencies_rad_s, film.spectral_weights)
    mean = _expand(weighted_mean(na_c, weights), na_c)
    return na, mean + g * (na_c - mean)


def film_factors(omega_rad_s, weights, radius_m, gap_m, nu_m2_s, rho_kg_m3, b_1_K,
                 film: FilmHeating):
    """Heated/isothermal power factor of a clearance at each node of a duty cycle [-].

    ``1 - s(Ta_i) (1 - Phi(Na_eff,i))``: the exact laminar factor of
    :func:`~oilgap.model.film_heating.film_factor` at the lagged, curvature-corrected
    Nahme number (:func:`effective_nahme`), faded out above Taylor onset
    (:func:`laminar_weight`).

    Parameters
    ----------
    omega_rad_s : array or casadi.DM
        Node speeds [rad/s], nodes along the last axis.
    weights : array
        Node weights [-] (sum 1).
    radius_m, gap_m : float, array or CasADi symbol
        R and delta [m].
    nu_m2_s : float, array or CasADi symbol
        Kinematic viscosity at the bulk temperature [m^2/s].
    rho_kg_m3 : float, array or CasADi symbol
        Density [kg/m^3].
    b_1_K : float, array or CasADi symbol
        ``-d ln(mu)/dT`` at the bulk temperature [1/K].
    film : FilmHeating
        Walls, k, alpha and heating spectrum.

    Returns
    -------
    float, array or CasADi expression
        Factor at each node [-], in (0, 1].

    References
    ----------
    Nahme; Gavis & Laurence [1]_; Taylor [3]_.
    """
    _, na_eff = effective_nahme(omega_rad_s, weights, radius_m, gap_m,
                                nu_m2_s * rho_kg_m3, b_1_K, film)
    phi = film_factor(na_eff, film.wall_setting)
    ta = taylor_number(couette_reynolds(omega_rad_s, radius_m, gap_m, nu_m2_s), gap_m,
                       radius_m)
    return 1.0 - laminar_weight(ta) * (1.0 - phi)


@dataclass(frozen=True)
class FilmPeak:
    """The film at a cycle's peak speed, for reports (floats only; :func:`film_peak`).

    Attributes
    ----------
    nahme_peak : float
        Raw Nahme number b mu (omega R)^2/k at the peak speed (plane film) [-].
    nahme_effective_peak : float
        The effective Nahme number the film modes use there: curvature-corrected and
        lagged over the cycle (:func:`effective_nahme`) [-].
    film_factor_steady_peak : float
        Steady factor Phi of a film held at the peak speed: at the raw Nahme number
        (times the film strength s), curvature-corrected, not lagged [-].
    film_factor_effective_peak : float
        The factor the film modes apply at the peak node: Phi at the effective Nahme
        number, faded out above Taylor onset (:func:`film_factors`) [-].
    film_temp_rise_peak_K : float or None
        Hottest point of the film above the bulk there (laminar solution, effective Na)
        [K]; None when the flow there has Taylor vortices.
    """

    nahme_peak: float
    nahme_effective_peak: float
    film_factor_steady_peak: float
    film_factor_effective_peak: float
    film_temp_rise_peak_K: float | None

    def applied(self, film_applied: bool) -> float:
        """The factor applied at the peak under a mode [-]: 1 when it applies no film.

        Parameters
        ----------
        film_applied : bool
            Whether the mode applies the film correction.

        Returns
        -------
        float
            :attr:`film_factor_effective_peak` or 1.0 [-].
        """
        return self.film_factor_effective_peak if film_applied else 1.0


def film_peak(omega_rad_s, weights, radius_m, gap_m, nu_m2_s, rho_kg_m3, b_1_K,
              film: FilmHeating) -> FilmPeak:
    """The film at the cycle's peak speed, for reports (floats only).

    Parameters
    ----------
    omega_rad_s : array
        Node speeds [rad/s] (1-D).
    weights : array
        Node weights [-].
    radius_m, gap_m : float
        R and delta [m].
    nu_m2_s, rho_kg_m3, b_1_K : float
        Oil state at the bulk temperature: [m^2/s], [kg/m^3], [1/K].
    film : FilmHeating
        Walls, k, alpha and heating spectrum.

    Returns
    -------
    FilmPeak
        Raw and effective Nahme numbers [-], the steady factor at the raw one and the
        factor the film modes apply [-], the film's temperature rise [K] or None.

    References
    ----------
    Nahme; Gavis & Laurence [1]_.
    """
    nodes = np.abs(np.asarray(omega_rad_s, dtype=float))
    i = int(np.argmax(nodes))
    na, na_eff = effective_nahme(nodes, weights, radius_m, gap_m, nu_m2_s * rho_kg_m3,
                                 b_1_K, film)
    factor = film_factors(nodes, weights, radius_m, gap_m, nu_m2_s, rho_kg_m3, b_1_K, film)
    ta = taylor_number(couette_reynolds(nodes[i], radius_m, gap_m, nu_m2_s), gap_m, radius_m)
    laminar = float(laminar_weight(ta)) >= 0.5
    rise = (float(film_temperature_rise(na_eff[i], b_1_K, film.wall_setting)) if laminar
            else None)
    steady = film_factor(curvature_corrected_nahme(film.strength * na[i], gap_m / radius_m,
                                                   film.wall_setting), film.wall_setting)
    return FilmPeak(float(na[i]), float(na_eff[i]), float(steady), float(factor[i]), rise)


def film_heating_for(duty_cycle, thermal=None) -> FilmHeating:
    """The film settings of a case: its duty cycle's heating spectrum, walls and k.

    Parameters
    ----------
    duty_cycle : DutyCycle
        The cycle (``time_s`` [s], ``omega_rad_s`` [rad/s]).
    thermal : ThermalSpec, optional
        The case's ``[thermal]`` table (walls, conductivity [W/(m K)], film strength and
        wall floating [-]); without it the film has isothermal walls, the mineral-oil
        conductivity 0.13 W/(m K) and strength 1.

    Returns
    -------
    FilmHeating
        Walls, k [W/(m K)], alpha [m^2/s] and the heating spectrum [rad/s], [-].

    References
    ----------
    Nahme; Gavis & Laurence [1]_ (walls); Carslaw & Jaeger [2]_ (time constant).
    """
    freqs, weights = heating_spectrum(duty_cycle.time_s, duty_cycle.omega_rad_s)
    walls = "isothermal-walls" if thermal is None else thermal.walls
    k = None if thermal is None else thermal.conductivity_W_mK
    s = None if thermal is None else getattr(thermal, "film_strength", None)
    w = None if thermal is None else getattr(thermal, "wall_floating", None)
    return FilmHeating(
        walls=walls, conductivity_W_mK=MINERAL_OIL_CONDUCTIVITY_W_MK if k is None else float(k),
        diffusivity_m2_s=MINERAL_OIL_DIFFUSIVITY_M2_S,
        frequencies_rad_s=tuple(float(f) for f in freqs),
        spectral_weights=tuple(float(p) for p in weights), strength=1.0 if s is None else float(s),
        wall_floating=None if w is None else float(w))
