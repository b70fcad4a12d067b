"""The user's input files and values at the edge: read, or refused in one line.

Every input file of a case (the case TOML, an oils table, a fluid table, a duty-cycle
CSV) is read by :func:`read_input_text`: a file that is missing, a directory, a device,
unreadable (permission, I/O error), too large or not UTF-8 text is refused with one
:class:`~oilgap.model.errors.InputError` naming the key that gave the path, the path
and the reason, never with a traceback and **never with the file's content** (the
path may point anywhere: ``oils_csv = "/etc/passwd"`` must not print the first line of
that file). A CSV header that lacks the columns the reader needs is refused by
:func:`header_error` without echoing the header. Once the header is right the file is
the user's table, and a bad cell is named with its line (shortened by
:func:`cell_for_message`).

:func:`check_physical` refuses a number outside the physical range of a quantity, with
the reason for the bound in the message (the ranges of the case file are listed with
their reasons in ``docs/case-file.md``).
"""

from __future__ import annotations

import errno
import json
import os
import stat
import tomllib
from pathlib import Path
from typing import Any

from ..errors import InputError, check_finite

MAX_INPUT_BYTES = 1 << 30
"""Largest input text file [bytes] (1 GiB): ten times a duty cycle of
:data:`~oilgap.model.duty_cycle.MAX_SAMPLES` rows; a larger file is refused before it
is read into memory."""

MAX_CELL_CHARS = 40
"""Longest cell text [characters] an error message repeats (longer cells are cut)."""


def _reason(e: OSError) -> str:
    """The operating system's words for an error, without the file's content."""
    if isinstance(e, PermissionError) or e.errno in (errno.EACCES, errno.EPERM):
        return "permission denied"
    if e.errno == errno.EIO:
        return "input/output error while reading it"
    return (e.strerror or type(e).__name__).lower()


def read_input_text(path: str | Path, field: str, what: str = "text file",
                    where: str | None = None, max_bytes: int = MAX_INPUT_BYTES) -> str:
    """The text of an input file, or an InputError naming ``field``, the path and why.

    A UTF-8 byte-order mark (spreadsheets write one) is dropped.

    Parameters
    ----------
    path : str or Path
        The file [-].
    field : str
        The key or option that gave the path (``"oil.oils_csv"``, ``"--oils"``) [-].
    what : str
        What the file should be, for the message (``"CSV file"``, ``"TOML file"``) [-].
    where : str, optional
        Where the path came from, for the message [-].
    max_bytes : int
        Largest accepted size [bytes].

    Returns
    -------
    str
        The file's text [-].

    Raises
    ------
    InputError
        Missing, a directory or not a regular file, unreadable, larger than
        ``max_bytes`` or not UTF-8; the message never holds the file's content.
    """
    p = Path(path)
    shown = str(p)
    try:
        st = os.stat(p)
    except FileNotFoundError:
        raise InputError(field, shown, f"no such file; an existing {what} is required",
                         where) from None
    except OSError as e:
        raise InputError(field, shown, f"cannot be read ({_reason(e)}); a readable {what} "
                         "is required", where) from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError(field, shown, f"is a directory; a {what} is required", where)
    if not stat.S_ISREG(st.st_mode):
        raise InputError(field, shown, f"is not a regular file (a device, pipe or socket); "
                         f"a {what} is required", where)
    if st.st_size > max_bytes:
        raise InputError(field, shown, f"is {st.st_size / 2**20:.0f} MiB; at most "
                         f"{max_bytes / 2**20:.0f} MiB is read", where)
    try:
        with open(p, "rb") as fh:
            data = fh.read(max_bytes + 1)
    except OSError as e:
        raise InputError(field, shown, f"cannot be read ({_reason(e)}); a readable {what} "
                         "is required", where) from None
    if len(data) > max_bytes:
        raise InputError(field, shown, f"is larger than {max_bytes / 2**20:.0f} MiB, the "
                         "most that is read", where)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        line = data[:e.start].count(b"\n") + 1
        raise InputError(field, shown, f"is not UTF-8 text (an invalid byte on line {line}); "
                         f"a UTF-8 {what} is required", where) from None


_KINDS = {".csv": "CSV", ".toml": "TOML", ".json": "JSON"}


