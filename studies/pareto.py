"""Pareto sweeps of the clearance design: magnetic gap against loss, loss against inertia.

Both fronts are epsilon-constraint sweeps of the design NLP of issue 3
(:class:`oilgap.optim.design.DesignProblem`, built once and re-solved with
parameters), each point one IPOPT solve warm-started (primal and dual) from its
neighbour, run through the grid engine
(:func:`oilgap.studies.grid.runner.run_grid` in ``mode="optimize"``, one chunk, so
the grid is one warm-started chain):

* **Gap front** (objectives: magnetic gap delta, mean viscous power; both
  minimised): ``min P  s.t.  delta <= eps``, torque capability >= the case's
  (or ``torque_min_Nm``), rotor inertia <= its limit, all bounds. A larger gap
  lowers the oil shear but weakens the motor, which the torque constraint makes
  the design pay for with radius and length. ``eps`` runs from the gap of the
  unconstrained optimum (beyond it the epsilon constraint is inactive and the
  front ends) down to the case's ``gap_min``, spread evenly along the front's
  arc length.
* **Inertia front** (objectives: rotor inertia, mean viscous power): ``min P
  s.t.  J <= eps`` with the same torque constraint; ``eps`` runs from the
  lightest feasible rotor (found by bisection on the NLP's exact feasibility
  check) up to the inertia of the optimum without an inertia limit.

On the seed case the seed joint (T = 4) and the smoothed seed (T = 2) are evaluated
with the same objective (smooth C_m over the duty cycle) and marked; on any other case
only the case's own design is, as "this design (<case name>)", and titles and labels
name the case. ``mean_power_exact_W`` gives every design with the exact Eq. 6 C_m as
``oilgap evaluate`` prints it, and ``film_band_*`` the same design under the opposite
film choice (:func:`~oilgap.model.joint_loss.film_band`).

Every front is solved under a thermal mode of :mod:`oilgap.model.joint_loss` (``thermal``;
default :func:`~oilgap.model.joint_loss.default_thermal_mode`: ``bulk`` with
``[thermal]``, else ``none``), the same as ``oilgap evaluate`` and ``oilgap optimize``;
titles, the summary and ``provenance.json`` name it.

Front quality is measured by the 2-D hypervolume (:func:`hypervolume_2d`)
with respect to a stated reference point (default: the case's ``gap_max`` and
its own design's mean power, i.e. "better than this design on both").

References
----------
.. [1] Y. Y. Haimes, L. S. Lasdon, D. A. Wismer, "On a bicriterion formulation
   of the problems of integrated system identification and system
   optimization", IEEE Trans. SMC 1(3):296-297, 1971 (epsilon-constraint).
.. [2] E. Zitzler, L. Thiele, "Multiobjective evolutionary algorithms: a
   comparative case study and the strength Pareto approach", IEEE Trans. EC
   3(4):257-271, 1999 (hypervolume).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import (
    InfeasibleError,
    InputError,
    SolverError,
    check_positive,
)
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.defaults import Default, case_defaults, defaults_markdown, study_default
from oilgap.model.joint_loss import film_band, resolve_thermal_mode
from oilgap.model.units import MM_TO_M
from oilgap.optim.design import DesignProblem
from oilgap.optim.multiobjective import arc_length_epsilons, hypervolume_2d
from oilgap.optim.progress import report
from oilgap.studies.grid.evaluate import band_text, evaluate_cases, thermal_description
from oilgap.studies.grid.optimize import solve_design_point
from oilgap.studies.grid.runner import run_grid
from oilgap.studies.reporting import (
    markdown_table,
    new_figure,
    save_figure,
    write_tables,
    write_text,
)
from oilgap.studies.settings import (
    DEFAULT_POINTS,
    MIN_POINTS,
    ParetoSettings,
    RunOptions,
    SweepSettings,
    split_keywords,
)
from oilgap.studies.user_case import design_label, is_seed_case

SEED_LABELS = ("seed (T = 4)", "smoothed seed (T = 2)")
"""The ``design`` labels of the seed joint's rows (seed case only)."""


# --------------------------------------------------------------------------- fronts


