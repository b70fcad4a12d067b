"""The lean solve of a sweep: the isothermal design NLP and only the numbers a sweep writes.

:meth:`DesignProblem.solve <oilgap.optim.design.DesignProblem.solve>` returns a
:class:`~oilgap.optim.design.DesignResult`: both design points with the motor's flux
density and Carter coefficient, every multiplier converted to physical units, the
solved case. A sweep of many points writes a few columns of each
(:data:`oilgap.studies.grid.columns.OPTIMIZE_RESULTS`), so :func:`solve_lean` makes the
same IPOPT call from the same start (the same solver, options, bounds and warm start)
and computes only those columns: the powers of the optimum (IPOPT's own f and g there),
the radii and T, the torque and inertia, the active constraints (the rule of
:func:`~oilgap.optim.design.convert_multipliers`) and the start's power. The optimum's
evaluation with the exact C_m is left to the caller, who evaluates a whole chunk at
once (:func:`optimal_case` gives the case to evaluate), and so may be region 2's power
(:func:`add_constant_powers`, many oil states in one call).

The calls to IPOPT and to the report function go through CasADi's buffers
(:class:`LeanSolver`): the numbers are those of the ordinary call, without its
per-call conversion of every input and output (0.2-0.4 ms a solve, a quarter of the
IPOPT call on the seed case). Python outside the solver is what is left: about
0.25-0.3 of the IPOPT call on the seed case (``benchmarks/bench_sweep_scale.py``).
"""

from __future__ import annotations

import math
import threading
import time
import weakref
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from oilgap.model.case import DesignCase, OperatingPoint, RotorStatorClearance
from oilgap.model.errors import SolverError
from oilgap.model.regions import joint_regions, region_mean_power, rotor_stator_radii
from oilgap.model.skin_friction import groove_roughness
from oilgap.model.units import MM_TO_M
from oilgap.optim.interrupts import raise_if_interrupted

from .parameters import DesignParameters
from .session import Buffered, clamp, run_starts, snap_to_bounds
from .variables import ACTIVE_RTOL, SUCCESS_STATUSES, VARIABLE_LABELS, VARIABLES, from_nlp, to_nlp

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .problem import DesignProblem


@dataclass(frozen=True)
class LeanStart:
    """What the next solve of a chain starts from: an optimum [m] and its multipliers.

    Parameters
    ----------
    x_m : ndarray of 5 floats
        (R, delta, d_r, d_s, L) of the optimum [m].
    lam_x, lam_g : ndarray or None
        IPOPT's multipliers of the scaled NLP [-] (None: a primal start alone).
    """

    x_m: np.ndarray
    lam_x: np.ndarray | None
    lam_g: np.ndarray | None

    def start_m(self) -> np.ndarray:
        """The start [m] as ``DesignProblem.solve`` takes it from a result (through mm)."""
        return (self.x_m / MM_TO_M) * MM_TO_M


