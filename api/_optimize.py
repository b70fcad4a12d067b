"""The façade's design function: ``og.optimize`` (``oilgap optimize``), the region-1
clearance geometry of least mean power (:class:`oilgap.optim.design.DesignProblem`)."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

from oilgap._evaluate import as_case, thermal_case, with_operating
from oilgap._results_design import Optimization, thermal_line
from oilgap._results_robust import RobustOptimization
from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.joint_loss import film_band
from oilgap.model.oils import Oil
from oilgap.model.thermal_modes import ThermalMode
from oilgap.optim.design import DesignProblem, compare_heating
from oilgap.optim.design.robust import ROBUST_MODES, check_statistic
from oilgap.studies.robust import RobustSettings, robust_design
from oilgap.studies.settings import DesignLimits


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
    robust = kw.pop("robust", None)
    robust_kw = {k: kw.pop(k) for k in _ROBUST_KEYWORDS if k in kw}
    if robust is None and robust_kw:
        raise TypeError(f"{', '.join(sorted(robust_kw))} only with robust=")
    lim = kw.pop("limits", None)
    unknown = set(kw) - DesignLimits.names()
    if unknown:
        raise TypeError(f"unexpected keyword(s): {', '.join(sorted(unknown))}")
    if lim is not None and kw:
        raise TypeError(f"give limits or {', '.join(sorted(kw))}, not both")
    lim = lim if lim is not None else DesignLimits(**kw)
    starts, limits = lim.starts, lim.constraints()
    c = with_operating(as_case(case), oil, oils, oil_temp_C, depth_m)
    c, mode = thermal_case(c, thermal, oil_temp_C, sea_temp_C)
    if robust is not None:
        return _robust(c, mode, robust, robust_kw, lim, verbose)
    header = thermal_line(mode, thermal is None)
    if mode == ThermalMode.NONE:
        res = DesignProblem(c, verbose=verbose).solve(starts=starts, **limits)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OilgapWarning)
            exact = res.evaluate()
        return Optimization(res, c, exact, header, limits, tuple(e.film_band for e in exact))
    cmp = compare_heating(DesignProblem(c, verbose=verbose, thermal=mode), starts=starts,
                          **limits)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        exact = (*cmp.heated.operating(), cmp.isothermal.evaluate()[1])
        bands = tuple(film_band(d, mode, mean_power_W=e.mean_power_W)
                      for d, e in zip(cmp.heated.design_cases(), exact[:2], strict=True))
    return Optimization(cmp, c, exact, header, limits, bands)


_ROBUST_KEYWORDS = ("scenarios", "seed", "mc_samples", "pareto")


def _robust(case: DesignCase, mode: str, statistic: str, kw: dict, lim: DesignLimits,
            verbose: bool) -> RobustOptimization:
    """``optimize(robust=...)``: the robust design study (thermal ``none`` or ``bulk``)."""
    check_statistic(statistic)
    if str(mode) not in ROBUST_MODES:
        raise InputError("--robust", statistic, f"thermal modes none and bulk only (here "
                         f"{mode}: give --thermal none or bulk)", "optimize")
    given = {k: kw.get(k) is not None for k in ("scenarios", "seed")}
    s = RobustSettings(statistic=statistic, starts=lim.starts,
                       **{("pareto_points" if k == "pareto" else k): v
                          for k, v in kw.items() if v is not None})
    res = robust_design(case, s, verbose=verbose, mode=str(mode), **lim.constraints())
    return RobustOptimization(res, given)


__all__ = ["optimize"]
