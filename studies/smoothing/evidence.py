"""Does Table 4 support film heating? The film strength s fitted with the rig's heat balance.

The seed's Table 4 (eight mean viscous powers: four oils, grooved and smoothed rotor) is
the only measurement in oil that oilgap has. With one free run temperature per oil, any
film strength fits it: the temperatures absorb the heating (at 22 degC the ``film`` mode
gives 107 W for VG1000, close to the measured 106 W, while the isothermal model needs
47 degC for it). The comparison is therefore made with the run temperatures tied to a
physical heat balance of the rig, one for all runs::

    T_run = T0 + R (P_dry,run + P_visc(T_run; s))

``T0`` is the tank's room temperature (bounded :data:`ROOM_TEMP_BOUNDS_C`), ``R >= 0`` the
rig's thermal resistance and ``P_dry`` Table 4's dry run (24.42 W with the grooved rotor,
25.36 W smoothed: the motor's own losses heat the oil too). ``P_visc`` is the joint's mean
loss with the film factor at the Nahme number s Na (:class:`~oilgap.model.film_cycle.
FilmHeating` ``strength``; s = 0 the isothermal model, s = 1 the smooth-film theory).
gamma (shared), T0 and R are fitted by :func:`scipy.optimize.least_squares` at each s of
a grid (the profile), and s then freely in [0, 1]. The interval on s is the
profile-likelihood one (Gaussian errors of unknown variance): the s whose profile
``n ln(SSR(s)/SSR_min)`` stays below the chi-square(1) quantile 3.84 (95 %).

The module also reproduces the issue's diagnostics: the per-oil temperatures of the
isothermal fit regressed on each oil's total measured power (dry + viscous, mean of its two
runs), the same for the per-oil fit with the film-heated loss, and the film mode's
powers at the isothermal fit's temperatures (docs/thermal.md#evidence).

References
----------
.. [1] Seed paper, Sec. IV.C.2 and Table 4 (``shared/reference/seed-paper.md``).
.. [2] R. Nahme, Ingenieur-Archiv 11:191-209, 1940 (the film factor).
.. [3] D. J. Venzon, S. H. Moolgavkar, "A method for computing profile-likelihood-based
   confidence intervals", Applied Statistics 37(1):87-94, 1988.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import pandas as pd
from scipy.optimize import brentq, least_squares

from oilgap.model.case import DesignCase
from oilgap.model.errors import SolverError
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import case_film
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.regions import region_mean_power
from oilgap.model.thermal import MAX_OIL_TEMP_C, steady_temperature
from oilgap.model.units import celsius_to_kelvin

from .fit import (
    MAX_RESISTANCE_K_W,
    cases_power,
    fit_smoothing,
    load_table4,
    measured_runs,
    power_function,
    rig_case,
    stacked_power_function,
)

FILM_STRENGTH_GRID = tuple(round(0.1 * i, 1) for i in range(11))
"""Film strengths of the profile [-]: 0, 0.1, ..., 1."""
ROOM_TEMP_BOUNDS_C = (15.0, 30.0)
"""Bounds of the tank's room temperature T0 [degC] (an indoor laboratory)."""
CHI2_1_95 = 3.841458820694124
"""95 % quantile of the chi-square distribution with one degree of freedom [-]."""


def film_power_function(cases: list[DesignCase], strength: float,
                        walls: str | float | None = None):
    """``power_at(temps)``: mean viscous power [W] of the cases at temperatures [degC] with
    the film factor at strength s (s = 0: the isothermal loss, mode ``none``).

    :func:`~oilgap.studies.smoothing.fit.power_function` with each case's film settings
    (:func:`~oilgap.model.joint_loss.case_film`) given ``strength`` (and ``walls``: a
    name or the wall parameter w; None keeps the case's).
    """
    if strength == 0.0:
        return power_function(cases, "none")

    def evaluate(c, temps_C, depth, regions):
        film = replace(case_film(c), strength=float(strength))
        if walls is not None:
            film = (replace(film, walls=walls, wall_floating=None) if isinstance(walls, str)
                    else replace(film, wall_floating=float(walls)))
        t_k = celsius_to_kelvin(temps_C)
        p = seawater_gauge_pressure(depth)
        nu, _, rho = c.oil.properties(t_k, p)
        b = c.oil.temperature_slope(t_k, p)
        nu, rho, b = (np.asarray(v, dtype=float)[..., None] for v in (nu, rho, b))
        nodes, weights = c.duty_cycle.speed_distribution()
        return sum(region_mean_power(r, nodes, weights, nu, rho, c.friction, film, b)
                   for r in regions)

    return stacked_power_function(
        cases, evaluate, key=lambda c: (c.oil, c.friction, id(c.duty_cycle), c.thermal))


