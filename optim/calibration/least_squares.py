"""Stage 3 of the calibration: nonlinear least squares of Eq. 8 (and effects) on the power.

``C_m = C (delta/R)^alpha Re^beta T^gamma`` (``FrictionLaw(form="power-law")``)
is fitted to the oil runs' viscous power in W by ``scipy.optimize.least_squares``
[2]. Why not a linear fit of ln C_m: the noise is additive in W (a power
meter), samples near zero speed carry no information about C_m and can be
negative, and with two regions the power is a sum of two power laws, not
linear in the parameters in any log space. Which parameters are free is
decided from the data (:func:`decide_spec`: gamma needs two values of T, alpha
two region-1 gap ratios, beta a spread of Re).

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 6, 8 and 9, Table 3.
.. [2] M. A. Branch, T. F. Coleman, Y. Li, "A subspace, interior, and conjugate
   gradient method for large-scale bound-constrained minimization problems",
   SIAM J. Sci. Comput. 21:1-23, 1999 (the "trf" method).
.. [3] J. Nocedal, S. J. Wright, *Numerical Optimization*, 2nd ed., Springer
   2006, sec. 10.3 (Gauss-Newton step).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from oilgap.model.case import DesignCase
from oilgap.model.effects import EFFECTS
from oilgap.model.errors import SolverError
from oilgap.model.measured_data import Samples
from oilgap.model.regions import JointGeometry
from oilgap.model.skin_friction import BILGEN_BOULOS_ALPHA, FrictionLaw
from oilgap.model.taylor_couette import couette_reynolds

from .forward import ForwardModel

BASE_PARAMS = ("C", "alpha", "beta", "gamma")
"""The Eq. 8 parameters, in the order they are reported."""

START_VALUES = {"C": 10.0, "alpha": BILGEN_BOULOS_ALPHA, "beta": -1.0, "gamma": 0.0}
"""Start of the free parameters before C is rescaled to the data."""

BETA_MIN_SPREAD = 0.2
"""Power-weighted standard deviation of ln Re_1 above which beta is identifiable [-]."""


@dataclass(frozen=True)
class BaseSpec:
    """Which Eq. 8 parameters are fitted and the values of the fixed ones.

    Parameters
    ----------
    free : tuple of str
        Fitted parameters, in :data:`BASE_PARAMS` order (C enters as ln C).
    fixed : dict
        Values of the others (alpha [-], beta [-], gamma [-]).
    """

    free: tuple[str, ...]
    fixed: dict

    def law(self, x: np.ndarray) -> FrictionLaw:
        """Friction law at the free-parameter vector ``x`` (C as ln C) [1].

        Parameters
        ----------
        x : array
            Free parameters [-].

        Returns
        -------
        FrictionLaw
            ``form="power-law"`` with C, alpha, beta, gamma.
        """
        v = dict(self.fixed)
        for name, val in zip(self.free, x, strict=True):
            v[name] = math.exp(val) if name == "C" else float(val)
        return FrictionLaw(form="power-law", C=v["C"], alpha=v["alpha"], beta=v["beta"],
                           gamma=v["gamma"])

    def values(self, x: np.ndarray) -> dict:
        """All four parameters by name [-].

        Parameters
        ----------
        x : array
            Free parameters (C as ln C) [-].

        Returns
        -------
        dict
            C, alpha, beta, gamma.
        """
        law = self.law(x)
        return {"C": law.C, "alpha": law.alpha, "beta": law.beta, "gamma": law.gamma}

    def start(self, values: dict) -> np.ndarray:
        """Free-parameter vector from parameter values.

        Parameters
        ----------
        values : dict
            Parameter name -> value [-].

        Returns
        -------
        array
            Free parameters (C as ln C) [-].
        """
        return np.array([math.log(values[k]) if k == "C" else values[k] for k in self.free])


@dataclass
class ModelFit:
    """A fitted model: Eq. 8 parameters, effect coefficients, prediction, Jacobian.

    Attributes
    ----------
    x : array
        Free Eq. 8 parameters (C as ln C) [-].
    theta : array
        Effect coefficients (library units).
    law : FrictionLaw
        Friction law at ``x``.
    pred : array
        Model power per sample [W].
    jac_base : array
        Jacobian columns of ``x`` [W per unit parameter] (zero on a subset fit).
    jac : array or None
        Full Jacobian in the solver's unknowns :attr:`z` [W per unit].
    scale : array or None
        Scale of each effect coefficient in the solver (RMS of its feature) [W/unit].
    names : tuple of str
        Effects of ``theta``.
    lower : array or None
        Lower bound of each effect coefficient (0 or -inf).
    """

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


class _ScaledProblem:
    """The least-squares problem in the solver's unknowns z = (x, theta * scale)."""

    def __init__(self, model: ForwardModel, spec: BaseSpec, names: tuple[str, ...],
                 q: int, scale: np.ndarray, lower: np.ndarray):
        self.model, self.spec, self.names = model, spec, names
        self.q, self.scale, self.lower = q, scale, lower
        self.y = model.samples.viscous_W

    def unpack(self, z: np.ndarray) -> tuple[np.ndarray, dict]:
        return z[:self.q], dict(zip(self.names, z[self.q:] / self.scale, strict=True))

    def power(self, z: np.ndarray, model: ForwardModel | None = None) -> np.ndarray:
        x, coefs = self.unpack(z)
        return (model or self.model).power(self.spec.law(x), coefs)

    def residual(self, z: np.ndarray) -> np.ndarray:
        return self.power(z) - self.y

    def jacobian(self, z: np.ndarray) -> np.ndarray:
        """Central differences of the model (one-sided at a zero lower bound)."""
        q = self.q
        cols = []
        for j in range(len(z)):
            h = 1e-6 * max(1.0, abs(z[j]))
            zp, zm = z.copy(), z.copy()
            zp[j] += h
            zm[j] -= h
            if j >= q and self.lower[j - q] == 0.0 and zm[j] < 0:  # one-sided at the bound
                zm[j] = z[j]
                cols.append((self.power(zp) - self.power(zm)) / h)
            else:
                cols.append((self.power(zp) - self.power(zm)) / (2 * h))
        return np.column_stack(cols)


