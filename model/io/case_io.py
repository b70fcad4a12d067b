"""Design cases as TOML: read and validate, and the seed joint.

The TOML file carries units in its key names (``T1_mm``, ``depth_m``,
``peak_speed_rpm``); :func:`case_from_dict` converts them to the SI dataclasses
of :mod:`oilgap.model.case` and :func:`oilgap.model.io.case_write.case_to_dict` back
(:mod:`oilgap.model.io.case_write` writes case files). Every key is listed
with its unit and default in ``docs/case-file.md``; the ``[oil]`` keys of each kind of
fluid (``kind = "mineral" | "table" | "gas"``) in ``docs/fluids.md``.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Table 1 (the joint's geometry) and Eq. 9.
"""

from __future__ import annotations

import tomllib
import warnings
from dataclasses import replace
from importlib import resources
from pathlib import Path
from typing import Any

from ..case import (
    DEFAULT_GAMMA,
    GAMMA_DEFAULT_SOURCE,
    MISSION_TEMP_KEYS,
    MOTOR_TOML_KEYS,
    THERMAL_TOML_KEYS,
    BearingClearance,
    DesignBounds,
    DesignCase,
    MissionSegment,
    Motor,
    OperatingPoint,
    RotorStatorClearance,
    ThermalSpec,
)
from ..duty_cycle import DutyCycle
from ..errors import InputError, OilgapWarning, check_finite, check_range
from ..fluids import FLUID_KINDS, Fluid, GasFluid, builtin_gases, gas_key, read_fluid_table
from ..oils import Oil, get_oil, read_oils_csv, with_builtin
from ..skin_friction import BRANCH_KEYS, FrictionLaw, check_friction_ranges
from ..units import MM_TO_M, celsius_to_kelvin
from .case_bearing import BEARING_TABLE, bearing_from_doc
from .case_linear import LINEAR_TABLES, drive_kind, linear_drive_from, linear_duty_cycle
from .case_uncertainty import UNCERTAINTY_TABLE, uncertainty_from_doc
from .defaults import reader_defaults
from .inputs import cell_for_message, file_kind, read_input_text

MAX_CASE_BYTES = 16 * 2**20
"""Largest case TOML file read [bytes] (16 MiB; the seed's is under 2 kB)."""

# --------------------------------------------------------------------------- TOML schema

_MM = "mm"
_TOP_KEYS = {"name"}
_TABLES = {
    "region1": {"T1_mm", "T2_mm", "T3_mm", "T4_mm", "length_mm", "T1_unfilled_mm",
                "T4_unfilled_mm"},
    "region2": {"radius_mm", "length_mm", "gap_mm"},
    "oil": set(),  # the union of _OIL_KEYS, filled in below
    "operating": {"depth_m", "oil_temp_C"},
    "duty_cycle": {"kind", "peak_speed_rpm", "frequency_hz", "duration_s", "sample_interval_s",
                   "csv"},
    "friction": {"form", "laminar_law", "transition", "gamma", "scale", "C", "alpha", "beta",
                 *BRANCH_KEYS},
    "motor": {"remanence_T", "magnet_thickness_mm", "recoil_permeability", "slot_count",
              "slot_opening_mm", "saturation_factor", "electric_loading_A_per_m",
              "winding_factor", "shaft_bore_radius_mm", "rotor_density_kg_m3",
              "epoxy_density_kg_m3", "rotor_groove_solid_fraction", "gear_ratio",
              "gear_efficiency"},
    "bounds": {"gap_min_mm", "gap_max_mm", "radius_min_mm", "radius_max_mm", "length_min_mm",
               "length_max_mm", "inertia_max_ratio", "torque_min_Nm"},
    "thermal": set(THERMAL_TOML_KEYS),
}
_ARRAY_TABLES = {"mission": {"depth_m", "oil_temp_C", "sea_temp_C", "fraction"}}
_OIL_KEYS = {  # [oil] keys of each kind of fluid
    "mineral": {"kind", "name", "oils_csv", "nu40_cSt", "nu100_cSt", "density_kg_m3",
                "barus_1_GPa", "polymer_thickened"},
    "table": {"kind", "name", "table_csv", "outside_table", "polymer_thickened"},
    "gas": {"kind", "name", "molar_mass_kg_per_mol", "sutherland_mu_ref_Pa_s",
            "sutherland_T_ref_K", "sutherland_S_K", "trusted_min_C", "trusted_max_C"},
}
_TABLES["oil"] = set().union(*_OIL_KEYS.values())
_GAS_CONSTANTS = {  # TOML key -> GasFluid field (SI: kg/mol, Pa s, K)
    "molar_mass_kg_per_mol": "molar_mass_kg_mol", "sutherland_mu_ref_Pa_s": "mu_ref_Pa_s",
    "sutherland_T_ref_K": "T_ref_K", "sutherland_S_K": "sutherland_S_K"}