def dry_powers(table4: pd.DataFrame) -> np.ndarray:
    """Table 4's dry-run power of each run in :func:`measured_runs`'s order [W]: the grooved
    rotor's (before) and the smoothed rotor's (after) row-0 values."""
    dry = table4[table4["group"] == 0].iloc[0]
    n = int((table4["group"] > 0).sum())
    return np.tile([float(dry["measured_before_W"]), float(dry["measured_after_W"])], n)


@dataclass(frozen=True, kw_only=True)
class BalanceFit:
    """One fit of Table 4 with the rig's heat balance at film strength ``strength``.

    ``strength_se`` is the standard error of s when it was fitted (Jacobian based,
    ``sqrt(s^2 (J^T J)^-1)`` over the parameters off their bounds; None when held),
    ``gamma`` [-], ``room_temp_C`` T0 [degC], ``resistance_K_W`` R [K/W], ``ssr_W2`` the
    sum of squared residuals [W^2], ``rms_W`` [W], ``at_bounds`` the parameters ending on a
    bound of the fit (names), ``temps_C`` and ``powers_W`` per run [degC], [W].
    """

    strength: float
    strength_se: float | None
    gamma: float
    room_temp_C: float
    resistance_K_W: float
    ssr_W2: float
    rms_W: float
    at_bounds: tuple[str, ...]
    temps_C: tuple[float, ...]
    powers_W: tuple[float, ...]


class _Rig:
    """Table 4's runs, their measured and dry powers, and the rig's cases per gamma."""

    def __init__(self, base: DesignCase, table4: pd.DataFrame, walls):
        self.base, self.walls = base, walls
        self.runs, self.meas = measured_runs(table4)
        self.dry = dry_powers(table4)
        self._cache: dict[float, list[DesignCase]] = {}

    def cases(self, gamma: float) -> list[DesignCase]:
        if gamma not in self._cache:
            self._cache.clear()
            self._cache[gamma] = [rig_case(o, t, gamma, self.base) for o, t in self.runs]
        return self._cache[gamma]

    def model(self, gamma: float, t0: float, r: float, s: float):
        """(temps [degC], powers [W]) of the runs under the balance at strength s."""
        power_at = film_power_function(self.cases(gamma), s, self.walls)
        return steady_temperature(power_at, t0 + r * self.dry, r, len(self.runs), 1e-9, 60,
                                  MAX_OIL_TEMP_C)


_NAMES = ("gamma", "T0", "R", "s")


def _fit(rig: _Rig, strength: float | None, x0: np.ndarray) -> BalanceFit:
    """Least squares of gamma, T0, R (and s when ``strength`` is None) [1]_."""
    lo = [0.0, ROOM_TEMP_BOUNDS_C[0], 0.0] + ([0.0] if strength is None else [])
    hi = [3.0, ROOM_TEMP_BOUNDS_C[1], MAX_RESISTANCE_K_W] + ([1.0] if strength is None
                                                              else [])
    x0 = np.clip(np.asarray(x0[:len(lo)], dtype=float), lo, hi)

    def res(x):
        s = x[3] if strength is None else strength
        return rig.model(x[0], x[1], x[2], s)[1] - rig.meas

    sol = least_squares(res, x0, bounds=(lo, hi), jac="2-point", x_scale="jac",
                        xtol=1e-10, ftol=1e-10, gtol=1e-10)
    if not sol.success:
        raise SolverError(f"heat-balance fit of Table 4 failed: {sol.message}", str(sol.status))
    s = float(sol.x[3]) if strength is None else float(strength)
    temps, powers = rig.model(sol.x[0], sol.x[1], sol.x[2], s)
    ssr = float(sol.fun @ sol.fun)
    pinned = tuple(n for n, a in zip(_NAMES, sol.active_mask, strict=False) if a != 0)
    se = None
    if strength is None and sol.active_mask[3] == 0:
        free = sol.active_mask == 0
        j = sol.jac[:, free]
        try:
            cov = np.linalg.inv(j.T @ j) * ssr / max(len(rig.meas) - int(free.sum()), 1)
            se = float(np.sqrt(max(cov[-1, -1], 0.0)))
        except np.linalg.LinAlgError:
            se = float("inf")
    return BalanceFit(
        strength=s, strength_se=se, gamma=float(sol.x[0]), room_temp_C=float(sol.x[1]),
        resistance_K_W=float(sol.x[2]), ssr_W2=ssr, rms_W=float(np.sqrt(ssr / len(rig.meas))),
        at_bounds=pinned, temps_C=tuple(map(float, temps)), powers_W=tuple(map(float, powers)))


