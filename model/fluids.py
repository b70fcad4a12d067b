"""Fluids that are not mineral oils (an ideal gas; the property table of
:mod:`oilgap.model.fluid_table`) and the interface every fluid shares.

Every fluid of a case (a mineral :class:`~oilgap.model.oils.Oil`, a
:class:`~oilgap.model.fluid_table.TableFluid`, a :class:`GasFluid`) offers the same
interface, :class:`Fluid`:
``properties(temp_K, pressure_gauge_Pa) -> (nu [m^2/s], mu [Pa s], rho [kg/m^3])``,
``kinematic_viscosity_cSt(temp_C, depth_m)``, ``temperature_slope(temp_K,
pressure_gauge_Pa) = -d ln(mu)/dT [1/K]``, ``kind``, ``trusted_range_C`` and
``polymer_thickened``. The pressure is the gauge pressure of the compensating system
(the sea-water column at the case's depth), as for oils.

Laws
----
* Gas viscosity, Sutherland: ``mu = mu_ref (T/T_ref)^(3/2) (T_ref + S)/(T + S)`` [1, 2];
  independent of pressure (a dilute-gas law).
* Gas density, ideal gas: ``rho = p_abs M / (R_u T)``, ``p_abs = 101325 Pa + p_gauge`` [3].
* Table (:mod:`~oilgap.model.fluid_table`): ``ln nu`` and ``rho`` linear in T, bilinear
  in (T, p) with pressures; refused (or clamped with a warning) outside the table.

References
----------
.. [1] W. Sutherland, "The viscosity of gases and molecular force", Phil. Mag. S. 5,
   36:507-531, 1893.
.. [2] F. M. White, *Viscous Fluid Flow*, 3rd ed., McGraw-Hill 2006, Eq. 1-36 and
   Table 1-2 (Sutherland constants; range of 2 % error).
.. [3] CODATA 2018: molar gas constant R_u = 8.314462618 J/(mol K) (exact in the SI
   since 2019); ideal-gas law.
.. [4] E. W. Lemmon, R. T. Jacobsen, "Viscosity and thermal conductivity equations for
   nitrogen, oxygen, argon, and air", Int. J. Thermophys. 25:21-69, 2004 (the dense-gas
   part of the viscosity that Sutherland's law leaves out).
"""

from __future__ import annotations

import csv
import math
import warnings
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Protocol, runtime_checkable

import numpy as np

from . import _math as m
from .errors import InputError, OilgapWarning, check_finite
from .fluid_table import TableFluid, number_or_raw, read_fluid_table, uncommented_csv
from .io.inputs import check_physical
from .oil_properties import seawater_gauge_pressure
from .units import (
    MPA_TO_PA,
    STANDARD_ATMOSPHERE_PA,
    celsius_to_kelvin,
    kelvin_to_celsius,
    m2_s_to_cst,
)

__all__ = ["FLUID_KINDS", "Fluid", "GasFluid", "ScaledFluid", "TableFluid", "builtin_gases",
           "gas_key", "read_fluid_table", "read_gases_csv", "warn_if_sea_below_pour_point",
           "warn_if_untrusted_state"]

FLUID_KINDS = ("mineral", "table", "gas")
"""The kinds of fluid a case may hold."""

MOLAR_GAS_CONSTANT_J_MOL_K = 8.314462618
"""Molar gas constant R_u [J/(mol K)] (CODATA 2018, exact) [3]."""

GAS_TRUSTED_PRESSURE_ABS_PA = 1.0e6
"""Absolute pressure [Pa] above which oilgap warns that a gas is no longer dilute: the
ideal-gas density and Sutherland's pressure-free viscosity leave out the real-gas
compressibility and the dense-gas rise of viscosity [4]."""

GAS_LIMITS = {  # TOML key -> (largest value, why)
    "molar_mass_kg_per_mol": (1.0, "the heaviest gases (UF6 0.352, SF6 0.146 kg/mol) are "
                              "far below 1 kg/mol"),
    "sutherland_mu_ref_Pa_s": (1.0e-3, "gases have 1e-5-5e-5 Pa s; 1e-3 is a liquid's"),
    "sutherland_T_ref_K": (5000.0, "Sutherland's law is fitted between ~100 and ~2000 K"),
    "sutherland_S_K": (5000.0, "Sutherland constants are 70-700 K [2]"),
}
"""Largest physical value of each constant of a gas, with the reason (all must be > 0)."""

