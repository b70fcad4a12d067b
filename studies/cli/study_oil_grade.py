"""``oilgap study oil-grade``: the grade table and the recommendation (arguments in
:func:`oilgap.studies.cli.parsers.add_study`); a thin layer over
:func:`oilgap.studies.oil_grade.run`. Exit 3 if no grade passes both limits."""

from __future__ import annotations

import argparse

from oilgap.model.errors import InfeasibleError
from oilgap.studies import oil_grade
from oilgap.studies.cli.common import case_or_seed, file_list, study_out
from oilgap.studies.oil_grade import read_mission_csv


def run(args: argparse.Namespace) -> int:
    """``oilgap study oil-grade``: grade table and recommendation; exit 3 if none passes."""
    case = case_or_seed(args.case)
    mission = read_mission_csv(args.mission) if args.mission else None
    out = study_out(args, "oil-grade")
    r = oil_grade.run(out, case, mission, nu_min_cSt=args.nu_min_cst,
                      nu_max_cSt=args.nu_max_cst, iso_tolerance=args.iso_tolerance,
                      depth_range_m=(args.depth_min_m, args.depth_max_m),
                      temp_range_C=(args.temp_min_c, args.temp_max_c),
                      mission_hours=args.mission_hours, workers=args.workers,
                      progress=args.progress)
    t = r.table
    if r.recommended is not None:
        print(f"recommended: {r.recommended}   runner-up: {r.runner_up or 'none'}\n")
    print(f"{'oil':<8}{'nu min':>9}{'nu max':>10}{'mission W':>11}{'energy Wh':>11}  verdict")
    for _, row in t.iterrows():
        print(f"{row['oil']:<8}{row['nu_min_envelope_cSt']:>9.1f}"
              f"{row['nu_max_envelope_cSt']:>10.0f}{row['mission_mean_power_W']:>11.2f}"
              f"{row['mission_energy_Wh']:>11.1f}  {row['verdict']}: {row['reason']}")
    print(f"\nmission: {r.mission_source}; " + ", ".join(
        f"{m.depth_m:g} m/{m.oil_temp_C:g} degC/{m.fraction:g}" for m in r.mission))
    print(f"wrote {out}/:\n" + file_list(r.files))
    if r.recommended is None:
        raise InfeasibleError("no oil grade meets both the lubrication limit "
                              f"({args.nu_min_cst:g} cSt) and the cold-start limit "
                              f"({args.nu_max_cst:g} cSt) over the envelope",
                              "no feasible grade")
    return 0
