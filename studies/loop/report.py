"""Report of the measured-data loop: terminal summary, ``loop.json``, ``report.md``, figures.

Tables and figures follow :mod:`oilgap.studies.reporting`. Figures (drawn by
:mod:`oilgap.studies.loop.figures` on the Agg canvas), written next to the report:

* ``measured_vs_model.png``: per run, the whole record: measured viscous power with the
  model without T, with T (before) and with the accepted effects (after);
* ``measured_vs_model_window.png``: per run, the last three speed cycles (the shape),
  measured, base model and with effect, one y scale;
* ``residual_vs_speed.png``: residual against signed speed, before and after;
* ``residual_vs_time.png``: residual against time, before and after, one line per run
  named in the legend.

More than 12 runs: ``measured_vs_model_2.png``... and ``measured_vs_model_window_2.png``...
More than :data:`~oilgap.studies.loop.figures.CAP` runs (a campaign): a summary instead
(the overview and windows of the 12 worst runs by held-out error after, the residuals, and
``measured_vs_model_grid.png``, small multiples of up to 48 runs spread over all);
every run's pages with ``figures="all"`` (``oilgap loop --figures all``).
"""

from __future__ import annotations

import inspect
import json
import math
import warnings
from pathlib import Path

import numpy as np

from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.io.defaults import (
    Default,
    case_defaults,
    defaults_block,
    defaults_lines,
    study_default,
)
from oilgap.model.io.serialize import Exact, dumps
from oilgap.model.io.text import layout, wrap
from oilgap.optim.calibration.estimator import LoopEstimator
from oilgap.optim.calibration.model_io import FittedModel
from oilgap.optim.calibration.ranges import effective_scale
from oilgap.studies.loop.base_table import base_markdown, base_summary_lines
from oilgap.studies.loop.figures import OVERVIEW, SPEED, TIME
from oilgap.studies.loop.report_figures import (
    figure_mode,
    md_figures,
    write_figures,
)
from oilgap.studies.reporting import markdown_rows, write_text

FIGURES = (OVERVIEW, SPEED, TIME, f"{OVERVIEW[:-4]}_*.png")
"""The figures' files (names or glob patterns; :func:`figure_names` for a given loop)."""


def _cell(x: float, width: int) -> str:
    """A number right-aligned in ``width`` columns with a separating space (3 decimals
    while they fit, else 4 significant digits)."""
    text = f"{x:.3f}" if abs(x) < 10 ** (width - 6) else f"{x:.4g}"
    return f"{text:>{width}}"


def _num(x: float, digits: int = 4) -> str:
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    return f"{x:.{digits}g}"


def error_table(est: LoopEstimator) -> str:
    """Table 3 of the seed (RMSE by oil and roughness, without T, with T, reduction)."""
    lines = [f"{'oil':<14}{'T':>5}{'without T W':>14}{'with T W':>11}{'reduction':>11}"]
    for r in est.table3_:
        lines.append(f"{r['oil']:<14}{r['roughness_T']:>5g}{r['rmse_without_T_W']:>14.3f}"
                     f"{r['rmse_with_T_W']:>11.3f}{r['reduction_pct']:>10.0f} %")
    return "\n".join(lines)


def _base_text(est: LoopEstimator, long: bool = False) -> str:
    """The base model in words."""
    if est.spec_.base == "branches":
        return ("the smooth maximum of Eq. 6's branches, C_k (delta/R)^alpha_k Re^beta_k, x "
                "T^gamma" if not long else
                f"the smooth maximum of Eq. 6's four branches (laminar law "
                f"`{est.spec_.laminar_law}`), each C_k (delta/R)^alpha_k Re^beta_k with only "
                "the C_k, alpha_k and beta_k the data identify freed (the others held at "
                "their published values, see the identifiability statements), times T^gamma")
    if est.spec_.base == "eq6":
        return ("the smooth Eq. 6 x scale x T^gamma" if not long else
                f"the design tool's Eq. 6 in its smooth form (laminar law "
                f"`{est.spec_.laminar_law}`) times one scale (1 = published) and T^gamma")
    return ("power law C (delta/R)^alpha Re^beta T^gamma" if not long else
            "a free power law, C_m = C (delta/R)^alpha Re^beta T^gamma")


