"""The thermal modes' names and what each applies: the one list every command uses.

A light module (no numpy, CasADi or SciPy), so that the command line's argument tables
import it. The composition of the modes is :mod:`.joint_loss`.

``none``
    The seed paper's isothermal model at the given oil temperature.
``bulk``
    The isothermal film at the bulk temperature of the joint's heat balance to the sea.
``film``
    The film-heating correction at the given oil temperature.
``full``
    The film correction at the heat balance's bulk temperature.

The default (:func:`oilgap.model.joint_loss.default_thermal_mode`) is ``bulk`` with a
``[thermal]`` table, else ``none``: the model the seed's Table 4 supports
(docs/thermal.md, Evidence).

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Table 4 (the measurements the default reproduces).
"""

from __future__ import annotations

from enum import StrEnum


class ThermalMode(StrEnum):
    """A thermal mode (see the module's text); equal to its plain string, so case files,
    JSON and the command line keep naming it ``"none"``, ``"bulk"``, ``"film"``, ``"full"``.

    Attributes
    ----------
    NONE, BULK, FILM, FULL : str
        Isothermal at the given temperature, isothermal at the heat balance's, film
        heating at the given temperature, film heating at the balance's [-].
    """

    NONE = "none"
    BULK = "bulk"
    FILM = "film"
    FULL = "full"


THERMAL_MODES = tuple(m.value for m in ThermalMode)
"""Thermal modes: isothermal at the given temperature, isothermal at the bulk balance's,
film heating at the given temperature, film heating at the bulk balance's [-]."""

FILM_MODES = (ThermalMode.FILM.value, ThermalMode.FULL.value)
"""The modes that apply the film-heating correction [-]."""

BALANCE_MODES = (ThermalMode.BULK.value, ThermalMode.FULL.value)
"""The modes whose bulk oil temperature is the heat balance's (need ``[thermal]``) [-]."""

THERMAL_MODE_TEXT = {
    "none": "isothermal oil, the seed paper's model",
    "bulk": "isothermal film at the oil temperature of the heat balance to the sea",
    "film": "the film's own shear heating at the given oil temperature",
    "full": "film heating at the oil temperature of the heat balance to the sea",
}
"""What each thermal mode computes (the words of the reports' header lines)."""

DEFAULT_MODE_WHY = ("the model the evidence supports: the isothermal film reproduces "
                    "Table 4 of the seed paper")
"""Why the default thermal mode is the default (the reports' header lines)."""

FILM_EVIDENCE = "not supported by Table 4 of the seed paper, see docs/thermal.md#evidence"
"""The evidence of the film-heated modes, as the reports label their band."""


def applies_film(mode: str) -> bool:
    """Whether a thermal mode applies the film-heating correction.

    Parameters
    ----------
    mode : str
        A mode of :data:`THERMAL_MODES` [-].

    Returns
    -------
    bool
        True under ``film`` and ``full`` [-].
    """
    return mode in FILM_MODES


def uses_balance(mode: str) -> bool:
    """Whether a thermal mode takes the bulk temperature from the heat balance.

    Parameters
    ----------
    mode : str
        A mode of :data:`THERMAL_MODES` [-].

    Returns
    -------
    bool
        True under ``bulk`` and ``full`` [-].
    """
    return mode in BALANCE_MODES


def film_counterpart(mode: str) -> ThermalMode:
    """The mode with the same bulk temperature and the opposite film choice.

    Parameters
    ----------
    mode : str
        A mode of :data:`THERMAL_MODES` [-].

    Returns
    -------
    ThermalMode
        ``none`` <-> ``film``, ``bulk`` <-> ``full``: the other side of the film band
        [-] (as resolved as ``mode``: it needs ``[thermal]`` exactly when ``mode`` does).
    """
    return _COUNTERPART[mode]


_COUNTERPART = {ThermalMode.NONE: ThermalMode.FILM, ThermalMode.FILM: ThermalMode.NONE,
                ThermalMode.BULK: ThermalMode.FULL, ThermalMode.FULL: ThermalMode.BULK}
"""The other side of each mode's film band."""


__all__ = ["BALANCE_MODES", "DEFAULT_MODE_WHY", "FILM_EVIDENCE", "FILM_MODES",
           "THERMAL_MODES", "THERMAL_MODE_TEXT", "applies_film", "film_counterpart",
           "uses_balance"]
