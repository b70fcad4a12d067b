"""The ``oilgap`` command line: a thin layer over the Python API.

The argument tables live in :mod:`oilgap.studies.cli.parsers` (cheap to import);
each command's ``run(args)`` lives in its own module, named in
:data:`COMMANDS` and imported only when that command runs (loading cvxpy,
CasADi's NLP or matplotlib costs seconds that ``oilgap evaluate`` should not
pay). Errors: bad input exits 2 with one line naming the field, the value and
what is allowed; an infeasible design problem exits 3; another solver failure
exits 4. No traceback reaches the user.
"""

from __future__ import annotations

import importlib
import sys
import warnings
from collections.abc import Sequence

from oilgap.model.errors import InfeasibleError, InputError, OilgapWarning, SolverError
from oilgap.studies.cli.parsers import build_parser, finite_float

__all__ = ["COMMANDS", "build_parser", "finite_float", "main"]

COMMANDS: dict[str, str] = {
    "evaluate": "oilgap.studies.cli.evaluate",
    "optimize": "oilgap.studies.cli.optimize",
    "study smoothing": "oilgap.studies.cli.study_smoothing",
    "study pareto": "oilgap.studies.cli.study_pareto",
    "study oil-grade": "oilgap.studies.cli.study_oil_grade",
    "study sweep": "oilgap.studies.cli.study_sweep",
    "loop": "oilgap.studies.cli.loop",
    "predict": "oilgap.studies.cli.predict",
    "synth": "oilgap.studies.cli.synth",
}
"""The one dispatch table: command -> module whose ``run(args)`` returns the exit code."""


def _show_warning(message, category, filename, lineno, file=None, line=None):
    print(f"oilgap: warning: {message}", file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``oilgap`` console script; returns the exit code."""
    args = build_parser().parse_args(argv)
    warnings.showwarning = _show_warning
    warnings.simplefilter("default", OilgapWarning)
    try:
        command = importlib.import_module(COMMANDS[args.command])
        return int(command.run(args) or 0)
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
