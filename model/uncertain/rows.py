"""Stacked rows of one case: the joint's loss of many variants in one vectorised evaluation.

The one composition behind :func:`~oilgap.model.uncertain.arrays.joint_loss_arrays` (the
uncertain inputs) and the grid engine's evaluate mode (:mod:`oilgap.studies.grid.evaluate`):
rows that share a case's oil law, friction form, duty cycle shape, heat path and bearing,
and differ in per-row values (:class:`RowValues`: oil temperature, depth, viscosity factor,
gamma, friction scale, film strength, bearing drag factor, peak speed, sea temperature and
the regions' geometry), evaluated as (rows x speed nodes) arrays by the model's laws, as
:func:`~oilgap.model.joint_loss.joint_mean_power` composes them:

- the oil's (nu, rho) from the fluid at the rows' (T, p), on the row's own Walther line
  (A, B) where the rows carry one (``nu40_factor``/``nu100_factor``,
  :mod:`.grade`), nu times the row's factor (as :class:`~oilgap.model.fluids.ScaledFluid`);
- the cycle's speed nodes times the row's ``peak / peak0`` (as
  :meth:`~oilgap.model.duty_cycle.DutyCycle.with_peak_speed`);
- each region's mean by :func:`~oilgap.model.regions.region_mean_power` with the law at
  gamma = 0, times ``friction_scale * T^gamma`` (Eqs. 6-8 are linear in both);
- the film factor (``film``/``full``) with the film strength carried by b (the Nahme number
  ``s b mu U^2/k`` is linear in b);
- the bearing's terms (:func:`~oilgap.model.bearing.bearing_moment_terms`), SKF's drag
  terms times the row's drag factor;
- under ``bulk``/``full`` the balance ``T = T_sea + R (P(T) + Q)``: :func:`row_balance` by
  the model's one solver, :func:`~oilgap.model.thermal.steady_temperature`, polished to
  the root as the scalar path is (the grid engine's rows; the uncertain inputs' rows
  :func:`~oilgap.model.uncertain.balance.root_balance` hands back).

References
----------
.. [1] Seed paper, Eqs. 5, 6, 8 and 10 (the isothermal loss over the cycle).
.. [2] T. L. Bergman et al., *Fundamentals of Heat and Mass Transfer*, 7th ed., Wiley
   2011, sec. 3.1 (the bulk balance).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from ..bearing.friction import bearing_mean_power, bearing_moment_terms, skf_speed_terms
from ..elements import BearingElement, joint_elements
from ..fluids import ScaledFluid
from ..joint_loss import case_film
from ..oil_properties import (
    oil_viscosities,
    oil_viscosity_temperature_slope,
    seawater_gauge_pressure,
)
from ..regions import Region, joint_regions, region_mean_power
from ..skin_friction import groove_roughness_factor
from ..taylor_couette import couette_floor_form
from ..thermal import steady_temperature
from ..thermal_modes import applies_film
from ..units import celsius_to_kelvin, rad_s_to_rpm
from ..viscous_loss import weighted_mean

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase

_DRAG_TERMS = ("drag_vm", "drag_rs")
"""The SKF terms a drag factor multiplies (:func:`~oilgap.model.bearing.friction.skf_moments`)."""


@dataclass(frozen=True, kw_only=True)
class RowValues:
    """Per-row values of stacked rows: 1-D arrays of length ``n`` (a float: every row).

    Attributes
    ----------
    n : int
        Number of rows [-].
    oil_temp_C : array
        Oil temperature [degC] (the given one; under ``bulk``/``full`` the balance sets the
        operating one).
    depth_m : float or array
        Sea depth [m].
    nu_factor : array or None
        Factor on the fluid's viscosity at every state [-] (None: 1).
    walther_A, walther_B : array or None
        Each row's Walther coefficients [-] (an oil's line rebuilt through its rows'
        nu40 and nu100, :func:`~oilgap.model.oil_properties.walther_coefficients`;
        None: the fluid's own).
    gamma : array or None
        Groove exponent of Eq. 8 [-] (None: the law's own).
    friction_scale : array or None
        Factor on C_m relative to the law [-] (None: 1).
    film_strength : array or None
        Film strength s [-] (None: the case's film).
    drag_scale : array or None
        Factor on the bearing's SKF drag terms [-] (None: 1).
    speed_factor : array or None
        Factor on every speed of the duty cycle [-] (None: 1).
    sea_temp_C : array or None
        Sea temperature of the balance [degC] (``bulk``/``full``).
    regions : tuple of Region or None
        Per-row geometry: each Region's R, delta, L [m] and T [-] as arrays (None: the
        case's regions).
    memo : dict
        What the rows' losses keep between temperatures: the bearing's speed terms of
        every row (:func:`_speed_terms`); filled on first use, never passed in (a
        ``replace`` of the rows starts an empty one).
    """

    n: int
    oil_temp_C: Any
    depth_m: Any
    nu_factor: Any = None
    walther_A: Any = None
    walther_B: Any = None
    gamma: Any = None
    friction_scale: Any = None
    film_strength: Any = None
    drag_scale: Any = None
    speed_factor: Any = None
    sea_temp_C: Any = None
    regions: tuple[Region, ...] | None = None
    memo: dict = field(default_factory=dict, init=False, compare=False, repr=False)


@dataclass(frozen=True, kw_only=True)
class RowModel:
    """What stacked rows share (:func:`row_model`).

    Attributes
    ----------
    case : DesignCase
        The case (bearing, ``[thermal]``).
    fluid : Fluid
        The fluid whose properties are evaluated (a scaled fluid's base).
    factor0 : float
        The case's own viscosity factor [-].
    law : FrictionLaw
        The friction law (gamma 0 when rows carry gamma).
    nodes, weights : ndarray
        The duty cycle's speed nodes [rad/s] and weights [-].
    film : FilmHeating or None
        The film under ``film``/``full`` (strength 1 when rows carry it).
    """

    case: Any
    fluid: Any
    factor0: float
    law: Any
    nodes: np.ndarray
    weights: np.ndarray
    film: Any


def row_model(case: DesignCase, mode: str, vary_gamma: bool = False,
              vary_strength: bool = False) -> RowModel:
    """The shared part of stacked rows of a case under a thermal mode.

    Parameters
    ----------
    case : DesignCase
        The case.
    mode : str
        Thermal mode (``film``/``full`` apply the film).
    vary_gamma : bool
        Rows carry gamma (the law is taken at gamma = 0).
    vary_strength : bool
        Rows carry the film strength.

    Returns
    -------
    RowModel
        Fluid, law, speed nodes [rad/s] and weights [-], film.
    """
    oil = case.oil
    fluid, f0 = (oil.base, oil.factor) if isinstance(oil, ScaledFluid) else (oil, 1.0)
    law = replace(case.friction, gamma=0.0) if vary_gamma else case.friction
    nodes, weights = case.duty_cycle.speed_distribution()
    film = case_film(case) if applies_film(mode) else None
    if film is not None and vary_strength:
        film = replace(film, strength=1.0)
    return RowModel(case=case, fluid=fluid, factor0=float(f0), law=law, nodes=nodes,
                    weights=weights, film=film)


def _at(v, idx, column: bool = True):
    """A row value at rows ``idx`` (as a column), or a float as it is."""
    if v is None or np.ndim(v) == 0:
        return v
    a = np.asarray(v)[idx]
    return a[:, None] if column else a


def _regions(model: RowModel, rows: RowValues, idx) -> tuple[Region, ...]:
    if rows.regions is None:
        return joint_regions(model.case)
    return tuple(Region(r.name, *(_at(getattr(r, f), idx) for f in
                                  ("radius_m", "gap_m", "length_m", "roughness_T")))
                 for r in rows.regions)


def row_losses(model: RowModel, rows: RowValues, temp_C: np.ndarray, idx: np.ndarray
               ) -> tuple[np.ndarray, np.ndarray]:
    """Cycle-mean loss [W] of each region and of the bearing at bulk temperatures.

    Parameters
    ----------
    model : RowModel
        The shared part.
    rows : RowValues
        The rows.
    temp_C : ndarray
        Bulk oil temperature [degC], one per entry of ``idx``.
    idx : ndarray of int
        The row of each temperature.

    Returns
    -------
    regions : ndarray
        Shape (len(idx), regions) [W], region 1 first.
    bearing : ndarray
        Shape (len(idx),) [W]: the bearing's and every other element's
        (:func:`~oilgap.model.elements.joint_elements`: a linear drive's screw, rod guide
        and passages); zeros without elements.

    References
    ----------
    Seed paper [1]_ (Eqs. 5, 6, 8, 10); the bearing: :mod:`oilgap.model.bearing`.
    """
    t_k = celsius_to_kelvin(np.asarray(temp_C, dtype=float))
    p = seawater_gauge_pressure(_at(rows.depth_m, idx, False))
    nu, rho, slope = _oil(model, rows, t_k, p, idx)
    nu = np.broadcast_to(np.asarray(nu, dtype=float), t_k.shape)
    factor = rows.nu_factor if rows.nu_factor is not None else (
        None if model.factor0 == 1.0 else model.factor0)
    nu_c = (nu if factor is None else _at(factor, idx, False) * nu)[:, None]
    rho_c = np.broadcast_to(np.asarray(rho, dtype=float), t_k.shape)[:, None]
    nodes = model.nodes if rows.speed_factor is None else _at(rows.speed_factor, idx) \
        * model.nodes
    b = None
    if model.film is not None:
        b = np.broadcast_to(np.asarray(slope(), dtype=float), t_k.shape)[:, None]
        if rows.film_strength is not None:
            b = _at(rows.film_strength, idx) * b
    fs, gam = _at(rows.friction_scale, idx, False), _at(rows.gamma, idx, False)
    regions = _regions(model, rows, idx)
    out = np.empty((len(t_k), len(regions)))
    for j, reg in enumerate(regions):
        mean = _scaled_mean(fs, reg, nodes, model, nu_c, rho_c, b)
        if gam is not None and not np.all(np.asarray(reg.roughness_T) == 1.0):
            t = reg.roughness_T
            mean = groove_roughness_factor(t[:, 0] if np.ndim(t) else t, gam) * mean
        out[:, j] = mean
    spec = model.case.bearing
    if spec is None:
        bearing = np.zeros(len(t_k))
    else:
        bearing = _bearing(spec, nodes, model.weights, nu_c, _at(rows.drag_scale, idx),
                           _speed_terms(model, rows, idx))
    for element in joint_elements(model.case):  # a linear drive's screw, rod guide, passages
        if not isinstance(element, BearingElement):
            bearing = bearing + np.broadcast_to(np.asarray(element.mean_power(
                nodes, model.weights, nu_c, rho_c), dtype=float), bearing.shape)
    return out, bearing


def _scaled_mean(fs, reg, nodes, model: RowModel, nu_c, rho_c, b):
    """The region's mean power at the rows' friction scales [W] (``fs`` None: the law's).

    Where the Couette floor can apply (:func:`~oilgap.model.taylor_couette.couette_floor_form`:
    the Couette laminar law, a form with a scale), the law carries each row's scale
    ``scale fs``, as the scalar path's (:func:`~oilgap.model.uncertain.inputs.apply_inputs`),
    so that a row below 1 is floored node by node (issue 27 item 4) and a row at or above
    1 is ``scale fs C_m`` (the floor changes nothing there, the laminar law being at least
    Couette): one evaluation of C_m for all rows. Otherwise ``fs`` times the mean (the
    power law's C: the mean is linear in it)."""
    law = model.law
    if fs is None or not couette_floor_form(law) or not isinstance(law.scale, (int, float)):
        mean = region_mean_power(reg, nodes, model.weights, nu_c, rho_c, law, model.film, b)
        return mean if fs is None else fs * mean
    rows_law = copy.copy(law)  # the law with one scale per row (a frozen dataclass's copy)
    object.__setattr__(rows_law, "scale", (law.scale * fs)[:, None])
    return region_mean_power(reg, nodes, model.weights, nu_c, rho_c, rows_law, model.film, b)


def _oil(model: RowModel, rows: RowValues, t_k, p, idx):
    """(nu [m^2/s], rho [kg/m^3], a callable giving b [1/K]) at the rows' states: the
    fluid's, or the rows' own Walther line (A, B) of the oil (ASTM D341)."""
    fl = model.fluid
    if rows.walther_A is None:
        nu, _, rho = fl.properties(t_k, p)
        return nu, rho, lambda: fl.temperature_slope(t_k, p)
    a, b = _at(rows.walther_A, idx, False), _at(rows.walther_B, idx, False)
    nu, _, rho = oil_viscosities(a, b, fl.density_kg_m3, t_k, p, fl.barus_1_Pa)
    return nu, rho, lambda: oil_viscosity_temperature_slope(a, b, fl.density_kg_m3, t_k, p,
                                                            fl.barus_1_Pa)


def _speed_terms(model: RowModel, rows: RowValues, idx):
    """The bearing's speed-only terms (:func:`~oilgap.model.bearing.friction.skf_speed_terms`)
    at rows ``idx``: evaluated once for all rows and kept in ``rows.memo`` (a row's speeds
    do not change with the temperature a balance tries), the same numbers as evaluated
    afresh; None for a model without them (Palmgren's)."""
    spec = model.case.bearing
    if spec.model != "skf":
        return None
    sf = rows.speed_factor
    per_row = sf is not None and np.ndim(sf) > 0
    terms = rows.memo.get("skf_speed")
    if terms is None:
        nodes = model.nodes if sf is None else (np.asarray(sf)[:, None] if per_row
                                                else sf) * model.nodes
        terms = skf_speed_terms(spec, rad_s_to_rpm(np.abs(nodes)))
        rows.memo["skf_speed"] = terms
    if not per_row:
        return terms
    idx = np.asarray(idx)
    if idx.size and np.all(np.diff(idx) == 1):  # a run of rows (a first step): views
        return {k: np.asarray(v)[idx[0]:idx[-1] + 1] for k, v in terms.items()}
    return {k: np.asarray(v)[idx] for k, v in terms.items()}


def _added(values):
    """``sum(values)`` without its first ``0 +`` (a pass over the arrays saved) [unit of
    the values]."""
    it = iter(values)
    total = next(it)
    for v in it:
        total = total + v
    return total


def _bearing(spec, nodes, weights, nu_c, drag, speed):
    """Cycle-mean bearing power [W] per row (the speed terms ``speed`` given), SKF's drag
    terms times the rows' factor ``drag``."""
    if drag is None or spec.model != "skf":
        return np.broadcast_to(np.asarray(bearing_mean_power(spec, nodes, weights, nu_c, speed),
                                          dtype=float), nu_c.shape[:1])
    terms = bearing_moment_terms(spec, nodes, nu_c, speed)
    drag_m = _added(terms.pop(k) for k in _DRAG_TERMS)
    moment = _added(terms.values()) + drag * drag_m
    return weighted_mean(moment * np.abs(nodes), weights)


def row_total(model: RowModel, rows: RowValues, temp_C: np.ndarray, idx: np.ndarray
              ) -> np.ndarray:
    """Total loss [W] (regions and bearing) at bulk temperatures (:func:`row_losses`).

    Parameters
    ----------
    model : RowModel
        The shared part.
    rows : RowValues
        The rows.
    temp_C : ndarray
        Bulk oil temperature [degC], one per entry of ``idx``.
    idx : ndarray of int
        The row of each temperature.

    Returns
    -------
    ndarray
        Loss [W], shape (len(idx),).
    """
    regions, bearing = row_losses(model, rows, temp_C, idx)
    return regions.sum(axis=1) + bearing


def row_balance(model: RowModel, rows: RowValues) -> tuple[np.ndarray, np.ndarray]:
    """Bulk temperature and total loss of every row: ``T = T_sea + R (P(T) + Q)``.

    The model's one solver, :func:`~oilgap.model.thermal.steady_temperature`, over all rows
    at once (base ``T_sea + R Q`` per row, the case's R and Q), polished to the root
    (:func:`~oilgap.model.thermal.polish_roots`, as the scalar path); the solver's
    ``power_at`` evaluates only the rows whose temperature moved (it holds a converged
    row's).

    Parameters
    ----------
    model : RowModel
        The shared part (the case's ``[thermal]``).
    rows : RowValues
        The rows (``sea_temp_C``).

    Returns
    -------
    temps_C : ndarray
        Steady bulk temperature [degC]; at or above
        :data:`~oilgap.model.thermal.MAX_OIL_TEMP_C` where the balance has no root below it.
    power_W : ndarray
        Total loss there [W].

    Raises
    ------
    SolverError
        The iteration did not converge.

    References
    ----------
    Bergman et al. [2]_, sec. 3.1.
    """
    th = model.case.thermal
    base = rows.sea_temp_C + th.resistance_K_W * th.other_heat_W
    n = rows.n
    seen: list[tuple[np.ndarray, np.ndarray]] = []

    def power_at(temp_C: np.ndarray) -> np.ndarray:
        k = len(temp_C) // n
        t = temp_C.reshape(k, n)
        p = np.full((k, n), np.nan)
        todo = np.ones((k, n), bool)
        for ts, ps in seen:  # P(row, T) is a function: a row's last values are reused
            hit = todo & (t == ts)
            p[hit] = np.broadcast_to(ps, (k, n))[hit]
            todo &= ~hit
        if todo.any():
            p[todo] = row_total(model, rows, t[todo], np.nonzero(todo)[1])
        seen[:] = [(t[j], p[j].copy()) for j in range(k)] + seen[:2]
        return p.reshape(-1)

    return steady_temperature(power_at, base, th.resistance_K_W, n, polish=True)


__all__ = ["RowModel", "RowValues", "row_balance", "row_losses", "row_model", "row_total"]
