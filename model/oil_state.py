"""One oil state per sample: the temperatures the clearance's oil is at, and its properties.

A measured record gives the oil temperature at the sensor. The loop's thermal effects
move the temperature the oil actually has where it is sheared: ``thermal_lag`` (the gap
oil follows the sensor through a first-order lag, or leads it) and ``film_heating`` (the
film runs hotter than the bulk by ``c P``). :class:`OilState` holds, per sample, the
measured, lagged and film-heated temperatures and the kinematic viscosity and density at
each, computed once (per fit iteration when the lag or the film coefficient change).
Every viscosity-dependent term of a forward model reads the *applied* state (the
film-heated temperature, which is the lagged one without film heating, which is the
measured one without a lag): the clearance regions, the bearing, the end-face discs, the
seal, shear thinning and the Taylor-vortex excess, so that two effects combine at one
oil temperature.

References
----------
.. [1] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 5.2 (first-order lag of a lumped capacitance).
.. [2] H. Nahme, "Beiträge zur hydrodynamischen Theorie der Lagerreibung", Ing.-Arch.
   11:191-209, 1940 (the heated film; the lumped film of :mod:`oilgap.model.film_heating`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from .film_heating import film_temperature
from .units import ZERO_CELSIUS_K

OIL_STATES = ("measured", "lagged", "film-heated", "lagged and film-heated")
"""Names of the applied oil state: no thermal effect, thermal lag, film heating, both."""


@dataclass(frozen=True)
class OilState:
    """The oil's temperature and properties per sample (arrays of one length).

    Attributes
    ----------
    temp_measured_K, temp_lagged_K, temp_film_K : ndarray
        Measured oil temperature, the gap oil's temperature after the first-order lag
        (the measured one without a lag) [1], and the film's temperature ``T_lag + c P``
        (the lagged one without film heating) [2] [K].
    nu_measured_m2_s, nu_lagged_m2_s, nu_film_m2_s : ndarray
        Kinematic viscosity at each temperature [m^2/s].
    density_measured_kg_m3, density_lagged_kg_m3, density_film_kg_m3 : ndarray
        Density at each temperature [kg/m^3].
    lag_s : float
        Time constant of the lag [s] (0: none; < 0: the oil leads the sensor).
    film_K_W : float
        Film rise per watt of the clearance's loss, c [K/W] (0: none).
    key : hashable or None
        Identifies a state that depends only on the lag (cacheable); None for a
        film-heated state, which depends on the friction law too.
    """

    temp_measured_K: np.ndarray
    temp_lagged_K: np.ndarray
    temp_film_K: np.ndarray
    nu_measured_m2_s: np.ndarray
    nu_lagged_m2_s: np.ndarray
    nu_film_m2_s: np.ndarray
    density_measured_kg_m3: np.ndarray
    density_lagged_kg_m3: np.ndarray
    density_film_kg_m3: np.ndarray
    lag_s: float = 0.0
    film_K_W: float = 0.0
    key: tuple | None = ("measured",)

    @property
    def nu_m2_s(self) -> np.ndarray:
        """Kinematic viscosity every term reads: at the applied temperature [m^2/s]."""
        return self.nu_film_m2_s

    @property
    def density_kg_m3(self) -> np.ndarray:
        """Density every term reads: at the applied temperature [kg/m^3]."""
        return self.density_film_kg_m3

    @property
    def temp_K(self) -> np.ndarray:
        """The applied temperature [K] (film-heated, lagged, or measured)."""
        return self.temp_film_K

    @property
    def applied(self) -> str:
        """Which state the terms read (one of :data:`OIL_STATES`)."""
        return applied_state_name(self.lag_s != 0.0, self.film_K_W > 0.0)


def applied_state_name(lagged: bool, film_heated: bool) -> str:
    """Name of the oil state the terms read (:data:`OIL_STATES`).

    Parameters
    ----------
    lagged : bool
        Thermal lag in the model [-].
    film_heated : bool
        Film heating in the model [-].

    Returns
    -------
    str
        "measured", "lagged", "film-heated" or "lagged and film-heated" [-].
    """
    return OIL_STATES[int(bool(lagged)) + 2 * int(bool(film_heated))]


OIL_STATE_READERS = ("bearing_ball_churning", "end_face_disc", "oil_inertia",
                     "shear_thinning", "taylor_vortex_onset")
"""Effects whose term reads the oil's viscosity or density (beside the clearance regions);
the seal's Coulomb torque and the sensor delay do not depend on the oil state."""


def oil_state_record(coefs: dict, film_theory_K_W: float = 0.0) -> dict:
    """Which oil state the forward model's terms read under the effects ``coefs``.

    Parameters
    ----------
    coefs : dict
        Effect name -> coefficient (library units; ``film_heating``: the strength s).
    film_theory_K_W : float
        The film coefficient at s = 1 under the model's wall condition
        (the calibration forward model's
        ``film_theory_K_W``) [K/W].

    Returns
    -------
    dict
        ``applied`` (measured, lagged, film-heated, lagged and film-heated), the lag
        ``thermal_lag_s`` [s], the film strength ``film_strength`` [-] and its film
        coefficient ``film_heating_K_W`` = s c_theory [K/W] (0: none), and ``terms``:
        the clearance regions and the effects that read that state.
    """
    tau = float(coefs.get("thermal_lag", 0.0))
    s = max(0.0, float(coefs.get("film_heating", 0.0)))
    return {"applied": applied_state_name(tau != 0.0, s > 0.0), "thermal_lag_s": tau,
            "film_strength": s, "film_heating_K_W": s * float(film_theory_K_W),
            "terms": ["regions", *(n for n in coefs if n in OIL_STATE_READERS)]}


