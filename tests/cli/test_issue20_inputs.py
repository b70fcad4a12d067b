"""Issue 20, classes 5-7: model-level inputs, through the command line and the façade.

5. A heat balance without a root below the solver's cap is a solver failure (exit 4, one
   line naming the bound and why), never an operating temperature; a heat source that
   alone puts the oil above the cap, before any loss, is an impossible input, refused
   before the solver (exit 2, issue 26).
6. Impossible joints and fluids are refused with their reasons: the bearing inside the
   joint, L/gap and L/R ranges with a "mm written as m?" hint, fluid tables monotone in
   the physical direction, measured power > 0, a non-empty oil name.
7. Messages quote the value in the user's units, as written (``T1_mm = -1``, not -0.001).

Each row of :data:`ROWS` states the promise it checks; the rows run in the campaign's one
table (``tests/cli/campaign_rows20.py`` makes each a command-line row and a façade row of
``tests/cli/test_campaign.py``): exit code, exactly one line on stderr, no traceback, the
words that name the field, the value as written and what is allowed; through the façade
(``import oilgap as og``) the project's own error class.
"""

from __future__ import annotations

from pathlib import Path

import oilgap as og
from oilgap.cli import main

CASE = """name = "t"
[region1]
T1_mm = 38.5
T2_mm = 40.0
T3_mm = 40.8
T4_mm = 42.3
length_mm = 30.0
[region2]
radius_mm = 34.0
length_mm = 20.0
gap_mm = 4.0
[oil]
name = "VG32"
[operating]
depth_m = 4000.0
oil_temp_C = 4.0
[friction]
gamma = 0.566
"""

THERMAL = ("[thermal]\nsea_temp_C = 4.0\nresistance_K_per_W = {r}\nother_heat_W = {q}\n"
           "heat_capacity_J_per_K = 4000.0\n")

WATER_OK = "temp_C,nu_cSt,density_kg_m3\n20,1.004,998.2\n40,0.658,992.2\n60,0.474,983.2\n"


def _table(rows: str) -> str:
    return "temp_C,nu_cSt,density_kg_m3\n" + rows


def _press(rows: str) -> str:
    return "temp_C,pressure_MPa,nu_cSt,density_kg_m3\n" + rows


def _rig(sign: float, oils=("VG22", "VG46"), col="viscous_power_W", mixed=False) -> str:
    """Steady rig points, P = 2e-5 n^2 [W] (n [rpm]) times ``sign``."""
    lines = [f"speed_rpm,temp_C,oil,roughness_T,{col}"]
    for oil in oils:
        for k, n in enumerate((500, 1000, 1500, 2000, 2500, 3000)):
            s = -sign if (mixed and k == 0) else sign
            lines.append(f"{n},20,{oil},4,{s * 2e-5 * n * n:.4f}")
    return "\n".join(lines) + "\n"


def R(promise, *, case=None, extra="", replace=(), files=None, argv=(), code=2,
      words=(), facade="evaluate", fkw=None, measured=None, xfail=None, cmd="evaluate"):
    """One row: a promise, the input (case edits, extra files, CLI options) and what must
    happen (exit code, words of the one line)."""
    return dict(promise=promise, case=case, extra=extra, replace=replace, files=files or {},
                argv=list(argv), code=code, words=words, facade=facade, fkw=fkw or {},
                measured=measured, xfail=xfail, cmd=cmd)


