"""The smoothing study's fit: gamma and the rig's oil temperatures from Table 4.

The experiment ran at the surface in a tank (atmospheric pressure, depth 0 m)
with the seed's sine duty cycle (3000 rpm peak, 0.05 Hz) and ISO VG 150, 320,
680 and 1000 oils. Rows 1-4 of Table 4 are mean *viscous* power: the dry run
(row 0) is already subtracted (row 1 after smoothing, 25.35 W, is below the
dry 25.36 W, so it cannot include it).

Run temperature
---------------
The oil was not at 40 degC: the paper says it heated up quickly and then held
a steady temperature (measured on the motor coil; the values are not
published). Each run's oil temperature is one steady heat balance::

    T_run = T_base[oil] + R_th * P_visc(T_run)

solved exactly (:func:`oilgap.model.thermal.steady_temperature`; one root: P_visc
falls as the oil warms). Three ways to set it:

* ``"per-oil"`` (default): one effective temperature ``T_base`` per oil, fitted,
  shared by that oil's grooved and smoothed runs (``R_th`` = 0 by default; a
  fixed ``R_th`` > 0 makes the smoothed run colder by ``R_th`` times its lower
  power).
* ``"shared"``: one ``T_base`` and one ``R_th`` for all eight runs, fitted
  (a single steady temperature-rise model for the rig).
* ``"heat-balance"``: the rig's bulk heat balance with the film-heated loss
  (thermal mode ``full``): ``T_run = T_0 + R_th P_film(T_run)``, ``T_0`` (the oil
  temperature of a run without viscous loss: the tank plus the motor's own losses,
  which are the same in every run, 24.4-25.4 W dry) and ``R_th`` shared by all
  runs; P_film is :func:`oilgap.model.joint_loss.joint_mean_power` in mode
  ``"film"`` (the film factor at the bulk temperature).

The loss in ``per-oil`` and ``shared`` is the seed's isothermal model (thermal mode
``none``) unless ``thermal="film"`` is asked (``shared`` with the film-heated loss
is ``heat-balance``).

``gamma`` (Eq. 8) is ONE model parameter for all oils; it and the temperature
parameters are fitted by nonlinear least squares
(:func:`scipy.optimize.least_squares`) to the eight measured mean powers. Each
run is a :class:`~oilgap.model.case.DesignCase` whose loss is
:func:`oilgap.model.joint_loss.joint_mean_power`. Besides the powers, each fit
reports the error of the four reductions (model change after - before against
Table 4's printed change), the measure the paper's own model is judged by.

References
----------
.. [1] Seed paper, Sec. IV and Tables 2-4 (``shared/reference/seed-paper.md``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from importlib import resources

import numpy as np
import pandas as pd
from scipy.optimize import least_squares

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, SolverError, check_finite
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import joint_mean_power
from oilgap.model.regions import Region, joint_regions
from oilgap.model.thermal import MAX_OIL_TEMP_C, steady_temperature
from oilgap.model.thermal_modes import ThermalMode
from oilgap.studies.grid.schema import apply_params

EXPERIMENT_OILS = ("VG150", "VG320", "VG680", "VG1000")
"""ISO VG grades standing for the seed's 150/320/680/1000 cSt (at 40 degC) oils."""

RIG_DEPTH_M = 0.0
"""The rig is a tank at the surface: atmospheric pressure."""

T_GROOVED = 4.0
T_SMOOTHED = 2.0
HEATING_METHODS = ("per-oil", "shared", "heat-balance")
"""How the runs' oil temperatures are set (module docstring)."""
FIT_THERMAL_MODES = ("none", "film", "full")
"""Thermal modes of a fit: the loss isothermal (``none``) or film-heated (``film``) at
the fitted temperatures; ``full`` is the ``heat-balance`` method."""
DEFAULT_METHOD = "per-oil"
"""The study's default: :func:`fit_comparison` shows the heat balance does not beat it."""
NEGLIGIBLE_RESISTANCE_K_W = 1e-6
"""R_th below this is taken as 0 [K/W]: the balance's rise R_th P < 1e-3 K, far below
anything the fit resolves (and the bracket of the fixed point is then a rounding)."""
MAX_RESISTANCE_K_W = 3.0
"""Largest fixed R_th of the per-oil fit [K/W], the shared fits' bound too: the runs'
25-110 W would heat the oil by 75-330 K, towards the 250 degC cap of the balance (the
seed rig's shared fit gives 0.21 K/W). Within it, a fit that ends on the bounds of its
parameters is reported as failed (:func:`fit_smoothing`)."""

