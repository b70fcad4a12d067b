"""The linear actuator's tables of a case file: ``[drive]``, ``[screw]``, ``[rod]``,
``[passages]``, ``[compensator]`` and the rod's duty cycle.

``[drive] kind = "linear"`` makes the case a linear actuator (``"rotary"``, the default,
keeps today's joint and refuses the linear tables). The duty cycle is the rod's velocity
over time, a sine (``peak_velocity_m_s``, ``frequency_hz``, ``duration_s``,
``sample_interval_s``) or a CSV with ``time_s`` and ``rod_velocity_m_s`` or
``rod_position_m``; the motor's speed follows from the lead, ``omega = 2 pi v/lead``, and
becomes the case's :class:`~oilgap.model.duty_cycle.DutyCycle`. Every key is checked and
refused with its name; units are in the key names (docs/linear-joint.md lists them).

References
----------
.. [1] docs/linear-joint.md (the keys, their units and defaults).
"""

from __future__ import annotations

import csv
import io
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from ..duty_cycle import MAX_SPEED_RPM, SPEED_REASON, DutyCycle
from ..errors import InputError, check_finite, check_positive
from ..linear.drive import Compensator, LinearDrive
from ..linear.laws import motor_speed
from ..units import MM_TO_M, rad_s_to_rpm, rpm_to_rad_s
from .inputs import cell_for_message, check_physical, header_error, read_input_text

LINEAR_TABLES = {
    "drive": {"kind", "stroke_mm", "required_force_N", "max_motor_speed_rpm"},
    "screw": {"lead_mm", "pitch_diameter_mm", "type", "f0", "efficiency", "lead_min_mm",
              "lead_max_mm"},
    "rod": {"diameter_mm", "guide_length_mm", "guide_clearance_mm", "eccentricity",
            "guide_clearance_min_mm", "guide_clearance_max_mm"},
    "passages": {"count", "diameter_mm", "length_mm", "max_velocity_m_s", "diameter_min_mm",
                 "diameter_max_mm"},
    "compensator": {"capacity_mL", "oil_volume_mL", "temp_min_C", "temp_max_C"},
}
"""Tables of a linear case and their keys."""
LINEAR_DUTY_KEYS = {"kind", "peak_velocity_m_s", "frequency_hz", "duration_s",
                    "sample_interval_s", "csv"}
"""``[duty_cycle]`` keys of a linear case."""
DRIVE_KINDS = ("rotary", "linear")
"""``[drive] kind`` values."""


def _table(doc: dict, name: str) -> dict:
    t = doc.get(name, {})
    if not isinstance(t, dict):
        raise InputError(name, cell_for_message(t), f"must be a table [{name}]", "case TOML")
    bad = [k for k in t if k not in LINEAR_TABLES.get(name, LINEAR_DUTY_KEYS)]
    if bad:
        allowed = sorted(LINEAR_TABLES.get(name, LINEAR_DUTY_KEYS))
        raise InputError(f"{name}.{bad[0]}", cell_for_message(t[bad[0]]),
                         f"unknown key; allowed keys: {', '.join(allowed)}", "case TOML")
    return t


def _num(t: dict, key: str, where: str, default: Any = "required") -> Any:
    if key not in t:
        if default == "required":
            raise InputError(f"{where}.{key}", None, "is required", "case TOML")
        return default
    return check_finite(key, t[key], where)


def _mm(t: dict, key: str, where: str, default: Any = "required") -> Any:
    v = _num(t, key, where, default)
    return v if v is None or key not in t else v * MM_TO_M


def drive_kind(doc: dict) -> str:
    """``[drive] kind`` of a parsed case (``"rotary"`` without ``[drive]``).

    Parameters
    ----------
    doc : dict
        The parsed TOML.

    Returns
    -------
    str
        One of :data:`DRIVE_KINDS`.

    Raises
    ------
    InputError
        An unknown kind, or linear tables in a rotary case.
    """
    kind = _table(doc, "drive").get("kind", "rotary")
    if kind not in DRIVE_KINDS:
        raise InputError("drive.kind", cell_for_message(kind),
                         f"one of {', '.join(DRIVE_KINDS)}", "case TOML")
    if kind == "rotary":
        extra = [t for t in LINEAR_TABLES if t in doc and t != "drive"]
        extra += [k for k in doc.get("drive", {}) if k != "kind"]
        if extra:
            raise InputError(extra[0], "given", 'only with [drive] kind = "linear"',
                             "case TOML")
    return kind


