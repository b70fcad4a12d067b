"""The clearance geometry of region 1 as a CasADi/IPOPT nonlinear program.

Decision variables (non-redundant)::

    x = (R, delta, d_r, d_s, L)
    R      = T2        rotor outer radius (region 1 radius)
    delta  = T3 - T2   clearance, also the magnetic gap g
    d_r    = T2 - T1   rotor groove depth left open by the epoxy fill
    d_s    = T4 - T3   stator groove depth left open by the epoxy fill
    L                  clearance (stack) length

so that T1 = R - d_r, T3 = R + delta, T4 = R + delta + d_s and
T = (T4 - T1)/(T3 - T2) = 1 + (d_r + d_s)/delta >= 1 by construction (Eq. 9).

Problem::

    min   P1(x; nu, rho) + P2(nu, rho)          mean viscous power over the duty cycle [W]
    s.t.  tau(R, delta, L)      >= tau_min      torque capability [N m]
          J(R, d_r, L)          <= J_max        rotor inertia with the epoxy fill [kg m^2]
          R_min <= R <= R_max,  delta_min <= delta <= delta_max,  L_min <= L <= L_max
          0 <= d_r <= d_r0,     0 <= d_s <= d_s0  (filling only makes grooves shallower)

with ``P1 = sum_i w_i clearance_power(omega_i, nu, rho, R, delta, L, law_smooth, T)``
over the exact speed distribution (omega_i, w_i) of the duty cycle
(:meth:`DutyCycle.speed_distribution`), the smooth C_m (no ``if_else`` in the
NLP), and P2 the (constant) bearing-annulus power. The torque capability and
inertia are :mod:`oilgap.model.motor` (Carter coefficient with slot pitch
2 pi T3 / Q_s, B_g, tau = 2 pi R^2 L k_w B_g A / sqrt 2, grooved rotor with
T1_unfilled = R - d_r0).

Scaling: IPOPT sees y = (ln R/mm, ln delta/mm, d_r/mm, d_s/mm, ln L/mm), the
objective ln P1 and the constraints ln(tau/tau_ref) >= ln(tau_min/tau_ref),
ln(J/J_ref) <= ln(J_max/J_ref) (tau_ref, J_ref: the case's motor and unfilled
rotor). All are O(1), and the laminar loss, a near-monomial in R, delta, L, is
near-linear in the logarithms, which saves IPOPT iterations. The same optimum,
the multipliers are converted back to d(P*)/d(bound) in physical units.

The NLP is built once per case (:class:`DesignProblem`); the oil state
(nu, rho), tau_min, J_max and every bound are parameters of each
:meth:`DesignProblem.solve` (``p`` and the bound vectors of ``nlpsol``), so
studies re-solve it without rebuilding.

References
----------
.. [1] Seed paper, Eqs. 4-10 (``../shared/reference/seed-paper.md``).
.. [2] J. F. Gieras, *Permanent Magnet Motor Technology*, 3rd ed., 2010, A.27-A.28.
.. [3] A. Wächter, L. T. Biegler, "On the implementation of an interior-point
   filter line-search algorithm for large-scale nonlinear programming",
   Math. Program. 106:25-57, 2006 (IPOPT).
.. [4] J. Nocedal, S. J. Wright, *Numerical Optimization*, 2nd ed., Springer
   2006, sec. 12.8 (multipliers as sensitivities of the optimal value).
"""

from __future__ import annotations

import time
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, field, replace
from typing import Any

import casadi as ca
import numpy as np

from oilgap.model.case import DesignBounds, DesignCase, OperatingPoint, RotorStatorClearance
from oilgap.model.errors import (
    InfeasibleError,
    InputError,
    OilgapWarning,
    SolverError,
    check_finite,
    check_positive,
)
from oilgap.model.evaluation import CaseEvaluation, oil_state
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.oils import Oil
from oilgap.model.regions import (
    Region,
    region_mean_power,
    rotor_stator_radii,
    rotor_stator_region,
)
from oilgap.model.skin_friction import FrictionLaw, groove_roughness
from oilgap.model.units import MM_TO_M, m2_s_to_cst

VARIABLES = ("R", "delta", "d_r", "d_s", "L")
"""Decision variables, in the order of the NLP vector."""

VARIABLE_LABELS = {
    "R": ("R_mm", "radius", "rotor outer radius R = T2"),
    "delta": ("delta_mm", "gap", "clearance delta = T3 - T2 (= magnetic gap)"),
    "d_r": ("rotor_groove_depth_mm", "rotor_groove_depth", "rotor groove depth T2 - T1"),
    "d_s": ("stator_groove_depth_mm", "stator_groove_depth", "stator groove depth T4 - T3"),
    "L": ("L_mm", "length", "clearance length L"),
}
"""variable -> (JSON key, bound name stem, description)."""

