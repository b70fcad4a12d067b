"""Golden outputs of every command: produce them, and compare two sets of them.

``python tests/golden/golden.py regenerate`` rewrites ``tests/golden/data`` from the
current code (do this only when a change of output is intended, and say so in the
commit); ``tests/golden/test_golden.py`` runs the same commands and compares.

Numbers are compared with the tolerance of the solver that made them (:data:`TOLERANCES`,
one row per output and field pattern, with its reason; the same table is in
docs/development.md#golden-outputs): pure evaluations to 1e-12, a heat balance solved
to 1e-9 K to 1e-9, IPOPT optima and least-squares fits to 1e-6. Numbers inside text
(stdout, Markdown) are compared as numbers too, to the same tolerance or one unit of
their last printed digit. Wall-clock timings (``solve_time_s``, ``... s``/``ms`` in
Markdown) and figures are not compared.

Why not 1e-12 everywhere (issue 18): numpy picks its SIMD kernels at run time from
the processor (AVX2 or AVX-512) and from its version; ``exp``, ``log``, ``power``,
``log10``, ``expm1`` and ``arctan`` then differ in the last bit for a few per cent of
their arguments. That moves a synthetic rig's CSV (7 significant digits) by one unit
of its last digit in a few dozen of 15000 rows, and the loop's fitted parameters
follow the data by ~1e-8. On one install (one processor), the outputs are
bit-identical whatever the load and thread count (tests/golden/test_determinism.py).
"""

from __future__ import annotations

import json
import math
import os
import re
import shutil
import sys
from contextlib import redirect_stdout
from dataclasses import dataclass
from fnmatch import fnmatch
from io import StringIO
from pathlib import Path

import pandas as pd

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
RTOL = 1e-12
"""Relative tolerance of a pure evaluation (no solver): float noise."""
ATOL = 1e-12
TIMING_KEYS = {"solve_time_s"}
_TIMING_MD = re.compile(r"\d+(?:\.\d+)?\s?(?:s|ms)\b")

LSQ_RTOL = 1e-6
"""Least-squares fits (loop, smoothing): scipy ``least_squares`` (trf) stops at
``ftol = xtol = gtol = 1e-10`` (optim/calibration/least_squares.py, studies/smoothing/fit.py),
a relative change of the cost; the parameters are then fixed to ~sqrt(1e-10) = 1e-5 in the
flattest direction at worst, ~1e-8 in practice."""
IPOPT_RTOL = 1e-6
"""IPOPT optima (optimize, pareto, sweep --mode optimize): ``ipopt.tol = 1e-9`` on the scaled
KKT error (optim/design/variables.py IPOPT_TOL); design variables, objective and multipliers to
1e-6 (tests/optim/design/test_design_verification.py checks the KKT conditions to 1e-6)."""
BALANCE_RTOL = 1e-9
"""The joint's heat balance (a ``[thermal]`` table): safeguarded Newton to |g| < 1e-9 K
(model/thermal.py steady_temperature); temperatures and losses to 1e-9."""
RESIDUAL_ATOL = 1e-5
"""Statistics of the loop's residual (autocorrelations, correlations, eta^2, structured RMS
[W], held-out gains [%]): differences of near-equal numbers, so an absolute tolerance; a
parameter change of 1e-6 moves them by less than 1e-5."""


@dataclass(frozen=True)
class Tol:
    """A tolerance row: outputs ``files`` (fnmatch on the path in the golden folder), fields
    ``field`` (regex searched in the JSON path or CSV column; None: every field)."""

    files: str
    field: str | None
    rtol: float
    atol: float
    reason: str