def gamma_text(est: LoopEstimator) -> str:
    """The rig case's groove exponent, where it came from and when the loop uses it."""
    case = est.case_
    return (f"{case.friction.gamma:g} (the rig case's, from: {case.gamma_source}; used only "
            "where the oil runs cannot identify gamma: one value of T > 1)")


UNIT_HINT_RATIO = 10.0
"""A calibrated level this many times above (or below 1/this of) the published law's
is named as a possible unit mistake in the data."""


def unit_hints(est: LoopEstimator) -> list[str]:
    """Unit mistakes the calibrated level points to (empty when it is near the published
    law's, or the data show no viscous signal): a speed in rad/s makes the model's speeds
    9.55x too low and the level ~91x too high (laminar loss ~ omega^2); power in kW makes it
    1000x too low."""
    if not hasattr(est, "law_with_T_") or any(f.kind == "no viscous signal"
                                               for f in getattr(est, "findings_", [])):
        return []
    r = effective_scale(est.forward_model_, est.law_with_T_, est.spec_.laminar_law)
    if not np.isfinite(r) or 1 / UNIT_HINT_RATIO < r < UNIT_HINT_RATIO:
        return []
    what = (f"{r:.3g}x the published law's: if speed_rpm is in rad/s, multiply it by 9.549 "
            "(60/2 pi; the loss then looks ~91x too high); if the power is in mW, divide it by "
            "1000; else check the oil and temp_C" if r > 1 else
            f"{r:.3g}x the published law's: if the power is in kW, multiply it by 1000; if "
            "speed_rpm is scaled up, divide it; else check the oil and temp_C")
    return [f"{est.data_.source}: the calibrated viscous loss is {what}"]


def unit_mistake(est: LoopEstimator, source: str, err: Exception) -> InputError | None:
    """The refusal to raise instead of ``err`` (a solver failure after the calibration) when
    the calibrated level points to a unit mistake in the data; None otherwise."""
    hints = unit_hints(est)
    if not hints:
        return None
    what = hints[0].split(": ", 1)[1]
    return InputError("data", source, f"{what}; the fit then failed ({err})")


def warn_unit_hints(est: LoopEstimator) -> None:
    """Each of :func:`unit_hints` as an OilgapWarning (stderr; the run goes on)."""
    for h in unit_hints(est):
        warnings.warn(OilgapWarning(h), stacklevel=2)


def not_identifiable(est: LoopEstimator) -> list[str]:
    """Fitted base parameters without an interval: the data do not identify them."""
    ci = est.calibration_ci_
    return [k for k, v in ci.items() if isinstance(v, list)
            and not all(isinstance(x, float) and math.isfinite(x) for x in v)]


def identifiability(est: LoopEstimator) -> dict:
    """The estimator's statement per parameter, with each fitted parameter that has no
    interval called not identifiable (and why), never "identified"."""
    out = dict(est.identifiability_)
    kinds = {(f.kind, f.parameter) for f in est.findings_}
    for k in not_identifiable(est):
        if ("no viscous signal", None) in kinds:
            why = "no viscous signal: the level is pinned by the noise"
        elif ("at numerical limit", k) in kinds:
            why = "it ran to the edge of the solver's box"
        else:
            why = "every cross-validation fold gives it the same value, or too few groups"
        out[k] = f"not identifiable by these data (no interval: {why}); by design: {out.get(k)}"
    return out


def _range_text(ranges: dict, k: str) -> str:
    """A parameter's physical range as text; a branch's alpha_k, beta_k take alpha's, beta's."""
    r = ranges.get(k, ranges.get(k.rstrip("0123456789")) if k[-1:].isdigit() else None)
    return f"{r['range'][0]:g} .. {r['range'][1]:g}" if r else "-"


def _ci_text(ci) -> str:
    if not isinstance(ci, list):
        return " (fixed)"
    if not all(isinstance(x, float) and math.isfinite(x) for x in ci):
        return " (not identifiable: no interval)"
    return f" [{_num(ci[0])}, {_num(ci[1])}]"


