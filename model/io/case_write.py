"""Design cases as TOML text: the case document (units in key names) and its text.

The inverse of :func:`oilgap.model.io.case_io.case_from_dict`: :func:`case_to_dict`
gives the document, :func:`dumps_toml` its text through
:func:`oilgap.model.io.serialize.toml_dumps` (tomli-w; floats rounded to 6 significant
digits, ``T1_mm = 37.7133``: what the model can claim, and a file a person reads). The
file is written by :func:`oilgap.studies.io.case_write.write_case_toml` (atomically, with
a stamp line); read back, a written case equals the original to the rounding (relative
5e-6 on each key's value).
"""

from __future__ import annotations

import math
from dataclasses import fields
from typing import Any

from ..case import MOTOR_FIELD_TO_KEY, THERMAL_TOML_KEYS, DesignCase, motor_value_in_toml_units
from ..errors import InputError
from ..fluids import Fluid, builtin_gases, gas_key
from ..oils import builtin_oils, normalize_oil_name, read_oils_csv
from ..skin_friction import BRANCH_KEYS
from ..units import MM_TO_M, kelvin_to_celsius
from .case_bearing import BEARING_TABLE, bearing_to_doc
from .case_io import _GAS_CONSTANTS
from .case_linear import linear_to_doc
from .case_uncertainty import UNCERTAINTY_TABLE, uncertainty_to_doc
from .serialize import SIGNIFICANT_DIGITS, toml_dumps


def case_to_dict(case: DesignCase) -> dict:
    """The TOML document (units in key names) of a case; inverse of :func:`case_from_dict`.

    Parameters
    ----------
    case : DesignCase
        The case (SI inside).

    Returns
    -------
    dict
        Tables and keys of the case file, values in the unit of each key (``T1_mm``
        [mm], ``depth_m`` [m]); a custom oil or gas is written out in full, a table
        fluid by the absolute path of its CSV; a mineral oil's ``[oil]`` has no ``kind``.
    """
    mm = 1.0 / MM_TO_M
    r1 = case.region1
    doc: dict[str, Any] = {"name": case.name}
    doc["region1"] = {"T1_mm": r1.T1 * mm, "T2_mm": r1.T2 * mm, "T3_mm": r1.T3 * mm,
                      "T4_mm": r1.T4 * mm, "length_mm": r1.length * mm,
                      "T1_unfilled_mm": r1.T1_unfilled * mm,
                      "T4_unfilled_mm": r1.T4_unfilled * mm}
    if case.region2 is not None:
        r2 = case.region2
        doc["region2"] = {"radius_mm": r2.radius * mm, "length_mm": r2.length * mm,
                          "gap_mm": r2.gap * mm}
    doc["oil"] = _oil_to_dict(case.oil, case.oils_csv)
    doc["operating"] = {"depth_m": case.operating.depth_m,
                        "oil_temp_C": case.operating.oil_temp_C}
    doc["duty_cycle"] = dict(case.duty_cycle.spec)
    f = case.friction
    doc["friction"] = {"form": f.form, "laminar_law": f.laminar_law, "gamma": f.gamma,
                       "scale": f.scale, "C": f.C, "alpha": f.alpha, "beta": f.beta}
    if f.form == "branches":
        doc["friction"].update({k: list(getattr(f, k)) for k in BRANCH_KEYS})
    if f.transition != "reynolds":  # the default is left out: written cases stay as they were
        doc["friction"]["transition"] = f.transition
    md = {}
    for fl in fields(case.motor):
        key = MOTOR_FIELD_TO_KEY.get(fl.name, fl.name)
        md[key] = motor_value_in_toml_units(fl.name, getattr(case.motor, fl.name))
    doc["motor"] = md
    b = case.bounds
    bd = {k + "_mm": getattr(b, k) * mm for k in ("gap_min", "gap_max", "radius_min",
                                                  "radius_max", "length_min", "length_max")}
    bd["inertia_max_ratio"] = b.inertia_max_ratio
    if b.torque_min_Nm is not None:
        bd["torque_min_Nm"] = b.torque_min_Nm
    doc["bounds"] = bd
    if case.thermal is not None:  # only when given: documents of other cases are unchanged
        th = {k: getattr(case.thermal, f) for k, f in THERMAL_TOML_KEYS.items()}
        doc["thermal"] = {k: v for k, v in th.items() if v is not None}
    if case.bearing is not None:  # what the user gave; without one, the document is unchanged
        doc[BEARING_TABLE] = bearing_to_doc(case.bearing)
    if case.uncertainty is not None:  # only when given, like [bearing]
        doc[UNCERTAINTY_TABLE] = uncertainty_to_doc(case.uncertainty)
    if case.linear is not None:  # [drive] kind = "linear": its tables (docs/linear-joint.md)
        doc.update(linear_to_doc(case.linear))
    if case.calibration_model is not None:  # a calibrated loop model, by reference
        doc["calibration"] = {"model": case.calibration_model}
    if case.mission:
        doc["mission"] = [{"depth_m": s.depth_m, s.temp_key: s.oil_temp_C,
                           "fraction": s.fraction} for s in case.mission]
    return doc


