"""oilgap: viscous-loss design of the oil-filled clearances of deep-sea manipulator joints.

``import oilgap as og`` gives the notebook API (the façade over
:mod:`oilgap.model`, :mod:`oilgap.optim` and :mod:`oilgap.studies`); the
``oilgap`` command line calls exactly these functions::

    import oilgap as og
    ev = og.evaluate("my_joint.toml", thermal="none")   # og.Evaluation
    ev.to_frame(); ev.plot(); print(ev)
    opt = og.optimize("my_joint.toml", starts=8)         # og.Optimization

Each name is loaded on first use (:data:`EXPORTS`), so ``import oilgap`` stays fast
and loads neither pandas, CasADi nor dask. The user guide is ``docs/api.md``.
"""

from __future__ import annotations

import importlib
from importlib.metadata import PackageNotFoundError, version
from typing import Any

try:
    __version__ = version("oilgap")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0+unknown"

EXPORTS: dict[str, str] = {
    "read_case": "oilgap._evaluate",
    "seed_case": "oilgap._evaluate",
    "read_oils": "oilgap._evaluate",
    "write_case": "oilgap._evaluate",
    "evaluate": "oilgap._evaluate",
    "optimize": "oilgap._optimize",
    "pareto": "oilgap._studies",
    "oil_grade": "oilgap._studies",
    "smoothing": "oilgap._studies",
    "sweep": "oilgap._studies",
    "uncertainty": "oilgap._uncertainty",
    "Loop": "oilgap._loop",
    "predict": "oilgap._loop",
    "synth": "oilgap._loop",
    "read_measured": "oilgap._loop",
    "plan": "oilgap._plan",
    "synth_plan": "oilgap._plan",
    "progress_bars": "oilgap._progress",
    "Evaluation": "oilgap._results",
    "Optimization": "oilgap._results_design",
    "RobustOptimization": "oilgap._results_robust",
    "Pareto": "oilgap._results_studies",
    "OilGrade": "oilgap._results_studies",
    "Smoothing": "oilgap._results_studies",
    "Sweep": "oilgap._results_sweep",
    "Uncertainty": "oilgap._uncertainty",
    "InputError": "oilgap.model.errors",
    "ArgumentError": "oilgap.model.errors",
    "InfeasibleError": "oilgap.model.errors",
    "SolverError": "oilgap.model.errors",
    "NotFittedError": "oilgap.model.errors",
}
"""The façade's names and the module each is loaded from on first use (the one table, as
the command line's dispatch table)."""

__all__ = ["__version__", *EXPORTS]


def __getattr__(name: str) -> Any:
    """``og.<name>``: loaded from its module in :data:`EXPORTS` on first use."""
    if name not in EXPORTS:
        raise AttributeError(f"module 'oilgap' has no attribute {name!r}")
    value = getattr(importlib.import_module(EXPORTS[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    """``dir(og)``: the public names only (:data:`__all__`), loaded or not."""
    return sorted(__all__)
