"""The out-of-family rig against hand calculations, published values and oilgap's own laws.

The rig (``oilgap.studies.rigs.outside_rig``, laws in ``outside_laws``) must not share code
with the estimator; where oilgap has the same law (Eq. 6, Walther, the first-order
lag) the two implementations are compared here as a second method.
"""

import ast
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from oilgap.model.effects.laws import first_order_lag
from oilgap.model.errors import InputError
from oilgap.model.measured.data import validate
from oilgap.model.oils import builtin_oils
from oilgap.model.skin_friction import bilgen_boulos_cm, couette_law_cm
from oilgap.studies.reporting import write_data_csv
from oilgap.studies.rigs import outside_laws as laws
from oilgap.studies.rigs.outside_rig import (
    NEWTONIAN,
    OutsideConfig,
    SpeedProfile,
    effect_size_W,
    inject,
    simulate,
    steady_points,
    synthesize,
)

ROOT = Path(__file__).resolve().parents[2]
W0 = 3000 * 2 * math.pi / 60  # 314.159 rad/s


def test_imports_no_oilgap_physics():
    allowed = {"oilgap.model.errors", "oilgap.model.units"}
    for name in ("outside_rig.py", "outside_laws.py"):
        tree = ast.parse((ROOT / "studies" / "rigs" / name).read_text())
        mods = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.level == 0}
        mods |= {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
        assert {m for m in mods if m.startswith("oilgap")} <= allowed, name


# --------------------------------------------------------------------------- Eq. 6, Couette


def test_eq6_piecewise_by_hand():
    x = 0.04
    x03 = math.exp(0.3 * math.log(0.04))  # 0.380731
    assert x03 == pytest.approx(0.380731, rel=1e-6)
    cases = [(10.0, 10.0 / 10.0),                     # laminar: 10 Re^-1 = 1
             (63.9, 10.0 / 63.9),                     # just below the first break
             (64.0, 2.00 * 64.0**-0.6),               # 2 * 0.082469 = 0.164938
             (100.0, 2.00 * 0.0630957),               # 100^-0.6 = 10^-1.2
             (1000.0, 1.03 * 0.0316228),              # 1000^-0.5
             (1.0e4, 0.065 * 0.1584893),              # 1e4^-0.2 = 10^-0.8
             (1.0e5, 0.065 * 0.1)]                    # 1e5^-0.2 = 0.1
    for re, c in cases:
        assert laws.eq6_moment_coefficient(re, x) == pytest.approx(c * x03, rel=1e-6), re
    assert 2.00 * 64.0**-0.6 == pytest.approx(0.164938, rel=1e-5)


def test_eq6_against_oilgap_exact_form():
    # a second implementation: oilgap's bilgen_boulos_cm (piecewise Eq. 6)
    re = np.geomspace(1.0, 1e6, 997)
    for x in (0.02, 0.04, 0.227):
        assert np.allclose(laws.eq6_moment_coefficient(re, x), bilgen_boulos_cm(re, x),
                           rtol=1e-12)
        floor = np.maximum(laws.eq6_moment_coefficient(re, x),
                           laws.couette_moment_coefficient(re, x))
        assert np.allclose(floor, couette_law_cm(re, x), rtol=1e-12)


def test_couette_power_is_the_margules_torque():
    # narrow laminar gap, floor active: P = M w, M = 4 pi mu L w R1^2 R2^2 / (R2^2 - R1^2)
    R, d, L, w, nu, rho = 0.0254, 0.001, 0.01476, 100.0, 1.0e-3, 900.0
    p, re = laws.annulus_power(w, nu, rho, R, d, L)
    assert re == pytest.approx(100.0 * 0.0254 * 0.001 / 1.0e-3)   # 2.54
    R2 = R + d
    M = 4 * math.pi * (nu * rho) * L * w * R**2 * R2**2 / (R2**2 - R**2)
    assert p == pytest.approx(M * w, rel=1e-12)
    # by hand: Cm = 8 (1.03937)^2 / (2.03937 * 2.54) = 1.66839; P = 0.5 pi Cm rho w^3 R^4 L
    assert p == pytest.approx(0.5 * math.pi * 1.66839 * 900 * 1e6 * R**4 * L, rel=1e-5)
    # the groove factor multiplies: T^gamma = 4^0.5 = 2
    p4, _ = laws.annulus_power(w, nu, rho, R, d, L, roughness=(4.0, 0.5))
    assert p4 == pytest.approx(2 * p, rel=1e-12)
    # x = 0.227 (region 2): Eq. 6 lies above Couette at Re = 10, so the floor is not active
    x = 5 / 22
    assert laws.eq6_moment_coefficient(10.0, x) > laws.couette_moment_coefficient(10.0, x)


# --------------------------------------------------------------------------- fluids


@pytest.mark.parametrize("name", ["VG10", "VG22", "VG150", "VG1000"])
def test_walther_against_the_catalogue(name):
    oil = builtin_oils()[name]
    assert laws.VG_OILS[name] == (oil.nu40_cSt, oil.nu100_cSt, oil.density_kg_m3)
    for t_C, nu_expected in ((40.0, oil.nu40_cSt), (100.0, oil.nu100_cSt)):
        nu, _ = laws.fluid_state(name, t_C)
        assert nu * 1e6 == pytest.approx(nu_expected, rel=1e-12)
        nu_oilgap, _, _ = oil.properties(t_C + 273.15, 0.0)
        assert nu_oilgap * 1e6 == pytest.approx(nu_expected, rel=1e-12)
    # in between and outside the points, the two Walther implementations agree
    for t_C in (5.0, 25.0, 70.0, 120.0):
        nu, rho = laws.fluid_state(name, t_C)
        nu_oilgap, _, rho_oilgap = oil.properties(t_C + 273.15, 0.0)
        assert nu == pytest.approx(nu_oilgap, rel=1e-10)
        assert rho == pytest.approx(rho_oilgap, rel=3e-3)  # another expansion law


def test_density_and_silicone_by_hand():
    _, rho = laws.fluid_state("VG22", 40.0)
    assert rho == pytest.approx(860.0 / (1 + 7.0e-4 * 25.0))          # 845.21 kg/m^3
    nu25, rho25 = laws.fluid_state("PDMS50", 25.0)
    assert nu25 * 1e6 == pytest.approx(50.0) and rho25 == pytest.approx(960.0)
    nu38, _ = laws.fluid_state("PDMS50", 38.0)
    nu99, _ = laws.fluid_state("PDMS50", 99.0)
    assert 1 - nu99 / nu38 == pytest.approx(0.59, rel=1e-12)          # the data sheet's VTC


# --------------------------------------------------------------------------- effects


def test_effect_laws_by_hand():
    w, nu, rho = 200.0, 1.0e-4, 870.0
    # enclosed disc, regime II: Re = 200 * 0.0254^2 / 1e-4 = 1290.32, G = 5/25.4
    re, g = 200 * 0.0254**2 / 1e-4, 5 / 25.4
    cm = 3.70 * g**0.1 / math.sqrt(re)
    p = laws.enclosed_disc_power(w, nu, rho, 0.0254, 0.010, 0.005)
    assert p == pytest.approx(0.5 * cm * rho * w**3 * (0.0254**5 - 0.010**5), rel=1e-12)
    # regime II holds here: 2 pi / (G Re) = 0.0247 < C_M = 0.0876
    assert cm == pytest.approx(0.0876, rel=1e-3)
    assert laws.enclosed_disc_power(w, nu, rho, 0.0254, 0.010, 0.005, merged=True) == p
    # a 30x more viscous oil, Re = 43.0: regime I (Couette disc) 0.741 > regime II 0.480
    re3 = re / 30
    c1, c2 = 2 * math.pi / (g * re3), 3.70 * g**0.1 / math.sqrt(re3)
    assert (c1, c2) == pytest.approx((0.741, 0.480), rel=2e-3)
    pm = laws.enclosed_disc_power(w, 30 * nu, rho, 0.0254, 0.010, 0.005, merged=True)
    assert pm == pytest.approx(0.5 * c1 * rho * w**3 * (0.0254**5 - 0.010**5), rel=1e-12)
    # Palmgren: nu n = 100 cSt * 1909.86 rpm; M0 = 1e-7 f0 (nu n)^(2/3) 49^3 N mm
    n = 200 * 60 / (2 * math.pi)
    m0 = 1e-7 * 2.0 * (100 * n) ** (2 / 3) * 49.0**3
    assert laws.palmgren_churning_power(w, nu, 0.049, 2.0) == pytest.approx(m0 * 1e-3 * w)
    slow = laws.palmgren_churning_power(1.0, 1e-5, 0.049, 2.0)   # nu n = 95.5 < 2000
    assert slow == pytest.approx(160e-7 * 2.0 * 49.0**3 * 1e-3 * 1.0)
    # seal: Coulomb far above the Stribeck speed, breakaway 1.5 tau_c near rest
    assert laws.stribeck_seal_power(200.0, 0.02) == pytest.approx(0.02 * 200, rel=1e-12)
    assert laws.stribeck_seal_power(-1e-3, 0.02) == pytest.approx(0.03 * 1e-3, rel=1e-6)
    # Taylor excess: zero below Re_c = 41.3 (R/d)^0.5, sqrt(4) - 1 = 1 at 4 Re_c
    rec = 41.3 * math.sqrt(22 / 5)
    assert laws.wendt_taylor_excess(0.99 * rec, 5e-3, 22e-3) == 0.0
    assert laws.wendt_taylor_excess(4 * rec, 5e-3, 22e-3) == pytest.approx(1.0)
    # Carreau n = 0.6 at lambda gamma_dot = 1: 2^-0.2
    assert laws.carreau_ratio(1e4, 1e-4) == pytest.approx(2.0**-0.2)


def test_lag_update_against_oilgap_first_order_lag():
    t = np.linspace(0, 60, 301)
    x = 25 + 10 * np.sin(0.2 * t) + 0.1 * t
    y = np.empty_like(x)
    y[0] = x[0]
    for k in range(len(t) - 1):
        y[k + 1] = laws.lag_update(y[k], x[k], x[k + 1], t[k + 1] - t[k], 4.0)
    assert np.allclose(y, first_order_lag(t, x, 4.0), atol=1e-10)


def test_thermal_node_step_is_the_exact_solution():
    node = laws.ThermalNode()
    T, Q, tau = 25.0, 80.0, 0.25 * 240.0
    for _ in range(120):
        T = node.step(T, Q, 0.5)
    assert T == pytest.approx(25.0 + 0.25 * 80.0 * (1 - math.exp(-60.0 / tau)), rel=1e-12)


def test_baseline_by_hand():
    b = laws.RigBaseline()
    elec, heat = b.power(100.0, 0.0, 20.0)
    gear = 0.1 * 8.0**1.3                     # 8 W of load power: 8^1.3 = 14.929
    copper = 40.0 * 0.08**2                   # 0.256 W at 20 degC
    assert gear == pytest.approx(1.4929, rel=1e-4)
    assert elec == pytest.approx(4.0 + 8.0 + gear + copper, rel=1e-12)
    assert heat == pytest.approx(copper + 0.5 * gear, rel=1e-12)
    hot, _ = b.power(-100.0, 50.0, 45.0)      # reverse, braking J dw/dt, copper +9.8 %
    tau_m = -0.08 + 2e-4 * 50.0
    assert hot == pytest.approx(4.0 + 8.0 + gear + 2e-4 * -100 * 50 +
                                40.0 * (1 + 0.00393 * 25) * tau_m**2, rel=1e-12)


# --------------------------------------------------------------------------- noise, profiles


def test_ar1_noise_variance_and_correlation():
    e = laws.ar1_noise(np.random.default_rng(3), 200_000, 1.5, 0.8)
    assert np.var(e) == pytest.approx(2.25, rel=0.03)
    r1 = np.corrcoef(e[:-1], e[1:])[0, 1]
    assert r1 == pytest.approx(0.8, abs=0.005)
    # what the loop's successive-difference estimator sees: 2 sigma^2 (1 - phi)
    assert np.mean(np.diff(e) ** 2) == pytest.approx(2 * 2.25 * 0.2, rel=0.02)


def test_trapezoid_profile_shape():
    p = SpeedProfile("trapezoid", peak_rpm=3000, period_s=20.0, ramp_s=3.0)  # hold 4 s
    t = np.array([-1.0, 0.0, 1.5, 3.0, 5.0, 8.5, 10.0, 11.5, 15.0, 18.5, 20.0, 25.0])
    w, a = p(t)
    expect_w = W0 * np.array([0, 0, 0.5, 1, 1, 0.5, 0, -0.5, -1, -0.5, 0, 1])
    assert np.allclose(w, expect_w, atol=1e-12)
    expect_a = W0 / 3 * np.array([0, 1, 1, 0, 0, -1, -1, -1, 0, 1, 1, 0])
    assert np.allclose(a, expect_a, atol=1e-12)
    with pytest.raises(InputError):
        SpeedProfile("trapezoid", period_s=10.0, ramp_s=3.0).knots()


def test_step_and_sine_profiles():
    p = SpeedProfile("step", period_s=20.0, ramp_s=0.2, levels=(0.5, -1.0))  # H = 9.9 s
    w, a = p(np.array([0.1, 5.0, 9.95, 10.0, 15.0, 19.9]))
    assert np.allclose(w, W0 * np.array([0.25, 0.5, 0.5 - 0.375, -0.25, -1, -0.5]))
    assert np.allclose(a, W0 * np.array([2.5, 0, -7.5, -7.5, 0, 5]))
    s = SpeedProfile("sine", period_s=20.0)
    w, a = s(np.array([5.0, 10.0]))
    assert np.allclose(w, [W0, 0.0], atol=1e-9)
    assert np.allclose(a, [0.0, -W0 * 2 * math.pi / 20], atol=1e-9)


# --------------------------------------------------------------------------- the rig


def test_format_seed_and_catalogue_names():
    cfg = inject(OutsideConfig(n_samples=50), seal_coulomb_friction=0.02)
    a, b, c = synthesize(cfg, 1), synthesize(cfg, 1), synthesize(cfg, 2)
    assert a.equals(b) and not a.equals(c)
    assert list(a.columns) == ["run", "time_s", "speed_rpm", "temp_C", "oil", "roughness_T",
                               "power_W"]
    assert len(a) == 10 * 50
    data = validate(a)                      # oilgap's reader finds every oil by name
    assert data.n_dropped == 0 and data.kind == "power_W"
    text = a.to_csv()
    assert "seal" not in text and "coulomb" not in text.lower()


def test_oil_runs_follow_eq6_and_oil_free_runs_the_baseline():
    cfg = OutsideConfig(n_samples=60)
    tr = simulate(cfg)
    t = tr["time_s"]
    w, acc = cfg.profile(t)
    for i, (name, oil, T, gap) in enumerate(tr["runs"]):
        if oil is None:
            elec, _ = cfg.baseline.power(w, acc, tr["temp_meas_C"][i])
            assert np.allclose(tr["measured_W"][i], elec, rtol=1e-12), name
            continue
        nu, rho = laws.fluid_state(oil, tr["temp_oil_C"][i])
        r1, r2 = cfg.geometry.region1, cfg.geometry.region2
        p1, _ = laws.annulus_power(w, nu, rho, r1.radius_m, gap, r1.length_m, roughness=(T, 0.5))
        p2, _ = laws.annulus_power(w, nu, rho, r2.radius_m, r2.gap_m, r2.length_m)
        assert np.allclose(tr["viscous_W"][i], p1 + p2, rtol=1e-12), name


def test_sensor_delay_is_a_time_shift():
    base = OutsideConfig(n_samples=80)
    d = 0.4                                  # two samples: the shifted record is on the grid
    clean, late = simulate(base), simulate(inject(base, sensor_delay=d))
    assert np.allclose(late["measured_W"][:, 2:], clean["measured_W"][:, :-2], rtol=1e-12)
    assert np.allclose(late["measured_W"][:, :2], 4.0)   # at rest before t = 0: electronics


def test_thermal_lag_moves_the_oil_temperature_only():
    tr = simulate(inject(OutsideConfig(n_samples=100), thermal_lag=3.0))
    for i in (1, 4):
        lagged = first_order_lag(tr["time_s"], tr["temp_meas_C"][i], 3.0)
        assert np.allclose(tr["temp_oil_C"][i], lagged, atol=1e-9)
        assert tr["temp_oil_C"][i][-1] < tr["temp_meas_C"][i][-1]


def test_shear_thinning_follows_carreau_in_laminar_flow():
    # heavy oil, narrow region 1 at the Couette floor: the power scales with mu exactly
    base = OutsideConfig(oils=("VG680",), roughness=(2.0,), kind="viscous_power_W",
                         n_samples=40, geometry=laws.RigGeometry(
                             "one region", laws.Annulus(0.0254, 0.001, 0.01476)))
    lam = 1.0e-4
    clean, thin = simulate(base), simulate(inject(base, shear_thinning=lam))
    ratio = laws.carreau_ratio(np.abs(clean["omega"][0]) * 25.4, lam)
    moving = np.abs(clean["omega"][0]) > 1.0
    # the temperatures differ slightly (less heat), so compare at the thinned run's state:
    # laminar flow at the Couette floor, P proportional to mu, so P_thin / P = Carreau ratio
    nu, rho = laws.fluid_state("VG680", thin["temp_oil_C"][0])
    p, re = laws.annulus_power(thin["omega"][0], nu, rho, 0.0254, 0.001, 0.01476,
                               roughness=(2.0, 0.5))
    assert np.all(re[moving] < 64)
    assert np.allclose(thin["measured_W"][0][moving] / p[moving], ratio[moving], rtol=1e-12)
    assert np.min(ratio[moving]) == pytest.approx((1 + (lam * W0 * 25.4) ** 2) ** -0.2)  # 0.906
    assert effect_size_W(inject(base, shear_thinning=lam)) > 0.5


def test_oil_inertia_is_stored_not_dissipated():
    base = OutsideConfig(oils=("VG22",), roughness=(4.0,), n_samples=100, sample_interval_s=0.2,
                         kind="viscous_power_W")   # 20 s = one trapezoid period
    tr = simulate(inject(base, oil_inertia=1e-6))
    # t = 1 s on the first ramp: w = w0/3, dw/dt = w0/3 -> rho I_V w0^2 / 9
    rho = laws.fluid_state("VG22", tr["temp_oil_C"][0][5])[1]
    assert tr["effect_W"][0][5] == pytest.approx(rho * 1e-6 * W0 * W0 / 9, rel=1e-12)
    assert np.allclose(tr["temp_oil_C"], simulate(base)["temp_oil_C"], rtol=0, atol=0)


def test_gaps_silicone_and_steady_points(tmp_path):
    cfg = OutsideConfig(oils=("PDMS10", "VG22"), roughness=(1.0,), gaps_mm=(0.5, 1.0),
                        n_samples=30)
    df = synthesize(cfg, 0)
    assert {"gap_mm", "nu_cSt", "density_kg_m3"} <= set(df.columns)
    pd_rows = df[df["oil"] == "PDMS10"]
    nu, rho = laws.fluid_state("PDMS10", pd_rows["temp_C"].to_numpy())
    assert np.allclose(pd_rows["nu_cSt"], nu * 1e6) and np.allclose(pd_rows["density_kg_m3"], rho)
    assert df.loc[df["oil"] == "VG22", "nu_cSt"].isna().all()
    assert sorted(df.loc[df["oil"] != "none", "gap_mm"].unique()) == [0.5, 1.0]
    assert validate(df).n_dropped == 0
    write_data_csv(df, tmp_path / "rig.csv")
    assert len(pd.read_csv(tmp_path / "rig.csv")) == len(df)
    st = steady_points(replace(NEWTONIAN, noise_power_W=0.0), speeds_rpm=(1000.0,),
                       temps_C=(25.0,))
    assert "time_s" not in st.columns and len(st) == 3
    R, d, L = 0.040, 0.0006, 0.030
    w = 1000 * 2 * math.pi / 60
    nu, rho = laws.fluid_state("PDMS50", 25.0)
    expect, _ = laws.annulus_power(w, nu, rho, R, d, L)
    assert st.loc[st["oil"] == "PDMS50", "viscous_power_W"].item() == pytest.approx(expect)


@pytest.mark.parametrize("bad", [dict(oils=("VG9999",)), dict(roughness=(0.5,)),
                                 dict(kind="torque"), dict(effects={"warp_drive": 1.0}),
                                 dict(effects={"sensor_delay": float("nan")}),
                                 dict(profile=SpeedProfile("zigzag")), dict(n_samples=5),
                                 dict(geometry=laws.OPEN_GEOMETRY,
                                      effects={"bearing_ball_churning": 1.0})])
def test_bad_configuration(bad):
    with pytest.raises(InputError):
        OutsideConfig(**bad)
