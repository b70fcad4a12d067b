"""The bad-input campaign of issue 12, kept as tests: one row per input, as a careful user
and a hostile one would try them.

Each row writes its input files into a fresh folder, runs ``oilgap`` there (in-process
through :func:`oilgap.cli.main`; a real process only where the process is the
point: a closed pipe, Ctrl-C, IPOPT's C-level log) and classifies what happened:

* **refused**: exit 2, exactly one line on stderr starting ``oilgap: error:`` (or
  argparse's usage and its one ``error:`` line for a malformed option), no traceback, and
  nothing written, changed or removed in the folder;
* **warned**: exit 0 with an ``oilgap: warning:`` line, no traceback;
* **accepted**: exit 0, no warning, no traceback;
* **ended cleanly** (process rows): a closed stdout ends quietly, Ctrl-C ends with the
  one line ``oilgap: interrupted`` and exit 130;
* anything else (a traceback, another exit code, several lines, a file written by a
  refusal) is **still failing**.

A row passes when its class is one it allows, its message names what it must (``needle``,
regular expressions), it echoes nothing it must not (``forbid``), it wrote only its
``outputs`` and its own ``check`` of the outputs holds. Rows are written to the behaviour
the README promises, not to what the code did when the campaign was run.
``python tests/cli/campaign_table.py`` prints the table of outcomes per class.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import shlex
import shutil
import tempfile
from collections.abc import Callable
from functools import cache
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from campaign_table import (
    CLASSES,
    Row,
    case_written,
    cwd,
    dropped_or_refused,
    figures_written,
    finite_results,
    gamma_in_header,
    gamma_in_json,
    grid_row_not_ok,
    intervals_honest,
    json_stdout,
    loop_dropped,
    markdown_tables_intact,
    no_formula_cells,
    no_stale,
    nothing_escaped,
    proc_closed_pipe,
    proc_ctrl_c,
    proc_verbose_json,
    resumed_same,
    run_row,
    truncate_store,
)

from oilgap.cli import main
from oilgap.studies.rigs.synth import SynthConfig, synthesize

# --------------------------------------------------------------------------- inputs


class Raw(str):
    """A TOML token written as is (``nan``, ``inf``, ``true``)."""


DROP = object()
"""An edit that removes the key (or the table)."""

BASE_CASE: dict = {
    "name": "campaign joint",
    "region1": {"T1_mm": 23.9, "T2_mm": 25.4, "T3_mm": 26.4, "T4_mm": 27.9,
                "length_mm": 14.76},
    "region2": {"radius_mm": 22.0, "length_mm": 14.24, "gap_mm": 5.0},
    "oil": {"name": "VG22"},
    "operating": {"depth_m": 0.0, "oil_temp_C": 40.0},
    "duty_cycle": {"kind": "sine", "peak_speed_rpm": 3000.0, "frequency_hz": 0.05,
                   "duration_s": 20.0, "sample_interval_s": 0.2},
    "friction": {"gamma": 0.5},
}
"""The seed's geometry (Table 1, T = 4) at 40 degC and the surface, a 20 s cycle."""


def _toml_value(v) -> str:
    if isinstance(v, Raw):
        return str(v)
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    return repr(v)


def toml_text(doc: dict) -> str:
    """A small TOML writer: top-level keys, tables, arrays of tables (lists of dicts)."""
    lines = [f"{k} = {_toml_value(v)}" for k, v in doc.items() if not isinstance(v, dict | list)]
    for k, v in doc.items():
        if isinstance(v, dict):
            lines += ["", f"[{k}]"] + [f"{kk} = {_toml_value(vv)}" for kk, vv in v.items()]
        elif isinstance(v, list):
            for row in v:
                lines += ["", f"[[{k}]]"] + [f"{kk} = {_toml_value(vv)}"
                                             for kk, vv in row.items()]
    return "\n".join(lines) + "\n"


def case(**edits) -> str:
    """The base case's TOML with edits: ``friction=DROP`` removes a table,
    ``friction={"gamma": 1e300}`` updates its keys (a key set to DROP is removed), a
    value that is not a dict replaces the entry (``region1=5``, ``mission=[...]``)."""
    doc = json.loads(json.dumps(BASE_CASE))
    for table, upd in edits.items():
        if upd is DROP:
            doc.pop(table, None)
        elif isinstance(upd, dict) and isinstance(doc.get(table), dict):
            for k, v in upd.items():
                if v is DROP:
                    doc[table].pop(k, None)
                else:
                    doc[table][k] = v
        else:
            doc[table] = upd
    return toml_text(doc)


