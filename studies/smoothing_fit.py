"""The smoothing study's fit: gamma and the rig's effective oil temperatures from Table 4.

The experiment ran at the surface in a tank (atmospheric pressure, depth 0 m)
with the seed's sine duty cycle (3000 rpm peak, 0.05 Hz) and ISO VG 150, 320,
680 and 1000 oils. Rows 1-4 of Table 4 are mean *viscous* power: the dry run
(row 0) is already subtracted (row 1 after smoothing, 25.35 W, is below the
dry 25.36 W, so it cannot include it).

Effective oil temperature
-------------------------
The oil was not at 40 degC: the paper says it heated up quickly and then held
a steady temperature. Each run's oil temperature is one steady heat balance::

    T_run = T_base[oil] + R_th * P_visc(T_run)

solved exactly (one root: P_visc falls as the oil warms). Two ways to set it:

* ``"per-oil"`` (default): one effective temperature ``T_base`` per oil, fitted,
  shared by that oil's grooved and smoothed runs (``R_th`` = 0 by default; a
  fixed ``R_th`` > 0 makes the smoothed run colder by ``R_th`` times its lower
  power).
* ``"shared"``: one ``T_base`` and one ``R_th`` for all eight runs, fitted
  (a single steady temperature-rise model for the rig).

``gamma`` (Eq. 8) is ONE model parameter for all oils; it and the temperature
parameters are fitted by nonlinear least squares
(:func:`scipy.optimize.least_squares`) to the eight measured mean powers. Each
run is a :class:`~oilgap.model.case.DesignCase` evaluated by
:func:`oilgap.studies.grid.evaluate.evaluate_arrays`.

References
----------
.. [1] Seed paper, Sec. IV and Tables 2-4 (``shared/reference/seed-paper.md``).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from importlib import resources

import numpy as np
import pandas as pd
from scipy.optimize import least_squares

from oilgap.model.case import DesignCase, OperatingPoint
from oilgap.model.case_io import seed_case
from oilgap.model.errors import InputError, SolverError, check_finite
from oilgap.model.thermal import MAX_OIL_TEMP_C, steady_temperature
from oilgap.studies.grid.evaluate import evaluate_arrays
from oilgap.studies.grid.schema import apply_params

EXPERIMENT_OILS = ("VG150", "VG320", "VG680", "VG1000")
"""ISO VG grades standing for the seed's 150/320/680/1000 cSt (at 40 degC) oils."""

RIG_DEPTH_M = 0.0
"""The rig is a tank at the surface: atmospheric pressure."""

T_GROOVED = 4.0
T_SMOOTHED = 2.0
HEATING_METHODS = ("shared", "per-oil")
PLATEAU_TOL = 0.05
"""Default criterion: the loss has stopped falling once it is within this fraction of
its value at T = 1 (the smooth-wall floor)."""


def load_table4() -> pd.DataFrame:
    """Table 4 of the seed paper as shipped in ``studies/data/seed_table4.csv`` (with source)."""
    with resources.as_file(resources.files("oilgap.studies") / "data" /
                           "seed_table4.csv") as p:
        return pd.read_csv(p)


# --------------------------------------------------------------------------- heat balance


def _at_temperatures(cases: list[DesignCase], temps_C: np.ndarray) -> np.ndarray:
    """Mean viscous power [W] of the cases at the temperatures (k per case, case fastest)."""
    k = len(temps_C) // len(cases)
    cs = [replace(c, operating=OperatingPoint(c.operating.depth_m, float(t)))
          for c, t in zip(cases * k, temps_C, strict=True)]
    return evaluate_arrays(cs)[0]["mean_power_W"]


def steady_temperatures(cases: list[DesignCase], base_temp_C, resistance_K_W: float,
                        tol_K: float = 1e-9, max_iter: int = 60
                        ) -> tuple[np.ndarray, np.ndarray]:
    """Steady oil temperature [degC] and mean viscous power [W] of every case on the rig.

    The lumped balance ``T = T_base + R_th P(T)`` of
    :func:`oilgap.model.thermal.steady_temperature`, with P the case's mean
    viscous power over its duty cycle at oil temperature T; ``T_base`` [degC]
    one for all cases or one per case, ``R_th`` [K/W] >= 0.
    """
    return steady_temperature(lambda t: _at_temperatures(cases, t), base_temp_C,
                              resistance_K_W, len(cases), tol_K, max_iter, MAX_OIL_TEMP_C)


# --------------------------------------------------------------------------- the fit


def rig_case(oil: str, roughness_T: float, gamma: float,
             base: DesignCase | None = None) -> DesignCase:
    """The joint on the rig: the given oil, roughness T and gamma, at 0 m (atmospheric)."""
    base = base if base is not None else seed_case()
    return apply_params(base, {"oil": oil, "T": roughness_T, "gamma": gamma,
                               "depth_m": RIG_DEPTH_M})