TABLE_NO_PRESSURE_WARN_PA = 1.0e6
"""Gauge pressure [Pa] above which oilgap warns that a table without pressures is used at
atmospheric-pressure properties."""


@runtime_checkable
class Fluid(Protocol):
    """The interface every fluid of a case offers (Oil, TableFluid, GasFluid).

    Attributes
    ----------
    name : str
        Name in reports [-].
    kind : str
        ``"mineral"``, ``"table"`` or ``"gas"`` [-].
    trusted_range_C : tuple of float
        Temperatures [degC] over which the fluid's law is trusted.
    polymer_thickened : bool
        True for a polymer-thickened liquid (shear thinning plausible) [-].
    """

    name: str

    @property
    def kind(self) -> str: ...

    @property
    def trusted_range_C(self) -> tuple[float, float]: ...

    @property
    def polymer_thickened(self) -> bool: ...

    def properties(self, temp_K, pressure_gauge_Pa=0.0): ...

    def kinematic_viscosity_cSt(self, temp_C, depth_m=0.0) -> float: ...

    def temperature_slope(self, temp_K, pressure_gauge_Pa=0.0): ...


# --------------------------------------------------------------------------- scaled


@dataclass(frozen=True)
class ScaledFluid:
    """A fluid whose viscosity is a constant factor times another's, at every state.

    The uncertain input ``nu_factor_all_temperatures`` of :mod:`oilgap.model.uncertain`:
    one factor on the viscosity at every temperature and pressure, the Walther line
    shifted in ``ln nu``, its slope ``b = -d ln(mu)/dT`` and the density unchanged. (ISO
    3448's grade tolerance [1]_ bounds nu at 40 degC alone: ``nu40_factor``,
    :mod:`oilgap.model.uncertain.grade`.)

    Attributes
    ----------
    base : Fluid
        The nominal fluid.
    factor : float
        Viscosity factor f > 0 [-] (1: the nominal fluid).

    References
    ----------
    .. [1] ISO 3448:1992, *Industrial liquid lubricants - ISO viscosity classification*
       (mid-point kinematic viscosity at 40 degC, limits +-10 %).
    """

    base: Fluid
    factor: float

    def __post_init__(self):
        if isinstance(self.factor, bool) or not isinstance(self.factor, (int, float)) \
                or not math.isfinite(self.factor) or self.factor <= 0:
            raise InputError("nu_factor_all_temperatures", self.factor, "a finite number > 0",
                             "oil")

    @property
    def name(self) -> str:
        """The base fluid's name [-]."""
        return self.base.name

    @property
    def kind(self) -> str:
        """The base fluid's kind [-]."""
        return self.base.kind

    @property
    def trusted_range_C(self) -> tuple[float, float]:
        """The base fluid's trusted range [degC]."""
        return self.base.trusted_range_C

    @property
    def polymer_thickened(self) -> bool:
        """The base fluid's flag [-]."""
        return self.base.polymer_thickened

    @property
    def newtonian(self) -> bool:
        """The base fluid's flag [-]."""
        return getattr(self.base, "newtonian", True)

    def properties(self, temp_K, pressure_gauge_Pa=0.0):
        """The base fluid's properties with both viscosities times the factor.

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Temperature [K].
        pressure_gauge_Pa : float, array or CasADi symbol
            Pressure above atmospheric [Pa].

        Returns
        -------
        nu_m2_s, mu_Pa_s, rho_kg_m3
            [m^2/s], [Pa s], [kg/m^3].
        """
        nu, mu, rho = self.base.properties(temp_K, pressure_gauge_Pa)
        return self.factor * nu, self.factor * mu, rho

    def kinematic_viscosity_cSt(self, temp_C, depth_m=0.0) -> float:
        """Kinematic viscosity [cSt] at oil temperature [degC] and sea depth [m].

        Parameters
        ----------
        temp_C : float
            Temperature [degC].
        depth_m : float
            Sea depth [m].

        Returns
        -------
        float
            The base fluid's value times the factor [cSt].
        """
        return self.factor * self.base.kinematic_viscosity_cSt(temp_C, depth_m)

    def temperature_slope(self, temp_K, pressure_gauge_Pa=0.0):
        """``b = -d ln(mu)/dT`` [1/K]: the base fluid's (a constant factor drops out).

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Temperature [K].
        pressure_gauge_Pa : float, array or CasADi symbol
            Pressure above atmospheric [Pa].

        Returns
        -------
        float, array or CasADi expression
            b [1/K].
        """
        return self.base.temperature_slope(temp_K, pressure_gauge_Pa)