SMOOTH_CASE = case(region1={"T1_mm": 25.4, "T4_mm": 26.4}, friction=DROP)
"""T = 1 (no grooves) and no ``[friction]``: gamma does not matter."""

PASSWD_FIRST_LINE = (Path("/etc/passwd").read_text(errors="replace").splitlines() or ["-"])[0]
"""A file's content that an error must never echo."""


@cache
def rig_frame(kind: str = "viscous_power_W") -> pd.DataFrame:
    """A small synthetic rig (VG320 and VG1000 at T = 4 and 2, 30 samples of 0.2 s per run;
    with ``power_W`` also the oil-free runs), the loop's data format."""
    cfg = SynthConfig(n_samples=30, kind=kind, oils=("VG320", "VG1000"))
    return synthesize(cfg, seed=1)


def rig(mutate: Callable[[pd.DataFrame], pd.DataFrame] | None = None,
        kind: str = "viscous_power_W", name: str = "data.csv", encoding: str = "utf-8"):
    """A setup writing the small rig, changed by ``mutate``, to ``name``."""
    def setup(d: Path) -> None:
        df = rig_frame(kind).copy()
        df = mutate(df) if mutate else df
        (d / name).write_text(df.to_csv(index=False), encoding=encoding)
    return setup


@cache
def fitted_model_json() -> str:
    """loop.json of the loop fitted once on the small rig (for the predict rows)."""
    d = Path(tempfile.mkdtemp(prefix="oilgap-campaign-model-"))
    try:
        rig()(d)
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            rc = main(["loop", str(d / "data.csv"), "--out", str(d / "o"), "--no-figures"])
        assert rc == 0, "the loop on the clean small rig must fit"
        return (d / "o" / "loop.json").read_text()
    finally:
        shutil.rmtree(d, ignore_errors=True)


def with_model(d: Path) -> None:
    """Setup: a fitted loop.json and the rig's oil rows without power, to predict."""
    (d / "loop.json").write_text(fitted_model_json())
    df = rig_frame().drop(columns=["viscous_power_W"])
    df.to_csv(d / "new.csv", index=False)


def run_cli(argv: str) -> Callable[[Path], None]:
    """Setup: an earlier command run in the folder (its outputs are then inputs)."""
    def setup(d: Path) -> None:
        with contextlib.redirect_stdout(io.StringIO()), \
                contextlib.redirect_stderr(io.StringIO()), cwd(d):
            assert main(shlex.split(argv)) == 0, f"setup command failed: {argv}"
    return setup


def utf16(text: str) -> bytes:
    """A CSV saved as "Unicode text" by a spreadsheet: UTF-16 with a BOM, not UTF-8."""
    return text.encode("utf-16")


def _formula_runs(df: pd.DataFrame) -> pd.DataFrame:
    """Run names a spreadsheet would take for formulas: ``=VG320-T4``."""
    return df.assign(run="=" + df["run"].astype(str))


# --------------------------------------------------------------------------- rows


ROWS: list[Row] = []
GROUP = "?"


def row(id, argv, expect="refused", needle=(), files=None, setup=(), outputs=(), check=None,
        forbid=(), proc=None, ends=""):
    """Add a row to :data:`ROWS` under the current :data:`GROUP`."""
    ROWS.append(Row(id, argv, tuple(expect.split("|")), GROUP,
                    (needle,) if isinstance(needle, str) else tuple(needle), files or {},
                    setup if isinstance(setup, tuple) else (setup,), outputs, check, forbid,
                    proc, ends))


DUPLICATE = r"unique|duplicate|twice|more than once"
"""What a refusal of a repeated column name must say."""


def refused_case(id, needle, **edits):
    """``oilgap evaluate case.toml`` on the base case with edits: refused naming ``needle``."""
    row(id, "evaluate case.toml", "refused", needle, {"case.toml": case(**edits)})


# ---- the rows, by the issue's sections

