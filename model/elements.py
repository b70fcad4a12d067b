"""A joint's elements besides its clearance regions: the one list the composition sums.

A joint is a set of elements, each a law of the oil state and its own kinematics, called
with the motor's speed nodes, their weights and the oil's (nu, rho). The clearance
regions (:mod:`.regions`) carry the film (and its correction) and stay their own list;
everything else is an element here: the rolling bearing of a rotary joint
(:mod:`.bearing`) and, for a linear actuator (``[drive] kind = "linear"``), the screw, the
rod guide and the passages (:mod:`.linear.elements`). The loss
(:func:`~oilgap.model.joint_loss.joint_mean_power`), the heat balance, the evaluation and
the vectorised rows reach every element through :func:`joint_elements`; each element's
heat goes into the same balance.

References
----------
.. [1] SKF, *Rolling bearings*, catalogue 10000 EN (2013), "Friction" (the bearing).
.. [2] docs/linear-joint.md (the linear actuator's elements and their sources).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .bearing.friction import BearingSpec, bearing_mean_power
from .linear.elements import linear_elements

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .case import DesignCase


@dataclass(frozen=True)
class BearingElement:
    """The case's rolling bearing as an element (its friction at the bulk viscosity).

    Attributes
    ----------
    spec : BearingSpec
        The bearing [SI].
    name : str
        ``"bearing"`` [-].
    """

    spec: BearingSpec
    name: str = "bearing"

    def mean_power(self, nodes_rad_s, weights, nu_m2_s, rho_kg_m3=None):
        """Cycle-mean power [W] (:func:`~oilgap.model.bearing.bearing_mean_power`)."""
        return bearing_mean_power(self.spec, nodes_rad_s, weights, nu_m2_s)


def joint_elements(case: DesignCase, **design: Any) -> tuple:
    """The case's elements besides its regions: the bearing, then the linear drive's.

    Parameters
    ----------
    case : DesignCase
        The case (``bearing``, ``linear``).
    **design : Any
        Overrides of the linear drive's design variables (``lead_m``,
        ``guide_clearance_m``, ``passage_diameter_m`` [m]; floats or CasADi symbols),
        passed to :func:`~oilgap.model.linear.elements.linear_elements`.

    Returns
    -------
    tuple
        Elements with ``name`` and ``mean_power(nodes, weights, nu, rho)`` [W]; empty for
        a rotary joint without a bearing.

    References
    ----------
    The bearing [1]_; the linear elements [2]_.
    """
    out: tuple = ()
    if case.bearing is not None:
        out += (BearingElement(case.bearing),)
    linear = getattr(case, "linear", None)
    if linear is not None:
        out += linear_elements(linear, **design)
    return out


def element_names(case: DesignCase) -> tuple[str, ...]:
    """Names of :func:`joint_elements` in order (``"bearing"``, ``"screw"``, ...).

    Parameters
    ----------
    case : DesignCase
        The case.

    Returns
    -------
    tuple of str
        The names [-].
    """
    return tuple(e.name for e in joint_elements(case))
