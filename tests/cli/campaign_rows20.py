"""Issue 20's rows of the bad-input campaign (:data:`ROWS20`, added to
``test_campaign.ROWS``): the Python façade's wrong arguments (class 1), conflicting
options on the command line and in the façade (class 4), hand-edited sweep stores
(class 2), and the rows of ``test_issue20_inputs.py`` (classes 5-7: a heat balance without
a root, impossible joints and fluids, values quoted as written) through the command line
and the façade; each row states the promise it checks.

How to add a row (the list is :data:`ROWS20`; each section below is a marked block):

* a command line: ``cli(id, argv, expect, needle, promise, files=..., setup=...)``, as
  ``row`` in ``test_campaign.py`` (``argv`` without ``oilgap``; ``files``: name ->
  content written into the row's fresh folder first; ``setup``: functions of the folder);
* a façade call: ``facade(id, call, expect, needle, promise, ...)`` where ``call`` takes
  the row's folder and calls ``og.*`` (``lambda d: og.read_case(None)``). An InputError
  with a one-line message is "refused"; returning is "accepted" (or "warned" with an
  OilgapWarning); any other exception is still failing (a broken promise).

``expect`` is "refused", "warned", "accepted" or several joined by ``|``; ``needle`` holds
regular expressions the message must match (the argument or option named, the value or
its type, what is allowed).
"""

from __future__ import annotations

import json
import re
import shlex
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
from campaign_table import Row
from test_campaign import DROP, case, rig, run_cli, with_model
from test_issue20_inputs import CASE as CASE20
from test_issue20_inputs import ROWS as INPUT_ROWS

import oilgap as og
from oilgap.model.oils import builtin_oils

ROWS20: list[Row] = []
GROUP = "?"


def _add(id, argv, expect, needle, promise, files=None, setup=(), outputs=(), call=None,
         check=None):
    ROWS20.append(Row(id, argv, tuple(expect.split("|")), GROUP,
                      (needle,) if isinstance(needle, str) else tuple(needle), files or {},
                      setup if isinstance(setup, tuple) else (setup,), outputs, check, (),
                      None, "", call, promise))


def cli(id: str, argv: str, expect: str, needle, promise: str, **kw) -> None:
    """A command-line row of :data:`ROWS20`."""
    _add(id, argv, expect, needle, promise, **kw)


def facade(id: str, call: Callable[[Path], object], expect: str, needle, promise: str,
           text: str = "", **kw) -> None:
    """A façade row of :data:`ROWS20`: ``call(folder)`` runs ``og.*`` in-process."""
    _add(id, text or f"og ({id})", expect, needle, promise, call=call, **kw)


GRID_CSV = {"grid.csv": "gap_mm\n0.8\n1.2\n"}
VG1000 = builtin_oils()["VG1000"]
RIG_OIL = {"RigOil": {"nu40_cSt": 46.0, "nu100_cSt": 7.0, "density_kg_m3": 870.0}}
OILS_CSV = {"oils.csv": "oil,nu40_cSt,nu100_cSt,density_kg_m3\nRigOil,46,7,870\n"}
OILS_VG22 = {"oils.csv": "oil,nu40_cSt,nu100_cSt,density_kg_m3\nVG22,25,4.9,860\n"}
THERMAL = {"sea_temp_C": 4.0, "resistance_K_per_W": 0.05, "heat_capacity_J_per_K": 4000.0}


def _grid() -> pd.DataFrame:
    return pd.DataFrame({"gap_mm": [0.8, 1.2]})


def _model_doc(d: Path) -> dict:
    return json.loads((d / "loop.json").read_text())


def _custom_rig(df: pd.DataFrame) -> pd.DataFrame:
    """The VG1000 runs renamed to a custom oil with VG1000's properties: the data name a
    custom oil and an ISO oil (VG320)."""
    return df.assign(oil=df["oil"].replace({"VG1000": "MyVG1000"}),
                     run=df["run"].str.replace("VG1000", "MyVG1000"))


MY_VG1000 = {"oils.csv": "oil,nu40_cSt,nu100_cSt,density_kg_m3\n"
             f"MyVG1000,{VG1000.nu40_cSt:g},{VG1000.nu100_cSt:g},{VG1000.density_kg_m3:g}\n"}


# ==================================================================== class 1: the façade
GROUP = "20.1 façade: wrong argument types"
_P = "the façade refuses"
facade("og-read-case-none", lambda d: og.read_case(None), "refused",
       (r"path = None", r"str or pathlib\.Path"), f"1: {_P} read_case(None) naming path")
