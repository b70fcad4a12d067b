"""The rolling bearing's row of an evaluation: its record and the function that fills it.

The bearing is its own row beside the clearance's regions (:mod:`oilgap.model.evaluation`),
at the bulk oil's viscosity, averaged over the duty cycle by its exact speed
distribution (Eq. 10 of the seed paper [1]_ applied to the bearing's moment).

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eq. 10.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..case import DesignCase
from ..io.case_bearing import bearing_default_notes, bearing_defaults
from ..viscous_loss import weighted_mean
from .band import BearingModelBand, bearing_model_band
from .friction import (
    BearingSpec,
    bearing_mean_power,
    bearing_moment_terms,
    bearing_torque,
    bearing_validity,
)


@dataclass(frozen=True, kw_only=True)
class BearingResult:
    """Result for the case's rolling bearing over the duty cycle (its own row).

    Attributes
    ----------
    name : str
        The bearing's name (its designation, or ``[bearing] name``).
    model : str
        ``"skf"`` or ``"palmgren"`` (:mod:`oilgap.model.bearing`).
    kind : str
        Bearing type (``"deep-groove-ball"``).
    pitch_diameter_m : float
        Pitch diameter d_m = (d + D)/2 [m].
    mean_power_W : float
        Mean power of its friction and drag over the cycle at the bulk oil's viscosity
        [W] (:func:`~oilgap.model.bearing.bearing_mean_power`; no film factor).
    torque_peak_Nm : float
        Its moment at the peak speed [N m].
    terms : dict
        Model term (``rolling``, ``sliding``, ``drag_vm``, ``drag_rs``;
        ``load_independent``, ``load_dependent``) -> its mean power over the cycle [W];
        they sum to ``mean_power_W``.
    defaults : dict
        ``[bearing]`` key -> the value the tool filled in, in the key's unit (the
        designation's geometry, the model's constants): what the user did not give.
    default_notes : tuple of str
        The same, one ``"key = value (basis)"`` line each.
    kappa_peak : float
        Viscosity ratio nu/nu_1 at the peak speed [-] (normal bearing practice 1-4).
    speed_factor_peak_mm_rpm : float
        Speed factor n d_m at the peak speed [mm rpm].
    validity_notes : tuple of str
        One sentence per range of validity of the model the point is outside.
    model_band : BearingModelBand or None
        Its mean power under every available bearing model at the same oil state [W]
        (:func:`~oilgap.model.bearing.band.bearing_model_band`), beside the chosen one;
        ``model_band_W`` in the JSON.
    """

    name: str
    model: str
    kind: str
    pitch_diameter_m: float
    mean_power_W: float
    torque_peak_Nm: float
    terms: dict
    defaults: dict
    default_notes: tuple[str, ...]
    kappa_peak: float
    speed_factor_peak_mm_rpm: float
    validity_notes: tuple[str, ...]
    model_band: BearingModelBand | None = None


def bearing_result(case: DesignCase, spec: BearingSpec, nu_m2_s: float,
                   rho_kg_m3: float | None = None) -> BearingResult:
    """The rolling bearing's row at a kinematic viscosity (the bulk oil's).

    Parameters
    ----------
    case : DesignCase
        The case (its duty cycle).
    spec : BearingSpec
        The bearing.
    nu_m2_s : float
        Kinematic viscosity of the oil [m^2/s].
    rho_kg_m3 : float or None
        Density of the oil [kg/m^3]; given, the row carries the band of bearing models.

    Returns
    -------
    BearingResult
        Mean power [W] in total and per term, moment at the peak speed [N m], the
        defaults the tool filled in, kappa [-] and n d_m [mm rpm] at the peak speed,
        the band of bearing models [W].

    References
    ----------
    SKF's frictional-moment model, Palmgren's load-independent/load-dependent pair:
    :mod:`oilgap.model.bearing`.
    """
    cycle = case.duty_cycle
    nodes, weights = cycle.speed_distribution()
    terms = {k: float(weighted_mean(np.broadcast_to(np.asarray(v, dtype=float), nodes.shape)
                                    * nodes, weights))
             for k, v in bearing_moment_terms(spec, nodes, nu_m2_s).items()}
    valid = bearing_validity(spec, cycle.peak_omega_rad_s, nu_m2_s)
    return BearingResult(
        name=spec.name, model=spec.model, kind=spec.kind,
        pitch_diameter_m=float(spec.pitch_diameter_m),
        mean_power_W=float(bearing_mean_power(spec, nodes, weights, nu_m2_s)),
        torque_peak_Nm=float(bearing_torque(spec, cycle.peak_omega_rad_s, nu_m2_s)), terms=terms,
        defaults=bearing_defaults(spec), default_notes=bearing_default_notes(spec),
        kappa_peak=float(valid.kappa), speed_factor_peak_mm_rpm=float(valid.speed_factor_mm_rpm),
        validity_notes=valid.notes,
        model_band=None if rho_kg_m3 is None else bearing_model_band(
            spec, nodes, weights, nu_m2_s, rho_kg_m3))
