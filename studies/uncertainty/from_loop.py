"""A calibrated ``loop.json``'s fitted parameters as the joint law of uncertain inputs.

``oilgap loop`` stores, for its final model (``calibration_with_effect``), each fitted
parameter's 95 % interval (``calibration_with_effect_ci95``: a delete-one-run jackknife
with Student's t on folds - 1 degrees of freedom, the scale's in log space;
:mod:`oilgap.optim.calibration.uncertainty`), each accepted effect's interval
(``effects[].ci_low/ci_high``) and the correlation of the fit's Jacobian columns
(``identifiability.correlations``). It stores no covariance matrix. From these:

============== ================== ===========================================================
loop parameter input              law
============== ================== ===========================================================
``gamma``      ``gamma``          normal: the fitted value, sd = half-width / t
``scale``      ``friction_scale`` lognormal: median = fitted scale / the case's scale,
                                  sigma_ln = half-width of ln(scale) / t (form with a scale)
film_heating   ``film_strength``  normal: the coefficient s, sd = half-width / t (needs the
effect                            case's ``[thermal]``)
============== ================== ===========================================================

with t = t_{0.975, g-1}, g the loop's runs (``per_run``). Correlated by a normal copula:
the parameters' correlation is that of (J^T J)^-1, approximated from the Jacobian
columns' correlation R as the normalised R^-1 (for two parameters, -r). Not mapped, each
named in the spec's notes: ``alpha`` (not an input: fixed by one gap ratio), ``C`` and
``beta`` of a power-law fit, the bearing effects (the library's ball drag and churning
terms are other laws than the case's SKF drag: no ``bearing_drag_scale``) and every
other effect (seal friction, sensor delay... are not inputs of the joint's loss).

References
----------
.. [1] B. Efron, C. Stein, "The jackknife estimate of variance", Ann. Stat. 9 (1981)
   586-596.
.. [2] JCGM 100:2008 (GUM), sec. 5.2 (correlated input quantities).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

import numpy as np
from scipy import stats

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError
from oilgap.model.io.inputs import file_kind
from oilgap.model.uncertain.distributions import Distribution, UncertaintySpec

_CORR = re.compile(r"corr\((\w+), (\w+)\) = ([+-]?\d*\.?\d+)")
_INPUT = {"gamma": "gamma", "scale": "friction_scale", "film_heating": "film_strength"}


def _read(path: str | Path) -> dict:
    p = Path(path)
    if not p.is_file():
        raise InputError("--model", str(p), "must be an existing loop.json (written by "
                         "oilgap loop)")
    try:
        doc = json.loads(p.read_text(encoding="utf-8"))
    except json.JSONDecodeError as e:
        kind = file_kind(p, e.doc)
        if kind in ("CSV", "TOML"):
            raise InputError("--model", str(p), f"is a {kind} file where the loop.json "
                             "written by oilgap loop is expected") from None
        raise InputError("--model", str(p), f"is not JSON ({e})") from None
    except UnicodeDecodeError as e:
        raise InputError("--model", str(p), f"is not JSON ({e})") from None
    if not isinstance(doc, dict) or not isinstance(doc.get("calibration_with_effect"), dict):
        raise InputError("--model", str(p), "a loop.json written by oilgap loop (its "
                         "calibration_with_effect and calibration_with_effect_ci95)")
    return doc


def _interval(ci: Any) -> tuple[float, float] | None:
    if isinstance(ci, list) and len(ci) == 2 and all(isinstance(x, (int, float)) for x in ci) \
            and all(math.isfinite(x) for x in ci) and ci[1] > ci[0]:
        return float(ci[0]), float(ci[1])
    return None


def _correlation(text: str, names: list[str]) -> np.ndarray | None:
    """Parameter correlation of ``names`` (loop parameter names) from the Jacobian
    columns' correlations: the normalised inverse of the columns' matrix."""
    pairs = {(a, b): float(r) for a, b, r in _CORR.findall(text or "")}
    if len(names) < 2 or not pairs:
        return None
    params = sorted({a for a, _ in pairs} | {b for _, b in pairs})
    if not set(names) <= set(params):
        return None
    R = np.eye(len(params))
    for (a, b), r in pairs.items():
        i, j = params.index(a), params.index(b)
        R[i, j] = R[j, i] = r
    try:
        inv = np.linalg.inv(R)
    except np.linalg.LinAlgError:
        return None
    d = np.sqrt(np.diag(inv))
    full = inv / np.outer(d, d)
    np.fill_diagonal(full, 1.0)
    idx = [params.index(n) for n in names]
    return full[np.ix_(idx, idx)]


def loop_uncertainty(path: str | Path, case: DesignCase) -> UncertaintySpec:
    """The joint law of the inputs a calibrated loop fitted.

    Parameters
    ----------
    path : str or Path
        A ``loop.json`` written by ``oilgap loop``.
    case : DesignCase
        The case studied (its friction scale and ``[thermal]``).

    Returns
    -------
    UncertaintySpec
        ``gamma`` [-], ``friction_scale`` [-] and ``film_strength`` [-] where the loop
        fitted them with an interval, normal-copula correlated; its notes name what was
        not mapped and why.

    Raises
    ------
    InputError
        Not a loop.json, or none of its parameters maps to an input.

    References
    ----------
    Efron & Stein [1]_ (the intervals); GUM [2]_ (correlated inputs).
    """
    doc = _read(path)
    fit, cis = doc["calibration_with_effect"], doc.get("calibration_with_effect_ci95", {})
    g = len(doc.get("per_run", []))
    t = float(stats.t.ppf(0.975, g - 1)) if g >= 3 else float(stats.norm.ppf(0.975))
    src = (f"{Path(path).name}: jackknife 95 % interval of the loop's fit / "
           f"t(0.975, {g - 1 if g >= 3 else 'inf'}) = {t:.3f}")
    dists, mapped, notes = [], [], []
    for name, value in fit.items():
        ci = _interval(cis.get(name))
        if name not in ("gamma", "scale") or ci is None:
            notes.append(f"{name}: not mapped (" + ("not an uncertain input of the joint's "
                         "loss" if name not in ("gamma", "scale") else "no interval: not "
                         "identified by the loop") + ")")
            continue
        if name == "gamma":
            d = Distribution(input="gamma", kind="normal", source=src,
                             params=(("mean", float(value)), ("sd", (ci[1] - ci[0]) / (2 * t))))
        elif case.friction.form == "power-law":
            notes.append("scale: not mapped (the case's friction law is a power law: its C, "
                         "not a scale)")
            continue
        else:
            d = Distribution(input="friction_scale", kind="lognormal", source=src, params=(
                ("median", float(value) / case.friction.scale),
                ("sigma_ln", math.log(ci[1] / ci[0]) / (2 * t))))
        dists.append(d)
        mapped.append(name)
    for e in doc.get("effects", []) or []:
        ci = _interval([e.get("ci_low"), e.get("ci_high")])
        if e.get("name") == "film_heating" and ci is not None and case.thermal is not None:
            dists.append(Distribution(input="film_strength", kind="normal", source=src, params=(
                ("mean", float(e["coefficient"])), ("sd", (ci[1] - ci[0]) / (2 * t)))))
        else:
            notes.append(f"effect {e.get('name')}: not mapped ("
                         + ("needs the case's [thermal]" if e.get("name") == "film_heating"
                            else "the library's term is not an input of the joint's loss "
                            "(bearing effects: other laws than the case's SKF drag)") + ")")
    if not dists:
        raise InputError("--model", str(path), "a loop whose fitted gamma or scale has an "
                         "interval (none maps to an uncertain input)")
    corr = _correlation(str(doc.get("identifiability", {}).get("correlations", "")), mapped)
    if corr is not None:
        full = np.eye(len(dists))
        full[:len(mapped), :len(mapped)] = corr
        notes.append("correlation of " + ", ".join(_INPUT[m] for m in mapped) + " from the "
                     "fit's Jacobian columns (normalised inverse of their correlation)")
    return UncertaintySpec(distributions=tuple(dists), source=f"loop {Path(path).name}",
                           correlation=None if corr is None
                           else tuple(tuple(float(x) for x in r) for r in full),
                           notes=tuple(notes))


__all__ = ["loop_uncertainty"]
