"""A saved loop model read for prediction: refused from a folder marked incomplete unless
asked, then checked against its schema (:func:`read_model`).

``oilgap loop`` writes ``loop.json`` into a result folder that holds the marker file
:data:`~oilgap.studies.io.files.MARKER` while it writes
(:class:`~oilgap.studies.io.result_folder.ResultFolder`): a ``loop.json`` beside the
marker is the output of a loop that failed or was killed, or that is still running.
Prediction refuses it with one line saying what to do; ``allow_incomplete`` (``oilgap
predict --allow-incomplete``, ``og.predict(..., allow_incomplete=True)``) uses it with a
warning line. The model itself is checked by
:func:`~oilgap.optim.calibration.model_io.load_model` (the schema of
:mod:`~oilgap.optim.calibration.model_schema`).
"""

from __future__ import annotations

import warnings
from pathlib import Path

from oilgap.model.errors import InputError, OilgapWarning
from oilgap.optim.calibration.model_io import FittedModel, load_model
from oilgap.studies.io.files import MARKER


def incomplete_marker(path: str | Path) -> Path | None:
    """The marker of the folder holding a saved model, if the folder is marked incomplete.

    Parameters
    ----------
    path : str or Path
        The model file (``loop.json``).

    Returns
    -------
    Path or None
        ``<folder>/INCOMPLETE`` when it exists, else None.
    """
    marker = Path(path).parent / MARKER
    return marker if marker.exists() else None


def read_model(path: str | Path, allow_incomplete: bool = False,
               option: str = "--allow-incomplete (og.predict: allow_incomplete=True)"
               ) -> FittedModel:
    """The model saved at ``path``: refused from a folder marked incomplete unless
    ``allow_incomplete`` (then a warning), then checked against its schema and ranges.

    Parameters
    ----------
    path : str or Path
        ``loop.json`` (or a bare model document).
    allow_incomplete : bool
        Use a model from a folder marked incomplete, with a warning.
    option : str
        How the caller asks for it (named in the refusal).

    Returns
    -------
    FittedModel

    Raises
    ------
    InputError
        The folder is marked incomplete (without ``allow_incomplete``); the file fails
        its schema.
    """
    if not isinstance(allow_incomplete, bool):
        raise InputError("allow_incomplete", allow_incomplete, "True or False")
    marker = incomplete_marker(path)
    if marker is not None:
        what = (f"its folder is marked incomplete ({marker}: the loop that wrote it failed, "
                "was killed or is still running)")
        if not allow_incomplete:
            raise InputError("--model", str(path), f"{what}: run oilgap loop again (with "
                             f"--force) and predict with its loop.json, or pass {option} to "
                             "use this model anyway")
        warnings.warn(OilgapWarning(f"--model {path}: {what}; predicting with it as asked "
                                    "(allow incomplete): it may be a partial fit"),
                      stacklevel=3)
    return load_model(path)


__all__ = ["incomplete_marker", "read_model"]
