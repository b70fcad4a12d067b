"""Vectorised evaluation of many cases: the mean viscous power over each duty cycle.

Cases that share an oil, a friction law, a duty cycle and a heat path are evaluated
together: their regions are stacked (R, delta, L, T of shape (cases, 1)) and the loss
is :func:`oilgap.model.joint_loss.joint_mean_power` over a (cases x speed nodes)
array, the same composition as ``oilgap evaluate``. Physics is never re-written here.
A case's rolling bearing (``[bearing]``) is part of the joint: ``mean_power_W`` and
``isothermal_power_W`` include it (``include_bearing=True`` where the regions are
stacked), and so does the heat balance under ``bulk``/``full``; ``region1_power_W`` and
``region2_power_W`` stay the clearances' own (the bearing is their difference from the
total).

Thermal modes (:data:`oilgap.model.joint_loss.THERMAL_MODES`):

``none``
    the seed's isothermal loss at each row's oil temperature;
``bulk``
    the isothermal loss at the bulk temperature that balances each row's heat,
    ``T = T_sea + R (P(T) + Q)``: one vectorised fixed point for the whole group
    (:func:`oilgap.model.thermal.steady_temperature`, one base temperature
    ``T_sea + R Q`` per row);
``film``
    the film-heating correction at each row's oil temperature;
``full``
    the film correction at the bulk temperature of the same balance.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import replace

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning, SolverError
from oilgap.model.evaluation import oil_state
from oilgap.model.fluids import warn_if_untrusted_state
from oilgap.model.joint_loss import FilmBand
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.oils import Oil
from oilgap.model.regions import Region, joint_regions
from oilgap.model.taylor_couette import couette_reynolds
from oilgap.model.thermal import MAX_OIL_TEMP_C, require_balanced
from oilgap.model.thermal_modes import (
    DEFAULT_MODE_WHY,
    THERMAL_MODE_TEXT,
    THERMAL_MODES,
    ThermalMode,
    uses_balance,
)
from oilgap.model.uncertain.rows import RowValues, row_balance, row_losses, row_model, row_total
from oilgap.model.units import MM_TO_M, m2_s_to_cst
from oilgap.studies.grid.columns import EVALUATE_NUMBERS
from oilgap.studies.grid.schema import WHERE, apply_params


def _heat_path(case: DesignCase) -> tuple | None:
    """What the film and the balance share within a group (the sea temperature excepted)."""
    th = case.thermal
    if th is None:
        return None
    return (th.resistance_K_W, th.other_heat_W, th.walls, th.conductivity_W_mK,
            th.film_strength, th.wall_floating)


def _group_by_law(cases: list[DesignCase]) -> list[list[int]]:
    """Indices of the cases sharing an oil, a friction law, a duty cycle, a heat path and a
rolling bearing (or none)."""
    groups: dict[tuple, list[int]] = {}
    for i, c in enumerate(cases):
        key = (c.oil, c.friction, id(c.duty_cycle), c.region2 is None, _heat_path(c),
               c.bearing)
        groups.setdefault(key, []).append(i)
    return list(groups.values())


def _stacked_regions(cases: list[DesignCase], idx: list[int]) -> tuple[Region, ...]:
    """The group's regions, one per region index, with R, delta, L, T arrays of one value
    per case."""
    geos = [joint_regions(cases[i]) for i in idx]
    return tuple(Region(geos[0][r].name, *(np.array([getattr(g[r], k) for g in geos])
                                           for k in ("radius_m", "gap_m", "length_m",
                                                     "roughness_T")))
                 for r in range(len(geos[0])))


def _oil_states(c0: DesignCase, idx: list[int], temps: np.ndarray, depths: np.ndarray,
                warn_col: list[str | None]) -> tuple[np.ndarray, np.ndarray]:
    """Viscosity [m^2/s] and density [kg/m^3] at the rows' (operating) temperatures; a
    temperature outside the oil's trusted range puts its warning in ``warn_col``."""
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always", OilgapWarning)
        nu, _, rho = oil_state(c0, temps, depths)
    if rec:
        for i, t, dep in zip(idx, temps, np.broadcast_to(depths, temps.shape), strict=True):
            with warnings.catch_warnings(record=True) as r1:
                warnings.simplefilter("always", OilgapWarning)
                warn_if_untrusted_state(c0.oil, t, seawater_gauge_pressure(dep))
            if r1:
                warn_col[i] = "; ".join(w for w in (warn_col[i], str(r1[0].message)) if w)
    nu = np.broadcast_to(np.asarray(nu, dtype=float), temps.shape)
    rho = np.broadcast_to(np.asarray(rho, dtype=float), temps.shape)
    return nu, rho


