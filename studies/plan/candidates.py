"""Candidate runs of a rig campaign, simulated by the synthetic rig, and their information.

Each candidate (oil, rotor roughness T, bath temperature, speed profile, pressure) is run
through the rig simulator of :mod:`oilgap.studies.rigs.synth` (speed profile, the lumped
thermal model heating the oil), read through the loop's data contract
(:func:`~oilgap.model.measured.validation.validate`,
:func:`~oilgap.model.measured.data.oil_samples`) into the loop's
:class:`~oilgap.optim.calibration.forward.ForwardModel`, and its Fisher information taken
from that model (:mod:`oilgap.optim.planning.fisher`). The same simulation, with noise
and chosen effects, rehearses a plan (:func:`plan_data`).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.effects import EFFECTS
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.measured.data import oil_samples
from oilgap.model.measured.validation import validate
from oilgap.model.oils import builtin_fluids
from oilgap.model.taylor_couette import couette_reynolds, taylor_number
from oilgap.model.units import rad_s_to_rpm, rpm_to_rad_s
from oilgap.optim.calibration.forward import ForwardModel
from oilgap.optim.calibration.spec import START_VALUES, BaseSpec, decide_spec
from oilgap.optim.planning.fisher import Parameters, base_jacobian, effect_columns, run_information
from oilgap.optim.planning.floor import below_floor, floor_gaps
from oilgap.studies.rigs.synth import (
    DEFAULT_STRENGTH,
    SynthConfig,
    seed_truth_law,
    simulate_truth,
    synthesize,
)

from .settings import PlanSettings

RUN_COLUMNS = ("run", "order", "oil", "roughness_T", "bath_C", "profile", "peak_speed_rpm",
               "frequency_hz", "duration_s", "sample_interval_s", "pressure_MPa")
"""Columns of plan.csv and naive.csv: one row per run, in the order the rig runs them."""


@dataclass(frozen=True)
class Candidate:
    """One candidate run: what the rig is set to."""

    oil: str
    roughness_T: float
    bath_C: float
    profile: str
    pressure_MPa: float = 0.0

    @property
    def label(self) -> str:
        """Readable name, e.g. ``VG320-T4-25C-sine``."""
        p = f"-{self.pressure_MPa:g}MPa" if self.pressure_MPa else ""
        return f"{self.oil}-T{self.roughness_T:g}-{self.bath_C:g}C-{self.profile}{p}"


def candidate_runs(settings: PlanSettings) -> list[Candidate]:
    """Every combination of the settings' factors (the full factorial).

    Ordered rotor, oil, pressure, temperature, profile (the hard-to-change factors first).
    """
    return [Candidate(o, float(T), float(b), pr, float(p)) for T, o, p, b, pr in
            itertools.product(settings.roughness, settings.oils, settings.pressures_MPa,
                              settings.bath_C, settings.profiles)]


def _config(settings: PlanSettings, case: DesignCase, oils, roughness, bath_C, profile,
            effects=None, noise=True) -> SynthConfig:
    kw = {} if noise else {"noise_power_W": 0.0, "noise_speed_rpm": 0.0, "noise_temp_K": 0.0}
    truth = None if settings.scale == 1.0 else replace(seed_truth_law(case), scale=settings.scale)
    return SynthConfig(case=case, oils=tuple(oils), roughness=tuple(roughness), truth=truth,
                       n_samples=settings.n_samples, sample_interval_s=settings.sample_interval_s,
                       peak_speed_rpm=settings.peak_speed_rpm,
                       frequency_hz=settings.frequency_hz, ambient_C=bath_C, profile=profile,
                       kind="viscous_power_W", effects=effects or None,
                       **(kw or {"noise_power_W": settings.noise_W,
                                 "noise_speed_rpm": settings.noise_speed_rpm,
                                 "noise_temp_K": settings.noise_temp_K}))


def plan_data(settings: PlanSettings, runs: list[Candidate], case: DesignCase | None = None,
              effects: dict | None = None, seed: int | None = None) -> pd.DataFrame:
    """The runs simulated by the synthetic rig, in the loop's data format.

    Parameters
    ----------
    settings : PlanSettings
        Duration, sample step, peak speed and frequency of every run.
    runs : list of Candidate
        The runs, in order (a candidate may repeat).
    case : DesignCase, optional
        The rig (default: the settings' or the seed joint).
    effects : dict, optional
        Effect -> strength injected (None strength: its test strength).
    seed : int, optional
        Noise seed; None: noise-free (for the information).

    Returns
    -------
    pandas.DataFrame
        ``run, time_s, speed_rpm, temp_C, oil, roughness_T, viscous_power_W``; runs named
        ``P01-<label>``...
    """
    case = case or settings.case or seed_case()
    if any(r.pressure_MPa for r in runs) and seed is not None:
        raise InputError("pressure_MPa", max(r.pressure_MPa for r in runs), "0: the synthetic "
                         "rig stands at atmospheric pressure (a tank)", "synth --plan")
    groups: dict[tuple, list[int]] = {}  # one simulation per (bath, profile)
    for i, r in enumerate(runs):
        groups.setdefault((r.bath_C, r.profile), []).append(i)
    frames: dict[int, pd.DataFrame] = {}
    for (bath, profile), idx in groups.items():
        cfg = _config(settings, case, dict.fromkeys(runs[i].oil for i in idx),
                      dict.fromkeys(runs[i].roughness_T for i in idx), bath, profile,
                      effects, noise=seed is not None)
        seen: dict[Candidate, int] = {}
        for i in idx:
            r = runs[i]
            rep = seen[r] = seen.get(r, -1) + 1
            frames[i] = _run_frame(cfg, r, None if seed is None else int(seed) * 1000 + rep)
            frames[i].insert(0, "run", f"P{i + 1:02d}-{r.label}")
    out = pd.concat([frames[i] for i in range(len(runs))], ignore_index=True)
    return out[["run", "time_s", "speed_rpm", "temp_C", "oil", "roughness_T",
                "viscous_power_W"]]


def _run_frame(cfg: SynthConfig, r: Candidate, seed: int | None) -> pd.DataFrame:
    """One run of a simulated group: noise-free from the truth, else the rig's noisy
    record (``seed``: a distinct draw for each repeat of a setting)."""
    name = f"{r.oil}-T{r.roughness_T:g}"
    if seed is None:
        tr = simulate_truth(cfg)
        i = [n for n, _, _ in tr["runs"]].index(name)
        df = pd.DataFrame({"time_s": np.round(tr["time_s"], 6),
                           "speed_rpm": rad_s_to_rpm(tr["omega"][i]),
                           "temp_C": tr["temp_meas_C"][i], "viscous_power_W": tr["measured_W"][i]})
    else:
        df = synthesize(cfg, seed=seed)
        df = df[df["run"] == name].drop(columns=["run"]).reset_index(drop=True)
    df["oil"] = r.oil
    df["roughness_T"] = r.roughness_T
    return df[["time_s", "speed_rpm", "temp_C", "oil", "roughness_T", "viscous_power_W"]]


@dataclass
class CandidateSet:
    """The candidates and the information of one run of each.

    Attributes
    ----------
    runs : list of Candidate
    info : array, shape (m, p, p)
        Information of one run of each candidate [unit^-2] (power noise alone).
    meat : array, shape (m, p, p)
        The same with each sample's full noise variance (speed and temperature readings
        included): the middle of the least-squares sandwich [unit^-2].
    params : Parameters
        The matrix's parameters (base, effects, pressure-viscosity).
    spec : BaseSpec
        The base law's free parameters (decided on all candidates).
    x0 : array
        Expansion point (the case's law) in the solver's unknowns [-].
    notes : dict
        Parameter -> why its column is zero.
    ref : array
        Reference size of each effect coefficient (its test strength) [unit].
    re_peak, ta_peak, temp_mean : arrays
        Per candidate: largest region-1 Couette Reynolds and Taylor numbers [-] and mean
        oil temperature [degC] of its simulated run.
    floor_gap : array, shape (m,)
        Per candidate: distance in ln scale from the expansion point down to the Couette
        floor's first kink (:func:`~oilgap.optim.planning.floor.floor_gaps`; inf: none).
    floor_info, floor_meat : arrays, shape (m, q, q)
        The base block of ``info`` and ``meat`` just below that kink, where the floored
        rows carry no information on the scale (equal to ``info``'s where no kink).
    """

    runs: list[Candidate]
    info: np.ndarray
    meat: np.ndarray
    params: Parameters
    spec: BaseSpec
    x0: np.ndarray
    notes: dict
    ref: np.ndarray
    re_peak: np.ndarray
    ta_peak: np.ndarray
    temp_mean: np.ndarray
    floor_gap: np.ndarray
    floor_info: np.ndarray
    floor_meat: np.ndarray


def candidate_information(settings: PlanSettings) -> CandidateSet:
    """Simulate every candidate once (noise-free) and take its Fisher information.

    Parameters
    ----------
    settings : PlanSettings

    Returns
    -------
    CandidateSet
    """
    case = settings.case or seed_case()
    runs = candidate_runs(settings)
    pressure = any(p > 0 for p in settings.pressures_MPa)
    blocks, spec, x0, why = [], None, None, {}
    for p in sorted(set(settings.pressures_MPa)):
        idx = [i for i, r in enumerate(runs) if r.pressure_MPa == p]
        df = plan_data(settings, [runs[i] for i in idx], case)
        data = validate(df, builtin_fluids(), "candidate runs", "fit")
        s = oil_samples(data, case.region1.gap, pressure_gauge_Pa=p * 1e6)
        model = ForwardModel(s, case, data.oils)
        if spec is None:
            spec, _ = decide_spec(model.samples, model.geometry, case, settings.base)
            x0 = spec.start({**START_VALUES, "scale": settings.scale,
                             "gamma": case.friction.gamma})
        jb, dP_dw = base_jacobian(model, spec, x0,
                                  np.full(s.n, p * 1e6) if pressure else None)
        je, why = effect_columns(model, spec.law(x0), settings.effects)
        jac = np.column_stack([jb[:, :len(spec.free)], je, jb[:, len(spec.free):]])
        order = np.argsort([int(n.split("-")[0][1:]) for n in s.run_names])
        A, B = run_information(jac, s.run_code, settings.noise_W,
                               sample_variance(settings, model, spec.law(x0), dP_dw))
        blocks.append((idx, A[order], B[order], _run_stats(model)[:, order],
                       *_floor_block(settings, model, spec, x0, (A, B), order)))
    params = Parameters(spec.free, settings.effects, pressure)
    info = np.zeros((len(runs), len(params.names), len(params.names)))
    meat = np.zeros_like(info)
    stats = np.zeros((3, len(runs)))
    q = len(spec.free)
    gap, finfo = np.zeros(len(runs)), np.zeros((len(runs), q, q))
    fmeat = np.zeros_like(finfo)
    for idx, A, B, st, g, fA, fB in blocks:
        info[idx], meat[idx] = A, B
        stats[:, idx] = st
        gap[idx], finfo[idx], fmeat[idx] = g, fA, fB
    ref = np.array([EFFECTS[e].coefficient_from_strength(DEFAULT_STRENGTH[e])
                    for e in settings.effects])
    return CandidateSet(runs=runs, info=info, meat=meat, params=params, spec=spec, x0=x0,
                        notes=why, ref=ref, re_peak=stats[0], ta_peak=stats[1],
                        temp_mean=stats[2], floor_gap=gap, floor_info=finfo, floor_meat=fmeat)


def _floor_block(settings: PlanSettings, model: ForwardModel, spec: BaseSpec, x0: np.ndarray,
                 at_x0: tuple, order: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per run (in candidate order): the distance down to the Couette floor's first kink
    [ln scale] and the base information and meat just below it, by the same AD
    (:mod:`oilgap.optim.planning.floor`); without a kink, those at ``x0`` (``at_x0``)."""
    s = model.samples
    q = len(spec.free)
    gaps = floor_gaps(model, spec, x0)
    if not np.isfinite(gaps).any():
        A, B = (m[:, :q, :q] for m in at_x0)
    else:
        jb, dP_dw = base_jacobian(model, spec, below_floor(x0, spec, gaps, s.run_code))
        A, B = run_information(jb[:, :q], s.run_code, settings.noise_W,
                               sample_variance(settings, model, spec.law(x0), dP_dw))
    return gaps[order], A[order], B[order]


def sample_variance(settings: PlanSettings, model: ForwardModel, law, dP_dw: np.ndarray
                    ) -> np.ndarray:
    """Noise variance of each sample's power residual [W^2]: the power reading's, plus
    the speed and temperature readings' carried through the model,
    ``(dP/domega sigma_omega)^2 + (dP/dT sigma_T)^2`` (the model is evaluated at the
    read speed and temperature)."""
    dP_dT = np.nan_to_num(np.asarray(model.context(law).dpower_dtemp_W_K, float))
    sw = rpm_to_rad_s(settings.noise_speed_rpm)
    return settings.noise_W ** 2 + (dP_dw * sw) ** 2 + (dP_dT * settings.noise_temp_K) ** 2


def _run_stats(model: ForwardModel) -> np.ndarray:
    """Per run: peak region-1 Re and Ta [-], mean oil temperature [degC] (Eq. 4 [1])."""
    s = model.samples
    r1 = model.geometry.regions[0]
    re = couette_reynolds(np.abs(s.omega), r1.radius_m, s.gap1_m, s.nu_m2_s)
    ta = taylor_number(re, s.gap1_m, r1.radius_m)
    return np.array([[re[idx].max() for idx in model.runs], [ta[idx].max() for idx in model.runs],
                     [s.temp_C[idx].mean() for idx in model.runs]])


def plan_table(settings: PlanSettings, runs: list[Candidate]) -> pd.DataFrame:
    """plan.csv / naive.csv: one row per run in the given order (:data:`RUN_COLUMNS`)."""
    rows = [{"run": f"P{i + 1:02d}", "order": i + 1, "oil": r.oil,
             "roughness_T": r.roughness_T, "bath_C": r.bath_C, "profile": r.profile,
             "peak_speed_rpm": settings.peak_speed_rpm, "frequency_hz": settings.frequency_hz,
             "duration_s": settings.duration_s, "sample_interval_s": settings.sample_interval_s,
             "pressure_MPa": r.pressure_MPa} for i, r in enumerate(runs)]
    return pd.DataFrame(rows, columns=list(RUN_COLUMNS))


def runs_from_table(df: pd.DataFrame, source: str = "plan") -> tuple[PlanSettings, list]:
    """The settings and runs of a plan.csv (one duration, step, speed and frequency).

    Raises
    ------
    InputError
        A missing column, or runs of different durations, steps, speeds or frequencies.
    """
    missing = [c for c in RUN_COLUMNS if c not in df.columns]
    if missing:
        raise InputError(source, list(df.columns), f"missing columns {missing}; a plan.csv "
                         f"has {list(RUN_COLUMNS)}")
    common = {}
    for c in ("peak_speed_rpm", "frequency_hz", "duration_s", "sample_interval_s"):
        vals = pd.to_numeric(df[c], errors="coerce").unique()
        if len(vals) != 1 or not np.isfinite(vals[0]):
            raise InputError(f"{source}: {c}", list(vals), "one number for every run")
        common[c] = float(vals[0])
    for c in ("order", "roughness_T", "bath_C", "pressure_MPa"):
        vals = pd.to_numeric(df[c], errors="coerce")
        bad = np.nonzero(~np.isfinite(vals.to_numpy(dtype=float)))[0]
        if len(bad):
            raise InputError(f"{source}: {c} (row {bad[0] + 1})", df[c].iloc[bad[0]],
                             "a finite number")
        df = df.assign(**{c: vals})
    df = df.sort_values("order", kind="stable")
    runs = [Candidate(str(r.oil), float(r.roughness_T), float(r.bath_C), str(r.profile),
                      float(r.pressure_MPa)) for r in df.itertuples()]
    st = PlanSettings(oils=tuple(dict.fromkeys(r.oil for r in runs)),
                      bath_C=tuple(dict.fromkeys(r.bath_C for r in runs)),
                      roughness=tuple(dict.fromkeys(r.roughness_T for r in runs)),
                      profiles=tuple(dict.fromkeys(r.profile for r in runs)),
                      pressures_MPa=tuple(dict.fromkeys(r.pressure_MPa for r in runs)),
                      runs=max(2, len(runs)), **common)
    return st, runs
