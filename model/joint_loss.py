"""A joint's viscous loss under a thermal mode: the one composition of film and bulk.

Four modes, the same for every command and study:

``none``
    The seed paper's isothermal model: the film at the given oil temperature.
``bulk``
    The isothermal film at the bulk oil temperature that balances the joint's heat:
    ``T = T_sea + R (P(T) + Q)`` (:func:`~oilgap.model.thermal.joint_steady_temperature`,
    the case's ``[thermal]`` table), no film correction.
``film``
    The film-heating correction (:mod:`.film_cycle`) at the given oil temperature.
``full``
    The film correction at the bulk temperature of the same balance as ``bulk``.

The default is the model the measurements support (:func:`default_thermal_mode`):
``bulk`` with a ``[thermal]`` table, ``none`` without. The seed's Table 4 (grooved
joint, four oils) is reproduced by the isothermal film at per-oil run temperatures
that follow a physical heat balance; the film-heated modes fall 19-45 % below it
(docs/thermal.md, Evidence). ``film`` and ``full`` stay available as options, and
every report shows their number beside the default's (:func:`film_band`).

A case's rolling bearing (``[bearing]``, :mod:`.bearing`) is part of the joint's loss
under every mode: its friction and drag at the bulk oil's viscosity (it is not a film,
so no film factor) are added by :func:`joint_mean_power`, and its heat goes into the
oil's balance under ``bulk``/``full``. Region 2, the annulus, keeps its own term.

Functions accept floats and numpy arrays of temperatures; :func:`joint_mean_power`
also CasADi symbols (the design NLP differentiates it).

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 5 and 10 (the isothermal loss).
.. [2] R. Nahme, 1940; J. Gavis, R. L. Laurence, 1968 (the heated film).
.. [3] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 3.1 (the bulk balance).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import casadi as ca
import numpy as np

from . import _math as m
from .elements import element_mean_powers_at, joint_elements
from .errors import InputError
from .film_cycle import FilmHeating, film_heating_for
from .oil_properties import seawater_gauge_pressure
from .regions import Region, joint_regions, region_mean_power
from .thermal import joint_steady_temperature
from .thermal_modes import (  # noqa: F401  (re-exported: the modes' one list)
    BALANCE_MODES,
    FILM_EVIDENCE,
    FILM_MODES,
    THERMAL_MODE_TEXT,
    THERMAL_MODES,
    ThermalMode,
    applies_film,
    film_counterpart,
    uses_balance,
)
from .units import celsius_to_kelvin

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .case import DesignCase

@dataclass(frozen=True)
class OperatingTemperature:
    """The bulk oil temperature a thermal mode gives, and the loss there.

    Attributes
    ----------
    mode : str
        One of :data:`THERMAL_MODES`.
    oil_temp_C : float
        Bulk oil temperature [degC] (the case's, or the balance's under
        ``bulk``/``full``).
    sea_temp_C : float or None
        Sea temperature [degC] under ``bulk``/``full``; None otherwise.
    mean_power_W : float
        Mean viscous loss over the duty cycle at ``oil_temp_C`` under the mode [W].
    region_mean_powers_W : tuple of float
        The same per region, region 1 first (:func:`region_mean_powers`) [W].
    bearing_mean_power_W : float
        The rolling bearing's part of ``mean_power_W`` (:func:`bearing_mean_power_at`) [W];
        0 without a bearing.
    element_mean_powers_W : tuple of float
        Every element's part (:func:`~oilgap.model.elements.joint_elements`: the bearing,
        then a linear drive's screw, rod guide and passages) [W]; empty without elements.
    """

    mode: str
    oil_temp_C: float
    sea_temp_C: float | None
    mean_power_W: float
    region_mean_powers_W: tuple[float, ...] = ()
    bearing_mean_power_W: float = 0.0
    element_mean_powers_W: tuple[float, ...] = ()


def default_thermal_mode(case: DesignCase) -> str:
    """The model the evidence supports: ``"bulk"`` with ``[thermal]``, else ``"none"``.

    The isothermal film reproduces the seed's Table 4; the film-heated modes do not
    (module docstring).

    Parameters
    ----------
    case : DesignCase
        The case.

    Returns
    -------
    str
        A mode of :data:`THERMAL_MODES`.
    """
    return "bulk" if case.thermal is not None else "none"


def resolve_thermal_mode(case: DesignCase, mode: str | None) -> ThermalMode:
    """Check a requested mode against the case (None: :func:`default_thermal_mode`).

    The one resolution of a command: the façade and the command line call it once and
    pass the result down; the functions below take a resolved mode as it is
    (:func:`resolved_mode`).

    Parameters
    ----------
    case : DesignCase
        The case.
    mode : str or None
        Requested mode.

    Returns
    -------
    ThermalMode
        The mode to use (equal to its name, ``"none"``, ``"bulk"``, ...).

    Raises
    ------
    InputError
        An unknown mode, or ``"bulk"``/``"full"`` for a case without a ``[thermal]``
        table.
    """
    if mode is None:
        return ThermalMode(default_thermal_mode(case))
    if mode not in THERMAL_MODES:
        raise InputError("thermal", mode, f"one of {', '.join(THERMAL_MODES)}")
    if uses_balance(mode) and case.thermal is None:
        raise InputError("thermal", mode, "'none' or 'film': the case has no [thermal] "
                         "table (sea_temp_C, resistance_K_per_W, heat_capacity_J_per_K)")
    return ThermalMode(mode)


def resolved_mode(case: DesignCase, mode: str | None) -> ThermalMode:
    """A mode already resolved (:func:`resolve_thermal_mode` returns a
    :class:`~oilgap.model.thermal_modes.ThermalMode`) as it is, else resolved here.

    A resolved mode that does not fit the case (``bulk``/``full`` without ``[thermal]``,
    another case than the one it was resolved for) is resolved again, and so refused.

    Parameters
    ----------
    case : DesignCase
        The case.
    mode : ThermalMode, str or None
        A resolved mode, or a requested one (None: :func:`default_thermal_mode`).

    Returns
    -------
    ThermalMode
        The mode to use.

    Raises
    ------
    InputError
        As :func:`resolve_thermal_mode`.
    """
    if isinstance(mode, ThermalMode) and (case.thermal is not None or not uses_balance(mode)):
        return mode
    return resolve_thermal_mode(case, mode)


def case_film(case: DesignCase) -> FilmHeating:
    """The case's film settings (walls and k from ``[thermal]`` if given; the duty
    cycle's heating spectrum), cached on the case's duty cycle.

    Parameters
    ----------
    case : DesignCase
        The case.

    Returns
    -------
    FilmHeating
        Walls, k [W/(m K)], alpha [m^2/s], heating spectrum [rad/s], [-].
    """
    cache = case.duty_cycle.cache.setdefault("film", {})
    th = case.thermal
    key = ((th.walls, th.conductivity_W_mK, th.film_strength, th.wall_floating) if th
           else None)
    if key not in cache:
        cache[key] = film_heating_for(case.duty_cycle, case.thermal)
    return cache[key]


def mode_film(case: DesignCase, mode: str, temp_K, pressure_gauge_Pa):
    """The film correction a mode applies: the case's film and the oil's ``b`` there.

    Parameters
    ----------
    case : DesignCase
        The case (oil, duty cycle, ``[thermal]``).
    mode : str
        A mode of :data:`THERMAL_MODES`.
    temp_K : float, array or CasADi symbol
        Bulk oil temperature [K].
    pressure_gauge_Pa : float, array or CasADi symbol
        Gauge pressure of the oil [Pa].

    Returns
    -------
    film : FilmHeating or None
        :func:`case_film` under ``film``/``full``; None under ``none``/``bulk``.
    b_1_K : float, array, CasADi expression or None
        ``-d ln(mu)/dT`` at (T, p) [1/K] (the oil's own law); None under
        ``none``/``bulk``.

    References
    ----------
    Nahme, Gavis & Laurence [2]_ (Na = b mu U^2/k needs b at the wall temperature).
    """
    if not applies_film(mode):
        return None, None
    return case_film(case), case.oil.temperature_slope(temp_K, pressure_gauge_Pa)


def joint_mean_power(case: DesignCase, oil_temp_C, mode: str, depth_m: float | None = None,
                     regions=None, include_bearing: bool | None = None, *,
                     speed_scale=None, design: dict | None = None):
    """Mean loss [W] of all regions (and the rolling bearing) over the duty cycle at a
    bulk temperature.

    Parameters
    ----------
    case : DesignCase
        The joint, oil, friction law, duty cycle (and ``[thermal]`` for the film's walls).
    oil_temp_C : float, array or CasADi symbol
        Bulk oil temperature(s) [degC]; an array gives one loss per temperature
        (broadcast with ``depth_m`` and the regions' leading axes).
    mode : str
        ``"none"``/``"bulk"`` (isothermal) or ``"film"``/``"full"`` (film correction
        at this temperature; the bulk balance is :func:`operating_temperature`'s).
    depth_m : float or array, optional
        Sea depth [m] (default: the case's).
    regions : sequence of Region, optional
        The regions (default: :func:`~oilgap.model.regions.joint_regions` of the case;
        the design NLP passes region 1 with symbolic geometry, a sweep regions whose
        R, delta, L, T have shape (n, 1)).
    include_bearing : bool, optional
        Add the case's elements (:func:`~oilgap.model.elements.joint_elements`: the rolling
        bearing and a linear drive's screw, rod guide and passages, each at the bulk
        oil state, no film factor) -- the rolling bearing (``case.bearing``,
        :func:`~oilgap.model.bearing.bearing_mean_power` at the bulk viscosity, no film
        factor) when it has one (default: when ``regions`` is None, i.e. the whole
        joint; a caller passing its own regions says whether they stand for the joint).
        Its result must broadcast like the regions' means: one bearing term per
        temperature, not per region.
    speed_scale : float or CasADi symbol, optional
        Factor on the duty cycle's motor speeds [-] (the linear design NLP: a lead
        changed from the case's to ``lead`` turns the motor ``lead0/lead`` times as
        fast for the same rod cycle); default: none.
    design : dict, optional
        The linear drive's design variables [m] passed to
        :func:`~oilgap.model.elements.joint_elements` (``lead_m``,
        ``guide_clearance_m``, ``passage_diameter_m``); default: the case's.

    Returns
    -------
    float, array or CasADi expression
        Mean loss [W] (Eq. 10 with the film factor per node, plus the bearing).

    References
    ----------
    Seed paper [1]_ (Eqs. 5, 10); Nahme, Gavis & Laurence [2]_; the bearing's laws:
    :mod:`oilgap.model.bearing`.
    """
    d = case.operating.depth_m if depth_m is None else depth_m
    p = seawater_gauge_pressure(d)
    symbolic = m.is_symbolic(oil_temp_C, speed_scale)
    t = oil_temp_C if m.is_symbolic(oil_temp_C) else np.asarray(oil_temp_C, dtype=float)
    t_k = celsius_to_kelvin(t)
    nu, _, rho = case.oil.properties(t_k, p)
    nodes, weights = case.duty_cycle.speed_distribution()
    film, b = mode_film(case, mode, t_k, p)
    if symbolic:
        nodes = ca.DM(nodes)
    elif np.ndim(nu) or np.ndim(rho) or np.ndim(b):
        shape = np.broadcast_shapes(np.shape(nu), np.shape(rho), np.shape(b))
        nu, rho = (np.broadcast_to(v, shape)[..., None] for v in (nu, rho))
        b = None if b is None else np.broadcast_to(b, shape)[..., None]
    if speed_scale is not None:
        nodes = nodes * speed_scale
    if include_bearing is None:
        include_bearing = regions is None
    regions = joint_regions(case) if regions is None else regions
    total = sum(region_mean_power(r, nodes, weights, nu, rho, case.friction, film, b)
                for r in regions)
    if include_bearing:
        for element in joint_elements(case, **(design or {})):
            total = total + element.mean_power(nodes, weights, nu, rho)
    return total


def bearing_mean_power_at(case: DesignCase, oil_temp_C, depth_m: float | None = None):
    """Mean power [W] of the case's rolling bearing over the duty cycle at bulk
    temperature(s), numpy only; 0 without a bearing. The same under every thermal mode
    (the bearing's laws take the bulk viscosity; no film factor).

    Parameters
    ----------
    case : DesignCase
        The case (``bearing``, oil, duty cycle, depth).
    oil_temp_C : float or array
        Bulk oil temperature(s) [degC].
    depth_m : float, optional
        Sea depth [m] (default: the case's).

    Returns
    -------
    float or ndarray
        Shape ``np.shape(oil_temp_C)`` [W].

    References
    ----------
    :func:`oilgap.model.bearing.bearing_mean_power` (SKF's frictional-moment model or
    Palmgren's, as the case's ``[bearing]`` chooses).
    """
    t = np.asarray(oil_temp_C, dtype=float)
    if case.bearing is None:
        return np.zeros(t.shape) if t.ndim else 0.0
    p = element_mean_powers_at(case, t, depth_m)[..., 0]  # the bearing is the first
    return p if t.ndim else float(p)


def _stacked_regions(case: DesignCase) -> Region:
    """The case's regions as one Region whose R, delta, L, T have shape (n_regions, 1)."""
    regions = joint_regions(case)
    cols = (np.array([getattr(r, f) for r in regions], dtype=float)[:, None]
            for f in ("radius_m", "gap_m", "length_m", "roughness_T"))
    return Region("stacked", *cols)


def region_mean_powers(case: DesignCase, oil_temp_C, mode: str,
                       depth_m: float | None = None) -> np.ndarray:
    """Mean viscous loss [W] of each region at bulk temperature(s), numpy only.

    :func:`joint_mean_power` with the regions stacked along one axis (one evaluation
    of the laws for all regions: the fast path of the heat balance and of
    :func:`~oilgap.model.evaluation.evaluate_case`).

    Parameters
    ----------
    case : DesignCase
        The joint, oil, friction law, duty cycle (and ``[thermal]`` for the film).
    oil_temp_C : float or array
        Bulk oil temperature(s) [degC].
    mode : str
        A mode of :data:`THERMAL_MODES` (``film`` and ``full`` apply the film factor).
    depth_m : float, optional
        Sea depth [m] (default: the case's).

    Returns
    -------
    ndarray
        Shape ``np.shape(oil_temp_C) + (n_regions,)``: region 1 first [W].

    References
    ----------
    Seed paper [1]_ (Eqs. 5, 10); Nahme, Gavis & Laurence [2]_.
    """
    return _stacked_powers(case, oil_temp_C, mode, depth_m, _stacked_regions(case))


def _stacked_powers(case: DesignCase, oil_temp_C, mode: str, depth_m: float | None,
                    stacked: Region) -> np.ndarray:
    """:func:`region_mean_powers` with the stacked regions given (built once per solve)."""
    t = np.asarray(oil_temp_C, dtype=float)
    p = joint_mean_power(case, t.reshape(-1, 1), mode, depth_m, (stacked,))
    return np.asarray(p, dtype=float).reshape(t.shape + (-1,))


def _balance(case: DesignCase, mode: str, depth_m: float | None
             ) -> tuple[float, np.ndarray]:
    """``T = T_sea + R (P(T) + Q)`` by :func:`~oilgap.model.thermal.joint_steady_temperature`
    (the one solver of the lumped balance), with the losses per region at the root (and
    the elements' as last columns, the bearing first: their heat is in P)."""
    stacked = _stacked_regions(case)
    has_elements = bool(joint_elements(case))

    def power_at(ts):
        p = _stacked_powers(case, ts, mode, depth_m, stacked)
        if not has_elements:
            return p
        return np.concatenate([p, element_mean_powers_at(case, ts, depth_m)], -1)

    temps, powers = joint_steady_temperature(power_at, case.thermal, 1,
                                             case.oil.trusted_range_C)
    return float(temps[0]), powers[0]


def operating_temperature(case: DesignCase, mode: str | None = None,
                          depth_m: float | None = None) -> OperatingTemperature:
    """The bulk oil temperature and loss of a case under a thermal mode.

    ``none``/``film``: the case's oil temperature. ``bulk``/``full``: the unique root of
    ``T = T_sea + R (P(T) + Q)`` (the balance of
    :func:`~oilgap.model.thermal.joint_steady_temperature`, whose uniqueness argument
    holds; three evaluations of the loss on the seed joint).

    Parameters
    ----------
    case : DesignCase
        The case.
    mode : str, optional
        A mode of :data:`THERMAL_MODES` (default: :func:`default_thermal_mode`).
    depth_m : float, optional
        Sea depth [m] (default: the case's).

    Returns
    -------
    OperatingTemperature
        Mode, T_oil [degC], T_sea [degC] or None, mean loss [W] in total (the bearing
        included), per region and of the bearing.

    Raises
    ------
    InputError
        An unknown mode or ``bulk``/``full`` without ``[thermal]``.
    SolverError
        The balance did not converge.

    References
    ----------
    Bergman et al. [3]_, sec. 3.1.
    """
    mode = resolved_mode(case, mode)
    nreg = len(joint_regions(case))
    if not uses_balance(mode):
        t = float(case.operating.oil_temp_C)
        return OperatingTemperature(
            mode, t, None, float(joint_mean_power(case, t, mode, depth_m)),
            tuple(float(v) for v in region_mean_powers(case, t, mode, depth_m)),
            bearing_mean_power_W=float(bearing_mean_power_at(case, t, depth_m)),
            element_mean_powers_W=tuple(float(v) for v in element_mean_powers_at(
                case, t, depth_m)))
    t, powers = _balance(case, mode, depth_m)
    els = tuple(float(v) for v in powers[nreg:])
    return OperatingTemperature(mode, float(t), float(case.thermal.sea_temp_C),
                                float(powers.sum()), tuple(float(v) for v in powers[:nreg]),
                                bearing_mean_power_W=els[0] if case.bearing is not None
                                else 0.0, element_mean_powers_W=els)


@dataclass(frozen=True)
class FilmBand:
    """A loss beside the same design's under the opposite film choice (the film band).

    Under ``none``/``bulk`` (no film) the other side is the film-heated loss at full
    strength (``film``/``full``); under ``film``/``full`` it is the default's loss
    without film (``none``/``bulk``). Reports print both, so the comparison is always
    visible, with the evidence of the film-heated side (:data:`FILM_EVIDENCE`).

    Attributes
    ----------
    mode : str
        The reported mode.
    mean_power_W : float
        The reported mean loss [W].
    other_mode : str
        :func:`film_counterpart` of ``mode``.
    other_mean_power_W : float
        The same design's mean loss under ``other_mode`` [W].
    other_oil_temp_C : float
        Bulk oil temperature under ``other_mode`` [degC].
    """

    mode: str
    mean_power_W: float
    other_mode: str
    other_mean_power_W: float
    other_oil_temp_C: float

    @property
    def change_pct(self) -> float:
        """The other side relative to the reported loss [%]."""
        return 100.0 * (self.other_mean_power_W / self.mean_power_W - 1.0)

    def line(self, fmt: str = ".4g") -> str:
        """The band as one report line, labelled with its evidence.

        Parameters
        ----------
        fmt : str
            Format of the loss [W].

        Returns
        -------
        str
            E.g. ``film heating at full strength (film): 34.9 W (-29 %); not supported
            by the seed's Table 4, see docs/thermal.md#evidence``.
        """
        num = f"{self.other_mean_power_W:{fmt}} W ({self.change_pct:+.0f} %)"
        if applies_film(self.other_mode):
            return (f"film heating at full strength ({self.other_mode}): {num}; "
                    f"{FILM_EVIDENCE}")
        return (f"without film heating ({self.other_mode}, the default the evidence "
                f"supports): {num}; film heating is {FILM_EVIDENCE}")

    def to_dict(self) -> dict:
        """Plain-dict form (the ``film_band`` block of the JSON outputs).

        Returns
        -------
        dict
            ``mode``, ``mean_power_W`` [W], ``change_pct`` [%], ``oil_temp_C`` [degC]
            of the other side, ``film_applied`` (whether the other side applies the
            film), ``evidence``.
        """
        return {"mode": self.other_mode, "mean_power_W": self.other_mean_power_W,
                "change_pct": self.change_pct, "oil_temp_C": self.other_oil_temp_C,
                "film_applied": applies_film(self.other_mode), "evidence": FILM_EVIDENCE}


def film_band(case: DesignCase, mode: str | None = None, depth_m: float | None = None,
              mean_power_W: float | None = None) -> FilmBand:
    """The film band of a case: its loss under a mode and under the mode's counterpart.

    The one computation of the band every report prints: the same design evaluated by
    :func:`operating_temperature` under :func:`film_counterpart` of the mode (``film``
    without ``[thermal]``, ``full`` with it, beside ``none``/``bulk``; the film at full
    strength, s = 1, whatever ``[thermal] film_strength`` says).

    Parameters
    ----------
    case : DesignCase
        The design (its oil temperature, or ``[thermal]`` for the balance modes).
    mode : str, optional
        The reported mode (default: :func:`default_thermal_mode`).
    depth_m : float, optional
        Sea depth [m] (default: the case's).
    mean_power_W : float, optional
        The reported loss [W] when the caller has it (default: computed here).

    Returns
    -------
    FilmBand
        Both losses [W] and the other side's oil temperature [degC].

    References
    ----------
    Seed paper [1]_ (the isothermal loss); Nahme, Gavis & Laurence [2]_ (the film);
    Bergman et al. [3]_ (the balance).
    """
    mode = resolved_mode(case, mode)
    if mean_power_W is None:
        mean_power_W = operating_temperature(case, mode, depth_m).mean_power_W
    at = case
    if applies_film(film_counterpart(mode)) and case.thermal is not None:
        at = replace(case, thermal=replace(case.thermal, film_strength=None))  # s = 1
    other = operating_temperature(at, film_counterpart(mode), depth_m)
    return FilmBand(mode, float(mean_power_W), other.mode, other.mean_power_W,
                    other.oil_temp_C)