def _oil_to_dict(o: Fluid, oils_csv: str | None) -> dict[str, Any]:
    """The [oil] table of a fluid (a mineral oil's is what it was before fluids had kinds)."""
    if o.kind == "gas":
        od: dict[str, Any] = {"kind": "gas", "name": o.name}
        if builtin_gases().get(gas_key(o.name)) != o:
            od.update({k: getattr(o, f) for k, f in _GAS_CONSTANTS.items()})
            lo, hi = o.trusted_range_K
            if lo > 0.0:
                od["trusted_min_C"] = float(kelvin_to_celsius(lo))
            if math.isfinite(hi):
                od["trusted_max_C"] = float(kelvin_to_celsius(hi))
        return od
    if o.kind == "table":
        if o.source is None:
            raise InputError("oil.table_csv", None, f"the table fluid {o.name!r} was not read "
                             "from a CSV file, so it cannot be written to a case file")
        od = {"kind": "table", "name": o.name, "table_csv": o.source}
        if o.outside != "refuse":
            od["outside_table"] = o.outside
        if o.polymer_thickened:
            od["polymer_thickened"] = True
        return od
    od = {"name": o.name}
    if oils_csv:
        od["oils_csv"] = oils_csv
        if o.polymer_thickened != _csv_flag(oils_csv, o.name):
            od["polymer_thickened"] = o.polymer_thickened
    elif builtin_oils().get(normalize_oil_name(o.name)) != o:
        od.update(nu40_cSt=o.nu40_cSt, nu100_cSt=o.nu100_cSt, density_kg_m3=o.density_kg_m3,
                  barus_1_GPa=o.barus_1_Pa * 1e9)
        if o.polymer_thickened:
            od["polymer_thickened"] = True
    return od


def _csv_flag(oils_csv: str, name: str) -> bool:
    """The polymer_thickened flag the oils CSV gives the oil (False if it cannot tell)."""
    try:
        oil = read_oils_csv(oils_csv).get(normalize_oil_name(name))
    except InputError:
        return False
    return bool(oil is not None and oil.polymer_thickened)


def dumps_toml(doc: dict, digits: int = SIGNIFICANT_DIGITS) -> str:
    """The TOML text of a case document (:func:`oilgap.model.io.serialize.toml_dumps`).

    Parameters
    ----------
    doc : dict
        Scalars, tables (dicts) and arrays of tables (lists of dicts), values in
        the units of their keys (``T1_mm`` [mm]).
    digits : int
        Significant digits of the floats [-] (:data:`~oilgap.model.io.serialize.FULL_DIGITS`:
        every digit, the file reads back to the same floats).

    Returns
    -------
    str
        TOML text, floats rounded to ``digits`` significant digits (default 6).
    """
    return toml_dumps(doc, digits)


__all__ = ["case_to_dict", "dumps_toml"]
