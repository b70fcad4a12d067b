"""Stage 3a of the calibration: the base model and which of its parameters the data identify.

Two base models of the clearance loss (seed Eqs. 6-8):

* ``"eq6"`` (default): the model the design tool uses, the Eq. 6 regime
  structure in its smooth form (``FrictionLaw(form="smooth")`` with the case's
  laminar law, as in the NLP) times one ``scale`` (1 = the published law) and
  ``T^gamma``; the gap-ratio exponent ``alpha`` (0.3 in Eq. 6) is freed only
  where several region-1 gap ratios identify it.
* ``"power-law"``: one free power law ``C (delta/R)^alpha Re^beta T^gamma``
  (Eq. 7/8 with a free slope beta), the model of the seed's Table 3 fit.
* ``"branches"``: the smooth maximum of Eq. 6's four branches, each with its own
  ``C_k (delta/R)^alpha_k Re^beta_k`` (``FrictionLaw(form="branches")`` with the
  case's laminar law) times ``T^gamma``. Only what the data identify is fitted
  (:func:`branch_identifiability`): C_k of a branch that governs samples, its
  alpha_k where those samples have several gap ratios, its beta_k where they span
  a speed range at one gap; the rest stay at Eq. 6's published values.

Positive parameters (``C``, ``scale``) are fitted as their logarithm. Every
parameter is kept inside a numerical box (:data:`PARAM_LIMITS`) so that no
evaluation overflows; a fit that ends on that box is reported, never used as a
number. :func:`decide_spec` decides from the data which parameters are free;
:func:`fold_spec` does the same for the training data of one cross-validation
fold; what that fold cannot identify is held at its *prior* (:meth:`BaseSpec.prior_values`:
the published value of Eq. 6, the case's gamma, the base form's default), never at the
all-data fit, which has seen the held-out group.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 6-9, Table 3.
.. [2] E. Bilgen, R. Boulos, ASME J. Fluids Eng. 95(1):122-126, 1973.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from oilgap.model.case import DesignCase
from oilgap.model.measured.data import Samples
from oilgap.model.regions import JointGeometry
from oilgap.model.skin_friction import (
    BILGEN_BOULOS_ALPHA,
    BRANCH_ALPHA,
    BRANCH_BETA,
    BRANCH_C,
    BRANCH_KEYS,
    FrictionLaw,
)
from oilgap.model.taylor_couette import couette_reynolds

from .branch_ident import (  # re-exported: the branch rules are part of the base spec
    BRANCH_MIN_SAMPLES,
    branch_identifiability,
    distinct_values,
)

BASES = ("eq6", "power-law", "branches")
"""The base models of the calibration."""

N_BRANCHES = len(BRANCH_C)
"""Branches of the ``"branches"`` base: Eq. 6's four."""

BRANCH_PARAMS = (("scale",) + tuple(f"C{k + 1}" for k in range(N_BRANCHES))
                 + tuple(f"alpha{k + 1}" for k in range(N_BRANCHES))
                 + tuple(f"beta{k + 1}" for k in range(N_BRANCHES)) + ("gamma",))
"""The parameters of the branches base, in the order they are reported (the scale, 1, is
fitted only where no branch governs enough samples: the level of the Couette bound)."""

BRANCH_START = {"scale": 1.0, **{f"C{k + 1}": v for k, v in enumerate(BRANCH_C)},
                **{f"alpha{k + 1}": v for k, v in enumerate(BRANCH_ALPHA)},
                **{f"beta{k + 1}": v for k, v in enumerate(BRANCH_BETA)}}
"""Published values of the branch parameters (Eq. 6 [2]): start values and held values."""

BASE_PARAMS = ("C", "alpha", "beta", "gamma")
"""The parameters of the power-law base, in the order they are reported."""

EQ6_PARAMS = ("scale", "alpha", "gamma")
"""The parameters of the Eq. 6 base, in the order they are reported."""

LOG_PARAMS = ("C", "scale") + tuple(f"C{k + 1}" for k in range(N_BRANCHES))
"""Parameters that must be positive: fitted, and given intervals, as their logarithm."""

