"""oilgap.model.effects: the candidate effects the seed's viscous-loss model leaves out.

:mod:`.library` (the library ``EFFECTS`` and the one builder of an ``EffectContext``),
:mod:`oilgap.model.effects.laws` (the effects' physical laws) and :mod:`.plausibility`
(each coefficient's plausible range with its basis). The library's public names, the laws and
ranges it
re-exports among them, are importable from here (``from oilgap.model.effects import
EFFECTS``).
"""

from .library import *  # noqa: F403
from .library import __all__, taylor_feature  # noqa: F401 (taylor_feature: not in __all__)
