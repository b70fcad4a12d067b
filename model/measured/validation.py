"""Validation of measured rig data: column checks, counted drop reasons, run checks.

The rules of the data format (:mod:`oilgap.model.measured.data`, whose
:func:`~oilgap.model.measured.data.validate` this is): every row that is dropped
is counted under the first reason that applies, in the order the checks run
(text columns, numbers, fluids, run consistency, time order, baselines). The
checks work on whole columns (numpy, pandas' grouped cumulative maxima) and on
the distinct values of the text columns, so a million rows cost well under a
second; no row is visited in Python.

References
----------
.. [1] ISO 3448:1992 (oil names of the catalogue), via :mod:`oilgap.model.oils`.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pandas as pd

from ..errors import InputError, OilgapWarning
from ..io.tables import numeric_column, text_cells, text_codes
from ..oils import Oil, builtin_fluids, normalize_oil_name
from .plausibility import check_units

REQUIRED_COLUMNS = ("run", "time_s", "speed_rpm", "temp_C", "oil", "roughness_T")
"""Columns of a time-series file (the synthetic rig's format)."""
CORE_COLUMNS = ("speed_rpm", "temp_C", "oil", "roughness_T")
"""Columns every file needs; ``time_s`` (then ``run`` too) makes it a time series."""
POWER_COLUMNS = ("power_W", "viscous_power_W")
OPTIONAL_COLUMNS = ("nu_cSt", "density_kg_m3", "gap_mm")
OIL_FREE = "none"
MIN_RUN_SAMPLES = 10
"""Fewest samples of a time-series run (steady points have no minimum)."""
TEMP_LIMITS_C = (-60.0, 300.0)
"""Temperatures outside this range [degC] are not oil temperatures: rows dropped."""
TEMP_STEP_K = 0.5
"""Half-step [K] of the central difference for dP/dT."""
PURPOSES = ("fit", "predict")
"""What the data are validated for: fitting (a power column) or prediction (none needed)."""
MAX_CV_GROUPS = 1000
"""Most groups leave-one-group-out validation accepts (one fold per group)."""
INTERNAL_COLUMNS = ("line", "oil_free", "run_code", "omega", "domega_dt", "dtemp_dt")
"""Columns validation and kinematics add to the frame."""
OVERRIDE_DEFAULT = {"nu_cSt": "the oils table's viscosity",
                    "density_kg_m3": "the oils table's density",
                    "gap_mm": "the case's region-1 clearance"}
"""What an empty cell of each per-row override column takes."""


DROP_WARN_SHARE = 0.25
"""Share of the rows read whose dropping the loop warns about on stderr [-]."""


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
        The usable rows, units in the column names (``time_s`` [s], zero without
        time; ``speed_rpm`` [rpm], ``temp_C`` [degC], ``power_W`` [W]), plus the
        file's line number in ``line`` (header = line 1; the input row is
        ``line - 2``), ``oil_free`` (bool) and ``run_code`` (index in the sorted
        run names).
    kind : str
        ``"power_W"`` or ``"viscous_power_W"``: which power column the file has
        (``"none"`` when validated for prediction).
    dropped : tuple of DropRecord
        Dropped rows by reason.
    n_read : int
        Rows read [-].
    source : str
        File name (for messages).
    ignored_columns : tuple of str
        Columns that are not part of the format (kept in ``frame``).
    oils : dict of str to Oil
        The oils table the names were checked against.
    has_time : bool
        False for steady operating points (no ``time_s``).
    drop_code : ndarray of int or None
        Per input row: the index in ``dropped`` of its reason, -1 if kept.
    notes : tuple of str
        What the tool filled in, e.g. oil rows with an empty ``gap_mm`` [-] that take
        the case's clearance (nothing is filled in silently).
    """

    frame: pd.DataFrame
    kind: str
    dropped: tuple[DropRecord, ...]
    n_read: int
    source: str
    ignored_columns: tuple[str, ...]
    oils: dict[str, Oil] = field(repr=False)
    has_time: bool = True
    drop_code: np.ndarray | None = field(default=None, repr=False)
    notes: tuple[str, ...] = ()

    @property
    def n_dropped(self) -> int:
        """Total number of dropped rows [-]."""
        return sum(d.count for d in self.dropped)

    def warn_if_many_dropped(self) -> None:
        """An OilgapWarning (one stderr line) when :data:`DROP_WARN_SHARE` or more of the
        rows read were dropped, naming the largest reasons: a quarter of the data lost is
        news (an oil not in the table, a unit slip), not a footnote in the report."""
        if not self.n_read or self.n_dropped < DROP_WARN_SHARE * self.n_read:
            return
        top = sorted(self.dropped, key=lambda d: -d.count)[:2]
        why = "; ".join(f"{d.count} {d.reason}" for d in top)
        warnings.warn(OilgapWarning(
            f"{self.source}: {self.n_dropped} of {self.n_read} rows "
            f"({100 * self.n_dropped / self.n_read:.0f} %) dropped ({why})"), stacklevel=2)

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

    def row_reasons(self) -> np.ndarray:
        """Each input row's drop reason (``""`` if kept).

        Returns
        -------
        ndarray of str
            One entry per row read [-].
        """
        names = np.array([d.reason for d in self.dropped] + [""], dtype=object)
        code = np.full(self.n_read, -1) if self.drop_code is None else self.drop_code
        return names[np.where(code < 0, len(names) - 1, code)]


# --------------------------------------------------------------------------- validation


def _check_columns(cols: list[str], where: str, purpose: str
                   ) -> tuple[str, tuple[str, ...], bool]:
    """(power column or "none", ignored columns, has_time) of a table's columns."""
    lower = {c.lower(): c for c in cols}
    has_time = "time_s" in cols
    need = list(CORE_COLUMNS) + (["run"] if has_time else [])
    missing = [c for c in need if c not in cols]
    if missing:
        hints = [f"{lower[m.lower()]!r} -> {m!r}" for m in missing if m.lower() in lower]
        hint = f" (column names are case-sensitive: {', '.join(hints)})" if hints else ""
        power = f" and one of {list(POWER_COLUMNS)}" if purpose == "fit" else ""
        raise InputError("columns", cols, f"missing {missing}; required {list(CORE_COLUMNS)}"
                         f"{power}, with run when time_s is given{hint}", where)
    present = [c for c in POWER_COLUMNS if c in cols]
    if purpose == "fit" and len(present) != 1:
        what = "both" if present else "neither"
        hints = [f"{lower[m.lower()]!r} -> {m!r}" for m in POWER_COLUMNS
                 if not present and m.lower() in lower]
        hint = f"; column names are case-sensitive: {', '.join(hints)}" if hints else ""
        raise InputError("columns", cols, f"exactly one of {list(POWER_COLUMNS)} is required "
                         f"({what} given{hint})", where)
    dup = sorted({c for c in cols if cols.count(c) > 1})
    if dup:
        raise InputError("columns", dup, "column names must be unique", where)
    known = set(REQUIRED_COLUMNS) | set(POWER_COLUMNS) | set(OPTIONAL_COLUMNS)
    kind = present[0] if purpose == "fit" else "none"
    return kind, tuple(c for c in cols if c not in known), has_time


