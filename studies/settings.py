"""The studies' settings and the run options as records, each value checked once.

The command line builds them from its arguments, the façade (``og.*``) from its keywords,
and the study engines take them; their defaults are the one default of each setting (the
command line's argument tables read them from here). A light module: no numpy, pandas,
SciPy or CasADi, so the argument tables import it.

* :class:`RunOptions`: how a study runs (processes, Dask scheduler, progress line,
  chunking); never what it computes.
* :class:`DesignLimits`: the design NLP's limits and its multi-start (``og.optimize``).
* :class:`OilGradeSettings`, :class:`SweepSettings`, :class:`SmoothingSettings`,
  :class:`ParetoSettings`: what each study computes.

A bad value raises :class:`~oilgap.model.errors.InputError` naming the field as the
façade's keyword spells it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, fields
from typing import Any

from oilgap.model.errors import (
    ArgumentError,
    InputError,
    check_finite,
    check_positive,
    check_range,
)
from oilgap.model.thermal_modes import THERMAL_MODES

# ------------------------------------------------------------------------- the defaults
DEFAULT_STARTS = 8
"""Start points of the design NLP: the case's design and 7 random points in the bounds
(the multi-start that finds the global optimum where the problem has several local ones)."""

DEFAULT_CHUNK_SECONDS = 3.0
"""Target wall time of a sweep's chunk on its worker [s]."""

ISO_GRADES = ("VG10", "VG15", "VG22", "VG32", "VG46", "VG68", "VG100", "VG150", "VG220",
              "VG320", "VG460", "VG680", "VG1000")
"""The ISO VG grades of the built-in catalogue, the oil-grade study's candidates."""

DEFAULT_NU_MIN_CST = 13.0
"""Lubrication limit [cSt]: the thinnest the oil may get anywhere in the envelope."""
DEFAULT_NU_MAX_CST = 1000.0
"""Cold-start limit [cSt]: the thickest the oil may get anywhere in the envelope."""
DEFAULT_ISO_TOLERANCE = 0.10
"""ISO 3448's +-10 % on the grade's 40 degC viscosity, applied at its worst [-]."""
DEFAULT_DEPTH_RANGE_M = (0.0, 7000.0)
"""The envelope's depths [m]."""
DEFAULT_TEMP_RANGE_C = (0.0, 40.0)
"""The envelope's oil temperatures (none, film) or sea temperatures (bulk, full) [degC]."""
DEFAULT_MISSION_HOURS = 8.0
"""Mission duration [h]."""
DEFAULT_N_DEPTH = 29
"""Depths of the envelope grid."""
DEFAULT_N_TEMP = 21
"""Temperatures of the envelope grid."""

MIN_POINTS = 50
MAX_POINTS = 2000
"""Most points per Pareto front: each is one IPOPT solve (0.1-1 s) on each of two fronts,
so 2000 points are about an hour of CPU; the fronts are smooth curves (60 by default)."""
MAX_MISSION_HOURS = 1.0e6
"""Longest mission [h] of the oil-grade study: 10^6 h is 114 years, beyond any joint's
service life."""
"""Fewest points per Pareto front."""
DEFAULT_POINTS = 60
"""Points per Pareto front."""

PLATEAU_TOL = 0.05
"""Where the loss counts as levelled off: within 5 % of its smooth-wall value [-]."""
HEATING_METHODS = ("per-oil", "shared", "heat-balance")
"""How the smoothing study fits the runs' temperatures."""
FIT_THERMAL_MODES = ("none", "film", "full")
"""The smoothing study's thermal modes."""
DEFAULT_SENSITIVITY_K_W = (0.05, 0.1, 0.2)
"""R_th values [K/W] of the smoothing study's per-oil sensitivity fits."""

SWEEP_MODES = ("evaluate", "optimize")
"""What a sweep does to each row."""

DEFAULT_UNCERTAINTY_SAMPLES = 2**13
"""Quasi-Monte Carlo points of the uncertainty study's percentiles [-]."""
DEFAULT_SOBOL_SAMPLES = 2**11
"""Base points N of the Saltelli design of its Sobol' indices (N (d + 2) evaluations) [-]."""
DEFAULT_CONFIDENCE = 0.95
"""Confidence level of the Sobol' indices' intervals [-]."""