facade("og-read-case-int", lambda d: og.read_case(42), "refused",
       (r"path = 42 \(int\)",), f"1: {_P} read_case(42), the value and its type named")
facade("og-read-case-missing", lambda d: og.read_case("missing.toml"), "refused",
       "missing.toml", f"1: {_P} a case path that does not exist, naming it")
facade("og-read-case-empty-path", lambda d: og.read_case(""), "refused",
       (r"path = ''", "non-empty path"), f"1: {_P} an empty path")
facade("og-read-measured-int", lambda d: og.read_measured(42), "refused",
       (r"path = 42 \(int\)", "DataFrame"), f"1: {_P} read_measured(42)")
facade("og-read-measured-none", lambda d: og.read_measured(None), "refused",
       (r"path = None",), f"1: {_P} read_measured(None)")
facade("og-read-measured-array", lambda d: og.read_measured(np.zeros((2, 2))), "refused",
       (r"numpy ndarray of shape \(2, 2\)",), f"1: {_P} a numpy array as rig data")
facade("og-read-measured-frame-empty", lambda d: og.read_measured(pd.DataFrame()),
       "refused", ("speed_rpm",), f"1: {_P} an empty DataFrame naming the missing columns")
facade("og-predict-int", lambda d: og.predict(42, "new.csv"), "refused",
       (r"model = 42 \(int\)", "loop.json"), f"1: {_P} predict(42, ...) naming model",
       setup=with_model)
facade("og-predict-model-dict", lambda d: og.predict(_model_doc(d), "new.csv"), "refused",
       (r"model = a dict", "path"), "1: a model dict (read from loop.json) is refused by "
       "name, saying to pass the file's path", setup=with_model)
facade("og-predict-none", lambda d: og.predict(None, "new.csv"), "refused",
       (r"model = None",), f"1: {_P} predict(None, ...)", setup=with_model)
facade("og-predict-data-int", lambda d: og.predict("loop.json", 42), "refused",
       (r"data = 42",), f"1: {_P} data of a wrong type", setup=with_model)
facade("og-predict-stage", lambda d: og.predict("loop.json", "new.csv", stage="final"),
       "refused", (r"stage = 'final'", "with_effect"), f"1: {_P} an unknown stage",
       setup=with_model)
facade("og-oil-grade-mission-ints", lambda d: og.oil_grade(mission=[1, 2]), "refused",
       (r"mission\[0\] = 1 \(int\)", "depth_m"), f"1: {_P} a mission of numbers")
facade("og-oil-grade-mission-int", lambda d: og.oil_grade(mission=42), "refused",
       (r"mission = 42",), f"1: {_P} a mission that is a number")
facade("og-oil-grade-mission-dict", lambda d: og.oil_grade(mission={"depth_m": 0.0}),
       "refused", (r"mission = a dict",), "1: a mission as one dict is refused by name "
       "(a list of rows or a DataFrame is documented)")
facade("og-oil-grade-mission-nan", lambda d: og.oil_grade(mission=[(float("nan"), 20, 1)]),
       "refused", (r"depth_m = nan",), f"1: {_P} a NaN in a mission row")
facade("og-evaluate-oils-plain-dict", lambda d: og.evaluate(oils=RIG_OIL, oil="RigOil"),
       "accepted", (), "1: oils as {name: {nu40_cSt, nu100_cSt, density_kg_m3}} is accepted "
       "(the CSV's columns, documented)")
facade("og-evaluate-oils-bad-key", lambda d: og.evaluate(
    oils={"X": {"nu40": 46.0, "nu100_cSt": 7.0, "density_kg_m3": 870.0}}, oil="X"),
    "refused", (r"nu40 = 46", "nu40_cSt"), f"1: {_P} an oil dict with an unknown key")
facade("og-evaluate-oils-nan", lambda d: og.evaluate(
    oils={"X": {"nu40_cSt": float("nan"), "nu100_cSt": 7.0, "density_kg_m3": 870.0}},
    oil="X"), "refused", (r"nu40_cSt = nan",), f"1: {_P} NaN in an oil dict")
facade("og-evaluate-oils-negative", lambda d: og.evaluate(
    oils={"X": {"nu40_cSt": -46.0, "nu100_cSt": 7.0, "density_kg_m3": 870.0}}, oil="X"),
    "refused", (r"nu40_cSt = -46", "> 0"), f"1: {_P} a negative viscosity in an oil dict")
