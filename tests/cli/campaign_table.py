"""The bad-input campaign's harness and table.

The rows are in ``tests/cli/test_campaign.py`` (issue 12's) and
``tests/cli/campaign_rows20.py`` (issue 20's: the façade, conflicting options, stored
files), each stating what it is and what must happen. A row runs the command line
(``argv``), a real process (``proc``) or, a **façade row** (``call``), an ``og.*`` call
in-process, judged as the command line would print it (:func:`run_facade`): the
project's :class:`~oilgap.model.errors.InputError` with a one-line message is refused
cleanly; a raw Python exception (TypeError, AttributeError, ...) is still failing.
This module runs a row in a fresh folder and judges it (:func:`run_row`, :func:`classify`),
holds the checks of the rows' outputs and the rows that need a real process, and, run as a
script, runs every row and prints the table of outcomes per class: refused cleanly,
warned, accepted, ended cleanly (the process rows), still failing; then the rows that still
fail and why.

    python tests/cli/campaign_table.py            # Markdown table and the failing rows
    python tests/cli/campaign_table.py --rows     # also one line per row
    python tests/cli/campaign_table.py -k loop    # only rows whose id contains "loop"

Exit code 0 when every row behaves as the campaign demands, 1 otherwise.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import hashlib
import importlib
import io
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import traceback
import warnings
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.cli import main as oilgap_main

# --------------------------------------------------------------------------- a row


@dataclass(frozen=True)
class Row:
    """One input of the campaign and what must happen."""

    id: str
    argv: str
    expect: tuple[str, ...]
    group: str
    needle: tuple[str, ...] = ()
    files: dict = field(default_factory=dict)
    setup: tuple = ()
    outputs: tuple[str, ...] = ()
    check: Callable | None = None
    forbid: tuple[str, ...] = ()
    proc: Callable | None = None
    ends: str = ""
    call: Callable | None = None
    promise: str = ""

    @property
    def kind(self) -> str:
        """How the row runs: ``"façade"`` (an og.* call), ``"process"`` or ``"CLI"``."""
        return "façade" if self.call else "process" if self.proc else "CLI"

    def states(self) -> str:
        """The promise the row checks: its own words, else what its expectation says."""
        if self.promise:
            return self.promise
        named = f", naming {' and '.join(self.needle)}" if self.needle else ""
        return f"`oilgap {self.argv}` is {' or '.join(self.expect)}{named}"


CLASSES = ("refused", "warned", "accepted", "ended cleanly", "failed cleanly",
           "still failing")
"""The outcome classes, in the table's order."""


@contextlib.contextmanager
def cwd(d: Path):
    """Run the block in folder ``d``."""
    old = os.getcwd()
    os.chdir(d)
    try:
        yield
    finally:
        os.chdir(old)


def _snapshot(d: Path) -> dict[str, str]:
    snap = {}
    for p in sorted(d.rglob("*")):
        rel = p.relative_to(d).as_posix()
        snap[rel] = "dir" if p.is_dir() else hashlib.sha1(p.read_bytes()).hexdigest()
    return snap


@dataclass
class Outcome:
    """What one row did and its verdict."""

    row: Row
    rc: int
    out: str
    err: str
    changed: list[str]
    cls: str
    problems: list[str]
    seconds: float

    @property
    def passed(self) -> bool:
        return not self.problems

    def explain(self) -> str:
        err = self.err if len(self.err) < 3000 else self.err[:1500] + "\n...\n" + \
            self.err[-1500:]
        return (f"{self.row.id}: expected {'|'.join(self.row.expect)}, got {self.cls} "
                f"(exit {self.rc})\n  " + "\n  ".join(self.problems)
                + f"\n--- stderr ---\n{err}")


