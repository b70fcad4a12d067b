"""The ``[bearing]`` table of a case file: read into a bearing, written back as given.

A case's rolling bearing is one optional table, ``[bearing]`` (keys with their units:
``designation``, ``bore_mm``, ``outside_mm``, ``radial_load_N``, ...; every key, unit and
default in ``docs/case-file.md``). The table is read by
:func:`oilgap.model.bearing.catalogue.bearing_spec_from`, which fills in what the user
left out (the designation's catalogue geometry, the models' constants) and names it in
``BearingSpec.defaults_used``; it is written back by
:func:`~oilgap.model.bearing.catalogue.bearing_table`, the keys the user gave and only
those, so a case read, written and read again has the same bearing and the same
defaults. Without the table the case has no bearing and its document is what it was
before bearings existed.

References
----------
.. [1] SKF, *Rolling bearings*, catalogue 10000 EN (2013), "Friction" and the deep-groove
   ball bearing tables (the laws and data behind :mod:`oilgap.model.bearing`).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from ..bearing.catalogue import bearing_spec_from, bearing_table, describe_defaults
from ..bearing.friction import BearingSpec

BEARING_TABLE = "bearing"
"""Name of the case file's bearing table [-]."""


def bearing_from_doc(doc: dict) -> BearingSpec | None:
    """The bearing of a parsed case document, or None without a ``[bearing]`` table.

    Parameters
    ----------
    doc : dict
        The parsed TOML of a case (units in the key names: ``bore_mm`` [mm],
        ``radial_load_N`` [N]).

    Returns
    -------
    BearingSpec or None
        The bearing [SI], the defaults filled in named in ``defaults_used``.

    Raises
    ------
    InputError
        ``bearing`` not a table, an unknown key or a bad value (the message names the
        key).

    References
    ----------
    SKF catalogue [1]_ (the designation's geometry).
    """
    if BEARING_TABLE not in doc:
        return None
    return bearing_spec_from(doc[BEARING_TABLE], "case TOML [bearing]")


def bearing_to_doc(spec: BearingSpec) -> dict[str, Any]:
    """The ``[bearing]`` table of a bearing: what the user gave, not the defaults.

    Parameters
    ----------
    spec : BearingSpec
        The bearing [SI].

    Returns
    -------
    dict
        TOML key -> value in the key's unit [mm, N, -]; :func:`bearing_from_doc` reads
        it back to the same bearing.
    """
    return bearing_table(spec)


def bearing_defaults(spec: BearingSpec) -> dict[str, Any]:
    """The values the tool filled in for a bearing, by ``[bearing]`` key.

    Parameters
    ----------
    spec : BearingSpec
        The bearing [SI].

    Returns
    -------
    dict
        TOML key of each entry of ``spec.defaults_used`` -> its value in the key's unit
        [mm, N, -] (what the output shows as the defaults).
    """
    full = bearing_table(replace(spec, defaults_used=()))
    return {k: full[k] for k in spec.defaults_used if k in full}


def bearing_default_notes(spec: BearingSpec) -> tuple[str, ...]:
    """One line per default the tool filled in, with its value and its basis.

    Parameters
    ----------
    spec : BearingSpec
        The bearing [SI].

    Returns
    -------
    tuple of str
        ``"key = value (basis)"`` [units of the key]
        (:func:`~oilgap.model.bearing.catalogue.describe_defaults`).
    """
    return describe_defaults(spec)