def fit_model(model: ForwardModel, spec: BaseSpec, x0: np.ndarray, names: tuple[str, ...] = (),
              theta0: np.ndarray | None = None, scale: np.ndarray | None = None,
              full: ForwardModel | None = None) -> ModelFit:
    """Nonlinear least squares of the model (Eq. 8 + effects ``names``) to the power [W].

    Unknowns: the free Eq. 8 parameters (C as ln C) and one coefficient per
    effect, bounded below by 0 where the library says so; effect coefficients
    are scaled by ``scale`` for conditioning. The Jacobian is by central
    differences of the model; the solver is SciPy's trust-region reflective [2].

    Parameters
    ----------
    model : ForwardModel
        Samples the model is fitted to (their ``viscous_W`` [W]).
    spec : BaseSpec
        Free and fixed Eq. 8 parameters.
    x0 : array
        Start of the free parameters (C as ln C) [-].
    names : tuple of str
        Library effects fitted with the law.
    theta0 : array, optional
        Start of their coefficients (library units; default 0).
    scale : array, optional
        RMS of each effect's feature [W/unit] (default 1).
    full : ForwardModel, optional
        Model on which the returned prediction is computed (default ``model``;
        the Jacobian is returned only then).

    Returns
    -------
    ModelFit

    Raises
    ------
    SolverError
        The least-squares solver reports failure or a non-finite result.
    """
    k = len(names)
    q = len(x0)
    sc = np.ones(k) if scale is None else np.where(np.asarray(scale) > 0, scale, 1.0)
    lo_t = np.array([0.0 if EFFECTS[n].nonnegative else -np.inf for n in names])
    t0 = np.zeros(k) if theta0 is None else np.maximum(np.asarray(theta0, float), lo_t)
    prob = _ScaledProblem(model, spec, tuple(names), q, sc, lo_t)
    z0 = np.concatenate([x0, t0 * sc])
    lo = np.concatenate([np.full(q, -np.inf), lo_t * sc])
    hi = np.full(q + k, np.inf)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        res = least_squares(prob.residual, z0, jac=prob.jacobian, bounds=(lo, hi),
                            method="trf", x_scale="jac", xtol=1e-10, ftol=1e-10, gtol=1e-10,
                            max_nfev=100)
    if res.status < 0 or not np.all(np.isfinite(res.x)):
        raise SolverError(f"calibration least squares failed: {res.message}", str(res.status))
    x, coefs = prob.unpack(res.x)
    out = full or model
    jfull = prob.jacobian(res.x) if out is model else None
    jb = jfull[:, :q] if jfull is not None else np.zeros((out.samples.n, q))
    return ModelFit(x, np.array([coefs[n] for n in names]), spec.law(x), prob.power(res.x, out),
                    jb, jfull, sc, tuple(names), lo_t)


def one_step_fold(fit: ModelFit, model: ForwardModel, spec: BaseSpec, train: np.ndarray
                  ) -> ModelFit:
    """Refit without some runs by one Gauss-Newton step from the all-runs solution [3].

    ``dz = -(J_tr' J_tr)^-1 J_tr' r_tr`` with the all-runs Jacobian J and
    residual r restricted to the training rows (coefficients projected onto
    their bounds), then the exact model at the new parameters. The step is
    exact for a model linear in its parameters and accurate to second order
    in the change otherwise.

    Parameters
    ----------
    fit : ModelFit
        All-runs fit (with its Jacobian).
    model : ForwardModel
        The all-runs model.
    spec : BaseSpec
    train : array of bool
        Samples of the training runs [-].

    Returns
    -------
    ModelFit
        Parameters after the step; prediction on all samples [W].
    """
    q = len(fit.x)
    J = fit.jac[train]
    r = (fit.pred - model.samples.viscous_W)[train]
    dz, *_ = np.linalg.lstsq(J, -r, rcond=None)
    z = fit.z + dz
    lo = np.concatenate([np.full(q, -np.inf), fit.lower * fit.scale])
    z = np.maximum(z, lo)
    x = z[:q]
    theta = z[q:] / fit.scale
    coefs = dict(zip(fit.names, theta, strict=True))
    law = spec.law(x)
    return ModelFit(x, theta, law, model.power(law, coefs), fit.jac_base, None, fit.scale,
                    fit.names, fit.lower)


