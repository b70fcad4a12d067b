"""The optimum with and without the oil's heating, side by side, and what changed.

:func:`compare_heating` solves the thermal design NLP
(:class:`~oilgap.optim.design.thermal.ThermalDesignProblem`, mode ``bulk``, ``film``
or ``full``) and the isothermal one (:class:`~oilgap.optim.design.DesignProblem`, the
seed paper's model at the case's oil temperature) with the same limits and bounds,
and :class:`HeatingComparison` lists what heating changes: each design variable,
the loss, the oil temperature and the active constraints. Under ``bulk``/``full`` the
multiplier of the heat balance gives what a kelvin of sea temperature costs
(Nocedal & Wright [1]).

References
----------
.. [1] J. Nocedal, S. J. Wright, *Numerical Optimization*, 2nd ed., Springer 2006,
   sec. 12.8 (multipliers as sensitivities of the optimal value).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from oilgap.model.errors import InputError

from .problem import DesignProblem
from .results import POINT_MEANINGS, DesignResult, ThermalDesignResult
from .session import DEFAULT_STARTS

COMPARED = tuple((k, POINT_MEANINGS[k]) for k in (
    "delta_mm", "R_mm", "L_mm", "rotor_groove_depth_mm", "stator_groove_depth_mm", "T",
    "region1_power_W", "region2_power_W", "bearing_power_W", "mean_power_W",
    "torque_capability_Nm", "inertia_ratio"))
"""Quantities of the optimal DesignPoint compared (key of ``to_dict``, meaning);
``bearing_power_W`` only for a case with a ``[bearing]``."""


@dataclass(frozen=True)
class HeatingComparison:
    """The optimum with heating (a thermal mode) beside the one without (``none``).

    Parameters
    ----------
    heated : ThermalDesignResult
        Optimum of the thermal NLP (``bulk``, ``film`` or ``full``).
    isothermal : DesignResult
        Optimum of the isothermal NLP at the case's oil temperature.
    """

    heated: ThermalDesignResult
    isothermal: DesignResult

    @property
    def mode(self) -> str:
        """The thermal mode of the heated optimum [-]."""
        return self.heated.thermal_mode

    @property
    def isothermal_oil_temp_C(self) -> float:
        """Oil temperature of the isothermal optimum: the solve's (case's) [degC]."""
        return float(self.isothermal.parameters.oil_temp_C)

    def changes(self) -> dict[str, dict[str, float | None]]:
        """Each compared quantity without and with heating, and the change.

        Returns
        -------
        dict
            key (units in the key: ``_mm`` [mm], ``_W`` [W], ``_Nm`` [N m], ``T`` and
            ``inertia_ratio`` [-], ``oil_temp_C`` [degC]) -> ``without_heating``,
            ``with_heating``, ``change`` (with - without, same unit) and
            ``change_pct`` [%] (None where the value without heating is 0).
        """
        a, b = self.isothermal.optimal.to_dict(), self.heated.optimal.to_dict()
        pairs = [(k, a[k], b[k]) for k, _ in COMPARED if k in a and k in b]
        pairs.append(("oil_temp_C", self.isothermal_oil_temp_C, self.heated.oil_temp_C))
        out = {}
        for k, x, y in pairs:
            pct = None if x == 0 or k == "oil_temp_C" else 100.0 * (y - x) / x
            out[k] = {"without_heating": x, "with_heating": y, "change": y - x,
                      "change_pct": pct}
        return out

    def active(self) -> dict[str, list[str]]:
        """Active constraints: of both optima, only with heating, only without.

        Returns
        -------
        dict
            ``both``, ``only_with_heating``, ``only_without_heating``: names of
            constraints and bounds (:attr:`DesignResult.active_constraints`).
        """
        a, b = self.isothermal.active_constraints, self.heated.active_constraints
        return {"both": [n for n in b if n in a],
                "only_with_heating": [n for n in b if n not in a],
                "only_without_heating": [n for n in a if n not in b]}

    def to_dict(self) -> dict[str, Any]:
        """Plain dict for JSON (the ``--json`` output of ``oilgap optimize``).

        Returns
        -------
        dict
            The heated optimum's :meth:`ThermalDesignResult.to_dict`, plus
            ``without_heating`` (the isothermal optimum: status, iterations,
            ``oil_temp_C`` [degC], optimal design, active constraints, multipliers),
            ``heating_changes`` (:meth:`changes`) and ``active_constraints_compared``
            (:meth:`active`).
        """
        d = self.heated.to_dict()
        iso = self.isothermal.to_dict()
        d["without_heating"] = {
            "thermal_mode": "none", "status": iso["status"],
            "iterations": iso["iterations"], "starts": iso["starts"],
            "solve_time_s": iso["solve_time_s"], "oil_temp_C": self.isothermal_oil_temp_C,
            "optimal": iso["optimal"], "active_constraints": iso["active_constraints"],
            "multipliers": iso["multipliers"]}
        d["heating_changes"] = self.changes()
        d["active_constraints_compared"] = self.active()
        return d


def compare_heating(problem: DesignProblem, starts: int = DEFAULT_STARTS, seed: int = 0,
                    **overrides: Any) -> HeatingComparison:
    """Solve the design with and without heating under the same limits and bounds.

    Parameters
    ----------
    problem : DesignProblem
        Built with a thermal mode ``bulk``, ``film`` or ``full`` (``thermal=``): its
        :meth:`~DesignProblem.solve` gives the heated optimum, its
        :meth:`~DesignProblem.solve_isothermal` the one without heating.
    starts : int
        Start points of each solve.
    seed : int
        Seed of the random start points.
    **overrides
        As :meth:`DesignProblem.solve`; the balance overrides (``sea_temp_C``,
        ``resistance_K_W``, ``other_heat_W``) apply to the heated solve only, the others
        to both.

    Returns
    -------
    HeatingComparison
        Both optima: powers [W], lengths [m], oil temperatures [degC].

    Raises
    ------
    InputError
        A problem without a thermal mode, or a bad override.
    InfeasibleError, SolverError
        As the solves.
    """
    if problem.heated is None:
        raise InputError("thermal", problem.thermal_mode, "'bulk', 'film' or 'full' (a "
                         "problem built with a thermal mode)", "optimize")
    heated = problem.solve(starts=starts, seed=seed, **overrides)
    plain = {k: v for k, v in overrides.items()
             if k not in ("sea_temp_C", "resistance_K_W", "other_heat_W")}
    iso = problem.solve_isothermal(starts=starts, seed=seed, **plain)
    return HeatingComparison(heated, iso)


__all__ = ["COMPARED", "HeatingComparison", "compare_heating"]
