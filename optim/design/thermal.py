"""The design NLP with the oil's own heating: film factor and bulk heat balance.

Under the thermal modes of :mod:`oilgap.model.joint_loss` the NLP of
:mod:`.problem` gains the bulk oil temperature T as a sixth variable
(``w = (x, T)``, ``x = (R, delta, d_r, d_s, L)``)::

    min   P(x, T) = P1(x, T) + P2(T) [+ P_b(T)]       mean viscous power [W]
    s.t.  tau(R, delta, L) >= tau_min,  J(R, d_r, L) <= J_max,  bounds on x
          bulk, full:  (T - T_sea - R_th (P(x, T) + Q)) / 1 K = 0,  T_sea + R_th Q <= T <= 250
          film:        T = the solve's oil temperature (given; no balance)

P1 and P2 are :func:`~oilgap.model.joint_loss.joint_mean_power` of region 1 built
from the symbolic design (:func:`~oilgap.model.regions.rotor_stator_region`) and of
the bearing region, with the smooth C_m of the isothermal NLP and, under ``film`` and
``full``, the film factor at T (nu, rho and b = -d ln mu/dT from the oil's own law at
the symbolic T); under ``bulk`` the loss is the isothermal film's at T (no film factor,
the default with ``[thermal]``). ``bulk`` and ``full`` carry the heat balance of
:mod:`oilgap.model.thermal` as an equality: a design that loses less also runs
colder, so its oil is more viscous [1, 2]. CasADi gives IPOPT exact first and second
derivatives [3].

P_b is the case's rolling bearing (``[bearing]``; absent without one): its friction and
drag at the bulk viscosity (:func:`~oilgap.model.bearing.bearing_mean_power`, no film
factor) [5], what ``joint_mean_power`` adds with ``include_bearing``. It does not depend
on the design, but under ``bulk``/``full`` its heat goes into the balance, so it warms the oil
and thins it for the clearances too.

Under ``film`` the oil temperature is given: the NLP has the five design variables and
the oil state (nu, rho, b) at that temperature as parameters, like the isothermal NLP's
(nu, rho), so any fluid serves, and P1, P2 are :func:`~oilgap.model.regions.
region_mean_power` with the film (what ``joint_mean_power`` composes). Since no
constraint depends on T, ``dP*/dT_oil`` is dP/dT at the optimal design (envelope
theorem [4]). Under ``bulk``/``full`` T_sea, R_th and Q are parameters: one NLP per (oil, depth),
re-solved without rebuilding; the fluid's law must be CasADi's (not a table).

Scaling: y as :mod:`.variables`, ``t = T / 10 K``; the objective is ln P and the
balance is in kelvin. The multiplier lam of the balance gives what a kelvin of sea
temperature costs: ``dP*/dT_sea = -lam P* / 1 K`` (ln P is the objective and
d(residual)/dT_sea = -1 K/K) [4].
The start design's temperature is its own balance (the model's fixed point,
:func:`~oilgap.model.thermal.steady_temperature` with the base T_sea + R Q as in
:func:`~oilgap.model.thermal.joint_steady_temperature`); after IPOPT the temperature
is polished by Newton steps on the optimal design's balance to 1e-11 K (IPOPT leaves
it within about 1e-9 K), so the reported state satisfies it to round-off.

References
----------
.. [1] R. Nahme, 1940; J. Gavis, R. L. Laurence, Ind. Eng. Chem. Fundam.
   7(2):232-239, 1968 (the heated film, :mod:`oilgap.model.film_cycle`).
.. [2] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed.,
   Wiley 2011, sec. 3.1 (the bulk balance, :mod:`oilgap.model.thermal`).
.. [3] J. A. E. Andersson et al., "CasADi: a software framework for nonlinear
   optimization and optimal control", Math. Prog. Comp. 11:1-36, 2019.
.. [4] J. Nocedal, S. J. Wright, *Numerical Optimization*, 2nd ed., Springer 2006,
   sec. 12.8 (multipliers as sensitivities of the optimal value).
.. [5] SKF's frictional-moment model; Palmgren's load-independent/load-dependent pair
   (:mod:`oilgap.model.bearing`, its references).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import casadi as ca
import numpy as np

from oilgap.model.bearing import bearing_mean_power
from oilgap.model.case import ThermalSpec
from oilgap.model.errors import InputError, SolverError
from oilgap.model.joint_loss import THERMAL_MODES, case_film, joint_mean_power, uses_balance
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.regions import joint_regions, region_mean_power, rotor_stator_region
from oilgap.model.thermal import MAX_OIL_TEMP_C, require_balanced, steady_temperature
from oilgap.model.units import MM_TO_M, celsius_to_kelvin

from .parameters import DesignParameters
from .results import (
    DesignPoint,
    DesignResult,
    ThermalDesignResult,
    convert_multipliers,
    design_point,
    start_point,
)
from .session import (
    DEFAULT_STARTS,
    SolveOutput,
    SolverSession,
    check_starts,
    clamp,
    run_starts,
    snap_to_bounds,
    solver_failure,
)
from .variables import LOG_VARIABLES, VARIABLE_LABELS, VARIABLES, from_nlp, to_nlp

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .problem import DesignProblem

TEMP_SCALE_K = 10.0
"""The NLP's temperature variable is ``T / TEMP_SCALE_K`` (T in degC) [K]."""

