"""``og.progress_bars()``: the command line's progress bars around façade calls.

The computing layers report their progress (:mod:`oilgap.optim.progress`); the command
line draws it on a terminal (:func:`oilgap.studies.progress.shown`). In Python nothing
is drawn unless asked::

    with og.progress_bars():
        opt = og.optimize("my_joint.toml", robust="p95")
"""

from __future__ import annotations

import contextlib

from oilgap._checks import Arg, checked
from oilgap.studies.progress import shown


@checked(enabled=Arg((bool, "bool_"), "True, False or None (on a terminal only)",
                     optional=True))
def progress_bars(enabled: bool | None = True) -> contextlib.AbstractContextManager:
    """A context inside which long façade calls (multi-start and robust ``optimize``, the
    studies, ``Loop.fit``) draw tqdm bars on stderr, as ``oilgap`` does on a terminal.

    Parameters
    ----------
    enabled : bool or None
        True (default): draw (a notebook's stderr is no terminal); None: only when stderr
        is a terminal; False: never.

    Returns
    -------
    context manager
    """
    return shown(enabled)


__all__ = ["progress_bars"]