def _marked(prob: DesignProblem, c: DesignCase, x: np.ndarray, label: str,
            thermal: str) -> dict:
    """One marked design's row: the NLP's point under the mode (smooth C_m), the exact
    loss as ``oilgap evaluate`` prints it and the film band beside it."""
    pt = prob.point(x) if prob.heated is None else prob.heated.point(x)[0]
    ex = evaluate_cases([c], thermal)
    exact = float(ex["mean_power_W"].iloc[0])
    band = film_band(c, thermal, mean_power_W=exact)
    return dict(pt.to_dict(), design=label, mean_power_exact_W=exact,
                oil_temp_op_C=float(ex["oil_temp_op_C"].iloc[0]),
                film_band_mode=band.other_mode, film_band_power_W=band.other_mean_power_W,
                film_band_change_pct=band.change_pct)


def _problem(case: DesignCase, thermal: str) -> DesignProblem:
    return DesignProblem(case) if thermal == "none" else DesignProblem(case, thermal=thermal)


def marked_cases(case: DesignCase | None = None) -> list[tuple[str, DesignCase]]:
    """The designs marked on the fronts as (label, case): the seed joint (T = 4) and the
    smoothed seed (T = 2) under the case's friction transition on the seed case, else the
    case's own design."""
    if not is_seed_case(case):
        return [(design_label(case), case)]
    pair = [seed_case(False), seed_case(True)]
    if case is not None:  # the seed under the case's transition
        pair = [replace(c, friction=replace(c.friction, transition=case.friction.transition))
                for c in pair]
    return list(zip(SEED_LABELS, pair, strict=True))


def seed_points(case: DesignCase | None = None, thermal: str = "none") -> pd.DataFrame:
    """The designs marked on the fronts, in the fronts' objective space.

    On the seed case (``case`` None or the seed joint, grooved or smoothed): the seed
    joint (T = 4) and the smoothed seed (T = 2), both through the grooved seed's
    DesignProblem (smooth C_m, inertia with the epoxy fill of the smoothed one). On any
    other case: only the case's own design, ``design`` = "this design (<case name>)".
    Each with the exact C_m too (``mean_power_exact_W`` [W], at ``oil_temp_op_C``
    [degC]) and its film band (``film_band_mode``, ``film_band_power_W`` [W],
    ``film_band_change_pct`` [%]), under the thermal mode ``thermal``.
    """
    if not is_seed_case(case):
        p = _problem(case, thermal)
        return pd.DataFrame([_marked(p, case, p.x_case_m, design_label(case), thermal)])
    marked = marked_cases(case)
    prob = _problem(marked[0][1], thermal)
    rows = []
    for label, c in marked:
        r1 = c.region1
        x = np.array([r1.T2, r1.gap, r1.T2 - r1.T1, r1.T4 - r1.T3, r1.length])
        rows.append(_marked(prob, c, x, label, thermal))
    return pd.DataFrame(rows)


def _check_points(n: int) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < MIN_POINTS:
        raise InputError("points", n, f"must be an integer >= {MIN_POINTS}", "pareto study")
    return int(n)


_QUIET = RunOptions(progress=False)
"""The fronts' default run: in this process, no progress line."""


def _sweep(case: DesignCase, column: str, eps: np.ndarray, extra: dict, out_dir,
           options: RunOptions, label: str, thermal: str = "none") -> pd.DataFrame:
    """One front: one warm-started chain (one chunk) on this process, or on ``workers``
    processes of a Dask ``scheduler`` (:func:`~oilgap.studies.grid.runner.run_grid`)."""
    grid = pd.DataFrame({column: eps})
    for k, v in extra.items():
        grid[k] = v
    o = options
    chain = RunOptions(workers=1 if o.scheduler is None else (o.workers or 1),
                       scheduler=o.scheduler, chunk_size=len(grid),
                       progress=False if o.scheduler is None else o.progress)
    # one chunk: its rows report themselves in this process (optimize_chunk), the runner's
    # bar per chunk would only jump from 0 to the end
    res = run_grid(grid, case, SweepSettings(mode="optimize", thermal=thermal), chain,
                   out_dir=out_dir, label=label)
    res["epsilon"] = eps
    return res


