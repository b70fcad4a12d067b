"""The joint's loss over arrays of uncertain inputs: one vectorised evaluation for all rows.

:func:`joint_loss_arrays` gives, for every row of broadcast input arrays (names of
:data:`~oilgap.model.uncertain.inputs.INPUTS`), the number of the scalar reference path
``operating_temperature(apply_inputs(case, row), mode).mean_power_W`` (the
``total_mean_power_W`` of :func:`~oilgap.model.evaluation.evaluate_case`): the regions'
cycle-mean loss and the rolling bearing's, under any thermal mode.

It is a composition of the model's laws, as :func:`~oilgap.model.joint_loss.joint_mean_power`
is, with every input an array over rows:

- the oil's (nu, rho) from the case's fluid at the rows' (T, p), nu times the rows'
  ``nu40_factor`` (as :class:`~oilgap.model.fluids.ScaledFluid` does);
- the duty cycle's speed nodes times ``peak / peak0`` per row (as
  :meth:`~oilgap.model.duty_cycle.DutyCycle.with_peak_speed`: a (rows x nodes) array);
- each region's cycle mean by :func:`~oilgap.model.regions.region_mean_power` with the law
  at gamma = 0, times ``friction_scale * T^gamma`` per row (C_m of Eqs. 6-8 is linear in
  its scale, C for the power-law form, and in T^gamma);
- the film factor (``film``/``full``) with the rows' film strength carried by b (the Nahme
  number ``s b mu U^2/k`` is linear in b);
- the bearing's terms by :func:`~oilgap.model.bearing.bearing_moment_terms`, its SKF drag
  terms times ``bearing_drag_scale``;
- under ``bulk``/``full`` the balance ``T = T_sea + R (P(T) + Q)`` of every row at once by
  the model's one solver, :func:`~oilgap.model.thermal.steady_temperature` (the same
  iteration and tolerance as the scalar path).

Rows are processed in blocks of :data:`BLOCK_ROWS` (memory stays bounded and the arrays of a
block stay in cache).

References
----------
.. [1] Seed paper, Eqs. 5, 6, 8 and 10 (the isothermal loss over the cycle).
.. [2] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 3.1 (the bulk balance).
.. [3] ISO 3448:1992, industrial liquid lubricants, ISO viscosity classification.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from ..bearing.friction import bearing_mean_power, bearing_moment_terms
from ..errors import InputError, SolverError
from ..fluids import ScaledFluid
from ..joint_loss import case_film, operating_temperature, resolve_thermal_mode
from ..oil_properties import seawater_gauge_pressure
from ..regions import joint_regions, region_mean_power
from ..skin_friction import groove_roughness_factor
from ..thermal import MAX_OIL_TEMP_C, steady_temperature
from ..thermal_modes import applies_film, uses_balance
from ..units import celsius_to_kelvin, rpm_to_rad_s
from ..viscous_loss import weighted_mean
from .inputs import INPUTS, apply_inputs

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase

BLOCK_ROWS = 4096
"""Rows evaluated together [-]: (rows x nodes) arrays of a block stay in the CPU's cache."""

_DRAG_TERMS = ("drag_vm", "drag_rs")
"""The SKF terms ``bearing_drag_scale`` multiplies (:func:`~oilgap.model.bearing.friction.
skf_moments`)."""


def broadcast_inputs(inputs: Mapping[str, Any]) -> tuple[dict[str, np.ndarray], tuple]:
    """The inputs as float arrays of one broadcast shape, names checked.

    Parameters
    ----------
    inputs : mapping
        Input name (:data:`INPUTS`) -> value(s) in its unit.

    Returns
    -------
    arrays : dict
        Name -> float array of the common shape.
    shape : tuple
        The broadcast shape.

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


@dataclass(frozen=True)
class _Setup:
    """What every block shares: the case's regions, nodes, law, fluid, film and bearing."""

    case: Any
    mode: str
    fluid: Any
    factor0: float
    regions: tuple
    gammas: tuple
    nodes: np.ndarray
    weights: np.ndarray
    peak0_rad_s: float
    law: Any
    film: Any


