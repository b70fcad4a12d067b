"""The plan's outputs: the terminal summary (answer first) and the result folder.

Files (:data:`PLAN_OUTPUTS`): ``plan.csv`` and ``naive.csv`` (the runs, same columns),
``parameters.csv`` (expected sd and 95 % interval of each base parameter, both plans),
``effects.csv`` (smallest detectable coefficient of each effect, both plans),
``plan.json`` (everything, with the design's gap and the confounding), ``plan_runs.png``
(the runs in (Re, oil temperature, oil) space) and ``summary.md``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.effects import EFFECTS
from oilgap.optim.planning.fisher import BARUS
from oilgap.studies.reporting import new_figure, save_figure, write_tables, write_text
from oilgap.studies.rigs.synth import DEFAULT_STRENGTH

from .candidates import plan_table
from .study import PlanEvaluation, PlanResult

PLAN_OUTPUTS = ("plan.csv", "naive.csv", "parameters.csv", "effects.csv", "plan.json",
                "plan_runs.png", "summary.md")
"""Files ``oilgap plan --out DIR`` writes."""

CRITERION_NAMES = {"D": "D-optimal", "A": "A-optimal", "E": "E-optimal", "T": "T-optimal"}


def _fmt(x: float, digits: int = 3) -> str:
    return "not identifiable" if not math.isfinite(x) else f"{x:.{digits}g}"


def _runs_text(ev: PlanEvaluation) -> str:
    out, last, k = [], None, 0
    for r in ev.runs + [None]:
        if r == last:
            k += 1
            continue
        if last is not None:
            out.append(f"{last.oil} T={last.roughness_T:g} {last.bath_C:g} degC {last.profile}"
                       + (f" {last.pressure_MPa:g} MPa" if last.pressure_MPa else "")
                       + (f" x{k}" if k > 1 else ""))
        last, k = r, 1
    return "; ".join(out)


def headline(res: PlanResult) -> list[str]:
    """The answer: the plan, its key intervals beside the naive plan's, detection."""
    st, p, nv = res.settings, res.plan, res.naive
    crit = CRITERION_NAMES[st.criterion]
    over = ", ".join(res.design_params)
    lines = [f"plan        {len(p.runs)} runs, {crit} over {over}: {_runs_text(p)}",
             f"rig time    {p.cost_h:.1f} h (naive full factorial of the same size "
             f"{nv.cost_h:.1f} h); continuous design gap {res.design.gap:.2g}, "
             f"rounded efficiency >= {res.d_efficiency:.3f}"]
    for k in res.candidates.spec.free:
        a, b = p.sd[k], nv.sd[k]
        cut = (f", {100 * (1 - a / b):.0f} % narrower than naive"
               if math.isfinite(a) and math.isfinite(b) and a < b else
               (f", {100 * (a / b - 1):.0f} % wider than naive" if math.isfinite(a)
                and math.isfinite(b) else ""))
        lines.append(f"{k:<12}expected sd {_fmt(a)} (naive {_fmt(b)}){cut}; the loop's 95 % "
                     f"interval {_iv(p.interval[k])} (naive {_iv(nv.interval[k])})")
    det = [f"{e} {_ratio(p.detectable[e], e)}" for e in res.candidates.params.effects]
    if BARUS in p.detectable:
        det.append(f"{BARUS} {_fmt(p.detectable[BARUS])} 1/GPa (naive "
                   f"{_fmt(nv.detectable[BARUS])})")
    lines.append("detectable  smallest effect detected (5 % level, 80 % power), x its test "
                 "strength: " + ", ".join(det))
    return lines


def detectable_strength(size: float, effect: str) -> float:
    """A detectable coefficient in the effect's strength unit (``--strength`` of synth)."""
    return (math.inf if not math.isfinite(size)
            else float(EFFECTS[effect].strength_from_coefficient(size)))


def _ratio(size: float, effect: str) -> str:
    """The detectable size as a multiple of the effect's test strength."""
    x = detectable_strength(size, effect)
    return "never" if not math.isfinite(x) else f"{x / DEFAULT_STRENGTH[effect]:.2g}"


def _iv(iv) -> str:
    lo, hi = iv
    return "none" if not (math.isfinite(lo) and math.isfinite(hi)) else f"[{lo:.5g}, {hi:.5g}]"


