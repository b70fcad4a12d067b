"""A design case written as a TOML file: atomically, with a stamp line.

The text is the model's (:func:`oilgap.model.io.case_write.dumps_toml` of
:func:`~oilgap.model.io.case_write.case_to_dict`: units in key names, 6 significant
digits, or every digit with ``exact``); this module writes it
(:func:`oilgap.studies.io.files.atomic_write_text`) with a first comment line saying
which oilgap wrote it, when and by which command
(:func:`oilgap.studies.io.provenance.stamp_line`). Read back, a written case equals the
original to the rounding (relative 5e-6 on each key's value); written ``exact``, it reads
back to the same floats (up to the mm/m conversion's last bit), so that the optimum ``oilgap
optimize --out`` writes, evaluated again, gives the loss the optimizer printed.
"""

from __future__ import annotations

from pathlib import Path

from oilgap.model.case import DesignCase
from oilgap.model.io.case_write import case_to_dict, dumps_toml
from oilgap.model.io.serialize import FULL_DIGITS, SIGNIFICANT_DIGITS

from .files import atomic_write_text
from .provenance import RunRecord, stamp_line


def write_case_toml(case: DesignCase, path: str | Path, header: bool = True,
                    run: RunRecord | None = None, exact: bool = False) -> Path:
    """Write a case as TOML that :func:`~oilgap.model.io.case_io.read_case_toml` reads back
    to the same case (to 6 significant digits; with ``exact`` to every digit).

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
    exact : bool
        Write every float with all its digits (repr-exact, :data:`FULL_DIGITS`), not
        rounded to 6 significant digits: a computed design (an optimum) read back is the
        design computed.

    Returns
    -------
    Path
        The file written.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    text = dumps_toml(case_to_dict(case), FULL_DIGITS if exact else SIGNIFICANT_DIGITS)
    return atomic_write_text(path, (stamp_line(run=run) + "\n" if header else "") + text)


__all__ = ["write_case_toml"]
