"""Golden outputs of every command: produce them, and compare two sets of them.

``python tests/golden/golden.py regenerate`` rewrites ``tests/golden/data`` from the
current code (do this only when a change of output is intended, and say so in the
commit); ``tests/golden/test_golden.py`` runs the same commands and compares.

Numbers are compared with the tolerance of the solver that made them (:data:`TOLERANCES`,
one row per output and field pattern, with its reason; the same table is in
docs/development.md#golden-outputs): pure evaluations to 1e-12, a heat balance solved
to 1e-9 K to 1e-9, IPOPT optima and least-squares fits to 1e-6 (the smoothing study's
8-point fits to 1e-5). Numbers inside text (stdout, Markdown) are compared as numbers
too, to the same tolerance or one unit of their last printed digit. Wall-clock timings
(``solve_time_s``, ``... s``/``ms`` in Markdown) and figures are not compared. CSV rows
are matched by what names them (:data:`IDENTITY`: a grid point by its inputs), never by
position, and a ``point_key`` through the inputs it hashes (issue 26).

Why not 1e-12 everywhere (issue 18): numpy picks its SIMD kernels at run time from
the processor (AVX2 or AVX-512) and from its version; ``exp``, ``log``, ``power``,
``log10``, ``expm1`` and ``arctan`` then differ in the last bit for a few per cent of
their arguments. That moves a synthetic rig's CSV (7 significant digits) by one unit
of its last digit in a few dozen of 15000 rows, and the loop's fitted parameters
follow the data by ~1e-8. OpenBLAS also picks its kernels by processor (SkylakeX or
Haswell) and splits its sums by thread count, which moves a least-squares fit in its last
bits and a quantity that is zero (a held-out gain of -2.8e-11 %) anywhere below 1e-10.
``python tests/golden/golden.py env-without-avx512`` prints the environment that makes
this machine compute as one without AVX-512 on one thread (:func:`without_avx512_env`;
``.ci/run`` runs the golden tests a second time under it).
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

import numpy as np
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
LSQ_FLAT_RTOL = 1e-5
"""The smoothing study's fits (8 measured powers, up to 5 parameters, studies/smoothing/fit.py,
``ftol = 1e-10``): a fit stopped at a relative cost change ``ftol`` fixes a parameter to about
sqrt(ftol (n - p)) = 2e-5 of its standard error. For the R_th = 0.2 K/W variant (gamma =
0.958 +- 0.118) that is 2e-6 of gamma, and numpy/OpenBLAS without AVX-512 move it by 1.1e-6
and its standard error by 2.7e-6 (issue 26): sqrt(ftol) = 1e-5 relative, the flattest
direction's bound stated above."""
FIT_RESIDUAL_ATOL = 1e-4
"""[W] The largest |residual| of a smoothing fit: a parameter change of 2e-5 standard errors
moves a residual by ~2e-5 sigma sqrt(p) ~ 2e-4 W at sigma = 4 W at worst; 1.3e-5 W seen."""
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
    Tol("smoothing*", r"max_abs", LSQ_FLAT_RTOL, FIT_RESIDUAL_ATOL,
        "the largest residual of a fit moves with every parameter"),
    Tol("smoothing*", None, LSQ_FLAT_RTOL, 1e-9,
        "least squares of gamma and run temperatures, 8 data and up to 5 parameters"),
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
                        "--no-figures", "--base", "eq6"]),  # the default's choice: loop_clean
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


IDENTITY: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("smoothing/smoothing_fits.csv", ("variant",)),
    ("smoothing/smoothing_loss_vs_T.csv", ("curve", "T")),
    ("smoothing/smoothing_run_temps.csv", ("variant", "oil", "T")),
    ("smoothing/smoothing_plateau.csv", ("curve",)),
    ("smoothing/smoothing_table4.csv", ("group", "oil")),
    ("*oil_grade_table.csv", ("oil",)),
    ("pareto/pareto_seeds.csv", ("design",)),
    ("predict_*.csv", ("speed_rpm", "temp_C", "oil", "roughness_T")),
)
"""The columns that name a row of a CSV output (fnmatch on its path, first match wins).
Rows are matched by these, never by position (issue 26). Not listed: a grid table (a
``status`` column) is named by its input columns, those before ``status``; a store
``points_*.csv`` by the inputs its ``point_key`` stands for (the ``results.csv`` beside
it); any other CSV by all its columns (an input file)."""

KEY_INPUTS = "@"
"""Prefix of the input columns joined to a ``points_*.csv`` through its ``point_key``."""


def identity(rel: str, df: pd.DataFrame) -> list[str]:
    """The columns that name a row of the CSV output ``rel`` (see :data:`IDENTITY`)."""
    top = rel.replace("\\", "/")
    for pattern, cols in IDENTITY:
        if fnmatch(top, pattern):
            return list(cols)
    keyed = [c for c in df.columns if str(c).startswith(KEY_INPUTS)]
    if keyed:
        return keyed
    if "status" in df.columns:
        return list(df.columns[: list(df.columns).index("status")])
    return list(df.columns)