GROUP = "already fine (kept as regression)"
refused_case("typo-table", "regoin1", regoin1={"T1_mm": 1.0})
refused_case("typo-key-region1", "T1mm", region1={"T1mm": 23.9})
refused_case("typo-key-friction", "gama", friction={"gamma": DROP, "gama": 0.5})
refused_case("typo-key-oil", "nmae", oil={"name": DROP, "nmae": "VG22"})
refused_case("typo-key-duty-cycle", "peak_speed", duty_cycle={"peak_speed": 3000.0})
refused_case("typo-top-level", "nmae", nmae="x")
refused_case("type-number-as-text", "T1_mm", region1={"T1_mm": "23.9"})
refused_case("type-bool-depth", "depth_m", operating={"depth_m": Raw("true")})
refused_case("type-gamma-text", "gamma", friction={"gamma": "high"})
refused_case("type-slot-count-float", "slot_count", motor={"slot_count": 12.5})
refused_case("type-table-as-number", "region1", region1=5)
refused_case("nan-radius", "T2_mm", region1={"T2_mm": Raw("nan")})
refused_case("inf-length", "length_mm", region1={"length_mm": Raw("inf")})
refused_case("minus-inf-temp", "oil_temp_C", operating={"oil_temp_C": Raw("-inf")})
refused_case("nan-gamma", "gamma", friction={"gamma": Raw("nan")})
refused_case("radii-T3-below-T2", "T3_mm", region1={"T3_mm": 25.0})
refused_case("radii-T4-below-T3", "T4_mm", region1={"T4_mm": 26.0})
refused_case("radii-T1-above-T2", "T1_mm", region1={"T1_mm": 26.0})
refused_case("gap2-zero", "gap_mm", region2={"gap_mm": 0.0})
refused_case("length-negative", "length_mm", region1={"length_mm": -1.0})
refused_case("bounds-gap-order", "gap_m(in|ax)_mm", bounds={"gap_min_mm": 2.0,
                                                             "gap_max_mm": 0.5})
refused_case("bounds-radius-order", "radius_m(in|ax)_mm", bounds={"radius_min_mm": 28.0,
                                                                   "radius_max_mm": 22.0})
refused_case("no-region1", "region1", region1=DROP)
refused_case("depth-too-deep", "depth_m", operating={"depth_m": 20000.0})
refused_case("custom-oil-nu100-above-nu40", "nu100_cSt",
             oil={"name": "mine", "nu40_cSt": 10.0, "nu100_cSt": 20.0, "density_kg_m3": 870.0})
refused_case("mission-fractions", "fraction",
             mission=[{"depth_m": 0.0, "oil_temp_C": 20.0, "fraction": 0.5}])
refused_case("thermal-negative-resistance", "resistance_K_per_W",
             thermal={"sea_temp_C": 2.0, "resistance_K_per_W": -1.0,
                      "heat_capacity_J_per_K": 1000.0})
refused_case("bearing-sealed", "designation", bearing={"designation": "6205-2RS1"})
row("toml-syntax", "evaluate case.toml", "refused", "case", {"case.toml": "name = \n[region1\n"})
row("case-missing", "evaluate missing.toml", "refused", "missing.toml")
row("oil-unknown", "evaluate --oil VG23", "refused", "VG23")
row("depth-negative-cli", "evaluate --depth-m -5", "refused", "depth_m")
row("temp-nan-cli", "evaluate --temp-c nan", "refused", "--temp-c")
row("oil-temp-untrusted", "evaluate case.toml", "warned", "oil_temp_C|temperature",
    {"case.toml": case(operating={"oil_temp_C": 200.0})})
row("base-case-fine", "evaluate case.toml", "accepted", files={"case.toml": case()})
row("duty-csv-time-order", "evaluate case.toml", "refused", "time_s",
    {"case.toml": case(duty_cycle={"kind": "csv", "csv": "cycle.csv", "peak_speed_rpm": DROP,
                                   "frequency_hz": DROP, "duration_s": DROP,
                                   "sample_interval_s": DROP}),
     "cycle.csv": "time_s,speed_rpm\n0,0\n2,100\n1,200\n"})
