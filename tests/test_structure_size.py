"""The code's size (the developers' guide): files under 600 lines, functions under 80.

A file of ``model/``, ``optim/``, ``studies/``, ``api/``, ``benchmarks/`` and
``examples/`` has at most :data:`MAX_FILE_LINES` lines; a function's code, its docstring
left out (numpydoc blocks are long by design), at most :data:`MAX_FUNCTION_LINES`. The
offenders are printed with their size, so a failure says what to split.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FOLDERS = ("model", "optim", "studies", "api", "benchmarks", "examples")
MAX_FILE_LINES = 600
MAX_FUNCTION_LINES = 80


def _files():
    for folder in FOLDERS:
        yield from sorted((ROOT / folder).rglob("*.py"))


def _code_lines(node: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    """Lines of a function from its ``def`` to its end, less its docstring's lines."""
    lines = node.end_lineno - node.lineno + 1
    first = node.body[0]
    if (isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant)
            and isinstance(first.value.value, str)):
        lines -= first.end_lineno - first.lineno + 1
    return lines


def _long_functions(tree: ast.AST) -> list[tuple[str, int]]:
    return [(n.name, _code_lines(n)) for n in ast.walk(tree)
            if isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef)
            and _code_lines(n) > MAX_FUNCTION_LINES]


def test_files_are_under_600_lines():
    long = {str(f.relative_to(ROOT)): n for f in _files()
            if (n := len(f.read_text(encoding="utf-8").splitlines())) > MAX_FILE_LINES}
    assert not long, f"files over {MAX_FILE_LINES} lines: {long}"


def test_functions_are_under_80_lines():
    long = {f"{f.relative_to(ROOT)}:{name}": n for f in _files()
            for name, n in _long_functions(ast.parse(f.read_text(encoding="utf-8")))}
    assert not long, f"functions over {MAX_FUNCTION_LINES} lines of code: {long}"


def test_the_size_checks_can_fail():
    # a function of 81 code lines under a long docstring, and a short one
    body = "".join(f"    x{i} = {i}\n" for i in range(80))
    source = f'def big():\n    """Doc.\n\n    More.\n    """\n{body}\ndef small():\n    return 1\n'
    assert _long_functions(ast.parse(source)) == [("big", 81)]