# --------------------------------------------------------------------------- gas


@dataclass(frozen=True)
class GasFluid:
    """An ideal gas with Sutherland's viscosity law [1, 2, 3].

    Attributes
    ----------
    name : str
        Name in reports ('air', 'nitrogen') [-].
    molar_mass_kg_mol : float
        Molar mass M [kg/mol].
    mu_ref_Pa_s : float
        Dynamic viscosity at the reference temperature [Pa s].
    T_ref_K : float
        Reference temperature of Sutherland's law [K].
    sutherland_S_K : float
        Sutherland temperature S [K].
    trusted_range_K : tuple of float
        Temperatures [K] over which the law is trusted (default: unbounded).

    Raises
    ------
    InputError
        A non-positive constant, or a trusted range that is not lo < hi.
    """

    name: str
    molar_mass_kg_mol: float
    mu_ref_Pa_s: float
    T_ref_K: float
    sutherland_S_K: float
    trusted_range_K: tuple[float, float] = (0.0, math.inf)

    def __post_init__(self):
        where = f"gas {self.name!r}"
        for f, key in (("molar_mass_kg_mol", "molar_mass_kg_per_mol"),
                       ("mu_ref_Pa_s", "sutherland_mu_ref_Pa_s"),
                       ("T_ref_K", "sutherland_T_ref_K"), ("sutherland_S_K", "sutherland_S_K")):
            object.__setattr__(self, f, check_physical(key, getattr(self, f), 0.0,
                                                       GAS_LIMITS[key][0], GAS_LIMITS[key][1],
                                                       where, lo_open=True))
        lo, hi = (float(v) for v in self.trusted_range_K)
        if not (lo < hi) or math.isnan(lo) or math.isnan(hi) or lo < 0.0:
            raise InputError("trusted range [K]", (lo, hi), "must be 0 <= lo < hi", where)
        object.__setattr__(self, "trusted_range_K", (lo, hi))

    @property
    def kind(self) -> str:
        """``"gas"`` [-]."""
        return "gas"

    @property
    def polymer_thickened(self) -> bool:
        """Always False: a gas is Newtonian [-]."""
        return False

    @property
    def newtonian(self) -> bool:
        """Always True [-]."""
        return True

    @property
    def trusted_range_C(self) -> tuple[float, float]:
        """Trusted temperatures of the Sutherland law [degC]."""
        lo, hi = self.trusted_range_K
        return (float(kelvin_to_celsius(lo)), float(kelvin_to_celsius(hi)))

    def viscosity(self, temp_K):
        """Dynamic viscosity by Sutherland's law [Pa s] [1, 2].

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Temperature [K].

        Returns
        -------
        float, array or CasADi expression
            ``mu_ref (T/T_ref)^(3/2) (T_ref + S)/(T + S)`` [Pa s].
        """
        t = temp_K / self.T_ref_K
        return (self.mu_ref_Pa_s * t * m.sqrt(t) * (self.T_ref_K + self.sutherland_S_K)
                / (temp_K + self.sutherland_S_K))

    def density(self, temp_K, pressure_gauge_Pa=0.0):
        """Ideal-gas density ``p_abs M / (R_u T)`` [kg/m^3] [3].

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Temperature [K].
        pressure_gauge_Pa : float, array or CasADi symbol
            Pressure above the standard atmosphere [Pa].

        Returns
        -------
        float, array or CasADi expression
            Density [kg/m^3].

        Raises
        ------
        InputError
            A numeric absolute pressure <= 0.
        """
        p_abs = STANDARD_ATMOSPHERE_PA + pressure_gauge_Pa
        if not m.is_symbolic(p_abs) and np.any(np.asarray(p_abs) <= 0.0):
            raise InputError("pressure_gauge_Pa", float(np.min(pressure_gauge_Pa)),
                             "the absolute pressure of a gas must be > 0", f"gas {self.name!r}")
        return p_abs * self.molar_mass_kg_mol / (MOLAR_GAS_CONSTANT_J_MOL_K * temp_K)

    def properties(self, temp_K, pressure_gauge_Pa=0.0):
        """Kinematic and dynamic viscosity and density at temperature and gauge pressure.

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Gas temperature [K].
        pressure_gauge_Pa : float, array or CasADi symbol
            Pressure above the standard atmosphere [Pa].

        Returns
        -------
        nu_m2_s, mu_Pa_s, rho_kg_m3
            [m^2/s], [Pa s], [kg/m^3]: Sutherland [1, 2] and the ideal gas [3].
        """
        mu = self.viscosity(temp_K)
        rho = self.density(temp_K, pressure_gauge_Pa)
        return mu / rho, mu, rho

    def kinematic_viscosity_cSt(self, temp_C, depth_m=0.0) -> float:
        """Kinematic viscosity [cSt] at temperature [degC] and the pressure of a depth [m].

        Parameters
        ----------
        temp_C : float
            Gas temperature [degC].
        depth_m : float
            Sea depth [m]; the compensated gas carries the water column's gauge pressure.

        Returns
        -------
        float
            Kinematic viscosity [cSt].
        """
        nu, _, _ = self.properties(celsius_to_kelvin(temp_C), seawater_gauge_pressure(depth_m))
        return m2_s_to_cst(nu)

    def temperature_slope(self, temp_K, pressure_gauge_Pa=0.0):
        """Viscosity-temperature slope ``b = -d ln(mu)/dT = -(3/(2T) - 1/(T + S))`` [1/K].

        Negative: a gas's viscosity rises with temperature. Sutherland's law has no
        pressure term, so ``pressure_gauge_Pa`` does not enter.

        Parameters
        ----------
        temp_K : float, array or CasADi symbol
            Temperature [K].
        pressure_gauge_Pa : float or array
            Gauge pressure [Pa] (no effect).

        Returns
        -------
        float, array or CasADi expression
            b [1/K].

        References
        ----------
        The derivative of Sutherland's law [1, 2].
        """
        return 1.0 / (temp_K + self.sutherland_S_K) - 1.5 / temp_K