def _integer(field: str, value: Any, lowest: int, where: str) -> int:
    if isinstance(value, bool) or not hasattr(value, "__index__") or int(value) < lowest:
        raise InputError(field, value, f"must be an integer >= {lowest}", where)
    return int(value)


def _mission_hours(value: Any, where: str) -> float:
    hours = check_positive("mission_hours", value, where)
    if hours > MAX_MISSION_HOURS:
        raise InputError("mission_hours", value, f"at most {MAX_MISSION_HOURS:g} h (114 "
                         "years, beyond any joint's service life)", where)
    return hours


def _thermal(value: Any, allowed: Sequence[str], where: str) -> str | None:
    if value is not None and value not in allowed:
        raise InputError("thermal", value, f"one of {', '.join(allowed)}", where)
    return None if value is None else str(value)


def _pair(field: str, value: Sequence[float], lo: float, hi: float,
          where: str) -> tuple[float, float]:
    """A (min, max) range within [lo, hi]."""
    if isinstance(value, str) or not hasattr(value, "__len__") or len(value) != 2:
        raise InputError(field, value, "needs (min, max)", where)
    a = check_range(field + " min", value[0], lo, hi, where)
    b = check_range(field + " max", value[1], lo, hi, where)
    if b < a:
        raise InputError(field, (a, b), "max must be >= min", where)
    return a, b


def _set(obj: Any, **values: Any) -> None:
    """Store checked values on a frozen record (in ``__post_init__`` only)."""
    for k, v in values.items():
        object.__setattr__(obj, k, v)


class _Record:
    """``to_dict()`` and ``from_keywords`` for the settings records."""

    def to_dict(self) -> dict:
        """The settings as a plain dict (field name -> value)."""
        return {f.name: getattr(self, f.name) for f in fields(self)}

    @classmethod
    def names(cls) -> frozenset[str]:
        """The fields' names (the façade's keywords)."""
        return frozenset(f.name for f in fields(cls))


@dataclass(frozen=True, kw_only=True)
class RunOptions(_Record):
    """How a study runs; none changes its numbers.

    Attributes
    ----------
    workers : int, optional
        Processes (None: all local cores, where the study runs a grid; >= 1).
    scheduler : str, optional
        None (local processes), ``"local"`` (a Dask LocalCluster of ``workers``
        processes) or ``"tcp://HOST:PORT"`` (a running Dask scheduler).
    progress : bool, optional
        Progress line on stderr (None: when stderr is a terminal).
    chunk_size : int, optional
        Fixed rows per task of a sweep (None: chunks sized by time).
    chunk_seconds : float, optional
        Target wall time of a sweep's chunk on its worker [s] (> 0; None:
        :data:`DEFAULT_CHUNK_SECONDS`). Not with ``chunk_size`` (refused naming both).
    """

    workers: int | None = None
    scheduler: str | None = None
    progress: bool | None = None
    chunk_size: int | None = None
    chunk_seconds: float | None = None

    def __post_init__(self):
        where = "trade study"
        if self.workers is not None:
            _set(self, workers=_integer("workers", self.workers, 1, where))
        if self.chunk_size is not None:
            _set(self, chunk_size=_integer("chunk_size", self.chunk_size, 1, where))
        if self.chunk_seconds is not None:
            _set(self, chunk_seconds=check_positive("chunk_seconds", self.chunk_seconds,
                                                    where))
            if self.chunk_size is not None:
                raise InputError("chunk_size", self.chunk_size, "not with chunk_seconds: a "
                                 "fixed number of rows per task, or chunks sized by time; "
                                 "choose one", where)
        if self.progress is not None:
            _set(self, progress=bool(self.progress))


INLINE = RunOptions(workers=1, progress=False)
"""In this process, silently (a study's own small grids)."""


