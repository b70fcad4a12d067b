"""The robust design NLP under the ``bulk`` thermal mode: one oil temperature per scenario.

Under ``bulk`` the oil of each scenario runs at the bulk temperature of its own heat
balance to the sea (:mod:`oilgap.model.thermal`): a design that loses less also runs
colder, so its oil is more viscous. The robust NLP therefore carries N temperatures
u_i = T_i / 10 K besides the design y and one equality per scenario::

    L_i(y, T_i) = joint_mean_power(case_i, T_i, "bulk", regions = (region 1 of y, ...))
    (T_i - T_sea,i - R_th (L_i + Q)) / 1 K = 0,    T_sea,i + R_th Q <= T_i <= 250 degC

with case_i the scenario's case (:func:`~oilgap.model.uncertain.apply_inputs`, the smooth
C_m): its oil by ``nu40_factor``/``nu100_factor`` (or the uniform factor), its depth,
gamma, C_m scale, bearing drag scale,
peak speed and, for ``oil_temp_C``, the sea temperature moved by the same amount. The
loss is the model's own composition (:func:`~oilgap.model.joint_loss.joint_mean_power`,
the one the nominal thermal NLP uses, :mod:`~oilgap.optim.design.thermal`), one SX function per
scenario; the NLP strings the N calls together in MX and CasADi derives its exact first and
second derivatives (no hand assembly: cost is not the target here). Statistics as
:mod:`.robust_nlp`; the geometry rows are the same (the third, the nominal loss bound of
the Pareto, is inactive: under ``bulk`` the Pareto is not offered). Seed paper [1],
heat balance [2].

References
----------
.. [1] *Modeling and Optimization of Compensating Oil Viscous Power for a Deep-Sea
   Electric Manipulator* (the seed paper), Eqs. 4-10.
.. [2] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 3.1 (the bulk balance).
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

import casadi as ca
import numpy as np

from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.joint_loss import joint_mean_power, operating_temperature
from oilgap.model.regions import joint_regions, rotor_stator_region
from oilgap.model.thermal import MAX_OIL_TEMP_C
from oilgap.model.uncertain import apply_inputs

from .robust_nlp import CVAR_ALPHA, EPS_VAR, _design, _geometry_functions
from .scenarios import check_scenarios, design_case

TEMP_SCALE_K = 10.0
"""The NLP's temperature variables are T / TEMP_SCALE_K (T in degC) [K]."""


@dataclass(frozen=True, kw_only=True)
class BulkNLP:
    """The robust NLP under ``bulk``.

    Attributes
    ----------
    nlp : dict
        ``x`` = (y, u_1..u_N[, t, s_1..s_N]), ``p``, ``f``, ``g`` (MX) [-].
    cases : tuple of DesignCase
        Each scenario's case (smooth C_m).
    u_bounds : (ndarray, ndarray)
        Bounds of u_i = T_i / 10 K [-].
    report : casadi.Function
        (y, u) -> losses [W] (N x 1).
    """

    nlp: dict
    cases: tuple
    u_bounds: tuple
    report: ca.Function


def scenario_cases(case: Any, scenarios: Mapping[str, Any]) -> tuple:
    """Each scenario's case under ``bulk`` (smooth C_m), through ``apply_inputs``.

    Parameters
    ----------
    case : DesignCase
        The nominal case (with ``[thermal]``).
    scenarios : mapping of str -> array
        Input name -> N values [the inputs' units].

    Returns
    -------
    tuple of DesignCase
    """
    vals = {k: v for k, v in check_scenarios(scenarios).items() if k != "film_strength"}
    n = next(iter(vals.values())).size if vals else 0
    smooth = replace(case, friction=case.friction.smooth())
    return tuple(apply_inputs(smooth, {k: float(v[i]) for k, v in vals.items()})
                 for i in range(n))