PARAM_LIMITS = {"C": (-50.0, 50.0), "scale": (-50.0, 50.0), "alpha": (-3.0, 3.0),
                "beta": (-3.0, 3.0), "gamma": (-10.0, 10.0),
                **{k: (-50.0, 50.0) if k.startswith("C") else (-3.0, 3.0)
                   for k in BRANCH_PARAMS if k not in ("gamma", "scale")}}
"""Numerical box of each parameter in the solver's unknown (ln C, ln scale) [-]: far
outside every physical range, it keeps each evaluation finite (x^alpha, Re^beta, exp)."""

START_VALUES = {"C": 10.0, "scale": 1.0, "alpha": BILGEN_BOULOS_ALPHA, "beta": -1.0,
                "gamma": 0.0, **BRANCH_START}
"""Start of the free parameters before C (or the scale) is rescaled to the data."""

BETA_MIN_SPREAD = 0.2
"""Power-weighted standard deviation of ln Re_1 above which beta is identifiable [-]."""

ALPHA_MIN_R2_GAP = 1e-6
"""alpha is identifiable only if its Jacobian column is not (1 - this) explained by the
others' (with the Couette laminar law, Eq. 6 may lie below Couette at every sample)."""


def _clip(name: str, value: float) -> float:
    lo, hi = PARAM_LIMITS[name]
    return min(hi, max(lo, float(value)))


@dataclass(frozen=True)
class BaseSpec:
    """Which base-model parameters are fitted and the values of the fixed ones.

    Parameters
    ----------
    free : tuple of str
        Fitted parameters, in the base's order (C and scale enter as logarithms).
    fixed : dict
        Values of the others [-].
    base : {"power-law", "eq6", "branches"}
        The base model (:data:`BASES`).
    laminar_law : {"couette", "bilgen-boulos"}
        Laminar law of the Eq. 6 base (the case's).
    prior : dict
        Value of each parameter before any data [-]: the published Eq. 6 value, the
        case's gamma (0 on smooth walls), the base form's default
        (:meth:`prior_values`). A cross-validation fold holds what it cannot
        identify here.
    scale_min : float
        Lowest scale the fit may take [-] (0: the box only; where the Couette floor
        governs, the scale it starts at: :func:`.base_choice.laminar_share`).
    transition : {"reynolds", "taylor"}
        Transition rule of the Eq. 6 base (the case's ``[friction] transition``).
    """

    free: tuple[str, ...]
    fixed: dict
    base: str = "power-law"
    laminar_law: str = field(default="couette")
    prior: dict = field(default_factory=dict)
    scale_min: float = 0.0
    transition: str = "reynolds"

    def prior_values(self) -> dict:
        """Every parameter's prior [-] (:attr:`prior`, else the published start value).

        Returns
        -------
        dict
            Parameter -> value held by a fold that cannot identify it [-].
        """
        return {k: float({**START_VALUES, **self.prior}[k]) for k in self.params}

    @property
    def params(self) -> tuple[str, ...]:
        """All parameters of the base, in their reported order."""
        return {"eq6": EQ6_PARAMS, "branches": BRANCH_PARAMS}.get(self.base, BASE_PARAMS)

    def values(self, x: np.ndarray) -> dict:
        """All parameters by name [-] (positive ones exponentiated, all within the box).

        Parameters
        ----------
        x : array
            Free parameters (C, scale as logarithms) [-].

        Returns
        -------
        dict
            Parameter -> value [-].
        """
        v = dict(self.fixed)
        for name, val in zip(self.free, x, strict=True):
            val = _clip(name, val)
            v[name] = math.exp(val) if name in LOG_PARAMS else val
        return {k: float(v[k]) for k in self.params}

    def law(self, x: np.ndarray) -> FrictionLaw:
        """Friction law at the free-parameter vector ``x`` [1], [2].

        Parameters
        ----------
        x : array
            Free parameters (C, scale as logarithms) [-].

        Returns
        -------
        FrictionLaw
            ``form="power-law"`` with C, alpha, beta, gamma, ``form="smooth"`` (the
            Eq. 6 regime structure) with scale, alpha, gamma, or ``form="branches"``
            with C_k, alpha_k, beta_k, gamma.
        """
        v = self.values(x)
        if self.base == "branches":
            return FrictionLaw(form="branches", laminar_law=self.laminar_law, gamma=v["gamma"],
                               scale=v["scale"],
                               **{key: tuple(v[f"{name}{k + 1}"] for k in range(N_BRANCHES))
                                  for key, name in zip(BRANCH_KEYS, ("C", "alpha", "beta"),
                                                       strict=True)})
        if self.base == "eq6":
            return FrictionLaw(form="smooth", laminar_law=self.laminar_law, scale=v["scale"],
                               alpha=v["alpha"], gamma=v["gamma"], transition=self.transition)
        return FrictionLaw(form="power-law", C=v["C"], alpha=v["alpha"], beta=v["beta"],
                           gamma=v["gamma"])

    def start(self, values: dict) -> np.ndarray:
        """Free-parameter vector from parameter values.

        Parameters
        ----------
        values : dict
            Parameter name -> value [-].

        Returns
        -------
        array
            Free parameters (C, scale as logarithms) [-].
        """
        return np.array([math.log(values[k]) if k in LOG_PARAMS else values[k]
                         for k in self.free], dtype=float)

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """The numerical box of the free parameters (:data:`PARAM_LIMITS`).

        Returns
        -------
        (lo, hi) : arrays
            Bounds of the solver's unknowns [-].
        """
        lo = np.array([PARAM_LIMITS[k][0] for k in self.free])
        if self.scale_min > 0 and "scale" in self.free:  # the Couette floor (issue 27)
            i = self.free.index("scale")
            lo[i] = max(lo[i], math.log(self.scale_min))
        return lo, np.array([PARAM_LIMITS[k][1] for k in self.free])

    def at_limit(self, x: np.ndarray) -> list[str]:
        """Free parameters that sit on their numerical box (not identified by the data).

        Parameters
        ----------
        x : array
            Free parameters [-].

        Returns
        -------
        list of str
        """
        lo = np.array([PARAM_LIMITS[k][0] for k in self.free])  # the box, not the floor
        hi = np.array([PARAM_LIMITS[k][1] for k in self.free])
        tol = 1e-6 * (hi - lo)
        return [k for k, v, a, b, t in zip(self.free, x, lo, hi, tol, strict=True)
                if v <= a + t or v >= b - t]

    def holding(self, values: dict) -> BaseSpec:
        """The same base with some parameters moved from free to fixed.

        Parameters
        ----------
        values : dict
            Parameter -> value it is held at [-].

        Returns
        -------
        BaseSpec
        """
        return replace(self, free=tuple(k for k in self.free if k not in values),
                       fixed={**self.fixed, **values})


