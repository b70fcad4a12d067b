"""What the tool filled in: every default a command used, with its value, unit and source.

A case TOML may leave out most tables (``docs/case-file.md``, "Defaults the tool fills
in"); the reader records each value it filled in as a :class:`Default` in
``DesignCase.defaults`` (:func:`reader_defaults`). :func:`case_defaults` adds the ones
that follow from the case itself (gamma from ``gamma_source``, the rolling bearing's
filled-in keys, the NLP's groove-depth bounds) and drops an entry whose value was
changed after reading (``--temp-c``, ``--oil``). The studies add their own (a default
mission, the envelope, the number of points; :func:`study_default`). Every output lists
them the same way: :func:`defaults_lines` for a command's header,
:func:`defaults_block` for the ``defaults`` block of a JSON document and
:func:`defaults_markdown` for a ``summary.md``.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, fields, replace
from typing import TYPE_CHECKING, Any

from ..case import (
    DEFAULT_GAMMA,
    GAMMA_DEFAULT_SOURCE,
    MOTOR_FIELD_TO_KEY,
    DesignBounds,
    Motor,
    OperatingPoint,
    ThermalSpec,
    motor_value_in_toml_units,
)
from ..duty_cycle import DutyCycle
from ..motor import motor_torque
from ..skin_friction import BRANCH_KEYS, FrictionLaw
from ..uncertain.distributions import default_uncertainty
from ..units import MM_TO_M
from .case_bearing import bearing_default_notes, bearing_defaults
from .serialize import round_sig

if TYPE_CHECKING:  # pragma: no cover - typing only
    from ..case import DesignCase

SEED_SOURCE = "the seed joint's"
FILM_STRENGTH_SOURCE = ("the smooth-film theory, used by the film/full modes; the seed's "
                        "Table 4 does not support it at full strength: docs/thermal.md#evidence")
"""Source of the values that stand for the seed joint (motor, operating point, cycle)."""

_MOTOR_UNITS = {"remanence_T": "T", "magnet_thickness_mm": "mm", "recoil_permeability": "-",
                "slot_count": "-", "slot_opening_mm": "mm", "saturation_factor": "-",
                "electric_loading_A_per_m": "A/m", "winding_factor": "-",
                "shaft_bore_radius_mm": "mm", "rotor_density_kg_m3": "kg/m^3",
                "epoxy_density_kg_m3": "kg/m^3", "rotor_groove_solid_fraction": "-",
                "gear_ratio": "-", "gear_efficiency": "-"}
"""Unit of each [motor] key's value."""
_BOUND_RULES = {  # [bounds] key -> (DesignBounds field, rule of DesignBounds.around)
    "gap_min_mm": ("gap_min", "0.5 x the case's gap, at least 1 um"),
    "gap_max_mm": ("gap_max", "2 x the case's gap, at most 0.5 x radius_min"),
    "radius_min_mm": ("radius_min", "0.9 x the case's R"),
    "radius_max_mm": ("radius_max", "1.1 x the case's R, at most 2 m"),
    "length_min_mm": ("length_min", "0.8 x the case's L"),
    "length_max_mm": ("length_max", "1.2 x the case's L, at most 5 m"),
}
_DUTY_UNITS = {"peak_speed_rpm": "rpm", "frequency_hz": "Hz", "duration_s": "s",
               "sample_interval_s": "s"}


@dataclass(frozen=True)
class Default:
    """One value the tool filled in.

    Attributes
    ----------
    field : str
        Where it belongs [-]: the case TOML's ``table.key`` (``motor.remanence_T``,
        ``bounds.gap_min_mm``) or a study's option (``pareto.points``).
    value : float, int, str, bool or None
        The value [``unit``] (None: decided at run time, see ``source``).
    unit : str
        Unit of ``value`` [-] (``"mm"``, ``"degC"``, ``"-"``; ``""`` for a name).
    source : str
        Where the value comes from [-] (``"the seed joint's"``, ``"0.5 x the case's gap"``).
    """

    field: str
    value: Any
    unit: str
    source: str

    def to_dict(self) -> dict[str, Any]:
        """``{field, value, unit, source}`` (value rounded to 6 significant digits)."""
        v = self.value
        if isinstance(v, float):
            v = round_sig(v)
        return {"field": self.field, "value": v, "unit": self.unit, "source": self.source}

    def text(self) -> str:
        """``field = value unit`` (without the source); ``field [unit]`` for a value
        decided at run time (None)."""
        v = self.value
        unit = "" if self.unit in ("", "-") else f" {self.unit}"
        if v is None:
            return f"{self.field}{f' [{self.unit}]' if unit else ''}"
        shown = f"{v:.6g}" if isinstance(v, float) else str(v)
        return f"{self.field} = {shown}{unit}"