@dataclass(frozen=True, kw_only=True, slots=True)
class LeanRecord:
    """What a sweep writes of one lean solve (:func:`solve_lean`): the optimum's columns
    of :data:`oilgap.studies.grid.columns.OPTIMIZE_RESULTS` the solve gives.

    Attributes
    ----------
    region1_power_W : float
        Region 1's mean power at the optimum (smooth C_m, IPOPT's f) [W].
    T : float
        Groove roughness of the optimum [-].
    delta_mm, R_mm, L_mm : float
        Gap, rotor radius and length of the optimum [mm].
    T1_mm, T2_mm, T3_mm, T4_mm : float
        The optimum's rotor and stator radii [mm].
    torque_capability_Nm : float
        The optimum's torque capability [N m].
    inertia_kgm2 : float
        The rotor's inertia [kg m^2].
    inertia_ratio : float
        Over the case's design's inertia [-].
    torque_min_Nm_used : float
        The solve's torque floor [N m].
    inertia_max_kgm2_used : float
        The solve's inertia ceiling [kg m^2].
    active_constraints : str
        The active constraints' names, space-separated.
    iterations : int
        IPOPT's iterations (-1: unknown).
    initial_region1_power_W : float
        Region 1's power at the solve's start [W].
    mean_power_W, region2_power_W, initial_mean_power_W : float or None
        The optimum's mean power, region 2's, the start's mean power [W] (smooth C_m,
        bearing included); None until :func:`add_constant_powers`.
    """

    region1_power_W: float
    T: float
    delta_mm: float
    R_mm: float
    L_mm: float
    T1_mm: float
    T2_mm: float
    T3_mm: float
    T4_mm: float
    torque_capability_Nm: float
    inertia_kgm2: float
    inertia_ratio: float
    torque_min_Nm_used: float
    inertia_max_kgm2_used: float
    active_constraints: str
    iterations: int
    initial_region1_power_W: float
    mean_power_W: float | None = None
    region2_power_W: float | None = None
    initial_mean_power_W: float | None = None

    def to_dict(self) -> dict[str, Any]:
        """The sweep's columns, in the order a sweep's row holds them (the start's
        region-1 power, an intermediate, left out).

        Returns
        -------
        dict
            Column name to value (powers [W], lengths [mm]).
        """
        return {"mean_power_W": self.mean_power_W, "region1_power_W": self.region1_power_W,
                "region2_power_W": self.region2_power_W, "T": self.T,
                "delta_mm": self.delta_mm, "R_mm": self.R_mm, "L_mm": self.L_mm,
                "T1_mm": self.T1_mm, "T2_mm": self.T2_mm, "T3_mm": self.T3_mm,
                "T4_mm": self.T4_mm, "torque_capability_Nm": self.torque_capability_Nm,
                "inertia_kgm2": self.inertia_kgm2, "inertia_ratio": self.inertia_ratio,
                "initial_mean_power_W": self.initial_mean_power_W,
                "torque_min_Nm_used": self.torque_min_Nm_used,
                "inertia_max_kgm2_used": self.inertia_max_kgm2_used,
                "active_constraints": self.active_constraints,
                "iterations": self.iterations}


def _total(p1: float, p2: float, pb: float | None) -> float:
    """Mean power [W]: region 1, region 2 and the rolling bearing (if any), summed in
    :func:`~oilgap.optim.design.results.design_point`'s order."""
    return p1 + p2 if pb is None else p1 + p2 + pb


def active_constraints(params: DesignParameters, x_m: np.ndarray, tau_Nm: float,
                       inertia_kgm2: float) -> tuple[str, ...]:
    """Names of the active constraints, as :func:`~oilgap.optim.design.convert_multipliers`
    lists them (torque and inertia first, then the bounds).

    Parameters
    ----------
    params : DesignParameters
        The solve's bounds [m] and limits.
    x_m : array of 5 floats
        The optimum (R, delta, d_r, d_s, L) [m].
    tau_Nm : float
        Its torque capability [N m].
    inertia_kgm2 : float
        Its rotor inertia [kg m^2].

    Returns
    -------
    tuple of str
    """
    lo, hi = params.lower_m, params.upper_m
    bounds = []
    for i, v in enumerate(VARIABLES):
        stem = VARIABLE_LABELS[v][1]
        if hi[i] == lo[i]:
            bounds.append(f"{stem}_fixed")
            continue
        scale = max(hi[i] - lo[i], abs(hi[i]), 1e-6)
        if abs(x_m[i] - lo[i]) <= ACTIVE_RTOL * scale:
            bounds.append(f"{stem}_min")
        if abs(x_m[i] - hi[i]) <= ACTIVE_RTOL * scale:
            bounds.append(f"{stem}_max")
    tmin, jmax = params.torque_min_Nm, params.inertia_max_kgm2
    head = [n for n, a in (("torque_min", tau_Nm - tmin <= ACTIVE_RTOL * tmin),
                           ("inertia_max", jmax - inertia_kgm2 <= ACTIVE_RTOL * jmax)) if a]
    return tuple(head + bounds)