RESISTANCE_REASON = ("the runs' 25-110 W would heat the oil by 75-330 K, towards the "
                     "balance's 250 degC cap (the seed rig's fitted R_th is 0.21 K/W)")
PLATEAU_TOL = 0.05
"""Default criterion: the loss has stopped falling once it is within this fraction of
its value at T = 1 (the smooth-wall floor)."""


def load_table4() -> pd.DataFrame:
    """Table 4 of the seed paper as shipped in ``studies/data/seed_table4.csv`` (with source)."""
    with resources.as_file(resources.files("oilgap.studies") / "data" /
                           "seed_table4.csv") as p:
        return pd.read_csv(p)


def resolve_fit_mode(method: str | None, thermal: str | None) -> tuple[str, str, bool]:
    """(method, thermal mode, whether the mode is the default: not chosen) of a fit.

    ``method`` None: ``heat-balance`` for ``thermal="full"``, else :data:`DEFAULT_METHOD`.
    ``thermal`` None: ``full`` for ``heat-balance``, else ``none``. ``shared`` with
    ``film`` is ``heat-balance`` (``full``).

    Raises
    ------
    InputError
        An unknown method or mode; ``per-oil`` with ``full`` (per-oil temperatures are
        fitted, not balanced); ``heat-balance`` with ``none`` (use ``shared``).
    """
    if method is not None and method not in HEATING_METHODS:
        raise InputError("method", method, f"one of {', '.join(HEATING_METHODS)}",
                         "smoothing study")
    if thermal is not None and thermal not in FIT_THERMAL_MODES:
        raise InputError("thermal", thermal, f"one of {', '.join(FIT_THERMAL_MODES)}",
                         "smoothing study")
    default = thermal is None and method != "heat-balance"
    if method is None:
        method = "heat-balance" if thermal == ThermalMode.FULL else DEFAULT_METHOD
    if method == "shared" and thermal in (ThermalMode.FILM, ThermalMode.FULL):
        method = "heat-balance"
    if method == "heat-balance":
        if thermal == ThermalMode.NONE:
            raise InputError("thermal", thermal, "'film' or 'full': the heat-balance fit "
                             "uses the film-heated loss (method 'shared' is the isothermal "
                             "balance)", "smoothing study")
        return method, "full", default
    if thermal == ThermalMode.FULL:
        raise InputError("thermal", thermal, "'none' or 'film' with the per-oil method "
                         "(full, the rig's heat balance, is method 'heat-balance')",
                         "smoothing study")
    return method, thermal or "none", default


def check_fixed_resistance(method: str | None, thermal: str | None, resistance_K_W: float,
                           names: tuple[str, str] = ("resistance_K_W", "method")) -> None:
    """A fixed R_th [K/W] is an input of the per-oil method only: with a method that fits
    R_th itself (``shared``, ``heat-balance``, chosen or implied by ``thermal="full"``)
    it would have no effect, and is refused naming both (``names``: the spellings of R_th
    and of the method in the message).

    Raises
    ------
    InputError
        ``resistance_K_W`` != 0 with a method other than per-oil.
    """
    resolved, _, _ = resolve_fit_mode(method, thermal)
    if resistance_K_W and resolved != "per-oil":
        how = f"{names[1]} {method!r}" if method else f"thermal {thermal!r} (method {resolved!r})"
        raise InputError(names[0], resistance_K_W, f"only with {names[1]} 'per-oil': under "
                         f"{how} R_th is fitted, the value would have no effect",
                         "smoothing study")


def loss_mode(thermal: str) -> str:
    """The mode of :func:`~oilgap.model.joint_loss.joint_mean_power` for a fit's thermal
    mode: ``none`` stays, ``film`` and ``full`` use the film factor at the run temperature."""
    return "none" if thermal == ThermalMode.NONE else "film"


# --------------------------------------------------------------------------- heat balance


