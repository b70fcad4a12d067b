"""Where an output came from: the version, the date, the command and its inputs.

Every result folder gets ``provenance.json`` (written atomically by
:class:`oilgap.studies.io.result_folder.ResultFolder` when writing starts, through
:func:`oilgap.model.io.serialize.dumps`); a one-file output that can carry a comment (a
case TOML written by ``oilgap optimize --out``) gets :func:`stamp_line` as its first
line. CSV outputs get no comment line: a reader (pandas, a spreadsheet) would take it
for data.

The run is a record, :class:`RunRecord`, that the caller builds and passes in: the
command line builds one from its arguments (``argv``, the input files, the thermal mode
asked for) and hands it to the result folder or the case writer; a folder written from
Python (a notebook) without one records ``sys.argv`` and no inputs. Facts learnt while
the run reads its inputs (the case's gamma) are noted by the code that read them
(:meth:`~oilgap.studies.io.result_folder.ResultFolder.note`): nothing here reads a case.
"""

from __future__ import annotations

import datetime as _dt
import hashlib
import platform
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

PROVENANCE_NAME = "provenance.json"
"""Name of the provenance file of a result folder."""

PACKAGES = ("numpy", "scipy", "casadi", "pandas")
"""The libraries whose versions a provenance records (besides Python and oilgap)."""


@dataclass(frozen=True, kw_only=True)
class RunRecord:
    """The run an output comes from, as its caller knows it.

    Parameters
    ----------
    argv : tuple of str, optional
        The command, ``("oilgap", "study", "sweep", ...)``; None for a run from Python
        (the record then names ``sys.argv``) [-].
    inputs : mapping, optional
        Role (``"case"``, ``"grid"``, ``"mission"``, ``"data"``, ``"oils"``,
        ``"model"``) -> input file path [-].
    details : mapping, optional
        Other facts known before the run (``thermal_mode_asked``) [-].
    """

    argv: tuple[str, ...] | None = None
    inputs: Mapping[str, str] = field(default_factory=dict)
    details: Mapping[str, Any] = field(default_factory=dict)

    @classmethod
    def command_line(cls, argv: Sequence[str] | None,
                     inputs: Mapping[str, str | Path] | None = None,
                     **details: Any) -> RunRecord:
        """The record of an ``oilgap`` command.

        Parameters
        ----------
        argv : sequence of str or None
            The arguments after ``oilgap`` (None: ``sys.argv[1:]``) [-].
        inputs : mapping, optional
            Role -> input file path [-].
        **details
            Other facts known before the run [-].

        Returns
        -------
        RunRecord
            ``argv`` starting with ``"oilgap"``, the inputs as strings [-].
        """
        args = sys.argv[1:] if argv is None else list(argv)
        return cls(argv=("oilgap", *args), inputs={k: str(v) for k, v in (inputs or {}).items()},
                   details=dict(details))


def package_version(name: str) -> str | None:
    """The installed version of a distribution, or None if it is not installed.

    Parameters
    ----------
    name : str
        Distribution name (``"numpy"``) [-].

    Returns
    -------
    str or None
        Its version string [-].
    """
    try:
        return version(name)
    except PackageNotFoundError:
        return None


def oilgap_version() -> str:
    """oilgap's installed version (``"0+unknown"`` from a source tree never installed).

    Returns
    -------
    str
        The version [-].
    """
    return package_version("oilgap") or "0+unknown"


def file_sha256(path: str | Path) -> str:
    """The SHA-256 of a file's bytes (hex).

    Parameters
    ----------
    path : str or Path
        The file [-].

    Returns
    -------
    str
        64 hexadecimal digits [-].
    """
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def utc_now() -> str:
    """The current UTC date-time, ISO 8601 to the second (``2026-05-01T12:00:00Z``).

    Returns
    -------
    str
        The time stamp [-].
    """
    return _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%dT%H:%M:%SZ")


def inputs_record(inputs: Mapping[str, str | Path]) -> dict[str, dict[str, Any]]:
    """Each input file with its path, size and SHA-256 (an unreadable one with its
    reason instead).

    Parameters
    ----------
    inputs : mapping
        Role -> path [-].

    Returns
    -------
    dict
        Role -> ``{"path", "bytes", "sha256"}`` or ``{"path", "error"}`` [-].
    """
    out: dict[str, dict[str, Any]] = {}
    for role, path in inputs.items():
        p = Path(path)
        try:
            out[role] = {"path": str(p.resolve()), "bytes": p.stat().st_size,
                         "sha256": file_sha256(p)}
        except OSError as e:
            out[role] = {"path": str(p), "error": e.strerror or type(e).__name__}
    return out


def provenance(run: RunRecord | None = None, **details: Any) -> dict[str, Any]:
    """The provenance document of an output written now.

    Parameters
    ----------
    run : RunRecord, optional
        The run (None: a run from Python, ``sys.argv`` and no inputs) [-].
    **details
        Facts the writer knows (``thermal_mode``, ``gamma``); they override the
        ones in the run's record [-].

    Returns
    -------
    dict
        ``oilgap_version``, ``created_utc``, ``command`` (argv list), ``inputs``
        (:func:`inputs_record`), ``python``, ``platform``, ``packages`` (name ->
        version), then the details [-].
    """
    run = run or RunRecord()
    argv = list(run.argv) if run.argv else ["oilgap-python", *sys.argv]
    return {
        "oilgap_version": oilgap_version(),
        "created_utc": utc_now(),
        "command": argv,
        "inputs": inputs_record(run.inputs),
        "python": platform.python_version(),
        "platform": platform.platform(terse=True),
        "packages": {name: package_version(name) for name in PACKAGES},
        **run.details,
        **details,
    }


def stamp_line(what: str = "written", run: RunRecord | None = None) -> str:
    """One comment line for a one-file output: ``# written by oilgap X on DATE by:
    oilgap optimize ...`` (no newline).

    Parameters
    ----------
    what : str
        The verb [-].
    run : RunRecord, optional
        The run (None: a run from Python, named by ``sys.argv``) [-].

    Returns
    -------
    str
        The line, starting with ``#`` [-].
    """
    argv = list(run.argv) if run is not None and run.argv else ["python", *sys.argv]
    return (f"# {what} by oilgap {oilgap_version()} on {utc_now()} by: "
            + " ".join(argv)).replace("\n", " ")


__all__ = ["PACKAGES", "PROVENANCE_NAME", "RunRecord", "file_sha256", "inputs_record",
           "oilgap_version", "package_version", "provenance", "stamp_line", "utc_now"]