def cv_groups(s: Samples) -> np.ndarray:
    """Group code of each sample for cross-validation (``cv_group``, else the run).

    Parameters
    ----------
    s : Samples

    Returns
    -------
    array of int
        Group code [-]; samples of one group are left out together.
    """
    g = getattr(s, "cv_group", None)
    return s.run_code if g is None else np.asarray(g)


def _log_re_spread(s: Samples, radius1_m: float) -> tuple[float, float]:
    """Power-weighted sd of ln Re_1 [-] and the largest Re_1 [-] of the samples."""
    re = couette_reynolds(s.omega, radius1_m, s.gap1_m, s.nu_m2_s)
    w = np.abs(s.omega) ** 2
    ok = (re > 0) & (w > 0)
    if ok.sum() < 2:
        return 0.0, float(np.max(re, initial=0.0))
    lre = np.log(re[ok])
    sd = float(np.sqrt(np.average((lre - np.average(lre, weights=w[ok])) ** 2, weights=w[ok])))
    return sd, float(re.max())


def identifiable(s: Samples, radius1_m: float) -> dict[str, str | None]:
    """For gamma, alpha and beta: None if the samples identify it, else the reason.

    gamma needs two values of T, alpha two region-1 gap ratios, beta a spread of
    ln Re_1 of :data:`BETA_MIN_SPREAD` (power-weighted).

    Parameters
    ----------
    s : Samples
        Samples (T [-], region-1 gap [m], speed [rad/s], nu [m^2/s]).
    radius1_m : float
        Region-1 radius [m].

    Returns
    -------
    dict
        gamma, alpha, beta -> None or the reason it is not identifiable.
    """
    Ts = distinct_values(s.roughness_T, 9)
    ratios = distinct_values(s.gap1_m / radius1_m, 6)
    sd, _ = _log_re_spread(s, radius1_m)
    return {"gamma": None if len(Ts) >= 2 else f"one roughness (T = {Ts[0]:g})",
            "alpha": None if len(ratios) >= 2 else f"one gap ratio (delta/R = {ratios[0]:.4g})",
            "beta": None if sd >= BETA_MIN_SPREAD else f"Re hardly varies (sd of ln Re = "
            f"{sd:.2f})"}


