"""The joint's loss over arrays of uncertain inputs: one vectorised evaluation for all rows.

:func:`joint_loss_arrays` gives, for every row of broadcast input arrays (names of
:data:`~oilgap.model.uncertain.inputs.INPUTS`), the number of the scalar reference path
``operating_temperature(apply_inputs(case, row), mode).mean_power_W`` (the
``total_mean_power_W`` of :func:`~oilgap.model.evaluation.evaluate_case`): the regions'
cycle-mean loss and the rolling bearing's, under any thermal mode.

It is the stacked evaluation of :mod:`.rows` (the composition of
:func:`~oilgap.model.joint_loss.joint_mean_power` with every input an array over rows: the
oil's state, on each row's own Walther line where ``nu40_factor``/``nu100_factor`` vary,
the speed nodes times ``peak / peak0``, C_m at gamma 0 times ``friction_scale T^gamma``,
the film strength on b, SKF's drag terms times ``bearing_drag_scale``). Under
``bulk``/``full`` the balance of all rows is solved at once to its exact root
(:func:`~oilgap.model.uncertain.balance.root_balance`, about 3.2 losses a row); the rows it
hands back (a loss that rises, a root on a downward step of Eq. 6, no root below the cap)
are solved by the model's one solver over those rows
(:func:`~oilgap.model.uncertain.rows.row_balance`, the scalar path's
:func:`~oilgap.model.thermal.steady_temperature`, polished to the root as the scalar path
is). Measured against the scalar path: 1e-15 relative without a balance, 1e-13 with it
(tests/model/test_uncertain_arrays.py and test_uncertain_balance.py; 10^4 rows in
docs/benchmarks.md).

Rows are processed in blocks of :data:`BLOCK_ROWS` (memory stays bounded), whose losses are
evaluated :data:`EVAL_ROWS` rows a call (the arrays of a call stay in a core's cache); a
row's speed-only bearing terms are evaluated once, not at every temperature the balance
tries (:class:`~oilgap.model.uncertain.rows.RowValues` ``memo``).

References
----------
.. [1] Seed paper, Eqs. 5, 6, 8 and 10 (the isothermal loss over the cycle).
.. [2] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 3.1 (the bulk balance).
.. [3] ISO 3448:1992, industrial liquid lubricants, ISO viscosity classification.
"""

from __future__ import annotations

from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import InputError, SolverError
from ..joint_loss import operating_temperature, resolve_thermal_mode
from ..oil_properties import walther_coefficients
from ..thermal import MAX_OIL_TEMP_C
from ..thermal_modes import uses_balance
from ..units import ZERO_CELSIUS_K
from .balance import fit_predictor, root_balance
from .inputs import INPUTS, apply_inputs
from .rows import RowModel, RowValues, row_balance, row_model, row_total

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase

BLOCK_ROWS = 16384
"""Rows whose balance is solved together [-] (one iteration's bookkeeping, the rows left
for its last steps, and the roots' predictions are shared by this many)."""

EVAL_ROWS = 2048
"""Rows whose loss is evaluated in one call [-]: the (rows x nodes) arrays of a call (2048 x
26 doubles, 0.4 MB) stay in a core's L2 cache (2 MB on the benchmark's machine; 4096 rows
spilled out of it and ran 1.5-2 times slower, docs/benchmarks.md)."""


def _total(model: RowModel, rows: RowValues):
    """The loss [W] of rows ``i`` at temperatures ``t`` [degC]: :func:`.rows.row_total` in
    calls of at most :data:`EVAL_ROWS` rows (each row's loss is its own; the cycle mean's
    matrix-vector product may round a row by its place in a call, 1 ulp)."""
    def power(t: np.ndarray, i: np.ndarray) -> np.ndarray:
        if i.size <= EVAL_ROWS:
            return row_total(model, rows, t, i)
        out = np.empty(i.size)
        for s in range(0, i.size, EVAL_ROWS):
            out[s:s + EVAL_ROWS] = row_total(model, rows, t[s:s + EVAL_ROWS],
                                             i[s:s + EVAL_ROWS])
        return out
    return power


