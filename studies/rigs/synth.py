"""A synthetic rig: the seed's viscous-power experiment, simulated.

The oil-free group and four oils (ISO VG 150, 320, 680, 1000: 150 ... 1000 cSt
at 40 degC), each with the grooved (T = 4) and the smoothed (T = 2) rotor;
1500 samples every 0.2 s of ``3000 rpm sin(0.1 pi t)`` per run (or a trapezoid or
steps profile, :mod:`.profiles`). What it
simulates, per run:

* Viscous power from the physics core: ``clearance_power`` per region (region 1
  with the run's T, region 2 with T = 1) under a *truth* friction law, by
  default the design tool's: the case's Eq. 6 in its smooth form (as the NLP
  and the loop's default base model use it) with the case's laminar law and
  gamma; and the oil's nu, rho from its Walther line and density law at the
  oil temperature (atmospheric pressure: the seed's rig stands in a tank). A
  power law (the loop's ``--base power-law``) can be given as ``truth``.
* A lumped thermal model heated by the losses, integrated with
  ``scipy.integrate.solve_ivp`` (all runs at once):
  ``C_th dT/dt = P_heat - (T - T_amb)/R_th``, P_heat = viscous power +
  dissipative effect + motor heat (iron, copper, a share of the gear loss).
* The electrical input power: a baseline of load and motor losses
  (:class:`BaselineTruth`, the same for oil-free and oil runs of one T) plus the
  viscous power and, optionally, one or several library effects at given
  strengths (:mod:`oilgap.model.effects`; thermal lag acts through the oil temperature,
  sensor delay by shifting the power record in time, shear thinning with the
  full Cross law, the others as their library terms).
* Measurement noise on power, speed and temperature (seeded).

The output is a data frame in the loop's data format and carries no trace of
the effect (no column, no metadata). The noise-free simulation is cached, so
seeds of one configuration cost only the noise.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd
from scipy.integrate import solve_ivp

from oilgap.model.case import DesignCase
from oilgap.model.effects import (
    EFFECTS,
    EffectContext,
    cross_region_ratios,
    effect_context,
    film_temperature,
    get_effect,
)
from oilgap.model.errors import InputError, SolverError, check_finite
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.case_write import case_to_dict
from oilgap.model.oil_properties import oil_viscosities
from oilgap.model.oils import builtin_fluids, get_oil, normalize_oil_name
from oilgap.model.regions import joint_geometry
from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.thermal import lumped_temperature_rate
from oilgap.model.units import ZERO_CELSIUS_K, rad_s_to_rpm, rpm_to_rad_s
from oilgap.optim.calibration import LoopEstimator
from oilgap.optim.calibration.forward import case_film_theory_K_W
from oilgap.studies.rigs.profiles import PROFILES, profile_speed

DEFAULT_STRENGTH = {
    "end_face_disc": 4.0,
    "bearing_ball_churning": 1.0,
    "bearing_ball_drag": 1.0,
    "seal_coulomb_friction": 0.04,
    "oil_inertia": 5.0e-7,
    "thermal_lag": 4.0,
    "taylor_vortex_onset": 1.0,
    "shear_thinning": 7.5e-5,
    "sensor_delay": 0.2,
    "film_heating": 0.015,
}
"""Strength of each effect when ``--strength`` is not given (unit: Effect.strength_unit)."""


@dataclass(frozen=True, kw_only=True)
class BaselineTruth:
    """Load and motor losses of the simulated joint (electrical input without oil).

    ``P = P_0 + p_T T + tau_L |w| + b w^2 + J w dw/dt + k_cu (1 + a (T_c - 20)) tau_m^2``
    with the motor torque ``tau_m = tau_L sign(w) + J dw/dt``: electronics, the
    load (a constant torque at the motor), iron loss, rotor inertia and copper
    loss. Heat into the joint: iron + copper + ``gear_heat_share`` of the load.
    """

    electronics_W: float = 3.5
    per_roughness_W: float = 0.25
    load_torque_Nm: float = 0.09
    iron_W_s2: float = 1.5e-5
    rotor_inertia_kg_m2: float = 2.0e-4
    copper_W_Nm2: float = 50.0
    copper_tempco_1_K: float = 0.00393
    gear_heat_share: float = 0.3

    def power(self, omega, domega_dt, coil_temp_C, roughness_T):
        """Electrical input power [W] without oil."""
        tau_m = self.load_torque_Nm * np.sign(omega) + self.rotor_inertia_kg_m2 * domega_dt
        copper = self.copper_W_Nm2 * (1.0 + self.copper_tempco_1_K * (coil_temp_C - 20.0)) \
            * tau_m * tau_m
        return (self.electronics_W + self.per_roughness_W * roughness_T
                + self.load_torque_Nm * np.abs(omega) + self.iron_W_s2 * omega * omega
                + self.rotor_inertia_kg_m2 * omega * domega_dt + copper)

    def heat(self, omega, domega_dt, coil_temp_C):
        """Heat released inside the joint [W] (iron, copper, share of the load)."""
        tau_m = self.load_torque_Nm * np.sign(omega) + self.rotor_inertia_kg_m2 * domega_dt
        copper = self.copper_W_Nm2 * (1.0 + self.copper_tempco_1_K * (coil_temp_C - 20.0)) \
            * tau_m * tau_m
        return (self.iron_W_s2 * omega * omega + copper
                + self.gear_heat_share * self.load_torque_Nm * np.abs(omega))


def seed_truth_law(case: DesignCase | None = None) -> FrictionLaw:
    """The synthetic rig's true friction law: the design tool's Eq. 6 in its smooth form.

    ``FrictionLaw(form="smooth")`` with the case's laminar law, scale 1, alpha 0.3
    and the case's gamma (the seed's, by default): the loop's default base model
    at scale 1.
    """
    case = case or seed_case()
    return FrictionLaw(form="smooth", laminar_law=case.friction.laminar_law,
                       gamma=case.friction.gamma)


def power_law_truth(case: DesignCase | None = None) -> FrictionLaw:
    """A power-law truth: Eq. 8 with the Eq. 6 laminar branch (C = 10, alpha = 0.3,
    beta = -1) and the case's gamma (the loop's ``--base power-law`` model)."""
    case = case or seed_case()
    return FrictionLaw(form="power-law", C=10.0, alpha=0.3, beta=-1.0, gamma=case.friction.gamma)


SYNTH_OILS = ("VG150", "VG320", "VG680", "VG1000")
"""The rig's four oils (ISO VG grades of the built-in catalogue)."""


