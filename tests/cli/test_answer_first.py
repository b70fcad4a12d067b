"""Issue 26: the answer in the first 5 lines, the assumptions after it (``-q`` drops them),
prose wrapped at 100 characters, ``optimize --out`` re-evaluated gives the loss printed,
``--report DIR`` folders, progress bars only on a terminal.

The studies' stdout is checked on their golden outputs (tests/golden/data, produced by the
same commands and compared by tests/golden), the robust optimum, the uncertainty study and
the loop in their own CLI tests (tests/cli/test_optimize_robust.py, test_study_uncertainty.py,
test_loop_cli.py): no study runs twice for this file.
"""

import io
import json
import re
from pathlib import Path

import pytest

from oilgap.cli import main
from oilgap.model.io.text import WIDTH, layout, wrap
from oilgap.optim.progress import report, reporting, steps

GOLDEN = Path(__file__).parents[1] / "golden" / "data"


def _run(capsys, argv):
    code = main(argv)
    cap = capsys.readouterr()
    return code, cap.out, cap.err


def _head(text: str) -> str:
    return "\n".join(text.splitlines()[:5])


def test_evaluate_total_first_and_equal_to_the_json(capsys):
    code, out, _ = _run(capsys, ["evaluate"])
    assert code == 0
    m = re.match(r"total mean viscous power\s+([\d.]+) W", out)
    assert m, out.splitlines()[0]
    _, doc, _ = _run(capsys, ["evaluate", "--json"])
    assert float(m.group(1)) == pytest.approx(json.loads(doc)["total_mean_power_W"], abs=5e-4)
    lines = out.splitlines()
    # the assumptions follow the table: thermal and gamma after the region table
    table = next(i for i, x in enumerate(lines) if x.startswith("region "))
    assert table < next(i for i, x in enumerate(lines) if x.startswith("thermal     "))
    assert table < next(i for i, x in enumerate(lines) if x.startswith("gamma       "))


def test_quiet_drops_the_assumptions_not_the_answer(capsys):
    _, out, _ = _run(capsys, ["evaluate"])
    _, quiet, err = _run(capsys, ["evaluate", "-q"])
    assert quiet.splitlines()[0] == out.splitlines()[0]
    assert not re.search(r"^(thermal|gamma|case|oil) ", quiet, re.M)
    assert re.search(r"^thermal ", out, re.M) and err == ""
    assert len(quiet.splitlines()) < len(out.splitlines())


def test_prose_is_wrapped_tables_are_not(capsys):
    _, out, _ = _run(capsys, ["evaluate"])
    long = [x for x in out.splitlines() if len(x) > WIDTH]
    assert long and all(x.startswith(("region ", "rotor-stator ", "bearing ")) for x in long)
    # the 157-character thermal line of the seed joint: two lines, the second under the text
    at = next(i for i, x in enumerate(out.splitlines()) if x.startswith("thermal     "))
    assert out.splitlines()[at + 1].startswith(" " * 12 + "of the seed paper")


def test_wrap_keeps_numbers_with_units_and_indents_under_the_label():
    line = ("film band                  film heating at full strength (film): 34.9 W (-29 %);"
            " not supported by Table 4 of the seed paper, see docs/thermal.md#evidence")
    got = wrap(line, 75)
    assert " ".join(" ".join(got).split()) == " ".join(line.split())  # no word lost
    assert all(len(x) <= 75 for x in got) and got[1].startswith(" " * 27 + "(-29 %)")
    text = layout(["answer"], ["a  b", "", "c"], ["thermal     t"], ["wrote x"], defaults=False)
    assert text == "answer\n\na  b\n\nc\n\nwrote x"


@pytest.mark.parametrize("name, answer", [
    ("pareto.txt", r"^gap front: 60/60 points.*\n.*\n\s+hypervolume [\d.]+ mm W"),
    ("oil-grade.txt", r"^recommended: VG15   runner-up: VG22"),
    ("oil-grade_none.txt", r"^recommended: VG15"),
    ("smoothing.txt", r"^fitted gamma = 0.566 \+- 0.041.*\nreductions within [\d.]+ W"),
])
def test_golden_studies_print_their_answer_first(name, answer):
    text = (GOLDEN / name).read_text()
    assert re.search(answer, _head(text)), _head(text)
    defaults = next(i for i, x in enumerate(text.splitlines()) if x.startswith("defaults "))
    assert defaults > 5  # the block of defaults follows the answer