def measured_oil_state(temp_K, nu_m2_s, density_kg_m3) -> OilState:
    """The oil state without thermal effect: every temperature the measured one.

    Parameters
    ----------
    temp_K : array
        Measured oil temperature per sample [K].
    nu_m2_s : array
        Kinematic viscosity at it [m^2/s].
    density_kg_m3 : array
        Density at it [kg/m^3].

    Returns
    -------
    OilState
        Lagged and film states the same arrays as the measured one.
    """
    T = np.asarray(temp_K, dtype=float)
    return OilState(
        temp_measured_K=T, temp_lagged_K=T, temp_film_K=T, nu_measured_m2_s=nu_m2_s,
        nu_lagged_m2_s=nu_m2_s, nu_film_m2_s=nu_m2_s, density_measured_kg_m3=density_kg_m3,
        density_lagged_kg_m3=density_kg_m3, density_film_kg_m3=density_kg_m3)


def lagged_oil_state(measured: OilState, lag_s: float, temp_lagged_K,
                     properties: Callable[[np.ndarray], tuple]) -> OilState:
    """The oil state with the gap oil at a lagged temperature [1] (no film heating).

    Parameters
    ----------
    measured : OilState
        The measured state.
    lag_s : float
        Lag time constant [s] (0 returns ``measured``).
    temp_lagged_K : array
        The gap oil's temperature per sample [K].
    properties : callable
        Temperature [K] per sample -> (kinematic viscosity [m^2/s], density [kg/m^3]).

    Returns
    -------
    OilState
        Film state the same arrays as the lagged one; ``key`` ``("lag", lag_s)``.
    """
    if lag_s == 0.0:
        return measured
    T = np.asarray(temp_lagged_K, dtype=float)
    nu, rho = properties(T)
    return replace(measured, temp_lagged_K=T, temp_film_K=T, nu_lagged_m2_s=nu,
                   nu_film_m2_s=nu, density_lagged_kg_m3=rho, density_film_kg_m3=rho,
                   lag_s=float(lag_s), film_K_W=0.0, key=("lag", float(lag_s)))


def film_heated_oil_state(state: OilState, film_K_W: float,
                          power_at: Callable[[np.ndarray, np.ndarray], np.ndarray],
                          properties: Callable[[np.ndarray], tuple],
                          start_K: np.ndarray | None = None) -> OilState:
    """The oil state with the film at ``T_f = T_lag + c P(T_f)`` per sample [2].

    ``g(T_f) = T_f - T_lag - c P(T_f)`` rises where P falls with the temperature, so
    the root is unique, between ``T_lag`` and ``T_lag + c P(T_lag)``; solved by the
    library's film solver, :func:`~oilgap.model.effects.film_temperature` (the lumped
    balance's safeguarded Newton, vectorised over the samples). From ``start_K`` (the
    solution at nearby coefficients, as in a fit's iterations) a few plain Newton steps
    are tried first (``g' = 1 - c dP/dT >= 1``: well conditioned); they are kept only if
    they converge to 1e-11 K, otherwise the safeguarded solver runs.

    Parameters
    ----------
    state : OilState
        The measured or lagged state (its lagged temperature is the film's base).
    film_K_W : float
        Film rise per watt of the clearance's loss, c [K/W] (<= 0 returns ``state``).
    power_at : callable
        (kinematic viscosity [m^2/s], density [kg/m^3]) per sample -> the clearance's
        viscous power [W] per sample.
    properties : callable
        Temperature [K] per sample -> (kinematic viscosity [m^2/s], density [kg/m^3]).
    start_K : array, optional
        A film temperature per sample near the root [K] (a warm start).

    Returns
    -------
    OilState
        With the film temperature and the properties there; ``key`` None.

    Raises
    ------
    SolverError
        The fixed point did not converge.
    """
    if not film_K_W > 0.0:
        return state

    def power_at_C(temp_C):
        return power_at(*properties(np.asarray(temp_C) + ZERO_CELSIUS_K))

    base_C = state.temp_lagged_K - ZERO_CELSIUS_K
    tf = None if start_K is None else _warm_newton(np.asarray(start_K) - ZERO_CELSIUS_K,
                                                   base_C, film_K_W, power_at_C)
    if tf is None:
        tf = film_temperature(base_C, power_at_C, film_K_W)
    tf = tf + ZERO_CELSIUS_K
    nu, rho = properties(tf)
    return replace(state, temp_film_K=tf, nu_film_m2_s=nu, density_film_kg_m3=rho,
                   film_K_W=float(film_K_W), key=None)


WARM_STEPS = 6
"""Newton steps tried from a warm start before the safeguarded solver takes over."""


def _warm_newton(start_C, base_C, c, power_at_C, tol_K: float = 1e-11):
    """``T_f = base + c P(T_f)`` by Newton from ``start_C`` [degC] (forward-difference
    slope); None unless every sample's step falls below ``tol_K`` within
    :data:`WARM_STEPS` steps and the root lies above the base (P >= 0)."""
    T = np.array(start_C, dtype=float)
    h = 1e-6
    for _ in range(WARM_STEPS):
        p = np.asarray(power_at_C(T), dtype=float)
        slope = 1.0 - c * (np.asarray(power_at_C(T + h), dtype=float) - p) / h
        if not np.all(np.isfinite(slope) & (slope > 0.0)):
            return None
        step = (T - base_C - c * p) / slope
        T = T - step
        if not np.all(np.isfinite(T)):
            return None
        if np.max(np.abs(step), initial=0.0) < tol_K:
            return T if np.all(T >= base_C - tol_K) else None
    return None
