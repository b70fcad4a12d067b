"""The design NLP of a linear actuator: lead, guide clearance, passage diameter and the
motor's clearance of least mean loss under force, speed and passage-velocity limits.

Decision variables (IPOPT sees their logarithms in mm, groove depths in mm)::

    x = (lead, c_rod, d_pass, delta, d_r, d_s)

with the motor's radius R and length L as the case gives them. The objective is the
joint's mean loss over the rod's duty cycle, :func:`~oilgap.model.joint_loss.joint_mean_power`
(the one composition: region 1 built from (R, delta, d_r, d_s, L), region 2, the bearing,
the screw, the rod guide and the passages) with the motor's speeds scaled by
``lead0/lead`` (the same rod cycle at another lead) and the smooth C_m. Under ``bulk`` and
``full`` the oil temperature is a variable with the balance ``T = T_sea + R_th (P + Q)`` an
equality (every element's heat in it); under ``film``/``full`` the film factor applies to
the motor gap, as in the evaluation.

Constraints: the rod force ``2 pi eta T_mag/lead >= F_req`` (``[drive] required_force_N``;
T_mag the motor's torque capability, :func:`~oilgap.model.motor.motor_torque`), the
motor's speed ``2 pi v_max/lead <= omega_max`` (``max_motor_speed_rpm``), the passage
velocity ``A_rod v_max/(n pi d^2/4) <= V_max`` (``[passages] max_velocity_m_s``). The
compensator's volume (displaced volume plus thermal expansion) does not depend on these
variables: it is checked before the solve (InfeasibleError). A drive without passages is
refused as a dashpot (InputError, with its force).

References
----------
.. [1] docs/linear-joint.md (the elements and constraints).
.. [2] A. Wächter, L. T. Biegler, Math. Program. 106:25-57, 2006 (IPOPT).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import casadi as ca
import numpy as np

from oilgap.model.case import DesignCase
from oilgap.model.errors import InfeasibleError, InputError
from oilgap.model.joint_loss import joint_mean_power, operating_temperature, uses_balance
from oilgap.model.linear.laws import rod_force_capability
from oilgap.model.linear.report import compensator_volume, peak_rod_velocity, refuse_dashpot
from oilgap.model.motor import motor_torque
from oilgap.model.regions import joint_regions, rotor_stator_region
from oilgap.model.units import MM_TO_M

from .session import SolverSession, solver_failure
from .variables import SUCCESS_STATUSES

LINEAR_VARIABLES = ("lead_mm", "guide_clearance_mm", "passage_diameter_mm", "delta_mm",
                    "rotor_groove_depth_mm", "stator_groove_depth_mm")
"""The NLP's variables, in order, by their output names [mm]."""
_LOG = np.array([True, True, True, True, False, False])
TEMP_SCALE_K = 10.0
"""The NLP's temperature variable is ``T/10`` [degC]."""


@dataclass(frozen=True, kw_only=True)
class LinearDesign:
    """A solved linear design.

    Attributes
    ----------
    x_mm : ndarray
        The optimum, :data:`LINEAR_VARIABLES` [mm].
    x0_mm : ndarray
        The case's design [mm].
    lower_mm, upper_mm : ndarray
        The bounds [mm].
    mean_power_W : float
        The NLP's objective at the optimum [W] (smooth C_m, at its oil state).
    oil_temp_C : float
        The NLP's oil temperature [degC].
    constraints : dict
        Name -> (value, limit, unit) at the optimum.
    nlp_mode : str
        The thermal mode the NLP was solved under.
    iterations : int
        IPOPT iterations.
    """

    x_mm: np.ndarray
    x0_mm: np.ndarray
    lower_mm: np.ndarray
    upper_mm: np.ndarray
    mean_power_W: float
    oil_temp_C: float
    constraints: dict
    nlp_mode: str
    iterations: int


