"""Measured rig data: read, validate, derive the viscous power per sample.

Data format (CSV, or Parquet with ``.parquet``/``.pq``), one row per sample:

* ``run``: one continuous recording; ``time_s``: seconds from the run's start,
  increasing within a run; ``speed_rpm``: signed motor speed; ``temp_C``: the
  temperature the viscosity follows; ``oil``: a name in the oils table, or
  ``none`` for an oil-free baseline run; ``roughness_T``: the clearance roughness
  T of the run (>= 1);
* exactly one of ``power_W`` (electrical input power; the viscous part is what
  remains after the oil-free baseline of the same T is taken away) or
  ``viscous_power_W`` (the loss measured directly; no baseline needed);
* optional ``nu_cSt``, ``density_kg_m3`` (override the oils table for that row;
  with both, ``oil`` may name a fluid the table does not hold), ``gap_mm``
  (region-1 clearance of that row).

Every row that is dropped is counted under the first reason that applies
(:class:`DropRecord`); a file that cannot be used at all raises
:class:`~oilgap.model.errors.InputError` with one message.

The oil-free baseline that turns ``power_W`` into the viscous power is fitted
by the calibration (:mod:`oilgap.optim.calibration.baseline`) and handed to
:func:`oil_samples`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from scipy.signal import savgol_filter

from .errors import InputError
from .oils import Oil, builtin_oils, normalize_oil_name, read_oils_csv
from .units import (
    ZERO_CELSIUS_K,
    cst_to_m2_s,
    mm_to_m,
    rpm_to_rad_s,
)

REQUIRED_COLUMNS = ("run", "time_s", "speed_rpm", "temp_C", "oil", "roughness_T")
POWER_COLUMNS = ("power_W", "viscous_power_W")
OPTIONAL_COLUMNS = ("nu_cSt", "density_kg_m3", "gap_mm")
OIL_FREE = "none"
MIN_RUN_SAMPLES = 10
TEMP_LIMITS_C = (-60.0, 300.0)
"""Temperatures outside this range [degC] are not oil temperatures: rows dropped."""
SPEED_DERIVATIVE_WINDOW_S = 1.0
"""Savitzky-Golay window [s] for d(omega)/dt (quadratic, at least 5 samples)."""
TEMP_DERIVATIVE_WINDOW_S = 3.0
"""Savitzky-Golay window [s] for dT/dt."""
TEMP_STEP_K = 0.5
"""Half-step [K] of the central difference for dP/dT."""


@dataclass(frozen=True)
class DropRecord:
    """Rows dropped for one reason: count and up to five file line numbers.

    Attributes
    ----------
    reason : str
        Why the rows were dropped (the first reason that applies to a row).
    count : int
        Number of rows dropped [-].
    lines : tuple of int
        Up to five line numbers of the file (header = line 1).
    """

    reason: str
    count: int
    lines: tuple[int, ...] = ()

    def to_dict(self) -> dict:
        """JSON form.

        Returns
        -------
        dict
            ``reason``, ``count`` [-] and ``example_lines``.
        """
        return {"reason": self.reason, "count": self.count, "example_lines": list(self.lines)}


@dataclass(frozen=True, eq=False)
class MeasuredData:
    """Validated samples (``frame``, sorted by run and time) and what was dropped.

    Attributes
    ----------
    frame : pandas.DataFrame
        The usable rows, units in the column names (``time_s`` [s], ``speed_rpm``
        [rpm], ``temp_C`` [degC], ``power_W`` [W]), plus the file's line number in
        ``line`` (header = line 1) and ``oil_free`` (bool).
    kind : str
        ``"power_W"`` or ``"viscous_power_W"``: which power column the file has.
    dropped : tuple of DropRecord
        Dropped rows by reason.
    n_read : int
        Rows read [-].
    source : str
        File name (for messages).
    ignored_columns : tuple of str
        Columns that are not part of the format.
    oils : dict of str to Oil
        The oils table the names were checked against.
    """

    frame: pd.DataFrame
    kind: str
    dropped: tuple[DropRecord, ...]
    n_read: int
    source: str
    ignored_columns: tuple[str, ...]
    oils: dict[str, Oil] = field(repr=False)

    @property
    def n_dropped(self) -> int:
        """Total number of dropped rows [-]."""
        return sum(d.count for d in self.dropped)

    def drop_summary(self) -> str:
        """One line per reason.

        Returns
        -------
        str
            "N rows read, M dropped:" and one line per reason with its count [-].
        """
        if not self.dropped:
            return f"{self.n_read} rows read, none dropped"
        lines = [f"{self.n_read} rows read, {self.n_dropped} dropped:"]
        lines += [f"  {d.count:>6}  {d.reason}" for d in self.dropped]
        return "\n".join(lines)


# --------------------------------------------------------------------------- reading


def read_table(path: str | Path) -> pd.DataFrame:
    """Read a CSV or Parquet file as text-preserving columns.

    Parameters
    ----------
    path : str or Path
        ``.csv``, or ``.parquet``/``.pq`` (needs pyarrow); units in column names.

    Returns
    -------
    pandas.DataFrame
        The raw table (CSV values as text), column names stripped [units as named].

    Raises
    ------
    InputError
        Missing file, unreadable content, no rows.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("data", str(path), "must be an existing CSV or Parquet file")
    suffix = path.suffix.lower()
    try:
        if suffix in (".parquet", ".pq"):
            try:
                df = pd.read_parquet(path)
            except ImportError:
                raise InputError("data", str(path), "reading Parquet needs pyarrow "
                                 "(pip install 'oilgap[parquet]')") from None
        else:
            df = pd.read_csv(path, dtype=str, keep_default_na=False, skipinitialspace=True)
    except InputError:
        raise
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError, OSError,
            ValueError) as e:
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        raise InputError("data", str(path), f"is not a readable CSV/Parquet table ({first})") \
            from None
    if df.shape[0] == 0:
        raise InputError("data", str(path), "holds no data rows")
    df.columns = [str(c).strip() for c in df.columns]
    return df


