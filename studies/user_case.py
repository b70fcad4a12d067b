"""The user's case first: is a case the seed joint, and how do outputs name its design.

The studies (Pareto, oil grade, smoothing) compare against the seed joint only when the
case IS the seed (grooved or smoothed: the same TOML document but for the name); on any
other case they show that case alone, labelled from its name.
"""

from __future__ import annotations

from dataclasses import replace

from oilgap.model.case import DesignCase
from oilgap.model.io.case_io import seed_case
from oilgap.studies.grid.store import case_fingerprint

_SEED_FINGERPRINTS: list[str] = []


def seed_fingerprints() -> tuple[str, str]:
    """Fingerprints of the seed joint, grooved and smoothed (computed once)."""
    if not _SEED_FINGERPRINTS:
        _SEED_FINGERPRINTS.extend(case_fingerprint(seed_case(s)) for s in (False, True))
    return _SEED_FINGERPRINTS[0], _SEED_FINGERPRINTS[1]


def is_seed_case(case: DesignCase | None) -> bool:
    """True for None (the seed by default) and for the seed joint, grooved or smoothed
    (its document but for the name, a ``[thermal]`` table and ``[friction] transition``:
    geometry, oil, operating point, cycle, motor, bounds)."""
    if case is None:
        return True
    if case.thermal is not None:
        case = replace(case, thermal=None)
    if case.friction.transition != "reynolds":  # the seed rig under either transition
        case = replace(case, friction=replace(case.friction, transition="reynolds"))
    return case_fingerprint(case) in seed_fingerprints()


def design_label(case: DesignCase) -> str:
    """How an output names the case's own design: ``this design (<case name>)``."""
    return f"this design ({case.name})"


__all__ = ["design_label", "is_seed_case", "seed_fingerprints"]
