"""Close the loop with measured data: calibrate, find the missing effect, report.

:class:`LoopEstimator` is a scikit-learn style estimator (``fit(data)``,
``predict(data)``, learned attributes ending in ``_``). What ``fit`` does:

1. Validate and load (:mod:`oilgap.studies.measured_data`), fit the oil-free
   baseline of each T and take it away (or read ``viscous_power_W``), get nu and
   rho per sample from each oil's Walther line and density law.
2. The seed's Table 3 comparison. *Without T*: the case's published friction
   law (Eq. 6) with gamma = 0, nothing fitted. *With T*: Eq. 8,
   ``C_m = C (delta/R)^alpha Re^beta T^gamma`` (``FrictionLaw(form="power-law")``)
   for both regions (region 2 at T = 1), fitted by nonlinear least squares on
   the power in W (``scipy.optimize.least_squares``). Why not a linear fit of
   ln C_m: the noise is additive in W (a power meter), samples near zero speed
   carry no information about C_m and can be negative, and with two regions
   the power is a sum of two power laws, not linear in the parameters in any
   log space. Which parameters are free is decided from the data (gamma needs
   two values of T, alpha two region-1 gap ratios, beta a spread of Re) and
   reported with the Jacobian's parameter correlations.
3. Residual analysis of the calibrated model: binned structure against speed,
   acceleration, temperature, viscosity and time, autocorrelation, and the
   noise level from successive differences.
4. Effect search over the library of :mod:`oilgap.model.effects`: each effect
   is a regression feature. Features that the data cannot tell apart from the
   calibration (R^2 > 0.99 on its Jacobian) or that vanish on these data are set
   aside and reported. Sparse regression: the non-negative lasso path (cvxpy;
   sign constraints where physics demands them; the calibration's own
   directions unpenalised) ranks the effects; leave-one-run-out
   cross-validation judges supports. An effect is accepted only if it lowers the
   held-out RMSE by the margin (default 10 %) *and* explains at least half of
   the held-out structure above the noise; otherwise the answer is "no missing
   effect found", and structure left over is reported with what it correlates
   with.
5. Refit with the accepted effects (nonlinear, all parameters), errors before
   and after in-sample and on held-out runs, each coefficient with a
   jackknife-over-runs 95 % confidence interval.

References
----------
.. [1] Seed paper, Eqs. 5-9 and Table 3 (``shared/reference/seed-paper.md``).
.. [2] R. Tibshirani, "Regression shrinkage and selection via the lasso",
   J. R. Stat. Soc. B 58:267-288, 1996; relaxed lasso: N. Meinshausen,
   Comput. Stat. Data Anal. 52:374-393, 2007.
.. [3] B. Efron, C. Stein, "The jackknife estimate of variance", Ann. Stat.
   9:586-596, 1981 (delete-one-group jackknife).
.. [4] J. von Neumann, "Distribution of the ratio of the mean square successive
   difference to the variance", Ann. Math. Stat. 12:367-395, 1941.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace
from pathlib import Path

import cvxpy as cp
import numpy as np
import pandas as pd
from scipy import stats
from scipy.linalg import solve_triangular
from scipy.optimize import least_squares

from oilgap.model.case import DesignCase
from oilgap.model.case_io import seed_case
from oilgap.model.effects import (
    CONFOUNDED_FORMS,
    EFFECTS,
    EffectContext,
    RegionState,
    couette_shear_rate,
    cross_viscosity_ratio,
    first_order_lag,
)
from oilgap.model.errors import InputError, SolverError
from oilgap.model.measured_data import (
    TEMP_STEP_K,
    MeasuredData,
    Samples,
    load_measured,
    oil_samples,
    validate,
)
from oilgap.model.oils import Oil
from oilgap.model.skin_friction import BILGEN_BOULOS_ALPHA, FrictionLaw
from oilgap.model.taylor_couette import couette_reynolds, taylor_number
from oilgap.model.units import m2_s_to_cst
from oilgap.model.viscous_loss import clearance_power

from .baseline import BaselineFit, fit_baselines

BASE_PARAMS = ("C", "alpha", "beta", "gamma")
DEFAULT_MARGIN = 0.10
"""Relative fall of the held-out RMSE an effect must bring [-]."""
DEFAULT_MIN_EXPLAINED = 0.5
"""Share of the held-out structure above noise an accepted effect must explain [-]."""
CONFOUNDED_R2 = 1.0 - 1e-6
"""A feature whose R^2 on the calibration's Jacobian exceeds this is numerically one of its
directions and is set aside; below it, cross-validation decides."""
STRUCTURE_FRACTION = 0.2
"""Residual with more than this share of its variance above the noise is 'structured'."""
RESIDUAL_VARIABLES = ("speed_rpm", "abs_speed_rpm", "accel_rad_s2", "temp_C", "nu_cSt",
                      "time_s")
ACF_LAGS = (1, 2, 5, 10, 25, 50)


# --------------------------------------------------------------------------- geometry


@dataclass(frozen=True)
class RigGeometry:
    """Clearance geometry of a rig [m]; region 2 (bearing annulus) optional."""

    radius1_m: float
    gap1_m: float
    length1_m: float
    region2: tuple[float, float, float] | None
    disc_radii_m: tuple[float, float]

    @classmethod
    def from_case(cls, case: DesignCase) -> RigGeometry:
        """Geometry of a design case (region 1 radius T2, gap T3 - T2; region 2 if any)."""
        r1 = case.region1
        r2 = case.region2
        reg2 = None if r2 is None else (r2.radius, r2.gap, r2.length)
        return cls(r1.radius, r1.gap, r1.length, reg2, (r1.radius, case.motor.shaft_bore_radius))

    @property
    def bearing_pitch_diameter_m(self) -> float | None:
        """Pitch diameter of the bearing balls, ``2 R2 + delta2`` [m] (None without region 2)."""
        return None if self.region2 is None else 2.0 * self.region2[0] + self.region2[1]


def region_powers(s: Samples, geom: RigGeometry, law: FrictionLaw, nu=None, rho=None
                  ) -> list[np.ndarray]:
    """Viscous power [W] per region and sample: ``clearance_power`` of the model.

    Region 1 with each sample's T and gap, region 2 (if the rig has one) with T = 1.
    """
    nu = s.nu_m2_s if nu is None else nu
    rho = s.density_kg_m3 if rho is None else rho
    out = [clearance_power(s.omega, nu, rho, geom.radius1_m, s.gap1_m, geom.length1_m, law,
                           s.roughness_T)]
    if geom.region2 is not None:
        R, gap, L = geom.region2
        out.append(clearance_power(s.omega, nu, rho, R, gap, L, law, 1.0))
    return out


def effect_context(s: Samples, geom: RigGeometry, law: FrictionLaw) -> EffectContext:
    """Per-sample context of the effect features under the friction law ``law``."""
    pw = region_powers(s, geom, law)
    states = _region_states(s, geom, pw)
    # dP/domega by central difference of the model; dP/dT through nu(T), rho(T)
    h = 1e-4
    sp = replace(s, omega=s.omega * (1 + h))
    sm = replace(s, omega=s.omega * (1 - h))
    w = np.where(np.abs(s.omega) > 0, s.omega, 1.0)
    dP_dw = (sum(region_powers(sp, geom, law)) - sum(region_powers(sm, geom, law))) / (2 * h * w)
    dP_dT = np.full(s.n, np.nan)
    ok = np.isfinite(s.nu_pm[0]) & np.isfinite(s.nu_pm[1])
    if ok.any():
        nu_m, nu_p = (np.where(ok, x, s.nu_m2_s) for x in s.nu_pm)
        rho_m, rho_p = (np.where(ok, x, s.density_kg_m3) for x in s.rho_pm)
        d = (sum(region_powers(s, geom, law, nu_p, rho_p))
             - sum(region_powers(s, geom, law, nu_m, rho_m))) / (2 * TEMP_STEP_K)
        dP_dT = np.where(ok, d, np.nan)
    dP_dt = dP_dw * s.domega_dt + np.nan_to_num(dP_dT) * s.dtemp_dt
    return EffectContext(s.omega, s.domega_dt, s.nu_m2_s, s.density_kg_m3, s.dtemp_dt, dP_dt,
                         dP_dT, tuple(states), geom.disc_radii_m, geom.bearing_pitch_diameter_m)


# --------------------------------------------------------------------------- base model


@dataclass(frozen=True)
class BaseSpec:
    """Which Eq. 8 parameters are fitted and the values of the fixed ones."""

    free: tuple[str, ...]
    fixed: dict

    def law(self, x: np.ndarray) -> FrictionLaw:
        """Friction law at the free-parameter vector x (C enters as ln C)."""
        v = dict(self.fixed)
        for name, val in zip(self.free, x, strict=True):
            v[name] = math.exp(val) if name == "C" else float(val)
        return FrictionLaw(form="power-law", C=v["C"], alpha=v["alpha"], beta=v["beta"],
                           gamma=v["gamma"])

    def values(self, x: np.ndarray) -> dict:
        """All four parameters by name."""
        law = self.law(x)
        return {"C": law.C, "alpha": law.alpha, "beta": law.beta, "gamma": law.gamma}

    def start(self, values: dict) -> np.ndarray:
        """Free-parameter vector from parameter values."""
        return np.array([math.log(values[k]) if k == "C" else values[k] for k in self.free])


EXACT_FORMS = ("thermal_lag", "sensor_delay", "shear_thinning")
"""Effects refitted with their full nonlinear form (the regression feature is its first
order): the first-order lag of the oil temperature, the time shift of the power
record, the Cross viscosity ratio 1/(1 + lambda^2 gamma_dot^2)."""


class _Evaluator:
    """Model power of a sample set for any friction law and effect coefficients.

    ``power(law, coefs)``: Eq. 8 per region through ``clearance_power``, with
    the effects of ``coefs`` (name -> coefficient in the library's unit):
    thermal lag moves the oil temperature the viscosity follows (the oil's
    Walther line and density law are evaluated there), shear thinning scales
    each region by the Cross ratio, sensor delay shifts the whole record in
    time, and the others add their library term.
    """

    def __init__(self, s: Samples, geom: RigGeometry, oils: dict[str, Oil]):
        from oilgap.model.oils import normalize_oil_name

        self.s = s
        self.geom = geom
        self.runs = [np.nonzero(s.run_code == c)[0] for c in np.unique(s.run_code)]
        law_rows = np.isfinite(s.nu_pm[0])
        uniq, inv = np.unique(s.oil.astype(str), return_inverse=True)
        keys = np.array([normalize_oil_name(o) for o in uniq])[inv]
        self.oil_groups = [(np.nonzero((keys == k) & law_rows)[0], oils[k])
                           for k in np.unique(keys[law_rows]) if k in oils]
        self._static: dict[str, np.ndarray] = {}

    def subset(self, mask: np.ndarray) -> _Evaluator:
        """Evaluator of the samples where ``mask`` holds."""
        ev = _Evaluator.__new__(_Evaluator)
        s = self.s.subset(mask)
        ev.s, ev.geom = s, self.geom
        ev.runs = [np.nonzero(s.run_code == c)[0] for c in np.unique(s.run_code)]
        pos = np.cumsum(mask) - 1
        ev.oil_groups = [(pos[idx[mask[idx]]], oil) for idx, oil in self.oil_groups]
        ev._static = {k: v[mask] for k, v in self._static.items()}
        return ev

    def _oil_at(self, temp_C: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        from oilgap.model.units import celsius_to_kelvin

        nu = self.s.nu_m2_s.copy()
        rho = self.s.density_kg_m3.copy()
        for idx, oil in self.oil_groups:
            nu[idx], _, rho[idx] = oil.properties(celsius_to_kelvin(temp_C[idx]), 0.0)
        return nu, rho

    def lagged_temperature(self, tau_s: float) -> np.ndarray:
        """Oil temperature [degC] lagging (tau > 0) or leading (tau < 0) the measured one."""
        s = self.s
        if tau_s < 0:
            return s.temp_C - tau_s * s.dtemp_dt
        out = np.empty(s.n)
        for idx in self.runs:
            out[idx] = first_order_lag(s.time_s[idx], s.temp_C[idx], tau_s)
        return out

    def static_feature(self, name: str) -> np.ndarray:
        """Feature of an effect that does not depend on the friction law (cached)."""
        if name not in self._static:
            ctx = self.context(FrictionLaw(form="power-law"), derivatives=False)
            self._static[name] = EFFECTS[name].feature_values(ctx)
        return self._static[name]

    def context(self, law: FrictionLaw, derivatives: bool = True, s: Samples | None = None
                ) -> EffectContext:
        """Effect context under ``law`` (derivative fields zero if not asked for)."""
        s = self.s if s is None else s
        if derivatives:
            return effect_context(s, self.geom, law)
        pw = region_powers(s, self.geom, law)
        return _light_context(s, self.geom, pw)

    def power(self, law: FrictionLaw, coefs: dict | None = None) -> np.ndarray:
        """Model viscous power [W] per sample."""
        coefs = coefs or {}
        s = self.s
        if coefs.get("thermal_lag", 0.0):
            nu, rho = self._oil_at(self.lagged_temperature(coefs["thermal_lag"]))
            s = replace(s, nu_m2_s=nu, density_kg_m3=rho)
        pw = region_powers(s, self.geom, law)
        ctx = _light_context(s, self.geom, pw)
        total = 0.0
        lam2 = max(0.0, coefs.get("shear_thinning", 0.0))
        for r in ctx.regions:
            ratio = cross_viscosity_ratio(couette_shear_rate(s.omega, r.radius_m, r.gap_m),
                                          math.sqrt(lam2)) if lam2 else 1.0
            total = total + r.power_W * ratio
        for name, c in coefs.items():
            if name in EXACT_FORMS or c == 0.0:
                continue
            f = EFFECTS[name].feature_values(ctx) if name == "taylor_vortex_onset" \
                else self.static_feature(name)
            total = total + c * f
        d = coefs.get("sensor_delay", 0.0)
        if d:
            out = np.empty(s.n)
            for idx in self.runs:
                t = s.time_s[idx]
                out[idx] = np.interp(t - d, t, total[idx])
            total = out
        return np.asarray(total, dtype=float) * np.ones(s.n)


def _region_states(s: Samples, geom: RigGeometry, pw: list[np.ndarray]) -> list[RegionState]:
    """Per-region state (geometry, power, Re, Ta) of the samples, powers ``pw`` given."""
    regs = [("rotor-stator", geom.radius1_m, s.gap1_m, geom.length1_m)]
    if geom.region2 is not None:
        R, gap, L = geom.region2
        regs.append(("bearing", R, np.full(s.n, gap), L))
    states = []
    for (name, R, gap, L), p in zip(regs, pw, strict=True):
        re = couette_reynolds(s.omega, R, gap, s.nu_m2_s)
        states.append(RegionState(name, R, gap, L, p, re, taylor_number(re, gap, R)))
    return states


def _light_context(s: Samples, geom: RigGeometry, pw: list[np.ndarray]) -> EffectContext:
    states = _region_states(s, geom, pw)
    z = np.zeros(s.n)
    return EffectContext(s.omega, s.domega_dt, s.nu_m2_s, s.density_kg_m3, s.dtemp_dt, z, z,
                         tuple(states), geom.disc_radii_m, geom.bearing_pitch_diameter_m)


@dataclass
class _Fit:
    x: np.ndarray
    theta: np.ndarray
    law: FrictionLaw
    pred: np.ndarray
    jac_base: np.ndarray
    jac: np.ndarray | None = None
    scale: np.ndarray | None = None
    names: tuple[str, ...] = ()
    lower: np.ndarray | None = None

    @property
    def z(self) -> np.ndarray:
        """The solver's unknowns: free Eq. 8 parameters, then scaled effect coefficients."""
        sc = np.ones(0) if self.scale is None else self.scale
        return np.concatenate([self.x, self.theta * sc])


def one_step_fold(fit: _Fit, ev: _Evaluator, spec: BaseSpec, train: np.ndarray) -> _Fit:
    """Refit without some runs by one Gauss-Newton step from the all-runs solution.

    ``dz = -(J_tr' J_tr)^-1 J_tr' r_tr`` with the all-runs Jacobian J and
    residual r restricted to the training rows (coefficients projected onto
    their bounds), then the exact model at the new parameters. The step is
    exact for a model linear in its parameters and accurate to second order
    in the change otherwise (checked against full refits in the tests).
    """
    q = len(fit.x)
    J = fit.jac[train]
    r = (fit.pred - ev.s.viscous_W)[train]
    dz, *_ = np.linalg.lstsq(J, -r, rcond=None)
    z = fit.z + dz
    lo = np.concatenate([np.full(q, -np.inf), fit.lower * fit.scale])
    z = np.maximum(z, lo)
    x = z[:q]
    theta = z[q:] / fit.scale
    coefs = dict(zip(fit.names, theta, strict=True))
    law = spec.law(x)
    return _Fit(x, theta, law, ev.power(law, coefs), fit.jac_base, None, fit.scale, fit.names,
                fit.lower)


def _base_power(s: Samples, geom: RigGeometry, law: FrictionLaw) -> np.ndarray:
    return sum(region_powers(s, geom, law))


def fit_model(ev: _Evaluator, spec: BaseSpec, x0: np.ndarray, names: tuple[str, ...] = (),
              theta0: np.ndarray | None = None, scale: np.ndarray | None = None,
              full: _Evaluator | None = None) -> _Fit:
    """Nonlinear least squares of the model (Eq. 8 + effects ``names``) to the power [W].

    Unknowns: the free Eq. 8 parameters (C as ln C) and one coefficient per
    effect, bounded below by 0 where the library says so; effect coefficients
    are scaled by ``scale`` (the RMS of their feature) for conditioning. The
    Jacobian is by central differences of the model. ``full``: evaluator on
    which the returned prediction is computed (default ``ev``).

    Raises
    ------
    SolverError
        The least-squares solver reports failure or a non-finite result.
    """
    k = len(names)
    q = len(x0)
    y = ev.s.viscous_W
    sc = np.ones(k) if scale is None else np.where(np.asarray(scale) > 0, scale, 1.0)
    lo_t = np.array([0.0 if EFFECTS[n].nonnegative else -np.inf for n in names])
    t0 = np.zeros(k) if theta0 is None else np.maximum(np.asarray(theta0, float), lo_t)

    def unpack(z):
        return z[:q], dict(zip(names, z[q:] / sc, strict=True))

    def model(z, e=ev):
        x, coefs = unpack(z)
        return e.power(spec.law(x), coefs)

    def fun(z):
        return model(z) - y

    def jac(z):
        cols = []
        for j in range(len(z)):
            h = 1e-6 * max(1.0, abs(z[j]))
            zp, zm = z.copy(), z.copy()
            zp[j] += h
            zm[j] -= h
            if j >= q and lo_t[j - q] == 0.0 and zm[j] < 0:  # one-sided at the bound
                zm[j] = z[j]
                cols.append((model(zp) - model(zm)) / h)
            else:
                cols.append((model(zp) - model(zm)) / (2 * h))
        return np.column_stack(cols)

    z0 = np.concatenate([x0, t0 * sc])
    lo = np.concatenate([np.full(q, -np.inf), lo_t * sc])
    hi = np.full(q + k, np.inf)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        res = least_squares(fun, z0, jac=jac, bounds=(lo, hi), method="trf", x_scale="jac",
                            xtol=1e-10, ftol=1e-10, gtol=1e-10, max_nfev=100)
    if res.status < 0 or not np.all(np.isfinite(res.x)):
        raise SolverError(f"calibration least squares failed: {res.message}", str(res.status))
    x, coefs = unpack(res.x)
    out = full or ev
    jfull = jac(res.x) if out is ev else None
    jb = jfull[:, :q] if jfull is not None else np.zeros((out.s.n, q))
    return _Fit(x, np.array([coefs[n] for n in names]), spec.law(x), model(res.x, out), jb,
                jfull, sc, tuple(names), lo_t)


def decide_spec(s: Samples, geom: RigGeometry, case: DesignCase) -> tuple[BaseSpec, dict]:
    """Which parameters the data identify, with the reason for each (statement dict)."""
    stmt = {"C": "identified: the scale of the loss"}
    free = ["C"]
    fixed = {"alpha": BILGEN_BOULOS_ALPHA, "beta": -1.0, "gamma": case.friction.gamma}
    Ts = sorted(set(np.round(s.roughness_T, 9)))
    if len(Ts) >= 2:
        free.append("gamma")
        stmt["gamma"] = f"identified from the runs at T = {', '.join(f'{t:g}' for t in Ts)}"
    else:
        fixed["gamma"] = 0.0 if Ts == [1.0] else case.friction.gamma
        stmt["gamma"] = (f"not identifiable: every oil run has T = {Ts[0]:g}; fixed at "
                         f"{fixed['gamma']:g} (only C T^gamma is identified)")
    ratios = sorted(set(np.round(s.gap1_m / geom.radius1_m, 6)))
    if len(ratios) >= 2:
        free.append("alpha")
        stmt["alpha"] = (f"identified from {len(ratios)} region-1 gap ratios "
                         f"{ratios[0]:.4g}..{ratios[-1]:.4g}")
    else:
        stmt["alpha"] = (f"not identifiable: one region-1 gap ratio (delta/R = {ratios[0]:.4g});"
                         f" fixed at {BILGEN_BOULOS_ALPHA:g} (Eq. 6), C absorbs (delta/R)^alpha")
    re = couette_reynolds(s.omega, geom.radius1_m, s.gap1_m, s.nu_m2_s)
    w = np.abs(s.omega) ** 2
    ok = re > 0
    lre = np.log(re[ok])
    sd = float(np.sqrt(np.average((lre - np.average(lre, weights=w[ok])) ** 2, weights=w[ok])))
    if sd >= 0.2:
        free.append("beta")
        stmt["beta"] = (f"identified from the spread of Re over the data (power-weighted sd of "
                        f"ln Re_1 = {sd:.2f}; Re_1 up to {re.max():.3g})")
    else:
        stmt["beta"] = (f"not identifiable: Re hardly varies (sd of ln Re = {sd:.2f}); fixed at "
                        "-1 (laminar)")
    order = [p for p in BASE_PARAMS if p in free]
    return BaseSpec(tuple(order), {k: v for k, v in fixed.items() if k not in order}), stmt


# --------------------------------------------------------------------------- residuals


def noise_estimate(res: np.ndarray, run_code: np.ndarray) -> float:
    """White-noise level [W] from successive differences within runs [4]:
    ``sigma^2 = sum (r_k+1 - r_k)^2 / (2 (n - runs))``."""
    same = run_code[1:] == run_code[:-1]
    d = np.diff(res)[same]
    return float(np.sqrt(np.sum(d * d) / (2.0 * max(1, len(d)))))


def _acf(res, run_code, lag):
    num = den = 0.0
    for c in np.unique(run_code):
        r = res[run_code == c]
        r = r - r.mean()
        den += float(r @ r)
        if len(r) > lag:
            num += float(r[lag:] @ r[:-lag])
    return num / den if den > 0 else 0.0


def residual_structure(res: np.ndarray, s: Samples, bins: int = 12) -> dict:
    """Structure of a residual [W]: noise, share above noise, binned means, ACF.

    For each variable in :data:`RESIDUAL_VARIABLES`: Pearson r, the correlation
    ratio eta^2 (share of the residual variance explained by the means of
    ``bins`` quantile bins) and the bin centres and means.
    """
    mse = float(np.mean(res * res))
    sig = noise_estimate(res, s.run_code)
    var = {"speed_rpm": s.speed_rpm, "abs_speed_rpm": np.abs(s.speed_rpm),
           "accel_rad_s2": s.domega_dt, "temp_C": s.temp_C, "nu_cSt": m2_s_to_cst(s.nu_m2_s),
           "time_s": s.time_s}
    out_vars = {}
    vres = float(np.var(res))
    for name, v in var.items():
        edges = np.unique(np.quantile(v, np.linspace(0, 1, bins + 1)))
        idx = np.clip(np.searchsorted(edges, v, side="right") - 1, 0, len(edges) - 2) \
            if len(edges) > 1 else np.zeros(len(v), int)
        nb = int(idx.max()) + 1
        cnt = np.bincount(idx, minlength=nb)
        mean = np.bincount(idx, weights=res, minlength=nb) / np.maximum(cnt, 1)
        cen = np.bincount(idx, weights=v, minlength=nb) / np.maximum(cnt, 1)
        eta2 = float(np.sum(cnt * (mean - res.mean()) ** 2) / (len(res) * vres)) if vres > 0 \
            else 0.0
        r = float(np.corrcoef(v, res)[0, 1]) if np.std(v) > 0 and np.std(res) > 0 else 0.0
        out_vars[name] = {"pearson_r": r, "eta2": eta2, "bin_centres": cen.tolist(),
                          "bin_means_W": mean.tolist()}
    frac = max(0.0, 1.0 - sig * sig / mse) if mse > 0 else 0.0
    return {"rmse_W": math.sqrt(mse), "noise_W": sig,
            "structured_rms_W": math.sqrt(max(0.0, mse - sig * sig)),
            "structured_fraction": frac,
            "autocorrelation": {str(k): _acf(res, s.run_code, k) for k in ACF_LAGS},
            "variables": out_vars}


def describe_structure(rs: dict) -> str:
    """One sentence on what a structured residual correlates with."""
    vs = sorted(rs["variables"].items(), key=lambda kv: -kv[1]["eta2"])
    parts = [f"{k} (eta^2 = {v['eta2']:.2f}, r = {v['pearson_r']:+.2f})" for k, v in vs[:3]
             if v["eta2"] >= 0.02]
    corr = "; correlates with " + ", ".join(parts) if parts else \
        "; no single variable explains it (eta^2 < 0.02 for all)"
    return (f"{rs['structured_rms_W']:.3g} W RMS above the noise ({rs['noise_W']:.3g} W), "
            f"{100 * rs['structured_fraction']:.0f} % of the residual variance, lag-1 "
            f"autocorrelation {rs['autocorrelation']['1']:.2f}{corr}")


# --------------------------------------------------------------------------- selection


class _Lasso:
    """Sign-constrained lasso ``min ||A x - b||^2 + pen . |x|, lo <= x <= hi`` (cvxpy).

    A and the data are fixed; ``pen`` (the penalty weights, zero on the
    calibration's own columns) is a parameter, so the path re-solves without
    recompiling. |x| is written with an epigraph variable t >= |x|.
    """

    def __init__(self, A: np.ndarray, b: np.ndarray, lo: np.ndarray, hi: np.ndarray):
        p = len(b)
        self.pen = cp.Parameter(p, nonneg=True)
        self.x = cp.Variable(p)
        t = cp.Variable(p)
        big = 1e6
        cons = [self.x >= np.clip(lo, -big, big), self.x <= np.clip(hi, -big, big),
                t >= self.x, t >= -self.x]
        self.prob = cp.Problem(cp.Minimize(cp.sum_squares(A @ self.x - b) + self.pen @ t), cons)

    def solve(self, pen: np.ndarray) -> np.ndarray:
        self.pen.value = pen
        try:
            self.prob.solve(solver=cp.CLARABEL)
        except cp.error.SolverError:
            self.prob.solve(solver=cp.SCS, eps=1e-9, max_iters=100000)
        if self.x.value is None or self.prob.status not in ("optimal", "optimal_inaccurate"):
            raise SolverError(f"sparse regression: cvxpy status {self.prob.status}")
        return np.asarray(self.x.value)


def _box_lstsq(G: np.ndarray, h: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """``min x'Gx - 2h'x`` on the box [lo, hi] (entries fixed where lo = hi).

    Unconstrained solve on the free entries first; if a bound is violated, the
    bounded-variable least squares of Stark & Parker (``scipy lsq_linear``,
    method "bvls") on the Cholesky factor. Exact for this convex problem.
    """
    from scipy.optimize import lsq_linear

    p = len(h)
    x = np.zeros(p)
    fixed = lo == hi
    x[fixed] = lo[fixed]
    f = ~fixed
    if not f.any():
        return x
    Gf = G[np.ix_(f, f)]
    ridge = 1e-10 * max(1.0, float(np.trace(Gf)) / f.sum())
    Gf = Gf + ridge * np.eye(f.sum())
    hf = h[f] - G[np.ix_(f, fixed)] @ x[fixed]
    xf = np.linalg.solve(Gf, hf)
    lf, uf = lo[f], hi[f]
    if np.all(xf >= lf - 1e-12) and np.all(xf <= uf + 1e-12):
        x[f] = xf
        return x
    L = np.linalg.cholesky(Gf)
    b = solve_triangular(L, hf, lower=True)
    res = lsq_linear(L.T, b, bounds=(lf, uf), method="bvls", tol=1e-12)
    x[f] = res.x
    return x


class _Selector:
    """Linearised sparse selection with leave-one-run-out CV on Gram matrices.

    Columns: the calibration's Jacobian (free, unpenalised), then the
    candidate columns, each scaled to unit RMS. Each candidate column belongs
    to one effect (``group``); a support holds at most one column per effect.
    ``nonneg[j]``: column j's coefficient must be >= 0.
    """

    def __init__(self, J: np.ndarray, F: np.ndarray, r: np.ndarray, run_code: np.ndarray,
                 nonneg: np.ndarray, group: np.ndarray):
        self.q = J.shape[1]
        X = np.column_stack([J, F])
        sc = np.sqrt(np.mean(X * X, axis=0))
        self.scale = np.where(sc > 0, sc, 1.0)
        X = X / self.scale
        self.k = F.shape[1]
        self.nonneg = np.asarray(nonneg, bool)
        self.group = np.asarray(group)
        self.runs = np.unique(run_code)
        self.G, self.h, self.s, self.n = {}, {}, {}, {}
        for c in self.runs:
            m = run_code == c
            self.G[c] = X[m].T @ X[m]
            self.h[c] = X[m].T @ r[m]
            self.s[c] = float(r[m] @ r[m])
            self.n[c] = int(m.sum())
        self.Gt = sum(self.G.values())
        self.ht = sum(self.h.values())
        self.nt = sum(self.n.values())
        self._cache: dict = {}

    def _bounds(self, support) -> tuple[np.ndarray, np.ndarray]:
        p = self.q + self.k
        lo = np.full(p, -np.inf)
        hi = np.full(p, np.inf)
        for j in range(self.k):
            if j not in support:
                lo[self.q + j] = hi[self.q + j] = 0.0
            elif self.nonneg[j]:
                lo[self.q + j] = 0.0
        return lo, hi

    def cv(self, support) -> float:
        """Pooled held-out RMSE [W] of calibration + support, leaving one run out at a time."""
        key = frozenset(support)
        if key not in self._cache:
            lo, hi = self._bounds(key)
            sse = 0.0
            for c in self.runs:
                ntr = self.nt - self.n[c]
                x = _box_lstsq((self.Gt - self.G[c]) / ntr, (self.ht - self.h[c]) / ntr, lo, hi)
                sse += max(0.0, self.s[c] - 2 * x @ self.h[c] + x @ self.G[c] @ x)
            self._cache[key] = math.sqrt(sse / self.nt)
        return self._cache[key]

    def coef(self, support) -> np.ndarray:
        """Full-data coefficients of the candidate columns (natural units)."""
        lo, hi = self._bounds(frozenset(support))
        x = _box_lstsq(self.Gt / self.nt, self.ht / self.nt, lo, hi)
        return (x / self.scale)[self.q:]

    def lasso_path(self, n_lambda: int = 12) -> list[tuple[float, tuple[int, ...]]]:
        """Supports along the sign-constrained lasso path (lambda relative to lambda_max)."""
        if self.k == 0:
            return []
        G = self.Gt / self.nt
        h = self.ht / self.nt
        lo0, hi0 = self._bounds(frozenset())
        x0 = _box_lstsq(G, h, lo0, hi0)
        grad = 2 * (h - G @ x0)[self.q:]
        g = np.where(self.nonneg, np.maximum(grad, 0.0), np.abs(grad))
        lam_max = float(g.max())
        if lam_max <= 0:
            return []
        p = self.q + self.k
        L = np.linalg.cholesky(G + 1e-10 * max(1.0, float(np.trace(G)) / p) * np.eye(p))
        lo, hi = self._bounds(frozenset(range(self.k)))
        lasso = _Lasso(L.T, solve_triangular(L, h, lower=True), lo, hi)
        path = []
        # a coefficient counts as non-zero above 1e-4 of the residual's RMS (the columns
        # are scaled to unit RMS, so coefficients are in W)
        tol = 1e-4 * math.sqrt(sum(self.s.values()) / self.nt)
        for lam in lam_max * np.logspace(0, -3, n_lambda):
            x = lasso.solve(np.concatenate([np.zeros(self.q), np.full(self.k, lam)]))
            sup = tuple(int(j) for j in np.nonzero(np.abs(x[self.q:]) > tol)[0])
            path.append((float(lam / lam_max), sup))
        return path


def _variants(name: str, s: Samples, geom: RigGeometry) -> tuple[float, ...]:
    """Coefficient values at which an exact-form effect is also screened.

    The first-order feature of an exact-form effect holds only while the effect
    is small; these variants (the exact form at a grid of its nonlinear
    parameter) let the screening see large lags, long delays and strong thinning.
    """
    if name == "thermal_lag":
        return (-30.0, -10.0, -3.0, -1.0, 1.0, 3.0, 10.0, 30.0)
    if name == "sensor_delay":
        return (0.5, 1.0, 2.0, 5.0)
    if name == "shear_thinning":
        gmax = float(np.max(np.abs(s.omega) * geom.radius1_m / s.gap1_m))
        return tuple((c / gmax) ** 2 for c in (0.5, 1.0, 2.0)) if gmax > 0 else ()
    return ()


# --------------------------------------------------------------------------- results


@dataclass(frozen=True)
class EffectResult:
    """An accepted effect with its fitted coefficient and confidence interval."""

    name: str
    title: str
    formula: str
    reference: str
    coefficient: float
    ci_low: float
    ci_high: float
    unit: str
    strength: float
    strength_unit: str
    heldout_gain_pct: float
    rms_power_W: float

    def coefficient_label(self) -> str:
        """Symbol of the coefficient (e.g. ``tau_c``)."""
        return EFFECTS[self.name].coefficient.split(" (")[0]

    def to_dict(self) -> dict:
        """JSON form (the issue's keys first)."""
        return {"name": self.name, "formula": self.formula, "coefficient": self.coefficient,
                "ci_low": self.ci_low, "ci_high": self.ci_high,
                "heldout_gain_pct": self.heldout_gain_pct, "title": self.title,
                "symbol": self.coefficient_label(),
                "reference": self.reference, "unit": self.unit, "strength": self.strength,
                "strength_unit": self.strength_unit, "rms_power_W": self.rms_power_W}


def _rmse(a: np.ndarray) -> float:
    return float(np.sqrt(np.mean(a * a))) if len(a) else float("nan")


def _jackknife_ci(full: np.ndarray, folds: np.ndarray, extra_var: np.ndarray | None = None,
                  level: float = 0.95):
    """Delete-one-run jackknife interval [3], variance widened by ``extra_var``."""
    g = folds.shape[0]
    if g < 3:
        return np.full_like(full, np.nan), np.full_like(full, np.nan)
    mean = folds.mean(axis=0)
    var = (g - 1) / g * np.sum((folds - mean) ** 2, axis=0)
    if extra_var is not None:
        var = var + extra_var
    t = stats.t.ppf(0.5 + level / 2, g - 1)
    return full - t * np.sqrt(var), full + t * np.sqrt(var)


def _baseline_variance(fit: _Fit, spec: BaseSpec, s: Samples, baselines: dict) -> np.ndarray:
    """Variance of (free Eq. 8 parameters, effect coefficients) due to the baseline's error.

    The oil-free baseline is estimated once per T and taken away from every oil
    run of that T, so its error is shared by those runs and a jackknife over
    runs cannot see it. Linear propagation: dz = J^+ dy, dy = -X_T dc_T,
    Cov(dc_T) from the baseline's least squares.
    """
    p = fit.jac.shape[1] if fit.jac is not None else 0
    if not baselines or fit.jac is None:
        return np.zeros(p)
    A = np.linalg.pinv(fit.jac)
    cov = np.zeros((p, p))
    for T, b in baselines.items():
        rows = s.roughness_T == T
        if b.cov is None or not rows.any():
            continue
        B = A[:, rows] @ b.design(s.omega[rows], s.domega_dt[rows], s.temp_C[rows])
        cov += B @ b.cov @ B.T
    var = np.diag(cov).copy()
    q = len(spec.free)
    if "C" in spec.free:  # ln C -> C
        i = spec.free.index("C")
        var[i] *= spec.law(fit.x).C ** 2
    var[q:] /= fit.scale ** 2
    return var


class LoopEstimator:
    """Calibrate the viscous-loss model on measured runs and search for a missing effect.

    Parameters
    ----------
    case : DesignCase, optional
        Rig geometry (default: the seed joint). Its friction law is the
        "without T" model (with gamma = 0).
    oils : dict or path, optional
        Oils table (default: the built-in catalogue).
    margin : float
        Relative fall of the held-out RMSE an effect must bring (default 0.10).
    min_explained : float
        Share of the held-out structure above noise it must explain (default 0.5).
    effects : sequence of str, optional
        Library effects to consider (default: all).
    max_effects : int
        Most effects accepted together (default 3).
    cv : {"one-step", "full"}
        How each leave-one-run-out fold is refitted for the reported held-out
        errors and the jackknife: one Gauss-Newton step from the all-runs fit
        (default, fast) or a complete nonlinear refit.

    Attributes (after ``fit``)
    --------------------------
    data_ : MeasuredData; baselines_ : dict T -> BaselineFit
    law_without_T_, law_with_T_ : FrictionLaw; law_ : the final law
    calibration_ : dict of fitted Eq. 8 parameters; calibration_ci_ : their CIs
    identifiability_ : dict parameter -> statement
    effects_ : list of EffectResult; candidates_ : list of dict (every library effect)
    rmse_ : dict without_T / with_T / with_effect [W]; heldout_rmse_ : before / after [W]
    per_run_, table3_ : lists of dict; residual_before_, residual_after_ : dict
    unexplained_ : dict or None; noise_W_ : float; lasso_path_ : list
    """

    def __init__(self, case: DesignCase | None = None, oils: dict[str, Oil] | str | Path |
                 None = None, margin: float = DEFAULT_MARGIN,
                 min_explained: float = DEFAULT_MIN_EXPLAINED, effects=None,
                 max_effects: int = 3, cv: str = "one-step"):
        self.case = case
        self.oils = oils
        self.margin = margin
        self.min_explained = min_explained
        self.effects = effects
        self.max_effects = max_effects
        self.cv = cv

    # ------------------------------------------------------------------ helpers
    def _as_data(self, data) -> MeasuredData:
        if isinstance(data, MeasuredData):
            return data
        oils = self.oils
        if isinstance(data, (str, Path)):
            return load_measured(data, oils)
        if isinstance(data, pd.DataFrame):
            from oilgap.model.oils import read_oils_csv

            cat = read_oils_csv(oils) if isinstance(oils, (str, Path)) else oils
            return validate(data, cat, "data frame")
        raise InputError("data", type(data).__name__, "a path, a pandas DataFrame or "
                         "MeasuredData is required")

    def _samples(self, data: MeasuredData, baselines=None) -> Samples:
        geom = self.geometry_
        if data.kind == "power_W":
            from oilgap.model.measured_data import add_kinematics

            own = fit_baselines(add_kinematics(data.frame))
            baselines = {**own, **(baselines or {})}
        return oil_samples(data, geom.gap1_m, baselines)

    # ------------------------------------------------------------------ fit
    def fit(self, data) -> LoopEstimator:
        """Run the whole loop on measured data (path, DataFrame or MeasuredData)."""
        case = self.case or seed_case()
        for k, v in (("margin", self.margin), ("min_explained", self.min_explained)):
            if not (isinstance(v, (int, float)) and 0.0 <= v < 1.0):
                raise InputError(k, v, "must be a number in [0, 1)", "loop")
        if self.cv not in ("one-step", "full"):
            raise InputError("cv", self.cv, "allowed: one-step, full", "loop")
        names = list(EFFECTS) if self.effects is None else list(self.effects)
        for n in names:
            if n not in EFFECTS:
                raise InputError("effect", n, f"library effects are {', '.join(EFFECTS)}")
        self.geometry_ = geom = RigGeometry.from_case(case)
        self.data_ = data = self._as_data(data)
        from oilgap.model.measured_data import add_kinematics

        kin = add_kinematics(data.frame)
        self.baselines_: dict[float, BaselineFit] = {}
        if data.kind == "power_W":
            self.baselines_ = fit_baselines(kin)
        s = oil_samples(data, geom.gap1_m, self.baselines_ or None, frame=kin)
        self.samples_ = s
        if len(s.run_names) < 2:
            raise InputError("oil runs", len(s.run_names), "the loop needs at least 2 oil runs "
                             "(it validates on whole runs left out)", data.source)
        bad = ~(np.isfinite(s.nu_m2_s) & np.isfinite(s.density_kg_m3))
        if bad.any():  # pragma: no cover - validation guarantees properties
            raise InputError("oil", s.oil[bad][0], "no viscosity or density for this row")
        y = s.viscous_W

        # Table 3: without T (published law, gamma = 0) and with T (Eq. 8 fitted)
        self.law_without_T_ = replace(case.friction, gamma=0.0)
        p_wo = _base_power(s, geom, self.law_without_T_)
        spec, stmt = decide_spec(s, geom, case)
        self.spec_ = spec
        start = {"C": 10.0, "alpha": BILGEN_BOULOS_ALPHA, "beta": -1.0, "gamma": 0.0}
        x0 = spec.start({**start, **spec.fixed})
        p0 = _base_power(s, geom, spec.law(x0))
        if "C" in spec.free:
            x0[spec.free.index("C")] += math.log(max(1e-12, float(p0 @ y) / float(p0 @ p0)))
        ev = _Evaluator(s, geom, data.oils)
        self.evaluator_ = ev
        base = fit_model(ev, spec, x0)
        self.law_with_T_ = base.law
        p_wt = base.pred
        r0 = y - p_wt
        self.residual_before_ = residual_structure(r0, s)
        sigma = self.residual_before_["noise_W"]
        self.noise_W_ = sigma
        jc = base.jac_base
        corr = np.corrcoef(jc.T) if jc.shape[1] > 1 else np.ones((1, 1))
        self.identifiability_ = dict(stmt)
        if jc.shape[1] > 1:
            pairs = [f"corr({spec.free[i]}, {spec.free[j]}) = {corr[i, j]:+.3f}"
                     for i in range(len(spec.free)) for j in range(i + 1, len(spec.free))]
            self.identifiability_["correlations"] = "; ".join(pairs) + \
                " (Jacobian columns at the fit)"

        # candidates: one linear column per effect, plus exact-form variants
        ctx = effect_context(s, geom, base.law)
        ymax = max(1.0, float(np.max(np.abs(y))))
        cand_info = []
        usable: list[str] = []
        cols, col_name, col_variant, col_nonneg = [], [], [], []
        p_base = ev.power(base.law)
        for n in names:
            eff = EFFECTS[n]
            f = eff.feature_values(ctx)
            info = {"name": n, "title": eff.title, "formula": eff.formula,
                    "nonnegative": eff.nonnegative}
            cand_info.append(info)
            if f is None:
                info["status"] = "not applicable: the rig has no bearing region"
                continue
            if not np.any(np.abs(f) > 1e-12 * ymax):
                info["status"] = ("inactive on these data" + (
                    ": Ta never exceeds 41.3" if n == "taylor_vortex_onset" else
                    ": no temperature law for dP/dT" if n == "thermal_lag" else ""))
                continue
            coef, *_ = np.linalg.lstsq(jc, f, rcond=None)
            r2 = 1.0 - float(np.sum((f - jc @ coef) ** 2)) / float(np.sum(f * f))
            info["r2_on_calibration"] = r2
            if r2 > CONFOUNDED_R2:
                info["status"] = (f"confounded with the calibration (R^2 = {r2:.6f} on "
                                  f"{', '.join(spec.free)}): absorbed, cannot be named")
                continue
            info["status"] = "candidate"
            usable.append(n)
            cols.append(f)
            col_name.append(n)
            col_variant.append(None)
            col_nonneg.append(eff.nonnegative)
            for v in _variants(n, s, geom):
                fv = ev.power(base.law, {n: v}) - p_base
                if np.any(np.abs(fv) > 1e-9 * ymax):
                    cols.append(fv)
                    col_name.append(n)
                    col_variant.append(v)
                    col_nonneg.append(True)
        F = np.column_stack(cols) if cols else np.zeros((s.n, 0))
        group = np.array([usable.index(n) for n in col_name], int)
        sel = _Selector(jc, F, r0, s.run_code, np.array(col_nonneg, bool), group)
        e0 = sel.cv(())
        path = sel.lasso_path()
        entry: dict[str, float] = {}
        for lam, sup in path:
            for j in sup:
                entry.setdefault(col_name[j], lam)
        self.lasso_path_ = [{"lambda_rel": lam, "support": sorted({col_name[j] for j in sup})}
                            for lam, sup in path]

        def label(j):
            v = col_variant[j]
            return col_name[j] if v is None else f"{col_name[j]} (exact form, {v:.3g})"

        for info in cand_info:
            if info["status"] == "candidate":
                js = [j for j in range(len(cols)) if col_name[j] == info["name"]]
                best = min(js, key=lambda j: sel.cv((j,)))
                info["heldout_rmse_alone_W"] = sel.cv((best,))
                info["heldout_gain_alone_pct"] = 100.0 * (1.0 - sel.cv((best,)) / e0)
                st0 = e0 * e0 - sigma * sigma
                info["explained_structure_alone"] = (
                    (e0 * e0 - sel.cv((best,)) ** 2) / st0 if st0 > 0 else 0.0)
                info["best_column"] = label(best)
                info["lasso_entry_lambda_rel"] = entry.get(info["name"])

        def structure(e):
            return e * e - sigma * sigma

        chosen: tuple[int, ...] = ()
        e_cur = e0
        log = []
        while len({col_name[j] for j in chosen}) < min(self.max_effects, len(usable)):
            taken = {col_name[j] for j in chosen}
            trials = {j: sel.cv(chosen + (j,)) for j in range(len(cols))
                      if col_name[j] not in taken}
            # near-ties (0.1 %) go to the effect the lasso path takes in first
            best = min(trials, key=lambda j: (round(trials[j] / e_cur, 3),
                                              -entry.get(col_name[j], 0.0)))
            e_new = trials[best]
            gain = 1.0 - e_new / e_cur
            st = structure(e_cur)
            explained = (e_cur ** 2 - e_new ** 2) / st if st > 0 else 0.0
            ok = gain >= self.margin and explained >= self.min_explained
            log.append({"step": len(chosen) + 1, "best": label(best), "heldout_rmse_W": e_new,
                        "gain_pct": 100 * gain, "explained_structure": explained,
                        "accepted": bool(ok)})
            if not ok:
                break
            chosen = chosen + (best,)
            e_cur = e_new
        # backward check: each effect must still bring the margin in the final set
        changed = True
        while changed and len(chosen) > 1:
            changed = False
            for j in chosen:
                rest = tuple(i for i in chosen if i != j)
                if sel.cv(rest) * (1 - self.margin) < sel.cv(chosen):
                    chosen = rest
                    changed = True
                    log.append({"step": "prune", "dropped": label(j)})
                    break
        self.selection_log_ = log

        # final refit (nonlinear; exact forms where the library has them)
        fscale = {n: float(np.sqrt(np.mean(F[:, col_name.index(n)] ** 2))) for n in usable}

        def refit(names, x_start, th_start, e=ev):
            sc = np.array([fscale[n] for n in names])
            return fit_model(e, spec, x_start, tuple(names), th_start, sc, full=ev)

        runs = np.unique(s.run_code)

        def loro(names, x_start, th_start, at: _Fit | None = None):
            """Held-out predictions and per-fold fits of model ``names`` (one Gauss-Newton
            step from the all-runs fit ``at`` unless cv = "full")."""
            pred = np.empty(s.n)
            folds = []
            if at is None or self.cv == "full":
                subs = {c: ev.subset(s.run_code != c) for c in runs}
            for c in runs:
                if at is not None and self.cv != "full":
                    f = one_step_fold(at, ev, spec, s.run_code != c)
                else:
                    f = refit(names, x_start, th_start, subs[c])
                pred[s.run_code == c] = f.pred[s.run_code == c]
                folds.append(f)
            return pred, folds

        ho_before, folds_b = loro((), base.x, None, base)
        hb = _rmse(y - ho_before)
        accepted = [col_name[j] for j in chosen]
        lin_coef = sel.coef(chosen)
        start = []
        for j in chosen:  # coefficient start: linear amplitude, or amplitude x variant value
            a_j = float(lin_coef[j])
            start.append(a_j if col_variant[j] is None else a_j * col_variant[j])
        fit = base
        ho_after, folds_a = ho_before, folds_b
        self.nonlinear_check_ = None
        if accepted:
            fit = refit(accepted, base.x, np.array(start))
            ho_after, folds_a = loro(accepted, fit.x, fit.theta, fit)
            ha = _rmse(y - ho_after)
            self.nonlinear_check_ = {"heldout_before_W": hb, "heldout_after_W": ha,
                                     "gain_pct": 100 * (1 - ha / hb)}
            if ha > hb * (1.0 - self.margin):  # the honest held-out check overrules
                log.append({"step": "nonlinear check", "rejected": accepted,
                            "gain_pct": 100 * (1 - ha / hb)})
                accepted, chosen = [], ()
                fit, ho_after, folds_a = base, ho_before, folds_b
        self.heldout_linear_ = {"before": e0, "after": sel.cv(chosen)}
        self.final_fit_ = fit
        self.law_ = fit.law
        self.effect_coef_ = dict(zip(accepted, map(float, fit.theta), strict=True))
        p_we = fit.pred
        self.heldout_pred_ = {"before": ho_before, "after": ho_after}

        # jackknife-over-runs confidence intervals
        vals_b = spec.values(base.x)
        vals_f = spec.values(fit.x)

        def ci(vals, folds, f_full):
            full = np.array([vals[k] for k in spec.free])
            fv = np.array([[spec.values(f.x)[k] for k in spec.free] for f in folds])
            extra = _baseline_variance(f_full, spec, s, self.baselines_)[:len(spec.free)]
            lo, hi = _jackknife_ci(full, fv, extra)
            return {k: ([float(lo[spec.free.index(k)]), float(hi[spec.free.index(k)])]
                        if k in spec.free else "fixed") for k in BASE_PARAMS}

        self.calibration_ = {k: float(vals_b[k]) for k in BASE_PARAMS}
        self.calibration_ci_ = ci(vals_b, folds_b, base)
        self.calibration_after_ = {k: float(vals_f[k]) for k in BASE_PARAMS}
        self.calibration_after_ci_ = ci(vals_f, folds_a, fit)
        if accepted:
            extra = _baseline_variance(fit, spec, s, self.baselines_)[len(spec.free):]
            lo_t, hi_t = _jackknife_ci(fit.theta, np.array([f.theta for f in folds_a]), extra)
        else:
            lo_t = hi_t = np.zeros(0)

        # held-out gain of each accepted effect: without it vs with it (nonlinear LORO)
        gains = {}
        for n in accepted:
            rest = [m for m in accepted if m != n]
            if rest:
                keep = [accepted.index(m) for m in rest]
                f_rest = refit(rest, fit.x, fit.theta[keep])
                pr, _ = loro(rest, fit.x, fit.theta[keep], f_rest)
                e_rest = _rmse(y - pr)
            else:
                e_rest = hb
            gains[n] = 100.0 * (1.0 - _rmse(y - ho_after) / e_rest)

        rmse_wo, rmse_wt, rmse_we = _rmse(y - p_wo), _rmse(y - p_wt), _rmse(y - p_we)
        self.rmse_ = {"without_T": rmse_wo, "with_T": rmse_wt, "with_effect": rmse_we}
        self.heldout_rmse_ = {"before": hb, "after": _rmse(y - ho_after)}

        self.effects_ = []
        for i, n in enumerate(accepted):
            eff = EFFECTS[n]
            c = float(fit.theta[i])
            only = ev.power(fit.law, dict(self.effect_coef_)) - ev.power(
                fit.law, {m: v for m, v in self.effect_coef_.items() if m != n})
            self.effects_.append(EffectResult(
                n, eff.title, eff.formula, eff.reference, c, float(lo_t[i]), float(hi_t[i]),
                eff.unit, float(eff.strength_from_coefficient(c)), eff.strength_unit, gains[n],
                _rmse(only)))
        e_acc = sel.cv(chosen)
        for info in cand_info:
            if info["name"] in accepted:
                info["status"] = "accepted"
            elif info["status"] != "candidate":
                continue
            elif structure(e0) <= 0:
                info["status"] = "rejected: no structure above the noise"
            elif accepted:
                js = [j for j in range(len(cols)) if col_name[j] == info["name"]]
                add = min(sel.cv(chosen + (j,)) for j in js)
                info["heldout_gain_added_pct"] = 100.0 * (1.0 - add / e_acc)
                info["status"] = (f"rejected: adds {info['heldout_gain_added_pct']:.1f} % to "
                                  f"{', '.join(accepted)} (margin {100 * self.margin:.0f} %)")
            else:
                g, x = info["heldout_gain_alone_pct"], info["explained_structure_alone"]
                info["status"] = (f"rejected: held-out gain {g:.1f} % " + (
                    f"< margin {100 * self.margin:.0f} %" if g < 100 * self.margin else
                    f"but explains only {100 * x:.0f} % of the structure "
                    f"(< {100 * self.min_explained:.0f} %)"))
        self.candidates_ = cand_info
        self.confounded_forms_ = dict(CONFOUNDED_FORMS)

        r_after = y - p_we
        self.residual_after_ = residual_structure(r_after, s)
        ra = self.residual_after_
        self.unexplained_ = None
        if ra["structured_fraction"] >= STRUCTURE_FRACTION:
            self.unexplained_ = {
                "description": ("structure no library effect explains: "
                                + describe_structure(ra)),
                "structured_rms_W": ra["structured_rms_W"], "noise_W": ra["noise_W"],
                "structured_fraction": ra["structured_fraction"],
                "correlates_with": sorted(
                    ({"variable": k, "eta2": v["eta2"], "pearson_r": v["pearson_r"]}
                     for k, v in ra["variables"].items()), key=lambda d: -d["eta2"]),
                "autocorrelation_lag1": ra["autocorrelation"]["1"]}

        # per run and Table 3
        self.pred_ = {"without_T": p_wo, "with_T": p_wt, "with_effect": p_we}
        self.per_run_ = []
        for c, name in enumerate(s.run_names):
            m = s.run_code == c
            self.per_run_.append({
                "run": name, "oil": str(s.oil[m][0]), "roughness_T": float(s.roughness_T[m][0]),
                "n_samples": int(m.sum()), "rmse_without_T_W": _rmse((y - p_wo)[m]),
                "rmse_with_T_W": _rmse((y - p_wt)[m]), "rmse_with_effect_W": _rmse((y - p_we)[m]),
                "heldout_rmse_before_W": _rmse((y - ho_before)[m]),
                "heldout_rmse_after_W": _rmse((y - ho_after)[m])})
        t3 = []
        keys = pd.DataFrame({"oil": s.oil, "T": s.roughness_T})
        for (oil, T), g in keys.groupby(["oil", "T"], sort=False):
            m = g.index.to_numpy()
            wo, wt = _rmse((y - p_wo)[m]), _rmse((y - p_wt)[m])
            t3.append({"oil": oil, "roughness_T": float(T), "rmse_without_T_W": wo,
                       "rmse_with_T_W": wt, "reduction_pct": 100.0 * (1.0 - wt / wo)
                       if wo > 0 else float("nan")})
        order = {o: float(np.median(s.nu_m2_s[s.oil == o])) for o in set(s.oil)}
        self.table3_ = sorted(t3, key=lambda r: (order[r["oil"]], r["roughness_T"]))
        rank = {(r["oil"], r["roughness_T"]): i for i, r in enumerate(self.table3_)}
        self.per_run_.sort(key=lambda r: (rank[(r["oil"], r["roughness_T"])], r["run"]))
        return self

    # ------------------------------------------------------------------ predict
    def predict(self, data, stage: str = "with_effect") -> pd.Series:
        """Model viscous power [W] of the oil-run samples of ``data``.

        ``stage``: "without_T" (published law, gamma = 0), "with_T" (calibrated
        Eq. 8) or "with_effect" (calibrated, with the accepted effects). The
        result is indexed by the rows of the validated frame.
        """
        if not hasattr(self, "law_"):
            raise InputError("estimator", "unfitted", "call fit(data) before predict")
        if stage not in ("without_T", "with_T", "with_effect"):
            raise InputError("stage", stage, "allowed: without_T, with_T, with_effect")
        d = self._as_data(data)
        s = self._samples(d, self.baselines_)
        ev = _Evaluator(s, self.geometry_, d.oils)
        if stage == "without_T":
            p = ev.power(self.law_without_T_)
        elif stage == "with_T":
            p = ev.power(self.law_with_T_)
        else:
            p = ev.power(self.law_, self.effect_coef_)
        return pd.Series(p, index=s.index, name=f"viscous_power_W_{stage}")

    # ------------------------------------------------------------------ report
    def to_dict(self) -> dict:
        """The loop.json document."""
        d = self.data_
        return {
            "rmse_W": dict(self.rmse_),
            "heldout_rmse_W": dict(self.heldout_rmse_),
            "per_run": [{k: r[k] for k in ("run", "oil", "roughness_T", "rmse_without_T_W",
                                           "rmse_with_T_W", "rmse_with_effect_W")}
                        for r in self.per_run_],
            "calibration": dict(self.calibration_),
            "effects": [e.to_dict() for e in self.effects_],
            "unexplained": self.unexplained_,
            "calibration_ci95": self.calibration_ci_,
            "calibration_with_effect": self.calibration_after_,
            "calibration_with_effect_ci95": self.calibration_after_ci_,
            "identifiability": self.identifiability_,
            "table3": self.table3_,
            "per_run_detail": self.per_run_,
            "candidates": self.candidates_,
            "selection": {"margin": self.margin, "min_explained": self.min_explained,
                          "noise_W": self.noise_W_, "heldout_linearised_W": self.heldout_linear_,
                          "steps": self.selection_log_, "lasso_path": self.lasso_path_},
            "confounded_forms": self.confounded_forms_,
            "residual_before": _strip_bins(self.residual_before_),
            "residual_after": _strip_bins(self.residual_after_),
            "data": {"source": d.source, "kind": d.kind, "rows_read": d.n_read,
                     "rows_dropped": d.n_dropped, "dropped": [x.to_dict() for x in d.dropped],
                     "ignored_columns": list(d.ignored_columns),
                     "oil_runs": len(self.samples_.run_names),
                     "oil_samples": int(self.samples_.n)},
            "baseline": [b.to_dict() for b in self.baselines_.values()],
            "models": {"without_T": _law_dict(self.law_without_T_),
                       "with_T": _law_dict(self.law_with_T_),
                       "with_effect": _law_dict(self.law_)},
        }


def _strip_bins(rs: dict) -> dict:
    out = {k: v for k, v in rs.items() if k != "variables"}
    out["variables"] = {k: {"pearson_r": v["pearson_r"], "eta2": v["eta2"]}
                        for k, v in rs["variables"].items()}
    return out


def _law_dict(law: FrictionLaw) -> dict:
    return {"form": law.form, "laminar_law": law.laminar_law, "gamma": law.gamma,
            "scale": law.scale, "C": law.C, "alpha": law.alpha, "beta": law.beta}