def study_default(field: str, value: Any, unit: str, source: str = "default") -> Default:
    """A study's default (its option left out), e.g. ``study_default("pareto.points", 60,
    "-")``.

    Parameters
    ----------
    field : str
        ``study.option``.
    value : float, int, str or tuple
        The value [``unit``]; a tuple becomes the range ``"a..b"``.
    unit : str
        Its unit (``"degC"``, ``"-"`` [-]).
    source : str
        Where it comes from.

    Returns
    -------
    Default
    """
    if isinstance(value, tuple):
        value = "..".join(f"{v:g}" for v in value)
    return Default(field, value, unit, source)


# --------------------------------------------------------------------------- the reader


def reader_defaults(doc: Mapping[str, Any], bounds: DesignBounds, motor: Motor,
                    duty: DutyCycle | None = None, thermal: ThermalSpec | None = None
                    ) -> tuple[Default, ...]:
    """The values :func:`~oilgap.model.io.case_io.case_from_dict` filled in for ``doc``.

    Parameters
    ----------
    doc : mapping
        The parsed case TOML (units in the key names).
    bounds : DesignBounds
        The bounds in use [m] (``DesignBounds.around`` where ``[bounds]`` is left out).
    motor : Motor
        The motor in use [SI].
    duty : DutyCycle, optional
        Unused; the sine's defaults are the signature's of :meth:`DutyCycle.sine`.
    thermal : ThermalSpec, optional
        The heat balance, if the case has ``[thermal]``.

    Returns
    -------
    tuple of Default
        Oil name, operating point, duty cycle, friction form and laminar law, motor
        data, design bounds and ``[thermal]`` keys left out, each with its value [the
        key's unit] and source.
    """
    out: list[Default] = []
    od = doc.get("oil", {})
    if od.get("kind", "mineral") == "mineral" and "name" not in od:
        out.append(Default("oil.name", "VG22", "", f"{SEED_SOURCE} oil"))
    opd = doc.get("operating", {})
    for k, unit in (("depth_m", "m"), ("oil_temp_C", "degC")):
        if k not in opd:
            out.append(Default(f"operating.{k}", float(getattr(OperatingPoint(), k)), unit,
                               f"{SEED_SOURCE} rated point"))
    drive = doc.get("drive", {})
    if isinstance(drive, dict) and drive.get("kind") == "linear":  # the rod's cycle
        from .case_linear import linear_defaults, linear_drive_from
        out += linear_defaults(doc, linear_drive_from(doc))
    else:
        out += _duty_defaults(doc.get("duty_cycle", {}))
    fd = doc.get("friction", {})
    for k in ("form", "laminar_law"):
        if k not in fd:
            out.append(Default(f"friction.{k}", getattr(FrictionLaw(), k), "", "default"))
    if fd.get("form") == "branches":
        for k in BRANCH_KEYS:
            if k not in fd:
                out.append(Default(f"friction.{k}", list(getattr(FrictionLaw(), k)), "-",
                                   "Eq. 6's four branches (Bilgen & Boulos 1973)"))
    md = doc.get("motor", {})
    for f in fields(Motor):
        key = MOTOR_FIELD_TO_KEY.get(f.name, f.name)
        if key not in md:
            v = motor_value_in_toml_units(f.name, getattr(motor, f.name))
            out.append(Default(f"motor.{key}", v if f.name == "slot_count" else float(v),
                               _MOTOR_UNITS.get(key, "-"), f"{SEED_SOURCE} motor"))
    bd = doc.get("bounds", {})
    for key, (attr, rule) in _BOUND_RULES.items():
        if key not in bd:
            out.append(Default(f"bounds.{key}", getattr(bounds, attr) / MM_TO_M, "mm", rule))
    if "inertia_max_ratio" not in bd:
        out.append(Default("bounds.inertia_max_ratio", float(bounds.inertia_max_ratio),
                           "-", "default: 1.05 x the case's unfilled rotor"))
    if "torque_min_Nm" not in bd:
        out.append(Default("bounds.torque_min_Nm", None, "N m",
                           "the case's own torque capability"))
    if thermal is not None:
        td = doc.get("thermal", {})
        for k, unit in (("other_heat_W", "W"), ("walls", "")):
            if k not in td:
                out.append(Default(f"thermal.{k}", getattr(thermal, k), unit, "default"))
        if "film_strength" not in td:
            out.append(Default("thermal.film_strength", 1.0, "", FILM_STRENGTH_SOURCE))
    return tuple(out)