row("duty-csv-missing-column", "evaluate case.toml", "refused", "time_s",
    {"case.toml": case(duty_cycle={"kind": "csv", "csv": "cycle.csv", "peak_speed_rpm": DROP,
                                   "frequency_hz": DROP, "duration_s": DROP,
                                   "sample_interval_s": DROP}),
     "cycle.csv": "t,speed_rpm\n0,0\n1,100\n2,200\n"})
row("sweep-unknown-column", "study sweep grid.csv --workers 1", "refused", "gapp_mm",
    {"grid.csv": "gapp_mm\n1.0\n"})
row("sweep-text-number", "study sweep grid.csv --workers 1", "refused", "gap_mm",
    {"grid.csv": "gap_mm\n1.0\nabc\n"})
row("sweep-T-below-1", "study sweep grid.csv --workers 1", "refused", r"\bT\b",
    {"grid.csv": "T\n0.5\n"})
row("loop-missing-column", "loop data.csv --no-figures", "refused", "speed_rpm",
    setup=rig(lambda df: df.drop(columns=["speed_rpm"])))
row("loop-cv-by-unknown", "loop data.csv --no-figures --cv-by nope", "refused", "nope",
    setup=rig())
row("loop-effects-unknown", "loop data.csv --no-figures --effects bogus", "refused", "bogus",
    setup=rig())
row("loop-drops-counted", "loop data.csv --no-figures --out o", "accepted|warned", "dropped",
    setup=rig(lambda df: df.assign(viscous_power_W=df["viscous_power_W"].where(
        df.index % 40 != 7), temp_C=df["temp_C"].where(df.index % 60 != 11, 400.0))),
    outputs=("o",), check=loop_dropped(3 + 2))
row("loop-run-name-traversal", "loop data.csv --no-figures --out a/b/o", "accepted",
    setup=rig(lambda df: df.assign(run=df["run"].replace(
        {"VG320-T4": "../../../escape", "VG320-T2": "/tmp/campaign-abs"}))),
    outputs=("a",), check=nothing_escaped)
row("pareto-few-points", "study pareto --points 10", "refused", "points")
row("smoothing-t-min", "study smoothing --t-min 0.5", "refused", "t[-_]min")
row("synth-roughness-text", "synth --roughness 4,x", "refused", "--roughness")
row("predict-model-missing", "predict new.csv --model none.json --out p.csv", "refused",
    "none.json", setup=with_model)
row("optimize-starts-zero", "optimize --starts 0", "refused", "starts")

GROUP = "tracebacks (exit 1) where one line and exit 2 are promised"
refused_case("gamma-1e300", "gamma", friction={"gamma": 1e300})
refused_case("peak-speed-1e300", "peak_speed_rpm", duty_cycle={"peak_speed_rpm": 1e300})
refused_case("power-law-beta-1000", "beta", friction={"form": "power-law", "beta": 1000.0})
refused_case("power-law-C-1e300", r"\bC\b", friction={"form": "power-law", "C": 1e300})
refused_case("power-law-alpha-1e6", "alpha", friction={"form": "power-law", "alpha": 1e6})
refused_case("scale-1e300", "scale", friction={"scale": 1e300})
refused_case("duty-7-TiB", "duration_s|sample_interval_s|samples",
             duty_cycle={"duration_s": 1e9, "sample_interval_s": 0.001})
row("sweep-peak-speed-1e300", "study sweep grid.csv --workers 1 --out sw",
    "refused|warned|accepted", "peak_speed_rpm", {"grid.csv": "peak_speed_rpm\n1e300\n"},
    outputs=("sw",), check=finite_results)
_CSV_CYCLE = {"kind": "csv", "csv": "cycle.csv", "peak_speed_rpm": DROP, "frequency_hz": DROP,
              "duration_s": DROP, "sample_interval_s": DROP}
row("duty-csv-utf16", "evaluate case.toml", "refused", "cycle.csv",
    {"case.toml": case(duty_cycle=_CSV_CYCLE),
     "cycle.csv": utf16("time_s,speed_rpm\n0,0\n1,100\n2,200\n")})
row("oils-csv-utf16", "evaluate --oils oils.csv --oil RigOil", "refused", "oils.csv",
    {"oils.csv": utf16("oil,nu40_cSt,nu100_cSt,density_kg_m3\nRigOil,46,7,870\n")})