BALANCE_SCALE_K = 1.0
"""The heat-balance equality is its residual over this [K]."""

BALANCE_TOL_K = 1e-11
"""Tolerance of the temperature polished on the optimal design's balance [K]."""


@dataclass
class _ThermalNLP:
    """The NLP of one (oil, depth): its solver session and functions of (y, q).

    ``q`` is what the loss depends on besides the design: ``t = T / TEMP_SCALE_K``
    under bulk/full, the oil state (nu [m^2/s], rho [kg/m^3], b [1/K]) under film."""

    session: SolverSession
    parts: Any
    """(y, q) -> (P1 [W], P2 [W], P_b [W], tau [N m], J [kg m^2]) (P_b = 0 without a
    bearing)."""
    oil: Any
    pressure_Pa: float
    """Gauge pressure of the oil [Pa]."""
    loss2: Any = None
    """bulk/full: (y, row of two t) -> P1 + P2 + P_b [W] at both."""
    balance: Any = None
    """bulk/full: (y, t, p) -> (residual [BALANCE_SCALE_K], its derivative in T [1/K])."""

    def q(self, temp_C: float) -> np.ndarray:
        """``q`` at a bulk temperature [degC] (film: the oil's own law there, numpy)."""
        if self.loss2 is not None:
            return np.array([temp_C / TEMP_SCALE_K])
        t_k = celsius_to_kelvin(float(temp_C))
        nu, _, rho = self.oil.properties(t_k, self.pressure_Pa)
        return np.array([float(nu), float(rho),
                         float(self.oil.temperature_slope(t_k, self.pressure_Pa))])