def _check_keys(table: dict, allowed: set[str], where: str) -> None:
    """Refuse an unknown key by name. At the top level its value is not shown: a file
    that is not a case at all (``oilgap evaluate ~/.config/x.toml``) is not echoed."""
    for k in table:
        if k not in allowed:
            shown = table[k] if where else f"<{_toml_type(table[k])}>"
            raise InputError(f"{where}.{k}" if where else k, cell_for_message(shown),
                             f"unknown key; allowed keys: {', '.join(sorted(allowed))}",
                             "case TOML")


def _toml_type(v: Any) -> str:
    return {dict: "a table", list: "an array", str: "a string"}.get(type(v), "a value")


def _mm(table: dict, key: str, where: str, default: float | None = None) -> float | None:
    if key not in table:
        if default is None:
            return None
        return default
    return check_finite(key, table[key], where) * MM_TO_M


def _require(table: dict, key: str, where: str) -> Any:
    if key not in table:
        raise InputError(f"{where}.{key}", None, "is required", "case TOML")
    return table[key]


def case_from_dict(doc: dict, base_dir: Path | None = None) -> DesignCase:
    """Build and validate a DesignCase from a parsed TOML document.

    Parameters
    ----------
    doc : dict
        The parsed TOML, units in the key names (``T1_mm`` [mm], ``depth_m`` [m],
        ``oil_temp_C`` [degC], ``peak_speed_rpm`` [rpm]).
    base_dir : Path, optional
        Directory that relative paths (``oils_csv``, ``table_csv``, ``duty_cycle.csv``)
        are read from (default: the working directory).

    Returns
    -------
    DesignCase
        The case, SI inside.

    Raises
    ------
    InputError
        Unknown tables or keys, missing required keys, non-finite numbers or values
        a dataclass refuses; the message names the key.
    """
    base_dir = base_dir or Path.cwd()
    if not isinstance(doc, dict):
        raise InputError("case", doc, "must be a TOML table")
    allowed_top = _TOP_KEYS | set(_TABLES) | set(_ARRAY_TABLES) | {BEARING_TABLE,
                                                                   UNCERTAINTY_TABLE,
                                                                   CALIBRATION_TABLE}
    _check_keys(doc, allowed_top | set(LINEAR_TABLES), "")
    linear = linear_drive_from(doc) if drive_kind(doc) == "linear" else None
    for t in _TABLES:
        if linear is not None and t == "duty_cycle":  # the rod's cycle: linear_duty_cycle
            continue
        if t in doc and not isinstance(doc[t], dict):
            raise InputError(t, doc[t], "must be a table [" + t + "]", "case TOML")
        _check_keys(doc.get(t, {}), _TABLES[t], t)

    region1 = _region1_from(doc)
    region2 = _region2_from(doc)
    oil, oils_csv = _oil_from(doc.get("oil", {}), base_dir)

    opd = doc.get("operating", {})
    operating = OperatingPoint(**{k: check_finite(k, v, "operating") for k, v in opd.items()})
    duty = (_duty_cycle_from(dict(doc.get("duty_cycle", {})), base_dir) if linear is None
            else linear_duty_cycle(doc.get("duty_cycle", {}), linear, base_dir))

    fd = doc.get("friction", {})
    friction = check_friction_ranges(FrictionLaw(**{k: _friction_value(k, v, fd)
                                                    for k, v in fd.items()}))
    motor = _motor_from(doc.get("motor", {}))
    bounds = _bounds_from(doc, region1)
    mission = _mission_from(doc.get("mission", []))
    thermal = _thermal_from(doc["thermal"]) if "thermal" in doc else None

    name = str(doc.get("name", "unnamed case"))
    friction, gamma_source = _gamma_default(fd, friction, region1)
    bounds = bounds if bounds is not None else DesignBounds.around(region1)
    return DesignCase(
        name=name, region1=region1, region2=region2, oil=oil, operating=operating, duty_cycle=duty,
        friction=friction, motor=motor, bounds=bounds, mission=tuple(mission), oils_csv=oils_csv,
        thermal=thermal, bearing=bearing_from_doc(doc), gamma_source=gamma_source,
        defaults=reader_defaults(doc, bounds, motor, thermal=thermal),
        uncertainty=uncertainty_from_doc(doc), linear=linear,
        calibration_model=_calibration_from(doc, base_dir))


