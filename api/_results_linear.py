"""The linear actuator's block of ``oilgap evaluate``'s text: the loss by element.

Motor gap (region 1), the motor's rolling bearing, the screw, the rod guide and the
passages, each with its share of the total, then the drive's peak numbers
(:class:`~oilgap.model.linear.report.LinearSummary`).
"""

from __future__ import annotations

import numpy as np

from oilgap.model.evaluation import CaseEvaluation


def linear_rows(ev: CaseEvaluation) -> list[str]:
    """The loss-by-element table of a linear case (none for a rotary joint).

    Parameters
    ----------
    ev : CaseEvaluation
        The evaluation.

    Returns
    -------
    list of str
        Lines of text.
    """
    if ev.linear is None:
        return []
    s = ev.linear
    total = ev.total_mean_power_W
    parts = [("motor gap" if i == 0 else f"motor {r.name}", r.mean_power_W, "")
             for i, r in enumerate(ev.regions)]
    parts += [(f"motor bearing {b.name}", b.mean_power_W,
               f"{b.torque_peak_Nm:.4g} N m") for b in ev.bearings]
    parts += [(e.name, e.mean_power_W, f"{e.peak_load:.4g} {e.peak_load_unit}")
              for e in ev.linear_elements]
    lines = ["", f"linear drive: lead {s.lead_mm:g} mm, peak rod velocity "
             f"{s.peak_rod_velocity_m_s:.4g} m/s -> motor {s.peak_motor_speed_rpm:.4g} rpm "
             "(omega = 2 pi v/lead)",
             f"{'element':<26}{'mean W':>10}{'share':>8}   at peak"]
    for name, p, peak in parts:
        share = f"{100 * p / total:.1f} %" if total > 0 else "-"
        lines.append(f"{name:<26}{p:>10.4f}{share:>8}   {peak}")
    lines.append(f"{'total over the cycle':<26}{total:>10.4f}")
    lines.append(f"passages at peak: {s.passage_velocity_peak_m_s:.3g} m/s, Re "
                 f"{s.passage_reynolds_peak:.3g}, dp {s.passage_pressure_drop_peak_Pa / 1e5:.4g}"
                 f" bar; the guide clearance would carry {100 * s.guide_leakage_share_peak:.2g}"
                 " % of the flow at that dp (taken through the passages)")
    return lines


