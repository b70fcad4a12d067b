"""Stage 5a of the calibration: the library effects as candidate regression columns.

Each effect of :mod:`oilgap.model.effects` is a regression feature (its power
per unit coefficient) evaluated at the calibrated law. Features that vanish on
these data, that the rig cannot have, or that the data cannot tell apart from
the calibration (R^2 > :data:`CONFOUNDED_R2` on its Jacobian) are set aside
with the reason. An effect with an exact nonlinear form (thermal lag, sensor
delay, shear thinning) also gets columns of that form at a grid of its
parameter (:func:`exact_form_variants`), so that large lags, long delays and
strong thinning are seen too; Taylor-vortex onset gets columns of its other
published shapes (excess exponent m = 0.5 (Wendt 1933) and 1, beside Stuart's 2).

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eq. 8 (the calibrated law).
.. [2] The effect library's own references (:mod:`oilgap.model.effects`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from oilgap.model.effects import EFFECTS, RigFacts, taylor_feature
from oilgap.model.film_heating import film_theory_coefficient
from oilgap.model.measured.data import Samples
from oilgap.model.regions import JointGeometry

from .forward import TAYLOR_SHAPES, ForwardModel
from .least_squares import BaseSpec, ModelFit

CONFOUNDED_R2 = 1.0 - 1e-6
"""A feature whose R^2 on the calibration's Jacobian exceeds this is numerically one of its
directions and is set aside; below it, cross-validation decides."""


def exact_form_variants(name: str, s: Samples, geometry: JointGeometry) -> tuple[float, ...]:
    """Coefficient values at which an exact-form effect is also screened.

    The first-order feature of an exact-form effect holds only while the effect
    is small; these variants (the exact form at a grid of its nonlinear
    parameter) let the screening see large lags, long delays and strong thinning.

    Parameters
    ----------
    name : str
        Library effect.
    s : Samples
        Oil-run samples (speed [rad/s], region-1 gap [m]).
    geometry : JointGeometry
        Rig regions (region-1 radius [m]).

    Returns
    -------
    tuple of float
        Thermal lag tau [s], sensor delay d [s], film strength s [-] (film rises of
        1-30 K at the largest loss, s <= 1), shear thinning lambda^2
        [s^2] (at lambda gamma_dot_max = 0.5, 1, 2) or the Taylor-vortex shape
        exponent m [-] (other than the linear feature's 2); empty for other effects.
    """
    if name == "taylor_vortex_onset":
        return tuple(m for m in TAYLOR_SHAPES if m != 2.0)
    if name == "thermal_lag":
        return (-30.0, -10.0, -3.0, -1.0, 1.0, 3.0, 10.0, 30.0)
    if name == "sensor_delay":
        return (0.5, 1.0, 2.0, 5.0)
    if name == "film_heating":  # strengths of film rises of 1-30 K at the largest loss, <= 1
        pmax = float(np.max(np.abs(np.nan_to_num(s.viscous_W))))
        g = geometry.regions[0]
        c0 = float(film_theory_coefficient(float(np.max(g.gap_m)), g.radius_m, g.length_m))
        return tuple(dT / (pmax * c0) for dT in (1.0, 3.0, 10.0, 30.0)
                     if dT / (pmax * c0) <= 1.0) if pmax > 0 else ()
    if name == "shear_thinning":
        gmax = float(np.max(np.abs(s.omega) * geometry.regions[0].radius_m / s.gap1_m))
        return tuple((c / gmax) ** 2 for c in (0.5, 1.0, 2.0)) if gmax > 0 else ()
    return ()


@dataclass
class Candidates:
    """The candidate columns of the effect search and every effect's screening record.

    Attributes
    ----------
    info : list of dict
        One record per library effect considered (name, title, formula,
        nonnegative, status, and R^2 on the calibration where computed).
    usable : list of str
        Effects with status "candidate".
    columns : array, shape (n, k)
        Candidate columns [W per unit coefficient].
    name : list of str
        Effect of each column.
    variant : list of float or None
        Exact-form parameter of each column (None: the linear feature).
    nonneg : list of bool
        Whether each column's coefficient must be >= 0.
    """

    info: list[dict] = field(default_factory=list)
    usable: list[str] = field(default_factory=list)
    columns: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    name: list[str] = field(default_factory=list)
    variant: list[float | None] = field(default_factory=list)
    nonneg: list[bool] = field(default_factory=list)

    @property
    def group(self) -> np.ndarray:
        """Index in :attr:`usable` of each column's effect."""
        return np.array([self.usable.index(n) for n in self.name], int)

    def label(self, j: int) -> str:
        """Name of column ``j`` (with its exact-form parameter if it is a variant)."""
        v = self.variant[j]
        if v is None:
            return self.name[j]
        return f"{self.name[j]} ({'shape m' if self.is_shape(j) else 'exact form'}, {v:.3g})"

    def is_shape(self, j: int) -> bool:
        """Whether column ``j`` is a shape variant (its coefficient is the linear one's)."""
        return self.variant[j] is not None and self.name[j] == "taylor_vortex_onset"

    def taylor_exponent(self, chosen) -> float:
        """Taylor-vortex shape exponent m [-] of the columns ``chosen`` (2 if none)."""
        return next((float(self.variant[j]) for j in chosen if self.is_shape(j)), 2.0)

    def columns_of(self, name: str) -> list[int]:
        """Columns of effect ``name``."""
        return [j for j in range(len(self.name)) if self.name[j] == name]

    def feature_scale(self) -> dict[str, float]:
        """RMS of each usable effect's linear feature [W per unit coefficient]."""
        F = self.columns
        return {n: float(np.sqrt(np.mean(F[:, self.name.index(n)] ** 2))) for n in self.usable}


def _record(name: str, status: str | None = None) -> dict:
    """An effect's screening record: its name, title, formula, sign rule (and status)."""
    eff = EFFECTS[name]
    info = {"name": name, "title": eff.title, "formula": eff.formula,
            "nonnegative": eff.nonnegative}
    return info if status is None else {**info, "status": status}


def _screen(name: str, f: np.ndarray | None, jc: np.ndarray, spec: BaseSpec, ymax: float
            ) -> dict:
    """Screening record of one effect's feature ``f`` [W/unit] (status and R^2)."""
    info = _record(name)
    if f is None:
        info["status"] = ("not applicable: the case has no [bearing] (the drag term needs "
                          "the bearing's rings)" if name == "bearing_ball_drag" else
                          "not applicable: the rig has no bearing region")
        return info
    if not np.any(np.abs(f) > 1e-12 * ymax):
        info["status"] = ("inactive on these data" + (  # Ta below onset: its domain
            ": no temperature law for dP/dT" if name in ("thermal_lag", "film_heating")
            else ""))
        return info
    coef, *_ = np.linalg.lstsq(jc, f, rcond=None)
    r2 = 1.0 - float(np.sum((f - jc @ coef) ** 2)) / float(np.sum(f * f))
    info["r2_on_calibration"] = r2
    if r2 > CONFOUNDED_R2:
        info["status"] = (f"confounded with the calibration (R^2 = {r2:.6f} on "
                          f"{', '.join(spec.free)}): absorbed, cannot be named")
    else:
        info["status"] = "candidate"
    return info


STEADY_POINT_STATUS = ("not a candidate: steady-point data (no time_s); a time-dependent "
                       "effect needs a time record")
"""Status of a time-dependent effect on data without a time column."""


def screen_candidates(model: ForwardModel, spec: BaseSpec, base: ModelFit,
                      names: list[str], has_time: bool = True,
                      facts: RigFacts | None = None) -> Candidates:
    """Candidate columns of the library effects ``names`` at the calibrated law.

    Parameters
    ----------
    model : ForwardModel
        The oil runs.
    spec : BaseSpec
        Free base parameters (named in the confounding statement).
    base : ModelFit
        Calibration without effect (law, Jacobian [W per unit parameter]).
    names : list of str
        Library effects considered.
    has_time : bool
        False for steady-point data: time-dependent effects (oil inertia,
        thermal lag, sensor delay) are not candidates, with that reason.
    facts : RigFacts, optional
        The rig's fluids: an effect whose physical domain
        (:attr:`~oilgap.model.effects.Effect.domain`) the data never reach is not a
        candidate, with the reason and its number (e.g. the largest Taylor number).

    Returns
    -------
    Candidates
        One linear column per usable effect, then its exact-form variants
        (``power(law, {name: v}) - power(law)`` [W]; for Taylor-vortex onset the
        feature at shape exponent v [W per unit k]) that do not vanish.
    """
    s = model.samples
    ctx = model.context(base.law)
    ymax = max(1.0, float(np.max(np.abs(s.viscous_W))))
    p_base = model.power(base.law)
    out = Candidates()
    cols = []
    for n in names:
        eff = EFFECTS[n]
        if not has_time and eff.time_dependent:
            out.info.append(_record(n, STEADY_POINT_STATUS))
            continue
        outside = eff.domain.reason(ctx, facts) if eff.domain is not None else None
        if outside is not None:
            out.info.append(_record(n, outside))
            continue
        f = eff.feature_values(ctx)
        if f is not None and not np.all(np.isfinite(f)):
            out.info.append(_record(n, "not usable: its feature is not finite on these data"))
            continue
        info = _screen(n, f, base.jac_base, spec, ymax)
        out.info.append(info)
        if info["status"] != "candidate":
            continue
        out.usable.append(n)
        cols.append(f)
        out.name.append(n)
        out.variant.append(None)
        out.nonneg.append(EFFECTS[n].nonnegative)
        for v in exact_form_variants(n, s, model.geometry):
            fv = (taylor_feature(ctx, v) if n == "taylor_vortex_onset"
                  else model.power(base.law, {n: v}) - p_base)
            # a variant whose exact form leaves the fluid's law on these data (e.g. a long
            # negative lag applied to a noisy temperature rate) is not a column
            if np.all(np.isfinite(fv)) and np.any(np.abs(fv) > 1e-9 * ymax):
                cols.append(fv)
                out.name.append(n)
                out.variant.append(v)
                out.nonneg.append(True)
    out.columns = np.column_stack(cols) if cols else np.zeros((s.n, 0))
    return out
