"""The resumable store: point keys and the ``points_<mode>.csv`` file of finished points.

Each grid row's key is a hash of (engine version, mode, base case, row
parameters); a rerun with the same folder computes only the points not in the
store. Crash-safe: each finished chunk is written atomically as a file of its own
in ``points_<mode>.chunks/`` (whole or absent, never a partial row), and the
chunks are folded into ``points_<mode>.csv`` (written atomically) at the end of a
run, or at the start of the next one after a kill. Before a run resumes, every row
is checked (:func:`repair_store`): a partial or invalid row (a file cut short by a
full disk, an older writer) is dropped, counted in a warning, and computed again.
"""

from __future__ import annotations

import contextlib
import csv
import hashlib
import io
import itertools
import json
import os
import time
import warnings
import weakref
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.compute as pc

from oilgap.model.case import DesignCase
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.io.case_write import case_to_dict
from oilgap.studies.grid.columns import ENGINE_VERSION, result_columns
from oilgap.studies.grid.schema import WHERE, is_missing
from oilgap.studies.grid.store_check import clean_rows, row_problem
from oilgap.studies.io.csv_text import float_texts
from oilgap.studies.io.files import OutputError, atomic_to_csv, atomic_write_text
from oilgap.studies.io.result_folder import LOCK_NAME

_FINGERPRINTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_SEQ = itertools.count()
_DTYPES = {"point_key": str, "status": str, "error": str, "warning": str, "thermal_mode": str}


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
    """Key of each grid row: hash of (engine version, mode, base case, row parameters).

    The hashed text of a row is ``json.dumps`` of its (column, value) pairs sorted by
    column, empty cells left out, numbers as ``repr(float(v))``; it is built column by
    column (numbers through :func:`~oilgap.studies.io.csv_text.float_texts`, one JSON text
    per distinct name, Arrow joins), then hashed row by row."""
    head = json.dumps([ENGINE_VERSION, mode, case_fingerprint(base),
                       sorted((extra or {}).items())], default=str)
    cols = sorted(c for c in grid.columns if c != "label")
    if not cols:
        texts = pa.array([head + "[]"] * len(grid), pa.large_string())
    else:
        empty = pa.scalar("", pa.large_string())
        joined = pc.binary_join_element_wise(*(_key_pieces(grid[c], c) for c in cols), empty)
        texts = pc.binary_join_element_wise(  # "[" + pairs (their first ", " cut) + "]"
            pa.scalar(head + "[", pa.large_string()), pc.utf8_slice_codeunits(joined, 2),
            pa.scalar("]", pa.large_string()), empty)
    sha1 = hashlib.sha1
    return [sha1(b).hexdigest()[:20] for b in texts.cast(pa.large_binary()).to_pylist()]


def _key_pieces(s: pd.Series, name: str) -> pa.Array:
    """``', ["name", "value"]'`` of each cell of a column as the row key's text holds it
    (``""`` for an empty cell; Arrow strings)."""
    lead = ", [" + json.dumps(name) + ", "
    kind = s.dtype.kind
    if kind in "fiu":
        v = s.to_numpy(dtype=float)
        text = pc.binary_join_element_wise(
            pa.scalar(lead + '"', pa.large_string()), float_texts(v).cast(pa.large_string()),
            pa.scalar('"]', pa.large_string()), pa.scalar("", pa.large_string()))
        nan = np.isnan(v)
        return pc.if_else(pa.array(nan), pa.scalar("", pa.large_string()), text) \
            if nan.any() else text
    if pd.api.types.infer_dtype(s, skipna=True) in ("string", "empty"):
        codes, uniq = pd.factorize(s, use_na_sentinel=True)
        table = pa.array([("" if is_missing(u) else lead + json.dumps(str(u)) + "]")
                          for u in uniq] + [""], pa.large_string())
        return table.take(pa.array(np.where(codes < 0, len(uniq), codes)))
    return pa.array([("" if is_missing(v) else lead + json.dumps(_canon(v)) + "]")
                     for v in s.tolist()], pa.large_string())


def points_path(out_dir: str | Path, mode: str) -> Path:
    """``out_dir/points_<mode>.csv``."""
    return Path(out_dir) / f"points_{mode}.csv"


def store_files(sub: str = "") -> tuple[str, ...]:
    """The files of a store in folder ``sub`` (``""`` or ``"grid/"``) as glob patterns
    relative to a result folder: what ``--force`` removes."""
    lock = (f"{sub}{LOCK_NAME}",) if sub else ()  # a subfolder's lock left by a killed run
    return (f"{sub}points_*.csv", f"{sub}points_*.chunks/*.csv",
            f"{sub}points_*.chunks/.*.tmp", f"{sub}results.csv", f"{sub}results.parquet",
            *lock)


