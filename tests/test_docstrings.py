"""Docstrings are part of the interface: every public function documents itself and
every module that implements a law cites its reference (python-control style)."""

import importlib
import inspect
import pkgutil

import pytest

import oilgap.model

LAW_MODULES = ["oil_properties", "taylor_couette", "skin_friction", "viscous_loss",
               "motor"]


def public_functions(mod):
    for name, obj in vars(mod).items():
        if name.startswith("_") or not inspect.isfunction(obj):
            continue
        if obj.__module__ == mod.__name__:
            yield name, obj


@pytest.mark.parametrize("modname", [m.name for m in pkgutil.iter_modules(oilgap.model.__path__)
                                     if not m.name.startswith("_")])
def test_public_functions_have_docstrings(modname):
    mod = importlib.import_module(f"oilgap.model.{modname}")
    assert mod.__doc__ and mod.__doc__.strip()
    missing = [n for n, f in public_functions(mod) if not (f.__doc__ or "").strip()]
    assert missing == []


@pytest.mark.parametrize("modname", LAW_MODULES)
def test_law_modules_cite_references_and_units(modname):
    mod = importlib.import_module(f"oilgap.model.{modname}")
    assert "References" in mod.__doc__
    for name, f in public_functions(mod):
        doc = f.__doc__
        assert "[" in doc, f"{modname}.{name}: no unit in brackets or reference"