def broadcast_inputs(inputs: Mapping[str, Any]) -> tuple[dict[str, np.ndarray], tuple]:
    """The inputs as float arrays of one broadcast shape, names checked.

    Parameters
    ----------
    inputs : mapping
        Input name (:data:`INPUTS`) -> value(s) in its unit.

    Returns
    -------
    arrays : dict
        Name -> float array of the common shape, in the input's unit ([-], [degC], [m],
        [rpm]).
    shape : tuple
        The broadcast shape [-].

    Raises
    ------
    InputError
        An unknown name, or arrays that do not broadcast.
    """
    for k in inputs:
        if k not in INPUTS:
            raise InputError("uncertainty input", k, f"one of {', '.join(INPUTS)}")
    arrs = {k: np.asarray(v, dtype=float) for k, v in inputs.items()}
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrs.values()))
    except ValueError:
        raise InputError("uncertainty inputs", {k: a.shape for k, a in arrs.items()},
                         "arrays of shapes that broadcast together") from None
    return {k: np.broadcast_to(a, shape) for k, a in arrs.items()}, shape


def check_input_ranges(case: DesignCase, arrays: Mapping[str, np.ndarray]) -> None:
    """Refuse values :func:`apply_inputs` refuses: each input's lowest and highest value
    go through it (every input's allowed set is an interval; a NaN is its own min).

    Parameters
    ----------
    case : DesignCase
        The nominal case.
    arrays : mapping
        Input name -> array [input's unit].

    Raises
    ------
    InputError
        As :func:`apply_inputs`, naming the input.
    """
    for k, a in arrays.items():
        if a.size == 0:
            continue
        lo, hi = float(np.min(a)), float(np.max(a))
        for v in (lo, hi) if np.isfinite(lo) else (lo,):
            apply_inputs(case, {k: v})


def _row_values(case: DesignCase, arrs: Mapping[str, np.ndarray], model: RowModel
                ) -> RowValues:
    """A block's inputs as :class:`RowValues` (factors relative to the case's values)."""
    op, th = case.operating, case.thermal
    n = len(next(iter(arrs.values())))
    t_oil = arrs.get("oil_temp_C")
    f = arrs.get("nu_factor_all_temperatures")
    peak = arrs.get("peak_speed_rpm")
    a, b = _walther(model.fluid, arrs)
    return RowValues(
        n=n, oil_temp_C=np.full(n, float(op.oil_temp_C)) if t_oil is None else t_oil,
        depth_m=float(op.depth_m) if "depth_m" not in arrs else arrs["depth_m"],
        nu_factor=None if f is None else f * model.factor0, walther_A=a, walther_B=b,
        gamma=arrs.get("gamma"),
        friction_scale=arrs.get("friction_scale"), film_strength=arrs.get("film_strength"),
        drag_scale=arrs.get("bearing_drag_scale"),
        speed_factor=None if peak is None else case.duty_cycle.speed_factor(peak),
        sea_temp_C=None if th is None else (
            np.full(n, float(th.sea_temp_C)) if t_oil is None
            else th.sea_temp_C + (t_oil - op.oil_temp_C)))


def _walther(oil, arrs: Mapping[str, np.ndarray]):
    """Each row's Walther coefficients (A, B) [-] through ``(f40 nu40, f100 nu100)``, as
    :func:`.grade.walther_rebuilt` builds the scalar path's oil (ASTM D341); (None, None)
    without those inputs."""
    f40, f100 = arrs.get("nu40_factor"), arrs.get("nu100_factor")
    if f40 is None and f100 is None:
        return None, None
    nu40 = oil.nu40_cSt if f40 is None else oil.nu40_cSt * f40
    nu100 = oil.nu100_cSt if f100 is None else oil.nu100_cSt * f100
    n = len(next(iter(arrs.values())))
    a, b = walther_coefficients(np.broadcast_to(nu40, (n,)), ZERO_CELSIUS_K + 40.0,
                                np.broadcast_to(nu100, (n,)), ZERO_CELSIUS_K + 100.0)
    return np.asarray(a, float), np.asarray(b, float)


