"""Uncertainty study: the joint's loss as a distribution over uncertain inputs, and what
drives it (``oilgap study uncertainty``, ``og.uncertainty``).

:mod:`.study` runs it, :mod:`.indices` computes the Sobol' indices through SALib,
:mod:`.from_loop` reads a calibrated ``loop.json``'s fit as the inputs' joint law and
:mod:`.report` writes the tables, figures and summary.
"""

from .study import UncertaintyResult, run

__all__ = ["UncertaintyResult", "run"]