CALIBRATION_TABLE = "calibration"
"""``[calibration] model = "loop.json"``: a calibrated loop model the commands fold into
the case (a path relative to the case file)."""


def _calibration_from(doc: dict, base_dir: Path) -> str | None:
    """The ``[calibration]`` table's model path, absolute (None without the table)."""
    if CALIBRATION_TABLE not in doc:
        return None
    t = doc[CALIBRATION_TABLE]
    if not isinstance(t, dict):
        raise InputError("calibration", t, "must be a table [calibration]", "case TOML")
    _check_keys(t, {"model"}, CALIBRATION_TABLE)
    model = t.get("model")
    if not isinstance(model, str) or not model.strip():
        raise InputError("calibration.model", model, "the path of a loop.json written by "
                         "oilgap loop (relative to the case file)", "case TOML")
    return str((base_dir / model).resolve())


def _friction_value(key: str, value, fd: dict):
    """One ``[friction]`` value checked: the branch arrays element by element (form
    ``"branches"`` only), the others as text or a finite number."""
    if key in ("form", "laminar_law", "transition"):
        return str(value)
    if key not in BRANCH_KEYS:
        return check_finite(key, value, "friction")
    if fd.get("form") != "branches":
        raise InputError(key, value, 'applies to form = "branches" only', "friction")
    if not isinstance(value, list) or not value:
        raise InputError(key, value, "an array of numbers, one per branch (e.g. four for "
                         "the branches of Eq. 6)", "friction")
    return tuple(check_finite(f"{key}[{i + 1}]", v, "friction") for i, v in enumerate(value))


def _gamma_default(fd: dict, friction: FrictionLaw, region1: RotorStatorClearance
                   ) -> tuple[FrictionLaw, str]:
    """The law with DEFAULT_GAMMA where ``[friction]`` gives no gamma, and its source; a
    warning when the default matters (grooves, T > 1)."""
    if "gamma" in fd:
        return friction, "case"
    T = region1.roughness
    if T > 1.0 + 1e-9:
        warnings.warn(OilgapWarning(
            f"[friction] gives no gamma: the groove exponent defaults to {DEFAULT_GAMMA:g}, "
            "the seed rig's fit (oilgap study smoothing), the only evidence the tool has; "
            f"this joint is grooved (T = {T:.3g}): give gamma in [friction] to use another"),
            stacklevel=3)
    return replace(friction, gamma=DEFAULT_GAMMA), GAMMA_DEFAULT_SOURCE


def _thermal_from(td: dict) -> ThermalSpec:
    for k in ("sea_temp_C", "resistance_K_per_W", "heat_capacity_J_per_K"):
        _require(td, k, "thermal")
    return ThermalSpec(**{f: (str(td[k]) if k == "walls" else check_finite(k, td[k], "thermal"))
                          for k, f in THERMAL_TOML_KEYS.items() if k in td})


