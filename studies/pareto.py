"""Pareto sweeps of the clearance design: magnetic gap against loss, loss against inertia.

Both fronts are epsilon-constraint sweeps of the design NLP of issue 3
(:class:`oilgap.optim.design.DesignProblem`, built once and re-solved with
parameters), each point one IPOPT solve warm-started (primal and dual) from its
neighbour, run through the trade-study engine
(:func:`oilgap.studies.trade.run_grid` in ``mode="optimize"``, one chunk, so
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

The seed joint (T = 4) and the smoothed seed (T = 2) are evaluated with the same
objective (smooth C_m over the duty cycle) and marked; ``mean_power_exact_W``
gives every design with the exact Eq. 6 C_m as ``oilgap evaluate`` prints it.

Front quality is measured by the 2-D hypervolume (:func:`hypervolume_2d`)
with respect to a stated reference point (default: the case's ``gap_max`` and
the seed's mean power, i.e. "better than the seed on both").

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
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.case_io import seed_case
from oilgap.model.errors import (
    InfeasibleError,
    InputError,
    OilgapWarning,
    SolverError,
    check_positive,
)
from oilgap.model.oils import get_oil
from oilgap.model.units import MM_TO_M
from oilgap.studies.trade import (
    case_fingerprint,
    evaluate_arrays,
    evaluate_cases,
    markdown_table,
    new_figure,
    run_grid,
    save_figure,
    write_tables,
)

MIN_POINTS = 50
"""The fewest points a front may have."""
DEFAULT_POINTS = 60


# --------------------------------------------------------------------------- one solve


_PROBLEMS: dict[str, Any] = {}
"""DesignProblems built in this process, by case fingerprint (the NLP is built once)."""
_MAX_PROBLEMS = 16


def _problem(case: DesignCase, problems: dict | None = None) -> tuple[str, Any]:
    from oilgap.optim.design import DesignProblem

    cache = _PROBLEMS if problems is None else problems
    key = case_fingerprint(case)
    if key not in cache:
        if len(cache) >= _MAX_PROBLEMS:
            cache.pop(next(iter(cache)))
        cache[key] = DesignProblem(case)
    return key, cache[key]


_OVERRIDE_MAP = {"torque_min_Nm": ("torque_min_Nm", 1.0),
                 "delta_min_mm": ("gap_min_m", MM_TO_M),
                 "delta_max_mm": ("gap_max_m", MM_TO_M),
                 "inertia_max_ratio": ("inertia_max_ratio", 1.0)}


def solve_design_point(case: DesignCase, overrides: Mapping[str, float], x0=None,
                       problems: dict | None = None, operating: Mapping[str, Any] | None = None
                       ) -> tuple[dict, Any]:
    """Solve the design NLP of ``case`` with grid overrides; return (record, warm start).

    Parameters
    ----------
    case : DesignCase
        The structure (geometry, friction, duty cycle, motor, bounds); its
        DesignProblem is built once per distinct case (cached in ``problems``,
        default a per-process cache).
    overrides : mapping
        Grid columns ``torque_min_Nm`` [N m], ``delta_min_mm``, ``delta_max_mm``
        [mm], ``inertia_max_ratio`` [-].
    x0 : optional
        The warm start returned by a previous call (primal and dual if it came
        from the same problem, primal only otherwise).
    operating : mapping, optional
        ``oil`` (name), ``oil_temp_C``, ``depth_m``: NLP parameters, no rebuild.

    Returns
    -------
    record : dict
        The result columns of :data:`oilgap.studies.trade.OPTIMIZE_RESULTS`.
    warm : tuple
        (problem key, DesignResult), to pass as the next ``x0``.

    Raises
    ------
    InputError, InfeasibleError, SolverError
        As :meth:`DesignProblem.solve`.
    """
    key, prob = _problem(case, problems)
    kw: dict[str, Any] = {}
    for k, v in overrides.items():
        name, f = _OVERRIDE_MAP[k]
        kw[name] = float(v) * f
    for k, v in (operating or {}).items():
        kw[k] = get_oil(str(v)) if k == "oil" else float(v)
    start = None
    if x0 is not None:
        k0, r0 = x0
        start = r0 if k0 == key else r0.optimal
    t0 = time.perf_counter()
    res = prob.solve(x0=start, **kw)
    dt = time.perf_counter() - t0
    o = res.optimal
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        exact = float(evaluate_arrays([res.to_case()])[0]["mean_power_W"][0])
    rec = dict(o.to_dict(), initial_mean_power_W=res.initial.mean_power_W,
               mean_power_exact_W=exact, solve_time_s=dt, iterations=res.iterations,
               active_constraints=" ".join(res.active_constraints),
               torque_min_Nm_used=res.parameters.torque_min_Nm,
               inertia_max_kgm2_used=res.parameters.inertia_max_kgm2)
    return rec, (key, res)


# --------------------------------------------------------------------------- fronts


def hypervolume_2d(points: np.ndarray, ref: tuple[float, float]) -> float:
    """Hypervolume (area) dominated by a set of 2-D points, both objectives minimised.

    The area of the union of the boxes ``[f1, r1] x [f2, r2]`` over the points
    that dominate the reference point ``r``; exact (sweep over f1).

    References
    ----------
    Zitzler & Thiele [2].
    """
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    p = p[np.all(np.isfinite(p), axis=1) & (p[:, 0] < ref[0]) & (p[:, 1] < ref[1])]
    if p.size == 0:
        return 0.0
    p = p[np.lexsort((p[:, 1], p[:, 0]))]
    area, best_f2 = 0.0, float(ref[1])
    for f1, f2 in p:  # f1 ascending: each new best f2 adds a strip of width ref1 - f1
        if f2 < best_f2:
            area += (ref[0] - f1) * (best_f2 - f2)
            best_f2 = f2
    return float(area)


def nondominated(points: np.ndarray) -> np.ndarray:
    """Mask of the points no other point dominates (both objectives minimised)."""
    p = np.asarray(points, dtype=float).reshape(-1, 2)
    le = (p[None, :, 0] <= p[:, None, 0]) & (p[None, :, 1] <= p[:, None, 1])
    lt = (p[None, :, 0] < p[:, None, 0]) | (p[None, :, 1] < p[:, None, 1])
    return ~np.any(le & lt, axis=1)


def seed_points(case: DesignCase | None = None) -> pd.DataFrame:
    """The seed joint (T = 4) and the smoothed seed (T = 2) in the fronts' objective space.

    Both through the grooved seed's DesignProblem (smooth C_m, inertia with the
    epoxy fill of the smoothed one) and with the exact C_m (``mean_power_exact_W``).
    If ``case`` is given, it is marked as ``case`` too.
    """
    from oilgap.optim.design import DesignProblem

    grooved, smoothed = seed_case(False), seed_case(True)
    prob = DesignProblem(grooved)
    rows = []
    for label, c in (("seed (T = 4)", grooved), ("smoothed seed (T = 2)", smoothed)):
        r1 = c.region1
        x = np.array([r1.T2, r1.gap, r1.T2 - r1.T1, r1.T4 - r1.T3, r1.length])
        pt = prob.point(x)
        rows.append(dict(pt.to_dict(), design=label,
                         mean_power_exact_W=float(evaluate_cases([c])["mean_power_W"].iloc[0])))
    if case is not None and case_fingerprint(case) not in (case_fingerprint(grooved),
                                                           case_fingerprint(smoothed)):
        p = DesignProblem(case)
        pt = p.point(p.x_case_m)
        rows.append(dict(pt.to_dict(), design="case",
                         mean_power_exact_W=float(evaluate_cases([case])["mean_power_W"]
                                                  .iloc[0])))
    return pd.DataFrame(rows)


def _check_points(n: int) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < MIN_POINTS:
        raise InputError("points", n, f"must be an integer >= {MIN_POINTS}", "pareto study")
    return int(n)


def _sweep(case: DesignCase, column: str, eps: np.ndarray, extra: dict, out_dir,
           progress: bool | None, label: str) -> pd.DataFrame:
    grid = pd.DataFrame({column: eps})
    for k, v in extra.items():
        grid[k] = v
    res = run_grid(grid, case, mode="optimize", out_dir=out_dir, workers=1,
                   chunk_size=len(grid), progress=progress, label=label)
    res["epsilon"] = eps
    return res


def arc_length_epsilons(x_top: float, y_top: float, x_bot: float, y_bot: float,
                        points: int) -> np.ndarray:
    """Epsilon values from ``x_top`` down to ``x_bot``, equally spaced along the front's
    normalised arc length, the front modelled as ``y = a + b / x`` through its two ends.

    Equal steps in delta crowd the flat part of a front shaped like 1/delta and
    leave big steps on the steep part; equal arc length in normalised objective
    space spreads the points evenly along the curve (a larger hypervolume for
    the same number of solves). Falls back to equal steps in x if the ends do
    not describe a falling front.
    """
    if not (x_top > x_bot > 0 and y_bot > y_top):
        return np.linspace(x_top, x_bot, points)
    b = (y_bot - y_top) / (1.0 / x_bot - 1.0 / x_top)
    x = np.linspace(x_bot, x_top, 4001)
    y = y_top + b * (1.0 / x - 1.0 / x_top)
    xn = (x - x_bot) / (x_top - x_bot)
    yn = (y - y_top) / (y_bot - y_top)
    s = np.r_[0.0, np.cumsum(np.hypot(np.diff(xn), np.diff(yn)))]
    eps = np.interp(np.linspace(0.0, s[-1], points), s, x)[::-1]
    eps[0], eps[-1] = x_top, x_bot
    return eps


def gap_front(case: DesignCase | None = None, points: int = DEFAULT_POINTS,
              torque_min_Nm: float | None = None, out_dir: str | Path | None = None,
              progress: bool | None = False, spacing: str = "arc") -> pd.DataFrame:
    """The gap-loss front: ``min P s.t. delta <= eps`` for ``points`` values of eps.

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
    top, warm = solve_design_point(base, extra)
    lo = base.bounds.gap_min / MM_TO_M
    hi = max(top["delta_mm"], lo)
    eps = np.linspace(hi, lo, points)
    if spacing == "arc" and hi > lo:
        try:
            bot, _ = solve_design_point(base, dict(extra, delta_max_mm=lo), x0=warm)
            eps = arc_length_epsilons(hi, top["mean_power_W"], lo, bot["mean_power_W"],
                                      points)
        except (InfeasibleError, SolverError):
            pass  # the sweep reports the failing end as a row; keep equal steps
    return _sweep(base, "delta_max_mm", eps, extra, out_dir, progress, "pareto gap")