def _setup(case: DesignCase, mode: str, names) -> _Setup:
    oil = case.oil
    fluid, f0 = (oil.base, oil.factor) if isinstance(oil, ScaledFluid) else (oil, 1.0)
    law = case.friction
    if "gamma" in names:
        law = replace(law, gamma=0.0)
    regions = joint_regions(case)
    nodes, weights = case.duty_cycle.speed_distribution()
    film = case_film(case) if applies_film(mode) else None
    if film is not None and "film_strength" in names:
        film = replace(film, strength=1.0)
    return _Setup(case, mode, fluid, float(f0), regions,
                  tuple(r.roughness_T for r in regions), nodes, weights,
                  case.duty_cycle.peak_omega_rad_s, law, film)


def _rows(case: DesignCase, arrs: Mapping[str, np.ndarray], s: _Setup) -> dict:
    """The block's per-row parameters (1-D arrays, or None where the case's value holds)."""
    op, th = case.operating, case.thermal
    r: dict[str, Any] = {k: arrs.get(k) for k in INPUTS}
    n = len(next(iter(arrs.values())))
    r["n"] = n
    r["temp_C"] = np.full(n, float(op.oil_temp_C)) if r["oil_temp_C"] is None \
        else r["oil_temp_C"]
    r["depth"] = float(op.depth_m) if r["depth_m"] is None else r["depth_m"]
    f = r["nu40_factor"]
    r["factor"] = (None if s.factor0 == 1.0 else s.factor0) if f is None else f * s.factor0
    if r["peak_speed_rpm"] is not None:
        r["speed"] = rpm_to_rad_s(r["peak_speed_rpm"]) / s.peak0_rad_s
    if th is not None:
        t_oil = r["oil_temp_C"]
        r["sea_C"] = (np.full(n, float(th.sea_temp_C)) if t_oil is None
                      else th.sea_temp_C + (t_oil - op.oil_temp_C))
    return r


def _col(v, idx):
    """A row parameter for a (possibly tiled) block: v[idx] as a column, or v as is."""
    return v if np.ndim(v) == 0 else np.asarray(v)[idx][:, None]


def _power(s: _Setup, r: dict, temp_C: np.ndarray, idx: np.ndarray) -> np.ndarray:
    """Total loss [W] (regions and bearing) of the block's rows ``idx`` at bulk
    temperatures ``temp_C`` (one per index)."""
    t_k = celsius_to_kelvin(temp_C)
    depth = r["depth"] if np.ndim(r["depth"]) == 0 else r["depth"][idx]
    p = seawater_gauge_pressure(depth)
    nu, _, rho = s.fluid.properties(t_k, p)
    nu = np.broadcast_to(np.asarray(nu, dtype=float), t_k.shape)
    if r["factor"] is not None:
        nu = _col(r["factor"], idx)[:, 0] * nu
    nu_c = nu[:, None]
    rho_c = np.broadcast_to(np.asarray(rho, dtype=float), t_k.shape)[:, None]
    nodes = s.nodes if r.get("speed") is None else _col(r["speed"], idx) * s.nodes
    b = None
    if s.film is not None:
        b = np.broadcast_to(np.asarray(s.fluid.temperature_slope(t_k, p), dtype=float),
                            t_k.shape)[:, None]
        if r["film_strength"] is not None:
            b = _col(r["film_strength"], idx) * b
    fs = None if r["friction_scale"] is None else _col(r["friction_scale"], idx)[:, 0]
    gam = None if r["gamma"] is None else _col(r["gamma"], idx)[:, 0]
    total = np.zeros(len(temp_C))
    for reg, t_rough in zip(s.regions, s.gammas, strict=True):
        mean = region_mean_power(reg, nodes, s.weights, nu_c, rho_c, s.law, s.film, b)
        if fs is not None:
            mean = fs * mean
        if gam is not None and t_rough != 1.0:
            mean = groove_roughness_factor(t_rough, gam) * mean
        total += mean
    spec = s.case.bearing
    if spec is not None:
        total += _bearing(spec, nodes, s.weights, nu_c, r["bearing_drag_scale"], idx)
    return total