def _region1_from(doc: dict) -> RotorStatorClearance:
    r1d = doc.get("region1")
    if r1d is None:
        raise InputError("region1", None, "a [region1] table with T1_mm..T4_mm and length_mm "
                         "is required", "case TOML")
    for k in ("T1_mm", "T2_mm", "T3_mm", "T4_mm", "length_mm"):
        _require(r1d, k, "region1")
    region1 = RotorStatorClearance(
        *(_mm(r1d, k, "region1") for k in ("T1_mm", "T2_mm", "T3_mm", "T4_mm", "length_mm")),
        T1_unfilled=_mm(r1d, "T1_unfilled_mm", "region1"),
        T4_unfilled=_mm(r1d, "T4_unfilled_mm", "region1"))
    return region1


def _region2_from(doc: dict) -> BearingClearance | None:
    region2 = None
    if "region2" in doc:
        r2d = doc["region2"]
        for k in ("radius_mm", "length_mm", "gap_mm"):
            _require(r2d, k, "region2")
        region2 = BearingClearance(*(_mm(r2d, k, "region2")
                                     for k in ("radius_mm", "length_mm", "gap_mm")))
    return region2


def _oil_from(od: dict, base_dir: Path) -> tuple[Fluid, str | None]:
    kind = od.get("kind", "mineral")
    if kind not in FLUID_KINDS:
        raise InputError("oil.kind", kind, f"allowed: {', '.join(FLUID_KINDS)}", "case TOML")
    for k in od:
        if k not in _OIL_KEYS[kind]:
            raise InputError(f"oil.{k}", od[k], f"not a key of kind = \"{kind}\"; its keys: "
                             f"{', '.join(sorted(_OIL_KEYS[kind]))}", "case TOML")
    flag = od.get("polymer_thickened")
    if flag is not None and not isinstance(flag, bool):
        raise InputError("oil.polymer_thickened", flag, "true or false", "case TOML")
    if kind == "table":
        p = Path(str(_require(od, "table_csv", "oil")))
        p = p if p.is_absolute() else base_dir / p
        return read_fluid_table(p, str(od["name"]) if "name" in od else None, bool(flag),
                                str(od.get("outside_table", "refuse"))), None
    if kind == "gas":
        return _gas_from(od), None
    return _mineral_from(od, base_dir, flag)


def _mineral_from(od: dict, base_dir: Path, flag: bool | None) -> tuple[Oil, str | None]:
    oils_csv = None
    catalogue = None
    if "oils_csv" in od:
        p = Path(str(od["oils_csv"]))
        p = p if p.is_absolute() else base_dir / p
        catalogue = with_builtin(read_oils_csv(p, "oil.oils_csv"), "oil.oils_csv")
        oils_csv = str(p)
    oil_name = str(od.get("name", "VG22"))
    if not oil_name.strip():
        raise InputError("name", oil_name, "a non-empty oil name (an ISO VG grade such as "
                         "VG22, a row of --oils, or a name for the fluid given here)", "oil")
    own = [k for k in ("nu40_cSt", "nu100_cSt", "density_kg_m3") if k in od]
    if own:
        missing = [k for k in ("nu40_cSt", "nu100_cSt", "density_kg_m3") if k not in od]
        if missing:
            raise InputError("oil." + missing[0], None, "a custom oil needs nu40_cSt, "
                             "nu100_cSt and density_kg_m3", "case TOML")
        kw = {}
        if "barus_1_GPa" in od:
            kw["barus_1_Pa"] = check_range("barus_1_GPa", od["barus_1_GPa"], 0.0, None,
                                           "oil") * 1e-9
        oil = Oil(oil_name, check_finite("nu40_cSt", od["nu40_cSt"], "oil"),
                  check_finite("nu100_cSt", od["nu100_cSt"], "oil"),
                  check_finite("density_kg_m3", od["density_kg_m3"], "oil"), **kw)
    else:
        if "barus_1_GPa" in od:
            raise InputError("oil.barus_1_GPa", od["barus_1_GPa"], "only with a custom oil "
                             "(nu40_cSt, nu100_cSt, density_kg_m3)", "case TOML")
        oil = get_oil(oil_name, catalogue)
        if oil.kind != "mineral":
            raise InputError("oil.name", oil_name, f"is a {oil.kind}: write kind = "
                             f"\"{oil.kind}\" in [oil]", "case TOML")
    if flag is not None:
        oil = replace(oil, polymer_thickened=flag)
    return oil, oils_csv


