"""The robust optimum beside the nominal one as a façade view (``og.optimize(robust=...)``,
``oilgap optimize --robust``): :class:`RobustOptimization` and the text it prints."""

from __future__ import annotations

from typing import Any

from oilgap._results import ResultView, case_defaults, lazy, new_axes
from oilgap.model.io.defaults import gamma_line
from oilgap.model.io.text import layout, wrapped
from oilgap.optim.design.robust import CVAR_ALPHA
from oilgap.optim.design.scenarios import FILM_ONLY
from oilgap.studies.robust.design import (
    DEFAULT_SCENARIOS,
    MC_SEED_OFFSET,
    STABILITY_DESIGN_TOL,
    STABILITY_STAT_TOL,
    RobustDesign,
)
from oilgap.studies.settings import DEFAULT_STARTS

STATISTIC_TEXT = {
    "p95": ("minimises the CVaR at 95 % (mean of the worst 5 % of the scenarios, "
            "Rockafellar-Uryasev): a smooth upper bound of p95; the empirical p95 is reported"),
    "mean": "minimises the sample mean of the loss over the scenarios",
    "mean+2sd": "minimises the sample mean + 2 sample standard deviations of the loss",
}
"""What each statistic minimises, for the header."""

_DESIGN_ROWS = (("R_mm", "radius R = T2"), ("delta_mm", "clearance delta (magnetic gap)"),
                ("rotor_groove_depth_mm", "open rotor groove depth"),
                ("stator_groove_depth_mm", "open stator groove depth"), ("L_mm", "length L"),
                ("torque_capability_Nm", "torque capability"),
                ("inertia_kgm2", "rotor inertia"))


def _f(v: float) -> str:
    a = abs(v)  # 5 significant digits below 1, as optimize's table (issue 26: inertia)
    if 1e-3 <= a < 1:
        return f"{v:#.5g}"
    return f"{v:.4f}" if v == 0 or 1 <= a < 1e4 else f"{v:.4e}"


def _header(r: RobustDesign, given: dict) -> list[str]:
    s = r.settings
    src = {k: "" if given.get(k) else " (default)" for k in ("scenarios", "seed")}
    mode_text = {"none": "isothermal oil at each scenario's temperature",
                 "bulk": "each scenario's oil at the bulk temperature of its own heat "
                 "balance, one temperature variable and balance row per scenario"}
    lines = [f"case        {r.case.name}",
             f"thermal     {r.mode} ({mode_text[r.mode]}; the robust NLP supports none and "
             "bulk)",
             gamma_line(r.case),
             f"robust      {s.statistic}: {STATISTIC_TEXT[s.statistic]}",
             f"scenarios   N = {s.scenarios}{src['scenarios']}, Sobol' seed {s.seed}"
             f"{src['seed']}; uncertainty from: {r.spec.source}"]
    for d in r.spec.distributions:
        lines.append(f"              {d.input:<20}{d.text():<40}{d.source}")
    ignored = [d.input for d in r.spec.distributions if d.input in FILM_ONLY]
    if ignored:
        lines.append(f"              ({', '.join(ignored)}: no effect under thermal {r.mode}, "
                     "left out of the scenarios)")
    rb = r.robust
    lines.append(f"solver      IPOPT {rb.status} in {rb.iterations} iterations, "
                 f"{rb.solve_time_s:.2f} s (best of {rb.starts} starts); NLP built in "
                 f"{r.build_time_s:.2f} s; nominal optimum {r.nominal.solve_time_s * 1e3:.1f} ms")
    return lines


def _table(r: RobustDesign) -> list[str]:
    d = r.to_dict()
    n, b = d["nominal"], d["robust"]
    lines = [f"{'quantity':<32}{'nominal':>12}{'robust':>12}{'change':>11}  meaning"]

    def row(key: str, a: float, c: float, meaning: str) -> None:
        ch = "" if a == 0 else f"{100 * (c - a) / a:+.3f} %"
        lines.append(f"{key:<32}{_f(a):>12}{_f(c):>12}{ch:>11}  {meaning}")

    for k, meaning in _DESIGN_ROWS:
        row(k, n[k], b[k], meaning)
    row("loss_at_nominal_W", n["nominal_loss_W"], b["nominal_loss_W"],
        "nominal inputs, case's exact C_m (oilgap evaluate)")
    for k, what in (("mean_W", "mean"), ("p50_W", "p50"), ("p95_W", "p95"),
                    ("cvar95_W", "CVaR95")):
        row(f"mc_{k}", n["mc"][k], b["mc"][k], f"{what}, independent Monte Carlo")
    return lines