def gap_front(case: DesignCase | None = None, points: int = DEFAULT_POINTS,
              torque_min_Nm: float | None = None, out_dir: str | Path | None = None, *,
              spacing: str = "arc", options: RunOptions | None = None,
              thermal: str = "none") -> pd.DataFrame:
    """The gap-loss front: ``min P subject to delta <= eps`` for ``points`` values of eps, under
    the thermal mode ``thermal``.

    eps runs from the gap of the unconstrained optimum down to the case's
    ``gap_min``, each solve warm-started from the previous one; ``spacing``
    ``"arc"`` (default) spreads eps evenly along the front's arc length
    (:func:`arc_length_epsilons`, from the two end solves), ``"linear"`` uses
    equal steps in delta.

    Returns
    -------
    DataFrame
        One row per eps (``delta_max_mm``): status, the optimal design
        (``delta_mm``, ``R_mm``, ``L_mm``, ``T1_mm``..``T4_mm``, ``T``),
        ``mean_power_W`` (NLP objective, smooth C_m), ``mean_power_exact_W``,
        ``torque_capability_Nm``, ``inertia_kgm2``, ``active_constraints``,
        ``solve_time_s``.
    """
    base = case if case is not None else seed_case()
    points = _check_points(points)
    if spacing not in ("arc", "linear"):
        raise InputError("spacing", spacing, "allowed: arc, linear", "pareto study")
    extra = {}
    if torque_min_Nm is not None:
        extra["torque_min_Nm"] = check_positive("torque_min_Nm", torque_min_Nm,
                                                "pareto study")
    top, warm = solve_design_point(base, extra, thermal=thermal)
    lo = base.bounds.gap_min / MM_TO_M
    hi = max(top["delta_mm"], lo)
    eps = np.linspace(hi, lo, points)
    if spacing == "arc" and hi > lo:
        try:
            bot, _ = solve_design_point(base, dict(extra, delta_max_mm=lo), x0=warm,
                                        thermal=thermal)
            eps = arc_length_epsilons(hi, top["mean_power_W"], lo, bot["mean_power_W"],
                                      points)
        except (InfeasibleError, SolverError):
            pass  # the sweep reports the failing end as a row; keep equal steps
    return _sweep(base, "delta_max_mm", eps, extra, out_dir, options or _QUIET, "pareto gap",
                  thermal)


def min_feasible_inertia_ratio(case: DesignCase, torque_min_Nm: float | None = None,
                               rtol: float = 1e-6) -> float:
    """Smallest ``inertia_max_ratio`` for which the design problem is feasible (bisection
    on :meth:`DesignProblem.check_feasible`, which decides feasibility exactly)."""
    prob = DesignProblem(case)
    kw = {} if torque_min_Nm is None else {"torque_min_Nm": torque_min_Nm}

    def feasible(r: float) -> bool:
        try:
            prob.check_feasible(prob.parameters(inertia_max_ratio=r, **kw))
            return True
        except InfeasibleError:
            return False

    lo, hi = 1e-3, 1.0
    while not feasible(hi):
        hi *= 2.0
        if hi > 1e3:
            raise InfeasibleError("no inertia limit makes the torque requirement feasible",
                                  "infeasible")
    while hi - lo > rtol * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if feasible(mid) else (mid, hi)
    return hi