TAYLOR_ALPHA_HELD = (
    f"held at {BILGEN_BOULOS_ALPHA:g} (Eq. 6) under the Taylor transition: alpha acts only "
    "through Eq. 6's turbulent branches where they rise above Wendt's correlation, so a free "
    "alpha can switch them off and the fit has several minima (on Wendt's three-gap air "
    "data, leave-one-gap-out fits from different starts predict the held-out gap 5 to 35 W "
    "apart)")
"""The statement of alpha under ``[friction] transition = "taylor"``: the scale (and gamma)
are the Taylor candidate's free parameters, so its held-out error does not depend on where
a fit starts."""


def decide_spec(s: Samples, geometry: JointGeometry, case: DesignCase,
                base: str = "power-law") -> tuple[BaseSpec, dict]:
    """Which base-model parameters the data identify, with the reason for each.

    The level (C or scale) is always fitted; gamma if the samples have two
    values of T; alpha if they have two region-1 gap ratios; beta (power-law
    base only) if ln Re_1 spreads by :data:`BETA_MIN_SPREAD`. Fixed ones take
    the published values (alpha of Eq. 6, beta = -1, gamma = 0 at T = 1 else
    the case's) [1].

    Parameters
    ----------
    s : Samples
        Oil-run samples.
    geometry : JointGeometry
        Rig regions (region 1's radius [m]).
    case : DesignCase
        Rig (its friction law's gamma and laminar law).
    base : {"power-law", "eq6", "branches"}
        Base model (``"branches"``: see :func:`branch_identifiability`).

    Returns
    -------
    (BaseSpec, dict)
        The specification and a statement per parameter.
    """
    radius1 = geometry.regions[0].radius_m
    why = identifiable(s, radius1)
    level = {"eq6": "scale", "branches": "C_k"}.get(base, "C")
    stmt = {} if base == "branches" else {level: "identified: the level of the loss" + (
        " (1 = the published Eq. 6)" if base == "eq6" else "")}
    free = [] if base == "branches" else [level]
    fixed = {"scale": 1.0, "C": 10.0, "alpha": BILGEN_BOULOS_ALPHA, "beta": -1.0,
             "gamma": case.friction.gamma}
    Ts = distinct_values(s.roughness_T, 9)
    prior = {**fixed, **BRANCH_START, "scale": 1.0,
             "gamma": 0.0 if Ts == [1.0] else case.friction.gamma}
    if why["gamma"] is None:
        free.append("gamma")
        stmt["gamma"] = f"identified from the runs at T = {', '.join(f'{t:g}' for t in Ts)}"
    else:
        fixed["gamma"] = 0.0 if Ts == [1.0] else case.friction.gamma
        stmt["gamma"] = (f"not identifiable: every oil run has T = {Ts[0]:g}; fixed at "
                         f"{fixed['gamma']:g} (only {level} T^gamma is identified)")
    if base == "branches":
        bfree, bstmt = _branch_spec(s, radius1, case.friction.laminar_law)
        order = [p for p in BRANCH_PARAMS if p in free or p in bfree]
        return BaseSpec(tuple(order), {k: {**BRANCH_START, **fixed}[k] for k in BRANCH_PARAMS
                                       if k not in order}, base,
                        case.friction.laminar_law, prior), {**bstmt, **stmt}
    ratios = distinct_values(s.gap1_m / radius1, 6)
    taylor = base == "eq6" and case.friction.transition == "taylor"
    if why["alpha"] is None and taylor:
        stmt["alpha"] = TAYLOR_ALPHA_HELD
    elif why["alpha"] is None:
        free.append("alpha")
        stmt["alpha"] = (f"identified from {len(ratios)} region-1 gap ratios "
                         f"{ratios[0]:.4g}..{ratios[-1]:.4g}")
    else:
        stmt["alpha"] = (f"not identifiable: one region-1 gap ratio (delta/R = {ratios[0]:.4g});"
                         f" fixed at {BILGEN_BOULOS_ALPHA:g} (Eq. 6), {level} absorbs "
                         "(delta/R)^alpha")
    if base == "power-law":
        sd, re_max = _log_re_spread(s, radius1)
        if why["beta"] is None:
            free.append("beta")
            stmt["beta"] = (f"identified from the spread of Re over the data (power-weighted sd"
                            f" of ln Re_1 = {sd:.2f}; Re_1 up to {re_max:.3g})")
        else:
            stmt["beta"] = (f"not identifiable: Re hardly varies (sd of ln Re = {sd:.2f}); "
                            "fixed at -1 (laminar)")
    spec_params = EQ6_PARAMS if base == "eq6" else BASE_PARAMS
    order = [p for p in spec_params if p in free]
    return BaseSpec(tuple(order), {k: fixed[k] for k in spec_params if k not in order}, base,
                    case.friction.laminar_law, prior,
                    transition=case.friction.transition if base == "eq6" else "reynolds"), stmt


