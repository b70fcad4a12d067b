"""``oilgap synth``: synthetic rig data in the measured-data format (arguments in
:func:`oilgap.cli.parsers.add_synth`); a thin layer over
:func:`oilgap._loop.synth` (``og.synth``)."""

from __future__ import annotations

import argparse
import sys

from oilgap._loop import synth
from oilgap.model.effects import EFFECTS
from oilgap.model.errors import InputError
from oilgap.studies.io.files import check_out_file
from oilgap.studies.reporting import write_data_csv
from oilgap.studies.rigs.synth import DEFAULT_STRENGTH


def run(args: argparse.Namespace) -> int:
    """Write the synthetic data; returns the exit code."""
    if args.list_effects:
        print(f"{'effect':<24}{'strength unit':<15}{'default':>10}  formula")
        for n, e in EFFECTS.items():
            print(f"{n:<24}{e.strength_unit:<15}{DEFAULT_STRENGTH[n]:>10.3g}  {e.formula}")
        return 0
    if getattr(args, "plan", None) is not None:
        return _plan_run(args)
    if getattr(args, "effects", None) is not None:
        raise InputError("--effects", args.effects, "only with --plan (else --effect NAME)")
    if getattr(args, "truth_scale", None) is not None:
        raise InputError("--truth-scale", args.truth_scale, "only with --plan")
    if args.strength is not None and args.effect is None:
        raise InputError("--strength", args.strength, "needs --effect NAME")
    if args.seed < 0:
        raise InputError("--seed", args.seed, "an integer >= 0 is required (the noise seed)")
    try:
        rough = tuple(float(x) for x in args.roughness.split(","))
    except ValueError:
        raise InputError("--roughness", args.roughness, "comma-separated numbers >= 1, "
                         "e.g. 4,2") from None
    check_out_file(args.out, getattr(args, "force", False))  # before any computation
    df = synth(args.case, roughness=rough, effect=args.effect, strength=args.strength,
               seed=args.seed, viscous=args.viscous)
    try:
        path = write_data_csv(df, args.out)
    except OSError as e:
        raise InputError("--out", args.out, f"cannot write the file ({e.strerror})") from None
    runs = df["run"].nunique()
    col = df.attrs["power_column"]
    print(f"wrote {path}: {len(df)} rows, {runs} runs, columns {', '.join(df.columns)}")
    if args.effect:
        s, unit = df.attrs["strength"], df.attrs["strength_unit"]
        print(f"injected {args.effect} at strength {s:g}{'' if unit == '-' else ' ' + unit}"
              f" (not recorded in the file); {col} noise {df.attrs['noise_power_W']:g} W",
              file=sys.stderr)
    return 0


def _plan_run(args: argparse.Namespace) -> int:
    """``synth --plan plan.csv``: the planned runs, in the loop's data format."""
    from oilgap._plan import synth_plan
    from oilgap.cli.plan import named_by_option

    if args.effect is not None or args.strength is not None:
        raise InputError("--effect", args.effect, "with --plan give --effects NAME[=S],...")
    if args.seed < 0:
        raise InputError("--seed", args.seed, "an integer >= 0 is required (the noise seed)")
    check_out_file(args.out, getattr(args, "force", False))
    try:
        df = synth_plan(args.plan, case=args.case, effects=args.effects, seed=args.seed,
                        scale=1.0 if args.truth_scale is None else args.truth_scale)
    except InputError as e:
        raise named_by_option(e, {"scale": "--truth-scale"}) from None
    try:
        path = write_data_csv(df, args.out)
    except OSError as e:
        raise InputError("--out", args.out, f"cannot write the file ({e.strerror})") from None
    print(f"wrote {path}: {len(df)} rows, {df['run'].nunique()} runs of {args.plan}, "
          f"columns {', '.join(df.columns)}")
    if args.effects:
        print(f"injected {args.effects} (not recorded in the file)", file=sys.stderr)
    return 0
