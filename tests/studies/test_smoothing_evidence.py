"""The film-strength evidence fit (oilgap.studies.smoothing.evidence).

Synthetic Table-4-like data are generated here with a known film strength s, room
temperature T0, resistance R and gamma by another code path than the fit's: the case's
own ``[thermal] film_strength`` through :func:`joint_mean_power` (mode ``film``), and the
rig's balance T = T0 + R (P_dry + P(T)) solved run by run with brentq in this test. The fit
must recover s, T0 and R.
"""

from dataclasses import replace

import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.model.case import ThermalSpec
from oilgap.model.joint_loss import joint_mean_power
from oilgap.studies.smoothing.evidence import film_evidence, film_power_function
from oilgap.studies.smoothing.fit import cases_power, load_table4, rig_case

S_TRUE, T0_TRUE, R_TRUE, GAMMA_TRUE = 0.5, 22.0, 0.15, 0.6


def _synthetic_table4():
    t4 = load_table4().copy()
    dry = t4[t4["group"] == 0].iloc[0]
    for i, r in t4[t4["group"] > 0].iterrows():
        for col, T, p_dry in (("measured_before_W", 4.0, dry["measured_before_W"]),
                              ("measured_after_W", 2.0, dry["measured_after_W"])):
            c = rig_case(str(r["oil"]), T, GAMMA_TRUE)
            c = replace(c, thermal=ThermalSpec(20.0, 1.0, 1.0, film_strength=S_TRUE))

            def g(t, c=c, p_dry=p_dry):
                return t - T0_TRUE - R_TRUE * (p_dry + float(joint_mean_power(c, t, "film")))
            t = brentq(g, T0_TRUE, 150.0, xtol=1e-10)
            t4.loc[i, col] = float(joint_mean_power(c, t, "film"))
    return t4


def test_strength_plumbing_matches_the_modes():
    cs = [rig_case("VG1000", 4.0, 0.566), rig_case("VG150", 2.0, 0.566)]
    t = np.array([22.0, 35.0])
    assert np.array_equal(film_power_function(cs, 1.0)(t), cases_power(cs, t, "film"))
    assert np.array_equal(film_power_function(cs, 0.0)(t), cases_power(cs, t, "none"))
    mid = film_power_function(cs, 0.5)(t)
    assert np.all(mid < cases_power(cs, t, "none")) and np.all(mid > cases_power(cs, t, "film"))


def test_recovers_strength_room_temperature_and_resistance():
    ev = film_evidence(table4=_synthetic_table4(), grid=(0.0, 0.5, 1.0))
    b = ev.best
    assert b.strength == pytest.approx(S_TRUE, abs=0.01)
    assert b.room_temp_C == pytest.approx(T0_TRUE, abs=0.1)
    assert b.resistance_K_W == pytest.approx(R_TRUE, abs=0.005)
    assert b.gamma == pytest.approx(GAMMA_TRUE, abs=0.01)
    assert b.rms_W < 1e-3
    lo, hi = ev.interval  # noise-free data: the interval closes around the truth
    assert lo <= S_TRUE <= hi
    assert ev.row(0.0)["rms_W"] > 0.1 and ev.row(1.0)["rms_W"] > 0.1


def test_issue_numbers_on_the_seed_table4():
    # the issue's figures (issue 18, item 1-2), reproduced from the shipped Table 4
    ev = film_evidence(grid=(0.0, 1.0))
    fa = ev.film_at_isothermal
    assert np.round(fa["film_grooved_W"].to_numpy(), 1).tolist() == [28.7, 39.8, 48.0, 58.2]
    po, pf = ev.per_oil_none, ev.per_oil_film
    assert po["intercept_C"] == pytest.approx(22.3, abs=0.1)
    assert po["slope_K_W"] == pytest.approx(0.235, abs=0.001)
    assert po["r2"] == pytest.approx(0.86, abs=0.01)
    assert pf["slope_K_W"] == pytest.approx(-0.08, abs=0.005)
    assert ev.vg1000["film_W_at_22C"] == pytest.approx(107.0, abs=0.5)
    assert ev.vg1000["none_temp_C"] == pytest.approx(47.0, abs=0.5)


def test_cli_flag_and_seed_only():
    from oilgap.cli import build_parser
    from oilgap.model.errors import InputError
    from oilgap.studies.settings import SmoothingSettings
    from oilgap.studies.smoothing import study as smoothing

    args = build_parser().parse_args(["study", "smoothing", "--film-evidence"])
    assert args.film_evidence is True
    assert build_parser().parse_args(["study", "smoothing"]).film_evidence is False
    other = rig_case("VG150", 3.0, 0.5)  # not the seed joint: no Table 4
    with pytest.raises(InputError, match="film_evidence"):
        smoothing.run(case=other, settings=SmoothingSettings(film_evidence=True))
