"""Evaluate a design case over its duty cycle, region by region.

Thin layer over the physics functions: the fluid's properties at the operating
condition (any fluid of the case: :mod:`oil_properties`, :mod:`fluids`), Re and Ta
(:mod:`taylor_couette`), C_m (:mod:`skin_friction`) and the power of each region
(:mod:`viscous_loss`), averaged over the duty cycle by its exact speed distribution,
under a thermal mode of :mod:`.joint_loss` (``none``: the seed paper's isothermal
model; ``bulk``: the same at the bulk temperature of the heat balance to the sea;
``film``: the film-heating factor at the given oil temperature; ``full``: the film
factor at the balance's temperature). Under every mode the film at the peak speed
(raw and effective Nahme numbers, steady and applied factors, temperature rise) is
reported with ``film_applied``; under ``none``/``bulk`` it is a diagnostic of the
heating the model leaves out, not applied, and the film band
(:func:`~oilgap.model.joint_loss.film_band`) gives the loss with it. A case's
rolling bearing (``[bearing]``, :mod:`.bearing`) is its own row beside the regions, at
the bulk oil's viscosity under every mode, and in the totals.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 3-6 and 8-10.
"""

from __future__ import annotations

import warnings
from dataclasses import asdict, dataclass, replace

import numpy as np

from .bearing.result import BearingResult, bearing_result
from .case import DesignCase
from .errors import InputError, SolverError
from .film_cycle import FilmPeak, film_peak
from .fluids import warn_if_sea_below_pour_point, warn_if_untrusted_state
from .joint_loss import (
    FilmBand,
    applies_film,
    film_band,
    joint_mean_power,
    mode_film,
    operating_temperature,
    region_mean_powers,
    resolved_mode,
    uses_balance,
)
from .linear.report import (
    LinearElementResult,
    LinearSummary,
    linear_element_results,
    refuse_dashpot,
)
from .oil_properties import seawater_gauge_pressure
from .regions import joint_regions, region_mean_power, region_power
from .skin_friction import moment_coefficient
from .taylor_couette import couette_reynolds, taylor_number
from .thermal_modes import ThermalMode
from .transition import transition_regime
from .units import celsius_to_kelvin, m2_s_to_cst, m_to_mm, rad_s_to_rpm
from .viscous_loss import viscous_torque


@dataclass(frozen=True, kw_only=True)
class RegionResult:
    """Result for one clearance region over the duty cycle.

    Attributes
    ----------
    name : str
        ``"rotor-stator"`` or ``"bearing"``.
    radius_m, gap_m, length_m : float
        R, delta, L [m].
    roughness_T : float
        Clearance roughness T [-].
    Re_peak, Ta_peak : float
        Couette Reynolds and Taylor numbers at the peak speed and the operating
        temperature [-].
    regimes : tuple of str
        Flow regimes the cycle visits (Bilgen-Boulos names), in Re order.
    Cm_peak : float
        Isothermal moment coefficient at the peak speed [-] (the applied film factor
        multiplies it under ``film``/``full``).
    mean_power_W : float
        Mean viscous power over the cycle under the thermal mode [W].
    torque_peak_Nm : float
        Viscous torque at the peak speed under the thermal mode [N m].
    nahme_peak : float
        Raw Nahme-Griffith number b mu U^2/k at the peak speed and the operating
        temperature (plane film, rotor surface speed) [-].
    nahme_effective_peak, film_factor_steady_peak, film_factor_effective_peak : float
        The film at the peak speed as :class:`~oilgap.model.film_cycle.FilmPeak` gives
        it: effective Na, steady Phi, the factor ``film``/``full`` apply [-].
    film_factor_applied_peak : float
        The factor this evaluation applied there: the effective one under
        ``film``/``full``, 1.0 under ``none``/``bulk`` [-].
    film_applied : bool
        Whether the mode applies the film correction.
    film_temp_rise_peak_K : float or None
        Hottest point of the film above the bulk at the peak speed [K] (laminar
        solution; under ``none`` a diagnostic as above); None when the flow there has
        Taylor vortices (the film correction is laminar-only).
    """

    name: str
    radius_m: float
    gap_m: float
    length_m: float
    roughness_T: float
    Re_peak: float
    Ta_peak: float
    regimes: tuple[str, ...]
    Cm_peak: float
    mean_power_W: float
    torque_peak_Nm: float
    nahme_peak: float
    nahme_effective_peak: float
    film_factor_steady_peak: float
    film_factor_effective_peak: float
    film_factor_applied_peak: float
    film_applied: bool
    film_temp_rise_peak_K: float | None