def read_gases_csv(path: str | Path) -> dict[str, GasFluid]:
    """Read a gas table ``gas,molar_mass_kg_per_mol,mu_ref_Pa_s,T_ref_K,S_K,trusted_min_K,
    trusted_max_K`` (lines starting with ``#`` are comments).

    Parameters
    ----------
    path : str or Path
        CSV file; molar mass [kg/mol], Sutherland constants [Pa s], [K], [K], trusted
        range [K].

    Returns
    -------
    dict of str to GasFluid
        Keyed by :func:`gas_key`.

    Raises
    ------
    InputError
        Missing columns or bad values.
    """
    path = Path(path)
    rows = list(csv.DictReader(uncommented_csv(path)))
    cols = ("gas", "molar_mass_kg_per_mol", "mu_ref_Pa_s", "T_ref_K", "S_K", "trusted_min_K",
            "trusted_max_K")
    out: dict[str, GasFluid] = {}
    for i, row in enumerate(rows, start=2):
        missing = [c for c in cols if c not in row or row[c] in (None, "")]
        if missing:
            raise InputError("columns", missing, f"required: {list(cols)}", f"{path} row {i}")
        where = f"{path} row {i}"
        v = {c: check_finite(c, number_or_raw(row[c]), where) for c in cols[1:]}
        out[gas_key(row["gas"])] = GasFluid(
            row["gas"].strip(), v["molar_mass_kg_per_mol"], v["mu_ref_Pa_s"], v["T_ref_K"],
            v["S_K"], (v["trusted_min_K"], v["trusted_max_K"]))
    return out


def gas_key(name: str) -> str:
    """Canonical key of a gas name ('Air', ' N2 ' -> 'AIR', 'N2'); as the oils' keys [-].

    Parameters
    ----------
    name : str
        Name as written [-].

    Returns
    -------
    str
        Upper case without spaces, dashes or underscores.
    """
    return str(name).strip().upper().replace(" ", "").replace("-", "").replace("_", "")


_GASES: dict[str, GasFluid] | None = None


def builtin_gases() -> dict[str, GasFluid]:
    """The built-in gases ('air', 'nitrogen'), keyed by :func:`gas_key`.

    Returns
    -------
    dict of str to GasFluid
        Sutherland constants of White's Table 1-2 [2] ([Pa s], [K]) and molar masses
        [kg/mol] (``model/data/gases.csv``).
    """
    global _GASES
    if _GASES is None:
        with resources.as_file(resources.files(__package__) / "data" / "gases.csv") as p:
            _GASES = read_gases_csv(p)
    return dict(_GASES)