class _Dropper:
    """The first drop reason of each row (-1: kept), applied to kept rows only."""

    def __init__(self, n: int):
        self.code = np.full(n, -1, dtype=np.int16)
        self.reasons: list[str] = []

    @property
    def alive(self) -> np.ndarray:
        return self.code < 0

    def drop(self, mask, reason: str) -> None:
        m = np.asarray(mask, dtype=bool) & (self.code < 0)
        if m.any():
            if reason not in self.reasons:
                self.reasons.append(reason)
            self.code[m] = self.reasons.index(reason)

    def result(self) -> tuple[DropRecord, ...]:
        counts = np.bincount(self.code[self.code >= 0], minlength=len(self.reasons))
        return tuple(DropRecord(r, int(counts[k]),
                                tuple(int(i) + 2 for i in np.flatnonzero(self.code == k)[:5]))
                     for k, r in enumerate(self.reasons))


def _run_mode(run: np.ndarray, val: np.ndarray, alive: np.ndarray) -> np.ndarray:
    """Per row, whether its value differs from the most frequent one of its run (among
    kept rows; a tie goes to the value met first in the file)."""
    out = np.zeros(len(run), bool)
    a = np.flatnonzero(alive)
    if not len(a):
        return out
    r = run[a].astype(np.int64)
    v, _ = pd.factorize(val[a])
    k = int(v.max()) + 1
    key = r * k + v
    uk, first, cnt = np.unique(key, return_index=True, return_counts=True)
    ur = uk // k
    order = np.lexsort((first, -cnt, ur))          # per run: most frequent, then earliest
    head = np.ones(len(order), bool)
    head[1:] = ur[order][1:] != ur[order][:-1]
    best = np.full(int(r.max()) + 1, -1, np.int64)
    best[ur[order][head]] = uk[order][head]
    out[a] = key != best[r]
    return out