class LinearOptimization:
    """A linear actuator's optimum beside the case as given (``og.optimize`` on a linear
    case): the design variables, the loss by element of both under the thermal mode
    (evaluated exactly, :func:`oilgap.model.evaluation.evaluate_case`), the constraints.

    Parameters
    ----------
    design : oilgap.optim.design.linear.LinearDesign
        The NLP's optimum.
    case : DesignCase
        The case as given.
    mode : str
        The thermal mode the designs are evaluated under.
    header : str
        The thermal-mode line.
    """

    def __init__(self, design, case, mode: str, header: str):
        from oilgap.model.evaluation import evaluate_case
        from oilgap.optim.design.linear import linear_design_case
        self.design = design
        self.case = case
        self.optimum_case = linear_design_case(case, design.x_mm)
        self.header = header
        self.initial = evaluate_case(case, thermal=mode)
        self.optimum = evaluate_case(self.optimum_case, thermal=mode)

    def to_case(self):
        """The optimum as a case (``--out`` writes it).

        Returns
        -------
        DesignCase
            The case with the optimum's lead, clearances, passage and motor gap.
        """
        return self.optimum_case

    @staticmethod
    def _elements(ev: CaseEvaluation) -> dict:
        out = {("motor gap" if i == 0 else r.name): r.mean_power_W
               for i, r in enumerate(ev.regions)}
        if ev.bearings:
            out["motor bearing"] = sum(b.mean_power_W for b in ev.bearings)
        out.update({e.name: e.mean_power_W for e in ev.linear_elements})
        out["total"] = ev.total_mean_power_W
        return out

    def to_dict(self) -> dict:
        """Plain-dict form (``--json``): variables [mm], losses by element [W], constraints.

        Returns
        -------
        dict
            ``variables`` (name -> initial, optimum, lower, upper [mm]),
            ``loss_by_element_W`` (``initial``, ``optimum``), ``oil_temp_C``,
            ``constraints`` (name -> value, limit, unit, sense), ``nlp``.
        """
        from oilgap.optim.design.linear import LINEAR_VARIABLES
        d = self.design
        return {
            "thermal_mode": self.optimum.thermal_mode,
            "variables": {k: {"initial": float(a), "optimum": float(b), "lower": float(lo),
                              "upper": float(hi)}
                          for k, a, b, lo, hi in zip(LINEAR_VARIABLES, d.x0_mm, d.x_mm,
                                                     d.lower_mm, d.upper_mm, strict=True)},
            "loss_by_element_W": {"initial": self._elements(self.initial),
                                  "optimum": self._elements(self.optimum)},
            "oil_temp_C": {"initial": self.initial.oil_temp_C,
                           "optimum": self.optimum.oil_temp_C},
            "constraints": {k: {"value": v[0], "limit": v[1], "unit": v[2], "sense": v[3]}
                            for k, v in d.constraints.items()},
            "nlp": {"mode": d.nlp_mode, "iterations": d.iterations,
                    "mean_power_W": d.mean_power_W},
        }

    def summary(self, defaults: bool = True) -> str:
        """The optimum first, then the design variables, the loss by element and the
        constraints (``defaults`` False leaves out the case, thermal and oil lines, ``-q``).

        Returns
        -------
        str
            Text.
        """
        from oilgap.optim.design.linear import LINEAR_VARIABLES
        d, a, b = self.design, self._elements(self.initial), self._elements(self.optimum)
        lines = [f"optimum     {b['total']:.4g} W mean over the cycle (as given "
                 f"{a['total']:.4g} W, {100 * (b['total'] / a['total'] - 1):+.0f} %)",
                 *([f"case        {self.case.name}", self.header,
                    f"oil         {self.optimum.oil} at {self.optimum.oil_temp_C:.2f} degC "
                    f"(as given {self.initial.oil_temp_C:.2f} degC)"] if defaults else []), "",
                 f"{'variable':<26}{'as given':>10}{'optimum':>10}{'bounds':>18}"]
        for k, x0, x, lo, hi in zip(LINEAR_VARIABLES, d.x0_mm, d.x_mm, d.lower_mm,
                                    d.upper_mm, strict=True):
            at = " (at bound)" if min(x - lo, hi - x) <= 1e-6 * max(hi, 1e-9) else ""
            lines.append(f"{k:<26}{x0:>10.4g}{x:>10.4g}{f'[{lo:.4g}, {hi:.4g}]':>18}{at}")
        lines += ["", f"{'element':<26}{'as given W':>12}{'optimum W':>12}"]
        lines += [f"{k:<26}{a[k]:>12.4f}{b[k]:>12.4f}" for k in a]
        lines += ["", "constraints at the optimum"]
        for k, (v, lim, unit, sense) in d.constraints.items():
            shown = (v * 1e6, lim * 1e6, "mL") if unit == "m^3" else (v, lim, unit)
            lines.append(f"  {k:<34}{shown[0]:>10.4g} {sense} {shown[1]:.4g} {shown[2]}")
        lines.append(f"NLP: thermal {d.nlp_mode}, smooth C_m, {d.iterations} IPOPT "
                     "iterations; the motor's radius and length as given; the losses above "
                     "are the evaluation's (exact C_m)")
        return "\n".join(lines)