def inertia_front(case: DesignCase | None = None, points: int = DEFAULT_POINTS,
                  torque_min_Nm: float | None = None, out_dir: str | Path | None = None, *,
                  options: RunOptions | None = None, thermal: str = "none") -> pd.DataFrame:
    """The loss-inertia front: ``min P subject to J <= eps`` for ``points`` values of eps, under
    the thermal mode ``thermal``.

    eps (as ``inertia_max_ratio`` of the case's unfilled rotor) runs from just
    above the lightest feasible rotor to the inertia of the optimum without an
    inertia limit (quadratically spaced, denser at the light end where the loss
    rises steeply), solved from the top down with warm starts.
    """
    base = case if case is not None else seed_case()
    points = _check_points(points)
    extra = {}
    if torque_min_Nm is not None:
        extra["torque_min_Nm"] = check_positive("torque_min_Nm", torque_min_Nm,
                                                "pareto study")
    free, _ = solve_design_point(base, dict(extra, inertia_max_ratio=1e3), thermal=thermal)
    r_min = min_feasible_inertia_ratio(base, torque_min_Nm) * (1 + 1e-4)
    r_max = max(free["inertia_ratio"], r_min)
    s = np.linspace(1.0, 0.0, points)
    eps = r_min + (r_max - r_min) * s * s  # denser towards the steep end at the lightest rotor
    return _sweep(base, "inertia_max_ratio", eps, extra, out_dir, options or _QUIET,
                  "pareto inertia", thermal)


# --------------------------------------------------------------------------- the study


@dataclass(frozen=True, eq=False, kw_only=True)
class ParetoResult:
    """Everything the Pareto study computes."""

    gap_front: pd.DataFrame
    inertia_front: pd.DataFrame
    seeds: pd.DataFrame
    reference_point: tuple[float, float]
    hypervolume: float
    sweep_time_s: float
    files: tuple[Path, ...] = ()
    defaults: tuple[Default, ...] = ()
    """What the tool filled in: the case's (:func:`~oilgap.model.io.defaults.case_defaults`)
    and the study's (points, reference point)."""
    is_seed: bool = True
    """Whether the case is the seed joint (the seed's designs are marked only then)."""
    case_name: str = ""
    """The case's name (titles and labels of a case other than the seed)."""
    thermal_mode: str = "none"
    """The thermal mode of the fronts and the marked designs."""
    thermal_default: bool = False
    """Whether the mode is the default (not chosen)."""


def default_reference_point(case: DesignCase, seeds: pd.DataFrame) -> tuple[float, float]:
    """Reference point of the gap front's hypervolume: (the case's gap_max [mm], the
    mean power [W] of the case's own design, NLP objective): the region better than
    the design on both. For the seed case that is the seed's power."""
    own = seeds[~seeds["design"].isin(SEED_LABELS)]
    if own.empty:
        own = seeds[seeds["design"] == SEED_LABELS[0]]
    return case.bounds.gap_max / MM_TO_M, float(own["mean_power_W"].iloc[0])


def study_defaults(base: DesignCase, points: int, ref: tuple[float, float]
                   ) -> tuple[Default, ...]:
    """The case's defaults and the study's: ``points`` when it is the default, and the
    reference point (always the tool's)."""
    out = list(case_defaults(base))
    if points == DEFAULT_POINTS:
        out.append(study_default("pareto.points", DEFAULT_POINTS, "-"))
    who = "the seed's" if is_seed_case(base) else "this design's"
    out.append(study_default("pareto.reference_point", f"({ref[0]:g} mm, {ref[1]:.6g} W)",
                             "", f"the case's gap_max and {who} mean power"))
    return tuple(out)