def linear_drive_from(doc: dict) -> LinearDrive:
    """The :class:`~oilgap.model.linear.drive.LinearDrive` of a linear case's tables.

    Parameters
    ----------
    doc : dict
        The parsed TOML (units in the key names: ``lead_mm`` [mm]).

    Returns
    -------
    LinearDrive
        The drive [SI].

    Raises
    ------
    InputError
        An unknown or missing key, or a value out of range (named).
    """
    dr, sc, rod, pa = (_table(doc, n) for n in ("drive", "screw", "rod", "passages"))
    comp = None
    if "compensator" in doc:
        ct = _table(doc, "compensator")
        comp = Compensator(capacity_m3=_num(ct, "capacity_mL", "compensator") / 1e6,
                           oil_volume_m3=_num(ct, "oil_volume_mL", "compensator") / 1e6,
                           temp_min_C=_num(ct, "temp_min_C", "compensator"),
                           temp_max_C=_num(ct, "temp_max_C", "compensator"))
    count = pa.get("count", 1)
    if isinstance(count, bool) or not isinstance(count, int):
        raise InputError("count", cell_for_message(count), "an integer >= 0", "passages")
    stype = sc.get("type", "ball")
    max_rpm = _num(dr, "max_motor_speed_rpm", "drive", None)
    drive = LinearDrive(
        lead_m=_mm(sc, "lead_mm", "screw"),
        screw_pitch_diameter_m=_mm(sc, "pitch_diameter_mm", "screw"),
        screw_type=str(stype), screw_f0=_num(sc, "f0", "screw", None),
        screw_efficiency=_num(sc, "efficiency", "screw", None),
        rod_diameter_m=_mm(rod, "diameter_mm", "rod"),
        guide_length_m=_mm(rod, "guide_length_mm", "rod"),
        guide_clearance_m=_mm(rod, "guide_clearance_mm", "rod"),
        eccentricity=_num(rod, "eccentricity", "rod", 0.0),
        passage_count=count, passage_diameter_m=_mm(pa, "diameter_mm", "passages"),
        passage_length_m=_mm(pa, "length_mm", "passages"),
        passage_velocity_limit_m_s=_num(pa, "max_velocity_m_s", "passages", 3.0),
        stroke_m=_mm(dr, "stroke_mm", "drive"),
        required_force_N=_num(dr, "required_force_N", "drive", None),
        max_motor_speed_rad_s=None if max_rpm is None else rpm_to_rad_s(max_rpm),
        compensator=comp)
    return replace(drive, design_bounds=design_ranges(doc, drive))


def design_ranges(doc: dict, drive: LinearDrive) -> tuple[tuple[float, float], ...]:
    """Bounds of the linear design variables [m]: given, or x[0.5, 2] of the case's.

    Parameters
    ----------
    doc : dict
        The parsed TOML (``lead_min_mm`` ... [mm]).
    drive : LinearDrive
        The drive as given.

    Returns
    -------
    tuple
        (lo, hi) [m] of the lead, the guide clearance and the passage diameter.
    """
    out = []
    for table, key, value in (("screw", "lead", drive.lead_m),
                              ("rod", "guide_clearance", drive.guide_clearance_m),
                              ("passages", "diameter", drive.passage_diameter_m)):
        t = doc.get(table, {})
        lo = _num(t, f"{key}_min_mm", table, None)
        hi = _num(t, f"{key}_max_mm", table, None)
        lo = 0.5 * value if lo is None else check_positive(f"{key}_min_mm", lo, table) * MM_TO_M
        hi = 2.0 * value if hi is None else check_positive(f"{key}_max_mm", hi, table) * MM_TO_M
        if hi < lo:
            raise InputError(f"{key}_max_mm", hi / MM_TO_M, f"must be >= {key}_min_mm = "
                             f"{lo / MM_TO_M:g}", table)
        out.append((lo, hi))
    return tuple(out)


def _rod_csv(path: Path) -> tuple[np.ndarray, np.ndarray, str]:
    """(time [s], rod velocity [m/s], column) of a rod duty-cycle CSV."""
    text = read_input_text(path, "duty_cycle.csv", "CSV file")
    reader = csv.DictReader(io.StringIO(text, newline=""))
    cols = [c.strip() for c in (reader.fieldnames or [])]
    col = "rod_position_m" if "rod_position_m" in cols else "rod_velocity_m_s"
    err = header_error(path, cols, ("time_s", col))
    if err is not None:
        raise err
    reader.fieldnames = cols
    t, x = [], []
    for i, row in enumerate(reader, start=2):
        rw = f"{path} line {i}"
        t.append(check_finite("time_s", cell_for_message(row["time_s"]), rw))
        x.append(check_finite(col, cell_for_message(row[col]), rw))
    if len(t) < 3:
        raise InputError("rows", len(t), "a rod duty cycle needs at least 3 samples", str(path))
    t_arr, x_arr = np.asarray(t), np.asarray(x)
    if np.any(np.diff(t_arr) <= 0):
        i = int(np.nonzero(np.diff(t_arr) <= 0)[0][0]) + 1
        raise InputError("time_s", t[i], f"must increase strictly (line {i + 2})", str(path))
    if col == "rod_position_m":  # second-order central differences inside
        return t_arr, np.gradient(x_arr, t_arr), col
    return t_arr, x_arr, col


