"""The grid engine: vectorised evaluation against the model's own per-case
path and an exact Couette hand calculation, grid parameters, failed points,
resumable runs, parallel = serial, bad grids, the progress line."""

import io
import math
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from oilgap.cli import main
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.errors import InputError
from oilgap.model.evaluation import mean_viscous_power, oil_state
from oilgap.model.io.case_io import seed_case
from oilgap.model.oils import get_oil
from oilgap.studies.grid import runner
from oilgap.studies.grid.evaluate import evaluate_cases
from oilgap.studies.grid.runner import progress_bar
from oilgap.studies.grid.schema import apply_params, read_grid_csv, validate_grid
from oilgap.studies.settings import SweepSettings, split_keywords


def run_grid(grid, case=None, *, out_dir=None, catalogue=None, label="sweep", on_chunk=None,
             **keywords):
    """The engine from keywords, as the façade builds its records."""
    return runner.run_grid(grid, case, *split_keywords(keywords, SweepSettings),
                           out_dir=out_dir, catalogue=catalogue, label=label,
                           on_chunk=on_chunk)


def random_grid(n, seed=0):
    rng = np.random.default_rng(seed)
    return pd.DataFrame({"oil": rng.choice(["VG15", "VG22", "VG46", "VG150"], n),
                         "oil_temp_C": rng.uniform(0, 40, n), "depth_m": rng.uniform(0, 7000, n),
                         "T": rng.uniform(1, 5, n), "gap_mm": rng.uniform(0.4, 2.0, n),
                         "gamma": rng.choice([0.3, 0.5, 0.8], n)})


def test_vectorised_evaluation_equals_mean_viscous_power_case_by_case():
    grid = random_grid(40, seed=1)
    base = seed_case()
    cases = [apply_params(base, r) for r in grid.to_dict("records")]
    got = evaluate_cases(cases)["mean_power_W"].to_numpy()
    ref = np.array([mean_viscous_power(c) for c in cases])
    np.testing.assert_allclose(got, ref, rtol=1e-12)


def test_laminar_region_power_equals_exact_couette_hand_calculation():
    # Constant speed, slow enough for Ta < 41.3 (laminar Couette law), smooth clearance.
    # Exact circular Couette torque per Eq. 2 times L: tau = 4 pi mu R1^2 R2^2 L w/(R2^2-R1^2);
    # the power is tau * w.
    w = 20.0  # rad/s
    duty = DutyCycle(np.array([0.0, 1.0]), np.array([w, w]), "constant")
    case = replace(seed_case(), duty_cycle=duty, region2=None)
    row = {"oil": "VG46", "oil_temp_C": 10.0, "depth_m": 0.0, "T": 1.0, "gamma": 0.5}
    c = apply_params(case, row)
    _, mu, _ = oil_state(c)
    R1, R2, L = 25.4e-3, 26.4e-3, 14.76e-3
    hand = 4 * math.pi * mu * R1**2 * R2**2 * L * w / (R2**2 - R1**2) * w
    res = evaluate_cases([c])
    assert res["Re1_peak"].iloc[0] * math.sqrt(1.0 / 25.4) < 41.3
    assert res["mean_power_W"].iloc[0] == pytest.approx(hand, rel=1e-12)


def test_geometry_parameters():
    base = seed_case()
    # T = 2 on the seed is the smoothed seed of the paper (T1 24.9, T4 26.9 mm).
    c = apply_params(base, {"T": 2.0})
    s = seed_case(smoothed=True)
    assert (c.region1.T1, c.region1.T4) == pytest.approx((s.region1.T1, s.region1.T4),
                                                         abs=1e-15)
    c = apply_params(base, {"gap_mm": 1.5, "T": 3.0, "R_mm": 24.0})
    r1 = c.region1
    assert r1.gap == pytest.approx(1.5e-3) and r1.radius == pytest.approx(24.0e-3)
    assert r1.roughness == pytest.approx(3.0)
    # groove depth split kept (seed: even): (T - 1) * gap / 2 each
    assert r1.T2 - r1.T1 == pytest.approx(1.5e-3) and r1.T4 - r1.T3 == pytest.approx(1.5e-3)
    c = apply_params(base, {"peak_speed_rpm": 1500.0})
    assert c.duty_cycle.peak_omega_rad_s == pytest.approx(1500 * 2 * math.pi / 60)
    c = apply_params(base, {"oil": "VG68", "oil_temp_C": 5.0, "depth_m": 100.0})
    assert (c.oil.name, c.operating.oil_temp_C, c.operating.depth_m) == ("VG68", 5.0, 100.0)


