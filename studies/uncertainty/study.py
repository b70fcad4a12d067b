"""Uncertainty study: the joint's mean loss as a distribution, and what drives it.

The inputs declared uncertain (the case's ``[uncertainty]`` table, its documented
defaults, or a calibrated ``loop.json``'s fit: :mod:`oilgap.model.uncertain.distributions`,
:mod:`.from_loop`) are propagated through the vectorised joint loss
(:func:`oilgap.model.uncertain.arrays.joint_loss_arrays`, the same number as
``evaluate_case`` of each scenario's case) three ways:

* **Percentiles.** ``samples`` scrambled Sobol' points (``scipy.stats.qmc.Sobol``, a
  sample of its own, not the Saltelli design) mapped through the inputs' inverse CDFs:
  the loss's mean, sd and 5th/50th/95th percentiles [W] (empirical quantiles of the
  quasi-random sample) and its histogram.
* **Tornado.** Each input at its own 5th and 95th percentiles with every other input at
  the case's nominal value: the loss's swing per input [W] (one-at-a-time, so it shows
  the direction and size of each input's effect; interactions are the Sobol' table's).
* **Sobol' indices.** First-order and total, with bootstrap intervals, from a Saltelli
  design of ``sobol_samples`` base points through SALib (:mod:`.indices`).

Film strength declared uncertain: the film strength acts only where the film's own shear
heating is modelled, so the study runs under the film counterpart of the default mode
(``none`` -> ``film``, ``bulk`` -> ``full``), where s = 0 reproduces the default mode
exactly: "somewhere between none and the smooth-film theory" becomes s in [0, 1].

References
----------
.. [1] A. B. Owen, "Scrambling Sobol' and Niederreiter-Xing points", J. Complexity 14
   (1998) 466-489 (the quasi-Monte Carlo sample).
.. [2] A. Saltelli et al., *Global Sensitivity Analysis. The Primer*, Wiley 2008
   (the indices, the tornado as a one-at-a-time screening).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.defaults import (
    Default,
    case_defaults,
    study_default,
    uncertainty_defaults,
)
from oilgap.model.joint_loss import resolve_thermal_mode
from oilgap.model.thermal_modes import applies_film, film_counterpart
from oilgap.model.uncertain.arrays import joint_loss_arrays
from oilgap.model.uncertain.distributions import UncertaintySpec, case_uncertainty
from oilgap.model.uncertain.grade import carried_text, has_walther_line
from oilgap.model.uncertain.inputs import INPUTS, nominal_inputs
from oilgap.optim.progress import report
from oilgap.studies.settings import (
    DEFAULT_SOBOL_SAMPLES,
    DEFAULT_UNCERTAINTY_SAMPLES,
    UncertaintySettings,
)
from oilgap.studies.uncertainty.indices import sobol_indices
from oilgap.studies.uncertainty.report import write_outputs

PERCENTILES = (5.0, 50.0, 95.0)
"""The loss's percentiles reported [%]."""
TORNADO_LEVELS = (0.05, 0.95)
"""Each input's probability levels of the tornado [-]."""


@dataclass(frozen=True, eq=False, kw_only=True)
class UncertaintyResult:
    """Everything the uncertainty study computes.

    Attributes
    ----------
    case_name : str
        The case's name [-].
    spec : UncertaintySpec
        The uncertain inputs' joint law used.
    settings : UncertaintySettings
        Samples, seed, confidence, thermal mode asked for.
    thermal_mode : str
        The thermal mode of every evaluation [-].
    thermal_default : bool
        Whether it is the default (not chosen by the caller).
    nominal_W : float
        The loss at the case's own inputs [W].
    samples : pandas.DataFrame
        The quasi-random sample: one column per input [its unit] and ``loss_W`` [W].
    statistics : pandas.DataFrame
        ``statistic`` (mean, sd, p5, p50, p95, nominal) and ``loss_W`` [W].
    tornado : pandas.DataFrame
        Per input: its values at the 5th and 95th percentiles [its unit], the loss there
        ``loss_low_W``/``loss_high_W`` [W] and ``swing_W`` [W], largest swing first.
    sobol : pandas.DataFrame or None
        Per input: ``S1``, ``ST`` and their interval bounds [-] (None with
        ``sobol=False``).
    failed : int
        Points of the percentile sample whose loss could not be computed [-].
    elapsed_s : float
        Wall time of the study [s].
    files : tuple of Path
        Files written (empty without ``out_dir``).
    defaults : tuple of Default
        What the tool filled in (the case's, the uncertain inputs', the study's).
    carried : tuple of str
        What the bands on nu40 and nu100 give at the case's oil temperature (ISO 3448's
        tolerance carried by the Walther line, :func:`~oilgap.model.uncertain.grade.
        carried_text`).
    """

    case_name: str
    spec: UncertaintySpec
    settings: UncertaintySettings
    thermal_mode: str
    thermal_default: bool
    nominal_W: float
    samples: pd.DataFrame
    statistics: pd.DataFrame
    tornado: pd.DataFrame
    sobol: pd.DataFrame | None
    failed: int = 0
    elapsed_s: float = float("nan")
    files: tuple[Path, ...] = ()
    defaults: tuple = ()
    carried: tuple = ()

    def statistic(self, name: str) -> float:
        """One statistic of the loss [W] (``"p95"``, ``"mean"``...)."""
        s = self.statistics.set_index("statistic")["loss_W"]
        return float(s[name])


