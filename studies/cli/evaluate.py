"""``oilgap evaluate``: the viscous loss of a joint, region by region (arguments in
:func:`oilgap.studies.cli.parsers.add_evaluate`)."""

from __future__ import annotations

import argparse
import json

from oilgap.model.evaluation import CaseEvaluation, evaluate_case
from oilgap.model.units import m_to_mm
from oilgap.studies.cli.common import load_case


def format_evaluation(ev: CaseEvaluation) -> str:
    """Human-readable table of an evaluation."""
    lines = [
        f"case        {ev.case_name}",
        f"oil         {ev.oil} at {ev.oil_temp_C:g} degC, {ev.depth_m:g} m: "
        f"nu = {ev.nu_cSt:.4g} cSt, rho = {ev.density_kg_m3:.1f} kg/m^3",
        f"friction    C_m form {ev.form}, laminar law {ev.laminar_law}; "
        f"peak speed {ev.peak_speed_rpm:g} rpm",
        "",
        f"{'region':<14}{'R mm':>7}{'gap mm':>8}{'L mm':>7}{'T':>6}{'Re_peak':>10}"
        f"{'Ta_peak':>10}{'Cm_peak':>11}{'mean W':>9}  regimes visited",
    ]
    for r in ev.regions:
        lines.append(
            f"{r.name:<14}{m_to_mm(r.radius_m):>7.2f}{m_to_mm(r.gap_m):>8.3f}{m_to_mm(r.length_m):>7.2f}"
            f"{r.roughness_T:>6.2f}{r.Re_peak:>10.4g}{r.Ta_peak:>10.4g}{r.Cm_peak:>11.4g}"
            f"{r.mean_power_W:>9.3f}  {', '.join(r.regimes)}")
    share = ", ".join(f"{r.name} {100 * r.mean_power_W / ev.total_mean_power_W:.0f} %"
                      for r in ev.regions) if ev.total_mean_power_W > 0 else ""
    lines += [
        "",
        f"total mean viscous power   {ev.total_mean_power_W:.3f} W   ({share})",
        f"viscous torque at peak     {ev.viscous_torque_peak_Nm:.4f} N m",
        f"energy per cycle           {ev.cycle_energy_J:.1f} J",
    ]
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    """Evaluate the case and print the table (or JSON); returns the exit code."""
    case = load_case(args)
    ev = evaluate_case(case, laminar_law=args.laminar_law)
    if args.json:
        print(json.dumps(ev.to_dict(), indent=2))
    else:
        print(format_evaluation(ev))
    return 0