BRANCH_SPEED_SHARE = 0.1
"""Samples below this share of the data's largest |speed| do not count for a branch: their
loss (~ omega^2 or faster) is under 1 % of the peak's, noise rather than a regime."""


def _region1_re_x(s: Samples, radius1_m: float) -> tuple[np.ndarray, np.ndarray]:
    """Region 1's Couette Reynolds number [-] and gap ratio [-] at the samples that carry
    loss (|speed| at least :data:`BRANCH_SPEED_SHARE` of the largest)."""
    re = couette_reynolds(s.omega, radius1_m, s.gap1_m, s.nu_m2_s)
    x = np.broadcast_to(np.asarray(s.gap1_m, float) / radius1_m, re.shape)
    w = np.abs(np.asarray(s.omega, float))
    ok = (w > 0) & (w >= BRANCH_SPEED_SHARE * float(np.max(w, initial=0.0)))
    return re[ok], x[ok]


def _branch_spec(s: Samples, radius1_m: float, laminar_law: str) -> tuple[list[str], dict]:
    """Free branch parameters and a statement for each (:func:`branch_identifiability` on
    region 1's samples under the published branches); if no branch governs enough
    samples, the C_k of the one governing most is fitted as the level."""
    re, x = _region1_re_x(s, radius1_m)
    pub = FrictionLaw(form="branches", laminar_law=laminar_law)
    ident = branch_identifiability(re, x, pub)
    free = [k for k in BRANCH_PARAMS[1:-1] if ident[k][0]]
    stmt = {k: t for k, (_, t) in ident.items()}
    if not any(k.startswith("C") for k in free):
        free.insert(0, "scale")
        stmt["scale"] = (f"fitted as the level of the loss: no branch governs "
                         f"{BRANCH_MIN_SAMPLES} samples (the laminar Couette bound governs "
                         "the rest), so no C_k is identified")
    else:
        stmt["scale"] = "held at 1: the fitted C_k carry the level"
    return free, stmt


def fold_spec(spec: BaseSpec, s_train: Samples, radius1_m: float) -> tuple[str, ...]:
    """Free parameters that the training samples of one fold cannot identify.

    They are held at their priors in that fold (:meth:`BaseSpec.prior_values`; the
    level, C or scale, is always identified). Never at the all-data fit: it has seen
    the held-out group, and a held-out error computed with it leaks.

    Parameters
    ----------
    spec : BaseSpec
        The all-data specification.
    s_train : Samples
        The fold's training samples.
    radius1_m : float
        Region-1 radius [m].

    Returns
    -------
    tuple of str
        Parameters of ``spec.free`` to hold in this fold.
    """
    why = identifiable(s_train, radius1_m)
    if spec.base == "branches":
        free, _ = _branch_spec(s_train, radius1_m, spec.laminar_law)
        hold = [k for k in spec.free if (k == "gamma" and why["gamma"] is not None)
                or (k != "gamma" and k not in free)]
        levels = [k for k in spec.free if k.startswith("C") or k == "scale"]
        if levels and all(k in hold for k in levels):
            hold.remove(levels[0])  # the fold keeps a level
        return tuple(hold)
    return tuple(k for k in spec.free if why.get(k) is not None)