facade("og-evaluate-oils-list", lambda d: og.evaluate(oils=["VG22"]), "refused",
       (r"oils = a list",), f"1: {_P} oils as a list")
facade("og-evaluate-case-int", lambda d: og.evaluate(42), "refused", (r"case = 42",),
       f"1: {_P} evaluate(42)")
facade("og-evaluate-case-dict", lambda d: og.evaluate({"region1": {}}), "refused",
       (r"case = a dict", "DesignCase"), "1: a case as a dict is refused by name (a "
       "DesignCase or its TOML is documented)")
facade("og-evaluate-temp-nan", lambda d: og.evaluate(oil_temp_C=float("nan")), "refused",
       (r"oil_temp_C = nan",), f"1: {_P} a NaN temperature")
facade("og-evaluate-depth-array", lambda d: og.evaluate(depth_m=np.array([1.0, 2.0])),
       "refused", (r"depth_m = a numpy ndarray of shape \(2,\)",),
       f"1: {_P} an array where a number is taken")
facade("og-evaluate-thermal-int", lambda d: og.evaluate(thermal=3), "refused",
       (r"thermal = 3", "bulk"), f"1: {_P} thermal=3")
facade("og-optimize-starts-text", lambda d: og.optimize(starts="8"), "refused", "starts",
       f"1: {_P} starts as text")
facade("og-optimize-unknown-keyword", lambda d: og.optimize(bogus=1), "refused",
       ("bogus", "starts"), "1: an unknown keyword is the project's error naming it and "
       "the keywords allowed")
facade("og-sweep-grid-int", lambda d: og.sweep(42), "refused", (r"grid = 42",),
       f"1: {_P} sweep(42)")
facade("og-sweep-grid-array", lambda d: og.sweep(np.zeros((2, 2))), "refused",
       (r"grid = a numpy ndarray",), f"1: {_P} a numpy grid")
facade("og-sweep-grid-missing", lambda d: og.sweep("nogrid.csv"), "refused", "nogrid.csv",
       f"1: {_P} a grid path that does not exist")
facade("og-sweep-out-int", lambda d: og.sweep(_grid(), out=42), "refused", (r"out = 42",),
       f"1: {_P} out=42")
facade("og-pareto-points-text", lambda d: og.pareto(points="50"), "refused", "points",
       f"1: {_P} points as text")
facade("og-pareto-out-int", lambda d: og.pareto(out=42), "refused", (r"out = 42",),
       f"1: {_P} an out folder of a wrong type")
facade("og-smoothing-T-values-text", lambda d: og.smoothing(T_values="abc"), "refused",
       "T_values", f"1: {_P} T_values as text")
facade("og-smoothing-force-text", lambda d: og.smoothing(force="yes"), "refused",
       (r"force = 'yes'", "True or False"), f"1: {_P} force='yes'")
facade("og-loop-fit-int", lambda d: og.Loop().fit(42), "refused", (r"data = 42",),
       f"1: {_P} Loop().fit(42)")
facade("og-loop-effects-int", lambda d: og.Loop(effects=42).fit("data.csv"), "refused",
       (r"effects = 42",), f"1: {_P} Loop(effects=42)", setup=rig())
facade("og-loop-case-int", lambda d: og.Loop(case=42).fit("data.csv"), "refused",
       (r"case = 42",), f"1: {_P} Loop(case=42)", setup=rig())
facade("og-loop-unfitted", lambda d: og.Loop().summary(), "refused", "fit",
       "1: a method of an unfitted Loop names fit")
facade("og-synth-roughness-int", lambda d: og.synth(roughness=42), "refused",
       (r"roughness = 42",), f"1: {_P} roughness=42")
facade("og-write-case-int", lambda d: og.write_case(42, "x.toml"), "refused",
       (r"case = 42", "DesignCase"), f"1: {_P} write_case(42, ...)")
facade("og-seed-case-text", lambda d: og.seed_case("yes"), "refused", (r"smoothed = 'yes'",),
       f"1: {_P} seed_case('yes')")
facade("og-to-json-int", lambda d: og.evaluate().to_json(42), "refused", (r"path = 42",),
       f"1: {_P} result.to_json(42)")
facade("og-to-json-no-folder", lambda d: og.evaluate().to_json("nodir/x.json"), "refused",
       "nodir", "1: result.to_json into a folder that does not exist is refused naming it")
facade("og-plot-ax-int", lambda d: og.evaluate().plot(ax=42), "refused",
       (r"ax = 42 \(int\)", "Axes"), f"1: {_P} result.plot(ax=42)")
