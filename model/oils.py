"""The oil catalogue: ISO VG grades and user oils read from CSV.

An :class:`Oil` carries the two Walther points (nu at 40 and 100 degC), the
density at 15 degC and its pressure and temperature coefficients. Its methods
wrap the pure functions of :mod:`oilgap.model.oil_properties`.

The built-in catalogue holds ISO VG 10 to 1000 (ISO 3448: nu at 40 degC is the
grade number) with typical nu at 100 degC of VI ~ 100 mineral oils and typical
densities (850-910 kg/m^3). A user CSV has the columns
``oil,nu40_cSt,nu100_cSt,density_kg_m3`` and optionally
``barus_1_GPa`` (pressure-viscosity coefficient, default 17 /GPa) and
``polymer_thickened`` (true/false, default false: a straight mineral oil).

:func:`get_oil` also finds the built-in gases of :mod:`oilgap.model.fluids` ('air',
'nitrogen'); an Oil has the interface of every fluid
(:class:`~oilgap.model.fluids.Fluid`).

References
----------
.. [1] ISO 3448:1992, Industrial liquid lubricants -- ISO viscosity classification
   (nu at 40 degC = the grade number, +-10 %).
.. [2] ASTM D341-20 (the Walther line through the 40 and 100 degC points).
.. [3] Barus (1893) with Roelands' temperature dependence of the pressure-viscosity
   coefficient; the density law of Vacca & Franzoni (see
   :mod:`oilgap.model.oil_properties`).
"""

from __future__ import annotations

import csv
import io
import math
import warnings
from dataclasses import dataclass, replace
from importlib import resources
from pathlib import Path

from . import oil_properties as op
from .errors import InputError, OilgapWarning, check_positive, check_range
from .fluids import Fluid, builtin_gases, gas_key
from .io.inputs import cell_for_message, check_physical, header_error, read_input_text
from .units import ZERO_CELSIUS_K, celsius_to_kelvin, m2_s_to_cst, per_gpa_to_per_pa

OIL_COLUMNS = ("oil", "nu40_cSt", "nu100_cSt", "density_kg_m3")
OPTIONAL_OIL_COLUMNS = ("barus_1_GPa", "polymer_thickened")
TRUE_WORDS = ("true", "yes", "1")
FALSE_WORDS = ("false", "no", "0", "")

WALTHER_MIN_CST = 1.0 - op.WALTHER_OFFSET_CST
"""Viscosity [cSt] at and below which the Walther line is undefined: it takes
log10(log10(nu + 0.7)), and log10(nu + 0.7) <= 0 there (0.3 cSt) [2]."""

MAX_OIL_CST = 1.0e6
"""Largest nu at 40 or 100 degC of an oil [cSt]: 300 times the heaviest ISO grade (VG 3200
[1]); a larger number is a unit slip (mm^2/s vs m^2/s)."""

NU_REASON = ("the Walther line (ASTM D341) takes log10(log10(nu + 0.7)), undefined at or "
             "below 0.3 cSt; above 1e6 cSt (300 x ISO VG 3200) the number is a unit slip")

OIL_DENSITY_RANGE_KG_M3 = (600.0, 2200.0)
"""Allowed density of a liquid oil at 15 degC [kg/m^3]: compensating and lubricating
liquids lie between light hydrocarbons (~700) and perfluoropolyethers (~1950)."""

DENSITY_REASON = ("liquid oils lie between light hydrocarbons (~700 kg/m^3) and "
                  "perfluoropolyethers (~1950 kg/m^3); outside it is a unit slip (g/cm^3)")

MAX_BARUS_1_GPA = 100.0
"""Largest pressure-viscosity coefficient at 40 degC [1/GPa]: mineral oils have 15-35,
traction fluids up to ~40 [3]."""

BARUS_REASON = ("mineral oils have 15-35 /GPa at 40 degC, traction fluids up to ~40; "
                "a larger number is a unit slip (1/bar vs 1/GPa)")


