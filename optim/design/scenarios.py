"""Scenarios of the uncertain inputs, resolved once into what the design NLP needs.

A scenario is one set of values of the uncertain inputs of
:data:`oilgap.model.uncertain.INPUTS` (``nu40_factor``, ``oil_temp_C``, ``depth_m``,
``gamma``, ``friction_scale``, ``bearing_drag_scale``, ``peak_speed_rpm``;
``film_strength`` acts under the ``film``/``full`` modes only and is left out under
``none``). :func:`resolve_scenarios` turns N of them into the model data of each scenario
through the scalar reference path, :func:`~oilgap.model.uncertain.apply_inputs`:

* the oil state (nu_i, rho_i) of the scenario's case (:func:`~oilgap.model.evaluation.
  oil_state`: its oil's Walther line rebuilt by ``nu40_factor``/``nu100_factor``, or
  scaled by ``nu_factor_all_temperatures``, at its temperature and depth);
* its friction law (gamma and the scale on C_m, in the smooth form the NLP uses);
* its duty cycle's speed distribution (the peak speed scales every node);
* its design-independent loss: region 2 (the bearing annulus) and the rolling bearing
  (with the scenario's drag scale).

Region 1's loss of a design x in scenario i is then :func:`.objective.region1_mean_power`
with these data: the NLP calls it with CasADi symbols (:mod:`~oilgap.optim.design.robust`), and
:meth:`ScenarioSet.losses` with numpy arrays of designs (the brute-force check and the
reports). Seed paper, Eqs. 4-10 [1]; ISO 3448 grades [2].

References
----------
.. [1] *Modeling and Optimization of Compensating Oil Viscous Power for a Deep-Sea
   Electric Manipulator* (the seed paper), Eqs. 4-10.
.. [2] ISO 3448:1992, industrial liquid lubricants, ISO viscosity classification.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from oilgap.model.bearing import bearing_mean_power
from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.evaluation import oil_state
from oilgap.model.regions import joint_regions, region_mean_power, rotor_stator_radii
from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.uncertain import INPUTS, apply_inputs

from .objective import region1_mean_power

FILM_ONLY = ("film_strength",)
"""Inputs that act under the film modes only (left out of an isothermal scenario)."""


@dataclass(frozen=True, kw_only=True)
class ScenarioSet:
    """N scenarios resolved into model data (SI).

    Attributes
    ----------
    values : dict of str -> ndarray
        The inputs' values, N each, in the inputs' units.
    ignored : tuple of str
        Inputs given but without effect under the mode (e.g. ``film_strength``).
    nu_m2_s, rho_kg_m3 : ndarray of shape (N,)
        Oil state of each scenario [m^2/s], [kg/m^3].
    laws : tuple of FrictionLaw
        Each scenario's friction law (smooth C_m) [-].
    nodes_rad_s : tuple of ndarray
        Each scenario's nonzero speed nodes [rad/s].
    weights : tuple of ndarray
        Their weights [-].
    constant_W : ndarray of shape (N,)
        Each scenario's design-independent loss: region 2 and the rolling bearing [W].
    """

    values: dict
    ignored: tuple
    nu_m2_s: np.ndarray
    rho_kg_m3: np.ndarray
    laws: tuple
    nodes_rad_s: tuple
    weights: tuple
    constant_W: np.ndarray

    @property
    def n(self) -> int:
        """Number of scenarios N [-]."""
        return int(self.nu_m2_s.size)

    def region1(self, i: int, x_m) -> object:
        """Region 1's mean power of design(s) ``x_m`` in scenario ``i``.

        Parameters
        ----------
        i : int
            Scenario index.
        x_m : sequence of 5 (float, ndarray of shape (n, 1), or CasADi symbol)
            (R, delta, d_r, d_s, L) [m].

        Returns
        -------
        float, ndarray or CasADi expression
            Mean power [W] (:func:`.objective.region1_mean_power`).
        """
        nodes = self.nodes_rad_s[i]
        if not isinstance(x_m[0], (float, np.floating, np.ndarray)):
            import casadi as ca  # symbols: nodes as a DM
            nodes = ca.DM(nodes)
        elif np.ndim(x_m[0]):
            nodes = nodes[None, :]
        return region1_mean_power(x_m, self.nu_m2_s[i], self.rho_kg_m3[i], nodes,
                                  self.weights[i], self.laws[i])

    def losses(self, x_m) -> np.ndarray:
        """Total loss of design(s) in every scenario (numpy).

        Parameters
        ----------
        x_m : array of shape (5,) or (n, 5)
            (R, delta, d_r, d_s, L) [m].

        Returns
        -------
        ndarray of shape (N,) or (n, N)
            Region 1 + region 2 + bearing [W].
        """
        x = np.asarray(x_m, dtype=float)
        rows = x.ndim == 2
        cols = tuple(x[:, k:k + 1] for k in range(5)) if rows else tuple(x)
        out = np.column_stack([np.ravel(self.region1(i, cols)) for i in range(self.n)])
        out = out + self.constant_W[None, :]
        return out if rows else out[0]


def check_scenarios(scenarios: Mapping[str, object]) -> dict[str, np.ndarray]:
    """Check a scenarios mapping: known inputs, equal lengths, finite values.

    Parameters
    ----------
    scenarios : mapping of str -> array
        Input name (:data:`~oilgap.model.uncertain.INPUTS`) -> N values in its unit.

    Returns
    -------
    dict of str -> ndarray
        The values as float arrays of shape (N,) [the inputs' units].

    Raises
    ------
    InputError
        Unknown input, arrays of different lengths or not 1-D, non-finite values.
    """
    out: dict[str, np.ndarray] = {}
    for k, v in scenarios.items():
        if k not in INPUTS:
            raise InputError("scenarios", k, f"one of {', '.join(INPUTS)}", "robust")
        a = np.asarray(v, dtype=float)
        if a.ndim != 1 or not np.all(np.isfinite(a)):
            raise InputError(f"scenarios[{k}]", "array", "a 1-D array of finite numbers",
                             "robust")
        out[k] = a
    sizes = {a.size for a in out.values()}
    if len(sizes) > 1:
        raise InputError("scenarios", sorted(sizes), "one length for every input", "robust")
    return out


def _scenario_data(case: DesignCase, row: Mapping[str, float]
                   ) -> tuple[float, float, FrictionLaw, np.ndarray, np.ndarray, float]:
    """(nu, rho, law, nodes, weights, constant loss) of one scenario of ``case``."""
    c = apply_inputs(case, row)
    nu, _, rho = (float(v) for v in oil_state(c))
    law = c.friction.smooth()
    nodes, weights = c.duty_cycle.speed_distribution()
    keep = nodes > 0.0  # zero speed carries no power (Eq. 5)
    nodes, weights = np.ascontiguousarray(nodes[keep]), np.ascontiguousarray(weights[keep])
    const = 0.0
    if c.region2 is not None:
        const += float(region_mean_power(joint_regions(c)[1], nodes, weights, nu, rho, law))
    if c.bearing is not None:
        const += float(bearing_mean_power(c.bearing, nodes, weights, nu))
    return nu, rho, law, nodes, weights, const


def resolve_scenarios(case: DesignCase, scenarios: Mapping[str, object],
                      mode: str = "none") -> ScenarioSet:
    """The model data of each scenario (through :func:`~oilgap.model.uncertain.apply_inputs`).

    Parameters
    ----------
    case : DesignCase
        The nominal case (its region 1 is irrelevant: the design varies it).
    scenarios : mapping of str -> array
        Input name -> N values in the input's unit (missing inputs: nominal).
    mode : str
        Thermal mode; only ``"none"`` (isothermal oil at each scenario's temperature)
        is supported.

    Returns
    -------
    ScenarioSet
        nu [m^2/s], rho [kg/m^3], laws, nodes [rad/s], constant losses [W] per scenario.

    Raises
    ------
    InputError
        Bad scenarios, an unsupported mode, or a scenario value its field refuses.
    """
    if mode != "none":
        raise InputError("thermal", mode, "the robust design NLP supports thermal mode "
                         "none only (isothermal oil at each scenario's temperature)", "robust")
    vals = check_scenarios(scenarios)
    used = {k: v for k, v in vals.items() if k not in FILM_ONLY}
    ignored = tuple(k for k in vals if k in FILM_ONLY)
    n = next(iter(vals.values())).size if vals else 0
    data = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OilgapWarning)  # the nominal case warned already
        for i in range(n):
            data.append(_scenario_data(case, {k: float(v[i]) for k, v in used.items()}))
    cols = list(zip(*data, strict=True)) if data else [()] * 6
    return ScenarioSet(values=vals, ignored=ignored, nu_m2_s=np.array(cols[0], dtype=float),
                       rho_kg_m3=np.array(cols[1], dtype=float), laws=tuple(cols[2]),
                       nodes_rad_s=tuple(cols[3]), weights=tuple(cols[4]),
                       constant_W=np.array(cols[5], dtype=float))


def design_case(case: DesignCase, x_m, machined_m: tuple[float, float]) -> DesignCase:
    """The case with region 1 set to design ``x_m`` (machined groove bottoms kept).

    Parameters
    ----------
    case : DesignCase
        The case.
    x_m : sequence of 5 floats
        (R, delta, d_r, d_s, L) [m].
    machined_m : (float, float)
        Groove depths as machined, d_r0 and d_s0 [m].

    Returns
    -------
    DesignCase
        What ``oilgap evaluate`` of the design reads.
    """
    R, d, a, b, L = (float(v) for v in x_m)
    T1, T2, T3, T4 = rotor_stator_radii(R, d, a, b)
    return case.with_region1(T1=T1, T2=T2, T3=T3, T4=T4, length=L,
                             T1_unfilled=R - machined_m[0], T4_unfilled=T3 + machined_m[1])


def smooth_case(case: DesignCase) -> DesignCase:
    """The case with its friction law in the smooth form the NLP uses.

    Parameters
    ----------
    case : DesignCase
        The case.

    Returns
    -------
    DesignCase
        The same case, C_m [-] in the smooth form of Eq. 6.
    """
    return replace(case, friction=case.friction.smooth())


__all__ = ["FILM_ONLY", "ScenarioSet", "check_scenarios", "design_case", "resolve_scenarios",
           "smooth_case"]
