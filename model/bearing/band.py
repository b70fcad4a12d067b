"""The band of bearing models: what every available model gives at one operating point.

The bearing's loss depends more on the choice of model than on any input
(docs/bearing.md, "Sensitivity"): at the seed's rated point SKF's model with the V_M
drag term gives about 10 W, with its full drag about 140 W, and Palmgren's f_0 range
sits between. :func:`bearing_model_band` computes each of them at the case's duty
cycle and oil state, beside the value the case's own model gives, so that an output can
show the chosen number with the spread it was chosen from. docs/bearing.md, "The
bearing-model band", lists the members and why each is there.

References
----------
.. [1] SKF, *Rolling bearings*, catalogue 10000 EN (2013) / 17000 EN (2018), "Friction"
   (the SKF model and its drag terms; :mod:`oilgap.model.bearing`).
.. [2] T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
   CRC 2006, ch. 9 (Palmgren's M_0 and the f_0 table, recalled).
.. [3] L. Schiller, A. Naumann, *Z. Ver. Dtsch. Ing.* 77 (1933) 318-320; R. Clift,
   J. R. Grace, M. E. Weber, *Bubbles, Drops, and Particles*, 1978, ch. 5 (sphere drag).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace

import numpy as np

from ..viscous_loss import weighted_mean
from .friction import BearingSpec, bearing_mean_power
from .laws import F0_OIL_RANGE, SERIES_CONSTANTS, balls_in_still_oil_power

BAND_DOC = "docs/bearing.md#the-bearing-model-band"
"""Where the band's members and their basis are explained [-]."""


@dataclass(frozen=True)
class BearingModelBand:
    """A bearing's mean power under every available model at one operating point [W].

    Attributes
    ----------
    chosen : str
        The case's own model and option (``"skf, drag skf-vm-term"``, ``"palmgren, f0 4"``).
    chosen_W : float
        Its mean power [W] (the bearing's row of the evaluation).
    min_W, max_W : float
        The least and greatest of ``members_W`` [W]: the band.
    members_W : dict
        Model -> mean power [W], each a model of the whole bearing: ``skf_vm_term``
        (SKF with the V_M drag term only), ``skf_full`` (SKF with the V_M and R_s drag
        terms), ``palmgren_f0_<lo>`` and ``palmgren_f0_<hi>`` (Palmgren at both ends of
        the published f_0 range for oil at a level), ``skf_no_drag_plus_spheres`` (SKF's
        rolling and sliding with the balls' drag as spheres in still oil). The SKF
        members are absent without an SKF series.
    parts_W : dict
        Pieces shown beside the band, not in it [W]: ``skf_no_drag`` (SKF's rolling and
        sliding alone, ``drag = "none"``: a floor that leaves out the drag SKF prescribes
        for oil), ``drag_vm_term`` (SKF's V_M drag term alone) and
        ``drag_spheres_still_oil`` (the balls as spheres in still oil alone).
    f0_range : tuple of float
        The f_0 range of the Palmgren members [-].
    """

    chosen: str
    chosen_W: float
    min_W: float
    max_W: float
    members_W: dict
    parts_W: dict
    f0_range: tuple[float, float]

    def to_dict(self) -> dict:
        """Plain-dict form (the ``--json`` output's ``model_band_W``).

        Returns
        -------
        dict
            The fields, powers [W] in the ``*_W`` keys, ``f0_range`` as a list [-].
        """
        d = asdict(self)
        d["f0_range"] = list(self.f0_range)
        return d


def chosen_label(spec: BearingSpec) -> str:
    """The case's bearing model and its option, for outputs [-].

    Parameters
    ----------
    spec : BearingSpec
        The bearing.

    Returns
    -------
    str
        ``"skf, drag <option>"`` or ``"palmgren, f0 <f_0>"``.
    """
    if spec.model == "skf":
        return f"skf, drag {spec.drag}"
    return f"palmgren, f0 {spec.f0:g}"


def bearing_model_band(spec: BearingSpec, nodes_rad_s, weights, nu_m2_s: float,
                       rho_kg_m3: float) -> BearingModelBand:
    """The bearing's mean power under each available model at one oil state [W].

    The members are SKF's model with the V_M drag term and with its full drag [1]_,
    Palmgren's at both ends of :data:`~oilgap.model.bearing.laws.F0_OIL_RANGE` [2]_,
    and SKF's rolling and sliding with the balls' drag as spheres in still oil
    (:func:`~oilgap.model.bearing.laws.balls_in_still_oil_power`, Schiller-Naumann
    [3]_). Numpy only (an output, not a term of the NLP).

    Parameters
    ----------
    spec : BearingSpec
        The case's bearing (its geometry, loads and lubrication; its own model gives
        ``chosen_W``).
    nodes_rad_s : array
        Distinct ``|omega|`` of the duty cycle [rad/s].
    weights : array
        Their time weights [-] (sum 1).
    nu_m2_s : float
        Kinematic viscosity of the oil [m^2/s] (the bulk oil's).
    rho_kg_m3 : float
        Density of the oil [kg/m^3] (only the spheres' drag depends on it).

    Returns
    -------
    BearingModelBand
        Each member's and part's mean power [W], the band's min and max [W], the
        chosen model's value [W].
    """
    nodes = np.asarray(nodes_rad_s, dtype=float)

    def mean(s: BearingSpec) -> float:
        return float(bearing_mean_power(s, nodes, weights, nu_m2_s))

    spheres = float(weighted_mean(balls_in_still_oil_power(
        nodes, spec.balls, spec.ball_diameter_m, spec.pitch_diameter_m, nu_m2_s,
        rho_kg_m3), weights))
    lo, hi = F0_OIL_RANGE
    members = {}
    parts = {"drag_spheres_still_oil": spheres}
    if spec.series in SERIES_CONSTANTS:
        skf = replace(spec, model="skf")
        no_drag = mean(replace(skf, drag="none"))
        vm_term = mean(replace(skf, drag="skf-vm-term"))
        members.update(skf_vm_term=vm_term, skf_full=mean(replace(skf, drag="skf-full")),
                       skf_no_drag_plus_spheres=no_drag + spheres)
        parts.update(skf_no_drag=no_drag, drag_vm_term=vm_term - no_drag)
    members[f"palmgren_f0_{lo:g}"] = mean(replace(spec, model="palmgren", f0=lo))
    members[f"palmgren_f0_{hi:g}"] = mean(replace(spec, model="palmgren", f0=hi))
    return BearingModelBand(
        chosen=chosen_label(spec), chosen_W=mean(spec), min_W=min(members.values()),
        max_W=max(members.values()), members_W=members, parts_W=parts, f0_range=(lo, hi))
