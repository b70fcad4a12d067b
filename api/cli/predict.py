"""``oilgap predict``: the power of new rows with the model ``oilgap loop`` fitted
(arguments in :func:`oilgap.cli.parsers.add_predict`); a thin layer over
:func:`oilgap._loop.predict` (``og.predict``).

The output is the input table with ``predicted_viscous_power_W`` (and
``predicted_power_W`` where a baseline was fitted) and ``prediction_note`` (why a
row has no prediction) added, written to a temporary file next to ``--out`` and
moved into place (``os.replace``), so an interrupted run never leaves half a
file; an existing ``--out`` is replaced only with ``--force``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import pandas as pd

from oilgap._loop import predict
from oilgap.model.errors import InputError
from oilgap.optim.calibration.model_io import REASON
from oilgap.studies.io.files import atomic_to_csv, atomic_to_parquet, check_out_file

OUT_SUFFIXES = (".csv", ".parquet", ".pq")

THERMAL_WHY = {
    "none": "every term at the measured oil temperature, as the loop calibrated it",
    "film": "the film heated above the measured oil by the loop's calibrated film_heating",
}
"""What each thermal mode of a fitted model means (the header line of ``oilgap predict``)."""


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


MEASURED = (("viscous_power_W", "predicted_viscous_power_W"), ("power_W", "predicted_power_W"))
"""(measured column, predicted column) pairs scored when the input has the measured one."""


def error_lines(table: pd.DataFrame) -> list[str]:
    """RMSE and bias (predicted - measured) [W] where the input carries measured power."""
    out = []
    for meas, pred in MEASURED:
        if meas not in table or pred not in table:
            continue
        d = (pd.to_numeric(table[pred], errors="coerce")
             - pd.to_numeric(table[meas], errors="coerce")).dropna()
        if len(d):
            out.append(f"error       {meas}: RMSE {float((d * d).mean()) ** 0.5:.4g} W, bias "
                       f"{float(d.mean()):+.4g} W (predicted - measured) over {len(d)} rows")
    return out


def run(args: argparse.Namespace) -> int:
    """Predict the rows of DATA and write them with the predictions; returns the exit code."""
    out = check_out_file(args.out, args.force, suffixes=OUT_SUFFIXES)
    res = predict(args.model, args.data, stage=args.stage, oils=args.oils,
                  allow_incomplete=args.allow_incomplete)
    write_table(res, out)
    print(f"predicted {res.attrs['predicted']} of {len(res)} rows ({args.stage}: "
          f"{', '.join(res.attrs['columns'])}); wrote {out}")
    for line in _summary(res) + error_lines(res):
        print(line)
    film = ""
    if "film_strength" in res.attrs:
        film = (f", film strength s = {res.attrs['film_strength']:.4g} of the smooth-film "
                f"theory, wall condition w = {res.attrs['wall_floating']:g}")
    print(f"thermal     {res.attrs['thermal_mode']} (the mode recorded in {args.model}: "
          f"{THERMAL_WHY[res.attrs['thermal_mode']]}{film})")
    print(f"gamma       {res.attrs['gamma']:g} (groove exponent of Eq. 8; from: the "
          f"{args.stage} model of {args.model}, as oilgap loop calibrated it)")
    return 0
