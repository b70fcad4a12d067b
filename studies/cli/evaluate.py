"""``oilgap evaluate``: the viscous loss of a joint, region by region."""

from __future__ import annotations

import argparse
import json

from oilgap.model.case import DesignCase
from oilgap.model.case_io import read_case_toml, seed_case
from oilgap.model.evaluation import CaseEvaluation, evaluate_case
from oilgap.model.oils import get_oil, read_oils_csv
from oilgap.model.units import m_to_mm


def add_parser(sub) -> None:
    from oilgap.studies.cli import finite_float

    p = sub.add_parser("evaluate", help="viscous loss of a joint over its duty cycle",
                       description="Evaluate a joint's viscous loss over its duty cycle, region "
                       "by region. Without CASE: the built-in seed joint, grooved (T = 4).")
    p.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    p.add_argument("--oil", help="oil name (overrides the case), e.g. VG22")
    p.add_argument("--oils", metavar="OILS.csv", help="oils table to look --oil up in")
    p.add_argument("--temp-c", type=finite_float, help="oil temperature [degC]")
    p.add_argument("--depth-m", type=finite_float, help="sea depth [m]")
    p.add_argument("--laminar-law", choices=("couette", "bilgen-boulos"),
                   help="law below the critical Taylor number (default: the case's)")
    p.add_argument("--smoothed", action="store_true",
                   help="without CASE: the seed joint smoothed with epoxy (T = 2)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run)


def load_case(args: argparse.Namespace) -> DesignCase:
    """The case named on the command line (or the seed), with --oil/--oils, --temp-c and
    --depth-m applied and validated. Shared by the subcommands that take a CASE."""
    from dataclasses import replace

    from oilgap.model.case import OperatingPoint

    case = read_case_toml(args.case) if args.case else seed_case(getattr(args, "smoothed",
                                                                         False))
    if getattr(args, "oil", None) or getattr(args, "oils", None):
        cat = read_oils_csv(args.oils) if getattr(args, "oils", None) else None
        case = replace(case, oil=get_oil(args.oil or case.oil.name, cat))
    op = case.operating
    if getattr(args, "temp_c", None) is not None or getattr(args, "depth_m", None) is not None:
        op = OperatingPoint(op.depth_m if args.depth_m is None else args.depth_m,
                            op.oil_temp_C if args.temp_c is None else args.temp_c)
        case = replace(case, operating=op)
    return case


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
    case = load_case(args)
    ev = evaluate_case(case, laminar_law=args.laminar_law)
    if args.json:
        print(json.dumps(ev.to_dict(), indent=2))
    else:
        print(format_evaluation(ev))
    return 0