LOOP_OPTIONS: dict[str, tuple[str, str]] = {
    "margin": ("-", "held-out gain an effect must bring to be accepted"),
    "min_explained": ("-", "share of the residual's structure an effect must explain"),
    "max_effects": ("-", "effects accepted at most"),
    "cv": ("", "cross-validation scheme"),
    "base": ("", "the base law calibrated"),
    "cv_by": ("", "column whose groups are held out"),
}
"""The estimator's options listed as defaults when left at their value (unit, meaning)."""


def loop_defaults(est: LoopEstimator) -> tuple[Default, ...]:
    """What the loop filled in: the rig case (the seed rig without ``--case``) and those of
    its defaults the loop uses (not the motor, the NLP's bounds or the duty cycle), the effect
    library, and every option left at its default.

    Parameters
    ----------
    est : LoopEstimator
        A fitted estimator.

    Returns
    -------
    tuple of Default
        Each with its value and unit ([-] for the options).
    """
    out = []
    if est.case is None:
        out.append(study_default("loop.case", est.case_.name, "", "the seed rig (the seed "
                                 "paper's experiment): no --case given"))
    out += [d for d in case_defaults(est.case_)  # motor, bounds, duty cycle: unused here
            if not d.field.startswith(("motor.", "bounds.", "design.", "duty_cycle."))]
    if est.effects is None:
        out.append(study_default("loop.effects", "the whole library", "",
                                 "oilgap synth --list-effects"))
    given = inspect.signature(LoopEstimator.__init__).parameters
    for name, (unit, meaning) in LOOP_OPTIONS.items():
        value = getattr(est, name)
        if value == given[name].default:
            out.append(study_default(f"loop.{name}", value, unit, f"default: {meaning}"))
    return tuple(out)


def oil_state_text(est: LoopEstimator) -> str | None:
    """Which oil temperature the final model's terms read, or None if the measured one."""
    st = getattr(est, "oil_state_", None)
    if not st or st["applied"] == "measured":
        return None
    how = []
    if st["thermal_lag_s"]:
        how.append(f"lagged by thermal_lag {_num(st['thermal_lag_s'])} s")
    if st["film_heating_K_W"]:
        how.append(f"heated by film_heating, film strength s = {_num(st['film_strength'])} "
                   f"(c = {_num(st['film_heating_K_W'])} K/W)")
    return (f"every term ({', '.join(st['terms'])}) read at the {st['applied']} oil "
            f"temperature ({'; '.join(how)}): one oil state per sample")


