"""The base-law comparison of the loop (``base = "auto"``) as text and Markdown."""

from __future__ import annotations

import math


def _cell(v: float, fmt: str) -> str:
    return format(v, fmt) if isinstance(v, (int, float)) and math.isfinite(v) else "-"


def base_rows(est) -> list[list[str]]:
    """One row per candidate base: name, free parameters (base and accepted effects), its
    effects, the held-out log-RMSE of the base alone, the log-RMSE in-sample and held out
    and the RMSE [W] in-sample and held out of base and effects, and whether it was chosen."""
    return [[r["base"], str(r["free_parameters"]), ", ".join(r.get("effects", [])) or "none",
             _cell(r.get("base_heldout_log_rmse", float("nan")), ".4f"),
             _cell(r["log_rmse"], ".4f"), _cell(r["heldout_log_rmse"], ".4f"),
             _cell(r["rmse_W"], ".3f"), _cell(r["heldout_rmse_W"], ".3f"),
             "chosen" if r["chosen"] else (r.get("error") or "")]
            for r in getattr(est, "base_selection_", [])]


HEADER = ["base", "free", "effects", "held-out log-RMSE, base alone", "log-RMSE",
          "held-out log-RMSE", "RMSE W", "held-out RMSE W", ""]


def base_summary_lines(est) -> list[str]:
    """The terminal's table of the candidate bases (empty when ``--base`` forced one)."""
    rows = base_rows(est)
    if not rows:
        return []
    out = [f"base law    chosen by held-out log-RMSE over {len(rows)} candidates, each after "
           f"its own effect search (a simpler one kept within the margin {est.margin:g})"]
    out.append(f"  {'base':<11}{'free':>5}{'alone':>8}{'log-RMSE':>9}{'held-out':>9}"
               f"{'held-out W':>11}  {'':<6}  effects")
    # the mark before the effects: a long list of effects wraps, the columns stay aligned;
    # the in-sample RMSE in W is in report.md and loop.json
    out += [f"  {r[0]:<11}{r[1]:>5}{r[3]:>8}{r[4]:>9}{r[5]:>9}{r[7]:>11}"
            f"  {r[8]:<6}  {r[2]}" for r in rows]
    return out


def base_markdown(est, markdown_rows) -> list[str]:
    """The report's section on the base law's choice (empty when it was forced)."""
    rows = base_rows(est)
    if not rows:
        return []
    return ["## Base law chosen by held-out error", "",
            "Each candidate base was fitted on all oil runs, given its own effect search, and "
            "cross-validated on the same folds (each fold refitted on its training groups "
            "only, what it cannot identify held at its prior); the least held-out log-RMSE "
            "of base and accepted effects wins unless a simpler one (fewer base parameters "
            f"and effects) comes within the margin {est.margin:g} of it. The base alone's "
            "held-out error is shown beside it: a flexible base can take in an effect's "
            "share before the search, so the comparison is made after it.", "",
            markdown_rows(HEADER, rows), ""]