def min_feasible_inertia_ratio(case: DesignCase, torque_min_Nm: float | None = None,
                               rtol: float = 1e-6) -> float:
    """Smallest ``inertia_max_ratio`` for which the design problem is feasible (bisection
    on :meth:`DesignProblem.check_feasible`, which decides feasibility exactly)."""
    from oilgap.optim.design import DesignProblem

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
                  torque_min_Nm: float | None = None, out_dir: str | Path | None = None,
                  progress: bool | None = False) -> pd.DataFrame:
    """The loss-inertia front: ``min P s.t. J <= eps`` for ``points`` values of eps.

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
    free, _ = solve_design_point(base, dict(extra, inertia_max_ratio=1e3))
    r_min = min_feasible_inertia_ratio(base, torque_min_Nm) * (1 + 1e-4)
    r_max = max(free["inertia_ratio"], r_min)
    s = np.linspace(1.0, 0.0, points)
    eps = r_min + (r_max - r_min) * s * s  # denser towards the steep end at the lightest rotor
    return _sweep(base, "inertia_max_ratio", eps, extra, out_dir, progress, "pareto inertia")


# --------------------------------------------------------------------------- the study


@dataclass(frozen=True, eq=False)
class ParetoResult:
    """Everything the Pareto study computes."""

    gap_front: pd.DataFrame
    inertia_front: pd.DataFrame
    seeds: pd.DataFrame
    reference_point: tuple[float, float]
    hypervolume: float
    sweep_time_s: float
    files: tuple[Path, ...] = ()


def default_reference_point(case: DesignCase, seeds: pd.DataFrame) -> tuple[float, float]:
    """Reference point of the gap front's hypervolume: (the case's gap_max [mm], the
    mean power [W] of the case's own design, NLP objective): the region better than
    the design on both. For the seed case that is the seed's power."""
    own = seeds[seeds["design"] == "case"]
    if own.empty:
        own = seeds[seeds["design"] == "seed (T = 4)"]
    return case.bounds.gap_max / MM_TO_M, float(own["mean_power_W"].iloc[0])