class LeanSolver:
    """The IPOPT calls and the report (P1, tau, J) of one DesignProblem, buffered.

    One per problem and thread (:func:`lean_solver`): the buffers are reused by every
    solve. The solvers are those of the problem's session
    (:meth:`.session.SolverSession.buffered`, the cold and the warm-start one).

    Attributes
    ----------
    timings : list of float or None
        If a list, the wall time [s] of each IPOPT call is appended (benchmarks).
    """

    def __init__(self, problem: DesignProblem):
        self.problem = problem
        self._cold: Buffered | None = None
        self._warm: Buffered | None = None
        self._report = Buffered(problem.report_fn)
        self._bounds: tuple = ((), ())
        self._feasible: set[tuple] = set()
        self.timings: list[float] | None = None

    def _solver(self, warm: bool) -> Buffered:
        """The buffered cold or warm-start solver of the problem's session."""
        if not warm:
            if self._cold is None:
                self._cold = self.problem.session.buffered(False)
            return self._cold
        if self._warm is None:
            self._warm = self.problem.session.buffered(True)
        return self._warm

    def nlp_bounds(self, params: DesignParameters) -> tuple[np.ndarray, ...]:
        """(lower, upper [m], lbx, ubx of the scaled NLP) of the bounds of ``params``
        (kept while the bounds do not change)."""
        key = (params.lower_m, params.upper_m)
        if self._bounds[0] != key:
            lo, hi = np.asarray(key[0], dtype=float), np.asarray(key[1], dtype=float)
            self._bounds = (key, (lo, hi, to_nlp(lo), to_nlp(hi)))
        return self._bounds[1]

    def check_feasible(self, params: DesignParameters, x_start: np.ndarray) -> None:
        """:meth:`DesignProblem.check_feasible`, once per set of bounds and limits (what
        it depends on: not the oil state)."""
        key = (params.lower_m, params.upper_m, params.torque_min_Nm, params.inertia_max_kgm2)
        if key not in self._feasible:
            self.problem.check_feasible(params, x_start)
            if len(self._feasible) > 4096:
                self._feasible.clear()
            self._feasible.add(key)

    def report(self, x_m: np.ndarray, nu: float, rho: float) -> tuple[float, float, float]:
        """(P1 [W], tau [N m], J [kg m^2]) of a design [m] in an oil state (SI)."""
        r = self._report
        r.arg["i0"][:] = to_nlp(x_m)
        p = r.arg["i1"]
        p[0], p[1] = nu, rho
        r.run()
        p1, tau, J = r.res["o0"].tolist()
        return p1, tau, J

    def ipopt(self, params: DesignParameters, x_start: np.ndarray, lam: tuple | None
              ) -> tuple[dict, dict, np.ndarray, tuple | None]:
        """One IPOPT call as :meth:`DesignProblem.solve` makes it: (outputs, stats,
        the optimum [m], (P1, tau, J) at it or None). The outputs are the buffer's
        arrays (valid until the next call)."""
        prob = self.problem
        s = self._solver(lam is not None)
        a = s.arg
        lo, hi, ylo, yhi = self.nlp_bounds(params)
        a["x0"][:] = to_nlp(x_start)
        a["p"][0], a["p"][1] = params.nu_m2_s, params.rho_kg_m3
        a["lbx"][:], a["ubx"][:] = ylo, yhi
        a["lbg"][:], a["ubg"][:] = prob.constraint_bounds(params)
        if lam is not None:
            a["lam_x0"][:], a["lam_g0"][:] = lam
        t0 = time.perf_counter()
        s.run()
        if self.timings is not None:
            self.timings.append(time.perf_counter() - t0)
        raise_if_interrupted()  # CasADi turns Ctrl-C into a failed solve: re-raise it
        stats = s.stats()
        out = s.res
        y = out["x"]
        if str(stats.get("return_status", "unknown")) not in SUCCESS_STATUSES or \
                not np.isfinite(y).all():
            raise self.failure(stats, out, params)
        y_in, x_m = snap_to_bounds(y, ylo, yhi, lo, hi, from_nlp)
        values = None
        if (y_in == y).all():  # IPOPT's f and g are at this very point
            g = out["g"]
            values = (float(np.exp(out["f"][0])), float(np.exp(g[0]) * prob.tau_ref_Nm),
                      float(np.exp(g[1]) * prob.inertia_ref_kgm2))
        return out, stats, x_m, values

    def failure(self, stats: dict, out: dict, params: DesignParameters,
                status: str | None = None) -> Exception:
        """The problem's SolverError of a failed call (its last iterate)."""
        status = str(stats.get("return_status", "unknown")) if status is None else status
        return self.problem.failure(status, stats.get("iter_count", "?"), out["x"].copy(),
                                    float(out["f"][0]), out["g"].copy(), params.nu_m2_s,
                                    params.rho_kg_m3)


