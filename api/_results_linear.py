"""The linear actuator's block of ``oilgap evaluate``'s text: the loss by element.

Motor gap (region 1), the motor's rolling bearing, the screw, the rod guide and the
passages, each with its share of the total, then the drive's peak numbers
(:class:`~oilgap.model.linear.report.LinearSummary`).
"""

from __future__ import annotations

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