row("case-latin1", "evaluate case.toml", "refused", "case.toml",
    {"case.toml": case(name="joint à Brest").encode("latin-1")})
row("rig-data-utf16", "loop data.csv --no-figures", "refused", "data.csv",
    setup=rig(encoding="utf-16"))
row("grid-utf16", "study sweep grid.csv --workers 1", "refused", "grid.csv",
    {"grid.csv": utf16("gap_mm\n0.8\n1.2\n")})
row("mission-utf16", "study oil-grade --mission m.csv --workers 1", "refused", "m.csv",
    {"m.csv": utf16("depth_m,oil_temp_C,fraction\n0,20,1\n")})
row("case-is-a-folder", "evaluate folder.toml", "refused", "folder.toml",
    setup=lambda d: (d / "folder.toml").mkdir())
row("case-eio", "evaluate /proc/self/mem", "refused", "/proc/self/mem")
row("oils-csv-eio", "evaluate case.toml", "refused", "/proc/self/mem",
    {"case.toml": case(oil={"oils_csv": "/proc/self/mem"})})
row("duty-csv-eio", "evaluate case.toml", "refused", "/proc/self/mem",
    {"case.toml": case(duty_cycle={**_CSV_CYCLE, "csv": "/proc/self/mem"})})
row("oils-csv-folder", "evaluate --oils adir --oil x", "refused", "adir",
    setup=lambda d: (d / "adir").mkdir())
row("oils-csv-etc-passwd", "evaluate case.toml", "refused", "oils_csv|/etc/passwd",
    {"case.toml": case(oil={"oils_csv": "/etc/passwd"})}, forbid=(PASSWD_FIRST_LINE, "root:"))
row("oils-cli-etc-passwd", "evaluate --oils /etc/passwd --oil VG22", "refused",
    "/etc/passwd", forbid=(PASSWD_FIRST_LINE, "root:"))
row("loop-data-etc-passwd", "loop /etc/passwd --no-figures", "refused", "/etc/passwd",
    forbid=(PASSWD_FIRST_LINE, "root:"))
row("grid-etc-passwd", "study sweep /etc/passwd --workers 1", "refused", "/etc/passwd",
    forbid=(PASSWD_FIRST_LINE, "root:"))
row("pareto-out-proc", "study pareto --points 50 --out /proc/x", "refused", "--out")
row("oil-grade-out-proc", "study oil-grade --workers 1 --out /proc/x", "refused", "--out")
row("sweep-out-proc", "study sweep grid.csv --workers 1 --out /proc/x", "refused", "--out",
    {"grid.csv": "gap_mm\n0.8\n"})
row("smoothing-out-file", "study smoothing --out taken", "refused", "--out",
    {"taken": "a file, not a folder\n"})
row("sweep-out-file", "study sweep grid.csv --workers 1 --out taken", "refused", "--out",
    {"grid.csv": "gap_mm\n0.8\n", "taken": "a file, not a folder\n"})
row("loop-out-json-is-folder", "loop data.csv --no-figures --out o", "refused", "loop.json|--out",
    setup=(rig(), lambda d: (d / "o" / "loop.json").mkdir(parents=True)))
row("synth-out-proc", "synth --out /proc/x/s.csv", "refused", "--out")
row("optimize-out-missing-folder", "optimize --starts 1 --out nodir/opt.toml", "refused",
    "--out")
row("predict-out-proc", "predict new.csv --model loop.json --out /proc/x.csv", "refused",
    "--out", setup=with_model)
row("synth-seed-negative", "synth --seed -1", "refused", "seed")
row("synth-strength-negative", "synth --effect seal_coulomb_friction --strength -1",
    "refused", "strength")
row("loop-speed-zero-power", "loop data.csv --no-figures", "refused", "speed",
    setup=rig(lambda df: df.assign(speed_rpm=0.0), kind="power_W"))
row("loop-speed-zero-viscous", "loop data.csv --no-figures", "refused", "speed",
    setup=rig(lambda df: df.assign(speed_rpm=0.0)))
row("loop-run-name-mathtext", "loop data.csv --out o", "accepted",
    setup=rig(lambda df: df.assign(run=df["run"].replace({"VG320-T4": "$\\frac{$"}))),
    outputs=("o",), check=figures_written)
