"""The README's five-minute tour runs as written: its case file and every Python block,
in a fresh folder, printing the numbers its comments promise (a user copies them)."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")

README = Path(__file__).resolve().parents[1] / "README.md"
TEXT = README.read_text()
CASE = re.search(r"`my_joint.toml`:\n\n```toml\n(.*?)```", TEXT, re.S).group(1)
BLOCKS = re.findall(r"```python\n(.*?)```", TEXT, re.S)

PROMISED = [  # what each block prints, as its comments say
    ["141.3 W none", "9.155", "53.5 W", "49.453 W"],
    ["0.800000  4.75    141.40", "1.185106  1.00     50.04"],
    ["60 98.90 mm W", "1.185106     50.041298", "0.400000     93.824761"],
    ["VG15 VG22"],
    ["('seal_coulomb_friction', 0.04027)", "'before': 5.238", "'after': 1.125"],
]


def test_the_tour_has_five_blocks():
    assert len(BLOCKS) == len(PROMISED) == 5


@pytest.mark.parametrize("k", range(5))
def test_readme_block_runs_and_prints_what_it_promises(k, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "my_joint.toml").write_text(CASE)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(BLOCKS[k], f"README block {k + 1}", "exec"), {"__name__": "__readme__"})
    printed = out.getvalue()
    for text in PROMISED[k]:
        assert text in printed, (text, printed)
    matplotlib.pyplot.close("all")