def chunks_dir(path: Path) -> Path:
    """The folder of the chunk files not yet folded into ``path``:
    ``points_<mode>.chunks/`` beside it."""
    return path.with_name(path.stem + ".chunks")


# --------------------------------------------------------------------------- reading


@dataclass
class _Rows:
    """The rows of one points file: header fields, the valid data lines (each ending in a
    newline), their keys, the number of partial or invalid rows left out and why
    (``file:line: reason``)."""

    header: list[str] | None
    lines: list[str]
    dropped: int
    keys: list[str] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)


def _read_rows(path: Path, mode: str) -> _Rows:
    """The rows of a points file, checked line by line.

    A row is valid when it ends in a newline (a row cut short by a full disk or a kill
    does not), has as many fields as the header and reads as a fresh row of ``mode``
    would (:func:`oilgap.studies.grid.store_check.row_problem`: a key, a status
    ``ok``/``error``, every number of an ``ok`` row finite and physical).

    Raises
    ------
    InputError
        The header holds no ``point_key`` (oilgap did not write the file).
    """
    text = path.read_bytes().decode("utf-8", errors="replace")
    parts = text.split("\n")
    complete, tail = parts[:-1], parts[-1]
    if not complete:  # not even a whole header line: a file cut short at its start
        cut = [f"{path}:1: the file is cut short"] if tail.strip() else []
        return _Rows(None, [], len(cut), problems=cut)
    header = next(csv.reader([complete[0]]))
    if "point_key" not in header:
        raise InputError("out_dir", str(path), "holds a points file oilgap did not write; "
                         "choose another --out", WHERE)
    rows = _Rows(header, [], 0)
    columns = result_columns(mode)
    bad_header = _header_problem(header, columns)
    if bad_header:
        for no, line in enumerate(complete[1:], start=2):
            if line.strip():
                rows.dropped += 1
                rows.problems.append(f"{path}:{no}: {bad_header}")
    else:
        body = text[len(complete[0]) + 1:len(text) - len(tail) - 1]
        _check_lines(rows, complete[1:], path, mode, columns, body)
    if tail.strip():
        rows.dropped += 1
        rows.problems.append(f"{path}:{len(complete) + 1}: the row is cut short")
    return rows


def _header_problem(header: list[str], columns: tuple[str, ...]) -> str | None:
    """Why no row under ``header`` can be read as a result (a column twice, or one of the
    mode's result columns missing: a renamed column); None if they can."""
    twice = sorted({h for h in header if header.count(h) > 1})
    if twice:
        return f"the header holds {', '.join(twice)} twice"
    missing = [c for c in columns if c not in header]
    return f"the header has no {', '.join(missing[:3])} column" if missing else None


def _check_lines(rows: _Rows, body: list[str], path: Path, mode: str,
                 columns: tuple[str, ...], text: str) -> None:
    """Keep the valid lines of ``body`` (the data lines of ``path``) in ``rows``, count
    the others and say why. The plain lines (the header's number of fields, no quote,
    no carriage return) are read at once and checked column by column
    (:func:`~oilgap.studies.grid.store_check.clean_rows`); every other line, and every
    plain line those checks do not pass for certain, is checked on its own
    (:func:`_check_line`, :func:`~oilgap.studies.grid.store_check.row_problem`).
    ``text`` is ``"\\n".join(body)``."""
    if not body:
        return
    lines = np.array(body, dtype=object)
    clean = np.zeros(len(body), dtype=bool)
    keys = np.empty(len(body), dtype=object)
    plain = _plain_lines(body, len(rows.header), text)
    if plain.size:
        cells = _cells(rows.header, text if plain.size == len(body)
                       else "\n".join(lines[plain].tolist()), plain.size)
        if cells is not None:
            clean[plain] = clean_rows(cells, mode, columns)
            keys[plain] = cells["point_key"].astype(object).to_numpy()
    keep = clean.copy()
    for i in np.flatnonzero(~clean).tolist():
        line = body[i]
        if line.strip():
            before = len(rows.lines)
            _check_line(rows, line, f"{path}:{i + 2}", mode, columns)
            if len(rows.lines) > before:
                keep[i], keys[i] = True, rows.keys[-1]
    rows.lines = [x + "\n" for x in lines[keep].tolist()]
    rows.keys = keys[keep].tolist()


