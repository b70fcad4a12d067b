"""The groove band: in laminar flow, the loss with the groove factor of creeping-flow
theory (1) beside the loss with the seed rig's fit T^gamma (seed Eq. 8).

By the minimum-dissipation theorem of Stokes flow (Helmholtz [1]_, Korteweg [2]_) grooves
cannot raise the loss of a creeping flow: the grooved clearance contains the smooth one,
and the smooth flow, continued as rigid motion into the grooves, is an admissible field of
the same dissipation, so the grooved flow dissipates no more. Below the critical Taylor
number (:func:`~oilgap.model.transition.critical_taylor_number`) the flow in region 1 is
such a flow (the inertia there only shapes the vortices that have not started). The seed's
Table 4 [3]_ measured lower losses after smoothing, on oils whose runs were laminar too:
T^gamma is an empirical fit of that rig, whose cause is not groove friction (docs/model.md,
"The groove factor in creeping flow"). Every report shows both wherever region 1 is laminar
at the peak speed, as it shows the film band (:func:`~oilgap.model.joint_loss.film_band`).

References
----------
.. [1] H. Helmholtz, "Zur Theorie der stationären Ströme in reibenden Flüssigkeiten",
   Verh. naturhist.-med. Ver. Heidelberg 5:1-7, 1868.
.. [2] D. J. Korteweg, "On a general theorem of the stability of the motion of a viscous
   fluid", Phil. Mag. 16:112-118, 1883.
.. [3] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Eqs. 8-9 and Table 4.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from .evaluation import oil_state
from .joint_loss import operating_temperature, resolved_mode
from .regions import joint_regions
from .taylor_couette import couette_reynolds, taylor_number
from .transition import critical_taylor_number

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .case import DesignCase

GROOVE_EVIDENCE = ("creeping-flow theory (Helmholtz-Korteweg) says grooves cannot raise a "
                   "laminar loss; T^gamma is the seed rig's fit of Table 4, see "
                   "docs/model.md#the-groove-factor-in-creeping-flow")
"""The evidence behind the two sides of the band, for every report."""


@dataclass(frozen=True)
class GrooveBand:
    """A laminar design's loss with T^gamma (reported) and with groove factor 1 (theory).

    Attributes
    ----------
    mean_power_W : float
        The reported loss, region 1 with T^gamma [W].
    theory_mean_power_W : float
        The same design with groove factor 1 (creeping-flow theory's bound) [W].
    gamma, roughness_T : float
        The groove exponent and region 1's roughness T [-].
    taylor_peak, taylor_critical : float
        Region 1's Taylor number at the peak speed and its critical value [-].
    """

    mean_power_W: float
    theory_mean_power_W: float
    gamma: float
    roughness_T: float
    taylor_peak: float
    taylor_critical: float

    @property
    def change_pct(self) -> float:
        """The theory side relative to the reported loss [%]."""
        return 100.0 * (self.theory_mean_power_W / self.mean_power_W - 1.0)

    def line(self, fmt: str = ".4g") -> str:
        """The band as one report line, labelled with its evidence.

        Parameters
        ----------
        fmt : str
            Format of the loss [W].

        Returns
        -------
        str
            E.g. ``groove factor 1 (creeping-flow theory): 22.6 W (-54 %) beside
            T^gamma = 2.19 (the seed rig's fit); laminar (Ta 5.5 < Ta_c 42.3); ...``.
        """
        factor = self.roughness_T ** self.gamma
        return (f"groove factor 1 (creeping-flow theory): {self.theory_mean_power_W:{fmt}} W "
                f"({self.change_pct:+.0f} %) beside T^gamma = {factor:.3g} (the seed rig's "
                f"fit); laminar (Ta {self.taylor_peak:.3g} < Ta_c {self.taylor_critical:.3g}); "
                f"{GROOVE_EVIDENCE}")

    def to_dict(self) -> dict:
        """Plain-dict form (the ``groove_band`` block of the JSON outputs).

        Returns
        -------
        dict
            ``theory_mean_power_W`` [W], ``change_pct`` [%], ``groove_factor`` (T^gamma)
            [-], ``gamma`` [-], ``roughness_T`` [-], ``Ta_peak``, ``Ta_critical``
            [-], ``evidence``.
        """
        return {"theory_mean_power_W": self.theory_mean_power_W,
                "change_pct": self.change_pct,
                "groove_factor": self.roughness_T ** self.gamma, "gamma": self.gamma,
                "roughness_T": self.roughness_T, "Ta_peak": self.taylor_peak,
                "Ta_critical": self.taylor_critical, "evidence": GROOVE_EVIDENCE}


def region1_taylor(case: DesignCase, oil_temp_C: float | None = None,
                   depth_m: float | None = None) -> tuple[float, float]:
    """Region 1's Taylor number at the peak speed and its critical value [-].

    Parameters
    ----------
    case : DesignCase
        The design (region 1, duty cycle, oil).
    oil_temp_C : float, optional
        Bulk oil temperature [degC] (default: the case's).
    depth_m : float, optional
        Sea depth [m] (default: the case's).

    Returns
    -------
    tuple of float
        (Ta at the peak speed, Ta_c of region 1's gap ratio) [-].

    References
    ----------
    Seed paper (Eqs. 3-4); Esser & Grossmann (Ta_c,
    :func:`~oilgap.model.transition.critical_taylor_number`).
    """
    nu, _, _ = oil_state(case, oil_temp_C, depth_m)
    r = joint_regions(case)[0]
    re = couette_reynolds(case.duty_cycle.peak_omega_rad_s, r.radius_m, r.gap_m, nu)
    return (float(taylor_number(re, r.gap_m, r.radius_m)),
            float(critical_taylor_number(r.gap_m / r.radius_m)))


def groove_band(case: DesignCase, mode: str | None = None, depth_m: float | None = None,
                mean_power_W: float | None = None) -> GrooveBand | None:
    """The groove band of a case, or None where it does not apply.

    None when region 1 has no grooves (T = 1) or gamma = 0 (both sides equal), or when its
    flow is not laminar at the peak speed (Ta >= Ta_c at the mode's bulk oil temperature:
    the theorem is one of creeping flow).

    Parameters
    ----------
    case : DesignCase
        The design.
    mode : str, optional
        Thermal mode (default: the case's default).
    depth_m : float, optional
        Sea depth [m] (default: the case's).
    mean_power_W : float, optional
        The reported loss [W] when the caller has it (default: computed here).

    Returns
    -------
    GrooveBand or None
        Both losses [W], gamma, T and the Taylor numbers [-].

    References
    ----------
    Helmholtz [1]_; Korteweg [2]_; seed paper (Eq. 8, Table 4) [3]_.
    """
    T, gamma = float(joint_regions(case)[0].roughness_T), float(case.friction.gamma)
    if T <= 1.0 + 1e-12 or gamma == 0.0:
        return None
    mode = resolved_mode(case, mode)
    op = operating_temperature(case, mode, depth_m)
    ta, ta_c = region1_taylor(case, op.oil_temp_C, depth_m)
    if not ta < ta_c:
        return None
    flat = replace(case, friction=replace(case.friction, gamma=0.0))
    theory = operating_temperature(flat, mode, depth_m).mean_power_W
    reported = op.mean_power_W if mean_power_W is None else float(mean_power_W)
    return GrooveBand(reported, float(theory), gamma, T, ta, ta_c)
