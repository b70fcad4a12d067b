"""The one progress display of oilgap: tqdm bars on stderr, shown only on a terminal.

:func:`progress_bar` is the bar (the grid runner's, :mod:`oilgap.studies.grid.runner`);
:class:`Bars` turns the reports of the computing layers (:func:`oilgap.optim.progress.report`:
a task, steps done, steps in all) into one such bar per task; :func:`shown` installs it
for a run (the command line wraps every command in it; ``og.progress_bars()`` in Python).
Nothing is drawn when stderr is not a terminal (piped, redirected, a test's capture)
unless asked (``--progress``), nor with ``-q`` (``--no-progress``).

Why tqdm (docs/development.md, "Progress"): it is already a dependency, it writes to any
stream and disables itself cleanly, it costs nothing when disabled, and it works in
worker processes and notebooks alike; rich would add a dependency for a bar, and
oilgap's tables are plain text that must stay greppable when piped.
"""

from __future__ import annotations

import contextlib
import sys
import threading
import time
from collections.abc import Iterator
from typing import IO

from tqdm import tqdm

from oilgap.optim.progress import reporting

MIN_SECONDS = 1.0
"""A task's bar appears once it has run this long [s] (short tasks draw nothing)."""
TICK_SECONDS = 0.5
"""The bars are redrawn this often [s] (their elapsed time moves during a long step)."""


def progress_bar(total: int, label: str = "sweep", enabled: bool | None = None,
                 stream: IO[str] | None = None, initial: int = 0,
                 unit: str = " points", leave: bool = True) -> tqdm:
    """The progress bar of a run on stderr (tqdm [1]): bar, percent, count, steps per
    second, elapsed time and ETA; ``initial`` steps already done (a resumed run).

    ``enabled`` None: shown when ``stream`` (default stderr) is a terminal.

    References
    ----------
    .. [1] C. da Costa-Luis et al., *tqdm: a fast, extensible progress meter*,
       https://tqdm.github.io
    """
    stream = stream if stream is not None else sys.stderr
    if enabled is None:
        enabled = is_terminal(stream)
    return tqdm(total=max(int(total), 0), initial=int(initial), desc=f"oilgap {label}",
                unit=unit, file=stream, disable=not enabled, mininterval=0.1,
                dynamic_ncols=True, leave=leave)


def is_terminal(stream) -> bool:
    """Whether ``stream`` is a terminal (False for anything without ``isatty``)."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


class Bars:
    """A reporter (:data:`oilgap.optim.progress.Reporter`): one :func:`progress_bar` per
    task, drawn on ``stream`` once the task has run :data:`MIN_SECONDS` and removed when
    it is done. A daemon thread (:meth:`start`) redraws the bars every
    :data:`TICK_SECONDS`, so that a long step shows its elapsed time moving.

    Parameters
    ----------
    stream : file, optional
        Where to draw (default: stderr at the time of drawing).
    """

    def __init__(self, stream: IO[str] | None = None):
        self.stream = stream
        self._bars: dict[str, tqdm] = {}
        self._tasks: dict[str, list] = {}  # task -> [start, done, total]
        self._lock = threading.RLock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def __call__(self, task: str, done: int, total: int) -> None:
        with self._lock:
            state = self._tasks.setdefault(task, [time.monotonic(), 0, 0])
            state[1:] = [min(done, total), total]
            if done >= total:
                self._done(task)
            else:
                self._draw(task)

    def _draw(self, task: str) -> None:
        """Create the task's bar once it is :data:`MIN_SECONDS` old; show its count."""
        start, done, total = self._tasks[task]
        bar = self._bars.get(task)
        if bar is None:
            if time.monotonic() - start < MIN_SECONDS:
                return
            bar = self._bars[task] = progress_bar(
                total, task, True, self.stream if self.stream is not None else sys.stderr,
                unit=" steps", leave=False)
        bar.n = done
        bar.refresh()

    def _done(self, task: str) -> None:
        self._tasks.pop(task, None)
        bar = self._bars.pop(task, None)
        if bar is not None:
            bar.close()

    def _tick(self) -> None:
        while not self._stop.wait(TICK_SECONDS):
            with self._lock:
                for task in list(self._tasks):
                    self._draw(task)

    def start(self) -> Bars:
        """Start redrawing every :data:`TICK_SECONDS` (a daemon thread)."""
        self._thread = threading.Thread(target=self._tick, name="oilgap-progress",
                                        daemon=True)
        self._thread.start()
        return self

    def close(self) -> None:
        """Stop redrawing and remove every bar still drawn."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        with self._lock:
            for task in list(self._tasks):
                self._done(task)


@contextlib.contextmanager
def shown(enabled: bool | None = None, stream: IO[str] | None = None) -> Iterator[None]:
    """While inside, the computing layers' progress reports are drawn as bars
    (:class:`Bars`) when ``enabled``, or (None) when stderr is a terminal; otherwise
    nothing is installed and nothing drawn.

    Parameters
    ----------
    enabled : bool or None
        True: always; False: never; None: on a terminal only.
    stream : file, optional
        Where to draw (default stderr).
    """
    on = enabled if enabled is not None else is_terminal(stream or sys.stderr)
    if not on:
        with reporting(None):
            yield
        return
    bars = Bars(stream).start()
    try:
        with reporting(bars):
            yield
    finally:
        bars.close()


__all__ = ["Bars", "MIN_SECONDS", "TICK_SECONDS", "is_terminal", "progress_bar", "shown"]
