"""Fisher information of candidate rig runs from the loop's forward model.

The loop fits the oil runs' viscous power ``P(z)`` with its :class:`ForwardModel` (Eq. 8
per region through :func:`~oilgap.model.regions.region_power`, the base law of a
:class:`~oilgap.optim.calibration.spec.BaseSpec` in the solver's unknowns, e.g. ln scale
and gamma, plus library effects at their coefficients). With additive white noise of sd
sigma [W] on each sample, the information of a run about ``z`` is
``M = J^T J / sigma^2`` [1], with ``J = dP/dz`` over the run's samples.

* The base law's columns are CasADi's exact derivatives [2] of the forward model's own
  composition: ``sum_regions region_power(region(T, delta), omega, nu, rho, law(z))``,
  the regions of :func:`~oilgap.model.regions.joint_geometry` at each sample's
  roughness and gap, exactly as :meth:`ForwardModel.region_powers` sums them; one
  CasADi function of one sample mapped over all samples.
* The pressure-viscosity coefficient enters as ``nu exp(d_alpha p)`` (Barus) with
  ``d_alpha`` a deviation [1/GPa] from the oil's own at 0: its column is
  ``dP/dnu nu p``, by the same AD; zero at atmospheric pressure.
* An effect enters the loop's model as ``c f`` (its library feature, evaluated by the
  forward model's :meth:`ForwardModel.context`): its column at c = 0 is ``f`` exactly;
  for the exact forms (thermal lag, sensor delay, shear thinning, film heating) ``f``
  is the library's first-order term, so their columns are the linearisation at 0.

References
----------
.. [1] F. Pukelsheim, *Optimal Design of Experiments*, Wiley 1993, ch. 3 (moment and
   information matrices of a linearised model).
.. [2] J. A. E. Andersson et al., "CasADi: a software framework for nonlinear
   optimization and optimal control", Math. Prog. Comp. 11:1-36, 2019.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from oilgap.model.effects import EFFECTS, taylor_feature
from oilgap.model.errors import InputError
from oilgap.model.regions import joint_geometry, region_power
from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration.forward import ForwardModel
from oilgap.optim.calibration.spec import LOG_PARAMS, BaseSpec

BARUS = "pressure_viscosity"
"""Name of the pressure-viscosity deviation parameter [1/GPa]."""

PER_GPA = 1e-9
"""1/GPa in 1/Pa."""

LAW_FIELDS = {"eq6": ("scale", "alpha", "gamma"), "power-law": ("C", "alpha", "beta", "gamma")}
"""The FrictionLaw fields each base's parameters set (the branches base is not planned)."""


def symbolic_law(law: FrictionLaw, values: dict) -> FrictionLaw:
    """``law`` with some numeric fields replaced by CasADi expressions.

    FrictionLaw checks that its numbers are finite at construction, which a symbol is
    not; the copy is made from a checked law and only the given fields are set, so the
    law's form and laminar law are the checked ones.

    Parameters
    ----------
    law : FrictionLaw
        A checked law (its values at the expansion point).
    values : dict
        Field -> CasADi expression (scale, C, alpha, beta, gamma) [-].

    Returns
    -------
    FrictionLaw
        Shallow copy with the symbolic fields (for AD only, never for evaluation).
    """
    out = copy.copy(law)
    for k, v in values.items():
        object.__setattr__(out, k, v)
    return out


@dataclass(frozen=True)
class Parameters:
    """The parameters of the information matrix, in order.

    Attributes
    ----------
    base : tuple of str
        Free base parameters of the spec (the solver's unknowns: ln C, ln scale).
    effects : tuple of str
        Library effects (their coefficients, library units).
    pressure : bool
        Whether the pressure-viscosity deviation [1/GPa] is the last parameter.
    """

    base: tuple[str, ...]
    effects: tuple[str, ...] = ()
    pressure: bool = False

    @property
    def names(self) -> tuple[str, ...]:
        """All parameter names in the matrix order."""
        return self.base + self.effects + ((BARUS,) if self.pressure else ())

    def label(self, name: str) -> str:
        """How a parameter is reported (``ln scale`` for a log parameter)."""
        return f"ln {name}" if name in LOG_PARAMS else name