facade("og-loop-fit-missing", lambda d: og.Loop().fit("missing.csv"), "refused",
       "missing.csv", "1: Loop().fit on a file that does not exist is refused naming it")
facade("og-predict-data-missing", lambda d: og.predict("loop.json", "none.csv"), "refused",
       "none.csv", f"1: {_P} rows to predict from a missing file", setup=with_model)
facade("og-sweep-oils-int", lambda d: og.sweep(_grid(), oils=42), "refused",
       (r"oils = 42",), f"1: {_P} sweep(oils=42)")
facade("og-evaluate-oil-empty", lambda d: og.evaluate(oil=""), "refused", "oil = ''",
       f"1: {_P} an empty oil name")
facade("og-read-measured-oils-missing", lambda d: og.read_measured("data.csv",
                                                                   oils="none.csv"),
       "refused", "none.csv", f"1: {_P} an oils table that does not exist", setup=rig())

# ==================================================================== class 4: conflicts
GROUP = "20.4 conflicting options"
_C = "the pair is refused naming both"
cli("cli-evaluate-case-smoothed", "evaluate case.toml --smoothed", "refused",
    ("--smoothed", "CASE"), f"4: evaluate CASE --smoothed: {_C}", files={"case.toml": case()})
cli("cli-optimize-case-smoothed", "optimize case.toml --smoothed --starts 1", "refused",
    ("--smoothed", "CASE"), f"4: optimize CASE --smoothed: {_C}",
    files={"case.toml": case()})
cli("cli-evaluate-smoothed-seed", "evaluate --smoothed", "accepted", (),
    "4: --smoothed without CASE is the smoothed seed joint (no conflict)")
cli("cli-sweep-retry-failed-force", "study sweep grid.csv --workers 1 --out sw "
    "--retry-failed --force", "refused", ("--force", "--retry-failed"),
    f"4: --retry-failed --force: {_C}", files=GRID_CSV)
cli("cli-sweep-resume-force", "study sweep grid.csv --workers 1 --out sw --resume --force",
    "refused", ("--force", "--resume"), f"4: --resume --force: {_C}", files=GRID_CSV)
cli("cli-sweep-chunk-size-seconds", "study sweep grid.csv --workers 1 --chunk-size 2 "
    "--chunk-seconds 1", "refused", ("--chunk-size", "--chunk-seconds"),
    f"4: --chunk-size with --chunk-seconds: {_C}", files=GRID_CSV)
cli("cli-oils-only-without-oils", "evaluate --oils-only", "refused", ("--oils-only",
    "--oils FILE"), "4: --oils-only without --oils is refused naming both")
cli("cli-oils-adds-to-catalogue", "evaluate --oils oils.csv --oil VG46", "accepted", (),
    "4: a user's oils table adds to the ISO VG catalogue (VG46 still known)",
    files=OILS_CSV)
cli("cli-oils-only-alone", "evaluate --oils oils.csv --oils-only --oil VG46", "refused",
    ("VG46", "RigOil"), "4: with --oils-only the table alone: VG46 unknown, the known "
    "oils listed", files=OILS_CSV)
cli("cli-oils-clash-warns", "evaluate --oils oils.csv --oil VG22", "warned", "VG22",
    "4: a table row named like a built-in oil wins, with a warning naming it",
    files=OILS_VG22)
cli("cli-loop-custom-and-iso-oils", "loop data.csv --oils oils.csv --no-figures --out o",
    "accepted|warned", (), "4: a loop on data naming a custom oil (in --oils) and an ISO "
    "oil (VG320) runs", files=MY_VG1000, setup=rig(_custom_rig), outputs=("o",))
cli("cli-bearing-f0-skf", "evaluate case.toml", "refused", ("f0", "skf", "palmgren"),
    "4: [bearing] f0 under model = 'skf' (no effect) is refused naming the key and the "
    "model", files={"case.toml": case(bearing={"designation": "61807", "f0": 3.0})})
cli("cli-bearing-mu-ehl-palmgren", "evaluate case.toml", "refused", ("mu_ehl", "palmgren"),
    "4: [bearing] mu_ehl under model = 'palmgren' is refused naming both",
    files={"case.toml": case(bearing={"designation": "61807", "model": "palmgren",
                                      "mu_ehl": 0.1})})
