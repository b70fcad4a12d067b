"""The parameters of one solve of the design NLP: resolution and validation.

The NLP is built once per case; the oil state (nu, rho), the required torque,
the inertia limit and every bound are parameters of each solve. This module
turns a solve's overrides (an oil at a condition or nu/rho directly, limits in
SI, variables held fixed) into a validated :class:`DesignParameters`.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from oilgap.model.case import OperatingPoint
from oilgap.model.errors import InputError, check_finite, check_positive
from oilgap.model.evaluation import oil_state
from oilgap.model.fluids import Fluid
from oilgap.model.units import MM_TO_M, m2_s_to_cst

from .variables import VARIABLE_LABELS, VARIABLES

if TYPE_CHECKING:  # pragma: no cover - typing only
    from .problem import DesignProblem


@dataclass(frozen=True, kw_only=True)
class DesignParameters:
    """The parameters one solve used (SI).

    Parameters
    ----------
    oil : str
        Name of the oil.
    oil_temp_C : float
        Oil temperature [degC].
    depth_m : float
        Depth [m] (sets the pressure).
    nu_m2_s : float
        Kinematic viscosity [m^2/s].
    rho_kg_m3 : float
        Density [kg/m^3].
    torque_min_Nm : float
        Required torque capability [N m].
    inertia_ref_kgm2 : float
        Reference inertia: the case's unfilled rotor [kg m^2].
    inertia_max_kgm2 : float
        Inertia limit [kg m^2].
    lower_m, upper_m : tuple of 5 floats
        Bounds of (R, delta, d_r, d_s, L) [m].
    raw_oil_state : bool
        True if nu/rho were given directly (not from an oil at a condition).
    oil_obj : Fluid or None
        The fluid given as an override (None: the case's).
    """

    oil: str
    oil_temp_C: float
    depth_m: float
    nu_m2_s: float
    rho_kg_m3: float
    torque_min_Nm: float
    inertia_ref_kgm2: float
    inertia_max_kgm2: float
    lower_m: tuple[float, ...]
    """Lower bounds of (R, delta, d_r, d_s, L) [m]."""
    upper_m: tuple[float, ...]
    """Upper bounds of (R, delta, d_r, d_s, L) [m]."""
    raw_oil_state: bool = False
    """True if nu/rho were given directly (not from an oil at a condition)."""
    oil_obj: Fluid | None = field(default=None, repr=False, compare=False)
    """The oil given as an override (None: the case's)."""

    @property
    def inertia_max_ratio(self) -> float:
        """Inertia limit over the reference inertia [-]."""
        return self.inertia_max_kgm2 / self.inertia_ref_kgm2

    def to_dict(self) -> dict[str, Any]:
        """Unit-keyed plain dict for JSON.

        Returns
        -------
        dict
            The oil state (``nu_cSt`` [cSt], ``density_kg_m3``), the limits
            (``torque_min_Nm`` [N m], ``inertia_*_kgm2`` [kg m^2],
            ``inertia_max_ratio`` [-]) and the bounds (``*_min_mm``, ``*_max_mm`` [mm]).
        """
        mm = 1.0 / MM_TO_M
        d: dict[str, Any] = {"oil": self.oil, "oil_temp_C": self.oil_temp_C,
                             "depth_m": self.depth_m, "nu_cSt": m2_s_to_cst(self.nu_m2_s),
                             "density_kg_m3": self.rho_kg_m3,
                             "torque_min_Nm": self.torque_min_Nm,
                             "inertia_ref_kgm2": self.inertia_ref_kgm2,
                             "inertia_max_kgm2": self.inertia_max_kgm2,
                             "inertia_max_ratio": self.inertia_max_ratio}
        for v, lo, hi in zip(VARIABLES, self.lower_m, self.upper_m, strict=True):
            stem = VARIABLE_LABELS[v][1]
            d[f"{stem}_min_mm"] = lo * mm
            d[f"{stem}_max_mm"] = hi * mm
        return d


def _finite_or_none(name: str, value: Any, positive: bool = True) -> float | None:
    if value is None:
        return None
    return check_positive(name, value, "optimize") if positive else check_finite(
        name, value, "optimize")


def _oil_state(problem: DesignProblem, oil: Fluid | None, oil_temp_C: float | None,
               depth_m: float | None, nu_m2_s: float | None, rho_kg_m3: float | None
               ) -> tuple[Fluid, float, float, float, float, bool]:
    """(oil, temperature [degC], depth [m], nu [m^2/s], rho [kg/m^3], raw) of a solve."""
    case = problem.case
    raw = nu_m2_s is not None or rho_kg_m3 is not None
    if raw and (oil is not None or oil_temp_C is not None or depth_m is not None):
        raise InputError("nu_m2_s/rho_kg_m3", (nu_m2_s, rho_kg_m3),
                         "give either nu/rho or oil/oil_temp_C/depth_m, not both",
                         "optimize")
    op = case.operating
    t = op.oil_temp_C if oil_temp_C is None else check_finite("oil_temp_C", oil_temp_C,
                                                                "optimize")
    d = op.depth_m if depth_m is None else check_finite("depth_m", depth_m, "optimize")
    the_oil = case.oil if oil is None else oil
    if oil is None and oil_temp_C is None and depth_m is None:
        nu, rho = problem.nu_m2_s, problem.rho_kg_m3
    else:
        OperatingPoint(d, t)  # validates the ranges
        with_oil = case if the_oil is case.oil else replace(case, oil=the_oil)
        nu, _, rho = (float(v) for v in oil_state(with_oil, t, d))
    if nu_m2_s is not None:
        nu = check_positive("nu_m2_s", nu_m2_s, "optimize")
    if rho_kg_m3 is not None:
        rho = check_positive("rho_kg_m3", rho_kg_m3, "optimize")
    return the_oil, t, d, nu, rho, raw


def _bounds(problem: DesignProblem, overrides: Sequence[tuple[Any, Any]],
            fix: Mapping[str, float] | Sequence[str] | None) -> tuple[list, list]:
    """Lower and upper bounds [m] of (R, delta, d_r, d_s, L): the case's, overridden,
    with the ``fix``-ed variables pinned."""
    b = problem.case.bounds
    lo = [b.radius_min, b.gap_min, 0.0, 0.0, b.length_min]
    hi = [b.radius_max, b.gap_max, problem.machined_rotor_groove_m,
          problem.machined_stator_groove_m, b.length_max]
    for i, (nlo, nhi) in enumerate(overrides):
        stem = VARIABLE_LABELS[VARIABLES[i]][1]
        v = _finite_or_none(f"{stem}_min_m", nlo)
        lo[i] = lo[i] if v is None else v
        v = _finite_or_none(f"{stem}_max_m", nhi)
        hi[i] = hi[i] if v is None else v
    if fix:
        items = fix.items() if isinstance(fix, Mapping) else ((k, None) for k in fix)
        for k, v in items:
            if k not in VARIABLES:
                raise InputError("fix", k, f"allowed: {', '.join(VARIABLES)}", "optimize")
            i = VARIABLES.index(k)
            val = problem.x_case_m[i] if v is None else check_finite(f"fix[{k}]", v,
                                                                      "optimize")
            lo[i] = hi[i] = val
    return lo, hi


def _check_bounds(problem: DesignProblem, lo: list, hi: list) -> None:
    """Raise InputError if the bounds [m] are inconsistent or leave the shaft bore."""
    for i, v in enumerate(VARIABLES):
        stem = VARIABLE_LABELS[v][1]
        if lo[i] > hi[i]:
            raise InputError(f"{stem}_max_mm", hi[i] / MM_TO_M,
                             f"must be >= {stem}_min_mm = {lo[i] / MM_TO_M:g}", "optimize")
        if v in ("d_r", "d_s"):
            top = (problem.machined_rotor_groove_m if v == "d_r"
                   else problem.machined_stator_groove_m)
            if lo[i] < 0.0 or hi[i] > top * (1 + 1e-12) + 1e-15:
                raise InputError(f"fix[{v}]", hi[i] / MM_TO_M,
                                 f"groove depth must lie in [0, {top / MM_TO_M:g}] mm "
                                 "(filling only makes grooves shallower)", "optimize")
        elif lo[i] <= 0.0:
            raise InputError(f"{stem}_min_mm", lo[i] / MM_TO_M, "must be > 0", "optimize")
    if lo[0] - problem.machined_rotor_groove_m <= problem.case.motor.shaft_bore_radius:
        raise InputError("radius_min_mm", lo[0] / MM_TO_M, "must leave the machined groove "
                         "bottoms outside the shaft bore", "optimize")


def _resolve_parameters(problem: DesignProblem, *, oil: Fluid | None = None,
                        oil_temp_C: float | None = None, depth_m: float | None = None,
                        nu_m2_s: float | None = None, rho_kg_m3: float | None = None,
                        torque_min_Nm: float | None = None,
                        inertia_max_ratio: float | None = None,
                        gap_min_m: float | None = None, gap_max_m: float | None = None,
                        radius_min_m: float | None = None, radius_max_m: float | None = None,
                        length_min_m: float | None = None, length_max_m: float | None = None,
                        fix: Mapping[str, float] | Sequence[str] | None = None
                        ) -> DesignParameters:
    """Resolve and validate the parameters of a solve of ``problem``.

    The body of :meth:`.problem.DesignProblem.parameters` (its only caller: the
    overrides of a solve, by keyword).

    Parameters
    ----------
    problem : DesignProblem
        Supplies the case (oil, operating point, bounds, motor), its oil state,
        default torque, machined groove depths and inertia reference.
    oil : Fluid, optional
        Oil, table fluid or gas (default: the case's).
    oil_temp_C : float, optional
        Oil temperature [degC] (default: the case's).
    depth_m : float, optional
        Depth [m] (default: the case's).
    nu_m2_s, rho_kg_m3 : float, optional
        Kinematic viscosity [m^2/s] and density [kg/m^3] directly (not with an
        oil, temperature or depth).
    torque_min_Nm : float, optional
        Required torque capability [N m] (default:
        ``problem.default_torque_min_Nm``).
    inertia_max_ratio : float, optional
        Inertia limit over the case's unfilled rotor [-] (default: the case's).
    gap_min_m, gap_max_m, radius_min_m, radius_max_m, length_min_m, length_max_m : float
        Bounds [m] replacing the case's.
    fix : sequence of names or mapping name -> [m], optional
        Variables held at the case's value or at the given value; names from
        :data:`~oilgap.optim.design.variables.VARIABLES`.

    Returns
    -------
    DesignParameters

    Raises
    ------
    InputError
        A bad override (the field names it).
    """
    the_oil, t, d, nu, rho, raw = _oil_state(problem, oil, oil_temp_C, depth_m, nu_m2_s,
                                             rho_kg_m3)
    tmin = problem.default_torque_min_Nm if torque_min_Nm is None else check_positive(
        "torque_min_Nm", torque_min_Nm, "optimize")
    ratio = problem.case.bounds.inertia_max_ratio if inertia_max_ratio is None else \
        check_positive("inertia_max_ratio", inertia_max_ratio, "optimize")
    lo, hi = _bounds(problem, ((radius_min_m, radius_max_m), (gap_min_m, gap_max_m),
                               (None, None), (None, None), (length_min_m, length_max_m)), fix)
    _check_bounds(problem, lo, hi)
    return DesignParameters(oil=the_oil.name, oil_temp_C=t, depth_m=d, nu_m2_s=nu, rho_kg_m3=rho,
                            torque_min_Nm=tmin, inertia_ref_kgm2=problem.inertia_ref_kgm2,
                            inertia_max_kgm2=ratio * problem.inertia_ref_kgm2, lower_m=tuple(lo),
                            upper_m=tuple(hi), raw_oil_state=raw, oil_obj=oil)


__all__ = ["DesignParameters"]
