"""The ``[uncertainty]`` table of a case file: read into an UncertaintySpec, written back.

One sub-table per uncertain input (:data:`oilgap.model.uncertain.inputs.INPUTS`), its law
in ``dist`` and the law's parameters with their units in the key names
(:func:`oilgap.model.uncertain.distributions.param_key`)::

    [uncertainty.oil_temp_C]
    dist = "normal"
    mean_C = 2.0
    sd_K = 1.5

    [uncertainty.nu40_factor]
    dist = "uniform"
    low = 0.9
    high = 1.1

    [uncertainty.gamma]
    dist = "lognormal"      # median [-] and sigma_ln, the sd of ln gamma [-]
    median = 0.566
    sigma_ln = 0.07

    [uncertainty.depth_m]
    dist = "triangular"
    low_m = 2500.0
    mode_m = 3000.0
    high_m = 3500.0

An optional ``source`` string says where a law comes from (shown in the output). Every
key is checked; ``film_strength`` needs ``[thermal]`` (its walls and strength live there);
``bearing_drag_scale`` without ``[bearing]`` changes nothing and is refused as well.
Without the table the case's ``uncertainty`` is None and the documented defaults apply
(:func:`oilgap.model.uncertain.distributions.case_uncertainty`).

References
----------
.. [1] ISO 3448:1992 (the +-10 % band on a grade's nu at 40 degC, the default on
   ``nu40_factor``).
"""

from __future__ import annotations

from typing import Any

from ..errors import InputError, check_finite
from ..uncertain.distributions import KINDS, Distribution, UncertaintySpec, param_key
from ..uncertain.inputs import INPUTS

UNCERTAINTY_TABLE = "uncertainty"
"""Name of the case file's uncertainty table [-]."""
_NEEDS = {"film_strength": ("thermal", "the film's walls and strength live in [thermal]"),
          "bearing_drag_scale": ("bearing", "it scales the rolling bearing's drag: without "
                                            "[bearing] it changes nothing")}


def uncertainty_from_doc(doc: dict) -> UncertaintySpec | None:
    """The uncertain inputs of a parsed case document, or None without ``[uncertainty]``.

    Parameters
    ----------
    doc : dict
        The parsed TOML of a case (units in the key names: ``mean_C`` [degC], ``sd_K``
        [K], ``low_m`` [m], ``mean_rpm`` [rpm]; factors and exponents [-]).

    Returns
    -------
    UncertaintySpec or None
        One :class:`~oilgap.model.uncertain.distributions.Distribution` per sub-table, in
        the file's order.

    Raises
    ------
    InputError
        ``uncertainty`` or one of its inputs not a table, an unknown input, law or key,
        a missing or non-finite parameter, sd <= 0, low >= high, a mode outside
        low..high, a law reaching outside the input's range, ``film_strength`` without
        ``[thermal]``, ``bearing_drag_scale`` without ``[bearing]``; the message names
        ``uncertainty.<input>.<key>``.

    References
    ----------
    ISO 3448 [1]_ (the default band on nu40 when the table is absent).
    """
    if UNCERTAINTY_TABLE not in doc:
        return None
    ud = doc[UNCERTAINTY_TABLE]
    if not isinstance(ud, dict) or not ud:
        raise InputError("uncertainty", ud, "a table of inputs, e.g. [uncertainty.gamma] "
                         "dist = \"normal\", mean = 0.566, sd = 0.041", "case TOML")
    dists = [_distribution(name, table, doc) for name, table in ud.items()]
    return UncertaintySpec(distributions=tuple(dists), source="case [uncertainty]")


def _distribution(name: str, table: Any, doc: dict) -> Distribution:
    where = f"uncertainty.{name}"
    if name not in INPUTS:
        raise InputError("uncertainty", name, f"an input: one of {', '.join(INPUTS)}",
                         "case TOML")
    if not isinstance(table, dict):
        raise InputError(where, table, f"a table [{where}] with dist and its parameters",
                         "case TOML")
    if name in _NEEDS and _NEEDS[name][0] not in doc:
        need, why = _NEEDS[name]
        raise InputError(where, table.get("dist"), f"an input of a case with a [{need}] "
                         f"table ({why})", "case TOML")
    kind = table.get("dist")
    if kind not in KINDS:
        raise InputError(f"{where}.dist", kind, f"one of {', '.join(KINDS)}", "case TOML")
    keys = {param_key(name, p): p for p in KINDS[kind]}
    for k in table:
        if k not in keys and k not in ("dist", "source"):
            raise InputError(f"{where}.{k}", table[k], f"unknown key; a {kind} law of {name} "
                             f"takes {', '.join(keys)} (and source)", "case TOML")
    for k in keys:
        if k not in table:
            raise InputError(f"{where}.{k}", None, f"is required by a {kind} law", "case TOML")
    params = tuple((p, check_finite(f"{where}.{k}", table[k], "case TOML"))
                   for k, p in keys.items())
    source = table.get("source", "case [uncertainty]")
    if not isinstance(source, str):
        raise InputError(f"{where}.source", source, "a string", "case TOML")
    return Distribution(input=name, kind=kind, params=params, source=source)


def uncertainty_to_doc(spec: UncertaintySpec) -> dict[str, dict[str, Any]]:
    """The ``[uncertainty]`` table of a spec (inverse of :func:`uncertainty_from_doc`).

    Parameters
    ----------
    spec : UncertaintySpec
        The uncertain inputs (a correlated spec from a ``loop.json`` is refused: the
        table holds independent laws only).

    Returns
    -------
    dict
        Input -> ``{dist, <param key>: value [its unit], source}`` (source only when it
        is not the table's own).
    """
    if spec.correlation is not None:
        raise InputError("uncertainty.correlation", "given", "independent laws only in a "
                         "case file (a loop.json's joint law is read with --model)")
    out: dict[str, dict[str, Any]] = {}
    for d in spec.distributions:
        t: dict[str, Any] = {"dist": d.kind, **{param_key(d.input, k): v for k, v in d.params}}
        if d.source != "case [uncertainty]":
            t["source"] = d.source
        out[d.input] = t
    return out


__all__ = ["UNCERTAINTY_TABLE", "uncertainty_from_doc", "uncertainty_to_doc"]