def test_optimize_out_evaluated_again_gives_the_loss_printed(tmp_path, capsys):
    """155.699 against 155.6965 W (issue 26): the file holds every digit of the optimum, so
    ``oilgap evaluate`` of it gives the exact-C_m loss optimize printed, to its digits."""
    case = tmp_path / "opt.toml"
    code, out, _ = _run(capsys, ["optimize", "--starts", "2", "--out", str(case)])
    assert code == 0 and out.startswith("optimum     ")
    printed = float(re.search(r"([\d.]+) W with the case's exact C_m",
                              re.sub(r"\s+", " ", _head(out))).group(1))
    table = float(re.search(r"^mean_power_exact_W\s+[\d.]+\s+([\d.]+)", out, re.M).group(1))
    assert printed == table
    _, doc, _ = _run(capsys, ["evaluate", str(case), "--json"])
    again = json.loads(doc)["total_mean_power_W"]
    assert round(again, 4) == printed  # to the 4 decimals printed
    assert re.search(r"^T2_mm = \d+\.\d{9,}$", case.read_text(), re.M)  # not 6 digits


def test_evaluate_report_folder(tmp_path, capsys):
    rep = tmp_path / "review"
    code, out, _ = _run(capsys, ["evaluate", "--report", str(rep)])
    assert code == 0 and f"wrote {rep}/:" in out
    names = {p.name for p in rep.iterdir()}
    assert names == {"summary.md", "evaluate.json", "evaluate_regions.csv",
                     "evaluate_power.png", "provenance.json"}
    md = (rep / "summary.md").read_text()
    total = json.loads((rep / "evaluate.json").read_text())["total_mean_power_W"]
    assert f"total mean viscous power   {total:.3f} W" in md
    assert "| rotor-stator" in md and "![evaluate_power.png](evaluate_power.png)" in md
    assert "## Defaults the tool filled in" in md
    code, _, err = _run(capsys, ["evaluate", "--report", str(rep)])
    assert code == 2 and len(err.strip().splitlines()) == 1 and "--report" in err
    assert _run(capsys, ["evaluate", "--report", str(rep), "--force"])[0] == 0


def test_optimize_report_folder_holds_the_optimum(tmp_path, capsys):
    rep = tmp_path / "opt"
    code, out, _ = _run(capsys, ["optimize", "--starts", "1", "--report", str(rep), "--json"])
    assert code == 0 and json.loads(out)["report"]
    assert {"summary.md", "optimize.json", "optimize_designs.csv", "optimize_change.png",
            "optimum.toml", "provenance.json"} == {p.name for p in rep.iterdir()}
    assert "optimum     " in (rep / "summary.md").read_text()


def test_progress_is_drawn_on_a_terminal_only(monkeypatch):
    import oilgap.studies.progress as progress

    monkeypatch.setattr(progress, "MIN_SECONDS", 0.0)

    class Tty(io.StringIO):
        def isatty(self):
            return True

    piped, tty = io.StringIO(), Tty()
    for stream in (piped, tty):
        with progress.shown(None, stream):
            for _ in steps("demo", range(3)):
                pass
    assert piped.getvalue() == ""
    assert "oilgap demo" in tty.getvalue() and "3/3" not in tty.getvalue()  # left off at 2/3
    before = tty.getvalue()
    with progress.shown(False, tty), reporting(None):
        report("quiet", 1, 2)  # -q: nothing installed, nothing drawn
    assert tty.getvalue() == before


def test_cli_draws_no_progress_when_not_a_terminal(capsys):
    code, _, err = _run(capsys, ["optimize", "--starts", "3"])
    assert code == 0 and "steps" not in err and "oilgap optimize: starts" not in err


def test_a_forked_worker_does_not_draw_its_parents_bars():
    """run_grid's workers are forked: they inherit the installed reporter, not the right
    to draw on the parent's terminal."""
    import os

    seen = []
    with reporting(lambda *a: seen.append(a)):
        report("parent", 1, 2)
        pid = os.fork()
        if pid == 0:  # the child: exit 3 if its report reached the parent's reporter
            report("child", 1, 2)
            os._exit(3 if seen[-1][0] == "child" else 0)
        _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0 and seen == [("parent", 1, 2)]
