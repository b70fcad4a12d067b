"""oilgap.studies: smoothing, Pareto, oil-grade and trade studies; the command line."""
