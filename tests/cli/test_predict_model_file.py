"""Issue 20, class 3: ``predict`` never trusts the saved model.

A loop.json edited by hand, cut short or left by a loop that did not finish is checked once
on load (:mod:`oilgap.optim.calibration.model_schema`): every row of :data:`ROWS` is a real
model written by ``oilgap loop`` on a small synthetic rig (oil-free runs, so the model
holds baselines), then tampered with, and states the promise it checks. Each row runs
through the command line (``oilgap predict``: exit 2, exactly one ``oilgap: error:`` line
naming the field by its JSON path, no traceback, no output file) and through the façade
(``og.predict``: the project's :class:`~oilgap.model.errors.InputError`, one line, the same
field). Rows that must be accepted predict finite numbers only (never a NaN prediction).
"""

from __future__ import annotations

import contextlib
import io
import json
import re
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import oilgap as og
from oilgap.cli import main
from oilgap.model.errors import InputError, OilgapWarning
from oilgap.studies.rigs.synth import SynthConfig, synthesize

STAGE = "with_effect"


@pytest.fixture(scope="module")
def saved(tmp_path_factory) -> tuple[str, pd.DataFrame]:
    """loop.json written by ``oilgap loop`` on a small rig with oil-free runs (fitted once
    per module, about 3 s), and the rig's oil rows without power, to predict."""
    d = tmp_path_factory.mktemp("fit")
    df = synthesize(SynthConfig(n_samples=30, kind="power_W", oils=("VG320", "VG1000")),
                    seed=1)
    df.to_csv(d / "rig.csv", index=False)
    with contextlib.redirect_stdout(io.StringIO()):
        assert main(["loop", str(d / "rig.csv"), "--out", str(d / "o"), "--no-figures"]) == 0
    text = (d / "o" / "loop.json").read_text()
    assert len(json.loads(text)["model"]["baselines"]) == 2  # what the rows tamper with
    return text, df[df["oil"] != "none"].drop(columns=["power_W"])


# --------------------------------------------------------------------------- edits


def _model(edit: Callable[[dict], object]) -> Callable[[str], str]:
    """An edit of the parsed ``model`` block, written back as JSON."""
    def apply(text: str) -> str:
        doc = json.loads(text)
        edit(doc["model"])
        return json.dumps(doc)
    return apply


def _set(path: str, value) -> Callable[[str], str]:
    """Set ``model.<path>`` (dots; ``[i]`` indexes a list) to ``value``."""
    keys = [int(k) if k.isdigit() else k for k in path.replace("[", ".").replace("]", "")
            .split(".")]

    def edit(m: dict) -> None:
        for k in keys[:-1]:
            m = m[k]
        m[keys[-1]] = value
    return _model(edit)


def _drop(path: str) -> Callable[[str], str]:
    keys = path.split(".")

    def edit(m: dict) -> None:
        for k in keys[:-1]:
            m = m[k]
        del m[keys[-1]]
    return _model(edit)


def _text(old: str, new: str) -> Callable[[str], str]:
    """Replace the first ``old`` of the file's text (a literal JSON cannot hold)."""
    def apply(text: str) -> str:
        assert old in text, f"{old!r} not in the saved model"
        return text.replace(old, new, 1)
    return apply


def _gamma_literal(literal: str) -> Callable[[str], str]:
    """The with_effect law's gamma written as ``literal`` (NaN, Infinity, ...)."""
    def apply(text: str) -> str:
        doc = json.loads(text)
        doc["model"]["laws"][STAGE]["gamma"] = "@@"
        return json.dumps(doc).replace('"@@"', literal)
    return apply


def _add_effect(name: str, value: float, shapes: dict | None = None):
    def edit(m: dict) -> None:
        m["effects"][name] = value
        if shapes:
            m.setdefault("shapes", {}).update(shapes)
        if name == "film_heating":
            m["thermal_mode"] = "film"
    return _model(edit)


def _branches(n_alpha: int):
    def edit(m: dict) -> None:
        m["laws"]["with_T"].update(form="branches", branch_C=[10.0, 2.0, 1.03, 0.065],
                                   branch_alpha=[0.3] * n_alpha,
                                   branch_beta=[-1.0, -0.6, -0.5, -0.2])
    return _model(edit)


FILM = {"film_heating": {"coefficient": "film_strength", "wall_floating": 0.0}}


def _incomplete(d: Path) -> None:
    (d / "INCOMPLETE").write_text("oilgap loop started writing here\n")


