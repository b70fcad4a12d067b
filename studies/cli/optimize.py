"""``oilgap optimize``: the region-1 clearance geometry of least mean viscous power.

Thin layer over :class:`oilgap.optim.design.DesignProblem`: loads the case
(or the seed joint), applies the oil/operating overrides, solves the design NLP
and prints the initial and optimal designs side by side, the active constraints
and what each constraint costs (its multiplier in physical units). Exit codes:
2 bad input, 3 infeasible problem, 4 solver failure (from ``oilgap.studies.cli``).
Arguments in :func:`oilgap.studies.cli.parsers.add_optimize`.
"""

from __future__ import annotations

import argparse
import json
import warnings
from pathlib import Path

from oilgap.model.case_io import write_case_toml
from oilgap.model.errors import InputError, OilgapWarning, check_finite, check_positive
from oilgap.model.units import m2_s_to_cst
from oilgap.optim.design import DesignProblem, DesignResult
from oilgap.studies.cli.common import load_case


def _number(args: argparse.Namespace, attr: str, field: str,
            positive: bool = False) -> float | None:
    raw = getattr(args, attr)
    if raw is None:
        return None
    try:
        value = float(raw)
    except ValueError:
        raise InputError(field, raw, "a finite number is required") from None
    return check_positive(field, value) if positive else check_finite(field, value)


def _fmt(v: float) -> str:
    a = abs(v)
    if v == 0 or 1e-3 <= a < 1e5:
        return f"{v:.4f}" if a < 100 else f"{v:.2f}"
    return f"{v:.4e}"


def format_result(res: DesignResult, exact: tuple | None = None) -> str:
    """Side-by-side table of the initial and optimal designs, with the multipliers."""
    prm = res.parameters
    i, o = res.initial.to_dict(), res.optimal.to_dict()
    rows = [
        ("delta_mm", "clearance delta = T3 - T2 (magnetic gap)"),
        ("R_mm", "radius R = T2"),
        ("L_mm", "length L"),
        ("T1_mm", "rotor groove bottom"),
        ("T2_mm", "rotor surface"),
        ("T3_mm", "stator bore"),
        ("T4_mm", "stator groove bottom"),
        ("rotor_groove_depth_mm", "open rotor groove depth"),
        ("stator_groove_depth_mm", "open stator groove depth"),
        ("T", "roughness (T4 - T1)/(T3 - T2)"),
        ("region1_power_W", "rotor-stator clearance"),
        ("region2_power_W", "bearing annulus"),
        ("mean_power_W", "mean viscous power (smooth C_m)"),
        ("torque_capability_Nm", f"torque capability (>= {prm.torque_min_Nm:.5g})"),
        ("airgap_flux_density_T", "air-gap flux density B_g"),
        ("inertia_kgm2", f"rotor inertia (<= {prm.inertia_max_kgm2:.5g})"),
        ("inertia_ratio", "inertia / the case's unfilled rotor"),
    ]
    lines = [
        f"case        {res.case.name}",
        f"oil         {prm.oil} at {prm.oil_temp_C:g} degC, {prm.depth_m:g} m: "
        f"nu = {m2_s_to_cst(prm.nu_m2_s):.4g} cSt, rho = {prm.rho_kg_m3:.1f} kg/m^3",
        f"solver      IPOPT {res.status} in {res.iterations} iterations, "
        f"{res.solve_time_s * 1e3:.1f} ms" + (f" (best of {res.starts} starts)"
                                               if res.starts > 1 else ""),
        "",
        f"{'quantity':<24}{'initial':>13}{'optimal':>13}{'change':>11}  meaning",
    ]
    for key, meaning in rows:
        a, b = i[key], o[key]
        pct = 100 * (b - a) / a if a != 0 else None
        ch = "" if pct is None else ("0.0 %" if abs(pct) < 0.05 else f"{pct:+.1f} %")
        lines.append(f"{key:<24}{_fmt(a):>13}{_fmt(b):>13}{ch:>11}  {meaning}")
    if exact is not None:
        a, b = exact[0].total_mean_power_W, exact[1].total_mean_power_W
        lines.append(f"{'mean_power_exact_W':<24}{_fmt(a):>13}{_fmt(b):>13}"
                     f"{100 * (b - a) / a:>+9.1f} %  same, case's exact C_m (oilgap evaluate)")
    lines += ["", "active constraints and what they cost (d optimal power / d bound):"]
    act = [res.multipliers[n] for n in res.active_constraints]
    if not act:
        lines.append("  none (unconstrained optimum)")
    for mu in act:
        lines.append(f"  {mu.name:<25}{mu.constraint:<52}{mu.value:+.4g} {mu.unit}")
    tq = res.multipliers.get("torque_min")
    if tq is not None and tq.active:
        lines.append(f"  (1 % more required torque costs {tq.value * prm.torque_min_Nm / 100:+.4g}"
                     " W)")
    inactive = [n for n, mu in res.multipliers.items() if not mu.active]
    if inactive:
        lines.append("inactive: " + ", ".join(inactive))
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    """Solve the design NLP and print (or write) the result; returns the exit code."""
    args.temp_c = _number(args, "temp_c", "--temp-c")
    args.depth_m = _number(args, "depth_m", "--depth-m")
    torque_min = _number(args, "torque_min_nm", "--torque-min-nm", positive=True)
    inertia_ratio = _number(args, "inertia_max_ratio", "--inertia-max-ratio", positive=True)
    try:
        starts = int(args.starts)
    except ValueError:
        raise InputError("--starts", args.starts, "an integer >= 1 is required") from None
    if starts < 1:
        raise InputError("--starts", args.starts, "an integer >= 1 is required")
    case = load_case(args)
    res = DesignProblem(case, verbose=args.verbose).solve(
        torque_min_Nm=torque_min, inertia_max_ratio=inertia_ratio, starts=starts)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)
        exact = res.evaluate()
    out_path = None
    if args.out:
        try:
            out_path = write_case_toml(res.to_case(), args.out)
        except OSError as e:
            raise InputError("--out", args.out, f"cannot be written ({e.strerror})") from None
    if args.json:
        d = res.to_dict()
        d["initial"]["mean_power_exact_W"] = exact[0].total_mean_power_W
        d["optimal"]["mean_power_exact_W"] = exact[1].total_mean_power_W
        d["out"] = str(out_path) if out_path else None
        print(json.dumps(d, indent=2))
    else:
        print(format_result(res, exact))
        if out_path:
            print(f"\nwrote {Path(out_path)}")
    return 0
