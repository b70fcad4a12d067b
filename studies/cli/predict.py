"""``oilgap predict``: the power of new rows with the model ``oilgap loop`` fitted
(arguments in :func:`oilgap.studies.cli.parsers.add_predict`).

The output is the input table with ``predicted_viscous_power_W`` (and
``predicted_power_W`` where a baseline was fitted) and ``prediction_note`` (why a
row has no prediction) added, written to a temporary file next to ``--out`` and
moved into place (``os.replace``), so an interrupted run never leaves half a
file; an existing ``--out`` is replaced only with ``--force``.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.measured_data import read_table
from oilgap.model.oils import read_oils_csv
from oilgap.optim.calibration.model_io import (
    PREDICTED_POWER,
    PREDICTED_VISCOUS,
    REASON,
    load_model,
)

OUT_SUFFIXES = (".csv", ".parquet", ".pq")


def _checked_out(path: str, force: bool) -> Path:
    out = Path(path)
    if out.suffix.lower() not in OUT_SUFFIXES:
        raise InputError("--out", str(out), f"must end in {', '.join(OUT_SUFFIXES)}")
    if not out.parent.is_dir():
        raise InputError("--out", str(out), f"directory {str(out.parent)!r} does not exist")
    if out.is_dir():
        raise InputError("--out", str(out), "is a directory; a file name is required")
    if out.exists() and not force:
        raise InputError("--out", str(out), "exists; pass --force to overwrite it")
    return out


def write_atomic(df: pd.DataFrame, out: Path) -> Path:
    """Write ``df`` (CSV or Parquet by suffix) to a temporary file, then move it to ``out``."""
    fd, tmp = tempfile.mkstemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.parent)
    os.close(fd)
    try:
        if out.suffix.lower() == ".csv":
            df.to_csv(tmp, index=False)
        else:
            try:
                df.to_parquet(tmp, index=False)
            except ImportError:
                raise InputError("--out", str(out), "writing Parquet needs pyarrow "
                                 "(pip install 'oilgap[parquet]')") from None
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp's 0600 -> what a plain write would give
        os.replace(tmp, out)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return out


def _summary(table: pd.DataFrame) -> list[str]:
    notes = table.loc[table[REASON] != "", REASON].value_counts()
    return [f"  {n:>6}  {r}" for r, n in notes.items()]


def run(args: argparse.Namespace) -> int:
    """Predict the rows of DATA and write them with the predictions; returns the exit code."""
    out = _checked_out(args.out, args.force)
    model = load_model(args.model)
    oils = read_oils_csv(args.oils) if args.oils else None
    raw = read_table(args.data)
    table = model.predict_table(raw, args.stage, oils, source=args.data)
    ok = int(table[PREDICTED_VISCOUS].notna().sum())
    if ok == 0:
        reasons = "; ".join(f"{n} x {r}" for r, n in table[REASON].value_counts().items())
        raise InputError("data", args.data, f"no row can be predicted ({reasons})")
    ext = table["outside_fitted_range"].to_numpy()
    if ext.any():
        lines = ", ".join(str(i + 2) for i in np.flatnonzero(ext)[:5])
        warnings.warn(OilgapWarning(f"{int(ext.sum())} row(s) outside the fitted range of "
                                    f"speed, temperature, viscosity, gap or T (lines {lines}"
                                    f"{', ...' if ext.sum() > 5 else ''}): extrapolated"),
                      stacklevel=1)
    res = raw.copy(deep=False)
    cols = [PREDICTED_VISCOUS] + ([PREDICTED_POWER] if PREDICTED_POWER in table else [])
    for c in cols + [REASON]:
        res[c] = table[c].to_numpy()
    write_atomic(res, out)
    print(f"predicted {ok} of {len(table)} rows ({args.stage}: {', '.join(cols)}); "
          f"wrote {out}")
    for line in _summary(table):
        print(line)
    return 0
