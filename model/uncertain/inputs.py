"""The uncertain inputs of a joint's loss and how one set of their values makes a case.

One source of truth for what an uncertain input *is* (the ``[uncertainty]`` table, the
uncertainty study, the robust design NLP and the vectorised loss all use these names):

=============================== ====== ============================================================
input                           unit   acts on
=============================== ====== ============================================================
``nu40_factor``                 [-]    factor on the oil's nu at 40 degC alone (ISO 3448's grade
                                       tolerance): its Walther line rebuilt through (f nu40, nu100)
                                       (:mod:`oilgap.model.uncertain.grade`); nominal 1
``nu100_factor``                [-]    factor on the oil's nu at 100 degC (its viscosity index),
                                       the Walther line rebuilt the same way; nominal 1
``nu_factor_all_temperatures``  [-]    one factor on the viscosity at every state (the Walther
                                       line shifted, :class:`~oilgap.model.fluids.ScaledFluid`);
                                       nominal 1
``oil_temp_C``                  [degC] the case's oil temperature; with a ``[thermal]`` table the
                                       sea temperature of the balance moves by the same amount
``depth_m``                     [m]    the sea depth (the oil's gauge pressure)
``gamma``                       [-]    groove exponent gamma of Eq. 8 (``[friction] gamma``)
``friction_scale``              [-]    factor on C_m (the law's ``scale``; its ``C`` for the
                                       power-law form); nominal 1
``film_strength``               [-]    film strength s on the Nahme number (``[thermal]``; acts
                                       under the ``film``/``full`` thermal modes only)
``bearing_drag_scale``          [-]    factor on the bearing's SKF drag terms; nominal 1
``peak_speed_rpm``              [rpm]  the duty cycle's peak speed (every speed scaled alike)
``groove_exponent_scale``       [-]    factor 0..1 on gamma: 0 is creeping-flow theory's groove
                                       factor 1 (Helmholtz-Korteweg), 1 the seed rig's T^gamma (the
                                       groove band, :mod:`oilgap.model.groove_band`); nominal 1
=============================== ====== ============================================================

:func:`apply_inputs` is the scalar reference path: a copy of the case with the given
values, to be evaluated by :func:`oilgap.model.joint_loss.joint_mean_power` or
:func:`oilgap.model.evaluation.evaluate_case` like any case. Vectorised evaluations over
arrays of these inputs must equal it.

References
----------
.. [1] ISO 3448:1992, industrial liquid lubricants, ISO viscosity classification.
.. [2] Seed paper, Eqs. 6, 8 and 10 (gamma, C_m, the cycle mean).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from ..errors import InputError
from ..fluids import ScaledFluid
from ..units import rad_s_to_rpm
from .grade import walther_rebuilt

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase


@dataclass(frozen=True, kw_only=True)
class InputInfo:
    """What one uncertain input is.

    Attributes
    ----------
    name : str
        Key of the input [-].
    unit : str
        Its unit ("-" for factors and exponents).
    title : str
        One line for tables and figures.
    factor : bool
        True for a factor on the case's value (nominal 1) [-].
    """

    name: str
    unit: str
    title: str
    factor: bool = False


INPUTS: dict[str, InputInfo] = {i.name: i for i in (
    InputInfo(name="nu40_factor", unit="-", title="oil's nu40 factor (ISO 3448 grade)",
              factor=True),
    InputInfo(name="nu100_factor", unit="-", title="oil's nu100 factor (viscosity index)",
              factor=True),
    InputInfo(name="nu_factor_all_temperatures", unit="-",
              title="oil viscosity factor at every temperature", factor=True),
    InputInfo(name="oil_temp_C", unit="degC", title="oil temperature"),
    InputInfo(name="depth_m", unit="m", title="sea depth"),
    InputInfo(name="gamma", unit="-", title="groove exponent gamma"),
    InputInfo(name="friction_scale", unit="-", title="skin-friction factor on C_m", factor=True),
    InputInfo(name="film_strength", unit="-", title="film heating strength s"),
    InputInfo(name="bearing_drag_scale", unit="-", title="bearing drag factor", factor=True),
    InputInfo(name="peak_speed_rpm", unit="rpm", title="duty cycle's peak speed"),
    InputInfo(name="groove_exponent_scale", unit="-",
              title="groove exponent scale (0 creeping-flow theory, 1 the rig's T^gamma)",
              factor=True),
)}
"""The uncertain inputs, in their order of tables [-]."""


def nominal_inputs(case: DesignCase) -> dict[str, float]:
    """The case's own value of every uncertain input (factors are 1).

    Parameters
    ----------
    case : DesignCase
        The case.

    Returns
    -------
    dict
        Input name -> value in the input's unit ([-], [degC], [m], [rpm]: :data:`INPUTS`).
    """
    th = case.thermal
    return {
        "nu40_factor": 1.0,
        "nu100_factor": 1.0,
        "nu_factor_all_temperatures": 1.0,
        "oil_temp_C": float(case.operating.oil_temp_C),
        "depth_m": float(case.operating.depth_m),
        "gamma": float(case.friction.gamma),
        "friction_scale": 1.0,
        "film_strength": 1.0 if th is None or th.film_strength is None else th.film_strength,
        "bearing_drag_scale": 1.0,
        "peak_speed_rpm": float(rad_s_to_rpm(case.duty_cycle.peak_omega_rad_s)),
        "groove_exponent_scale": 1.0,
    }


def _value(name: str, value) -> float:
    if name not in INPUTS:
        raise InputError("uncertainty input", name, f"one of {', '.join(INPUTS)}")
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(float(value)):
        raise InputError(name, value, "a finite number", "scenario")
    return float(value)


def apply_inputs(case: DesignCase, values: Mapping[str, float]) -> DesignCase:
    """A copy of the case with the given uncertain inputs set (the scalar reference path).

    Inputs not given keep the case's value. Each value is checked as the case's own
    field would be (a depth outside [0, 11000] m, a negative factor... raise).

    Parameters
    ----------
    case : DesignCase
        The nominal case.
    values : mapping
        Input name (:data:`INPUTS`) -> value in its unit (factors relative to the
        case's own value, nominal 1).

    Returns
    -------
    DesignCase
        The scenario's case.

    Raises
    ------
    InputError
        An unknown input, a non-finite or out-of-range value, ``film_strength``
        on a case without ``[thermal]`` (the film's settings live there),
        ``nu40_factor``/``nu100_factor`` on a fluid without a Walther line.
    """
    v = {k: _value(k, x) for k, x in values.items()}
    changes: dict = {}
    oil = case.oil
    if "nu40_factor" in v or "nu100_factor" in v:
        oil = walther_rebuilt(oil, v.get("nu40_factor", 1.0), v.get("nu100_factor", 1.0))
    if "nu_factor_all_temperatures" in v:
        base = oil.base if isinstance(oil, ScaledFluid) else oil
        f = v["nu_factor_all_temperatures"] * (oil.factor if isinstance(oil, ScaledFluid)
                                               else 1.0)
        oil = base if f == 1.0 else ScaledFluid(base, f)
    if oil is not case.oil:
        changes["oil"] = oil
    op = case.operating
    if "oil_temp_C" in v or "depth_m" in v:
        changes["operating"] = replace(op, oil_temp_C=v.get("oil_temp_C", op.oil_temp_C),
                                       depth_m=v.get("depth_m", op.depth_m))
    th = case.thermal
    if th is not None and "oil_temp_C" in v:
        th = replace(th, sea_temp_C=th.sea_temp_C + (v["oil_temp_C"] - op.oil_temp_C))
    if "film_strength" in v:
        if th is None:
            raise InputError("film_strength", v["film_strength"], "an input of a case with "
                             "a [thermal] table (the film's walls and strength live there)",
                             "uncertainty")
        th = replace(th, film_strength=v["film_strength"])
    if th is not case.thermal:
        changes["thermal"] = th
    law = case.friction
    if "gamma" in v:
        law = replace(law, gamma=v["gamma"])
    if "groove_exponent_scale" in v:  # over the groove band: gamma x 0..1
        g = v["groove_exponent_scale"]
        if not 0.0 <= g <= 1.0:
            raise InputError("groove_exponent_scale", g, "0..1 (0: groove factor 1 of "
                             "creeping-flow theory, 1: the seed rig's T^gamma)", "scenario")
        law = replace(law, gamma=law.gamma * g)
    if "friction_scale" in v:
        law = (replace(law, C=law.C * v["friction_scale"]) if law.form == "power-law"
               else replace(law, scale=law.scale * v["friction_scale"]))
    if law is not case.friction:
        changes["friction"] = law
    if "bearing_drag_scale" in v and case.bearing is not None:
        changes["bearing"] = replace(case.bearing,
                                     drag_scale=case.bearing.drag_scale * v["bearing_drag_scale"])
    if "peak_speed_rpm" in v:
        changes["duty_cycle"] = case.duty_cycle.with_peak_speed(v["peak_speed_rpm"])
    return replace(case, **changes) if changes else case


__all__ = ["INPUTS", "InputInfo", "apply_inputs", "nominal_inputs"]