def _regression(temps_C: np.ndarray, power_W: np.ndarray) -> dict[str, float]:
    """Least-squares line T = a + c P: intercept [degC], slope [K/W], R^2 [-]."""
    a = np.vstack([np.ones_like(power_W), power_W]).T
    coef = np.linalg.lstsq(a, temps_C, rcond=None)[0]
    r2 = 1.0 - np.sum((temps_C - a @ coef) ** 2) / np.sum((temps_C - temps_C.mean()) ** 2)
    return {"intercept_C": float(coef[0]), "slope_K_W": float(coef[1]), "r2": float(r2)}


@dataclass(frozen=True, kw_only=True)
class FilmEvidence:
    """What Table 4 says about film heating (module docstring).

    Attributes
    ----------
    profile : DataFrame
        One row per grid strength: ``film_strength``, ``gamma``, ``room_temp_C``,
        ``resistance_K_per_W``, ``rms_W``, ``at_bounds``, ``delta_n_log_ssr``.
    best : BalanceFit
        The fit with s free in [0, 1].
    interval : tuple of float
        95 % profile-likelihood interval of s [-] (within [0, 1]).
    per_oil_none, per_oil_film : dict
        The per-oil fits' temperatures regressed on each oil's total measured power:
        ``intercept_C``, ``slope_K_W``, ``r2`` and ``temps_C`` (per oil).
    film_at_isothermal : DataFrame
        Per oil: ``oil``, ``oil_temp_C`` (isothermal per-oil fit), ``film_grooved_W``,
        ``film_smoothed_W`` (mode ``film`` there), ``measured_grooved_W``,
        ``measured_smoothed_W``.
    vg1000 : dict
        ``film_W_at_22C`` (grooved, mode ``film``), ``none_temp_C`` (the temperature at
        which the isothermal model gives the measured grooved power) [W], [degC].
    walls : str or float
        The wall condition of the film [-].
    """

    profile: pd.DataFrame
    best: BalanceFit
    interval: tuple[float, float]
    per_oil_none: dict
    per_oil_film: dict
    film_at_isothermal: pd.DataFrame
    vg1000: dict
    walls: str | float = "isothermal-walls"

    def row(self, s: float) -> pd.Series:
        """The profile's row at grid strength ``s``."""
        return self.profile.loc[np.isclose(self.profile["film_strength"], s)].iloc[0]


def _interval(profile: pd.DataFrame) -> tuple[float, float]:
    """Where ``delta_n_log_ssr`` crosses the chi-square(1) quantile, linear in s between
    grid points (the grid's ends where it does not cross)."""
    s = profile["film_strength"].to_numpy()
    d = profile["delta_n_log_ssr"].to_numpy() - CHI2_1_95
    i = int(np.argmin(d))
    lo, hi = s[0], s[-1]
    for j in range(i, 0, -1):
        if d[j - 1] > 0 >= d[j]:
            lo = s[j - 1] + (s[j] - s[j - 1]) * d[j - 1] / (d[j - 1] - d[j])
            break
    for j in range(i, len(s) - 1):
        if d[j] <= 0 < d[j + 1]:
            hi = s[j] + (s[j + 1] - s[j]) * (-d[j]) / (d[j + 1] - d[j])
            break
    return float(lo), float(hi)


def _per_oil(thermal: str, base: DesignCase, table4: pd.DataFrame) -> dict:
    """The per-oil fit (mode ``thermal``): its temperatures regressed on each oil's total
    measured power (dry + viscous, mean of its grooved and smoothed runs)."""
    fit = fit_smoothing("per-oil", 0.0, base, table4, thermal)
    t4 = table4[table4["group"] > 0]
    dry = table4[table4["group"] == 0].iloc[0]
    total = 0.5 * (t4["measured_before_W"].to_numpy(dtype=float)
                   + t4["measured_after_W"].to_numpy(dtype=float)
                   + float(dry["measured_before_W"]) + float(dry["measured_after_W"]))
    temps = np.array([fit.base_temp_C[str(o)] for o in t4["oil"]])
    return {**_regression(temps, total), "gamma": fit.gamma, "rms_W": fit.rms_W,
            "temps_C": dict(zip(map(str, t4["oil"]), map(float, temps), strict=True))}


