"""The grade tolerance as ISO 3448 states it: a tolerance on nu40, carried by the Walther line.

ISO 3448 [1]_ bounds a grade's kinematic viscosity at 40 degC (+-10 % of the grade
number); it says nothing of other temperatures. How a tolerance at 40 degC carries to
the joint's cold oil depends on the oil's viscosity at 100 degC (its viscosity index):
the oil's ASTM D341 (Walther) line [2]_ is rebuilt through ``(f40 nu40, f100 nu100)``,
the same construction as every catalogue oil (:attr:`oilgap.model.oils.Oil.walther`).

- ``nu40_factor`` f40: the factor on nu40 alone (nu100 held unless ``nu100_factor`` moves it);
- ``nu100_factor`` f100: the factor on nu100 (the viscosity index's uncertainty);
- ``nu_factor_all_temperatures``: the old reading, one factor on nu at every temperature
  (:class:`~oilgap.model.fluids.ScaledFluid`), kept as an option (and the only one for
  a fluid without a Walther line: a gas, a tabulated fluid).

:func:`carried_factor` is the factor the two give at another temperature: for VG22
(22/4.5 cSt) ``f40`` 0.9..1.1 gives about 0.75..1.30 at 2 degC (the module's test writes
the Walther equation out by hand).

References
----------
.. [1] ISO 3448:1992, *Industrial liquid lubricants - ISO viscosity classification*
   (mid-point kinematic viscosity at 40 degC, limits +-10 %).
.. [2] ASTM D341-20, viscosity-temperature relationships for liquid petroleum products
   (the Walther line through two points).
"""

from __future__ import annotations

from dataclasses import replace

from ..errors import InputError
from ..fluids import ScaledFluid
from ..oils import Oil


def walther_rebuilt(fluid, nu40_factor: float = 1.0, nu100_factor: float = 1.0):
    """The fluid with its Walther line through ``(f40 nu40, f100 nu100)`` [2]_.

    Parameters
    ----------
    fluid : Oil or ScaledFluid of an Oil
        The case's oil (a scaled oil keeps its uniform factor on top).
    nu40_factor : float
        Factor f40 on the kinematic viscosity at 40 degC [-] (ISO 3448's tolerance [1]_).
    nu100_factor : float
        Factor f100 on the kinematic viscosity at 100 degC [-].

    Returns
    -------
    Oil or ScaledFluid
        The oil with ``nu40_cSt`` and ``nu100_cSt`` scaled (the fluid itself at 1, 1).

    Raises
    ------
    InputError
        A fluid without a Walther line (a gas, a tabulated fluid), or factors that make
        nu100 >= nu40 or leave the Walther line's range.
    """
    if isinstance(fluid, ScaledFluid):
        return ScaledFluid(walther_rebuilt(fluid.base, nu40_factor, nu100_factor),
                           fluid.factor)
    if not isinstance(fluid, Oil):
        raise InputError("nu40_factor", getattr(fluid, "name", fluid),
                         "an oil with a Walther line (nu40_cSt, nu100_cSt); a gas or a "
                         "tabulated fluid takes nu_factor_all_temperatures", "uncertainty")
    for name, f in (("nu40_factor", nu40_factor), ("nu100_factor", nu100_factor)):
        if not f > 0:
            raise InputError(name, f, "a finite number > 0", "uncertainty")
    if nu40_factor == 1.0 and nu100_factor == 1.0:
        return fluid
    if not fluid.nu100_cSt * nu100_factor < fluid.nu40_cSt * nu40_factor:
        raise InputError("nu100_factor", nu100_factor, f"a factor that keeps nu100 below nu40 "
                         f"(below {fluid.nu40_cSt * nu40_factor / fluid.nu100_cSt:.4g} with "
                         f"nu40_factor {nu40_factor:g}, oil {fluid.name!r})", "uncertainty")
    return replace(fluid, nu40_cSt=fluid.nu40_cSt * nu40_factor,
                   nu100_cSt=fluid.nu100_cSt * nu100_factor)


def carried_factor(fluid, temp_C: float, nu40_factor: float = 1.0,
                   nu100_factor: float = 1.0, depth_m: float = 0.0) -> float:
    """Factor on nu at ``temp_C`` of the Walther line rebuilt through (f40 nu40, f100 nu100).

    Parameters
    ----------
    fluid : Oil or ScaledFluid of an Oil
        The oil.
    temp_C : float
        Temperature [degC].
    nu40_factor, nu100_factor : float
        Factors on nu at 40 and 100 degC [-].
    depth_m : float
        Sea depth [m] (the oil's gauge pressure; its Barus factor nearly cancels).

    Returns
    -------
    float
        ``nu_rebuilt(T) / nu(T)`` [-].

    References
    ----------
    ISO 3448 [1]_; ASTM D341 [2]_.
    """
    rebuilt = walther_rebuilt(fluid, nu40_factor, nu100_factor)
    return (rebuilt.kinematic_viscosity_cSt(temp_C, depth_m)
            / fluid.kinematic_viscosity_cSt(temp_C, depth_m))


def carried_text(fluid, temp_C: float, bands: dict[str, tuple[float, float]],
                 depth_m: float = 0.0) -> list[str]:
    """Lines saying what the bands on nu40 and nu100 give at ``temp_C``.

    ``nu40 x0.9..1.1 (nu100 held) -> nu(2 degC) -25/+30 %``, then the same with nu100
    over its band (the four corners' extremes).

    Parameters
    ----------
    fluid : Oil or ScaledFluid of an Oil
        The oil.
    temp_C : float
        The case's oil temperature [degC].
    bands : dict
        ``nu40_factor``/``nu100_factor`` -> (low, high) [-] (their laws' 0/100 % or
        5/95 % points); a missing one is held at 1.
    depth_m : float
        Sea depth [m].

    Returns
    -------
    list of str
        One line per band given (empty without ``nu40_factor`` and ``nu100_factor``).
    """
    b40, b100 = bands.get("nu40_factor"), bands.get("nu100_factor")
    if b40 is None and b100 is None:
        return []

    def pct(f: float) -> str:
        return f"{100 * (f - 1):+.0f} %"

    def span(pairs) -> str:
        fs = [carried_factor(fluid, temp_C, a, b, depth_m) for a, b in pairs]
        return f"{pct(min(fs))}/{pct(max(fs))}"

    at = f"nu({temp_C:g} degC)"
    lines = []
    if b40 is not None:
        lines.append(f"nu40 x{b40[0]:g}..{b40[1]:g} (nu100 held) -> {at} "
                     f"{span([(b40[0], 1.0), (b40[1], 1.0)])}")
    if b100 is not None:
        corners = [(a, b) for a in (b40 or (1.0, 1.0)) for b in b100]
        lines.append(f"nu100 x{b100[0]:g}..{b100[1]:g}"
                     + (" with nu40's band" if b40 is not None else "")
                     + f" -> {at} {span(corners)}")
    return lines


def has_walther_line(fluid) -> bool:
    """Whether a fluid has a Walther line that ``nu40_factor`` can rebuild.

    Parameters
    ----------
    fluid : Fluid
        An oil, a scaled oil, a gas or a property table.

    Returns
    -------
    bool
        True for an oil (or a scaled oil) with a Walther line (ASTM D341) [-].
    """
    return isinstance(fluid.base if isinstance(fluid, ScaledFluid) else fluid, Oil)


__all__ = ["carried_factor", "carried_text", "has_walther_line", "walther_rebuilt"]