SUCCESS_STATUSES = ("Solve_Succeeded", "Solved_To_Acceptable_Level")
"""IPOPT return statuses accepted as an optimum."""

IPOPT_TOL = 1e-9
"""IPOPT convergence tolerance on the NLP error (objective ln P1, variables ln mm or mm)."""

ACTIVE_RTOL = 1e-6
"""A bound or constraint is active when its slack is below this fraction of its scale."""

_QUIET = {"ipopt.print_level": 0, "ipopt.sb": "yes", "print_time": False}
_SOLVER_OPTIONS = {"ipopt.tol": IPOPT_TOL, "ipopt.mu_init": 1e-3,
                   "ipopt.barrier_tol_factor": 100, "ipopt.nlp_scaling_method": "none",
                   "ipopt.constr_mult_init_max": 0.0, "calc_lam_p": False,
                   "error_on_fail": False, "expand": True}
"""nlpsol options (measured on the seed and 120 random cases: 8-9 IPOPT iterations). The
NLP is scaled by construction, so IPOPT's own gradient scaling is off; the constraint
multipliers start at 0 (no least-squares estimate: one factorization less)."""
_WARM_OPTIONS = {"ipopt.warm_start_init_point": "yes", "ipopt.warm_start_bound_push": 1e-9,
                 "ipopt.warm_start_bound_frac": 1e-9, "ipopt.warm_start_slack_bound_push": 1e-9,
                 "ipopt.warm_start_slack_bound_frac": 1e-9,
                 "ipopt.warm_start_mult_bound_push": 1e-9, "ipopt.mu_init": 1e-6}
_LOG = np.array([True, True, False, False, True])
"""Which NLP variables are logarithms of the length in mm."""


def _to_nlp(x_m: np.ndarray) -> np.ndarray:
    """Design vector [m] -> NLP vector y (ln mm for R, delta, L; mm for d_r, d_s)."""
    y = np.array(x_m, dtype=float) / MM_TO_M
    y[_LOG] = np.log(y[_LOG])
    return y


def _from_nlp(y: np.ndarray) -> np.ndarray:
    """NLP vector y -> design vector [m]."""
    x = np.array(y, dtype=float)
    x[_LOG] = np.exp(x[_LOG])
    return x * MM_TO_M


# --------------------------------------------------------------------------- design functions


def region1_mean_power(R_m, delta_m, rotor_groove_m, stator_groove_m, L_m, nu_m2_s,
                       rho_kg_m3, nodes_rad_s, weights, law: FrictionLaw) -> Any:
    """Mean viscous power [W] of region 1 over a speed distribution (seed Eqs. 4-10).

    :func:`~oilgap.model.regions.region_mean_power` of the region built from the
    design variables (T from Eq. 9). For CasADi arguments pass ``nodes_rad_s``
    as a ``casadi.DM``.
    """
    region = rotor_stator_region(R_m, delta_m, rotor_groove_m, stator_groove_m, L_m)
    return region_mean_power(region, nodes_rad_s, weights, nu_m2_s, rho_kg_m3, law)


# --------------------------------------------------------------------------- results