def _film_at(per_oil_none: dict, base: DesignCase, table4: pd.DataFrame) -> pd.DataFrame:
    """Mode ``film`` at the isothermal per-oil fit's temperatures and gamma."""
    rows = []
    for _, r in table4[table4["group"] > 0].iterrows():
        oil = str(r["oil"])
        t = per_oil_none["temps_C"][oil]
        cases = [rig_case(oil, T, per_oil_none["gamma"], base) for T in (4.0, 2.0)]
        p = cases_power(cases, np.array([t, t]), "film")
        rows.append({"oil": oil, "oil_temp_C": t, "film_grooved_W": float(p[0]),
                     "film_smoothed_W": float(p[1]),
                     "measured_grooved_W": float(r["measured_before_W"]),
                     "measured_smoothed_W": float(r["measured_after_W"])})
    return pd.DataFrame(rows)


def _vg1000(per_oil_none: dict, base: DesignCase, table4: pd.DataFrame) -> dict:
    """VG1000 grooved: mode ``film`` at 22 degC, and the isothermal model's temperature for
    the measured power."""
    c = [rig_case("VG1000", 4.0, per_oil_none["gamma"], base)]
    meas = float(table4.loc[table4["oil"] == "VG1000", "measured_before_W"].iloc[0])
    film = float(cases_power(c, np.array([22.0]), "film")[0])
    t = brentq(lambda x: float(cases_power(c, np.array([x]), "none")[0]) - meas, 0.0, 150.0,
               xtol=1e-6)
    return {"film_W_at_22C": film, "none_temp_C": float(t), "measured_W": meas}


def film_evidence(base: DesignCase | None = None, table4: pd.DataFrame | None = None,
                  grid: tuple[float, ...] = FILM_STRENGTH_GRID,
                  walls: str | float = "isothermal-walls") -> FilmEvidence:
    """Fit the film strength s to Table 4 with the rig's heat balance (module docstring).

    Parameters
    ----------
    base : DesignCase, optional
        The rig's joint (default: the seed joint).
    table4 : DataFrame, optional
        Table 4 (default: the shipped copy).
    grid : tuple of float
        Strengths of the profile [-], in [0, 1] (default 0, 0.1, ..., 1).
    walls : str or float
        The film's wall condition: a name or w in [0, 1] [-].

    Returns
    -------
    FilmEvidence

    Raises
    ------
    SolverError
        A least-squares fit did not converge.

    References
    ----------
    Seed paper Table 4 [1]_; profile likelihood [3]_.
    """
    base = base if base is not None else seed_case()
    table4 = table4 if table4 is not None else load_table4()
    rig = _Rig(base, table4, walls)
    x, fits = np.array([0.6, 22.0, 0.2, 0.5]), []
    for s in grid:
        f = _fit(rig, float(s), x)
        fits.append(f)
        x = np.array([f.gamma, f.room_temp_C, max(f.resistance_K_W, 1e-3), 0.5])
    k = int(np.argmin([f.ssr_W2 for f in fits]))
    best = _fit(rig, None, np.array([fits[k].gamma, fits[k].room_temp_C,
                                     max(fits[k].resistance_K_W, 1e-3), fits[k].strength]))
    best = min([best, fits[k]], key=lambda f: f.ssr_W2)
    n = len(rig.meas)
    profile = pd.DataFrame([{
        "film_strength": f.strength, "gamma": f.gamma, "room_temp_C": f.room_temp_C,
        "resistance_K_per_W": f.resistance_K_W, "rms_W": f.rms_W,
        "at_bounds": ",".join(f.at_bounds),
        "delta_n_log_ssr": n * np.log(f.ssr_W2 / best.ssr_W2)} for f in fits])
    po_none = _per_oil("none", base, table4)
    return FilmEvidence(
        profile=profile, best=best, interval=_interval(profile), per_oil_none=po_none,
        per_oil_film=_per_oil("film", base, table4),
        film_at_isothermal=_film_at(po_none, base, table4), vg1000=_vg1000(po_none, base, table4),
        walls=walls)


EVIDENCE_VERDICT = ("film heating at full strength (s = 1) is not supported by Table 4: at "
                    "the isothermal fit's run temperatures it predicts 19-45 % below the "
                    "measured powers, freed per-oil temperatures fall as the loss rises, and "
                    "with the rig's heat balance s is not identified; film heating is an "
                    "option with a band (docs/thermal.md#evidence)")