class LinearRobustOptimization:
    """The robust linear design beside the nominal one (``optimize --robust`` on a linear
    case, :func:`oilgap.optim.design.linear_robust.solve_linear_robust`).

    Parameters
    ----------
    res : oilgap.optim.design.linear_robust.LinearRobustDesign
        The solve.
    case : DesignCase
        The case as given.
    """

    def __init__(self, res, case):
        from oilgap.optim.design.linear import linear_design_case
        self.res = res
        self.case = case
        self.optimum_case = linear_design_case(case, res.robust.x_mm)

    def to_case(self):
        """The robust optimum as a case (``--out``).

        Returns
        -------
        DesignCase
            The case with the robust design.
        """
        return self.optimum_case

    def plot(self, ax=None):
        """The scenarios' losses at the robust and the nominal optimum, sorted.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (default: a new figure).

        Returns
        -------
        matplotlib Axes
            Loss [W] against the scenarios' rank.
        """
        import matplotlib.pyplot as plt
        if ax is None:
            _, ax = plt.subplots(figsize=(6, 4))
        for key in ("robust", "nominal"):
            v = np.sort(np.asarray(self.res.losses_W[key]))
            ax.plot(np.arange(1, len(v) + 1) / len(v), v, marker=".", label=key)
        ax.set_xlabel("share of scenarios [-]")
        ax.set_ylabel("mean loss over the cycle [W]")
        ax.set_title(f"{self.res.statistic} over {self.res.scenarios} scenarios")
        ax.legend()
        return ax

    def _stats(self, key: str) -> dict:
        v = np.asarray(self.res.losses_W[key])
        return {"p5_W": float(np.percentile(v, 5)), "p50_W": float(np.percentile(v, 50)),
                "p95_W": float(np.percentile(v, 95)), "mean_W": float(v.mean())}

    def to_dict(self) -> dict:
        """Plain-dict form (``--json``).

        Returns
        -------
        dict
            ``statistic``, ``scenarios``, the two designs [mm] and their loss statistics
            over the scenarios [W], the constraints at the robust optimum.
        """
        from oilgap.optim.design.linear import LINEAR_VARIABLES
        r = self.res
        return {"statistic": r.statistic, "scenarios": r.scenarios,
                "thermal_mode": r.robust.nlp_mode,
                "robust": {"design_mm": dict(zip(LINEAR_VARIABLES, map(float, r.robust.x_mm),
                                                 strict=True)), **self._stats("robust")},
                "nominal": {"design_mm": dict(zip(LINEAR_VARIABLES, map(float, r.nominal.x_mm),
                                                  strict=True)), **self._stats("nominal")},
                "constraints": {k: {"value": v[0], "limit": v[1], "unit": v[2], "sense": v[3]}
                                for k, v in r.robust.constraints.items()}}

    def summary(self, defaults: bool = True) -> str:
        """The robust optimum's statistic first, then both designs side by side (``defaults``
        False leaves out the case line, ``-q``).

        Returns
        -------
        str
            Text.
        """
        from oilgap.optim.design.linear import LINEAR_VARIABLES
        r, a, b = self.res, self._stats("robust"), self._stats("nominal")
        lines = [f"robust optimum ({r.statistic} over {r.scenarios} scenarios, thermal "
                 f"{r.robust.nlp_mode}): "
                 f"p95 {a['p95_W']:.4g} W, mean {a['mean_W']:.4g} W (nominal optimum: p95 "
                 f"{b['p95_W']:.4g} W, mean {b['mean_W']:.4g} W)",
                 *([f"case        {self.case.name}"] if defaults else []), "",
                 f"{'variable':<26}{'robust':>10}{'nominal':>10}"]
        lines += [f"{k:<26}{x:>10.4g}{y:>10.4g}" for k, x, y in
                  zip(LINEAR_VARIABLES, r.robust.x_mm, r.nominal.x_mm, strict=True)]
        lines += ["", "constraints at the robust optimum"]
        for k, (v, lim, unit, sense) in r.robust.constraints.items():
            shown = (v * 1e6, lim * 1e6, "mL") if unit == "m^3" else (v, lim, unit)
            lines.append(f"  {k:<34}{shown[0]:>10.4g} {sense} {shown[1]:.4g} {shown[2]}")
        return "\n".join(lines)


class LeadFront:
    """The lead-loss front of a linear actuator (``oilgap study pareto`` on a linear
    case, :func:`oilgap.studies.linear_lead.lead_front`).

    Parameters
    ----------
    df : DataFrame
        One row per lead.
    case_name : str
        The case.
    thermal_mode : str
        The mode.
    out : Path or None
        The folder written.
    """

    def __init__(self, df, case_name: str, thermal_mode: str, out):
        self.df = df
        self.case_name = case_name
        self.thermal_mode = thermal_mode
        self.out = out

    def summary(self, defaults: bool = True) -> str:
        """The best lead first, then the front, then the thermal mode (``defaults`` False
        leaves it out, ``-q``).

        Returns
        -------
        str
            Text.
        """
        from oilgap.studies.linear_lead import summary_text
        text = summary_text(self.df, self.case_name) + (f"thermal {self.thermal_mode}\n"
                                                         if defaults else "")
        return text + (f"\nwrote {self.out}/" if self.out else "")

    def to_dict(self) -> dict:
        """``{thermal_mode, rows, out}`` (rows as records).

        Returns
        -------
        dict
            The front.
        """
        rows = self.df.astype(object).where(self.df.notna(), None).to_dict("records")
        return {"thermal_mode": self.thermal_mode, "rows": rows,
                "out": None if self.out is None else str(self.out)}

    def to_json(self) -> str:
        """:meth:`to_dict` as JSON.

        Returns
        -------
        str
            JSON text.
        """
        from oilgap.model.io.serialize import dumps
        return dumps(self.to_dict())
