"""Smoothing study with the rig's heat balance (issue 10): the fitted runs against the
balance solved by hand, the optimum against its neighbours, a plumbing test on synthetic
Table 4 numbers, the paper's own errors from Table 4 by hand, the mode rules."""

from dataclasses import replace

import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.cli import main
from oilgap.model.case import OperatingPoint
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import joint_mean_power
from oilgap.model.oils import get_oil
from oilgap.studies.smoothing.fit import fit_smoothing, load_table4, resolve_fit_mode
from oilgap.studies.smoothing.study import _table, loss_vs_T, paper_row

OILS = ("VG150", "VG320", "VG680", "VG1000")


def rig(oil, smoothed, gamma):
    """The rig run built independently of the study: seed_case(smoothed) at 0 m."""
    c = seed_case(smoothed)
    return replace(c, oil=get_oil(oil), friction=replace(c.friction, gamma=gamma),
                   operating=OperatingPoint(0.0, 20.0))


def balance(case, t0, r):
    """T = T0 + R P_film(T) by Brent's method (R = 0: T = T0)."""
    if r == 0.0:
        return t0
    return brentq(lambda t: t - t0 - r * joint_mean_power(case, t, "film"), t0, t0 + 200.0,
                  xtol=1e-13)


def powers(gamma, t0, r):
    """The eight runs' film-heated powers [W] at their balance, in Table 4's order."""
    out = []
    for oil in OILS:
        for smoothed in (False, True):
            c = rig(oil, smoothed, gamma)
            out.append(joint_mean_power(c, balance(c, t0, r), "film"))
    return np.array(out)


def measured(t4):
    rows = t4[t4["group"] > 0]
    return np.column_stack([rows["measured_before_W"], rows["measured_after_W"]]).ravel()


@pytest.fixture(scope="module")
def hb():
    return fit_smoothing("heat-balance")


def check_runs_balance(f):
    """Every run at T = T0 + R P(T), P recomputed at the reported T."""
    for (oil, T), temp in f.temps_C.items():
        p = joint_mean_power(rig(oil, T == 2.0, f.gamma), temp, "film")
        assert p == pytest.approx(f.powers_W[(oil, T)], rel=1e-10)
        assert temp - f.base_temp_C["all"] - f.resistance_K_W * p == pytest.approx(0.0,
                                                                                   abs=1e-7)


def test_heat_balance_runs_satisfy_the_balance(hb):
    assert hb.method == "heat-balance" and hb.thermal_mode == "full"
    check_runs_balance(hb)


def test_study_tables_use_the_film_heated_loss(hb):
    t4 = load_table4()
    rows = _table(hb, seed_case(), t4, None)
    for _, row in rows[rows["group"] > 0].iterrows():
        for T, col, smoothed in ((4.0, "before", False), (2.0, "after", True)):
            temp = row[f"oil_temp_{col}_C"]
            assert temp == pytest.approx(hb.temps_C[(row["oil"], T)], abs=1e-12)
            p = joint_mean_power(rig(row["oil"], smoothed, hb.gamma), temp, "film")
            assert row[f"model_{col}_W"] == pytest.approx(p, rel=1e-10)
        assert row["thermal_mode"] == "full"
    cur = loss_vs_T(hb, T_values=np.array([1.0, 4.0]), table4=t4)
    r = cur[(cur["oil"] == "VG1000") & (cur["T"] == 4.0)].iloc[0]
    p = joint_mean_power(rig("VG1000", False, hb.gamma), r["oil_temp_C"], "film")
    assert r["mean_power_W"] == pytest.approx(p, rel=1e-10)


def test_heat_balance_optimum_is_a_local_minimum(hb):
    meas = measured(load_table4())

    def cost(gamma, t0, r):
        res = powers(gamma, t0, r) - meas
        return float(res @ res)

    x = (hb.gamma, hb.base_temp_C["all"], hb.resistance_K_W)
    c0 = cost(*x)
    assert c0 == pytest.approx(8 * hb.rms_W ** 2, rel=1e-9)
    for i, step in enumerate((0.01, 0.1, 0.005)):
        for sign in (1, -1):
            y = list(x)
            y[i] += sign * step
            if y[2] < 0:  # R_th at its bound 0: only the feasible side
                assert x[2] == 0.0
                continue
            assert cost(*y) > c0


