"""Evaluate a design case over its duty cycle, region by region.

Thin layer over the physics functions: the fluid's properties at the operating
condition (any fluid of the case: :mod:`oil_properties`, :mod:`fluids`), Re and Ta
(:mod:`taylor_couette`), C_m (:mod:`skin_friction`) and the power of each region
(:mod:`viscous_loss`), averaged over the duty cycle by its exact speed distribution.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 3-6 and 8-10.
"""

from __future__ import annotations

import warnings
from dataclasses import asdict, dataclass, replace

import numpy as np

from .case import DesignCase
from .fluids import warn_if_untrusted_state
from .oil_properties import seawater_gauge_pressure
from .regions import joint_regions, region_mean_power, region_power
from .skin_friction import moment_coefficient
from .taylor_couette import couette_reynolds, flow_regime, taylor_number
from .units import celsius_to_kelvin, m2_s_to_cst, rad_s_to_rpm
from .viscous_loss import viscous_torque


@dataclass(frozen=True)
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
        Couette Reynolds and Taylor numbers at the peak speed [-].
    regimes : tuple of str
        Flow regimes the cycle visits (Bilgen-Boulos names), in Re order.
    Cm_peak : float
        Moment coefficient at the peak speed [-].
    mean_power_W : float
        Mean viscous power over the cycle [W].
    torque_peak_Nm : float
        Viscous torque at the peak speed [N m].
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


@dataclass(frozen=True)
class CaseEvaluation:
    """Result of :func:`evaluate_case`.

    Attributes
    ----------
    case_name, oil : str
        Names of the case and the oil.
    oil_temp_C : float
        Oil temperature [degC].
    depth_m : float
        Sea depth [m].
    nu_cSt : float
        Kinematic viscosity at the condition [cSt].
    density_kg_m3 : float
        Oil density at the condition [kg/m^3].
    laminar_law, form : str
        The friction law's laminar law and form.
    peak_speed_rpm : float
        Peak speed of the cycle [rpm].
    regions : tuple of RegionResult
        Region 1, then region 2 if any.
    total_mean_power_W : float
        Mean viscous power of all regions (Eq. 10) [W].
    viscous_torque_peak_Nm : float
        Viscous torque of all regions at the peak speed [N m].
    cycle_energy_J : float
        Energy dissipated over one cycle [J].
    """

    case_name: str
    oil: str
    oil_temp_C: float
    depth_m: float
    nu_cSt: float
    density_kg_m3: float
    laminar_law: str
    form: str
    peak_speed_rpm: float
    regions: tuple[RegionResult, ...]
    total_mean_power_W: float
    viscous_torque_peak_Nm: float
    cycle_energy_J: float

    def to_dict(self) -> dict:
        """Plain-dict form (the ``--json`` output).

        Returns
        -------
        dict
            The fields with their unit-carrying names (``mean_power_W`` [W]).
        """
        d = asdict(self)
        d["regions"] = [dict(asdict(r), regimes=list(r.regimes)) for r in self.regions]
        return d


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
    """Mean viscous power [W] of all regions over the case's duty cycle (Eq. 10).

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
    Seed paper (Modeling and Optimization of Compensating Oil Viscous Power for a
    Deep-Sea Electric Manipulator, Eqs. 5 and 10) [1].
    """
    nu, _, rho = oil_state(case, oil_temp_C, depth_m)
    nodes, weights = case.duty_cycle.speed_distribution()
    return float(sum(region_mean_power(r, nodes, weights, nu, rho, case.friction)
                     for r in joint_regions(case)))


def evaluate_case(case: DesignCase, oil_temp_C: float | None = None,
                  depth_m: float | None = None, laminar_law: str | None = None) -> CaseEvaluation:
    """Evaluate a case region by region over its duty cycle.

    Parameters
    ----------
    case : DesignCase
        The joint, oil, condition, duty cycle and friction law.
    oil_temp_C : float, optional
        Oil temperature [degC] (default: the case's).
    depth_m : float, optional
        Sea depth [m] (default: the case's).
    laminar_law : {"couette", "bilgen-boulos"}, optional
        Override of the friction law's laminar law.

    Returns
    -------
    CaseEvaluation
        Oil state, and per region Re, Ta, C_m at the peak speed, the regimes
        visited and the mean power [W]; totals [W], [N m], [J].

    References
    ----------
    Seed paper (Modeling and Optimization of Compensating Oil Viscous Power for a
    Deep-Sea Electric Manipulator, Eqs. 3-6 and 8-10) [1].
    """
    if laminar_law is not None:
        case = replace(case, friction=replace(case.friction, laminar_law=laminar_law))
    t = case.operating.oil_temp_C if oil_temp_C is None else float(oil_temp_C)
    d = case.operating.depth_m if depth_m is None else float(depth_m)
    with warnings.catch_warnings():
        warnings.simplefilter("default")
        nu, _, rho = oil_state(case, t, d)
    cycle = case.duty_cycle
    nodes, weights = cycle.speed_distribution()
    w_peak = cycle.peak_omega_rad_s
    results = []
    total_torque = 0.0
    for region in joint_regions(case):
        name, R, gap, L, T = (region.name, region.radius_m, region.gap_m, region.length_m,
                              region.roughness_T)
        re_nodes = couette_reynolds(nodes, R, gap, nu)
        p_mean = region_mean_power(region, nodes, weights, nu, rho, case.friction)
        re_peak = float(couette_reynolds(w_peak, R, gap, nu))
        p_peak = float(region_power(region, w_peak, nu, rho, case.friction))
        tq = float(viscous_torque(p_peak, w_peak))
        total_torque += tq
        visited = set(flow_regime(re_nodes[weights > 0]))
        regimes = tuple(r for r in ("laminar", "laminar with vortices",
                                    "turbulent with vortices", "turbulent") if r in visited)
        results.append(RegionResult(
            name, R, gap, L, float(T), re_peak, float(taylor_number(re_peak, gap, R)), regimes,
            float(moment_coefficient(re_peak, gap / R, case.friction, T)),
            float(p_mean), tq))
    total = sum(r.mean_power_W for r in results)
    return CaseEvaluation(case.name, case.oil.name, t, d, m2_s_to_cst(nu), float(rho),
                          case.friction.laminar_law, case.friction.form,
                          rad_s_to_rpm(w_peak), tuple(results), total, total_torque,
                          total * cycle.duration_s)