@dataclass(frozen=True, kw_only=True)
class CaseEvaluation:
    """Result of :func:`evaluate_case`.

    Attributes
    ----------
    case_name, oil : str
        Names of the case and the oil.
    thermal_mode : str
        ``"none"``, ``"bulk"``, ``"film"`` or ``"full"`` (:mod:`.joint_loss`).
    thermal_mode_default : bool
        True when the mode is the default (the user did not choose it).
    oil_temp_C : float
        Operating bulk oil temperature [degC]: the case's (or the given) one, or the
        heat balance's under ``bulk``/``full``.
    sea_temp_C : float or None
        Sea temperature of the heat balance [degC] under ``bulk``/``full``; None
        otherwise.
    resistance_K_per_W, other_heat_W : float or None
        The balance's resistance oil to sea [K/W] and other heat [W] under
        ``bulk``/``full``; None otherwise.
    depth_m : float
        Sea depth [m].
    nu_cSt : float
        Kinematic viscosity at the operating condition [cSt].
    density_kg_m3 : float
        Oil density at the operating condition [kg/m^3].
    laminar_law, form : str
        The friction law's laminar law and form.
    peak_speed_rpm : float
        Peak speed of the cycle [rpm].
    regions : tuple of RegionResult
        Region 1, then region 2 if any.
    total_mean_power_W : float
        Mean viscous power of all regions under the thermal mode (Eq. 10), plus the
        rolling bearing's [W].
    isothermal_total_mean_power_W : float
        The seed paper's isothermal model (mode ``none``) at the case's own oil
        temperature, plus the bearing there [W]: what the heating changed.
    viscous_torque_peak_Nm : float
        Viscous torque of all regions, plus the bearing's moment, at the peak speed [N m].
    cycle_energy_J : float
        Energy dissipated over one cycle [J].
    bearings : tuple of BearingResult
        The case's rolling bearing, if any (empty without ``[bearing]``).
    film_applied : bool
        Whether the mode applies the film correction (``film``/``full``).
    film_band : FilmBand or None
        The same design under the opposite film choice
        (:func:`~oilgap.model.joint_loss.film_band`); None when not computed.
    linear_elements : tuple of LinearElementResult
        A linear actuator's screw, rod guide and passages at the bulk oil state
        (:mod:`oilgap.model.linear.report`); empty for a rotary joint.
    linear : LinearSummary or None
        A linear actuator's lead, peak rod velocity and motor speed, passage flow
        numbers; None for a rotary joint.
    """

    case_name: str
    oil: str
    thermal_mode: str
    thermal_mode_default: bool
    oil_temp_C: float
    sea_temp_C: float | None
    resistance_K_per_W: float | None
    other_heat_W: float | None
    depth_m: float
    nu_cSt: float
    density_kg_m3: float
    laminar_law: str
    form: str
    peak_speed_rpm: float
    regions: tuple[RegionResult, ...]
    total_mean_power_W: float
    isothermal_total_mean_power_W: float
    viscous_torque_peak_Nm: float
    cycle_energy_J: float
    bearings: tuple[BearingResult, ...] = ()
    film_applied: bool = False
    film_band: FilmBand | None = None
    linear_elements: tuple[LinearElementResult, ...] = ()
    linear: LinearSummary | None = None

    def to_dict(self) -> dict:
        """Plain-dict form (the ``--json`` output).

        Returns
        -------
        dict
            The fields with their unit-carrying names (``mean_power_W`` [W]); lengths
            in mm at this edge (``radius_mm``, ``gap_mm``, ``length_mm``,
            ``pitch_diameter_mm`` [mm]; the attributes stay in m), a bearing's
            ``terms`` as ``terms_W`` (term -> mean power [W]); ``bearings`` only
            when the case has a bearing (a case without one gives the document it
            gave before bearings existed); ``film_band`` as
            :meth:`~oilgap.model.joint_loss.FilmBand.to_dict`.
        """
        d = asdict(self)
        d["film_band"] = None if self.film_band is None else self.film_band.to_dict()
        d["regions"] = [_lengths_in_mm(dict(asdict(r), regimes=list(r.regimes)))
                        for r in self.regions]
        d["bearings"] = [_lengths_in_mm(dict(asdict(b), default_notes=list(b.default_notes),
                                             validity_notes=list(b.validity_notes)))
                         for b in self.bearings]
        if not self.bearings:
            del d["bearings"]
        if self.linear is None:  # a rotary joint's document is what it was
            del d["linear_elements"], d["linear"]
        return d