cli("cli-bearing-k-rs-palmgren", "evaluate case.toml", "refused", ("k_rs", "palmgren"),
    "4: [bearing] k_rs under model = 'palmgren' is refused naming both",
    files={"case.toml": case(bearing={"designation": "61807", "model": "palmgren",
                                      "k_rs": 1e-8})})
cli("cli-bearing-drag-palmgren", "evaluate case.toml", "refused", ("drag", "palmgren"),
    "4: [bearing] drag under model = 'palmgren' is refused naming both",
    files={"case.toml": case(bearing={"designation": "61807", "model": "palmgren",
                                      "drag": "none"})})
cli("cli-bearing-f0-palmgren", "evaluate case.toml", "accepted|warned", (),
    "4: [bearing] f0 under model = 'palmgren' is its own key (no conflict)",
    files={"case.toml": case(bearing={"designation": "61807", "model": "palmgren",
                                      "f0": 3.0})})
cli("cli-smoothing-r-th-shared", "study smoothing --method shared --r-th-k-per-w 2",
    "refused", ("--r-th-k-per-w", "--method"), f"4: a fixed R_th with a method fitting "
    f"R_th: {_C}")
cli("cli-smoothing-r-th-full", "study smoothing --thermal full --r-th-k-per-w 2", "refused",
    ("--r-th-k-per-w", "thermal"), "4: a fixed R_th under --thermal full (heat-balance "
    "fit) is refused naming both")
cli("cli-quiet-verbose", "evaluate -q -v", "refused", ("-q|--quiet", "-v|--verbose"),
    f"4: -q -v: {_C}")
cli("cli-temp-under-bulk", "evaluate case.toml --thermal bulk --temp-c 20", "refused",
    ("--temp-c", "--thermal bulk"), f"4: --temp-c under --thermal bulk: {_C}",
    files={"case.toml": case(thermal=THERMAL)})
cli("cli-sea-temp-under-none", "evaluate case.toml --thermal none --sea-temp-c 4",
    "refused", ("--sea-temp-c", "none"), f"4: --sea-temp-c under --thermal none: {_C}",
    files={"case.toml": case(thermal=THERMAL)})
cli("cli-strength-without-effect", "synth --strength 1", "refused", ("strength", "effect"),
    "4: --strength without --effect is refused naming both")
facade("og-sweep-resume-force", lambda d: og.sweep(_grid(), out="sw", resume=True,
                                                  force=True), "refused",
       ("force", "resume"), f"4: og.sweep(resume=True, force=True): {_C}, as the CLI")
facade("og-sweep-retry-force", lambda d: og.sweep(_grid(), out="sw", retry_failed=True,
                                                 force=True), "refused",
       ("force", "retry_failed"), f"4: og.sweep(retry_failed=True, force=True): {_C}")
facade("og-sweep-chunk-size-seconds", lambda d: og.sweep(_grid(), chunk_size=2,
                                                        chunk_seconds=1.0), "refused",
       ("chunk_size", "chunk_seconds"), f"4: chunk_size with chunk_seconds: {_C}")
facade("og-smoothing-r-th-shared", lambda d: og.smoothing(method="shared",
                                                          resistance_K_W=2.0), "refused",
       ("resistance_K_W", "method"), f"4: a fixed R_th with method 'shared': {_C}")
facade("og-oils-adds", lambda d: og.evaluate(oils=RIG_OIL, oil="VG46"), "accepted", (),
       "4: oils= adds to the ISO VG catalogue (VG46 still known)")
facade("og-oils-only", lambda d: og.evaluate(oils=og.read_oils(RIG_OIL, only=True),
                                             oil="VG46"), "refused", ("VG46", "RigOil"),
       "4: og.read_oils(..., only=True): the table alone, VG46 unknown")
facade("og-oils-clash-warns", lambda d: og.evaluate(
    oils={"VG22": {"nu40_cSt": 25.0, "nu100_cSt": 4.9, "density_kg_m3": 860.0}},
    oil="VG22"), "warned", "VG22", "4: a user's VG22 wins over the built-in, with a warning")
facade("og-temp-under-bulk", lambda d: og.evaluate("case.toml", oil_temp_C=20.0,
                                                   thermal="bulk"), "refused",
       ("oil_temp_C", "bulk"), f"4: oil_temp_C under thermal='bulk': {_C}",
       files={"case.toml": case(thermal=THERMAL)})
facade("og-synth-strength-without-effect", lambda d: og.synth(strength=1.0), "refused",
       ("strength", "effect"), f"4: strength without effect: {_C}")