def _duty_defaults(dcd: Mapping[str, Any]) -> list[Default]:
    """The sine's keys left out (none for a CSV cycle)."""
    if dcd.get("kind", "csv" if "csv" in dcd else "sine") != "sine":
        return []
    sig = DutyCycle.sine.__func__.__defaults__  # (peak, frequency, duration, interval)
    return [Default(f"duty_cycle.{k}", float(v), _DUTY_UNITS[k], f"{SEED_SOURCE} sine")
            for k, v in zip(_DUTY_UNITS, sig, strict=True) if k not in dcd]


# --------------------------------------------------------------------------- a case


_CURRENT = {  # field -> its value in the case now (an entry changed since reading is dropped)
    "oil.name": lambda c: c.oil.name,
    "operating.depth_m": lambda c: float(c.operating.depth_m),
    "operating.oil_temp_C": lambda c: float(c.operating.oil_temp_C),
}


def case_defaults(case: DesignCase) -> tuple[Default, ...]:
    """Every default in ``case``: what the reader filled in (still as read), gamma when
    the reader filled it in, the rolling bearing's filled-in keys and the NLP's
    groove-depth bounds (the epoxy fill can only take groove away).

    Parameters
    ----------
    case : DesignCase
        The case (SI inside).

    Returns
    -------
    tuple of Default
        Each with its value in its unit ([mm], [degC], [-] ...).
    """
    out = [_torque_valued(d, case) for d in getattr(case, "defaults", ())
           if d.field not in _CURRENT or _CURRENT[d.field](case) == d.value]
    if case.gamma_source == GAMMA_DEFAULT_SOURCE:
        out.append(Default("friction.gamma", float(DEFAULT_GAMMA), "-", GAMMA_DEFAULT_SOURCE))
    r1 = case.region1
    fill = "the machined depth: the epoxy fill only removes groove"
    for name, depth in (("rotor", r1.T2 - r1.T1_unfilled), ("stator", r1.T4_unfilled - r1.T3)):
        out.append(Default(f"design.{name}_groove_depth_mm", f"0..{depth / MM_TO_M:.6g}",
                           "mm", fill))
    if case.bearing is not None:
        notes = dict(_note(n) for n in bearing_default_notes(case.bearing))
        for k, v in bearing_defaults(case.bearing).items():
            out.append(Default(f"bearing.{k}", v, _key_unit(k), notes.get(k, "default")))
    return tuple(out)


def _torque_valued(d: Default, case: DesignCase) -> Default:
    """The torque bound's default with its value: the case's own torque capability [N m]
    (:func:`oilgap.model.motor.motor_torque` at the case's R, delta and L)."""
    if d.field != "bounds.torque_min_Nm" or d.value is not None:
        return d
    r1 = case.region1
    tau = float(motor_torque(case.motor, r1.T2, r1.gap, r1.length)[0])
    return replace(d, value=tau)


def _note(line: str) -> tuple[str, str]:
    """``"key = value (basis)"`` -> (key, basis)."""
    key = line.split("=", 1)[0].strip()
    basis = line[line.find("(") + 1:line.rfind(")")] if "(" in line else "default"
    return key, basis


def _key_unit(key: str) -> str:
    for suffix, unit in (("_mm", "mm"), ("_N", "N"), ("_Nm", "N m")):
        if key.endswith(suffix):
            return unit
    return "-"


