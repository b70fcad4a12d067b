"""The façade's design function: ``og.optimize`` (``oilgap optimize``), the region-1
clearance geometry of least mean power (:class:`oilgap.optim.design.DesignProblem`)."""

from __future__ import annotations

import warnings
from pathlib import Path

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning, check_positive
from oilgap.model.joint_loss import film_band
from oilgap.model.oils import Oil
from oilgap.model.thermal_modes import ThermalMode
from oilgap.optim.design import DesignProblem, compare_heating
from oilgap.studies.api import as_case, thermal_case, with_operating
from oilgap.studies.results_design import Optimization, thermal_line


def _starts(starts: int) -> int:
    if isinstance(starts, bool) or not isinstance(starts, int) or starts < 1:
        raise InputError("starts", starts, "an integer >= 1 is required")
    return starts


def optimize(case: DesignCase | str | Path | None = None, *, oil: str | None = None,
             oils: dict[str, Oil] | str | Path | None = None,
             oil_temp_C: float | None = None, depth_m: float | None = None,
             thermal: str | None = None, sea_temp_C: float | None = None, starts: int = 1,
             torque_min_Nm: float | None = None, inertia_max_ratio: float | None = None,
             verbose: bool = False) -> Optimization:
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
        As :func:`oilgap.studies.api.evaluate` (oil temperature [degC], depth [m], sea
        temperature [degC]).
    starts : int
        Start points: the case's design and ``starts - 1`` random points in the bounds.
    torque_min_Nm : float, optional
        Required torque capability [N m] (default: the case's, else the initial design's).
    inertia_max_ratio : float, optional
        Rotor inertia limit over the case's unfilled rotor [-] (default: the case's).
    verbose : bool
        IPOPT's iterations printed.

    Returns
    -------
    Optimization
        ``.raw``: a DesignResult (``none``) or HeatingComparison; powers [W].

    Raises
    ------
    InputError, InfeasibleError, SolverError
        Bad input; constraints that conflict; IPOPT failing.
    """
    starts = _starts(starts)
    limits = {"torque_min_Nm": None if torque_min_Nm is None
              else check_positive("torque_min_Nm", torque_min_Nm),
              "inertia_max_ratio": None if inertia_max_ratio is None
              else check_positive("inertia_max_ratio", inertia_max_ratio)}
    c = with_operating(as_case(case), oil, oils, oil_temp_C, depth_m)
    c, mode = thermal_case(c, thermal, oil_temp_C, sea_temp_C)
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


__all__ = ["optimize"]