class ThermalDesignProblem:
    """The design NLP of a case under a thermal mode, built once and re-solved.

    Built by :class:`~oilgap.optim.design.DesignProblem` with ``thermal="bulk"``,
    ``"film"`` or ``"full"`` (its ``heated`` attribute; its
    :meth:`~oilgap.optim.design.DesignProblem.solve` solves this NLP). The bounds, limits,
    start points and feasibility check are those of the isothermal problem, which also
    solves the case without heating.

    Parameters
    ----------
    isothermal : DesignProblem
        The case's isothermal problem.
    mode : str
        ``"bulk"``, ``"film"`` or ``"full"`` (checked against the case).
    verbose : bool
        Let IPOPT print its iterations.

    Attributes
    ----------
    mode : str
        The thermal mode.
    build_time_s : float
        Time to build the thermal NLP [s].

    Raises
    ------
    InputError
        An unknown mode, ``none``, ``bulk``/``full`` without ``[thermal]``, or an oil whose
        law CasADi cannot differentiate.

    Examples
    --------
    >>> from oilgap.model.io.case_io import seed_case
    >>> from oilgap.optim.design import DesignProblem
    >>> prob = DesignProblem(seed_case(), thermal="film")      # doctest: +SKIP
    >>> res = prob.solve()                                     # doctest: +SKIP
    >>> res.optimal.mean_power_W, res.oil_temp_cost_W_per_K    # doctest: +SKIP
    """

    def __init__(self, isothermal: DesignProblem, mode: str, verbose: bool = False):
        # the mode as DesignProblem resolved it (resolve_thermal_mode): resolved once
        self.mode = mode
        if mode == "none" or mode not in THERMAL_MODES:
            raise InputError("thermal", mode, "'bulk', 'film' or 'full' here (the isothermal "
                             "problem is DesignProblem's own)", "optimize")
        self.isothermal = isothermal
        self.case = isothermal.case
        self.verbose = bool(verbose)
        t0 = time.perf_counter()
        self._nlps: dict[tuple, _ThermalNLP] = {}
        self._nlp_for(self.case.oil, self.case.operating.depth_m)
        self.build_time_s = time.perf_counter() - t0

    def _nlp_for(self, oil, depth_m: float) -> _ThermalNLP:
        """The NLP of ``oil`` at ``depth_m`` [m], built on first use."""
        key = (oil.name, id(oil), float(depth_m))
        if key not in self._nlps:
            self._nlps[key] = self._build(oil, float(depth_m))
        return self._nlps[key]

    def _build(self, oil, depth_m: float) -> _ThermalNLP:
        """The scaled CasADi NLP (module docstring) and its IPOPT solver."""
        iso = self.isothermal
        m = self.case.motor
        y = ca.SX.sym("y", 5)  # as the isothermal NLP (.variables)
        R, delta, d_r, d_s, L = ((ca.exp(y[i]) if LOG_VARIABLES[i] else y[i]) * MM_TO_M
                                 for i in range(5))
        case = replace(self.case, oil=oil, friction=iso.law)
        regions = (rotor_stator_region(R, delta, d_r, d_s, L), *joint_regions(case)[1:])
        full = uses_balance(self.mode)
        has_bearing = case.bearing is not None
        if full:
            q = ca.SX.sym("t")  # T / TEMP_SCALE_K, T in degC
            try:
                powers = [joint_mean_power(case, q * TEMP_SCALE_K, self.mode, depth_m,
                                           regions=(r,)) for r in regions]
                pb = (joint_mean_power(case, q * TEMP_SCALE_K, self.mode, depth_m,
                                       regions=(), include_bearing=True)
                      if has_bearing else ca.SX(0))
            except (TypeError, NotImplementedError, RuntimeError) as e:
                raise InputError("oil", oil.name, "a fluid whose viscosity law CasADi can "
                                 f"differentiate (thermal {self.mode} carries the temperature; "
                                 f"'film' takes any fluid): {e}", "optimize") from None
        else:  # film at a given temperature: the oil state (nu, rho, b) is a parameter
            q = ca.SX.sym("q", 3)
            nodes, weights = case.duty_cycle.speed_distribution()
            powers = [region_mean_power(r, ca.DM(nodes), weights, q[0], q[1], iso.law,
                                        case_film(case), q[2]) for r in regions]
            pb = (bearing_mean_power(case.bearing, ca.DM(nodes), weights, q[0])
                  if has_bearing else ca.SX(0))
        p1, p2 = powers[0], (powers[1] if len(powers) > 1 else ca.SX(0))
        loss = p1 + p2 + pb if has_bearing else p1 + p2  # the one objective and heat
        tau = motor_torque(m, R, delta, L)[0]
        J = rotor_inertia(m, R, d_r, L, iso.machined_rotor_groove_m)
        g = [ca.log(tau / iso.tau_ref_Nm), ca.log(J / iso.inertia_ref_kgm2)]
        p = ca.SX.sym("p", 3)  # bulk/full: (T_sea [degC], R_th [K/W], Q [W])
        balance = (q * TEMP_SCALE_K - p[0] - p[1] * (loss + p[2])) / BALANCE_SCALE_K
        nlp = ({"x": ca.vertcat(y, q), "p": p, "f": ca.log(loss),
                "g": ca.vertcat(*g, balance)} if full else
               {"x": y, "p": q, "f": ca.log(loss), "g": ca.vertcat(*g)})
        session = SolverSession(f"oilgap_design_{self.mode}", nlp, self.verbose)
        parts = ca.Function("parts", [y, q], [ca.vertcat(p1, p2, pb, tau, J)])
        out = _ThermalNLP(session, parts, oil, float(seawater_gauge_pressure(depth_m)))
        if full:
            out.loss2 = ca.Function("loss", [y, q], [loss]).map(2)
            out.balance = ca.Function("balance", [y, q, p],
                                      [balance, ca.jacobian(balance, q) / TEMP_SCALE_K])
        return out

    # ----------------------------------------------------------------- numbers

    def thermal_spec(self, sea_temp_C: float | None = None,
                     resistance_K_W: float | None = None,
                     other_heat_W: float | None = None) -> ThermalSpec | None:
        """The heat balance of a solve: the case's ``[thermal]`` with overrides.

        Parameters
        ----------
        sea_temp_C : float, optional
            Sea temperature [degC].
        resistance_K_W : float, optional
            Thermal resistance oil to sea [K/W].
        other_heat_W : float, optional
            Other heat deposited in the oil [W].

        Returns
        -------
        ThermalSpec or None
            None under ``film`` (which has no balance).

        Raises
        ------
        InputError
            An override under ``film``, or out of range (ThermalSpec's checks).
        SolverError
            ``T_sea + R Q`` at or above :data:`~oilgap.model.thermal.MAX_OIL_TEMP_C`: no
            design balances (:func:`~oilgap.model.thermal.require_balanced`).
        """
        given = {k: v for k, v in (("sea_temp_C", sea_temp_C),
                                   ("resistance_K_W", resistance_K_W),
                                   ("other_heat_W", other_heat_W)) if v is not None}
        if not uses_balance(self.mode):
            if given:
                k = next(iter(given))
                raise InputError(k, given[k], "only with thermal mode 'bulk' or 'full'",
                                 "optimize")
            return None
        spec = replace(self.case.thermal, **{k: float(v) for k, v in given.items()})
        # T_sea + R Q at or above the cap: no design balances (a solver failure, exit 4,
        # as evaluate's; issue 20 class 5)
        require_balanced(spec.sea_temp_C + spec.resistance_K_W * spec.other_heat_W, spec,
                         self.case.oil.trusted_range_C)
        return spec

    def point(self, x_m: Sequence[float], oil_temp_C: float | None = None,
              **thermal: float) -> tuple[DesignPoint, float]:
        """A design's heated DesignPoint and its oil temperature, at the case's oil and depth.

        Parameters
        ----------
        x_m : sequence of 5 floats
            (R, delta, d_r, d_s, L) [m].
        oil_temp_C : float, optional
            Bulk oil temperature [degC] (default: the case's under ``film``, the
            design's own balance under ``bulk``/``full``).
        **thermal
            ``sea_temp_C``, ``resistance_K_W``, ``other_heat_W`` (:meth:`thermal_spec`).

        Returns
        -------
        point : DesignPoint
            Powers [W] at the temperature (the film factor under ``film``/``full``),
            smooth C_m.
        oil_temp_C : float
            The temperature used [degC].
        """
        nlp = self._nlp_for(self.case.oil, self.case.operating.depth_m)
        x = np.asarray(x_m, dtype=float)
        if oil_temp_C is None:
            oil_temp_C = self._temperature(nlp, x, self.thermal_spec(**thermal),
                                           self.case.operating.oil_temp_C)
        return self._point(nlp, x, float(oil_temp_C)), float(oil_temp_C)

    def _point(self, nlp: _ThermalNLP, x_m: np.ndarray, temp_C: float) -> DesignPoint:
        p1, p2, pb, tau, J = (float(v) for v in self._parts(nlp, x_m, temp_C))
        return design_point(x_m, p1, tau, J, p2, self.case.motor,
                            self.isothermal.inertia_ref_kgm2,
                            None if self.case.bearing is None else pb)

    @staticmethod
    def _parts(nlp: _ThermalNLP, x_m: np.ndarray, temp_C: float) -> np.ndarray:
        """(P1, P2, P_b [W], tau [N m], J [kg m^2]) of design ``x_m`` [m] at ``temp_C``."""
        return np.asarray(nlp.parts(to_nlp(x_m), nlp.q(temp_C))).ravel()

    def _temperature(self, nlp: _ThermalNLP, x_m: np.ndarray, spec: ThermalSpec | None,
                     oil_temp_C: float, guess_C: float | None = None) -> float:
        """Oil temperature of a design [degC]: ``oil_temp_C`` (film) or the root of its
        balance ``T = T_sea + R (P(T) + Q)`` (bulk/full).

        From a close ``guess_C`` (IPOPT's T), Newton steps with the balance's exact slope
        to :data:`BALANCE_TOL_K`; otherwise (or should they stall) the model's safeguarded
        fixed point, :func:`~oilgap.model.thermal.steady_temperature` with the base
        T_sea + R Q (as :func:`~oilgap.model.thermal.joint_steady_temperature`)."""
        if spec is None:
            return float(oil_temp_C)
        y = to_nlp(x_m)
        if guess_C is not None:
            t, prm = guess_C / TEMP_SCALE_K, [spec.sea_temp_C, spec.resistance_K_W,
                                                spec.other_heat_W]
            for _ in range(4):
                h, dh = (float(v) for v in nlp.balance(y, t, prm))
                if abs(h) * BALANCE_SCALE_K <= BALANCE_TOL_K:
                    return float(t * TEMP_SCALE_K)
                t -= h / (dh * TEMP_SCALE_K)

        def power_at(ts):
            t = np.asarray(ts, dtype=float) / TEMP_SCALE_K
            return np.asarray(nlp.loss2(y, np.resize(t, 2)[None, :])).ravel()[:t.size]

        temps, _ = steady_temperature(
            power_at, spec.sea_temp_C + spec.resistance_K_W * spec.other_heat_W,
            spec.resistance_K_W, 1, tol_K=BALANCE_TOL_K)
        require_balanced(temps, spec, self.case.oil.trusted_range_C, power_at(temps))
        return float(temps[0])

    # ----------------------------------------------------------------- solve

    def solve(self, x0: DesignResult | DesignPoint | Sequence[float] | None = None, *,
              warm_start_duals: bool = True, starts: int = DEFAULT_STARTS, seed: int = 0,
              sea_temp_C: float | None = None, resistance_K_W: float | None = None,
              other_heat_W: float | None = None, **overrides: Any) -> ThermalDesignResult:
        """Solve the thermal NLP; return the optimum or raise.

        Parameters
        ----------
        x0 : DesignResult, DesignPoint, sequence of (R, delta, d_r, d_s, L) [m], or None
            Start point (default: the case's design); a ThermalDesignResult of the same
            mode also warm-starts the multipliers unless ``warm_start_duals`` is False
            (retried from the primal point alone should that fail).
        warm_start_duals : bool
            Use the multipliers of a ThermalDesignResult ``x0``.
        starts : int
            Start points: ``x0`` and ``starts - 1`` uniform random points in the bounds
            (numpy generator ``seed``); the best optimum is returned.
        seed : int
            Seed of the random start points.
        sea_temp_C, resistance_K_W, other_heat_W : float, optional
            Overrides of the balance (bulk/full only): [degC], [K/W], [W].
        **overrides
            As :meth:`DesignProblem.solve <oilgap.optim.design.DesignProblem.solve>`,
            except nu/rho given directly (the film needs the oil's law) and, under
            ``bulk``/``full``, ``oil_temp_C`` (a result of the balance).

        Returns
        -------
        ThermalDesignResult
            The (best) optimum: powers [W], lengths [m], oil temperature [degC],
            multipliers, ``sea_temp_cost_W_per_K`` [W/K] (bulk/full).

        Raises
        ------
        InputError
            A bad override.
        InfeasibleError
            No design meets the torque and inertia limits (checked before IPOPT).
        SolverError
            IPOPT failed.
        """
        spec = self.thermal_spec(sea_temp_C, resistance_K_W, other_heat_W)
        for k in ("nu_m2_s", "rho_kg_m3"):
            if overrides.get(k) is not None:
                raise InputError(k, overrides[k], f"not with thermal mode '{self.mode}' (the "
                                 "film needs the oil's law: give oil, oil_temp_C, depth_m)",
                                 "optimize")
        if spec is not None and overrides.get("oil_temp_C") is not None:
            raise InputError("oil_temp_C", overrides["oil_temp_C"], "not with thermal mode "
                             f"'{self.mode}': the oil temperature is the heat balance's "
                             "result (give sea_temp_C)", "optimize")
        check_starts(starts)
        iso = self.isothermal
        params = iso.parameters(**overrides)
        nlp = self._nlp_for(params.oil_obj or self.case.oil, params.depth_m)
        x_start, lam = start_point(x0, iso.x_case_m, warm_start_duals)
        if lam is not None and (not isinstance(x0, ThermalDesignResult) or
                                x0.thermal_mode != self.mode):
            lam = None  # multipliers of another NLP
        x_start = clamp(x_start, params.lower_m, params.upper_m)
        iso.check_feasible(params, x_start)
        best = run_starts(lambda x, lm: self._solve_from(params, spec, nlp, x, lm), x_start,
                          lam, params.lower_m, params.upper_m, starts, seed)
        if starts == 1:
            return best
        t0 = self._temperature(nlp, x_start, spec, params.oil_temp_C)
        return replace(best, starts=starts, initial=self._point(nlp, x_start, t0),
                       initial_oil_temp_C=t0)

    def _args(self, params: DesignParameters, spec: ThermalSpec | None, nlp: _ThermalNLP,
              x_start: np.ndarray, t_start: float) -> dict:
        """nlpsol's arguments: start, parameters, bounds (module docstring)."""
        y0, ylo, yhi = (to_nlp(np.asarray(v)) for v in (x_start, params.lower_m,
                                                         params.upper_m))
        lbg, ubg = self.isothermal.constraint_bounds(params)
        if spec is None:  # film: the oil state at the solve's temperature, no balance
            return {"x0": y0, "p": nlp.q(params.oil_temp_C), "lbx": ylo, "ubx": yhi,
                    "lbg": lbg, "ubg": ubg}
        t_lo = (spec.sea_temp_C + spec.resistance_K_W * spec.other_heat_W) / TEMP_SCALE_K
        return {"x0": np.append(y0, t_start / TEMP_SCALE_K),
                "p": [spec.sea_temp_C, spec.resistance_K_W, spec.other_heat_W],
                "lbx": np.append(ylo, t_lo), "ubx": np.append(yhi, MAX_OIL_TEMP_C / TEMP_SCALE_K),
                "lbg": [*lbg, 0.0], "ubg": [*ubg, 0.0]}

    def _solve_from(self, params: DesignParameters, spec: ThermalSpec | None,
                    nlp: _ThermalNLP, x_start: np.ndarray, lam) -> ThermalDesignResult:
        """One IPOPT solve from ``x_start`` [m] (and multipliers ``lam``)."""
        lo, hi = np.asarray(params.lower_m), np.asarray(params.upper_m)
        t_start = self._temperature(nlp, x_start, spec, params.oil_temp_C)
        initial = self._point(nlp, x_start, t_start)
        args = self._args(params, spec, nlp, x_start, t_start)
        out = nlp.session.solve(lam=lam, **args)
        if not out.ok:
            raise self._failure(out, params)
        w = out.x
        ylo, yhi = args["lbx"][:5], args["ubx"][:5]
        _, x_m = snap_to_bounds(w[:5], ylo, yhi, lo, hi, from_nlp)
        full = spec is not None
        temp = self._temperature(nlp, x_m, spec, params.oil_temp_C,  # polished on x*
                                 guess_C=float(w[5] * TEMP_SCALE_K) if full else None)
        optimal = self._point(nlp, x_m, temp)
        lam_x, lam_g = out.lam_x, out.lam_g
        total = optimal.mean_power_W
        mults, active = convert_multipliers(params, optimal, lam_x[:5], lam_g[:2],
                                            objective_W=total)
        if full:
            costs = {"sea_temp_cost_W_per_K": float(-lam_g[2] * total / BALANCE_SCALE_K),
                     "balance_residual_K": float(out.g[2] * BALANCE_SCALE_K)}
        else:  # envelope theorem: no constraint depends on T, so dP*/dT = dP/dT at x*
            h = 1e-2
            costs = {"oil_temp_cost_W_per_K": float(
                (self._parts(nlp, x_m, temp + h)[:3].sum()
                 - self._parts(nlp, x_m, temp - h)[:3].sum()) / (2 * h))}
        case = self.isothermal.case_for(params)
        return ThermalDesignResult(
            status=out.status, success=True, iterations=out.iterations, solve_time_s=out.time_s,
            initial=initial, optimal=optimal, active_constraints=active,
            multipliers=mults, parameters=params,
            case=replace(case, thermal=spec) if full else case,
            machined_rotor_groove_m=self.isothermal.machined_rotor_groove_m,
            machined_stator_groove_m=self.isothermal.machined_stator_groove_m,
            starts=1, _raw={"lam_x": lam_x, "lam_g": lam_g}, thermal_mode=self.mode,
            initial_oil_temp_C=t_start, oil_temp_C=temp,
            sea_temp_C=spec.sea_temp_C if full else None, thermal=spec, **costs)

    def _failure(self, out: SolveOutput, params: DesignParameters) -> SolverError:
        """The SolverError of a failed solve, with its last iterate in physical units."""
        w, gv = out.x, out.g
        last = {VARIABLE_LABELS[v][0]: float(xv) for v, xv in
                zip(VARIABLES, from_nlp(w[:5]) / MM_TO_M, strict=True)}
        last["oil_temp_C"] = (float(w[5] * TEMP_SCALE_K) if uses_balance(self.mode)
                              else float(params.oil_temp_C))
        last["torque_capability_Nm"] = float(np.exp(gv[0]) * self.isothermal.tau_ref_Nm)
        last["inertia_kgm2"] = float(np.exp(gv[1]) * self.isothermal.inertia_ref_kgm2)
        last["mean_power_W"] = float(np.exp(out.f))
        if uses_balance(self.mode):
            last["balance_residual_K"] = float(gv[2] * BALANCE_SCALE_K)
        return solver_failure(out.status, out.iterations, last,
                              f"the design NLP under thermal {self.mode}")


__all__ = ["BALANCE_SCALE_K", "TEMP_SCALE_K", "ThermalDesignProblem"]
