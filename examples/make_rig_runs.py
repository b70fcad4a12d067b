"""Write ``examples/rig_runs.csv`` and ``rig_new_points.csv``: the rig data of notebook 04.

Made ONCE and committed.

The data do not come from oilgap's model. They come from the out-of-family rig
:mod:`oilgap.studies.rigs.outside_rig`, an independent simulation with laws of its own
(Eq. 6 of Bilgen & Boulos piecewise with a Couette floor, the groove factor T^0.5,
Walther written again, a gearbox loss ``k |tau w|^1.3``, a lumped thermal node,
AR(1) noise of 1 W on the power). Its geometry is the joint of
``examples/my_joint.toml`` (region 1: R 40 mm, gap 0.8 mm, L 30 mm; region 2:
R 34 mm, gap 4 mm, L 20 mm), run at atmospheric pressure in a 25 degC lab.

The rig carries one effect the loop is NOT told of: a shaft seal with Coulomb +
Stribeck friction, tau_c = 0.04 N m (``seal_coulomb_friction``; about 8.5 W RMS on
the oil runs). The loop has to find it.

Runs: ISO VG 15, 32 and 68, each with the grooved rotor (T = 4.75) and with
grooves filled to T = 2, plus one oil-free run per T (the baseline): 8 runs x 50
samples every 0.4 s of the trapezoid profile (3000 rpm, 20 s period) = 400 rows.

``rig_new_points.csv``: steady points measured later on the same rig (another noise
seed), for checking predictions: VG 32 and VG 46 (a grade the runs never used), both
rotors, five speeds at 25 degC = 20 rows with their measured ``power_W``.

Run from the repository root: ``python examples/make_rig_runs.py [--force]``.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

from oilgap.model.errors import InputError
from oilgap.studies.io.files import atomic_to_csv, check_out_file
from oilgap.studies.rigs.outside_laws import Annulus, RigGeometry
from oilgap.studies.rigs.outside_rig import OutsideConfig, steady_points, synthesize

HERE = Path(__file__).resolve().parent
OUT = HERE / "rig_runs.csv"
OUT_NEW = HERE / "rig_new_points.csv"

GEOMETRY = RigGeometry("my joint rig (outside rig)", Annulus(40.0e-3, 0.8e-3, 30.0e-3),
                       Annulus(34.0e-3, 4.0e-3, 20.0e-3))
CONFIG = OutsideConfig(geometry=GEOMETRY, oils=("VG15", "VG32", "VG68"),
                       roughness=(4.75, 2.0), n_samples=50, sample_interval_s=0.4,
                       effects={"seal_coulomb_friction": 0.04})
SEED = 0
NEW = replace(CONFIG, oils=("VG32", "VG46"))
NEW_SEED = 1
NEW_SPEEDS_RPM = (-3000.0, -1500.0, 500.0, 1500.0, 3000.0)
NEW_TEMPS_C = (25.0,)
DIGITS = {"time_s": 3, "speed_rpm": 2, "temp_C": 3, "power_W": 3}
"""Decimals kept in the CSV (a rig logger's resolution; far below the noise)."""


def main(argv: list[str]) -> int:
    """Write both CSVs (refusing existing ones unless ``--force``)."""
    try:
        for path in (OUT, OUT_NEW):
            check_out_file(path, force="--force" in argv)
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    runs = synthesize(CONFIG, seed=SEED).round(DIGITS)
    new = steady_points(NEW, seed=NEW_SEED, speeds_rpm=NEW_SPEEDS_RPM, temps_C=NEW_TEMPS_C)
    new = new[new["oil"] != "none"].round(DIGITS)
    for df, path in ((runs, OUT), (new, OUT_NEW)):
        atomic_to_csv(df, path, index=False)
        print(f"wrote {path} ({len(df)} rows, {df['run'].nunique()} runs)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
