"""oilgap.model.bearing: a rolling bearing running in oil.

:mod:`.friction` (``BearingSpec``, the bearing's moments, power, torque and cycle mean in
SI, validity; its public names are re-exported here),
:mod:`oilgap.model.bearing.laws` (the published laws in catalogue units), :mod:`.catalogue`
(designations, product rows, the ``[bearing]``
table to a spec) and :mod:`.band` (every published model at one oil state).
"""

from .friction import *  # noqa: F403
from .friction import __all__  # noqa: F401
