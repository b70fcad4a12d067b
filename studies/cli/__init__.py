"""The ``oilgap`` command line: a thin layer over the Python API.

The argument tables live in :mod:`oilgap.studies.cli.parsers` (cheap to import);
each command's ``run(args)`` lives in its own module, named in
:data:`COMMANDS` and imported only when that command runs (loading cvxpy,
CasADi's NLP or matplotlib costs seconds that ``oilgap evaluate`` should not
pay). Errors: bad input exits 2 with one line naming the field, the value and
what is allowed; an infeasible design problem exits 3; another solver failure
exits 4; an output that cannot be written (full disk, no permission) exits 2 with
one line naming the file. Ctrl-C prints one line, ``oilgap: interrupted``, and
exits 130 (worker processes ignore SIGINT and are ended by the parent). A closed
stdout (``oilgap evaluate | head -1``) ends the command quietly with exit 141
(128 + SIGPIPE, what a shell reports for a command killed by a broken pipe). No
traceback reaches the user.
"""

from __future__ import annotations

import importlib
import os
import sys
import warnings
from collections.abc import Sequence

from oilgap.model.errors import InfeasibleError, InputError, OilgapWarning, SolverError
from oilgap.model.interrupts import catching_interrupts, interrupt_pending
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


EXIT_BROKEN_PIPE = 141
"""Exit status when stdout is closed before the output is written (128 + SIGPIPE)."""


def _broken_pipe() -> int:
    """stdout was closed by its reader: point it at /dev/null so that the interpreter's
    final flush cannot fail again (the Python documentation's recipe for SIGPIPE), and
    exit quietly with :data:`EXIT_BROKEN_PIPE`."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (AttributeError, OSError, ValueError):  # a stdout without a descriptor
        pass
    return EXIT_BROKEN_PIPE


def _os_error(e: OSError) -> str:
    """One line for an OSError that no reader or writer turned into an InputError."""
    name = f" {str(e.filename)!r}" if e.filename is not None else ""
    return f"oilgap: error: cannot access{name}: {e.strerror or type(e).__name__}"


class _QuietSolverInterrupt:
    """``sys.stderr`` while a command runs: CasADi's own warning on Ctrl-C
    (``CasADi - ... WARNING("KeyboardInterruptException")``, written through
    ``sys.stderr``, sometimes in pieces) is dropped up to its newline; ``oilgap:
    interrupted`` is the one line said."""

    def __init__(self, stream):
        self._stream = stream
        self._dropping = False

    def write(self, text: str) -> int:
        if not self._dropping and ("KeyboardInterruptException" in text or (
                interrupt_pending() and text.startswith("CasADi - "))):
            self._dropping = True
        if self._dropping:
            self._dropping = "\n" not in text
            return len(text)
        return self._stream.write(text)

    def __getattr__(self, name: str):
        return getattr(self._stream, name)


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``oilgap`` console script; returns the exit code."""
    args = build_parser().parse_args(argv)
    warnings.showwarning = _show_warning
    warnings.simplefilter("default", OilgapWarning)
    stderr = sys.stderr
    sys.stderr = _QuietSolverInterrupt(stderr)
    try:
        with catching_interrupts():
            return _dispatch(args)
    finally:
        sys.stderr = stderr


def _dispatch(args) -> int:
    """Run the command; every failure is one line on stderr and an exit code."""
    try:
        command = importlib.import_module(COMMANDS[args.command])
        code = int(command.run(args) or 0)
        sys.stdout.flush()  # a closed pipe is found here, not at the interpreter's exit
        return code
    except BrokenPipeError:
        return _broken_pipe()
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
    except OSError as e:  # a file no reader or writer checked: one line, exit 2
        print(_os_error(e), file=sys.stderr)
        return 2
    except Exception as e:
        if not (interrupt_pending() or _from_interrupt(e)):
            raise  # a bug: its traceback is what a report needs
        # Ctrl-C inside a C extension's callback comes back as another error (CasADi:
        # "SystemError: ... returned a result with an exception set")
        print("oilgap: interrupted", file=sys.stderr)
        return 130


def _from_interrupt(e: BaseException) -> bool:
    """Whether ``e`` was caused by a KeyboardInterrupt (its chain of causes)."""
    seen = set()
    while e is not None and id(e) not in seen:
        if isinstance(e, KeyboardInterrupt):
            return True
        seen.add(id(e))
        e = e.__cause__ or e.__context__
    return False


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
