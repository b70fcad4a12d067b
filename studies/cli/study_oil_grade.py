"""``oilgap study oil-grade``: the grade table and the recommendation (arguments in
:func:`oilgap.studies.cli.parsers.add_study`); a thin layer over
:func:`oilgap.studies.oil_grade.run`. Exit 3 if no grade passes both limits."""

from __future__ import annotations

import argparse

from oilgap.model.errors import InfeasibleError
from oilgap.studies import oil_grade
from oilgap.studies.cli.common import case_or_seed, file_list, gamma_line, study_out
from oilgap.studies.cli.outputs import out_folder
from oilgap.studies.grid.evaluate import thermal_description
from oilgap.studies.oil_grade import DEFAULT_TEMP_RANGE_C, OilGradeResult, read_mission_csv


def _temp_range(args: argparse.Namespace) -> tuple[float, float] | None:
    """--temp-min-c/--temp-max-c (None when neither is given; default 0-40 degC)."""
    if args.temp_min_c is None and args.temp_max_c is None:
        return None
    lo, hi = DEFAULT_TEMP_RANGE_C
    return (lo if args.temp_min_c is None else args.temp_min_c,
            hi if args.temp_max_c is None else args.temp_max_c)


def _print_table(r: OilGradeResult) -> None:
    full = r.thermal_mode == "full"
    print(f"{'oil':<8}{'nu min':>9}" + (f"{'T oil max':>10}" if full else "")
          + f"{'nu max':>10}{'mission W':>11}{'energy Wh':>11}  verdict")
    for _, row in r.table.iterrows():
        print(f"{row['oil']:<8}{row['nu_min_envelope_cSt']:>9.1f}"
              + (f"{row['oil_temp_op_max_C']:>10.1f}" if full else "")
              + f"{row['nu_max_envelope_cSt']:>10.0f}{row['mission_mean_power_W']:>11.2f}"
              f"{row['mission_energy_Wh']:>11.1f}  {row['verdict']}: {row['reason']}")


def run(args: argparse.Namespace) -> int:
    """``oilgap study oil-grade``: grade table and recommendation; exit 3 if none passes."""
    case = case_or_seed(args.case)
    mission = read_mission_csv(args.mission) if args.mission else None
    out = study_out(args, "oil-grade")
    with out_folder(args, out) as folder:  # checked and locked before any computation
        folder.begin()
        r = oil_grade.run(out, case, mission, nu_min_cSt=args.nu_min_cst,
                          nu_max_cSt=args.nu_max_cst, iso_tolerance=args.iso_tolerance,
                          depth_range_m=(args.depth_min_m, args.depth_max_m),
                          temp_range_C=_temp_range(args),
                          sea_temp_range_C=args.sea_temp_range_c,
                          mission_hours=args.mission_hours, workers=args.workers,
                          progress=args.progress, thermal=args.thermal)
    s = r.settings
    print(f"thermal     {thermal_description(case, r.thermal_mode, s['thermal_default'])}")
    print(gamma_line(case))
    axis = "sea" if r.thermal_mode == "full" else "oil"
    print(f"envelope    {s['depth_range_m'][0]:g}-{s['depth_range_m'][1]:g} m x {axis} "
          f"{s['temp_range_C'][0]:g}-{s['temp_range_C'][1]:g} degC\n")
    if r.recommended is not None:
        print(f"recommended: {r.recommended}   runner-up: {r.runner_up or 'none'}\n")
    _print_table(r)
    print(f"\nmission: {r.mission_source}; " + ", ".join(
        f"{m.depth_m:g} m/{'sea ' if axis == 'sea' else ''}{m.oil_temp_C:g} degC/"
        f"{m.fraction:g}" for m in r.mission))
    if r.comparison is not None:
        c = r.comparison
        print(f"\nisothermal recommendation: {c['recommended_isothermal'] or 'none'}; under "
              f"{r.thermal_mode}: {c['recommended'] or 'none'} "
              f"({'changed' if c['changed'] else 'unchanged'})\nwhy: {c['why']}")
    print(f"wrote {out}/:\n" + file_list(r.files))
    if r.recommended is None:
        raise InfeasibleError("no oil grade meets both the lubrication limit "
                              f"({args.nu_min_cst:g} cSt) and the cold-start limit "
                              f"({args.nu_max_cst:g} cSt) over the envelope",
                              "no feasible grade")
    return 0