facade("og-optimize-limits-and-starts", lambda d: og.optimize(
    limits=__import__("oilgap.studies.settings", fromlist=["x"]).DesignLimits(), starts=2),
    "refused", ("limits", "starts"), f"4: limits= with starts=: {_C}")

# ==================================================================== class 2: stores
GROUP = "20.2 hand-edited sweep stores"
_SWEEP = "study sweep grid.csv --workers 1 --out sw"


def _tamper(value: str) -> Callable[[Path], None]:
    """Setup: the stored first point's mean_power_W replaced by ``value`` (status ok)."""
    def setup(d: Path) -> None:
        p = d / "sw" / "points_evaluate.csv"
        df = pd.read_csv(p, dtype=str, keep_default_na=False)
        df.loc[0, "mean_power_W"] = value
        df.to_csv(p, index=False)
    return setup


for _name, _value in (("text", "abc"), ("empty", ""), ("negative", "-1e9"), ("nan", "nan")):
    cli(f"store-power-{_name}", f"{_SWEEP} --resume", "warned", ("points_evaluate.csv",),
        f"2: a stored ok row with mean_power_W = {_value!r} is recomputed with a warning "
        "naming the file, never reused", files=GRID_CSV,
        setup=(run_cli(_SWEEP), _tamper(_value)), outputs=("sw",))

# ==================================================================== classes 5, 6, 7
# the rows of tests/cli/test_issue20_inputs.py (its ROWS: the balance without a root,
# impossible joints and fluids, values quoted as written), each run through the command
# line and the façade


def _inputs_row(rid: str, r: dict) -> None:
    """One row of ``test_issue20_inputs.ROWS`` as a CLI row and a façade row."""
    expect = "refused" if r["code"] == 2 else "failed cleanly"
    needle = tuple(re.escape(w) for w in r["words"])
    files = dict(r["files"])
    if r["measured"] is not None:
        files["rig.csv"] = r["measured"]
        argv, path = "loop rig.csv --out o --no-figures", "rig.csv"
    else:
        text = CASE20
        for old, new in ([r["replace"]] if r["replace"] else []):
            text = text.replace(old, new, 1)
        files["case.toml"] = text + r["extra"]
        argv = " ".join([r["cmd"], "case.toml", *map(shlex.quote, r["argv"])])
        path = "case.toml"
    slug = re.sub(r"[^a-z0-9]+", "-", rid.lower()).strip("-")
    cli(f"i20-{slug}", argv, expect, needle, r["promise"], files=files, outputs=("o",))
    facade(f"og-i20-{slug}", _inputs_call(r["facade"], path, r["fkw"]), expect, needle,
           r["promise"] + " (façade)", files=files)


def _inputs_call(kind: str, path: str, kw: dict) -> Callable[[Path], object]:
    calls = {"read_measured": lambda d: og.read_measured(path),
             "optimize": lambda d: og.optimize(path, **kw),
             "read_case": lambda d: og.read_case(path)}
    return calls.get(kind, lambda d: og.evaluate(path, **kw).summary())


GROUP = "20.5-7 heat balance, impossible joints and fluids, values as written"
for _rid, _r in INPUT_ROWS.items():
    _inputs_row(_rid, _r)

# ==================================================================== saved loop models
# (class 3, lane model20; moved here from test_campaign.py with its groups: the section
# names what each row did before the fix)


def row(id, argv, expect="refused", needle=(), files=None, setup=(), outputs=(), check=None):
    """A command-line row in ``test_campaign.row``'s form, its promise said from its
    expectation (class 3: the saved model checked on load)."""
    named = f", naming {needle if isinstance(needle, str) else ' and '.join(needle)}" \
        if needle else ""
    cli(id, argv, expect, needle, f"3: `oilgap {argv}` on a hand-edited, cut short or "
        f"unfinished loop.json is {expect.replace('|', ' or ')}{named}", files=files,
        setup=setup, outputs=outputs, check=check)


# ---- issue 20 class 3 (lane model20): loop.json files edited by hand, cut short or left
# by an unfinished loop. predict checks the saved model once on load against its schema
# and ranges (oilgap.optim.calibration.model_schema) and refuses naming the field by its
# JSON path; a folder marked INCOMPLETE is refused unless --allow-incomplete. The façade
# variants are in tests/cli/test_predict_model_file.py.


def tampered(edit: Callable[[str], str]) -> tuple:
    """Setup: the fitted model and rows to predict, then loop.json's text edited."""
    def setup(d: Path) -> None:
        p = d / "loop.json"
        p.write_text(edit(p.read_text()))
    return (with_model, setup)