def _time_problems(d: _Dropper, run: np.ndarray, t: np.ndarray, ordered: bool) -> None:
    """Duplicate and (if ``ordered``) non-increasing times within runs in file order, then
    runs too short."""
    a = np.flatnonzero(d.alive)
    o = np.lexsort((a, t[a], run[a]))
    sr, st = run[a][o], t[a][o]
    dup = np.zeros(len(a), bool)
    dup[1:] = (sr[1:] == sr[:-1]) & (st[1:] == st[:-1])
    mask = np.zeros(len(run), bool)
    mask[a[o][dup]] = True
    d.drop(mask, "duplicate time_s within run")
    if ordered:
        a = np.flatnonzero(d.alive)
        s = pd.Series(t[a])
        prev = s.groupby(run[a]).cummax().groupby(run[a]).shift(1)
        mask = np.zeros(len(run), bool)
        mask[a] = (prev.notna() & (s <= prev)).to_numpy()
        d.drop(mask, "time_s does not increase within run")
    counts = np.bincount(run[d.alive], minlength=int(run.max()) + 1 if len(run) else 0)
    d.drop(counts[run] < MIN_RUN_SAMPLES, f"run shorter than {MIN_RUN_SAMPLES} samples")


def _numbers(df: pd.DataFrame, d: _Dropper, kind: str, has_time: bool) -> dict:
    """The numeric columns as float64, rows dropped by the row-level number checks."""
    num = {}
    main = (("time_s",) if has_time else ()) + ("speed_rpm", "temp_C", "roughness_T") + \
        ((kind,) if kind in POWER_COLUMNS else ())
    for c in main:
        num[c] = numeric_column(df[c])
        d.drop(~np.isfinite(num[c]), f"{c} missing or not a finite number")
    for c in OPTIONAL_COLUMNS:
        if c in df.columns:
            v = num[c] = numeric_column(df[c])
            d.drop(text_cells(df[c]), f"{c} is text, not a number (leave the cell empty for "
                   f"{OVERRIDE_DEFAULT[c]})")
            d.drop(~np.isnan(v) & ~(np.isfinite(v) & (v > 0)), f"{c} not a positive finite number")
    d.drop(num["roughness_T"] < 1.0, "roughness_T < 1")
    lo, hi = TEMP_LIMITS_C
    t = num["temp_C"]
    d.drop((t < lo) | (t > hi), f"temp_C outside [{lo:g}, {hi:g}] degC")
    if has_time:
        d.drop(num["time_s"] < 0.0, "time_s < 0")
    return num


def _oil_checks(d: _Dropper, oil: np.ndarray, oil_names: np.ndarray, num: dict,
                catalogue: Mapping) -> np.ndarray:
    """Drop rows naming an unknown fluid without both overrides; returns oil-free per row."""
    lname = np.array([n.lower() for n in oil_names], dtype=object)
    free_n = lname == OIL_FREE
    known_n = np.array([normalize_oil_name(n) in catalogue for n in oil_names], bool)
    override = np.ones(len(oil), bool)
    for c in ("nu_cSt", "density_kg_m3"):
        override &= np.isfinite(num[c]) if c in num else False
    unknown = ~free_n[oil] & ~known_n[oil] & ~override
    for k in np.unique(oil[unknown & d.alive]):
        d.drop(unknown & (oil == k), f"oil {oil_names[k]!r} not in the oils table (and no "
               "nu_cSt + density_kg_m3)")
    return free_n[oil]


def _setup_runs(oil: np.ndarray, oil_names: np.ndarray, T: np.ndarray, gap: np.ndarray | None
                ) -> tuple[np.ndarray, np.ndarray]:
    """Default groups of steady points without ``run``: one per (oil, T, gap_mm)."""
    keys = pd.DataFrame({"oil": oil_names[oil], "T": T,
                         "gap": np.full(len(oil), np.nan) if gap is None else gap})
    g = keys.groupby(["oil", "T", "gap"], sort=True, dropna=False)
    code = g.ngroup().to_numpy().astype(np.int32)
    names = [f"{o} T={t:.12g}" + ("" if gap is None else
                                  f" gap_mm={'case' if np.isnan(x) else format(x, '.12g')}")
             for o, t, x in g.size().index]
    names = [n if names.count(n) == 1 else f"{n} #{k}" for k, n in enumerate(names)]
    return code, np.array(names, dtype=object)