@dataclass(frozen=True, kw_only=True)
class SynthConfig:
    """What the synthetic rig simulates (SI unless the name says otherwise).

    ``case`` gives the geometry (region 1 radius, gap, length; region 2 if any;
    the rotor end-face radii); its own T is replaced by each run's
    ``roughness``. ``truth`` None means :func:`seed_truth_law` of the case.
    ``kind`` "power_W" writes the electrical input (with oil-free runs);
    "viscous_power_W" writes the viscous loss directly (no oil-free runs).
    ``effect``/``strength`` inject one library effect; ``effects`` several at
    once (``{name: strength}``, a strength None meaning the default); both
    together are refused. ``fluids`` holds oils that override the catalogue by
    name (e.g. a polymer-thickened VG320).
    """

    case: DesignCase | None = None
    oils: tuple[str, ...] = SYNTH_OILS
    roughness: tuple[float, ...] = (4.0, 2.0)
    n_samples: int = 1500
    sample_interval_s: float = 0.2
    peak_speed_rpm: float = 3000.0
    frequency_hz: float = 0.05
    profile: str = "sine"
    ambient_C: float = 25.0
    thermal_resistance_K_W: float = 0.25
    heat_capacity_J_K: float = 240.0
    truth: FrictionLaw | None = None
    baseline: BaselineTruth = field(default_factory=BaselineTruth)
    noise_power_W: float = 1.0
    noise_speed_rpm: float = 2.0
    noise_temp_K: float = 0.05
    kind: str = "power_W"
    effect: str | None = None
    strength: float | None = None
    extra_power: str | None = None
    effects: tuple | dict | None = None
    fluids: tuple = ()

    def __post_init__(self):
        if isinstance(self.effects, dict):  # hashable: a tuple of (name, strength)
            object.__setattr__(self, "effects", tuple(self.effects.items()))

    def oil(self, name: str):
        """The oil of that name: from ``fluids`` if there, else the catalogue."""
        for o in self.fluids:
            if normalize_oil_name(o.name) == normalize_oil_name(name):
                return o
        return get_oil(name)

    def injected(self) -> dict[str, float]:
        """Effect -> strength of a resolved configuration (empty without effects)."""
        return dict(self.effects or ())

    def resolved(self) -> SynthConfig:
        """The same configuration with defaults filled in and checked."""
        case = self.case or seed_case()
        truth = self.truth or seed_truth_law(case)
        if self.kind not in ("power_W", "viscous_power_W"):
            raise InputError("kind", self.kind, "allowed: power_W, viscous_power_W", "synth")
        if self.profile not in PROFILES:
            raise InputError("profile", self.profile, f"allowed: {', '.join(PROFILES)}", "synth")
        if self.n_samples < 20:
            raise InputError("n_samples", self.n_samples, "must be >= 20", "synth")
        for r in self.roughness:
            if not r >= 1.0:
                raise InputError("roughness_T", r, "must be >= 1", "synth")
        for o in self.oils:
            if getattr(self.oil(o), "kind", "mineral") != "mineral":  # Walther arrays below
                raise InputError("oil", o, "the synthetic rig takes mineral oils", "synth")
        strength = self.strength
        if self.effect is not None:
            if self.effects:
                raise InputError("effects", dict(self.effects), "give effect or effects, not "
                                 "both", "synth")
            get_effect(self.effect)
            strength = DEFAULT_STRENGTH[self.effect] if strength is None else \
                _checked_strength(self.effect, "strength", strength)
            effects = ((self.effect, strength),)
        elif strength is not None:
            raise InputError("strength", strength, "only together with an effect", "synth")
        else:
            effects = tuple((get_effect(n).name, DEFAULT_STRENGTH[n] if st is None else
                             _checked_strength(n, f"strength of {n}", st))
                            for n, st in self.effects or ())
        if case.bearing is None and any(n == "bearing_ball_drag" for n, _ in effects):
            raise InputError("effect", "bearing_ball_drag", "a case with a [bearing] (the "
                             "drag term needs the bearing's rings)", "synth")
        if self.extra_power not in (None, *OUTSIDE_LIBRARY):
            raise InputError("extra_power", self.extra_power,
                             f"allowed: {', '.join(OUTSIDE_LIBRARY)}", "synth")
        return replace(self, case=case, truth=truth, strength=strength, effects=effects)


