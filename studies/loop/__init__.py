"""The measured-data loop's outputs (``oilgap loop``): :mod:`~oilgap.studies.loop.report`
(terminal summary, ``loop.json``, ``report.md``) and :mod:`~oilgap.studies.loop.figures` (its
figures). The loop itself is
:class:`oilgap.optim.calibration.estimator.LoopEstimator`."""
