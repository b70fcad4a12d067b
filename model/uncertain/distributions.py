"""Distributions of the uncertain inputs and quasi-Monte Carlo samples of them.

A :class:`Distribution` is one input's law (normal, lognormal, uniform or triangular,
parameters in the input's unit); an :class:`UncertaintySpec` is the joint law of the
inputs declared uncertain (independent, or normal-copula correlated when a calibrated
``loop.json`` supplies a covariance) with where it came from.
:meth:`UncertaintySpec.sample` draws scrambled Sobol' points [1]_ (``scipy.stats.qmc.Sobol``)
on the unit hypercube and maps each coordinate through the input's inverse CDF (closed
forms [3]_); :meth:`UncertaintySpec.transform` does the mapping alone (the uncertainty
study feeds it SALib's Saltelli points).

:func:`case_uncertainty` is the case's ``[uncertainty]`` table or, without one, the
documented defaults (:func:`default_uncertainty`):

- ``nu40_factor`` uniform on 0.9..1.1: ISO 3448 [2]_ lets a grade's kinematic viscosity at
  40 degC lie within +-10 % of its midpoint; it gives the band, not a law inside it, and
  the uniform law is the least-informative one on a bounded band. It acts on nu40 alone
  (the Walther line rebuilt, :mod:`.grade`).
- ``nu100_factor`` uniform on 0.95..1.05: the viscosity index's spread. For the seed's
  VG22 (22/4.5 cSt, VI 118 by ASTM D2270 [4]_) the band spans VI 98 to 129: from a
  straight mineral oil (VI about 100 and below) to the modified mineral oils' 125-150
  [5]_. A fluid without a Walther line (a gas, a table) takes
  ``nu_factor_all_temperatures`` uniform 0.9..1.1 instead.
- ``gamma`` normal, sd 0.041 around the case's gamma: the seed rig fit of
  ``oilgap study smoothing`` (0.566 +- 0.041).

Lognormal parameters: the median (in the input's unit) and ``sigma_ln``, the standard
deviation of ln x [-] (scipy's ``lognorm(s=sigma_ln, scale=median)``); the geometric
standard deviation is exp(sigma_ln).

References
----------
.. [1] Owen, A. B., "Scrambling Sobol' and Niederreiter-Xing points", J. Complexity 14
   (1998) 466-489; scipy.stats.qmc.Sobol.
.. [2] ISO 3448:1992, industrial liquid lubricants, ISO viscosity classification
   (each grade's kinematic viscosity at 40 degC within +-10 % of its midpoint).
.. [3] N. L. Johnson, S. Kotz, N. Balakrishnan, *Continuous Univariate Distributions*,
   2nd ed., Wiley 1994-95 (normal, lognormal, uniform, triangular).
.. [4] ASTM D2270-10, calculating viscosity index from kinematic viscosity at 40 and
   100 degC (Table 1, procedures A and B).
.. [5] tribology-abc.com, ISO 3448 / viscosity index calculator notes: "the VI of
   conventional mineral oils roughly ranges between 0 and 100, for modified mineral oils
   between 125 and 150" (http://www.tribology-abc.com/calculators/iso_3348.htm).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from scipy import special

from ..errors import InputError
from .inputs import INPUTS

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase

KINDS: dict[str, tuple[str, ...]] = {
    "normal": ("mean", "sd"),
    "lognormal": ("median", "sigma_ln"),
    "uniform": ("low", "high"),
    "triangular": ("low", "mode", "high"),
}
"""Each kind of distribution and its parameters, in order [-]."""

RANGES: dict[str, tuple[float, float]] = {
    "nu40_factor": (0.0, math.inf), "nu100_factor": (0.0, math.inf),
    "nu_factor_all_temperatures": (0.0, math.inf), "oil_temp_C": (-40.0, 200.0),
    "depth_m": (0.0, 11000.0),
    "gamma": (0.0, 3.0), "friction_scale": (0.0, math.inf), "film_strength": (0.0, math.inf),
    "bearing_drag_scale": (0.0, math.inf), "peak_speed_rpm": (0.0, math.inf),
    "groove_exponent_scale": (0.0, 1.0),
}
"""Where each input may lie [its unit]: a distribution reaching outside is refused
(:meth:`Distribution.reach`)."""
TAIL = 1e-9
"""Probability clipped at either end by :meth:`Distribution.ppf` [-] (a normal's mean
+- 6.0 sd): no sample lies beyond."""

_LOCATION_SUFFIX = {"oil_temp_C": "_C", "depth_m": "_m", "peak_speed_rpm": "_rpm"}
_SPREAD_SUFFIX = {"oil_temp_C": "_K", "depth_m": "_m", "peak_speed_rpm": "_rpm"}

ISO3448_SOURCE = ("ISO 3448's +-10 % band on a grade's nu40, uniform over it (the standard "
                  "gives the band, not a law inside it)")
VI_SOURCE = ("the viscosity index's spread: nu100 +-5 % spans VI 98-129 for VG22 (ASTM "
             "D2270), straight mineral (VI ~100) to modified mineral oils (125-150)")
ALL_TEMPERATURES_SOURCE = ("ISO 3448's +-10 % band taken at every temperature (the fluid has "
                           "no Walther line to carry a tolerance on nu40)")
GAMMA_SD = 0.041
"""Standard deviation of gamma from the seed rig fit (``oilgap study smoothing``) [-]."""
GAMMA_SOURCE = "the seed rig fit, `oilgap study smoothing`: 0.566 +- 0.041"


def param_key(name: str, param: str) -> str:
    """The case-file key of one parameter, its unit in the name.

    Parameters
    ----------
    name : str
        The input (:data:`~oilgap.model.uncertain.inputs.INPUTS`).
    param : str
        ``mean``, ``sd``, ``median``, ``sigma_ln``, ``low``, ``mode`` or ``high``.

    Returns
    -------
    str
        ``mean_C`` / ``sd_K`` for ``oil_temp_C``, ``low_m`` for ``depth_m``, ``mean_rpm``
        for ``peak_speed_rpm``; the bare name for a factor or exponent [-] and for
        ``sigma_ln`` [-] (a spread of ln x has no unit).
    """
    if param == "sigma_ln":
        return param
    table = _SPREAD_SUFFIX if param == "sd" else _LOCATION_SUFFIX
    return param + table.get(name, "")


@dataclass(frozen=True, kw_only=True)
class Distribution:
    """One uncertain input's law.

    Attributes
    ----------
    input : str
        The input (:data:`~oilgap.model.uncertain.inputs.INPUTS`) [-].
    kind : str
        ``normal``, ``lognormal``, ``uniform`` or ``triangular`` [-].
    params : tuple of (str, float)
        The kind's parameters (:data:`KINDS`) in the input's unit ([degC], [m], [rpm]
        or [-]; ``sd`` of a temperature [K]; ``sigma_ln`` [-]).
    source : str
        Where the law comes from [-] (``"case [uncertainty]"``, a standard, a fit).
    """

    input: str
    kind: str
    params: tuple[tuple[str, float], ...]
    source: str = "case [uncertainty]"

    def __post_init__(self):
        where = f"uncertainty.{self.input}"
        if self.input not in INPUTS:
            raise InputError("uncertainty", self.input, f"an input: one of {', '.join(INPUTS)}",
                             "case TOML")
        if self.kind not in KINDS:
            raise InputError(f"{where}.dist", self.kind, f"one of {', '.join(KINDS)}",
                             "case TOML")
        p = dict(self.params)
        if set(p) != set(KINDS[self.kind]):
            raise InputError(where, sorted(p), f"a {self.kind} law takes "
                             f"{', '.join(param_key(self.input, k) for k in KINDS[self.kind])}",
                             "case TOML")
        object.__setattr__(self, "params", tuple((k, float(p[k])) for k in KINDS[self.kind]))
        self._check()

    def __getitem__(self, param: str) -> float:
        return dict(self.params)[param]

    def _bad(self, param: str, allowed: str):
        return InputError(f"uncertainty.{self.input}.{param_key(self.input, param)}",
                          self[param], allowed, "case TOML")

    def _check(self) -> None:
        p = dict(self.params)
        for k, v in p.items():
            if not math.isfinite(v):
                raise self._bad(k, "a finite number")
        if self.kind == "normal" and p["sd"] <= 0.0:
            raise self._bad("sd", "> 0 (a fixed value is the case's own, not an uncertainty)")
        if self.kind == "lognormal":
            if p["sigma_ln"] <= 0.0:
                raise self._bad("sigma_ln", "> 0 (the sd of ln x)")
            if p["median"] <= 0.0:
                raise self._bad("median", "> 0 (a lognormal lies on x > 0)")
        if self.kind in ("uniform", "triangular") and p["low"] >= p["high"]:
            raise self._bad("low", f"< high = {p['high']:g}")
        if self.kind == "triangular" and not p["low"] <= p["mode"] <= p["high"]:
            raise self._bad("mode", f"within low..high = {p['low']:g}..{p['high']:g}")
        lo, hi = RANGES[self.input]
        a, b = self.reach()
        if a < lo or b > hi:
            unit = INPUTS[self.input].unit
            raise InputError(f"uncertainty.{self.input}", self.text(),
                             f"a law within {lo:g}..{hi:g} {unit} (it reaches "
                             f"{a:.4g}..{b:.4g} between its 1e-9 and 1 - 1e-9 quantiles)",
                             "case TOML")

    def reach(self) -> tuple[float, float]:
        """Where the law lies [the input's unit]: its support; a normal's or lognormal's
        quantiles at :data:`TAIL` and 1 - :data:`TAIL` (about 6 sd from the middle), where
        :meth:`ppf` clips its probabilities."""
        if self.kind in ("normal", "lognormal"):
            a, b = self.ppf([TAIL, 1.0 - TAIL])
            return float(a), float(b)
        return self["low"], self["high"]

    def ppf(self, u):
        """Inverse CDF, vectorised (closed forms: the normal's through ``ndtri``).

        Parameters
        ----------
        u : float or array_like
            Probabilities in [0, 1] [-] (clipped to [:data:`TAIL`, 1 - :data:`TAIL`] so
            that a normal's tails stay finite and within :meth:`reach`).

        Returns
        -------
        numpy.ndarray
            The quantiles [the input's unit].

        References
        ----------
        N. L. Johnson, S. Kotz, N. Balakrishnan, *Continuous Univariate Distributions*,
        Wiley 1994-95 (normal, lognormal, uniform, triangular).
        """
        u = np.clip(np.asarray(u, dtype=float), TAIL, 1.0 - TAIL)
        p = dict(self.params)
        if self.kind == "normal":
            return p["mean"] + p["sd"] * special.ndtri(u)
        if self.kind == "lognormal":
            return p["median"] * np.exp(p["sigma_ln"] * special.ndtri(u))
        a, b = p["low"], p["high"]
        if self.kind == "uniform":
            return a + (b - a) * u
        c = p["mode"]
        fc = (c - a) / (b - a)
        return np.where(u < fc, a + np.sqrt(u * (b - a) * (c - a)),
                        b - np.sqrt((1.0 - u) * (b - a) * (b - c)))

    @property
    def mean(self) -> float:
        """The law's mean [the input's unit]."""
        p = dict(self.params)
        if self.kind == "normal":
            return p["mean"]
        if self.kind == "lognormal":
            return p["median"] * math.exp(0.5 * p["sigma_ln"] ** 2)
        if self.kind == "uniform":
            return 0.5 * (p["low"] + p["high"])
        return (p["low"] + p["mode"] + p["high"]) / 3.0

    @property
    def sd(self) -> float:
        """The law's standard deviation [the input's unit]."""
        p = dict(self.params)
        if self.kind == "normal":
            return p["sd"]
        if self.kind == "lognormal":
            return self.mean * math.sqrt(math.expm1(p["sigma_ln"] ** 2))
        if self.kind == "uniform":
            return (p["high"] - p["low"]) / math.sqrt(12.0)
        a, c, b = p["low"], p["mode"], p["high"]
        return math.sqrt((a * a + b * b + c * c - a * b - a * c - b * c) / 18.0)

    def text(self) -> str:
        """``normal(mean_C = 2, sd_K = 1.5)``: the kind and its keys with their values."""
        inner = ", ".join(f"{param_key(self.input, k)} = {v:.6g}" for k, v in self.params)
        return f"{self.kind}({inner})"

    def to_dict(self) -> dict[str, Any]:
        """``{input, unit, dist, <key>: value ..., source}``, keys as in the case file
        (``unit``: the input's; a temperature's ``sd_K`` in K)."""
        return {"input": self.input, "unit": INPUTS[self.input].unit, "dist": self.kind,
                **{param_key(self.input, k): v for k, v in self.params}, "source": self.source}


@dataclass(frozen=True, kw_only=True)
class UncertaintySpec:
    """The joint law of the uncertain inputs.

    Attributes
    ----------
    distributions : tuple of Distribution
        One per uncertain input, in the order of sampling [-].
    source : str
        Where the set comes from [-] (``"case [uncertainty]"``, ``"defaults"``, a
        ``loop.json``).
    correlation : tuple of tuple of float, optional
        Correlation matrix of the inputs' normal scores (a normal copula; None:
        independent). With normal marginals the joint law is the multivariate normal
        with these correlations [-].
    notes : tuple of str
        What was mapped and what not (a ``loop.json``'s parameters) [-].
    """

    distributions: tuple[Distribution, ...]
    source: str = "case [uncertainty]"
    correlation: tuple[tuple[float, ...], ...] | None = None
    notes: tuple[str, ...] = field(default=())

    def __post_init__(self):
        names = [d.input for d in self.distributions]
        if not names:
            raise InputError("uncertainty", "{}", "at least one uncertain input", "case TOML")
        if len(set(names)) != len(names):
            raise InputError("uncertainty", names, "each input once", "case TOML")
        if self.correlation is not None:
            c = np.asarray(self.correlation, dtype=float)
            if c.shape != (len(names),) * 2 or not np.allclose(c, c.T) \
                    or not np.allclose(np.diag(c), 1.0):
                raise InputError("uncertainty.correlation", c.tolist(),
                                 "a symmetric matrix with unit diagonal, one row per input")
            try:
                np.linalg.cholesky(c)
            except np.linalg.LinAlgError:
                raise InputError("uncertainty.correlation", c.tolist(),
                                 "positive definite") from None

    @property
    def names(self) -> tuple[str, ...]:
        """The uncertain inputs, in order [-]."""
        return tuple(d.input for d in self.distributions)

    def __getitem__(self, name: str) -> Distribution:
        return {d.input: d for d in self.distributions}[name]

    def transform(self, u) -> dict[str, np.ndarray]:
        """Map points of the unit hypercube to input values.

        Parameters
        ----------
        u : array_like, shape (n, d)
            Points in [0, 1]^d [-], one column per input in :attr:`names`' order.

        Returns
        -------
        dict
            Input name -> array of n values [the input's unit]. With a correlation the
            columns are first made normal scores z = Phi^-1(u), correlated by the
            Cholesky factor (z L^T) and mapped back (Phi) before each inverse CDF.
        """
        u = np.atleast_2d(np.asarray(u, dtype=float))
        if u.shape[1] != len(self.distributions):
            raise InputError("u", u.shape, f"an array of shape (n, {len(self.distributions)})")
        if self.correlation is not None:
            z = special.ndtri(np.clip(u, TAIL, 1.0 - TAIL))
            u = special.ndtr(z @ np.linalg.cholesky(np.asarray(self.correlation)).T)
        return {d.input: d.ppf(u[:, j]) for j, d in enumerate(self.distributions)}

    def unit_sample(self, n: int, seed: int = 0) -> np.ndarray:
        """``n`` scrambled Sobol' points in [0, 1)^d (``scipy.stats.qmc.Sobol``) [-].

        scipy.stats is imported here, not at the top: it costs about a second that every
        command reading a case (``oilgap evaluate``) would otherwise pay.
        """
        from scipy.stats import qmc

        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
            raise InputError("samples", n, "a whole number >= 1 (a power of 2 is balanced)")
        sob = qmc.Sobol(d=len(self.distributions), scramble=True, seed=seed)
        m = int(n).bit_length() - 1
        if 2 ** m == n:
            return sob.random_base2(m)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # "balance properties" for n != 2^m
            return sob.random(int(n))

    def sample(self, n: int, seed: int = 0) -> dict[str, np.ndarray]:
        """``n`` quasi-random draws of the inputs.

        Parameters
        ----------
        n : int
            Number of draws [-] (a power of 2 keeps the Sobol' points balanced).
        seed : int
            Seed of the scrambling [-].

        Returns
        -------
        dict
            Input name -> array of n values [the input's unit] (:meth:`transform` of
            :meth:`unit_sample`).
        """
        return self.transform(self.unit_sample(n, seed))

    def to_dict(self) -> dict[str, Any]:
        """``{source, inputs: [...], correlation, notes}`` for JSON documents."""
        return {"source": self.source, "inputs": [d.to_dict() for d in self.distributions],
                "correlation": None if self.correlation is None
                else [list(r) for r in self.correlation], "notes": list(self.notes)}


def default_uncertainty(case: DesignCase) -> UncertaintySpec:
    """The documented defaults: ISO 3448's band on nu40, the VI's on nu100, gamma's spread.

    Parameters
    ----------
    case : DesignCase
        The case (its gamma is the centre of gamma's law).

    Returns
    -------
    UncertaintySpec
        ``nu40_factor`` uniform 0.9..1.1 [-] (ISO 3448 [2]_), ``nu100_factor`` uniform
        0.95..1.05 [-] (the viscosity index [4]_ [5]_) and ``gamma`` normal with the case's
        gamma as mean and sd 0.041 [-] (the seed fit); for a fluid without a Walther line
        ``nu_factor_all_temperatures`` uniform 0.9..1.1 in place of the first two.
    """
    from .grade import has_walther_line

    g = float(case.friction.gamma)
    src = GAMMA_SOURCE if g == 0.566 else f"sd of {GAMMA_SOURCE}, around the case's gamma"
    band = (("low", 0.9), ("high", 1.1))
    oil = ((Distribution(input="nu40_factor", kind="uniform", params=band,
                         source=ISO3448_SOURCE),
            Distribution(input="nu100_factor", kind="uniform",
                         params=(("low", 0.95), ("high", 1.05)), source=VI_SOURCE))
           if has_walther_line(case.oil) else
           (Distribution(input="nu_factor_all_temperatures", kind="uniform", params=band,
                         source=ALL_TEMPERATURES_SOURCE),))
    return UncertaintySpec(distributions=(
        *oil,
        Distribution(input="gamma", kind="normal", params=(("mean", g), ("sd", GAMMA_SD)),
                     source=src),
    ), source="defaults (the case has no [uncertainty] table)")


def case_uncertainty(case: DesignCase) -> UncertaintySpec:
    """The case's uncertain inputs: its ``[uncertainty]`` table, else the defaults.

    Parameters
    ----------
    case : DesignCase
        The case (``case.uncertainty``, read from the case file).

    Returns
    -------
    UncertaintySpec
        The joint law [the inputs' units] (:func:`default_uncertainty` without a table).
    """
    spec = getattr(case, "uncertainty", None)
    return spec if spec is not None else default_uncertainty(case)


__all__ = ["Distribution", "KINDS", "RANGES", "UncertaintySpec", "case_uncertainty",
           "default_uncertainty", "param_key"]
