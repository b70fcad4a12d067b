"""oilgap: viscous-loss design of the oil-filled clearances of deep-sea manipulator joints.

``import oilgap as og`` gives the notebook API (the façade over
:mod:`oilgap.model`, :mod:`oilgap.optim` and :mod:`oilgap.studies`); the
``oilgap`` command line calls exactly these functions.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("oilgap")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0+unknown"

__all__ = ["__version__"]