def linear_design_vector(case: DesignCase) -> np.ndarray:
    """The case's design :data:`LINEAR_VARIABLES` [mm].

    Parameters
    ----------
    case : DesignCase
        A linear case.

    Returns
    -------
    ndarray
        [mm].
    """
    d, r1 = case.linear, case.region1
    return np.array([d.lead_m, d.guide_clearance_m, d.passage_diameter_m, r1.gap,
                     r1.T2 - r1.T1, r1.T4 - r1.T3]) / MM_TO_M


def linear_bounds(case: DesignCase) -> tuple[np.ndarray, np.ndarray]:
    """Bounds of :data:`LINEAR_VARIABLES` [mm]: the drive's design bounds, the case's
    gap bounds, the groove depths from 0 to as machined (the epoxy fill only raises them).

    Parameters
    ----------
    case : DesignCase
        A linear case.

    Returns
    -------
    lower, upper : ndarray
        [mm].
    """
    d, b, r1 = case.linear, case.bounds, case.region1
    db = d.design_bounds or tuple((0.5 * v, 2.0 * v) for v in (
        d.lead_m, d.guide_clearance_m, d.passage_diameter_m))
    lo = [db[0][0], db[1][0], db[2][0], b.gap_min, 0.0, 0.0]
    hi = [db[0][1], db[1][1], db[2][1], b.gap_max, r1.T2 - r1.T1_unfilled,
          r1.T4_unfilled - r1.T3]
    return np.array(lo) / MM_TO_M, np.array(hi) / MM_TO_M


def _to_y(x_mm):
    return np.where(_LOG, np.log(np.maximum(x_mm, 1e-300)), x_mm)


def check_compensator(case: DesignCase) -> tuple[float, float] | None:
    """The compensator's need and capacity [m^3], refused when the need is larger.

    Parameters
    ----------
    case : DesignCase
        A linear case.

    Returns
    -------
    tuple of float or None
        (volume needed, capacity) [m^3]; None without ``[compensator]``.

    Raises
    ------
    InfeasibleError
        The displaced volume plus the oil's expansion exceeds the capacity.
    """
    c = case.linear.compensator
    if c is None:
        return None
    need = compensator_volume(case)
    if need > c.capacity_m3:
        swept = case.linear.rod_area_m2 * case.linear.stroke_m
        raise InfeasibleError(f"the compensator takes {c.capacity_m3 * 1e6:.4g} mL but the rod "
                              f"displaces {swept * 1e6:.4g} mL and the oil expands by "
                              f"{(need - swept) * 1e6:.4g} mL over {c.temp_min_C:g}-"
                              f"{c.temp_max_C:g} degC: no lead, clearance or passage changes "
                              "that ([compensator] capacity_mL)", status="compensator")
    return need, c.capacity_m3


def design_expressions(case: DesignCase, x, temp_C, mode: str):
    """The NLP's loss and constraint quantities of a design.

    Parameters
    ----------
    case : DesignCase
        A linear case (its friction law as the NLP uses it).
    x : sequence of 6 (float or CasADi symbol)
        lead, guide clearance, passage diameter, motor gap, rotor and stator groove
        depths [m].
    temp_C : float or CasADi symbol
        Bulk oil temperature [degC].
    mode : str
        ``"none"`` or ``"bulk"``.

    Returns
    -------
    tuple
        Mean loss [W] (:func:`~oilgap.model.joint_loss.joint_mean_power`), rod force
        capability [N], motor speed at the peak rod velocity [rad/s], peak passage
        velocity [m/s].
    """
    d, r1 = case.linear, case.region1
    lead, c, dp, delta, d_r, d_s = x
    region1 = rotor_stator_region(r1.T2, delta, d_r, d_s, r1.length)
    regions = (region1, *joint_regions(case)[1:])
    loss = joint_mean_power(case, temp_C, mode, None, regions, True,
                            speed_scale=d.lead_m / lead,
                            design={"lead_m": lead, "guide_clearance_m": c,
                                    "passage_diameter_m": dp})
    tau = motor_torque(case.motor, r1.T2, delta, r1.length)[0]
    force = rod_force_capability(tau, lead, d.screw_efficiency)
    v_max = peak_rod_velocity(case)
    speed = 2.0 * math.pi * v_max / lead
    vel = d.rod_area_m2 * v_max / (max(d.passage_count, 1) * 0.25 * math.pi * dp**2)
    return loss, force, speed, vel


