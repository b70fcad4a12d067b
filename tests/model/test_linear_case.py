"""A linear actuator case (issue 29): read and refused by key, evaluated by element; the
rod and passage terms against their closed forms over the sampled rod velocity; the
elements' heat in the balance; the CLI's JSON and og.evaluate give the same numbers."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

import oilgap as og
from oilgap.cli import main
from oilgap.model.errors import InputError
from oilgap.model.evaluation import oil_state
from oilgap.model.io.case_io import case_from_dict, read_case_toml
from oilgap.model.io.case_write import case_to_dict
from oilgap.model.joint_loss import operating_temperature

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "linear_joint.toml"


@pytest.fixture(scope="module")
def doc():
    import tomllib
    return tomllib.loads(EXAMPLE.read_text())


def _case(doc, **tables):
    d = {k: dict(v) if isinstance(v, dict) else v for k, v in doc.items()}
    for t, changes in tables.items():
        d[t] = {**d.get(t, {}), **changes}
    return case_from_dict(d, EXAMPLE.parent)


def test_rod_and_passage_terms_match_their_closed_forms(doc):
    case = read_case_toml(EXAMPLE)
    ev = og.evaluate(case, thermal="none").raw
    nu, mu, _ = oil_state(case)
    # the rod's velocity sampled as the case file gives it, 0.1 sin(2 pi 0.5 t), every 0.01 s
    t = np.arange(2000) * 0.01
    v = 0.1 * np.sin(2 * math.pi * 0.5 * t)
    r_i, r_o = 0.010, 0.010 + 0.05e-3
    rod = np.mean(2 * math.pi * 0.030 * mu * v**2 / math.log(r_o / r_i))
    q = math.pi * 0.010**2 * v
    passages = np.mean(128 * mu * 0.050 * q**2 / (math.pi * 0.002**4))
    rows = {e.name: e.mean_power_W for e in ev.linear_elements}
    assert rows["rod guide"] == pytest.approx(rod, rel=1e-9)
    assert rows["passages"] == pytest.approx(passages, rel=1e-9)
    parts = [r.mean_power_W for r in ev.regions] + [b.mean_power_W for b in ev.bearings]
    assert ev.total_mean_power_W == pytest.approx(sum(parts) + sum(rows.values()), rel=1e-12)
    assert ev.linear.peak_motor_speed_rpm == pytest.approx(1200.0)


def test_every_elements_heat_is_in_the_balance():
    case = read_case_toml(EXAMPLE)
    op = operating_temperature(case, "bulk")
    th = case.thermal
    assert op.oil_temp_C == pytest.approx(th.sea_temp_C + th.resistance_K_W * op.mean_power_W,
                                          abs=1e-6)
    assert len(op.element_mean_powers_W) == 4  # bearing, screw, rod guide, passages
    ev = og.evaluate(case, thermal="bulk").raw
    assert ev.oil_temp_C == pytest.approx(op.oil_temp_C, abs=1e-9)
    assert ev.total_mean_power_W == pytest.approx(op.mean_power_W, rel=1e-9)


@pytest.mark.parametrize("mode", ["none", "bulk", "film", "full"])
def test_json_and_the_facade_agree(capsys, mode):
    assert main(["evaluate", str(EXAMPLE), "--thermal", mode, "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    ev = og.evaluate(str(EXAMPLE), thermal=mode).raw
    assert d["total_mean_power_W"] == pytest.approx(ev.total_mean_power_W, rel=1e-5)
    for row, e in zip(d["linear_elements"], ev.linear_elements, strict=True):
        assert row["name"] == e.name
        assert row["mean_power_W"] == pytest.approx(e.mean_power_W, rel=1e-5)


def test_text_prints_the_loss_by_element(capsys):
    assert main(["evaluate", str(EXAMPLE), "--thermal", "none"]) == 0
    out = capsys.readouterr().out
    for label in ("motor gap", "motor bearing", "screw", "rod guide", "passages",
                  "total over the cycle"):
        assert label in out


def test_a_drive_without_passages_is_refused_as_a_dashpot(doc):
    # refused when the case is made: no command (evaluate, optimize, studies) sees it
    with pytest.raises(InputError, match=r"passages\.count.*dashpot of [0-9.e+]+ N"):
        _case(doc, passages={"count": 0})
    # the force: 6 pi mu L R^3 v / c^3 with mu of the case's oil, L 30 mm, R 10 mm,
    # c 0.05 mm, v 0.1 m/s
    case = read_case_toml(EXAMPLE)
    mu = oil_state(case)[1]
    with pytest.raises(InputError) as e:
        _case(doc, passages={"count": 0})
    force = float(str(e.value).split("dashpot of ")[1].split(" N")[0])
    assert force == pytest.approx(6 * math.pi * mu * 0.03 * 0.01**3 * 0.1 / 0.05e-3**3,
                                  rel=1e-3)


def test_a_dashpot_exits_2_with_one_line(capsys, tmp_path):
    text = EXAMPLE.read_text().replace("count = 1", "count = 0")
    p = tmp_path / "dashpot.toml"
    p.write_text(text)
    assert main(["evaluate", str(p)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "dashpot" in err[0]


@pytest.mark.parametrize(("tables", "key"), [
    ({"rod": {"diamter_mm": 20.0}}, "rod.diamter_mm"),
    ({"screw": {"type": "acme"}}, "type"),
    ({"rod": {"eccentricity": 1.0}}, "eccentricity"),
    ({"drive": {"stroke_mm": 20.0}}, "stroke_mm"),
    ({"duty_cycle": {"peak_speed_rpm": 100.0}}, "duty_cycle.peak_speed_rpm"),
    ({"passages": {"diameter_mm": -1.0}}, "diameter_mm"),
])
def test_bad_keys_are_refused_by_name(doc, tables, key):
    with pytest.raises(InputError) as e:
        _case(doc, **tables)
    assert key in str(e.value)


def test_linear_tables_in_a_rotary_case_are_refused(doc):
    with pytest.raises(InputError, match="only with"):
        _case(doc, drive={"kind": "rotary"})


def test_written_back_reads_the_same(doc):
    case = read_case_toml(EXAMPLE)
    again = case_from_dict(case_to_dict(case), EXAMPLE.parent)
    assert again.linear == case.linear
    assert np.array_equal(again.duty_cycle.omega_rad_s, case.duty_cycle.omega_rad_s)


def test_a_position_csv_gives_the_velocity(doc, tmp_path):
    t = np.arange(0.0, 4.0, 0.001)
    x = 0.02 * np.sin(math.pi * t)  # v = 0.02 pi cos(pi t)
    p = tmp_path / "rod.csv"
    rows = (f"{float(a)!r},{float(b)!r}" for a, b in zip(t, x, strict=True))
    p.write_text("time_s,rod_position_m\n" + "\n".join(rows))
    d = {k: v for k, v in doc.items() if k != "duty_cycle"}
    case = case_from_dict({**d, "duty_cycle": {"kind": "csv", "csv": str(p)}}, tmp_path)
    v_peak = case.duty_cycle.peak_omega_rad_s * 0.005 / (2 * math.pi)
    assert v_peak == pytest.approx(0.02 * math.pi, rel=1e-5)


@pytest.mark.parametrize("mode", ["none", "bulk"])
def test_the_vectorised_rows_reach_the_linear_elements(mode):
    from oilgap.model.uncertain import apply_inputs
    from oilgap.model.uncertain.arrays import joint_loss_arrays
    case = read_case_toml(EXAMPLE)
    factors = np.array([0.9, 1.0, 1.1])
    rows = joint_loss_arrays(case, {"nu40_factor": factors}, mode)
    scalar = [operating_temperature(apply_inputs(case, {"nu40_factor": f}), mode).mean_power_W
              for f in factors]
    assert rows == pytest.approx(scalar, rel=1e-12)
    assert rows[1] == pytest.approx(og.evaluate(case, thermal=mode).raw.total_mean_power_W,
                                    rel=1e-9)
