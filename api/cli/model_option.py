"""``--model loop.json`` on evaluate, optimize and the studies: the option, the case with
the model folded in (:func:`oilgap._calibrated.with_model`, the one place), and the lines
each output prints about it (path, fit date, data, what was carried, the loss calibrated
beside uncalibrated)."""

from __future__ import annotations

import argparse

from oilgap._calibrated import model_lines, model_record, with_model
from oilgap.model.case import DesignCase
from oilgap.optim.calibration.calibrated_case import CalibratedCase


def add_model_option(p: argparse.ArgumentParser) -> None:
    """Register ``--model loop.json`` on a command that takes a CASE."""
    p.add_argument("--model", metavar="loop.json", help="a calibrated loop (oilgap loop): its "
                   "fitted friction law and the accepted effects that act on a design are "
                   "folded into the case; the output names the model")


def apply_model(case: DesignCase, args: argparse.Namespace
                ) -> tuple[DesignCase, CalibratedCase | None]:
    """The case with ``--model`` folded in (unchanged without it)."""
    return with_model(case, getattr(args, "model", None))


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
    print("\n".join(model_lines(cal, calibrated_W, uncalibrated_W, what)))


__all__ = ["add_model_option", "apply_model", "model_record", "report_model"]