def _bearing(spec, nodes, weights, nu_c, drag, idx):
    """Cycle-mean bearing power [W] per row, SKF's drag terms times the rows' factor."""
    if drag is None or spec.model != "skf":
        return np.asarray(bearing_mean_power(spec, nodes, weights, nu_c), dtype=float)
    terms = bearing_moment_terms(spec, nodes, nu_c)
    drag_m = sum(terms.pop(k) for k in _DRAG_TERMS)
    moment = sum(terms.values()) + _col(drag, idx) * drag_m
    return weighted_mean(moment * np.abs(nodes), weights)


def _block(s: _Setup, arrs: Mapping[str, np.ndarray]) -> np.ndarray:
    """Loss [W] of one block of rows (NaN: no balance root below the cap)."""
    case = s.case
    r = _rows(case, arrs, s)
    if not uses_balance(s.mode):
        return _power(s, r, r["temp_C"], np.arange(r["n"]))
    th = case.thermal
    base = r["sea_C"] + th.resistance_K_W * th.other_heat_W
    ok = base < MAX_OIL_TEMP_C
    out = np.full(r["n"], np.nan)
    if not ok.any():
        return out
    if not ok.all():
        sub = {k: v[ok] for k, v in arrs.items()}
        out[ok] = _block(s, sub)
        return out
    temps, p = steady_temperature(_memo_power(s, r), base, th.resistance_K_W, r["n"])
    return np.where(temps < MAX_OIL_TEMP_C, p, np.nan)


def _memo_power(s: _Setup, r: dict):
    """``power_at`` of the balance (temperatures of length k n, row index fastest) that
    evaluates only the rows whose temperature is not one of the last call's of that row
    (any slot): the solver holds a converged row's temperature, and P(row, T) is a
    function, so the reused value is the one it would compute."""
    n = r["n"]
    seen: list[tuple[np.ndarray, np.ndarray]] = []

    def power_at(temp_C: np.ndarray) -> np.ndarray:
        k = len(temp_C) // n
        t = temp_C.reshape(k, n)
        p = np.full((k, n), np.nan)
        todo = np.ones((k, n), bool)
        for ts, ps in seen:
            hit = todo & (t == ts)
            p[hit] = np.broadcast_to(ps, (k, n))[hit]
            todo &= ~hit
        if todo.any():
            rows = np.nonzero(todo)[1]
            p[todo] = _power(s, r, t[todo], rows)
        seen[:] = [(t[j], p[j].copy()) for j in range(k)] + seen[:2]
        return p.reshape(-1)
    return power_at


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
                      strict: bool = False, block_rows: int = BLOCK_ROWS) -> np.ndarray:
    """Cycle-mean loss [W] of the joint (regions and bearing) for each row of inputs.

    Row ``i`` equals ``operating_temperature(apply_inputs(case, row_i), mode)
    .mean_power_W`` (the ``total_mean_power_W`` of
    :func:`~oilgap.model.evaluation.evaluate_case` under that mode) to rounding, the
    balance modes to the balance's tolerance (module docstring; docs/benchmarks.md).

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
    s = _setup(case, mode, flat)
    out = np.empty(n)
    step = max(1, int(block_rows))
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        for i in range(0, n, step):
            part = {k: a[i:i + step] for k, a in flat.items()}
            try:
                out[i:i + step] = _block(s, part)
            except SolverError:
                out[i:i + step] = _loop(case, part, mode, strict)
    out[~np.isfinite(out)] = np.nan
    if strict and np.isnan(out).any():
        j = int(np.flatnonzero(np.isnan(out))[0])
        raise SolverError(f"row {j} of the uncertain inputs has no loss under thermal mode "
                          f"'{mode}' (no heat-balance root below {MAX_OIL_TEMP_C:g} degC, or "
                          "a non-finite loss)", "no_root")
    return out.reshape(shape)


__all__ = ["BLOCK_ROWS", "broadcast_inputs", "check_input_ranges", "joint_loss_arrays"]