def model_edit(path: str, value=DROP) -> tuple:
    """Setup: ``model.<path>`` of the fitted loop.json set to ``value`` (DROP: removed)."""
    keys = [int(k) if k.isdigit() else k for k in path.split(".")]

    def edit(text: str) -> str:
        doc = json.loads(text)
        m = doc["model"]
        for k in keys[:-1]:
            m = m[k]
        if value is DROP:
            del m[keys[-1]]
        else:
            m[keys[-1]] = value
        return json.dumps(doc)
    return tampered(edit)


def predicted_finite(d: Path, out: str, written: list[str]) -> None:
    """Every row of p.csv has a finite predicted power."""
    p = pd.read_csv(d / "p.csv")
    assert np.isfinite(p["predicted_viscous_power_W"].to_numpy(float)).all(), \
        "a non-finite prediction"


BASELINE_5_COEFS = {"roughness_T": 4.0, "terms": ["1", "|w|", "w^2", "w dw/dt",
                                                   "sign(w) dw/dt", "(dw/dt)^2"],
                    "coef": [1.0, 0.1, 1e-4, 0.0, 0.0], "temp_ref_C": 25.0, "rmse_W": 1.0,
                    "n_samples": 30, "temp_range_C": [24.0, 26.0], "speed_max_rpm": 3000.0}
"""A hand-written oil-free baseline with five coefficients for six basis functions."""

PREDICT = "predict new.csv --model loop.json --out p.csv"
WITH_EFFECT = r"model\.laws\.with_effect\."