ROWS = {
    # ------------------------------------------------------------------ class 5
    "balance R 1000": R(
        "5: R = 1000 K/W has no root below 250 degC: exit 4, the bound and the loss named",
        extra=THERMAL.format(r=1000, q=0), code=4,
        words=("below 250 degC", "resistance_K_per_W = 1000", "> 250", "trusted to")),
    "balance R 1e300": R(
        "5: R = 1e300 K/W is a failure, not 250 degC printed as the operating temperature",
        extra=THERMAL.format(r=1e300, q=0), code=4,
        words=("below 250 degC", "resistance_K_per_W = 1e+300")),
    "balance Q 1e6": R(
        "5: other heat 1e6 W puts the base above the cap before any loss: an impossible "
        "input, refused before the solver (exit 2, issue 26)",
        extra=THERMAL.format(r=0.05, q=1e6), code=2, facade="read_case",
        words=("other_heat_W = 1000000.0", "alone is 5e+04 degC", ">= 250")),
    "balance Q 1e4 R 1": R(
        "5: Q = 1e4 W through 1 K/W (1e4 degC) is no operating point: refused (exit 2)",
        extra=THERMAL.format(r=1, q=1e4), code=2, facade="read_case",
        words=("other_heat_W = 10000", ">= 250")),
    "balance R 20 full": R(
        "5: R = 20 K/W under --thermal full (the film mode) fails the same way",
        extra=THERMAL.format(r=20, q=0), argv=["--thermal", "full"], code=4,
        fkw={"thermal": "full"}, words=("below 250 degC", "resistance_K_per_W = 20")),
    "balance Q 300 R 1 bulk": R(
        "5: T_sea + R Q = 304 degC under --thermal bulk: refused (exit 2) naming other_heat_W",
        extra=THERMAL.format(r=1, q=300), argv=["--thermal", "bulk"], code=2,
        fkw={"thermal": "bulk"}, words=("other_heat_W = 300", "304")),
    "optimize R 1000": R(
        "5: optimize on a joint whose balance has no root fails (exit 4), not at 250 degC",
        extra=THERMAL.format(r=1000, q=0), cmd="optimize", facade="optimize", code=4,
        words=("below 250 degC", "resistance_K_per_W = 1000")),
    "optimize Q 1e6": R(
        "5: optimize with Q = 1e6 W: the base above the cap, refused (exit 2) naming "
        "other_heat_W", extra=THERMAL.format(r=0.05, q=1e6), cmd="optimize",
        facade="optimize", code=2, words=("other_heat_W = 1000000.0",)),
    # ------------------------------------------------------------------ class 6: joints
    "length m as mm": R(
        "6: length_mm = 0.035 (metres typed as mm) is refused with the hint",
        replace=("length_mm = 30.0", "length_mm = 0.035"),
        words=("length_mm = 0.035", "length/gap", "allowed 1 to", "m written in a mm key")),
    "length shorter than gap": R(
        "6: a 0.5 mm long clearance with a 0.8 mm gap is no annulus (L/gap >= 1)",
        replace=("length_mm = 30.0", "length_mm = 0.5"),
        words=("length_mm = 0.5", "length/gap = 0.625", "L >> gap")),
    "length 100 radii": R(
        "6: a 5 m long joint on a 40 mm rotor (L/R 125) is refused with its reason",
        replace=("length_mm = 30.0", "length_mm = 5000"),
        words=("length_mm = 5000", "length/radius = 125", "T2_mm in m written in a mm key")),
    "region2 length m as mm": R(
        "6: region2 length_mm = 0.02 (metres typed as mm) is refused, naming region2",
        replace=("length_mm = 20.0", "length_mm = 0.02"),
        words=("region2", "length_mm = 0.02", "length/gap")),
    "region2 flat": R(
        "6: region2 2 mm long beside a 4 mm gap is refused (L/gap >= 1)",
        replace=("length_mm = 20.0", "length_mm = 2.0"),
        words=("region2", "length_mm = 2.0", "allowed 1 to")),
    "bearing 400 mm bore": R(
        "6: a 400 mm bore in a joint whose largest radius is 42.3 mm is refused",
        extra='[bearing]\nbore_mm = 400\noutside_mm = 480\nseries = "618"\n',
        words=("bore_mm = 400", "inside the joint", "T4_mm = 42.3")),
    "bearing 100 mm bore": R(
        "6: a 100 mm bore (50 mm radius) outside a 42.3 mm joint is refused",
        extra='[bearing]\nbore_mm = 100\noutside_mm = 125\nseries = "618"\n',
        words=("bore_mm = 100", "bore radius 50 mm")),
    "empty oil name case": R(
        "6: [oil] name = '' is refused, naming the key",
        replace=('name = "VG32"', 'name = ""'), facade="read_case",
        words=("oil", "name = ''", "non-empty oil name")),
    "blank oil name custom": R(
        "6: a custom oil with a blank name is refused",
        replace=('name = "VG32"', 'name = "  "\nnu40_cSt = 32\nnu100_cSt = 5.4\n'
                 'density_kg_m3 = 870'), facade="read_case",
        words=("name = '  '", "non-empty")),
    "empty --oil": R(
        "6: --oil '' is refused, not replaced by the case's oil",
        argv=["--oil", ""], fkw={"oil": ""}, words=("oil = ''",)),
    # ------------------------------------------------------------------ class 6: tables
    "table nu rises 100x": R(
        "6: a table whose viscosity rises 100-fold over 20 K is refused (liquids thin)",
        replace=('name = "VG32"', 'kind = "table"\ntable_csv = "f.csv"'),
        files={"f.csv": _table("20,1.0,998\n40,100.0,992\n")}, facade="read_case",
        words=("nu_cSt = 100.0", "must not rise with temperature", "20 degC", "40 degC")),
    "table nu rises at end": R(
        "6: a table falling then rising (a shifted row) is refused at the rising step",
        replace=('name = "VG32"', 'kind = "table"\ntable_csv = "f.csv"'),
        files={"f.csv": _table("20,1.004,998.2\n40,0.658,992.2\n60,0.9,983.2\n")},
        facade="read_case", words=("nu_cSt = 0.9", "0.658 cSt at 40 degC")),
    "table rows unordered rising": R(
        "6: rows in any order are sorted first; a rise is still found",
        replace=('name = "VG32"', 'kind = "table"\ntable_csv = "f.csv"'),
        files={"f.csv": _table("60,3.0,983\n20,1.0,998\n40,2.0,992\n")},
        facade="read_case", words=("must not rise with temperature",)),
    "table nu falls with p": R(
        "6: a table whose viscosity falls with pressure is refused (Barus)",
        replace=('name = "VG32"', 'kind = "table"\ntable_csv = "f.csv"'),
        files={"f.csv": _press("20,0.1,10,870\n40,0.1,5,860\n20,40,8,880\n40,40,6,870\n")},
        facade="read_case", words=("nu_cSt = 8.0", "must not fall with pressure", "Barus")),
    # ------------------------------------------------------------------ class 6: rig data
    "rig power negative": R(
        "6: rig data whose viscous power is negative everywhere is refused (sign check)",
        measured=_rig(-1.0), facade="read_measured",
        words=("viscous_power_W median", "must be > 0", "positive")),
    "rig electrical negative": R(
        "6: a negative electrical input power_W is refused the same way",
        measured=_rig(-1.0, col="power_W"), facade="read_measured",
        words=("power_W median", "must be > 0")),
    "rig one oil negative": R(
        "6: mostly negative with one positive row per oil is still refused",
        measured=_rig(-1.0, mixed=True), facade="read_measured",
        words=("viscous_power_W median",)),
    # ------------------------------------------------------------------ class 7
    "T1 -1 as written": R(
        "7: T1_mm = -1 is quoted as -1 (mm), not -0.001 (m)",
        replace=("T1_mm = 38.5", "T1_mm = -1"), words=("T1_mm = -1.0 ",), facade="read_case"),
    "T2 0 as written": R(
        "7: T2_mm = 0 is quoted in mm", replace=("T2_mm = 40.0", "T2_mm = 0"),
        words=("T2_mm = 0.0 ", "must be > 0"), facade="read_case"),
    "length -30 as written": R(
        "7: length_mm = -30 is quoted as -30.0, not -0.03",
        replace=("length_mm = 30.0", "length_mm = -30"), words=("length_mm = -30.0 ",),
        facade="read_case"),
    "region2 gap -4 as written": R(
        "7: region2 gap_mm = -4 is quoted in mm",
        replace=("gap_mm = 4.0", "gap_mm = -4"), words=("gap_mm = -4.0 ",), facade="read_case"),
    "T1 0.035 no float noise": R(
        "7: T1_mm = 40.035 above T2 is quoted 40.035, not 40.035000000000004",
        replace=("T1_mm = 38.5", "T1_mm = 40.035"), words=("T1_mm = 40.035 ",),
        facade="read_case"),
    "T3 1e7 as written": R(
        "7: T3_mm = 1e7 (size limit) is quoted as written",
        replace=("T3_mm = 40.8\nT4_mm = 42.3", "T3_mm = 1e7\nT4_mm = 1.1e7"),
        words=("T3_mm = 10000000.0 ", "at most 2000 mm"), facade="read_case"),
}