def classify(rc: int, err: str, ends: str = "") -> str:
    """The class of an outcome from its exit code and stderr (files aside); ``ends`` names
    a process row's edge ("pipe": the reader has gone; "sigint": Ctrl-C)."""
    lines = [ln for ln in err.splitlines() if ln.strip()]
    if "Traceback" in err or "Exception ignored" in err:
        return "still failing"
    if ends == "sigint" and rc == 130 and len(lines) == 1 and \
            lines[0].startswith("oilgap: interrupted"):
        return "ended cleanly"
    if ends == "pipe" and rc in (0, 1, 141) and not lines:
        return "ended cleanly"
    if rc == 2 and len(lines) == 1 and lines[0].startswith("oilgap: error:"):
        return "refused"
    if rc in (3, 4) and len(lines) == 1 and \
            lines[0].startswith(("oilgap: solver failure:", "oilgap: infeasible:")):
        return "failed cleanly"     # no solution is a failure, one line, never a result
    if rc == 2 and lines and lines[0].startswith("usage: oilgap") and \
            re.match(r"oilgap [\w -]+: error: ", lines[-1]):
        return "refused"            # argparse: its usage, then one error line
    if rc == 0:
        return "warned" if any(ln.startswith("oilgap: warning:") for ln in lines) \
            else "accepted"
    return "still failing"


def why_failing(rc: int, err: str) -> str:
    """What makes an outcome still failing, in a few words (for the table)."""
    lines = [ln for ln in err.splitlines() if ln.strip()]
    if "Traceback" in err:
        last = next((ln for ln in reversed(lines) if not ln.startswith(" ")), "")
        return f"traceback: {last[:160]}"
    if "Exception ignored" in err:
        return "'Exception ignored' at exit"
    if rc == 2:
        kinds = Counter(ln.split(":")[1].strip() if ln.startswith("oilgap:") else "other"
                        for ln in lines)
        return f"exit 2 with {len(lines)} stderr lines ({dict(kinds)})"
    return f"exit {rc}: {lines[-1][:160] if lines else 'no message'}"


def _message(cls: str, out: str, err: str) -> str:
    lines = err.splitlines()
    if cls in ("refused", "failed cleanly"):
        return lines[-1] if lines else ""
    if cls == "warned":
        return "\n".join(ln for ln in lines if ln.startswith("oilgap: warning:"))
    return out + "\n" + err


def _run_in_process(argv: list[str], d: Path) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), cwd(d):
        try:
            rc = oilgap_main(argv)
        except SystemExit as e:
            rc = e.code if isinstance(e.code, int) else 1
        except Exception:                       # what the interpreter would print
            err.write(traceback.format_exc())
            rc = 1
    return rc, out.getvalue(), err.getvalue()


def run_facade(call: Callable[[Path], object], d: Path) -> tuple[int, str, str]:
    """A façade call in folder ``d``, as the command line would report it: exit 0 (each
    OilgapWarning an ``oilgap: warning:`` line), 2 and ``oilgap: error: <message>`` for
    the project's InputError, 3/4 and ``oilgap: solver failure:`` for a SolverError;
    any other exception is a traceback (still failing)."""
    from oilgap.model.errors import InputError, OilgapWarning, SolverError

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), cwd(d), \
            warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            call(d)
            rc = 0
        except InputError as e:
            err.write(f"oilgap: error: {e}\n")
            rc = 2
        except SolverError as e:
            err.write(f"oilgap: solver failure: {e}\n")
            rc = e.exit_code
        except Exception:                       # a raw Python error: broken
            err.write(traceback.format_exc())
            rc = 1
    if rc == 0:
        err.write("".join(f"oilgap: warning: {w.message}\n" for w in caught
                          if issubclass(w.category, OilgapWarning)))
    return rc, out.getvalue(), err.getvalue()


def run_row(r: Row, d: Path) -> Outcome:
    """Set the row up in the empty folder ``d``, run it and judge what happened."""
    d.mkdir(parents=True, exist_ok=True)
    for name, content in r.files.items():
        p = d / name
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_bytes(content if isinstance(content, bytes) else content.encode())
    for step in r.setup:
        step(d)
    before = _snapshot(d)
    t0 = time.perf_counter()
    rc, out, err = r.proc(d) if r.proc else run_facade(r.call, d) if r.call else \
        _run_in_process(shlex.split(r.argv), d)
    seconds = time.perf_counter() - t0
    after = _snapshot(d)
    changed = sorted(k for k in before.keys() | after.keys() if before.get(k) != after.get(k))
    cls = classify(rc, err, r.ends)
    why = why_failing(rc, err) if cls == "still failing" else ""
    problems = []
    if cls == "refused" and changed:
        cls, why = "still failing", f"refused, but wrote or changed {changed[:5]}"
    stray = [c for c in changed if not any(c == o or c.startswith(o + "/") for o in r.outputs)]
    if cls != "refused" and stray:
        problems.append(f"wrote outside its outputs: {stray[:5]}")
    if cls not in r.expect:
        problems.insert(0, f"class {cls}, expected {'|'.join(r.expect)}"
                        + (f" ({why})" if why else ""))
    msg = _message(cls, out, err)
    if cls in r.expect:
        problems += [f"message does not match {n!r}: {msg[:300]!r}" for n in r.needle
                     if not re.search(n, msg)]
    problems += [f"error echoes {f!r}" for f in r.forbid if f and f in err]
    if r.check and cls in r.expect:
        try:
            r.check(d, out, changed)
        except (AssertionError, ValueError, KeyError, OSError) as e:
            problems.append(f"check {getattr(r.check, '__name__', 'check')}: {e}")
    return Outcome(r, rc, out, err, changed, cls, problems, seconds)