def run(out_dir: str | Path | None = None, case: DesignCase | None = None,
        points: int = DEFAULT_POINTS, torque_min_Nm: float | None = None,
        progress: bool | None = False) -> ParetoResult:
    """Run both sweeps; with ``out_dir`` write CSVs, figures and ``summary.md``.

    Parameters
    ----------
    out_dir : path, optional
    case : DesignCase, optional
        Default: the seed joint (grooved).
    points : int
        Points per front (>= 50).
    torque_min_Nm : float, optional
        Required torque capability [N m] (default: the case's own).
    progress : bool, optional
        Progress line on stderr.
    """
    base = case if case is not None else seed_case()
    points = _check_points(points)
    out = Path(out_dir) if out_dir is not None else None
    t0 = time.perf_counter()
    gf = gap_front(base, points, torque_min_Nm, out / "grid_gap" if out else None, progress)
    sweep_t = time.perf_counter() - t0
    inf = inertia_front(base, points, torque_min_Nm, out / "grid_inertia" if out else None,
                        progress)
    seeds = seed_points(base)
    ref = default_reference_point(base, seeds)
    ok = gf[gf["status"] == "ok"]
    hv = hypervolume_2d(ok[["delta_mm", "mean_power_W"]].to_numpy(), ref)
    result = ParetoResult(gf, inf, seeds, ref, hv, sweep_t)
    if out is not None:
        result = replace(result, files=write_outputs(out, result, base))
    return result


