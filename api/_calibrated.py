"""A calibrated loop model applied to a design case: the file read here, at the top, and
the case folded by the one pure function
:func:`oilgap.optim.calibration.calibrated_case.calibrate_case`. Every command's
``--model loop.json`` and the façade's ``model=`` go through :func:`with_model`."""

from __future__ import annotations

import json
import warnings
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from oilgap.model.case import DesignCase
from oilgap.model.errors import OilgapWarning
from oilgap.optim.calibration.calibrated_case import CalibratedCase, calibrate_case
from oilgap.studies.loop.model_file import read_model


def model_provenance(path: str | Path) -> dict:
    """Path, fit date (the file's time), data and base of a ``loop.json``.

    Parameters
    ----------
    path : str or Path
        The model file (already checked by :func:`with_model`).

    Returns
    -------
    dict
        ``path``, ``fitted`` (ISO date-time, UTC), ``data`` (source and runs), ``base``.
    """
    p = Path(path)
    doc = json.loads(p.read_text(encoding="utf-8"))
    data = doc.get("data") if isinstance(doc.get("data"), dict) else {}
    when = datetime.fromtimestamp(p.stat().st_mtime, UTC).strftime("%Y-%m-%d %H:%M UTC")
    return {"path": str(p), "fitted": when,
            "data": f"{data.get('source', '?')} ({data.get('oil_runs', '?')} oil runs, "
                    f"{data.get('kind', '?')})", "base": doc.get("base", "?")}


def with_model(case: DesignCase, model: Any
               ) -> tuple[DesignCase, CalibratedCase | None]:
    """The case with the calibrated model of ``model`` folded in (unchanged without one).

    Parameters
    ----------
    case : DesignCase
    model : path, FittedModel, fitted og.Loop or None
        A ``loop.json`` (checked against its schema; refused with one line otherwise) or
        a model in memory; None: the case's own ``[calibration] model``, if any.

    Returns
    -------
    (DesignCase, CalibratedCase or None)
        The case to compute with, and what was carried (None without a model). Outside
        the model's fitted domain an :class:`~oilgap.model.errors.OilgapWarning` names
        each variable with both ranges.
    """
    given = "--model" if model is not None else "[calibration] model"
    model = model if model is not None else case.calibration_model
    if model is None:
        return case, None
    plain = replace(case, calibration_model=None)  # the reference is resolved once, here
    if isinstance(model, (str, Path)):
        fitted, pv = read_model(model), model_provenance(model)
    else:  # a FittedModel or a fitted og.Loop, in memory
        fitted = model.fitted_model() if hasattr(model, "fitted_model") else model
        pv = {"path": "(in memory)", "fitted": "-", "data": "-", "base": "-"}
    cal = replace(calibrate_case(plain, fitted), provenance=pv)
    for line in cal.domain:
        warnings.warn(OilgapWarning(f"{given} {model}: the case lies outside the model's "
                                    f"domain: {line}"), stacklevel=2)
    return cal.case, cal


def model_lines(cal: CalibratedCase | None, calibrated_W: float | None = None,
                uncalibrated_W: float | None = None, what: str = "loss") -> list[str]:
    """The lines every output prints about the model it used (empty without one).

    Parameters
    ----------
    cal : CalibratedCase or None
    calibrated_W, uncalibrated_W : float, optional
        The loss with the model and without it [W] (printed side by side).
    what : str
        What that loss is (e.g. "the given design's loss").

    Returns
    -------
    list of str
    """
    if cal is None:
        return []
    pv = cal.provenance
    out = [f"model       {pv.get('path')} (fitted {pv.get('fitted')}; data {pv.get('data')}; "
           f"base {pv.get('base')})"]
    out += [f"            carried: {c}" for c in cal.carried]
    out += [f"            not carried: {n}: {why}" for n, why in cal.not_carried]
    out += [f"            outside the model's domain: {d}" for d in cal.domain]
    if calibrated_W is not None and uncalibrated_W is not None:
        out.append(f"            {what} {calibrated_W:.4g} W calibrated, {uncalibrated_W:.4g} W "
                   "uncalibrated (the case's own law)")
    return out


def model_record(cal: CalibratedCase | None, calibrated_W: float | None = None,
                 uncalibrated_W: float | None = None) -> dict | None:
    """:func:`model_lines` as a JSON object (None without a model)."""
    if cal is None:
        return None
    return {**cal.provenance, "carried": list(cal.carried),
            "not_carried": [{"effect": n, "reason": why} for n, why in cal.not_carried],
            "outside_domain": list(cal.domain),
            **({"loss_calibrated_W": calibrated_W, "loss_uncalibrated_W": uncalibrated_W}
               if calibrated_W is not None else {})}
