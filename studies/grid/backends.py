"""Where the chunks of a grid run: local processes (the default) or a Dask cluster.

A backend submits one task per chunk and hands back each finished chunk as soon as it
is done (:class:`PoolBackend`, :class:`DaskBackend`; :func:`make_backend` picks one).
The runner (:mod:`oilgap.studies.grid.runner`) decides the chunks; a backend only
runs them, so both give the same rows and numbers.

* ``scheduler=None``: this process (one worker) or a pool of local processes
  (:mod:`concurrent.futures`); the workers ignore SIGINT and are ended on Ctrl-C.
* ``scheduler="local"``: a Dask ``LocalCluster`` of ``workers`` processes (one thread
  each), started for the run and closed after it.
* ``scheduler="tcp://HOST:PORT"``: the scheduler of a running Dask cluster (``dask
  scheduler`` and ``dask worker`` on the machines); the connection is given
  :data:`CONNECT_TIMEOUT_S` before the address is refused.

Dask [1] is optional (``pip install 'oilgap[dask]'``) and imported here only: it is
the Python ecosystem's standard way to run the same code on a laptop and on a
cluster.

References
----------
.. [1] Dask Development Team, *Dask: Library for dynamic task scheduling*, 2016,
   https://dask.org (``dask.distributed``: LocalCluster, Client).
"""

from __future__ import annotations

import contextlib
import logging
import signal
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from typing import Any

from oilgap.model.errors import InputError

CONNECT_TIMEOUT_S = 5.0
"""Seconds to wait for a Dask scheduler to answer before its address is refused."""

DASK_HINT = "pip install 'oilgap[dask]'"


class BackendError(InputError):
    """A scheduler that cannot be used (dask missing, an address nobody answers at):
    one line, exit 2 on the command line.

    Parameters
    ----------
    field : str
        The option (``scheduler``) [-].
    value : Any
        Its value [-].
    message : str
        The whole line said [-].
    """

    def __init__(self, field: str, value: Any, message: str):
        super().__init__(field, value, message)
        self.args = (message,)


def _ignore_sigint() -> None:
    """Worker initializer: Ctrl-C goes to the whole process group; the parent alone
    handles it (no traceback per worker)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


class InlineBackend:
    """Chunks run one after the other in this process (one worker)."""

    workers = 1
    name = "this process"

    def submit(self, fn: Callable, *args: Any) -> Future:
        """Run ``fn(*args)`` now; a finished future."""
        fut: Future = Future()
        fut.set_result(fn(*args))
        return fut

    def wait_any(self, futures: Iterable) -> set:
        """The finished futures (all of them here)."""
        return set(futures)

    def close(self, abort: bool = False, pending: Iterable = ()) -> None:
        """Nothing to end."""


class PoolBackend:
    """A pool of ``workers`` local processes (:class:`ProcessPoolExecutor`).

    Parameters
    ----------
    workers : int
        Processes [-].
    """

    name = "local processes"

    def __init__(self, workers: int):
        self.workers = int(workers)
        self._ex = ProcessPoolExecutor(max_workers=self.workers, initializer=_ignore_sigint)

    def submit(self, fn: Callable, *args: Any) -> Future:
        """Queue ``fn(*args)`` on the pool."""
        return self._ex.submit(fn, *args)

    def wait_any(self, futures: Iterable) -> set:
        """Block until at least one future is done; the done ones."""
        done, _ = wait(set(futures), return_when=FIRST_COMPLETED)
        return done

    def close(self, abort: bool = False, pending: Iterable = ()) -> None:
        """Shut the pool down; on ``abort`` at once: pending chunks cancelled, running
        workers ended (their chunks are not stored; a rerun computes them)."""
        if not abort:
            self._ex.shutdown(wait=True)
            return
        procs = list((getattr(self._ex, "_processes", None) or {}).values())
        self._ex.shutdown(wait=False, cancel_futures=True)
        for p in procs:
            with contextlib.suppress(Exception):
                p.terminate()
        for p in procs:
            with contextlib.suppress(Exception):
                p.join(5)


@contextlib.contextmanager
def _keep_malloc_threshold() -> Iterator[None]:
    """Workers started here without Dask's ``MALLOC_TRIM_THRESHOLD_=65536`` (its nanny's
    ``pre-spawn-environ``): glibc then returns freed memory to the system at once, and
    IPOPT, which allocates at each solve, ran 25-30 % slower in the workers (measured
    with ``benchmarks/bench_sweep_scale.py``). A sweep's workers hold little memory."""
    import dask  # optional dependency: only where Dask is used

    key = "distributed.nanny.pre-spawn-environ"
    env = dict(dask.config.get(key, default={}) or {})
    env.pop("MALLOC_TRIM_THRESHOLD_", None)
    with dask.config.set({key: env}):
        yield