def validate(df: pd.DataFrame, oils: dict[str, Oil] | None = None,
             source: str = "data", purpose: str = "fit") -> MeasuredData:
    """Validate a raw table and return the usable samples with a drop report.

    Parameters
    ----------
    df : pandas.DataFrame
        Raw table (columns as read, units in their names; values may be text).
    oils : dict of str to Oil, optional
        Oils table keyed by canonical name (default: the built-in oils and gases).
    source : str
        Name used in messages.
    purpose : {"fit", "predict"}
        "predict": no power column needed (any is ignored), no oil-free baseline
        needed, rows of a run in any order (sorted by time; fitting requires file
        order), oil-free rows dropped with their reason, and no error when nothing
        is left.

    Returns
    -------
    MeasuredData
        Usable rows (numeric columns as float: [s], [rpm], [degC], [W], [-]) and
        the drop report.

    Raises
    ------
    InputError
        Missing or ambiguous columns, or (fitting) no usable oil run left.
    """
    if purpose not in PURPOSES:
        raise InputError("purpose", purpose, "allowed: fit, predict", source)
    catalogue = builtin_fluids() if oils is None else oils
    kind, ignored, has_time = _check_columns([str(c) for c in df.columns], source, purpose)
    n_read = int(df.shape[0])
    d = _Dropper(n_read)
    run = run_names = None
    if "run" in df.columns:
        run, run_names = text_codes(df["run"])
        bad = np.array([n == "" or n.lower() == "nan" for n in run_names], bool)
        d.drop(bad[run], "missing run")
    oil, oil_names = text_codes(df["oil"])
    d.drop(np.array([n == "" or n.lower() == "nan" for n in oil_names], bool)[oil],
           "missing oil")
    num = _numbers(df, d, kind, has_time)
    oil_free = _oil_checks(d, oil, oil_names, num, catalogue)
    check_units(num, kind, has_time, run, d.alive & ~oil_free, purpose, source)
    if run is not None:
        for val, label in ((oil, "oil"), (num["roughness_T"], "roughness_T")):
            d.drop(_run_mode(run, val, d.alive), f"{label} differs from the rest of its run")
    if has_time:
        _time_problems(d, run, num["time_s"], purpose == "fit")
    _baseline_problems(d, kind, purpose, oil_free, num["roughness_T"])
    if purpose == "fit" and not (d.alive & ~oil_free).any():
        summary = "; ".join(f"{r.count} x {r.reason}" for r in d.result())
        raise InputError("data", source, f"no usable oil run remains (dropped: {summary})"
                         if summary else "holds no oil run (every row has oil = none)")
    keep = np.flatnonzero(d.alive)
    if run is None:
        run, run_names = _setup_runs(oil, oil_names, num["roughness_T"], num.get("gap_mm"))
    keys = (keep, num["time_s"][keep], run[keep]) if has_time else (keep, run[keep])
    rows = keep[np.lexsort(keys)]
    frame = _frame(df, rows, num, run, run_names, oil, oil_names, oil_free, has_time)
    return MeasuredData(
        frame=frame, kind=kind, dropped=d.result(), n_read=n_read, source=source,
        ignored_columns=ignored, oils=catalogue, has_time=has_time, drop_code=d.code,
        notes=_override_notes(num, d.alive & ~oil_free))


def _override_notes(num: dict, oil_rows: np.ndarray) -> tuple[str, ...]:
    """One note per override column with empty cells among the kept oil rows."""
    notes = []
    for c in OPTIONAL_COLUMNS:
        if c in num:
            n = int((np.isnan(num[c]) & oil_rows).sum())
            if n:
                notes.append(f"{c} empty in {n} of {int(oil_rows.sum())} oil rows: "
                             f"{OVERRIDE_DEFAULT[c]} used there")
    return tuple(notes)


def _baseline_problems(d: _Dropper, kind: str, purpose: str, oil_free: np.ndarray,
                       T: np.ndarray) -> None:
    """Oil rows without an oil-free run of their T (power_W); oil-free rows not needed."""
    if purpose == "predict":
        d.drop(oil_free, "oil-free row (no viscous loss to predict)")
    elif kind == "power_W":
        free_T = np.unique(T[d.alive & oil_free])
        nobase = d.alive & ~oil_free & ~np.isin(T, free_T)
        for t in np.unique(T[nobase]):
            d.drop(~oil_free & (T == t), f"no oil-free baseline run with roughness_T = {t:g}")
    else:
        d.drop(oil_free, "oil-free run (not needed: viscous_power_W is measured directly)")


def _categorical(codes: np.ndarray, names: np.ndarray) -> pd.Categorical:
    """Text column from codes, holding only the names that occur."""
    return pd.Categorical.from_codes(codes, categories=names).remove_unused_categories()


def _frame(df: pd.DataFrame, rows: np.ndarray, num: dict, run: np.ndarray,
           run_names: np.ndarray, oil: np.ndarray, oil_names: np.ndarray,
           oil_free: np.ndarray, has_time: bool) -> pd.DataFrame:
    """The kept rows in order ``rows``: converted columns, the others as read."""
    cols: dict[str, Any] = {}
    for c in df.columns:
        c = str(c)
        if c == "run":
            cols[c] = _categorical(run[rows], run_names)
        elif c == "oil":
            cols[c] = _categorical(oil[rows], oil_names)
        elif c in num:
            cols[c] = num[c][rows]
        else:
            cols[c] = df[c].to_numpy()[rows]
    if "run" not in cols:
        cols["run"] = _categorical(run[rows], run_names)
    if not has_time:
        cols["time_s"] = np.zeros(len(rows))
    cols["line"] = rows.astype(np.int64) + 2
    cols["oil_free"] = oil_free[rows]
    cols["run_code"] = run[rows]
    return pd.DataFrame(cols)
