"""Where an output came from: the version, the date, the command and its inputs.

Every result folder gets ``provenance.json`` (written atomically by
:class:`oilgap.model.result_folder.ResultFolder` when writing starts, through
:func:`oilgap.model.serialize.dumps`); a one-file output that can carry a comment (a
case TOML written by ``oilgap optimize --out``) gets :func:`stamp_line` as its first
line. CSV outputs get no comment line: a reader (pandas, a spreadsheet) would take it
for data.

The command line notes the run once (:func:`note_run`: ``argv``, the input files,
the thermal mode asked for); a folder written from Python (a notebook) without it
records ``sys.argv`` and no inputs.
"""

from __future__ import annotations

import datetime as _dt
import hashlib
import platform
import sys
import warnings
from collections.abc import Mapping, Sequence
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from .case_io import read_case_toml, seed_case
from .errors import InputError

PROVENANCE_NAME = "provenance.json"
"""Name of the provenance file of a result folder."""

PACKAGES = ("numpy", "scipy", "casadi", "pandas")
"""The libraries whose versions a provenance records (besides Python and oilgap)."""

_RUN: dict[str, Any] = {"argv": None, "inputs": {}, "details": {}}
"""The run noted by the command line (:func:`note_run`)."""


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


def note_run(argv: Sequence[str] | None, inputs: Mapping[str, str | Path] | None = None,
             **details: Any) -> None:
    """Note the command being run (called once by the command line's ``main``).

    Parameters
    ----------
    argv : sequence of str or None
        The arguments after ``oilgap`` (None: ``sys.argv[1:]``) [-].
    inputs : mapping, optional
        Role (``"case"``, ``"grid"``, ``"mission"``, ``"data"``, ``"oils"``,
        ``"model"``) -> input file path [-].
    **details
        Other facts known before the run (``thermal_mode`` asked for) [-].
    """
    _RUN["argv"] = ["oilgap", *(sys.argv[1:] if argv is None else list(argv))]
    _RUN["inputs"] = {k: str(v) for k, v in (inputs or {}).items()}
    _RUN["details"] = dict(details)


def clear_run() -> None:
    """Forget the run noted by :func:`note_run` (the end of ``main``).

    Returns
    -------
    None
        The noted argv, inputs and details [-] are cleared.
    """
    _RUN.update(argv=None, inputs={}, details={})


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


def _case_gamma(case_path: str | None) -> dict[str, Any]:
    """gamma and its source of the case file (or the seed joint); empty if unreadable."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            case = read_case_toml(case_path) if case_path else seed_case()
    except (InputError, OSError):
        return {}
    return {"gamma": float(case.friction.gamma), "gamma_source": case.gamma_source}


def provenance(**details: Any) -> dict[str, Any]:
    """The provenance document of an output written now.

    Parameters
    ----------
    **details
        Facts the writer knows (``thermal_mode``, ``gamma``); they override the
        ones noted with the run [-].

    Returns
    -------
    dict
        ``oilgap_version``, ``created_utc``, ``command`` (argv list), ``inputs``
        (:func:`inputs_record`), ``python``, ``platform``, ``packages`` (name ->
        version), then the details [-].
    """
    argv = _RUN["argv"] or ["oilgap-python", *sys.argv]
    inputs = dict(_RUN["inputs"])
    known = dict(_RUN["details"])
    if "gamma" not in details and "gamma" not in known and argv[0] == "oilgap":
        known.update(_case_gamma(inputs.get("case")))
    return {
        "oilgap_version": oilgap_version(),
        "created_utc": utc_now(),
        "command": argv,
        "inputs": inputs_record(inputs),
        "python": platform.python_version(),
        "platform": platform.platform(terse=True),
        "packages": {name: package_version(name) for name in PACKAGES},
        **known,
        **details,
    }


def stamp_line(what: str = "written") -> str:
    """One comment line for a one-file output: ``# written by oilgap X on DATE by:
    oilgap optimize ...`` (no newline).

    Parameters
    ----------
    what : str
        The verb [-].

    Returns
    -------
    str
        The line, starting with ``#`` [-].
    """
    argv = _RUN["argv"] or ["python", *sys.argv]
    return (f"# {what} by oilgap {oilgap_version()} on {utc_now()} by: "
            + " ".join(argv)).replace("\n", " ")


__all__ = ["PACKAGES", "PROVENANCE_NAME", "clear_run", "file_sha256", "inputs_record",
           "note_run", "oilgap_version", "package_version", "provenance", "stamp_line",
           "utc_now"]
