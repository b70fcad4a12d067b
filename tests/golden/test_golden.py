"""Every command prints the same numbers as the recorded golden outputs (to 1e-12 relative).

The golden outputs in ``tests/golden/data`` were recorded before the restructure of
issue 8; see ``golden.py`` for what is compared and how to regenerate them when a
change of output is intended.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

sys.path.insert(0, str(Path(__file__).resolve().parent))

import golden  # noqa: E402


def test_every_command_reproduces_its_golden_output(tmp_path):
    golden.produce(tmp_path)
    diffs = golden.compare_dirs(golden.DATA, tmp_path)
    assert not diffs, "\n".join(diffs[:40])
