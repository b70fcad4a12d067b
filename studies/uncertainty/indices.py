"""Sobol' sensitivity indices through SALib: the Saltelli design and its analysis.

Variance-based global sensitivity: the first-order index S_i = V[E(Y | X_i)] / V(Y) is
the share of the output's variance that input i explains alone, the total index
ST_i = E[V(Y | X_~i)] / V(Y) its share with every interaction it enters [1]_. They are
estimated from a Saltelli design [2]_ (``SALib.sample.sobol``: a scrambled Sobol'
sequence of dimension 2d split into matrices A and B, and the d matrices A_B^(i) that
take column i from B; N (d + 2) evaluations without second-order indices) by Saltelli's
first-order and Jansen's total estimators (``SALib.analyze.sobol``), each with a
bootstrap confidence interval. SALib [3]_ is the field's reference implementation of these
estimators (and of Morris, FAST, DGSM); oilgap calls it rather than re-deriving them.

:func:`sobol_indices` works on any vectorised function of the unit hypercube: the
uncertainty study composes the joint's loss with the inputs' inverse CDFs
(:meth:`oilgap.model.uncertain.distributions.UncertaintySpec.transform`); the tests use
the Ishigami function and a linear model, whose indices are known in closed form.

References
----------
.. [1] I. M. Sobol', "Global sensitivity indices for nonlinear mathematical models and
   their Monte Carlo estimates", Math. Comput. Simul. 55 (2001) 271-280.
.. [2] A. Saltelli et al., "Variance based sensitivity analysis of model output. Design
   and estimator for the total sensitivity index", Comput. Phys. Commun. 181 (2010)
   259-270; A. Saltelli et al., *Global Sensitivity Analysis. The Primer*, Wiley 2008.
.. [3] J. Herman, W. Usher, "SALib: An open-source Python library for Sensitivity
   Analysis", J. Open Source Softw. 2(9) (2017) 97; T. Iwanaga, W. Usher, J. Herman,
   Socio-Environmental Systems Modelling 4 (2022) 18155.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Sequence

import numpy as np
import pandas as pd

from oilgap.model.errors import InputError

try:  # a dependency of oilgap (pyproject.toml); a broken install gets one line, not a trace
    from SALib.analyze import sobol as _analyze
    from SALib.sample import sobol as _sample
except ImportError:  # pragma: no cover - SALib is installed with oilgap
    _analyze = _sample = None

SALIB_MISSING = ("SALib is not installed: the Sobol' indices need it "
                 "(pip install 'SALib>=1.5', or --no-sobol for the percentiles alone)")


def _salib():
    """``(SALib.sample.sobol, SALib.analyze.sobol)``, or one InputError line."""
    if _sample is None or _analyze is None:
        raise InputError("SALib", "missing", SALIB_MISSING)
    return _sample, _analyze


def _problem(names: Sequence[str]) -> dict:
    return {"num_vars": len(names), "names": list(names), "bounds": [[0.0, 1.0]] * len(names)}


def saltelli_points(names: Sequence[str], n: int, seed: int = 0) -> np.ndarray:
    """The Saltelli design on the unit hypercube (``SALib.sample.sobol.sample``).

    Parameters
    ----------
    names : sequence of str
        The d inputs [-].
    n : int
        Base points N [-] (a power of 2).
    seed : int
        Seed of the Sobol' sequence's scrambling [-].

    Returns
    -------
    numpy.ndarray, shape (N (d + 2), d)
        Points in [0, 1]^d [-], in SALib's order (no second-order indices).

    References
    ----------
    Saltelli et al. (2010) [2]_.
    """
    sample, _ = _salib()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # SALib's notes on its own sampler's defaults
        return sample.sample(_problem(names), int(n), calc_second_order=False,
                             scramble=True, seed=int(seed))


def analyse(names: Sequence[str], y: np.ndarray, confidence: float = 0.95,
            seed: int = 0) -> pd.DataFrame:
    """First-order and total indices of outputs on a Saltelli design.

    Parameters
    ----------
    names : sequence of str
        The d inputs [-].
    y : array, shape (N (d + 2),)
        The outputs on :func:`saltelli_points` [any unit].
    confidence : float
        Level of the bootstrap intervals [-].
    seed : int
        Seed of the bootstrap [-] (SALib gets ``seed + 1``: it leaves a seed of 0
        unseeded). The intervals repeat run to run.

    Returns
    -------
    pandas.DataFrame
        One row per input: ``S1``, ``S1_low``, ``S1_high``, ``ST``, ``ST_low``,
        ``ST_high`` [-] (the interval: SALib's estimate -+ its bootstrap half-width).

    References
    ----------
    Sobol' (2001) [1]_; Saltelli et al. (2010) [2]_; SALib [3]_.
    """
    _, analyze = _salib()
    y = np.asarray(y, dtype=float)
    if not np.all(np.isfinite(y)):
        raise InputError("loss", f"{int(np.sum(~np.isfinite(y)))} failed evaluations",
                         "a finite loss at every point of the Saltelli design")
    if np.ptp(y) == 0.0:
        raise InputError("loss", f"{y[0]:g} at every point", "an output that varies (no "
                         "input moves it: the indices are undefined)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        # SALib seeds its bootstrap only for a truthy seed (``if seed:``): seed + 1
        si = analyze.analyze(_problem(names), y, calc_second_order=False, num_resamples=200,
                             conf_level=float(confidence), print_to_console=False,
                             seed=int(seed) + 1)
    out = pd.DataFrame({"input": list(names)})
    for k in ("S1", "ST"):
        est, half = np.asarray(si[k], dtype=float), np.asarray(si[f"{k}_conf"], dtype=float)
        out[k], out[f"{k}_low"], out[f"{k}_high"] = est, est - half, est + half
    return out


def sobol_indices(fun: Callable[[np.ndarray], np.ndarray], names: Sequence[str], n: int,
                  seed: int = 0, confidence: float = 0.95) -> pd.DataFrame:
    """Sobol' first-order and total indices of a function of the unit hypercube.

    Parameters
    ----------
    fun : callable
        ``fun(u) -> y``: u of shape (m, d) in [0, 1]^d [-], y of shape (m,) [any unit]
        (compose the inputs' inverse CDFs inside).
    names : sequence of str
        The d inputs [-].
    n : int
        Base points N of the Saltelli design [-] (a power of 2; N (d + 2) evaluations).
    seed : int
        Seed of the design's scrambling and of the bootstrap [-].
    confidence : float
        Level of the intervals [-].

    Returns
    -------
    pandas.DataFrame
        :func:`analyse` of ``fun`` on :func:`saltelli_points`, plus ``evaluations`` [-].

    References
    ----------
    Sobol' (2001) [1]_; Saltelli et al. (2010) [2]_; SALib [3]_.
    """
    u = saltelli_points(names, n, seed)
    y = np.asarray(fun(u), dtype=float).reshape(-1)
    out = analyse(names, y, confidence, seed)
    out["evaluations"] = len(y)
    return out


__all__ = ["SALIB_MISSING", "analyse", "saltelli_points", "sobol_indices"]
