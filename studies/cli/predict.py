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
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.errors import InputError, OilgapWarning
from oilgap.model.files import atomic_to_csv, atomic_to_parquet, check_out_file
from oilgap.model.measured_data import read_table
from oilgap.model.oils import read_oils_csv
from oilgap.optim.calibration.model_io import (
    PREDICTED_POWER,
    PREDICTED_VISCOUS,
    REASON,
    load_model,
)

OUT_SUFFIXES = (".csv", ".parquet", ".pq")


def write_table(df: pd.DataFrame, out: Path) -> Path:
    """Write ``df`` (CSV or Parquet by suffix) atomically (a temporary file next to
    ``out``, then renamed)."""
    if out.suffix.lower() == ".csv":
        return atomic_to_csv(df, out, index=False)
    try:
        return atomic_to_parquet(df, out, index=False)
    except ImportError:
        raise InputError("--out", str(out), "writing Parquet needs pyarrow "
                         "(pip install 'oilgap[parquet]')") from None


def _summary(table: pd.DataFrame) -> list[str]:
    notes = table.loc[table[REASON] != "", REASON].value_counts()
    return [f"  {n:>6}  {r}" for r, n in notes.items()]


def run(args: argparse.Namespace) -> int:
    """Predict the rows of DATA and write them with the predictions; returns the exit code."""
    out = check_out_file(args.out, args.force, suffixes=OUT_SUFFIXES)
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
    write_table(res, out)
    print(f"predicted {ok} of {len(table)} rows ({args.stage}: {', '.join(cols)}); "
          f"wrote {out}")
    for line in _summary(table):
        print(line)
    g = model.laws[args.stage].gamma
    print(f"gamma       {g:g} (groove exponent of Eq. 8; from: the {args.stage} model of "
          f"{args.model}, as oilgap loop calibrated it)")
    return 0