def _lengths_in_mm(d: dict) -> dict:
    """The ``*_m`` lengths of a region's or bearing's dict as ``*_mm`` [mm] and ``terms``
    as ``terms_W`` [W], in place of their keys (the order kept)."""
    return {_EDGE_KEYS.get(k, k): (m_to_mm(v) if k in _LENGTH_KEYS else v)
            for k, v in d.items()}


_LENGTH_KEYS = ("radius_m", "gap_m", "length_m", "pitch_diameter_m")
"""Length fields [m] of :class:`RegionResult` and :class:`BearingResult`."""

_EDGE_KEYS = {**{k: k[:-2] + "_mm" for k in _LENGTH_KEYS}, "terms": "terms_W",
              "model_band": "model_band_W"}
"""Field -> its key in :meth:`CaseEvaluation.to_dict`."""


def oil_state(case: DesignCase, oil_temp_C: float | None = None, depth_m: float | None = None):
    """(nu [m^2/s], mu [Pa s], rho [kg/m^3]) of the case's fluid at its (or the given) condition.

    Warns (OilgapWarning) outside the fluid's trusted range (the Walther line's for a
    mineral oil, the Sutherland law's for a gas; a gas above 1 MPa absolute); a table
    fluid refuses temperatures outside its table (InputError).

    Parameters
    ----------
    case : DesignCase
        The case (oil and operating condition).
    oil_temp_C : float, optional
        Oil temperature [degC] (default: the case's).
    depth_m : float, optional
        Sea depth [m] (default: the case's).

    Returns
    -------
    nu_m2_s, mu_Pa_s, rho_kg_m3 : float
        [m^2/s], [Pa s], [kg/m^3].
    """
    t = case.operating.oil_temp_C if oil_temp_C is None else oil_temp_C
    d = case.operating.depth_m if depth_m is None else depth_m
    p = seawater_gauge_pressure(d)
    warn_if_untrusted_state(case.oil, t, p)
    return case.oil.properties(celsius_to_kelvin(t), p)


def region_powers(case: DesignCase, omega_rad_s, nu_m2_s, rho_kg_m3) -> dict[str, np.ndarray]:
    """Viscous power [W] of each region of the case at the given speeds and oil state.

    Parameters
    ----------
    case : DesignCase
        The joint's regions and friction law.
    omega_rad_s : float or array
        Rotor speed(s) [rad/s].
    nu_m2_s : float or array
        Kinematic viscosity [m^2/s].
    rho_kg_m3 : float or array
        Oil density [kg/m^3].

    Returns
    -------
    dict
        Region name -> power [W].
    """
    return {r.name: region_power(r, omega_rad_s, nu_m2_s, rho_kg_m3, case.friction)
            for r in joint_regions(case)}


def mean_viscous_power(case: DesignCase, oil_temp_C: float | None = None,
                       depth_m: float | None = None) -> float:
    """Mean viscous power [W] of all regions over the case's duty cycle (Eq. 10),
    isothermal (thermal mode ``none``; the other modes, and the regions with the case's
    rolling bearing: :func:`~oilgap.model.joint_loss.joint_mean_power`).

    Parameters
    ----------
    case : DesignCase
        The joint, oil, condition and duty cycle.
    oil_temp_C : float, optional
        Oil temperature [degC] (default: the case's).
    depth_m : float, optional
        Sea depth [m] (default: the case's).

    Returns
    -------
    float
        Mean power [W].

    References
    ----------
    Seed paper (Eqs. 5 and 10) [1].
    """
    nu, _, rho = oil_state(case, oil_temp_C, depth_m)
    nodes, weights = case.duty_cycle.speed_distribution()
    return float(sum(region_mean_power(r, nodes, weights, nu, rho, case.friction)
                     for r in joint_regions(case)))