# --------------------------------------------------------------------------- checks
# each takes (folder, stdout, files written) and raises AssertionError saying what is wrong


def _csv_cells(path: Path):
    with open(path, newline="", encoding="utf-8") as f:
        yield from (c for r in csv.reader(f) for c in r)


def _is_number(text: str) -> bool:
    try:
        float(text)
        return True
    except ValueError:
        return False


def _written(d: Path, written: list[str], suffix: str) -> list[Path]:
    return [d / w for w in written if w.endswith(suffix) and (d / w).is_file()]


def no_formula_cells(d: Path, out: str, written: list[str]) -> None:
    """No written CSV cell starts with = + - @ unless it is a number (spreadsheets run
    such cells as formulas)."""
    for p in _written(d, written, ".csv"):
        bad = [c for c in _csv_cells(p) if c[:1] and c[0] in "=+-@" and not _is_number(c)]
        assert not bad, f"{p.name}: formula-like cells written as is: {bad[:3]}"


def markdown_tables_intact(d: Path, out: str, written: list[str]) -> None:
    """Every Markdown table keeps its column count (a name's ``|`` escaped) and no raw
    HTML tag passes through."""
    for p in _written(d, written, ".md"):
        text = p.read_text(encoding="utf-8")
        assert "<img" not in text.lower(), f"{p.name}: raw HTML passed through"
        block: list[int] = []
        for line in text.splitlines() + [""]:
            if line.startswith("|"):
                block.append(len(re.findall(r"(?<!\\)\|", line)))
            elif block:
                assert len(set(block)) == 1, f"{p.name}: a table row has extra cells {block}"
                block = []


def figures_written(d: Path, out: str, written: list[str]) -> None:
    """The loop's three figures are written."""
    pngs = list(d.rglob("*.png"))
    assert len(pngs) >= 3 and all(p.stat().st_size > 10_000 for p in pngs), \
        f"figures missing: {[p.name for p in pngs]}"


def gamma_in_header(d: Path, out: str, written: list[str]) -> None:
    """The text names gamma on its own line (the assumptions block, after the answer since
    issue 26; ``-q`` leaves it out)."""
    assert re.search(r"^(gamma|γ)\s", out, re.M), "the header does not name gamma"


def gamma_in_json(d: Path, out: str, written: list[str]) -> None:
    """The JSON names gamma and where it came from (top level or a ``friction`` block)."""
    doc = json.loads(out)
    places = [doc] + ([doc["friction"]] if isinstance(doc.get("friction"), dict) else [])
    src = next((p for p in places if "gamma" in p and "gamma_source" in p), None)
    assert src is not None, "JSON lacks gamma and gamma_source"
    assert isinstance(src["gamma"], float | int) and src["gamma_source"], "empty gamma"


def loop_dropped(n: int):
    """loop.json counts ``n`` dropped rows."""
    def check(d: Path, out: str, written: list[str]) -> None:
        doc = json.loads(next(d.rglob("loop.json")).read_text())
        assert doc["data"]["rows_dropped"] == n, f"rows_dropped {doc['data']['rows_dropped']}"
    return check


def dropped_or_refused(n: int):
    """With exit 0, the loop counts the ``n`` bad override rows as dropped."""
    def check(d: Path, out: str, written: list[str]) -> None:
        if list(d.rglob("loop.json")):
            loop_dropped(n)(d, out, written)
    return check