TOLERANCES: tuple[Tol, ...] = (
    Tol("loop_*", r"autocorrelation|pearson_r|eta2|structured_|gain_.*pct|gain_pct",
        LSQ_RTOL, RESIDUAL_ATOL, "statistics of the residual after a least-squares fit"),
    Tol("loop_*", None, LSQ_RTOL, 1e-9, "least squares, ftol = xtol = 1e-10 (calibration)"),
    Tol("predict_*", None, LSQ_RTOL, 1e-9, "the loop's fitted model applied (least squares)"),
    Tol("smoothing*", None, LSQ_RTOL, 1e-9, "least squares of gamma and run temperatures"),
    Tol("optimize*", None, IPOPT_RTOL, 1e-9, "IPOPT, tol 1e-9 on the scaled KKT error"),
    Tol("pareto*", None, IPOPT_RTOL, 1e-9, "IPOPT per front point (warm-started)"),
    Tol("sweep_opt*", None, IPOPT_RTOL, 1e-9, "IPOPT per grid row"),
    Tol("evaluate_thermal*", None, BALANCE_RTOL, 1e-9, "heat balance, Newton to 1e-9 K"),
    Tol("*", None, RTOL, ATOL, "pure evaluation: closed forms, no solver (float noise)"),
)
"""Per-output, per-field tolerances, first match wins (docs/development.md#golden-outputs)."""


def tolerance(rel: str, field: str = "") -> tuple[float, float]:
    """(rtol, atol) of a field of an output (path relative to the golden folder)."""
    top = rel.replace("\\", "/")
    for t in TOLERANCES:
        if fnmatch(top, t.files) and (t.field is None or re.search(t.field, field)):
            return t.rtol, t.atol
    return RTOL, ATOL


GRID_EVAL = "oil,oil_temp_C,depth_m,gap_mm,T\nVG22,2,3000,1.0,4\nVG32,10,1000,0.8,2\nVG15,,,1.2,\n"
GRID_OPT = "oil,oil_temp_C,torque_min_Nm\nVG22,2,0.5\nVG46,20,0.45\n"
NEW_POINTS = ("speed_rpm,temp_C,oil,roughness_T\n1000,30,VG150,4\n3000,40,VG320,2\n"
              "-2000,25,VG680,4\n500,35,VG1000,2\n1500,30,none,4\n")
"""Steady operating points for ``oilgap predict`` (no power column, one oil-free row)."""

COMMANDS: list[tuple[str, list[str]]] = [
    ("evaluate.json", ["evaluate", "--json"]),
    ("evaluate_smoothed_bb.json", ["evaluate", "--smoothed", "--laminar-law", "bilgen-boulos",
                                   "--json"]),
    ("optimize.json", ["optimize", "--json"]),
    # --thermal none: the seed paper's isothermal model, today's numbers before issue 10
    ("evaluate_none.json", ["evaluate", "--thermal", "none", "--json"]),
    ("evaluate_smoothed_bb_none.json", ["evaluate", "--smoothed", "--laminar-law",
                                        "bilgen-boulos", "--thermal", "none", "--json"]),
    ("optimize_none.json", ["optimize", "--thermal", "none", "--json"]),
    ("oil-grade_none.txt", ["study", "oil-grade", "--thermal", "none", "--out",
                            "oil-grade_none"]),
    # a case with a [thermal] table: film heating and the bulk balance (mode full)
    ("evaluate_thermal.json", ["evaluate", "seed_thermal.toml", "--json"]),
    ("optimize_thermal.json", ["optimize", "seed_thermal.toml", "--json"]),
    ("smoothing.txt", ["study", "smoothing", "--out", "smoothing"]),
    ("pareto.txt", ["study", "pareto", "--out", "pareto"]),
    ("oil-grade.txt", ["study", "oil-grade", "--out", "oil-grade"]),
    ("sweep_eval.txt", ["study", "sweep", "grid.csv", "--out", "sweep_eval", "--workers", "1",
                        "--no-progress"]),
    ("sweep_opt.txt", ["study", "sweep", "grid_opt.csv", "--mode", "optimize", "--out",
                       "sweep_opt", "--workers", "1", "--no-progress"]),
    ("synth_clean.txt", ["synth", "--out", "synth_clean.csv"]),
    ("synth_seal.txt", ["synth", "--effect", "seal_coulomb_friction", "--seed", "3", "--out",
                        "synth_seal.csv"]),
    ("loop_clean.json", ["loop", "synth_clean.csv", "--out", "loop_clean", "--json",
                         "--no-figures"]),
    ("loop_seal.json", ["loop", "synth_seal.csv", "--out", "loop_seal", "--json",
                        "--no-figures"]),
    ("predict_seal.txt", ["predict", "new_points.csv", "--model", "loop_seal/loop.json",
                          "--out", "predict_seal.csv"]),
]