def lean_solver(problem: DesignProblem) -> LeanSolver:
    """The :class:`LeanSolver` of ``problem`` in this thread (built on first use).

    Parameters
    ----------
    problem : DesignProblem
        The design NLP (isothermal); its IPOPT solver and report function are wrapped.

    Returns
    -------
    LeanSolver
        One per problem and thread (CasADi's buffered calls are not shared between
        threads); its solves return the sweep's columns in SI [m, W, N m, kg m^2].
    """
    per_thread = _LEAN.get(problem)
    if per_thread is None:
        per_thread = _LEAN[problem] = {}
    key = threading.get_ident()
    ls = per_thread.get(key)
    if ls is None:
        ls = per_thread[key] = LeanSolver(problem)
    return ls


_LEAN: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
"""LeanSolvers by problem (dropped with it), then by thread: buffers are not shared."""


def solve_lean(problem: DesignProblem, x0: LeanStart | None = None, *, constant: bool = True,
               **overrides: Any) -> tuple[LeanRecord, LeanStart, DesignParameters]:
    """Solve the isothermal design NLP of ``problem``; return only what a sweep writes.

    The same IPOPT call as :meth:`DesignProblem.solve_isothermal` with ``starts=1``
    (a dual warm start retried from the primal point alone should it fail), made
    through buffers (:class:`LeanSolver`).

    Parameters
    ----------
    problem : DesignProblem
        Built with ``thermal="none"``.
    x0 : LeanStart, optional
        The previous optimum of the chain (primal and dual; default: the case's design).
    constant : bool
        Add the powers the design does not change (region 2, the bearing) here; False:
        leave ``mean_power_W``, ``region2_power_W`` and ``initial_mean_power_W`` to
        :func:`add_constant_powers`, for many records at once.
    **overrides
        As :meth:`DesignProblem.solve_isothermal` (oil, oil_temp_C, depth_m, limits,
        bounds).

    Returns
    -------
    record : LeanRecord
        The sweep's columns of the optimum: powers [W] (smooth C_m), lengths [mm],
        torque [N m], inertia [kg m^2] (``constant=False``: its constant powers still
        None).
    start : LeanStart
        The next solve's warm start.
    params : DesignParameters
        The solve's parameters (:func:`optimal_case` takes them).

    Raises
    ------
    InputError, InfeasibleError, SolverError
        As :meth:`DesignProblem.solve_isothermal`.
    """
    params = problem.parameters(**overrides)
    ls = lean_solver(problem)
    lo, hi = ls.nlp_bounds(params)[:2]
    x_start = problem.x_case_m if x0 is None else x0.start_m()
    lam = None if x0 is None or x0.lam_x is None else (x0.lam_x, x0.lam_g)
    x_start = clamp(x_start, lo, hi)
    ls.check_feasible(params, x_start)
    nu, rho = params.nu_m2_s, params.rho_kg_m3
    out, stats, x_m, values = run_starts(lambda x, lm: ls.ipopt(params, x, lm), x_start, lam,
                                         lo, hi)  # one start, a failed warm start retried
    p1, tau, J = ls.report(x_m, nu, rho) if values is None else values
    if not (math.isfinite(p1) and math.isfinite(tau) and math.isfinite(J)):
        raise ls.failure(stats, out, params, "non-finite result")
    start = LeanStart(x_m, out["lam_x"].copy(), out["lam_g"].copy())
    R, delta, d_r, d_s, L = x_m.tolist()
    T1, T2, T3, T4 = rotor_stator_radii(R, delta, d_r, d_s)
    mm = 1.0 / MM_TO_M
    rec = LeanRecord(region1_power_W=p1, T=float(groove_roughness(T1, T2, T3, T4)),
                     delta_mm=delta * mm, R_mm=R * mm, L_mm=L * mm, T1_mm=T1 * mm,
                     T2_mm=T2 * mm, T3_mm=T3 * mm, T4_mm=T4 * mm,
                     torque_capability_Nm=tau, inertia_kgm2=J,
                     inertia_ratio=J / problem.inertia_ref_kgm2,
                     torque_min_Nm_used=params.torque_min_Nm,
                     inertia_max_kgm2_used=params.inertia_max_kgm2,
                     active_constraints=" ".join(active_constraints(params, x_m, tau, J)),
                     iterations=int(stats.get("iter_count", -1)),
                     initial_region1_power_W=ls.report(x_start, nu, rho)[0])
    if constant:
        rec = add_constant_powers(problem, [rec], [params])[0]
    return rec, start, params