def _plain_lines(body: list[str], fields: int, text: str) -> np.ndarray:
    """Indices of the lines with ``fields`` fields, no quote, no carriage return, no NUL
    (``text``: the lines joined)."""
    arr = pa.array(body, pa.string())
    plain = pc.equal(pc.count_substring(arr, ","), fields - 1)
    for c in ('"', "\r", "\x00"):
        if c in text:
            plain = pc.and_(plain, pc.invert(pc.match_substring(arr, c)))
    return np.flatnonzero(np.asarray(plain.to_numpy(zero_copy_only=False), dtype=bool))


def _cells(header: list[str], lines: str, n: int) -> pd.DataFrame | None:
    """The cells of ``n`` plain lines (:func:`_plain_lines`, joined by newlines): text
    columns as text (empty: ``""``), numbers as read (empty: NaN); None if the reader sees
    another number of rows."""
    text = {c for c in _DTYPES if c in header}
    try:
        cells = pd.read_csv(io.StringIO(lines + "\n"), header=None, names=header,
                            dtype={c: str for c in text}, keep_default_na=False,
                            na_values={c: [""] for c in header if c not in text},
                            skip_blank_lines=False, engine="c")
    except (ValueError, pd.errors.ParserError):
        return None
    return cells if len(cells) == n else None


def _check_line(rows: _Rows, line: str, where: str, mode: str,
                columns: tuple[str, ...]) -> None:
    """Keep ``line`` in ``rows`` if it is a valid row, else count it and say why."""
    try:
        fields = next(csv.reader([line]))
    except csv.Error:
        fields = []
    if len(fields) != len(rows.header):
        why = f"{len(fields)} fields for {len(rows.header)} columns"
    else:
        cells = dict(zip(rows.header, fields, strict=True))
        why = row_problem(cells, mode, columns)
    if why:
        rows.dropped += 1
        rows.problems.append(f"{where}: {why}")
    else:
        rows.lines.append(line + "\n")
        rows.keys.append(fields[rows.header.index("point_key")])


def _drop_conflicts(rows: list[_Rows]) -> None:
    """Drop every row of a key stored twice with different contents (which one is the
    result cannot be told); identical copies (a crash between folding and removing the
    chunk files) are kept: they read the same."""
    seen: dict[str, str] = {}
    bad: set[str] = set()
    for r in rows:
        for k, line in zip(r.keys, r.lines, strict=True):
            if seen.setdefault(k, line) != line:
                bad.add(k)
    if not bad:
        return
    for r in rows:
        keep = [(k, x) for k, x in zip(r.keys, r.lines, strict=True) if k not in bad]
        gone = len(r.lines) - len(keep)
        if gone:
            r.dropped += gone
            r.problems.append(f"{gone} row(s) of key(s) {', '.join(sorted(bad)[:3])} "
                              "stored twice with different numbers")
        r.keys, r.lines = [k for k, _ in keep], [x for _, x in keep]


def _read_all(files: list[Path], mode: str) -> list[_Rows]:
    """The checked rows of each file, conflicting duplicates dropped."""
    rows = [_read_rows(f, mode) for f in files]
    _drop_conflicts(rows)
    return rows


def _chunk_files(path: Path) -> list[Path]:
    """The chunk files waiting to be folded into ``path``, oldest first."""
    d = chunks_dir(path)
    return sorted(d.glob("*.csv")) if d.is_dir() else []


def _frame(header: list[str], lines: list[str], mode: str) -> pd.DataFrame:
    """Rows (with their header) as a DataFrame with today's columns."""
    cols = ["point_key", *result_columns(mode)]
    if not lines:
        return pd.DataFrame(columns=cols)
    text = ",".join(_quote(h) for h in header) + "\n" + "".join(lines)
    df = pd.read_csv(io.StringIO(text), dtype=_DTYPES)
    return df.reindex(columns=cols) if list(df.columns) != cols else df


def _quote(field: str) -> str:
    return f'"{field}"' if any(c in field for c in ',"\n') else field


def read_store(path: Path, mode: str) -> tuple[pd.DataFrame, int]:
    """The finished points of a store (its file and any chunk files not yet folded in)
    and how many partial or invalid rows were left out.

    Raises
    ------
    InputError
        A file holds no ``point_key`` column (oilgap did not write it).
    """
    frames, dropped = [], 0
    for rows in _read_all(([path] if path.is_file() else []) + _chunk_files(path), mode):
        dropped += rows.dropped
        if rows.header is not None and rows.lines:
            frames.append(_frame(rows.header, rows.lines, mode))
    if not frames:
        return pd.DataFrame(columns=["point_key", *result_columns(mode)]), dropped
    return pd.concat(frames, ignore_index=True) if len(frames) > 1 else frames[0], dropped


