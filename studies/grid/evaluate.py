"""Vectorised evaluation of many cases: the mean viscous power over each duty cycle.

Cases that share an oil, a friction law and a duty cycle are evaluated in one
call per region of :func:`oilgap.model.regions.region_mean_power` over a
(cases x speed nodes) array. Physics is never re-written here: oil state,
regions and power come from :func:`oilgap.model.evaluation.oil_state`,
:func:`~oilgap.model.regions.joint_regions` and
:func:`~oilgap.model.regions.region_mean_power`.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.evaluation import oil_state
from oilgap.model.fluids import warn_if_untrusted_state
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.oils import Oil
from oilgap.model.regions import Region, joint_regions, region_mean_power
from oilgap.model.taylor_couette import couette_reynolds
from oilgap.model.units import MM_TO_M, m2_s_to_cst
from oilgap.studies.grid.columns import EVALUATE_NUMBERS
from oilgap.studies.grid.schema import apply_params


def _group_by_law(cases: list[DesignCase]) -> list[list[int]]:
    """Indices of the cases sharing an oil, a friction law and a duty cycle."""
    groups: dict[tuple, list[int]] = {}
    for i, c in enumerate(cases):
        key = (c.oil, c.friction, id(c.duty_cycle), c.region2 is None)
        groups.setdefault(key, []).append(i)
    return list(groups.values())


def _oil_states(cases: list[DesignCase], idx: list[int], warn_col: list[str | None]
                ) -> tuple[np.ndarray, np.ndarray]:
    """Viscosity [m^2/s] and density [kg/m^3] of the group's cases; a temperature outside
    the oil's trusted range puts its warning in ``warn_col``."""
    c0 = cases[idx[0]]
    temps = np.array([cases[i].operating.oil_temp_C for i in idx])
    depths = np.array([cases[i].operating.depth_m for i in idx])
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always", OilgapWarning)
        nu, _, rho = oil_state(c0, temps, depths)
    if rec:
        for i, t, dep in zip(idx, temps, depths, strict=True):
            with warnings.catch_warnings(record=True) as r1:
                warnings.simplefilter("always", OilgapWarning)
                warn_if_untrusted_state(c0.oil, t, seawater_gauge_pressure(dep))
            if r1:
                warn_col[i] = str(r1[0].message)
    nu = np.broadcast_to(np.asarray(nu, dtype=float), temps.shape)
    rho = np.broadcast_to(np.asarray(rho, dtype=float), temps.shape)
    return nu, rho


def _evaluate_group(cases: list[DesignCase], idx: list[int], nu: np.ndarray, rho: np.ndarray,
                    out: dict[str, np.ndarray]) -> None:
    """Fill ``out`` at ``idx``: the regions' mean powers, peak Reynolds numbers and the
    resolved region-1 geometry of the group's cases."""
    c0 = cases[idx[0]]
    ii = np.asarray(idx)
    nodes, weights = c0.duty_cycle.speed_distribution()
    w_peak = float(nodes.max())
    geos = [joint_regions(cases[i]) for i in idx]
    total = np.zeros(len(idx))
    for r in range(len(geos[0])):
        R, d, L, T = (np.array([getattr(g[r], k) for g in geos])
                      for k in ("radius_m", "gap_m", "length_m", "roughness_T"))
        stacked = Region(geos[0][r].name, R[:, None], d[:, None], L[:, None], T[:, None])
        mean = region_mean_power(stacked, nodes[None, :], weights, nu[:, None],
                                 rho[:, None], c0.friction)
        total += mean
        out[f"region{r + 1}_power_W"][ii] = mean
        out[f"Re{r + 1}_peak"][ii] = couette_reynolds(w_peak, R, d, nu)
        if r == 0:
            out["T_res"][ii] = T
            out["delta_mm_res"][ii] = d / MM_TO_M
            out["R_mm_res"][ii] = R / MM_TO_M
            out["L_mm_res"][ii] = L / MM_TO_M
    out["mean_power_W"][ii] = total
    out["nu_cSt"][ii] = m2_s_to_cst(nu)
    out["density_kg_m3"][ii] = rho


def evaluate_arrays(cases: list[DesignCase]) -> tuple[dict[str, np.ndarray], list[str | None]]:
    """The numbers of :func:`evaluate_cases` as a dict of arrays, and the warnings."""
    n = len(cases)
    out = {k: np.full(n, np.nan) for k in EVALUATE_NUMBERS}
    warn_col: list[str | None] = [None] * n
    for idx in _group_by_law(cases):
        nu, rho = _oil_states(cases, idx, warn_col)
        _evaluate_group(cases, idx, nu, rho, out)
    return out, warn_col


def evaluate_cases(cases: list[DesignCase]) -> pd.DataFrame:
    """Evaluate many cases at their own operating points, vectorised.

    Cases that share an oil, a friction law and a duty cycle are evaluated in
    one call of :func:`~oilgap.model.viscous_loss.clearance_power` on a
    (cases x speed nodes) array; the mean over the duty cycle is the
    speed-distribution quadrature of :meth:`DutyCycle.speed_distribution`, as
    in :func:`oilgap.model.evaluation.mean_viscous_power` (which this equals
    row by row to rounding).

    Returns
    -------
    DataFrame
        One row per case: ``mean_power_W``, ``region1_power_W``,
        ``region2_power_W`` [W], ``nu_cSt``, ``density_kg_m3``, ``Re1_peak``,
        ``Re2_peak`` (at the peak speed) and the resolved ``T_res``,
        ``delta_mm_res``, ``R_mm_res``, ``L_mm_res``; ``warning`` holds any
        OilgapWarning of the row.
    """
    out, warn_col = evaluate_arrays(cases)
    df = pd.DataFrame(out)
    df["warning"] = warn_col
    return df


def evaluate_chunk(base: DesignCase, rows: list[dict],
                   catalogue: Mapping[str, Oil] | None) -> list[dict]:
    """Evaluate one chunk of grid rows; a row that fails carries its error."""
    results: list[dict] = [{} for _ in rows]
    cases, where = [], []
    for i, row in enumerate(rows):
        try:
            cases.append(apply_params(base, row, catalogue))
            where.append(i)
        except (InputError, ValueError) as e:
            results[i] = {"status": "error", "error": str(e)}
    if cases:
        try:
            df = evaluate_cases(cases)
            recs = df.to_dict("records")
        except Exception:  # isolate the failing row(s): evaluate one by one
            recs = []
            for c in cases:
                try:
                    recs.append(evaluate_cases([c]).to_dict("records")[0])
                except Exception as e:  # noqa: BLE001 - a failed point is a row, not a crash
                    recs.append({"error": f"{type(e).__name__}: {e}"})
        for i, rec in zip(where, recs, strict=True):
            if "error" in rec:
                results[i] = {"status": "error", "error": rec["error"]}
            elif not np.isfinite(rec["mean_power_W"]):
                results[i] = {"status": "error",
                              "error": "non-finite result (oil state outside the laws' range)"}
            else:
                results[i] = dict(rec, status="ok", error=None)
    return results
