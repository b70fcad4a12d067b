"""What the commands write, and how: the outputs of each result folder, the folder opened
before any computation, and IPOPT's log kept off stdout.

* Every command that writes checks its ``--out`` first (before reading big inputs or
  computing): :func:`out_folder` for the folder commands (``study ...``, ``loop``),
  :func:`oilgap.studies.io.files.check_out_file` for the one-file commands (``optimize
  --out``, ``predict``, ``synth``). An existing output is refused unless ``--force``
  (or ``--resume`` for a sweep).
* The outputs of each folder command are listed in :data:`oilgap.studies.outputs.OUTPUTS`
  (shared with the façade): ``--force`` removes exactly these (never anything else in
  the folder) before the new run writes, so old and new outputs never sit side by side.
* :func:`solver_log_to_stderr` sends what a solver prints (IPOPT's iterations) to
  stderr, so that ``--json`` on stdout stays one JSON document.
"""

from __future__ import annotations

import argparse
import contextlib
import ctypes
import os
import sys
from collections.abc import Iterator
from pathlib import Path

from oilgap.studies.io.result_folder import ResultFolder
from oilgap.studies.outputs import OUTPUTS

SWEEP_HINT = "pass --resume to continue it or --force to start over"


def out_folder(args: argparse.Namespace, out: str | Path, resume: bool = False
               ) -> ResultFolder:
    """The result folder of the command in ``args`` (not yet opened: use it as a context
    manager, before any computation; call ``begin()`` when writing starts)."""
    command = args.command
    return ResultFolder(out, OUTPUTS[command], force=getattr(args, "force", False),
                        resume=resume, command=f"oilgap {command}",
                        hint=SWEEP_HINT if command == "study sweep"
                        else "pass --force to replace them", run=getattr(args, "run", None))


def report_folder(args: argparse.Namespace) -> contextlib.AbstractContextManager:
    """The ``--report DIR`` folder of evaluate/optimize (not yet opened: use it as a context
    manager before any computation; it yields None without ``--report``)."""
    if not getattr(args, "report", None):
        return contextlib.nullcontext(None)
    return ResultFolder(args.report, OUTPUTS[args.command], force=getattr(args, "force", False),
                        command=f"oilgap {args.command}", field="--report",
                        hint="pass --force to replace them", run=getattr(args, "run", None))


def print_wrote(args: argparse.Namespace, files: list) -> None:
    """The ``wrote DIR/:`` lines of a report (nothing with ``--json``: one document on
    stdout, or without files)."""
    if files and not getattr(args, "json", False):
        print(f"\nwrote {args.report}/:")
        for f in files:
            print(f"  {f}")


def json_quiet(args: argparse.Namespace) -> contextlib.AbstractContextManager:
    """With ``--json``, what a solver prints goes to stderr while inside (stdout carries
    the JSON document alone); otherwise nothing changes."""
    return solver_log_to_stderr() if getattr(args, "json", False) else contextlib.nullcontext()


def _flush_c_stdout() -> None:
    """Flush C's stdio buffers (IPOPT prints through them)."""
    with contextlib.suppress(Exception):
        ctypes.CDLL(None).fflush(None)


@contextlib.contextmanager
def solver_log_to_stderr() -> Iterator[None]:
    """While inside, what a solver prints goes to stderr: ``sys.stdout`` (CasADi writes
    IPOPT's log through it) and file descriptor 1 (C code printing directly) both point
    at stderr. Restored on exit."""
    with contextlib.suppress(Exception):
        sys.stdout.flush()
    _flush_c_stdout()
    try:
        saved = os.dup(1)
        os.dup2(2, 1)
    except OSError:  # no fd 1 or 2 (a detached process): Python's stream only
        saved = None
    try:
        with contextlib.redirect_stdout(sys.stderr):
            yield
    finally:
        _flush_c_stdout()
        if saved is not None:
            os.dup2(saved, 1)
            os.close(saved)