@dataclass(frozen=True, kw_only=True)
class DesignLimits(_Record):
    """The design NLP's limits and its multi-start.

    Attributes
    ----------
    torque_min_Nm : float, optional
        Required torque capability [N m] (None: the case's, else the initial design's).
    inertia_max_ratio : float, optional
        Rotor inertia limit over the case's unfilled rotor [-] (None: the case's).
    starts : int
        Start points: the case's design and ``starts - 1`` random points in the bounds
        (default :data:`DEFAULT_STARTS`).
    """

    torque_min_Nm: float | None = None
    inertia_max_ratio: float | None = None
    starts: int = DEFAULT_STARTS

    def __post_init__(self):
        if self.torque_min_Nm is not None:
            _set(self, torque_min_Nm=check_positive("torque_min_Nm", self.torque_min_Nm))
        if self.inertia_max_ratio is not None:
            _set(self, inertia_max_ratio=check_positive("inertia_max_ratio",
                                                        self.inertia_max_ratio))
        if isinstance(self.starts, bool) or not isinstance(self.starts, int) or self.starts < 1:
            raise InputError("starts", self.starts, "an integer >= 1 is required")

    def constraints(self) -> dict[str, float | None]:
        """The limits as :meth:`oilgap.optim.design.DesignProblem.solve` takes them."""
        return {"torque_min_Nm": self.torque_min_Nm,
                "inertia_max_ratio": self.inertia_max_ratio}


@dataclass(frozen=True, kw_only=True)
class OilGradeSettings(_Record):
    """What the oil-grade study computes (:func:`oilgap.studies.oil_grade.run`).

    Attributes
    ----------
    grades : sequence of str
        Oil names (default the ISO VG grades of the catalogue).
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode (None: ``bulk`` with ``[thermal]``, else ``none``).
    nu_min_cSt, nu_max_cSt : float
        Lubrication and cold-start limits [cSt] (0 < min < max).
    iso_tolerance : float
        Grade tolerance applied at its worst [-] (0 to 0.5; 0 switches it off).
    depth_range_m : pair of float
        The envelope's depths [m] (0 to 11 000).
    temp_range_C, sea_temp_range_C : pair of float, optional
        The envelope's oil temperatures (none, film) or sea temperatures (bulk, full)
        [degC] (-20 to 150; default :data:`DEFAULT_TEMP_RANGE_C`).
    n_depth, n_temp : int
        Grid points over the envelope (>= 2 each).
    mission_hours : float
        Mission duration [h] (> 0).
    rated_temps_C : sequence of float, optional
        Temperatures of the loss-vs-grade view at the rated depth [degC].
    """

    grades: tuple[str, ...] = ISO_GRADES
    thermal: str | None = None
    nu_min_cSt: float = DEFAULT_NU_MIN_CST
    nu_max_cSt: float = DEFAULT_NU_MAX_CST
    iso_tolerance: float = DEFAULT_ISO_TOLERANCE
    depth_range_m: tuple[float, float] = DEFAULT_DEPTH_RANGE_M
    temp_range_C: tuple[float, float] | None = None
    sea_temp_range_C: tuple[float, float] | None = None
    n_depth: int = DEFAULT_N_DEPTH
    n_temp: int = DEFAULT_N_TEMP
    mission_hours: float = DEFAULT_MISSION_HOURS
    rated_temps_C: tuple[float, ...] | None = None

    def __post_init__(self):
        where = "oil-grade study"
        if isinstance(self.grades, str) or not self.grades:
            raise InputError("grades", self.grades, "needs at least one oil", where)
        nu_min = check_positive("nu_min_cSt", self.nu_min_cSt, where)
        nu_max = check_positive("nu_max_cSt", self.nu_max_cSt, where)
        if nu_max <= nu_min:
            raise InputError("nu_max_cSt", nu_max, f"must be > nu_min_cSt = {nu_min:g}", where)
        ranges = {}
        for name, lo, hi in (("temp_range_C", -20.0, 150.0),
                             ("sea_temp_range_C", -20.0, 150.0)):
            v = getattr(self, name)
            ranges[name] = None if v is None else _pair(name, v, lo, hi, where)
        rated = self.rated_temps_C
        _set(self, grades=tuple(self.grades),
             thermal=_thermal(self.thermal, THERMAL_MODES, where),
             nu_min_cSt=nu_min, nu_max_cSt=nu_max,
             iso_tolerance=check_range("iso_tolerance", self.iso_tolerance, 0.0, 0.5, where),
             depth_range_m=_pair("depth_range_m", self.depth_range_m, 0.0, 11_000.0, where),
             n_depth=_integer("n_depth", self.n_depth, 2, where),
             n_temp=_integer("n_temp", self.n_temp, 2, where),
             mission_hours=_mission_hours(self.mission_hours, where),
             rated_temps_C=None if rated is None else tuple(
                 check_finite("rated_temps_C", t, where) for t in rated),
             **ranges)