GROUP = "already fine (kept as regression)"
row("predict-model-truncated", PREDICT, "refused", "--model.*not JSON",
    setup=tampered(lambda t: t[: len(t) // 2]))

# a traceback, or a refusal quoting a raw Python error (KeyError, AttributeError) as the
# value instead of naming the field
GROUP = "tracebacks (exit 1) where one line and exit 2 are promised"
row("predict-model-baseline-coef-short", PREDICT, "refused",
    r"model\.baselines\[0\]\.coef = '5 numbers'", setup=model_edit("baselines",
                                                                    [BASELINE_5_COEFS]))
row("predict-model-top-level-list", PREDICT, "refused", "JSON list",
    setup=tampered(lambda t: "[1, 2, 3]"))
row("predict-model-missing-laws", PREDICT, "refused", r"model\.laws = 'missing'",
    setup=model_edit("laws"))
row("predict-model-gamma-text", PREDICT, "refused", WITH_EFFECT + "gamma = 'high'",
    setup=model_edit("laws.with_effect.gamma", "high"))
row("predict-model-effects-list", PREDICT, "refused", r"model\.effects = 'list'",
    setup=model_edit("effects", []))

GROUP = "garbage accepted with exit 0"
row("predict-model-gamma-5", PREDICT, "refused", WITH_EFFECT + r"gamma = 5\.0.*\[0, 3\]",
    setup=model_edit("laws.with_effect.gamma", 5.0))
row("predict-model-gamma-1e300", PREDICT, "refused", WITH_EFFECT + r"gamma = 1e\+300",
    setup=model_edit("laws.with_effect.gamma", 1e300))
row("predict-model-gamma-negative", PREDICT, "refused", r"model\.laws\.with_T\.gamma",
    setup=model_edit("laws.with_T.gamma", -0.5))
row("predict-model-gamma-nan-literal", PREDICT, "refused", WITH_EFFECT + "gamma = 'NaN'",
    setup=tampered(lambda t: t[:t.index('"model": {')] + re.sub(
        r'("with_effect": \{[^}]*?"gamma": )[-0-9.e+]+', r"\1NaN",
        t[t.index('"model": {'):], count=1)))
row("predict-model-scale-negative", PREDICT, "refused", r"model\.laws\.with_T\.scale = -1",
    setup=model_edit("laws.with_T.scale", -1.0))
row("predict-model-effect-unknown", PREDICT, "refused", r"model\.effects\.magic_drag",
    setup=model_edit("effects", {"magic_drag": 1.0}))
row("predict-model-effect-implausible", PREDICT, "refused",
    r"model\.effects\.sensor_delay = 10\.0", setup=model_edit("effects", {"sensor_delay": 10.0}))
row("predict-model-thermal-mode-unknown", PREDICT, "refused", r"model\.thermal_mode = 'hot'",
    setup=model_edit("thermal_mode", "hot"))
row("predict-model-fitted-range-reversed", PREDICT, "refused",
    r"model\.fitted_range\.temp_C", setup=model_edit("fitted_range.temp_C", [40.0, 20.0]))
row("predict-model-key-twice", PREDICT, "refused", r"model\.thermal_mode = 'given twice'",
    setup=tampered(lambda t: t.replace('"thermal_mode": "none"',
                                       '"thermal_mode": "none", "thermal_mode": "film"', 1)))
row("predict-model-incomplete", PREDICT, "refused", "INCOMPLETE.*--allow-incomplete",
    setup=with_model, files={"INCOMPLETE": "oilgap loop started writing here\n"})
row("predict-model-incomplete-allowed", PREDICT + " --allow-incomplete", "warned",
    "marked incomplete", setup=with_model, files={"INCOMPLETE": "started\n"},
    outputs=("p.csv",), check=predicted_finite)
# ---- end of issue 20 class 3 (lane model20)


# ==================================================================== issue 21: uncertainty
# ([uncertainty] tables written by hand, the uncertainty study's and the robust design's
# options, through the command line and the façade)
GROUP = "21 uncertain inputs and robust design"
_U = "21: a bad [uncertainty] table is refused by one line naming the key"


def _uncertain(**tables) -> dict:
    """case.toml with an [uncertainty] table of the given inputs' laws."""
    text = case()
    for name, law in tables.items():
        text += f"\n[uncertainty.{name}]\n" + "".join(
            f"{k} = {json.dumps(v)}\n" for k, v in law.items())
    return {"case.toml": text}


cli("u-sd-negative", "study uncertainty case.toml --out o", "refused",
    ("uncertainty.gamma", "sd"), _U,
    files=_uncertain(gamma={"dist": "normal", "mean": 0.5, "sd": -1.0}))
cli("u-unknown-law", "study uncertainty case.toml --out o", "refused",
    ("uncertainty.gamma", "weibull"), _U,
    files=_uncertain(gamma={"dist": "weibull", "mean": 0.5, "sd": 0.1}))
cli("u-unknown-input", "study uncertainty case.toml --out o", "refused",
    ("uncertainty", "viscosity"), _U,
    files=_uncertain(viscosity={"dist": "uniform", "low": 0.9, "high": 1.1}))
cli("u-low-above-high", "study uncertainty case.toml --out o", "refused",
    ("uncertainty.nu40_factor", "low|high"), _U,
    files=_uncertain(nu40_factor={"dist": "uniform", "low": 1.1, "high": 0.9}))
cli("u-film-without-thermal", "study uncertainty case.toml --out o", "refused",
    ("film_strength", "thermal"), _U,
    files=_uncertain(film_strength={"dist": "uniform", "low": 0.0, "high": 1.0}))
cli("u-unit-missing", "study uncertainty case.toml --out o", "refused",
    ("uncertainty.oil_temp_C",), _U + " (a temperature's mean is mean_C)",
    files=_uncertain(oil_temp_C={"dist": "normal", "mean": 2.0, "sd_K": 1.0}))
cli("u-samples-not-power-of-2", "study uncertainty --samples 1000 --out o", "refused",
    ("samples", "1000"), "21: --samples must be a power of 2 (Sobol' points), said in one line")
cli("r-unknown-statistic", "optimize --robust p99", "refused", ("robust", "p99"),
    "21: --robust takes p95, mean or mean+2sd")
cli("r-too-few-scenarios", "optimize --robust p95 --scenarios 2 --starts 1", "refused",
    ("scenarios", "2"), "21: a robust design needs enough scenarios; the bound is named")
cli("r-film-mode", "optimize --robust p95 --thermal film --starts 1", "refused",
    ("--robust", "film"), "21: the robust NLP's thermal modes (none, bulk) are named")
cli("r-scenarios-without-robust", "optimize --scenarios 16 --starts 1", "refused",
    ("--scenarios", "--robust"), "21: --scenarios without --robust is a conflict naming both")
facade("f-uncertainty-samples-text", lambda d: og.uncertainty(samples="many"), "refused",
       ("samples",), "21: og.uncertainty(samples='many') refused naming the argument")
facade("f-optimize-robust-p99", lambda d: og.optimize(robust="p99", starts=1), "refused",
       ("p99",), "21: og.optimize(robust='p99') refused naming the value and the choices")
facade("f-optimize-scenarios-alone", lambda d: og.optimize(scenarios=16, starts=1), "refused",
       ("scenarios", "robust"), "21: og.optimize(scenarios=16) without robust= is refused")