"""The conclusion the evidence supports (printed under the table)."""


def evidence_lines(ev: FilmEvidence) -> list[str]:
    """The evidence as text lines (``oilgap study smoothing --film-evidence``).

    Parameters
    ----------
    ev : FilmEvidence

    Returns
    -------
    list of str
        The film mode at the isothermal temperatures, the two regressions, the profile
        over s with the balance, the best s with its interval, the verdict.
    """
    po, pf, b = ev.per_oil_none, ev.per_oil_film, ev.best
    lines = ["film heating evidence (Table 4; docs/thermal.md#evidence)",
             f"{'oil':<8}{'T_oil':>7}{'film T=4':>10}{'T=2':>8}{'measured T=4':>14}{'T=2':>8}"]
    for _, r in ev.film_at_isothermal.iterrows():
        lines.append(f"{r['oil']:<8}{r['oil_temp_C']:>7.1f}{r['film_grooved_W']:>10.1f}"
                     f"{r['film_smoothed_W']:>8.1f}{r['measured_grooved_W']:>14.1f}"
                     f"{r['measured_smoothed_W']:>8.1f}")
    v = ev.vg1000
    lines += [f"  (film mode at the per-oil isothermal temperatures, gamma {po['gamma']:.3f}; "
              f"VG1000 grooved at 22 degC: film {v['film_W_at_22C']:.1f} W, the isothermal "
              f"model needs {v['none_temp_C']:.1f} degC for the measured "
              f"{v['measured_W']:.1f} W)",
              f"per-oil temperatures vs total measured power (dry + viscous): isothermal "
              f"T = {po['intercept_C']:.2f} degC + {po['slope_K_W']:.3f} K/W x P "
              f"(R^2 {po['r2']:.2f}); film T = {pf['intercept_C']:.1f} degC "
              f"{pf['slope_K_W']:+.3f} K/W x P (R^2 {pf['r2']:.2f})",
              f"heat balance T_run = T0 + R (P_dry + P_visc), T0 in "
              f"[{ROOM_TEMP_BOUNDS_C[0]:g}, {ROOM_TEMP_BOUNDS_C[1]:g}] degC, R >= 0, gamma "
              f"shared, walls {ev.walls}:",
              f"{'s':>5}{'gamma':>8}{'T0 degC':>9}{'R K/W':>8}{'RMS W':>8}"
              f"{'n ln(SSR/min)':>15}  at bounds"]
    for _, r in ev.profile.iterrows():
        lines.append(f"{r['film_strength']:>5.1f}{r['gamma']:>8.3f}{r['room_temp_C']:>9.2f}"
                     f"{r['resistance_K_per_W']:>8.3f}{r['rms_W']:>8.2f}"
                     f"{r['delta_n_log_ssr']:>15.2f}  {r['at_bounds'] or '-'}")
    se = "" if b.strength_se is None else f" +- {b.strength_se:.2f} (Jacobian)"
    lo, hi = ev.interval
    lines += [f"best s = {b.strength:.2f}{se}, 95 % profile-likelihood interval "
              f"[{lo:.2f}, {hi:.2f}]; RMS {ev.row(0.0)['rms_W']:.2f} W (s = 0), "
              f"{b.rms_W:.2f} W (best), {ev.row(1.0)['rms_W']:.2f} W (s = 1); "
              f"T0 {b.room_temp_C:.2f} degC, R {b.resistance_K_W:.3f} K/W, gamma "
              f"{b.gamma:.3f}", EVIDENCE_VERDICT]
    return lines


def evidence_dict(ev: FilmEvidence) -> dict:
    """The evidence as a JSON-ready dict (``--json``): profile, best fit, interval,
    regressions, film at the isothermal temperatures, VG1000 check."""
    b = ev.best
    return {"walls": ev.walls, "room_temp_bounds_C": list(ROOM_TEMP_BOUNDS_C),
            "profile": ev.profile.to_dict("records"),
            "best": {"film_strength": b.strength, "film_strength_se": b.strength_se,
                     "gamma": b.gamma, "room_temp_C": b.room_temp_C,
                     "resistance_K_per_W": b.resistance_K_W, "rms_W": b.rms_W},
            "interval_95": list(ev.interval),
            "per_oil_none": ev.per_oil_none, "per_oil_film": ev.per_oil_film,
            "film_at_isothermal": ev.film_at_isothermal.to_dict("records"),
            "vg1000": ev.vg1000, "verdict": EVIDENCE_VERDICT}