def constraint_rows(d, force, speed, vel) -> tuple[list, list]:
    """The NLP's inequality rows ``g >= 0`` (logs of ratios) and their report entries.

    Parameters
    ----------
    d : LinearDrive
        The drive (limits).
    force, speed, vel : CasADi expression
        Rod force [N], motor speed at the peak rod velocity [rad/s], passage velocity
        [m/s] (:func:`design_expressions`).

    Returns
    -------
    g : list
        Rows, each >= 0 when its constraint holds.
    names : list
        (name, expression, limit, unit, sense) of each row.
    """
    g, names = [], []
    if d.required_force_N is not None:
        g.append(ca.log(force / d.required_force_N))
        names.append(("rod force", force, d.required_force_N, "N", ">="))
    if d.max_motor_speed_rad_s is not None:
        g.append(ca.log(d.max_motor_speed_rad_s / speed))
        names.append(("motor speed at peak rod velocity", speed, d.max_motor_speed_rad_s,
                      "rad/s", "<="))
    g.append(ca.log(d.passage_velocity_limit_m_s / vel))
    names.append(("passage velocity", vel, d.passage_velocity_limit_m_s, "m/s", "<="))
    return g, names


def solve_linear_design(case: DesignCase, mode: str = "none", verbose: bool = False,
                        lead_mm: float | None = None) -> LinearDesign:
    """Solve the linear design NLP of a case (module docstring).

    Parameters
    ----------
    case : DesignCase
        A linear case (``case.linear``).
    mode : str
        Thermal mode (``film``/``full``: the film factor on the motor gap, at the bulk
        temperature of the balance under ``full``).
    verbose : bool
        Print IPOPT's iterations.
    lead_mm : float, optional
        Hold the lead at this value [mm] (the lead-loss front); default: a variable.

    Returns
    -------
    LinearDesign
        The optimum [mm] and its constraints.

    Raises
    ------
    InputError
        Not a linear case, or a drive without passages (a dashpot, with its force).
    InfeasibleError
        The compensator too small, or IPOPT finds the constraints infeasible.
    SolverError
        IPOPT did not converge.

    References
    ----------
    IPOPT [2]_; the elements [1]_.
    """
    if case.linear is None:
        raise InputError("drive.kind", "rotary", '"linear" for this design problem', "optimize")
    refuse_dashpot(case)
    comp = check_compensator(case)
    nlp_mode = str(mode)
    case_s = replace(case, friction=case.friction.smooth())
    d = case.linear
    y = ca.SX.sym("y", 6)
    x = [ca.exp(y[i]) * MM_TO_M if _LOG[i] else y[i] * MM_TO_M for i in range(6)]
    q = ca.SX.sym("t") if uses_balance(nlp_mode) else None
    temp = q * TEMP_SCALE_K if q is not None else float(case.operating.oil_temp_C)
    loss, force, speed, vel = design_expressions(case_s, x, temp, nlp_mode)
    g, names = constraint_rows(d, force, speed, vel)
    lbg = [0.0] * len(g)
    ubg = [ca.inf] * len(g)
    lo, hi = linear_bounds(case)
    if lead_mm is not None:
        lo[0] = hi[0] = float(lead_mm)
    x0 = np.clip(linear_design_vector(case), lo, hi)
    z, lbx, ubx, z0 = y, _to_y(lo), _to_y(hi), _to_y(x0)
    if q is not None:
        th = case.thermal
        g.append(q * TEMP_SCALE_K - th.sea_temp_C - th.resistance_K_W
                  * (loss + th.other_heat_W))
        lbg.append(0.0)
        ubg.append(0.0)
        z = ca.vertcat(y, q)
        t0 = operating_temperature(case, nlp_mode).oil_temp_C / TEMP_SCALE_K
        lbx, ubx = np.append(lbx, -6.0), np.append(ubx, 30.0)
        z0 = np.append(z0, t0)
    session = SolverSession("oilgap_linear_design",
                            {"x": z, "p": ca.SX.sym("p", 0), "f": ca.log(loss),
                             "g": ca.vertcat(*g)}, verbose)
    out = session.solve(z0, [], lbx, ubx, lbg, ubg)
    xs = np.clip(np.where(_LOG, np.exp(out.x[:6]), out.x[:6]), lo, hi)  # IPOPT's 1e-8 slack
    last = dict(zip(LINEAR_VARIABLES, xs, strict=True))
    if out.status == "Infeasible_Problem_Detected":
        raise InfeasibleError(f"no design meets the constraints ({', '.join(n[0] for n in names)}"
                              f") within the bounds; last iterate "
                              + ", ".join(f"{k} = {v:.4g}" for k, v in last.items()),
                              status=out.status, last_iterate=last)
    if out.status not in SUCCESS_STATUSES or not np.all(np.isfinite(out.x)):
        raise solver_failure(out.status, out.iterations, last, "the linear design NLP")
    return _design_result(case, z, out, xs, lo, hi, loss, names, comp, q is not None,
                          nlp_mode)