class RowsFailed(SolverError):
    """Rows of :func:`evaluate_cases` without a result (a heat balance without a root below
    the cap), each with its message: :func:`_records` gives them their error and evaluates
    the others again, instead of halving the call until they are isolated."""

    def __init__(self, messages: dict[int, str]):
        self.messages = messages
        super().__init__(next(iter(messages.values())), "no_root")


def _balance(c0: DesignCase, rows: RowValues, idx: list[int], mode: str) -> np.ndarray:
    """Bulk temperature [degC] of each row under ``bulk``/``full`` (``T = T_sea + R (P(T)
    + Q)``, one vectorised fixed point, :func:`~oilgap.model.uncertain.rows.row_balance`);
    rows without a root below the cap raise :class:`RowsFailed`, each with its line."""
    if c0.thermal is None:
        raise InputError("thermal", mode, "'none' or 'film': the case has no [thermal] "
                         "table", WHERE)
    temps, p = row_balance(row_model(c0, mode, rows.gamma is not None), rows)
    failed = {}
    for j in np.flatnonzero(~(temps < MAX_OIL_TEMP_C)):
        try:
            require_balanced(temps[j:j + 1], replace(c0.thermal, sea_temp_C=float(
                rows.sea_temp_C[j])), c0.oil.trusted_range_C, p[j:j + 1])
        except SolverError as e:
            failed[idx[j]] = f"SolverError: {e}"
    if failed:
        raise RowsFailed(failed)
    return temps


def evaluate_rows(c0: DesignCase, rows: RowValues, mode: str, idx: list[int],
                  out: dict[str, np.ndarray], warn_col: list[str | None]) -> None:
    """Fill ``out`` at ``idx`` for stacked rows of ``c0`` (:mod:`oilgap.model.uncertain.rows`;
    rows that carry gamma and scale take ``c0``'s law at gamma 0 and scale 1): operating
    temperature, the regions' mean powers under ``mode``, the isothermal loss, peak
    Reynolds numbers and the resolved geometry."""
    ii = np.asarray(idx)
    every = np.arange(rows.n)
    given = rows.sea_temp_C if uses_balance(mode) else rows.oil_temp_C
    temps = _balance(c0, rows, idx, mode) if uses_balance(mode) else rows.oil_temp_C
    depths = np.broadcast_to(np.asarray(rows.depth_m, dtype=float), (rows.n,))
    nu, rho = _oil_states(c0, idx, temps, depths, warn_col)
    regs, bearing = row_losses(row_model(c0, mode, rows.gamma is not None), rows, temps, every)
    total = regs.sum(axis=1) + bearing
    nodes, _ = c0.duty_cycle.speed_distribution()
    w_peak = float(nodes.max()) * (1.0 if rows.speed_factor is None else rows.speed_factor)
    geo = rows.regions if rows.regions is not None else joint_regions(c0)
    for r, reg in enumerate(geo):
        out[f"region{r + 1}_power_W"][ii] = regs[:, r]
        out[f"Re{r + 1}_peak"][ii] = couette_reynolds(w_peak, reg.radius_m, reg.gap_m, nu)
    r1 = geo[0]
    out["T_res"][ii] = r1.roughness_T
    out["delta_mm_res"][ii] = np.asarray(r1.gap_m) / MM_TO_M
    out["R_mm_res"][ii] = np.asarray(r1.radius_m) / MM_TO_M
    out["L_mm_res"][ii] = np.asarray(r1.length_m) / MM_TO_M
    out["mean_power_W"][ii] = total
    out["isothermal_power_W"][ii] = total if mode == ThermalMode.NONE else row_total(
        row_model(c0, "none", rows.gamma is not None), rows, given, every)
    out["oil_temp_op_C"][ii] = temps
    out["sea_temp_C"][ii] = rows.sea_temp_C if uses_balance(mode) else np.nan
    out["nu_cSt"][ii] = m2_s_to_cst(nu)
    out["density_kg_m3"][ii] = rho


