"""The one way oilgap writes a file: atomically, and never over an earlier output unless
asked.

* **Atomic files.** :func:`atomic_write` writes to a temporary file in the target's
  folder, flushes and fsyncs it, then moves it into place with :func:`os.replace`:
  a reader (or a crash, a full disk, Ctrl-C) sees the old file or the new one, never
  half a file. :func:`atomic_write_text`,
  :func:`atomic_to_csv`, :func:`atomic_to_parquet` and :func:`atomic_savefig` are its
  forms. A failed write raises :class:`OutputError` naming the file (exit 2).
* **No silent overwrite.** :func:`check_out_file` and :func:`check_out_dir` check an
  output path before any computation: the folder exists (or can be made) and can be
  written, the name is not a directory, and an existing output is refused unless
  ``force``. Result folders, their lock and their incomplete marker are
  :mod:`oilgap.studies.io.result_folder`.
"""

from __future__ import annotations

import contextlib
import glob
import os
import tempfile
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import IO, Any

from oilgap.model.errors import InputError

MARKER = "INCOMPLETE"
"""Name of the marker file of a result folder whose outputs are not all written yet
(written and removed by :class:`oilgap.studies.io.result_folder.ResultFolder`)."""


class OutputError(InputError):
    """An output that cannot be written (full disk, no permission, not a folder...).

    An :class:`~oilgap.model.errors.InputError` (the command line prints its one line
    and exits 2) whose message names the file and the system's reason.

    Parameters
    ----------
    path : str or Path
        The file or folder that could not be written.
    reason : str or OSError
        Why (an OSError gives its ``strerror``).
    """

    def __init__(self, path: str | Path, reason: str | OSError):
        if isinstance(reason, OSError):
            reason = reason.strerror or type(reason).__name__
        self.field = "output"
        self.value = str(path)
        self.allowed = str(reason)
        self.where = None
        ValueError.__init__(self, f"cannot write {str(path)!r}: {reason}")


# --------------------------------------------------------------------------- atomic files


def _file_mode() -> int:
    """The permission bits a plain ``open(path, "w")`` would give (0666 less the umask)."""
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def atomic_write(path: str | Path, write: Callable[[IO], Any], binary: bool = False,
                 encoding: str = "utf-8", newline: str | None = None,
                 sync: bool = True) -> Path:
    """Write a file atomically: ``write(handle)`` into a temporary file of the same
    folder, flush, fsync, then :func:`os.replace` it onto ``path``.

    Parameters
    ----------
    path : str or Path
        The file to write [-]; its folder must exist.
    write : callable
        Called with the open handle of the temporary file (text or binary).
    binary : bool
        Open the handle in binary mode [-].
    encoding : str
        Text encoding (text mode) [-].
    newline : str, optional
        ``newline`` of :func:`open` (text mode; ``""`` for CSV writers) [-].
    sync : bool
        fsync the file before the rename (durable once the name is visible) [-].

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    OutputError
        The folder is missing or not writable, the disk is full, ``path`` is a
        directory: nothing is left behind (the temporary file is removed) and an
        earlier file at ``path`` is untouched.
    """
    path = Path(path)
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    except OSError as e:
        raise OutputError(path, e) from None
    try:
        mode = "wb" if binary else "w"
        kw = {} if binary else {"encoding": encoding, "newline": newline}
        with os.fdopen(fd, mode, **kw) as fh:
            write(fh)
            fh.flush()
            if sync:
                os.fsync(fh.fileno())
        os.chmod(tmp, _file_mode())  # mkstemp's 0600 -> what a plain write gives
        os.replace(tmp, path)
    except OSError as e:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise OutputError(path, e) from None
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    return path


def atomic_write_text(path: str | Path, text: str, encoding: str = "utf-8") -> Path:
    """Write ``text`` to ``path`` atomically (:func:`atomic_write`).

    Parameters
    ----------
    path : str or Path
        The file [-].
    text : str
        Its content [-].
    encoding : str
        Text encoding [-].

    Returns
    -------
    Path
        ``path``.
    """
    return atomic_write(path, lambda fh: fh.write(text), encoding=encoding)


FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
"""First characters that make a spreadsheet run a text cell as a formula."""


def neutralise_formulas(df: Any) -> Any:
    """A copy of a DataFrame whose text cells cannot run as spreadsheet formulas.

    A text cell beginning with one of :data:`FORMULA_START` (``=HYPERLINK(...)``,
    ``@SUM(...)``, ``+cmd``) gets a leading apostrophe, the usual neutralisation
    (OWASP, "CSV injection"); a cell that reads as a number (``-1.5``) is left as is.
    Numeric columns are untouched.

    Parameters
    ----------
    df : DataFrame
        The table (pandas) [-].

    Returns
    -------
    DataFrame
        ``df`` itself when no cell needs it, else a copy with those cells prefixed.
    """
    import pandas as pd

    out = df
    for i in range(df.shape[1]):
        s = df.iloc[:, i]
        if getattr(s.dtype, "kind", "O") not in "OSU":  # numbers, bools, dates: no text
            continue
        text = s.astype(object).where(_text_cells(s), "")
        risky = pd.Series(False, index=s.index)
        maybe = _formula_start(text).nonzero()[0]  # then is_number on those alone
        if maybe.size:
            risky.iloc[maybe] = ~text.iloc[maybe].map(is_number).to_numpy(dtype=bool)
        if risky.any():
            if out is df:
                out = df.copy()
            out.isetitem(i, s.astype(object).where(~risky, "'" + text))
    return out


