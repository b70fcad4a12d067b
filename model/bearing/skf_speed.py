"""The speed parts of SKF's friction factors: written once, evaluated once per speed.

SKF's inlet-shear factor ``phi_ish = 1/(1 + 1.84e-9 (n dm)^1.28 nu^0.64)`` and
boundary-film factor ``phi_bl = exp(-2.6e-8 (n nu)^1.4 dm)`` are products of a power of
the speed and a power of the viscosity. Their speed parts are these functions:
:mod:`oilgap.model.bearing.laws` multiplies them by the viscosity's power inside its
laws (the same operations, in the same order, as the laws written in one line), and the
vectorised heat balance (:mod:`oilgap.model.uncertain.rows`) evaluates them once per row
and speed node instead of at every temperature its iteration tries (the viscosity
changes, the speeds do not): the same numbers, without the three powers of n per node
and temperature.

Functions take floats, numpy arrays and CasADi symbols.

References
----------
.. [1] SKF, *Rolling bearings*, catalogue 10000 EN (2013) / 17000 EN (2018), section
   "Friction" (phi_ish).
.. [2] SKF, *General Catalogue* 6000 EN, "Friction", pp. 100-106 (mu_sl, phi_bl).
"""

from __future__ import annotations


def inlet_shear_speed(speed_rpm, dm_mm):
    """Speed part ``1.84e-9 n^1.28 dm^1.28`` of SKF's inlet-shear factor [-] [1]_.

    Parameters
    ----------
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm] (>= 0).
    dm_mm : float
        Pitch diameter [mm].

    Returns
    -------
    float, array or CasADi expression
        The speed part [(mm^2/s)^-0.64]: ``phi_ish = 1/(1 + this nu^0.64)``.
    """
    return 1.84e-9 * speed_rpm**1.28 * dm_mm**1.28


def boundary_film_speed(speed_rpm):
    """Speed part ``-2.6e-8 n^1.4`` of SKF's boundary-film factor [-] [2]_.

    Parameters
    ----------
    speed_rpm : float, array or CasADi symbol
        ``|n|`` [rpm] (>= 0).

    Returns
    -------
    float, array or CasADi expression
        The speed part [(mm^2/s)^-1.4 mm^-1]: ``phi_bl = exp(this nu^1.4 dm)``.
    """
    return -2.6e-8 * speed_rpm**1.4


__all__ = ["boundary_film_speed", "inlet_shear_speed"]
