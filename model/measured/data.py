"""Measured rig data: read, validate, derive the viscous power per sample.

Data format (CSV, or Parquet with ``.parquet``/``.pq``), one row per sample:

* ``speed_rpm``: signed motor speed; ``temp_C``: the temperature the viscosity
  follows; ``oil``: a name in the oils table (or a built-in gas), or ``none`` for
  an oil-free baseline run; ``roughness_T``: the clearance roughness T of the row
  (>= 1);
* ``time_s`` (optional): seconds from the run's start, increasing within a run,
  with ``run`` naming one continuous recording. **Without** ``time_s`` each row
  is a steady operating point: no rates (d omega/dt = dT/dt = 0), so effects
  that act through time are not candidates. ``run`` is then optional: rows that
  share ``oil``, ``roughness_T`` and ``gap_mm`` form one group (one setup), and
  leave-one-group-out validation leaves one setup out (leaving single rows out
  would let a point's neighbours in the same sweep predict it, and cost one fold
  per row);
* exactly one of ``power_W`` (electrical input power; the viscous part is what
  remains after the oil-free baseline of the same T is taken away) or
  ``viscous_power_W`` (the loss measured directly; no baseline needed); for
  prediction (:func:`validate` with ``purpose="predict"``) neither is needed;
* optional ``nu_cSt``, ``density_kg_m3`` (override the oils table for that row;
  with both, ``oil`` may name a fluid the table does not hold), ``gap_mm``
  (region-1 clearance of that row). Other columns are kept (for ``cv_by``).

Every row that is dropped is counted under the first reason that applies
(:class:`DropRecord`; :attr:`MeasuredData.drop_code` gives each input row's
reason); a file that cannot be used at all raises
:class:`~oilgap.model.errors.InputError` with one message. Validation works on
whole columns and on the distinct values of the text columns, never row by row
in Python.

The oil-free baseline that turns ``power_W`` into the viscous power is fitted
by the calibration (:mod:`oilgap.optim.calibration.baseline`) and handed to
:func:`oil_samples`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from ..errors import InputError
from ..fluids import warn_if_untrusted_state
from ..io.tables import read_table, text_codes
from ..oils import Oil, normalize_oil_name, read_oils_csv, with_builtin
from ..units import ZERO_CELSIUS_K, cst_to_m2_s, m_to_mm, mm_to_m
from .kinematics import (
    SPEED_DERIVATIVE_WINDOW_S,
    TEMP_DERIVATIVE_WINDOW_S,
    add_kinematics,
    time_derivative,
)
from .validation import (
    CORE_COLUMNS,
    INTERNAL_COLUMNS,
    MAX_CV_GROUPS,
    MIN_RUN_SAMPLES,
    OIL_FREE,
    OPTIONAL_COLUMNS,
    POWER_COLUMNS,
    PURPOSES,
    REQUIRED_COLUMNS,
    TEMP_LIMITS_C,
    TEMP_STEP_K,
    DropRecord,
    MeasuredData,
    validate,
)

__all__ = ["CORE_COLUMNS", "MAX_CV_GROUPS", "MIN_RUN_SAMPLES", "OIL_FREE", "OPTIONAL_COLUMNS",
           "POWER_COLUMNS", "PURPOSES", "REQUIRED_COLUMNS", "SPEED_DERIVATIVE_WINDOW_S",
           "TEMP_DERIVATIVE_WINDOW_S", "TEMP_LIMITS_C", "TEMP_STEP_K", "DropRecord",
           "MeasuredData", "Samples", "add_kinematics", "cv_groups", "load_measured",
           "oil_samples", "predict_samples", "read_table", "time_derivative", "validate"]


# --------------------------------------------------------------------------- reading


def load_measured(path: str | Path, oils: str | Path | dict[str, Oil] | None = None,
                  purpose: str = "fit") -> MeasuredData:
    """Read and validate a data file; ``oils`` is an oils CSV path or a catalogue.

    Parameters
    ----------
    path : str or Path
        CSV or Parquet data file (columns: see the module docstring; units in names).
    oils : str, Path or dict of str to Oil, optional
        Oils CSV (nu [cSt], density [kg/m^3]) or catalogue (default: built-in).
    purpose : {"fit", "predict"}
        As :func:`validate`.

    Returns
    -------
    MeasuredData
        As :func:`validate`.
    """
    cat = with_builtin(read_oils_csv(oils), "oils") if isinstance(oils, (str, Path)) else oils
    return validate(read_table(path), cat, str(path), purpose)


# --------------------------------------------------------------------------- samples


@dataclass(frozen=True, eq=False)
class Samples:
    """Oil-run samples ready for calibration (SI arrays, one entry per sample).

    Attributes
    ----------
    run, run_code, run_names : ndarray, ndarray of int, tuple of str
        Run name, its index in ``run_names``, and the run names in order.
    oil : ndarray of str
        Oil name as written in the file.
    roughness_T : ndarray
        Clearance roughness T of the run [-].
    time_s, speed_rpm, omega, domega_dt : ndarray
        Time [s] (zero without time), speed [rpm], speed [rad/s], acceleration
        [rad/s^2] (zero without time).
    temp_C, dtemp_dt : ndarray
        Measured temperature [degC] and its rate [K/s] (zero without time).
    nu_m2_s, density_kg_m3 : ndarray
        Oil state at the measured temperature [m^2/s], [kg/m^3].
    nu_pm, rho_pm : tuple of two ndarray
        The same at temperature -/+ :data:`TEMP_STEP_K` [m^2/s], [kg/m^3] (NaN where
        the row overrides the oil table, so no temperature law is known).
    gap1_m : ndarray
        Region-1 clearance [m].
    viscous_W : ndarray
        Measured viscous power [W] (directly, or power minus the baseline; NaN for
        samples to predict).
    index : ndarray of int
        Rows of the validated frame the samples come from.
    has_time : bool
        False for steady operating points (no rates; time-dependent effects are
        not candidates).
    cv_group, cv_names : ndarray of int, tuple of str
        Group of each sample for leave-one-group-out validation (index in
        ``cv_names``); by default the runs.
    cv_by : str
        The column the groups come from (``"run"`` by default).
    """

    run: np.ndarray
    run_code: np.ndarray
    run_names: tuple[str, ...]
    oil: np.ndarray
    roughness_T: np.ndarray
    time_s: np.ndarray
    speed_rpm: np.ndarray
    omega: np.ndarray
    domega_dt: np.ndarray
    temp_C: np.ndarray
    dtemp_dt: np.ndarray
    nu_m2_s: np.ndarray
    density_kg_m3: np.ndarray
    nu_pm: tuple[np.ndarray, np.ndarray]
    rho_pm: tuple[np.ndarray, np.ndarray]
    gap1_m: np.ndarray
    viscous_W: np.ndarray
    index: np.ndarray
    has_time: bool = True
    cv_group: np.ndarray | None = None
    cv_names: tuple[str, ...] | None = None
    cv_by: str = "run"

    def __post_init__(self):
        if self.cv_group is None:
            object.__setattr__(self, "cv_group", self.run_code)
        if self.cv_names is None:
            object.__setattr__(self, "cv_names", self.run_names)

    @property
    def n(self) -> int:
        """Number of samples [-]."""
        return len(self.omega)

    def subset(self, mask: np.ndarray) -> Samples:
        """The samples where ``mask`` holds (run and group codes kept).

        Parameters
        ----------
        mask : ndarray of bool or int
            Samples to keep [-].

        Returns
        -------
        Samples
            The subset (SI arrays as here).
        """
        kw = {}
        for k in self.__dataclass_fields__:
            v = getattr(self, k)
            if k in ("run_names", "cv_names", "has_time", "cv_by"):
                kw[k] = v
            elif isinstance(v, tuple):
                kw[k] = tuple(x[mask] for x in v)
            else:
                kw[k] = v[mask]
        return Samples(**kw)


def _properties(fluid, temp_K: np.ndarray, p_Pa: float, strict: bool):
    """(nu, rho) of a fluid; NaN instead of an error when not ``strict`` (a table edge)."""
    try:
        nu, _, rho = fluid.properties(temp_K, p_Pa)
    except InputError:
        if strict:
            raise
        return np.nan, np.nan
    return nu, rho


def _fluid_state(o: pd.DataFrame, oils: Mapping, region1_gap_m: float, p_Pa: float):
    """nu, rho, nu_pm, rho_pm and the region-1 gap of each row of ``o`` (SI)."""
    n = len(o)
    tK = o["temp_C"].to_numpy(dtype=float) + ZERO_CELSIUS_K
    nu, rho, nu_m, nu_p, rho_m, rho_p = (np.full(n, np.nan) for _ in range(6))
    codes, names = text_codes(o["oil"])
    own_nu = (~np.isnan(o["nu_cSt"].to_numpy(dtype=float)) if "nu_cSt" in o.columns
              else np.zeros(n, bool))
    for k, name in enumerate(names):
        key = normalize_oil_name(name)
        if key not in oils:
            continue
        sel = codes == k
        # the promised warning where a fluid's law is not trusted (rows with nu_cSt need none)
        warn_if_untrusted_state(oils[key], tK[sel & ~own_nu] - ZERO_CELSIUS_K, p_Pa, "temp_C")
        nu[sel], rho[sel] = _properties(oils[key], tK[sel], p_Pa, True)
        nu_m[sel], rho_m[sel] = _properties(oils[key], tK[sel] - TEMP_STEP_K, p_Pa, False)
        nu_p[sel], rho_p[sel] = _properties(oils[key], tK[sel] + TEMP_STEP_K, p_Pa, False)
    for col, arr, pm, scale in (("nu_cSt", nu, (nu_m, nu_p), cst_to_m2_s(1.0)),
                                ("density_kg_m3", rho, (rho_m, rho_p), 1.0)):
        if col in o.columns:
            v = o[col].to_numpy(dtype=float)
            given = ~np.isnan(v)
            arr[given] = v[given] * scale
            for x in pm:
                x[given] = np.nan
    gap = np.full(n, float(region1_gap_m))
    if "gap_mm" in o.columns:
        g = o["gap_mm"].to_numpy(dtype=float)
        given = ~np.isnan(g)
        gap[given] = mm_to_m(g[given])
    return nu, rho, (nu_m, nu_p), (rho_m, rho_p), gap


def cv_groups(o: pd.DataFrame, gap1_m: np.ndarray, cv_by: str, source: str = "data"
              ) -> tuple[np.ndarray, tuple[str, ...]]:
    """Groups of leave-one-group-out validation from a column of the oil rows.

    Parameters
    ----------
    o : pandas.DataFrame
        The oil rows of a validated frame.
    gap1_m : ndarray
        Their region-1 gap [m] (``cv_by="gap_mm"`` groups by it, the case's gap
        where the row gives none).
    cv_by : str
        ``"run"``, ``"gap_mm"`` or any other column of the data (e.g. ``oil``).
    source : str
        Name used in messages.

    Returns
    -------
    (codes, names)
        Group of each row [-] (index into ``names``, sorted by value).

    Raises
    ------
    InputError
        Not a column of the data; fewer than 2 groups among the oil rows; more than
        :data:`MAX_CV_GROUPS`.
    """
    if cv_by == "run":
        codes, names = _run_codes(o)
    elif cv_by == "gap_mm":
        vals, codes = np.unique(np.round(m_to_mm(gap1_m), 12), return_inverse=True)
        names = tuple(f"{v:g}" for v in vals)
    elif cv_by in o.columns and cv_by not in INTERNAL_COLUMNS:
        col = o[cv_by]
        if pd.api.types.is_numeric_dtype(col.dtype) and not pd.api.types.is_bool_dtype(col):
            v = col.to_numpy(dtype=float, na_value=np.nan)
            vals, codes = np.unique(v, return_inverse=True)   # NaN last, one group
            names = tuple("(missing)" if np.isnan(x) else f"{x:g}" for x in vals)
        else:
            codes, nm = text_codes(col)
            used, codes = np.unique(codes, return_inverse=True)
            names = tuple(str(nm[u]) or "(missing)" for u in used)
    else:
        cols = [c for c in o.columns if c not in INTERNAL_COLUMNS]
        raise InputError("cv_by", cv_by, f"is not a column of the data (columns: "
                         f"{', '.join(cols)})", source)
    k = len(names)
    if k < 2:
        raise InputError("cv_by", cv_by, f"has {k} group among the oil rows "
                         f"({', '.join(names) or 'none'}); leave-one-group-out needs at "
                         "least 2", source)
    if k > MAX_CV_GROUPS:
        raise InputError("cv_by", cv_by, f"has {k} groups among the oil rows; at most "
                         f"{MAX_CV_GROUPS}: round or bin the column", source)
    return np.asarray(codes, dtype=np.int64).ravel(), names


def _text(col: pd.Series) -> np.ndarray:
    """A text column as an object array (a categorical one through its few categories)."""
    if isinstance(col.dtype, pd.CategoricalDtype):
        return np.asarray(col.cat.categories, dtype=object)[col.cat.codes.to_numpy()]
    return col.to_numpy(dtype=object)


def _run_codes(o: pd.DataFrame) -> tuple[np.ndarray, tuple[str, ...]]:
    """Run of each row as 0, 1, ... in order of appearance, and the run names."""
    rc = o["run_code"].to_numpy() if "run_code" in o.columns else _text(o["run"])
    code, _ = pd.factorize(rc)
    _, idx = np.unique(code, return_index=True)
    runs = o["run"].iloc[idx].to_numpy(dtype=object)
    return code.astype(np.int64), tuple(str(r) for r in runs)


def _samples(o: pd.DataFrame, state, y: np.ndarray, has_time: bool, cv=None) -> Samples:
    """Samples of the rows ``o`` (with kinematics) and their fluid state."""
    code, names = _run_codes(o)
    runs = _text(o["run"])
    nu, rho, nu_pm, rho_pm, gap = state
    cv_group, cv_names, cv_by = cv if cv is not None else (None, None, "run")
    f = {c: o[c].to_numpy(dtype=float) for c in ("roughness_T", "time_s", "speed_rpm", "omega",
                                                 "domega_dt", "temp_C", "dtemp_dt")}
    return Samples(
        run=runs, run_code=code, run_names=names, oil=_text(o["oil"]), roughness_T=f["roughness_T"],
        time_s=f["time_s"], speed_rpm=f["speed_rpm"], omega=f["omega"], domega_dt=f["domega_dt"],
        temp_C=f["temp_C"], dtemp_dt=f["dtemp_dt"], nu_m2_s=nu, density_kg_m3=rho, nu_pm=nu_pm,
        rho_pm=rho_pm, gap1_m=gap, viscous_W=y, index=o.index.to_numpy(), has_time=has_time,
        cv_group=cv_group, cv_names=cv_names, cv_by=cv_by)


def oil_samples(data: MeasuredData, region1_gap_m: float,
                baselines: Mapping[float, Any] | None = None,
                pressure_gauge_Pa: float = 0.0, frame: pd.DataFrame | None = None,
                cv_by: str = "run") -> Samples:
    """The oil-run samples of validated data, with nu, rho and the viscous power.

    nu and rho follow each oil's Walther line and density law at ``temp_C`` unless the
    row gives ``nu_cSt``/``density_kg_m3``. With ``power_W`` the baseline of the run's T
    (``predict(omega, domega_dt, temp_C)`` [W], e.g.
    :func:`oilgap.optim.calibration.baseline.fit_baselines`) is subtracted.

    Parameters
    ----------
    data : MeasuredData
        Validated data.
    region1_gap_m : float
        Region-1 clearance of rows without ``gap_mm`` [m].
    baselines : mapping of float to baseline, optional
        Roughness T [-] -> oil-free baseline; required for ``power_W`` data.
    pressure_gauge_Pa : float
        Oil pressure above atmospheric [Pa].
    frame : pandas.DataFrame, optional
        ``data.frame`` after :func:`add_kinematics`, if at hand.
    cv_by : str
        Column whose values group the samples for leave-one-group-out validation
        (:func:`cv_groups`; default the runs).

    Returns
    -------
    Samples
        The oil-run samples (SI), viscous power [W].

    Raises
    ------
    InputError
        ``power_W`` data without baselines; an unusable ``cv_by``.
    """
    f = add_kinematics(data.frame, data.has_time) if frame is None else frame
    if data.kind == "power_W" and baselines is None:
        raise InputError("baselines", None, "power_W data need the oil-free baseline of each "
                         "roughness T", data.source)
    o = f[~f["oil_free"].to_numpy()]
    state = _fluid_state(o, data.oils, region1_gap_m, pressure_gauge_Pa)
    if data.kind == "power_W":
        y = o["power_W"].to_numpy(dtype=float).copy()
        T = o["roughness_T"].to_numpy()
        for t, b in baselines.items():
            sel = T == t
            y[sel] -= b.predict(o["omega"].to_numpy()[sel], o["domega_dt"].to_numpy()[sel],
                                o["temp_C"].to_numpy()[sel])
    else:
        y = o["viscous_power_W"].to_numpy(dtype=float)
    codes, names = cv_groups(o, state[4], cv_by, data.source)
    return _samples(o, state, y, data.has_time, (codes, names, cv_by))


def predict_samples(data: MeasuredData, region1_gap_m: float, pressure_gauge_Pa: float = 0.0,
                    frame: pd.DataFrame | None = None) -> Samples:
    """Samples of the oil rows of data validated for prediction (no power needed).

    Parameters
    ----------
    data : MeasuredData
        Validated with ``purpose="predict"`` (or for fitting: its oil rows).
    region1_gap_m : float
        Region-1 clearance of rows without ``gap_mm`` [m].
    pressure_gauge_Pa : float
        Oil pressure above atmospheric [Pa].
    frame : pandas.DataFrame, optional
        ``data.frame`` after :func:`add_kinematics`, if at hand.

    Returns
    -------
    Samples
        SI arrays as :func:`oil_samples`, ``viscous_W`` NaN [W].
    """
    f = add_kinematics(data.frame, data.has_time) if frame is None else frame
    o = f[~f["oil_free"].to_numpy()]
    state = _fluid_state(o, data.oils, region1_gap_m, pressure_gauge_Pa)
    return _samples(o, state, np.full(len(o), np.nan), data.has_time)
