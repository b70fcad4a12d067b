"""The argument table of ``oilgap plan`` and the ``--plan``/``--effects`` options of
``oilgap synth`` (cheap to import: argparse only). Defaults are None here and filled
from :class:`oilgap.studies.plan.settings.PlanSettings` when the command runs."""

from __future__ import annotations


def add_plan(sub, add_force) -> None:
    """Register ``oilgap plan``."""
    p = sub.add_parser(
        "plan", help="plan a rig campaign: the runs that identify the law and the effects",
        description="Choose the rig runs (oil, rotor roughness, bath temperature, speed "
        "profile, pressure) that identify the base law's parameters and detect the library "
        "effects: the Fisher information from the loop's forward model (CasADi AD), a "
        "continuous D/A/E/T-optimal design (cvxpy) with its optimality gap, rounded to "
        "whole runs; beside the naive full factorial of the same size. Writes DIR/plan.csv, "
        "naive.csv, parameters.csv, effects.csv, plan.json, plan_runs.png, summary.md.")
    p.add_argument("case", metavar="CASE", nargs="?", help="rig case TOML (default: the "
                   "seed joint)")
    p.add_argument("--oil-grades", metavar="A,B", help="candidate oils of the built-in "
                   "table (default VG150,VG320,VG680,VG1000)")
    p.add_argument("--bath-C", metavar="T,T", help="bath temperatures [degC] (default 25,40)")
    p.add_argument("--roughness", metavar="T,T", help="rotor variants by roughness T "
                   "(default 4,2)")
    p.add_argument("--profiles", metavar="P,P", help="speed profiles: sine, trapezoid, "
                   "steps (default sine,steps)")
    p.add_argument("--pressures-MPa", metavar="P,P", help="gauge pressures of the rig's "
                   "vessel [MPa] (default 0: no vessel)")
    p.add_argument("--effects", metavar="NAME,...", help="library effects to detect "
                   "(default: the library less the ball drag)")
    p.add_argument("--criterion", choices=("D", "A", "E", "T"), help="design criterion "
                   "(default D; T: detect the effects, the base law as nuisance)")
    p.add_argument("--targets", choices=("base", "all"), help="parameters of the D/A/E "
                   "criterion: the base law's (default) or those and the effects")
    p.add_argument("--base", choices=("eq6", "power-law"), help="the base law the loop "
                   "will fit (default eq6)")
    p.add_argument("--runs", type=int, help="number of runs (default 8)")
    p.add_argument("--budget-h", type=float, help="rig time available [h]: sets the number "
                   "of runs (instead of --runs)")
    p.add_argument("--noise-W", type=float, help="power noise sd per sample [W] (default 1)")
    p.add_argument("--expected-scale", type=float, help="the friction scale the rig is "
                   "expected to show: the plan's expansion point (default 1, Eq. 6 as "
                   "published; the Couette floor's kink then lies just below it)")
    p.add_argument("--duration-s", type=float, help="run length [s] (default 300)")
    p.add_argument("--sample-s", type=float, help="sample step [s] (default 0.2)")
    p.add_argument("--peak-rpm", type=float, help="peak speed [rpm] (default 3000)")
    for name, what in (("run", "one run beyond its duration (default 0.25)"),
                       ("oil", "an oil change (default 2)"),
                       ("temp", "a temperature change (default 1)"),
                       ("rotor", "a rotor change (default 4)")):
        p.add_argument(f"--cost-{name}-h", type=float, help=f"rig time of {what} [h]")
    p.add_argument("--out", metavar="DIR", default="plan_out",
                   help="output directory (default: plan_out)")
    add_force(p)
    p.add_argument("--json", action="store_true", help="print plan.json instead of the "
                   "tables")
    p.set_defaults(command="plan")


def add_synth_plan(p) -> None:
    """``oilgap synth --plan plan.csv [--effects NAME[=S],...]``."""
    p.add_argument("--plan", metavar="plan.csv", help="simulate the runs of a plan "
                   "(oilgap plan) instead of the seed's experiment; writes viscous_power_W")
    p.add_argument("--effects", metavar="NAME[=S],...", help="with --plan: inject these "
                   "library effects (at their test strength unless =S)")
    p.add_argument("--truth-scale", type=float, help="with --plan: the true friction scale "
                   "of the simulated rig (default 1; the plan's --expected-scale)")