def _stacked(cases: list[DesignCase], idx: list[int], k: int) -> list[Region]:
    """The regions of ``cases[idx]``, each with R, delta, L, T of shape (k len(idx), 1)."""
    geos = [joint_regions(cases[i]) for i in idx]
    return [Region(geos[0][r].name, *(np.tile([getattr(g[r], a) for g in geos], k)[:, None]
                                      for a in ("radius_m", "gap_m", "length_m",
                                                "roughness_T")))
            for r in range(len(geos[0]))]


def stacked_power_function(cases: list[DesignCase], evaluate, key=None):
    """``power_at(temps)`` over the cases (k temperatures per case, case fastest): the
    cases that share ``key(case)`` go in one ``evaluate(case, temps_C, depth_m, regions)``
    call on their stacked regions (built once per k). The skeleton of
    :func:`power_function` and the film evidence's strength-scaled power."""
    key = key or (lambda c: (c.oil, c.friction, id(c.duty_cycle), c.thermal,
                             c.region2 is None))
    groups: dict[tuple, list[int]] = {}
    for i, c in enumerate(cases):
        groups.setdefault(key(c), []).append(i)
    stacks: dict[int, list] = {}

    def power_at(temps_C) -> np.ndarray:
        t = np.asarray(temps_C, dtype=float).reshape(-1, len(cases))
        k = t.shape[0]
        if k not in stacks:
            stacks[k] = [(idx, _stacked(cases, idx, k),
                          np.tile([cases[i].operating.depth_m for i in idx], k))
                         for idx in groups.values()]
        out = np.empty_like(t)
        for idx, regions, depth in stacks[k]:
            p = evaluate(cases[idx[0]], t[:, idx].ravel(), depth, regions)
            out[:, idx] = np.asarray(p, dtype=float).reshape(k, len(idx))
        return out.ravel()
    return power_at


def power_function(cases: list[DesignCase], mode: str = "none"):
    """``power_at(temps)``: mean viscous power [W] of the cases at temperatures [degC]
    (k per case, case fastest), :func:`~oilgap.model.joint_loss.joint_mean_power` in
    ``mode`` (``none`` or ``film``). Cases sharing an oil, a friction law, a duty cycle
    and a heat path go in one call on their stacked regions (built once per k)."""
    return stacked_power_function(
        cases, lambda c, t, depth, regions: joint_mean_power(c, t, mode, depth, regions))


def cases_power(cases: list[DesignCase], temps_C: np.ndarray, mode: str = "none"
                ) -> np.ndarray:
    """Mean viscous power [W] of the cases at the temperatures (:func:`power_function`)."""
    return power_function(cases, mode)(temps_C)


def steady_temperatures(cases: list[DesignCase], base_temp_C, resistance_K_W: float,
                        tol_K: float = 1e-9, max_iter: int = 60, thermal: str = "none"
                        ) -> tuple[np.ndarray, np.ndarray]:
    """Steady oil temperature [degC] and mean viscous power [W] of every case on the rig.

    The lumped balance ``T = T_base + R_th P(T)`` of
    :func:`oilgap.model.thermal.steady_temperature`, with P the case's mean
    viscous power over its duty cycle at oil temperature T (isothermal for
    ``thermal="none"``, film-heated for ``"film"``/``"full"``); ``T_base`` [degC]
    one for all cases or one per case, ``R_th`` [K/W] >= 0 (below
    :data:`NEGLIGIBLE_RESISTANCE_K_W`: 0).
    """
    mode = loss_mode(thermal)
    rth = float(resistance_K_W)
    rth = 0.0 if 0.0 <= rth < NEGLIGIBLE_RESISTANCE_K_W else rth
    return steady_temperature(power_function(cases, mode), base_temp_C, rth, len(cases),
                              tol_K, max_iter, MAX_OIL_TEMP_C)


# --------------------------------------------------------------------------- the fit


def rig_case(oil: str, roughness_T: float, gamma: float,
             base: DesignCase | None = None) -> DesignCase:
    """The joint on the rig: the given oil, roughness T and gamma, at 0 m (atmospheric)."""
    base = base if base is not None else seed_case()
    return apply_params(base, {"oil": oil, "T": roughness_T, "gamma": gamma,
                               "depth_m": RIG_DEPTH_M})