def format_summary(est: LoopEstimator, defaults: bool = True) -> str:
    """What ``oilgap loop`` prints: the held-out error before and after and the effects
    first, then data, calibration, error table, effects, before/after, then gamma and
    the defaults (``defaults`` False leaves these out, ``-q``)."""
    d = est.data_
    c = est.calibration_
    ci = est.calibration_ci_
    lines = [f"data        {d.source}: {d.kind}, {est.samples_.n} oil samples in "
             f"{len(est.samples_.run_names)} runs; {d.drop_summary().splitlines()[0]}"]
    for r in d.dropped:
        lines.append(f"            dropped {r.count} x {r.reason}")
    if d.ignored_columns:
        lines.append(f"            ignored columns: {', '.join(d.ignored_columns)}")
    lines += [f"            {n}" for n in getattr(d, "notes", ())]
    for b in est.baselines_.values():
        lines.append(f"baseline    T = {b.roughness_T:g}: oil-free fit RMSE {b.rmse_W:.3f} W "
                     f"({b.n_samples} samples)" + ("; " + "; ".join(b.notes) if b.notes else ""))
    stage = "with T"
    if est.effects_:  # the model saved in loop.json: the refit with its effects (issue 25)
        c, ci = est.calibration_after_, est.calibration_after_ci_
        stage = "refitted with the effects (the saved model)"
    par = ", ".join(f"{k} = {_num(c[k])}{_ci_text(ci[k])}" for k in c)
    lines += [f"calibration {stage} ({_base_text(est)}): {par}",
              f"            without T: the case's law ({est.law_without_T_.form}, laminar "
              f"{est.law_without_T_.laminar_law}), gamma = 0, nothing fitted",
              *base_summary_lines(est), "",
              "error table (RMSE of the viscous power by oil and roughness)", error_table(est),
              ""]
    lines += [f"finding     {f.message}" + (f"\n            {f.evidence}"
                                             if f.evidence else "")
              for f in est.findings_]
    if est.findings_:
        lines.append("")
    if est.effects_:
        cv = getattr(est, "cv_scheme_", None) or {"scheme": "leave-one-group-out"}
        how = (f"grouped {cv['folds']}-fold over {cv['groups']} groups"
               if cv["scheme"] == "grouped k-fold" else
               f"one {getattr(est, 'cv_by', 'run')} left out at a time")
        lines.append(f"effects found (accepted by cross-validation, {how})")
        for e in est.effects_:
            lines.append(f"  {e.name}: {e.formula}")
            unit = "" if e.unit == "-" else f" {e.unit}"
            ci_txt = (f"[{_num(e.ci_low)}, {_num(e.ci_high)}] (95 %)" if math.isfinite(e.ci_low)
                      else "(no interval: fewer than 3 groups, or not identifiable)")
            if e.strength_unit != e.unit:  # e.g. lambda^2 fitted, lambda reported too
                unit += f" (strength {_num(e.strength)} {e.strength_unit})"
            lines.append(f"    {e.coefficient_label()} = {_num(e.coefficient)}{unit} "
                         f"{ci_txt}, held-out gain "
                         f"{e.heldout_gain_pct:.1f} %, RMS {e.rms_power_W:.3g} W")
    else:
        best = max((x for x in est.candidates_ if "heldout_gain_alone_pct" in x),
                   key=lambda x: x["heldout_gain_alone_pct"], default=None)
        # the reason is the candidate's own status: the rule that actually rejected it
        why = f" (best candidate {best['name']}: {best['status']})" if best else ""
        lines.append("no missing effect found" + why)
    if oil_state_text(est):
        lines.append(f"oil state   {oil_state_text(est)}")
    for x in est.candidates_:
        if x["status"].startswith(("implausible", "not a candidate")):
            lines.append(f"  {x['name']}: {x['status']}")
    if est.unexplained_:
        lines.append("unexplained: " + est.unexplained_["description"])
        lines += [f"            {t}" for t in est.unexplained_.get("described", {}).get(
            "text", [])]
    h = est.heldout_rmse_
    r = est.rmse_
    held = f"held-out (by {getattr(est, 'cv_by', 'run')})"[:21]
    lines += ["", f"{'RMSE W':<22}{'without T':>10}{'with T':>10}{'with effect':>13}",
              f"{'in-sample':<22}{_cell(r['without_T'], 10)}{_cell(r['with_T'], 10)}"
              f"{_cell(r['with_effect'], 13)}",
              f"{held:<22}{'':>10}{_cell(h['before'], 10)}{_cell(h['after'], 13)}",
              f"noise level {est.noise_W_:.3f} W; held-out RMSE "
              + (f"falls by {100 * (1 - h['after'] / h['before']):.1f} %"
                 if h["after"] < h["before"] else "unchanged (no effect accepted)")]
    return layout(_answer(est), [w for x in lines if x is not None  # tables < 100 wide
                                 for y in x.split("\n") for w in wrap(y)],
                  [f"gamma       {gamma_text(est)}", *defaults_lines(loop_defaults(est))],
                  defaults=defaults)


def _answer(est: LoopEstimator) -> list[str]:
    """The loop's answer in two lines: the held-out error before and after, the effects
    accepted."""
    h = est.heldout_rmse_
    fall = (f"falls by {100 * (1 - h['after'] / h['before']):.1f} %"
            if h["after"] < h["before"] else "unchanged")
    found = (", ".join(e.name for e in est.effects_) if est.effects_
             else "none (no missing effect found)")
    return [f"held-out RMSE {_num(h['before'])} W before -> {_num(h['after'])} W after "
            f"({fall}; by {getattr(est, 'cv_by', 'run')}); noise level {est.noise_W_:.3f} W",
            f"effects     {found}"]


