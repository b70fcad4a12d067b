"""Smoothing study: Table 4 data against the paper's own statements, the heat balance
against an independent evaluation, the fits recovering known parameters from
synthetic data, the plateau criterion against its closed form, bad input."""

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import brentq

from oilgap.cli import main
from oilgap.model.case import OperatingPoint
from oilgap.model.errors import InputError
from oilgap.model.evaluation import mean_viscous_power
from oilgap.model.io.case_io import seed_case
from oilgap.model.oils import get_oil
from oilgap.studies.settings import SmoothingSettings
from oilgap.studies.smoothing.fit import (
    T_GROOVED,
    T_SMOOTHED,
    fit_smoothing,
    load_table4,
    rig_case,
    steady_temperatures,
)
from oilgap.studies.smoothing.study import loss_vs_T, plateau_table, run


def rig(oil, smoothed, gamma, temp_C):
    """The rig run built independently of the study: seed_case(smoothed) at 0 m."""
    c = seed_case(smoothed)
    return replace(c, oil=get_oil(oil), friction=replace(c.friction, gamma=gamma),
                   operating=OperatingPoint(0.0, temp_C))


def test_table4_matches_the_papers_statements():
    t = load_table4()
    oil = t[t["group"] > 0]
    # Sec. V: "The viscous loss power decreases by an average of 19.75 W."
    assert -oil["measured_change_W"].mean() == pytest.approx(19.75, abs=0.005)
    # printed changes are after - before, except the VG680 row (documented in the file)
    ok = oil[oil["oil"] != "VG680"]
    np.testing.assert_allclose(ok["measured_after_W"] - ok["measured_before_W"],
                               ok["measured_change_W"], atol=0.006)
    np.testing.assert_allclose(oil["paper_model_after_W"] - oil["paper_model_before_W"],
                               oil["paper_model_change_W"], atol=0.006)
    # rows 1-4 are net of the dry run: 150 cSt smoothed is below the dry power
    assert oil["measured_after_W"].iloc[0] < t.loc[t["group"] == 0, "measured_after_W"].iloc[0]
    assert t["source"].str.contains("Table 4").all()


def test_rig_case_is_the_seed_on_the_rig():
    a = rig_case("VG320", T_SMOOTHED, 0.7)
    b = rig("VG320", True, 0.7, a.operating.oil_temp_C)
    assert mean_viscous_power(a, 35.0) == pytest.approx(mean_viscous_power(b, 35.0), rel=1e-14)


def test_steady_temperature_solves_the_heat_balance():
    cases = [rig_case(o, t, 0.6) for o in ("VG150", "VG1000") for t in (T_GROOVED, T_SMOOTHED)]
    tb, rth = 25.0, 0.2
    temps, powers = steady_temperatures(cases, tb, rth)
    for c, t, p in zip(cases, temps, powers, strict=True):
        p_ind = mean_viscous_power(c, t, 0.0)
        # the solver's last step (< 1e-4 K) may carry the loss to the root linearly
        assert p == pytest.approx(p_ind, rel=1e-10)
        assert t - tb - rth * p_ind == pytest.approx(0.0, abs=1e-8)
    # less power, colder oil: each smoothed run is colder than its grooved run
    assert temps[1] < temps[0] and temps[3] < temps[2]


def synthetic_table4(gamma, temps_of_run):
    """Table 4 with 'measured' powers made by the model itself at known parameters."""
    t = load_table4().copy()
    for i, r in t[t["group"] > 0].iterrows():
        for col, smoothed in (("measured_before_W", False), ("measured_after_W", True)):
            temp = temps_of_run(r["oil"], smoothed)
            t.loc[i, col] = mean_viscous_power(rig(r["oil"], smoothed, gamma, temp))
    return t


def test_per_oil_fit_recovers_known_parameters():
    truth = {"VG150": 31.0, "VG320": 38.0, "VG680": 44.0, "VG1000": 52.0}
    t4 = synthetic_table4(0.8, lambda oil, smoothed: truth[oil])
    f = fit_smoothing("per-oil", table4=t4)
    assert f.gamma == pytest.approx(0.8, abs=1e-6)
    for oil, temp in truth.items():
        assert f.base_temp_C[oil] == pytest.approx(temp, abs=1e-5)
    assert f.rms_W < 1e-6