def study_mode(case: DesignCase, spec: UncertaintySpec, thermal: str | None
               ) -> tuple[str, bool]:
    """The thermal mode of the study and whether it is the default.

    Parameters
    ----------
    case : DesignCase
    spec : UncertaintySpec
    thermal : str or None
        The mode asked for (None: the default).

    Returns
    -------
    (str, bool)
        The mode [-]: the asked one, else the case's default, or its film counterpart
        (``film``, ``full``) when ``film_strength`` is uncertain; and whether defaulted.

    Raises
    ------
    InputError
        ``film_strength`` uncertain under an asked mode without the film (none, bulk).
    """
    mode = resolve_thermal_mode(case, thermal)
    if "film_strength" in spec.names:
        if thermal is None and not applies_film(mode):
            mode = film_counterpart(mode)
        elif not applies_film(mode):
            raise InputError("thermal", thermal, "film or full: film_strength is uncertain "
                             "and acts only where the film's heating is modelled",
                             "uncertainty study")
    return mode, thermal is None


def mode_why(case: DesignCase, spec: UncertaintySpec, mode: str, default: bool) -> str | None:
    """Why a defaulted mode is what it is, when it is not the case's default: the film
    counterpart because ``film_strength`` is uncertain (None otherwise).

    Parameters
    ----------
    case : DesignCase
    spec : UncertaintySpec
    mode : str
        The study's mode [-].
    default : bool
        Whether it was defaulted.

    Returns
    -------
    str or None
        The text for the header's ``thermal`` line.
    """
    base = resolve_thermal_mode(case, None)
    if not default or mode == base:
        return None
    return (f"film_strength is uncertain, so the film counterpart of the default {base}; "
            f"s = 0 gives {base} exactly")


def _loss(case: DesignCase, values: dict[str, np.ndarray], mode: str) -> np.ndarray:
    return np.asarray(joint_loss_arrays(case, values, mode), dtype=float).reshape(-1)


def _statistics(y: np.ndarray, nominal: float) -> pd.DataFrame:
    ok = y[np.isfinite(y)]
    if not len(ok):
        raise InputError("loss", "no finite value", "at least one scenario that evaluates",
                         "uncertainty study")
    rows = [("mean", float(ok.mean())), ("sd", float(ok.std(ddof=1)) if len(ok) > 1 else 0.0)]
    rows += [(f"p{p:g}", float(np.percentile(ok, p))) for p in PERCENTILES]
    rows.append(("nominal", float(nominal)))
    return pd.DataFrame(rows, columns=["statistic", "loss_W"])


def _tornado(case: DesignCase, spec: UncertaintySpec, mode: str,
             nominal: dict[str, float]) -> pd.DataFrame:
    names = spec.names
    lo = {n: float(spec[n].ppf(TORNADO_LEVELS[0])) for n in names}
    hi = {n: float(spec[n].ppf(TORNADO_LEVELS[1])) for n in names}
    k = len(names)
    values = {n: np.full(2 * k, nominal[n]) for n in names}
    for i, n in enumerate(names):
        values[n][i], values[n][k + i] = lo[n], hi[n]
    y = _loss(case, values, mode)
    df = pd.DataFrame({"input": names, "unit": [INPUTS[n].unit for n in names],
                       "value_low": [lo[n] for n in names],
                       "value_high": [hi[n] for n in names],
                       "loss_low_W": y[:k], "loss_high_W": y[k:]})
    df["swing_W"] = (df["loss_high_W"] - df["loss_low_W"]).abs()
    return df.sort_values("swing_W", ascending=False, ignore_index=True)


