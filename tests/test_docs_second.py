"""The second half of the documents' blocks (tests/test_docs.py explains what runs and
how; split so that the two halves run on both cores)."""

from __future__ import annotations

import pytest
from test_docs import run_doc, runnable_docs


@pytest.mark.parametrize("path", runnable_docs(True), ids=lambda p: p.name)
def test_doc_blocks_run(path, tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    count = run_doc(path, tmp_path)
    assert count["shell"] + count["python"] > 0
