"""The linear actuator's elements: each a law of the oil state and its own kinematics.

Every element is called with the motor's speed nodes ``omega`` [rad/s] (the duty cycle's
distribution, :meth:`~oilgap.model.duty_cycle.DutyCycle.speed_distribution`), their
weights and the oil's (nu, rho), like the rotary joint's regions and bearing
(:mod:`oilgap.model.elements`, the one composition). The screw turns at omega; the rod
moves at ``v = omega lead/(2 pi)``. Each element's power is its force (or torque) times its
speed, so ``P = F v`` holds by construction. Geometry fields may be floats, numpy columns
or CasADi symbols (the design NLP passes the lead, the guide clearance and the passage
diameter as symbols).

References
----------
.. [1] F. M. White, *Viscous Fluid Flow*, 3rd ed., McGraw-Hill 2006, secs. 3-2, 3-3.
.. [2] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., Burbank 1959.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import casadi as ca
import numpy as np

from .. import _math as m
from ..viscous_loss import weighted_mean
from .drive import LinearDrive
from .laws import (
    annular_couette_force,
    eccentric_drag_factor,
    passages_power,
    rod_velocity,
    screw_viscous_torque,
)


def _nodes_for(nodes_rad_s, nu_m2_s, *geometry):
    """Nodes as a CasADi DM when anything else is symbolic (numpy otherwise)."""
    if m.is_symbolic(nu_m2_s, *geometry) and not m.is_symbolic(nodes_rad_s):
        return ca.DM(np.asarray(nodes_rad_s, dtype=float))
    return nodes_rad_s


@dataclass(frozen=True)
class ScrewElement:
    """The screw's nut churning in oil: Palmgren's load-independent torque at omega [2]_.

    Attributes
    ----------
    pitch_diameter_m : float
        Screw pitch diameter d_m [m].
    f0 : float
        Palmgren factor [-].
    name : str
        ``"screw"`` [-].
    """

    pitch_diameter_m: Any
    f0: float
    name: str = "screw"

    def torque(self, omega_rad_s, nu_m2_s, rho_kg_m3=None):
        """Churning torque [N m] (:func:`~oilgap.model.linear.laws.screw_viscous_torque`)."""
        return screw_viscous_torque(omega_rad_s, nu_m2_s, self.pitch_diameter_m, self.f0)

    def power(self, omega_rad_s, nu_m2_s, rho_kg_m3=None):
        """Power ``M_0 |omega|`` [W]."""
        return self.torque(omega_rad_s, nu_m2_s) * m.fabs(omega_rad_s)

    def mean_power(self, nodes_rad_s, weights, nu_m2_s, rho_kg_m3=None):
        """Cycle-mean power [W] over the motor's speed nodes."""
        nodes = _nodes_for(nodes_rad_s, nu_m2_s, self.pitch_diameter_m)
        return weighted_mean(self.power(nodes, nu_m2_s), weights)


@dataclass(frozen=True)
class RodGuideElement:
    """The rod sliding in its guide bushing: annular Couette drag [1]_.

    ``F = 2 pi L mu v / ln(r_o/r_i)`` times the thin-gap eccentric factor
    ``1/sqrt(1 - eps^2)``; ``P = F v``.

    Attributes
    ----------
    lead_m : float or CasADi symbol
        Screw lead [m] (the rod's speed is ``omega lead/(2 pi)``).
    rod_diameter_m, guide_length_m, clearance_m : float or CasADi symbol
        Rod diameter, guide length and radial clearance [m].
    eccentricity : float
        e/c [-].
    name : str
        ``"rod guide"`` [-].
    """

    lead_m: Any
    rod_diameter_m: Any
    guide_length_m: Any
    clearance_m: Any
    eccentricity: float = 0.0
    name: str = "rod guide"

    def force(self, rod_velocity_m_s, nu_m2_s, rho_kg_m3):
        """Drag force [N] at a rod velocity."""
        r = 0.5 * self.rod_diameter_m
        f = annular_couette_force(nu_m2_s * rho_kg_m3, rod_velocity_m_s, self.guide_length_m,
                                  r, r + self.clearance_m)
        return f * eccentric_drag_factor(self.eccentricity)

    def power(self, omega_rad_s, nu_m2_s, rho_kg_m3):
        """Power ``F |v|`` [W] at motor speed omega."""
        v = rod_velocity(m.fabs(omega_rad_s), self.lead_m)
        return self.force(v, nu_m2_s, rho_kg_m3) * v

    def mean_power(self, nodes_rad_s, weights, nu_m2_s, rho_kg_m3):
        """Cycle-mean power [W] over the motor's speed nodes."""
        nodes = _nodes_for(nodes_rad_s, nu_m2_s, self.lead_m, self.clearance_m)
        return weighted_mean(self.power(nodes, nu_m2_s, rho_kg_m3), weights)


@dataclass(frozen=True)
class PassagesElement:
    """The displaced oil through the compensation passages: Hagen-Poiseuille [1]_.

    Attributes
    ----------
    lead_m : float or CasADi symbol
        Screw lead [m].
    rod_diameter_m : float
        Rod diameter [m].
    count : int
        Number of passages [-] (>= 1).
    diameter_m, length_m : float or CasADi symbol
        Passage diameter and length [m].
    name : str
        ``"passages"`` [-].
    """

    lead_m: Any
    rod_diameter_m: Any
    count: int
    diameter_m: Any
    length_m: Any
    name: str = "passages"

    def power(self, omega_rad_s, nu_m2_s, rho_kg_m3):
        """Power ``dp Q`` [W] at motor speed omega
        (:func:`~oilgap.model.linear.laws.passages_power`)."""
        v = rod_velocity(m.fabs(omega_rad_s), self.lead_m)
        return passages_power(nu_m2_s * rho_kg_m3, v, self.rod_diameter_m, self.count,
                              self.diameter_m, self.length_m)

    def mean_power(self, nodes_rad_s, weights, nu_m2_s, rho_kg_m3):
        """Cycle-mean power [W] over the motor's speed nodes."""
        nodes = _nodes_for(nodes_rad_s, nu_m2_s, self.lead_m, self.diameter_m)
        return weighted_mean(self.power(nodes, nu_m2_s, rho_kg_m3), weights)


def linear_elements(drive: LinearDrive, *, lead_m: Any = None, guide_clearance_m: Any = None,
                    passage_diameter_m: Any = None) -> tuple:
    """The screw, rod guide and passages of a linear drive, in that order.

    Parameters
    ----------
    drive : LinearDrive
        The drive [SI].
    lead_m, guide_clearance_m, passage_diameter_m : float, array or CasADi symbol, optional
        Replace the drive's lead, guide clearance and passage diameter [m] (the design
        NLP's variables); default: the drive's.

    Returns
    -------
    tuple
        :class:`ScrewElement`, :class:`RodGuideElement`, :class:`PassagesElement`.

    References
    ----------
    Palmgren [2]_; White [1]_.
    """
    lead = drive.lead_m if lead_m is None else lead_m
    c = drive.guide_clearance_m if guide_clearance_m is None else guide_clearance_m
    d = drive.passage_diameter_m if passage_diameter_m is None else passage_diameter_m
    return (ScrewElement(drive.screw_pitch_diameter_m, drive.screw_f0),
            RodGuideElement(lead, drive.rod_diameter_m, drive.guide_length_m, c,
                            drive.eccentricity),
            PassagesElement(lead, drive.rod_diameter_m, max(drive.passage_count, 1), d,
                            drive.passage_length_m))
