"""The command line's one dispatch table: cheap argument tables, each command's module
imported only when it runs, every command reachable."""

import importlib
import json
import subprocess
import sys

import pytest

from oilgap.cli import COMMANDS, build_parser, parsers
from oilgap.cli.parsers import EFFECT_NAMES
from oilgap.model.effects import EFFECTS
from oilgap.model.joint_loss import THERMAL_MODES

HEAVY = ("pandas", "matplotlib", "cvxpy", "scipy.signal", "oilgap.optim.design",
         "oilgap.optim.calibration")
"""Not loaded by ``oilgap evaluate``: the optimizer's engines (``oilgap.optim.interrupts``,
the Ctrl-C guard every command installs, is a light module of the package)."""


def test_effect_names_are_the_library_keys():
    assert EFFECT_NAMES == tuple(EFFECTS)


def test_thermal_modes_are_the_models():
    assert parsers.THERMAL_MODES == THERMAL_MODES


@pytest.mark.parametrize("argv", [["evaluate"], ["study", "smoothing"], ["study", "pareto"],
                                  ["study", "oil-grade"], ["study", "sweep", "g.csv"],
                                  ["study", "uncertainty"], ["optimize"], ["loop", "d.csv"],
                                  ["synth"], ["plan"],
                                  ["predict", "d.csv", "--model", "m.json", "--out", "p.csv"]])
def test_every_parser_names_a_module_with_run(argv):
    args = build_parser().parse_args(argv)
    assert args.command == " ".join(argv[:2] if argv[0] == "study" else argv[:1])
    assert callable(importlib.import_module(COMMANDS[args.command]).run)


def test_every_table_entry_is_reachable_from_the_parser():
    parser = build_parser()
    keys = {parser.parse_args(a).command for a in (
        ["evaluate"], ["optimize"], ["study", "smoothing"], ["study", "pareto"],
        ["study", "oil-grade"], ["study", "sweep", "g.csv"], ["study", "uncertainty"],
        ["loop", "d.csv"], ["synth"], ["plan"],
        ["predict", "d.csv", "--model", "m.json", "--out", "p.csv"])}
    assert keys == set(COMMANDS)


def test_evaluate_loads_no_heavy_library():
    code = ("import sys, json, io, contextlib\n"
            "from oilgap.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    assert main(['evaluate']) == 0\n"
            f"print(json.dumps([m for m in {HEAVY!r} if m in sys.modules]))\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       check=True, timeout=120)
    assert json.loads(r.stdout) == []


def test_python_m_runs_the_same_main():
    r = subprocess.run([sys.executable, "-m", "oilgap.cli", "study", "--help"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0
    for study in ("smoothing", "pareto", "oil-grade", "sweep"):
        assert study in r.stdout
