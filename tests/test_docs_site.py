"""The documentation site's index (docs/index.md) reaches every page of docs/: each
Markdown page is listed in one of its toctrees, and each entry names a page that exists.

A cheap stand-in for the site build, which CI runs (``python -m sphinx -W``, .ci/run) and
which would fail on an orphaned page; this test says which page, in a second."""

from __future__ import annotations

import re
from pathlib import Path

DOCS = Path(__file__).resolve().parents[1] / "docs"
BUILT = {"_build", "generated", "examples", "jupyter_execute"}
"""Folders the build writes (ignored by git): not pages of the source."""

TOCTREE = re.compile(r"^```\{toctree\}[^\n]*\n(.*?)^```", re.S | re.M)


def toctree_entries(text: str) -> list[str]:
    """The page names of a Markdown text's ``{toctree}`` blocks (option lines left out)."""
    return [ln.strip() for body in TOCTREE.findall(text) for ln in body.splitlines()
            if ln.strip() and not ln.lstrip().startswith(":")]


def pages() -> set[str]:
    """The Markdown pages of docs/ as Sphinx names them (path without ``.md``)."""
    return {p.relative_to(DOCS).with_suffix("").as_posix() for p in DOCS.rglob("*.md")
            if not BUILT & set(p.relative_to(DOCS).parts[:-1])}


def test_toctree_parser_on_a_written_index():
    text = ("# t\n\n```{toctree}\n:caption: Guide\n:maxdepth: 2\n\na\nsub/b\n```\n\n"
            "```python\nnot_a_page\n```\n```{toctree}\nc\n```\n")
    assert toctree_entries(text) == ["a", "sub/b", "c"]


def test_index_lists_every_page_and_only_pages():
    listed = toctree_entries((DOCS / "index.md").read_text())
    assert len(listed) == len(set(listed)), "a page listed twice"
    found = pages() - {"index"}
    orphans = sorted(found - set(listed))
    assert not orphans, f"docs pages in no toctree of docs/index.md: {orphans}"
    missing = sorted(set(listed) - found)
    assert not missing, f"docs/index.md lists pages that do not exist: {missing}"
