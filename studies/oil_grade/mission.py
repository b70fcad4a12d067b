"""The oil-grade study's mission profile: read, checked, and its temperature matched to the
thermal mode (the oil's under ``none``/``film``, the sea's under ``bulk``/``full``).

A mission row holds (depth [m], temperature [degC], fraction [-]); its temperature is
written ``oil_temp_C`` or ``sea_temp_C`` (``[[mission]]`` keys, CSV columns). Under a mode
with the heat balance, the oil's temperature is a result: a row that gives one is refused
and asked for ``sea_temp_C`` (issue 26: it was silently taken for the sea's).
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import pandas as pd

from oilgap.model.case import MissionSegment
from oilgap.model.errors import InputError, check_finite
from oilgap.model.io.inputs import header_error, read_input_text
from oilgap.model.thermal_modes import ThermalMode, uses_balance

SEED_MISSION = (MissionSegment(0.0, 20.0, 0.05), MissionSegment(1500.0, 4.0, 0.10),
                MissionSegment(3000.0, 2.0, 0.85))
"""Default mission of the seed joint (it has none): fractions of the joint's running
time at (depth [m], oil temperature [degC]; the sea's under the thermal mode ``bulk``/``full``):
deck checks at 0 m and 20 degC (5 %), work on the way at 1500 m and 4 degC (10 %), work
at the rated 3000 m and 2 degC (85 %)."""


def parse_mission(mission) -> tuple[MissionSegment, ...]:
    """Validate a mission profile: MissionSegments, (depth_m, oil_temp_C, fraction)
    tuples, or a DataFrame with those columns. Fractions must sum to 1.

    Raises
    ------
    InputError
        Missing columns, bad values, no rows, fractions not summing to 1 (+-1e-6).
    """
    key = "oil_temp_C"
    if isinstance(mission, pd.DataFrame):
        key = "sea_temp_C" if "sea_temp_C" in mission.columns else "oil_temp_C"
        cols = ("depth_m", key, "fraction")
        missing = [c for c in cols if c not in mission.columns]
        extra = [c for c in mission.columns if c not in cols]
        if missing or extra:
            raise InputError("mission columns", list(mission.columns),
                             "required exactly depth_m, oil_temp_C (or sea_temp_C under the "
                             "thermal modes bulk/full), fraction", "oil-grade study")
        rows = list(mission[list(cols)].itertuples(index=False, name=None))
    else:
        rows = list(mission)
    if not rows:
        raise InputError("mission", "no rows", "needs at least one (depth_m, oil_temp_C, "
                         "fraction) row", "oil-grade study")
    segs = []
    for i, r in enumerate(rows):
        if isinstance(r, MissionSegment):
            segs.append(r)
            continue
        if len(r) != 3:
            raise InputError(f"mission[{i}]", r, "needs (depth_m, oil_temp_C, fraction)",
                             "oil-grade study")
        segs.append(MissionSegment(*(check_finite(k, v, f"mission row {i}") for k, v in
                                     zip(("depth_m", key, "fraction"), r, strict=True)),
                                   temp_key=key))
    total = sum(s.fraction for s in segs)
    if abs(total - 1.0) > 1e-6:
        raise InputError("mission fractions", round(total, 9), "must sum to 1",
                         "oil-grade study")
    return tuple(segs)


def read_mission_csv(path: str | Path) -> tuple[MissionSegment, ...]:
    """Read a UTF-8 mission CSV ``depth_m,oil_temp_C,fraction`` (see :func:`parse_mission`);
    a file that cannot be read, or whose header is not those columns once each, is
    refused naming the file and the reason, never its content."""
    p = Path(path)
    text = read_input_text(p, "--mission", "CSV file")
    header = [c.strip() for c in next(csv.reader(io.StringIO(text)), [])]
    temp = "sea_temp_C" if "sea_temp_C" in header else "oil_temp_C"
    err = header_error(p, header, ("depth_m", temp, "fraction"))
    if err is not None:
        raise err
    df = pd.read_csv(io.StringIO(text), skipinitialspace=True)
    df.columns = [str(c).strip() for c in df.columns]
    return parse_mission(df)


def mission_temps(segs: tuple[MissionSegment, ...], mode: str, what: str
              ) -> tuple[MissionSegment, ...]:
    """The mission's rows if their temperature is the one the mode takes: the sea's
    (``sea_temp_C``) under ``bulk``/``full``, where the oil's is the balance's result, the
    oil's (``oil_temp_C``) under ``none``/``film``; else the InputError that asks for the
    other key (issue 26: an oil temperature was silently used as the sea's)."""
    want = "sea_temp_C" if uses_balance(mode) else "oil_temp_C"
    bad = next((i for i, s in enumerate(segs) if s.temp_key != want), None)
    if bad is None:
        return segs
    why = ("the sea's temperature is the input there and the oil's is the heat balance's "
           "result" if uses_balance(mode) else "the oil's temperature is the input there")
    raise InputError(f"mission[{bad}].{segs[bad].temp_key}", segs[bad].oil_temp_C,
                     f"under thermal mode '{ThermalMode(mode).value}' {why}: write {want} in "
                     f"{what}",
                     "oil-grade study")