def test_heat_balance_fit_recovers_known_parameters_plumbing():
    """Plumbing, not physics: 'measured' powers made by the model itself at known
    gamma, T0 and R (balance solved here by Brent); the fit must find them again."""
    gamma, t0, r = 0.7, 28.0, 0.15
    t4 = load_table4().copy()
    p = powers(gamma, t0, r)
    idx = t4.index[t4["group"] > 0]
    t4.loc[idx, "measured_before_W"] = p[0::2]
    t4.loc[idx, "measured_after_W"] = p[1::2]
    t4.loc[idx, "measured_change_W"] = p[1::2] - p[0::2]
    f = fit_smoothing("heat-balance", table4=t4, x0=[0.5, 25.0, 0.3])
    assert f.gamma == pytest.approx(gamma, abs=1e-5)
    assert f.base_temp_C["all"] == pytest.approx(t0, abs=1e-4)
    assert f.resistance_K_W == pytest.approx(r, abs=1e-6)
    assert f.rms_W < 1e-6 and f.reduction_max_abs_W < 1e-6
    check_runs_balance(f)


def test_paper_errors_from_table4_by_hand():
    # Table 4, brackets minus measured change: -13.21+10.85, -11.20+11.90, -20.57+22.25,
    # -31.28+34.01 (VG680 as printed)
    d = np.array([-2.36, 0.70, 1.68, 2.73])
    row = paper_row(load_table4())
    assert row["reduction_rms_W"] == pytest.approx(np.sqrt(np.mean(d ** 2)), abs=1e-9)
    # the "RMS 2.0 W, worst 2.7 W", to the digits quoted
    assert row["reduction_rms_W"] == pytest.approx(2.0, abs=0.05)
    assert row["reduction_max_abs_W"] == pytest.approx(2.7, abs=0.05)


def test_reduction_errors_and_the_documented_verdict(hb):
    t4 = load_table4()
    rows = t4[t4["group"] > 0]
    d = [hb.powers_W[(o, 2.0)] - hb.powers_W[(o, 4.0)] - c
         for o, c in zip(rows["oil"], rows["measured_change_W"], strict=True)]
    assert hb.reduction_rms_W == pytest.approx(np.sqrt(np.mean(np.square(d))), rel=1e-12)
    assert hb.reduction_max_abs_W == pytest.approx(np.max(np.abs(d)), rel=1e-12)
    # docs/studies.md: with gamma + 2 shared thermal parameters the heat balance does not
    # beat the paper's reductions (2.02 W RMS, 2.73 W worst); the fit puts R_th at 0
    paper = paper_row(t4)
    assert hb.reduction_rms_W > paper["reduction_rms_W"]
    assert hb.reduction_max_abs_W > paper["reduction_max_abs_W"]
    assert hb.resistance_K_W == 0.0


def test_mode_rules(tmp_path):
    assert resolve_fit_mode(None, None) == ("per-oil", "none", True)
    assert resolve_fit_mode("per-oil", None) == ("per-oil", "none", True)
    assert resolve_fit_mode("heat-balance", None) == ("heat-balance", "full", False)
    assert resolve_fit_mode(None, "full") == ("heat-balance", "full", False)
    assert resolve_fit_mode("shared", "film") == ("heat-balance", "full", False)
    assert resolve_fit_mode("per-oil", "film") == ("per-oil", "film", False)
    for bad in (("per-oil", "full"), ("heat-balance", "none"), ("x", None), (None, "hot")):
        with pytest.raises(InputError):
            resolve_fit_mode(*bad)
    out = str(tmp_path / "s")
    assert main(["study", "smoothing", "--method", "per-oil", "--thermal", "full",
                 "--out", out]) == 2