row("loop-run-names-markdown", "loop data.csv --no-figures --out o", "accepted",
    setup=rig(lambda df: df.assign(run=df["run"].replace(
        {"VG320-T4": "a|b", "VG1000-T4": "<img src=x onerror=alert(1)>"}))),
    outputs=("o",), check=markdown_tables_intact)
row("sweep-label-formula", "study sweep grid.csv --workers 1 --out sw", "accepted",
    files={"grid.csv": 'gap_mm,label\n0.8,"=HYPERLINK(""http://x"",""y"")"\n0.9,+cmd\n'
           '1.0,@SUM(1)\n1.1,-1+2\n1.2,a|b\n'},
    outputs=("sw",), check=lambda d, out, written: (no_formula_cells(d, out, written),
                                                     markdown_tables_intact(d, out, written)))
row("predict-run-name-formula", "predict new.csv --model loop.json --out p.csv", "accepted",
    setup=(with_model, lambda d: (d / "new.csv").write_text(
        _formula_runs(pd.read_csv(d / "new.csv")).to_csv(index=False))),
    outputs=("p.csv",), check=no_formula_cells)
row("closed-pipe", "evaluate --json | (reader gone)", "ended cleanly", proc=proc_closed_pipe,
    ends="pipe")
row("ctrl-c-sweep", "study sweep grid.csv --mode optimize --workers 2 + SIGINT",
    "ended cleanly", files={"grid.csv": "gap_mm\n" + "\n".join(
        f"{0.5 + 0.01 * i:.2f}" for i in range(150)) + "\n"},
    outputs=("sw",), proc=proc_ctrl_c, ends="sigint")

GROUP = "garbage accepted with exit 0"
row("no-friction-table", "evaluate case.toml", "warned", "gamma",
    {"case.toml": case(friction=DROP)}, check=gamma_in_header)
row("friction-without-gamma", "evaluate case.toml", "warned", "gamma",
    {"case.toml": case(friction={"gamma": DROP, "form": "bilgen-boulos"})},
    check=gamma_in_header)
row("no-friction-json", "evaluate case.toml --json", "warned", "gamma",
    {"case.toml": case(friction=DROP)}, check=gamma_in_json)
row("smooth-no-friction", "evaluate case.toml", "accepted|warned",
    files={"case.toml": SMOOTH_CASE}, check=gamma_in_header)
row("gamma-named-text", "evaluate", "accepted", check=gamma_in_header)
row("gamma-named-json", "evaluate --json", "accepted", check=gamma_in_json)


def _noise_only(df: pd.DataFrame) -> pd.DataFrame:
    """No viscous signal: the measured loss is noise of 1 W around 0."""
    return df.assign(viscous_power_W=np.random.default_rng(0).normal(0.0, 1.0, len(df)))


def _text_in_rows(col: str, bad: str, rows: int = 5):
    def mutate(df: pd.DataFrame) -> pd.DataFrame:
        df = df.copy()
        df[col] = {"gap_mm": "1.0", "nu_cSt": ""}[col]
        if col == "nu_cSt":
            df["density_kg_m3"] = ""
        df.loc[df.index[df["oil"] != "none"][:rows], col] = bad
        return df
    return mutate


row("loop-gap-override-text", "loop data.csv --no-figures --out o", "refused|warned|accepted",
    "gap_mm", setup=rig(_text_in_rows("gap_mm", "abc")), outputs=("o",),
    check=dropped_or_refused(5))
row("loop-nu-override-text", "loop data.csv --no-figures --out o", "refused|warned|accepted",
    "nu_cSt", setup=rig(_text_in_rows("nu_cSt", "thick")), outputs=("o",),
    check=dropped_or_refused(5))
row("grid-cell-nan", "study sweep grid.csv --workers 1 --out sw", "refused|warned|accepted",
    "gap_mm", {"grid.csv": "gap_mm\n0.8\nnan\n"}, outputs=("sw",), check=grid_row_not_ok(1))
row("grid-cell-NA", "study sweep grid.csv --workers 1 --out sw", "refused|warned|accepted",
    "gap_mm", {"grid.csv": "gap_mm\n0.8\nNA\n"}, outputs=("sw",), check=grid_row_not_ok(1))