class DaskBackend:
    """Chunks as tasks of a Dask cluster: a LocalCluster of ``workers`` processes
    (``scheduler="local"``) or the scheduler at ``tcp://HOST:PORT``.

    Parameters
    ----------
    scheduler : str
        ``"local"`` or a scheduler address [-].
    workers : int
        Processes of the LocalCluster (ignored for an address: the cluster's own) [-].

    Raises
    ------
    BackendError
        dask[distributed] is not installed, or no scheduler answers at the address
        within :data:`CONNECT_TIMEOUT_S`.
    """

    def __init__(self, scheduler: str, workers: int):
        try:
            from dask import distributed
        except ImportError:
            raise BackendError("scheduler", scheduler, f"--scheduler {scheduler} needs "
                               f"dask[distributed]: {DASK_HINT}") from None
        self._dd = distributed
        self._cluster = None
        self.scheduler = scheduler
        quiet = logging.getLogger("distributed")
        level = quiet.level
        quiet.setLevel(logging.ERROR)
        try:
            if scheduler == "local":
                with _keep_malloc_threshold():
                    self._cluster = distributed.LocalCluster(
                        n_workers=int(workers), threads_per_worker=1, processes=True,
                        dashboard_address=None, silence_logs=logging.ERROR)
                self._client = distributed.Client(self._cluster)
                self.name = f"a Dask LocalCluster of {int(workers)} processes"
            else:
                self._client = self._connect(scheduler)
                self.name = f"the Dask scheduler at {scheduler}"
        finally:
            quiet.setLevel(level)
        n = len(self._client.scheduler_info().get("workers", {}))
        self.workers = max(1, n if scheduler != "local" else int(workers))

    def _connect(self, address: str):
        """A Client of the scheduler at ``address``, or a one-line refusal."""
        try:
            return self._dd.Client(address, timeout=f"{CONNECT_TIMEOUT_S}s")
        except (OSError, TimeoutError, ValueError, TypeError) as e:
            why = (str(e).strip().splitlines() or [type(e).__name__])[0][:160]
            raise BackendError("scheduler", address, f"--scheduler {address}: no Dask "
                               f"scheduler answered within {CONNECT_TIMEOUT_S:g} s ({why}); "
                               "give tcp://HOST:PORT of a running scheduler, or local") \
                from None

    def submit(self, fn: Callable, *args: Any):
        """Queue ``fn(*args)`` on the cluster (never merged with another task)."""
        return self._client.submit(fn, *args, pure=False)

    def wait_any(self, futures: Iterable) -> set:
        """Block until at least one future is done; the done ones."""
        done, _ = self._dd.wait(list(futures), return_when="FIRST_COMPLETED")
        return set(done)

    def close(self, abort: bool = False, pending: Iterable = ()) -> None:
        """Close the client (and the LocalCluster this run started); on ``abort`` the
        ``pending`` tasks are cancelled first."""
        pending = list(pending)
        if abort and pending:
            with contextlib.suppress(Exception):
                self._client.cancel(pending, force=True)
        with contextlib.suppress(Exception):
            self._client.close()
        if self._cluster is not None:
            with contextlib.suppress(Exception):
                self._cluster.close()


SCHEDULER_HELP = ("local (a Dask LocalCluster of --workers processes) or tcp://HOST:PORT "
                  "(a running Dask scheduler); default: local processes without Dask")


def check_scheduler(scheduler: str | None) -> str | None:
    """``None``, ``"local"`` or a ``tcp://``/``tls://`` address.

    Raises
    ------
    InputError
        Anything else.
    """
    if scheduler is None or scheduler == "local":
        return scheduler
    if not isinstance(scheduler, str) or "://" not in scheduler:
        raise InputError("scheduler", scheduler, SCHEDULER_HELP, "trade study")
    return scheduler


def make_backend(scheduler: str | None, workers: int, tasks: int):
    """The backend of a run: this process (one worker or one task), a process pool, or
    Dask (``scheduler``).

    Parameters
    ----------
    scheduler : str or None
        None, ``"local"`` or ``tcp://HOST:PORT`` [-].
    workers : int
        Processes [-].
    tasks : int
        Chunks to run (at most this many pool processes are started) [-].
    """
    if scheduler is not None:
        return DaskBackend(scheduler, workers)
    if workers == 1 or tasks <= 1:
        return InlineBackend()
    return PoolBackend(min(workers, tasks))


__all__ = ["CONNECT_TIMEOUT_S", "BackendError", "DaskBackend", "InlineBackend",
           "PoolBackend", "check_scheduler", "make_backend"]
