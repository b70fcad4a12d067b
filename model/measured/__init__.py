"""oilgap.model.measured: measured rig data: schema, validation, plausibility, rates.

:mod:`.data` (the data format, :func:`load_measured`, :class:`Samples`; its public names
are re-exported here), :mod:`.validation` (column and run checks, counted drops),
:mod:`.plausibility` (unit mistakes named) and :mod:`.kinematics` (speed and temperature
rates per run).
"""

from .data import *  # noqa: F403
from .data import __all__  # noqa: F401
