"""Weakest strength at which the measured-data loop names each library effect.

Not a speed benchmark: for every effect of ``oilgap.model.effects.EFFECTS`` the
synthetic rig (``oilgap.studies.rigs.synth``) injects it at its default strength,
then at strengths smaller by sqrt(2) each step, and the loop (not told which)
must accept exactly that effect on seeds 0, 1 and 2. Prints the table that
``docs/benchmarks.md`` quotes and writes it to ``out/detect_loop.json``.

    python benchmarks/detect_loop.py [EFFECT ...]
"""

from __future__ import annotations

import json
import sys
import time
from dataclasses import replace
from pathlib import Path

from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.effects import EFFECTS
from oilgap.model.io.case_io import seed_case
from oilgap.studies.rigs.synth import SynthConfig, weakest_strength

BEARING_RIG = SynthConfig(case=replace(seed_case(), bearing=bearing_spec_from(
    {"designation": "6809"})))
"""The rig of the balls' drag, which needs a rolling bearing: the seed with a 6809."""


def main(names: list[str]) -> None:
    names = names or list(EFFECTS)
    rows = []
    print(f"{'effect':<24}{'default':>11}{'weakest found':>15}{'first missed':>14}  unit   "
          "held-out cut at weakest (seeds 0,1,2)   time")
    for n in names:
        t0 = time.perf_counter()
        r = weakest_strength(n, BEARING_RIG if n == "bearing_ball_drag" else None)
        dt = time.perf_counter() - t0
        last = [s for s in r["steps"] if s["found_on_all_seeds"]]
        cuts = ", ".join(f"{c:.0f} %" for c in last[-1]["heldout_cut_pct"]) if last else "-"
        miss = f"{r['first_missed']:.3g}" if r["first_missed"] is not None else "-"
        found = f"{r['weakest_found']:.3g}" if r["weakest_found"] is not None else "none"
        print(f"{n:<24}{r['default']:>11.3g}{found:>15}{miss:>14}  {r['unit']:<6} {cuts:<38}"
              f"{dt:5.0f} s", flush=True)
        rows.append(r)
    out = Path("out")
    out.mkdir(exist_ok=True)
    (out / "detect_loop.json").write_text(json.dumps(rows, indent=2))


if __name__ == "__main__":
    main(sys.argv[1:])