@dataclass(frozen=True)
class SmoothingFit:
    """One set of model parameters for all oils, fitted to Table 4's measured powers.

    Each run's oil temperature is ``T_run = T_base[oil] + R_th P_run``:
    method ``"per-oil"`` fits one ``T_base`` per oil with ``R_th`` held at the
    given value (default 0: an oil's grooved and smoothed runs share one
    effective temperature); ``"shared"`` fits one ``T_base`` and ``R_th`` for
    all runs. ``*_se`` are standard errors ``sqrt(diag(s^2 (J^T J)^-1))``,
    ``s^2 = SSR/(m - p)``.
    """

    method: str
    gamma: float
    gamma_se: float
    base_temp_C: dict[str, float]
    base_temp_se: dict[str, float]
    resistance_K_W: float
    resistance_se: float | None
    rms_W: float
    max_abs_W: float
    n_data: int
    n_params: int
    temps_C: dict[tuple[str, float], float] = field(default_factory=dict)
    powers_W: dict[tuple[str, float], float] = field(default_factory=dict)

    def describe(self) -> str:
        """One line: the method and its numbers."""
        if self.method == "shared":
            heat = (f"T_run = {self.base_temp_C['all']:.2f} degC + "
                    f"{self.resistance_K_W:.4f} K/W x P_run")
        else:
            heat = ("one effective temperature per oil ("
                    + ", ".join(f"{k} {v:.1f} degC" for k, v in self.base_temp_C.items())
                    + (f") + {self.resistance_K_W:g} K/W x P_run" if self.resistance_K_W
                       else ") shared by its grooved and smoothed runs"))
        return (f"{self.method}: gamma = {self.gamma:.3f} +- {self.gamma_se:.3f}; {heat}; "
                f"RMS {self.rms_W:.2f} W, max |residual| {self.max_abs_W:.2f} W "
                f"({self.n_data} data, {self.n_params} parameters)")


def _measured(table4: pd.DataFrame) -> tuple[list[tuple[str, float]], np.ndarray]:
    runs, meas = [], []
    for _, r in table4[table4["group"] > 0].iterrows():
        runs += [(str(r["oil"]), T_GROOVED), (str(r["oil"]), T_SMOOTHED)]
        meas += [r["measured_before_W"], r["measured_after_W"]]
    return runs, np.asarray(meas, dtype=float)


def fit_smoothing(method: str = "per-oil", resistance_K_W: float = 0.0,
                  base: DesignCase | None = None,
                  table4: pd.DataFrame | None = None) -> SmoothingFit:
    """Fit gamma and the run temperatures to Table 4's eight measured mean powers.

    Parameters
    ----------
    method : {"per-oil", "shared"}
        See :class:`SmoothingFit`.
    resistance_K_W : float
        ``R_th`` [K/W] held fixed by ``"per-oil"`` (ignored by ``"shared"``).
    base : DesignCase, optional
        Base case (default: the seed joint); its friction form and laminar law
        are kept, its gamma is replaced by the fitted one.
    table4 : DataFrame, optional
        Default :func:`load_table4`.

    Raises
    ------
    InputError
        Unknown method, negative ``resistance_K_W``.
    SolverError
        The least-squares fit did not converge.
    """
    if method not in HEATING_METHODS:
        raise InputError("method", method, f"allowed: {', '.join(HEATING_METHODS)}",
                         "smoothing study")
    rth_fixed = check_finite("resistance_K_W", resistance_K_W, "smoothing study")
    if rth_fixed < 0:
        raise InputError("resistance_K_W", rth_fixed, "must be >= 0", "smoothing study")
    base = base if base is not None else seed_case()
    table4 = table4 if table4 is not None else load_table4()
    runs, meas = _measured(table4)
    oils = list(dict.fromkeys(o for o, _ in runs))
    oil_idx = np.array([oils.index(o) for o, _ in runs])
    cache: dict[float, list[DesignCase]] = {}

    def cases_for(gamma: float) -> list[DesignCase]:
        if gamma not in cache:
            cache.clear()
            cache[gamma] = [rig_case(o, t, gamma, base) for o, t in runs]
        return cache[gamma]

    if method == "shared":
        x0 = np.array([0.5, 25.0, 0.2])
        lb, ub = np.array([0.0, -10.0, 0.0]), np.array([3.0, 80.0, 3.0])

        def model(x):
            return steady_temperatures(cases_for(x[0]), x[1], x[2])
    else:
        x0 = np.concatenate([[0.5], np.full(len(oils), 40.0)])
        lb = np.concatenate([[0.0], np.full(len(oils), -10.0)])
        ub = np.concatenate([[3.0], np.full(len(oils), 120.0)])

        def model(x):
            return steady_temperatures(cases_for(x[0]), x[1:][oil_idx], rth_fixed)

    sol = least_squares(lambda x: model(x)[1] - meas, x0, bounds=(lb, ub), x_scale="jac",
                        xtol=1e-10, ftol=1e-10, gtol=1e-10)
    if not sol.success:
        raise SolverError(f"least-squares fit failed: {sol.message}", str(sol.status))
    m, p = len(meas), len(x0)
    ssr = float(sol.fun @ sol.fun)
    try:
        cov = np.linalg.inv(sol.jac.T @ sol.jac) * ssr / max(m - p, 1)
        se = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    except np.linalg.LinAlgError:
        se = np.full(p, np.nan)
    temps, powers = model(sol.x)
    common = dict(rms_W=float(np.sqrt(ssr / m)), max_abs_W=float(np.max(np.abs(sol.fun))),
                  n_data=m, n_params=p,
                  temps_C={r: float(t) for r, t in zip(runs, temps, strict=True)},
                  powers_W={r: float(v) for r, v in zip(runs, powers, strict=True)})
    if method == "shared":
        return SmoothingFit(method, float(sol.x[0]), float(se[0]), {"all": float(sol.x[1])},
                            {"all": float(se[1])}, float(sol.x[2]), float(se[2]), **common)
    return SmoothingFit(method, float(sol.x[0]), float(se[0]),
                        {o: float(sol.x[1 + i]) for i, o in enumerate(oils)},
                        {o: float(se[1 + i]) for i, o in enumerate(oils)}, rth_fixed, None,
                        **common)


def run_base_temps(fit: SmoothingFit, oils: list[str]) -> np.ndarray:
    """``T_base`` [degC] of each of ``oils`` under a fit."""
    if fit.method == "shared":
        return np.full(len(oils), fit.base_temp_C["all"])
    return np.array([fit.base_temp_C[o] for o in oils])