def _excursion(t: np.ndarray, v: np.ndarray) -> float:
    """Range of the rod's position over the cycle [m] (trapezoidal integral of v)."""
    x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))])
    return float(x.max() - x.min())


def linear_duty_cycle(dcd: dict, drive: LinearDrive, base_dir: Path) -> DutyCycle:
    """The motor's duty cycle of a rod's: ``omega = 2 pi v/lead`` at every sample.

    Parameters
    ----------
    dcd : dict
        The ``[duty_cycle]`` table: ``kind = "sine"`` with ``peak_velocity_m_s`` [m/s],
        ``frequency_hz`` [Hz], ``duration_s`` [s], ``sample_interval_s`` [s], or
        ``kind = "csv"`` with ``csv`` (``time_s`` and ``rod_velocity_m_s`` or
        ``rod_position_m``).
    drive : LinearDrive
        The drive (lead, stroke).
    base_dir : Path
        Directory of a relative CSV path.

    Returns
    -------
    DutyCycle
        Motor speed [rad/s] against time [s]; ``spec`` holds the rod's cycle as given.

    Raises
    ------
    InputError
        A bad key or value, a motor speed above the duty cycle's limit, or a rod
        excursion longer than the stroke (named).
    """
    dcd = dict(_table({"duty_cycle": dcd}, "duty_cycle"))
    kind = dcd.pop("kind", "csv" if "csv" in dcd else "sine")
    where = "duty_cycle"
    if kind == "sine":
        if "csv" in dcd:
            raise InputError("duty_cycle.csv", dcd["csv"], 'only with kind = "csv"', "case TOML")
        v = check_positive("peak_velocity_m_s", _num(dcd, "peak_velocity_m_s", where), where)
        f = check_positive("frequency_hz", dcd.get("frequency_hz", 0.05), where)
        rpm = rad_s_to_rpm(motor_speed(v, drive.lead_m))
        check_physical("peak_velocity_m_s", v, 0.0, MAX_SPEED_RPM / rpm * v,
                       f"the motor would turn faster than {MAX_SPEED_RPM:g} rpm at this lead "
                       f"({SPEED_REASON})", where)
        rest = {k: dcd[k] for k in ("duration_s", "sample_interval_s") if k in dcd}
        cyc = DutyCycle.sine(peak_speed_rpm=rpm, frequency_hz=f, **rest)
        excursion, peak_v = v / (3.141592653589793 * f), v
        spec = {"kind": "sine", "peak_velocity_m_s": v, "frequency_hz": f,
                **{k: cyc.spec[k] for k in ("duration_s", "sample_interval_s")}}
        desc = f"rod {v:g} m/s * sin(2 pi {f:g} Hz t) -> motor {rpm:.4g} rpm peak"
    elif kind == "csv":
        extra = [k for k in dcd if k != "csv"]
        if extra:
            raise InputError("duty_cycle." + extra[0], dcd[extra[0]],
                             'a csv duty cycle takes only csv = "path"', "case TOML")
        if "csv" not in dcd:
            raise InputError("duty_cycle.csv", None, "is required", "case TOML")
        p = Path(str(dcd["csv"]))
        p = p if p.is_absolute() else base_dir / p
        t, vel, col = _rod_csv(p)
        w = motor_speed(vel, drive.lead_m)
        bad = np.abs(rad_s_to_rpm(w)) > MAX_SPEED_RPM
        if bad.any():
            raise InputError(col, float(vel[np.argmax(bad)]), f"the motor would turn faster "
                             f"than {MAX_SPEED_RPM:g} rpm at this lead ({SPEED_REASON})", str(p))
        if not np.any(w != 0.0):
            raise InputError(col, 0.0, "the rod never moves: no loss to evaluate", str(p))
        cyc = DutyCycle(t, w)
        excursion, peak_v = _excursion(t, vel), float(np.max(np.abs(vel)))
        spec = {"kind": "csv", "csv": str(p)}
        desc = f"rod {p.name} ({col}), {len(t)} samples"
    else:
        raise InputError("duty_cycle.kind", kind, "allowed: sine, csv", "case TOML")
    if excursion > drive.stroke_m * (1.0 + 1e-9):
        raise InputError("stroke_mm", drive.stroke_m / MM_TO_M, f"the duty cycle moves the "
                         f"rod over {excursion / MM_TO_M:.4g} mm (peak {peak_v:g} m/s); give "
                         "a longer stroke or a shorter cycle", "drive")
    return replace(cyc, description=desc, spec=spec)