def pareto_study(out_dir: str | Path | None = None, **kwargs) -> pd.DataFrame:
    """The Pareto study as one call: the gap-loss front (see :func:`run`).

    ``attrs`` carries the hypervolume, its reference point and the sweep time.
    """
    r = run(out_dir, **kwargs)
    t = r.gap_front.copy()
    t.attrs.update(hypervolume=r.hypervolume, reference_point=r.reference_point,
                   sweep_time_s=r.sweep_time_s)
    return t


# --------------------------------------------------------------------------- outputs


def _mark_seeds(ax, seeds: pd.DataFrame, xcol: str, xscale: float = 1.0) -> None:
    style = {"seed (T = 4)": ("s", "k"), "smoothed seed (T = 2)": ("o", "#1f4e79"),
             "case": ("^", "purple")}
    for _, s in seeds.iterrows():
        mk, col = style.get(s["design"], ("x", "k"))
        ax.plot(s[xcol] * xscale, s["mean_power_W"], mk, color=col, ms=9, mfc="white",
                mew=2, label=f"{s['design']}: {s['mean_power_W']:.1f} W")


def _figure_gap(result: ParetoResult, path: Path) -> Path:
    f = result.gap_front[result.gap_front["status"] == "ok"]
    fig, ax = new_figure(7.8, 5.0)
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
    ax.set_title("Magnetic gap against viscous loss (torque >= seed's, inertia limited)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, path)


def _figure_inertia(result: ParetoResult, path: Path) -> Path:
    f = result.inertia_front[result.inertia_front["status"] == "ok"]
    fig, ax = new_figure(7.8, 5.0)
    ax.plot(f["inertia_kgm2"] * 1e6, f["mean_power_W"], "o-", ms=3, color="C2",
            label=f"Pareto front ({len(f)} NLP solves, warm-started)")
    _mark_seeds(ax, result.seeds, "inertia_kgm2", 1e6)
    ax.set_xlabel("rotor inertia incl. epoxy fill [kg mm^2]")
    ax.set_ylabel("mean viscous power over the duty cycle [W]")
    ax.set_title("Viscous loss against rotor inertia (torque >= seed's)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, path)


_SHOW = ["epsilon", "status", "delta_mm", "R_mm", "L_mm", "T", "mean_power_W",
         "mean_power_exact_W", "torque_capability_Nm", "inertia_ratio", "active_constraints"]


def summary_markdown(result: ParetoResult, base: DesignCase) -> str:
    """The study's short Markdown summary."""
    g, i = result.gap_front, result.inertia_front
    gok, iok = g[g["status"] == "ok"], i[i["status"] == "ok"]
    s = result.seeds
    seed = s[s["design"] == "seed (T = 4)"].iloc[0]
    at_seed_gap = gok.iloc[(gok["delta_mm"] - seed["delta_mm"]).abs().argmin()]
    pick = np.unique(np.linspace(0, len(gok) - 1, 7).round().astype(int))
    pick_i = np.unique(np.linspace(0, len(iok) - 1, 7).round().astype(int))
    lines = [
        f"# Pareto sweeps for {base.name}",
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
        "Seed designs in the same objective (`mean_power_W`: the NLP's smooth C_m; "
        "`mean_power_exact_W`: the exact Eq. 6 form, as `oilgap evaluate` prints it):",
        "",
        markdown_table(s.assign(inertia_kgmm2=s["inertia_kgm2"] * 1e6)[
            ["design", "delta_mm", "T", "mean_power_W", "mean_power_exact_W",
             "torque_capability_Nm", "inertia_kgmm2"]], 3),
        "",
        f"At the seed's gap ({seed['delta_mm']:g} mm) the front reaches "
        f"{at_seed_gap['mean_power_W']:.2f} W (T = {at_seed_gap['T']:.2f}, R = "
        f"{at_seed_gap['R_mm']:.2f} mm, L = {at_seed_gap['L_mm']:.2f} mm) against the seed's "
        f"{seed['mean_power_W']:.2f} W.",
        "",
        markdown_table(gok.iloc[pick][_SHOW], 3),
        "",
        f"Inertia front: {len(iok)}/{len(i)} points; loss {iok['mean_power_W'].max():.2f} W "
        f"at {iok['inertia_ratio'].min():.3f} x the seed rotor's inertia down to "
        f"{iok['mean_power_W'].min():.2f} W at {iok['inertia_ratio'].max():.3f} x.",
        "",
        markdown_table(iok.iloc[pick_i][_SHOW], 3),
    ]
    failed = pd.concat([g[g["status"] != "ok"], i[i["status"] != "ok"]])
    if len(failed):
        lines += ["", f"{len(failed)} points failed; first: {failed['error'].iloc[0]}"]
    return "\n".join(lines) + "\n"


def write_outputs(out: Path, result: ParetoResult, base: DesignCase) -> tuple[Path, ...]:
    """Write ``pareto_gap.csv``, ``pareto_inertia.csv``, ``pareto_seeds.csv``, the two
    PNG figures and ``summary.md`` into ``out``."""
    files = write_tables(out, {
        "pareto_gap.csv": result.gap_front,
        "pareto_inertia.csv": result.inertia_front,
        "pareto_seeds.csv": result.seeds,
    })
    files.append(_figure_gap(result, out / "pareto_gap.png"))
    files.append(_figure_inertia(result, out / "pareto_inertia.png"))
    md = out / "summary.md"
    md.write_text(summary_markdown(result, base), encoding="utf-8")
    files.append(md)
    return tuple(files)


# --------------------------------------------------------------------------- numpy problem


def gap_problem_numpy(case: DesignCase | None = None, torque_min_Nm: float | None = None):
    """The gap front's two-objective problem on the numpy path, for other optimizers.

    Returns ``(lower_m, upper_m, evaluate)`` where ``evaluate(X)`` takes an
    (n, 5) array of (R, delta, d_r, d_s, L) [m] and returns ``F`` (n, 2) =
    (delta [mm], mean power [W]) and ``G`` (n, 2) <= 0 for feasibility
    (torque_min - torque, J - J_max, scaled). Same functions and parameters as
    the NLP (:func:`oilgap.optim.design.region1_mean_power`, ``motor_torque``,
    ``rotor_inertia``, smooth C_m, the case's speed distribution).
    """
    from oilgap.model.motor import motor_torque, rotor_inertia
    from oilgap.optim.design import DesignProblem, region1_mean_power

    base = case if case is not None else seed_case()
    prob = DesignProblem(base)
    params = prob.parameters(**({} if torque_min_Nm is None else
                                {"torque_min_Nm": torque_min_Nm}))
    nu, rho = params.nu_m2_s, params.rho_kg_m3
    p2 = prob.region2_power(nu, rho)
    m = base.motor
    nodes, weights = prob.nodes_rad_s, prob.weights

    def evaluate(X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        X = np.atleast_2d(np.asarray(X, dtype=float))
        R, d, dr, ds, L = (X[:, k:k + 1] for k in range(5))
        p1 = region1_mean_power(R, d, dr, ds, L, nu, rho, nodes[None, :], weights, prob.law)
        F = np.column_stack([X[:, 1] / MM_TO_M, np.ravel(p1) + p2])
        tau = np.ravel(motor_torque(m, R, d, L)[0])
        J = np.ravel(rotor_inertia(m, R, dr, L, prob.machined_rotor_groove_m))
        G = np.column_stack([(params.torque_min_Nm - tau) / params.torque_min_Nm,
                             (J - params.inertia_max_kgm2) / params.inertia_max_kgm2])
        return F, G

    return np.asarray(params.lower_m), np.asarray(params.upper_m), evaluate