def _md_data(est: LoopEstimator) -> list[str]:
    """Report section: the data read, dropped and ignored; the oil-free baseline."""
    d = est.data_
    parts = ["# Measured-data loop report", "",
             f"Data: `{d.source}` ({d.kind}); {d.n_read} rows read, {d.n_dropped} dropped; "
             f"{est.samples_.n} oil samples in {len(est.samples_.run_names)} runs.", "",
             f"Rig case: {est.case_.name}; groove exponent gamma = {gamma_text(est)}.", ""]
    notes = getattr(d, "notes", ())
    if notes:
        parts += [f"- {n}" for n in notes] + [""]
    if d.dropped:
        parts += [markdown_rows(["reason", "rows", "first lines"],
                                [[x.reason, x.count, ", ".join(map(str, x.lines))]
                                 for x in d.dropped]), ""]
    if d.ignored_columns:
        parts += [f"Ignored columns: {', '.join(d.ignored_columns)}.", ""]
    if est.baselines_:
        parts += ["## Oil-free baseline", "",
                  markdown_rows(["T", "samples", "RMSE W", "temperature range degC", "notes"],
                                [[f"{b.roughness_T:g}", b.n_samples, f"{b.rmse_W:.3f}",
                                  f"{b.temp_range_C[0]:.1f}..{b.temp_range_C[1]:.1f}",
                                  "; ".join(b.notes) or "-"]
                                 for b in est.baselines_.values()]),
                  ""]
    return parts


def _md_calibration(est: LoopEstimator) -> list[str]:
    """Report section: the calibration (seed Table 3)."""
    c, ci = est.calibration_, est.calibration_ci_
    ranges = est.to_dict()["parameter_ranges"]
    parts = ["## Calibration (seed Table 3)", "",
             f"Without T: the case's friction law (form `{est.law_without_T_.form}`, laminar "
             f"law `{est.law_without_T_.laminar_law}`) with gamma = 0, nothing fitted. "
             f"With T: {_base_text(est, long=True)}, region 2 at T = 1, fitted by nonlinear "
             "least squares on the power.", "",
             markdown_rows(["parameter", "value", "95 % CI (jackknife over groups + baseline)",
                            "physical range", "identifiability"],
                           [[k, _num(c[k], 5), (("not identifiable (no interval)"
                                                  if k in not_identifiable(est) else
                                                  f"{_num(ci[k][0], 5)} .. {_num(ci[k][1], 5)}")
                                                 if isinstance(ci[k], list) else "fixed"),
                             _range_text(ranges, k),
                             identifiability(est).get(k, "")]
                            for k in c]), "", *base_markdown(est, markdown_rows)]
    parts += [f"Possible unit mistake: {h}." for h in unit_hints(est)]
    nid = not_identifiable(est)
    if nid:
        parts += [f"Not identifiable by these data (no interval is given): {', '.join(nid)}.",
                  ""]
    if est.findings_:
        parts += ["### Findings", ""] + [
            f"- {f.message}." + (f" {f.evidence[0].upper()}{f.evidence[1:]}."
                                 if f.evidence else "") for f in est.findings_] + [""]
    parts += ["Physical ranges: " + "; ".join(
        f"{k}: {v['basis']} ({v['source']})" for k, v in ranges.items() if k in c) + ".", ""]
    if "correlations" in est.identifiability_:
        parts += [f"Parameter correlations: {est.identifiability_['correlations']}.", ""]
    parts += [markdown_rows(["oil", "T", "RMSE without T W", "RMSE with T W", "reduction"],
                            [[x["oil"], f"{x['roughness_T']:g}", f"{x['rmse_without_T_W']:.3f}",
                              f"{x['rmse_with_T_W']:.3f}", f"{x['reduction_pct']:.0f} %"]
                             for x in est.table3_]), ""]
    return parts


