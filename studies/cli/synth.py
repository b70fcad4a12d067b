"""``oilgap synth``: synthetic rig data in the measured-data format."""

from __future__ import annotations

import argparse
import sys


def add_parser(sub) -> None:
    """Register ``oilgap synth``."""
    from oilgap.model.effects import EFFECTS
    from oilgap.studies.cli import finite_float

    p = sub.add_parser(
        "synth", help="simulate the seed's viscous-power experiment (test data for loop)",
        description="Simulate the seed's experiment: oil-free runs and four oils (ISO VG 150, "
        "320, 680, 1000), grooved (T = 4) and smoothed (T = 2), 1500 samples every 0.2 s of "
        "3000 rpm sin(0.1 pi t), a lumped thermal model heated by the losses, load and motor "
        "losses, measurement noise, and optionally one library effect. The CSV carries no "
        "trace of the effect.")
    p.add_argument("--effect", choices=list(EFFECTS), metavar="NAME",
                   help="inject this library effect (see --list-effects)")
    p.add_argument("--strength", type=finite_float,
                   help="strength of the effect in its unit (default: its test strength)")
    p.add_argument("--seed", type=int, default=0, help="noise seed (default 0)")
    p.add_argument("--out", metavar="data.csv", default="synth.csv",
                   help="output CSV (default: synth.csv)")
    p.add_argument("--case", metavar="RIG.toml", help="rig geometry (default: the seed joint)")
    p.add_argument("--roughness", metavar="T,T", default="4,2",
                   help="roughness T of the two rotor builds (default 4,2)")
    p.add_argument("--viscous", action="store_true",
                   help="write viscous_power_W (a torque balance) instead of power_W; no "
                   "oil-free runs")
    p.add_argument("--list-effects", action="store_true",
                   help="list the library effects with their strength units and exit")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Write the synthetic data; returns the exit code."""
    from oilgap.model.case_io import read_case_toml
    from oilgap.model.effects import EFFECTS
    from oilgap.model.errors import InputError
    from oilgap.studies.synth import DEFAULT_STRENGTH, SynthConfig, synthesize, write_synth_csv

    if args.list_effects:
        print(f"{'effect':<24}{'strength unit':<15}{'default':>10}  formula")
        for n, e in EFFECTS.items():
            print(f"{n:<24}{e.strength_unit:<15}{DEFAULT_STRENGTH[n]:>10.3g}  {e.formula}")
        return 0
    if args.strength is not None and args.effect is None:
        raise InputError("--strength", args.strength, "needs --effect NAME")
    try:
        rough = tuple(float(x) for x in args.roughness.split(","))
    except ValueError:
        raise InputError("--roughness", args.roughness, "comma-separated numbers >= 1, "
                         "e.g. 4,2") from None
    case = read_case_toml(args.case) if args.case else None
    cfg = SynthConfig(case=case, roughness=rough, effect=args.effect, strength=args.strength,
                      kind="viscous_power_W" if args.viscous else "power_W")
    df = synthesize(cfg, seed=args.seed)
    try:
        path = write_synth_csv(df, args.out)
    except OSError as e:
        raise InputError("--out", args.out, f"cannot write the file ({e.strerror})") from None
    runs = df["run"].nunique()
    col = "viscous_power_W" if args.viscous else "power_W"
    print(f"wrote {path}: {len(df)} rows, {runs} runs, columns {', '.join(df.columns)}")
    if args.effect:
        s = cfg.resolved().strength
        unit = EFFECTS[args.effect].strength_unit
        print(f"injected {args.effect} at strength {s:g}{'' if unit == '-' else ' ' + unit}"
              f" (not recorded in the file); {col} noise {cfg.noise_power_W:g} W",
              file=sys.stderr)
    return 0