def _check_columns(cols: list[str], where: str) -> tuple[str, tuple[str, ...]]:
    missing = [c for c in REQUIRED_COLUMNS if c not in cols]
    if missing:
        lower = {c.lower(): c for c in cols}
        hints = [f"{lower[m.lower()]!r} -> {m!r}" for m in missing if m.lower() in lower]
        hint = f" (column names are case-sensitive: {', '.join(hints)})" if hints else ""
        raise InputError("columns", cols, f"missing {missing}; required "
                         f"{list(REQUIRED_COLUMNS)} and one of {list(POWER_COLUMNS)}{hint}",
                         where)
    present = [c for c in POWER_COLUMNS if c in cols]
    if len(present) != 1:
        what = "both" if present else "neither"
        lower = {c.lower(): c for c in cols}
        hints = [f"{lower[m.lower()]!r} -> {m!r}" for m in POWER_COLUMNS
                 if not present and m.lower() in lower]
        hint = f"; column names are case-sensitive: {', '.join(hints)}" if hints else ""
        raise InputError("columns", cols, f"exactly one of {list(POWER_COLUMNS)} is required "
                         f"({what} given{hint})", where)
    dup = sorted({c for c in cols if cols.count(c) > 1})
    if dup:
        raise InputError("columns", dup, "column names must be unique", where)
    known = set(REQUIRED_COLUMNS) | set(POWER_COLUMNS) | set(OPTIONAL_COLUMNS)
    return present[0], tuple(c for c in cols if c not in known)


def _given(frame: pd.DataFrame, col: str) -> pd.Series:
    if col not in frame.columns:
        return pd.Series(False, index=frame.index)
    return frame[col].notna()


def _numeric(s: pd.Series) -> pd.Series:
    if s.dtype == object or pd.api.types.is_string_dtype(s):
        s = s.astype(str).str.strip().replace({"": np.nan})
    return pd.to_numeric(s, errors="coerce").astype(float)


class _Dropper:
    def __init__(self):
        self.records: dict[str, list[int]] = {}

    def drop(self, df: pd.DataFrame, mask, reason: str) -> pd.DataFrame:
        mask = np.asarray(mask, dtype=bool)
        if mask.any():
            self.records.setdefault(reason, []).extend(df["line"].to_numpy()[mask].tolist())
            return df.loc[~mask]
        return df

    def result(self) -> tuple[DropRecord, ...]:
        return tuple(DropRecord(r, len(v), tuple(sorted(v)[:5])) for r, v in self.records.items())


