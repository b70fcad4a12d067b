"""The synthetic rig: format, physics from the model, thermal model, effects, noise."""

from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import quad

from oilgap.model.effects import end_face_disc_power, first_order_lag
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.measured.data import REQUIRED_COLUMNS
from oilgap.model.oils import get_oil
from oilgap.model.regions import joint_geometry
from oilgap.model.viscous_loss import clearance_power
from oilgap.studies.reporting import write_data_csv
from oilgap.studies.rigs.synth import (
    BaselineTruth,
    SynthConfig,
    fluid_table,
    polymer_thickened,
    seed_truth_law,
    simulate_truth,
    synthesize,
)


def test_format_and_no_hint_of_the_effect(tmp_path):
    clean = synthesize(SynthConfig(), seed=0)
    lag = synthesize(SynthConfig(effect="thermal_lag"), seed=0)
    assert list(clean.columns) == list(REQUIRED_COLUMNS) + ["power_W"]
    assert list(lag.columns) == list(clean.columns)
    assert len(clean) == 10 * 1500
    assert sorted(clean["oil"].unique()) == ["VG1000", "VG150", "VG320", "VG680", "none"]
    assert sorted(clean["roughness_T"].unique()) == [2.0, 4.0]
    t = clean.loc[clean["run"] == "VG150-T4", "time_s"].to_numpy()
    assert t[0] == 0.0 and np.allclose(np.diff(t), 0.2)
    p = write_data_csv(lag, tmp_path / "lag.csv")
    text = p.read_text()
    assert "lag" not in text and "thermal" not in text and "effect" not in text


def test_oil_runs_follow_the_clearance_model():
    tr = simulate_truth(SynthConfig())
    case = seed_case()
    law = seed_truth_law(case)
    r1, r2 = case.region1, case.region2
    for i, (name, oil, T) in enumerate(tr["runs"]):
        if oil is None:
            assert np.all(tr["viscous_W"][i] == 0)
            continue
        nu, _, rho = get_oil(oil).properties(tr["temp_oil_C"][i] + 273.15, 0.0)
        w = tr["omega"][i]
        p = clearance_power(w, nu, rho, r1.radius, r1.gap, r1.length, law, T) + \
            clearance_power(w, nu, rho, r2.radius, r2.gap, r2.length, law, 1.0)
        assert np.allclose(tr["viscous_W"][i], p, rtol=1e-12), name


def test_oil_free_run_temperature_against_convolution():
    # without oil the heat input is a known function of time (the copper term depends on
    # temperature only through a 0.4 %/K coefficient on a 0.4 W loss); the lumped model
    # C dT/dt = Q(t) - (T - Ta)/R has T(t) = Ta + int_0^t Q(s) e^{-(t-s)/RC} ds / C
    cfg = SynthConfig()
    tr = simulate_truth(cfg)
    i = [r[1] for r in tr["runs"]].index(None)
    bl = cfg.baseline
    w0, om = 3000 * 2 * np.pi / 60, 2 * np.pi * cfg.frequency_hz
    tau = cfg.thermal_resistance_K_W * cfg.heat_capacity_J_K
    T_mid = 26.0  # copper evaluated at a fixed temperature: error < 0.004*1.5 K*0.4 W

    def q(s):
        return bl.heat(w0 * np.sin(om * s), w0 * om * np.cos(om * s), T_mid)

    for k in (100, 700, 1499):
        t = tr["time_s"][k]
        kinks = np.arange(10.0, t, 10.0)  # |w| and sign(w) change at the zero crossings
        integral, _ = quad(lambda s, t=t: q(s) * np.exp(-(t - s) / tau), 0, t, points=kinks,
                           limit=400)
        expected = cfg.ambient_C + integral / cfg.heat_capacity_J_K
        assert tr["temp_meas_C"][i][k] == pytest.approx(expected, abs=2e-3)


def test_oil_free_mean_power_near_seed_table4():
    # seed paper Table 4, group 0: 24.42 W (grooved) and 25.36 W (smoothed) average power
    tr = simulate_truth(SynthConfig())
    free = [i for i, r in enumerate(tr["runs"]) if r[1] is None]
    for i in free:
        assert tr["measured_W"][i].mean() == pytest.approx(24.9, rel=0.1)


def test_noise_levels_and_seeds():
    cfg = SynthConfig()
    tr = simulate_truth(cfg)
    a = synthesize(cfg, seed=1)
    b = synthesize(cfg, seed=1)
    c = synthesize(cfg, seed=2)
    assert a.equals(b) and not a.equals(c)
    resid = a["power_W"].to_numpy() - tr["measured_W"].ravel()
    assert np.std(resid) == pytest.approx(cfg.noise_power_W, rel=0.05)
    temp_res = a["temp_C"].to_numpy() - tr["temp_meas_C"].ravel()
    assert np.std(temp_res) == pytest.approx(cfg.noise_temp_K, rel=0.05)