def _log_re_spread(s: Samples, radius1_m: float) -> tuple[float, float]:
    """Power-weighted sd of ln Re_1 [-] and the largest Re_1 [-] of the samples."""
    re = couette_reynolds(s.omega, radius1_m, s.gap1_m, s.nu_m2_s)
    w = np.abs(s.omega) ** 2
    ok = re > 0
    lre = np.log(re[ok])
    sd = float(np.sqrt(np.average((lre - np.average(lre, weights=w[ok])) ** 2, weights=w[ok])))
    return sd, float(re.max())


def decide_spec(s: Samples, geometry: JointGeometry, case: DesignCase) -> tuple[BaseSpec, dict]:
    """Which Eq. 8 parameters the data identify, with the reason for each.

    C is always fitted; gamma if the oil runs have two values of T; alpha if
    they have two region-1 gap ratios; beta if ln Re_1 spreads by
    :data:`BETA_MIN_SPREAD` (power-weighted). Fixed ones take the published
    values (alpha of Eq. 6, beta = -1, the case's gamma) [1].

    Parameters
    ----------
    s : Samples
        Oil-run samples.
    geometry : JointGeometry
        Rig regions (region 1's radius [m]).
    case : DesignCase
        Rig (its friction law's gamma).

    Returns
    -------
    (BaseSpec, dict)
        The specification and a statement per parameter.
    """
    radius1 = geometry.regions[0].radius_m
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
    ratios = sorted(set(np.round(s.gap1_m / radius1, 6)))
    if len(ratios) >= 2:
        free.append("alpha")
        stmt["alpha"] = (f"identified from {len(ratios)} region-1 gap ratios "
                         f"{ratios[0]:.4g}..{ratios[-1]:.4g}")
    else:
        stmt["alpha"] = (f"not identifiable: one region-1 gap ratio (delta/R = {ratios[0]:.4g});"
                         f" fixed at {BILGEN_BOULOS_ALPHA:g} (Eq. 6), C absorbs (delta/R)^alpha")
    sd, re_max = _log_re_spread(s, radius1)
    if sd >= BETA_MIN_SPREAD:
        free.append("beta")
        stmt["beta"] = (f"identified from the spread of Re over the data (power-weighted sd of "
                        f"ln Re_1 = {sd:.2f}; Re_1 up to {re_max:.3g})")
    else:
        stmt["beta"] = (f"not identifiable: Re hardly varies (sd of ln Re = {sd:.2f}); fixed at "
                        "-1 (laminar)")
    order = [p for p in BASE_PARAMS if p in free]
    return BaseSpec(tuple(order), {k: v for k, v in fixed.items() if k not in order}), stmt


def initial_guess(model: ForwardModel, spec: BaseSpec) -> np.ndarray:
    """Start of the free parameters: :data:`START_VALUES`, C scaled to the data.

    Parameters
    ----------
    model : ForwardModel
    spec : BaseSpec

    Returns
    -------
    array
        Free parameters (C as ln C) [-]; ln C moved by the least-squares factor
        ``p0'y / p0'p0`` of the start's power p0 [W] onto the measured y [W].
    """
    y = model.samples.viscous_W
    x0 = spec.start({**START_VALUES, **spec.fixed})
    p0 = model.base_power(spec.law(x0))
    if "C" in spec.free:
        x0[spec.free.index("C")] += math.log(max(1e-12, float(p0 @ y) / float(p0 @ p0)))
    return x0


def identifiability(statements: dict, spec: BaseSpec, fit: ModelFit) -> dict:
    """The per-parameter statements with the Jacobian's parameter correlations.

    Parameters
    ----------
    statements : dict
        From :func:`decide_spec`.
    spec : BaseSpec
    fit : ModelFit
        Calibration (its ``jac_base`` [W per unit parameter]).

    Returns
    -------
    dict
        Parameter -> statement, plus ``"correlations"`` with two or more free
        parameters (correlation of the Jacobian columns [-]).
    """
    out = dict(statements)
    jc = fit.jac_base
    if jc.shape[1] > 1:
        corr = np.corrcoef(jc.T)
        pairs = [f"corr({spec.free[i]}, {spec.free[j]}) = {corr[i, j]:+.3f}"
                 for i in range(len(spec.free)) for j in range(i + 1, len(spec.free))]
        out["correlations"] = "; ".join(pairs) + " (Jacobian columns at the fit)"
    return out