@dataclass(frozen=True, kw_only=True)
class SmoothingFit:
    """One set of model parameters for all oils, fitted to Table 4's measured powers.

    Each run's oil temperature is ``T_run = T_base[oil] + R_th P_run``:
    method ``"per-oil"`` fits one ``T_base`` per oil with ``R_th`` held at the
    given value (default 0: an oil's grooved and smoothed runs share one
    effective temperature); ``"shared"`` fits one ``T_base`` and ``R_th`` for
    all runs; ``"heat-balance"`` is ``"shared"`` with the film-heated loss
    (``T_base`` is then ``T_0``, key ``"all"``). ``*_se`` are standard errors
    ``sqrt(diag(s^2 (J^T J)^-1))``, ``s^2 = SSR/(m - p)``. ``rms_W`` and
    ``max_abs_W`` are over the measured powers, ``reduction_*`` over the
    reductions (model after - before against Table 4's printed change).
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
    thermal_mode: str = "none"
    reduction_rms_W: float = float("nan")
    reduction_max_abs_W: float = float("nan")

    @property
    def loss_mode(self) -> str:
        """The loss at the run temperatures: ``none`` (isothermal) or ``film``."""
        return loss_mode(self.thermal_mode)

    @property
    def label(self) -> str:
        """Method and thermal mode, e.g. ``per-oil/none``."""
        return f"{self.method}/{self.thermal_mode}"

    def describe(self) -> str:
        """One line: the method and its numbers."""
        if self.method in ("shared", "heat-balance"):
            loss = "film-heated loss, " if self.method == "heat-balance" else ""
            bound = " (at its bound 0)" if self.resistance_K_W == 0.0 else ""
            heat = (f"{loss}T_run = {self.base_temp_C['all']:.2f} degC + "
                    f"{self.resistance_K_W:.4f} K/W{bound} x P_run")
        else:
            loss = "film-heated loss at " if self.thermal_mode == ThermalMode.FILM else ""
            heat = (loss + "one effective temperature per oil ("
                    + ", ".join(f"{k} {v:.1f} degC" for k, v in self.base_temp_C.items())
                    + (f") + {self.resistance_K_W:g} K/W x P_run" if self.resistance_K_W
                       else ") shared by its grooved and smoothed runs"))
        return (f"{self.method}: gamma = {self.gamma:.3f} +- {self.gamma_se:.3f}; {heat}; "
                f"RMS {self.rms_W:.2f} W, max |residual| {self.max_abs_W:.2f} W "
                f"({self.n_data} data, {self.n_params} parameters)")


def measured_runs(table4: pd.DataFrame) -> tuple[list[tuple[str, float]], np.ndarray]:
    """The runs (oil, T) of Table 4 (grooved, smoothed per oil) and their measured powers [W]."""
    runs, meas = [], []
    for _, r in table4[table4["group"] > 0].iterrows():
        runs += [(str(r["oil"]), T_GROOVED), (str(r["oil"]), T_SMOOTHED)]
        meas += [r["measured_before_W"], r["measured_after_W"]]
    return runs, np.asarray(meas, dtype=float)


def reduction_errors(powers_W: np.ndarray, table4: pd.DataFrame) -> np.ndarray:
    """Model reduction minus measured reduction [W], one per oil of Table 4 (rows > 0).

    ``powers_W`` are the runs' powers in :func:`measured_runs`'s order (grooved, smoothed per
    oil); the model's reduction is smoothed - grooved, the measured one Table 4's
    printed change (VG680 as printed, -22.25 W).
    """
    p = np.asarray(powers_W, dtype=float)
    change = table4.loc[table4["group"] > 0, "measured_change_W"].to_numpy(dtype=float)
    return (p[1::2] - p[0::2]) - change


SHARED_STEPS = (1e-6, 1e-5, 1e-5)
"""Forward-difference steps of the shared fits' Jacobian: gamma [-], T_base [K], R_th
[K/W] (absolute, so that R_th at its bound 0 is stepped beyond
:data:`NEGLIGIBLE_RESISTANCE_K_W`)."""


class _Residual:
    """Residuals ``P(x) - measured`` [W], remembering the last evaluation (the Jacobian's
    base point)."""

    def __init__(self, model, meas: np.ndarray):
        self.model, self.meas, self.last = model, meas, (None, None)

    def __call__(self, x: np.ndarray) -> np.ndarray:
        if self.last[0] is None or not np.array_equal(self.last[0], x):
            self.last = (np.array(x, dtype=float), self.model(x)[1] - self.meas)
        return self.last[1]

    def jacobian(self, steps, lb: np.ndarray, ub: np.ndarray):
        """Forward differences with absolute ``steps``, backward where a step would
        leave the bounds."""
        def jac(x: np.ndarray) -> np.ndarray:
            f0 = self(x)
            cols = []
            for i, h in enumerate(steps):
                h = h if x[i] + h <= ub[i] else -h
                xi = np.array(x, dtype=float)
                xi[i] = max(xi[i] + h, lb[i])
                cols.append((self.model(xi)[1] - self.meas - f0) / (xi[i] - x[i]))
            return np.column_stack(cols)
        return jac


def _parameterisation(method: str, thermal: str, n_oils: int, oil_idx: np.ndarray,
                      rth_fixed: float, cases_for):
    """(x0, lower, upper, model): start, bounds and ``model(x) -> (temps, powers)``;
    x = [gamma, T_base (one or per oil), R_th (shared methods)]."""
    if method == "per-oil":
        x0 = np.concatenate([[0.5], np.full(n_oils, 40.0)])
        lb = np.concatenate([[0.0], np.full(n_oils, -10.0)])
        ub = np.concatenate([[3.0], np.full(n_oils, 120.0)])

        def model(x):
            return steady_temperatures(cases_for(x[0]), x[1:][oil_idx], rth_fixed,
                                       thermal=thermal)
    else:
        x0 = np.array([0.5, 25.0, 0.2])
        lb, ub = np.array([0.0, -10.0, 0.0]), np.array([3.0, 80.0, 3.0])

        def model(x):
            return steady_temperatures(cases_for(x[0]), x[1], x[2], thermal=thermal)
    return x0, lb, ub, model


def fit_smoothing(method: str | None = "per-oil", resistance_K_W: float = 0.0,
                  base: DesignCase | None = None, table4: pd.DataFrame | None = None,
                  thermal: str | None = None, x0=None) -> SmoothingFit:
    """Fit gamma and the run temperatures to Table 4's eight measured mean powers.

    Parameters
    ----------
    method : {"per-oil", "shared", "heat-balance"} or None
        See :class:`SmoothingFit` and :func:`resolve_fit_mode` (None: the default).
    resistance_K_W : float
        ``R_th`` [K/W] held fixed by ``"per-oil"`` (ignored by the others).
    base : DesignCase, optional
        Base case (default: the seed joint); its friction form and laminar law
        are kept, its gamma is replaced by the fitted one.
    table4 : DataFrame, optional
        Default :func:`load_table4`.
    thermal : {"none", "film", "full"} or None
        The loss at the run temperatures (:func:`resolve_fit_mode`).
    x0 : array, optional
        Start [gamma, T_base..., R_th] (default: 0.5, 40 degC per oil or 25 degC
        shared, 0.2 K/W).

    Raises
    ------
    InputError
        Unknown method or mode, ``resistance_K_W`` outside [0,
        :data:`MAX_RESISTANCE_K_W`].
    SolverError
        The least-squares fit did not converge, or did not identify its parameters
        (a singular Jacobian: no standard error).
    """
    method, thermal, _ = resolve_fit_mode(method, thermal)
    rth_fixed = check_finite("resistance_K_W", resistance_K_W, "smoothing study")
    if not 0.0 <= rth_fixed <= MAX_RESISTANCE_K_W:
        raise InputError("R_th (--r-th-k-per-w)", rth_fixed, f"allowed range is [0, "
                         f"{MAX_RESISTANCE_K_W:g}] K/W: {RESISTANCE_REASON}", "smoothing study")
    base = base if base is not None else seed_case()
    table4 = table4 if table4 is not None else load_table4()
    runs, meas = measured_runs(table4)
    oils = list(dict.fromkeys(o for o, _ in runs))
    cache: dict[float, list[DesignCase]] = {}

    def cases_for(gamma: float) -> list[DesignCase]:
        if gamma not in cache:
            cache.clear()
            cache[gamma] = [rig_case(o, t, gamma, base) for o, t in runs]
        return cache[gamma]

    start, lb, ub, model = _parameterisation(
        method, thermal, len(oils), np.array([oils.index(o) for o, _ in runs]), rth_fixed,
        cases_for)
    start = start if x0 is None else np.clip(np.asarray(x0, dtype=float), lb, ub)
    fun = _Residual(model, meas)
    jac = "2-point" if method == "per-oil" else fun.jacobian(SHARED_STEPS, lb, ub)
    sol = least_squares(fun, start, jac=jac, bounds=(lb, ub), x_scale="jac", xtol=1e-10,
                        ftol=1e-10, gtol=1e-10)
    if not sol.success:
        raise SolverError(f"least-squares fit failed: {sol.message}", str(sol.status))
    return _result(method, thermal, sol, model, runs, meas, oils, rth_fixed, table4)


def _result(method, thermal, sol, model, runs, meas, oils, rth_fixed, table4) -> SmoothingFit:
    """The :class:`SmoothingFit` of a least-squares solution."""
    m, p = len(meas), len(sol.x)
    ssr = float(sol.fun @ sol.fun)
    try:
        cov = np.linalg.inv(sol.jac.T @ sol.jac) * ssr / max(m - p, 1)
        se = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    except np.linalg.LinAlgError:
        se = np.full(p, np.nan)
    _refuse_unidentified(method, thermal, sol, se, rth_fixed)
    temps, powers = model(sol.x)
    red = reduction_errors(powers, table4)
    common = dict(rms_W=float(np.sqrt(ssr / m)), max_abs_W=float(np.max(np.abs(sol.fun))),
                  n_data=m, n_params=p,
                  temps_C={r: float(t) for r, t in zip(runs, temps, strict=True)},
                  powers_W={r: float(v) for r, v in zip(runs, powers, strict=True)},
                  thermal_mode=thermal, reduction_rms_W=float(np.sqrt(np.mean(red ** 2))),
                  reduction_max_abs_W=float(np.max(np.abs(red))))
    if method != "per-oil":
        rth = float(sol.x[2]) if sol.x[2] >= NEGLIGIBLE_RESISTANCE_K_W else 0.0
        return SmoothingFit(
            method=method, gamma=float(sol.x[0]), gamma_se=float(se[0]),
            base_temp_C={"all": float(sol.x[1])}, base_temp_se={"all": float(se[1])},
            resistance_K_W=rth, resistance_se=float(se[2]), **common)
    return SmoothingFit(
        method=method, gamma=float(sol.x[0]), gamma_se=float(se[0]),
        base_temp_C={o: float(sol.x[1 + i]) for i, o in enumerate(oils)},
        base_temp_se={o: float(se[1 + i]) for i, o in enumerate(oils)}, resistance_K_W=rth_fixed,
        resistance_se=None, **common)


def _refuse_unidentified(method, thermal, sol, se, rth_fixed) -> None:
    """A fit whose parameters the data do not identify is a failure, not a result: no
    finite standard error (singular Jacobian), or a parameter on the bounds of the fit
    (R_th at 0 aside, which the shared fits report as such)."""
    note = f" with R_th = {rth_fixed:g} K/W" if method == "per-oil" and rth_fixed else ""
    if not (np.all(np.isfinite(se)) and np.all(np.isfinite(sol.x))):
        raise SolverError(f"the {method}/{thermal} fit of Table 4{note} did not identify its "
                          "parameters (singular Jacobian: no standard error), so it gives no "
                          "result", "not identified")
    names = ["gamma"] + (["T_base"] * (len(sol.x) - 1) if method == "per-oil"
                         else ["T_base", "R_th"])
    pinned = [n for n, a in zip(names, sol.active_mask, strict=True)
              if a != 0 and not (n == "R_th" and a < 0)]
    if pinned:
        raise SolverError(f"the {method}/{thermal} fit of Table 4{note} ended on the bounds "
                          f"of {', '.join(dict.fromkeys(pinned))}: the data are not explained "
                          "within them, so it gives no result", "at bounds")


def run_base_temps(fit: SmoothingFit, oils: list[str]) -> np.ndarray:
    """``T_base`` [degC] of each of ``oils`` under a fit."""
    if fit.method != "per-oil":
        return np.full(len(oils), fit.base_temp_C["all"])
    return np.array([fit.base_temp_C[o] for o in oils])