def region2_powers(problem: DesignProblem, nu_m2_s: np.ndarray, rho_kg_m3: np.ndarray
                   ) -> np.ndarray:
    """Mean power of region 2 (smooth C_m) in many oil states at once [W].

    Parameters
    ----------
    problem : DesignProblem
    nu_m2_s, rho_kg_m3 : array of n floats
        Kinematic viscosity [m^2/s] and density [kg/m^3].

    Returns
    -------
    ndarray of n floats
        :meth:`DesignProblem.region2_power` of each state (equal to rounding) [W].
    """
    nu = np.asarray(nu_m2_s, dtype=float).reshape(-1, 1)
    if problem.case.region2 is None:
        return np.zeros(nu.shape[0])
    rho = np.asarray(rho_kg_m3, dtype=float).reshape(-1, 1)
    return np.asarray(region_mean_power(joint_regions(problem.case)[1], problem.nodes_rad_s,
                                        problem.weights, nu, rho, problem.law),
                      dtype=float).reshape(-1)


def add_constant_powers(problem: DesignProblem, records: list[LeanRecord],
                        params: list[DesignParameters]) -> list[LeanRecord]:
    """Complete records of :func:`solve_lean` (``constant=False``) of one problem: region 2
    (:func:`region2_powers`, all at once) and the bearing added to the optimum's and the
    start's power.

    Parameters
    ----------
    problem : DesignProblem
    records : list of LeanRecord
        Records of ``problem`` whose ``mean_power_W``, ``region2_power_W`` and
        ``initial_mean_power_W`` are still None.
    params : list of DesignParameters
        The solve of each record.

    Returns
    -------
    list of LeanRecord
        The records completed: ``mean_power_W``, ``region2_power_W``,
        ``initial_mean_power_W`` [W].

    Raises
    ------
    SolverError
        A power that is not finite.
    """
    if not records:
        return []
    p2 = region2_powers(problem, [q.nu_m2_s for q in params], [q.rho_kg_m3 for q in params])
    if not np.all(np.isfinite(p2)):
        raise SolverError("non-finite region-2 power")
    out = []
    for rec, q, v in zip(records, params, p2.tolist(), strict=True):
        pb = problem.bearing_power(q.nu_m2_s)
        out.append(replace(rec, mean_power_W=_total(rec.region1_power_W, v, pb),
                           region2_power_W=v,
                           initial_mean_power_W=_total(rec.initial_region1_power_W, v, pb)))
    return out


def optimal_case(problem: DesignProblem, params: DesignParameters, x_m: np.ndarray
                 ) -> DesignCase:
    """The optimum as a case to evaluate: the optimal region 1 (machined groove bottoms
    kept, as :meth:`DesignResult.to_case`) with the solve's oil and operating point.

    Parameters
    ----------
    problem : DesignProblem
    params : DesignParameters
    x_m : array of 5 floats
        (R, delta, d_r, d_s, L) [m].

    Returns
    -------
    DesignCase
    """
    R, delta, d_r, d_s, L = (float(v) for v in x_m)
    T1, T2, T3, T4 = rotor_stator_radii(R, delta, d_r, d_s)
    r1 = RotorStatorClearance(T1, T2, T3, T4, L,
                              T1_unfilled=R - problem.machined_rotor_groove_m,
                              T4_unfilled=T3 + problem.machined_stator_groove_m)
    c = problem.case
    changes: dict[str, Any] = {"region1": r1}
    if not params.raw_oil_state and (  # the solve's oil state, as DesignProblem.case_for
            params.oil != c.oil.name or params.oil_temp_C != c.operating.oil_temp_C
            or params.depth_m != c.operating.depth_m):
        changes["oil"] = c.oil if params.oil_obj is None else params.oil_obj
        changes["operating"] = OperatingPoint(params.depth_m, params.oil_temp_C)
    return replace(c, **changes)


__all__ = ["LeanRecord", "LeanSolver", "LeanStart", "active_constraints", "add_constant_powers",
           "lean_solver", "optimal_case", "region2_powers", "solve_lean"]