def run(out_dir: str | Path | None = None, case: DesignCase | None = None,
        settings: ParetoSettings | None = None,
        options: RunOptions | None = None) -> ParetoResult:
    """Run both sweeps; with ``out_dir`` write CSVs, figures and ``summary.md``.

    Parameters
    ----------
    out_dir : path, optional
    case : DesignCase, optional
        Default: the seed joint (grooved).
    settings : ParetoSettings, optional
        ``points`` per front (>= 50), ``torque_min_Nm`` (required torque capability
        [N m]; default: the case's own) and ``thermal``, the thermal mode of the fronts
        and the marked designs (default:
        :func:`~oilgap.model.joint_loss.default_thermal_mode`, ``bulk`` with
        ``[thermal]``, else ``none``).
    options : RunOptions, optional
        ``progress`` (progress line on stderr), ``scheduler`` (run the sweeps on Dask:
        ``"local"``, a LocalCluster of ``workers`` processes, or ``"tcp://HOST:PORT"``,
        :mod:`oilgap.studies.grid.backends`; each front is one warm-started chain, so one
        task) and ``workers`` (processes of the LocalCluster, default 1).
    """
    s = settings if settings is not None else ParetoSettings()
    o = options if options is not None else _QUIET
    base = case if case is not None else seed_case()
    points, torque_min_Nm = s.points, s.torque_min_Nm
    mode = resolve_thermal_mode(base, s.thermal)
    out = Path(out_dir) if out_dir is not None else None
    task = "pareto: gap front, inertia front, designs, files"
    report(task, 0, 4)
    t0 = time.perf_counter()
    gf = gap_front(base, points, torque_min_Nm, out / "grid_gap" if out else None,
                   options=o, thermal=mode)
    sweep_t = time.perf_counter() - t0
    report(task, 1, 4)
    inf = inertia_front(base, points, torque_min_Nm, out / "grid_inertia" if out else None,
                        options=o, thermal=mode)
    report(task, 2, 4)
    seeds = seed_points(base, mode)
    report(task, 3, 4)
    ref = default_reference_point(base, seeds)
    ok = gf[gf["status"] == "ok"]
    hv = hypervolume_2d(ok[["delta_mm", "mean_power_W"]].to_numpy(), ref)
    result = ParetoResult(gap_front=gf, inertia_front=inf, seeds=seeds,
                          reference_point=ref, hypervolume=hv, sweep_time_s=sweep_t,
                          defaults=study_defaults(base, points, ref),
                          is_seed=is_seed_case(base), case_name=base.name, thermal_mode=mode,
                          thermal_default=s.thermal is None)
    if out is not None:
        result = replace(result, files=write_outputs(out, result, base))
    report(task, 4, 4)
    return result


def pareto_study(out_dir: str | Path | None = None, case: DesignCase | None = None,
                 **keywords) -> pd.DataFrame:
    """The Pareto study as one call: the gap-loss front (see :func:`run`).

    ``attrs`` carries the hypervolume, its reference point and the sweep time.
    """
    settings, options = split_keywords(keywords, ParetoSettings)
    r = run(out_dir, case, settings, options)
    t = r.gap_front.copy()
    t.attrs.update(hypervolume=r.hypervolume, reference_point=r.reference_point,
                   sweep_time_s=r.sweep_time_s)
    return t


# --------------------------------------------------------------------------- outputs


def _mark_seeds(ax, seeds: pd.DataFrame, xcol: str, xscale: float = 1.0) -> None:
    style = {SEED_LABELS[0]: ("s", "k"), SEED_LABELS[1]: ("o", "#1f4e79")}
    for _, s in seeds.iterrows():
        mk, col = style.get(s["design"], ("^", "purple"))
        ax.plot(s[xcol] * xscale, s["mean_power_W"], mk, color=col, ms=9, mfc="white",
                mew=2, label=f"{s['design']}: {s['mean_power_W']:.1f} W")


def _whose(result: ParetoResult) -> str:
    """Whose torque the fronts keep: ``seed's`` or ``<case name>'s``."""
    return "seed's" if result.is_seed else f"{result.case_name}'s"


def draw_gap_front(result: ParetoResult, ax) -> None:
    """The gap-loss front on ``ax``: loss [W] against delta [mm], its hypervolume shaded,
    the case's designs marked (``pareto_gap.png``, ``og.Pareto.plot``)."""
    f = result.gap_front[result.gap_front["status"] == "ok"]
    f = f.sort_values("delta_mm")
    ax.fill_between(np.r_[f["delta_mm"], result.reference_point[0]],
                    np.r_[f["mean_power_W"], f["mean_power_W"].iloc[-1]],
                    result.reference_point[1], step="post", color="C0", alpha=0.08,
                    label=f"hypervolume {result.hypervolume:.2f} mm W (ref. "
                          f"{result.reference_point[0]:g} mm, {result.reference_point[1]:.1f} W)")
    ax.plot(f["delta_mm"], f["mean_power_W"], "o-", ms=3, color="C0",
            label=f"Pareto front ({len(f)} NLP solves, warm-started)")
    _mark_seeds(ax, result.seeds, "delta_mm")
    ax.set_xlabel("magnetic gap = clearance delta [mm]")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title(f"Magnetic gap against viscous loss (torque >= {_whose(result)}, inertia "
                 f"limited; thermal {result.thermal_mode})")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)


