"""The lead-loss front of a linear actuator: the least loss at each screw lead.

For each lead on a grid over the case's lead bounds the linear design NLP
(:func:`oilgap.optim.design.linear.solve_linear_design`) is solved with the lead held, its
other variables (guide clearance, passage diameter, the motor's gap and grooves) free,
under the same constraints; the optimum is evaluated exactly under the thermal mode
(:func:`oilgap.model.evaluation.evaluate_case`), element by element. A lead where no
design meets the rod force (too long) or the motor speed (too short) is a row with its
status, not a point. ``oilgap study pareto`` runs it on a linear case.

References
----------
.. [1] docs/linear-joint.md (the elements and the NLP).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import InfeasibleError, SolverError
from oilgap.model.evaluation import evaluate_case
from oilgap.optim.design.linear import (
    LINEAR_VARIABLES,
    linear_bounds,
    linear_design_case,
    solve_linear_design,
)

from .io.files import atomic_write, atomic_write_text

OUTPUTS = ("lead_front.csv", "lead_front.png", "summary.md")
"""Files the study writes."""


def lead_front(case: DesignCase, points: int = 12, mode: str = "none") -> pd.DataFrame:
    """The least loss at each lead (module docstring).

    Parameters
    ----------
    case : DesignCase
        A linear case.
    points : int
        Leads on the grid, geometric over the case's lead bounds [-].
    mode : str
        Thermal mode.

    Returns
    -------
    DataFrame
        One row per lead: ``lead_mm``, ``status``, ``mean_power_W`` and each element's
        ``*_W`` [W], the other variables at the optimum [mm].
    """
    lo, hi = linear_bounds(case)
    rows = []
    for lead in np.geomspace(lo[0], hi[0], int(points)):
        row = {"lead_mm": float(lead)}
        try:
            d = solve_linear_design(case, mode, lead_mm=float(lead))
        except (InfeasibleError, SolverError) as e:
            kind = "infeasible" if isinstance(e, InfeasibleError) else "solver failure"
            rows.append({**row, "status": kind, "error": str(e)})
            continue
        ev = evaluate_case(linear_design_case(case, d.x_mm), thermal=mode)
        row.update(status="ok", mean_power_W=ev.total_mean_power_W,
                   motor_gap_W=ev.regions[0].mean_power_W,
                   motor_bearing_W=sum(b.mean_power_W for b in ev.bearings),
                   **{f"{e.name.replace(' ', '_')}_W": e.mean_power_W
                      for e in ev.linear_elements},
                   **dict(zip(LINEAR_VARIABLES[1:], map(float, d.x_mm[1:]), strict=True)))
        rows.append(row)
    return pd.DataFrame(rows)


def write_lead_front(df: pd.DataFrame, out: str | Path, case_name: str) -> list[Path]:
    """The front's CSV, figure (loss by element against lead) and summary.md.

    Parameters
    ----------
    df : DataFrame
        :func:`lead_front`'s result.
    out : path
        The folder.
    case_name : str
        For the titles.

    Returns
    -------
    list of Path
        The files written.
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    paths = [atomic_write(out / OUTPUTS[0], lambda f: df.to_csv(f, index=False), newline="")]
    ok = df[df["status"] == "ok"]
    fig, ax = plt.subplots(figsize=(6, 4))
    parts = [c for c in ("motor_gap_W", "motor_bearing_W", "screw_W", "rod_guide_W",
                         "passages_W") if c in ok]
    ax.stackplot(ok["lead_mm"], *[ok[c] for c in parts], labels=[p[:-2] for p in parts])
    ax.set_xlabel("screw lead [mm]")
    ax.set_ylabel("mean loss over the cycle [W]")
    ax.set_title(f"least loss at each lead: {case_name}")
    ax.legend(fontsize=8)
    paths.append(atomic_write(out / OUTPUTS[1], lambda f: fig.savefig(f, format="png", dpi=110),
                              binary=True))
    plt.close(fig)
    paths.append(atomic_write_text(out / OUTPUTS[2], summary_text(df, case_name)))
    return paths


def summary_text(df: pd.DataFrame, case_name: str) -> str:
    """The front as text: the best lead first, then one line per lead.

    Parameters
    ----------
    df : DataFrame
        :func:`lead_front`'s result.
    case_name : str
        The case.

    Returns
    -------
    str
        Text (also summary.md).
    """
    ok = df[df["status"] == "ok"]
    lines = []
    if len(ok):
        best = ok.loc[ok["mean_power_W"].idxmin()]
        lines.append(f"least loss {best['mean_power_W']:.4g} W at lead {best['lead_mm']:.4g} mm "
                     f"({case_name}); {len(ok)} of {len(df)} leads feasible")
    else:
        lines.append(f"no lead on the grid is feasible ({case_name})")
    lines += ["", f"{'lead mm':>9}{'loss W':>10}{'gap W':>9}{'passages W':>12}  status"]
    for _, r in df.iterrows():
        if r["status"] == "ok":
            lines.append(f"{r['lead_mm']:>9.4g}{r['mean_power_W']:>10.4g}"
                         f"{r['motor_gap_W']:>9.4g}{r['passages_W']:>12.4g}  ok")
        else:
            lines.append(f"{r['lead_mm']:>9.4g}{'-':>10}{'-':>9}{'-':>12}  {r['status']}")
    return "\n".join(lines) + "\n"
