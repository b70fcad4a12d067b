"""One IPOPT session for the design NLP: every solve of every thermal mode goes through it.

A formulation (the isothermal NLP of :mod:`.problem`, the thermal NLPs of
:mod:`~oilgap.optim.design.thermal`) builds its symbols, objective, constraints and report
functions; the solving is here, once:

* :class:`SolverSession`: the IPOPT solver of one NLP (the one call to ``ca.nlpsol`` for
  the design NLP), its warm-start twin built on first use, the ordinary call
  (:meth:`SolverSession.solve`) and the buffered one (:meth:`SolverSession.buffered`,
  the sweep's: no per-call conversion of inputs and outputs, the same numbers);
* :func:`clamp`: a start clamped to the bounds; :func:`snap_to_bounds`: IPOPT's optimum
  clamped to the bounds, a variable left on its bound reported at the bound exactly;
* :func:`run_starts`: one start with the dual warm start retried from the primal point
  alone should it fail, or several starts (multi-start) and the best optimum;
* :func:`solver_failure`: the one SolverError message of a failed solve.

IPOPT is the interior-point method of [1]; CasADi [2] gives it exact derivatives.

References
----------
.. [1] A. Wächter, L. T. Biegler, "On the implementation of an interior-point
   filter line-search algorithm for large-scale nonlinear programming",
   Math. Program. 106:25-57, 2006 (IPOPT).
.. [2] J. A. E. Andersson et al., "CasADi: a software framework for nonlinear
   optimization and optimal control", Math. Prog. Comp. 11:1-36, 2019.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import casadi as ca
import numpy as np

from oilgap.model.errors import InputError, SolverError
from oilgap.optim.interrupts import raise_if_interrupted
from oilgap.optim.progress import steps

from .variables import QUIET_OPTIONS, SOLVER_OPTIONS, SUCCESS_STATUSES, WARM_OPTIONS

DEFAULT_STARTS = 1
"""Start points of a design solve unless told otherwise (:func:`run_starts`)."""

MAX_STARTS = 1000
"""Most start points of a design solve: each is one IPOPT solve (0.1-1 s), so 1000 starts
are minutes to hours; a multi-start search of a 5-variable design needs tens."""


def solver_options(verbose: bool = False, **extra: Any) -> dict:
    """The nlpsol options of a design solve.

    Parameters
    ----------
    verbose : bool
        Let IPOPT print its iterations (drops :data:`.variables.QUIET_OPTIONS`).
    **extra
        Further nlpsol options (e.g. ``record_time=True``).

    Returns
    -------
    dict
        :data:`.variables.SOLVER_OPTIONS` with the quiet (or verbose) options (tolerances
        of the scaled NLP [-]).
    """
    opts = dict(SOLVER_OPTIONS, **QUIET_OPTIONS)
    if verbose:
        opts.update({"ipopt.print_level": 5, "print_time": True})
        opts.pop("ipopt.sb")
    opts.update(extra)
    return opts


class Buffered:
    """A CasADi Function called through its buffers (``Function.buffer``, CasADi >= 3.6):
    the numpy arrays of its inputs and outputs are bound once, so a call converts and
    allocates nothing (a dict call spends 0.2-0.4 ms per IPOPT solve doing so).

    Parameters
    ----------
    fn : casadi.Function
        Dense inputs and outputs.

    Attributes
    ----------
    arg, res : dict of str -> ndarray
        The inputs (written before a call) and outputs (read after it, overwritten by
        the next call: copy what is kept).
    """

    def __init__(self, fn: ca.Function):
        self.fn = fn
        self._buf, self.run = fn.buffer()
        self.arg = {fn.name_in(i): np.zeros(fn.nnz_in(i)) for i in range(fn.n_in())}
        self.res = {fn.name_out(i): np.zeros(fn.nnz_out(i)) for i in range(fn.n_out())}
        for i in range(fn.n_in()):
            self._buf.set_arg(i, memoryview(self.arg[fn.name_in(i)]))
        for i in range(fn.n_out()):
            self._buf.set_res(i, memoryview(self.res[fn.name_out(i)]))

    def stats(self) -> dict:
        """The statistics of the last call (IPOPT's ``return_status``, ``iter_count``)."""
        return self._buf.stats()


@dataclass(kw_only=True)
class SolveOutput:
    """What one IPOPT call returned (the ordinary call's, as numpy arrays).

    Attributes
    ----------
    status : str
        IPOPT's return status.
    iterations : int
        IPOPT iterations (-1 if unknown).
    time_s : float
        Wall time of the call [s].
    x, g, lam_x, lam_g : ndarray
        The NLP's variables, constraints and multipliers at the last iterate (scaled).
    f : float
        The objective there (scaled).
    """

    status: str
    iterations: int
    time_s: float
    x: np.ndarray
    f: float
    g: np.ndarray
    lam_x: np.ndarray
    lam_g: np.ndarray

    @property
    def ok(self) -> bool:
        """IPOPT reports an optimum and every variable is finite."""
        return self.status in SUCCESS_STATUSES and bool(np.all(np.isfinite(self.x)))


class SolverSession:
    """The IPOPT solver of one design NLP, built once and called many times.

    Parameters
    ----------
    name : str
        Name of the CasADi solver.
    nlp : dict
        CasADi NLP (``x``, ``p``, ``f``, ``g``).
    verbose : bool
        Let IPOPT print its iterations.
    **extra
        Further nlpsol options (:func:`solver_options`).

    Examples
    --------
    >>> import casadi as ca
    >>> x = ca.SX.sym("x")
    >>> s = SolverSession("demo", {"x": x, "p": ca.SX.sym("p", 0), "f": (x - 1) ** 2,
    ...                            "g": ca.SX(0, 1)})
    >>> round(float(s.solve([0.0], [], [-5.0], [5.0], [], []).x[0]), 6)
    1.0
    """

    def __init__(self, name: str, nlp: dict, verbose: bool = False, **extra: Any):
        self.name = name
        self._nlp = nlp
        self._verbose = bool(verbose)
        self._extra = extra
        self._opts = solver_options(verbose, **extra)
        self._cold = self._ipopt(name, self._opts)
        self._warm: ca.Function | None = None

    def _ipopt(self, name: str, opts: dict) -> ca.Function:
        """The IPOPT solver of the NLP with ``opts``: the one ``nlpsol`` call of the
        design NLP (a test greps the package for it)."""
        return ca.nlpsol(name, "ipopt", self._nlp, opts)

    def solver(self, warm: bool = False) -> ca.Function:
        """The IPOPT solver (``warm``: with :data:`.variables.WARM_OPTIONS`, built on
        first use).

        Parameters
        ----------
        warm : bool
            The solver that starts from primal and dual values.

        Returns
        -------
        casadi.Function
        """
        if not warm:
            return self._cold
        if self._warm is None:
            self._warm = self._ipopt(f"{self.name}_warm", dict(self._opts, **WARM_OPTIONS))
        return self._warm

    def with_options(self, **extra: Any) -> SolverSession:
        """A session of the same NLP with further nlpsol options (e.g. ``record_time``).

        Parameters
        ----------
        **extra
            nlpsol options added to this session's.

        Returns
        -------
        SolverSession
        """
        return SolverSession(self.name, self._nlp, self._verbose, **{**self._extra, **extra})

    def solve(self, x0: Any, p: Any, lbx: Any, ubx: Any, lbg: Any, ubg: Any,
              lam: tuple[np.ndarray, np.ndarray] | None = None) -> SolveOutput:
        """One ordinary IPOPT call.

        Parameters
        ----------
        x0, p, lbx, ubx, lbg, ubg : array_like
            Start, parameters, variable and constraint bounds of the scaled NLP.
        lam : (lam_x, lam_g), optional
            Multipliers to warm-start with (the warm solver).

        Returns
        -------
        SolveOutput
            Whatever IPOPT returned (check :attr:`SolveOutput.ok`).

        Raises
        ------
        KeyboardInterrupt
            Ctrl-C during the call (CasADi turns it into a failed solve).
        """
        args = {"x0": x0, "p": p, "lbx": lbx, "ubx": ubx, "lbg": lbg, "ubg": ubg}
        solver = self.solver(lam is not None)
        if lam is not None:
            args.update(lam_x0=lam[0], lam_g0=lam[1])
        t0 = time.perf_counter()
        sol = solver(**args)
        raise_if_interrupted()  # CasADi turns Ctrl-C into a failed solve: re-raise it
        dt = time.perf_counter() - t0
        stats = solver.stats()
        return SolveOutput(status=str(stats.get("return_status", "unknown")),
                           iterations=int(stats.get("iter_count", -1)), time_s=dt,
                           x=np.asarray(sol["x"]).ravel(), f=float(sol["f"]),
                           g=np.asarray(sol["g"]).ravel(),
                           lam_x=np.asarray(sol["lam_x"]).ravel(),
                           lam_g=np.asarray(sol["lam_g"]).ravel())

    def buffered(self, warm: bool = False) -> Buffered:
        """A new buffered caller of the solver (one per thread: buffers are not shared).

        Parameters
        ----------
        warm : bool
            Of the warm-start solver.

        Returns
        -------
        Buffered
            Write ``arg`` (``x0``, ``p``, ``lbx``, ``ubx``, ``lbg``, ``ubg``, and
            ``lam_x0``, ``lam_g0`` when warm), call ``run()`` then
            :func:`~oilgap.optim.interrupts.raise_if_interrupted`, read ``res`` and
            ``stats()``.
        """
        return Buffered(self.solver(warm))


def clamp(x: Any, lower: Any, upper: Any) -> np.ndarray:
    """``x`` clamped to [lower, upper] (np.clip without its dispatch; a new array).

    Parameters
    ----------
    x, lower, upper : array_like
        Values and their bounds (same units).

    Returns
    -------
    ndarray
    """
    return np.minimum(np.maximum(x, lower), upper)


def snap_to_bounds(y: np.ndarray, ylo: np.ndarray, yhi: np.ndarray, lo: np.ndarray,
                   hi: np.ndarray, from_nlp: Callable[[np.ndarray], np.ndarray]
                   ) -> tuple[np.ndarray, np.ndarray]:
    """IPOPT's design variables clamped to their bounds, in NLP and physical units.

    Parameters
    ----------
    y : ndarray
        IPOPT's (scaled) design variables.
    ylo, yhi : ndarray
        Their bounds (scaled).
    lo, hi : ndarray
        The bounds in physical units [m].
    from_nlp : callable
        Scaled -> physical (:func:`.variables.from_nlp`).

    Returns
    -------
    y_in : ndarray
        ``y`` clamped to [ylo, yhi].
    x : ndarray
        The design [m], clamped to [lo, hi]; a variable on its bound is reported at the
        bound exactly (no exp/log round-off).
    """
    y_in = clamp(y, ylo, yhi)
    x = clamp(from_nlp(y_in), lo, hi)
    return y_in, np.where(y_in == ylo, lo, np.where(y_in == yhi, hi, x))


def check_starts(starts: Any) -> int:
    """Check a number of start points.

    Parameters
    ----------
    starts : int
        Start points (>= 1) [-].

    Returns
    -------
    int
        ``starts`` [-].

    Raises
    ------
    InputError
        Not an integer in [1, :data:`MAX_STARTS`].
    """
    if isinstance(starts, bool) or not isinstance(starts, int) or not 1 <= starts <= MAX_STARTS:
        raise InputError("starts", starts, f"must be an integer from 1 to {MAX_STARTS} (each "
                         "start is one IPOPT solve; tens are enough for 5 design variables)",
                         "optimize")
    return starts


def run_starts(solve_from: Callable[[np.ndarray, Any], Any], x_start: np.ndarray,
               lam: Any, lower: Any, upper: Any, starts: int = DEFAULT_STARTS,
               seed: int = 0, power: Callable[[Any], float] | None = None) -> Any:
    """The best optimum of one or several starts.

    Parameters
    ----------
    solve_from : callable
        ``solve_from(x, lam)``: one solve from the design ``x`` (with multipliers ``lam``
        or None); returns a result or raises SolverError.
    x_start : ndarray
        The first start (within the bounds).
    lam : object or None
        Multipliers for the first start. With one start, a failed warm-started solve is
        retried from ``x_start`` alone.
    lower, upper : sequence of floats
        The bounds the random starts are drawn in (uniformly).
    starts : int
        ``x_start`` and ``starts - 1`` random points (numpy generator ``seed``) [-].
        IPOPT is a local method, so several starts guard against a local optimum.
    seed : int
        Seed of the random starts.
    power : callable, optional
        The value compared between optima (default: ``r.optimal.mean_power_W``).

    Returns
    -------
    object
        The result of lowest ``power``; each start done is reported
        (:func:`oilgap.optim.progress.report`, task ``"optimize: starts"``).

    Raises
    ------
    SolverError
        Every start failed (the first start's error).
    """
    if starts == 1:
        if lam is not None:
            try:
                return solve_from(x_start, lam)
            except SolverError:  # a stale dual warm start: retry from x0 alone
                pass
        return solve_from(x_start, None)
    power = power or (lambda r: r.optimal.mean_power_W)
    lo, hi = np.asarray(lower), np.asarray(upper)
    pts = np.random.default_rng(seed).uniform(size=(starts - 1, lo.size))
    best, first_error = None, None
    for k, x in enumerate(steps("optimize: starts", [x_start, *(lo + pts * (hi - lo))])):
        try:
            r = solve_from(x, lam if k == 0 else None)
        except SolverError as e:
            first_error = first_error or e
            continue
        if best is None or power(r) < power(best):
            best = r
    if best is None:
        raise first_error
    return best


def solver_failure(status: str, iterations: Any, last_iterate: Mapping[str, float],
                   nlp: str = "the design NLP") -> SolverError:
    """The SolverError of a failed solve.

    Parameters
    ----------
    status : str
        IPOPT's return status (or why the result was refused, e.g. non-finite).
    iterations : int or str
        IPOPT iterations [-].
    last_iterate : mapping of str -> float
        The last iterate in physical units (key names carry the units).
    nlp : str
        Which NLP failed (e.g. ``"the design NLP under thermal full"``).

    Returns
    -------
    SolverError
        One line: status, iterations and the last iterate; ``status`` and
        ``last_iterate`` as attributes.
    """
    last = dict(last_iterate)
    it = ", ".join(f"{k} = {v:.6g}" for k, v in last.items())
    return SolverError(f"IPOPT did not converge on {nlp} (status {status} after "
                       f"{iterations} iterations); last iterate: {it}", status=status,
                       last_iterate=last)


__all__ = ["Buffered", "DEFAULT_STARTS", "SolveOutput", "SolverSession", "check_starts", "clamp",
           "run_starts", "snap_to_bounds", "solver_failure", "solver_options"]