def _text_cells(s: Any) -> Any:
    """Which cells of a column are text (a column of text and empty cells at once)."""
    import pandas as pd

    if pd.api.types.infer_dtype(s, skipna=True) in ("string", "empty"):
        return s.notna()
    return s.map(lambda v: isinstance(v, str))


def _formula_start(text: Any) -> Any:
    """Whether each text of a column of texts begins with one of :data:`FORMULA_START`
    (Arrow, column-wise)."""
    import numpy as np
    import pyarrow as pa
    import pyarrow.compute as pc

    arr = pa.array(text.to_numpy(dtype=object), pa.string())
    first = pc.utf8_slice_codeunits(arr, 0, 1)
    return np.asarray(pc.is_in(first, pa.array(FORMULA_START)).to_numpy(zero_copy_only=False),
                      dtype=bool)


def is_number(text: str) -> bool:
    """Whether ``text`` reads as a number: a cell such as ``-1.5`` is data, not a
    spreadsheet formula.

    Parameters
    ----------
    text : str
        A table cell [-].

    Returns
    -------
    bool
        ``float(text)`` succeeds (``-1.5``, ``1e3``, ``nan``) [-].
    """
    try:
        float(text)
    except ValueError:
        return False
    return True


def atomic_to_csv(df: Any, path: str | Path, neutralise: bool = True, **kwargs: Any) -> Path:
    """``df.to_csv(path, **kwargs)``, atomically (:func:`atomic_write`), text cells that
    a spreadsheet would run as formulas neutralised (:func:`neutralise_formulas`).

    Parameters
    ----------
    df : DataFrame
        The table (pandas) [-].
    path : str or Path
        The CSV file [-].
    neutralise : bool
        Neutralise formula-like text cells (a file only oilgap reads back, such as a
        sweep's store, keeps its cells as they are) [-].
    **kwargs
        Passed to ``to_csv`` (``index``, ``float_format``...).

    Returns
    -------
    Path
        ``path``.
    """
    safe = neutralise_formulas(df) if neutralise else df
    if kwargs == {"index": False}:  # the same bytes, column by column (csv_text)
        from oilgap.studies.io.csv_text import csv_text

        data = csv_text(safe)
        if data is not None:
            return atomic_write(path, lambda fh: fh.write(data), binary=True)
    return atomic_write(path, lambda fh: safe.to_csv(fh, **kwargs), newline="")


def atomic_to_parquet(df: Any, path: str | Path, **kwargs: Any) -> Path:
    """``df.to_parquet(path, **kwargs)``, atomically (:func:`atomic_write`).

    Parameters
    ----------
    df : DataFrame
        The table [-].
    path : str or Path
        The Parquet file [-].
    **kwargs
        Passed to ``to_parquet``.

    Returns
    -------
    Path
        ``path``.
    """
    return atomic_write(path, lambda fh: df.to_parquet(fh, **kwargs), binary=True)


def atomic_savefig(fig: Any, path: str | Path, **kwargs: Any) -> Path:
    """``fig.savefig(path, **kwargs)``, atomically (:func:`atomic_write`); the format
    is the suffix's (``.png``).

    Parameters
    ----------
    fig : matplotlib Figure
        The figure [-].
    path : str or Path
        The image file [-].
    **kwargs
        Passed to ``savefig`` (``dpi``...).

    Returns
    -------
    Path
        ``path``.
    """
    fmt = Path(path).suffix.lstrip(".").lower() or "png"
    return atomic_write(path, lambda fh: fig.savefig(fh, format=fmt, **kwargs), binary=True)


# --------------------------------------------------------------------------- checks


def refuse_existing(path: str | Path, force: bool, field: str = "--out",
                    option: str = "--force") -> Path:
    """Refuse an output that exists unless ``force``.

    Parameters
    ----------
    path : str or Path
        The output [-].
    force : bool
        Overwriting was asked for [-].
    field : str
        The option that named the output, for the message [-].
    option : str
        The option that allows overwriting [-].

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        ``path`` exists and ``force`` is false.
    """
    path = Path(path)
    if not force and (path.exists() or path.is_symlink()):
        raise InputError(field, str(path), f"exists; pass {option} to overwrite it")
    return path


def first_existing(path: Path) -> tuple[Path, list[Path]]:
    """The nearest existing ancestor of a path and the folders below it to create.

    Parameters
    ----------
    path : Path
        A file or folder that may not exist yet [-].

    Returns
    -------
    tuple of (Path, list of Path)
        The nearest existing ancestor (or ``path`` itself), and the missing folders
        from the top down.
    """
    missing = []
    p = path
    while not p.exists() and p != p.parent:
        missing.append(p)
        p = p.parent
    return p, missing[::-1]


