"""The façade is the top package: its modules are private, the engines never import it.

``api/`` is installed as ``oilgap`` itself; ``og.*``, the result views and the command line
live there in private modules (``_evaluate.py``, ``_results.py``, ...), re-exported lazily by
``api/__init__.py``. Arrows point down: no module of ``model/``, ``optim/`` or ``studies/``
imports the façade or the command line.
"""

from __future__ import annotations

import ast
from pathlib import Path

import oilgap as og

ROOT = Path(__file__).resolve().parents[2]


def _facade_imports(path: Path) -> list[str]:
    """The façade or CLI modules that ``path`` imports (``oilgap``, ``oilgap._x``, ``.cli``)."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names = [node.module]
        elif isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        else:
            continue
        for name in names:
            parts = name.split(".")
            if parts[0] == "oilgap" and (len(parts) == 1 or parts[1].startswith("_")
                                         or parts[1] == "cli"):
                found.append(name)
    return found


def test_no_engine_imports_the_facade_or_the_cli():
    offenders = {str(p.relative_to(ROOT)): _facade_imports(p)
                 for pkg in ("model", "optim", "studies") for p in (ROOT / pkg).rglob("*.py")}
    offenders = {k: v for k, v in offenders.items() if v}
    assert offenders == {}


def test_facade_modules_are_private():
    public = [p.name for p in (ROOT / "api").glob("*.py")
              if not p.name.startswith("_")]
    assert public == []
    assert not list((ROOT / "studies").glob("api*.py"))
    assert not list((ROOT / "studies").glob("results*.py"))


def test_dir_shows_only_the_public_names():
    assert dir(og) == sorted(og.__all__)
    assert all(not n.startswith("_") or n == "__version__" for n in dir(og))
    for name in og.EXPORTS:
        assert getattr(og, name).__name__ == name
    assert dir(og) == sorted(og.__all__)  # loading names does not add to dir()


def test_views_declare_their_fields_and_forward_nothing():
    """No ``__getattr__`` forwarding: each field a view shows is declared on it and is a
    field of the module-level result it reads (so a renamed field fails here)."""
    import dataclasses

    from oilgap._results import ResultView
    from oilgap.model.evaluation import CaseEvaluation
    from oilgap.optim.design.results import DesignResult
    from oilgap.studies.oil_grade.study import OilGradeResult
    from oilgap.studies.pareto import ParetoResult
    from oilgap.studies.smoothing.study import SmoothingResult

    assert "__getattr__" not in vars(ResultView)
    raws = {og.Evaluation: CaseEvaluation, og.Optimization: DesignResult,
            og.Pareto: ParetoResult, og.OilGrade: OilGradeResult,
            og.Smoothing: SmoothingResult}
    for view, raw in raws.items():
        fields = {f.name for f in dataclasses.fields(raw)}
        declared = {n for n, v in vars(view).items() if isinstance(v, property)}
        own = {"defaults"} | ({"result", "thermal_mode"} if view is og.Optimization else set())
        assert declared - own <= fields, view
        assert len(declared) >= 5, view
    ev = og.evaluate(None)
    assert ev.thermal_mode == ev.raw.thermal_mode and ev.regions is ev.raw.regions
    try:
        ev.not_a_field  # noqa: B018
    except AttributeError:
        pass
    else:
        raise AssertionError("a view forwarded an unknown attribute")


def test_loop_init_only_stores_and_unfitted_methods_refuse(tmp_path):
    """``og.Loop(...)`` reads nothing (a missing case file is only met in ``fit``), takes
    no ``**options``, and a method that needs the fit names ``fit`` first."""
    import inspect

    import pytest

    params = inspect.signature(og.Loop).parameters.values()
    assert all(p.kind is not inspect.Parameter.VAR_KEYWORD for p in params)
    missing = tmp_path / "missing.toml"
    loop = og.Loop(missing, oils=tmp_path / "missing.csv", effects="a,b", max_effects=2)
    assert (loop.case, loop.effects, loop.max_effects) == (missing, "a,b", 2)
    for call in (loop.summary, loop.to_frame, loop.to_dict, loop.plot, loop.fitted_model,
                 lambda: loop.report(tmp_path / "out")):
        with pytest.raises(og.NotFittedError, match=r"call fit\(data\) before"):
            call()
    assert issubclass(og.NotFittedError, og.InputError)
    with pytest.raises(og.InputError):
        loop.fit(tmp_path / "runs.csv")
    assert loop.case == missing  # fit leaves the arguments as given
    assert not (tmp_path / "out").exists()
