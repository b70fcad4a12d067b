"""``oilgap study pareto``: the gap-loss and loss-inertia fronts (arguments in
:func:`oilgap.studies.cli.parsers.add_study`); a thin layer over
:func:`oilgap.studies.pareto.run`."""

from __future__ import annotations

import argparse

import pandas as pd

from oilgap.studies import pareto
from oilgap.studies.cli.common import case_or_seed, file_list, gamma_line, study_out
from oilgap.studies.cli.outputs import out_folder


def run(args: argparse.Namespace) -> int:
    """``oilgap study pareto``: the two fronts; returns the exit code."""
    case = case_or_seed(args.case)
    out = study_out(args, "pareto")
    with out_folder(args, out) as folder:  # checked and locked before any computation
        folder.begin()
        r = pareto.run(out, case, args.points, args.torque_min_nm, args.progress)
    g, i = r.gap_front, r.inertia_front
    gok = g[g["status"] == "ok"]
    iok = i[i["status"] == "ok"]
    print("thermal     none (isothermal oil at the case's temperature, the seed paper's "
          "model: the fronts do not take --thermal yet; `oilgap optimize --thermal` "
          "gives the heated optimum)")
    print(gamma_line(case))
    print(f"gap front: {len(gok)}/{len(g)} points, delta {gok['delta_mm'].min():.3f}.."
          f"{gok['delta_mm'].max():.3f} mm, loss {gok['mean_power_W'].max():.2f}.."
          f"{gok['mean_power_W'].min():.2f} W; sweep {r.sweep_time_s:.2f} s "
          f"(median solve {1e3 * gok['solve_time_s'].median():.1f} ms)")
    print(f"  hypervolume {r.hypervolume:.4f} mm W, reference point "
          f"(delta {r.reference_point[0]:g} mm, P {r.reference_point[1]:.3f} W)")
    print(f"inertia front: {len(iok)}/{len(i)} points, inertia "
          f"{iok['inertia_ratio'].min():.3f}..{iok['inertia_ratio'].max():.3f} x the case's "
          f"rotor, loss {iok['mean_power_W'].max():.2f}..{iok['mean_power_W'].min():.2f} W")
    for _, s in r.seeds.iterrows():
        print(f"  {s['design']:<22} delta {s['delta_mm']:.3f} mm  T {s['T']:.2f}  "
              f"P {s['mean_power_W']:.2f} W  inertia {s['inertia_ratio']:.3f} x")
    bad = pd.concat([g[g["status"] != "ok"], i[i["status"] != "ok"]])
    if len(bad):
        print(f"{len(bad)} points failed (rows kept with their error); first: "
              f"{bad['error'].iloc[0]}")
    print(f"\nwrote {out}/:\n" + file_list(r.files))
    return 0
