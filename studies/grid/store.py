"""The resumable store: point keys and the ``points_<mode>.csv`` file of finished points.

Each grid row's key is a hash of (engine version, mode, base case, row
parameters); each finished chunk is appended to ``out_dir/points_<mode>.csv``
under those keys, and a rerun with the same folder computes only the points
not in that file.
"""

from __future__ import annotations

import hashlib
import json
import weakref
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.case_io import case_to_dict
from oilgap.model.errors import InputError
from oilgap.studies.grid.columns import ENGINE_VERSION, result_columns
from oilgap.studies.grid.schema import WHERE, is_missing

_FINGERPRINTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def case_fingerprint(case: DesignCase) -> str:
    """Short hash of everything in a case but its name (its TOML document); cached per
    (immutable) case object."""
    try:
        return _FINGERPRINTS[case]
    except KeyError:
        pass
    doc = case_to_dict(case)
    doc.pop("name", None)
    duty = case.duty_cycle  # the samples themselves (a cycle made in Python has no spec)
    doc["duty_cycle_samples"] = hashlib.sha1(np.ascontiguousarray(duty.time_s).tobytes()
                                             + np.ascontiguousarray(duty.omega_rad_s)
                                             .tobytes()).hexdigest()
    fp = hashlib.sha1(json.dumps(doc, sort_keys=True, default=str).encode()).hexdigest()[:16]
    _FINGERPRINTS[case] = fp
    return fp


def _canon(v: Any) -> Any:
    if is_missing(v):
        return None
    if isinstance(v, (float, int, np.floating, np.integer)) and not isinstance(v, bool):
        return repr(float(v))
    return str(v)


def point_keys(grid: pd.DataFrame, base: DesignCase, mode: str,
               extra: Mapping[str, Any] | None = None) -> list[str]:
    """Key of each grid row: hash of (engine version, mode, base case, row parameters)."""
    head = json.dumps([ENGINE_VERSION, mode, case_fingerprint(base),
                       sorted((extra or {}).items())], default=str)
    keys = []
    cols = [c for c in grid.columns if c != "label"]
    for rec in grid[cols].itertuples(index=False, name=None):
        body = json.dumps(sorted((c, _canon(v)) for c, v in zip(cols, rec, strict=True)
                                 if not is_missing(v)))
        keys.append(hashlib.sha1((head + body).encode()).hexdigest()[:20])
    return keys


def points_path(out_dir: str | Path, mode: str) -> Path:
    """``out_dir/points_<mode>.csv``."""
    return Path(out_dir) / f"points_{mode}.csv"


def load_points(path: Path, mode: str) -> pd.DataFrame:
    """The finished points stored at ``path`` (an empty frame if there is no file yet).

    Raises
    ------
    InputError
        The file holds no ``point_key`` column (oilgap did not write it).
    """
    if not path.is_file():
        return pd.DataFrame(columns=["point_key", *result_columns(mode)])
    try:
        df = pd.read_csv(path, dtype={"point_key": str, "status": str, "error": str,
                                      "warning": str, "thermal_mode": str})
    except pd.errors.EmptyDataError:
        return pd.DataFrame(columns=["point_key", *result_columns(mode)])
    if "point_key" not in df.columns:
        raise InputError("out_dir", str(path), "holds a points file oilgap did not write; "
                         "choose another --out", WHERE)
    return df


def finished_points(path: Path, mode: str, retry_failed: bool = False) -> dict[str, dict]:
    """The stored points by key; with ``retry_failed`` the failed ones are left out."""
    done: dict[str, dict] = {}
    for rec in load_points(path, mode).to_dict("records"):
        if retry_failed and rec.get("status") != "ok":
            continue
        done[str(rec["point_key"])] = rec
    return done


def append_points(path: Path, keys: list[str], recs: list[dict], mode: str) -> None:
    """Append finished points (one chunk) to the points file, with a header if new; a file
    written by an older engine (other columns) is rewritten with today's columns first."""
    cols = result_columns(mode)
    df = pd.DataFrame([{c: r.get(c) for c in cols} for r in recs], columns=list(cols))
    df.insert(0, "point_key", keys)
    new = not path.is_file() or path.stat().st_size == 0
    if not new:
        with path.open(encoding="utf-8") as f:
            header = f.readline().strip().split(",")
        if header != list(df.columns):
            old = load_points(path, mode).reindex(columns=df.columns)
            df = pd.concat([old, df], ignore_index=True)
            new = True
    df.to_csv(path, mode="w" if new else "a", header=new, index=False)