def _design_result(case, z, out, xs, lo, hi, loss, names, comp, balance: bool,
                   nlp_mode: str) -> LinearDesign:
    """The :class:`LinearDesign` of a solve: the loss and constraints at the optimum."""
    parts = ca.Function("parts", [z], [ca.vertcat(loss, *[n[1] for n in names])])
    vals = np.asarray(parts(out.x)).ravel()
    rpm = 30.0 / math.pi  # rad/s -> rpm at the edge
    cons = {n[0]: ((float(v) * rpm, float(n[2]) * rpm, "rpm", n[4]) if n[3] == "rad/s" else
                   (float(v), float(n[2]), n[3], n[4]))
            for n, v in zip(names, vals[1:], strict=True)}
    if comp is not None:
        cons["compensator volume"] = (comp[0], comp[1], "m^3", "<=")
    return LinearDesign(x_mm=xs, x0_mm=linear_design_vector(case), lower_mm=lo, upper_mm=hi,
                        mean_power_W=float(vals[0]),
                        oil_temp_C=float(out.x[6] * TEMP_SCALE_K) if balance
                        else float(case.operating.oil_temp_C),
                        constraints=cons, nlp_mode=nlp_mode, iterations=out.iterations)


def linear_design_case(case: DesignCase, x_mm) -> DesignCase:
    """The case with a linear design applied (lead, clearances, passage, motor gap).

    The motor's duty cycle follows the lead (the rod's cycle is the same): its speeds
    are scaled by ``lead0/lead``.

    Parameters
    ----------
    case : DesignCase
        A linear case.
    x_mm : sequence of 6 float
        :data:`LINEAR_VARIABLES` [mm].

    Returns
    -------
    DesignCase
        The design, validated.
    """
    lead, c, dp, delta, d_r, d_s = (float(v) * MM_TO_M for v in x_mm)
    d, r1 = case.linear, case.region1
    cyc = case.duty_cycle
    duty = replace(cyc, omega_rad_s=cyc.omega_rad_s * (d.lead_m / lead),
                   description=cyc.description.split(" -> ")[0]
                   + f" -> motor at lead {lead / MM_TO_M:.4g} mm")
    T3 = r1.T2 + delta
    region1 = replace(r1, T1=r1.T2 - d_r, T3=T3, T4=T3 + d_s,
                      T4_unfilled=max(r1.T4_unfilled, T3 + d_s))
    drive = replace(d, lead_m=lead, guide_clearance_m=c, passage_diameter_m=dp)
    return replace(case, region1=region1, linear=drive, duty_cycle=duty)