def uncertainty_defaults(case: DesignCase) -> tuple[Default, ...]:
    """The uncertain inputs' laws filled in when the case has no ``[uncertainty]`` table.

    Listed by the commands that use them (``oilgap study uncertainty``, the robust
    design), not by every command: a nominal number does not use them.

    Parameters
    ----------
    case : DesignCase
        The case (``case.uncertainty``; its gamma centres gamma's law).

    Returns
    -------
    tuple of Default
        ``uncertainty.nu40_factor = uniform(low = 0.9, high = 1.1)`` (ISO 3448),
        ``uncertainty.nu100_factor = uniform(low = 0.95, high = 1.05)`` (the VI) and
        ``uncertainty.gamma = normal(mean = 0.566, sd = 0.041)`` [-] (the seed fit), each
        with its source; empty when the case declares its own.
    """
    if case.uncertainty is not None:
        return ()
    return tuple(Default(f"uncertainty.{d.input}", d.text(), "", d.source)
                 for d in default_uncertainty(case).distributions)


# --------------------------------------------------------------------------- outputs


def defaults_block(defaults: Iterable[Default]) -> list[dict[str, Any]]:
    """The ``defaults`` block of a JSON document.

    Parameters
    ----------
    defaults : iterable of Default

    Returns
    -------
    list of dict
        One ``{field, value, unit, source}`` per default (value in its unit [mm],
        [degC], [-] ..., rounded to 6 significant digits).
    """
    return [d.to_dict() for d in defaults]


def _pieces(defaults: Iterable[Default]) -> list[str]:
    """``a = 1 mm,`` ... ``b = 2 mm (source);``: each entry, the source after the last of
    a run of entries with the same source."""
    ds = list(defaults)
    out = []
    for i, d in enumerate(ds):
        last = i + 1 == len(ds) or ds[i + 1].source != d.source
        out.append(d.text() + (f" ({d.source});" if last else ","))
    return out


def defaults_lines(defaults: Iterable[Default], width: int = 100) -> list[str]:
    """The header lines of a command.

    Parameters
    ----------
    defaults : iterable of Default
    width : int
        Wrap at this many characters [-].

    Returns
    -------
    list of str
        ``defaults    <field> = <value> <unit> (<source>); ...`` (values in their units
        [mm, degC, -, ...]; entries of one source share it), continuation lines indented;
        ``defaults    none (every value given)`` when empty.
    """
    pieces = _pieces(defaults)
    if not pieces:
        return ["defaults    none (every value given)"]
    lines, cur = [], "defaults   "
    for p in pieces:
        if len(cur) + 1 + len(p) > width and cur.strip() != "defaults":
            lines.append(cur)
            cur = " " * 11
        cur += " " + p
    lines.append(cur.rstrip(";"))
    return lines


def defaults_markdown(defaults: Iterable[Default]) -> list[str]:
    """A ``summary.md`` section.

    Parameters
    ----------
    defaults : iterable of Default

    Returns
    -------
    list of str
        ``## Defaults the tool filled in`` and one bullet per default (value in its unit
        [mm, degC, -, ...]) with its source.
    """
    ds = list(defaults)
    if not ds:
        return ["## Defaults the tool filled in", "", "None: every value was given."]
    return (["## Defaults the tool filled in", ""]
            + [f"- `{d.text()}` ({d.source})" for d in ds])


def gamma_fields(case: DesignCase) -> dict[str, Any]:
    """The groove exponent in use and where it came from, for a JSON document's top level.

    Parameters
    ----------
    case : DesignCase
        The case computed.

    Returns
    -------
    dict
        ``gamma`` [-] (Eq. 8's exponent) and ``gamma_source`` ("case", "default (seed
        rig fit)", "given").
    """
    return {"gamma": float(case.friction.gamma), "gamma_source": case.gamma_source}


def gamma_line(case: DesignCase) -> str:
    """The header line naming gamma and its source (every command that uses a case).

    Parameters
    ----------
    case : DesignCase
        The case computed.

    Returns
    -------
    str
        ``gamma       0.566 (groove exponent of Eq. 8, ...; from: <source>)``, gamma [-].
    """
    return (f"gamma       {case.friction.gamma:g} (groove exponent of Eq. 8, T^gamma on "
            f"region 1; from: {case.gamma_source})")


__all__ = ["Default", "SEED_SOURCE", "case_defaults", "defaults_block", "defaults_lines",
           "defaults_markdown", "gamma_fields", "gamma_line", "reader_defaults",
           "study_default", "uncertainty_defaults"]