@dataclass(frozen=True)
class Case:
    """One saved-model variant and what must happen."""

    id: str
    promise: str
    edit: Callable[[str], str] | None = None
    needle: str = ""
    accepted: bool = False
    setup: Callable[[Path], None] | None = None


ROWS = [
    # the file as a whole
    Case("truncated", "a loop.json cut short is refused as not JSON, naming the file",
         lambda t: t[: len(t) // 2], r"--model.*not JSON"),
    Case("empty-file", "an empty loop.json is refused as not JSON", lambda t: "",
         r"--model.*not JSON"),
    Case("top-level-array", "a JSON array instead of the object is refused naming its type",
         lambda t: "[1, 2]", r"--model.*JSON list"),
    Case("model-block-a-number", "a 'model' block that is not an object is refused",
         lambda t: json.dumps({"model": 5}), r"\bmodel = 'int'"),
    Case("version-2", "a version this oilgap does not read is refused naming the version",
         _set("version", 2), r"model\.version = 2"),
    Case("unknown-key", "a key the model block does not have (a typo) is refused by name",
         _set("gama", 0.5), r"model\.gama"),
    Case("duplicate-key", "a key given twice in one object is refused naming it",
         _text('"thermal_mode": "none"', '"thermal_mode": "none", "thermal_mode": "film"'),
         r"model\.thermal_mode = 'given twice'"),
    # missing keys, wrong types
    Case("missing-laws", "a missing required block is refused naming it",
         _drop("laws"), r"model\.laws = 'missing'"),
    Case("missing-stage", "a missing stage's law is refused naming the stage",
         _drop("laws.with_T"), r"model\.laws\.with_T = 'missing'"),
    Case("missing-gamma", "a law without gamma is refused naming the field",
         _drop(f"laws.{STAGE}.gamma"), rf"model\.laws\.{STAGE}\.gamma = 'missing'"),
    Case("gamma-text", "a string where a number is is refused naming the field",
         _set(f"laws.{STAGE}.gamma", "high"), rf"model\.laws\.{STAGE}\.gamma = 'high'"),
    Case("gamma-bool", "true where a number is is refused (a bool is not a number)",
         _set(f"laws.{STAGE}.gamma", True), rf"model\.laws\.{STAGE}\.gamma = True"),
    Case("scale-nan-string", "the string 'nan' where a number is is refused",
         _set("laws.with_T.scale", "nan"), r"model\.laws\.with_T\.scale = 'nan'"),
    Case("effects-a-list", "a block of the wrong type is refused naming it",
         _set("effects", []), r"model\.effects = 'list'"),
    # NaN / Infinity literals
    Case("gamma-NaN-literal", "a NaN literal (not JSON) is refused naming the field",
         _gamma_literal("NaN"), rf"model\.laws\.{STAGE}\.gamma = 'NaN'"),
    Case("gamma-Infinity-literal", "an Infinity literal is refused naming the field",
         _gamma_literal("Infinity"), rf"model\.laws\.{STAGE}\.gamma = 'Infinity'"),
    Case("gamma-1e400-overflows", "a number too large for a float (read as inf) is refused",
         _gamma_literal("1e400"), rf"model\.laws\.{STAGE}\.gamma = inf"),
    Case("gamma-400-digit-integer", "an integer too large for a float is refused",
         _gamma_literal("1" + "0" * 400), rf"model\.laws\.{STAGE}\.gamma = 'an integer of 401"),
    Case("gap-minus-Infinity", "a -Infinity literal anywhere is refused naming the field",
         _text('"region1_gap_m": ', '"region1_gap_m": -Infinity, "x": '),
         r"model\.region1_gap_m = '-Infinity'"),
    # ranges of the fitted numbers
    Case("gamma-5", "gamma outside the documented [0, 3] is refused with the range",
         _set(f"laws.{STAGE}.gamma", 5.0), rf"model\.laws\.{STAGE}\.gamma = 5\.0.*\[0, 3\]"),
    Case("gamma-1e300", "gamma = 1e300 is refused (it overflowed to NaN predictions)",
         _set(f"laws.{STAGE}.gamma", 1e300), rf"model\.laws\.{STAGE}\.gamma = 1e\+300"),
    Case("gamma-negative", "a negative gamma (grooves lowering the loss) is refused",
         _set("laws.with_T.gamma", -0.5), r"model\.laws\.with_T\.gamma = -0\.5"),
    Case("scale-negative", "a negative scale is refused naming the field and the range",
         _set("laws.with_T.scale", -1.0), r"model\.laws\.with_T\.scale = -1\.0.*\[0\.01, 100\]"),
    Case("scale-zero", "a zero scale (no loss at all) is refused",
         _set(f"laws.{STAGE}.scale", 0.0), rf"model\.laws\.{STAGE}\.scale = 0\.0"),
    Case("beta-wild", "a Reynolds exponent no clearance flow has is refused",
         _set("laws.without_T.beta", 4.0), r"model\.laws\.without_T\.beta = 4\.0"),
    Case("form-unknown", "a friction form that does not exist is refused with the forms",
         _set(f"laws.{STAGE}.form", "magic"), rf"model\.laws\.{STAGE}\.form = 'magic'.*smooth"),
    Case("branches-lengths", "branch arrays of different lengths are refused naming one",
         _branches(3), r"model\.laws\.with_T\.branch_alpha = '3 numbers'.*4 numbers"),
    Case("gap-negative", "a negative region-1 clearance is refused",
         _set("region1_gap_m", -0.001), r"model\.region1_gap_m = -0\.001"),
    Case("gap-beyond-rotor", "a clearance wider than the rotor's radius is refused",
         _set("region1_gap_m", 1.0), r"model\.region1_gap_m = 1\.0.*rotor radius"),
    Case("fitted-range-reversed", "a fitted range with low > high is refused",
         _set("fitted_range.temp_C", [40.0, 20.0]), r"model\.fitted_range\.temp_C"),
    Case("pressure-negative", "a negative gauge pressure is refused",
         _set("pressure_gauge_Pa", -5.0), r"model\.pressure_gauge_Pa = -5\.0"),
    # baselines: lengths and names
    Case("baseline-coef-short", "a baseline coefficient list of the wrong length is refused "
         "naming it (it gave a matmul traceback)", _model(
             lambda m: m["baselines"][0]["coef"].pop()),
         r"model\.baselines\[0\]\.coef = '5 numbers'.*\(6\)"),
    Case("baseline-coef-text", "a string among the baseline's coefficients is refused",
         _set("baselines[1].coef[2]", "x"), r"model\.baselines\[1\]\.coef\[2\] = 'x'"),
    Case("baseline-terms-unknown", "a basis function the baseline does not know is refused",
         _set("baselines[0].terms[5]", "w^3"), r"model\.baselines\[0\]\.terms"),
    Case("baseline-T-below-1", "a baseline roughness T < 1 is refused",
         _set("baselines[0].roughness_T", 0.5), r"model\.baselines\[0\]\.roughness_T = 0\.5"),
    Case("baseline-twice", "two baselines of one roughness T are refused",
         _set("baselines[1].roughness_T", 2.0),
         r"model\.baselines = '2, 2'.*one baseline per roughness T"),
    # effects: names, signs, plausible ranges
    Case("effect-unknown", "an effect the library does not hold is refused naming it",
         _add_effect("magic_drag", 1.0), r"model\.effects\.magic_drag.*library"),
    Case("effect-negative", "a coefficient of the wrong sign is refused",
         _add_effect("seal_coulomb_friction", -0.1),
         r"model\.effects\.seal_coulomb_friction = -0\.1"),
    Case("effect-implausible", "a coefficient outside the library's plausible range is "
         "refused with the range", _add_effect("sensor_delay", 10.0),
         r"model\.effects\.sensor_delay = 10\.0.*\[0, 2\]"),
    Case("film-strength-above-1", "a film strength s > 1 is refused (s in [0, 1])",
         _add_effect("film_heating", 1.5, FILM), r"model\.effects\.film_heating = 1\.5"),
    Case("taylor-exponent-7", "a Taylor-vortex exponent the loop does not fit is refused",
         _add_effect("taylor_vortex_onset", 0.5, {"taylor_vortex_onset": {"exponent": 7.0}}),
         r"model\.shapes\.taylor_vortex_onset\.exponent = 7\.0"),
    # names of the enums, and the nested blocks
    Case("thermal-mode-unknown", "a thermal mode outside the loop's enum is refused",
         _set("thermal_mode", "hot"), r"model\.thermal_mode = 'hot'.*none, film"),
    Case("kind-unknown", "a power column the loop does not fit is refused",
         _set("kind", "torque_Nm"), r"model\.kind = 'torque_Nm'"),
    Case("case-radius-text", "a tampered rig case is refused naming its field",
         _set("case.region1.T1_mm", "abc"), r"model\.case\..*T1_mm"),
    Case("fluid-negative-viscosity", "a tampered fluid is refused naming the fluid",
         _set("fluids.VG320.nu40_cSt", -1.0), r"model\.fluids\.VG320"),
    # an unfinished folder
    Case("incomplete-folder", "a model from a folder marked INCOMPLETE is refused, saying "
         "what to do", None, r"INCOMPLETE.*oilgap loop again.*--allow-incomplete",
         setup=_incomplete),
    # what must still be accepted
    Case("untouched", "the model as the loop saved it predicts finite numbers", None,
         accepted=True),
    Case("plausible-effect-by-hand", "a plausible effect added by hand is accepted",
         _add_effect("seal_coulomb_friction", 0.05), accepted=True),
    Case("gamma-3-at-the-bound", "gamma = 3, the range's end, is accepted",
         _set(f"laws.{STAGE}.gamma", 3.0), accepted=True),
    Case("film-strength-1", "a film strength at its bound s = 1 is accepted",
         _add_effect("film_heating", 1.0, FILM), accepted=True),
    Case("branches-law", "a branches law with one number per branch is accepted",
         _branches(4), accepted=True),
    Case("taylor-exponent-half", "a Taylor-vortex exponent the loop fits (0.5) is accepted",
         _add_effect("taylor_vortex_onset", 0.5, {"taylor_vortex_onset": {"exponent": 0.5}}),
         accepted=True),
]


def _write(case: Case, saved, d: Path) -> tuple[Path, Path]:
    text, new = saved
    d.mkdir(parents=True, exist_ok=True)
    model = d / "loop.json"
    model.write_text(case.edit(text) if case.edit else text)
    data = d / "new.csv"
    new.to_csv(data, index=False)
    if case.setup:
        case.setup(d)
    return model, data


def _finite(pred: pd.DataFrame) -> None:
    for c in ("predicted_viscous_power_W", "predicted_power_W"):
        v = pred[c].to_numpy(float)
        assert np.isfinite(v).all() and (pred["prediction_note"].fillna("") == "").all(), c


@pytest.mark.parametrize("case", ROWS, ids=[c.id for c in ROWS])
def test_cli(case: Case, saved, tmp_path, capsys):
    model, data = _write(case, saved, tmp_path)
    out = tmp_path / "p.csv"
    capsys.readouterr()
    rc = main(["predict", str(data), "--model", str(model), "--out", str(out)])
    err = [ln for ln in capsys.readouterr().err.splitlines() if ln.strip()]
    assert "Traceback" not in "\n".join(err), case.promise
    if case.accepted:
        assert rc == 0 and not err, (case.promise, err)
        _finite(pd.read_csv(out))
        return
    assert rc == 2 and len(err) == 1 and err[0].startswith("oilgap: error:"), \
        (case.promise, rc, err)
    assert re.search(case.needle, err[0]), (case.promise, err[0])
    assert not out.exists(), case.promise


@pytest.mark.parametrize("case", ROWS, ids=[c.id for c in ROWS])
def test_facade(case: Case, saved, tmp_path):
    model, data = _write(case, saved, tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)   # no overflow on the way
        if case.accepted:
            _finite(og.predict(str(model), data, stage=STAGE))
            return
        with pytest.raises(InputError) as e:
            og.predict(model, data, stage=STAGE)
    msg = str(e.value)
    assert "\n" not in msg, case.promise
    assert re.search(case.needle, msg), (case.promise, msg)


def test_incomplete_folder_when_asked_predicts_with_a_warning(saved, tmp_path, capsys):
    """--allow-incomplete / allow_incomplete=True: the model is used and a warning line
    says its folder is incomplete; the schema is still checked."""
    model, data = _write(ROWS[[c.id for c in ROWS].index("incomplete-folder")], saved,
                         tmp_path)
    out = tmp_path / "p.csv"
    assert main(["predict", str(data), "--model", str(model), "--out", str(out),
                 "--allow-incomplete"]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("oilgap: warning:") and \
        "marked incomplete" in err[0]
    _finite(pd.read_csv(out))
    with pytest.warns(OilgapWarning, match="marked incomplete"):
        _finite(og.predict(model, data, allow_incomplete=True))
    with pytest.raises(InputError, match="allow_incomplete"):
        og.predict(model, data, allow_incomplete="yes")
    model.write_text(_set(f"laws.{STAGE}.gamma", 5.0)(saved[0]))
    with pytest.warns(OilgapWarning), pytest.raises(InputError, match="gamma"):
        og.predict(model, data, allow_incomplete=True)


def test_the_table_covers_the_promises():
    """At least 15 refused variants, each a distinct id with its promise stated; the
    untouched model is accepted (the schema refuses what the loop never writes)."""
    refused = [c for c in ROWS if not c.accepted]
    assert len(refused) >= 15 and len({c.id for c in ROWS}) == len(ROWS)
    assert all(c.promise and (c.accepted or c.needle) for c in ROWS)