def _gas_from(od: dict) -> GasFluid:
    own = {k: od[k] for k in _GAS_CONSTANTS if k in od}
    if own:
        missing = [k for k in _GAS_CONSTANTS if k not in od]
        if missing:
            raise InputError("oil." + missing[0], None, "a custom gas needs "
                             f"{', '.join(_GAS_CONSTANTS)}", "case TOML")
        gas = GasFluid(str(od.get("name", "custom gas")),
                       **{f: check_finite(k, od[k], "oil") for k, f in _GAS_CONSTANTS.items()})
    else:
        name = str(_require(od, "name", "oil"))
        gases = builtin_gases()
        if gas_key(name) not in gases:
            raise InputError("oil.name", name, "built-in gases are "
                             f"{', '.join(g.name for g in gases.values())}; or give "
                             f"{', '.join(_GAS_CONSTANTS)}", "case TOML")
        gas = gases[gas_key(name)]
    if "trusted_min_C" in od or "trusted_max_C" in od:
        lo, hi = gas.trusted_range_K
        if "trusted_min_C" in od:
            lo = celsius_to_kelvin(check_finite("trusted_min_C", od["trusted_min_C"], "oil"))
        if "trusted_max_C" in od:
            hi = celsius_to_kelvin(check_finite("trusted_max_C", od["trusted_max_C"], "oil"))
        gas = replace(gas, trusted_range_K=(lo, hi))
    return gas


def _duty_cycle_from(dcd: dict, base_dir: Path) -> DutyCycle:
    kind = dcd.pop("kind", "csv" if "csv" in dcd else "sine")
    if kind == "sine":
        if "csv" in dcd:
            raise InputError("duty_cycle.csv", dcd["csv"], "only with kind = \"csv\"",
                             "case TOML")
        duty = DutyCycle.sine(**{k: check_finite(k, v, "duty_cycle") for k, v in dcd.items()})
    elif kind == "csv":
        extra = [k for k in dcd if k != "csv"]
        if extra:
            raise InputError("duty_cycle." + extra[0], dcd[extra[0]],
                             "a csv duty cycle takes only csv = \"path\"", "case TOML")
        p = Path(str(_require(dcd, "csv", "duty_cycle")))
        duty = DutyCycle.from_csv(p if p.is_absolute() else base_dir / p)
    else:
        raise InputError("duty_cycle.kind", kind, "allowed: sine, csv", "case TOML")
    return duty


def _motor_from(md: dict) -> Motor:
    mkw = {}
    for k, v in md.items():
        if k == "slot_count":
            mkw[k] = v
        elif k in MOTOR_TOML_KEYS:
            attr, factor = MOTOR_TOML_KEYS[k]
            mkw[attr] = check_finite(k, v, "motor") * factor
        else:
            mkw[k] = check_finite(k, v, "motor")
    return Motor(**mkw)


def _bounds_from(doc: dict, region1: RotorStatorClearance) -> DesignBounds | None:
    bounds = None
    if "bounds" in doc:
        bd = doc["bounds"]
        dflt = DesignBounds.around(region1)
        bkw = {}
        for f in ("gap_min", "gap_max", "radius_min", "radius_max", "length_min", "length_max"):
            bkw[f] = _mm(bd, f + "_mm", "bounds", getattr(dflt, f))
        if "inertia_max_ratio" in bd:
            bkw["inertia_max_ratio"] = check_finite("inertia_max_ratio",
                                                    bd["inertia_max_ratio"], "bounds")
        if "torque_min_Nm" in bd:
            bkw["torque_min_Nm"] = check_finite("torque_min_Nm", bd["torque_min_Nm"], "bounds")
        bounds = DesignBounds(**bkw)
    return bounds