MAX_STRENGTH_FACTOR = 1000.0
"""Largest |strength| as a multiple of the effect's :data:`DEFAULT_STRENGTH`: a thousand
times the test strength already swamps the oil's own loss (kW on the seed rig); beyond,
the rig's thermal model leaves its range."""


def _checked_strength(effect: str, field: str, value) -> float:
    """A finite strength, >= 0 where the effect's coefficient must be (``nonnegative``),
    at most :data:`MAX_STRENGTH_FACTOR` times the default in size."""
    x = check_finite(field, value, "synth")
    if x < 0.0 and EFFECTS[effect].nonnegative:
        raise InputError(field, value, f"must be >= 0: the coefficient of {effect} is "
                         "non-negative by physics (dissipation, inertia, causality)", "synth")
    top = MAX_STRENGTH_FACTOR * DEFAULT_STRENGTH[effect]
    if abs(x) > top:
        raise InputError(field, value, f"at most {top:g} in size ({MAX_STRENGTH_FACTOR:g} "
                         f"times the test strength {DEFAULT_STRENGTH[effect]:g}, which already "
                         "swamps the oil's loss)", "synth")
    return x


def polymer_thickened(oils: tuple[str, ...] = SYNTH_OILS) -> tuple:
    """The catalogue's oils of those names, marked polymer-thickened (for ``fluids``).

    Parameters
    ----------
    oils : tuple of str
        Catalogue names (default: the rig's four oils).

    Returns
    -------
    tuple of Oil
        The same Walther lines and densities with ``polymer_thickened=True``.
    """
    return tuple(replace(get_oil(o), polymer_thickened=True) for o in oils)


def fluid_table(config: SynthConfig | None = None) -> dict:
    """The fluid table the loop needs for the rig's data: the catalogue, ``fluids`` over it.

    Parameters
    ----------
    config : SynthConfig, optional

    Returns
    -------
    dict
        Normalised name -> fluid.
    """
    cfg = config or SynthConfig()
    return {**builtin_fluids(), **{normalize_oil_name(o.name): o for o in cfg.fluids}}


