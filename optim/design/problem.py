"""The clearance geometry of region 1 as a CasADi/IPOPT nonlinear program.

Problem (variables ``x = (R, delta, d_r, d_s, L)``, :mod:`.variables`)::

    min   P1(x; nu, rho) + P2(nu, rho)          mean viscous power over the duty cycle [W]
    s.t.  tau(R, delta, L)      >= tau_min      torque capability [N m]
          J(R, d_r, L)          <= J_max        rotor inertia with the epoxy fill [kg m^2]
          R_min <= R <= R_max,  delta_min <= delta <= delta_max,  L_min <= L <= L_max
          0 <= d_r <= d_r0,     0 <= d_s <= d_s0  (filling only makes grooves shallower)

with ``P1 = sum_i w_i clearance_power(omega_i, nu, rho, R, delta, L, law_smooth, T)``
over the exact speed distribution (omega_i, w_i) of the duty cycle
(:meth:`DutyCycle.speed_distribution`), the smooth C_m (no ``if_else`` in the
NLP), and P2 the (constant) bearing-annulus power: the objective of :mod:`.objective`,
Eqs. 4-10 of the seed paper [1]. A rolling bearing (``[bearing]``, [5]) adds its friction
and drag, constant in x like P2 (:meth:`DesignProblem.constant_power`). The torque
capability and inertia are :mod:`oilgap.model.motor` (Carter coefficient with slot pitch
2 pi T3 / Q_s, B_g, tau = 2 pi R^2 L k_w B_g A / sqrt 2, grooved rotor with
T1_unfilled = R - d_r0) [2].

Scaling: IPOPT [3] sees the variables of :func:`.variables.to_nlp`, the objective ln P1 and
the constraints ln(tau/tau_ref) >= ln(tau_min/tau_ref), ln(J/J_ref) <= ln(J_max/J_ref)
(tau_ref, J_ref: the case's motor and unfilled rotor), all O(1). The same optimum; the
multipliers go back to d(P*)/d(bound) in physical units (:func:`.results.convert_multipliers`) [4].

The NLP is built once per case (:class:`DesignProblem`); the oil state (nu, rho), tau_min,
J_max and every bound are parameters of each :meth:`DesignProblem.solve` (:mod:`.parameters`),
so studies re-solve it without rebuilding; infeasible limits are caught before IPOPT
(:mod:`.feasibility`).
IPOPT is called through the problem's :class:`~.session.SolverSession` (``session``), as
every design solve is: its start clamp, bound snapping, warm-start retry, multi-start and
failure message are those of :mod:`.session`.

Built with a thermal mode (``thermal="bulk"``, ``"film"``, ``"full"``;
:mod:`~oilgap.optim.design.thermal`) the problem's :meth:`DesignProblem.solve` solves the
NLP of :mod:`~oilgap.optim.design.thermal` instead, which carries the oil temperature as a
variable and the heat balance as an equality;
:meth:`DesignProblem.solve_isothermal` still solves the one above (the optimum without
heating, :func:`~oilgap.optim.design.heating.compare_heating`).

References
----------
.. [1] *Modeling and Optimization of Compensating Oil Viscous Power for a Deep-Sea
   Electric Manipulator* (the seed paper), Eqs. 4-10.
.. [2] J. F. Gieras, *Permanent Magnet Motor Technology*, 3rd ed., 2010, A.27-A.28.
.. [3] A. Wächter, L. T. Biegler, "On the implementation of an interior-point
   filter line-search algorithm for large-scale nonlinear programming",
   Math. Program. 106:25-57, 2006 (IPOPT).
.. [4] J. Nocedal, S. J. Wright, *Numerical Optimization*, 2nd ed., Springer
   2006, sec. 12.8 (multipliers as sensitivities of the optimal value).
.. [5] SKF's frictional-moment model; Palmgren's load-independent/load-dependent pair
   (:mod:`oilgap.model.bearing`, its references).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import casadi as ca
import numpy as np

from oilgap.model.bearing import bearing_mean_power
from oilgap.model.case import DesignCase, OperatingPoint
from oilgap.model.errors import InputError, SolverError
from oilgap.model.evaluation import oil_state
from oilgap.model.io.limits import check_slot_pitch
from oilgap.model.joint_loss import resolved_mode
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.regions import joint_regions, region_mean_power
from oilgap.model.units import MM_TO_M

from .feasibility import check_feasible
from .objective import DesignObjective, region1_mean_power
from .parameters import DesignParameters, _resolve_parameters
from .results import (
    DesignPoint,
    DesignResult,
    convert_multipliers,
    design_point,
    start_point,
)
from .session import (
    DEFAULT_STARTS,
    SolverSession,
    check_starts,
    clamp,
    run_starts,
    snap_to_bounds,
    solver_failure,
)
from .thermal import ThermalDesignProblem
from .variables import LOG_VARIABLES, VARIABLE_LABELS, VARIABLES, from_nlp, to_nlp


def _memo(cache: dict, key: Any, compute: Any) -> float:
    """``cache[key]``, computed by ``compute()`` once (the cache emptied past 4096 keys)."""
    if key not in cache:
        if len(cache) > 4096:
            cache.clear()
        cache[key] = float(compute())
    return cache[key]


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
    thermal : str or None
        Thermal mode (:mod:`oilgap.model.joint_loss`): ``"none"`` (default, the
        isothermal NLP above), ``"bulk"``, ``"film"`` or ``"full"`` (:meth:`solve`
        solves the NLP of :mod:`~oilgap.optim.design.thermal`, which carries the oil
        temperature), None for the default (``bulk`` with ``[thermal]``, else ``none``).

    Attributes
    ----------
    thermal_mode : str
        The thermal mode.
    heated : ThermalDesignProblem or None
        The thermal NLP (None under ``none``).
    x_case_m : ndarray
        The case's design (R, delta, d_r, d_s, L) [m].
    nodes_rad_s, weights : ndarray
        The duty cycle's nonzero speed nodes [rad/s] and their weights [-].
    tau_ref_Nm : float
        The case's torque capability [N m].
    inertia_ref_kgm2 : float
        The case's unfilled rotor's inertia [kg m^2].
    machined_rotor_groove_m, machined_stator_groove_m : float
        Groove depths as machined, d_r0 and d_s0 [m].
    build_time_s : float
        Time to build the NLP [s].

    Examples
    --------
    >>> from oilgap.model.io.case_io import seed_case
    >>> prob = DesignProblem(seed_case())
    >>> res = prob.solve()                        # doctest: +SKIP
    >>> res.optimal.mean_power_W, res.multipliers["torque_min"].value  # doctest: +SKIP
    >>> res2 = prob.solve(x0=res, torque_min_Nm=0.45)  # warm start  # doctest: +SKIP
    """

    def __init__(self, case: DesignCase, verbose: bool = False, thermal: str | None = "none"):
        t0 = time.perf_counter()
        self.thermal_mode = resolved_mode(case, thermal)
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
        check_slot_pitch(m, b.radius_min + b.gap_min, "bounds.radius_min_mm",
                         b.radius_min / MM_TO_M, "the smallest stator bore of the bounds "
                         "(radius_min_mm + gap_min_mm)", "case")
        nodes, weights = case.duty_cycle.speed_distribution()
        keep = nodes > 0.0  # zero speed: |omega|^3 = 0, exactly no power (Eq. 5)
        self.nodes_rad_s = np.ascontiguousarray(nodes[keep])
        self.weights = np.ascontiguousarray(weights[keep])
        self.tau_ref_Nm = float(motor_torque(m, r1.T2, r1.gap, r1.length)[0])
        self.inertia_ref_kgm2 = float(rotor_inertia(m, r1.T2, self.machined_rotor_groove_m,
                                                    r1.length, self.machined_rotor_groove_m))
        self.nu_m2_s, _, self.rho_kg_m3 = (float(v) for v in oil_state(case))
        self._build()
        self._p2_cache: dict[tuple[float, float], float] = {}
        self._bearing_cache: dict[float, float] = {}
        self._point_cache: dict[tuple, DesignPoint] = {}
        self.heated = (None if self.thermal_mode == "none" else
                       ThermalDesignProblem(self, self.thermal_mode, verbose))
        self.build_time_s = time.perf_counter() - t0

    def _build(self) -> None:
        """The CasADi NLP (scaled, :mod:`.variables`), its solver session
        (:class:`.session.SolverSession`) and a report function (P1, tau, J) of (y, p)."""
        m = self.case.motor
        y = ca.SX.sym("y", 5)  # (ln R/mm, ln delta/mm, d_r/mm, d_s/mm, ln L/mm)
        p = ca.SX.sym("p", 2)  # (nu [m^2/s], rho [kg/m^3])
        R, delta, d_r, d_s, L = ((ca.exp(y[i]) if LOG_VARIABLES[i] else y[i]) * MM_TO_M
                                 for i in range(5))
        p1 = region1_mean_power((R, delta, d_r, d_s, L), p[0], p[1], ca.DM(self.nodes_rad_s),
                                self.weights, self.law)
        tau = motor_torque(m, R, delta, L)[0]
        J = rotor_inertia(m, R, d_r, L, self.machined_rotor_groove_m)
        g = ca.vertcat(ca.log(tau / self.tau_ref_Nm), ca.log(J / self.inertia_ref_kgm2))
        self.session = SolverSession("oilgap_design", {"x": y, "p": p, "f": ca.log(p1),
                                                       "g": g}, self.verbose)
        self.report_fn = ca.Function("report", [y, p], [ca.vertcat(p1, tau, J)])
        """(y, (nu, rho)) -> (P1 [W], tau [N m], J [kg m^2])."""

    # ----------------------------------------------------------------- helpers

    @property
    def default_torque_min_Nm(self) -> float:
        """``case.bounds.torque_min_Nm`` or, if unset, the case's own torque capability
        [N m]."""
        t = self.case.bounds.torque_min_Nm
        return self.tau_ref_Nm if t is None else float(t)

    def region2_power(self, nu_m2_s: float, rho_kg_m3: float) -> float:
        """Mean power of region 2 (constant for the design), smooth C_m.

        Parameters
        ----------
        nu_m2_s : float
            Kinematic viscosity [m^2/s].
        rho_kg_m3 : float
            Density [kg/m^3].

        Returns
        -------
        float
            Mean power [W] of the bearing region; 0 if the joint has none.
        """
        if self.case.region2 is None:
            return 0.0
        return _memo(self._p2_cache, (float(nu_m2_s), float(rho_kg_m3)),
                     lambda: region_mean_power(joint_regions(self.case)[1], self.nodes_rad_s,
                                               self.weights, nu_m2_s, rho_kg_m3, self.law))

    def bearing_power(self, nu_m2_s: float) -> float | None:
        """Mean power of the case's rolling bearing (constant for the design).

        Parameters
        ----------
        nu_m2_s : float
            Kinematic viscosity of the oil [m^2/s].

        Returns
        -------
        float or None
            Mean friction and drag power over the duty cycle [W]
            (:func:`~oilgap.model.bearing.bearing_mean_power`); None if the case has
            no ``[bearing]``.

        References
        ----------
        SKF's frictional-moment model or Palmgren's, as the case's ``[bearing]``
        chooses [5].
        """
        if self.case.bearing is None:
            return None
        return _memo(self._bearing_cache, float(nu_m2_s),
                     lambda: bearing_mean_power(self.case.bearing, self.nodes_rad_s,
                                                self.weights, float(nu_m2_s)))

    def constant_power(self, nu_m2_s: float, rho_kg_m3: float) -> float:
        """The mean power the design variables do not change: region 2 and the bearing.

        Parameters
        ----------
        nu_m2_s : float
            Kinematic viscosity [m^2/s].
        rho_kg_m3 : float
            Density [kg/m^3].

        Returns
        -------
        float
            :meth:`region2_power` plus :meth:`bearing_power` (0 without one) [W].
        """
        p2 = self.region2_power(nu_m2_s, rho_kg_m3)
        pb = self.bearing_power(nu_m2_s)
        return p2 if pb is None else p2 + pb

    def point(self, x_m: Sequence[float], nu_m2_s: float | None = None,
              rho_kg_m3: float | None = None) -> DesignPoint:
        """The DesignPoint of a design vector.

        Parameters
        ----------
        x_m : sequence of 5 floats
            (R, delta, d_r, d_s, L) [m].
        nu_m2_s : float, optional
            Kinematic viscosity [m^2/s] (default: the case's oil state).
        rho_kg_m3 : float, optional
            Density [kg/m^3] (default: the case's oil state).

        Returns
        -------
        DesignPoint
        """
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
                           np.asarray(self.report_fn(ca.DM(to_nlp(x_m)),
                                                   ca.DM([nu, rho]))).ravel())
        p1, tau, J = values
        pt = design_point(x_m, p1, tau, J, p2, self.case.motor, self.inertia_ref_kgm2,
                          self.bearing_power(nu))
        if key is not None:
            if len(self._point_cache) > 1024:
                self._point_cache.clear()
            self._point_cache[key] = pt
        return pt

    def objective(self, params: DesignParameters | None = None) -> DesignObjective:
        """The problem's objective and constraint functions on the numpy path.

        Parameters
        ----------
        params : DesignParameters, optional
            A solve's parameters (its oil state); default: the case's oil state.

        Returns
        -------
        DesignObjective
            P1 [W], torque [N m] and inertia [kg m^2] of design vectors [m].
        """
        nu, rho = ((self.nu_m2_s, self.rho_kg_m3) if params is None
                   else (params.nu_m2_s, params.rho_kg_m3))
        return DesignObjective(nodes_rad_s=self.nodes_rad_s, weights=self.weights, law=self.law,
                               motor=self.case.motor,
                               machined_rotor_groove_m=self.machined_rotor_groove_m, nu_m2_s=nu,
                               rho_kg_m3=rho)

    def parameters(self, **overrides: Any) -> DesignParameters:
        """Resolve and validate the parameters of a solve.

        Parameters
        ----------
        **overrides
            As :meth:`solve` (resolved by ``parameters._resolve_parameters``).

        Returns
        -------
        DesignParameters
        """
        return _resolve_parameters(self, **overrides)

    def check_feasible(self, params: DesignParameters, x_hint_m: np.ndarray | None = None
                       ) -> None:
        """Raise InfeasibleError, naming the conflicting constraints, if no design meets
        the torque and inertia limits within the bounds (:func:`.feasibility.check_feasible`).

        Parameters
        ----------
        params : DesignParameters
            Bounds [m] and limits (``torque_min_Nm`` [N m], ``inertia_max_kgm2`` [kg m^2]).
        x_hint_m : array of 5 floats, optional
            A design [m] tried first.

        Returns
        -------
        None
        """
        check_feasible(self.case.motor, self.machined_rotor_groove_m, params, x_hint_m)

    # ----------------------------------------------------------------- solve

    def solve(self, x0: DesignResult | DesignPoint | Sequence[float] | None = None,
              **kwargs: Any) -> DesignResult:
        """Solve the problem's NLP (its thermal mode's); return the optimum or raise.

        Parameters
        ----------
        x0 : DesignResult, DesignPoint, sequence of (R, delta, d_r, d_s, L) [m], or None
            Start point (default: the case's design).
        **kwargs
            As :meth:`solve_isothermal` (mode ``none``) or
            :meth:`ThermalDesignProblem.solve <.thermal.ThermalDesignProblem.solve>`
            (``film``, ``full``: also ``sea_temp_C`` [degC], ``resistance_K_W`` [K/W],
            ``other_heat_W`` [W]).

        Returns
        -------
        DesignResult
            The optimum (a ThermalDesignResult under ``film``/``full``): powers [W],
            lengths [m].
        """
        if self.heated is not None:
            return self.heated.solve(x0, **kwargs)
        return self.solve_isothermal(x0, **kwargs)

    def solve_isothermal(self, x0: DesignResult | DesignPoint | Sequence[float] | None = None,
                         *, warm_start_duals: bool = True, starts: int = DEFAULT_STARTS,
                         seed: int = 0, **overrides: Any) -> DesignResult:
        """Solve the isothermal NLP (the seed's model); return the optimum or raise.

        Parameters
        ----------
        x0 : DesignResult, DesignPoint, sequence of (R, delta, d_r, d_s, L) [m], or None
            Start point (default: the case's design). A DesignResult (e.g. the
            neighbour in a sweep) also warm-starts the multipliers unless
            ``warm_start_duals`` is False; should that warm-started solve fail,
            it is retried from the primal point alone before anything is raised.
        warm_start_duals : bool
            Use the multipliers of a DesignResult ``x0``.
        starts : int
            Number of start points: ``x0`` and ``starts - 1`` points drawn
            uniformly in the bounds (numpy generator ``seed``); the best optimum is
            returned. IPOPT is a local method and warm thin oils near the
            Re = 64 / 500 regime breaks make the loss non-convex, so several
            starts guard against a local optimum.
        seed : int
            Seed of the random start points.
        **overrides
            ``oil`` (an :class:`Oil`), ``oil_temp_C`` [degC], ``depth_m`` [m], or
            ``nu_m2_s`` [m^2/s] and ``rho_kg_m3`` [kg/m^3] directly;
            ``torque_min_Nm`` [N m]; ``inertia_max_ratio`` [-] (of the case's
            unfilled rotor); ``gap_min_m``, ``gap_max_m``, ``radius_min_m``,
            ``radius_max_m``, ``length_min_m``, ``length_max_m`` [m]; ``fix``:
            variables held at the case's value (sequence of names) or at given
            values (mapping name -> [m]), names from :data:`VARIABLES`.

        Returns
        -------
        DesignResult
            The (best) optimum, powers [W] and lengths [m].

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
        x_start, lam = start_point(x0, self.x_case_m, warm_start_duals)
        x_start = clamp(x_start, params.lower_m, params.upper_m)
        check_starts(starts)
        self.check_feasible(params, x_start)
        p2 = self.region2_power(params.nu_m2_s, params.rho_kg_m3)
        best = run_starts(lambda x, lm: self._solve_from(params, x, lm, p2), x_start, lam,
                          params.lower_m, params.upper_m, starts, seed)
        if starts == 1:
            return best
        return replace(best, starts=starts,
                       initial=self._point(x_start, params.nu_m2_s, params.rho_kg_m3, p2))

    def constraint_bounds(self, params: DesignParameters) -> tuple[list, list]:
        """(lbg, ubg) of the scaled torque and inertia constraints (module docstring).

        Parameters
        ----------
        params : DesignParameters
            The limits ``torque_min_Nm`` [N m] and ``inertia_max_kgm2`` [kg m^2].

        Returns
        -------
        lbg, ubg : list of 2 floats
            ln(tau_min/tau_ref) and -inf; inf and ln(J_max/J_ref).
        """
        return ([np.log(params.torque_min_Nm / self.tau_ref_Nm), -np.inf],
                [np.inf, np.log(params.inertia_max_kgm2 / self.inertia_ref_kgm2)])

    def _solve_from(self, params: DesignParameters, x_start: np.ndarray,
                    lam: tuple[np.ndarray, np.ndarray] | None, p2: float) -> DesignResult:
        """One IPOPT solve from ``x_start`` [m] (and multipliers ``lam``)."""
        lo, hi = np.asarray(params.lower_m), np.asarray(params.upper_m)
        nu, rho = params.nu_m2_s, params.rho_kg_m3
        initial = self._point(x_start, nu, rho, p2)
        ylo, yhi = to_nlp(lo), to_nlp(hi)
        out = self.session.solve(to_nlp(x_start), [nu, rho], ylo, yhi,
                                 *self.constraint_bounds(params), lam)
        if not out.ok:
            raise self.failure(out.status, out.iterations, out.x, out.f, out.g, nu, rho)
        y = out.x
        y_in, x_m = snap_to_bounds(y, ylo, yhi, lo, hi, from_nlp)
        values = None
        if np.array_equal(y_in, y):  # IPOPT's f and g are at this very point
            gv = out.g
            values = (float(np.exp(out.f)), float(np.exp(gv[0]) * self.tau_ref_Nm),
                      float(np.exp(gv[1]) * self.inertia_ref_kgm2))
        optimal = self._point(x_m, nu, rho, p2, values)
        if not np.all(np.isfinite([optimal.mean_power_W, optimal.torque_capability_Nm,
                                   optimal.inertia_kgm2])):  # never a non-finite result
            raise self.failure("non-finite result", out.iterations, y, out.f, out.g, nu, rho)
        lam_x, lam_g = out.lam_x, out.lam_g
        mults, active = convert_multipliers(params, optimal, lam_x, lam_g)
        return DesignResult(status=out.status, success=True, iterations=out.iterations,
                            solve_time_s=out.time_s, initial=initial,
                            optimal=optimal, active_constraints=active, multipliers=mults,
                            parameters=params, case=self.case_for(params),
                            machined_rotor_groove_m=self.machined_rotor_groove_m,
                            machined_stator_groove_m=self.machined_stator_groove_m, starts=1,
                            _raw={"lam_x": lam_x, "lam_g": lam_g})

    def failure(self, status: str, iterations: int, y: np.ndarray, f: float, g: np.ndarray,
                nu_m2_s: float, rho_kg_m3: float) -> SolverError:
        """The SolverError of a failed solve, with its last iterate in physical units.

        Parameters
        ----------
        status : str
            IPOPT's return status (or why the result was refused).
        iterations : int
            IPOPT iterations.
        y, f, g : ndarray, float, ndarray
            The last iterate, objective (ln P1) and constraints of the scaled NLP.
        nu_m2_s, rho_kg_m3 : float
            The solve's oil state [m^2/s], [kg/m^3].

        Returns
        -------
        SolverError
            :func:`.session.solver_failure`: R, delta, groove depths, L [mm], torque
            [N m], inertia [kg m^2] and the mean power [W] at the last iterate.
        """
        last = {VARIABLE_LABELS[v][0]: float(xv) for v, xv in
                zip(VARIABLES, from_nlp(y) / MM_TO_M, strict=True)}
        last["torque_capability_Nm"] = float(np.exp(g[0]) * self.tau_ref_Nm)
        last["inertia_kgm2"] = float(np.exp(g[1]) * self.inertia_ref_kgm2)
        pb = self.bearing_power(nu_m2_s)
        last["mean_power_W"] = (float(np.exp(float(f))) + self.region2_power(nu_m2_s, rho_kg_m3)
                                + (pb or 0.0))
        return solver_failure(status, iterations, last)

    def case_for(self, params: DesignParameters) -> DesignCase:
        """The case with the solve's oil and operating point (unchanged for raw nu/rho).

        Parameters
        ----------
        params : DesignParameters
            A solve's parameters.

        Returns
        -------
        DesignCase
        """
        c = self.case
        if params.raw_oil_state:
            return c
        if params.oil != c.oil.name or params.oil_temp_C != c.operating.oil_temp_C or \
                params.depth_m != c.operating.depth_m:
            oil = c.oil if params.oil_obj is None else params.oil_obj
            c = replace(c, oil=oil, operating=OperatingPoint(params.depth_m, params.oil_temp_C))
        return c


def solve_design(case: DesignCase, verbose: bool = False, thermal: str | None = "none",
                 **overrides: Any) -> DesignResult:
    """One-shot: build the NLP of ``case`` and solve it.

    Parameters
    ----------
    case : DesignCase
        The joint.
    verbose : bool
        Let IPOPT print its iterations.
    thermal : str or None
        Thermal mode (``"none"`` default, ``"bulk"``, ``"film"``, ``"full"``; None: the
        default of :func:`~oilgap.model.joint_loss.default_thermal_mode`).
    **overrides
        As :meth:`DesignProblem.solve` (``x0``, ``starts``, the parameters).

    Returns
    -------
    DesignResult
        The optimum: mean powers [W], design lengths [m], multipliers.
    """
    return DesignProblem(case, verbose=verbose, thermal=thermal).solve(**overrides)


__all__ = ["DesignProblem", "solve_design"]
