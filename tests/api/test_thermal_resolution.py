"""A command resolves its thermal mode once: ``og.evaluate``, ``og.optimize`` and
``oilgap optimize``/``evaluate`` check the mode against the case at the top and pass the
resolved :class:`~oilgap.model.thermal_modes.ThermalMode` down; the model's reports
(``evaluate_case``, ``operating_temperature``, ``film_band``) and the design NLP take it
as it is. Counted by wrapping the resolvers wherever a module holds them."""

from __future__ import annotations

import contextlib
import importlib
import io
import pkgutil
import sys
from pathlib import Path

import pytest

import oilgap
import oilgap as og
from oilgap.cli import main
from oilgap.model import joint_loss
from oilgap.model.errors import InputError
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import read_case_toml, seed_case
from oilgap.model.thermal_modes import ThermalMode

MY_JOINT = Path(__file__).parents[2] / "examples" / "my_joint.toml"
RESOLVERS = ("resolve_thermal_mode", "default_thermal_mode")


def _import_all() -> None:
    """Import every module of the package (not ``__main__``), so that the wrappers reach
    each module that imported a resolver by name."""
    for m in pkgutil.walk_packages(oilgap.__path__, "oilgap."):
        if "__main__" not in m.name:
            with contextlib.suppress(ImportError):
                importlib.import_module(m.name)


@pytest.fixture
def resolutions(monkeypatch):
    """A list that gets one entry per resolution: a call of a resolver from outside the
    resolvers (``resolve_thermal_mode`` calling ``default_thermal_mode`` is one)."""
    _import_all()
    seen: list[str] = []
    depth = [0]

    def wrap(name, f):
        def counted(*a, **k):
            if depth[0] == 0:
                seen.append(name)
            depth[0] += 1
            try:
                return f(*a, **k)
            finally:
                depth[0] -= 1
        return counted

    wrapped = 0
    for name in RESOLVERS:
        orig = getattr(joint_loss, name)
        w = wrap(name, orig)
        for mod in list(sys.modules.values()):
            if getattr(mod, "__name__", "").startswith("oilgap"):
                for attr, val in list(vars(mod).items()):
                    if val is orig:
                        monkeypatch.setattr(mod, attr, w)
                        wrapped += 1
    assert wrapped >= 4  # joint_loss, the façade, the grid runner, the studies
    return seen


@pytest.fixture(scope="module")
def hot():
    case = read_case_toml(MY_JOINT)
    assert case.thermal is not None
    return case


@pytest.mark.parametrize("thermal", [None, "none", "full"])
def test_evaluate_resolves_once(resolutions, hot, thermal):
    res = og.evaluate(hot, thermal=thermal)
    assert len(resolutions) == 1
    assert res.raw.thermal_mode == ("bulk" if thermal is None else thermal)
    assert res.raw.thermal_mode_default is (thermal is None)


@pytest.mark.parametrize("thermal", [None, "film"])
def test_optimize_resolves_once(resolutions, hot, thermal):
    og.optimize(hot, thermal=thermal, starts=1)
    assert len(resolutions) == 1


@pytest.mark.parametrize("argv", [["optimize", "--starts", "1"], ["evaluate"]])
def test_the_command_line_resolves_once(resolutions, argv):
    with contextlib.redirect_stdout(io.StringIO()) as out:
        assert main([argv[0], str(MY_JOINT), *argv[1:]]) == 0
    assert len(resolutions) == 1
    assert "(default:" in out.getvalue()  # the default still reported as one


def test_the_counter_counts(resolutions, hot):
    # a mode given as a string is resolved by the function that takes it
    evaluate_case(hot, thermal="bulk")
    assert len(resolutions) == 1


def test_a_resolved_mode_that_does_not_fit_the_case_is_refused():
    # resolved for a case with [thermal], passed with one without: checked again
    with pytest.raises(InputError, match="thermal"):
        evaluate_case(seed_case(), thermal=ThermalMode.BULK)