def _features(rows: RowValues) -> np.ndarray:
    """The per-row values of a block as columns (the root's predictors)."""
    vals = [getattr(rows, k) for k in ("sea_temp_C", "depth_m", "nu_factor", "walther_A",
                                       "walther_B", "gamma",
                                       "friction_scale", "film_strength", "drag_scale",
                                       "speed_factor")]
    for reg in rows.regions or ():
        vals += [reg.radius_m, reg.gap_m, reg.length_m, reg.roughness_T]
    cols = [np.asarray(v, float).reshape(-1) for v in vals if np.ndim(v) > 0]
    return np.column_stack([c for c in cols if c.size == rows.n] or [np.zeros(rows.n)])


def _block(case: DesignCase, mode: str, model: RowModel, arrs: Mapping[str, np.ndarray],
           fallback: bool = False, predictor=None, back: np.ndarray | None = None
           ) -> np.ndarray:
    """Loss [W] of one block of rows (NaN: no balance root below the cap): the balance by
    :func:`.balance.root_balance`, the rows it hands back (or all, ``fallback``) by
    :func:`.rows.row_balance`; with ``back`` (bool, one per row) the rows handed back
    are marked there (their loss NaN) for the caller to solve together."""
    rows = _row_values(case, arrs, model)
    if not uses_balance(mode):
        return _total(model, rows)(rows.oil_temp_C, np.arange(rows.n))
    th = case.thermal
    ok = rows.sea_temp_C + th.resistance_K_W * th.other_heat_W < MAX_OIL_TEMP_C
    out = np.full(rows.n, np.nan)
    if not ok.all():
        if ok.any():
            sub = None if back is None else np.zeros(int(ok.sum()), bool)
            out[ok] = _block(case, mode, model, {k: v[ok] for k, v in arrs.items()},
                             fallback, predictor, sub)
            if back is not None:
                back[np.flatnonzero(ok)[sub]] = True
        return out
    if not fallback:
        base = rows.sea_temp_C + th.resistance_K_W * th.other_heat_W
        temps, p, ok = root_balance(_total(model, rows), base,
                                    th.resistance_K_W, features=_features(rows),
                                    predictor=predictor)
        if back is not None:
            back |= ~ok
        elif not ok.all():
            p[~ok] = _block(case, mode, model, {k: v[~ok] for k, v in arrs.items()}, True)
        return p
    temps, p = row_balance(model, rows)
    return np.where(temps < MAX_OIL_TEMP_C, p, np.nan)


def _run_blocks(case: DesignCase, mode: str, model: RowModel, flat: Mapping[str, np.ndarray],
                n: int, step: int, threads: int, strict: bool) -> np.ndarray:
    """Loss [W] of all rows, block by block (threads: blocks at once); the rows the
    balance hands back solved together after the blocks (``step`` at a time)."""
    predictor = _predictor(case, mode, model, flat, n)
    out = np.empty(n)
    back = np.zeros(n, bool)  # rows root_balance handed back: solved together below

    def run(i: int, rows=None) -> None:
        sel = slice(i, i + step) if rows is None else rows[i:i + step]
        part = {k: a[sel] for k, a in flat.items()}
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            try:
                out[sel] = (_block(case, mode, model, part, predictor=predictor,
                                   back=back[sel]) if rows is None
                            else _block(case, mode, model, part, fallback=True))
            except SolverError:
                out[sel] = _loop(case, part, mode, strict)
                back[sel] = False

    starts = range(0, n, step)
    if threads > 1 and len(starts) > 1:  # numpy's loops release the GIL
        with ThreadPoolExecutor(int(threads)) as pool:
            list(pool.map(run, starts))
    else:
        for i in starts:
            run(i)
    handed = np.flatnonzero(back)
    for i in range(0, handed.size, step):
        run(i, handed)
    return out


PILOT_ROWS = 512
"""Rows solved from their brackets before a large balance run (evenly spaced over all
rows): the :class:`~oilgap.model.uncertain.balance.Predictor` of every block's roots."""


def _predictor(case: DesignCase, mode: str, model: RowModel,
               flat: Mapping[str, np.ndarray], n: int):
    """The roots' predictor of a balance run of ``n`` rows (None below 16 pilot sizes:
    each block fits its own from 64 rows)."""
    if not uses_balance(mode) or n < 16 * PILOT_ROWS:
        return None
    pick = np.linspace(0, n - 1, PILOT_ROWS).astype(np.int64)
    rows = _row_values(case, {k: a[pick] for k, a in flat.items()}, model)
    th = case.thermal
    base = rows.sea_temp_C + th.resistance_K_W * th.other_heat_W
    keep = np.flatnonzero(base < MAX_OIL_TEMP_C)
    with np.errstate(all="ignore"):
        return fit_predictor(_total(model, rows), base,
                             th.resistance_K_W, _features(rows), keep)


