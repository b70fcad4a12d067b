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

import numpy as np

from .bearing.friction import BearingSpec, bearing_mean_power
from .linear.elements import linear_elements
from .oil_properties import seawater_gauge_pressure
from .units import celsius_to_kelvin

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


def element_mean_powers_at(case: DesignCase, oil_temp_C, depth_m: float | None = None
                           ) -> np.ndarray:
    """Mean power [W] of each of the case's elements over the duty cycle at bulk
    temperature(s), numpy only (:func:`~oilgap.model.elements.joint_elements`; the same
    under every thermal mode: the elements take the bulk oil state, no film factor).

    Parameters
    ----------
    case : DesignCase
        The case (``bearing``, ``linear``, oil, duty cycle, depth).
    oil_temp_C : float or array
        Bulk oil temperature(s) [degC].
    depth_m : float, optional
        Sea depth [m] (default: the case's).

    Returns
    -------
    ndarray
        Shape ``np.shape(oil_temp_C) + (n_elements,)`` [W].

    References
    ----------
    :func:`oilgap.model.bearing.bearing_mean_power` (SKF or Palmgren);
    :mod:`oilgap.model.linear.elements` (docs/linear-joint.md).
    """
    t = np.asarray(oil_temp_C, dtype=float)
    elements = joint_elements(case)
    if not elements:
        return np.zeros(t.shape + (0,))
    d = case.operating.depth_m if depth_m is None else depth_m
    nu, _, rho = case.oil.properties(celsius_to_kelvin(t), seawater_gauge_pressure(d))
    nodes, weights = case.duty_cycle.speed_distribution()
    nu = np.broadcast_to(np.asarray(nu, dtype=float), t.shape)[..., None]
    rho = np.broadcast_to(np.asarray(rho, dtype=float), t.shape)[..., None]
    cols = [np.asarray(e.mean_power(nodes, weights, nu, rho), dtype=float).reshape(t.shape)
            for e in elements]
    return np.stack(cols, -1)


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
