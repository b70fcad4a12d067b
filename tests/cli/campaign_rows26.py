"""Issue 26's rows of the bad-input campaign (:data:`ROWS26`, added to
``test_campaign.ROWS``): nothing unbounded, nothing misleading. Each case of the issue's
item 4, through the command line and the façade (``import oilgap as og``) alike, with a
neighbour that must still be accepted where the bound could bite a real input.

* upper bounds: ``optimize --starts``, ``study pareto --points`` (nothing written, no lock
  left), ``study oil-grade --mission-hours``;
* a temperature in kelvin in a degC key (``oil_temp_C = 275.15``) refused with the hint;
  a negative peak speed refused for being negative; a denormal one (5e-324) refused, no
  traceback;
* a file of the wrong kind named as such: a TOML given as ``--model``, a CSV given as the
  case;
* the loop warns when a quarter or more of the rows are dropped;
* ``[[mission]] oil_temp_C`` under ``bulk`` refused, asking for ``sea_temp_C``;
* a sea below the oil's trusted range (near its pour point) warned;
* impossible inputs refused before the solver (exit 2, not 4): a heat source that alone
  puts the oil above the balance's cap, a fluid-table viscosity that gives no finite loss.

The helpers are ``campaign_rows20``'s (``cli``, ``facade``); see its docstring.
"""

from __future__ import annotations

import campaign_rows20 as r20
from campaign_rows20 import cli, facade
from campaign_table import grid_row_not_ok
from test_campaign import DROP, case, rig, with_model

import oilgap as og

START = len(r20.ROWS20)
"""Rows of ROWS20 before these (this module appends through the same helpers)."""

THERMAL = {"sea_temp_C": 4.0, "resistance_K_per_W": 0.05, "heat_capacity_J_per_K": 4000.0}


def _table_case(nu: tuple[float, float, float]) -> dict:
    """A case on a fluid table ``f.csv`` with viscosities ``nu`` [cSt] at 0, 40, 100 degC."""
    rows = "".join(f"{t},{v!r},{rho}\n" for t, v, rho in
                   zip((0, 40, 100), nu, (900, 890, 880), strict=True))
    return {"case.toml": case(oil={"name": DROP, "kind": "table", "table_csv": "f.csv"}),
            "f.csv": "temp_C,nu_cSt,density_kg_m3\n" + rows}


def _drop_oil(df):
    """The VG320 runs renamed to an oil no table holds: half the rows dropped."""
    return df.assign(oil=df["oil"].replace({"VG320": "VG9999"}))


def _drop_run(df):
    """The first of the four runs given an unknown oil: a quarter dropped."""
    first = sorted(df["run"].unique())[0]
    return df.assign(oil=df["oil"].where(df["run"] != first, "VG9999"))


def _drop_few(df):
    """Three rows in 120 given an unknown oil: well under a quarter dropped."""
    return df.assign(oil=df["oil"].where(df.index % 40 != 3, "VG9999"))


# ==================================================================== 26.4 upper bounds
r20.GROUP = "26.4 unbounded inputs"
cli("i26-starts-1e9", "optimize --starts 1000000000", "refused", ("--starts", "1000"),
    "26.4: optimize --starts 1e9 is refused with its upper bound (each start is one IPOPT "
    "solve), not a 37 GiB allocation traceback")
cli("i26-starts-1000", "optimize --starts 1001", "refused", ("--starts", "1 to 1000"),
    "26.4: one start above the bound is refused too")
facade("og26-starts-1e9", lambda d: og.optimize(starts=10**9), "refused", ("starts", "1000"),
       "26.4: og.optimize(starts=10**9) is refused with the bound")
cli("i26-pareto-points-1e9", "study pareto --points 1000000000 --out p", "refused",
    ("points", "2000"), "26.4: study pareto --points 1e9 is refused at once, writing "
    "nothing and leaving no lock (today: 103 s silent, then killed, a lock left)")
facade("og26-pareto-points-1e9", lambda d: og.pareto(points=10**9, out="p"), "refused",
       ("points", "2000"), "26.4: og.pareto(points=10**9, out=...) is refused, nothing written")