def base_jacobian(model: ForwardModel, spec: BaseSpec, x: np.ndarray,
                  pressure_Pa: np.ndarray | None = None) -> np.ndarray:
    """Exact Jacobian of the forward model's base power w.r.t. the free base parameters.

    Parameters
    ----------
    model : ForwardModel
        The runs' samples (speed [rad/s], nu [m^2/s], rho [kg/m^3], T [-], gap [m]).
    spec : BaseSpec
        Free parameters (``eq6`` or ``power-law`` base).
    x : array, shape (q,) or (n, q)
        Expansion point in the solver's unknowns (ln scale, gamma, ...) [-], one for all
        samples or one per sample (e.g. just below the Couette floor's kink of each run,
        :func:`~.floor.below_floor`).
    pressure_Pa : array, optional
        Gauge pressure of each sample [Pa]; given, a last column for the
        pressure-viscosity deviation [W per 1/GPa] is added.

    Returns
    -------
    (array, array)
        dP/dz, shape (n, q [+ 1]) [W per unit parameter], and dP/domega, shape (n,)
        [W s/rad] (for the speed reading's share of the noise).
    """
    if spec.base not in LAW_FIELDS:
        raise InputError("base", spec.base, "the planner takes the eq6 or power-law base",
                         "plan")
    z = ca.SX.sym("z", len(spec.free))
    d_alpha = ca.SX.sym("d_alpha")
    w, nu, rho, rough, gap, p = (ca.SX.sym(n) for n in ("w", "nu", "rho", "T", "gap", "p"))
    sym = {}
    for i, name in enumerate(spec.free):
        sym[name] = ca.exp(z[i]) if name in LOG_PARAMS else z[i]
    x = np.asarray(x, float)
    law = symbolic_law(spec.law(x if x.ndim == 1 else x[0]), {k: v for k, v in sym.items()
                                     if k in LAW_FIELDS[spec.base]})
    geo = joint_geometry(model.case, roughness_T=rough, gap1_m=gap)
    nu_p = nu if pressure_Pa is None else nu * ca.exp(d_alpha * PER_GPA * p)  # Barus
    power = 0
    for r in geo.regions:  # the forward model's sum over regions (ForwardModel.region_powers)
        power = power + region_power(r, w, nu_p, rho, law)
    params = ca.vertcat(z, d_alpha) if pressure_Pa is not None else z
    jac = ca.Function("dP_dz", [params, w, nu, rho, rough, gap, p],
                      [ca.horzcat(ca.jacobian(power, params), ca.jacobian(power, w))])
    s = model.samples
    n = s.n
    at = np.broadcast_to(x, (n, x.shape[-1]))
    at = np.column_stack([at, np.zeros(n)]) if pressure_Pa is not None else at
    pres = np.zeros(n) if pressure_Pa is None else np.asarray(pressure_Pa, float)
    out = jac.map(n)(np.ascontiguousarray(at.T), np.abs(s.omega)[None, :],
                     s.nu_m2_s[None, :], s.density_kg_m3[None, :],
                     np.broadcast_to(s.roughness_T, (n,))[None, :],
                     np.broadcast_to(s.gap1_m, (n,))[None, :], pres[None, :])
    out = np.asarray(out, dtype=float).reshape(n, at.shape[1] + 1)
    return out[:, :-1], out[:, -1]


def effect_columns(model: ForwardModel, law: FrictionLaw, effects: tuple[str, ...]
                   ) -> tuple[np.ndarray, dict[str, str]]:
    """Each effect's column dP/dc at c = 0: its library feature on the samples [W/unit].

    Parameters
    ----------
    model : ForwardModel
    law : FrictionLaw
        The base law at the expansion point.
    effects : tuple of str
        Library effects.

    Returns
    -------
    (array, dict)
        Columns (n, k) [W per unit coefficient]; effect -> why its column is zero.
    """
    ctx = model.context(law)
    cols, why = [], {}
    for name in effects:
        f = (taylor_feature(ctx, model.taylor_exponent) if name == "taylor_vortex_onset"
             else EFFECTS[name].feature_values(ctx))
        if f is None or not np.all(np.isfinite(f)):
            why[name] = "no feature on these runs (no temperature law or not finite)"
            f = np.zeros(model.samples.n)
        cols.append(np.broadcast_to(np.asarray(f, float), (model.samples.n,)))
    return (np.column_stack(cols) if cols else np.zeros((model.samples.n, 0))), why


def run_information(jac: np.ndarray, run_code: np.ndarray, sigma_W: float,
                    sample_var_W2: np.ndarray | None = None
                    ) -> tuple[np.ndarray, np.ndarray]:
    """Information matrix of each run, ``J_r^T J_r / sigma^2``, and its noise "meat".

    The loop fits by unweighted least squares, so with per-sample noise variances
    ``v_s`` its covariance is the sandwich ``A^-1 B A^-1`` [1] with ``A = sum J^T J /
    sigma^2`` and ``B = sum J^T diag(v) J / sigma^4`` (``B = A`` for white noise of sd
    sigma).

    Parameters
    ----------
    jac : array, shape (n, p)
        Jacobian over all samples [W per unit parameter].
    run_code : array of int, shape (n,)
        Run index of each sample (0 .. m-1).
    sigma_W : float
        Sd of the power noise per sample [W].
    sample_var_W2 : array, shape (n,), optional
        Total noise variance of each sample [W^2] (default sigma^2).

    Returns
    -------
    (A, B) : arrays, shape (m, p, p)
        Per run [unit^-2].
    """
    if not sigma_W > 0 or not math.isfinite(sigma_W):
        raise InputError("noise_W", sigma_W, "a finite noise sd > 0 W is required", "plan")
    m = int(run_code.max()) + 1
    v = np.full(len(jac), sigma_W ** 2) if sample_var_W2 is None else sample_var_W2
    A = np.zeros((m, jac.shape[1], jac.shape[1]))
    B = np.zeros_like(A)
    for r in range(m):
        sel = run_code == r
        j = jac[sel]
        A[r] = j.T @ j / sigma_W ** 2
        B[r] = (j * v[sel, None]).T @ j / sigma_W ** 4
    return A, B
