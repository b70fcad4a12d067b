"""Stage 3b of the calibration: nonlinear least squares of the base model (and effects).

The base model (:mod:`.spec`: the Eq. 6 regime structure times a scale and
T^gamma by default, or a free power law ``C (delta/R)^alpha Re^beta T^gamma``)
is fitted to the oil runs' viscous power in W by
``scipy.optimize.least_squares`` [2]. Why not a linear fit of ln C_m: the
noise is additive in W (a power meter), samples near zero speed carry no
information about C_m and can be negative, and with two regions the power is a
sum of two laws, not linear in the parameters in any log space. Every unknown
stays inside the numerical box of :data:`.spec.PARAM_LIMITS`.

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

from oilgap.model.effects import EFFECTS
from oilgap.model.errors import SolverError
from oilgap.model.skin_friction import BILGEN_BOULOS_ALPHA, FrictionLaw

from .forward import ForwardModel
from .spec import START_VALUES, BaseSpec

FOLD_STEP_LIMIT = 2.0
"""Largest change of a base parameter (ln C, ln scale, exponents) [-] a one-step fold may
make; a larger step falls back to a full nonlinear refit of that fold."""


@dataclass
class ModelFit:
    """A fitted model: base parameters, effect coefficients, prediction, Jacobian.

    Attributes
    ----------
    x : array
        Free base parameters (C, scale as logarithms) [-].
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
        """The solver's unknowns: free base parameters, then scaled effect coefficients."""
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

    Unknowns: the free base parameters (C, scale as logarithms, within their
    box) and one coefficient per effect, bounded below by 0 where the library
    says so and above by its ``upper`` (the film strength by 1); effect coefficients
    are scaled by ``scale`` for conditioning. The Jacobian is by central
    differences of the model; the solver is SciPy's trust-region reflective [2].

    Parameters
    ----------
    model : ForwardModel
        Samples the model is fitted to (their ``viscous_W`` [W]).
    spec : BaseSpec
        Free and fixed base parameters.
    x0 : array
        Start of the free parameters (C, scale as logarithms) [-].
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
    if q + k == 0:  # nothing to fit: the model at the given parameters
        law = spec.law(np.zeros(0))
        out = full or model
        return ModelFit(
            x=np.zeros(0), theta=np.zeros(0), law=law, pred=out.base_power(law),
            jac_base=np.zeros((out.samples.n, 0)), jac=np.zeros((model.samples.n, 0)),
            scale=np.ones(0), names=(), lower=np.zeros(0))
    sc = np.ones(k) if scale is None else np.where(np.asarray(scale) > 0, scale, 1.0)
    lo_t = np.array([0.0 if EFFECTS[n].nonnegative else -np.inf for n in names])
    hi_t = np.array([EFFECTS[n].upper for n in names])
    t0 = np.zeros(k) if theta0 is None else np.clip(np.asarray(theta0, float), lo_t, hi_t)
    prob = _ScaledProblem(model, spec, tuple(names), q, sc, lo_t)
    z0 = np.concatenate([x0, t0 * sc])
    blo, bhi = spec.bounds()
    x0 = np.clip(np.asarray(x0, float), blo, bhi)
    z0 = np.concatenate([x0, t0 * sc])
    lo = np.concatenate([blo, lo_t * sc])
    hi = np.concatenate([bhi, hi_t * sc])
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
    return ModelFit(
        x=x, theta=np.array([coefs[n] for n in names]), law=spec.law(x),
        pred=prob.power(res.x, out), jac_base=jb, jac=jfull, scale=sc, names=tuple(names),
        lower=lo_t)


def one_step_fold(fit: ModelFit, model: ForwardModel, spec: BaseSpec, train: np.ndarray,
                  hold: tuple[str, ...] = ()) -> ModelFit | None:
    """Refit without some runs by one Gauss-Newton step from the all-runs solution [3].

    ``dz = -(J_tr' J_tr)^-1 J_tr' r_tr`` with the all-runs Jacobian J and
    residual r restricted to the training rows (coefficients projected onto
    their bounds), then the exact model at the new parameters. The step is
    exact for a model linear in its parameters and accurate to second order
    in the change otherwise. Parameters in ``hold`` keep their all-data values
    here; the loop's folds never pass any (:meth:`.refit.Refitter.leave_one_run_out`
    refits a fold that cannot identify a parameter in full, with it at its prior).

    Parameters
    ----------
    fit : ModelFit
        All-runs fit (with its Jacobian).
    model : ForwardModel
        The all-runs model.
    spec : BaseSpec
    train : array of bool
        Samples of the training runs [-].
    hold : tuple of str
        Free base parameters held at their all-data values in this fold.

    Returns
    -------
    ModelFit or None
        Parameters after the step; prediction on all samples [W]. None if the
        step moves a base parameter by more than :data:`FOLD_STEP_LIMIT` or
        leaves the numerical box (the caller refits that fold in full).
    """
    q = len(fit.x)
    keep = np.ones(len(fit.z), bool)
    keep[[spec.free.index(k) for k in hold]] = False
    J = fit.jac[train][:, keep]
    r = (fit.pred - model.samples.viscous_W)[train]
    dz = np.zeros(len(fit.z))
    dz[keep], *_ = np.linalg.lstsq(J, -r, rcond=None)
    blo, bhi = spec.bounds()
    x = fit.x + dz[:q]
    if (not np.all(np.isfinite(dz)) or np.any(np.abs(dz[:q]) > FOLD_STEP_LIMIT)
            or np.any(x < blo) or np.any(x > bhi)):
        return None
    z = np.maximum(fit.z + dz, np.concatenate([np.full(q, -np.inf), fit.lower * fit.scale]))
    z[q:] = np.minimum(z[q:], np.array([EFFECTS[n].upper for n in fit.names]) * fit.scale)
    theta = z[q:] / fit.scale
    coefs = dict(zip(fit.names, theta, strict=True))
    law = spec.law(x)
    pred = model.power(law, coefs)
    if not np.all(np.isfinite(pred)):
        return None
    return ModelFit(
        x=x, theta=theta, law=law, pred=pred, jac_base=fit.jac_base, jac=None, scale=fit.scale,
        names=fit.names, lower=fit.lower)


