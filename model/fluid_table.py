"""A fluid given by a property table: nu and rho against temperature (and pressure).

``ln nu`` and ``rho`` are interpolated linearly in T between the table's temperatures,
bilinearly in (T, p) when the table has pressures; ``mu = nu rho``. Outside the table
the fluid refuses (InputError), or, with ``outside = "clamp"``, uses the nearest edge
of the table with an OilgapWarning. The CSV format is ``temp_C,[pressure_MPa,]nu_cSt,
density_kg_m3`` (absolute pressure; ``#`` lines are comments).

Part of the common fluid interface of :mod:`oilgap.model.fluids`.

References
----------
.. [1] Linear interpolation of ln(nu) in T: the Andrade form ``ln mu = a + b/T`` is
   near-linear in T over a table step; e.g. E. N. da C. Andrade, "The viscosity of
   liquids", Nature 125:309-310, 1930.
"""

from __future__ import annotations

import csv
import io
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import _math as m
from .errors import InputError, OilgapWarning, check_finite, check_positive
from .io.inputs import cell_for_message, header_error, read_input_text
from .oil_properties import seawater_gauge_pressure
from .units import (
    MPA_TO_PA,
    STANDARD_ATMOSPHERE_PA,
    celsius_to_kelvin,
    cst_to_m2_s,
    kelvin_to_celsius,
    m2_s_to_cst,
)

MAX_TABLE_NU_CST = 1.0e8
"""Largest viscosity of a fluid table [cSt]: road bitumen at room temperature, no fluid
that fills a clearance; a larger number is a unit slip, and 1e200 cSt gives no finite
loss (issue 26)."""

TABLE_NU_REASON = ("1e8 cSt is road bitumen at room temperature, not a fluid that fills a "
                   "clearance (a unit slip?); a larger viscosity gives no finite loss")

TABLE_COLUMNS = ("temp_C", "nu_cSt", "density_kg_m3")
"""Required columns of a fluid table: temperature [degC], nu [cSt], density [kg/m^3]."""

TABLE_OPTIONAL_COLUMNS = ("pressure_MPa",)
"""Optional column of a fluid table: absolute pressure [MPa]."""

OUTSIDE_TABLE = ("refuse", "clamp")
"""What a table fluid does outside its table: refuse (InputError) or clamp (warning)."""

def _check_monotone(t_K: np.ndarray, p_Pa: np.ndarray, nu: np.ndarray, where: str) -> None:
    """Refuse a liquid table whose viscosity rises with temperature or falls with pressure.

    A liquid's viscosity falls as it warms (Andrade: ``ln nu`` near-linear in 1/T) and
    rises under pressure (Barus) [1]; a table that runs the other way is a typo (a column
    shifted, a digit lost), and its interpolant would extrapolate the wrong way (a
    100-fold rise over 20 K ends in NaN in the heat balance). Equal neighbours (a flat
    table) are allowed.

    Raises
    ------
    InputError
        Naming ``nu_cSt``, the two values as written [cSt] and their temperatures [degC]
        or pressures [MPa].

    References
    ----------
    .. [1] E. N. da C. Andrade, Nature 125:309-310, 1930; C. Barus, Am. J. Sci.
       45:87-96, 1893.
    """
    up_T = np.diff(nu, axis=1) > 0
    if np.any(up_T):
        i, j = (int(k[0]) for k in np.nonzero(up_T))
        at = f" at {p_Pa[i] / MPA_TO_PA:g} MPa" if len(p_Pa) else ""
        a, b = (float(f"{m2_s_to_cst(v):.12g}") for v in nu[i, j:j + 2])
        raise InputError("nu_cSt", b, f"must not rise with temperature: {a:g} cSt at "
                         f"{kelvin_to_celsius(t_K[j]):g} degC, {b:g} cSt at "
                         f"{kelvin_to_celsius(t_K[j + 1]):g} degC{at} (a liquid thins as it "
                         "warms: rows in the wrong column or order?)", where)
    down_p = np.diff(nu, axis=0) < 0
    if np.any(down_p):
        i, j = (int(k[0]) for k in np.nonzero(down_p))
        a, b = (float(f"{m2_s_to_cst(v):.12g}") for v in nu[i:i + 2, j])
        raise InputError("nu_cSt", b, f"must not fall with pressure: {a:g} cSt at "
                         f"{p_Pa[i] / MPA_TO_PA:g} MPa, {b:g} cSt at {p_Pa[i + 1] / MPA_TO_PA:g}"
                         f" MPa ({kelvin_to_celsius(t_K[j]):g} degC; a liquid thickens under "
                         "pressure, Barus)", where)