@dataclass(frozen=True)
class Oil:
    """A compensating oil.

    Attributes
    ----------
    name : str
        Name as written by the user or the catalogue ('VG22', 'Tellus S2 M 22').
    nu40_cSt, nu100_cSt : float
        Kinematic viscosity at 40 and 100 degC, atmospheric pressure [cSt].
    density_kg_m3 : float
        Density at 15 degC, atmospheric pressure [kg/m^3].
    barus_1_Pa : float
        Pressure-viscosity coefficient at 40 degC [1/Pa] (default 1.7e-8, i.e. 17 /GPa).
    polymer_thickened : bool
        True for a polymer-thickened (VI-improved) oil, whose shear thinning is plausible
        [-]; default False (a straight mineral oil is Newtonian).

    Raises
    ------
    InputError
        A property outside its physical range (:data:`NU_REASON`,
        :data:`DENSITY_REASON`, :data:`BARUS_REASON`), or nu100 >= nu40.
    """

    name: str
    nu40_cSt: float
    nu100_cSt: float
    density_kg_m3: float
    barus_1_Pa: float = op.BARUS_MINERAL_OIL_1_PA
    polymer_thickened: bool = False

    def __post_init__(self):
        where = f"oil {self.name!r}"
        for f in ("nu40_cSt", "nu100_cSt"):
            check_physical(f, getattr(self, f), WALTHER_MIN_CST, MAX_OIL_CST, NU_REASON, where,
                           lo_open=True)
        check_physical("density_kg_m3", self.density_kg_m3, *OIL_DENSITY_RANGE_KG_M3,
                       DENSITY_REASON, where)
        if not self.barus_1_Pa >= 0 or not math.isfinite(self.barus_1_Pa):
            raise InputError("barus_1_GPa", self.barus_1_Pa * 1e9, "must be >= 0 and finite",
                             where)
        check_physical("barus_1_GPa", self.barus_1_Pa * 1e9, 0.0, MAX_BARUS_1_GPA,
                       BARUS_REASON, where)
        if self.nu100_cSt >= self.nu40_cSt:
            raise InputError("nu100_cSt", self.nu100_cSt,
                             f"must be below nu40_cSt = {self.nu40_cSt:g}", where)
        if not isinstance(self.polymer_thickened, bool):
            raise InputError("polymer_thickened", self.polymer_thickened, "true or false",
                             where)

    @property
    def kind(self) -> str:
        """``"mineral"`` [-]."""
        return "mineral"

    @property
    def newtonian(self) -> bool:
        """Not polymer-thickened [-]."""
        return not self.polymer_thickened

    @property
    def trusted_range_C(self) -> tuple[float, float]:
        """Temperatures [degC] over which the Walther line is trusted
        (:data:`~oilgap.model.oil_properties.WALTHER_TRUSTED_RANGE_C`)."""
        return op.WALTHER_TRUSTED_RANGE_C

    @property
    def walther(self) -> tuple[float, float]:
        """ASTM D341 coefficients (A [-], B [-]) through the 40 and 100 degC points [2]."""
        return op.walther_coefficients(self.nu40_cSt, ZERO_CELSIUS_K + 40.0,
                                       self.nu100_cSt, ZERO_CELSIUS_K + 100.0)

    def properties(self, temp_K, pressure_gauge_Pa=0.0):
        """Kinematic and dynamic viscosity and density at temperature and gauge pressure.

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Oil temperature [K].
        pressure_gauge_Pa : float, array or CasADi symbol
            Pressure above atmospheric [Pa].

        Returns
        -------
        nu_m2_s, mu_Pa_s, rho_kg_m3
            [m^2/s], [Pa s], [kg/m^3]
            (:func:`~oilgap.model.oil_properties.oil_viscosities`).
        """
        A, B = self.walther
        return op.oil_viscosities(A, B, self.density_kg_m3, temp_K, pressure_gauge_Pa,
                                  self.barus_1_Pa)

    def kinematic_viscosity_cSt(self, temp_C, depth_m=0.0) -> float:
        """Kinematic viscosity [cSt] at oil temperature [degC] and sea depth [m].

        Parameters
        ----------
        temp_C : float
            Oil temperature [degC].
        depth_m : float
            Sea depth [m]; the oil carries the water column's gauge pressure.

        Returns
        -------
        float
            Kinematic viscosity [cSt].
        """
        nu, _, _ = self.properties(celsius_to_kelvin(temp_C),
                                   op.seawater_gauge_pressure(depth_m))
        return m2_s_to_cst(nu)

    def temperature_slope(self, temp_K, pressure_gauge_Pa=0.0):
        """Viscosity-temperature slope ``b = -d ln(mu)/dT`` [1/K] at (T, p), closed form.

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Oil temperature [K].
        pressure_gauge_Pa : float, array or CasADi symbol
            Pressure above atmospheric [Pa].

        Returns
        -------
        float, array or CasADi expression
            b [1/K] (:func:`~oilgap.model.oil_properties.oil_viscosity_temperature_slope`:
            Walther [2], density and Barus-Roelands terms [3]).
        """
        A, B = self.walther
        return op.oil_viscosity_temperature_slope(A, B, self.density_kg_m3, temp_K,
                                                  pressure_gauge_Pa, self.barus_1_Pa)