def _probe_folder(folder: Path, field: str, shown: Path) -> None:
    """Refuse a folder that cannot take a new file (create and remove a probe)."""
    if not folder.is_dir():
        raise InputError(field, str(shown), f"{str(folder)!r} is not a folder")
    try:
        fd, probe = tempfile.mkstemp(prefix=".oilgap-probe.", dir=folder)
    except OSError as e:
        raise InputError(field, str(shown), f"cannot write in {str(folder)!r} "
                         f"({e.strerror})") from None
    os.close(fd)
    with contextlib.suppress(OSError):
        os.unlink(probe)


def check_out_file(path: str | Path, force: bool = False, field: str = "--out",
                   suffixes: Sequence[str] | None = None, make_parents: bool = False,
                   option: str = "--force") -> Path:
    """Check an output file before any computation.

    Parameters
    ----------
    path : str or Path
        The output file [-].
    force : bool
        An existing file may be overwritten [-].
    field : str
        The option naming it, for messages [-].
    suffixes : sequence of str, optional
        Allowed suffixes (``".csv"``...) [-].
    make_parents : bool
        A missing folder will be created (its nearest existing ancestor must be a
        writable folder); else the folder must exist [-].
    option : str
        How the caller asks for an overwrite, for messages (``--force``; the Python
        API's ``force=True``) [-].

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        A suffix not allowed, a directory, a folder that does not exist or cannot be
        written, an existing file without ``force``. Nothing is created.
    """
    out = Path(path)
    if suffixes and out.suffix.lower() not in suffixes:
        raise InputError(field, str(out), f"must end in {', '.join(suffixes)}")
    if out.is_dir():
        raise InputError(field, str(out), "is a directory; a file name is required")
    parent = out.parent
    if make_parents:
        parent, _ = first_existing(parent)
    elif not parent.is_dir():
        what = "is not a folder" if parent.exists() else "does not exist"
        raise InputError(field, str(out), f"directory {str(parent)!r} {what}")
    _probe_folder(parent, field, out)
    refuse_existing(out, force, field, option)
    return out


def _is_pattern(name: str) -> bool:
    return any(c in name for c in "*?[")


def existing_outputs(folder: str | Path, outputs: Iterable[str]) -> list[Path]:
    """The outputs (names or glob patterns relative to ``folder``) that exist there.

    Parameters
    ----------
    folder : str or Path
        The result folder [-].
    outputs : iterable of str
        File names or glob patterns (``"points_*.csv"``, ``"grid/results.csv"``) [-].

    Returns
    -------
    list of Path
        The existing paths, in the order of ``outputs``.
    """
    folder = Path(folder)
    found: list[Path] = []
    for name in outputs:
        if _is_pattern(name):
            found += sorted(Path(p) for p in glob.glob(str(folder / name)))
        elif (folder / name).exists():
            found.append(folder / name)
    return found


def check_out_dir(path: str | Path, outputs: Sequence[str] = (), force: bool = False,
                  resume: bool = False, field: str = "--out",
                  hint: str = "pass --force to replace them") -> Path:
    """Check a result folder before any computation.

    Parameters
    ----------
    path : str or Path
        The folder (created later if missing) [-].
    outputs : sequence of str
        The command's outputs in it (names or glob patterns) [-].
    force : bool
        Earlier outputs may be replaced [-].
    resume : bool
        Earlier outputs are the start of this run (a resumable sweep) [-].
    field : str
        The option naming the folder [-].
    hint : str
        What the refusal of earlier outputs tells the user to do [-].

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        ``path`` is a file; its nearest existing ancestor is not a writable folder; an
        output's name is taken by a directory; the folder holds earlier outputs (or
        the :data:`MARKER` of an unfinished run) and neither ``force`` nor ``resume``
        is given. Nothing is created.
    """
    out = Path(path)
    if out.exists() and not out.is_dir():
        raise InputError(field, str(out), "is a file; a folder is required")
    base, _ = first_existing(out)
    _probe_folder(base, field, out)
    if not out.is_dir():
        return out
    for name in outputs:
        if not _is_pattern(name) and not name.endswith("/") and (out / name).is_dir():
            raise InputError(field, str(out), f"{str(out / name)!r} is a directory where "
                             "an output file goes; remove it or choose another folder")
    earlier = existing_outputs(out, [*outputs, MARKER])
    if earlier and not (force or resume):
        names = ", ".join(p.name for p in earlier[:3]) + (", ..." if len(earlier) > 3 else "")
        what = ("the unfinished outputs of an earlier run" if (out / MARKER).exists()
                else "the outputs of an earlier run")
        raise InputError(field, str(out), f"holds {what} ({names}); {hint}")
    return out


__all__ = ["FORMULA_START", "MARKER", "OutputError", "atomic_savefig", "atomic_to_csv",
           "atomic_to_parquet", "atomic_write", "atomic_write_text",
           "check_out_dir", "check_out_file", "existing_outputs", "first_existing",
           "is_number", "neutralise_formulas", "refuse_existing"]