@dataclass(frozen=True)
class TableFluid:
    """A fluid given by a property table: nu and rho against temperature (and pressure).

    ``ln nu`` and ``rho`` are interpolated linearly in T (bilinearly in (T, p) when the
    table has pressures); ``mu = nu rho``. Without pressures the properties do not
    depend on pressure.

    Attributes
    ----------
    name : str
        Name in reports [-].
    temps_K : tuple of float
        The table's temperatures, increasing [K] (at least 2).
    nu_m2_s : tuple of tuple of float
        Kinematic viscosity [m^2/s], one row per pressure (one row without pressures),
        one column per temperature.
    rho_kg_m3 : tuple of tuple of float
        Density [kg/m^3], laid out as ``nu_m2_s``.
    pressures_Pa : tuple of float
        The table's absolute pressures, increasing [Pa]; empty: no pressure dependence.
    polymer_thickened : bool
        True for a polymer-thickened liquid [-] (default False).
    outside : str
        ``"refuse"`` (InputError, the default) or ``"clamp"`` (the nearest edge of the
        table, with an OilgapWarning) outside the table [-].
    source : str or None
        The CSV file the table was read from [-].

    Raises
    ------
    InputError
        Fewer than 2 temperatures, a grid of the wrong shape, non-positive properties,
        an unknown ``outside``.
    """

    name: str
    temps_K: tuple[float, ...]
    nu_m2_s: tuple[tuple[float, ...], ...]
    rho_kg_m3: tuple[tuple[float, ...], ...]
    pressures_Pa: tuple[float, ...] = ()
    polymer_thickened: bool = False
    outside: str = "refuse"
    source: str | None = None

    def __post_init__(self):
        where = f"fluid table {self.name!r}"
        t = np.asarray(self.temps_K, dtype=float)
        p = np.asarray(self.pressures_Pa, dtype=float)
        shape = (max(len(p), 1), len(t))
        if len(t) < 2 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
            raise InputError("temp_C", tuple(kelvin_to_celsius(t)), "a table needs at least 2 "
                             "different finite temperatures, increasing", where)
        if len(p) == 1 or (len(p) and (np.any(np.diff(p) <= 0) or not np.all(p > 0))):
            raise InputError("pressure_MPa", tuple(p / MPA_TO_PA), "pressures must be > 0, "
                             "different and increasing, at least 2 (or none)", where)
        for f, col in (("nu_m2_s", "nu_cSt"), ("rho_kg_m3", "density_kg_m3")):
            a = np.asarray(getattr(self, f), dtype=float)
            if a.shape != shape:
                raise InputError(col, a.shape, f"one value per (pressure, temperature): "
                                 f"shape {shape}", where)
            if not np.all(np.isfinite(a) & (a > 0)):
                raise InputError(col, float(a[~(np.isfinite(a) & (a > 0))][0]), "must be > 0 "
                                 "and finite", where)
        nu = np.asarray(self.nu_m2_s, dtype=float)
        if np.any(nu > cst_to_m2_s(MAX_TABLE_NU_CST)):  # before any solver: exit 2, not 4
            raise InputError("nu_cSt", float(m2_s_to_cst(nu.max())), f"at most "
                             f"{MAX_TABLE_NU_CST:g} cSt: {TABLE_NU_REASON}", where)
        _check_monotone(t, p, np.asarray(self.nu_m2_s, dtype=float), where)
        if self.outside not in OUTSIDE_TABLE:
            raise InputError("outside_table", self.outside, f"allowed: {', '.join(OUTSIDE_TABLE)}",
                             where)
        if not isinstance(self.polymer_thickened, bool):
            raise InputError("polymer_thickened", self.polymer_thickened, "true or false", where)

    @property
    def kind(self) -> str:
        """``"table"`` [-]."""
        return "table"

    @property
    def newtonian(self) -> bool:
        """Not polymer-thickened [-]."""
        return not self.polymer_thickened

    @property
    def trusted_range_C(self) -> tuple[float, float]:
        """The table's temperature range [degC]."""
        return (float(kelvin_to_celsius(self.temps_K[0])),
                float(kelvin_to_celsius(self.temps_K[-1])))

    def _axis(self, x, nodes, field, unit, scale):
        """Segment index, weight and clamped x on one axis; refuses or warns outside."""
        nodes = np.asarray(nodes, dtype=float)
        lo, hi = nodes[0], nodes[-1]
        bad = (x < lo) | (x > hi) | ~np.isfinite(x)
        if np.any(bad):
            v = float(np.asarray(x)[bad].flat[0])
            rng = f"{scale(lo):g}..{scale(hi):g} {unit}"
            if self.outside == "refuse" or not np.isfinite(v):
                raise InputError(field, round(scale(v), 9), f"outside the table of "
                                 f"{self.name!r}, which covers {rng} (outside_table = "
                                 "\"clamp\" uses the table's edge instead)", "fluid table")
            warnings.warn(f"{field} = {scale(v):g} {unit} lies outside the table of "
                          f"{self.name!r} ({rng}); the properties at the table's edge are used",
                          OilgapWarning, stacklevel=4)
        xc = np.clip(x, lo, hi)
        i = np.clip(np.searchsorted(nodes, xc, side="right") - 1, 0, len(nodes) - 2)
        w = (xc - nodes[i]) / (nodes[i + 1] - nodes[i])
        inside = ~bad
        return i, w, inside

    def _interpolate(self, temp_K, pressure_gauge_Pa):
        """(ln nu, rho, d ln nu/dT, d rho/dT) of the interpolant, numpy only."""
        if m.is_symbolic(temp_K, pressure_gauge_Pa):
            raise TypeError("a table fluid takes numeric temperatures and pressures, "
                            "not CasADi symbols")
        T, pg = np.broadcast_arrays(np.asarray(temp_K, dtype=float),
                                    np.asarray(pressure_gauge_Pa, dtype=float))
        tk = np.asarray(self.temps_K)
        L = np.log(np.asarray(self.nu_m2_s))
        R = np.asarray(self.rho_kg_m3)
        i, w, t_in = self._axis(T, tk, "oil_temp_C", "degC", kelvin_to_celsius)
        dT = tk[i + 1] - tk[i]
        if len(self.pressures_Pa):
            pa = pg + STANDARD_ATMOSPHERE_PA
            j, v, _ = self._axis(pa, self.pressures_Pa, "pressure_MPa", "MPa",
                                 lambda x: x / MPA_TO_PA)
        else:
            j, v = np.zeros_like(i), np.zeros(i.shape)
        jn = np.minimum(j + 1, L.shape[0] - 1)
        out = []
        for G in (L, R):
            lo = (1.0 - v) * G[j, i] + v * G[jn, i]       # at temps_K[i], pressure p
            hi = (1.0 - v) * G[j, i + 1] + v * G[jn, i + 1]
            out += [(1.0 - w) * lo + w * hi, np.where(t_in, (hi - lo) / dT, 0.0)]
        ln_nu, dln_nu, rho, drho = out
        return ln_nu, rho, dln_nu, drho

    def properties(self, temp_K, pressure_gauge_Pa=0.0):
        """Kinematic and dynamic viscosity and density at temperature and gauge pressure.

        Parameters
        ----------
        temp_K : float or array
            Temperature [K] (numeric: a table is not a CasADi expression).
        pressure_gauge_Pa : float or array
            Pressure above the standard atmosphere [Pa] (ignored without pressures).

        Returns
        -------
        nu_m2_s, mu_Pa_s, rho_kg_m3
            [m^2/s], [Pa s], [kg/m^3]: ``ln nu`` and ``rho`` interpolated linearly
            (bilinearly with pressures), ``mu = nu rho``.

        Raises
        ------
        InputError
            A temperature or pressure outside the table (``outside = "refuse"``).
        """
        ln_nu, rho, _, _ = self._interpolate(temp_K, pressure_gauge_Pa)
        nu = np.exp(ln_nu)
        return nu[()], (nu * rho)[()], rho[()]

    def kinematic_viscosity_cSt(self, temp_C, depth_m=0.0) -> float:
        """Kinematic viscosity [cSt] at temperature [degC] and the pressure of a depth [m].

        Parameters
        ----------
        temp_C : float
            Fluid temperature [degC].
        depth_m : float
            Sea depth [m] (gauge pressure of the compensating system).

        Returns
        -------
        float
            Kinematic viscosity [cSt].
        """
        nu, _, _ = self.properties(celsius_to_kelvin(temp_C), seawater_gauge_pressure(depth_m))
        return float(m2_s_to_cst(nu))

    def temperature_slope(self, temp_K, pressure_gauge_Pa=0.0):
        """Local slope ``b = -d ln(mu)/dT = -(d ln nu/dT + (d rho/dT)/rho)`` [1/K].

        The derivative of the interpolant on the segment that holds T (the right one at
        a table temperature, the last one at the table's end); 0 where a clamped table
        is flat.

        Parameters
        ----------
        temp_K : float or array
            Temperature [K].
        pressure_gauge_Pa : float or array
            Pressure above the standard atmosphere [Pa].

        Returns
        -------
        float or array
            b [1/K].
        """
        _, rho, dln_nu, drho = self._interpolate(temp_K, pressure_gauge_Pa)
        return (-(dln_nu + drho / rho))[()]