# --------------------------------------------------------------------------- warnings


_LAW_NOTE = {
    "mineral": "where the Walther line through the 40 and 100 degC points is trusted; the "
               "viscosity there is an extrapolation",
    "gas": "the range given for the Sutherland law of {name}; the viscosity there is an "
           "extrapolation",
}


def warn_if_sea_below_pour_point(fluid, sea_temp_C: float) -> None:
    """Warn (OilgapWarning) when the sea is colder than the lower end of a mineral oil's
    trusted range (-20 degC for the Walther line), near or below the pour point of mineral
    compensating oils (about -15 to -40 degC for ISO VG 15-100 hydraulic oils, ISO 3016):
    the oil that touches the sea (compensator, seals, outer wall) may not flow, whatever
    the balance makes of the bulk oil's temperature.

    Parameters
    ----------
    fluid : Fluid
        The fluid (its ``kind``, ``name`` and ``trusted_range_C``); only a mineral oil is
        checked.
    sea_temp_C : float
        Sea temperature [degC].
    """
    if fluid.kind != "mineral":
        return
    lo = fluid.trusted_range_C[0]
    if sea_temp_C < lo:
        warnings.warn(f"sea_temp_C = {sea_temp_C:g} degC lies below {lo:g} degC, near or "
                      "below the pour point of mineral compensating oils (about -15 to -40 "
                      f"degC, ISO 3016): {fluid.name!r} touching the sea may not flow, "
                      "whatever the balance makes of the bulk oil", OilgapWarning,
                      stacklevel=2)


def warn_if_untrusted_state(fluid, temp_C, pressure_gauge_Pa=0.0,
                            field: str = "oil_temp_C") -> None:
    """Warn (OilgapWarning) where a fluid's laws are not trusted.

    A mineral oil or a gas outside its ``trusted_range_C``; a gas above
    :data:`GAS_TRUSTED_PRESSURE_ABS_PA`; a table without pressures used above
    :data:`TABLE_NO_PRESSURE_WARN_PA`. (A table refuses, or warns, outside its
    temperatures by itself.)

    Parameters
    ----------
    fluid : Fluid
        The fluid (its ``kind``, ``name`` and ``trusted_range_C``).
    temp_C : float or array
        Temperature(s) [degC].
    pressure_gauge_Pa : float or array
        Gauge pressure(s) [Pa].
    field : str
        Name of the temperature in the warning [-].
    """
    kind = fluid.kind
    t = np.asarray(temp_C, dtype=float)
    if kind in _LAW_NOTE and t.size:
        lo, hi = fluid.trusted_range_C
        if np.nanmin(t) < lo or np.nanmax(t) > hi:
            lo_t, hi_t = float(np.nanmin(t)), float(np.nanmax(t))
            shown = f"{lo_t:g}" if lo_t == hi_t else f"{lo_t:g}..{hi_t:g}"
            warnings.warn(f"{field} = {shown} degC lies outside [{lo:g}, {hi:g}] degC, "
                          + _LAW_NOTE[kind].format(name=repr(fluid.name)),
                          OilgapWarning, stacklevel=2)
    p = np.asarray(pressure_gauge_Pa, dtype=float)
    if not p.size:
        return
    p_max = float(np.nanmax(p))
    if kind == "gas" and p_max + STANDARD_ATMOSPHERE_PA > GAS_TRUSTED_PRESSURE_ABS_PA:
        warnings.warn(f"gas {fluid.name!r} at {(p_max + STANDARD_ATMOSPHERE_PA) / MPA_TO_PA:g} "
                      f"MPa absolute: above {GAS_TRUSTED_PRESSURE_ABS_PA / MPA_TO_PA:g} MPa the "
                      "ideal-gas density and Sutherland's pressure-free viscosity leave out "
                      "real-gas effects", OilgapWarning, stacklevel=2)
    table = fluid.base if isinstance(fluid, ScaledFluid) else fluid
    if kind == "table" and not table.pressures_Pa and p_max > TABLE_NO_PRESSURE_WARN_PA:
        warnings.warn(f"the table of {fluid.name!r} has no pressures: its atmospheric "
                      f"properties are used at {p_max / MPA_TO_PA:g} MPa gauge",
                      OilgapWarning, stacklevel=2)