def _md_search(est: LoopEstimator) -> list[str]:
    """Report section: the calibrated model's residual and the effect search."""
    rb = est.residual_before_
    return ["## Residual of the calibrated model", "",
            f"RMSE {rb['rmse_W']:.3f} W; noise (successive differences) {rb['noise_W']:.3f} W;"
            f" structure above noise {rb['structured_rms_W']:.3f} W RMS "
            f"({100 * rb['structured_fraction']:.0f} % of the variance). Autocorrelation "
            + ", ".join(f"lag {k}: {v:.2f}" for k, v in rb["autocorrelation"].items()) + ".",
            "",
            markdown_rows(["variable", "eta^2", "Pearson r"],
                          [[k, f"{v['eta2']:.3f}", f"{v['pearson_r']:+.3f}"]
                           for k, v in rb["variables"].items()]), "",
            "## Effect search", "",
            f"Margin: each effect must lower the held-out (leave-one-group-out) RMSE by "
            f"{100 * est.margin:.0f} %, and the effects kept must together explain "
            f"{100 * est.min_explained:.0f} % of the held-out structure above noise. An effect "
            "fitted outside its plausible range is implausible and not accepted.", "",
            markdown_rows(["effect", "status", "held-out gain alone", "best column",
                           "lasso entry (lambda/lambda_max)", "R^2 on calibration"],
                          [[x["name"], x["status"],
                            (f"{x['heldout_gain_alone_pct']:.1f} %"
                             if "heldout_gain_alone_pct" in x else "-"),
                            x.get("best_column", "-"), _num(x.get("lasso_entry_lambda_rel")),
                            _num(x.get("r2_on_calibration"), 6)] for x in est.candidates_]), ""]


def _md_effects(est: LoopEstimator) -> list[str]:
    """Report section: the forms left out, the accepted effects and what stays unexplained."""
    parts = []
    for k, v in est.confounded_forms_.items():
        parts += [f"Not a candidate: `{k}`: {v}.", ""]
    if est.effects_:
        parts += ["### Accepted effects", "",
                  markdown_rows(["effect", "formula", "coefficient", "95 % CI", "unit",
                                 "held-out gain", "RMS power W", "reference"],
                                [[e.name, f"`{e.formula}`", _num(e.coefficient, 5),
                                  f"{_num(e.ci_low, 5)} .. {_num(e.ci_high, 5)}", e.unit,
                                  f"{e.heldout_gain_pct:.1f} %", f"{e.rms_power_W:.3g}",
                                  e.reference] for e in est.effects_]), ""]
        if oil_state_text(est):
            parts += [f"Oil state: {oil_state_text(est)}.", ""]
        ca, cia = est.calibration_after_, est.calibration_after_ci_
        parts += ["Calibration refitted with the effects: " + ", ".join(
            f"{k} = {_num(ca[k], 5)}" + (f" [{_num(cia[k][0], 5)}, {_num(cia[k][1], 5)}]"
                                         if isinstance(cia[k], list) else "")
            for k in ca) + ".", ""]
    else:
        parts += ["**No missing effect found.**", ""]
    if est.unexplained_:
        parts += ["### Unexplained structure", "", est.unexplained_["description"] + ".", "",
                  *[f"- {t}" for t in est.unexplained_.get("described", {}).get("text", [])],
                  ""]
    return parts


def _md_errors(est: LoopEstimator, figures: bool | str = True) -> list[str]:
    """Report section: the errors before and after, overall and per run; the figures."""
    h, r = est.heldout_rmse_, est.rmse_
    return ["## Errors before and after", "",
            markdown_rows(["RMSE W", "without T", "with T (before)", "with effect (after)"],
                          [["in-sample", f"{r['without_T']:.3f}", f"{r['with_T']:.3f}",
                            f"{r['with_effect']:.3f}"],
                           ["held-out runs", "-", f"{h['before']:.3f}", f"{h['after']:.3f}"]]),
            "", markdown_rows(["run", "oil", "T", "without T W", "with T W", "with effect W",
                               "held-out before W", "held-out after W"],
                              [[x["run"], x["oil"], f"{x['roughness_T']:g}",
                                f"{x['rmse_without_T_W']:.3f}", f"{x['rmse_with_T_W']:.3f}",
                                f"{x['rmse_with_effect_W']:.3f}",
                                f"{x['heldout_rmse_before_W']:.3f}",
                                f"{x['heldout_rmse_after_W']:.3f}"] for x in est.per_run_]), "",
            cv_sentence(est), "", *md_figures(est, figure_mode(figures))]