def normalize_oil_name(name: str) -> str:
    """Canonical key of an oil name: 'ISO VG 22', 'vg22', 'VG 22' -> 'VG22'.

    Parameters
    ----------
    name : str
        Oil name as written [-].

    Returns
    -------
    str
        Upper case without spaces, dashes, underscores or a leading 'ISO'.
    """
    key = str(name).strip().upper().replace(" ", "").replace("-", "").replace("_", "")
    if key.startswith("ISOVG"):
        key = key[3:]
    return key


def read_oils_csv(path: str | Path, field: str = "oils file") -> dict[str, Oil]:
    """Read an oils table ``oil,nu40_cSt,nu100_cSt,density_kg_m3[,barus_1_GPa]
    [,polymer_thickened]``.

    Parameters
    ----------
    path : str or Path
        UTF-8 CSV file; units in the column names: nu [cSt], density at 15 degC
        [kg/m^3], Barus coefficient [1/GPa] (optional, default 17), polymer_thickened
        [-] (optional: true/false, yes/no, 1/0; default false).
    field : str
        The key or option that named the file, for messages [-].

    Returns
    -------
    dict of str to Oil
        The oils keyed by :func:`normalize_oil_name` (SI inside each Oil).

    Raises
    ------
    InputError
        A file that cannot be read (missing, a directory, unreadable, not UTF-8),
        missing or unknown columns (named without repeating the header), non-numeric
        or out-of-range values, duplicate names.
    """
    path = Path(path)
    where = str(path)
    reader = csv.DictReader(io.StringIO(read_input_text(path, field, "CSV file"), newline=""))
    cols = [c.strip() for c in (reader.fieldnames or [])]
    err = header_error(path, cols, OIL_COLUMNS, OPTIONAL_OIL_COLUMNS)
    if err is not None:
        raise err
    reader.fieldnames = cols
    oils: dict[str, Oil] = {}
    for i, row in enumerate(reader, start=2):
        rwhere = f"{where} line {i}"
        name = (row["oil"] or "").strip()
        key = normalize_oil_name(name)
        if name and key in oils:
            raise InputError("oil", name, "names must be unique", rwhere)
        oils[key] = _oil_row(name, {c: row[c] for c in cols if c != "oil"}, rwhere)
    if not oils:
        raise InputError(field, str(path), "must hold at least one oil")
    return oils


def _oil_row(name: str, row: dict, where: str) -> Oil:
    """One oil from a row of its properties (CSV cells or numbers); keys as the CSV's."""
    if not name:
        raise InputError("oil", name, "a non-empty name is required", where)
    missing = [c for c in OIL_COLUMNS[1:] if c not in row]
    if missing:
        raise InputError(missing[0], None, f"required for each oil ({', '.join(OIL_COLUMNS[1:])}"
                         f"; optional {', '.join(OPTIONAL_OIL_COLUMNS)})", where)
    vals = {}
    for c in OIL_COLUMNS[1:] + OPTIONAL_OIL_COLUMNS:
        raw = row.get(c)
        if c in OPTIONAL_OIL_COLUMNS and (raw is None or str(raw).strip() == ""):
            continue
        if c == "polymer_thickened":
            vals[c] = raw if isinstance(raw, bool) else _flag(c, raw, where)
            continue
        vals[c] = check_positive(c, _num(raw), where) if c != "barus_1_GPa" else \
            _nonneg(c, raw, where)
    barus = per_gpa_to_per_pa(vals["barus_1_GPa"]) if "barus_1_GPa" in vals \
        else op.BARUS_MINERAL_OIL_1_PA
    return Oil(name, vals["nu40_cSt"], vals["nu100_cSt"], vals["density_kg_m3"],
               barus, vals.get("polymer_thickened", False))


