"""The measured-data loop on the out-of-family rig (``oilgap.studies.rigs.outside_rig``).

Not a speed benchmark: the rig's truth is the piecewise Eq. 6 with a Couette
floor, a gearbox loss outside the loop's baseline basis, AR(1) noise and each
effect by a law of its own, so the loop meets data it was not built from. For
each section the loop (``LoopEstimator(case=...).fit``, not told what was
injected) reports what it names and the held-out RMSE cut
``1 - after/before`` (leave-one-run-out):

1. each library effect alone at 0.5x, 1x, 2x its test strength (1x on seeds 0-2);
2. two and three effects at once;
3. clean data over 20 seeds (false effects);
4. a Newtonian silicone oil (no shear thinning, per-row nu and density);
5. other rigs, clean: profiles, sampling 1 ms and 0.5 s, no region 2, thin or
   heavy oils only, several gaps, white noise, viscous power, copper loss of the
   oil torque, film heating; an enclosed end-disc in regime I on heavy oils;
6. steady-point data (no ``time_s``).

Prints the tables and writes ``out/detect_outside.json``. ``--quick``: seed 0 only.

    python benchmarks/detect_outside.py [--quick] [SECTION ...]
"""

from __future__ import annotations

import json
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from oilgap.model.io.case_io import case_from_dict
from oilgap.optim.calibration import LoopEstimator
from oilgap.studies.rigs.outside_laws import OPEN_GEOMETRY, SpeedProfile
from oilgap.studies.rigs.outside_rig import (
    EFFECT_LAWS,
    NEWTONIAN,
    STRENGTH_UNIT,
    TEST_STRENGTH,
    OutsideConfig,
    effect_size_W,
    inject,
    steady_points,
    synthesize,
    write_oils_csv,
)

BASE = OutsideConfig()
PAIRS = (("seal_coulomb_friction", "thermal_lag"), ("bearing_ball_churning", "sensor_delay"),
         ("oil_inertia", "taylor_vortex_onset"), ("end_face_disc", "shear_thinning"),
         ("seal_coulomb_friction", "oil_inertia", "sensor_delay"))


TMP = Path(tempfile.mkdtemp(prefix="detect_outside_"))


def fit(cfg: OutsideConfig, seed: int = 0, data=None) -> dict:
    """One loop fit on the rig's data: named effects, held-out cut, calibration, or the error.

    The loop gets the rig's geometry as its case and the rig's oils table (which says
    whether the oils are polymer-thickened), nothing about the effects.
    """
    case = case_from_dict(cfg.geometry.case_document())
    oils = write_oils_csv(cfg, TMP / f"oils_{bool(cfg.strength('shear_thinning'))}.csv")
    df = synthesize(cfg, seed) if data is None else data
    t0 = time.perf_counter()
    try:
        est = LoopEstimator(case=case, oils=oils).fit(df)
    except Exception as e:  # noqa: BLE001 - reported, the sweep goes on
        return {"error": f"{type(e).__name__}: {str(e).splitlines()[0][:150]}"}
    h = est.heldout_rmse_
    return {"named": sorted(e.name for e in est.effects_),
            "cut_pct": 100.0 * (1.0 - h["after"] / h["before"]) if h["before"] > 0 else 0.0,
            "before_W": h["before"], "after_W": h["after"],
            "calibration": {k: round(float(v), 4) for k, v in est.calibration_.items()},
            "seconds": time.perf_counter() - t0}


def show(r: dict) -> str:
    """One cell: the named effects and the held-out cut (or the error)."""
    if "error" in r:
        return r["error"]
    names = ",".join(r["named"]) or "none"
    return f"{names} ({r['cut_pct']:.0f} %, {r['before_W']:.2f}->{r['after_W']:.2f} W)"


def single(seeds) -> list[dict]:
    print("1. each effect alone (named, held-out cut, held-out RMSE before->after)")
    rows = []
    for name in EFFECT_LAWS:
        for mult in (0.5, 1.0, 2.0):
            s = TEST_STRENGTH[name] * mult
            cfg = inject(BASE, **{name: s})
            res = [fit(cfg, seed) for seed in (seeds if mult == 1.0 else seeds[:1])]
            ok = sum(r.get("named") == [name] and r["cut_pct"] >= 50 for r in res)
            print(f"  {name:<22} {s:<8.3g} {STRENGTH_UNIT[name]:<4} {effect_size_W(cfg):5.2f} W"
                  f"  pass {ok}/{len(res)}  " + " | ".join(show(r) for r in res), flush=True)
            rows.append({"effect": name, "strength": s, "effect_W": effect_size_W(cfg),
                         "results": res})
    return rows