def test_thermal_lag_state_is_the_exact_lag_of_the_measured_temperature():
    tau = 4.0
    tr = simulate_truth(SynthConfig(effect="thermal_lag", strength=tau))
    for i in (1, 4):
        lagged = first_order_lag(tr["time_s"], tr["temp_meas_C"][i], tau)
        # the ODE state against the exact filter of the sampled record (piecewise linear)
        assert np.max(np.abs(tr["temp_oil_C"][i] - lagged)) < 2e-3


def test_sensor_delay_shifts_the_power_record():
    d = 0.2
    tr = simulate_truth(SynthConfig(effect="sensor_delay", strength=d, kind="viscous_power_W"))
    t = tr["time_s"]
    for i in range(len(tr["runs"])):
        shifted = np.interp(t - d, t, tr["viscous_W"][i])
        inner = t > 1.0
        # against the undelayed record interpolated back by d (0.2 s = one sample, exact
        # nodes): the remaining difference is the temperature's dense-output interpolation
        assert np.max(np.abs(tr["measured_W"][i][inner] - shifted[inner])) < 0.05


def test_viscous_kind_has_no_oil_free_runs():
    df = synthesize(SynthConfig(kind="viscous_power_W"), seed=0)
    assert "viscous_power_W" in df.columns and "power_W" not in df.columns
    assert "none" not in set(df["oil"])


def test_baseline_truth_terms_by_hand():
    bl = BaselineTruth()
    # at rest: electronics + roughness term + copper of the load torque
    p0 = bl.power(0.0, 0.0, 20.0, 4.0)
    assert p0 == pytest.approx(3.5 + 0.25 * 4 + 0.0)  # sign(0) = 0: no load torque at rest
    w = 100.0
    p = bl.power(w, 0.0, 20.0, 2.0)
    assert p == pytest.approx(3.5 + 0.5 + 0.09 * 100 + 1.5e-5 * 1e4 + 50 * 0.09**2)


@pytest.mark.parametrize("bad", [dict(oils=("VG9999",)), dict(roughness=(0.5,)),
                                 dict(strength=1.0), dict(kind="torque"),
                                 dict(effect="warp_drive")])
def test_bad_configuration(bad):
    with pytest.raises(InputError):
        simulate_truth(SynthConfig(**bad))


def test_the_truth_is_the_design_tools_smooth_eq6():
    law = seed_truth_law(seed_case())
    assert (law.form, law.laminar_law, law.scale, law.alpha) == ("smooth", "couette", 1.0, 0.3)
    assert law.gamma == seed_case().friction.gamma


def test_several_effects_at_once_add_their_terms():
    # seal (tau |w|) and free end-face discs (k x Pyrhonen's disc loss) injected together:
    # the injected power is the sum of the two terms at each run's own oil state
    cfg = SynthConfig(effects={"seal_coulomb_friction": 0.04, "end_face_disc": 3.0},
                      kind="viscous_power_W", n_samples=200)
    tr = simulate_truth(cfg)
    r_o, r_i = joint_geometry(seed_case()).disc_radii_m
    for i, (name, oil, _) in enumerate(tr["runs"]):
        nu, _, rho = get_oil(oil).properties(tr["temp_oil_C"][i] + 273.15, 0.0)
        w = tr["omega"][i]
        want = 0.04 * np.abs(w) + 3.0 * end_face_disc_power(w, nu, rho, r_o, r_i)
        assert np.allclose(tr["effect_W"][i], want, rtol=1e-9, atol=1e-12), name
    assert cfg.resolved().injected() == {"seal_coulomb_friction": 0.04, "end_face_disc": 3.0}
    # a strength None takes the default; the old single-effect API is the one-entry case
    one = SynthConfig(effects={"thermal_lag": None}).resolved()
    assert one.injected() == {"thermal_lag": 4.0}
    assert SynthConfig(effect="thermal_lag").resolved().injected() == one.injected()


def test_effect_and_effects_together_are_refused():
    with pytest.raises(InputError):
        SynthConfig(effect="oil_inertia", effects={"thermal_lag": 1.0}).resolved()
    with pytest.raises(InputError):
        SynthConfig(effects={"warp_drive": 1.0}).resolved()


def test_fluids_override_the_catalogue():
    thick = polymer_thickened(("VG320",))
    assert thick[0].polymer_thickened and thick[0].nu40_cSt == get_oil("VG320").nu40_cSt
    cfg = SynthConfig(oils=("VG320",), fluids=thick)
    assert cfg.oil("VG320") is thick[0] and cfg.oil("VG150") == get_oil("VG150")
    table = fluid_table(cfg)
    assert table["VG320"].polymer_thickened and not table["VG150"].polymer_thickened
    # same Walther line, so the same simulated record as the plain oil
    a = simulate_truth(replace(cfg, n_samples=50))
    b = simulate_truth(SynthConfig(oils=("VG320",), n_samples=50))
    assert np.array_equal(a["measured_W"], b["measured_W"])