def _region_result(case: DesignCase, region, p_mean: float, nu, rho, b, film,
                   apply_film: bool) -> RegionResult:
    """One region's numbers at the operating state (film applied or only reported)."""
    cycle = case.duty_cycle
    nodes, weights = cycle.speed_distribution()
    w_peak = cycle.peak_omega_rad_s
    R, gap = region.radius_m, region.gap_m
    re_peak = float(couette_reynolds(w_peak, R, gap, nu))
    peak: FilmPeak = film_peak(nodes, weights, R, gap, nu, rho, b, film)
    tq = float(viscous_torque(float(region_power(region, w_peak, nu, rho, case.friction)),
                              w_peak)) * peak.applied(apply_film)
    re_nodes = couette_reynolds(nodes, R, gap, nu)
    visited = set(transition_regime(re_nodes[weights > 0], gap / R, case.friction.transition))
    regimes = tuple(r for r in ("laminar", "laminar with vortices",
                                "turbulent with vortices", "turbulent") if r in visited)
    return RegionResult(
        name=region.name, radius_m=R, gap_m=gap, length_m=region.length_m,
        roughness_T=float(region.roughness_T), Re_peak=re_peak,
        Ta_peak=float(taylor_number(re_peak, gap, R)), regimes=regimes,
        Cm_peak=float(moment_coefficient(re_peak, gap / R, case.friction, region.roughness_T)),
        mean_power_W=float(p_mean), torque_peak_Nm=tq, nahme_peak=peak.nahme_peak,
        nahme_effective_peak=peak.nahme_effective_peak,
        film_factor_steady_peak=peak.film_factor_steady_peak,
        film_factor_effective_peak=peak.film_factor_effective_peak,
        film_factor_applied_peak=peak.applied(apply_film), film_applied=bool(apply_film),
        film_temp_rise_peak_K=peak.film_temp_rise_peak_K)


def _operating_state(case: DesignCase, mode: str, t_case: float, d: float, regions):
    """Operating temperature [degC], nu [m^2/s], rho [kg/m^3] and each region's mean loss
    [W] under the mode (today's isothermal path, unchanged, under ``none``)."""
    t = t_case
    if uses_balance(mode):
        warn_if_sea_below_pour_point(case.oil, case.thermal.sea_temp_C)
        op = operating_temperature(case, mode, d)
        t, means = op.oil_temp_C, op.region_mean_powers_W
    with warnings.catch_warnings():
        warnings.simplefilter("default")
        nu, _, rho = oil_state(case, t, d)
    if mode == ThermalMode.NONE:
        nodes, weights = case.duty_cycle.speed_distribution()
        means = [region_mean_power(r, nodes, weights, nu, rho, case.friction) for r in regions]
    elif mode == ThermalMode.FILM:
        means = region_mean_powers(case, t, mode, d)
    return t, nu, rho, means


def _refuse_non_finite(case: DesignCase, t: float, d: float, nu, rho,
                       results: tuple[RegionResult, ...],
                       bearings: tuple[BearingResult, ...]) -> None:
    """Never a non-finite loss as a result: an InputError naming the inputs that drive it
    (the fluid's state, the friction law, the speed and geometry), else a SolverError."""
    if not (np.isfinite(nu) and np.isfinite(rho) and nu > 0 and rho > 0):
        raise InputError("oil", case.oil.name, f"its state at {t:g} degC and {d:g} m is not a "
                         f"finite positive number (nu = {m2_s_to_cst(nu):g} cSt, rho = "
                         f"{float(rho):g} kg/m^3): check the oil's data and the operating "
                         "condition", "evaluation")
    law = case.friction
    for r in results:
        if not (np.isfinite(r.Re_peak) and np.isfinite(r.Cm_peak)):
            raise InputError("friction", f"gamma = {law.gamma:g}, C = {law.C:g}, alpha = "
                             f"{law.alpha:g}, beta = {law.beta:g}, scale = {law.scale:g}",
                             f"C_m of {r.name} at the peak speed is not finite (Re = "
                             f"{r.Re_peak:g}, T = {r.roughness_T:g}): the law's numbers or the "
                             "geometry are out of reach of the law", "evaluation")
        if not (np.isfinite(r.mean_power_W) and np.isfinite(r.torque_peak_Nm)):
            raise InputError("speed, size and oil", f"peak_speed_rpm = "
                             f"{rad_s_to_rpm(case.duty_cycle.peak_omega_rad_s):g}, R = "
                             f"{r.radius_m / 1e-3:g} mm, L = {r.length_m / 1e-3:g} mm, rho = "
                             f"{float(rho):g} kg/m^3, nu = {m2_s_to_cst(nu):g} cSt",
                             f"the loss of {r.name} (C_m rho omega^3 R^4 L) is not finite: "
                             "out of reach of the model", "evaluation")
    for b in bearings:
        if not (np.isfinite(b.mean_power_W) and np.isfinite(b.torque_peak_Nm)):
            raise InputError("bearing", b.name, "its loss is not finite at this speed and "
                             "viscosity: check the [bearing] table", "evaluation")
    if not all(np.isfinite(x) for r in results
               for x in (r.film_factor_effective_peak, r.nahme_peak)):
        raise SolverError("the film-heating factor at the peak speed is not finite; the "
                          "result is not reported")