def combined(seeds) -> list[dict]:
    print("2. several effects at once (at their test strengths)")
    rows = []
    for names in PAIRS:
        cfg = inject(BASE, **{n: TEST_STRENGTH[n] for n in names})
        res = [fit(cfg, seed) for seed in seeds]
        ok = sum(r.get("named") == sorted(names) for r in res)
        print(f"  {' + '.join(names)}: all named {ok}/{len(res)}  "
              + " | ".join(show(r) for r in res), flush=True)
        rows.append({"effects": list(names), "results": res})
    return rows


def clean(seeds) -> dict:
    n = 20 if len(seeds) > 1 else 5
    res = [fit(BASE, seed) for seed in range(n)]
    none = sum(r.get("named") == [] for r in res)
    print(f"3. clean data, {n} seeds: no effect named in {none}/{n}")
    for seed, r in enumerate(res):
        if r.get("named") != []:
            print(f"     seed {seed}: {show(r)}")
    print(f"     calibration seed 0: {res[0].get('calibration')}", flush=True)
    return {"seeds": n, "no_effect": none, "results": res}


def newtonian(seeds) -> dict:
    res = [fit(NEWTONIAN, seed) for seed in range(2 * len(seeds) + 1)]
    ok = sum(r.get("named") == [] for r in res)
    print(f"4. Newtonian silicone oil (PDMS 10/50/100 cSt, T = 1, no region 2, viscous power): "
          f"no effect named in {ok}/{len(res)}")
    for r in res:
        print(f"     {show(r)}  calibration {r.get('calibration')}", flush=True)
    return {"no_effect": ok, "results": res}


def variants() -> dict[str, OutsideConfig]:
    """Clean rigs of other shapes (and one confounded effect)."""
    fast = SpeedProfile("trapezoid", period_s=2.0, ramp_s=0.3)
    return {
        "sine profile": replace(BASE, profile=SpeedProfile("sine")),
        "step profile, 20 ms sampling": replace(BASE, profile=SpeedProfile("step", ramp_s=0.2),
                                                sample_interval_s=0.02, n_samples=1500),
        "1 ms sampling, 3 s runs (2 s trapezoid)": replace(
            BASE, profile=fast, sample_interval_s=0.001, n_samples=3000),
        "1 ms sampling, 10 s runs (2 s trapezoid)": replace(
            BASE, profile=fast, sample_interval_s=0.001, n_samples=10_000),
        "0.5 s sampling": replace(BASE, sample_interval_s=0.5),
        "no region 2": replace(BASE, geometry=OPEN_GEOMETRY),
        "thin oils VG10-VG32": replace(BASE, oils=("VG10", "VG15", "VG22", "VG32")),
        "heavy oils VG320-VG1000": replace(BASE, oils=("VG320", "VG460", "VG680", "VG1000")),
        "three gaps 0.6/1.0/1.5 mm": replace(BASE, gaps_mm=(0.6, 1.0, 1.5), n_samples=150),
        "white noise (phi = 0)": replace(BASE, noise_phi=0.0),
        "viscous_power_W": replace(BASE, kind="viscous_power_W"),
        "copper loss of the oil torque": replace(BASE, baseline=replace(
            BASE.baseline, copper_carries_viscous=True)),
        "film heating 0.05 K/W": replace(BASE, film_heating_K_W=0.05),
        "one oil only (VG68)": replace(BASE, oils=("VG68",)),
        "enclosed disc regime I+II, k = 1, heavy oils": inject(replace(
            BASE, oils=("VG320", "VG460", "VG680", "VG1000"), end_face_regime="I+II"),
            end_face_disc=1.0),
    }


def other_rigs(seeds) -> dict:
    print("5. other rigs (clean unless stated)")
    out = {}
    for label, cfg in variants().items():
        res = [fit(cfg, seed) for seed in seeds]
        extra = f"  effect {effect_size_W(cfg):.1f} W" if cfg.effects else ""
        print(f"  {label:<46}{extra} " + " | ".join(show(r) for r in res)
              + f"  calibration {res[0].get('calibration')}", flush=True)
        out[label] = res
    return out


def steady(seeds) -> dict:
    cfg = BASE
    r = fit(cfg, 0, data=steady_points(cfg, 0))
    print(f"6. steady-point data (no time_s, {len(steady_points(cfg, 0))} rows): {show(r)}")
    return r


SECTIONS = {"single": single, "combined": combined, "clean": clean, "newtonian": newtonian,
            "other": other_rigs, "steady": steady}


def main(argv: list[str]) -> None:
    seeds = (0,) if "--quick" in argv else (0, 1, 2)
    names = [a for a in argv if not a.startswith("--")] or list(SECTIONS)
    t0 = time.perf_counter()
    out = {n: SECTIONS[n](seeds) for n in names}
    print(f"total {time.perf_counter() - t0:.0f} s")
    Path("out").mkdir(exist_ok=True)
    Path("out/detect_outside.json").write_text(json.dumps(out, indent=1, default=str))


if __name__ == "__main__":
    main(sys.argv[1:])