def read_fluid_table(path: str | Path, name: str | None = None,
                     polymer_thickened: bool = False, outside: str = "refuse",
                     field: str = "table_csv") -> TableFluid:
    """Read a fluid table ``temp_C,[pressure_MPa,]nu_cSt,density_kg_m3``.

    Lines starting with ``#`` are comments (the source of the data). With a
    ``pressure_MPa`` column (absolute pressure) every temperature must appear at every
    pressure; rows may come in any order.

    Parameters
    ----------
    path : str or Path
        CSV file: temperature [degC], absolute pressure [MPa] (optional), kinematic
        viscosity [cSt], density [kg/m^3].
    name : str, optional
        Name of the fluid [-] (default: the file's stem).
    polymer_thickened : bool
        True for a polymer-thickened liquid [-].
    outside : {"refuse", "clamp"}
        Behaviour outside the table [-].
    field : str
        The key that named the file, for messages [-].

    Returns
    -------
    TableFluid
        SI inside ([K], [Pa], [m^2/s], [kg/m^3]).

    Raises
    ------
    InputError
        A file that cannot be read (missing, a directory, unreadable, not UTF-8),
        missing or unknown columns (named without repeating the header), bad numbers,
        duplicate or missing grid points.
    """
    path = Path(path)
    where = str(path)
    reader = csv.DictReader(uncommented_csv(path, field))
    cols = [c.strip() for c in (reader.fieldnames or [])]
    err = header_error(path, cols, TABLE_COLUMNS, TABLE_OPTIONAL_COLUMNS)
    if err is not None:
        raise err
    has_p = "pressure_MPa" in cols
    pts: dict[tuple[float, float], tuple[float, float]] = {}
    for i, raw in enumerate(reader, start=2):
        row = {k.strip(): v for k, v in raw.items() if k is not None}
        rw = f"{where} row {i}"
        t = check_finite("temp_C", number_or_raw(row["temp_C"]), rw)
        p = check_positive("pressure_MPa", number_or_raw(row["pressure_MPa"]), rw) if has_p else 0.0
        nu = check_positive("nu_cSt", number_or_raw(row["nu_cSt"]), rw)
        rho = check_positive("density_kg_m3", number_or_raw(row["density_kg_m3"]), rw)
        if (t, p) in pts:
            raise InputError("temp_C", t, "each (temperature, pressure) once", rw)
        pts[(t, p)] = (nu, rho)
    temps = sorted({k[0] for k in pts})
    press = sorted({k[1] for k in pts})
    absent = [(t, p) for p in press for t in temps if (t, p) not in pts]
    if absent:
        raise InputError("pressure_MPa", absent[0][1], f"the table needs every temperature "
                         f"at every pressure; temp_C = {absent[0][0]:g} is missing there", where)
    grid = [[pts[(t, p)] for t in temps] for p in press]
    return TableFluid(
        name=name or path.stem, temps_K=tuple(float(celsius_to_kelvin(t)) for t in temps),
        nu_m2_s=tuple(tuple(float(cst_to_m2_s(c[0])) for c in r) for r in grid),
        rho_kg_m3=tuple(tuple(c[1] for c in r) for r in grid),
        pressures_Pa=tuple(p * MPA_TO_PA for p in press) if has_p and len(press) > 1 else (),
        polymer_thickened=polymer_thickened, outside=outside, source=str(path))



# --------------------------------------------------------------------------- helpers


def uncommented_csv(path: Path, field: str = "table") -> io.StringIO:
    """The text of a CSV file without comment (``#``) and blank lines.

    Parameters
    ----------
    path : Path
        UTF-8 text file [-].
    field : str
        The key that named the file, for messages [-].

    Returns
    -------
    io.StringIO
        The remaining lines [-], for :class:`csv.DictReader`.

    Raises
    ------
    InputError
        The file cannot be read or is not UTF-8 text
        (:func:`~oilgap.model.io.inputs.read_input_text`).
    """
    text = read_input_text(path, field, "CSV file")
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    return io.StringIO("\n".join(lines) + "\n")


def number_or_raw(raw):
    """``float(raw)``, or ``raw`` itself (cut short) when it is not a number (the checks
    name it).

    Parameters
    ----------
    raw : Any
        A CSV cell [in the unit of its column].

    Returns
    -------
    float or Any
        The number [in the unit of its column], or ``raw``
        (:func:`~oilgap.model.io.inputs.cell_for_message`).
    """
    return cell_for_message(raw)
