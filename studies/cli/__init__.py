"""The ``oilgap`` command line: a thin layer over the Python API.

Each subcommand lives in its own module exposing ``add_parser(subparsers)``
which registers the parser and sets ``func`` to a callable taking the parsed
arguments and returning an exit code. Errors: bad input exits 2 with one line
naming the field, the value and what is allowed; an infeasible design problem
exits 3; another solver failure exits 4. No traceback reaches the user.
"""

from __future__ import annotations

import argparse
import math
import sys
import warnings
from collections.abc import Sequence

from oilgap.model.errors import InfeasibleError, InputError, OilgapWarning, SolverError

SUBCOMMAND_MODULES = (
    "oilgap.studies.cli.evaluate",
    "oilgap.studies.cli.optimize",
    "oilgap.studies.cli.study",
    "oilgap.studies.cli.loop",
    "oilgap.studies.cli.synth",
)


def finite_float(text: str) -> float:
    """argparse type: a finite float (NaN and infinity refused)."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"{text!r} is not allowed; a finite number is "
                                         "required") from None
    return x


def build_parser() -> argparse.ArgumentParser:
    """The top-level parser with every registered subcommand."""
    import importlib

    parser = argparse.ArgumentParser(
        prog="oilgap",
        description="Viscous-loss design tool for oil-filled joints of deep-sea manipulators.")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for name in SUBCOMMAND_MODULES:
        importlib.import_module(name).add_parser(sub)
    return parser


def _show_warning(message, category, filename, lineno, file=None, line=None):
    print(f"oilgap: warning: {message}", file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``oilgap`` console script; returns the exit code."""
    import matplotlib

    matplotlib.use("Agg")
    parser = build_parser()
    args = parser.parse_args(argv)
    warnings.showwarning = _show_warning
    warnings.simplefilter("default", OilgapWarning)
    try:
        return int(args.func(args) or 0)
    except InputError as e:
        print(f"oilgap: error: {e}", file=sys.stderr)
        return 2
    except InfeasibleError as e:
        print(f"oilgap: infeasible: {e}", file=sys.stderr)
        return e.exit_code
    except SolverError as e:
        print(f"oilgap: solver failure: {e}", file=sys.stderr)
        return e.exit_code
    except KeyboardInterrupt:
        print("oilgap: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