cli("i26-oil-grade-hours-1e300", "study oil-grade --mission-hours 1e300 --out o", "refused",
    ("mission_hours", "1e\\+06 h"), "26.4: study oil-grade --mission-hours 1e300 is refused "
    "(today: 300-digit energies)")
facade("og26-oil-grade-hours-1e300", lambda d: og.oil_grade(mission_hours=1e300), "refused",
       ("mission_hours",), "26.4: og.oil_grade(mission_hours=1e300) is refused")

# ==================================================================== 26.4 misleading values
r20.GROUP = "26.4 misleading inputs"
cli("i26-oil-temp-kelvin", "evaluate case.toml", "refused",
    ("oil_temp_C = 275.15", "kelvin in a degC key", "2 degC"),
    "26.4: oil_temp_C = 275.15 gets a 'kelvin in a degC key?' hint, as metres in a mm key "
    "do", files={"case.toml": case(operating={"oil_temp_C": 275.15})})
cli("i26-sea-temp-kelvin", "evaluate case.toml", "refused", ("sea_temp_C = 277.15", "kelvin"),
    "26.4: [thermal] sea_temp_C = 277.15 gets the same hint",
    files={"case.toml": case(thermal={**THERMAL, "sea_temp_C": 277.15})})
cli("i26-oil-temp-cli-kelvin", "evaluate --temp-c 275.15", "refused", ("275.15", "kelvin"),
    "26.4: --temp-c 275.15 gets the hint too")
facade("og26-oil-temp-kelvin", lambda d: og.evaluate(oil_temp_C=275.15), "refused",
       ("oil_temp_C = 275.15", "kelvin"), "26.4: og.evaluate(oil_temp_C=275.15): the hint")
cli("i26-oil-temp-200-still-warned", "evaluate case.toml", "warned", ("oil_temp_C",),
    "26.4: the bound spares a hot but possible oil: 200 degC is warned, not refused",
    files={"case.toml": case(operating={"oil_temp_C": 200.0})})
cli("i26-peak-speed-negative", "evaluate case.toml", "refused",
    ("peak_speed_rpm = -2000", "must be positive", "^(?!.*faster than any)"),
    "26.4: peak_speed_rpm = -2000 is refused for being negative, not 'faster than any "
    "electric machine'", files={"case.toml": case(duty_cycle={"peak_speed_rpm": -2000.0})})
cli("i26-peak-speed-denormal", "evaluate case.toml", "refused", ("peak_speed_rpm = 5e-324",),
    "26.4: a denormal peak speed (5e-324) is refused naming it, no traceback",
    files={"case.toml": case(duty_cycle={"peak_speed_rpm": 5e-324})})
cli("i26-peak-speed-denormal-optimize", "optimize case.toml", "refused", ("peak_speed_rpm",),
    "26.4: optimize on a denormal peak speed: refused, no traceback",
    files={"case.toml": case(duty_cycle={"peak_speed_rpm": 5e-324})})
cli("i26-peak-speed-denormal-sweep", "study sweep grid.csv --workers 1 --out sw --no-progress",
    "accepted|warned", (), "26.4: a denormal peak speed in a sweep row is that row's error, "
    "no traceback", files={"grid.csv": "peak_speed_rpm\n5e-324\n3000\n"}, outputs=("sw",),
    check=grid_row_not_ok(0))
facade("og26-peak-speed-negative",
       lambda d: og.read_case("case.toml"), "refused", ("must be positive",),
       "26.4: og.read_case on peak_speed_rpm = -2000: negative, refused",
       files={"case.toml": case(duty_cycle={"peak_speed_rpm": -2000.0})})
cli("i26-peak-speed-slow-accepted", "evaluate case.toml", "accepted|warned", (),
    "26.4: a slow but real peak speed (0.5 rpm) is still evaluated",
    files={"case.toml": case(duty_cycle={"peak_speed_rpm": 0.5})})

# ==================================================================== 26.4 files of the wrong kind
r20.GROUP = "26.4 a file of the wrong kind"
cli("i26-predict-model-toml", "predict new.csv --model case.toml --out p.csv", "refused",
    ("--model", "TOML file where the loop.json"),
    "26.4: predict --model case.toml says a TOML was given where loop.json is expected",
    files={"case.toml": case()}, setup=with_model)
