"""A design case with a calibrated loop model folded in: the one place where a case and a
``loop.json`` model become the calibrated case (issue 25 item 1).

:func:`calibrate_case` is pure (no file is read here; the command line and the façade
read the model with :func:`oilgap.studies.loop.model_file.read_model` and pass it in).
What it carries from the model into the case:

* the fitted friction law of the final model (``with_effect``): its form, laminar law,
  scale, alpha, gamma and branch coefficients replace the case's ``[friction]``;
* the film strength s and wall condition w of an accepted ``film_heating`` into the
  case's ``[thermal]`` (when the case has one).

What it does not carry, each named with the reason (:data:`RIG_ONLY`,
:data:`NO_DESIGN_TERM`): the effects that describe the rig rather than the joint
(sensor delay, thermal lag of the rig's sensor), and the effects the design model has
no term for yet (their loss is left out of the design's, and the message says so).
It also states where the case lies outside the model's fitted domain (speed, oil
temperature, viscosity, gap, roughness, region 1's Reynolds and Taylor numbers) with
both ranges.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from oilgap.model.case import DesignCase
from oilgap.model.regions import joint_geometry
from oilgap.model.taylor_couette import couette_reynolds, taylor_number
from oilgap.model.units import cst_to_m2_s, m_to_mm

from .model_io import FittedModel

RIG_ONLY = {
    "sensor_delay": "describes the rig's power sensor (its record lags the shaft), not the "
                    "joint",
    "thermal_lag": "describes the rig's temperature sensor lagging the oil, not the joint",
}
"""Effects that describe the rig, never carried into a design: effect -> reason."""

NO_DESIGN_TERM = {
    "seal_coulomb_friction": "the design model has no seal term",
    "bearing_ball_churning": "the library's Palmgren churning is another law than the "
                             "case's SKF bearing drag",
    "bearing_ball_drag": "a factor on the rig's bearing drag (SKF's V_M term); the design's "
                         "bearing is another one: set its [bearing] drag_scale by hand if it "
                         "is the same bearing",
    "end_face_disc": "the design model has no end-face disc term",
    "taylor_vortex_onset": "the design model has no Taylor-vortex excess term",
    "shear_thinning": "the design model takes the oil as Newtonian",
    "oil_inertia": "the design's mean loss over a cycle has no inertia term",
}
"""Effects that act on a joint but have no term in the design model yet: effect -> reason
(their loss is not in the design's; the rig's coefficient is quoted)."""


@dataclass(frozen=True, kw_only=True)
class CalibratedCase:
    """A design case with a calibrated model folded in.

    Attributes
    ----------
    case : DesignCase
        The case with the model's law (and film strength) in it.
    uncalibrated : DesignCase
        The case as given.
    carried : tuple of str
        What was carried, one phrase each (e.g. "friction law smooth, scale 1.013").
    not_carried : tuple of (str, str)
        Accepted effects not carried: (name with its coefficient, reason).
    domain : tuple of str
        Where the case lies outside the model's fitted range: one sentence per variable
        with both ranges.
    provenance : dict
        Where the model came from (path, fit date, data), filled in by the caller that
        read the file.
    """

    case: DesignCase
    uncalibrated: DesignCase
    carried: tuple[str, ...]
    not_carried: tuple[tuple[str, str], ...]
    domain: tuple[str, ...]
    provenance: dict = field(default_factory=dict)


def _law_text(law) -> str:
    if law.form == "branches":
        body = ", ".join(f"C{k + 1} {c:.4g} alpha{k + 1} {a:.4g} beta{k + 1} {b:.4g}"
                         for k, (c, a, b) in enumerate(zip(
                             law.branch_C, law.branch_alpha, law.branch_beta, strict=True)))
        return f"friction law branches ({body}), scale {law.scale:.4g}, gamma {law.gamma:.4g}"
    if law.form == "power-law":
        return (f"friction law power-law, C {law.C:.4g}, alpha {law.alpha:.4g}, beta "
                f"{law.beta:.4g}, gamma {law.gamma:.4g}")
    return (f"friction law {law.form} (laminar {law.laminar_law}), scale {law.scale:.4g}, "
            f"alpha {law.alpha:.4g}, gamma {law.gamma:.4g}")


def case_conditions(case: DesignCase) -> dict[str, tuple[float, float]]:
    """The case's operating variables in the units of the model's fitted ranges.

    Parameters
    ----------
    case : DesignCase
        The design case (SI inside).

    Returns
    -------
    dict
        ``abs_speed_rpm`` [rpm] (0 to the duty cycle's peak), ``temp_C`` [degC], ``nu_cSt``
        [cSt] (at the oil temperature and depth), ``gap_mm`` [mm] and ``roughness_T`` [-]
        of region 1, and region 1's Couette Reynolds number ``reynolds`` and Taylor number
        ``taylor`` [-] (0 to the peak speed's; seed Eqs. 3-4) -> (low, high).
    """
    r1 = joint_geometry(case).regions[0]
    w = float(abs(case.duty_cycle.omega_rad_s).max())
    t = case.operating.oil_temp_C
    nu = float(case.oil.kinematic_viscosity_cSt(t, case.operating.depth_m))
    re = float(couette_reynolds(w, r1.radius_m, r1.gap_m, cst_to_m2_s(nu)))
    return {"abs_speed_rpm": (0.0, w * 30.0 / math.pi), "temp_C": (t, t), "nu_cSt": (nu, nu),
            "gap_mm": (m_to_mm(r1.gap_m),) * 2, "roughness_T": (r1.roughness_T,) * 2,
            "reynolds": (0.0, re), "taylor": (0.0, float(taylor_number(re, r1.gap_m,
                                                                         r1.radius_m)))}


UNITS = {"abs_speed_rpm": "rpm", "temp_C": "degC", "nu_cSt": "cSt", "gap_mm": "mm",
         "roughness_T": "", "reynolds": "", "taylor": ""}

FROM_REST = ("abs_speed_rpm", "reynolds", "taylor")
"""Variables whose case range starts at rest: only their high end is checked."""

FLOW_NUMBERS = ("reynolds", "taylor")
"""Ranges a model file written before they were recorded does not hold."""


def domain_warnings(case: DesignCase, ranges: dict) -> tuple[str, ...]:
    """One sentence per variable where the case lies outside the model's fitted range.

    Parameters
    ----------
    case : DesignCase
    ranges : dict
        The model's ``fitted_range``: variable -> [low, high] (units in the names).

    Returns
    -------
    tuple of str
        E.g. "nu_cSt 61.2..61.2 cSt outside the fitted 150..1000 cSt", "taylor 0..55.1
        outside the fitted 0.31..14.7"; for a model file without the Reynolds and Taylor
        ranges, one sentence saying they are unknown.
    """
    out = []
    for k, (lo, hi) in case_conditions(case).items():
        if k not in ranges:
            continue
        a, b = ranges[k]
        tol = 1e-9 * max(1.0, abs(a), abs(b))
        if hi > b + tol or (lo < a - tol and k not in FROM_REST):
            u = UNITS[k]
            out.append(f"{k} {lo:.4g}..{hi:.4g}{' ' + u if u else ''} outside the fitted "
                       f"{a:.4g}..{b:.4g}{' ' + u if u else ''}")
    missing = [k for k in FLOW_NUMBERS if k not in ranges]
    if ranges and missing:
        out.append(f"{' and '.join(missing)} ranges unknown: the model file predates them "
                   "(run oilgap loop again to record them)")
    return tuple(out)


def calibrate_case(case: DesignCase, model: FittedModel, stage: str = "with_effect"
                   ) -> CalibratedCase:
    """Fold a calibrated loop model into a design case (pure: no file read or written).

    Parameters
    ----------
    case : DesignCase
        The design case (or the rig case).
    model : FittedModel
        The loop's fitted model (:func:`.model_io.load_model`).
    stage : {"with_effect", "with_T", "without_T"}
        Which of the model's laws (default the final model).

    Returns
    -------
    CalibratedCase
        The case with the model's law (C_m [-]) and film strength s [-] in it, what was
        not carried, and the domain warnings.
    """
    law = model.laws[stage]
    carried = [_law_text(law)]
    out = replace(case, friction=law, gamma_source="calibrated")
    not_carried = []
    effects = model.effects if stage == "with_effect" else {}
    for name, coef in effects.items():
        if name == "film_heating":
            if case.thermal is not None:
                out = replace(out, thermal=replace(case.thermal, film_strength=float(coef),
                                                   wall_floating=float(model.film_wall)))
                carried.append(f"film strength s {coef:.4g}, wall condition w "
                               f"{model.film_wall:g} (into [thermal])")
            else:
                not_carried.append((f"film_heating (s = {coef:.4g})", "the case has no "
                                    "[thermal] to carry the film strength into"))
        elif name in RIG_ONLY:
            not_carried.append((f"{name} ({coef:.4g})", RIG_ONLY[name]))
        else:
            not_carried.append((f"{name} ({coef:.4g})", NO_DESIGN_TERM.get(
                name, "no term of the design model")
                + ": its loss is not in the design's"))
    return CalibratedCase(case=out, uncalibrated=case, carried=tuple(carried),
                          not_carried=tuple(not_carried),
                          domain=domain_warnings(case, model.ranges))


__all__ = ["NO_DESIGN_TERM", "RIG_ONLY", "CalibratedCase", "calibrate_case",
           "domain_warnings"]