def _evaluate_group(cases: list[DesignCase], idx: list[int], mode: str,
                    out: dict[str, np.ndarray], warn_col: list[str | None]) -> None:
    """Fill ``out`` at ``idx`` for a group of cases (:func:`_group_by_law`) by
    :func:`evaluate_rows`."""
    c0 = cases[idx[0]]
    if uses_balance(mode) and c0.thermal is None:
        raise InputError("thermal", mode, "'none' or 'film': the case has no [thermal] "
                         "table", WHERE)
    rows = RowValues(
        n=len(idx), oil_temp_C=np.array([cases[i].operating.oil_temp_C for i in idx], float),
        depth_m=np.array([cases[i].operating.depth_m for i in idx], float),
        sea_temp_C=None if c0.thermal is None else np.array(
            [cases[i].thermal.sea_temp_C for i in idx], float),
        regions=_stacked_regions(cases, idx))
    evaluate_rows(c0, rows, mode, idx, out, warn_col)


def check_mode(thermal: str) -> str:
    """The thermal mode, checked against :data:`THERMAL_MODES`."""
    if thermal not in THERMAL_MODES:
        raise InputError("thermal", thermal, f"one of {', '.join(THERMAL_MODES)}", WHERE)
    return thermal


def evaluate_arrays(cases: list[DesignCase], thermal: str = "none"
                    ) -> tuple[dict[str, np.ndarray], list[str | None]]:
    """The numbers of :func:`evaluate_cases` as a dict of arrays, and the warnings."""
    mode = check_mode(thermal)
    n = len(cases)
    out = {k: np.full(n, np.nan) for k in EVALUATE_NUMBERS}
    warn_col: list[str | None] = [None] * n
    for idx in _group_by_law(cases):
        _evaluate_group(cases, idx, mode, out, warn_col)
    return out, warn_col


def evaluate_cases(cases: list[DesignCase], thermal: str = "none") -> pd.DataFrame:
    """Evaluate many cases at their own operating points, vectorised.

    Cases that share an oil, a friction law, a duty cycle and a heat path are
    evaluated together by :func:`oilgap.model.joint_loss.joint_mean_power` on a
    (cases x speed nodes) array (stacked regions); the mean over the duty cycle is
    the speed-distribution quadrature of :meth:`DutyCycle.speed_distribution`, as in
    :func:`oilgap.model.joint_loss.operating_temperature` (which this equals row by
    row to rounding; under ``none`` it equals
    :func:`oilgap.model.evaluation.mean_viscous_power`).

    Parameters
    ----------
    cases : list of DesignCase
    thermal : {"none", "bulk", "film", "full"}
        Thermal mode (default ``"none"``, the seed's isothermal model; ``"bulk"`` and
        ``"full"`` need every case's ``[thermal]`` table).

    Returns
    -------
    DataFrame
        One row per case: ``mean_power_W`` (the rolling bearing's included),
        ``region1_power_W``, ``region2_power_W`` [W] under the mode,
        ``isothermal_power_W`` (the
        isothermal loss at the row's given temperature: the oil's under
        none/film, the sea's under full) [W], ``oil_temp_op_C`` (the operating
        bulk temperature) and ``sea_temp_C`` (full only) [degC], ``nu_cSt``,
        ``density_kg_m3`` at the operating temperature, ``Re1_peak``,
        ``Re2_peak`` (at the peak speed) and the resolved ``T_res``,
        ``delta_mm_res``, ``R_mm_res``, ``L_mm_res``; ``thermal_mode``;
        ``warning`` holds any OilgapWarning of the row.
    """
    out, warn_col = evaluate_arrays(cases, thermal)
    df = pd.DataFrame(out)
    df["thermal_mode"] = thermal
    df["warning"] = warn_col
    return df