cli("i26-predict-model-csv", "predict new.csv --model new.csv --out p.csv", "refused",
    ("CSV file where the loop.json",), "26.4: a CSV as --model is named as such",
    setup=with_model)
facade("og26-predict-model-toml", lambda d: og.predict("case.toml", "new.csv"), "refused",
       ("TOML file where the loop.json",), "26.4: og.predict('case.toml', ...): a TOML, said",
       files={"case.toml": case()}, setup=with_model)
cli("i26-uncertainty-model-toml", "study uncertainty --model case.toml --out u", "refused",
    ("TOML file where the loop.json",), "26.4: study uncertainty --model case.toml: said",
    files={"case.toml": case()})
cli("i26-evaluate-rig-csv", "evaluate data.csv", "refused", ("CSV file where a case TOML",),
    "26.4: evaluate rig.csv says a CSV was given where a case TOML is expected",
    setup=rig())
facade("og26-evaluate-rig-csv", lambda d: og.evaluate("data.csv"), "refused",
       ("CSV file where a case TOML",), "26.4: og.evaluate('data.csv'): a CSV, said",
       setup=rig())
cli("i26-optimize-loop-json", "optimize loop.json", "refused", ("JSON file where a case TOML",),
    "26.4: a loop.json given as the case is named as such", setup=with_model)

# ==================================================================== 26.4 the loop's dropped rows
r20.GROUP = "26.4 misleading inputs"
cli("i26-loop-half-dropped", "loop data.csv --no-figures --out o", "warned",
    ("60 of 120 rows \\(50 %\\) dropped", "VG9999"), "26.4: the loop warns on stderr when a "
    "quarter or more of the rows are dropped (an oil not in the table)",
    setup=rig(_drop_oil), outputs=("o",))
facade("og26-loop-half-dropped", lambda d: og.Loop().fit("data.csv"), "warned",
       ("50 %\\) dropped",), "26.4: og.Loop().fit on data half dropped: the same warning",
       setup=rig(_drop_oil))
cli("i26-loop-quarter-dropped", "loop data.csv --no-figures --out o", "warned",
    ("30 of 120 rows \\(25 %\\) dropped",), "26.4: one run of four lost (exactly a quarter) "
    "is warned", setup=rig(_drop_run), outputs=("o",))
cli("i26-loop-few-dropped", "loop data.csv --no-figures --out o", "accepted|warned",
    (r"^(?![\s\S]*\) dropped)",), "26.4: a few dropped rows (3 of 120) are counted in the "
    "report, without the warning",
    setup=rig(_drop_few), outputs=("o",))

# ==================================================================== 26.4 mission under bulk
cli("i26-mission-oil-temp-bulk", "study oil-grade case.toml --out o", "refused",
    ("mission\\[0\\].oil_temp_C", "write sea_temp_C"),
    "26.4: [[mission]] oil_temp_C under bulk (the case's [thermal]) is refused, asking for "
    "sea_temp_C (it was used as the sea temperature without a word)",
    files={"case.toml": case(thermal=THERMAL, mission=[
        {"depth_m": 100.0, "oil_temp_C": 4.0, "fraction": 1.0}])})
facade("og26-mission-oil-temp-bulk", lambda d: og.oil_grade("case.toml"), "refused",
       ("write sea_temp_C",), "26.4: og.oil_grade on that case: refused alike",
       files={"case.toml": case(thermal=THERMAL, mission=[
           {"depth_m": 100.0, "oil_temp_C": 4.0, "fraction": 1.0}])})
cli("i26-mission-sea-temp-none", "study oil-grade case.toml --thermal none --out o", "refused",
    ("sea_temp_C", "write oil_temp_C"),
    "26.4: [[mission]] sea_temp_C under none is refused, asking for oil_temp_C",
    files={"case.toml": case(thermal=THERMAL, mission=[
        {"depth_m": 100.0, "sea_temp_C": 4.0, "fraction": 1.0}])})
cli("i26-mission-both-temps", "evaluate case.toml", "refused", ("not both",),
    "26.4: a [[mission]] row with oil_temp_C and sea_temp_C is refused",
    files={"case.toml": case(mission=[
        {"depth_m": 100.0, "sea_temp_C": 4.0, "oil_temp_C": 4.0, "fraction": 1.0}])})