def format_robust(r: RobustDesign, given: dict | None = None, defaults: bool = True) -> str:
    """What ``oilgap optimize --robust`` prints.

    Parameters
    ----------
    r : RobustDesign
        The result.
    given : dict, optional
        Which of ``scenarios``, ``seed`` the user gave (the others are marked default).
    defaults : bool
        Print the case, mode, scenarios and solver lines after the tables (False:
        ``-q``).

    Returns
    -------
    str
        The answer first: the p95 gain, the price of robustness, the robust design.
    """
    s = r.settings
    lines = _table(r)
    stat = "CVaR95" if s.statistic == "p95" else s.statistic
    dx = max(abs(v) for v in r.design_change_mm.values())
    rb, nm = r.to_dict()["robust"], r.to_dict()["nominal"]
    answer = [
        f"p95 gain             {r.p95_gain_W:+.4g} W (nominal p95 - robust p95; "
        f"{s.mc_samples} Sobol' draws, seed {s.seed + MC_SEED_OFFSET}, vectorised loss "
        "joint_loss_arrays, case's C_m)",
        f"price of robustness  {r.price_W:+.4g} W at nominal inputs (robust - nominal)",
        f"robust design        delta {rb['delta_mm']:.4f} mm, R {rb['R_mm']:.4f} mm, L "
        f"{rb['L_mm']:.4f} mm: Monte Carlo p95 {rb['mc']['p95_W']:.4f} W (nominal design "
        f"{nm['mc']['p95_W']:.4f} W)"]
    lines += [
        "",
        f"in-sample {stat:<10} {r.robust.objective_W:.6g} W over the N scenarios "
        "(smooth C_m, the NLP's)",
        f"stability            2N = {2 * s.scenarios} scenarios: design moves by at most "
        f"{dx:.3g} mm, its Monte Carlo {s.statistic} by {100 * r.statistic_change:+.3f} % "
        f"-> {'stable' if r.stable else 'NOT stable'} (tolerances: "
        f"{100 * STABILITY_DESIGN_TOL:g} % of each bound range, "
        f"{100 * STABILITY_STAT_TOL:g} % of the statistic); in-sample {stat} "
        f"{100 * r.in_sample_change:+.3f} % (other scenarios, same design)",
    ]
    if r.same_design:
        lines.append("same design          the robust optimum is the nominal one (to 1e-6 of "
                     "each bound range): the nominal design already minimises the statistic "
                     "over these scenarios")
    if r.pareto:
        lines += ["", f"pareto: min {stat} s.t. nominal loss <= eps (smooth C_m, in sample; "
                  "mc_p95 on the independent Monte Carlo)",
                  f"{'eps_W':>12}{'nominal_W':>12}{stat + '_W':>12}{'p95_W':>12}"
                  f"{'mc_p95_W':>12}{'R_mm':>10}{'delta_mm':>10}{'L_mm':>10}"]
        for p in r.pareto:
            lines.append(f"{p['eps_W']:>12.5f}{p['nominal_loss_W']:>12.5f}"
                         f"{p['objective_W']:>12.5f}{p['p95_W']:>12.5f}"
                         f"{p['mc_p95_W']:>12.5f}{p['R_mm']:>10.4f}"
                         f"{p['delta_mm']:>10.4f}{p['L_mm']:>10.4f}")
        if len(r.pareto) == 1:
            lines.append("  (one point: the robust optimum is the nominal one)")
    return layout(answer, [*lines[:len(_table(r))], *wrapped(lines[len(_table(r)):])],
                  _header(r, given or {}), defaults=defaults)