@dataclass(frozen=True, kw_only=True)
class SweepSettings(_Record):
    """What a sweep computes (:func:`oilgap.studies.grid.runner.run_grid`).

    Attributes
    ----------
    mode : {"evaluate", "optimize"}
        Evaluate each row, or optimize its design.
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode (None: ``bulk`` with ``[thermal]``, else ``none``).
    retry_failed : bool
        Run again the stored points that failed.
    """

    mode: str = "evaluate"
    thermal: str | None = None
    retry_failed: bool = False

    def __post_init__(self):
        where = "trade study"
        if self.mode not in SWEEP_MODES:
            raise InputError("mode", self.mode, f"allowed: {', '.join(SWEEP_MODES)}", where)
        _set(self, mode=str(self.mode), thermal=_thermal(self.thermal, THERMAL_MODES, where),
             retry_failed=bool(self.retry_failed))


@dataclass(frozen=True, kw_only=True)
class SmoothingSettings(_Record):
    """What the smoothing study computes (:func:`oilgap.studies.smoothing.run`).

    Attributes
    ----------
    method : {"per-oil", "shared", "heat-balance"}, optional
        How the runs' temperatures are fitted (None: per-oil, or heat-balance under
        ``thermal="full"``).
    thermal : {"none", "film", "full"}, optional
        The loss at the runs' temperatures (None: none).
    resistance_K_W : float
        Per-oil method: fixed R_th [K/W] (its range is checked by the fit).
    T_values : sequence of float, optional
        Roughness values of the loss-vs-T view [-] (default 1 to 5 by 0.05).
    plateau_tol : float
        Where the loss counts as levelled off [-] (in (0, 1); fraction of P(T = 1)).
    sensitivity_K_W : tuple of float
        R_th values [K/W] of the per-oil sensitivity fits.
    film_evidence : bool
        Also fit the film strength with the rig's heat balance (seed rig only).
    """

    method: str | None = None
    thermal: str | None = None
    resistance_K_W: float = 0.0
    T_values: tuple[float, ...] | None = None
    plateau_tol: float = PLATEAU_TOL
    sensitivity_K_W: tuple[float, ...] = DEFAULT_SENSITIVITY_K_W
    film_evidence: bool = False

    def __post_init__(self):
        where = "smoothing study"
        if self.method is not None and self.method not in HEATING_METHODS:
            raise InputError("method", self.method, f"one of {', '.join(HEATING_METHODS)}",
                             where)
        tol = self.plateau_tol
        if not (isinstance(tol, (int, float)) and 0.0 < tol < 1.0):
            raise InputError("plateau_tol", tol, "must lie in (0, 1)", where)
        T = self.T_values
        try:
            T = None if T is None else tuple(check_finite("T_values", t, where) for t in T)
        except (TypeError, ValueError) as e:  # not a sequence, or an item not a number
            if isinstance(e, InputError):
                raise
            raise InputError("T_values", T, "a sequence of numbers >= 1", where) from None
        _set(self, T_values=T)
        _set(self, thermal=_thermal(self.thermal, FIT_THERMAL_MODES, where),
             plateau_tol=float(tol),
             resistance_K_W=check_finite("resistance_K_W", self.resistance_K_W, where),
             sensitivity_K_W=tuple(float(s) for s in self.sensitivity_K_W),
             film_evidence=bool(self.film_evidence))


@dataclass(frozen=True, kw_only=True)
class ParetoSettings(_Record):
    """What the Pareto study computes (:func:`oilgap.studies.pareto.run`).

    Attributes
    ----------
    points : int
        Points per front (>= :data:`MIN_POINTS`).
    torque_min_Nm : float, optional
        Required torque capability [N m] (None: the case's own).
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode of the fronts (None: ``bulk`` with ``[thermal]``, else ``none``).
    """

    points: int = DEFAULT_POINTS
    torque_min_Nm: float | None = None
    thermal: str | None = None

    def __post_init__(self):
        where = "pareto study"
        p = self.points
        if isinstance(p, bool) or not hasattr(p, "__index__") or \
                not MIN_POINTS <= int(p) <= MAX_POINTS:
            raise InputError("points", p, f"must be an integer from {MIN_POINTS} to "
                             f"{MAX_POINTS} (each point is one IPOPT solve on each of two "
                             "fronts)", where)
        if self.torque_min_Nm is not None:
            _set(self, torque_min_Nm=check_positive("torque_min_Nm", self.torque_min_Nm,
                                                    where))
        _set(self, points=int(p), thermal=_thermal(self.thermal, THERMAL_MODES, where))


