"""``oilgap evaluate``: the viscous loss of a joint, region by region, under a thermal mode
(arguments in :func:`oilgap.studies.cli.parsers.add_evaluate`)."""

from __future__ import annotations

import argparse
import json

from oilgap.model.evaluation import CaseEvaluation, evaluate_case
from oilgap.model.units import m_to_mm
from oilgap.studies.cli.common import gamma_fields, gamma_line, load_case, thermal_case

MODE_TEXT = {
    "none": "isothermal oil: the seed paper's model",
    "film": "film heating at the given oil temperature",
    "full": "film heating at the oil temperature of the heat balance to the sea",
}
"""What each thermal mode computes, for the header line."""

BEARING_MODEL_TEXT = {
    "skf": "SKF frictional-moment model (rolling, sliding, drag)",
    "palmgren": "Palmgren (load-independent M0 + load-dependent M1)",
}
"""The rolling bearing's model, for the header line."""


def _header(ev: CaseEvaluation) -> list[str]:
    """The case, thermal-mode, balance, oil and friction lines."""
    if ev.thermal_mode_default:
        mode = (f"thermal     {ev.thermal_mode} (default: the best physics this case allows; "
                "--thermal none for the seed's isothermal model")
    else:
        mode = f"thermal     {ev.thermal_mode} ({MODE_TEXT[ev.thermal_mode]}"
    lines = [f"case        {ev.case_name}", mode + ")"]
    temp = f"{ev.oil_temp_C:g} degC"
    if ev.sea_temp_C is not None:
        temp = f"{ev.oil_temp_C:.2f} degC (heat balance)"
        lines.append(
            f"balance     sea {ev.sea_temp_C:g} degC, R_th = {ev.resistance_K_per_W:g} K/W, "
            f"Q = {ev.other_heat_W:g} W: oil at {ev.oil_temp_C:.2f} degC, "
            f"{ev.oil_temp_C - ev.sea_temp_C:.2f} K above the sea")
    lines += [
        f"oil         {ev.oil} at {temp}, {ev.depth_m:g} m: "
        f"nu = {ev.nu_cSt:.4g} cSt, rho = {ev.density_kg_m3:.1f} kg/m^3",
        f"friction    C_m form {ev.form}, laminar law {ev.laminar_law}; "
        f"peak speed {ev.peak_speed_rpm:g} rpm",
    ]
    lines += [f"rolling brg {b.name} ({b.kind}, d_m = {m_to_mm(b.pitch_diameter_m):g} mm): "
              f"{BEARING_MODEL_TEXT.get(b.model, b.model)}, at the bulk oil's viscosity"
              for b in ev.bearings]
    return lines


def _bearing_rows(ev: CaseEvaluation) -> list[str]:
    """The rolling bearing's own rows below the regions (none without a bearing)."""
    if not ev.bearings:
        return []
    lines = ["", f"{'rolling bearing':<16}{'model':<10}{'mean W':>9}{'torque Nm':>11}"
                 "  mean W per term"]
    for b in ev.bearings:
        terms = ", ".join(f"{k} {v:.3g}" for k, v in b.terms.items())
        lines.append(f"{b.name:<16}{b.model:<10}{b.mean_power_W:>9.3f}"
                     f"{b.torque_peak_Nm:>11.4f}  {terms}")
    return lines


def _bearing_notes(ev: CaseEvaluation) -> list[str]:
    """What the bearing's row is, where it lies against its model's range, and every
    default the tool filled in."""
    notes = []
    for b in ev.bearings:
        notes.append(f"rolling bearing {b.name}: its friction and drag at the bulk oil's "
                     "viscosity under every thermal mode (not a film: no film factor); "
                     "region 2 'bearing' is the oil annulus beside it, a separate term")
        notes.append(f"  at the peak speed: kappa = nu/nu_1 = {b.kappa_peak:.3g}, "
                     f"n d_m = {b.speed_factor_peak_mm_rpm:.4g} mm rpm")
        notes += [f"  {v}" for v in b.validity_notes]
        if b.default_notes:
            notes.append("  defaults the tool filled in (give the key in [bearing] to "
                         "change one):")
            notes += [f"    {v}" for v in b.default_notes]
    return notes


