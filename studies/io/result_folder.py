"""A command's result folder: one run at a time, either complete or marked incomplete.

* **One run per folder.** :class:`FolderLock` holds :data:`LOCK_NAME` (created with
  ``O_EXCL``, holding the pid and host); a second run into the same folder is refused
  with one line, and a lock whose process is dead is taken over.
* **Complete or marked.** :class:`ResultFolder` checks the folder before any
  computation (:func:`oilgap.studies.io.files.check_out_dir`), writes the marker file
  :data:`MARKER` when the command starts writing and removes it when every output is
  in place: a folder holding the marker is the unfinished output of a run that failed
  or was killed. With ``force`` the earlier outputs of the same command are moved
  aside (:data:`STASH_NAME`) when writing starts, so new and old outputs never sit side
  by side; they are deleted when the run completes, and put back if it fails before
  writing an output of its own (a refused input loses nothing).
* **Where it came from.** :meth:`ResultFolder.begin` writes :data:`PROVENANCE_NAME`
  (oilgap's version, the UTC date-time, the command, each input's SHA-256, the
  library versions: :func:`oilgap.studies.io.provenance.provenance`); facts learnt during
  the run (:meth:`ResultFolder.note`) are added when the folder is complete.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import socket
import time
from collections.abc import Iterable, Sequence
from pathlib import Path

from oilgap.model.errors import InputError
from oilgap.model.io.serialize import dumps

from .files import (
    MARKER,
    OutputError,
    atomic_write_text,
    check_out_dir,
    existing_outputs,
    first_existing,
)
from .provenance import PROVENANCE_NAME, RunRecord, provenance

LOCK_NAME = ".oilgap.lock"
"""Name of the lock file of a folder an oilgap run is writing into."""

STASH_NAME = ".oilgap-replaced"
"""Subfolder holding the outputs a ``force`` run replaces until it completes."""

STALE_EMPTY_LOCK_S = 10.0
"""Age [s] after which an empty or unreadable lock file (a run killed between creating
it and writing its pid) counts as stale."""

_HELD: dict[str, int] = {}
"""Folders this process holds the lock of (real path -> depth of nested holds)."""


# --------------------------------------------------------------------------- locks


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _lock_owner(lock: Path) -> tuple[int | None, str | None]:
    """(pid, host) written in a lock file; (None, None) if unreadable."""
    try:
        lines = lock.read_text(encoding="utf-8").split("\n")
        return int(lines[0]), (lines[1] if len(lines) > 1 else None)
    except (OSError, ValueError, UnicodeDecodeError):
        return None, None


def _stale(lock: Path) -> bool:
    """The lock's process is gone (same host), or the file is empty and old."""
    pid, host = _lock_owner(lock)
    if pid is None:
        try:
            return time.time() - lock.stat().st_mtime > STALE_EMPTY_LOCK_S
        except OSError:
            return True
    if host not in (None, socket.gethostname()):
        return False  # another machine's run: cannot tell, so it holds
    if pid == os.getpid():
        return True  # this process, not holding it: left by an earlier process of that pid
    return not _pid_alive(pid)


