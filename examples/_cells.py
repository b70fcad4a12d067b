"""The cell builders of the example notebooks (:mod:`make_notebooks` is their source)."""

from __future__ import annotations

from nbformat.v4 import new_code_cell, new_markdown_cell

SETUP = '''\
import os
import tempfile
from pathlib import Path
{imports}
import oilgap as og

OUT = Path(os.environ.get("OILGAP_EXAMPLES_OUT") or tempfile.mkdtemp(prefix="oilgap-"))
OUT = OUT / "{name}"
OUT.mkdir(parents=True, exist_ok=True)
print("oilgap", og.__version__, "- outputs go to", OUT)'''


def setup(name: str, *imports: str) -> str:
    """The first code cell: imports and the output folder ``OUT`` of notebook ``name``."""
    lines = "".join(f"\n{i}" for i in imports)
    return SETUP.format(name=name, imports=lines + "\n" if imports else "")


def md(text: str):
    """A markdown cell."""
    return new_markdown_cell(text.strip("\n"))


def code(text: str):
    """A code cell."""
    return new_code_cell(text.strip("\n"))