def load_points(path: Path, mode: str) -> pd.DataFrame:
    """The finished points stored at ``path`` (an empty frame if there is no file yet);
    partial or invalid rows are left out (:func:`repair_store` says how many).

    Raises
    ------
    InputError
        The file holds no ``point_key`` column (oilgap did not write it).
    """
    return read_store(path, mode)[0]


def finished_points(path: Path, mode: str, retry_failed: bool = False) -> dict[str, dict]:
    """The stored points by key; with ``retry_failed`` the failed ones are left out."""
    done: dict[str, dict] = {}
    for rec in load_points(path, mode).to_dict("records"):
        if retry_failed and rec.get("status") != "ok":
            continue
        done[str(rec["point_key"])] = rec
    return done


# --------------------------------------------------------------------------- writing


def _clean_text(v: Any) -> Any:
    """A message cell on one line (a row of the store is one line)."""
    return " ".join(v.splitlines()) if isinstance(v, str) else v


def append_points(path: Path, keys: list[str], recs: list[dict], mode: str) -> Path:
    """Store finished points (one chunk) as a chunk file of their own, written
    atomically (temporary file, then rename) into ``points_<mode>.chunks/``: a crash,
    a kill or a full disk leaves the chunk whole or absent, never a partial row.
    :func:`fold_chunks` later folds the chunk files into ``path``. Returns the chunk
    file."""
    cols = result_columns(mode)
    df = pd.DataFrame(recs, columns=list(cols))  # a missing cell NaN: the same text
    for c in [c for c in df.columns if df[c].dtype.kind == "O"]:  # each message once
        if any(isinstance(u, str) and _clean_text(u) != u for u in pd.unique(df[c])):
            df[c] = df[c].map(_clean_text)
    df.insert(0, "point_key", keys)
    d = chunks_dir(path)
    try:
        d.mkdir(exist_ok=True)
    except OSError as e:
        raise OutputError(d, e) from None
    name = f"{time.time_ns():020d}-{os.getpid()}-{next(_SEQ):06d}.csv"
    return atomic_to_csv(df, d / name, neutralise=False, index=False)


def fold_chunks(path: Path, mode: str) -> int:
    """Fold the chunk files into ``path`` and drop partial or invalid rows; returns how
    many rows were dropped (:func:`fold_store` also says why).

    The new points file is written atomically (:func:`oilgap.studies.io.files.atomic_write`)
    before the chunk files are removed: a crash in between leaves rows twice, which
    reads the same (the last row of a key wins). A file written by an older engine
    (other columns) is rewritten with today's columns.
    """
    return len(fold_store(path, mode))


def fold_store(path: Path, mode: str) -> list[str]:
    """:func:`fold_chunks`, returning why each dropped row was dropped
    (``file:line: reason``, one entry a row but for conflicting duplicates)."""
    chunks = _chunk_files(path)
    files = ([path] if path.is_file() else []) + chunks
    rows = _read_all(files, mode)
    dropped = sum(r.dropped for r in rows)
    cols = ["point_key", *result_columns(mode)]
    same = all(r.header in (None, cols) for r in rows)
    if chunks or dropped or not same:
        if same:
            text = ",".join(cols) + "\n" + "".join(x for r in rows for x in r.lines)
            atomic_write_text(path, text)
        else:
            frames = [_frame(r.header, r.lines, mode) for r in rows if r.header is not None]
            atomic_to_csv(pd.concat(frames, ignore_index=True) if frames
                          else pd.DataFrame(columns=cols), path, neutralise=False, index=False)
    d = chunks_dir(path)
    for f in chunks + (sorted(d.glob(".*.tmp")) if d.is_dir() else []):
        with contextlib.suppress(OSError):
            f.unlink()
    with contextlib.suppress(OSError):
        d.rmdir()
    problems = [p for r in rows for p in r.problems]
    return problems + [f"{path}: a dropped row"] * (dropped - len(problems))


def repair_store(path: Path, mode: str) -> int:
    """Check a store before a run resumes it: chunk files of a run that was cut short
    folded in, partial or invalid rows dropped (an OilgapWarning says how many, and for
    the first three the file, the line and why: those points are computed again);
    returns that number."""
    if not path.is_file() and not chunks_dir(path).is_dir():
        return 0
    problems = fold_store(path, mode)
    dropped = len(problems)
    if dropped:
        shown = "; ".join(problems[:3]) + (f"; and {dropped - 3} more" if dropped > 3 else "")
        warnings.warn(OilgapWarning(
            f"{path}: {dropped} partial or invalid row{'s' if dropped > 1 else ''} "
            "dropped (a run cut short by a full disk, a crash or a kill, or a file edited "
            f"by hand): {shown}; {'they are' if dropped > 1 else 'it is'} computed again"),
            stacklevel=2)
    return dropped