def cv_sentence(est: LoopEstimator) -> str:
    """How the held-out errors and the intervals were obtained, in one sentence.

    Parameters
    ----------
    est : LoopEstimator
        A fitted estimator (its ``cv_scheme_``, :func:`oilgap.optim.calibration.folds.cv_scheme`).

    Returns
    -------
    str
        E.g. "Held-out error by grouped 10-fold cross-validation over 80 oil runs (...);
        intervals by the delete-a-group jackknife over the 10 folds."
    """
    cv = getattr(est, "cv_scheme_", None)
    if not cv:
        return ""
    text = cv["text"][0].upper() + cv["text"][1:]
    return f"{text} ({cv['rule']}); 95 % intervals by the {cv['jackknife']}."


def report_markdown(est: LoopEstimator, figures: bool | str = True) -> str:
    """The ``report.md`` text (``figures``: which figures are drawn and linked,
    :func:`figure_mode`)."""
    parts = (_md_data(est) + _md_calibration(est) + _md_search(est) + _md_effects(est)
             + _md_errors(est, figures))
    return "\n".join(parts) + "\n"


def _json_safe(x):
    if isinstance(x, dict):
        return {str(k): _json_safe(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_json_safe(v) for v in x]
    if isinstance(x, (np.floating, float)):
        v = float(x)
        return v if math.isfinite(v) else None
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    return x


def loop_json(est: LoopEstimator) -> dict:
    """The ``loop.json`` document (non-finite numbers as null): the estimator's, with the
    rig case's ``gamma`` and ``gamma_source``, ``data.notes`` and ``not_identifiable`` (the
    fitted parameters whose interval is null)."""
    doc = LoopEstimator.to_dict(est)  # the estimator's own (og.Loop.to_dict calls this)
    case = est.case_
    doc = {"gamma": float(case.friction.gamma), "gamma_source": case.gamma_source,
           "gamma_use": "the rig case's; used only where the oil runs cannot identify gamma "
                        "(one value of T > 1); calibration.gamma is the fitted one",
           **doc, "identifiability": identifiability(est),
           "not_identifiable": not_identifiable(est), "unit_hints": unit_hints(est),
           "defaults": defaults_block(loop_defaults(est))}
    if isinstance(doc.get("data"), dict):
        doc["data"] = {**doc["data"], "notes": list(getattr(est.data_, "notes", ()))}
    doc = _json_safe(doc)
    if isinstance(doc.get("model"), dict):  # every digit: predict reproduces the fit
        doc["model"] = Exact(doc["model"])
    return doc


def write_report(est: LoopEstimator, out_dir: str | Path, figures: bool | str = True) -> dict:
    """Write the figures, ``report.md`` and last ``loop.json`` to ``out_dir`` (each file
    atomically; the documents that name the others come last, so a failure while
    drawing never leaves a report linking figures that do not exist); returns the
    paths. ``figures``: ``"summary"`` (or True: every run's figures up to
    :data:`~oilgap.studies.loop.figures.CAP` runs, a summary above), ``"all"`` (every
    run's, however many), ``"none"`` (or False)."""
    mode = figure_mode(figures)
    out = Path(out_dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise InputError("--out", str(out), f"cannot create the directory ({e.strerror})") \
            from None
    paths = {"json": out / "loop.json", "report": out / "report.md"}
    paths["figures"] = write_figures(est, out, mode == "all") if mode != "none" else []
    text = report_markdown(est, mode)
    doc = dumps(loop_json(est))  # 6 significant digits; the model block in full
    write_text(paths["report"], text)
    write_text(paths["json"], doc)
    _warn_unpredictable(est, paths["json"])
    return paths


def _warn_unpredictable(est: LoopEstimator, path: Path) -> None:
    """A warning line when the saved model fails the schema ``oilgap predict`` checks
    (a fitted law outside the ranges a friction law may have): never silent."""
    try:
        FittedModel.from_dict(json.loads(json.dumps(est.fitted_model().to_dict())))
    except InputError as e:
        warnings.warn(OilgapWarning(f"{path}: oilgap predict will refuse this model ({e})"),
                      stacklevel=3)
