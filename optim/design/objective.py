"""The one objective of the design problem: mean power, torque and inertia of a design.

:func:`region1_mean_power` is the objective's composition (region 1 built from
the design variables, averaged over the duty cycle's speed distribution); the
CasADi NLP (:class:`~oilgap.optim.design.DesignProblem`) is built from it with
symbols, and :class:`DesignObjective` evaluates it with numpy, with the motor's
torque capability and the rotor's inertia, for design vectors
``x = (R, delta, d_r, d_s, L)`` [m] given one at a time (shape (5,)) or as the
rows of an (n, 5) array. The numpy path serves the SciPy cross-check
(:mod:`oilgap.optim.scipy_reference`), the other optimizers of the Pareto study
and the tests.

References
----------
.. [1] *Modeling and Optimization of Compensating Oil Viscous Power for a Deep-Sea
   Electric Manipulator* (the seed paper), Eqs. 4-10 (clearance loss, roughness T).
.. [2] J. F. Gieras, *Permanent Magnet Motor Technology*, 3rd ed., 2010, A.27-A.28
   (torque capability, rotor inertia).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from oilgap.model.case import Motor
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.model.regions import region_mean_power, rotor_stator_region
from oilgap.model.skin_friction import FrictionLaw


def region1_mean_power(x_m, nu_m2_s, rho_kg_m3, nodes_rad_s, weights,
                       law: FrictionLaw) -> Any:
    """Mean viscous power of region 1 over a speed distribution [1].

    :func:`~oilgap.model.regions.region_mean_power` of the region built from
    the design variables (:func:`~oilgap.model.regions.rotor_stator_region`,
    T from Eq. 9). Floats, numpy arrays (nodes along the last axis) or CasADi
    symbols (then pass ``nodes_rad_s`` as a ``casadi.DM``).

    Parameters
    ----------
    x_m : sequence of 5 (float, array or CasADi symbol)
        The design variables (R, delta, d_r, d_s, L) [m]: rotor outer radius R = T2,
        clearance delta = T3 - T2, groove depths d_r and d_s left open by the epoxy
        fill, clearance length L.
    nu_m2_s : float or CasADi symbol
        Kinematic viscosity [m^2/s].
    rho_kg_m3 : float or CasADi symbol
        Density [kg/m^3].
    nodes_rad_s : array or casadi.DM
        Speed nodes of the duty cycle [rad/s].
    weights : array
        Their weights [-] (summing to 1 over all nodes).
    law : FrictionLaw
        Skin-friction law (the NLP uses the smooth C_m).

    Returns
    -------
    float, array or CasADi expression
        Mean power [W].
    """
    region = rotor_stator_region(*x_m)
    return region_mean_power(region, nodes_rad_s, weights, nu_m2_s, rho_kg_m3, law)


@dataclass(frozen=True, kw_only=True)
class DesignObjective:
    """Mean power P1, torque capability and rotor inertia of design vectors (numpy).

    ``x`` is one design (R, delta, d_r, d_s, L) [m] of shape (5,) (scalar
    results) or the rows of an (n, 5) array (results of shape (n,)).
    :meth:`DesignProblem.objective <oilgap.optim.design.DesignProblem.objective>`
    builds one with a solve's oil state.

    Parameters
    ----------
    nodes_rad_s : ndarray
        Speed nodes of the duty cycle [rad/s] (the zero node may be left out: it
        carries no power).
    weights : ndarray
        Their weights [-].
    law : FrictionLaw
        Skin-friction law (the NLP's: smooth C_m).
    motor : Motor
        The case's motor.
    machined_rotor_groove_m : float
        Rotor groove depth as machined, d_r0 [m].
    nu_m2_s : float
        Kinematic viscosity [m^2/s].
    rho_kg_m3 : float
        Density [kg/m^3].
    """

    nodes_rad_s: np.ndarray
    weights: np.ndarray
    law: FrictionLaw
    motor: Motor
    machined_rotor_groove_m: float
    nu_m2_s: float
    rho_kg_m3: float

    @staticmethod
    def _columns(x_m) -> tuple[tuple[Any, ...], bool]:
        """The five variables of ``x`` (scalars, or (n, 1) columns of rows) and whether
        ``x`` held rows."""
        x = np.asarray(x_m, dtype=float)
        if x.ndim == 1:
            R, d, a, b, L = x
            return (R, d, a, b, L), False
        return tuple(x[:, k:k + 1] for k in range(5)), True

    def mean_power(self, x_m) -> Any:
        """Region-1 mean viscous power over the duty cycle (:func:`region1_mean_power`).

        Parameters
        ----------
        x_m : array of shape (5,) or (n, 5)
            (R, delta, d_r, d_s, L) [m].

        Returns
        -------
        float or ndarray of shape (n,)
            P1 [W].
        """
        (R, d, a, b, L), rows = self._columns(x_m)
        nodes = self.nodes_rad_s[None, :] if rows else self.nodes_rad_s
        p1 = region1_mean_power((R, d, a, b, L), self.nu_m2_s, self.rho_kg_m3, nodes,
                                self.weights, self.law)
        return np.ravel(p1) if rows else p1

    def torque(self, x_m) -> Any:
        """Torque capability (:func:`~oilgap.model.motor.motor_torque`) [2].

        Parameters
        ----------
        x_m : array of shape (5,) or (n, 5)
            (R, delta, d_r, d_s, L) [m].

        Returns
        -------
        float or ndarray of shape (n,)
            Torque capability [N m].
        """
        (R, d, _, _, L), rows = self._columns(x_m)
        tau = motor_torque(self.motor, R, d, L)[0]
        return np.ravel(tau) if rows else tau

    def inertia(self, x_m) -> Any:
        """Rotor inertia with the epoxy fill (:func:`~oilgap.model.motor.rotor_inertia`) [2].

        Parameters
        ----------
        x_m : array of shape (5,) or (n, 5)
            (R, delta, d_r, d_s, L) [m].

        Returns
        -------
        float or ndarray of shape (n,)
            Polar moment of inertia [kg m^2].
        """
        (R, _, a, _, L), rows = self._columns(x_m)
        J = rotor_inertia(self.motor, R, a, L, self.machined_rotor_groove_m)
        return np.ravel(J) if rows else J

    def __call__(self, x_m) -> tuple[Any, Any, Any]:
        """(P1 [W], torque [N m], inertia [kg m^2]) of ``x_m`` [m], shape (5,) or (n, 5)."""
        return self.mean_power(x_m), self.torque(x_m), self.inertia(x_m)


__all__ = ["DesignObjective", "region1_mean_power"]