row("rig-duplicate-column", "loop data.csv --no-figures", "refused",
    ("speed_rpm", DUPLICATE),
    setup=rig(lambda df: df.assign(extra=df["speed_rpm"]).rename(
        columns={"extra": "speed_rpm"})))
row("grid-duplicate-column", "study sweep grid.csv --workers 1", "refused",
    ("gap_mm", DUPLICATE), {"grid.csv": "gap_mm,gap_mm\n0.8,1.2\n"})
row("oils-duplicate-column", "evaluate --oils oils.csv --oil RigOil", "refused",
    ("nu40_cSt", DUPLICATE),
    {"oils.csv": "oil,nu40_cSt,nu100_cSt,density_kg_m3,nu40_cSt\nRigOil,46,7,870,68\n"})
row("duty-csv-duplicate-column", "evaluate case.toml", "refused",
    ("speed_rpm", DUPLICATE),
    {"case.toml": case(duty_cycle=_CSV_CYCLE),
     "cycle.csv": "time_s,speed_rpm,speed_rpm\n0,0,0\n1,100,1\n2,200,2\n"})
row("mission-duplicate-column", "study oil-grade --mission m.csv --workers 1", "refused",
    ("fraction", DUPLICATE),
    {"m.csv": "depth_m,oil_temp_C,fraction,fraction\n0,20,1,0\n"})
refused_case("slot-count-100000", "slot_count", motor={"slot_count": 100000})
refused_case("slot-opening-1e6", "slot_opening_mm", motor={"slot_opening_mm": 1e6})
refused_case("gap-1-km", "T3_mm|gap", region1={"T3_mm": 1e6, "T4_mm": 1e6 + 1.5})
refused_case("region2-gap-1-km", "gap_mm", region2={"gap_mm": 1e6})
refused_case("gamma-negative", "gamma", friction={"gamma": -0.5})
refused_case("custom-oil-too-thin", "nu40_cSt|nu100_cSt",
             oil={"name": "thin", "nu40_cSt": 0.2, "nu100_cSt": 0.1, "density_kg_m3": 800.0})
row("oils-csv-too-thin", "evaluate --oils oils.csv --oil thin", "refused", "nu40_cSt|nu100_cSt",
    {"oils.csv": "oil,nu40_cSt,nu100_cSt,density_kg_m3\nthin,0.2,0.1,800\n"})
row("loop-temp-in-kelvin", "loop data.csv --no-figures --out o", "refused|warned",
    r"kelvin|\bK\b", setup=rig(lambda df: df.assign(temp_C=df["temp_C"] + 273.15)),
    outputs=("o",))
row("loop-speed-in-rad-s", "loop data.csv --no-figures --out o", "refused|warned",
    r"rad/s|rad s|radian", setup=rig(lambda df: df.assign(
        speed_rpm=df["speed_rpm"] * math.pi / 30.0)), outputs=("o",))
row("loop-speed-x100", "loop data.csv --no-figures --out o", "refused|warned", "speed_rpm",
    setup=rig(lambda df: df.assign(speed_rpm=df["speed_rpm"] * 100.0)), outputs=("o",))
row("loop-power-in-kW", "loop data.csv --no-figures --out o", "refused|warned",
    r"\bkW\b|kilowatt", setup=rig(lambda df: df.assign(power_W=df["power_W"] / 1000.0),
                                  kind="power_W"), outputs=("o",))
row("loop-time-in-ms", "loop data.csv --no-figures --out o", "refused|warned",
    r"\bms\b|millisecond", setup=rig(lambda df: df.assign(time_s=df["time_s"] * 1000.0)),
    outputs=("o",))
row("loop-no-viscous-signal", "loop data.csv --no-figures --out o --base power-law",
    "refused|warned|accepted", setup=rig(lambda df: df.assign(viscous_power_W=0.0)),
    outputs=("o",), check=intervals_honest)
row("loop-no-viscous-signal-eq6", "loop data.csv --no-figures --out o",
    "refused|warned|accepted", setup=rig(lambda df: df.assign(viscous_power_W=0.0)),
    outputs=("o",), check=intervals_honest)
row("loop-noise-only", "loop data.csv --no-figures --out o --base power-law",
    "refused|warned|accepted", setup=rig(_noise_only), outputs=("o",), check=intervals_honest)
