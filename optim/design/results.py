"""Results of the design NLP: design points, multipliers and the optimum.

:func:`convert_multipliers` converts IPOPT's multipliers of the scaled NLP into
sensitivities of the optimal mean power to each bound in physical units
(Nocedal & Wright [1]).

References
----------
.. [1] J. Nocedal, S. J. Wright, *Numerical Optimization*, 2nd ed., Springer
   2006, sec. 12.8 (multipliers as sensitivities of the optimal value).
.. [2] J. F. Gieras, *Permanent Magnet Motor Technology*, 3rd ed., 2010, A.27-A.28
   (rotor inertia).
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, field, replace
from typing import Any

import numpy as np

from oilgap.model.case import DesignBounds, DesignCase, Motor, RotorStatorClearance, ThermalSpec
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.evaluation import CaseEvaluation, evaluate_case
from oilgap.model.joint_loss import OperatingTemperature, operating_temperature
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.regions import rotor_stator_radii
from oilgap.model.skin_friction import groove_roughness
from oilgap.model.thermal_modes import ThermalMode
from oilgap.model.units import MM_TO_M

from .parameters import DesignParameters
from .variables import ACTIVE_RTOL, VARIABLE_LABELS, VARIABLES

POINT_MEANINGS: dict[str, str] = {
    "delta_mm": "clearance delta = T3 - T2 (magnetic gap)",
    "R_mm": "radius R = T2",
    "L_mm": "length L",
    "T1_mm": "rotor groove bottom",
    "T2_mm": "rotor surface",
    "T3_mm": "stator bore",
    "T4_mm": "stator groove bottom",
    "rotor_groove_depth_mm": "open rotor groove depth",
    "stator_groove_depth_mm": "open stator groove depth",
    "T": "roughness (T4 - T1)/(T3 - T2)",
    "region1_power_W": "rotor-stator clearance",
    "region2_power_W": "bearing annulus",
    "bearing_power_W": "rolling bearing (friction and drag)",
    "mean_power_W": "mean viscous power (smooth C_m)",
    "torque_capability_Nm": "torque capability",
    "airgap_flux_density_T": "air-gap flux density B_g",
    "inertia_kgm2": "rotor inertia",
    "inertia_ratio": "inertia / the case's unfilled rotor",
}
"""What each quantity of :meth:`DesignPoint.to_dict` is, in report order (the one label
table of the optimize reports and the heating comparison)."""


@dataclass(frozen=True, kw_only=True)
class DesignPoint:
    """One region-1 design with everything the optimizer reports (SI).

    ``mean_power_W`` is the NLP's objective: region 1 plus region 2, both with the
    smooth C_m (``case.friction.smooth()``), plus the rolling bearing's friction and
    drag when the case has a ``[bearing]`` (:mod:`oilgap.model.bearing`; constant in
    the design variables, it shifts the total and, under ``bulk``/``full``, the heat balance);
    :meth:`DesignResult.evaluate` gives the exact-Eq.-6 numbers of ``oilgap evaluate``
    (equation numbers of the seed paper, *Modeling and Optimization of Compensating Oil
    Viscous Power for a Deep-Sea Electric Manipulator*).

    Parameters
    ----------
    R_m, delta_m, rotor_groove_depth_m, stator_groove_depth_m, L_m : float
        The design variables (R, delta, d_r, d_s, L) [m].
    T1_m, T2_m, T3_m, T4_m : float
        Region-1 radii [m].
    T : float
        Roughness (T4 - T1)/(T3 - T2) [-].
    region1_power_W, region2_power_W, mean_power_W : float
        Mean viscous power of region 1, region 2 and the total (with the bearing) [W].
    torque_capability_Nm : float
        Torque capability [N m].
    airgap_flux_density_T : float
        Air-gap flux density [T].
    carter_coefficient : float
        Carter coefficient [-].
    inertia_kgm2 : float
        Rotor inertia with the epoxy fill [kg m^2].
    inertia_ratio : float
        Inertia over the reference (the case's unfilled rotor) [-].
    bearing_power_W : float or None
        Mean power of the rolling bearing [W] (part of ``mean_power_W``); None for a
        case without ``[bearing]``.
    """

    R_m: float
    delta_m: float
    rotor_groove_depth_m: float
    stator_groove_depth_m: float
    L_m: float
    T1_m: float
    T2_m: float
    T3_m: float
    T4_m: float
    T: float
    region1_power_W: float
    region2_power_W: float
    mean_power_W: float
    torque_capability_Nm: float
    airgap_flux_density_T: float
    carter_coefficient: float
    inertia_kgm2: float
    inertia_ratio: float
    """Inertia over the reference (the case's unfilled rotor) [-]."""
    bearing_power_W: float | None = None
    """Mean power of the rolling bearing [W] (in ``mean_power_W``); None without one."""

    @property
    def x_mm(self) -> np.ndarray:
        """The NLP vector (R, delta, d_r, d_s, L) [mm]."""
        return np.array([self.R_m, self.delta_m, self.rotor_groove_depth_m,
                         self.stator_groove_depth_m, self.L_m]) / MM_TO_M

    def to_dict(self) -> dict[str, float]:
        """Unit-keyed plain dict for JSON and tables.

        Returns
        -------
        dict
            Powers [W], T [-], lengths [mm] (``*_mm``), torque [N m], flux
            density [T], Carter coefficient [-], inertia [kg m^2] and its ratio [-];
            ``bearing_power_W`` [W] only for a case with a bearing.
        """
        mm = 1.0 / MM_TO_M
        bearing = {} if self.bearing_power_W is None else {
            "bearing_power_W": self.bearing_power_W}
        return {
            "mean_power_W": self.mean_power_W,
            "region1_power_W": self.region1_power_W,
            "region2_power_W": self.region2_power_W,
            **bearing,
            "T": self.T,
            "delta_mm": self.delta_m * mm,
            "R_mm": self.R_m * mm,
            "L_mm": self.L_m * mm,
            "T1_mm": self.T1_m * mm,
            "T2_mm": self.T2_m * mm,
            "T3_mm": self.T3_m * mm,
            "T4_mm": self.T4_m * mm,
            "rotor_groove_depth_mm": self.rotor_groove_depth_m * mm,
            "stator_groove_depth_mm": self.stator_groove_depth_m * mm,
            "torque_capability_Nm": self.torque_capability_Nm,
            "airgap_flux_density_T": self.airgap_flux_density_T,
            "carter_coefficient": self.carter_coefficient,
            "inertia_kgm2": self.inertia_kgm2,
            "inertia_ratio": self.inertia_ratio,
        }


def design_point(x_m: np.ndarray, p1: float, tau: float, J: float, p2: float, motor: Motor,
                 inertia_ref_kgm2: float, bearing_W: float | None = None) -> DesignPoint:
    """The DesignPoint of a design vector whose loss, torque and inertia are known.

    Parameters
    ----------
    x_m : array of 5 floats
        (R, delta, d_r, d_s, L) [m].
    p1 : float
        Region-1 mean power [W].
    tau : float
        Torque capability [N m].
    J : float
        Rotor inertia [kg m^2].
    p2 : float
        Region-2 mean power [W].
    motor : Motor
        The case's motor (flux density and Carter coefficient at ``x_m``).
    inertia_ref_kgm2 : float
        Reference inertia [kg m^2].
    bearing_W : float, optional
        Mean power of the rolling bearing [W] (None: the case has none).

    Returns
    -------
    DesignPoint
        ``mean_power_W = p1 + p2 (+ bearing_W)`` [W].
    """
    R, delta, d_r, d_s, L = (float(v) for v in x_m)
    _, bg, kc = motor_torque(motor, R, delta, L)
    T1, T2, T3, T4 = rotor_stator_radii(R, delta, d_r, d_s)
    total = p1 + p2 if bearing_W is None else p1 + p2 + bearing_W
    return DesignPoint(R_m=R, delta_m=delta, rotor_groove_depth_m=d_r, stator_groove_depth_m=d_s,
                       L_m=L, T1_m=T1, T2_m=T2, T3_m=T3, T4_m=T4,
                       T=float(groove_roughness(T1, T2, T3, T4)), region1_power_W=p1,
                       region2_power_W=p2, mean_power_W=total, torque_capability_Nm=tau,
                       airgap_flux_density_T=float(bg), carter_coefficient=float(kc),
                       inertia_kgm2=J, inertia_ratio=J / inertia_ref_kgm2,
                       bearing_power_W=None if bearing_W is None else float(bearing_W))


@dataclass(frozen=True)
class Multiplier:
    """What a constraint costs: d(optimal mean power)/d(its bound), in physical units.

    ``value`` is the derivative of the optimal mean power [W] with respect to the
    constraint's bound in ``unit`` (e.g. W per N m of required torque, W per mm
    of gap_max, W per % of the reference inertia); it is zero when the constraint
    is inactive. Signs: raising a binding lower bound costs (> 0), raising a
    binding upper bound saves (< 0) [1].

    Parameters
    ----------
    name : str
        Constraint name (``torque_min``, ``inertia_max``, ``gap_max``, ...).
    constraint : str
        The constraint written out, in the units of the JSON output.
    value : float
        Sensitivity [W per ``unit``].
    unit : str
        Unit of ``value``'s denominator (``"W per mm"``, ``"W per N m"``, ...).
    active : bool
        Whether the constraint binds.
    value_si : float
        The same in SI: W per m (bounds), W per N m (torque), W per kg m^2 (inertia).
    """

    name: str
    constraint: str
    value: float
    unit: str
    active: bool
    value_si: float = 0.0
    """The same in SI: W per m (bounds), W per N m (torque), W per kg m^2 (inertia)."""

    def to_dict(self) -> dict[str, Any]:
        """Plain dict for JSON.

        Returns
        -------
        dict
            The fields; ``value`` [W per ``unit``], ``value_si`` [W per SI unit].
        """
        return asdict(self)


def _bound_multipliers(params: DesignParameters, x_m: tuple, lam_x: list, p1: float,
                       out: dict[str, Multiplier], active: list[str]) -> None:
    """Bound multipliers [W per m] into ``out``; names of the active bounds into ``active``."""
    lo, hi = params.lower_m, params.upper_m
    for i, v in enumerate(VARIABLES):
        key, stem, _ = VARIABLE_LABELS[v]
        scale = max(hi[i] - lo[i], abs(hi[i]), 1e-6)
        per = x_m[i] if v in ("R", "delta", "L") else MM_TO_M  # dx per unit of y
        sens_si = -lam_x[i] * p1 / per if per > 0 else 0.0  # W per m
        if hi[i] == lo[i]:
            name = f"{stem}_fixed"
            out[name] = Multiplier(name, f"{key} = {lo[i] / MM_TO_M:.6g}",
                                   sens_si * MM_TO_M, "W per mm", True, sens_si)
            active.append(name)
            continue
        at_lo = abs(x_m[i] - lo[i]) <= ACTIVE_RTOL * scale
        at_hi = abs(x_m[i] - hi[i]) <= ACTIVE_RTOL * scale
        for side, bnd, is_act, rel in (("min", lo[i], at_lo, ">="),
                                       ("max", hi[i], at_hi, "<=")):
            name = f"{stem}_{side}"
            val = sens_si if is_act else 0.0
            out[name] = Multiplier(name, f"{key} {rel} {bnd / MM_TO_M:.6g}",
                                   val * MM_TO_M, "W per mm", bool(is_act), val)
            if is_act:
                active.append(name)


def convert_multipliers(params: DesignParameters, opt: DesignPoint, lam_x: np.ndarray,
                        lam_g: np.ndarray, objective_W: float | None = None
                        ) -> tuple[dict[str, Multiplier], tuple[str, ...]]:
    """Sensitivities d(P*)/d(bound), converted to physical units [1].

    IPOPT minimizes F = ln P1 in y; at the optimum dF*/d(bound of y_i) = -lam_x[i]
    and dF*/d(bound of g_k) = -lam_g[k] (CasADi's sign convention). With
    dP* = P1* dF*, y_i = ln(x_i/mm) (dy = dx/x) or x_i/mm, g_0 = ln(tau/tau_ref)
    and g_1 = ln(J/J_ref) this gives W per m of a bound, W per N m of tau_min
    and W per kg m^2 of J_max.

    Parameters
    ----------
    params : DesignParameters
        The solve's bounds [m] and limits (``torque_min_Nm`` [N m],
        ``inertia_max_kgm2`` [kg m^2]).
    opt : DesignPoint
        The optimum.
    lam_x : ndarray of 5 floats
        IPOPT's bound multipliers of the scaled variables y [-].
    lam_g : ndarray of 2 floats
        IPOPT's multipliers of g = (ln tau/tau_ref, ln J/J_ref) [-].
    objective_W : float, optional
        The power whose logarithm IPOPT minimized [W] (default: P1, the isothermal
        NLP's; the thermal NLP minimizes ln(P1 + P2)).

    Returns
    -------
    multipliers : dict of name -> Multiplier
        Every bound (``*_min``, ``*_max``, or ``*_fixed``), ``torque_min`` and
        ``inertia_max``; zero if inactive.
    active : tuple of str
        Names of the active constraints, the torque and inertia ones first.
    """
    out: dict[str, Multiplier] = {}
    active: list[str] = []
    x_m = (opt.R_m, opt.delta_m, opt.rotor_groove_depth_m, opt.stator_groove_depth_m,
           opt.L_m)
    lam_x, lam_g = lam_x.tolist(), lam_g.tolist()
    p1 = opt.region1_power_W if objective_W is None else float(objective_W)
    _bound_multipliers(params, x_m, lam_x, p1, out, active)
    tmin, jmax = params.torque_min_Nm, params.inertia_max_kgm2
    t_act = opt.torque_capability_Nm - tmin <= ACTIVE_RTOL * tmin
    t_si = float(-lam_g[0] * p1 / tmin) if t_act else 0.0
    out["torque_min"] = Multiplier("torque_min", f"torque_capability_Nm >= {tmin:.6g}",
                                   t_si, "W per N m", bool(t_act), t_si)
    j_act = jmax - opt.inertia_kgm2 <= ACTIVE_RTOL * jmax
    j_si = float(-lam_g[1] * p1 / jmax) if j_act else 0.0
    out["inertia_max"] = Multiplier(
        "inertia_max", f"inertia_kgm2 <= {jmax:.6g} ({params.inertia_max_ratio:.6g} x "
        f"{params.inertia_ref_kgm2:.6g})", j_si * 0.01 * params.inertia_ref_kgm2,
        "W per % of the reference inertia", bool(j_act), j_si)
    head = [n for n, a in (("torque_min", t_act), ("inertia_max", j_act)) if a]
    return out, tuple(head + active)


@dataclass(frozen=True, eq=False, kw_only=True)
class DesignResult:
    """An optimum of the design NLP (solver failures raise instead).

    Parameters
    ----------
    status : str
        IPOPT return status.
    success : bool
        True (failures raise SolverError / InfeasibleError).
    iterations : int
        IPOPT iterations.
    solve_time_s : float
        Wall time of the IPOPT call [s].
    initial, optimal : DesignPoint
        The start point (the case's design unless ``x0`` was given) and the optimum.
    active_constraints : tuple of str
        Names of the active constraints and bounds.
    multipliers : mapping of name -> Multiplier
        Every constraint and bound, zero if inactive.
    parameters : DesignParameters
        The parameters of the solve.
    case : DesignCase
        The case solved (with the oil/operating overrides applied).
    machined_rotor_groove_m, machined_stator_groove_m : float
        Groove depths as machined, d_r0 and d_s0 [m].
    starts : int
        Number of start points tried (the best optimum is returned).
    """

    status: str
    success: bool
    iterations: int
    solve_time_s: float
    initial: DesignPoint
    optimal: DesignPoint
    active_constraints: tuple[str, ...]
    multipliers: Mapping[str, Multiplier]
    parameters: DesignParameters
    case: DesignCase = field(repr=False)
    machined_rotor_groove_m: float = field(repr=False, default=0.0)
    machined_stator_groove_m: float = field(repr=False, default=0.0)
    starts: int = 1
    """Number of start points tried (the best optimum is returned)."""
    _raw: Mapping[str, Any] = field(repr=False, default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        """Plain-dict form (the ``--json`` output of ``oilgap optimize``).

        Returns
        -------
        dict
            Status, iterations, starts, ``solve_time_s`` [s], the case's name,
            the parameters, both design points and the multipliers, each as
            their ``to_dict`` (units in the keys).
        """
        return {
            "status": self.status,
            "success": self.success,
            "iterations": self.iterations,
            "starts": self.starts,
            "solve_time_s": self.solve_time_s,
            "case": self.case.name,
            "parameters": self.parameters.to_dict(),
            "initial": self.initial.to_dict(),
            "optimal": self.optimal.to_dict(),
            "active_constraints": list(self.active_constraints),
            "multipliers": {k: v.to_dict() for k, v in self.multipliers.items()},
        }

    def to_case(self, name: str | None = None) -> DesignCase:
        """The optimal design as a DesignCase (``write_case_toml`` writes it).

        Region 1 takes the optimal T1..T4 and L with the machined groove bottoms
        ``T1_unfilled = R - d_r0``, ``T4_unfilled = T3 + d_s0``; the bounds are
        those of this solve, with ``torque_min_Nm`` the torque required here and
        ``inertia_max_ratio`` rescaled so that it gives the same absolute inertia
        limit for the new rotor (Gieras [2]). Re-optimizing the returned case
        therefore poses the same problem. If nu/rho were given directly (no oil),
        the case keeps its oil and a warning says so.

        Parameters
        ----------
        name : str, optional
            Name of the new case (default: the case's, ``", optimized"``).

        Returns
        -------
        DesignCase
        """
        if self.parameters.raw_oil_state:
            warnings.warn("the solve used nu/rho given directly; the case written keeps the "
                          f"oil {self.case.oil.name} at its operating condition",
                          OilgapWarning, stacklevel=2)
        o = self.optimal
        r1 = RotorStatorClearance(o.T1_m, o.T2_m, o.T3_m, o.T4_m, o.L_m,
                                  T1_unfilled=o.R_m - self.machined_rotor_groove_m,
                                  T4_unfilled=o.T3_m + self.machined_stator_groove_m)
        motor = self.case.motor
        j_ref_new = float(rotor_inertia(motor, o.R_m, self.machined_rotor_groove_m, o.L_m,
                                        self.machined_rotor_groove_m))
        lo, hi = self.parameters.lower_m, self.parameters.upper_m
        bounds = DesignBounds(lo[1], hi[1], lo[0], hi[0], lo[4], hi[4],
                              inertia_max_ratio=self.parameters.inertia_max_kgm2 / j_ref_new,
                              torque_min_Nm=self.parameters.torque_min_Nm)
        return replace(self.case, name=name or f"{self.case.name}, optimized",
                       region1=r1, bounds=bounds)

    def evaluate(self) -> tuple[CaseEvaluation, CaseEvaluation]:
        """The initial and the optimal design evaluated with the case's own (exact) C_m,
        isothermal (thermal mode ``none``, the seed's model).

        Returns
        -------
        initial, optimal : CaseEvaluation
            What ``oilgap evaluate --thermal none`` prints for the two designs (powers [W]).
        """
        i = self.initial
        start = self.case.with_region1(
            T1=i.T1_m, T2=i.T2_m, T3=i.T3_m, T4=i.T4_m, length=i.L_m,
            T1_unfilled=i.R_m - self.machined_rotor_groove_m,
            T4_unfilled=i.T3_m + self.machined_stator_groove_m)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OilgapWarning)
            opt = self.to_case()
        none = ThermalMode.NONE  # resolved: valid for every case
        return evaluate_case(start, thermal=none), evaluate_case(opt, thermal=none)


@dataclass(frozen=True, eq=False, kw_only=True)
class ThermalDesignResult(DesignResult):
    """An optimum of the design NLP under a thermal mode (``bulk``, ``film`` or ``full``).

    The powers of ``initial`` and ``optimal`` are the heated ones (film factor at
    their oil temperature, smooth C_m). Fields beyond :class:`DesignResult`:

    Parameters
    ----------
    thermal_mode : str
        ``"bulk"``, ``"film"`` or ``"full"``.
    initial_oil_temp_C : float
        Bulk oil temperature of the start design [degC] (its own balance under bulk/full).
    oil_temp_C : float
        Bulk oil temperature at the optimum [degC] (the balance's under bulk/full).
    sea_temp_C : float or None
        Sea temperature [degC] (bulk/full), else None.
    thermal : ThermalSpec or None
        The balance solved (bulk/full), else None.
    sea_temp_cost_W_per_K : float or None
        ``dP*/dT_sea`` from the balance's multiplier [W/K] (bulk/full), else None.
    oil_temp_cost_W_per_K : float or None
        ``dP*/dT_oil`` at a fixed oil temperature from its bound multiplier [W/K]
        (film), else None.
    balance_residual_K : float or None
        ``T - T_sea - R (P + Q)`` at IPOPT's last iterate [K] (bulk/full), else None.
    """

    thermal_mode: str = "film"
    initial_oil_temp_C: float = float("nan")
    oil_temp_C: float = float("nan")
    sea_temp_C: float | None = None
    thermal: ThermalSpec | None = field(default=None, repr=False)
    sea_temp_cost_W_per_K: float | None = None
    oil_temp_cost_W_per_K: float | None = None
    balance_residual_K: float | None = None

    def to_dict(self) -> dict[str, Any]:
        """Plain dict for JSON: :meth:`DesignResult.to_dict` and the thermal fields.

        Returns
        -------
        dict
            Adds ``thermal_mode``, ``initial_oil_temp_C`` and ``oil_temp_C`` [degC],
            ``sea_temp_C`` [degC], ``sea_temp_cost_W_per_K`` and
            ``oil_temp_cost_W_per_K`` [W/K], ``balance_residual_K`` [K] (None where
            the mode has none).
        """
        d = super().to_dict()
        d.update(thermal_mode=self.thermal_mode, initial_oil_temp_C=self.initial_oil_temp_C,
                 oil_temp_C=self.oil_temp_C, sea_temp_C=self.sea_temp_C,
                 sea_temp_cost_W_per_K=self.sea_temp_cost_W_per_K,
                 oil_temp_cost_W_per_K=self.oil_temp_cost_W_per_K,
                 balance_residual_K=self.balance_residual_K)
        return d

    def operating(self) -> tuple[OperatingTemperature, OperatingTemperature]:
        """The initial and optimal designs under the mode with the case's own (exact) C_m.

        Returns
        -------
        initial, optimal : OperatingTemperature
            :func:`~oilgap.model.joint_loss.operating_temperature` of each design
            (oil temperature [degC], mean loss [W]), as ``oilgap evaluate`` gives it.
        """
        start, opt = self.design_cases()
        return (operating_temperature(start, self.thermal_mode),
                operating_temperature(opt, self.thermal_mode))

    def design_cases(self) -> tuple[DesignCase, DesignCase]:
        """The initial and optimal designs as cases, with the balance solved.

        Returns
        -------
        initial, optimal : DesignCase
            The case with each design's region 1 (and ``thermal``: the solve's balance).
        """
        i = self.initial
        base = self.case if self.thermal is None else replace(self.case, thermal=self.thermal)
        start = base.with_region1(
            T1=i.T1_m, T2=i.T2_m, T3=i.T3_m, T4=i.T4_m, length=i.L_m,
            T1_unfilled=i.R_m - self.machined_rotor_groove_m,
            T4_unfilled=i.T3_m + self.machined_stator_groove_m)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OilgapWarning)
            opt = replace(self.to_case(), thermal=base.thermal)
        return start, opt


def start_point(x0: DesignResult | DesignPoint | Sequence[float] | None, default_m: np.ndarray,
                warm_start_duals: bool = True
                ) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray] | None]:
    """Start point and multipliers of a solve.

    Parameters
    ----------
    x0 : DesignResult, DesignPoint, sequence of (R, delta, d_r, d_s, L) [m], or None
        A previous optimum (its design and multipliers), a design point or a vector.
    default_m : ndarray of 5 floats
        The start when ``x0`` is None (the case's design) [m].
    warm_start_duals : bool
        Take the multipliers of a DesignResult ``x0``.

    Returns
    -------
    x_start : ndarray of 5 floats
        The start [m] (not yet clamped to the bounds).
    lam : (lam_x, lam_g) or None
        The multipliers to warm-start with.

    Raises
    ------
    InputError
        ``x0`` not 5 finite values.
    """
    lam = None
    if x0 is None:
        x_start = np.array(default_m, dtype=float)
    elif isinstance(x0, DesignResult):
        x_start = x0.optimal.x_mm * MM_TO_M
        if warm_start_duals and x0._raw:
            lam = (x0._raw["lam_x"], x0._raw["lam_g"])
    elif isinstance(x0, DesignPoint):
        x_start = x0.x_mm * MM_TO_M
    else:
        x_start = np.asarray(x0, dtype=float).ravel()
        if x_start.shape != (5,) or not np.all(np.isfinite(x_start)):
            raise InputError("x0", list(x_start), "needs 5 finite values (R, delta, d_r, "
                             "d_s, L) [m]", "optimize")
    return x_start, lam


__all__ = ["POINT_MEANINGS", "DesignPoint", "DesignResult", "Multiplier", "ThermalDesignResult",
           "convert_multipliers", "design_point", "start_point"]