def test_shared_fit_recovers_known_heat_balance():
    gamma, tb, rth = 0.7, 28.0, 0.15

    def temp(oil, smoothed):  # solve T = tb + rth P(T) independently (Brent)
        return brentq(lambda t: t - tb - rth * mean_viscous_power(rig(oil, smoothed, gamma, t)),
                      tb, tb + 100.0, xtol=1e-13)

    f = fit_smoothing("shared", table4=synthetic_table4(gamma, temp))
    assert f.gamma == pytest.approx(gamma, abs=1e-5)
    assert f.base_temp_C["all"] == pytest.approx(tb, abs=1e-4)
    assert f.resistance_K_W == pytest.approx(rth, abs=1e-6)


def test_plateau_criterion_against_closed_form():
    # P = a + b T^g: P(T) <= (1 + tol) P(1)  <=>  T <= ((tol (a + b) + b) / b)^(1/g)
    a, b, g, tol = 5.0, 20.0, 0.6, 0.05
    T = np.linspace(1, 5, 4001)
    P = a + b * T**g
    curves = pd.DataFrame({"curve": "x", "oil": "x", "T": T, "mean_power_W": P,
                           "dP_dT_W": b * g * T ** (g - 1)})
    row = plateau_table(curves, tol).iloc[0]
    assert row["T_stop"] == pytest.approx(((tol * (a + b) + b) / b) ** (1 / g), abs=1e-6)
    assert row["saving_per_unit_T_at_T4_W"] == pytest.approx(b * g * 4 ** (g - 1))
    share = (b * 4**g - b * 2**g) / (b * 4**g - b)
    assert row["share_of_possible_saving_4_to_2"] == pytest.approx(share, rel=1e-9)


def test_loss_vs_T_uses_the_model_and_refuses_T_below_1():
    f = fit_smoothing("per-oil")
    with pytest.raises(InputError):
        loss_vs_T(f, T_values=np.array([0.5, 1.0, 2.0]))
    cur = loss_vs_T(f, T_values=np.array([1.0, 2.0, 4.0]), include_rated=True)
    r = cur[(cur["oil"] == "VG680") & (cur["T"] == 4.0)].iloc[0]
    ind = mean_viscous_power(rig("VG680", False, f.gamma, r["oil_temp_C"]))
    assert r["mean_power_W"] == pytest.approx(ind, rel=1e-12)
    rated = cur[cur["curve"].str.contains("rated") & (cur["T"] == 4.0)].iloc[0]
    seed = replace(seed_case(), friction=replace(seed_case().friction, gamma=f.gamma))
    assert rated["mean_power_W"] == pytest.approx(mean_viscous_power(seed), rel=1e-12)


def test_study_table_and_outputs(tmp_path):
    r = run(tmp_path, settings=SmoothingSettings(sensitivity_K_W=(), T_values=np.linspace(1, 5, 9)))
    rows = r.table[r.table["group"] > 0]
    for _, row in rows.iterrows():
        before = mean_viscous_power(rig(row["oil"], False, r.fit.gamma,
                                        row["oil_temp_before_C"]))
        after = mean_viscous_power(rig(row["oil"], True, r.fit.gamma, row["oil_temp_after_C"]))
        assert row["model_before_W"] == pytest.approx(before, rel=1e-12)
        assert row["model_change_W"] == pytest.approx(after - before, rel=1e-12)
        assert row["model_minus_measured_change_W"] == pytest.approx(
            after - before - row["measured_change_W"], rel=1e-12)
    for f in ("smoothing_table4.csv", "smoothing_loss_vs_T.png", "smoothing_table4.png",
              "summary.md"):
        assert (tmp_path / f).stat().st_size > 0
    assert f"gamma = {r.fit.gamma:.3f}" in (tmp_path / "summary.md").read_text()


def test_cli_refuses_bad_T_range(capsys):
    assert main(["study", "smoothing", "--t-min", "0.5"]) == 2
    assert main(["study", "smoothing", "--t-step", "0"]) == 2
    assert main(["study", "smoothing", "--plateau-tol", "2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 3 and all(e.startswith("oilgap: error:") for e in err)
