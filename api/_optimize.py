"""The façade's design function: ``og.optimize`` (``oilgap optimize``), the region-1
clearance geometry of least mean power (:class:`oilgap.optim.design.DesignProblem`)."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

from oilgap._calibrated import with_model
from oilgap._checks import CASE, MODEL, NAME, NUMBER, OILS, checked, choice
from oilgap._evaluate import THERMAL, as_case, thermal_case, with_operating, with_transition
from oilgap._results_design import Optimization, thermal_line
from oilgap._results_linear import LinearOptimization, LinearRobustOptimization
from oilgap._results_robust import RobustOptimization
from oilgap.model.case import DesignCase
from oilgap.model.errors import ArgumentError, InputError, OilgapWarning
from oilgap.model.joint_loss import film_band
from oilgap.model.oils import Oil
from oilgap.model.thermal_modes import ThermalMode
from oilgap.model.transition import TRANSITIONS
from oilgap.optim.design import DesignProblem, compare_heating
from oilgap.optim.design.linear import solve_linear_design
from oilgap.optim.design.linear_robust import solve_linear_robust
from oilgap.optim.design.robust import ROBUST_MODES, check_statistic
from oilgap.studies.robust import RobustSettings, robust_design
from oilgap.studies.settings import DesignLimits


@checked(case=CASE, oil=NAME, oils=OILS, oil_temp_C=NUMBER, depth_m=NUMBER, thermal=THERMAL,
         sea_temp_C=NUMBER, transition=choice(*TRANSITIONS), model=MODEL)
def optimize(case: DesignCase | str | Path | None = None, *, oil: str | None = None,
             oils: dict[str, Oil] | str | Path | None = None,
             oil_temp_C: float | None = None, depth_m: float | None = None,
             thermal: str | None = None, sea_temp_C: float | None = None,
             **keywords: Any) -> Optimization | RobustOptimization:
    """The region-1 geometry (R, delta, groove fill, L) of least mean power under the
    motor's torque, the rotor inertia and the case's bounds (``oilgap optimize``).

    Under ``bulk``/``film``/``full`` the optimum without heating is solved too and shown
    beside it. The initial and optimal designs' film bands
    (:func:`~oilgap.model.joint_loss.film_band`) are reported under every mode.

    Parameters
    ----------
    case : DesignCase, path or None
        The joint (None: the seed joint).
    oil, oils, oil_temp_C, depth_m, thermal, sea_temp_C
        As :func:`oilgap._evaluate.evaluate` (oil temperature [degC], depth [m], sea
        temperature [degC]).
    **keywords
        ``model``: a ``loop.json`` path, a FittedModel or a fitted og.Loop, a calibrated
        loop model folded into the case (``--model``; :func:`oilgap._calibrated.with_model`).
        ``transition``: ``"reynolds"`` or ``"taylor"``, where C_m leaves the laminar law
        (default: the case's; :func:`oilgap._evaluate.with_transition`).
        ``robust``: ``"p95"``, ``"mean"`` or ``"mean+2sd"``: the robust design over
        scenarios of the case's uncertain inputs beside the nominal optimum (thermal modes
        ``none`` and ``bulk``; :func:`oilgap.studies.robust.robust_design`); then also
        ``scenarios`` (N, default 64), ``seed`` (Sobol' seed, default 0), ``mc_samples``
        (independent Monte Carlo draws, default 4096) and ``pareto`` (points of the
        nominal-vs-statistic front, default 0: none). And the fields of
        :class:`~oilgap.studies.settings.DesignLimits`, or ``limits=``,
        the record whole: ``starts`` (start points: the case's design and ``starts - 1``
        random points in the bounds; default
        :data:`~oilgap.studies.settings.DEFAULT_STARTS`, as ``oilgap optimize``),
        ``torque_min_Nm`` (required torque capability [N m]; default: the case's, else
        the initial design's), ``inertia_max_ratio`` (rotor inertia limit over the case's
        unfilled rotor [-]; default: the case's); and ``verbose=True`` to print IPOPT's
        iterations.

    Returns
    -------
    Optimization or RobustOptimization
        ``.raw``: a DesignResult (``none``) or HeatingComparison; with ``robust``, a
        RobustDesign; powers [W].

    Raises
    ------
    InputError, InfeasibleError, SolverError
        Bad input; constraints that conflict; IPOPT failing.
    """
    kw = dict(keywords)
    verbose = bool(kw.pop("verbose", False))
    transition = kw.pop("transition", None)
    model = kw.pop("model", None)
    robust = kw.pop("robust", None)
    robust_kw = {k: kw.pop(k) for k in _ROBUST_KEYWORDS if k in kw}
    if robust is None and robust_kw:
        raise ArgumentError(", ".join(sorted(robust_kw)), robust_kw[min(robust_kw)],
                            "only with robust= (p95, mean or mean+2sd)")
    lim = kw.pop("limits", None)
    unknown = set(kw) - DesignLimits.names()
    if unknown:
        raise ArgumentError(", ".join(sorted(unknown)), keywords[min(unknown)],
                            f"optimize's keywords are {', '.join(sorted(DesignLimits.names()))}"
                            ", limits, verbose, robust, scenarios, seed, mc_samples, pareto, "
                            "transition and model")
    if lim is not None and kw:
        raise ArgumentError("limits", lim, f"give limits or {', '.join(sorted(kw))}, not both")
    lim = lim if lim is not None else DesignLimits(**kw)
    c = with_transition(with_operating(as_case(case), oil, oils, oil_temp_C, depth_m),
                        transition)
    c, mode = thermal_case(c, thermal, oil_temp_C, sea_temp_C)  # the one resolution
    c = with_model(c, model)[0] if model is not None else c
    if robust is not None:
        return robust_resolved(c, mode, robust, robust_kw, lim, verbose)
    return optimize_resolved(c, mode, thermal is None, lim, verbose)


def optimize_resolved(case: DesignCase, mode: ThermalMode, by_default: bool,
                      limits: DesignLimits, verbose: bool = False) -> Optimization:
    """:func:`optimize` of a case whose thermal mode is resolved
    (:func:`oilgap._evaluate.thermal_case`; ``oilgap optimize`` resolves it with its
    options' names): the mode is passed down, not resolved again.

    Parameters
    ----------
    case : DesignCase
        The joint, its oil state and sea temperature applied.
    mode : ThermalMode
        The resolved mode.
    by_default : bool
        Whether it is the default (no mode asked for; the header says so).
    limits : DesignLimits
        Starts, torque and inertia limits.
    verbose : bool
        Print IPOPT's iterations.

    Returns
    -------
    Optimization
        As :func:`optimize`.
    """
    starts, lim = limits.starts, limits.constraints()
    header = thermal_line(mode, by_default)
    if case.linear is not None:  # the linear actuator's NLP (oilgap.optim.design.linear)
        return LinearOptimization(solve_linear_design(case, str(mode), verbose), case,
                                  str(mode), header)
    if mode == ThermalMode.NONE:
        res = DesignProblem(case, verbose=verbose, thermal=mode).solve(starts=starts, **lim)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OilgapWarning)
            exact = res.evaluate()
        return Optimization(res, case, exact, header, lim, tuple(e.film_band for e in exact))
    cmp = compare_heating(DesignProblem(case, verbose=verbose, thermal=mode), starts=starts,
                          **lim)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        exact = (*cmp.heated.operating(), cmp.isothermal.evaluate()[1])
        bands = tuple(film_band(d, mode, mean_power_W=e.mean_power_W)
                      for d, e in zip(cmp.heated.design_cases(), exact[:2], strict=True))
    return Optimization(cmp, case, exact, header, lim, bands)


_ROBUST_KEYWORDS = ("scenarios", "seed", "mc_samples", "pareto")


def robust_resolved(case: DesignCase, mode: str, statistic: str, kw: dict, lim: DesignLimits,
                    verbose: bool = False) -> RobustOptimization:
    """``optimize(robust=...)`` of a case whose thermal mode is resolved: the robust
    design study (thermal ``none`` or ``bulk``; ``oilgap optimize --robust``).

    Parameters
    ----------
    case : DesignCase
        The joint, its oil state applied.
    mode : str
        The resolved thermal mode.
    statistic : str
        ``"p95"``, ``"mean"`` or ``"mean+2sd"``.
    kw : dict
        ``scenarios``, ``seed``, ``mc_samples``, ``pareto`` (None: the default) [-].
    lim : DesignLimits
        Starts, torque [N m] and inertia limits.
    verbose : bool
        Print IPOPT's iterations.

    Returns
    -------
    RobustOptimization
        The robust and nominal designs side by side; powers [W].
    """
    check_statistic(statistic)
    if case.linear is not None:  # the linear robust NLP (thermal none)
        if str(mode) not in ROBUST_MODES:
            raise InputError("--robust", statistic, f"thermal modes none and bulk only (here "
                             f"{mode}: give --thermal none or bulk)", "optimize")
        extra = [k for k in ("pareto", "mc_samples") if kw.get(k) is not None]
        if extra:
            raise InputError(f"--{extra[0].replace('_', '-')}", kw[extra[0]], "not for a "
                             "linear actuator (its robust design takes --scenarios and "
                             "--seed)", "optimize")
        return LinearRobustOptimization(solve_linear_robust(
            case, statistic, kw.get("scenarios"), kw.get("seed"), verbose, str(mode)), case)
    if str(mode) not in ROBUST_MODES:
        raise InputError("--robust", statistic, f"thermal modes none and bulk only (here "
                         f"{mode}: give --thermal none or bulk)", "optimize")
    given = {k: kw.get(k) is not None for k in ("scenarios", "seed")}
    s = RobustSettings(statistic=statistic, starts=lim.starts,
                       **{("pareto_points" if k == "pareto" else k): v
                          for k, v in kw.items() if v is not None})
    res = robust_design(case, s, verbose=verbose, mode=str(mode), **lim.constraints())
    return RobustOptimization(res, given)


__all__ = ["optimize", "optimize_resolved", "robust_resolved"]
