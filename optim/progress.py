"""Progress of long work: the layers that compute report it, the caller shows it.

The model and optim layers never print. Where a computation loops long (the starts of a
multi-start optimize, the robust NLP's phases, the uncertainty study's samples, the
loop's candidate effects, the studies' fronts and grids), it calls :func:`report` with
the task's name, the steps done and the steps in all. That call goes to the *reporter*
the caller installed for the duration of a run with :func:`reporting` (the command line
does for every command, :mod:`oilgap.cli`; the façade's ``og.progress_bars()``): a
callable ``reporter(task, done, total)``. With none installed (the default, and in
worker processes, forked ones included), :func:`report` does nothing.

The reporter travels down through a :class:`contextvars.ContextVar`, not through
every function's signature: one mechanism for every command, without a ``progress``
argument on each of the dozen functions between the command and its loop. The one
reporter the project ships, tqdm bars on stderr shown only on a terminal, is
:class:`oilgap.studies.progress.Bars`.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterable, Iterator, Sized
from contextvars import ContextVar
from typing import TypeVar

Reporter = Callable[[str, int, int], None]
"""``reporter(task, done, total)``: ``done`` of ``total`` steps of ``task`` are done [-]."""

_REPORTER: ContextVar[tuple[int, Reporter] | None] = ContextVar("oilgap_progress",
                                                                default=None)
"""The installed reporter and the process that installed it (a forked worker inherits the
variable, not the right to draw: its reports are dropped)."""

T = TypeVar("T")


def report(task: str, done: int, total: int) -> None:
    """Tell the installed reporter that ``done`` of ``total`` steps of ``task`` are done
    (nothing without one).

    Parameters
    ----------
    task : str
        What runs, in a few words (``"optimize: starts"``) [-].
    done, total : int
        Steps done and in all [-].
    """
    installed = _REPORTER.get()
    if installed is not None and installed[0] == os.getpid():
        installed[1](task, int(done), int(total))


def steps(task: str, items: Iterable[T], total: int | None = None) -> Iterator[T]:
    """``items``, reporting each one done (:func:`report`).

    Parameters
    ----------
    task : str
        The task's name [-].
    items : iterable
        The steps.
    total : int, optional
        Their number (default ``len(items)``) [-].

    Yields
    ------
    object
        Each item, in order.
    """
    n = total if total is not None else (len(items) if isinstance(items, Sized) else 0)
    report(task, 0, n)
    for i, x in enumerate(items):
        yield x
        report(task, i + 1, n)


@contextlib.contextmanager
def reporting(reporter: Reporter | None) -> Iterator[None]:
    """Install ``reporter`` while inside (None: no progress); the previous one after.

    Parameters
    ----------
    reporter : callable or None
        ``reporter(task, done, total)`` [-].

    Returns
    -------
    context manager
        Inside it, :func:`report` calls ``reporter`` [-].
    """
    token = _REPORTER.set(None if reporter is None else (os.getpid(), reporter))
    try:
        yield
    finally:
        _REPORTER.reset(token)


__all__ = ["Reporter", "report", "reporting", "steps"]