class RobustOptimization(ResultView):
    """The robust optimum beside the nominal one (``og.optimize(robust=...)``).

    Parameters
    ----------
    raw : RobustDesign
        The study's result (:func:`oilgap.studies.robust.robust_design`).
    given : dict, optional
        Which of ``scenarios``, ``seed`` were given (the report marks the others default).
    """

    report_command = "optimize"

    def __init__(self, raw: RobustDesign, given: dict | None = None):
        self.raw = raw
        self.case = raw.case
        self.given = dict(given or {})

    @property
    def nominal(self) -> Any:
        """The nominal optimum (a DesignResult)."""
        return self.raw.nominal

    @property
    def robust(self) -> Any:
        """The robust optimum (a RobustSolve)."""
        return self.raw.robust

    @property
    def price_W(self) -> float:
        """Robust design's nominal loss minus the nominal design's [W]."""
        return self.raw.price_W

    @property
    def p95_gain_W(self) -> float:
        """Nominal design's Monte Carlo p95 minus the robust design's [W]."""
        return self.raw.p95_gain_W

    @property
    def stable(self) -> bool:
        """The 2N check within its tolerances."""
        return self.raw.stable

    def to_case(self, name: str | None = None) -> Any:
        """The robust design as a case (region 1 replaced; ``oilgap evaluate`` reads it).

        Parameters
        ----------
        name : str, optional
            Name of the new case (default: the case's, ``", robust <statistic>"``).

        Returns
        -------
        DesignCase
        """
        from dataclasses import replace

        from oilgap.optim.design.scenarios import design_case
        nom = self.raw.nominal
        dc = design_case(self.case, self.raw.robust.x_m,
                         (nom.machined_rotor_groove_m, nom.machined_stator_groove_m))
        return replace(dc, name=name or f"{self.case.name}, robust {self.raw.settings.statistic}")

    @property
    def defaults(self) -> list[dict]:
        """The case's defaults, the uncertain inputs' laws and the run's settings filled in."""
        from oilgap.model.io.defaults import defaults_block, uncertainty_defaults
        out = case_defaults(self.case) + defaults_block(uncertainty_defaults(self.case))
        s = self.raw.settings
        for key, value, src in (("scenarios", s.scenarios, f"default {DEFAULT_SCENARIOS}"),
                                ("seed", s.seed, "default 0")):
            if not self.given.get(key):
                out.append({"field": key, "value": value, "unit": "", "source": src})
        if s.starts == DEFAULT_STARTS:
            out.append({"field": "starts", "value": s.starts, "unit": "",
                        "source": f"default {DEFAULT_STARTS}"})
        out.append({"field": "cvar_alpha", "value": CVAR_ALPHA, "unit": "",
                    "source": "p95's smooth surrogate: CVaR at this level"})
        return out

    def to_dict(self) -> dict:
        """The ``oilgap optimize --robust --json`` document (without its ``out``)."""
        return {"case": self.case.name, "thermal_mode": self.raw.mode, **self.raw.to_dict(),
                "defaults": self.defaults}

    def to_frame(self) -> Any:
        """One row per design (``nominal``, ``robust``): geometry [mm], loss at nominal
        inputs and the independent Monte Carlo's statistics [W]."""
        d = self.raw.to_dict()
        rows = {}
        for k in ("nominal", "robust"):
            row = {key: d[k][key] for key, _ in _DESIGN_ROWS}
            row["loss_at_nominal_W"] = d[k]["nominal_loss_W"]
            row.update({f"mc_{m}": v for m, v in d[k]["mc"].items()})
            rows[k] = row
        frame = lazy("pandas").DataFrame.from_dict(rows, orient="index")
        frame.index.name = "design"
        return frame

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap optimize --robust`` prints: the p95 gain and the price first
        (``defaults`` False: without the case, mode, scenarios and solver lines, ``-q``)."""
        return format_robust(self.raw, self.given, defaults)

    def plot(self, ax: Any = None) -> Any:
        """The Pareto front (nominal loss vs the statistic) when computed, else the Monte
        Carlo histograms of both designs with their p95 [W]."""
        ax = new_axes(ax)
        r = self.raw
        if len(r.pareto) > 1:
            x = [p["nominal_loss_W"] for p in r.pareto]
            y = [p["objective_W"] for p in r.pareto]
            ax.plot(x, y, "o-", label="min statistic s.t. nominal loss <= eps (in sample)")
            ax.plot(x, [p["mc_p95_W"] for p in r.pareto], "s--",
                    label="p95, independent Monte Carlo")
            ax.set_xlabel("nominal loss [W] (smooth C_m)")
            ax.set_ylabel("upper-tail loss [W]")
            ax.set_title(f"{self.case.name}: nominal vs robust loss")
        else:
            for k, c in (("nominal", "tab:blue"), ("robust", "tab:orange")):
                ax.hist(r.mc_losses_W[k], bins=60, alpha=0.5, color=c, label=f"{k} design")
                ax.axvline(r.mc[k]["p95_W"], color=c, ls="--")
            ax.set_xlabel(f"loss [W] (independent Monte Carlo, case's C_m, {r.mode})")
            ax.set_ylabel("draws")
            ax.set_title(f"{self.case.name}: p95 gain {r.p95_gain_W:+.3g} W, "
                         f"price {r.price_W:+.3g} W")
        ax.legend()
        ax.grid(alpha=0.3)
        return ax


__all__ = ["RobustOptimization", "format_robust"]