def confounded_lines(res: PlanResult, ev: PlanEvaluation, name: str) -> list[str]:
    """What stays confounded in one plan, and why."""
    c = ev.confounded
    out = []
    for n in c["uninformed"]:
        out.append(f"{name}: {n} not informed: its column is zero on every run"
                   + (f" ({res.candidates.notes[n]})" if n in res.candidates.notes else
                      _why_zero(n)))
    for a, b, cos in c["pairs"]:
        out.append(f"{name}: {a} and {b} confounded: their Jacobian columns are parallel "
                   f"over these runs (cosine {cos:+.4f})")
    for d in c["directions"]:
        load = ", ".join(f"{k} {v:+.2f}" for k, v in d["loadings"].items())
        out.append(f"{name}: near-singular direction, condition index "
                   f"{d['condition_index']:.0f} > 30 (these move together): {load}")
    for e, r2 in ev.explained.items():
        if r2 > 0.999 and e not in c["uninformed"] and not any(e in (a, b) for a, b, _
                                                                in c["pairs"]):
            out.append(f"{name}: {e} {100 * r2:.3f} % explained by the base law's columns "
                       "(absorbed by the calibration)")
    return out


def _why_zero(n: str) -> str:
    if n == "taylor_vortex_onset":
        return " (Ta stays below 41.3 on every run)"
    if n == BARUS:
        return " (every run at atmospheric pressure)"
    return ""


def parameters_frame(res: PlanResult) -> pd.DataFrame:
    """Expected sd and 95 % interval of each base parameter, plan and naive."""
    vals = res.candidates.spec.values(res.candidates.x0)
    rows = []
    for k in res.candidates.spec.free:
        row = {"parameter": k, "value": vals[k],
               "sd_of": res.candidates.params.label(k)}
        for tag, ev in (("plan", res.plan), ("naive", res.naive)):
            row[f"{tag}_sd"] = ev.sd[k]
            row[f"{tag}_jackknife_sd"] = ev.jack_sd[k]
            row[f"{tag}_lo"], row[f"{tag}_hi"] = ev.interval[k]
        rows.append(row)
    return pd.DataFrame(rows)


def effects_frame(res: PlanResult) -> pd.DataFrame:
    """Smallest detectable coefficient of each effect, plan and naive."""
    rows = []
    cs = res.candidates
    extra = [(BARUS, "1/GPa", math.nan)] if BARUS in res.plan.detectable else []
    for e, unit, ref in [(e, EFFECTS[e].unit, r) for e, r in
                         zip(cs.params.effects, cs.ref, strict=True)] + extra:
        rows.append({"effect": e, "unit": unit, "test_coefficient": ref,
                     "plan_detectable": res.plan.detectable[e],
                     "plan_detectable_x_test_strength": _times(res.plan.detectable[e], e),
                     "naive_detectable_x_test_strength": _times(res.naive.detectable[e], e),
                     "plan_share_explained_by_base": res.plan.explained[e],
                     "naive_detectable": res.naive.detectable[e],
                     "naive_share_explained_by_base": res.naive.explained[e]})
    return pd.DataFrame(rows)


def _times(size: float, effect: str) -> float:
    if effect not in EFFECTS:
        return math.nan
    return detectable_strength(size, effect) / DEFAULT_STRENGTH[effect]


def plan_json(res: PlanResult) -> dict:
    """Everything the plan found, JSON-able."""
    def ev_dict(ev: PlanEvaluation) -> dict:
        return {"runs": [r.label for r in ev.runs], "sd": ev.sd, "jackknife_sd": ev.jack_sd,
                "interval95": ev.interval, "couette_floor": ev.floor,
                "detectable": ev.detectable, "explained_by_base": ev.explained,
                "confounded": ev.confounded, "cost_h": ev.cost_h, "changes": ev.changes}

    d = res.design
    return {"criterion": res.settings.criterion, "targets": res.settings.targets,
            "design_parameters": list(res.design_params),
            "continuous": {"weights": {r.label: float(w) for r, w in
                                       zip(res.candidates.runs, d.weights, strict=True) if w > 0},
                           "gap": d.gap, "efficiency_lower_bound": d.efficiency,
                           "status": d.status},
            "rounded_efficiency_lower_bound": res.d_efficiency,
            "excluded_from_design": res.excluded, "plan": ev_dict(res.plan),
            "naive": ev_dict(res.naive), "noise_W": res.settings.noise_W,
            "expected_scale": res.settings.scale,
            "candidates": len(res.candidates.runs)}