ALPHA_MIN_WEIGHT = 0.1
"""Share of the pure Eq. 6 gap sensitivity (d ln P_1 / d alpha = ln(delta/R)) below which
region 1's power is taken as independent of alpha [-]."""


def check_alpha(model: ForwardModel, spec: BaseSpec, stmt: dict) -> tuple[BaseSpec, dict]:
    """Fix alpha if region 1's power hardly depends on it at these samples.

    With the Couette laminar law region 1 follows ``max(Couette, Eq. 6)``; where
    Eq. 6 lies below the Couette bound the power has no alpha in it, however
    many gap ratios the data hold (alpha would act only on region 2, whose gap
    is fixed). The test: the power-weighted RMS of ``d ln P_1 / d alpha`` is
    below :data:`ALPHA_MIN_WEIGHT` of that of ``ln(delta/R)``, its value where
    Eq. 6 governs.

    Parameters
    ----------
    model : ForwardModel
    spec : BaseSpec
    stmt : dict
        Statements of :func:`decide_spec`.

    Returns
    -------
    (BaseSpec, dict)
        The specification (alpha [-] fixed at 0.3 if region 1 does not depend on
        it) and the statements.
    """
    if "alpha" not in spec.free:
        return spec, stmt
    vals = spec.values(spec.start({**START_VALUES, **spec.fixed}))
    h = 1e-3  # local: at x ~ 0.05 Eq. 6 is within 7 % of Couette
    p = [model.region_powers(spec.holding({**vals, "alpha": vals["alpha"] + d}).law(
        np.zeros(0)))[0] for d in (-h, h)]
    w = 0.5 * (p[0] + p[1])
    ok = (w > 0) & (p[0] > 0) & (p[1] > 0)
    if ok.any():
        dlnp = (np.log(p[1][ok]) - np.log(p[0][ok])) / (2 * h)
        lnx = np.log(model.samples.gap1_m[ok] / model.geometry.regions[0].radius_m)
        wk = w[ok] ** 2
        if np.sum(wk * dlnp ** 2) >= ALPHA_MIN_WEIGHT ** 2 * np.sum(wk * lnx ** 2):
            return spec, stmt
    stmt = {**stmt, "alpha": (f"not identifiable: region 1 follows the Couette bound (Eq. 6 "
                              f"lies below it at these samples), which has no alpha; fixed at "
                              f"{BILGEN_BOULOS_ALPHA:g} (Eq. 6)")}
    return spec.holding({"alpha": BILGEN_BOULOS_ALPHA}), stmt


def initial_guess(model: ForwardModel, spec: BaseSpec) -> np.ndarray:
    """Start of the free parameters: :data:`START_VALUES`, the level scaled to the data.

    Parameters
    ----------
    model : ForwardModel
    spec : BaseSpec

    Returns
    -------
    array
        Free parameters (C, scale as logarithms) [-]; the level (ln C or ln
        scale) moved by the least-squares factor ``p0'y / p0'p0`` of the start's
        power p0 [W] onto the measured y [W] (floored at 1e-12).
    """
    return rescale_level(model, spec, spec.start({**START_VALUES, **spec.fixed}))


def rescale_level(model: ForwardModel, spec: BaseSpec, x0: np.ndarray) -> np.ndarray:
    """A start with its level (ln C or ln scale) moved onto the data.

    Parameters
    ----------
    model : ForwardModel
    spec : BaseSpec
    x0 : array
        Free parameters (C, scale as logarithms) [-].

    Returns
    -------
    array
        ``x0`` with the level moved by ``ln(p0'y / p0'p0)`` (the factor floored at
        1e-12), p0 the power at ``x0`` [W], y the measured power [W].
    """
    x0 = np.array(x0, dtype=float)
    y = model.samples.viscous_W
    p0 = model.base_power(spec.law(x0))
    levels = [k for k in spec.free if k in ("C", "scale")
              or (spec.base == "branches" and k.startswith("C"))]
    den = float(p0 @ p0)
    if levels and den > 0 and np.isfinite(den):
        step = math.log(max(1e-12, float(p0 @ y) / den))
        for k in levels[:1] if spec.base != "branches" else levels:
            x0[spec.free.index(k)] += step  # branches: every fitted C_k by the same factor
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
    if jc.shape[1] > 1 and np.all(np.std(jc, axis=0) > 0):
        corr = np.corrcoef(jc.T)
        pairs = [f"corr({spec.free[i]}, {spec.free[j]}) = {corr[i, j]:+.3f}"
                 for i in range(len(spec.free)) for j in range(i + 1, len(spec.free))]
        out["correlations"] = "; ".join(pairs) + " (Jacobian columns at the fit)"
    return out
