"""Robust design study: the nominal and the robust optimum side by side, an independent
Monte Carlo of both, the 2N stability check and the nominal-vs-statistic Pareto
(:mod:`~oilgap.studies.robust.design`)."""

from .design import RobustDesign, RobustSettings, robust_design, robust_pareto

__all__ = ["RobustDesign", "RobustSettings", "robust_design", "robust_pareto"]