def _loop(case: DesignCase, flat: Mapping[str, np.ndarray], mode: str, strict: bool
          ) -> np.ndarray:
    """The scalar reference path, row by row (the fallback of a block whose balance did not
    converge as a whole)."""
    n = len(next(iter(flat.values())))
    out = np.full(n, np.nan)
    for i in range(n):
        c = apply_inputs(case, {k: float(a[i]) for k, a in flat.items()})
        try:
            out[i] = operating_temperature(c, mode).mean_power_W
        except SolverError:
            if strict:
                raise
    return out


def joint_loss_arrays(case: DesignCase, inputs: Mapping[str, Any], mode=None,
                      strict: bool = False, block_rows: int = BLOCK_ROWS,
                      threads: int = 1) -> np.ndarray:
    """Cycle-mean loss [W] of the joint (regions and bearing) for each row of inputs.

    Row ``i`` equals ``operating_temperature(apply_inputs(case, row_i), mode)
    .mean_power_W`` (the ``total_mean_power_W`` of
    :func:`~oilgap.model.evaluation.evaluate_case` under that mode) to rounding (the
    balance modes to 1e-12: both solve the balance to its root; module docstring,
    docs/benchmarks.md).

    Parameters
    ----------
    case : DesignCase
        The nominal case.
    inputs : mapping
        Input name (:data:`INPUTS`) -> array (or float) in its unit; all broadcast
        together; missing inputs keep the case's value.
    mode : str or ThermalMode, optional
        Thermal mode (default: the case's,
        :func:`~oilgap.model.joint_loss.default_thermal_mode`).
    strict : bool
        Raise :class:`SolverError` when a row has no result (a heat balance without a
        root below the cap, a non-finite loss) instead of giving it NaN.
    block_rows : int
        Rows evaluated together (:data:`BLOCK_ROWS`).
    threads : int
        Blocks evaluated at once by a pool of threads [-] (numpy's loops release the
        GIL; 1: one after another). The numbers do not depend on it.
    Returns
    -------
    ndarray
        Loss [W], the inputs' broadcast shape; NaN where a row has no result.

    Raises
    ------
    InputError
        An unknown input, an out-of-range value (as :func:`apply_inputs`), or a mode the
        case cannot take.
    SolverError
        ``strict`` and a row without a result.

    References
    ----------
    Seed paper [1]_ (Eqs. 5, 10); Bergman et al. [2]_ (the balance); ISO 3448 [3]_.
    """
    mode = resolve_thermal_mode(case, None if mode is None else str(mode))
    arrs, shape = broadcast_inputs(inputs)
    check_input_ranges(case, arrs)
    n = int(np.prod(shape, dtype=np.int64))
    flat = {k: np.ascontiguousarray(a).reshape(-1) for k, a in arrs.items()}
    if not flat:
        flat = {"nu40_factor": np.ones(n)}
    if "groove_exponent_scale" in flat:  # gamma x scale: the rows' gamma (apply_inputs')
        g0 = flat.get("gamma", np.full(n, float(case.friction.gamma)))
        flat["gamma"] = g0 * flat.pop("groove_exponent_scale")
    model = row_model(case, mode, "gamma" in flat, "film_strength" in flat)
    out = _run_blocks(case, mode, model, flat, n, max(1, int(block_rows)), threads, strict)
    out[~np.isfinite(out)] = np.nan
    if strict and np.isnan(out).any():
        j = int(np.flatnonzero(np.isnan(out))[0])
        raise SolverError(f"row {j} of the uncertain inputs has no loss under thermal mode "
                          f"'{mode}' (no heat-balance root below {MAX_OIL_TEMP_C:g} degC, or "
                          "a non-finite loss)", "no_root")
    return out.reshape(shape)


__all__ = ["BLOCK_ROWS", "broadcast_inputs", "check_input_ranges", "joint_loss_arrays"]
