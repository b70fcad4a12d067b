"""The argument tables of every ``oilgap`` command, cheap to import.

This module imports only :mod:`argparse` and the grid's column names
(:mod:`oilgap.studies.grid.columns`): building the parser never loads pandas,
matplotlib, SciPy, CasADi's NLP or cvxpy. Each command's parser sets ``command`` to
its key in :data:`oilgap.cli.COMMANDS`, the one dispatch table that
names the module whose ``run(args)`` executes it.
"""

from __future__ import annotations

import argparse
import math

from oilgap.cli.model_option import add_model_option
from oilgap.cli.plan_args import add_plan, add_synth_plan
from oilgap.model.thermal_modes import THERMAL_MODES
from oilgap.studies.grid.columns import OPTIMIZE_COLUMNS, PARAM_COLUMNS
from oilgap.studies.settings import (
    DEFAULT_CHUNK_SECONDS,
    DEFAULT_CONFIDENCE,
    DEFAULT_DEPTH_RANGE_M,
    DEFAULT_ISO_TOLERANCE,
    DEFAULT_MISSION_HOURS,
    DEFAULT_NU_MAX_CST,
    DEFAULT_NU_MIN_CST,
    DEFAULT_POINTS,
    DEFAULT_SOBOL_SAMPLES,
    DEFAULT_STARTS,
    DEFAULT_UNCERTAINTY_SAMPLES,
    MIN_POINTS,
    PLATEAU_TOL,
)

EFFECT_NAMES = ("end_face_disc", "bearing_ball_churning", "bearing_ball_drag",
                "seal_coulomb_friction",
                "oil_inertia", "thermal_lag", "taylor_vortex_onset", "shear_thinning",
                "sensor_delay", "film_heating")
"""The keys of :data:`oilgap.model.effects.EFFECTS`, in order (``synth --effect``
choices). Written out because importing the effect library loads scipy.signal
(about a second); ``tests/cli`` checks that the two agree."""


