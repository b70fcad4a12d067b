"""The measured-data loop's outputs (``oilgap loop``): :mod:`.report` (terminal summary,
``loop.json``, ``report.md``) and :mod:`.figures` (its figures). The loop itself is
:class:`oilgap.optim.calibration.estimator.LoopEstimator`."""
