"""Every fenced shell and Python block in docs/ runs as written (issue 18), as
tests/test_readme.py does for the README.

Per document, in one fresh folder and in order:

* a ``toml`` or ``csv`` block becomes a file when the document names it: the marker
  ``<!-- file: NAME -->`` before it, or a line ending in ```NAME`:`` just above it;
* ``<!-- test-setup: COMMANDS -->`` (invisible in the rendered page) runs COMMANDS in
  the folder first: the files a reader brings (their rig's CSV) made from oilgap's own;
  ``$REPO`` is the repository;
* a ``bash``/``sh`` block runs line by line in bash (``set -e``), a ``console`` block
  runs its ``$`` lines; each must exit 0, or 2 where the block shows
  ``oilgap: error:``; ``oilgap`` and ``python`` are this interpreter's;
* ``python`` blocks run in one namespace per document;
* a block after ``<!-- no-test: REASON -->`` is not run; the reasons are counted and
  listed (``pytest -s tests/test_docs.py -k reasons``); so are shell lines that run the
  test suite or install the package, which this test cannot do inside itself.

Numbers are checked only where a comment of the block promises one (:data:`PROMISED`):
the blocks must run; the printed tables of the docs are the code's output at the time
of writing and are not compared.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import matplotlib
import matplotlib.pyplot as plt
import pytest

matplotlib.use("Agg")  # before pyplot draws: figures go to files

ROOT = Path(__file__).resolve().parents[1]
DOCS = sorted(p for p in (ROOT / "docs").rglob("*.md"))
SHELL = {"bash", "sh", "shell", "console"}
FILES = {"toml", "csv"}
FENCE = re.compile(r"^(?P<ind>[ \t]*)```(?P<lang>[\w-]*)[^\n]*\n(?P<body>.*?)^(?P=ind)```[ \t]*$",
                   re.S | re.M)
MARKER = re.compile(r"<!--\s*(no-test|file|test-setup):\s*(.*?)\s*-->\s*\Z", re.S)
NAMED = re.compile(r"`([\w.-]+\.(?:toml|csv))`:\s*\Z")
NOT_HERE = [  # shell lines this test does not run inside itself, with the reason
    (re.compile(r"pip install"), "installs the package (CI's .ci/run does this)"),
    (re.compile(r"python -m pytest|(^|\s)pytest\s"), "runs the test suite (CI runs it)"),
    (re.compile(r"(^|\s)ruff "), "lint (CI runs it)"),
]

PROMISED = {  # (document, python block index in it): texts the block's comments promise
    ("case-file.md", 0): ["2.0 34.98642872"],
    ("getting-started.md", 0): ["134.6243"],
}


@dataclass
class Block:
    doc: str
    line: int
    lang: str
    body: str
    skip: str | None
    file: str | None
    setup: str | None


def blocks(path: Path) -> list[Block]:
    """The fenced blocks of a document with the markers just before each."""
    return parse(path.read_text(), path.name)


def parse(text: str, name: str) -> list[Block]:
    """The fenced blocks of a Markdown text with the markers just before each."""
    out, end = [], 0
    for m in FENCE.finditer(text):
        gap = text[end:m.start()]
        end = m.end()
        skip = file = setup = None
        g = gap
        while (mk := MARKER.search(g)) is not None:  # markers stacked before the block
            kind, arg = mk.group(1), mk.group(2)
            if kind == "no-test":
                skip = arg
            elif kind == "file":
                file = arg
            else:
                setup = arg
            g = g[:mk.start()]
        if file is None and (nm := NAMED.search(gap)):
            file = nm.group(1)
        lang = m.group("lang").lower()
        body = "\n".join(ln[len(m.group("ind")):] for ln in m.group("body").splitlines())
        out.append(Block(name, text.count("\n", 0, m.start()) + 1, lang, body, skip, file,
                         setup))
    return out


def _skipped_line(line: str) -> str | None:
    for pat, why in NOT_HERE:
        if pat.search(line):
            return why
    return None


def shell_commands(b: Block) -> list[tuple[str, int, str]]:
    """(command, expected exit code, start of the error line shown) of a shell block, lines
    this test cannot run left out."""
    if b.lang == "console":
        cmds, lines = [], b.body.splitlines()
        for i, ln in enumerate(lines):
            if ln.startswith("$ "):
                shown = []
                for later in lines[i + 1:]:
                    if later.startswith("$ "):
                        break
                    shown.append(later)
                err = [s for s in shown if s.startswith("oilgap: error:")]
                cmds.append((ln[2:], 2 if err else 0, err[0][:60] if err else ""))
    else:
        cmds = [(ln, 0, "") for ln in b.body.splitlines() if ln.strip()
                and not ln.lstrip().startswith("#")]
    return [c for c in cmds if _skipped_line(c[0]) is None]


def _env() -> dict[str, str]:
    bindir = str(Path(sys.executable).parent)
    return {**os.environ, "PATH": bindir + os.pathsep + os.environ.get("PATH", ""),
            "MPLBACKEND": "Agg", "REPO": str(ROOT), "PYTHONWARNINGS": "ignore"}


def _bash(cmd: str, cwd: Path, where: str) -> subprocess.CompletedProcess:
    script = ("set -eo pipefail\n"
              f'python() {{ "{sys.executable}" "$@"; }}\n' + cmd + "\n")
    r = subprocess.run(["bash", "-c", script], cwd=cwd, env=_env(), capture_output=True,
                       text=True, timeout=600)
    r.args = where
    return r


def _link_repo(tmp: Path) -> None:
    """``model/`` and ``tests/`` of the repository, for docs that run from its root."""
    for name in ("model", "tests"):
        (tmp / name).symlink_to(ROOT / name, target_is_directory=True)


README_CASE = re.search(r"`my_joint.toml`:\n\n```toml\n(.*?)```",
                        (ROOT / "README.md").read_text(), re.S).group(1)
"""The README tour's ``my_joint.toml``, which the docs' examples use."""


def run_doc(path: Path, tmp: Path) -> dict[str, int]:
    """Run a document's blocks in ``tmp`` (with the README's ``my_joint.toml``); the counts of
    what ran."""
    _link_repo(tmp)
    (tmp / "my_joint.toml").write_text(README_CASE)
    ns: dict = {"__name__": "__doc__"}
    count = {"shell": 0, "python": 0, "files": 0}
    k_py = 0
    for b in blocks(path):
        where = f"{b.doc}:{b.line}"
        if b.skip is not None:
            if b.lang == "python":
                k_py += 1
            continue
        if b.setup:
            r = _bash(b.setup, tmp, where + " (test-setup)")
            assert r.returncode == 0, (where, r.stderr[-2000:])
        if b.lang in FILES and b.file:
            (tmp / b.file).write_text(b.body + "\n")
            count["files"] += 1
        elif b.lang in SHELL:
            for cmd, want, err in shell_commands(b):
                r = _bash(cmd, tmp, where)
                assert r.returncode == want, (where, cmd, r.returncode, r.stderr[-3000:])
                assert err in r.stderr, (where, cmd, err, r.stderr[-3000:])
                count["shell"] += 1
        elif b.lang == "python":
            out = io.StringIO()
            cwd = Path.cwd()
            os.chdir(tmp)
            try:
                with contextlib.redirect_stdout(out):
                    exec(compile(b.body, where, "exec"), ns)
            finally:
                os.chdir(cwd)
                plt.close("all")
            for text in PROMISED.get((b.doc, k_py), []):
                assert text in out.getvalue(), (where, text, out.getvalue())
            k_py += 1
            count["python"] += 1
    return count


def _runnable(p: Path) -> bool:
    """A document with a Python block or a shell command to run."""
    return any(b.skip is None and (b.lang == "python" or (b.lang in SHELL and shell_commands(b)))
               for b in blocks(p))


SECOND_HALF = "loop.md"
"""Documents from this name on (sorted) run in tests/test_docs_second.py: pytest-xdist
gives a file to one worker (``--dist loadfile``), so the documents are split over two
files to run on both cores."""


def runnable_docs(second: bool) -> list[Path]:
    """The documents to run, in the first or the second file."""
    return [p for p in DOCS if _runnable(p) and (p.name >= SECOND_HALF) == second]


@pytest.mark.parametrize("path", runnable_docs(False), ids=lambda p: p.name)
def test_doc_blocks_run(path, tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    count = run_doc(path, tmp_path)
    assert count["shell"] + count["python"] > 0


def not_run() -> list[tuple[str, str]]:
    """(where, reason) of every block and shell line not run."""
    out = []
    for p in DOCS:
        for b in blocks(p):
            if b.lang not in SHELL | {"python"}:
                continue
            if b.skip is not None:
                out.append((f"{b.doc}:{b.line}", b.skip))
                continue
            if b.lang in SHELL:
                lines = [ln[2:] if b.lang == "console" and ln.startswith("$ ") else ln
                         for ln in b.body.splitlines()]
                out += [(f"{b.doc}:{b.line}", f"`{ln.strip()}`: {why}") for ln in lines
                        if (why := _skipped_line(ln))]
    return out


def test_every_block_not_run_says_why_reasons():
    skipped = not_run()
    for where, why in skipped:
        print(f"not run: {where}: {why}")
    assert all(why.strip() for _, why in skipped)
    total = sum(1 for p in DOCS for b in blocks(p) if b.lang in SHELL | {"python"})
    print(f"{total} shell/Python blocks in docs/, {len(skipped)} blocks or lines not run")
    assert len({w for w, _ in skipped}) < total / 2  # most of the docs' code runs


def test_markers_parse():
    """The markers and the file naming, on a document written here."""
    doc = ("`a.toml`:\n\n```toml\nx = 1\n```\n\n<!-- no-test: needs a network -->\n```bash\n"
           "curl x\n```\n\n<!-- file: b.csv -->\n```csv\nu\n1\n```\n"
           "<!-- test-setup: touch c -->\n```console\n$ oilgap loop c\noilgap: error: no\n```\n"
           "```bash\npython -m pytest -q\noilgap evaluate\n```\n")
    bs = parse(doc, "probe.md")
    assert [(b.lang, b.file, b.skip, b.setup) for b in bs] == [
        ("toml", "a.toml", None, None), ("bash", None, "needs a network", None),
        ("csv", "b.csv", None, None), ("console", None, None, "touch c"),
        ("bash", None, None, None)]
    assert shell_commands(bs[3]) == [("oilgap loop c", 2, "oilgap: error: no")]
    assert shell_commands(bs[4]) == [("oilgap evaluate", 0, "")]


def _slug(heading: str) -> str:
    """GitHub's anchor of a Markdown heading: lower case, punctuation dropped, spaces -> '-'."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def _anchors(path: Path) -> set[str]:
    out: set[str] = set()
    seen: dict[str, int] = {}
    code = False
    for ln in path.read_text().splitlines():
        if ln.lstrip().startswith("```"):
            code = not code
        if code:
            continue
        if m := re.match(r"#+\s+(.*)", ln):
            s = _slug(m.group(1))
            n = seen.get(s, 0)
            seen[s] = n + 1
            out.add(s if n == 0 else f"{s}-{n}")
        out.update(re.findall(r'<a (?:name|id)="([^"]+)"', ln))
    return out


def test_links_between_docs_reach_a_file_and_a_heading():
    """Every relative link of docs/, README.md and examples/README.md names an existing file
    and, with ``#anchor``, one of its headings (``thermal.md#next`` pointed at none)."""
    bad = []
    for p in [*DOCS, ROOT / "README.md", ROOT / "examples" / "README.md"]:
        for m in re.finditer(r"\]\(([^)\s]+)\)", p.read_text()):
            link = m.group(1)
            if link.startswith(("http:", "https:", "mailto:")):
                continue
            file, _, anchor = link.partition("#")
            target = (p.parent / file).resolve() if file else p
            if not target.exists():
                bad.append(f"{p.name}: {link} (no such file)")
            elif anchor and target.suffix == ".md" and anchor not in _anchors(target):
                bad.append(f"{p.name}: {link} (no such heading)")
    assert not bad, "\n".join(bad)