def draw_inertia_front(result: ParetoResult, ax) -> None:
    """The loss-inertia front on ``ax``: loss [W] against rotor inertia [kg m^2], the
    case's designs marked (``pareto_inertia.png``, ``og.Pareto.plot``)."""
    f = result.inertia_front[result.inertia_front["status"] == "ok"]
    ax.plot(f["inertia_kgm2"], f["mean_power_W"], "o-", ms=3, color="C2",
            label=f"Pareto front ({len(f)} NLP solves, warm-started)")
    _mark_seeds(ax, result.seeds, "inertia_kgm2")
    ax.set_xlabel("rotor inertia incl. epoxy fill [kg m^2]")
    ax.ticklabel_format(axis="x", style="sci", scilimits=(-3, 3))
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title(f"Viscous loss against rotor inertia (torque >= {_whose(result)}; "
                 f"thermal {result.thermal_mode})")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)


def _figure(draw, result: ParetoResult, path: Path) -> Path:
    """``draw`` on a new Agg figure, written as PNG."""
    fig, ax = new_figure(7.8, 5.0)
    draw(result, ax)
    return save_figure(fig, path)


_SHOW = ["epsilon", "status", "delta_mm", "R_mm", "L_mm", "T", "mean_power_W",
         "mean_power_exact_W", "torque_capability_Nm", "inertia_ratio", "active_constraints"]


def _own_design(result: ParetoResult) -> tuple[pd.Series, str, str]:
    """(the row the fronts are compared with, its name in sentences, the rotor the inertia
    ratio is relative to): the seed (T = 4) on the seed case, else the case's design."""
    s = result.seeds
    if result.is_seed:
        return s[s["design"] == SEED_LABELS[0]].iloc[0], "the seed's", "the seed rotor's"
    return s.iloc[0], "this design's", "this design's rotor"


def summary_markdown(result: ParetoResult, base: DesignCase) -> str:
    """The study's short Markdown summary (the seed's designs only on the seed case)."""
    g, i = result.gap_front, result.inertia_front
    gok, iok = g[g["status"] == "ok"], i[i["status"] == "ok"]
    s = result.seeds
    seed, whose, rotor = _own_design(result)
    at_seed_gap = gok.iloc[(gok["delta_mm"] - seed["delta_mm"]).abs().argmin()]
    pick = np.unique(np.linspace(0, len(gok) - 1, 7).round().astype(int))
    pick_i = np.unique(np.linspace(0, len(iok) - 1, 7).round().astype(int))
    lines = [
        f"# Pareto sweeps for {base.name}",
        "",
        f"Thermal mode: {thermal_description(base, result.thermal_mode, result.thermal_default)}.",
        "",
        f"Groove exponent: gamma = {base.friction.gamma:g} ({base.gamma_source}).",
        "",
        f"Gap front: {len(gok)}/{len(g)} points solved (epsilon on delta from "
        f"{g['epsilon'].max():.4g} down to {g['epsilon'].min():.4g} mm), sweep "
        f"{result.sweep_time_s:.2f} s, median solve {1e3 * gok['solve_time_s'].median():.1f} ms. "
        f"Loss {gok['mean_power_W'].max():.2f} W at delta = {gok['delta_mm'].min():.3f} mm "
        f"down to {gok['mean_power_W'].min():.2f} W at delta = {gok['delta_mm'].max():.3f} mm "
        "(the unconstrained optimum).",
        "",
        f"Hypervolume {result.hypervolume:.4f} mm W with reference point "
        f"(delta = {result.reference_point[0]:g} mm, P = {result.reference_point[1]:.3f} W: "
        "the case's gap_max and its own design's mean power).",
        "",
        ("Seed designs" if result.is_seed else "This design") + " in the same objective "
        "(`mean_power_W`: the NLP's smooth C_m; "
        "`mean_power_exact_W`: the exact Eq. 6 form, as `oilgap evaluate` prints it):",
        "",
        markdown_table(s.assign(inertia_kgm2=s["inertia_kgm2"].map("{:.4e}".format))[
            ["design", "delta_mm", "T", "mean_power_W", "mean_power_exact_W",
             "torque_capability_Nm", "inertia_kgm2"]], 3),
        "",
        *[f"Film band of {row['design']}: {band_text(row)}." for _, row in s.iterrows()],
        "",
        f"At {whose} gap ({seed['delta_mm']:g} mm) the front reaches "
        f"{at_seed_gap['mean_power_W']:.2f} W (T = {at_seed_gap['T']:.2f}, R = "
        f"{at_seed_gap['R_mm']:.2f} mm, L = {at_seed_gap['L_mm']:.2f} mm) against {whose} "
        f"{seed['mean_power_W']:.2f} W.",
        "",
        markdown_table(gok.iloc[pick][_SHOW], 3),
        "",
        f"Inertia front: {len(iok)}/{len(i)} points; loss {iok['mean_power_W'].max():.2f} W "
        f"at {iok['inertia_ratio'].min():.3f} x {rotor} inertia down to "
        f"{iok['mean_power_W'].min():.2f} W at {iok['inertia_ratio'].max():.3f} x.",
        "",
        markdown_table(iok.iloc[pick_i][_SHOW], 3),
    ]
    failed = pd.concat([g[g["status"] != "ok"], i[i["status"] != "ok"]])
    if len(failed):
        lines += ["", f"{len(failed)} points failed; first: {failed['error'].iloc[0]}"]
    lines += ["", *defaults_markdown(result.defaults)]
    return "\n".join(lines) + "\n"