class FolderLock:
    """The lock of a folder an oilgap run writes into (:data:`LOCK_NAME`, ``O_EXCL``).

    Re-entrant within a process (a study's grid runs inside the study's own lock).
    A lock whose process has died (same host) is taken over.

    Parameters
    ----------
    folder : str or Path
        The folder (it must exist) [-].
    field : str
        The option naming it, for the refusal [-].

    Attributes
    ----------
    folder, path : Path
        The folder and its lock file.
    """

    def __init__(self, folder: str | Path, field: str = "--out"):
        self.folder = Path(folder)
        self.path = self.folder / LOCK_NAME
        self.field = field
        self._key = os.path.realpath(self.folder)
        self._held = False

    def acquire(self) -> FolderLock:
        """Take the lock, or refuse (InputError) if another live run holds it."""
        if self._held:
            return self
        if _HELD.get(self._key):
            _HELD[self._key] += 1
            self._held = True
            return self
        for _ in range(3):
            try:
                fd = os.open(self.path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
            except FileExistsError:
                if _stale(self.path):
                    with contextlib.suppress(FileNotFoundError):
                        os.unlink(self.path)
                    continue
                pid, _ = _lock_owner(self.path)
                who = f"pid {pid}" if pid is not None else "a run starting"
                raise InputError(self.field, str(self.folder), f"is in use by another oilgap "
                                 f"run ({who}; lock file {self.path.name}); wait for it to "
                                 "finish, or delete the lock file if no run is active") \
                    from None
            except OSError as e:
                raise OutputError(self.path, e) from None
            with os.fdopen(fd, "w", encoding="utf-8") as fh:
                fh.write(f"{os.getpid()}\n{socket.gethostname()}\n")
            _HELD[self._key] = 1
            self._held = True
            return self
        raise InputError(self.field, str(self.folder), "its lock file could not be taken "
                         f"({self.path.name}); try again")

    def release(self) -> None:
        """Give the lock back (the file is removed when the outermost hold ends)."""
        if not self._held:
            return
        self._held = False
        _HELD[self._key] -= 1
        if _HELD[self._key] > 0:
            return
        del _HELD[self._key]
        if _lock_owner(self.path)[0] == os.getpid():
            with contextlib.suppress(OSError):
                os.unlink(self.path)

    def __enter__(self) -> FolderLock:
        return self.acquire()

    def __exit__(self, *exc: object) -> None:
        self.release()


# --------------------------------------------------------------------------- result folders


def _stash_outputs(folder: Path, outputs: Iterable[str]) -> None:
    """Move the existing outputs (files only) into :data:`STASH_NAME`, keeping their
    paths, and remove the subfolders they leave empty; a folder holding anything else
    stays. A stash left by a killed run is emptied first."""
    stash = folder / STASH_NAME
    shutil.rmtree(stash, ignore_errors=True)
    dirs: set[Path] = set()
    for p in existing_outputs(folder, outputs):
        if p.is_dir() and not p.is_symlink():
            dirs.add(p)
            continue
        dest = stash / p.relative_to(folder)
        try:
            dest.parent.mkdir(parents=True, exist_ok=True)
            os.replace(p, dest)
        except OSError as e:
            raise OutputError(p, e) from None
        dirs.update(q for q in p.parents if folder in q.parents)
    for d in sorted(dirs, key=lambda x: len(x.parts), reverse=True):
        with contextlib.suppress(OSError):
            d.rmdir()


def _restore_outputs(folder: Path) -> None:
    """Put the stashed outputs back where they were, then drop the stash."""
    stash = folder / STASH_NAME
    if not stash.is_dir():
        return
    for p in sorted(q for q in stash.rglob("*") if not q.is_dir() or q.is_symlink()):
        dest = folder / p.relative_to(stash)
        with contextlib.suppress(OSError):
            dest.parent.mkdir(parents=True, exist_ok=True)
            os.replace(p, dest)
    shutil.rmtree(stash, ignore_errors=True)


class ResultFolder:
    """A command's result folder: checked, locked, marked while written, cleared on
    ``force``.

    Use: ``with ResultFolder(out, OUTPUTS, force) as folder:`` before any computation
    (checks the path, creates the folder, takes its :class:`FolderLock`);
    :meth:`begin` when the command starts writing (removes the earlier outputs when
    ``force`` without ``resume``, writes :data:`MARKER`); the marker is removed when
    the block ends normally. After a failure the marker stays if any output was
    written (the folder is marked incomplete); otherwise nothing is left, and a folder
    this run created is removed.

    Parameters
    ----------
    path : str or Path
        The folder [-].
    outputs : sequence of str
        The command's outputs in it: names or glob patterns (``"points_*.csv"``,
        ``"grid/points_*.csv"``) [-].
    force : bool
        Replace earlier outputs [-].
    resume : bool
        Earlier outputs are kept and continued (a resumable sweep) [-].
    command : str
        The command, written in the marker [-].
    field : str
        The option naming the folder [-].
    hint : str
        What the refusal of earlier outputs tells the user to do [-].
    run : RunRecord, optional
        The run, for :data:`PROVENANCE_NAME` (None: a run from Python) [-].

    Attributes
    ----------
    path : Path
        The folder.
    outputs : tuple of str
        As given, and :data:`PROVENANCE_NAME`.
    """

    def __init__(self, path: str | Path, outputs: Sequence[str] = (), force: bool = False,
                 resume: bool = False, command: str = "oilgap", field: str = "--out",
                 hint: str = "pass --force to replace them", run: RunRecord | None = None):
        self.path = Path(path)
        self.run = run
        self.hint = hint
        self.outputs = tuple(dict.fromkeys((*outputs, PROVENANCE_NAME)))
        self.force = bool(force)
        self.resume = bool(resume)
        self.command = command
        self.field = field
        self._lock: FolderLock | None = None
        self._created: list[Path] = []
        self._begun = False
        self._details: dict = {}

    def note(self, **details) -> None:
        """Facts learnt during the run (``thermal_mode``, ``gamma``) for the folder's
        :data:`PROVENANCE_NAME`, written when the folder is complete.

        Parameters
        ----------
        **details
            Name -> value (JSON-able) [-].
        """
        self._details.update(details)

    def write_provenance(self) -> Path:
        """Write :data:`PROVENANCE_NAME` (atomically, :func:`~oilgap.model.io.serialize.dumps`).

        Returns
        -------
        Path
            The file written.
        """
        return atomic_write_text(self.path / PROVENANCE_NAME,
                                 dumps(provenance(self.run, **self._details)) + "\n")

    def open(self) -> ResultFolder:
        """Check the path, create the folder, take its lock, then check its earlier
        outputs (:func:`~oilgap.studies.io.files.check_out_dir`): a folder another run is
        writing is refused as in use before anything else is said about it."""
        check_out_dir(self.path, (), resume=True, field=self.field)  # the path alone
        _, missing = first_existing(self.path)
        try:
            self.path.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise OutputError(self.path, e) from None
        self._created = missing
        self._lock = FolderLock(self.path, self.field)
        try:
            self._lock.acquire()
            check_out_dir(self.path, self.outputs, self.force, self.resume, self.field,
                          self.hint)
        except BaseException:
            self._undo()
            raise
        return self

    def begin(self) -> None:
        """Writing starts: earlier outputs moved aside (``force`` without ``resume``),
        the marker written."""
        if self._begun:
            return
        if self.force and not self.resume:
            _stash_outputs(self.path, self.outputs)
        atomic_write_text(self.path / MARKER, (
            f"{self.command} started writing here at {time.strftime('%Y-%m-%d %H:%M:%S')} "
            f"(pid {os.getpid()}). This file is removed when every output is written; "
            "while it is here the folder's outputs are incomplete (the run failed or was "
            "killed): rerun with --force.\n"))
        self.write_provenance()
        self._begun = True

    def complete(self) -> None:
        """Every output is written: the replaced outputs and the marker are removed."""
        if self._begun:
            if self._details:
                self.write_provenance()
            shutil.rmtree(self.path / STASH_NAME, ignore_errors=True)
            with contextlib.suppress(FileNotFoundError):
                (self.path / MARKER).unlink()
            self._begun = False

    def _undo(self) -> None:
        """After a failure: if no output was written, the marker removed and the outputs
        a ``force`` run moved aside put back (else they stay replaced: the folder is
        marked incomplete); folders this run created removed if empty; the lock
        released."""
        prov = self.path / PROVENANCE_NAME
        if self._begun and not [p for p in existing_outputs(self.path, self.outputs)
                                if p != prov]:
            with contextlib.suppress(FileNotFoundError):
                prov.unlink()  # a stamp of nothing
            _restore_outputs(self.path)
            self._details = {}
            self.complete()
        elif self._begun:
            shutil.rmtree(self.path / STASH_NAME, ignore_errors=True)
        if self._lock is not None:
            self._lock.release()
            self._lock = None
        for d in reversed(self._created):
            with contextlib.suppress(OSError):
                d.rmdir()

    def close(self, failed: bool = False) -> None:
        """End: marker removed (success) or kept if outputs were written (failure)."""
        if failed:
            self._undo()
            return
        self.complete()
        if self._lock is not None:
            self._lock.release()
            self._lock = None

    def __enter__(self) -> ResultFolder:
        return self.open()

    def __exit__(self, exc_type, exc, tb) -> None:
        self.close(failed=exc_type is not None)


__all__ = ["LOCK_NAME", "MARKER", "PROVENANCE_NAME", "STASH_NAME", "FolderLock", "ResultFolder"]