def _mission_from(ms: Any) -> list[MissionSegment]:
    mission = []
    if not isinstance(ms, list):
        raise InputError("mission", ms, "must be an array of tables [[mission]]", "case TOML")
    for i, seg in enumerate(ms):
        if not isinstance(seg, dict):
            raise InputError(f"mission[{i}]", seg, "must be a table", "case TOML")
        where = f"mission[{i}]"
        _check_keys(seg, _ARRAY_TABLES["mission"], where)
        for k in ("depth_m", "fraction"):
            _require(seg, k, where)
        temps = [k for k in MISSION_TEMP_KEYS if k in seg]
        if not temps:
            _require(seg, "oil_temp_C", where)
        if len(temps) > 1:
            raise InputError("sea_temp_C", seg["sea_temp_C"], "give oil_temp_C (thermal modes "
                             "none/film) or sea_temp_C (bulk/full), not both", where)
        vals = {k: check_finite(k, v, where) for k, v in seg.items()}
        mission.append(MissionSegment(vals["depth_m"], vals[temps[0]], vals["fraction"],
                                      temps[0]))
    return mission


def read_case_toml(path: str | Path) -> DesignCase:
    """Read and validate a case TOML file.

    Parameters
    ----------
    path : str or Path
        UTF-8 TOML file; units in the key names (``T1_mm`` [mm], ``depth_m`` [m]).

    Returns
    -------
    DesignCase
        The case, SI inside (:func:`case_from_dict`).

    Raises
    ------
    InputError
        A file that cannot be read (missing, a directory, unreadable, larger than
        :data:`MAX_CASE_BYTES`, not UTF-8), malformed TOML, unknown keys, bad values;
        the message names the file and the reason, never its content.
    """
    path = Path(path)
    text = read_input_text(path, "case", "TOML file", max_bytes=MAX_CASE_BYTES)
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        kind = file_kind(path, text)
        if kind in ("CSV", "JSON"):
            raise InputError("case TOML", str(path), f"is a {kind} file where a case TOML is "
                             "expected (rig data go to oilgap loop DATA.csv; a loop.json to "
                             "predict --model)") from None
        raise InputError("case TOML", str(path), f"is malformed: {e}") from None
    return case_from_dict(doc, path.parent)


# --------------------------------------------------------------------------- the seed joint


def seed_case(smoothed: bool = False) -> DesignCase:
    """The seed paper's joint (Table 1), grooved (T = 4) or smoothed with epoxy (T = 2).

    Geometry: R1 = T2 = 25.4 mm, L1 = 14.76 mm, delta1 = 1 mm; R2 = 22 mm,
    L2 = 14.24 mm, delta2 = 5 mm. The seed gives only T; oilgap assumes the
    groove depth is split evenly between rotor and stator (1.5 mm each when
    grooved, T = 4; the epoxy fill takes 1 mm off each, leaving 0.5 mm, T = 2).

    Parameters
    ----------
    smoothed : bool
        False: grooved (T = 4 [-]); True: smoothed with epoxy (T = 2 [-]).

    Returns
    -------
    DesignCase
        The seed joint (``model/data/seed_joint.toml``), SI inside.

    References
    ----------
    Seed paper (Table 1 and Eq. 9) [1].
    """
    name = "seed_joint.toml"
    with resources.as_file(resources.files("oilgap.model") / "data" / name) as p:
        case = read_case_toml(p)
    if smoothed:
        r1 = case.region1
        case = replace(case, name="seed joint, smoothed with epoxy (T = 2)",
                       region1=replace(r1, T1=r1.T1 + 1.0e-3, T4=r1.T4 - 1.0e-3))
    return case