def finite_float(text: str) -> float:
    """argparse type: a finite float (NaN and infinity refused)."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"{text!r} is not allowed; a finite number is "
                                         "required") from None
    return x


def positive_int(text: str) -> int:
    """argparse type: an integer >= 1."""
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if v < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not allowed; an integer >= 1 is "
                                         "required")
    return v


SMOOTHING_THERMAL_MODES = ("none", "film", "full")
"""The modes of the smoothing study's Table 4 fit (its own methods: ``bulk`` there is the
``shared`` method, :mod:`oilgap.studies.smoothing.fit`)."""


def add_force(p, what: str = "--out") -> None:
    """The one ``--force`` option of every command that writes."""
    p.add_argument("--force", action="store_true",
                   help=f"replace the outputs of an earlier run at {what} (default: refuse "
                   "to overwrite anything)")


def add_report(p) -> None:
    """The ``--report DIR`` option of evaluate and optimize."""
    p.add_argument("--report", metavar="DIR", help="also write a report folder: summary.md "
                   "(the answer, the tables, the figure, the defaults), the JSON, a CSV, a "
                   "PNG and provenance.json (refused if DIR holds a report, unless --force)")


def add_thermal_argument(p) -> None:
    """The one ``--thermal`` option of every command that reports a loss."""
    p.add_argument("--thermal", choices=THERMAL_MODES, default=None,
                   help="none: isothermal oil at the given temperature (the seed paper's "
                   "model); bulk: isothermal film at the bulk oil temperature of the heat "
                   "balance to the sea (needs the case's [thermal] table); film: the film's "
                   "own shear heating at the given oil temperature; full: film heating at "
                   "the heat balance's temperature (needs [thermal]). Default: bulk with "
                   "[thermal], else none (the model the seed's Table 4 supports; "
                   "docs/thermal.md#evidence)")


def add_transition_argument(p) -> None:
    """``--transition``: where C_m leaves the laminar law (every command that takes a case)."""
    p.add_argument("--transition", choices=("reynolds", "taylor"),
                   help="where the vortex branch starts: Eq. 6's switch by Reynolds number "
                   "or exact Couette up to the critical Taylor number of the gap's radius "
                   "ratio (default: the case's [friction] transition, else reynolds; "
                   "docs/model.md#transition)")


def add_verbosity(p, top: bool = False) -> None:
    """The global ``-v``/``-q`` (on the main parser and every subparser, so that they go
    before or after the command; a subparser's copy sets nothing unless given)."""
    keep = {} if top else {"default": argparse.SUPPRESS}
    g = p.add_mutually_exclusive_group()
    g.add_argument("-v", "--verbose", action="count", **({"default": 0} if top else keep),
                   help="debug messages on stderr: the inputs read, versions, timings "
                   "(optimize: IPOPT's iterations too)")
    g.add_argument("-q", "--quiet", action="store_true", **({"default": False} if top
                                                             else keep),
                   help="errors and warnings only: no progress bars, no notes on stderr")


def build_parser() -> argparse.ArgumentParser:
    """The top-level parser with every command."""
    parser = argparse.ArgumentParser(
        prog="oilgap",
        description="Viscous-loss design tool for oil-filled joints of deep-sea manipulators.")
    parser.add_argument("--version", action="store_true",
                        help="print oilgap's version and exit")
    add_verbosity(parser, top=True)
    sub = parser.add_subparsers(dest="command_name", metavar="COMMAND")
    for add in (add_evaluate, add_optimize, add_study, add_loop, add_predict, add_synth):
        add(sub)
    add_plan(sub, add_force)
    _verbosity_everywhere(parser)
    return parser


def _verbosity_everywhere(parser: argparse.ArgumentParser) -> None:
    """:func:`add_verbosity` on every subparser below ``parser`` (``study`` and its
    studies too)."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sp in dict.fromkeys(action.choices.values()):
                add_verbosity(sp)
                _verbosity_everywhere(sp)


# --------------------------------------------------------------------------- evaluate


def add_evaluate(sub) -> None:
    """Register ``oilgap evaluate``."""
    p = sub.add_parser("evaluate", help="viscous loss of a joint over its duty cycle",
                       description="Evaluate a joint's viscous loss over its duty cycle, region "
                       "by region. Without CASE: the built-in seed joint, grooved (T = 4).")
    p.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    p.add_argument("--oil", help="oil name (overrides the case), e.g. VG22")
    p.add_argument("--oils", metavar="OILS.csv", help="oils table to look --oil up in")
    p.add_argument("--oils-only", action="store_true", help="the --oils table alone "
                   "(default: its oils are added to the built-in ISO VG catalogue, its row "
                   "winning a name clash with a warning)")
    p.add_argument("--temp-c", type=finite_float, help="oil temperature [degC]")
    p.add_argument("--depth-m", type=finite_float, help="sea depth [m]")
    p.add_argument("--laminar-law", choices=("couette", "bilgen-boulos"),
                   help="law below the critical Taylor number (default: the case's)")
    p.add_argument("--smoothed", action="store_true",
                   help="without CASE: the seed joint smoothed with epoxy (T = 2)")
    add_thermal_argument(p)
    add_transition_argument(p)
    p.add_argument("--sea-temp-c", type=finite_float, help="sea temperature [degC] of the "
                   "heat balance (overrides [thermal] sea_temp_C; --thermal bulk or full)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    add_report(p)
    add_force(p, "--report")
    add_model_option(p)  # --model loop.json (issue 25)
    p.set_defaults(command="evaluate")


# --------------------------------------------------------------------------- optimize


def add_optimize(sub) -> None:
    """Register ``oilgap optimize``."""
    p = sub.add_parser(
        "optimize", help="optimize the rotor-stator clearance geometry (CasADi/IPOPT)",
        description="Minimize the mean viscous power over the duty cycle by the region-1 "
        "geometry (R, delta, groove fill, L) subject to the motor's torque capability, the "
        "rotor inertia and the case's bounds. Without CASE: the built-in seed joint at its "
        "rated depth. Exit 3 if the constraints conflict, 4 if IPOPT fails.")
    p.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    p.add_argument("--oil", help="oil name (overrides the case), e.g. VG22")
    p.add_argument("--oils", metavar="OILS.csv", help="oils table to look --oil up in")
    p.add_argument("--oils-only", action="store_true", help="the --oils table alone "
                   "(default: its oils are added to the built-in ISO VG catalogue, its row "
                   "winning a name clash with a warning)")
    p.add_argument("--temp-c", metavar="X", help="oil temperature [degC]")
    p.add_argument("--depth-m", metavar="X", help="sea depth [m]")
    p.add_argument("--torque-min-nm", metavar="X",
                   help="required torque capability [N m] (default: the case's "
                   "bounds.torque_min_Nm, else the initial design's capability)")
    p.add_argument("--inertia-max-ratio", metavar="X",
                   help="rotor inertia limit as a multiple of the case's unfilled rotor "
                   "(default: the case's bounds.inertia_max_ratio)")
    p.add_argument("--starts", metavar="N", default=str(DEFAULT_STARTS),
                   help="start points: the case's design and N-1 random points in the bounds; "
                   f"the best optimum is reported (default {DEFAULT_STARTS}; the loss can be "
                   "non-convex near the Re = 64/500 regime breaks)")
    p.add_argument("--smoothed", action="store_true",
                   help="without CASE: start from the seed joint smoothed with epoxy (T = 2)")
    add_thermal_argument(p)
    add_transition_argument(p)
    p.add_argument("--sea-temp-c", metavar="X", help="sea temperature [degC] of the heat "
                   "balance (overrides [thermal] sea_temp_C; --thermal bulk or full)")
    p.add_argument("--robust", metavar="STAT", help="robust design: minimise p95 (its CVaR "
                   "surrogate), mean or mean+2sd of the loss over scenarios of the case's "
                   "uncertain inputs, printed beside the nominal optimum (thermal none or bulk)")
    p.add_argument("--scenarios", metavar="N", help="scenarios of --robust (default 64)")
    p.add_argument("--seed", metavar="S", help="Sobol' seed of the scenarios (default 0)")
    p.add_argument("--pareto", metavar="K", help="with --robust: K points of the front of "
                   "nominal loss against the statistic (default: none)")
    p.add_argument("--figure", metavar="FILE.png", help="with --robust: write the figure "
                   "(the front with --pareto, else both designs' Monte Carlo histograms)")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--out", metavar="CASE_OPT.toml",
                   help="write the optimal design as a case TOML (oilgap evaluate reads it)")
    add_force(p)
    add_report(p)
    _progress(p)
    add_model_option(p)  # --model loop.json (issue 25)
    p.set_defaults(command="optimize")  # -v/--verbose (every command) shows IPOPT's log


# --------------------------------------------------------------------------- study


def add_study(sub) -> None:
    """Register ``oilgap study`` and its five subcommands."""
    p = sub.add_parser("study", help="trade studies: smoothing, pareto, oil-grade, sweep, "
                       "uncertainty",
                       description="Trade studies. Each writes CSV, PNG figures and "
                       "summary.md to --out DIR (default out/<study>/).")
    ss = p.add_subparsers(dest="study", metavar="STUDY")
    ss.required = True
    for add in (_add_smoothing, _add_pareto, _add_oil_grade, _add_sweep, _add_uncertainty):
        add(ss)
    for s in ss.choices.values():  # every study: its result as one JSON document
        s.add_argument("--json", action="store_true", help="print one JSON document "
                       "(numbers, defaults, files written) instead of the text")


def _progress(s: argparse.ArgumentParser) -> None:
    s.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="progress line on stderr (default: if a terminal)")


def _scheduler(s: argparse.ArgumentParser) -> None:
    s.add_argument("--scheduler", metavar="local|tcp://HOST:PORT",
                   help="run on Dask (needs oilgap[dask]): local, a LocalCluster of "
                   "--workers processes; tcp://HOST:PORT, a running Dask scheduler "
                   "(default: local processes, no Dask); the same results")


def _add_smoothing(ss) -> None:
    s = ss.add_parser("smoothing", help="seed joint T = 4 vs T = 2 against Table 4; loss vs T",
                      description="Reproduce the seed's smoothing experiment (Table 4): "
                      "grooved T = 4 vs smoothed T = 2 with ISO VG150/320/680/1000 at 0 m; fit "
                      "gamma and the runs' effective oil temperatures; then loss against T.")
    s.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: the "
                   "seed rig and Table 4; a case: what smoothing its grooves would save)")
    add_transition_argument(s)
    s.add_argument("--out", metavar="DIR", help="output folder (default out/smoothing/)")
    add_force(s)
    s.add_argument("--method", choices=("per-oil", "shared", "heat-balance"), default=None,
                   help="run temperatures: one per oil (default), one shared steady balance "
                   "T = T_base + R_th P (isothermal loss), or heat-balance (the same with "
                   "the film-heated loss: --thermal full)")
    s.add_argument("--thermal", choices=SMOOTHING_THERMAL_MODES, default=None,
                   help="the loss at the runs' temperatures: none (default), isothermal oil "
                   "(the seed paper's model); film, the film's own shear heating; full, "
                   "film heating with the rig's heat balance T_run = T_0 + R_th P fitted "
                   "(the heat-balance method)")
    s.add_argument("--r-th-k-per-w", type=finite_float, default=0.0, metavar="K_PER_W",
                   help="per-oil method: fixed R_th [K/W] making smoothed runs colder "
                   "(default 0)")
    s.add_argument("--t-min", type=finite_float, default=1.0, help="smallest T (>= 1)")
    s.add_argument("--t-max", type=finite_float, default=None,
                   help="largest T (default 5; on a case its own T)")
    s.add_argument("--t-step", type=finite_float, default=0.05, help="T step")
    s.add_argument("--plateau-tol", type=finite_float, default=PLATEAU_TOL,
                   help="loss counts as levelled off within this fraction of P(T=1) "
                   f"(default {PLATEAU_TOL:g})")
    s.add_argument("--film-evidence", action="store_true",
                   help="seed rig: also fit the film strength s in [0, 1] with the rig's "
                   "heat balance T = T0 + R P (docs/thermal.md#evidence)")
    add_model_option(s)  # --model loop.json (issue 25)
    s.set_defaults(command="study smoothing")


def _add_pareto(ss) -> None:
    s = ss.add_parser("pareto", help="epsilon-constraint fronts: gap vs loss, loss vs inertia",
                      description="Pareto fronts of the design NLP by epsilon-constraint "
                      "sweeps (one warm-started IPOPT solve per point): magnetic gap vs loss "
                      "and loss vs rotor inertia; seed and smoothed seed marked.")
    s.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/pareto/)")
    add_force(s)
    s.add_argument("--points", type=positive_int, default=DEFAULT_POINTS,
                   help=f"points per front (>= {MIN_POINTS}, default {DEFAULT_POINTS})")
    s.add_argument("--torque-min-nm", type=finite_float,
                   help="required torque capability [N m] (default: the case's own)")
    s.add_argument("--workers", type=positive_int, help="processes (default: all cores)")
    _scheduler(s)
    add_thermal_argument(s)
    add_transition_argument(s)
    _progress(s)
    add_model_option(s)  # --model loop.json (issue 25)
    s.set_defaults(command="study pareto")


def _add_oil_grade(ss) -> None:
    s = ss.add_parser("oil-grade", help="choose the ISO VG grade over the envelope",
                      description="Mean loss of ISO VG10..VG1000 over the envelope, "
                      "lubrication and cold-start limits, mission energy; recommended grade.")
    s.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/oil-grade/)")
    add_force(s)
    s.add_argument("--mission", metavar="MISSION.csv",
                   help="mission profile depth_m,oil_temp_C,fraction (default: the case's "
                   "[[mission]] rows, else the stated seed mission)")
    s.add_argument("--nu-min-cst", type=finite_float, default=DEFAULT_NU_MIN_CST,
                   help="lubrication limit: minimum viscosity at the hottest point [cSt] "
                   f"(default {DEFAULT_NU_MIN_CST:g})")
    s.add_argument("--nu-max-cst", type=finite_float, default=DEFAULT_NU_MAX_CST,
                   help="cold-start limit: maximum viscosity at the coldest point [cSt] "
                   f"(default {DEFAULT_NU_MAX_CST:g})")
    s.add_argument("--iso-tolerance", type=finite_float, default=DEFAULT_ISO_TOLERANCE,
                   help="ISO 3448 grade tolerance applied at its worst "
                   f"(default {DEFAULT_ISO_TOLERANCE:.2f})")
    s.add_argument("--depth-min-m", type=finite_float, default=DEFAULT_DEPTH_RANGE_M[0])
    s.add_argument("--depth-max-m", type=finite_float, default=DEFAULT_DEPTH_RANGE_M[1])
    s.add_argument("--temp-min-c", type=finite_float,
                   help="oil temperature range, thermal none/film [degC] (default 0)")
    s.add_argument("--temp-max-c", type=finite_float, help="(default 40)")
    s.add_argument("--sea-temp-range-c", type=finite_float, nargs=2, metavar=("MIN", "MAX"),
                   help="thermal bulk/full: the envelope's sea temperatures [degC]; the oil's "
                   "operating temperature is a result (default 0 40, the same as the oil's "
                   "under none, so that the answers differ by the heating only)")
    s.add_argument("--mission-hours", type=finite_float, default=DEFAULT_MISSION_HOURS,
                   help=f"mission duration for the energy [h] (default {DEFAULT_MISSION_HOURS:g})")
    s.add_argument("--workers", type=positive_int, help="processes (default: all cores)")
    _scheduler(s)
    add_thermal_argument(s)
    add_transition_argument(s)
    _progress(s)
    add_model_option(s)  # --model loop.json (issue 25)
    s.set_defaults(command="study oil-grade")


def _add_sweep(ss) -> None:
    columns = list(PARAM_COLUMNS) + [f"{c} (optimize)" for c in OPTIMIZE_COLUMNS]
    s = ss.add_parser("sweep", help="evaluate or optimize every row of a grid CSV",
                      description="Run any grid of parameter combinations (one row per "
                      "point, columns: " + ", ".join(columns) + "). Empty cells keep the "
                      "case's value. A failed point is a row with its error; rerunning with "
                      "the same --out and --resume computes only the points not yet done.")
    s.add_argument("grid", metavar="GRID.csv", help="the grid: CSV, or Parquet (.parquet)")
    s.add_argument("--case", metavar="CASE.toml", help="base case (default: seed)")
    s.add_argument("--oils", metavar="OILS.csv", help="oils table to look oil names up in")
    s.add_argument("--oils-only", action="store_true", help="the --oils table alone "
                   "(default: its oils are added to the built-in ISO VG catalogue, its row "
                   "winning a name clash with a warning)")
    s.add_argument("--mode", choices=("evaluate", "optimize"), default="evaluate")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/sweep/)")
    again = s.add_mutually_exclusive_group()
    again.add_argument("--resume", action="store_true",
                       help="continue the sweep stored in --out (only the points not yet "
                       "done are computed)")
    again.add_argument("--force", action="store_true",
                       help="discard the sweep stored in --out and start over")
    s.add_argument("--workers", type=positive_int, help="processes (default: all cores)")
    s.add_argument("--chunk-size", type=positive_int, help="fixed rows per task (default: "
                   "chunks sized by time, --chunk-seconds)")
    s.add_argument("--chunk-seconds", type=finite_float, default=None,
                   metavar="S", help="target time of a chunk on a worker [s] (default "
                   f"{DEFAULT_CHUNK_SECONDS:g}): smooth "
                   "progress, and Ctrl-C loses at most one chunk per worker")
    _scheduler(s)
    s.add_argument("--retry-failed", action="store_true",
                   help="recompute points stored as failed (implies --resume; not with "
                   "--force)")
    add_thermal_argument(s)
    add_transition_argument(s)
    _progress(s)
    add_model_option(s)  # --model loop.json (issue 25)
    s.set_defaults(command="study sweep")


def _add_uncertainty(ss) -> None:
    s = ss.add_parser("uncertainty", help="the loss's p5/p50/p95 under uncertain inputs, "
                      "tornado and Sobol' indices",
                      description="Quasi-Monte Carlo (scrambled Sobol' points) of the joint's "
                      "mean loss over the case's [uncertainty] table (default: ISO 3448's "
                      "+-10 % on nu40, nu100 +-5 % and gamma 0.566 +- 0.041 from the seed fit): "
                      "its "
                      "percentiles, a histogram, a tornado and SALib's Sobol' indices.")
    s.add_argument("case", nargs="?", metavar="CASE.toml", help="design case (default: seed)")
    s.add_argument("--samples", type=positive_int, default=DEFAULT_UNCERTAINTY_SAMPLES,
                   metavar="N", help="Sobol' points of the percentiles, a power of 2 "
                   f"(default {DEFAULT_UNCERTAINTY_SAMPLES})")
    s.add_argument("--sobol-samples", type=positive_int, default=DEFAULT_SOBOL_SAMPLES,
                   metavar="N", help="Saltelli base points of the Sobol' indices, a power of "
                   f"2; N (d + 2) evaluations (default {DEFAULT_SOBOL_SAMPLES})")
    s.add_argument("--no-sobol", action="store_true", help="percentiles and tornado only "
                   "(no SALib)")
    s.add_argument("--seed", type=int, default=0, help="seed of the scrambling (default 0)")
    s.add_argument("--confidence", type=finite_float, default=DEFAULT_CONFIDENCE,
                   help=f"level of the indices' intervals (default {DEFAULT_CONFIDENCE:g})")
    s.add_argument("--model", metavar="loop.json", help="a calibrated loop: its fitted "
                   "gamma, friction scale and film strength (intervals, correlation) replace "
                   "the case's [uncertainty]")
    s.add_argument("--out", metavar="DIR", help="output folder (default out/uncertainty/)")
    add_force(s)
    add_thermal_argument(s)
    _progress(s)
    add_transition_argument(s)
    s.set_defaults(command="study uncertainty")


# --------------------------------------------------------------------------- loop


def add_loop(sub) -> None:
    """Register ``oilgap loop``."""
    p = sub.add_parser(
        "loop", help="calibrate on measured data, search a missing effect, report",
        description="Close the loop with measured data: validate DATA (CSV or Parquet), take "
        "away the oil-free baseline, fit the seed's model without and with T (Table 3), "
        "search the residual for a missing effect from the library (sparse regression, "
        "cross-validation over whole runs: leave-one-run-out up to 10 oil runs, grouped "
        "10-fold above), refit and report the errors before and after. "
        "Writes DIR/loop.json, DIR/report.md and figures.")
    p.add_argument("data", metavar="DATA.csv", help="measured runs (CSV, or .parquet)")
    p.add_argument("--oils", metavar="OILS.csv", help="oils table oil,nu40_cSt,nu100_cSt,"
                   "density_kg_m3 (default: the built-in ISO VG catalogue)")
    p.add_argument("--oils-only", action="store_true", help="the --oils table alone "
                   "(default: its oils are added to the built-in ISO VG catalogue, its row "
                   "winning a name clash with a warning)")
    p.add_argument("--case", metavar="RIG.toml", help="rig geometry (default: the seed joint)")
    p.add_argument("--out", metavar="DIR", default="loop_out",
                   help="output directory (default: loop_out)")
    add_force(p)
    p.add_argument("--json", action="store_true", help="print loop.json instead of the tables")
    p.add_argument("--margin", type=finite_float, default=0.10,
                   help="held-out RMSE fall an effect must bring (default 0.10)")
    p.add_argument("--effects", metavar="NAME,...", help="consider only these library effects")
    p.add_argument("--base", choices=("eq6", "auto", "power-law", "branches"), default="auto",
                   help="base model: auto = eq6, branches and eq6 with the Taylor transition "
                   "each fitted with its own effect search, the one of least held-out "
                   "log-RMSE kept, the simpler within --margin (default); "
                   "eq6 = the design tool's Eq. 6 x scale x T^gamma (the case's transition); "
                   "power-law = a free C (delta/R)^alpha Re^beta T^gamma; "
                   "branches = Eq. 6's branches, each C_k (delta/R)^alpha_k Re^beta_k freed "
                   "where the data identify it")
    p.add_argument("--write-case", metavar="CASE.toml", help="also write the rig case with "
                   "the fitted model folded in by reference ([calibration] model = the "
                   "loop.json): evaluate CASE.toml equals evaluate RIG --model loop.json")
    p.add_argument("--cv-by", metavar="COLUMN", default="run",
                   help="cross-validation groups: the values of this column of DATA, each "
                   "held out whole (default: run; e.g. gap_mm, oil; more than 10 groups: "
                   "grouped 10-fold)")
    p.add_argument("--no-figures", action="store_true", help="skip the figures")
    p.add_argument("--figures", choices=("summary", "all"), default="summary",
                   help="summary (default): every run's figures up to 24 runs, above that "
                   "the 12 worst runs and a grid of small multiples; all: every run's")
    _progress(p)
    p.set_defaults(command="loop")


# --------------------------------------------------------------------------- predict


def add_predict(sub) -> None:
    """Register ``oilgap predict``."""
    p = sub.add_parser(
        "predict", help="predict the power of new rows with a model fitted by oilgap loop",
        description="Predict with the model oilgap loop fitted (the 'model' block of its "
        "loop.json): writes the rows of DATA with predicted_viscous_power_W added (and "
        "predicted_power_W where an oil-free baseline was fitted: baseline + viscous). DATA "
        "is in the loop's format without a power column (new operating conditions; without "
        "time_s each row is a steady point). Rows that cannot be predicted are left empty "
        "with the reason in prediction_note.")
    p.add_argument("data", metavar="DATA.csv", help="rows to predict (CSV, or .parquet)")
    p.add_argument("--model", metavar="loop.json", required=True,
                   help="loop.json written by oilgap loop (or a bare model document)")
    p.add_argument("--out", metavar="pred.csv", required=True,
                   help="output table (CSV, or .parquet)")
    p.add_argument("--stage", choices=("without_T", "with_T", "with_effect"),
                   default="with_effect", help="which model (default: with the accepted "
                   "effects)")
    p.add_argument("--oils", metavar="OILS.csv", help="oils table for fluids the model does "
                   "not hold")
    p.add_argument("--oils-only", action="store_true", help="the --oils table alone "
                   "(default: its oils are added to the built-in ISO VG catalogue, its row "
                   "winning a name clash with a warning)")
    p.add_argument("--force", action="store_true", help="overwrite an existing --out")
    p.add_argument("--allow-incomplete", action="store_true", help="use a loop.json whose "
                   "folder is still marked INCOMPLETE (a loop that failed or was killed), "
                   "with a warning; refused otherwise")
    p.set_defaults(command="predict")


# --------------------------------------------------------------------------- synth


def add_synth(sub) -> None:
    """Register ``oilgap synth``."""
    p = sub.add_parser(
        "synth", help="simulate the seed's viscous-power experiment (test data for loop)",
        description="Simulate the seed's experiment: oil-free runs and four oils (ISO VG 150, "
        "320, 680, 1000), grooved (T = 4) and smoothed (T = 2), 1500 samples every 0.2 s of "
        "3000 rpm sin(0.1 pi t), a lumped thermal model heated by the losses, load and motor "
        "losses, measurement noise, and optionally one library effect. The CSV carries no "
        "trace of the effect.")
    p.add_argument("--effect", choices=list(EFFECT_NAMES), metavar="NAME",
                   help="inject this library effect (see --list-effects)")
    p.add_argument("--strength", type=finite_float,
                   help="strength of the effect in its unit (default: its test strength); >= 0 "
                   "where the effect's coefficient must be, at most 1000 x the test strength "
                   "(film_heating: the film strength s, 1 = the smooth-film theory)")
    p.add_argument("--seed", type=int, default=0, help="noise seed, an integer >= 0 (default 0)")
    p.add_argument("--out", metavar="data.csv", default="synth.csv",
                   help="output CSV (default: synth.csv)")
    add_force(p)
    p.add_argument("--case", metavar="RIG.toml", help="rig geometry (default: the seed joint)")
    p.add_argument("--roughness", metavar="T,T", default="4,2",
                   help="roughness T of the two rotor builds (default 4,2)")
    p.add_argument("--viscous", action="store_true",
                   help="write viscous_power_W (a torque balance) instead of power_W; no "
                   "oil-free runs")
    p.add_argument("--list-effects", action="store_true",
                   help="list the library effects with their strength units and exit")
    add_synth_plan(p)
    p.set_defaults(command="synth")