OUTSIDE_LIBRARY = {
    "direction_dependent": "0.15 * P_visc * sign(w): a loss that depends on the direction of "
                           "rotation (e.g. a helical groove pumping one way)",
    "power_meter_drift": "0.02 W/s * t: a slow drift of the power reading within each run",
}
"""Effects the library does not hold, for testing that the loop does not misname them."""


# --------------------------------------------------------------------------- simulation


@dataclass(frozen=True)
class _Run:
    name: str
    oil: str | None
    roughness: float


def _runs(cfg: SynthConfig) -> list[_Run]:
    out = []
    for T in cfg.roughness:
        if cfg.kind == "power_W":
            out.append(_Run(f"oilfree-T{T:g}", None, T))
        for o in cfg.oils:
            out.append(_Run(f"{o}-T{T:g}", o, T))
    return out


def _context(cfg: SynthConfig, omega, domega_dt, nu, rho, roughness) -> EffectContext:
    """Effect context of the rig's runs of the given roughness under the truth law."""
    geometry = joint_geometry(cfg.case, roughness_T=roughness)
    return effect_context(geometry, omega, domega_dt, nu, rho, cfg.truth)


def _effect_power(cfg: SynthConfig, ctx: EffectContext, dissipated: bool = False
                  ) -> np.ndarray:
    """Injected power of the configured effects [W] (static effects only; ``dissipated``:
    without the oil's inertia, which stores energy rather than heating the oil)."""
    total = np.zeros_like(np.asarray(ctx.power_W, dtype=float))
    for name, strength in cfg.injected().items():
        if name in ("thermal_lag", "sensor_delay", "film_heating") or (
                dissipated and name == "oil_inertia"):
            continue
        eff = EFFECTS[name]
        if name == "shear_thinning":  # the full Cross law, not its first-order term
            total = total + sum(r.power_W * (q - 1.0) for r, q in zip(
                ctx.regions, cross_region_ratios(ctx, strength), strict=True))
            continue
        f = eff.feature_values(ctx)
        if f is not None:
            total = total + eff.coefficient_from_strength(strength) * f
    return total


def _oil_state(oils, has_oil, temp_C):
    temp_C = np.asarray(temp_C, dtype=float)
    shape = (-1,) + (1,) * (temp_C.ndim - 1)
    A = np.array([o.walther[0] for o in oils]).reshape(shape)
    B = np.array([o.walther[1] for o in oils]).reshape(shape)
    rho15 = np.array([o.density_kg_m3 for o in oils]).reshape(shape)
    barus = np.array([o.barus_1_Pa for o in oils]).reshape(shape)
    nu, _, rho = oil_viscosities(A, B, rho15, np.asarray(temp_C) + ZERO_CELSIUS_K, 0.0, barus)
    return np.where(has_oil, nu, 1.0), np.where(has_oil, rho, 0.0)


_CACHE: dict[str, dict] = {}


def _key(cfg: SynthConfig) -> str:
    d = {k: getattr(cfg, k) for k in cfg.__dataclass_fields__ if k != "case"}
    return repr(d) + repr(case_to_dict(cfg.case))


