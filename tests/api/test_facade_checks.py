"""Issue 20, classes 1 and 4 in the façade: every public ``og.*`` function checks its
arguments at the entry (one decorator, ``oilgap._checks.checked``) and refuses a wrong
one with the project's error; a user's oils add to the catalogue; conflicting options are
refused naming both. The rows of bad calls are in the campaign
(``tests/cli/campaign_rows20.py``); these tests check the mechanism and the oils."""

from __future__ import annotations

import inspect
import warnings

import pytest

import oilgap as og
from oilgap._checks import Arg, check_arg, checked
from oilgap.cli import main
from oilgap.cli.study_sweep import interrupted_line
from oilgap.model.errors import ArgumentError, InputError, OilgapWarning
from oilgap.model.oils import builtin_oils
from oilgap.studies.grid.runner import SweepInterrupted

FUNCTIONS = [n for n in og.EXPORTS if inspect.isfunction(getattr(og, n))]
METHODS = [og.Loop.fit, og.Loop.predict, og.Loop.report, og.Evaluation.to_json]


@pytest.mark.parametrize("name", FUNCTIONS)
def test_every_facade_function_checks_its_arguments(name):
    """Each function of ``og`` is wrapped by ``checked`` and every parameter it names is
    one of the function's (a misspelt spec would check nothing)."""
    fn = getattr(og, name)
    assert hasattr(fn, "__checks__"), f"og.{name} does not check its arguments"
    params = set(inspect.signature(fn).parameters)
    extra = set(fn.__checks__) - params
    assert not extra or "keywords" in params, extra


@pytest.mark.parametrize("method", METHODS, ids=lambda m: m.__qualname__)
def test_methods_check_their_arguments(method):
    assert hasattr(method, "__checks__")


def test_argument_error_is_the_projects_error_and_a_type_error():
    """A wrong type is an InputError (exit 2 on the command line) and a TypeError (what
    Python code expects), with one line naming the argument, the value and its type."""
    with pytest.raises(ArgumentError) as e:
        og.read_case(None)
    assert isinstance(e.value, InputError) and isinstance(e.value, TypeError)
    assert str(e.value) == "path = None is not allowed; a path (str or pathlib.Path)"
    with pytest.raises(InputError, match=r"^mission\[1\] = 2 \(int\) is not allowed; "):
        og.oil_grade(mission=[{"depth_m": 0.0, "oil_temp_C": 4.0, "fraction": 1.0}, 2])


def test_calls_that_do_not_bind_are_the_projects_error():
    """Too many positional arguments, or an unknown keyword of a function without
    ``**keywords``: the project's error naming the function and its signature."""
    with pytest.raises(ArgumentError, match=r"read_case\(\) = .*signature is read_case"):
        og.read_case("a.toml", "b.toml")
    with pytest.raises(ArgumentError, match="evaluate"):
        og.evaluate(temperature=20.0)


def test_kinds_by_name_and_bools():
    """A kind named by its class matches subclasses; True is not taken for a number."""
    spec = Arg((int, float), "a number")
    assert check_arg("x", 2.5, spec) == 2.5
    with pytest.raises(ArgumentError, match=r"x = True \(bool\)"):
        check_arg("x", True, spec)
    with pytest.raises(ArgumentError, match=r"smoothed = 1 \(int\) .*True or False"):
        og.seed_case(1)

    import pandas as pd

    class Frame(pd.DataFrame):
        pass

    @checked(v=Arg(("DataFrame",), "a DataFrame"))
    def f(v):
        return len(v)
    assert f(Frame({"a": [1, 2]})) == 2       # a subclass of a kind named by its class
    with pytest.raises(ArgumentError, match=r"v = a list of 0 items"):
        f([])


def test_user_oils_add_to_the_catalogue():
    """``oils=`` adds to the ISO VG catalogue: the user's oil and VG46 are both found; the
    dict's values are the oil's (nu40 46 cSt given, 46 read back)."""
    mine = {"RigOil": {"nu40_cSt": 46.0, "nu100_cSt": 7.0, "density_kg_m3": 870.0}}
    cat = og.read_oils(mine)
    assert set(builtin_oils()) < set(cat) and cat["RIGOIL"].nu40_cSt == 46.0
    assert og.evaluate(oils=mine, oil="VG46").case.oil.name == builtin_oils()["VG46"].name
    alone = og.read_oils(mine, only=True)
    assert list(alone) == ["RIGOIL"]
    with pytest.raises(InputError, match="VG46"):
        og.evaluate(oils=alone, oil="VG46")


def test_a_clash_warns_only_when_the_values_differ(tmp_path):
    """A row named like a built-in oil wins; a warning names it when its values differ
    from the built-in's (the same values: silent)."""
    vg22 = builtin_oils()["VG22"]
    same = {"VG22": vg22}
    with warnings.catch_warnings():
        warnings.simplefilter("error", OilgapWarning)
        og.read_oils(same)
    with pytest.warns(OilgapWarning, match="VG22 replaces the built-in"):
        cat = og.read_oils({"VG22": {"nu40_cSt": 25.0, "nu100_cSt": 4.9,
                                     "density_kg_m3": 860.0}})
    assert cat["VG22"].nu40_cSt == 25.0


def test_cli_oils_only_and_clash(tmp_path, capsys):
    p = tmp_path / "oils.csv"
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3\nRigOil,46,7,870\n")
    assert main(["evaluate", "--oils", str(p), "--oil", "VG46"]) == 0
    assert main(["evaluate", "--oils", str(p), "--oils-only", "--oil", "VG46"]) == 2
    assert "known oils are RigOil" in capsys.readouterr().err


def test_an_interrupted_sweep_that_saved_nothing_says_so(tmp_path):
    """Not "0 of 600 points saved": plainly nothing, and what to do."""
    line = interrupted_line(SweepInterrupted(0, 600, tmp_path / "sw"))
    assert "nothing was saved" in line and "0 of" not in line and "rerun" in line
    assert "40 of 600 points saved" in interrupted_line(SweepInterrupted(40, 600, "sw"))


def test_chunk_size_and_chunk_seconds_exclude_each_other():
    """The run options' record refuses the pair (the façade and the command line build
    it); either alone is taken, and neither means chunks of the default 3 s of work."""
    from oilgap.studies.settings import DEFAULT_CHUNK_SECONDS, RunOptions

    with pytest.raises(InputError, match="chunk_size = 2 .*not with chunk_seconds"):
        RunOptions(chunk_size=2, chunk_seconds=1.0)
    assert RunOptions(chunk_size=2).chunk_seconds is None
    assert RunOptions(chunk_seconds=1.5).chunk_seconds == 1.5
    assert RunOptions().chunk_seconds is None and DEFAULT_CHUNK_SECONDS == 3.0
