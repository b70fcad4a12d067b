"""``--model loop.json`` on evaluate, optimize and the studies: the option, the case with
the model folded in (:func:`oilgap._calibrated.with_model`, the one place), and the lines
each output prints about it (path, fit date, data, what was carried, the loss calibrated
beside uncalibrated)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from oilgap.model.case import DesignCase

if TYPE_CHECKING:  # the calibration (pandas, the loop) loads only with --model
    from oilgap.optim.calibration.calibrated_case import CalibratedCase


def add_model_option(p: argparse.ArgumentParser) -> None:
    """Register ``--model loop.json`` on a command that takes a CASE."""
    p.add_argument("--model", metavar="loop.json", help="a calibrated loop (oilgap loop): its "
                   "fitted friction law and the accepted effects that act on a design are "
                   "folded into the case; the output names the model")


def apply_model(case: DesignCase, args: argparse.Namespace
                ) -> tuple[DesignCase, CalibratedCase | None]:
    """The case with ``--model`` folded in (unchanged without it)."""
    if getattr(args, "model", None) is None and case.calibration_model is None:
        return case, None  # no model given, none referenced by [calibration]
    from oilgap._calibrated import with_model
    return with_model(case, args.model)


def base_loss_W(case: DesignCase) -> float:
    """Mean loss of a case as ``oilgap evaluate`` gives it by default [W]."""
    from oilgap._evaluate import evaluate
    return float(evaluate(case).total_mean_power_W)


def report_model(cal: CalibratedCase | None, json_mode: bool = False,
                 calibrated_W: float | None = None, uncalibrated_W: float | None = None
                 ) -> None:
    """Print the model's lines (text) after a command's output; nothing without a model.
    Without the two losses given: the given case's, evaluated with and without the model."""
    if cal is None or json_mode:
        return
    what = "loss"
    if calibrated_W is None:
        calibrated_W, uncalibrated_W = base_loss_W(cal.case), base_loss_W(cal.uncalibrated)
        what = "the given case's loss"
    from oilgap._calibrated import model_lines
    print("\n".join(model_lines(cal, calibrated_W, uncalibrated_W, what)))


def model_record(cal: CalibratedCase | None, calibrated_W: float | None = None,
                 uncalibrated_W: float | None = None) -> dict | None:
    """The model's JSON record (:func:`oilgap._calibrated.model_record`), loaded lazily."""
    from oilgap._calibrated import model_record as record
    return record(cal, calibrated_W, uncalibrated_W)


__all__ = ["add_model_option", "apply_model", "model_record", "report_model"]
