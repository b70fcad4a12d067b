"""What a rig campaign may contain and what it must identify: :class:`PlanSettings`.

Units at the edges: temperatures in degC, speeds in rpm, pressures in MPa, durations in
s, costs in hours of rig time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from oilgap.model.case import DesignCase
from oilgap.model.effects import EFFECTS
from oilgap.model.errors import InputError
from oilgap.model.oils import get_oil
from oilgap.optim.planning.design import CRITERIA
from oilgap.studies.rigs.profiles import PROFILES
from oilgap.studies.rigs.synth import SYNTH_OILS

PLAN_EFFECTS = tuple(n for n in EFFECTS if n != "bearing_ball_drag")
"""Effects planned for by default: the library's, less the ball drag (it needs a case with
a [bearing]; name it to plan for it)."""

WHERE = "plan"


@dataclass(frozen=True, kw_only=True)
class PlanSettings:
    """The candidate runs, the targets, the noise and the budget of a rig campaign.

    Parameters
    ----------
    case : DesignCase, optional
        The rig (None: the seed joint).
    oils : tuple of str
        Oils in the oils table that may be poured.
    bath_C : tuple of float
        Bath (ambient) temperatures the rig can hold [degC].
    roughness : tuple of float
        Rotor variants by their roughness T [-] (>= 1).
    profiles : tuple of str
        Speed profiles (``sine``, ``trapezoid``, ``steps``).
    peak_speed_rpm : float
        Peak speed of every profile [rpm].
    frequency_hz : float
        Repetition frequency of the profile [Hz].
    duration_s, sample_interval_s : float
        Run length and sample step [s].
    pressures_MPa : tuple of float
        Oil gauge pressures the rig's vessel can hold [MPa] ((0,): no vessel).
    effects : tuple of str
        Library effects the plan must be able to detect.
    base : {"eq6", "power-law"}
        The base law the loop will fit.
    scale : float
        The scale the rig is expected to show [-]: the plan's expansion point and the
        synthetic rig's truth when the plan is rehearsed (default 1: exact Eq. 6, whose
        laminar annulus then sits 0.09 % above the Couette floor; a real rig's loss is
        usually above that, from eccentricity and end flows, docs/planning.md).
    noise_W : float
        Sd of the power noise per sample [W].
    noise_speed_rpm, noise_temp_K : float
        Sd of the speed [rpm] and temperature [K] readings per sample (the model is
        evaluated at the read values: their noise adds to the power residual).
    criterion : {"D", "A", "E", "T"}
        Design criterion (T: the effects' detection, the base law as nuisance).
    targets : {"base", "all"}
        What the D, A or E criterion is taken over: the base law's free parameters (what
        the loop fits; default) or those and every effect coefficient the candidates can
        separate from them.
    runs : int, optional
        Number of runs (the budget as a count).
    budget_h : float, optional
        Rig time available [h] (the budget as costs; with ``runs`` None).
    run_h, oil_change_h, temp_change_h, rotor_change_h : float
        Rig time of one run (beyond its duration), one oil change, one temperature
        change and one rotor change [h].
    """

    case: DesignCase | None = None
    oils: tuple[str, ...] = SYNTH_OILS
    bath_C: tuple[float, ...] = (25.0, 40.0)
    roughness: tuple[float, ...] = (4.0, 2.0)
    profiles: tuple[str, ...] = ("sine", "steps")
    peak_speed_rpm: float = 3000.0
    frequency_hz: float = 0.05
    duration_s: float = 300.0
    sample_interval_s: float = 0.2
    pressures_MPa: tuple[float, ...] = (0.0,)
    effects: tuple[str, ...] = PLAN_EFFECTS
    base: str = "eq6"
    scale: float = 1.0
    noise_W: float = 1.0
    noise_speed_rpm: float = 2.0
    noise_temp_K: float = 0.05
    criterion: str = "D"
    targets: str = "base"
    runs: int | None = 8
    budget_h: float | None = None
    run_h: float = 0.25
    oil_change_h: float = 2.0
    temp_change_h: float = 1.0
    rotor_change_h: float = 4.0

    def __post_init__(self):
        for name in ("oils", "bath_C", "roughness", "profiles", "pressures_MPa", "effects"):
            v = getattr(self, name)
            if isinstance(v, str) or not hasattr(v, "__len__"):
                raise InputError(name, v, "a list of values", WHERE)
            object.__setattr__(self, name, tuple(v))
        for name in ("oils", "bath_C", "roughness", "profiles"):
            if not getattr(self, name):
                raise InputError(name, [], "at least one value", WHERE)
        for o in self.oils:
            get_oil(o)
        for t in self.bath_C:
            _range("bath_C", t, -20.0, 150.0, "the oils' trusted range")
        for r in self.roughness:
            _range("roughness", r, 1.0, 100.0, "T >= 1 (1 = smooth)")
        for p in self.profiles:
            if p not in PROFILES:
                raise InputError("profiles", p, f"allowed: {', '.join(PROFILES)}", WHERE)
        for p in self.pressures_MPa:
            _range("pressures_MPa", p, 0.0, 120.0, "gauge pressure 0 .. 120 MPa (11 km)")
        for e in self.effects:
            if e not in EFFECTS:
                raise InputError("effects", e, f"allowed: {', '.join(EFFECTS)}", WHERE)
        if self.base not in ("eq6", "power-law"):
            raise InputError("base", self.base, "allowed: eq6, power-law", WHERE)
        if self.targets not in ("base", "all"):
            raise InputError("targets", self.targets, "allowed: base, all", WHERE)
        if self.criterion not in CRITERIA:
            raise InputError("criterion", self.criterion, f"allowed: {', '.join(CRITERIA)}",
                             WHERE)
        _range("peak_speed_rpm", self.peak_speed_rpm, 1.0, 2e4, "1 .. 20000 rpm")
        _range("frequency_hz", self.frequency_hz, 1e-4, 10.0, "1e-4 .. 10 Hz")
        _range("sample_interval_s", self.sample_interval_s, 1e-3, 60.0, "1 ms .. 60 s")
        _range("duration_s", self.duration_s, 20 * self.sample_interval_s, 1e5,
               f"at least 20 samples ({20 * self.sample_interval_s:g} s) .. 1e5 s")
        _range("scale", self.scale, 0.1, 10.0, "an expected scale 0.1 .. 10")
        _range("noise_W", self.noise_W, 1e-6, 1e4, "a noise sd > 0 W")
        _range("noise_speed_rpm", self.noise_speed_rpm, 0.0, 1e3, "a noise sd >= 0 rpm")
        _range("noise_temp_K", self.noise_temp_K, 0.0, 10.0, "a noise sd >= 0 K")
        for name in ("run_h", "oil_change_h", "temp_change_h", "rotor_change_h"):
            _range(name, getattr(self, name), 0.0, 1e4, "hours >= 0")
        if self.runs is None and self.budget_h is None:
            raise InputError("runs", None, "give a number of runs or a budget_h", WHERE)
        if self.runs is not None and (isinstance(self.runs, bool) or int(self.runs) != self.runs
                                      or not 2 <= self.runs <= 1000):
            raise InputError("runs", self.runs, "an integer 2 .. 1000", WHERE)
        if self.budget_h is not None:
            _range("budget_h", self.budget_h, 1e-3, 1e6, "hours > 0")

    @property
    def n_samples(self) -> int:
        """Samples per run [-]."""
        return int(round(self.duration_s / self.sample_interval_s))

    @property
    def run_cost_h(self) -> float:
        """Rig time of one run: its duration and the per-run overhead [h]."""
        return self.duration_s / 3600.0 + self.run_h


def _range(name: str, value, lo: float, hi: float, allowed: str) -> None:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InputError(name, value, allowed, WHERE) from None
    if not (math.isfinite(x) and lo <= x <= hi):
        raise InputError(name, value, allowed, WHERE)