def start_temperatures(cases: tuple, x_m: np.ndarray, machined_m: tuple) -> np.ndarray:
    """Each scenario's balance temperature at design ``x_m`` (the scalar path) [degC].

    Parameters
    ----------
    cases : tuple of DesignCase
        The scenarios' cases.
    x_m : ndarray
        (R, delta, d_r, d_s, L) [m].
    machined_m : (float, float)
        Machined groove depths [m].

    Returns
    -------
    ndarray
        T_i [degC] (:func:`~oilgap.model.joint_loss.operating_temperature`).
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        return np.array([operating_temperature(design_case(c, x_m, machined_m), "bulk")
                         .oil_temp_C for c in cases])


def build_bulk_nlp(problem: Any, scenarios: Mapping[str, Any], statistic: str,
                   loss_ref_W: float) -> BulkNLP:
    """The scaled robust NLP under ``bulk`` (module docstring).

    Parameters
    ----------
    problem : DesignProblem
        The nominal problem (motor, references); its case has ``[thermal]``.
    scenarios : mapping of str -> array
        N values of each uncertain input [their units].
    statistic : str
        ``mean``, ``mean+2sd`` or ``p95``.
    loss_ref_W : float
        Reference loss [W].

    Returns
    -------
    BulkNLP

    Raises
    ------
    InputError
        No ``[thermal]``, or an oil whose law CasADi cannot differentiate.
    """
    if problem.case.thermal is None:
        raise InputError("thermal", "bulk", "a case with a [thermal] table", "optimize")
    cases = scenario_cases(problem.case, scenarios)
    n = len(cases)
    ys, us = ca.SX.sym("y", 5), ca.SX.sym("u")
    x = _design(ys)
    fns, lo, hi = [], [], []
    for i, c in enumerate(cases):
        regions = (rotor_stator_region(*x), *joint_regions(c)[1:])
        try:
            loss = joint_mean_power(c, us * TEMP_SCALE_K, "bulk", regions=regions,
                                    include_bearing=True)
        except (TypeError, NotImplementedError, RuntimeError) as e:
            raise InputError("oil", c.oil.name, "a fluid whose viscosity law CasADi can "
                             f"differentiate (bulk carries the temperature): {e}",
                             "optimize") from None
        fns.append(ca.Function(f"bulk_loss_{i}", [ys, us], [loss]))
        th = c.thermal
        lo.append((th.sea_temp_C + th.resistance_K_W * th.other_heat_W) / TEMP_SCALE_K)
        hi.append(MAX_OIL_TEMP_C / TEMP_SCALE_K)
    geo, _ = _geometry_functions(problem, loss_ref_W)
    y, u = ca.MX.sym("y", 5), ca.MX.sym("u", n)
    losses = ca.vertcat(*[fns[i](y, u[i]) for i in range(n)])
    ell = losses / loss_ref_W
    g_geo = geo(y)[0]
    bal = ca.vertcat(*[(u[i] * TEMP_SCALE_K - c.thermal.sea_temp_C - c.thermal.resistance_K_W
                        * (losses[i] + c.thermal.other_heat_W)) for i, c in enumerate(cases)])
    m = ca.sum1(ell) / n
    w, g = ca.vertcat(y, u), [g_geo, bal]
    if statistic == "mean":
        f = ca.log(m)
    elif statistic == "mean+2sd":
        f = ca.log(m + 2 * ca.sqrt(ca.sumsqr(ell - m) / (n - 1) + EPS_VAR))
    else:
        t, s = ca.MX.sym("t"), ca.MX.sym("s", n)
        w = ca.vertcat(w, t, s)
        f = t + ca.sum1(s) / (n * (1.0 - CVAR_ALPHA))
        g.append(ell - t - s)
    report = ca.Function("bulk_report", [y, u], [losses])
    return BulkNLP(nlp={"x": w, "p": ca.MX.sym("p", 0), "f": f, "g": ca.vertcat(*g)},
                   cases=cases, u_bounds=(np.array(lo), np.array(hi)), report=report)


__all__ = ["BulkNLP", "TEMP_SCALE_K", "build_bulk_nlp", "scenario_cases",
           "start_temperatures"]
