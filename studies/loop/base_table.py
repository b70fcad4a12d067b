"""The base-law comparison of the loop (``base = "auto"``) as text and Markdown."""

from __future__ import annotations

import math


def _cell(v: float, fmt: str) -> str:
    return format(v, fmt) if isinstance(v, (int, float)) and math.isfinite(v) else "-"


def base_rows(est) -> list[list[str]]:
    """One row per candidate base: name, free parameters, log-RMSE in-sample and held out,
    RMSE [W] in-sample and held out, and whether it was chosen."""
    return [[r["base"], str(r["free_parameters"]), _cell(r["log_rmse"], ".4f"),
             _cell(r["heldout_log_rmse"], ".4f"), _cell(r["rmse_W"], ".3f"),
             _cell(r["heldout_rmse_W"], ".3f"),
             "chosen" if r["chosen"] else (r.get("error") or "")]
            for r in getattr(est, "base_selection_", [])]


HEADER = ["base", "free", "log-RMSE", "held-out log-RMSE", "RMSE W", "held-out RMSE W", ""]


def base_summary_lines(est) -> list[str]:
    """The terminal's table of the candidate bases (empty when ``--base`` forced one)."""
    rows = base_rows(est)
    if not rows:
        return []
    out = [f"base law    chosen by held-out log-RMSE over {len(rows)} candidates (a simpler "
           f"one kept within the margin {est.margin:g})"]
    out.append(f"  {'base':<11}{'free':>5}{'log-RMSE':>10}{'held-out':>10}{'RMSE W':>11}"
               f"{'held-out W':>12}")
    out += [f"  {r[0]:<11}{r[1]:>5}{r[2]:>10}{r[3]:>10}{r[4]:>11}{r[5]:>12}  {r[6]}"
            for r in rows]
    return out


def base_markdown(est, markdown_rows) -> list[str]:
    """The report's section on the base law's choice (empty when it was forced)."""
    rows = base_rows(est)
    if not rows:
        return []
    return ["## Base law chosen by held-out error", "",
            "Each candidate base was fitted on all oil runs and cross-validated on the same "
            "folds (each fold refitted on its training groups only, what it cannot identify "
            "held at its prior); the least held-out log-RMSE wins unless a simpler base "
            f"(fewer free parameters) comes within the margin {est.margin:g} of it.", "",
            markdown_rows(HEADER, rows), ""]
