"""An out-of-family rig: viscous-power data built from laws the estimator does not use.

The synthetic rig of :mod:`oilgap.studies.rigs.synth` is built from the estimator's
own model. This one is written apart from it, to test the measured-data loop
on data from outside its family (issue 9, "How to verify"). It imports no
oilgap physics (only :mod:`oilgap.model.errors` and :mod:`oilgap.model.units`);
its laws are in :mod:`oilgap.studies.rigs.outside_laws`:

* **Clearance loss**: Eq. 6 of Bilgen & Boulos *piecewise* (not a power law),
  by default bounded below by the exact Couette coefficient, times the groove
  factor T^gamma_true (0.5) in region 1.
* **Fluids**: ISO VG oils of oilgap's catalogue (Walther through 40 and 100
  degC, linear expansion), or Newtonian silicone oils (Andrade) written with
  per-row ``nu_cSt`` and ``density_kg_m3``; atmospheric pressure.
* **Baseline**: electronics, a constant-torque load, a gearbox loss
  ``k |tau_L w|^1.3`` (outside the loop's baseline basis), rotor inertia and a
  copper loss that grows with temperature; oil-free runs share it.
* **Thermal**: one lumped node heated by the losses, exact exponential step
  per sample with the heat held over the step.
* **Noise**: AR(1) on power (phi = 0.8), white on speed and temperature.
* **Effects**: each of the loop's library names by this rig's own law
  (:data:`EFFECT_LAWS`), at a strength in :data:`STRENGTH_UNIT`, several at once;
  thermal lag moves the oil temperature, sensor delay shifts the power record
  in time, shear thinning changes the viscosity in every Eq. 6 region.
* **Film heating**: the gap oil runs hotter than the node by c per watt of its
  loss (fixed point per sample), injected as the library's ``film_heating`` or
  through the older field ``film_heating_K_W`` (the two add).

Speed profiles: sine, trapezoid (accelerate, hold, decelerate, reverse) and
step. Output: a data frame in the loop's format (:func:`synthesize`), or steady
operating points without ``time_s`` (:func:`steady_points`). The noise-free
simulation is cached per configuration, so seeds cost only the noise.
:data:`TEST_STRENGTH`, :data:`NEWTONIAN` and the default :class:`OutsideConfig`
are the configurations of the acceptance tests (``tests/validation/
test_loop_outside_rig.py``) and of ``benchmarks/detect_outside.py``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.errors import InputError
from oilgap.model.units import m2_s_to_cst, m_to_mm, mm_to_m, rad_s_to_rpm, rpm_to_rad_s

from .outside_laws import (
    OPEN_GEOMETRY,
    PROFILES,
    SEED_GEOMETRY,
    SILICONE_OILS,
    VG_OILS,
    WHERE,
    RigBaseline,
    RigGeometry,
    SpeedProfile,
    ThermalNode,
    annulus_power,
    ar1_noise,
    carreau_ratio,
    enclosed_disc_power,
    fluid_state,
    lag_update,
    palmgren_churning_power,
    stribeck_seal_power,
    wendt_taylor_excess,
)

EFFECT_LAWS = {
    "end_face_disc": "k x both end faces as enclosed discs, Daily & Nece regime II (separate "
                     "laminar layers) C_M = 3.70 (s/r)^0.1 Re^-0.5; with end_face_regime "
                     "'I+II' the larger of that and regime I, 2 pi / ((s/r) Re); "
                     "P = 0.5 C_M rho |w|^3 (r_o^5 - r_i^5)",
    "bearing_ball_churning": "Palmgren M_0 = 1e-7 f0 (nu n)^(2/3) d_m^3 N mm (nu n >= 2000), "
                             "160e-7 f0 d_m^3 below; d_m = 2 R2 + delta2; P = M_0 |w|",
    "seal_coulomb_friction": "tau |w|, tau = tau_c (1 + 0.5 exp(-(w / 5 rad/s)^2)) "
                             "(Coulomb + Stribeck)",
    "oil_inertia": "rho I_V w dw/dt (stored kinetic energy, not heat)",
    "thermal_lag": "the gap oil follows the measured temperature through a first-order lag "
                   "tau (tau < 0: the sensor lags the oil), exact update per sample",
    "taylor_vortex_onset": "k P_i max(0, (Re_i/Re_c,i)^0.5 - 1) per region, "
                           "Re_c = 41.3 (R/delta)^0.5 (Wendt's Re^1.5 torque above onset)",
    "shear_thinning": "Carreau nu_eff = nu (1 + (lambda |w| R/delta)^2)^((n-1)/2), n = 0.6, "
                      "in every Eq. 6 region",
    "sensor_delay": "P_meas(t) = P(t - d): the power record shifted in time",
    "film_heating": "the gap oil is hotter than the node (or the lagged oil) by c times the "
                    "Eq. 6 loss of all regions, T_film = T + c P(T_film), fixed point per "
                    "sample",
}
"""The injectable effects (the loop's library names), each by this rig's own law."""

STRENGTH_UNIT = {"end_face_disc": "-", "bearing_ball_churning": "-",
                 "seal_coulomb_friction": "N m", "oil_inertia": "m^5", "thermal_lag": "s",
                 "taylor_vortex_onset": "-", "shear_thinning": "s", "sensor_delay": "s",
                 "film_heating": "K/W"}
"""Unit of each effect's strength: k, f0, tau_c, I_V, tau, k, lambda, d."""

TEST_STRENGTH = {
    "end_face_disc": 0.5, "bearing_ball_churning": 0.25, "seal_coulomb_friction": 0.025,
    "oil_inertia": 4.0e-7, "thermal_lag": 1.0, "taylor_vortex_onset": 2.0,
    "shear_thinning": 3.0e-4, "sensor_delay": 0.1, "film_heating": 0.005}
"""Strength of each effect in the acceptance tests (:data:`STRENGTH_UNIT`). On the default
configuration each changes the oil runs' noise-free reading by 4.5-5.7 W RMS (noise: 1 W,
AR(1)); shear thinning by 18 W, most of it a speed-dependent fall of every oil's loss
(lambda gamma_dot up to 2.4 in region 1) that a calibrated scale and gamma absorb, so
that what is left for the search is of the same few watts as the others."""


# --------------------------------------------------------------------------- configuration


@dataclass(frozen=True, kw_only=True)
class OutsideConfig:
    """What the outside rig simulates (SI unless the name says otherwise).

    The default is the acceptance rig: the seed joint, ISO VG 22, 68, 220, 680
    (thin to heavy), T = 4 and 2, the trapezoid profile (3000 rpm, 20 s period,
    3 s ramps), 300 samples every 0.2 s, electrical power with oil-free runs.
    ``effects`` maps library names to strengths in :data:`STRENGTH_UNIT` (a dict
    is accepted and stored as sorted pairs). ``gaps_mm``: one oil run per
    region-1 gap, with a ``gap_mm`` column (empty: the geometry's gap, no column).
    ``film_heating_K_W``: the gap oil is hotter than the node by this many kelvin
    per watt of its viscous loss (0 = off).
    """

    geometry: RigGeometry = SEED_GEOMETRY
    oils: tuple[str, ...] = ("VG22", "VG68", "VG220", "VG680")
    roughness: tuple[float, ...] = (4.0, 2.0)
    gaps_mm: tuple[float, ...] = ()
    profile: SpeedProfile = field(default_factory=SpeedProfile)
    n_samples: int = 300
    sample_interval_s: float = 0.2
    kind: str = "power_W"
    gamma_true: float = 0.5
    couette_floor: bool = True
    end_face_regime: str = "II"
    baseline: RigBaseline = field(default_factory=RigBaseline)
    thermal: ThermalNode = field(default_factory=ThermalNode)
    effects: tuple = ()
    film_heating_K_W: float = 0.0
    noise_power_W: float = 1.0
    noise_phi: float = 0.8
    noise_speed_rpm: float = 2.0
    noise_temp_K: float = 0.05

    def __post_init__(self):
        if isinstance(self.effects, dict):
            object.__setattr__(self, "effects", tuple(sorted(self.effects.items())))
        self.check()

    def check(self) -> None:
        """Raise InputError for a configuration the rig cannot simulate."""
        fluids = [*VG_OILS, *SILICONE_OILS]
        if not self.oils or any(o not in fluids for o in self.oils):
            raise InputError("oils", list(self.oils), f"names of {', '.join(fluids)}", WHERE)
        choices = (("kind", self.kind, ("power_W", "viscous_power_W")),
                   ("profile", self.profile.kind, PROFILES),
                   ("end_face_regime", self.end_face_regime, ("II", "I+II")))
        for name, v, allowed in choices:
            if v not in allowed:
                raise InputError(name, v, f"allowed: {', '.join(allowed)}", WHERE)
        if not (isinstance(self.n_samples, int) and self.n_samples >= 20):
            raise InputError("n_samples", self.n_samples, "an integer >= 20", WHERE)
        if not 0.0 < self.sample_interval_s <= 10.0:
            raise InputError("sample_interval_s", self.sample_interval_s, "in (0, 10] s", WHERE)
        if not 0.0 <= self.noise_phi < 1.0:
            raise InputError("noise_phi", self.noise_phi, "in [0, 1)", WHERE)
        if not self.roughness or any(not r >= 1.0 for r in self.roughness):
            raise InputError("roughness", list(self.roughness), "values >= 1", WHERE)
        if any(not g > 0 for g in self.gaps_mm):
            raise InputError("gaps_mm", list(self.gaps_mm), "positive gaps", WHERE)
        for name, s in self.effects:
            if name not in EFFECT_LAWS:
                raise InputError("effect", name, f"allowed: {', '.join(EFFECT_LAWS)}", WHERE)
            if not math.isfinite(s):
                raise InputError(f"strength of {name}", s, "a finite number", WHERE)
            if name == "bearing_ball_churning" and self.geometry.region2 is None:
                raise InputError("effect", name, "needs a bearing region (region 2)", WHERE)

    def strength(self, name: str) -> float:
        """Strength of an injected effect (0 if not injected) [STRENGTH_UNIT]."""
        return dict(self.effects).get(name, 0.0)


def inject(config: OutsideConfig, **strengths: float) -> OutsideConfig:
    """The configuration with these effects (name=strength) injected as well."""
    return replace(config, effects={**dict(config.effects), **strengths})


NEWTONIAN = OutsideConfig(geometry=OPEN_GEOMETRY, oils=("PDMS10", "PDMS50", "PDMS100"),
                          roughness=(1.0,), kind="viscous_power_W")
"""A Newtonian silicone oil of three grades in smooth clearances (T = 1) of the rig without a
bearing region, torque measured directly: nothing to find."""


# --------------------------------------------------------------------------- physics per sample


@dataclass(frozen=True)
class _Runs:
    names: tuple[str, ...]
    oils: tuple[str | None, ...]
    roughness: np.ndarray
    gap_m: np.ndarray
    has_oil: np.ndarray


def _runs(cfg: OutsideConfig) -> _Runs:
    names, oils, rough, gaps = [], [], [], []
    g1 = cfg.geometry.region1.gap_m
    for T in cfg.roughness:
        if cfg.kind == "power_W":
            names.append(f"oilfree-T{T:g}")
            oils.append(None), rough.append(T), gaps.append(g1)
        for o in cfg.oils:
            for g in cfg.gaps_mm or (None,):
                names.append(f"{o}-T{T:g}" + ("" if g is None else f"-g{g:g}"))
                oils.append(o), rough.append(T), gaps.append(g1 if g is None else mm_to_m(g))
    return _Runs(tuple(names), tuple(oils), np.array(rough), np.array(gaps),
                 np.array([o is not None for o in oils]))


def _per_run(values, ndim: int):
    """Per-run values shaped to broadcast against arrays with runs on the first axis."""
    return np.asarray(values, dtype=float).reshape((-1,) + (1,) * (ndim - 1))


def _fluid(runs: _Runs, temp_C):
    """nu [m^2/s] and rho [kg/m^3] per run (first axis) at temp_C (oil-free: placeholders)."""
    temp_C = np.asarray(temp_C, dtype=float)
    nu, rho = np.ones_like(temp_C), np.zeros_like(temp_C)
    for i, o in enumerate(runs.oils):
        if o is not None:
            nu[i], rho[i] = fluid_state(o, temp_C[i])
    return nu, rho


def _regions(cfg: OutsideConfig, runs: _Runs, omega, nu, rho):
    """[(power [W], Re [-], R [m], delta [m])] of each region; nu thinned if injected."""
    geo, lam, nd = cfg.geometry, cfg.strength("shear_thinning"), np.ndim(nu)
    specs = [(geo.region1, _per_run(runs.gap_m, nd), _per_run(runs.roughness, nd))]
    if geo.region2 is not None:
        specs.append((geo.region2, geo.region2.gap_m, 1.0))
    out = []
    for region, gap, T in specs:
        R = region.radius_m
        nu_eff = nu * carreau_ratio(np.abs(omega) * R / gap, lam) if lam else nu
        p, re = annulus_power(omega, nu_eff, rho, R, gap, region.length_m,
                              roughness=(T, cfg.gamma_true), couette_floor=cfg.couette_floor)
        out.append((p, re, R, gap))
    return out


def _effect_powers(cfg: OutsideConfig, omega, accel, nu, rho, regions) -> dict:
    """Power [W] of each injected effect that adds a term (inertia: stored, not heat)."""
    s, geo, out = cfg.strength, cfg.geometry, {}
    if s("end_face_disc"):
        out["end_face_disc"] = s("end_face_disc") * enclosed_disc_power(
            omega, nu, rho, geo.region1.radius_m, geo.shaft_bore_m, geo.disc_axial_gap_m,
            merged=cfg.end_face_regime == "I+II")
    if s("bearing_ball_churning"):
        out["bearing_ball_churning"] = palmgren_churning_power(
            omega, nu, geo.bearing_pitch_m, s("bearing_ball_churning"))
    if s("seal_coulomb_friction"):
        out["seal_coulomb_friction"] = stribeck_seal_power(omega, s("seal_coulomb_friction"))
    if s("oil_inertia"):
        out["oil_inertia"] = rho * s("oil_inertia") * omega * accel
    if s("taylor_vortex_onset"):
        out["taylor_vortex_onset"] = s("taylor_vortex_onset") * sum(
            p * wendt_taylor_excess(re, gap, R) for p, re, R, gap in regions)
    return out


def _powers(cfg: OutsideConfig, runs: _Runs, omega, accel, node_C, oil_C):
    """(viscous, effects, sensor reading, heat) [W], arrays shaped like node_C."""
    shape = np.shape(node_C)
    has_oil = _per_run(runs.has_oil, len(shape))
    omega = np.broadcast_to(omega, shape)
    accel = np.broadcast_to(accel, shape)
    film, c = oil_C, cfg.film_heating_K_W + cfg.strength("film_heating")
    for _ in range(8 if c else 1):  # fixed point of the film temperature (c |dP/dT| < 1)
        nu, rho = _fluid(runs, film)
        regions = _regions(cfg, runs, omega, nu, rho)
        visc = sum(r[0] for r in regions) * has_oil
        film = oil_C + c * visc
    eff = _effect_powers(cfg, omega, accel, nu, rho, regions)
    stored = eff.pop("oil_inertia", 0.0) * has_oil
    dissipated = sum(eff.values()) * has_oil if eff else np.zeros(shape)
    oil_part = visc + dissipated + stored
    base, base_heat = cfg.baseline.power(omega, accel, node_C, oil_part)
    reading = oil_part + base if cfg.kind == "power_W" else oil_part
    return visc, dissipated + stored, reading, base_heat + visc + dissipated


# --------------------------------------------------------------------------- simulation


def _integrate(cfg: OutsideConfig, runs: _Runs, t: np.ndarray, omega, accel):
    """Measured, oil and node temperatures [degC] of each run at the sample times."""
    n_r, n = len(runs.names), len(t)
    tau = cfg.strength("thermal_lag")
    node, lagged = np.empty((n_r, n)), np.empty((n_r, n))
    T = np.full(n_r, cfg.thermal.ambient_C)
    y = T.copy()
    for k in range(n):
        node[:, k], lagged[:, k] = T, y
        if k == n - 1:
            break
        heat = _powers(cfg, runs, omega[k], accel[k], T, y if tau > 0 else T)[3]
        h = t[k + 1] - t[k]
        T_new = cfg.thermal.step(T, heat, h)
        y = lag_update(y, T, T_new, h, tau) if tau else T_new
        T = T_new
    meas, oil = (node, lagged) if tau > 0 else (lagged, node)
    return meas, oil, node


_CACHE: dict = {}


def simulate(config: OutsideConfig | None = None) -> dict:
    """Noise-free simulation of every run (cached per configuration).

    Returns a dict: ``config``, ``runs`` (list of (name, oil or None, T, gap [m])),
    ``time_s``, ``omega`` [rad/s], ``temp_meas_C``, ``temp_oil_C`` [degC],
    ``viscous_W`` (Eq. 6 truth), ``effect_W`` (terms the effects add),
    ``measured_W`` (the sensor's reading, noise-free, after any delay); arrays
    (run, sample).
    """
    cfg = config or OutsideConfig()
    if cfg in _CACHE:
        return _CACHE[cfg]
    runs = _runs(cfg)
    t = np.arange(cfg.n_samples) * cfg.sample_interval_s
    omega, accel = cfg.profile(t)
    meas, oil, node = _integrate(cfg, runs, t, omega, accel)
    visc, eff, reading, _ = _powers(cfg, runs, omega[None, :], accel[None, :], node, oil)
    d = cfg.strength("sensor_delay")
    if d:  # the reading at t is the power at t - d (at rest and ambient before t = 0)
        td = t - d
        w_d, a_d = cfg.profile(td)
        amb = cfg.thermal.ambient_C
        node_d = np.array([np.interp(td, t, r, left=amb) for r in node])
        oil_d = np.array([np.interp(td, t, r, left=amb) for r in oil])
        reading = _powers(cfg, runs, w_d[None, :], a_d[None, :], node_d, oil_d)[2]
    out = {"config": cfg, "time_s": t, "omega": np.broadcast_to(omega, node.shape).copy(),
           "runs": [(runs.names[i], runs.oils[i], float(runs.roughness[i]),
                     float(runs.gap_m[i])) for i in range(len(runs.names))],
           "temp_meas_C": meas, "temp_oil_C": oil, "viscous_W": visc, "effect_W": eff,
           "measured_W": reading}
    if len(_CACHE) > 64:
        _CACHE.clear()
    _CACHE[cfg] = out
    return out


def effect_size_W(config: OutsideConfig) -> float:
    """RMS change [W] of the oil runs' noise-free reading that the injected effects make."""
    with_fx = simulate(config)
    clean = simulate(replace(config, effects=()))
    oil = np.array([r[1] is not None for r in with_fx["runs"]])
    d = with_fx["measured_W"][oil] - clean["measured_W"][oil]
    return float(np.sqrt(np.mean(d * d)))


# --------------------------------------------------------------------------- output


def _with_properties(cfg: OutsideConfig, f: pd.DataFrame) -> pd.DataFrame:
    """Per-row nu_cSt and density_kg_m3 of silicone runs (at the measured temperature)."""
    if not any(o in SILICONE_OILS for o in cfg.oils):
        return f
    oil = f["oil"].iloc[0]
    nu, rho = fluid_state(oil, f["temp_C"].to_numpy()) if oil in SILICONE_OILS else \
        (np.nan, np.nan)
    power = f.pop(cfg.kind)
    return f.assign(nu_cSt=m2_s_to_cst(np.asarray(nu)), density_kg_m3=rho,
                    **{cfg.kind: power})


def synthesize(config: OutsideConfig | None = None, seed: int = 0) -> pd.DataFrame:
    """Rig data in the loop's format, one row per sample, with noise drawn from ``seed``.

    Columns ``run, time_s, speed_rpm, temp_C, oil, roughness_T``, ``gap_mm`` with
    several gaps, ``nu_cSt, density_kg_m3`` with silicone oils, and ``power_W`` or
    ``viscous_power_W``; no trace of the effects.
    """
    tr = simulate(config)
    cfg = tr["config"]
    rng = np.random.default_rng(seed)
    t, n = tr["time_s"], len(tr["time_s"])
    frames = []
    for i, (name, oil, T, gap) in enumerate(tr["runs"]):
        f = {"run": name, "time_s": np.round(t, 9),
             "speed_rpm": rad_s_to_rpm(tr["omega"][i]) + rng.normal(0, cfg.noise_speed_rpm, n),
             "temp_C": tr["temp_meas_C"][i] + rng.normal(0, cfg.noise_temp_K, n),
             "oil": oil or "none", "roughness_T": T}
        if cfg.gaps_mm:
            f["gap_mm"] = m_to_mm(gap) if oil else np.nan
        f[cfg.kind] = tr["measured_W"][i] + ar1_noise(rng, n, cfg.noise_power_W, cfg.noise_phi)
        frames.append(_with_properties(cfg, pd.DataFrame(f)))
    return pd.concat(frames, ignore_index=True)


STEADY_SPEEDS_RPM = (-3000.0, -2000.0, -1000.0, -500.0, 500.0, 1000.0, 2000.0, 3000.0)
STEADY_TEMPS_C = (25.0, 40.0, 60.0)


def steady_points(config: OutsideConfig | None = None, seed: int = 0,
                  speeds_rpm=STEADY_SPEEDS_RPM, temps_C=STEADY_TEMPS_C) -> pd.DataFrame:
    """Steady operating points (no ``time_s``): each run at every speed and temperature.

    dw/dt = dT/dt = 0 and the oil at the measured temperature, so oil inertia,
    thermal lag and sensor delay leave no trace. White noise of ``noise_power_W``.
    """
    cfg = config or OutsideConfig()
    runs = _runs(cfg)
    w, temp = np.meshgrid(rpm_to_rad_s(np.asarray(speeds_rpm, float)),
                          np.asarray(temps_C, float))
    w, temp = w.ravel(), temp.ravel()
    node = np.broadcast_to(temp, (len(runs.names), len(temp))).copy()
    reading = _powers(cfg, runs, w[None, :], 0.0, node, node)[2]
    rng = np.random.default_rng(seed)
    frames = []
    for i, name in enumerate(runs.names):
        f = {"run": name, "speed_rpm": rad_s_to_rpm(w), "temp_C": temp,
             "oil": runs.oils[i] or "none", "roughness_T": runs.roughness[i]}
        if cfg.gaps_mm:
            f["gap_mm"] = m_to_mm(runs.gap_m[i]) if runs.has_oil[i] else np.nan
        f[cfg.kind] = reading[i] + rng.normal(0.0, cfg.noise_power_W, len(w))
        frames.append(_with_properties(cfg, pd.DataFrame(f)))
    return pd.concat(frames, ignore_index=True)


def write_oils_csv(config: OutsideConfig, path: str | Path) -> Path:
    """The rig's ISO VG oils as an oils table for the loop (``--oils``).

    ``oil,nu40_cSt,nu100_cSt,density_kg_m3,polymer_thickened``: the oils are
    VI-improved (polymer-thickened) when shear thinning is injected, straight
    mineral oils otherwise, which is what the rig's owner would know of them.
    """
    flag = "true" if config.strength("shear_thinning") else "false"
    rows = ["oil,nu40_cSt,nu100_cSt,density_kg_m3,polymer_thickened"]
    rows += [f"{n},{a:g},{b:g},{r:g},{flag}" for n, (a, b, r) in VG_OILS.items()]
    path = Path(path)
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return path