def figure(res: PlanResult, path: Path) -> None:
    """Runs in (peak Re of region 1, mean oil temperature, oil) space, plan beside naive."""
    from matplotlib import colormaps

    cs = res.candidates
    oils = list(dict.fromkeys(r.oil for r in cs.runs))
    colors = {o: colormaps["viridis"](i / max(1, len(oils) - 1)) for i, o in enumerate(oils)}
    marks = dict(zip(dict.fromkeys(r.roughness_T for r in cs.runs), "os^Dv", strict=False))
    fig, axes = new_figure(11, 4.5, ncols=2, sharey=True)
    for ax, (title, ev) in zip(axes, (("plan", res.plan), ("naive", res.naive)), strict=True):
        ax.scatter(cs.re_peak, cs.temp_mean, s=18, c="0.85", label="candidates")
        for i in np.nonzero(ev.counts)[0]:
            r = cs.runs[i]
            ax.scatter(cs.re_peak[i], cs.temp_mean[i], s=50 * ev.counts[i],
                       color=colors[r.oil], marker=marks.get(r.roughness_T, "o"),
                       edgecolor="k", alpha=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("peak Couette Reynolds number of region 1 [-]")
        ax.set_title(f"{title}: {len(ev.runs)} runs (marker size = repeats)")
    axes[0].set_ylabel("mean oil temperature [degC]")
    for o in oils:
        axes[1].scatter([], [], color=colors[o], label=o)
    for T, m in marks.items():
        axes[1].scatter([], [], color="w", edgecolor="k", marker=m, label=f"T = {T:g}")
    axes[1].legend(fontsize=8, loc="best")
    save_figure(fig, path)


def floor_lines(res: PlanResult) -> list[str]:
    """Where a plan's scale interval reaches the Couette floor's kink, what the plan did."""
    out = []
    for tag, ev in (("plan", res.plan), ("naive", res.naive)):
        f = ev.floor.get("scale")
        if f:
            lo = ev.interval["scale"][0]
            end = (f"its lower end {lo:.5g} is carried through the kink" if lo > 0 else
                   "below the kink these runs do not bound it: the interval is one-sided")
            out.append(f"couette floor ({tag}): the scale's interval reaches the floor's kink "
                       f"at {f['kink']:.5g}, below which floored rows say nothing of the "
                       f"scale (jackknife sd {_fmt(f['jack_sd_below'])} in ln scale there): "
                       f"{end} (linearised {f['linearised_lo']:.5g}); the loop's symmetric "
                       "jackknife scatters more there (docs/planning.md)")
    return out


def summary_lines(res: PlanResult) -> list[str]:
    """The terminal output: the headline, then tables and what stays confounded."""
    lines = headline(res)
    pf = parameters_frame(res)
    cols = ["order", "oil", "roughness_T", "bath_C", "profile", "pressure_MPa"]
    naive = plan_table(res.settings, res.naive.runs)[cols[1:]]
    runs = pd.concat([plan_table(res.settings, res.plan.runs)[cols],
                      naive.rename(columns={c: f"{c}_naive" for c in naive.columns})], axis=1)
    lines += ["", "run table (plan.csv; naive.csv beside it, suffix _naive)",
              runs.to_string(index=False)]
    lines += ["", "expected parameters: sd of the least-squares estimate; the loop's 95 % "
              "jackknife interval (its expected sd, t quantile)",
              pf.to_string(index=False, float_format=lambda x: f"{x:.5g}"),
              *floor_lines(res), "",
              "smallest detectable effect coefficient (library units)",
              effects_frame(res).to_string(index=False, float_format=lambda x: f"{x:.3g}"),
              "", "confounded"]
    conf = confounded_lines(res, res.plan, "plan") + confounded_lines(res, res.naive, "naive")
    conf += [f"design: {k} left out: {v}" for k, v in res.excluded.items()]
    lines += conf or ["nothing: every parameter and effect is separated on both plans"]
    st = res.settings
    lines += ["", f"defaults    noise {st.noise_W:g} W, {st.noise_speed_rpm:g} rpm, "
              f"{st.noise_temp_K:g} K per sample; expected scale {st.scale:g}; runs of "
              f"{st.duration_s:g} s every "
              f"{st.sample_interval_s:g} s at {st.peak_speed_rpm:g} rpm peak; costs "
              f"{st.run_h:g} h per run + duration, {st.oil_change_h:g} h per oil change, "
              f"{st.temp_change_h:g} h per temperature change, {st.rotor_change_h:g} h per "
              "rotor change (whole plots: runs sequenced rotor, oil, temperature)"]
    return lines


def write_plan(res: PlanResult, out: Path) -> list[Path]:
    """Write the plan's files into the folder ``out`` (atomic, each file).

    Returns
    -------
    list of Path
        The files written.
    """
    from oilgap.model.io.serialize import dumps

    out = Path(out)
    written = write_tables(out, {"plan.csv": plan_table(res.settings, res.plan.runs),
                                 "naive.csv": plan_table(res.settings, res.naive.runs),
                                 "parameters.csv": parameters_frame(res),
                                 "effects.csv": effects_frame(res)})
    written.append(write_text(out / "plan.json", dumps(plan_json(res)) + "\n"))
    written.append(write_text(out / "summary.md", "# Rig test plan\n\n```\n"
                              + "\n".join(summary_lines(res)) + "\n```\n\nRuns in (Re, "
                              "temperature, oil) space: ![runs](plan_runs.png)\n"))
    figure(res, out / "plan_runs.png")
    written.append(out / "plan_runs.png")
    return written
