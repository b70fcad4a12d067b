"""The layout's promises: the physics and the optimizer write no file, and the model's
root stays small (readers in model/io, measured data in model/measured, the effects and
the bearing in their subpackages).

The write check reads the source text: every call that writes, moves or creates a file
or folder (``open`` in a write mode, ``write_text``, ``to_csv``, ``savefig``,
``os.replace``, ``mkdir``, ``json.dump``...) is an offender in ``model/`` or ``optim/``.
Writing is the output layer's, ``studies/io`` (atomic writers, result folders,
provenance).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import oilgap.model
import oilgap.optim

MODEL = Path(oilgap.model.__file__).parent
OPTIM = Path(oilgap.optim.__file__).parent

MAX_MODEL_ROOT_FILES = 25
"""At most this many .py files at the root of model/ (issue 19)."""

WRITE_PATTERNS = {
    "open for writing": re.compile(
        r"\bopen\([^)]*?(?:,\s*|mode\s*=\s*)[\"'][rb+]*[wax][bt+]*[\"']"),
    "os.open for writing": re.compile(r"\bos\.open\([^)]*O_(?:WRONLY|RDWR|CREAT)"),
    "fdopen": re.compile(r"\bfdopen\("),
    ".write_text(": re.compile(r"\.write_text\("),
    ".write_bytes(": re.compile(r"\.write_bytes\("),
    "to_csv(": re.compile(r"\.to_csv\("),
    "to_parquet(": re.compile(r"\.to_parquet\("),
    "to_excel(": re.compile(r"\.to_excel\("),
    "to_json(path)": re.compile(r"\.to_json\(\s*[^)\s]"),
    "savefig(": re.compile(r"\bsavefig\("),
    "os.replace(": re.compile(r"\bos\.(?:replace|rename)\("),
    "mkdir(": re.compile(r"\b(?:mkdir|makedirs)\("),
    "json.dump(": re.compile(r"\bjson\.dump\("),
    "np.save": re.compile(r"\bnp\.(?:save|savez|savetxt)\w*\("),
    "shutil": re.compile(r"\bshutil\.(?:copy\w*|move|rmtree)\("),
    "unlink/rmdir": re.compile(r"\.(?:unlink|rmdir)\("),
    "tempfile": re.compile(r"\btempfile\.(?:mkstemp|NamedTemporaryFile|mkdtemp)\("),
    "atomic writer": re.compile(r"\batomic_\w+\("),
}
"""What writes, moves, creates or deletes a file or folder, as it appears in the source."""


def _sources(root: Path) -> list[Path]:
    return sorted(p for p in root.rglob("*.py") if "__pycache__" not in p.parts)


def _offenders(root: Path) -> list[str]:
    bad = []
    for path in _sources(root):
        for no, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            code = line.split("#", 1)[0]
            for what, pattern in WRITE_PATTERNS.items():
                if pattern.search(code):
                    bad.append(f"{path.relative_to(root.parent)}:{no}: {what}: {line.strip()}")
    return bad


@pytest.mark.parametrize("root", [MODEL, OPTIM], ids=["model", "optim"])
def test_model_and_optim_write_no_file(root):
    assert _offenders(root) == []


@pytest.mark.parametrize("line", [
    'with open(path, "w") as fh:', "open(p, 'ab')", 'open(p, mode="x")', "p.write_text(s)",
    "df.to_csv(p)", "fig.savefig(p)", "os.replace(a, b)", "path.parent.mkdir(parents=True)",
    "json.dump(doc, fh)", "atomic_write_text(p, s)", "df.to_parquet(p)", "p.unlink()",
])
def test_the_write_check_finds_each_writer(tmp_path, line):
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "m.py").write_text(f"def f(p):\n    {line}\n")
    assert len(_offenders(pkg)) == 1


@pytest.mark.parametrize("line", [
    'with open(path, encoding="utf-8") as fh:', 'open(p, "rb")', "json.loads(text)",
    "doc = json.dumps(x)  # text, not a file", "df.to_dict()", "pd.read_csv(p)",
])
def test_the_write_check_lets_readers_pass(tmp_path, line):
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "m.py").write_text(f"def f(p):\n    {line}\n")
    assert _offenders(pkg) == []


def test_model_root_is_small():
    files = sorted(p.name for p in MODEL.glob("*.py"))
    assert len(files) <= MAX_MODEL_ROOT_FILES, files


@pytest.mark.parametrize("sub", ["io", "measured", "effects", "bearing"])
def test_model_subpackages_are_packages(sub):
    assert (MODEL / sub / "__init__.py").is_file()