def nothing_escaped(d: Path, out: str, written: list[str]) -> None:
    """Run names like ``../../../escape`` or ``/tmp/campaign-abs`` write nothing outside."""
    escaped = [p.name for p in d.iterdir() if p.name not in ("data.csv", "a")]
    escaped += [str(p) for p in Path("/tmp").glob("campaign-abs*")]
    assert not escaped, f"written outside --out: {escaped}"


def no_stale(folder: str):
    """After ``--force`` no file of an earlier run is left in ``folder`` beside the new
    ones (a new loop.json beside the previous run's figures)."""
    def check(d: Path, out: str, written: list[str]) -> None:
        stale = [p.relative_to(d).as_posix() for p in (d / folder).rglob("*") if p.is_file()
                 and p.relative_to(d).as_posix() not in written]
        assert not stale, f"left from the earlier run: {stale}"
    return check


def intervals_honest(d: Path, out: str, written: list[str]) -> None:
    """No zero-width interval; a parameter without an interval is called not identifiable."""
    files = list(d.rglob("loop.json"))
    if not files:
        return
    doc = json.loads(files[0].read_text())
    for name, ci in doc["calibration_ci95"].items():
        said = str(doc["identifiability"].get(name, ""))
        if isinstance(ci, list) and None not in ci:
            assert ci[1] - ci[0] > 1e-9 * max(1.0, abs(doc["calibration"][name])), \
                f"{name}: zero-width interval {ci}"
        elif isinstance(ci, list):
            assert "not identifiable" in said, f"{name}: no interval but called {said!r}"


def grid_row_not_ok(i: int):
    """With exit 0 the grid row ``i`` is an error row (never the base value with ok)."""
    def check(d: Path, out: str, written: list[str]) -> None:
        files = list(d.rglob("results.csv"))
        if files:
            res = pd.read_csv(files[0])
            assert res["status"].iloc[i] != "ok", f"grid row {i} computed with status ok"
    return check


def finite_results(d: Path, out: str, written: list[str]) -> None:
    """No inf or nan printed as a result."""
    assert not re.search(r"\b(inf|nan)\b", out, re.I), "a non-finite number is printed"
    for p in d.rglob("results.csv"):
        res = pd.read_csv(p)
        ok = res[res["status"] == "ok"]
        assert np.isfinite(ok.select_dtypes("number").to_numpy(dtype=float)).all() or \
            ok.empty, f"{p.name}: non-finite value with status ok"


def case_written(d: Path, out: str, written: list[str]) -> None:
    """``--force`` replaced the stale file by the optimal case."""
    text = (d / "opt.toml").read_text()
    assert "[region1]" in text and "stale" not in text, "opt.toml not replaced"


def resumed_same(d: Path, out: str, written: list[str]) -> None:
    """After a truncated last store line, resume gives the first run's results."""
    ref = pd.read_csv(d / "ref_results.csv")
    got = pd.read_csv(d / "sw" / "results.csv")
    assert np.allclose(got["mean_power_W"], ref["mean_power_W"], rtol=1e-12), \
        "resumed results differ from the first run"