def seed_thermal_toml() -> str:
    """The seed joint with a ``[thermal]`` table: sea 2 degC, R 0.5 K/W, C 5e4 J/K."""
    from oilgap.model.io.case_io import seed_case
    from oilgap.model.io.case_write import case_to_dict, dumps_toml

    return dumps_toml(case_to_dict(seed_case())) + (
        "\n[thermal]\nsea_temp_C = 2.0\nresistance_K_per_W = 0.5\n"
        "heat_capacity_J_per_K = 50000.0\n")


def produce(out: Path) -> None:
    """Run every golden command in ``out`` (in-process), writing stdout to files."""
    from oilgap.cli import main

    out.mkdir(parents=True, exist_ok=True)
    (out / "grid.csv").write_text(GRID_EVAL)
    (out / "grid_opt.csv").write_text(GRID_OPT)
    (out / "new_points.csv").write_text(NEW_POINTS)
    (out / "seed_thermal.toml").write_text(seed_thermal_toml())
    cwd = os.getcwd()
    os.chdir(out)
    try:
        for name, argv in COMMANDS:
            buf = StringIO()
            with redirect_stdout(buf):
                code = main(argv)
            if code != 0:
                raise RuntimeError(f"oilgap {' '.join(argv)} exited {code}")
            (out / name).write_text(buf.getvalue())
    finally:
        os.chdir(cwd)


def _close(a: float, b: float, rtol: float = RTOL, atol: float = ATOL) -> bool:
    if isinstance(a, bool) or isinstance(b, bool):
        return a == b
    if math.isnan(a) and math.isnan(b):
        return True
    return abs(a - b) <= atol + rtol * max(abs(a), abs(b))


def compare_json(a, b, path: str = "", rel: str = "") -> list[str]:
    """Differences between two JSON documents (numbers to the tolerance of ``rel``'s fields)."""
    if isinstance(a, dict) and isinstance(b, dict):
        out = []
        if set(a) != set(b):
            out.append(f"{path}: keys differ {sorted(set(a) ^ set(b))}")
        for k in set(a) & set(b):
            if k not in TIMING_KEYS:
                out += compare_json(a[k], b[k], f"{path}.{k}", rel)
        return out
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: lengths {len(a)} != {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b, strict=True))
                for d in compare_json(x, y, f"{path}[{i}]", rel)]
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        ok = _close(float(a), float(b), *tolerance(rel, path))
        return [] if ok else [f"{path}: {a!r} != {b!r}"]
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]


def compare_csv(a: Path, b: Path, rel: str = "") -> list[str]:
    """Differences between two CSV files (numeric columns to their tolerance, timings skipped)."""
    rel = rel or a.name
    x, y = pd.read_csv(a), pd.read_csv(b)
    if a.name.startswith("points_") and "point_key" in x.columns:  # the store's row order
        x = x.sort_values("point_key", ignore_index=True)  # is the order chunks finished in
        y = y.sort_values("point_key", ignore_index=True)
    if list(x.columns) != list(y.columns) or len(x) != len(y):
        return [f"{a.name}: shape/columns differ"]
    out = []
    for c in x.columns:
        if c in TIMING_KEYS:
            continue
        rtol, atol = tolerance(rel, str(c))
        for i, (u, v) in enumerate(zip(x[c], y[c], strict=True)):
            num = isinstance(u, (int, float)) and isinstance(v, (int, float))
            if (num and not _close(float(u), float(v), rtol, atol)) or (not num and not (
                    u == v or (pd.isna(u) and pd.isna(v)))):
                out.append(f"{a.name}[{i}, {c}]: {u!r} != {v!r}")
    return out


_NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.(\d+))?(?:[eE]([-+]?\d+))?(?![\w.])")


def _last_digit(m: re.Match) -> float:
    """One unit of the last printed digit of a decimal in text (0 for an integer: a count)."""
    if m.group(1) is None and m.group(2) is None:
        return 0.0
    places = len(m.group(1) or "")
    return 10.0 ** (int(m.group(2) or 0) - places)


def compare_text(a: str, b: str, rel: str) -> list[str]:
    """Differences between two texts: words exactly, numbers to the output's tolerance or one
    unit of their last printed digit (a decimal printed to 4 digits may round the other way;
    integers, which are counts, get no such allowance)."""
    a, b = _TIMING_MD.sub("<t>", a), _TIMING_MD.sub("<t>", b)
    if a == b:
        return []
    ma, mb = list(_NUMBER.finditer(a)), list(_NUMBER.finditer(b))
    words_a = _NUMBER.sub("<n>", a)
    if len(ma) != len(mb) or words_a != _NUMBER.sub("<n>", b):
        return [f"{rel}: text differs"]
    rtol, atol = tolerance(rel)
    out = []
    for x, y in zip(ma, mb, strict=True):
        u, v = float(x.group(0)), float(y.group(0))
        unit = max(_last_digit(x), _last_digit(y))
        if not (_close(u, v, rtol, atol) or abs(u - v) <= unit * (1 + 1e-9)):
            line = a.count("\n", 0, x.start()) + 1
            out.append(f"{rel}:{line}: {x.group(0)} != {y.group(0)}")
    return out


def compare_dirs(golden: Path, fresh: Path) -> list[str]:
    """Every difference between a golden folder and a fresh run (figures: presence only)."""
    out = []
    for g in sorted(golden.rglob("*")):
        if g.is_dir():
            continue
        rel = g.relative_to(golden)
        key = rel.as_posix()
        f = fresh / rel
        if not f.exists():
            out.append(f"{rel}: missing")
        elif g.suffix == ".json" or (g.suffix == ".txt" and g.read_text().lstrip()[:1] == "{"):
            out += compare_json(json.loads(g.read_text()), json.loads(f.read_text()), str(rel),
                                key)
        elif g.suffix == ".csv":
            out += compare_csv(g, f, key)
        elif g.suffix in (".md", ".txt"):
            out += compare_text(g.read_text(), f.read_text(), key)
    return out


def regenerate() -> None:
    """Rewrite the golden folder from the current code (figures left out)."""
    if DATA.exists():
        shutil.rmtree(DATA)
    produce(DATA)
    for p in [*DATA.rglob("*.png"), *DATA.rglob("*.parquet")]:  # binary: results.csv holds the same
        p.unlink()
    for p in DATA.rglob("points_*.csv"):  # the store in key order: no churn from the order
        df = pd.read_csv(p)                # in which chunks happened to finish
        df.sort_values("point_key", ignore_index=True).to_csv(p, index=False)
    for p in list(DATA.rglob("provenance.json")):
        p.unlink()  # date, paths and versions of the run: checked by tests/cli/test_hygiene.py
    for p in (DATA / "synth_clean.csv", DATA / "synth_seal.csv"):
        p.unlink()  # regenerated from the seed by the synth commands; compared via the loop


if __name__ == "__main__":
    if sys.argv[1:] == ["regenerate"]:
        regenerate()
    else:
        print(__doc__)