def linear_to_doc(drive: LinearDrive) -> dict[str, dict]:
    """The linear tables of a drive, units in the key names (inverse of
    :func:`linear_drive_from`).

    Parameters
    ----------
    drive : LinearDrive
        The drive [SI].

    Returns
    -------
    dict
        ``drive``, ``screw``, ``rod``, ``passages`` (and ``compensator``) tables.
    """
    mm = 1.0 / MM_TO_M
    doc: dict[str, dict] = {
        "drive": {"kind": "linear", "stroke_mm": drive.stroke_m * mm},
        "screw": {"lead_mm": drive.lead_m * mm,
                  "pitch_diameter_mm": drive.screw_pitch_diameter_m * mm,
                  "type": drive.screw_type, "f0": drive.screw_f0,
                  "efficiency": drive.screw_efficiency},
        "rod": {"diameter_mm": drive.rod_diameter_m * mm,
                "guide_length_mm": drive.guide_length_m * mm,
                "guide_clearance_mm": drive.guide_clearance_m * mm,
                "eccentricity": drive.eccentricity},
        "passages": {"count": drive.passage_count, "diameter_mm": drive.passage_diameter_m * mm,
                     "length_mm": drive.passage_length_m * mm,
                     "max_velocity_m_s": drive.passage_velocity_limit_m_s}}
    (a, b), (c, d), (e, f) = drive.design_bounds or ((None, None),) * 3
    if a is not None:
        doc["screw"].update(lead_min_mm=a * mm, lead_max_mm=b * mm)
        doc["rod"].update(guide_clearance_min_mm=c * mm, guide_clearance_max_mm=d * mm)
        doc["passages"].update(diameter_min_mm=e * mm, diameter_max_mm=f * mm)
    if drive.required_force_N is not None:
        doc["drive"]["required_force_N"] = drive.required_force_N
    if drive.max_motor_speed_rad_s is not None:
        doc["drive"]["max_motor_speed_rpm"] = rad_s_to_rpm(drive.max_motor_speed_rad_s)
    c = drive.compensator
    if c is not None:
        doc["compensator"] = {"capacity_mL": c.capacity_m3 * 1e6,
                              "oil_volume_mL": c.oil_volume_m3 * 1e6,
                              "temp_min_C": c.temp_min_C, "temp_max_C": c.temp_max_C}
    return doc


def linear_defaults(doc: dict, drive: LinearDrive) -> list:
    """The linear keys the reader filled in, each with its value and source.

    Parameters
    ----------
    doc : dict
        The parsed TOML of a linear case.
    drive : LinearDrive
        The drive read from it.

    Returns
    -------
    list of oilgap.model.io.defaults.Default
        ``screw.f0`` [-], ``screw.efficiency`` [-], ``rod.eccentricity`` [-],
        ``passages.count`` [-], ``passages.max_velocity_m_s`` [m/s], the design bounds
        [mm] and the rod sine's keys [Hz, s] left out.
    """
    from .defaults import Default
    out = []
    rows = (("screw", "f0", drive.screw_f0, "-", f"a submerged {drive.screw_type} nut, "
             "Palmgren's f0 of a submerged bearing (recalled; docs/linear-joint.md)"),
            ("screw", "efficiency", drive.screw_efficiency, "-",
             f"catalogue range of a {drive.screw_type} screw (recalled)"),
            ("rod", "eccentricity", drive.eccentricity, "-", "a concentric rod"),
            ("passages", "count", drive.passage_count, "-", "one passage"),
            ("passages", "max_velocity_m_s", drive.passage_velocity_limit_m_s, "m/s",
             "return-line practice (recalled)"))
    for table, key, value, unit, source in rows:
        if key not in doc.get(table, {}):
            out.append(Default(f"{table}.{key}", value, unit, source))
    for (lo, hi), table, key in zip(drive.design_bounds or (), ("screw", "rod", "passages"),
                                    ("lead", "guide_clearance", "diameter"), strict=False):
        for k, v, what in ((f"{key}_min_mm", lo, "0.5"), (f"{key}_max_mm", hi, "2")):
            if k not in doc.get(table, {}):
                out.append(Default(f"{table}.{k}", v / MM_TO_M, "mm",
                                   f"{what} x the case's {key.replace('_', ' ')}"))
    dcd = doc.get("duty_cycle", {})
    if dcd.get("kind", "csv" if "csv" in dcd else "sine") == "sine":
        for k, v, unit in (("frequency_hz", 0.05, "Hz"), ("duration_s", 300.0, "s"),
                           ("sample_interval_s", 0.2, "s")):
            if k not in dcd:
                out.append(Default(f"duty_cycle.{k}", v, unit, "the seed joint's sine"))
    return out
