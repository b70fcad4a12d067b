"""The linear actuator's rows of an evaluation, its design checks and the dashpot refusal.

:func:`linear_element_results` gives each linear element's mean power over the cycle at
the bulk oil state with its peak force or torque and the passages' flow numbers;
:func:`refuse_dashpot` refuses a drive without a bypass with the force it would reach;
:func:`drive_checks` gives the design quantities the optimizer constrains (rod force,
motor speed, passage velocity, compensator volume).

References
----------
.. [1] F. M. White, *Viscous Fluid Flow*, 3rd ed., McGraw-Hill 2006, secs. 3-2, 3-3.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..errors import InputError
from ..oil_properties import seawater_gauge_pressure
from ..units import celsius_to_kelvin, rad_s_to_rpm
from .elements import linear_elements
from .laws import (
    annulus_leakage,
    dashpot_force,
    hagen_poiseuille_pressure_drop,
    motor_speed,
    rod_velocity,
)

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase
    from .drive import LinearDrive

LINEAR_LABELS = {"screw": "screw", "rod guide": "rod guide", "passages": "passages"}
"""Element name -> its label in reports."""


@dataclass(frozen=True, kw_only=True)
class LinearElementResult:
    """One linear element's row of an evaluation.

    Attributes
    ----------
    name : str
        ``"screw"``, ``"rod guide"`` or ``"passages"``.
    mean_power_W : float
        Mean power over the duty cycle at the bulk oil state [W].
    peak_power_W : float
        Power at the cycle's peak speed [W].
    peak_load : float
        At the peak speed: the screw's torque [N m], the rod guide's drag [N] or the
        passages' force ``dp A_rod`` on the rod [N].
    peak_load_unit : str
        ``"N m"`` or ``"N"``.
    """

    name: str
    mean_power_W: float
    peak_power_W: float
    peak_load: float
    peak_load_unit: str


@dataclass(frozen=True, kw_only=True)
class LinearSummary:
    """The drive's kinematics and flow numbers at the cycle's peak.

    Attributes
    ----------
    lead_mm : float
        Screw lead [mm].
    peak_rod_velocity_m_s : float
        Peak rod velocity [m/s].
    peak_motor_speed_rpm : float
        Peak motor speed ``2 pi v/lead`` [rpm].
    passage_velocity_peak_m_s : float
        Peak mean velocity in a passage [m/s].
    passage_reynolds_peak : float
        Its Reynolds number ``V d/nu`` [-] (laminar below about 2000).
    passage_pressure_drop_peak_Pa : float
        Peak pressure drop across the passages [Pa].
    guide_leakage_share_peak : float
        Flow the guide clearance would carry at that pressure drop, as a share of the
        displaced flow [-] (with ``1 + 1.5 eps^2``); the passages are taken to carry all.
    """

    lead_mm: float
    peak_rod_velocity_m_s: float
    peak_motor_speed_rpm: float
    passage_velocity_peak_m_s: float
    passage_reynolds_peak: float
    passage_pressure_drop_peak_Pa: float
    guide_leakage_share_peak: float


def refuse_dashpot(case: DesignCase, mu_Pa_s: float | None = None) -> None:
    """Refuse a drive whose displaced oil has no passage: its rod is a dashpot.

    Parameters
    ----------
    case : DesignCase
        The case (``linear``; its oil at the case's condition if ``mu_Pa_s`` is None).
    mu_Pa_s : float, optional
        Dynamic viscosity [Pa s].

    Raises
    ------
    InputError
        ``passages.count = 0``, naming the force ``6 pi mu L R^3 v/c^3`` at the peak
        rod velocity.

    References
    ----------
    :func:`~oilgap.model.linear.laws.dashpot_force`.
    """
    d = case.linear
    if d is None or d.has_bypass:
        return
    if mu_Pa_s is None:
        t_k = celsius_to_kelvin(case.operating.oil_temp_C)
        nu, _, rho = case.oil.properties(t_k, seawater_gauge_pressure(case.operating.depth_m))
        mu_Pa_s = float(nu * rho)
    v = rod_velocity(case.duty_cycle.peak_omega_rad_s, d.lead_m)
    f = float(dashpot_force(mu_Pa_s, v, d.guide_length_m, 0.5 * d.rod_diameter_m,
                            d.guide_clearance_m))
    raise InputError("passages.count", 0, f"at least 1: without a bypass the rod pushes its "
                     f"displaced oil through the {d.guide_clearance_m * 1e3:g} mm guide "
                     f"clearance, a dashpot of {f:.3g} N at {v:.3g} m/s "
                     "(F = 6 pi mu L R^3 v/c^3), a design error, not a loss", "passages")


def linear_element_results(case: DesignCase, nu_m2_s: float, rho_kg_m3: float
                           ) -> tuple[tuple[LinearElementResult, ...], LinearSummary]:
    """The linear elements' rows and the drive's peak numbers at a bulk oil state.

    Parameters
    ----------
    case : DesignCase
        A linear case (``case.linear``).
    nu_m2_s : float
        Kinematic viscosity [m^2/s].
    rho_kg_m3 : float
        Density [kg/m^3].

    Returns
    -------
    rows : tuple of LinearElementResult
        Screw, rod guide, passages.
    summary : LinearSummary
        Kinematics and flow numbers at the peak.

    References
    ----------
    White [1]_; :mod:`oilgap.model.linear.elements`.
    """
    d: LinearDrive = case.linear
    nodes, weights = case.duty_cycle.speed_distribution()
    w_pk = case.duty_cycle.peak_omega_rad_s
    v_pk = float(rod_velocity(w_pk, d.lead_m))
    rows = []
    for e in linear_elements(d):
        mean = float(e.mean_power(nodes, weights, nu_m2_s, rho_kg_m3))
        peak = float(e.power(w_pk, nu_m2_s, rho_kg_m3))
        if e.name == "screw":
            load, unit = float(e.torque(w_pk, nu_m2_s)), "N m"
        else:
            load, unit = peak / v_pk, "N"
        rows.append(LinearElementResult(name=e.name, mean_power_W=mean, peak_power_W=peak,
                                        peak_load=load, peak_load_unit=unit))
    mu = nu_m2_s * rho_kg_m3
    q = d.rod_area_m2 * v_pk
    n = max(d.passage_count, 1)
    vel = q / n / (0.25 * math.pi * d.passage_diameter_m**2)
    dp = float(hagen_poiseuille_pressure_drop(mu, d.passage_length_m, q / n,
                                              d.passage_diameter_m))
    leak = float(annulus_leakage(mu, dp, d.guide_length_m, d.rod_diameter_m,
                                 d.guide_clearance_m, d.eccentricity))
    summary = LinearSummary(
        lead_mm=d.lead_m * 1e3, peak_rod_velocity_m_s=v_pk,
        peak_motor_speed_rpm=float(rad_s_to_rpm(w_pk)), passage_velocity_peak_m_s=vel,
        passage_reynolds_peak=float(vel * d.passage_diameter_m / nu_m2_s),
        passage_pressure_drop_peak_Pa=dp, guide_leakage_share_peak=leak / q)
    return tuple(rows), summary


def compensator_volume(case: DesignCase, drive: LinearDrive | None = None) -> float:
    """Volume the compensator must take up [m^3]: the rod's displaced volume over the
    stroke plus the oil's thermal expansion over the compensator's temperature range.

    ``V = A_rod stroke + V_oil (rho(T_min)/rho(T_max) - 1)``, the oil's density from its
    own law at the case's depth.

    Parameters
    ----------
    case : DesignCase
        The case (oil, depth).
    drive : LinearDrive, optional
        The drive (default: the case's); needs a ``compensator``.

    Returns
    -------
    float
        Volume [m^3].

    References
    ----------
    Mass conservation of the oil in the housing.
    """
    d = case.linear if drive is None else drive
    c = d.compensator
    p = seawater_gauge_pressure(case.operating.depth_m)
    rho = [float(case.oil.properties(celsius_to_kelvin(t), p)[2])
           for t in (c.temp_min_C, c.temp_max_C)]
    return d.rod_area_m2 * d.stroke_m + c.oil_volume_m3 * (rho[0] / rho[1] - 1.0)


def peak_rod_velocity(case: DesignCase) -> float:
    """Peak rod velocity of the case's duty cycle [m/s] (the motor's peak times lead/2 pi).

    Parameters
    ----------
    case : DesignCase
        A linear case.

    Returns
    -------
    float
        [m/s].
    """
    return float(rod_velocity(case.duty_cycle.peak_omega_rad_s, case.linear.lead_m))


__all__ = ["ROD_VELOCITY_COLUMN", "LinearElementResult", "LinearSummary",
           "compensator_volume", "linear_element_results", "peak_rod_velocity",
           "refuse_dashpot", "rod_rows_as_motor_speed"]


ROD_VELOCITY_COLUMN = "rod_velocity_m_s"
"""Rig-data column of a linear actuator's rod velocity [m/s] (signed)."""


def rod_rows_as_motor_speed(df, drive: LinearDrive):
    """Rig data of a linear actuator with the motor's speed from the rod's velocity.

    ``speed_rpm = 60 v / lead`` (one screw turn per lead) replaces the column
    :data:`ROD_VELOCITY_COLUMN`; data without it is returned as it is.

    Parameters
    ----------
    df : pandas.DataFrame
        The rows (``rod_velocity_m_s`` [m/s]).
    drive : LinearDrive
        The drive (lead [m]).

    Returns
    -------
    pandas.DataFrame
        A copy with ``speed_rpm`` [rpm] in place of ``rod_velocity_m_s``.

    Raises
    ------
    InputError
        Both ``speed_rpm`` and ``rod_velocity_m_s`` given.

    References
    ----------
    :func:`~oilgap.model.linear.laws.motor_speed`.
    """
    if ROD_VELOCITY_COLUMN not in df.columns:
        return df
    if "speed_rpm" in df.columns:
        raise InputError("columns", "speed_rpm and rod_velocity_m_s", "one of them: the "
                         "motor's speed follows from the rod's (60 v/lead)", "rig data")
    out = df.copy()
    v = out.pop(ROD_VELOCITY_COLUMN)
    out.insert(list(df.columns).index(ROD_VELOCITY_COLUMN), "speed_rpm",
               rad_s_to_rpm(motor_speed(v.astype(float), drive.lead_m)))
    return out