def test_failed_point_is_a_row_and_the_sweep_goes_on():
    grid = pd.DataFrame({"gap_mm": [1.0, -2.0, 0.8], "T1_mm": [23.9, 23.9, 30.0]})
    res = run_grid(grid, workers=1, progress=False)
    assert list(res["status"]) == ["ok", "error", "error"]
    assert "gap_mm" in res["error"].iloc[1]
    assert "T1_mm" in res["error"].iloc[2]
    assert np.isnan(res["mean_power_W"].iloc[1])
    assert res["mean_power_W"].iloc[0] == pytest.approx(mean_viscous_power(seed_case()))


def test_rerun_with_same_folder_does_not_recompute(tmp_path):
    grid = random_grid(30, seed=2)
    first = run_grid(grid, out_dir=tmp_path, workers=1, chunk_size=10, progress=False)
    assert first.attrs["computed"] == 30
    calls = []
    again = run_grid(grid, out_dir=tmp_path, workers=1, chunk_size=10, progress=False,
                     on_chunk=calls.append)
    assert again.attrs["computed"] == 0 and calls == []
    pd.testing.assert_series_equal(first["mean_power_W"], again["mean_power_W"])
    more = pd.concat([grid, random_grid(5, seed=3)], ignore_index=True)
    third = run_grid(more, out_dir=tmp_path, workers=1, chunk_size=10, progress=False)
    assert third.attrs["computed"] == 5
    assert (tmp_path / "results.csv").is_file()
    # a different base case is a different point
    other = replace(seed_case(), name="other")
    other = apply_params(other, {"length_mm": 15.0})
    fourth = run_grid(grid, case=other, out_dir=tmp_path, workers=1, progress=False)
    assert fourth.attrs["computed"] == 30


def test_parallel_chunks_equal_serial():
    grid = random_grid(120, seed=4)
    a = run_grid(grid, workers=1, progress=False)
    b = run_grid(grid, workers=2, chunk_size=25, progress=False)
    np.testing.assert_allclose(a["mean_power_W"].to_numpy(), b["mean_power_W"].to_numpy(),
                               rtol=1e-13)


@pytest.mark.parametrize("grid, field", [
    (pd.DataFrame({"oil": []}), "grid"),
    (pd.DataFrame({"wheel_mm": [1.0]}), "column"),
    (pd.DataFrame({"T": [2.0, 0.9]}), "T"),
    (pd.DataFrame({"gap_mm": ["wide"]}), "gap_mm"),
    (pd.DataFrame({"T": [2.0], "T1_mm": [24.0]}), "column"),
    (pd.DataFrame({"torque_min_Nm": [0.5]}), "column"),  # optimize-only column
])
def test_bad_grids_raise_input_error(grid, field):
    with pytest.raises(InputError) as e:
        validate_grid(grid)
    assert e.value.field == field


def test_unknown_oil_is_bad_input():
    with pytest.raises(InputError):
        run_grid(pd.DataFrame({"oil": ["VG99"]}), workers=1, progress=False)


def test_cli_sweep_bad_input_exits_2_with_one_line(tmp_path, capsys):
    p = tmp_path / "g.csv"
    for text in ("oil,wheel_mm\nVG22,3\n", "T\n0.5\n", "oil,T\n"):
        p.write_text(text)
        assert main(["study", "sweep", str(p), "--out", str(tmp_path / "o")]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith("oilgap: error:")


def test_cli_sweep_writes_results_and_resumes(tmp_path, capsys):
    g = tmp_path / "grid.csv"
    pd.DataFrame({"T": [1.0, 2.0, 4.0], "oil": ["VG22", "VG22", "VG32"]}).to_csv(g, index=False)
    out = tmp_path / "out"
    assert main(["study", "sweep", str(g), "--out", str(out), "--workers", "1",
                 "--thermal", "none"]) == 0
    res = read_grid_csv(out / "results.csv")
    expect = mean_viscous_power(replace(seed_case(), oil=get_oil("VG32")))
    assert res["mean_power_W"].iloc[2] == pytest.approx(expect, rel=1e-12)
    for f in ("sweep.png", "summary.md", "points_evaluate.csv"):
        assert (out / f).stat().st_size > 0
    capsys.readouterr()
    assert main(["study", "sweep", str(g), "--out", str(out), "--workers", "1",
                 "--thermal", "none", "--resume"]) == 0
    assert "0 computed, 3 reused" in capsys.readouterr().out


def test_progress_line():
    buf = io.StringIO()
    with progress_bar(200, "sweep", True, buf) as bar:
        bar.update(60)
        bar.refresh()
        assert "oilgap sweep:  30%" in buf.getvalue() and "60/200" in buf.getvalue()
        bar.update(140)
    assert "100%" in buf.getvalue() and "200/200" in buf.getvalue()
    assert "points/s" in buf.getvalue()
    quiet = io.StringIO()  # not a terminal: no bar unless asked
    with progress_bar(10, "sweep", None, quiet) as bar:
        bar.update(10)
    assert quiet.getvalue() == ""