@dataclass(frozen=True)
class DesignPoint:
    """One region-1 design with everything the optimizer reports (SI).

    ``mean_power_W`` is the NLP's objective: region 1 plus region 2, both with the
    smooth C_m (``case.friction.smooth()``); :meth:`DesignResult.evaluate` gives
    the exact-Eq.-6 numbers of ``oilgap evaluate``.
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

    @property
    def x_mm(self) -> np.ndarray:
        """The NLP vector (R, delta, d_r, d_s, L) [mm]."""
        return np.array([self.R_m, self.delta_m, self.rotor_groove_depth_m,
                         self.stator_groove_depth_m, self.L_m]) / MM_TO_M

    def to_dict(self) -> dict[str, float]:
        """Unit-keyed plain dict (lengths in mm) for JSON and tables."""
        mm = 1.0 / MM_TO_M
        return {
            "mean_power_W": self.mean_power_W,
            "region1_power_W": self.region1_power_W,
            "region2_power_W": self.region2_power_W,
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


@dataclass(frozen=True)
class Multiplier:
    """What a constraint costs: d(optimal mean power)/d(its bound), in physical units.

    ``value`` is the derivative of the optimal mean power [W] with respect to the
    constraint's bound in ``unit`` (e.g. W per N m of required torque, W per mm
    of gap_max, W per % of the reference inertia); it is zero when the constraint
    is inactive. Signs: raising a binding lower bound costs (> 0), raising a
    binding upper bound saves (< 0) [4].
    """

    name: str
    constraint: str
    value: float
    unit: str
    active: bool
    value_si: float = 0.0
    """The same in SI: W per m (bounds), W per N m (torque), W per kg m^2 (inertia)."""

    def to_dict(self) -> dict[str, Any]:
        """Plain dict (JSON)."""
        return asdict(self)


@dataclass(frozen=True)
class DesignParameters:
    """The parameters one solve used (SI)."""

    oil: str
    oil_temp_C: float
    depth_m: float
    nu_m2_s: float
    rho_kg_m3: float
    torque_min_Nm: float
    inertia_ref_kgm2: float
    inertia_max_kgm2: float
    lower_m: tuple[float, ...]
    """Lower bounds of (R, delta, d_r, d_s, L) [m]."""
    upper_m: tuple[float, ...]
    """Upper bounds of (R, delta, d_r, d_s, L) [m]."""
    raw_oil_state: bool = False
    """True if nu/rho were given directly (not from an oil at a condition)."""
    oil_obj: Oil | None = field(default=None, repr=False, compare=False)
    """The oil given as an override (None: the case's)."""

    @property
    def inertia_max_ratio(self) -> float:
        """Inertia limit over the reference inertia [-]."""
        return self.inertia_max_kgm2 / self.inertia_ref_kgm2

    def to_dict(self) -> dict[str, Any]:
        """Unit-keyed plain dict (bounds in mm) for JSON."""
        mm = 1.0 / MM_TO_M
        d: dict[str, Any] = {"oil": self.oil, "oil_temp_C": self.oil_temp_C,
                             "depth_m": self.depth_m, "nu_cSt": m2_s_to_cst(self.nu_m2_s),
                             "density_kg_m3": self.rho_kg_m3,
                             "torque_min_Nm": self.torque_min_Nm,
                             "inertia_ref_kgm2": self.inertia_ref_kgm2,
                             "inertia_max_kgm2": self.inertia_max_kgm2,
                             "inertia_max_ratio": self.inertia_max_ratio}
        for v, lo, hi in zip(VARIABLES, self.lower_m, self.upper_m, strict=True):
            stem = VARIABLE_LABELS[v][1]
            d[f"{stem}_min_mm"] = lo * mm
            d[f"{stem}_max_mm"] = hi * mm
        return d


@dataclass(frozen=True, eq=False)
class DesignResult:
    """An optimum of the design NLP (solver failures raise instead).

    Attributes
    ----------
    status : IPOPT return status
    success : True (failures raise SolverError / InfeasibleError)
    iterations : IPOPT iterations
    solve_time_s : wall time of the IPOPT call [s]
    initial, optimal : DesignPoint
        The start point (the case's design unless ``x0`` was given) and the optimum.
    active_constraints : names of the active constraints and bounds
    multipliers : name -> Multiplier (every constraint and bound, zero if inactive)
    parameters : DesignParameters
    case : the case solved (with the oil/operating overrides applied)
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
        """Plain-dict form (the ``--json`` output of ``oilgap optimize``)."""
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
        limit for the new rotor. Re-optimizing the returned case therefore poses
        the same problem. If nu/rho were given directly (no oil), the case keeps
        its oil and a warning says so.
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
        """(initial, optimal) :class:`CaseEvaluation` with the case's own (exact) C_m form,
        i.e. what ``oilgap evaluate`` prints for the two designs."""
        from oilgap.model.evaluation import evaluate_case

        i = self.initial
        start = self.case.with_region1(
            T1=i.T1_m, T2=i.T2_m, T3=i.T3_m, T4=i.T4_m, length=i.L_m,
            T1_unfilled=i.R_m - self.machined_rotor_groove_m,
            T4_unfilled=i.T3_m + self.machined_stator_groove_m)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OilgapWarning)
            opt = self.to_case()
        return evaluate_case(start), evaluate_case(opt)


# --------------------------------------------------------------------------- the problem


def _finite_or_none(name: str, value: Any, positive: bool = True) -> float | None:
    if value is None:
        return None
    return check_positive(name, value, "optimize") if positive else check_finite(
        name, value, "optimize")


class DesignProblem:
    """The design NLP of a case, built once and re-solved with parameters.

    Parameters
    ----------
    case : DesignCase
        The joint; its region-1 design is the default start point, its bounds
        the default bounds, its torque capability the default ``torque_min``
        (unless ``case.bounds.torque_min_Nm`` is set), and its unfilled rotor the
        inertia reference.
    verbose : bool
        Let IPOPT print its iterations.

    Examples
    --------
    >>> from oilgap.model.case import seed_case
    >>> prob = DesignProblem(seed_case())
    >>> res = prob.solve()                        # doctest: +SKIP
    >>> res.optimal.mean_power_W, res.multipliers["torque_min"].value  # doctest: +SKIP
    >>> res2 = prob.solve(x0=res, torque_min_Nm=0.45)  # warm start  # doctest: +SKIP
    """

    def __init__(self, case: DesignCase, verbose: bool = False):
        t0 = time.perf_counter()
        self.case = case
        self.verbose = bool(verbose)
        self.law = case.friction.smooth()
        r1 = case.region1
        m = case.motor
        self.machined_rotor_groove_m = r1.T2 - r1.T1_unfilled
        self.machined_stator_groove_m = r1.T4_unfilled - r1.T3
        self.x_case_m = np.array([r1.T2, r1.gap, r1.T2 - r1.T1, r1.T4 - r1.T3, r1.length])
        b = case.bounds
        if b.radius_min - self.machined_rotor_groove_m <= m.shaft_bore_radius:
            raise InputError("bounds.radius_min_mm", b.radius_min / MM_TO_M,
                             "must leave the machined groove bottoms (R - "
                             f"{self.machined_rotor_groove_m / MM_TO_M:g} mm) outside the "
                             f"shaft bore ({m.shaft_bore_radius / MM_TO_M:g} mm)", "case")
        nodes, weights = case.duty_cycle.speed_distribution()
        keep = nodes > 0.0  # zero speed: |omega|^3 = 0, exactly no power (Eq. 5)
        self.nodes_rad_s = np.ascontiguousarray(nodes[keep])
        self.weights = np.ascontiguousarray(weights[keep])
        self.tau_ref_Nm = float(motor_torque(m, r1.T2, r1.gap, r1.length)[0])
        self.inertia_ref_kgm2 = float(rotor_inertia(m, r1.T2, self.machined_rotor_groove_m,
                                                    r1.length, self.machined_rotor_groove_m))
        self.nu_m2_s, _, self.rho_kg_m3 = (float(v) for v in oil_state(case))

        y = ca.SX.sym("y", 5)  # (ln R/mm, ln delta/mm, d_r/mm, d_s/mm, ln L/mm)
        p = ca.SX.sym("p", 2)  # (nu [m^2/s], rho [kg/m^3])
        R, delta, d_r, d_s, L = ((ca.exp(y[i]) if _LOG[i] else y[i]) * MM_TO_M
                                 for i in range(5))
        p1 = region1_mean_power(R, delta, d_r, d_s, L, p[0], p[1], ca.DM(self.nodes_rad_s),
                                self.weights, self.law)
        tau = motor_torque(m, R, delta, L)[0]
        J = rotor_inertia(m, R, d_r, L, self.machined_rotor_groove_m)
        g = ca.vertcat(ca.log(tau / self.tau_ref_Nm), ca.log(J / self.inertia_ref_kgm2))
        self._nlp = {"x": y, "p": p, "f": ca.log(p1), "g": g}
        opts = dict(_SOLVER_OPTIONS, **_QUIET)
        if self.verbose:
            opts.update({"ipopt.print_level": 5, "print_time": True})
            opts.pop("ipopt.sb")
        self._opts = opts
        self._solver = ca.nlpsol("oilgap_design", "ipopt", self._nlp, opts)
        self._warm_solver = None
        self._report = ca.Function("report", [y, p], [ca.vertcat(p1, tau, J)])
        self._p2_cache: dict[tuple[float, float], float] = {}
        self._point_cache: dict[tuple, DesignPoint] = {}
        self.build_time_s = time.perf_counter() - t0

    # ----------------------------------------------------------------- helpers

    @property
    def default_torque_min_Nm(self) -> float:
        """``case.bounds.torque_min_Nm`` or, if unset, the case's own torque capability."""
        t = self.case.bounds.torque_min_Nm
        return self.tau_ref_Nm if t is None else float(t)

    def region2_power(self, nu_m2_s: float, rho_kg_m3: float) -> float:
        """Mean power [W] of region 2 (constant for the design), smooth C_m."""
        r2 = self.case.region2
        if r2 is None:
            return 0.0
        key = (float(nu_m2_s), float(rho_kg_m3))
        if key not in self._p2_cache:
            if len(self._p2_cache) > 4096:
                self._p2_cache.clear()
            self._p2_cache[key] = float(region_mean_power(
                Region("bearing", r2.radius, r2.gap, r2.length, 1.0), self.nodes_rad_s,
                self.weights, nu_m2_s, rho_kg_m3, self.law))
        return self._p2_cache[key]

    def point(self, x_m: Sequence[float], nu_m2_s: float | None = None,
              rho_kg_m3: float | None = None) -> DesignPoint:
        """The DesignPoint of a design vector (R, delta, d_r, d_s, L) [m]."""
        nu = self.nu_m2_s if nu_m2_s is None else nu_m2_s
        rho = self.rho_kg_m3 if rho_kg_m3 is None else rho_kg_m3
        return self._point(np.asarray(x_m, dtype=float), nu, rho,
                           self.region2_power(nu, rho))

    def _point(self, x_m: np.ndarray, nu: float, rho: float, p2: float,
               values: tuple[float, float, float] | None = None) -> DesignPoint:
        """DesignPoint of x [m]; ``values`` = (P1, tau, J) if already known (from IPOPT)."""
        key = None
        if values is None:
            key = (x_m.tobytes(), nu, rho, p2)
            hit = self._point_cache.get(key)
            if hit is not None:
                return hit
            values = tuple(float(v) for v in
                           np.asarray(self._report(ca.DM(_to_nlp(x_m)),
                                                   ca.DM([nu, rho]))).ravel())
        p1, tau, J = values
        R, delta, d_r, d_s, L = (float(v) for v in x_m)
        _, bg, kc = motor_torque(self.case.motor, R, delta, L)
        T1, T2, T3, T4 = rotor_stator_radii(R, delta, d_r, d_s)
        pt = DesignPoint(R, delta, d_r, d_s, L, T1, T2, T3, T4,
                         float(groove_roughness(T1, T2, T3, T4)), p1, p2, p1 + p2, tau,
                         float(bg), float(kc), J, J / self.inertia_ref_kgm2)
        if key is not None:
            if len(self._point_cache) > 1024:
                self._point_cache.clear()
            self._point_cache[key] = pt
        return pt

    def parameters(self, *, oil: Oil | None = None, oil_temp_C: float | None = None,
                   depth_m: float | None = None, nu_m2_s: float | None = None,
                   rho_kg_m3: float | None = None, torque_min_Nm: float | None = None,
                   inertia_max_ratio: float | None = None, gap_min_m: float | None = None,
                   gap_max_m: float | None = None, radius_min_m: float | None = None,
                   radius_max_m: float | None = None, length_min_m: float | None = None,
                   length_max_m: float | None = None,
                   fix: Mapping[str, float] | Sequence[str] | None = None) -> DesignParameters:
        """Resolve and validate the parameters of a solve (see :meth:`solve`)."""
        case = self.case
        raw = nu_m2_s is not None or rho_kg_m3 is not None
        if raw and (oil is not None or oil_temp_C is not None or depth_m is not None):
            raise InputError("nu_m2_s/rho_kg_m3", (nu_m2_s, rho_kg_m3),
                             "give either nu/rho or oil/oil_temp_C/depth_m, not both",
                             "optimize")
        op = case.operating
        t = op.oil_temp_C if oil_temp_C is None else check_finite("oil_temp_C", oil_temp_C,
                                                                    "optimize")
        d = op.depth_m if depth_m is None else check_finite("depth_m", depth_m, "optimize")
        the_oil = case.oil if oil is None else oil
        if oil is None and oil_temp_C is None and depth_m is None:
            nu, rho = self.nu_m2_s, self.rho_kg_m3
        else:
            OperatingPoint(d, t)  # validates the ranges
            nu, _, rho = (float(v) for v in oil_state(replace(case, oil=the_oil), t, d))
        if nu_m2_s is not None:
            nu = check_positive("nu_m2_s", nu_m2_s, "optimize")
        if rho_kg_m3 is not None:
            rho = check_positive("rho_kg_m3", rho_kg_m3, "optimize")
        tmin = self.default_torque_min_Nm if torque_min_Nm is None else check_positive(
            "torque_min_Nm", torque_min_Nm, "optimize")
        ratio = case.bounds.inertia_max_ratio if inertia_max_ratio is None else check_positive(
            "inertia_max_ratio", inertia_max_ratio, "optimize")
        b = case.bounds
        lo = [b.radius_min, b.gap_min, 0.0, 0.0, b.length_min]
        hi = [b.radius_max, b.gap_max, self.machined_rotor_groove_m,
              self.machined_stator_groove_m, b.length_max]
        for i, (nlo, nhi) in enumerate(((radius_min_m, radius_max_m), (gap_min_m, gap_max_m),
                                        (None, None), (None, None),
                                        (length_min_m, length_max_m))):
            stem = VARIABLE_LABELS[VARIABLES[i]][1]
            v = _finite_or_none(f"{stem}_min_m", nlo)
            lo[i] = lo[i] if v is None else v
            v = _finite_or_none(f"{stem}_max_m", nhi)
            hi[i] = hi[i] if v is None else v
        if fix:
            items = fix.items() if isinstance(fix, Mapping) else ((k, None) for k in fix)
            for k, v in items:
                if k not in VARIABLES:
                    raise InputError("fix", k, f"allowed: {', '.join(VARIABLES)}", "optimize")
                i = VARIABLES.index(k)
                val = self.x_case_m[i] if v is None else check_finite(f"fix[{k}]", v,
                                                                       "optimize")
                lo[i] = hi[i] = val
        for i, v in enumerate(VARIABLES):
            stem = VARIABLE_LABELS[v][1]
            if lo[i] > hi[i]:
                raise InputError(f"{stem}_max_mm", hi[i] / MM_TO_M,
                                 f"must be >= {stem}_min_mm = {lo[i] / MM_TO_M:g}", "optimize")
            if v in ("d_r", "d_s"):
                top = (self.machined_rotor_groove_m if v == "d_r"
                       else self.machined_stator_groove_m)
                if lo[i] < 0.0 or hi[i] > top * (1 + 1e-12) + 1e-15:
                    raise InputError(f"fix[{v}]", hi[i] / MM_TO_M,
                                     f"groove depth must lie in [0, {top / MM_TO_M:g}] mm "
                                     "(filling only makes grooves shallower)", "optimize")
            elif lo[i] <= 0.0:
                raise InputError(f"{stem}_min_mm", lo[i] / MM_TO_M, "must be > 0", "optimize")
        if lo[0] - self.machined_rotor_groove_m <= case.motor.shaft_bore_radius:
            raise InputError("radius_min_mm", lo[0] / MM_TO_M, "must leave the machined groove "
                             "bottoms outside the shaft bore", "optimize")
        return DesignParameters(the_oil.name, t, d, nu, rho, tmin, self.inertia_ref_kgm2,
                                ratio * self.inertia_ref_kgm2, tuple(lo), tuple(hi), raw, oil)

    # ----------------------------------------------------------------- feasibility

    def check_feasible(self, params: DesignParameters, x_hint_m: np.ndarray | None = None
                       ) -> None:
        """Raise InfeasibleError, naming the conflicting constraints, if no design meets
        ``torque >= torque_min`` and ``inertia <= inertia_max`` within the bounds.

        The torque capability falls with delta and rises with R and L; the inertia
        rises with R, L and the fill. So the problem is feasible iff some R admits an
        L with ``tau(R, delta_min, L) >= tau_min`` and ``J(R, d_r,max, L) <= J_max``;
        both are linear in L, which leaves a 1-D search over R (grid, then refined).
        """
        m = self.case.motor
        lo, hi = np.asarray(params.lower_m), np.asarray(params.upper_m)
        tmin, jmax = params.torque_min_Nm, params.inertia_max_kgm2
        if x_hint_m is not None:
            x = np.clip(x_hint_m, lo, hi)
            if (float(motor_torque(m, x[0], x[1], x[4])[0]) >= tmin and
                    float(rotor_inertia(m, x[0], x[2], x[4], self.machined_rotor_groove_m))
                    <= jmax):
                return
        d_lo, dr_hi, L_lo, L_hi = lo[1], hi[2], lo[4], hi[4]

        def slack(R):
            R = np.asarray(R, dtype=float)
            t1 = motor_torque(m, R, d_lo, 1.0)[0]
            j1 = rotor_inertia(m, R, dr_hi, 1.0, self.machined_rotor_groove_m)
            need = np.maximum(L_lo, tmin / t1)
            allow = np.minimum(L_hi, jmax / j1)
            return (allow - need) / L_hi, need, allow

        grid = np.linspace(lo[0], hi[0], 401) if hi[0] > lo[0] else np.array([lo[0]])
        s, _, _ = slack(grid)
        if np.max(s) >= -1e-12:
            return
        k = int(np.argmax(s))
        R_best = grid[k]
        if grid.size > 1:
            from scipy.optimize import minimize_scalar

            a, bnd = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
            r = minimize_scalar(lambda R: -slack(R)[0], bounds=(a, bnd), method="bounded",
                                options={"xatol": 1e-12})
            if -r.fun >= -1e-12:
                return
            R_best = float(r.x)
        raise InfeasibleError(self._infeasibility_message(params, R_best),
                              status="infeasible (checked before solving)")

    def _infeasibility_message(self, params: DesignParameters, R_best: float) -> str:
        from scipy.optimize import brentq

        m = self.case.motor
        lo, hi = params.lower_m, params.upper_m
        tmin, jmax = params.torque_min_Nm, params.inertia_max_kgm2
        mm = 1.0 / MM_TO_M
        parts = []
        t_max = float(motor_torque(m, hi[0], lo[1], hi[4])[0])
        if t_max < tmin:
            where = f"R = R_max = {hi[0] * mm:.4g} mm, L = L_max = {hi[4] * mm:.4g} mm"
            tiny = 1e-9
            if float(motor_torque(m, hi[0], tiny, hi[4])[0]) >= tmin:
                d_need = brentq(lambda d: float(motor_torque(m, hi[0], d, hi[4])[0]) - tmin,
                                tiny, lo[1], xtol=1e-15)
                parts.append(f"torque >= {tmin:.6g} N m needs delta <= {d_need * mm:.4g} mm "
                             f"(at {where}), but delta_min = {lo[1] * mm:.4g} mm")
            else:
                parts.append(f"torque >= {tmin:.6g} N m exceeds the motor's capability at any "
                             f"gap ({t_max:.4g} N m at delta_min, {where})")
        j_min = float(rotor_inertia(m, lo[0], hi[2], lo[4], self.machined_rotor_groove_m))
        if j_min > jmax:
            parts.append(f"inertia <= {jmax:.4g} kg m^2 ({params.inertia_max_ratio:.4g} x the "
                         f"reference {params.inertia_ref_kgm2:.4g}) is below the lightest "
                         f"rotor within the bounds, {j_min:.4g} kg m^2 (R = R_min = "
                         f"{lo[0] * mm:.4g} mm, L = L_min = {lo[4] * mm:.4g} mm, grooves "
                         "as open as allowed)")
        if not parts:
            t1 = float(motor_torque(m, R_best, lo[1], 1.0)[0])
            j1 = float(rotor_inertia(m, R_best, hi[2], 1.0, self.machined_rotor_groove_m))
            parts.append(f"torque >= {tmin:.6g} N m and inertia <= {jmax:.4g} kg m^2 "
                         f"({params.inertia_max_ratio:.4g} x reference) conflict: at the best "
                         f"radius R = {R_best * mm:.4g} mm with delta = delta_min = "
                         f"{lo[1] * mm:.4g} mm the torque needs L >= "
                         f"{max(lo[4], tmin / t1) * mm:.4g} mm but the inertia allows L <= "
                         f"{min(hi[4], jmax / j1) * mm:.4g} mm")
        return "; ".join(parts)

    # ----------------------------------------------------------------- solve

    def solve(self, x0: DesignResult | DesignPoint | Sequence[float] | None = None, *,
              warm_start_duals: bool = True, starts: int = 1, seed: int = 0,
              **overrides: Any) -> DesignResult:
        """Solve the NLP; return the optimum or raise.

        Parameters
        ----------
        x0 : DesignResult, DesignPoint, sequence of (R, delta, d_r, d_s, L) [m], or None
            Start point (default: the case's design). A DesignResult (e.g. the
            neighbour in a sweep) also warm-starts the multipliers unless
            ``warm_start_duals`` is False; should that warm-started solve fail,
            it is retried from the primal point alone before anything is raised.
        starts : int
            Number of start points: ``x0`` and ``starts - 1`` points drawn
            uniformly in the bounds (numpy generator ``seed``); the best optimum is
            returned. IPOPT is
            a local method and warm thin oils near the Re = 64 / 500 regime breaks
            make the loss non-convex, so several starts guard against a local
            optimum.
        **overrides
            ``oil`` (an :class:`Oil`), ``oil_temp_C`` [degC], ``depth_m`` [m], or
            ``nu_m2_s`` and ``rho_kg_m3`` directly; ``torque_min_Nm`` [N m];
            ``inertia_max_ratio`` [-] (of the case's unfilled rotor);
            ``gap_min_m``, ``gap_max_m``, ``radius_min_m``, ``radius_max_m``,
            ``length_min_m``, ``length_max_m`` [m]; ``fix``: variables held at
            the case's value (sequence of names) or at given values
            (mapping name -> [m]), names from :data:`VARIABLES`.

        Raises
        ------
        InputError
            Bad override.
        InfeasibleError
            No design meets the constraints (message names them).
        SolverError
            IPOPT failed; ``status`` and ``last_iterate`` say how.
        """
        params = self.parameters(**overrides)
        lo, hi = np.asarray(params.lower_m), np.asarray(params.upper_m)
        lam = None
        if x0 is None:
            x_start = self.x_case_m.copy()
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
        x_start = np.clip(x_start, lo, hi)
        if isinstance(starts, bool) or not isinstance(starts, int) or starts < 1:
            raise InputError("starts", starts, "must be an integer >= 1", "optimize")
        self.check_feasible(params, x_start)
        p2 = self.region2_power(params.nu_m2_s, params.rho_kg_m3)
        if starts == 1:
            if lam is None:
                return self._solve_from(params, x_start, None, p2)
            try:
                return self._solve_from(params, x_start, lam, p2)
            except SolverError:  # a stale dual warm start: retry from x0 alone
                return self._solve_from(params, x_start, None, p2)
        pts = np.random.default_rng(seed).uniform(size=(starts - 1, 5))
        best, first_error = None, None
        for x in [x_start, *(lo + pts * (hi - lo))]:
            try:
                r = self._solve_from(params, x, lam if x is x_start else None, p2)
            except SolverError as e:
                first_error = first_error or e
                continue
            if best is None or r.optimal.mean_power_W < best.optimal.mean_power_W:
                best = r
        if best is None:
            raise first_error
        return replace(best, starts=starts,
                       initial=self._point(x_start, params.nu_m2_s, params.rho_kg_m3, p2))

    def _solve_from(self, params: DesignParameters, x_start: np.ndarray,
                    lam: tuple[np.ndarray, np.ndarray] | None, p2: float) -> DesignResult:
        lo, hi = np.asarray(params.lower_m), np.asarray(params.upper_m)
        nu, rho = params.nu_m2_s, params.rho_kg_m3
        initial = self._point(x_start, nu, rho, p2)
        ylo, yhi = _to_nlp(lo), _to_nlp(hi)
        args = {"x0": _to_nlp(x_start), "p": [nu, rho], "lbx": ylo, "ubx": yhi,
                "lbg": [np.log(params.torque_min_Nm / self.tau_ref_Nm), -np.inf],
                "ubg": [np.inf, np.log(params.inertia_max_kgm2 / self.inertia_ref_kgm2)]}
        solver = self._solver
        if lam is not None:
            if self._warm_solver is None:
                self._warm_solver = ca.nlpsol("oilgap_design_warm", "ipopt", self._nlp,
                                              dict(self._opts, **_WARM_OPTIONS))
            solver = self._warm_solver
            args.update(lam_x0=lam[0], lam_g0=lam[1])
        t0 = time.perf_counter()
        sol = solver(**args)
        dt = time.perf_counter() - t0
        stats = solver.stats()
        status = str(stats.get("return_status", "unknown"))
        y = np.asarray(sol["x"]).ravel()
        if status not in SUCCESS_STATUSES or not np.all(np.isfinite(y)):
            last = {VARIABLE_LABELS[v][0]: float(xv) for v, xv in
                    zip(VARIABLES, _from_nlp(y) / MM_TO_M, strict=True)}
            gv = np.asarray(sol["g"]).ravel()
            last["torque_capability_Nm"] = float(np.exp(gv[0]) * self.tau_ref_Nm)
            last["inertia_kgm2"] = float(np.exp(gv[1]) * self.inertia_ref_kgm2)
            last["mean_power_W"] = float(np.exp(float(sol["f"]))) + p2
            it = ", ".join(f"{k} = {v:.6g}" for k, v in last.items())
            raise SolverError(f"IPOPT did not converge (status {status} after "
                              f"{stats.get('iter_count', '?')} iterations); last iterate: {it}",
                              status=status, last_iterate=last)
        y_in = np.clip(y, ylo, yhi)
        x_m = np.clip(_from_nlp(y_in), lo, hi)
        # a variable IPOPT left on its bound is reported at the bound exactly (no exp/log
        # round-off)
        x_m = np.where(y_in == ylo, lo, np.where(y_in == yhi, hi, x_m))
        values = None
        if np.array_equal(y_in, y):  # IPOPT's f and g are at this very point
            gv = np.asarray(sol["g"]).ravel()
            values = (float(np.exp(float(sol["f"]))), float(np.exp(gv[0]) * self.tau_ref_Nm),
                      float(np.exp(gv[1]) * self.inertia_ref_kgm2))
        optimal = self._point(x_m, nu, rho, p2, values)
        lam_x = np.asarray(sol["lam_x"]).ravel()
        lam_g = np.asarray(sol["lam_g"]).ravel()
        mults, active = self._multipliers(params, optimal, lam_x, lam_g)
        return DesignResult(status, True, int(stats.get("iter_count", -1)), dt, initial,
                            optimal, active, mults, params, self._case_for(params),
                            self.machined_rotor_groove_m, self.machined_stator_groove_m, 1,
                            {"lam_x": lam_x, "lam_g": lam_g})

    def _case_for(self, params: DesignParameters) -> DesignCase:
        c = self.case
        if params.raw_oil_state:
            return c
        if params.oil != c.oil.name or params.oil_temp_C != c.operating.oil_temp_C or \
                params.depth_m != c.operating.depth_m:
            oil = c.oil if params.oil_obj is None else params.oil_obj
            c = replace(c, oil=oil, operating=OperatingPoint(params.depth_m, params.oil_temp_C))
        return c

    def _multipliers(self, params: DesignParameters, opt: DesignPoint, lam_x: np.ndarray,
                     lam_g: np.ndarray):
        """Sensitivities d(P*)/d(bound), converted to physical units [4].

        IPOPT minimizes F = ln P1 in y; at the optimum dF*/d(bound of y_i) = -lam_x[i]
        and dF*/d(bound of g_k) = -lam_g[k] (CasADi's sign convention). With
        dP* = P1* dF*, y_i = ln(x_i/mm) (dy = dx/x) or x_i/mm, g_0 = ln(tau/tau_ref)
        and g_1 = ln(J/J_ref) this gives W per m of a bound, W per N m of tau_min
        and W per kg m^2 of J_max.
        """
        out: dict[str, Multiplier] = {}
        active: list[str] = []
        x_m = (opt.R_m, opt.delta_m, opt.rotor_groove_depth_m, opt.stator_groove_depth_m,
               opt.L_m)
        lo, hi = params.lower_m, params.upper_m
        lam_x, lam_g = lam_x.tolist(), lam_g.tolist()
        p1 = opt.region1_power_W
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


def solve_design(case: DesignCase, verbose: bool = False, **overrides: Any) -> DesignResult:
    """One-shot: build the NLP of ``case`` and solve it (see :meth:`DesignProblem.solve`)."""
    return DesignProblem(case, verbose=verbose).solve(**overrides)


__all__ = [
    "VARIABLES", "DesignPoint", "DesignParameters", "DesignProblem", "DesignResult",
    "Multiplier", "region1_mean_power",
    "solve_design",
]