@dataclass(frozen=True, kw_only=True)
class _Computed:
    """The evaluation's numbers before they become a :class:`CaseEvaluation`."""

    oil_temp_C: float
    nu_m2_s: float
    rho_kg_m3: float
    regions: tuple[RegionResult, ...]
    bearings: tuple[BearingResult, ...]
    total_W: float
    isothermal_W: float
    linear_rows: tuple = ()
    linear: LinearSummary | None = None

    def evaluation(self, case: DesignCase, mode: str, by_default: bool, depth_m: float,
                   band) -> CaseEvaluation:
        """The :class:`CaseEvaluation` of these numbers (``band``: the film band)."""
        spec = case.thermal if uses_balance(mode) else None
        cycle, total, rows = case.duty_cycle, self.total_W, self.regions + self.bearings
        return CaseEvaluation(
            case_name=case.name, oil=case.oil.name, thermal_mode=mode,
            thermal_mode_default=by_default, oil_temp_C=self.oil_temp_C,
            sea_temp_C=None if spec is None else float(spec.sea_temp_C),
            resistance_K_per_W=None if spec is None else float(spec.resistance_K_W),
            other_heat_W=None if spec is None else float(spec.other_heat_W), depth_m=depth_m,
            nu_cSt=m2_s_to_cst(self.nu_m2_s), density_kg_m3=float(self.rho_kg_m3),
            laminar_law=case.friction.laminar_law, form=case.friction.form,
            peak_speed_rpm=rad_s_to_rpm(cycle.peak_omega_rad_s), regions=self.regions,
            total_mean_power_W=total, isothermal_total_mean_power_W=self.isothermal_W,
            viscous_torque_peak_Nm=sum(r.torque_peak_Nm for r in rows),
            cycle_energy_J=total * cycle.duration_s, bearings=self.bearings,
            film_applied=applies_film(mode), film_band=band, linear_elements=self.linear_rows,
            linear=self.linear)


def _computed(case: DesignCase, mode: str, t_case: float, d: float) -> _Computed:
    """The evaluation's numbers, checked finite (numpy's overflow warnings are replaced by
    the check: a non-finite loss is refused, never printed)."""
    try:
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            regions = joint_regions(case)
            t, nu, rho, means = _operating_state(case, mode, t_case, d, regions)
            film, b = mode_film(case, "film", celsius_to_kelvin(t), seawater_gauge_pressure(d))
            results = tuple(_region_result(case, r, p, nu, rho, b, film, applies_film(mode))
                            for r, p in zip(regions, means, strict=True))
            bearings = () if case.bearing is None else (bearing_result(case, case.bearing,
                                                                       nu, rho),)
            lin_rows, lin = ((), None) if case.linear is None else linear_element_results(
                case, nu, rho)
            total = sum(r.mean_power_W for r in results + bearings + lin_rows)
            iso = total if mode == ThermalMode.NONE else float(
                joint_mean_power(case, t_case, ThermalMode.NONE.value, d))
    except (OverflowError, ZeroDivisionError) as e:
        raise SolverError(f"the evaluation of {case.name!r} overflowed ({e}); the inputs "
                          "are out of reach of the model") from None
    _refuse_non_finite(case, t, d, nu, rho, results, bearings)
    if not (np.isfinite(total) and np.isfinite(iso)):
        raise SolverError(f"the total loss is not finite ({total:g} W, isothermal {iso:g} W); "
                          "the result is not reported")
    return _Computed(oil_temp_C=t, nu_m2_s=nu, rho_kg_m3=rho, regions=results,
                     bearings=bearings, total_W=total, isothermal_W=iso, linear_rows=lin_rows,
                     linear=lin)