def _records(cases: list[DesignCase], thermal: str) -> list[dict]:
    """The rows of :func:`evaluate_cases` as records; where the call fails, the cases are
    halved until the failing row(s) are isolated (each carries its error)."""
    try:
        return evaluate_cases(cases, thermal).to_dict("records")
    except RowsFailed as e:
        rest = [i for i in range(len(cases)) if i not in e.messages]
        recs = iter(_records([cases[i] for i in rest], thermal) if rest else [])
        return [{"error": e.messages[i]} if i in e.messages else next(recs)
                for i in range(len(cases))]
    except Exception as e:  # noqa: BLE001 - a failed point is a row, not a crash
        if len(cases) == 1:
            return [{"error": f"{type(e).__name__}: {e}"}]
        mid = len(cases) // 2
        return _records(cases[:mid], thermal) + _records(cases[mid:], thermal)


def evaluate_chunk(base: DesignCase, rows: list[dict],
                   catalogue: Mapping[str, Oil] | None, thermal: str = "none",
                   columnar: bool = True) -> list[dict]:
    """Evaluate one chunk of grid rows under a thermal mode; a row that fails carries
    its error. Rows that vary only what stacked rows take as arrays are evaluated from
    their columns (:mod:`oilgap.studies.grid.columnar`; ``columnar=False``: one case per
    row, as before issue 21), the others one case per row, grouped by law."""
    if columnar:
        from oilgap.studies.grid.columnar import columnar_chunk

        recs = columnar_chunk(base, rows, catalogue, thermal)
        if recs is not None:
            return recs
    results: list[dict] = [{} for _ in rows]
    cases, where = [], []
    for i, row in enumerate(rows):
        try:
            cases.append(apply_params(base, row, catalogue))
            where.append(i)
        except (InputError, ValueError) as e:
            results[i] = {"status": "error", "error": str(e)}
    if cases:
        recs = _records(cases, thermal)
        for i, rec in zip(where, recs, strict=True):
            if "error" in rec:
                results[i] = {"status": "error", "error": rec["error"]}
            elif not np.isfinite(rec["mean_power_W"]):
                results[i] = {"status": "error",
                              "error": "non-finite result (oil state outside the laws' range)"}
            else:
                results[i] = dict(rec, status="ok", error=None)
    return results


MODE_TEXT = THERMAL_MODE_TEXT
"""What each thermal mode computes (the words of ``oilgap evaluate``'s header line)."""


def band_text(row) -> str:
    """The film band of a study's row as the reports print it (``mean_power_exact_W``,
    ``film_band_mode``, ``film_band_power_W`` [W]; :meth:`FilmBand.line
    <oilgap.model.joint_loss.FilmBand.line>`)."""
    return FilmBand("", float(row["mean_power_exact_W"]), str(row["film_band_mode"]),
                    float(row["film_band_power_W"]), float("nan")).line(".4g")


def thermal_description(case: DesignCase, thermal: str, by_default: bool,
                        why: str | None = None) -> str:
    """The text after ``thermal`` in the studies' header lines, as ``oilgap evaluate``'s:
    the mode, whether it is the default, what it computes and, under ``bulk``/``full``,
    the heat path, e.g. ``bulk (default: the model the evidence supports: ...; isothermal
    film at the oil temperature of the heat balance to the sea; R 0.5 K/W, Q 0 W,
    isothermal-walls; --thermal none for the seed paper's isothermal model)``.

    ``why`` replaces :data:`~oilgap.model.thermal_modes.DEFAULT_MODE_WHY`."""
    text = f"{thermal} ("
    if by_default:
        text += f"default: {why or DEFAULT_MODE_WHY}; "
    text += MODE_TEXT[thermal]
    th = case.thermal
    if uses_balance(thermal) and th is not None:
        text += f"; R {th.resistance_K_W:g} K/W, Q {th.other_heat_W:g} W, {th.walls}"
    if thermal != ThermalMode.NONE:
        text += "; --thermal none for the seed paper's isothermal model"
    return text + ")"
