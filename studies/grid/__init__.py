"""The grid engine: a grid of parameter combinations in, a DataFrame of results out.

One room per responsibility (import from the module; this package imports
nothing, so that :mod:`~oilgap.studies.grid.columns` stays cheap for the
command line):

* :mod:`~oilgap.studies.grid.columns`: the parameter and result columns (plain data);
* :mod:`~oilgap.studies.grid.schema`: grid checks (:func:`validate_grid`,
  :func:`read_grid_csv`) and one row applied to a case (:func:`apply_params`);
* :mod:`~oilgap.studies.grid.evaluate`: vectorised evaluation (:func:`evaluate_cases`);
* :mod:`~oilgap.studies.grid.optimize`: one design NLP per row
  (:func:`solve_design_point`, the per-process cache of DesignProblems);
* :mod:`~oilgap.studies.grid.store`: case fingerprint, point keys, the resumable
  ``points_<mode>.csv``;
* :mod:`~oilgap.studies.grid.runner`: :func:`run_grid` (chunks, worker pool, progress).
"""