def truncate_store(d: Path) -> None:
    """Setup: keep the first run's results, then cut the store's last line in half."""
    shutil.copy(d / "sw" / "results.csv", d / "ref_results.csv")
    store = d / "sw" / "points_evaluate.csv"
    text = store.read_text()
    last = text.rstrip("\n").rsplit("\n", 1)[1]
    store.write_text(text[: len(text.rstrip("\n")) - len(last) // 2])


def json_stdout(d: Path, out: str, written: list[str]) -> None:
    """stdout is one JSON document (logs go to stderr)."""
    json.loads(out)


# ---- process rows (a real process: the pipe, the signal, the C-level log)

def _oilgap(*argv: str) -> list[str]:
    return [sys.executable, "-m", "oilgap.cli", *argv]


def proc_closed_pipe(d: Path) -> tuple[int, str, str]:
    """``oilgap evaluate | head -1`` made certain: the reader has gone before any write."""
    p = subprocess.Popen(_oilgap("evaluate", "--json"), cwd=d, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    p.stdout.close()
    err = p.stderr.read().decode()
    return p.wait(timeout=60), "", err


CTRL_C_S = 10.0
"""How long a run may take to stop after Ctrl-C [s]."""


def proc_ctrl_c(d: Path) -> tuple[int, str, str]:
    """Ctrl-C in a terminal: SIGINT to the whole process group (command and workers)
    while an optimize sweep runs in two worker processes. The run must end within
    :data:`CTRL_C_S` of the signal."""
    p = subprocess.Popen(_oilgap("study", "sweep", "grid.csv", "--mode", "optimize",
                                 "--workers", "2", "--chunk-size", "2", "--out", "sw",
                                 "--no-progress"),
                         cwd=d, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         start_new_session=True)
    deadline = time.monotonic() + 30          # until the first chunk is stored: the
    while not any((d / "sw").rglob("*.csv")) and time.monotonic() < deadline \
            and p.poll() is None:                # workers are then inside their NLPs
        time.sleep(0.05)
    time.sleep(0.3)
    with contextlib.suppress(ProcessLookupError):
        os.killpg(p.pid, signal.SIGINT)
    t0 = time.monotonic()
    out, err = p.communicate(timeout=120)
    late = time.monotonic() - t0 > CTRL_C_S
    return p.returncode, out.decode(), err.decode() + (
        f"\n(campaign: still running {CTRL_C_S:g} s after Ctrl-C)" if late else "")


def proc_verbose_json(d: Path) -> tuple[int, str, str]:
    """``optimize --json --verbose``: IPOPT writes on the C-level stdout."""
    r = subprocess.run(_oilgap("optimize", "--json", "--verbose", "--starts", "1"), cwd=d,
                       capture_output=True, text=True, timeout=120)
    return r.returncode, r.stdout, r.stderr


# --------------------------------------------------------------------------- the table


LABELS = {"refused": "refused cleanly", "warned": "warned", "accepted": "accepted",
          "ended cleanly": "ended cleanly", "failed cleanly": "failed cleanly (exit 3/4)",
          "still failing": "still failing"}


def table(outcomes) -> str:
    """Markdown table: rows per issue section and per class (a row that does not behave
    as its expectation demands counts as still failing, whatever its class)."""
    groups = list(dict.fromkeys(o.row.group for o in outcomes))
    head = ["section", "rows"] + [LABELS[c] for c in CLASSES]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    kinds = list(dict.fromkeys(o.row.kind for o in outcomes))
    parts = [(g, [o for o in outcomes if o.row.group == g]) for g in groups]
    parts += [(f"*{k} rows*", [o for o in outcomes if o.row.kind == k]) for k in kinds]
    for label, sel in parts + [("**all**", list(outcomes))]:
        n = Counter(o.cls if o.passed else "still failing" for o in sel)
        lines.append(f"| {label} | {len(sel)} | "
                     + " | ".join(str(n[c]) for c in CLASSES) + " |")
    return "\n".join(lines)


def main(argv=None) -> int:
    """Run the rows (all, or those named by ``-k``), print the table; 1 if a row fails."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rows", action="store_true", help="one line per row")
    p.add_argument("-k", metavar="TEXT", help="only rows whose id contains TEXT")
    args = p.parse_args(argv)
    rows = [r for r in importlib.import_module("test_campaign").ROWS
            if not args.k or args.k in r.id]
    outcomes = []
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="oilgap-campaign-") as tmp:
        for i, r in enumerate(rows):
            outcomes.append(run_row(r, Path(tmp) / f"{i:03d}"))
    print(f"Bad-input campaign: {len(rows)} rows in {time.perf_counter() - t0:.1f} s\n")
    print(table(outcomes))
    if args.rows:
        print()
        for o in outcomes:
            print(f"{'ok  ' if o.passed else 'FAIL'} {o.row.id:<34} {o.row.kind:<7} "
                  f"{o.cls:<14} exit {o.rc:<4} {o.seconds:6.2f} s  {o.row.states()}")
    failing = [o for o in outcomes if not o.passed]
    if failing:
        print("\nStill failing:\n")
        for o in failing:
            print(f"- {o.row.id} ({o.row.group}): {o.row.states()}; expected "
                  f"{'|'.join(o.row.expect)}, got {o.cls} (exit {o.rc}): "
                  + "; ".join(o.problems)[:400])
    return 1 if failing else 0


if __name__ == "__main__":
    sys.exit(main())