def _power_of_two(field: str, value: Any, lowest: int, where: str) -> int:
    n = _integer(field, value, lowest, where)
    if n & (n - 1):
        raise InputError(field, n, f"a power of 2 >= {lowest} (Sobol' points are balanced "
                         f"only then), e.g. {1 << (n.bit_length() - 1)}", where)
    return n


@dataclass(frozen=True, kw_only=True)
class UncertaintySettings(_Record):
    """What the uncertainty study computes (:func:`oilgap.studies.uncertainty.run`).

    Attributes
    ----------
    samples : int
        Scrambled Sobol' points of the percentiles (a power of 2, >= 16).
    sobol_samples : int
        Base points N of the Saltelli design of the Sobol' indices (a power of 2, >= 16;
        N (d + 2) evaluations for d uncertain inputs).
    seed : int
        Seed of the scrambling (>= 0).
    thermal : {"none", "bulk", "film", "full"}, optional
        Thermal mode (None: ``bulk`` with ``[thermal]``, else ``none``; with
        ``film_strength`` uncertain its film counterpart, ``film`` or ``full``).
    confidence : float
        Confidence level of the indices' intervals [-] (in (0, 1)).
    sobol : bool
        Compute the Sobol' indices (SALib); False: percentiles and tornado only.
    """

    samples: int = DEFAULT_UNCERTAINTY_SAMPLES
    sobol_samples: int = DEFAULT_SOBOL_SAMPLES
    seed: int = 0
    thermal: str | None = None
    confidence: float = DEFAULT_CONFIDENCE
    sobol: bool = True

    def __post_init__(self):
        where = "uncertainty study"
        c = check_finite("confidence", self.confidence, where)
        if not 0.0 < c < 1.0:
            raise InputError("confidence", c, "must lie in (0, 1)", where)
        _set(self, samples=_power_of_two("samples", self.samples, 16, where),
             sobol_samples=_power_of_two("sobol_samples", self.sobol_samples, 16, where),
             seed=_integer("seed", self.seed, 0, where),
             thermal=_thermal(self.thermal, THERMAL_MODES, where), confidence=c,
             sobol=bool(self.sobol))


def split_keywords(keywords: dict[str, Any], settings_type: type,
                   run_options: bool = True) -> tuple[Any, RunOptions | None]:
    """The façade's keywords as (settings, run options): each keyword goes to the record
    that has it; ``settings=`` and ``options=`` give a record whole (then none of its own
    keywords may be given beside it).

    Raises
    ------
    ArgumentError
        A keyword neither record has, one given beside its record, a record of another
        type (an InputError that is also a TypeError).
    """
    kw = dict(keywords)
    settings, options = kw.pop("settings", None), kw.pop("options", None)
    own = settings_type.names()
    run = RunOptions.names() if run_options else frozenset()
    unknown = set(kw) - own - run
    if unknown or (options is not None and not run_options):
        names = sorted(unknown) or ["options"]
        raise ArgumentError(", ".join(names), kw.get(names[0], options), "the keywords are "
                            f"{', '.join(sorted(own | run))}, settings"
                            + (", options" if run_options else ""))
    s_kw = {k: v for k, v in kw.items() if k in own}
    r_kw = {k: v for k, v in kw.items() if k in run}
    if settings is not None and s_kw:
        raise ArgumentError("settings", settings, f"give settings or "
                            f"{', '.join(sorted(s_kw))}, not both")
    if options is not None and r_kw:
        raise ArgumentError("options", options, f"give options or {', '.join(sorted(r_kw))}, "
                            "not both")
    if settings is not None and not isinstance(settings, settings_type):
        raise ArgumentError("settings", settings, f"a {settings_type.__name__}")
    if options is not None and not isinstance(options, RunOptions):
        raise ArgumentError("options", options, "a RunOptions")
    s = settings if settings is not None else settings_type(**s_kw)
    o = options if options is not None else (RunOptions(**r_kw) if run_options else None)
    return s, o


__all__ = ["DEFAULT_STARTS", "INLINE", "DesignLimits", "OilGradeSettings", "ParetoSettings",
           "RunOptions", "SmoothingSettings", "SweepSettings", "UncertaintySettings",
           "split_keywords"]
