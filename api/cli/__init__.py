"""The ``oilgap`` command line: a thin layer over the Python API.

The argument tables live in :mod:`oilgap.cli.parsers` (cheap to import);
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

Messages on stderr go through the ``"oilgap"`` :mod:`logging` logger, configured once
here (:func:`configure_logging`; plain ``oilgap: ...`` lines): by default notes
(INFO) and warnings; ``-q`` keeps errors and the warnings (every ``OilgapWarning``
says something about the result: a fluid outside its trusted range, a default that
changes a number) and drops the notes and the progress bars (tqdm on stderr, only on a
terminal: :func:`oilgap.studies.progress.shown` around every command); ``-v`` adds debug lines
(the command, the inputs read with their SHA-256, the library versions, the time
taken; ``optimize -v`` shows IPOPT's iterations). Results go to stdout, never
through the logger. ``oilgap --version`` prints ``oilgap X.Y.Z``.
"""

from __future__ import annotations

import argparse
import importlib
import logging
import os
import platform
import sys
import time
import warnings
from collections.abc import Sequence
from pathlib import Path

from oilgap.cli.parsers import build_parser, finite_float
from oilgap.model.errors import InfeasibleError, InputError, OilgapWarning, SolverError
from oilgap.optim.interrupts import catching_interrupts, interrupt_pending
from oilgap.studies.io.provenance import (
    PACKAGES,
    RunRecord,
    file_sha256,
    oilgap_version,
    package_version,
)
from oilgap.studies.progress import shown

__all__ = ["COMMANDS", "LOG", "build_parser", "configure_logging", "finite_float", "main"]

LOG = logging.getLogger("oilgap")
"""The logger of every message oilgap writes on stderr (results go to stdout)."""

INPUT_ARGUMENTS = ("case", "grid", "mission", "data", "oils", "model")
"""The options and arguments that name an input file (recorded in provenance.json)."""

COMMANDS: dict[str, str] = {
    "evaluate": "oilgap.cli.evaluate",
    "optimize": "oilgap.cli.optimize",
    "study smoothing": "oilgap.cli.study_smoothing",
    "study pareto": "oilgap.cli.study_pareto",
    "study oil-grade": "oilgap.cli.study_oil_grade",
    "study sweep": "oilgap.cli.study_sweep",
    "study uncertainty": "oilgap.cli.study_uncertainty",
    "loop": "oilgap.cli.loop",
    "predict": "oilgap.cli.predict",
    "synth": "oilgap.cli.synth",
    "plan": "oilgap.cli.plan",
}
"""The one dispatch table: command -> module whose ``run(args)`` returns the exit code."""


def _show_warning(message, category, filename, lineno, file=None, line=None):
    LOG.warning("warning: %s", message)


class _StderrHandler(logging.StreamHandler):
    """A handler writing to whatever ``sys.stderr`` is when a message is emitted (a test's
    capture, the solver-interrupt filter of :func:`main`)."""

    def __init__(self):
        super().__init__(sys.stderr)

    @property
    def stream(self):
        return sys.stderr

    @stream.setter
    def stream(self, value) -> None:  # the stream is always the current sys.stderr
        pass


def configure_logging(verbose: int = 0, quiet: bool = False) -> logging.Logger:
    """Configure the ``"oilgap"`` logger once (calling again replaces its handler):
    ``oilgap: <message>`` lines on stderr; level WARNING with ``quiet``, DEBUG with
    ``verbose``, INFO otherwise.

    Parameters
    ----------
    verbose : int
        Number of ``-v`` [-].
    quiet : bool
        ``-q`` [-].

    Returns
    -------
    logging.Logger
        :data:`LOG`.
    """
    for h in [h for h in LOG.handlers if isinstance(h, _StderrHandler)]:
        LOG.removeHandler(h)
    handler = _StderrHandler()
    handler.setFormatter(logging.Formatter("oilgap: %(message)s"))
    LOG.addHandler(handler)
    LOG.setLevel(logging.WARNING if quiet else logging.DEBUG if verbose else logging.INFO)
    LOG.propagate = False
    return LOG


def _inputs(args: argparse.Namespace) -> dict[str, str]:
    """The input files named on the command line (role -> path), those that exist."""
    return {k: str(v) for k in INPUT_ARGUMENTS
            if isinstance(v := getattr(args, k, None), str) and Path(v).is_file()}


def _debug_run(argv: Sequence[str] | None, inputs: dict[str, str]) -> None:
    """With -v: the command, oilgap's and the libraries' versions, the inputs read."""
    if not LOG.isEnabledFor(logging.DEBUG):
        return
    LOG.debug("command: oilgap %s", " ".join(sys.argv[1:] if argv is None else argv))
    LOG.debug("oilgap %s, python %s, %s", oilgap_version(), platform.python_version(),
              ", ".join(f"{n} {package_version(n)}" for n in PACKAGES))
    for role, path in inputs.items():
        LOG.debug("input %s: %s (sha256 %s)", role, path, file_sha256(path))


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
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.version:
        print(f"oilgap {oilgap_version()}")
        return 0
    if getattr(args, "command", None) is None:
        parser.error("the following arguments are required: COMMAND")
    configure_logging(args.verbose, args.quiet)
    if args.quiet and getattr(args, "progress", None) is None:
        args.progress = False  # -q: no progress bar unless --progress asks for one
    inputs = _inputs(args)
    asked = {"thermal_mode_asked": args.thermal or "default"} if hasattr(args, "thermal") \
        else {}
    args.run = RunRecord.command_line(argv, inputs, **asked)  # provenance of what it writes
    _debug_run(argv, inputs)
    warnings.showwarning = _show_warning
    warnings.simplefilter("default", OilgapWarning)
    stderr = sys.stderr
    sys.stderr = _QuietSolverInterrupt(stderr)
    start = time.perf_counter()
    try:
        with catching_interrupts():
            return _dispatch(args)
    finally:
        sys.stderr = stderr
        LOG.debug("%s took %.3f s", args.command, time.perf_counter() - start)


def _dispatch(args) -> int:
    """Run the command; every failure is one line on stderr and an exit code."""
    try:
        command = importlib.import_module(COMMANDS[args.command])
        _resolve_oils(args)
        with shown(getattr(args, "progress", None)):  # bars on a terminal's stderr only
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


def _resolve_oils(args: argparse.Namespace) -> None:
    """``--oils FILE`` read once, added to the built-in catalogue (or alone with
    ``--oils-only``), for the command to pass on as its ``oils``."""
    if getattr(args, "oils_only", False) and not args.oils:
        raise InputError("--oils-only", True, "needs --oils FILE (the table to use alone)")
    if getattr(args, "oils", None):
        from oilgap._evaluate import read_oils
        args.oils = read_oils(args.oils, only=args.oils_only, field="--oils")


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