def file_kind(path: str | Path, text: str) -> str | None:
    """What an input file is, for a message when it is not what the option expects:
    ``"CSV"``, ``"TOML"`` or ``"JSON"`` by its suffix, else by its text (a JSON document,
    a TOML document with keys, a first line of comma-separated names); None if unknown.

    Parameters
    ----------
    path : str or Path
        The file [-].
    text : str
        Its text [-].

    Returns
    -------
    str or None
        The kind of file [-].
    """
    kind = _KINDS.get(Path(path).suffix.lower())
    if kind:
        return kind
    try:
        json.loads(text)
        return "JSON"
    except (json.JSONDecodeError, RecursionError):
        pass
    try:
        if tomllib.loads(text):
            return "TOML"
    except tomllib.TOMLDecodeError:
        pass
    first = text.lstrip().split("\n", 1)[0]
    return "CSV" if "," in first and "=" not in first else None


def header_error(path: str | Path, cols: list[str], required: tuple[str, ...],
                 optional: tuple[str, ...] = ()) -> InputError | None:
    """The InputError of a CSV header that lacks required or has unknown columns, or None.

    The message names the missing columns and the positions of unknown ones, never the
    header's own text (the file may not be the table the user meant).

    Parameters
    ----------
    path : str or Path
        The file, named in the message [-].
    cols : list of str
        The header's column names [-].
    required, optional : tuple of str
        Columns that must be present, and those that may be [-].

    Returns
    -------
    InputError or None
        The error to raise (field ``"columns"``), or None when the header is right.
    """
    missing = [c for c in required if c not in cols]
    unknown = [i + 1 for i, c in enumerate(cols) if c not in required + optional]
    allowed = f"required columns {', '.join(required)}" + (
        f"; optional {', '.join(optional)}" if optional else "")
    where = str(path)
    if missing:
        return InputError("columns", f"{len(cols)} found", f"the header lacks "
                          f"{', '.join(missing)} ({allowed})", where)
    if unknown:
        pos = ", ".join(f"#{i}" for i in unknown[:10]) + ("..." if len(unknown) > 10 else "")
        return InputError("columns", pos, f"not known columns ({allowed})", where)
    if len(set(cols)) != len(cols):
        dup = next(c for c in cols if cols.count(c) > 1)
        return InputError("columns", dup, "named twice; each column once", where)
    return None


def cell_for_message(raw: Any) -> Any:
    """A CSV cell as an error message shows it: numbers as they are, text cut to
    :data:`MAX_CELL_CHARS` characters.

    Parameters
    ----------
    raw : Any
        The cell [in the unit of its column].

    Returns
    -------
    float or Any
        ``float(raw)`` if it is a number, else the (shortened) text.
    """
    try:
        return float(raw)
    except (TypeError, ValueError):
        pass
    if isinstance(raw, str) and len(raw) > MAX_CELL_CHARS:
        return raw[:MAX_CELL_CHARS] + "..."
    return raw


def check_physical(field: str, value: Any, lo: float | None, hi: float | None, reason: str,
                   where: str | None = None, lo_open: bool = False) -> float:
    """Return ``value`` as a finite float inside its physical range, or refuse it.

    Parameters
    ----------
    field : str
        Name of the value (the key the user wrote, with its unit) [-].
    value : Any
        The value [in the unit of ``field``].
    lo, hi : float or None
        Bounds [in the unit of ``field``]; None: none on that side.
    reason : str
        Why the range is what it is (shown in the message) [-].
    where : str, optional
        Where the value came from [-].
    lo_open : bool
        True: ``lo`` itself is refused (``value > lo``).

    Returns
    -------
    float
        ``float(value)`` [in the unit of ``field``].

    Raises
    ------
    InputError
        Not a finite number, or outside the range; the message gives the range and
        ``reason``.
    """
    x = check_finite(field, value, where)
    below = lo is not None and (x <= lo if lo_open else x < lo)
    if below or (hi is not None and x > hi):
        left = "(" if lo_open else "["
        lo_s = "-inf" if lo is None else f"{lo:g}"
        hi_s = "inf" if hi is None else f"{hi:g}"
        raise InputError(field, value, f"allowed range is {left}{lo_s}, {hi_s}]: {reason}",
                         where)
    return x
