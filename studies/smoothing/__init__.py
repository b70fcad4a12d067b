"""The smoothing study (``oilgap study smoothing``): Table 4 of the seed paper, the loss
against roughness T, and what smoothing a case's grooves saves.

:mod:`.study` runs it (``run``, ``SmoothingResult``), :mod:`.fit` fits the model to
Table 4, :mod:`.evidence` weighs Table 4's evidence on the film strength, :mod:`.case` is
the study on a case other than the seed rig, :mod:`.report` writes its files and
:mod:`.table4_holdout` holds groups of Table 4 out. The study's names are re-exported here
(``from oilgap.studies.smoothing import run``).
"""

from oilgap.studies.smoothing.study import (
    PAPER_LABEL,
    SmoothingResult,
    fit_comparison,
    loss_vs_T,
    paper_row,
    plateau_table,
    run,
    smoothing_study,
)

__all__ = ["PAPER_LABEL", "SmoothingResult", "fit_comparison", "loss_vs_T", "paper_row",
           "plateau_table", "run", "smoothing_study"]
