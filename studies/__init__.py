"""oilgap.studies: the studies (smoothing, Pareto, oil grade, sweep), the grid engine
(:mod:`oilgap.studies.grid`), the loop report, the synthetic rig, the report/figure
convention (:mod:`oilgap.studies.reporting`) and the command line
(:mod:`oilgap.cli`)."""
