"""The physical domain of each library effect: where its mechanism can act.

An effect whose domain the data never reach is not a candidate of the measured-data
loop (issue 25): its column would only fit noise or stand in, as a proxy, for a
mechanism the library lacks. Each effect of :data:`~oilgap.model.effects.EFFECTS`
carries a :class:`Domain` (its ``domain`` field): a short statement, the reference it
rests on, and a predicate on the data (an :class:`~oilgap.model.effects.EffectContext`)
and the rig's facts (:class:`~oilgap.model.effects.RigFacts`) that says, with the
numbers, why the data stay outside it.

- Taylor-vortex onset needs a clearance whose Taylor number exceeds the critical one
  (Ta > Ta_c = 41.3, narrow gap, the library's onset) at some sample [1]_.
- Shear thinning needs a polymer-thickened liquid among the fluids of the oil runs;
  straight mineral oils, synthetic base oils and gases are Newtonian at a clearance's
  shear rates [2]_.
- The bearing terms need a bearing: a bearing region for the ball churning, a case
  ``[bearing]`` for the balls' drag (their features say so when absent).
- The other effects (end faces, seal, inertia, lags, delay, film heating) act on every
  rotating joint; their time-dependent ones need a time record, which the loop's
  steady-point rule already states.

References
----------
.. [1] G. I. Taylor, "Stability of a viscous liquid contained between two rotating
   cylinders", Phil. Trans. R. Soc. A 223:289-343, 1923.
.. [2] R. B. Bird, R. C. Armstrong, O. Hassager, *Dynamics of Polymeric Liquids*, vol. 1,
   2nd ed., Wiley 1987, sec. 4.4.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .laws import CRITICAL_TAYLOR_NUMBER
from .plausibility import RigFacts

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .library import EffectContext


def _everywhere(ctx: EffectContext, facts: RigFacts | None) -> str | None:
    return None


@dataclass(frozen=True, kw_only=True)
class Domain:
    """Where an effect's mechanism can act.

    Attributes
    ----------
    statement : str
        The domain in words [-], e.g. ``"Ta > Ta_c = 41.3 in a clearance"``.
    reference : str
        What the statement rests on [-].
    outside : callable
        ``(EffectContext, RigFacts or None) -> str or None``: why the data never reach
        the domain, with the numbers in the data's units (None: they reach it) [-].
    """

    statement: str
    reference: str = ""
    outside: Callable[[EffectContext, RigFacts | None], str | None] = _everywhere

    def reason(self, ctx: EffectContext, facts: RigFacts | None = None) -> str | None:
        """``"not a candidate: ..."``, or None when the data reach the domain.

        Parameters
        ----------
        ctx : EffectContext
            The oil runs' per-sample quantities (SI).
        facts : RigFacts, optional
            The rig's fluids (None: unknown, the fluid rules are not applied).

        Returns
        -------
        str or None
        """
        why = self.outside(ctx, facts)
        return None if why is None else f"not a candidate: {why}"


def max_taylor_number(ctx: EffectContext) -> float:
    """Largest Taylor number ``Ta = Re (delta/R)^0.5`` of any clearance region over the
    samples [-] (seed Eq. 3; 0 without regions).

    Parameters
    ----------
    ctx : EffectContext

    Returns
    -------
    float
    """
    tas = [np.max(np.abs(np.asarray(r.taylor, float))) for r in ctx.regions]
    return float(max(tas)) if tas else 0.0


def _below_taylor_onset(ctx: EffectContext, facts: RigFacts | None) -> str | None:
    ta = max_taylor_number(ctx)
    if ta > CRITICAL_TAYLOR_NUMBER:
        return None
    return (f"the data never reach Ta > Ta_c = {CRITICAL_TAYLOR_NUMBER:g} "
            f"(max Ta {ta:.3g})")


def _no_polymer(ctx: EffectContext, facts: RigFacts | None) -> str | None:
    if facts is None or not facts.fluids or any(f.polymer_thickened for f in facts.fluids):
        return None
    names = ", ".join(f.name for f in facts.fluids)
    return (f"no polymer-thickened liquid among the fluids of the oil runs ({names}: "
            "Newtonian)")


DOMAINS: dict[str, Domain] = {
    "end_face_disc": Domain(statement="any rotating joint (the rotor's end faces)"),
    "bearing_ball_churning": Domain(statement="a bearing region (the feature is absent "
                                    "without one)"),
    "bearing_ball_drag": Domain(statement="a case with a [bearing] (the feature is absent "
                                "without one)"),
    "seal_coulomb_friction": Domain(statement="any joint with a contact seal"),
    "oil_inertia": Domain(statement="a time record with speed changes"),
    "thermal_lag": Domain(statement="a time record with temperature changes"),
    "taylor_vortex_onset": Domain(
        statement=f"Ta > Ta_c = {CRITICAL_TAYLOR_NUMBER:g} in a clearance (Taylor vortices)",
        reference="Taylor 1923", outside=_below_taylor_onset),
    "shear_thinning": Domain(
        statement="a polymer-thickened liquid among the fluids (non-Newtonian)",
        reference="Bird, Armstrong & Hassager 1987 sec. 4.4", outside=_no_polymer),
    "sensor_delay": Domain(statement="a time record with power changes"),
    "film_heating": Domain(statement="any clearance with a temperature law of viscosity"),
}
"""The physical domain of each library effect, by stable name."""