row("smoothing-r-th-1e6", "study smoothing --r-th-k-per-w 1e6 --out sm",
    "refused|warned|accepted", "[Rr][-_]th", outputs=("sm",), check=finite_results)

GROUP = "output safety"
row("optimize-out-exists", "optimize --starts 1 --out opt.toml", "refused", "--force",
    {"opt.toml": "# stale\n"})
row("optimize-out-force", "optimize --starts 1 --out opt.toml --force", "accepted",
    files={"opt.toml": "# stale\n"}, outputs=("opt.toml",), check=case_written)
row("synth-out-exists", "synth --out s.csv", "refused", "--force", {"s.csv": "keep me\n"})
row("smoothing-out-exists", "study smoothing --out sm", "refused", "--force",
    {"sm/summary.md": "keep me\n"})
row("pareto-out-exists", "study pareto --points 50 --out pa", "refused", "--force",
    {"pa/summary.md": "keep me\n"})
row("oil-grade-out-exists", "study oil-grade --workers 1 --out og", "refused", "--force",
    {"og/summary.md": "keep me\n"})
row("sweep-out-exists", "study sweep grid.csv --workers 1 --out sw", "refused",
    "--resume|--force", {"grid.csv": "gap_mm\n0.8\n1.2\n"},
    setup=run_cli("study sweep grid.csv --workers 1 --out sw"))
row("sweep-resume", "study sweep grid.csv --workers 1 --out sw --resume", "accepted",
    files={"grid.csv": "gap_mm\n0.8\n1.2\n"},
    setup=run_cli("study sweep grid.csv --workers 1 --out sw"), outputs=("sw",))
row("sweep-store-truncated", "study sweep grid.csv --workers 1 --out sw --resume",
    "warned|accepted", files={"grid.csv": "gap_mm\n0.8\n0.9\n1.0\n1.1\n1.2\n"},
    setup=(run_cli("study sweep grid.csv --workers 1 --out sw"), truncate_store),
    outputs=("sw",), check=resumed_same)
row("loop-out-exists", "loop data.csv --no-figures --out o", "refused", "--force",
    setup=rig(), files={"o/loop.json": "{}\n"})
row("loop-force-clears-stale", "loop data.csv --no-figures --out o --force", "accepted",
    setup=rig(), files={"o/loop.json": "{}\n", "o/report.md": "old\n",
                        "o/measured_vs_model.png": "old figure\n"},
    outputs=("o",), check=no_stale("o"))
row("predict-out-exists", "predict new.csv --model loop.json --out p.csv", "refused",
    "--force", {"p.csv": "keep me\n"}, setup=with_model)
row("optimize-json-verbose", "optimize --json --verbose --starts 1", "accepted",
    check=json_stdout, proc=proc_verbose_json)



# ---- issue 20's rows (the façade, conflicting options, stores, saved loop models):
# tests/cli/campaign_rows20.py
from campaign_rows20 import ROWS20  # noqa: E402  (it builds on the helpers above)

ROWS += ROWS20

# ---- issue 26's rows (nothing unbounded, nothing misleading): tests/cli/campaign_rows26.py
from campaign_rows26 import ROWS26  # noqa: E402

ROWS += ROWS26


@pytest.mark.parametrize("r", ROWS, ids=[r.id for r in ROWS])
def test_campaign_row(r: Row, tmp_path: Path):
    res = run_row(r, tmp_path / "w")
    assert res.passed, res.explain()


def test_campaign_covers_the_issue():
    """Every section of issues 12 and 20 has rows, ids are unique (the table names them),
    every row expects a known class and states its promise; issue 20's table holds at
    least 150 rows, façade rows among them."""
    assert len({r.id for r in ROWS}) == len(ROWS) and len(ROWS) >= 150
    groups = {r.group for r in ROWS}
    assert len(groups) >= 7 and {"20.1 façade: wrong argument types",
                                 "20.4 conflicting options"} <= groups
    assert all(set(r.expect) <= set(CLASSES[:-1]) for r in ROWS)
    assert all(r.states() for r in ROWS) and all(r.promise for r in ROWS20)
    assert sum(r.kind == "façade" for r in ROWS) >= 40