class _RigModel:
    """The rig's runs as one ODE system: speed, heat, thermal state and sensor readings."""

    def __init__(self, cfg: SynthConfig):
        self.cfg = cfg
        self.runs = _runs(cfg)
        self.n_r = len(self.runs)
        self.has_oil = np.array([r.oil is not None for r in self.runs])
        self.oils = [cfg.oil(r.oil or cfg.oils[0]) for r in self.runs]
        self.rough = np.array([r.roughness for r in self.runs])
        self.w0 = rpm_to_rad_s(cfg.peak_speed_rpm)
        self.two_pi_f = 2.0 * np.pi * cfg.frequency_hz
        self.lag = cfg.injected().get("thermal_lag", 0.0)
        self.film = cfg.injected().get("film_heating", 0.0) * case_film_theory_K_W(cfg.case)
        self.sol = None

    def film_state(self, w, a, toil, has_oil, rough):
        """(nu, rho) of the clearance's oil, ``toil`` [degC] raised by the film's heating
        ``c P`` (solved per sample) when film heating is injected: c = s c_theory(w), the
        injected film strength s times the case's ``case_film_theory_K_W``."""
        lam = self.cfg.injected().get("shear_thinning", 0.0)

        def power_at(temp_C):  # the film's own loss: the clearance's, thinned if injected
            nu, rho = _oil_state(self.oils, has_oil, temp_C)
            ctx = _context(self.cfg, w, a, nu, rho, rough)
            if not lam:
                return ctx.power_W
            return sum(r.power_W * q for r, q in zip(ctx.regions, cross_region_ratios(ctx, lam),
                                                     strict=True))

        if self.film:
            toil = film_temperature(toil, power_at, self.film)
        return _oil_state(self.oils, has_oil, toil)

    def speed(self, t):
        """Speed [rad/s] and acceleration [rad/s^2] at times t (the configured profile)."""
        return profile_speed(self.cfg.profile, t, self.w0, self.cfg.frequency_hz)

    def split(self, y):
        """(heated node, measured, oil) temperatures [degC]."""
        n_r, lag = self.n_r, self.lag
        th = y[:n_r]
        if lag > 0:
            return th, th, y[n_r:]
        if lag < 0:
            return th, y[n_r:], th
        return th, th, th

    def heat(self, t, y):
        """Heat released in each run's joint [W]."""
        cfg, has_oil = self.cfg, self.has_oil
        w, a = self.speed(t)
        th, _, toil = self.split(y)
        nu, rho = self.film_state(w, a, toil, has_oil, self.rough)
        ctx = _context(cfg, w, a, nu, rho, self.rough)
        p = (ctx.power_W + _effect_power(cfg, ctx, dissipated=True)) * has_oil
        return p + cfg.baseline.heat(w, a, th)

    def rhs(self, t, y):
        """d/dt of the thermal state: the lumped law, plus the lagging node if any."""
        cfg, n_r, lag = self.cfg, self.n_r, self.lag
        th = y[:n_r]
        dth = lumped_temperature_rate(th, self.heat(t, y), cfg.ambient_C,
                                      cfg.thermal_resistance_K_W, cfg.heat_capacity_J_K)
        if lag == 0.0:
            return dth
        other = y[n_r:]
        return np.concatenate([dth, (th - other) / abs(lag)])

    def integrate(self, t: np.ndarray) -> None:
        """Integrate the thermal state over the record (dense output kept)."""
        y0 = np.full(self.n_r * (2 if self.lag else 1), self.cfg.ambient_C)
        sol = solve_ivp(self.rhs, (0.0, t[-1]), y0, method="RK45", t_eval=t,
                        dense_output=True, rtol=1e-7, atol=1e-6, max_step=1.0)
        if not sol.success:  # pragma: no cover - a smooth, stable ODE
            raise SolverError(f"thermal model: {sol.message}")
        self.sol = sol

    def record(self, tt):
        """Everything the sensors see at times tt (n_runs x n arrays)."""
        cfg, has_oil, rough = self.cfg, self.has_oil, self.rough
        yy = self.sol.sol(np.clip(tt, 0.0, None)) if np.ndim(tt) else \
            self.sol.sol(max(tt, 0.0))
        w, a = self.speed(tt)
        th, tmeas, toil = self.split(yy)
        nu, rho = self.film_state(w[None, :], a[None, :], toil, has_oil[:, None], rough[:, None])
        ctx = _context(cfg, w[None, :], a[None, :], nu, rho, rough[:, None])
        visc = ctx.power_W * has_oil[:, None]
        eff = _effect_power(cfg, ctx) * has_oil[:, None]
        extra = np.zeros_like(visc)
        if cfg.extra_power == "direction_dependent":
            extra = 0.15 * visc * np.sign(w)[None, :]
        elif cfg.extra_power == "power_meter_drift":
            extra = 0.02 * np.broadcast_to(tt, visc.shape) * has_oil[:, None]
        base = cfg.baseline.power(w[None, :], a[None, :], th, rough[:, None])
        return w, th, tmeas, toil, visc, eff, extra, base