def _with_key_inputs(points: pd.DataFrame, results: Path) -> tuple[pd.DataFrame, list[str]]:
    """A store's rows with the inputs their ``point_key`` stands for (from ``results.csv``:
    the columns before ``status`` but ``label``, which the key leaves out)."""
    res = pd.read_csv(results)
    cols = [c for c in res.columns[: list(res.columns).index("status")] if c != "label"]
    keys = res[["point_key", *cols]].drop_duplicates("point_key")
    keys.columns = ["point_key", *(KEY_INPUTS + str(c) for c in cols)]
    missing = sorted(set(points["point_key"]) - set(keys["point_key"]))
    out = points.merge(keys, on="point_key", how="left", validate="one_to_one")
    return out, [f"point_key {k} is in no row of {results.name}" for k in missing[:5]]


def _same(u: pd.Series, v: pd.Series, rtol: float, atol: float) -> np.ndarray:
    """Row by row: the cells of two columns are equal (numbers as :func:`_close`, NaN equal
    to NaN; booleans and text exactly)."""
    if u.dtype.kind in "iuf" and v.dtype.kind in "iuf":
        a, b = u.to_numpy(dtype=float), v.to_numpy(dtype=float)
        with np.errstate(invalid="ignore"):
            close = np.abs(a - b) <= atol + rtol * np.maximum(np.abs(a), np.abs(b))
        return close | (np.isnan(a) & np.isnan(b))
    return _exactly(u, v)


def _exactly(u: pd.Series, v: pd.Series) -> np.ndarray:
    a, b = u.to_numpy(dtype=object), v.to_numpy(dtype=object)
    return (a == b) | (pd.isna(a) & pd.isna(b))


def compare_csv(a: Path, b: Path, rel: str = "") -> list[str]:
    """Differences between two CSV files: rows matched by their identity (:func:`identity`),
    numbers to their tolerance, timings skipped. A ``point_key`` is a hash of the text of its
    point's inputs: it is compared through those inputs (to their tolerance), and must be
    the same string only where the inputs are bit-identical (a fitted input may move in its
    last bit on another processor, and its key with it)."""
    rel = rel or a.name
    x, y = pd.read_csv(a), pd.read_csv(b)
    out: list[str] = []
    if a.name.startswith("points_") and "point_key" in x.columns:
        for side in (a, b):
            if not (side.parent / "results.csv").exists():
                return [f"{a.name}: no results.csv beside {side}"]
        x, bad_x = _with_key_inputs(x, a.parent / "results.csv")
        y, bad_y = _with_key_inputs(y, b.parent / "results.csv")
        out += bad_x + bad_y
    if list(x.columns) != list(y.columns) or len(x) != len(y):
        return [*out, f"{a.name}: shape/columns differ"]
    ids = identity(rel, x)
    x = x.sort_values(ids, kind="mergesort", ignore_index=True, na_position="last")
    y = y.sort_values(ids, kind="mergesort", ignore_index=True, na_position="last")
    tols = {c: tolerance(rel, str(c).removeprefix(KEY_INPUTS)) for c in x.columns}

    def cell(df: pd.DataFrame, c: str, i: int):
        v = df[c].iloc[i]
        return v.item() if isinstance(v, np.generic) else v

    def name(i: int) -> str:
        return " ".join(f"{c}={cell(x, c, i)}" for c in ids)

    found = np.logical_and.reduce([_same(x[c], y[c], *tols[c]) for c in ids])
    exact = np.logical_and.reduce([_exactly(x[c], y[c]) for c in ids])
    for i in np.flatnonzero(~found):
        out.append(f"{a.name}[{name(i)}]: no row with these inputs (got "
                   + " ".join(f"{c}={cell(y, c, i)}" for c in ids) + ")")
    for c in x.columns:
        if c in TIMING_KEYS or c in ids:
            continue
        bad = found & ~_same(x[c], y[c], *tols[c])
        if c == "point_key":
            bad &= exact
        out += [f"{a.name}[{name(i)}, {c}]: {cell(x, c, i)!r} != {cell(y, c, i)!r}"
                for i in np.flatnonzero(bad)]
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


THREAD_VARS = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def avx512_targets() -> list[str]:
    """numpy's AVX-512 dispatch targets that this processor runs (``X86_V4``,
    ``AVX512_ICL``, ... : their names vary with numpy's version; only dispatch targets can
    be switched off, and only those the processor has are listed)."""
    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    except ImportError:  # pragma: no cover - numpy < 2
        from numpy.core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    return [f for f in __cpu_dispatch__ if ("AVX512" in f or f == "X86_V4")
            and __cpu_features__.get(f)]


def without_avx512_env() -> dict[str, str]:
    """Environment that makes this machine compute as one without AVX-512 on one thread:
    numpy's AVX-512 kernels off (``NPY_DISABLE_CPU_FEATURES``), OpenBLAS on its AVX2
    (Haswell) kernels (``OPENBLAS_CORETYPE``; numpy's and scipy's OpenBLAS pick SkylakeX
    kernels on an AVX-512 processor), one BLAS/OpenMP thread. On a processor without
    AVX-512 only the thread counts are set."""
    env = dict.fromkeys(THREAD_VARS, "1")
    targets = avx512_targets()
    if targets:
        env["NPY_DISABLE_CPU_FEATURES"] = " ".join(targets)
        env["OPENBLAS_CORETYPE"] = "Haswell"
    return env


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
    elif sys.argv[1:] == ["env-without-avx512"]:  # NAME=value lines, for .ci/run
        print("\n".join(f"{k}={v}" for k, v in without_avx512_env().items()))
    else:
        print(__doc__)