def validate(df: pd.DataFrame, oils: dict[str, Oil] | None = None,
             source: str = "data") -> MeasuredData:
    """Validate a raw table and return the usable samples with a drop report.

    Parameters
    ----------
    df : pandas.DataFrame
        Raw table (columns as read, units in their names; values may be text).
    oils : dict of str to Oil, optional
        Oils table keyed by canonical name (default: the built-in catalogue).
    source : str
        Name used in messages.

    Returns
    -------
    MeasuredData
        Usable rows (numeric columns as float: [s], [rpm], [degC], [W], [-]) and
        the drop report.

    Raises
    ------
    InputError
        Missing or ambiguous columns, or no usable oil run left.
    """
    catalogue = builtin_oils() if oils is None else oils
    kind, ignored = _check_columns(list(df.columns), source)
    n_read = int(df.shape[0])
    df = df.copy()
    df["line"] = np.arange(2, n_read + 2)
    d = _Dropper()

    run = df["run"].astype(str).str.strip()
    run = run.where(~df["run"].isna(), "")
    df["run"] = run
    df = d.drop(df, (df["run"] == "") | (df["run"].str.lower() == "nan"), "missing run")
    oil = df["oil"].astype(str).str.strip()
    df["oil"] = oil
    df = d.drop(df, (df["oil"] == "") | (df["oil"].str.lower() == "nan"), "missing oil")

    for c in ("time_s", "speed_rpm", "temp_C", "roughness_T", kind):
        df[c] = _numeric(df[c])
        df = d.drop(df, ~np.isfinite(df[c].to_numpy()), f"{c} missing or not a finite number")
    for c in OPTIONAL_COLUMNS:
        if c in df.columns:
            df[c] = _numeric(df[c])
            raw_bad = ~np.isnan(df[c].to_numpy()) & ~(np.isfinite(df[c].to_numpy())
                                                     & (df[c].to_numpy() > 0))
            df = d.drop(df, raw_bad, f"{c} not a positive finite number")
    df = d.drop(df, df["roughness_T"].to_numpy() < 1.0, "roughness_T < 1")
    lo, hi = TEMP_LIMITS_C
    t = df["temp_C"].to_numpy()
    df = d.drop(df, (t < lo) | (t > hi), f"temp_C outside [{lo:g}, {hi:g}] degC")
    df = d.drop(df, df["time_s"].to_numpy() < 0.0, "time_s < 0")

    # oils: known name, or both property overrides
    def unknown_oil(frame: pd.DataFrame) -> np.ndarray:
        free = frame["oil"].str.lower() == OIL_FREE
        names = frame["oil"].unique()
        known_names = {n for n in names if normalize_oil_name(n) in catalogue}
        known = frame["oil"].isin(list(known_names))
        override = _given(frame, "nu_cSt") & _given(frame, "density_kg_m3")
        return (~free & ~known & ~override).to_numpy()

    for name in sorted(df.loc[unknown_oil(df), "oil"].unique()):
        df = d.drop(df, (df["oil"] == name).to_numpy() & unknown_oil(df),
                    f"oil {name!r} not in the oils table (and no nu_cSt + density_kg_m3)")
    df = df.copy()
    df["oil_free"] = df["oil"].str.lower() == OIL_FREE

    df = _drop_run_problems(df, d, kind)

    if not (~df["oil_free"]).any():
        summary = "; ".join(f"{r.count} x {r.reason}" for r in d.result())
        raise InputError("data", source, f"no usable oil run remains (dropped: {summary})"
                         if summary else "holds no oil run (every row has oil = none)")
    df = df.sort_values(["run", "time_s"], kind="stable").reset_index(drop=True)
    return MeasuredData(df, kind, d.result(), n_read, source, ignored, catalogue)