def simulate_truth(config: SynthConfig | None = None) -> dict:
    """Noise-free simulation of every run (cached).

    Returns
    -------
    dict with ``runs`` (list of (name, oil or None, T)), ``time_s`` [s],
    ``omega`` [rad/s] (n_runs x n), ``temp_meas_C``, ``temp_oil_C`` [degC],
    ``viscous_W`` (clearance model, truth law), ``effect_W`` (injected effect),
    ``measured_W`` (what the sensor reads: power_W or viscous_power_W, noise-free).
    """
    cfg = (config or SynthConfig()).resolved()
    key = _key(cfg)
    if key in _CACHE:
        return _CACHE[key]
    rig = _RigModel(cfg)
    t = np.arange(cfg.n_samples) * cfg.sample_interval_s
    rig.integrate(t)
    delay = cfg.injected().get("sensor_delay", 0.0)
    w, th, tmeas, toil, visc, eff, extra, base = rig.record(t)
    if delay:
        _, _, _, _, visc_d, eff_d, extra_d, base_d = rig.record(t - delay)
    else:
        visc_d, eff_d, extra_d, base_d = visc, eff, extra, base
    oil_part = visc_d + eff_d + extra_d
    measured = oil_part + base_d if cfg.kind == "power_W" else oil_part
    out = {"config": cfg, "runs": [(r.name, r.oil, r.roughness) for r in rig.runs],
           "time_s": t, "omega": np.broadcast_to(w, visc.shape).copy(), "temp_meas_C": tmeas,
           "temp_oil_C": toil, "viscous_W": visc, "effect_W": eff_d + extra_d,
           "measured_W": measured}
    if len(_CACHE) > 64:
        _CACHE.clear()
    _CACHE[key] = out
    return out


def synthesize(config: SynthConfig | None = None, seed: int = 0) -> pd.DataFrame:
    """Synthetic rig data in the loop's format (one row per sample), with noise.

    Columns ``run, time_s, speed_rpm, temp_C, oil, roughness_T`` and
    ``power_W`` or ``viscous_power_W``. ``seed`` draws the measurement noise.
    """
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError("seed", seed, "an integer >= 0 is required", "synth")
    tr = simulate_truth(config)
    cfg = tr["config"]
    rng = np.random.default_rng(seed)
    frames = []
    t = tr["time_s"]
    for i, (name, oil, T) in enumerate(tr["runs"]):
        n = len(t)
        speed = rad_s_to_rpm(tr["omega"][i]) + rng.normal(0.0, cfg.noise_speed_rpm, n)
        temp = tr["temp_meas_C"][i] + rng.normal(0.0, cfg.noise_temp_K, n)
        p = tr["measured_W"][i] + rng.normal(0.0, cfg.noise_power_W, n)
        frames.append(pd.DataFrame({
            "run": name, "time_s": np.round(t, 6), "speed_rpm": speed, "temp_C": temp,
            "oil": oil or "none", "roughness_T": T, cfg.kind: p}))
    return pd.concat(frames, ignore_index=True)


def weakest_strength(effect: str, config: SynthConfig | None = None,
                     seeds: tuple[int, ...] = (0, 1, 2), step: float = 2.0 ** -0.5,
                     max_steps: int = 20, **loop_options) -> dict:
    """Weakest strength at which the loop, not told which, still names ``effect``.

    Starting at :data:`DEFAULT_STRENGTH`, the strength is multiplied by ``step``
    until, on some seed, the loop does not accept exactly ``effect`` (shear
    thinning in the rig's oils marked polymer-thickened, where it is plausible). Returns
    the last strength found on every seed (``weakest_found``), the first one
    missed (``first_missed``) and each step's held-out cuts.
    """
    cfg = config or SynthConfig()
    get_effect(effect)
    if effect == "shear_thinning" and not cfg.fluids:  # plausible only in a thickened oil
        cfg = replace(cfg, fluids=polymer_thickened(cfg.oils))
    oils = fluid_table(cfg) if cfg.fluids else None
    s = DEFAULT_STRENGTH[effect]
    found = None
    steps = []
    for _ in range(max_steps):
        named, cuts = [], []
        for seed in seeds:
            est = LoopEstimator(case=cfg.case, oils=oils, **loop_options).fit(
                synthesize(replace(cfg, effect=effect, strength=s), seed))
            named.append([e.name for e in est.effects_])
            h = est.heldout_rmse_
            cuts.append(100.0 * (1.0 - h["after"] / h["before"]))
        ok = all(n == [effect] for n in named)
        steps.append({"strength": s, "found_on_all_seeds": ok, "named": named,
                      "heldout_cut_pct": cuts})
        if not ok:
            break
        found = s
        s *= step
    return {"effect": effect, "unit": EFFECTS[effect].strength_unit, "seeds": list(seeds),
            "default": DEFAULT_STRENGTH[effect], "weakest_found": found,
            "first_missed": s if steps and not steps[-1]["found_on_all_seeds"] else None,
            "steps": steps}