def study_defaults(case: DesignCase, settings: UncertaintySettings) -> tuple[Default, ...]:
    """The case's defaults, the uncertain inputs' default laws and the study's own
    (samples, Sobol' base points when left at their defaults).

    Parameters
    ----------
    case : DesignCase
    settings : UncertaintySettings

    Returns
    -------
    tuple of Default
    """
    out = [*case_defaults(case), *uncertainty_defaults(case)]
    if settings.samples == DEFAULT_UNCERTAINTY_SAMPLES:
        out.append(study_default("uncertainty.samples", settings.samples, "-",
                                 "default: 2^13 scrambled Sobol' points"))
    if settings.sobol and settings.sobol_samples == DEFAULT_SOBOL_SAMPLES:
        out.append(study_default("uncertainty.sobol_samples", settings.sobol_samples, "-",
                                 "default: Saltelli base points N, N (d + 2) evaluations"))
    return tuple(out)


def run(out_dir: str | Path | None = None, case: DesignCase | None = None,
        settings: UncertaintySettings | None = None,
        spec: UncertaintySpec | None = None) -> UncertaintyResult:
    """Propagate the uncertain inputs through the joint's loss.

    Parameters
    ----------
    out_dir : str or Path, optional
        Folder for the CSVs, figures and ``summary.md`` (None: no file).
    case : DesignCase, optional
        The joint (default: the seed joint).
    settings : UncertaintySettings, optional
        Samples, seed, thermal mode, confidence, Sobol' on/off.
    spec : UncertaintySpec, optional
        The inputs' joint law (default: :func:`case_uncertainty`, the case's
        ``[uncertainty]`` table or the documented defaults).

    Returns
    -------
    UncertaintyResult
        Percentiles and moments of the loss [W], the tornado [W], the Sobol' indices [-].

    References
    ----------
    Owen (1998) [1]_; Saltelli et al. (2008) [2]_.
    """
    t0 = time.perf_counter()
    case = case if case is not None else seed_case()
    settings = settings if settings is not None else UncertaintySettings()
    spec = spec if spec is not None else case_uncertainty(case)
    mode, default = study_mode(case, spec, settings.thermal)
    nom = nominal_inputs(case)
    nominal = float(_loss(case, {n: np.array([nom[n]]) for n in spec.names}, mode)[0])
    task = "uncertainty: samples, Sobol', files"
    report(task, 0, 3)
    x = spec.sample(settings.samples, settings.seed)
    y = _loss(case, x, mode)
    samples = pd.DataFrame(x).assign(loss_W=y)
    report(task, 1, 3)
    sobol = None
    if settings.sobol:
        sobol = sobol_indices(lambda u: _loss(case, spec.transform(u), mode), spec.names,
                              settings.sobol_samples, settings.seed, settings.confidence)
    report(task, 2, 3)
    result = UncertaintyResult(
        case_name=case.name, spec=spec, settings=settings, thermal_mode=mode,
        thermal_default=default, nominal_W=nominal, samples=samples,
        statistics=_statistics(y, nominal), tornado=_tornado(case, spec, mode, nom),
        sobol=sobol, failed=int(np.sum(~np.isfinite(y))),
        elapsed_s=time.perf_counter() - t0, defaults=study_defaults(case, settings),
        carried=_carried(case, spec))
    if out_dir is not None:
        files = write_outputs(Path(out_dir), result)
        object.__setattr__(result, "files", files)
    report(task, 3, 3)
    return result


def _carried(case: DesignCase, spec) -> tuple[str, ...]:
    """The bands on nu40/nu100 (their laws' reach) carried to the case's oil temperature."""
    bands = {n: spec[n].reach() for n in ("nu40_factor", "nu100_factor") if n in spec.names}
    if not bands or not has_walther_line(case.oil):
        return ()
    op = case.operating
    return tuple(carried_text(case.oil, float(op.oil_temp_C), bands, float(op.depth_m)))


__all__ = ["PERCENTILES", "UncertaintyResult", "mode_why", "run", "study_defaults",
           "study_mode"]