def _drop_run_problems(df: pd.DataFrame, d: _Dropper, kind: str) -> pd.DataFrame:
    # run consistency: one oil and one T per run
    for col, label in (("oil", "oil"), ("roughness_T", "roughness_T")):
        mode = df.groupby("run")[col].agg(lambda s: s.value_counts().index[0])
        df = d.drop(df, (df[col] != df["run"].map(mode)).to_numpy(),
                    f"{label} differs from the rest of its run")

    # time: duplicates, then not increasing (file order within each run)
    df = d.drop(df, df.duplicated(["run", "time_s"], keep="first").to_numpy(),
                "duplicate time_s within run")
    prev_max = df.groupby("run")["time_s"].transform(lambda s: s.cummax().shift(1))
    df = d.drop(df, (prev_max.notna() & (df["time_s"] <= prev_max)).to_numpy(),
                "time_s does not increase within run")

    counts = df.groupby("run")["run"].transform("size")
    df = d.drop(df, (counts < MIN_RUN_SAMPLES).to_numpy(),
                f"run shorter than {MIN_RUN_SAMPLES} samples")

    if kind == "power_W":
        free_T = list(df.loc[df["oil_free"], "roughness_T"].unique())
        nobase = ~df["oil_free"] & ~df["roughness_T"].isin(free_T)
        for T in sorted(df.loc[nobase, "roughness_T"].unique()):
            df = d.drop(df, (~df["oil_free"] & (df["roughness_T"] == T)).to_numpy(),
                        f"no oil-free baseline run with roughness_T = {T:g}")
    else:
        df = d.drop(df, df["oil_free"].to_numpy(),
                    "oil-free run (not needed: viscous_power_W is measured directly)")
    return df


def load_measured(path: str | Path, oils: str | Path | dict[str, Oil] | None = None
                  ) -> MeasuredData:
    """Read and validate a data file; ``oils`` is an oils CSV path or a catalogue.

    Parameters
    ----------
    path : str or Path
        CSV or Parquet data file (columns: see the module docstring; units in names).
    oils : str, Path or dict of str to Oil, optional
        Oils CSV (nu [cSt], density [kg/m^3]) or catalogue (default: built-in).

    Returns
    -------
    MeasuredData
        As :func:`validate`.
    """
    cat = read_oils_csv(oils) if isinstance(oils, (str, Path)) else oils
    return validate(read_table(path), cat, str(path))


# --------------------------------------------------------------------------- derivatives


def time_derivative(time_s: np.ndarray, x: np.ndarray, window_s: float) -> np.ndarray:
    """d x / d t of one run [unit of x per s]: Savitzky-Golay (quadratic) on a uniform
    record, central differences otherwise.

    Parameters
    ----------
    time_s : ndarray
        Sample times of one run [s], increasing.
    x : ndarray
        The signal [any unit].
    window_s : float
        Savitzky-Golay window [s] (odd number of samples, at least 5).

    Returns
    -------
    ndarray
        Derivative [unit of x per s] (zeros for fewer than 3 samples).

    References
    ----------
    A. Savitzky, M. J. E. Golay, Anal. Chem. 36:1627, 1964.
    """
    t = np.asarray(time_s, dtype=float)
    x = np.asarray(x, dtype=float)
    if len(t) < 3:
        return np.zeros_like(x)
    dt = np.diff(t)
    h = float(np.median(dt))
    win = int(round(window_s / h)) // 2 * 2 + 1
    win = max(win, 5)
    if len(t) >= win and np.all(np.abs(dt - h) <= 0.05 * h):
        return savgol_filter(x, win, 2, deriv=1, delta=h, mode="interp")
    return np.gradient(x, t)