# The rows run in the campaign (tests/cli/campaign_rows20.py turns each into a command-line
# row and a façade row of tests/cli/test_campaign.py's one table): the command line's exit
# code and its one line naming the words, the façade's own error class.


def test_table_size():
    """The campaign of classes 5-7 has at least 25 rows, each with its promise."""
    assert len(ROWS) >= 25 and all(r["promise"][:2] in ("5:", "6:", "7:") for r in ROWS.values())


def test_plausible_inputs_still_accepted(tmp_path):
    """The rules refuse nothing plausible: the base case, a monotone water table and
    positive rig data pass (a rule that refused everything would pass the rows above)."""
    p = tmp_path / "case.toml"
    p.write_text(CASE + THERMAL.format(r=0.05, q=10))
    ev = og.evaluate(str(p))  # T = 4 + 0.05 (P + 10) degC: a few K above the sea
    assert 0.0 < ev.total_mean_power_W < 1e4
    (tmp_path / "w.csv").write_text(WATER_OK)
    og.read_case(_case_with(tmp_path, 'kind = "table"\ntable_csv = "w.csv"'))
    (tmp_path / "rig.csv").write_text(_rig(1.0))
    assert og.read_measured(str(tmp_path / "rig.csv")).frame.shape[0] == 12


def _case_with(tmp_path: Path, oil: str) -> str:
    p = tmp_path / "t.toml"
    p.write_text(CASE.replace('name = "VG32"', oil, 1))
    return str(p)


def test_sweep_row_without_balance_fails_alone(tmp_path, capsys):
    """5: in a sweep, the row whose balance has no root (R = 1000 K/W) is an error row
    naming the bound; its neighbours (R = 0.05, 0.1 K/W) keep their results."""
    import pandas as pd

    (tmp_path / "case.toml").write_text(CASE + THERMAL.format(r=0.05, q=0))
    (tmp_path / "g.csv").write_text("resistance_K_per_W\n0.05\n1000\n0.1\n")
    assert main(["study", "sweep", str(tmp_path / "g.csv"), "--case",
                 str(tmp_path / "case.toml"), "--out", str(tmp_path / "o")]) == 0
    res = pd.read_csv(tmp_path / "o" / "results.csv")
    assert list(res["status"]) == ["ok", "error", "ok"]
    assert "below 250 degC" in res["error"][1] and "resistance_K_per_W = 1000" in res["error"][1]
    ok = res["mean_power_W"][[0, 2]]
    assert ok.notna().all() and (ok > 0).all()
    assert "first failure (row 1)" in capsys.readouterr().err