def oils_from_dict(table: dict, field: str = "oils") -> dict[str, Oil]:
    """Oils given as a dict: ``{name: Oil}`` or ``{name: {nu40_cSt, nu100_cSt,
    density_kg_m3[, barus_1_GPa][, polymer_thickened]}}`` (the columns of an oils CSV,
    checked as :func:`read_oils_csv` checks its rows).

    Parameters
    ----------
    table : dict
        Oil name -> Oil, or its properties: nu [cSt], density at 15 degC [kg/m^3],
        Barus coefficient [1/GPa].
    field : str
        The argument that gave the table, for messages [-].

    Returns
    -------
    dict of str to Oil
        Keyed by :func:`normalize_oil_name`.

    Raises
    ------
    InputError
        A name that is not a non-empty string, an entry neither an Oil nor a dict, an
        unknown or missing key, a bad value, two names that are the same oil.
    """
    oils: dict[str, Oil] = {}
    for name, entry in table.items():
        where = f"{field}[{name!r}]"
        if not isinstance(name, str) or not name.strip():
            raise InputError(f"{field} key", name, "an oil name (a non-empty str)")
        if isinstance(entry, Oil):
            oil = entry
        elif isinstance(entry, dict):
            unknown = sorted(set(entry) - set(OIL_COLUMNS[1:] + OPTIONAL_OIL_COLUMNS))
            if unknown:
                raise InputError(str(unknown[0]), entry[unknown[0]], "an oil's keys are "
                                 f"{', '.join(OIL_COLUMNS[1:] + OPTIONAL_OIL_COLUMNS)}", where)
            oil = _oil_row(name.strip(), entry, where)
        else:
            raise InputError(where, type(entry).__name__, "an Oil or a dict of its "
                             "properties {nu40_cSt, nu100_cSt, density_kg_m3}")
        key = normalize_oil_name(name)
        if key in oils:
            raise InputError(field, name, "names must be unique (case, spaces and ISO ignored)")
        oils[key] = oil
    if not oils:
        raise InputError(field, {}, "must hold at least one oil")
    return oils


def with_builtin(user: dict[str, Oil], field: str = "oils") -> dict[str, Oil]:
    """A user's oils added to the built-in ISO VG catalogue: the user's row wins on a
    name clash, with an OilgapWarning when its properties differ from the built-in's.

    Parameters
    ----------
    user : dict of str to Oil
        The user's oils, keyed by :func:`normalize_oil_name`.
    field : str
        The option or argument that gave them, for the warning [-].

    Returns
    -------
    dict of str to Oil
        The built-in oils, then the user's.
    """
    cat = builtin_oils()
    clash = [o.name for k, o in user.items() if k in cat and replace(o, name=cat[k].name) != cat[k]]
    if clash:
        warnings.warn(OilgapWarning(
            f"{field}: {', '.join(clash)} replace{'s' if len(clash) == 1 else ''} the "
            "built-in oil(s) of the same name (the table's values are used)"), stacklevel=3)
    return {**cat, **user}


def _num(raw):
    return cell_for_message(raw)


def _nonneg(field, raw, where):
    return check_range(field, _num(raw), 0.0, None, where)


def _flag(field, raw, where) -> bool:
    word = str(raw).strip().lower()
    if word not in TRUE_WORDS + FALSE_WORDS:
        raise InputError(field, cell_for_message(raw), "true or false (yes/no, 1/0)", where)
    return word in TRUE_WORDS


_BUILTIN: dict[str, Oil] | None = None


def builtin_oils() -> dict[str, Oil]:
    """The built-in ISO VG catalogue, keyed by canonical name ('VG10' ... 'VG1000').

    Returns
    -------
    dict of str to Oil
        A copy of the catalogue: nu at 40 degC = the grade number [cSt] [1], typical
        nu at 100 degC [cSt] and density [kg/m^3] of VI ~ 100 mineral oils.
    """
    global _BUILTIN
    if _BUILTIN is None:
        with resources.as_file(resources.files(__package__) / "data" / "iso_vg_oils.csv") as p:
            _BUILTIN = read_oils_csv(p)
    return dict(_BUILTIN)


def builtin_fluids() -> dict[str, Fluid]:
    """The built-in oils and gases, keyed by canonical name ('VG22', 'AIR').

    Returns
    -------
    dict of str to Fluid
        :func:`builtin_oils` and :func:`~oilgap.model.fluids.builtin_gases` (SI inside:
        nu [cSt] in attribute names, molar mass [kg/mol]).
    """
    return {**builtin_oils(), **builtin_gases()}


def get_oil(name: str, catalogue: dict[str, Oil] | None = None) -> Fluid:
    """Look a fluid up by name (case- and space-insensitive: 'VG22', 'ISO VG 22', 'Air').

    The catalogue first, then the built-in gases ('air', 'nitrogen').

    Parameters
    ----------
    name : str
        Oil or gas name [-].
    catalogue : dict of str to Oil, optional
        Oils keyed by canonical name (default: :func:`builtin_oils`).

    Returns
    -------
    Oil or GasFluid
        The fluid (properties in SI, nu in [cSt] in its attribute names).

    Raises
    ------
    InputError
        Unknown name; the message lists the known names.
    """
    cat = builtin_oils() if catalogue is None else catalogue
    key = normalize_oil_name(name)
    if key in cat:
        return cat[key]
    gases = builtin_gases()
    if gas_key(name) in gases:
        return gases[gas_key(name)]
    known = [o.name for o in cat.values()] + [g.name for g in gases.values()]
    raise InputError("oil", name, f"known oils are {', '.join(known)}")