def add_kinematics(frame: pd.DataFrame) -> pd.DataFrame:
    """Columns ``omega`` [rad/s], ``domega_dt`` [rad/s^2], ``dtemp_dt`` [K/s] per run.

    Parameters
    ----------
    frame : pandas.DataFrame
        Validated samples (``run``, ``time_s`` [s], ``speed_rpm`` [rpm], ``temp_C``).

    Returns
    -------
    pandas.DataFrame
        A copy with the three columns added (:func:`time_derivative` per run).
    """
    f = frame.copy()
    f["omega"] = rpm_to_rad_s(f["speed_rpm"].to_numpy())
    a = np.empty(len(f))
    dT = np.empty(len(f))
    for _, idx in f.groupby("run", sort=False).indices.items():
        t = f["time_s"].to_numpy()[idx]
        a[idx] = time_derivative(t, f["omega"].to_numpy()[idx], SPEED_DERIVATIVE_WINDOW_S)
        dT[idx] = time_derivative(t, f["temp_C"].to_numpy()[idx], TEMP_DERIVATIVE_WINDOW_S)
    f["domega_dt"] = a
    f["dtemp_dt"] = dT
    return f


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
        Time [s], speed [rpm], speed [rad/s], acceleration [rad/s^2].
    temp_C, dtemp_dt : ndarray
        Measured temperature [degC] and its rate [K/s].
    nu_m2_s, density_kg_m3 : ndarray
        Oil state at the measured temperature [m^2/s], [kg/m^3].
    nu_pm, rho_pm : tuple of two ndarray
        The same at temperature -/+ :data:`TEMP_STEP_K` [m^2/s], [kg/m^3] (NaN where
        the row overrides the oil table, so no temperature law is known).
    gap1_m : ndarray
        Region-1 clearance [m].
    viscous_W : ndarray
        Measured viscous power [W] (directly, or power minus the baseline).
    index : ndarray of int
        Rows of the validated frame the samples come from.
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

    @property
    def n(self) -> int:
        """Number of samples [-]."""
        return len(self.omega)

    def subset(self, mask: np.ndarray) -> Samples:
        """The samples where ``mask`` holds (run codes kept).

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
            if k == "run_names":
                kw[k] = v
            elif isinstance(v, tuple):
                kw[k] = tuple(x[mask] for x in v)
            else:
                kw[k] = v[mask]
        return Samples(**kw)


def oil_samples(data: MeasuredData, region1_gap_m: float,
                baselines: Mapping[float, Any] | None = None,
                pressure_gauge_Pa: float = 0.0, frame: pd.DataFrame | None = None) -> Samples:
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

    Returns
    -------
    Samples
        The oil-run samples (SI), viscous power [W].

    Raises
    ------
    InputError
        ``power_W`` data without baselines.
    """
    f = add_kinematics(data.frame) if frame is None else frame
    if data.kind == "power_W" and baselines is None:
        raise InputError("baselines", None, "power_W data need the oil-free baseline of each "
                         "roughness T", data.source)
    o = f[~f["oil_free"]]
    n = len(o)
    tK = o["temp_C"].to_numpy() + ZERO_CELSIUS_K
    nu = np.full(n, np.nan)
    rho = np.full(n, np.nan)
    nu_m, nu_p, rho_m, rho_p = (np.full(n, np.nan) for _ in range(4))
    uniq = {n: normalize_oil_name(n) for n in o["oil"].unique()}
    keys = o["oil"].map(uniq).to_numpy()
    for key in np.unique(keys):
        if key not in data.oils:
            continue
        sel = keys == key
        oil = data.oils[key]
        nu[sel], _, rho[sel] = oil.properties(tK[sel], pressure_gauge_Pa)
        nu_m[sel], _, rho_m[sel] = oil.properties(tK[sel] - TEMP_STEP_K, pressure_gauge_Pa)
        nu_p[sel], _, rho_p[sel] = oil.properties(tK[sel] + TEMP_STEP_K, pressure_gauge_Pa)
    if "nu_cSt" in o.columns:
        given = o["nu_cSt"].notna().to_numpy()
        nu[given] = cst_to_m2_s(o["nu_cSt"].to_numpy()[given])
        nu_m[given] = nu_p[given] = np.nan
    if "density_kg_m3" in o.columns:
        given = o["density_kg_m3"].notna().to_numpy()
        rho[given] = o["density_kg_m3"].to_numpy()[given]
        rho_m[given] = rho_p[given] = np.nan
    gap = np.full(n, float(region1_gap_m))
    if "gap_mm" in o.columns:
        given = o["gap_mm"].notna().to_numpy()
        gap[given] = mm_to_m(o["gap_mm"].to_numpy()[given])
    if data.kind == "power_W":
        y = o["power_W"].to_numpy().copy()
        for T, b in baselines.items():
            sel = o["roughness_T"].to_numpy() == T
            y[sel] -= b.predict(o["omega"].to_numpy()[sel], o["domega_dt"].to_numpy()[sel],
                                o["temp_C"].to_numpy()[sel])
    else:
        y = o["viscous_power_W"].to_numpy()
    names = tuple(dict.fromkeys(o["run"].tolist()))
    code = {r: i for i, r in enumerate(names)}
    return Samples(o["run"].to_numpy(), np.array([code[r] for r in o["run"]]), names,
                   o["oil"].to_numpy(), o["roughness_T"].to_numpy(), o["time_s"].to_numpy(),
                   o["speed_rpm"].to_numpy(), o["omega"].to_numpy(), o["domega_dt"].to_numpy(),
                   o["temp_C"].to_numpy(), o["dtemp_dt"].to_numpy(), nu, rho, (nu_m, nu_p),
                   (rho_m, rho_p), gap, y, o.index.to_numpy())