def evaluate_case(case: DesignCase, oil_temp_C: float | None = None,
                  depth_m: float | None = None, laminar_law: str | None = None,
                  thermal: str | None = None, *, thermal_default: bool | None = None
                  ) -> CaseEvaluation:
    """Evaluate a case region by region over its duty cycle under a thermal mode.

    ``none``: the seed paper's isothermal model at the oil temperature. ``bulk``: the
    same at the bulk temperature of the heat balance to the sea
    (:func:`~oilgap.model.joint_loss.operating_temperature`, the case's ``[thermal]``).
    ``film``: the film-heating factor (:mod:`.film_cycle`) at the given temperature.
    ``full``: the film factor at the balance's temperature. Under every mode the film's
    Nahme numbers, factors and temperature rise at the peak speed are reported (under
    ``none``/``bulk`` as diagnostics, not applied: ``film_applied`` says which), and the
    film band (:func:`~oilgap.model.joint_loss.film_band`) gives the same design under
    the opposite film choice. A rolling bearing (``case.bearing``) is its own row at the
    bulk viscosity under every mode (:func:`bearing_result`) and part of the totals (and
    of the balance under ``bulk``/``full``).

    Parameters
    ----------
    case : DesignCase
        The joint, oil, condition, duty cycle and friction law.
    oil_temp_C : float, optional
        Oil temperature [degC] (default: the case's); refused under ``bulk``/``full``,
        where the heat balance sets it.
    depth_m : float, optional
        Sea depth [m] (default: the case's).
    laminar_law : {"couette", "bilgen-boulos"}, optional
        Override of the friction law's laminar law.
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode (default: the model the evidence supports,
        :func:`~oilgap.model.joint_loss.default_thermal_mode`: ``bulk`` with
        ``[thermal]``, else ``none``); a resolved mode
        (:func:`~oilgap.model.joint_loss.resolve_thermal_mode`) is taken as it is.
    thermal_default : bool, optional
        Whether the mode is the default (reported so; default: ``thermal is None``), for
        a caller that passes the mode it resolved.

    Returns
    -------
    CaseEvaluation
        Mode, operating oil state, and per region Re, Ta, C_m at the peak speed, the
        regimes visited, the mean power [W] and the film at the peak; the bearing's
        row; totals [W], [N m], [J] and the isothermal total [W], bearing included; the
        film band [W].

    Raises
    ------
    InputError
        An unknown mode, ``bulk``/``full`` without ``[thermal]``, or ``oil_temp_C``
        under ``bulk``/``full``; a loss that is not a finite number, named by the inputs
        that drive it (the fluid's state, the friction law, the speed, the bearing).
    SolverError
        The heat balance did not converge, or a non-finite result that no input
        explains.

    References
    ----------
    Seed paper (Eqs. 3-6 and 8-10) [1]; Nahme (1940), Gavis &
    Laurence (1968) (the heated film).
    """
    mode = resolved_mode(case, thermal)
    by_default = thermal is None if thermal_default is None else thermal_default
    if laminar_law is not None:
        case = replace(case, friction=replace(case.friction, laminar_law=laminar_law))
    t_case = case.operating.oil_temp_C if oil_temp_C is None else float(oil_temp_C)
    d = case.operating.depth_m if depth_m is None else float(depth_m)
    spec = case.thermal if uses_balance(mode) else None
    if spec is not None and oil_temp_C is not None:
        raise InputError("oil_temp_C", oil_temp_C, f"not given under thermal mode '{mode}': "
                         "the heat balance sets the oil temperature (change [thermal] "
                         "sea_temp_C, or choose thermal 'none' or 'film')")
    refuse_dashpot(case)
    c = _computed(case, mode, t_case, d)
    at = case if oil_temp_C is None else replace(
        case, operating=replace(case.operating, oil_temp_C=t_case))
    return c.evaluation(case, mode, by_default, d, film_band(at, mode, d, c.total_W))
