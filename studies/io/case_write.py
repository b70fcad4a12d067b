"""A design case written as a TOML file: atomically, with a stamp line.

The text is the model's (:func:`oilgap.model.io.case_write.dumps_toml` of
:func:`~oilgap.model.io.case_write.case_to_dict`: units in key names, 6 significant
digits); this module writes it (:func:`oilgap.studies.io.files.atomic_write_text`) with a
first comment line saying which oilgap wrote it, when and by which command
(:func:`oilgap.studies.io.provenance.stamp_line`). Read back, a written case equals the
original to the rounding (relative 5e-6 on each key's value).
"""

from __future__ import annotations

from pathlib import Path

from oilgap.model.case import DesignCase
from oilgap.model.io.case_write import case_to_dict, dumps_toml

from .files import atomic_write_text
from .provenance import RunRecord, stamp_line


def write_case_toml(case: DesignCase, path: str | Path, header: bool = True,
                    run: RunRecord | None = None) -> Path:
    """Write a case as TOML that :func:`~oilgap.model.io.case_io.read_case_toml` reads back
    to the same case (to 6 significant digits).

    Parameters
    ----------
    case : DesignCase
        The case (SI inside; written with units in the key names, e.g. [mm]).
    path : str or Path
        Output file; parent directories are created.
    header : bool
        Start with the comment line ``# written by oilgap X on DATE by: COMMAND``.
    run : RunRecord, optional
        The run named in that line (None: a run from Python, ``sys.argv``).

    Returns
    -------
    Path
        The file written.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    text = dumps_toml(case_to_dict(case))
    return atomic_write_text(path, (stamp_line(run=run) + "\n" if header else "") + text)


__all__ = ["write_case_toml"]