def write_outputs(out: Path, result: ParetoResult, base: DesignCase) -> tuple[Path, ...]:
    """Write ``pareto_gap.csv``, ``pareto_inertia.csv``, the marked designs
    (``pareto_seeds.csv`` on the seed case, else ``pareto_design.csv``), the two PNG
    figures and ``summary.md`` into ``out``."""
    files = write_tables(out, {
        "pareto_gap.csv": result.gap_front,
        "pareto_inertia.csv": result.inertia_front,
        "pareto_seeds.csv" if result.is_seed else "pareto_design.csv": result.seeds,
    })
    files.append(_figure(draw_gap_front, result, out / "pareto_gap.png"))
    files.append(_figure(draw_inertia_front, result, out / "pareto_inertia.png"))
    md = out / "summary.md"
    write_text(md, summary_markdown(result, base))
    files.append(md)
    return tuple(files)


# --------------------------------------------------------------------------- numpy problem


def gap_problem_numpy(case: DesignCase | None = None, torque_min_Nm: float | None = None):
    """The gap front's two-objective problem on the numpy path, for other optimizers.

    Returns ``(lower_m, upper_m, evaluate)`` where ``evaluate(X)`` takes an
    (n, 5) array of (R, delta, d_r, d_s, L) [m] and returns ``F`` (n, 2) =
    (delta [mm], mean power [W]) and ``G`` (n, 2) <= 0 for feasibility
    (torque_min - torque, J - J_max, scaled). Same objective and parameters as
    the NLP (:class:`oilgap.optim.design.DesignObjective`: smooth C_m, the
    case's speed distribution, the motor's torque and inertia).
    """
    base = case if case is not None else seed_case()
    prob = DesignProblem(base)
    params = prob.parameters(**({} if torque_min_Nm is None else
                                {"torque_min_Nm": torque_min_Nm}))
    p2 = prob.constant_power(params.nu_m2_s, params.rho_kg_m3)  # region 2 and a bearing
    objective = prob.objective(params)

    def evaluate(X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        X = np.atleast_2d(np.asarray(X, dtype=float))
        p1, tau, J = objective(X)
        F = np.column_stack([X[:, 1] / MM_TO_M, p1 + p2])
        G = np.column_stack([(params.torque_min_Nm - tau) / params.torque_min_Nm,
                             (J - params.inertia_max_kgm2) / params.inertia_max_kgm2])
        return F, G

    return np.asarray(params.lower_m), np.asarray(params.upper_m), evaluate