cli("i26-mission-csv-oil-temp-bulk", "study oil-grade case.toml --mission m.csv --out o",
    "refused", ("write sea_temp_C",), "26.4: a mission CSV with oil_temp_C under bulk too",
    files={"case.toml": case(thermal=THERMAL), "m.csv": "depth_m,oil_temp_C,fraction\n100,4,1\n"})

# ==================================================================== 26.4 the cold sea
cli("i26-sea-below-pour-point", "evaluate case.toml", "warned", ("sea_temp_C = -55", "pour point"),
    "26.4: a sea at -55 degC, far below the oil's pour point, is warned even when the "
    "balance puts the bulk oil at a trusted temperature",
    files={"case.toml": case(thermal={**THERMAL, "sea_temp_C": -55.0,
                                      "other_heat_W": 1500.0})})
facade("og26-sea-below-pour-point", lambda d: og.evaluate("case.toml"), "warned",
       ("pour point",), "26.4: og.evaluate on that case: the same warning",
       files={"case.toml": case(thermal={**THERMAL, "sea_temp_C": -55.0,
                                         "other_heat_W": 1500.0})})
cli("i26-sea-cold-but-fine", "evaluate case.toml", "accepted", (),
    "26.4: a sea at 2 degC gives no pour-point warning",
    files={"case.toml": case(thermal={**THERMAL, "sea_temp_C": 2.0})})

# ============================================================ 26.4 impossible inputs: exit 2
r20.GROUP = "26.4 impossible inputs refused before the solver"
cli("i26-heat-source-alone", "evaluate case.toml", "refused",
    ("other_heat_W = 1000000.0", "alone is"), "26.4: a heat source no balance can hold "
    "(T_sea + R Q >= 250 degC) is refused, exit 2, not a solver failure",
    files={"case.toml": case(thermal={**THERMAL, "other_heat_W": 1e6})})
cli("i26-heat-source-alone-oil-grade", "study oil-grade case.toml --out o", "refused",
    ("other_heat_W",), "26.4: the oil-grade study on it: refused before any grid",
    files={"case.toml": case(thermal={**THERMAL, "other_heat_W": 1e6})})
cli("i26-heat-source-alone-sea-option", "evaluate case.toml --sea-temp-c 30", "refused",
    ("other_heat_W", "alone is"), "26.4: --sea-temp-c that tips sea + R Q over the cap: "
    "refused", files={"case.toml": case(thermal={**THERMAL, "resistance_K_per_W": 1.0,
                                                  "other_heat_W": 225.0})})
facade("og26-heat-source-alone", lambda d: og.optimize("case.toml"), "refused",
       ("other_heat_W",), "26.4: og.optimize on it: refused before the NLP",
       files={"case.toml": case(thermal={**THERMAL, "other_heat_W": 1e6})})
cli("i26-table-nu-1e300", "evaluate case.toml --thermal film", "refused", ("nu_cSt = 1e\\+300",
    "at most 1e\\+08 cSt"), "26.4: a table viscosity that makes no finite loss (1e300 cSt) is "
    "refused, exit 2, not a non-finite film factor (exit 4)", files=_table_case(
        (1e300, 1e299, 1e298)))
cli("i26-table-nu-1e200-optimize", "optimize case.toml", "refused", ("nu_cSt",),
    "26.4: optimize on that table: refused before the NLP",
    files=_table_case((1e200, 1e199, 1e198)))
facade("og26-table-nu-1e300", lambda d: og.read_case("case.toml"), "refused", ("nu_cSt",),
       "26.4: og.read_case on that table: refused", files=_table_case((1e300, 1e299, 1e298)))
cli("i26-table-nu-heavy-accepted", "evaluate case.toml", "accepted|warned", (),
    "26.4: a heavy but real table (1e6 cSt cold) is still evaluated",
    files=_table_case((1e6, 1e4, 1e2)))

ROWS26 = r20.ROWS20[START:]
"""Issue 26's rows (appended to ``test_campaign.ROWS``)."""
del r20.ROWS20[START:]  # made with issue 20's helpers, kept apart
