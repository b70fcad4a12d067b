"""Chunks sized by time: each task runs about ``chunk_seconds`` of work.

The runner (:mod:`oilgap.studies.grid.runner`) asks :class:`ChunkSizer` for the size of
each chunk it submits and tells it how long each finished chunk took on its worker.
Before the first chunk is back the cost per point is a prior per mode
(:data:`PRIOR_S_PER_POINT`) and the first chunks are a quarter of the target (a probe);
then the measured mean cost sizes them. So the progress moves every few seconds and a
Ctrl-C loses at most one chunk per worker, whatever the grid.

Optimize mode warm-starts each solve from the previous row; so that the rows and
numbers do not depend on how the grid was cut (the timing, the workers, the backend),
the warm-started chains are fixed runs of :data:`WARM_CHAIN` rows of the grid and
every chunk holds whole chains. Before a chunk is measured the optimize probe is one
chain (the prior is the cost of the seed case without a heat balance; a film or full
solve, a longer duty cycle cost many times more), and a measured chunk sizes the next
ones in whole chains rounded down, never up: a chunk is about ``chunk_seconds`` of work,
or one chain when one chain takes longer (the smallest unit whose rows do not depend on
the timing). An explicit ``chunk_size`` keeps the old meaning: fixed chunks, each one
chain.
"""

from __future__ import annotations

import math

from oilgap.model.errors import InputError, check_positive
from oilgap.studies.settings import DEFAULT_CHUNK_SECONDS

PRIOR_S_PER_POINT = {"evaluate": 2e-4, "optimize": 5e-3}
"""Cost of one point before any is measured [s]: vectorised evaluation, one IPOPT solve
(seed case, measured on one core)."""

WARM_CHAIN = 10
"""Rows per warm-started chain in optimize mode when chunks are sized by time [-]: the
least unit of an optimize chunk, so short that one chain of a costly case (0.5 s a solve)
is still a few seconds. Warm starts barely pay here: 50 film-mode rows of the seed case
took 364 IPOPT iterations in chains of 50, 357 in chains of 10, the same optima to
4e-9 (relative)."""

MAX_EVAL_CHUNK = 5000
"""Largest evaluate chunk [rows]: its (rows x speed nodes) arrays stay small."""

PROBE_FRACTION = 0.25
"""The first chunks (before one is measured) are this fraction of the target [-]."""


class ChunkSizer:
    """The size of the next chunk from the measured cost per point.

    Parameters
    ----------
    mode : {"evaluate", "optimize"}
    workers : int
        Workers the chunks are spread over [-].
    chunk_seconds : float
        Target wall time of a chunk [s] (> 0).
    chunk_size : int, optional
        Fixed rows per chunk (then each optimize chunk is one chain) [-].
    prior_s : float, optional
        Cost of a point before one is measured [s] (default: :data:`PRIOR_S_PER_POINT`).

    Attributes
    ----------
    chain : int or None
        Rows per warm-started chain (optimize; None: the chunk).
    """

    def __init__(self, mode: str, workers: int, chunk_seconds: float = DEFAULT_CHUNK_SECONDS,
                 chunk_size: int | None = None, prior_s: float | None = None):
        self.mode = mode
        self.workers = max(1, int(workers))
        self.chunk_seconds = check_positive("chunk_seconds", chunk_seconds, "trade study")
        if chunk_size is not None and (isinstance(chunk_size, bool) or int(chunk_size) < 1):
            raise InputError("chunk_size", chunk_size, "must be an integer >= 1",
                             "trade study")
        self.fixed = None if chunk_size is None else int(chunk_size)
        self.prior_s = PRIOR_S_PER_POINT[mode] if prior_s is None else float(prior_s)
        self.chain = None if (self.fixed is not None or mode != "optimize") else WARM_CHAIN
        self.points = 0
        self.seconds = 0.0
        self.chunks = 0

    @property
    def cost_s(self) -> float:
        """The cost of a point [s]: measured mean, else the prior."""
        return self.seconds / self.points if self.points and self.seconds > 0 else self.prior_s

    def observe(self, points: int, seconds: float) -> None:
        """A chunk of ``points`` took ``seconds`` [s] on its worker."""
        self.chunks += 1
        self.points += int(points)
        self.seconds += max(float(seconds), 0.0)

    def next_size(self, remaining: int) -> int:
        """Rows of the next chunk, ``remaining`` rows still to submit [-]."""
        if remaining <= 0:
            return 0
        if self.fixed is not None:
            return min(self.fixed, remaining)
        target = self.chunk_seconds / self.cost_s
        if not self.points:
            if self.chain:  # the probe: one chain, whatever the prior says
                return min(self.chain, remaining)
            target *= PROBE_FRACTION
        share = math.ceil(remaining / self.workers)  # the tail spread over the workers
        size = max(1, min(int(target), share))
        if self.mode == "evaluate":
            size = min(size, MAX_EVAL_CHUNK)
        if self.chain:  # whole chains: the chains are fixed runs of the grid
            size = self.chain * max(1, size // self.chain)  # down: at most the target
        return min(size, remaining)


__all__ = ["DEFAULT_CHUNK_SECONDS", "MAX_EVAL_CHUNK", "PRIOR_S_PER_POINT", "WARM_CHAIN",
           "ChunkSizer"]