def _film_notes(ev: CaseEvaluation) -> list[str]:
    """What the film columns mean under the mode."""
    notes = []
    if ev.thermal_mode == "none":
        notes.append("Na_peak, film, rise K: the film heating at the peak speed that "
                     "--thermal none leaves out (not applied; --thermal film applies it)")
    else:
        notes.append("Na_peak, film, rise K: Nahme number, heated/isothermal torque and the "
                     "film's hottest point above the bulk, at the peak speed")
    if any(r.film_temp_rise_peak_K is None for r in ev.regions):
        notes.append("rise K '-': Taylor vortices at the peak speed (the film correction is "
                     "laminar-only and fades out there)")
    return notes


def format_evaluation(ev: CaseEvaluation, gamma: str | None = None) -> str:
    """Human-readable table of an evaluation (``gamma``: the header line naming the groove
    exponent and its source, :func:`~oilgap.studies.cli.common.gamma_line`)."""
    lines = _header(ev) + ([gamma] if gamma else []) + [
        "",
        f"{'region':<14}{'R mm':>7}{'gap mm':>8}{'L mm':>7}{'T':>6}{'Re_peak':>10}"
        f"{'Ta_peak':>10}{'Cm_peak':>11}{'mean W':>9}{'Na_peak':>9}{'film':>7}{'rise K':>8}"
        "  regimes visited",
    ]
    for r in ev.regions:
        rise = "-" if r.film_temp_rise_peak_K is None else f"{r.film_temp_rise_peak_K:.2f}"
        lines.append(
            f"{r.name:<14}{m_to_mm(r.radius_m):>7.2f}{m_to_mm(r.gap_m):>8.3f}{m_to_mm(r.length_m):>7.2f}"
            f"{r.roughness_T:>6.2f}{r.Re_peak:>10.4g}{r.Ta_peak:>10.4g}{r.Cm_peak:>11.4g}"
            f"{r.mean_power_W:>9.3f}{r.nahme_peak:>9.3g}{r.film_factor_peak:>7.3f}{rise:>8}"
            f"  {', '.join(r.regimes)}")
    lines += _bearing_rows(ev)
    parts = [(r.name, r.mean_power_W) for r in ev.regions]
    parts += [(f"rolling bearing {b.name}", b.mean_power_W) for b in ev.bearings]
    share = ", ".join(f"{n} {100 * p / ev.total_mean_power_W:.0f} %"
                      for n, p in parts) if ev.total_mean_power_W > 0 else ""
    label = "total mean power          " if ev.bearings else "total mean viscous power  "
    lines += ["", f"{label} {ev.total_mean_power_W:.3f} W   ({share})"]
    if ev.thermal_mode != "none":
        iso = ev.isothermal_total_mean_power_W
        where = " at [operating] oil_temp_C" if ev.thermal_mode == "full" else ""
        change = (f"; the heating changes the loss by "
                  f"{100 * (ev.total_mean_power_W / iso - 1):+.1f} %") if iso > 0 else ""
        lines.append(f"isothermal (seed model)    {iso:.3f} W   (--thermal none{where}{change})")
    lines += [
        f"viscous torque at peak     {ev.viscous_torque_peak_Nm:.4f} N m",
        f"energy per cycle           {ev.cycle_energy_J:.1f} J",
        "",
    ] + _film_notes(ev) + _bearing_notes(ev)
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    """Evaluate the case and print the table (or JSON); returns the exit code."""
    case, _ = thermal_case(load_case(args), args)
    ev = evaluate_case(case, laminar_law=args.laminar_law, thermal=args.thermal)
    if args.json:
        print(json.dumps({**ev.to_dict(), **gamma_fields(case)}, indent=2))
    else:
        print(format_evaluation(ev, gamma_line(case)))
    return 0
