"""Stage 2, the forward model: Eq. 8 per region and each effect term, checked by hand."""

from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.oils import get_oil
from oilgap.model.units import ZERO_CELSIUS_K
from oilgap.model.viscous_loss import clearance_power
from oilgap.optim.calibration import ForwardModel


def _by_hand(s, case, law, nu=None, rho=None):
    """Region 1 (R = T2, delta = T3 - T2, sample T) + region 2 (T = 1) with clearance_power."""
    nu = s.nu_m2_s if nu is None else nu
    rho = s.density_kg_m3 if rho is None else rho
    r1, r2 = case.region1, case.region2
    p1 = clearance_power(s.omega, nu, rho, r1.T2, r1.T3 - r1.T2, r1.length, law, s.roughness_T)
    p2 = clearance_power(s.omega, nu, rho, r2.radius, r2.gap, r2.length, law, 1.0)
    return p1, p2


def _eq8(s, R, gap, L, law, T):
    """Eq. 5 with the power law of Eq. 8 written out: 0.5 pi C_m rho |w|^3 R^4 L."""
    re = np.abs(s.omega) * R * gap / s.nu_m2_s
    cm = law.C * (gap / R) ** law.alpha * re ** law.beta * T ** law.gamma
    return 0.5 * np.pi * cm * s.density_kg_m3 * np.abs(s.omega) ** 3 * R ** 4 * L


def test_power_is_the_sum_of_the_two_regions(rig):
    s, case = rig.samples, rig.case
    m = ForwardModel(s, case, rig.oils)
    p1, p2 = _by_hand(s, case, rig.law)
    assert np.allclose(m.power(rig.law), p1 + p2, rtol=1e-13, atol=0)
    assert np.allclose(m.base_power(rig.law), p1 + p2, rtol=1e-13, atol=0)
    r1, r2 = case.region1, case.region2
    assert np.allclose(p1, _eq8(s, r1.radius, r1.gap, r1.length, rig.law, s.roughness_T),
                       rtol=1e-12)
    assert np.allclose(p2, _eq8(s, r2.radius, r2.gap, r2.length, rig.law, 1.0), rtol=1e-12)


def test_geometry_comes_from_the_case(rig):
    m = ForwardModel(rig.samples, rig.case, rig.oils)
    r1, r2 = rig.case.region1, rig.case.region2
    g = m.geometry
    assert g.bearing_pitch_diameter_m == pytest.approx(2 * r2.radius + r2.gap, rel=1e-15)
    assert g.disc_radii_m == (r1.radius, rig.case.motor.shaft_bore_radius)
    assert np.array_equal(g.regions[0].roughness_T, rig.samples.roughness_T)
    assert g.regions[1].roughness_T == 1.0


def test_additive_effects_add_their_library_term(rig):
    s = rig.samples
    m = ForwardModel(s, rig.case, rig.oils)
    p0 = m.power(rig.law)
    tau, i_v = 0.03, 2e-7
    seal = m.power(rig.law, {"seal_coulomb_friction": tau}) - p0
    assert np.allclose(seal, tau * np.abs(s.omega), rtol=1e-9, atol=1e-12)
    inertia = m.power(rig.law, {"oil_inertia": i_v}) - p0
    assert np.allclose(inertia, s.density_kg_m3 * i_v * s.omega * s.domega_dt, rtol=1e-7,
                       atol=1e-12)


def test_shear_thinning_scales_each_region_by_the_cross_ratio(rig):
    s, case = rig.samples, rig.case
    m = ForwardModel(s, case, rig.oils)
    lam2 = 1e-8
    p1, p2 = _by_hand(s, case, rig.law)
    g1 = np.abs(s.omega) * case.region1.radius / case.region1.gap
    g2 = np.abs(s.omega) * case.region2.radius / case.region2.gap
    want = p1 / (1 + lam2 * g1 ** 2) + p2 / (1 + lam2 * g2 ** 2)
    assert np.allclose(m.power(rig.law, {"shear_thinning": lam2}), want, rtol=1e-12)


def test_shear_thinning_enters_the_reynolds_number_of_a_turbulent_law(rig):
    # P = C Re^beta rho w^3 R^4 L ... with Re = w R delta / nu: thinning nu -> q nu (Cross
    # q = 1/(1 + lambda^2 g^2)) multiplies P by q^-beta = q^0.5 at beta = -0.5, not by q
    s, case = rig.samples, rig.case
    law = replace(rig.law, beta=-0.5)
    m = ForwardModel(s, case, rig.oils)
    lam2 = 1e-8
    p1, p2 = _by_hand(s, case, law)
    q1 = 1 / (1 + lam2 * (np.abs(s.omega) * case.region1.radius / case.region1.gap) ** 2)
    q2 = 1 / (1 + lam2 * (np.abs(s.omega) * case.region2.radius / case.region2.gap) ** 2)
    assert np.allclose(m.power(law, {"shear_thinning": lam2}), p1 * q1 ** 0.5 + p2 * q2 ** 0.5,
                       rtol=1e-12)


def test_sensor_delay_of_one_sample_shifts_each_run_by_one_sample(rig):
    s = rig.samples
    m = ForwardModel(s, rig.case, rig.oils)
    p0 = m.power(rig.law)
    dt = s.time_s[1] - s.time_s[0]
    p = m.power(rig.law, {"sensor_delay": dt})
    for c in range(len(s.run_names)):
        i = np.nonzero(s.run_code == c)[0]
        assert p[i[0]] == pytest.approx(p0[i[0]], rel=1e-12)  # held at the first sample
        assert np.allclose(p[i[1:]], p0[i[:-1]], rtol=1e-9)


def test_leading_oil_temperature_moves_the_viscosity(rig):
    # tau < 0: the gap oil leads the sensor by -tau dT/dt; nu and rho from the oil's laws
    s, case = rig.samples, rig.case
    m = ForwardModel(s, case, rig.oils)
    tau = -4.0
    temp = s.temp_C - tau * s.dtemp_dt
    nu, rho = np.empty(s.n), np.empty(s.n)
    for oil in set(s.oil):
        k = s.oil == oil
        nu[k], _, rho[k] = get_oil(oil).properties(temp[k] + ZERO_CELSIUS_K, 0.0)
    p1, p2 = _by_hand(s, case, rig.law, nu, rho)
    assert np.allclose(m.power(rig.law, {"thermal_lag": tau}), p1 + p2, rtol=1e-10)


def test_lagging_oil_temperature_follows_a_ramp_tau_behind(rig):
    s = rig.samples
    m = ForwardModel(s, rig.case, rig.oils)
    tau = 2.0
    lag = m.lagged_temperature(tau)
    late = s.time_s > 10 * tau  # transient e^-10 gone: y = x - rate tau on a ramp
    assert np.allclose(lag[late], (s.temp_C - s.dtemp_dt * tau)[late], atol=1e-4)


def test_derivatives_of_the_context(rig):
    # power law: P ~ |w|^(3 + beta), so dP/dw = (3 + beta) P / w; dP/dT from nu(T), rho(T)
    s = rig.samples
    m = ForwardModel(s, rig.case, rig.oils)
    ctx = m.context(rig.law)
    p = m.base_power(rig.law)
    h = 0.5
    nu_p, rho_p, nu_m, rho_m = (np.empty(s.n) for _ in range(4))
    for oil in set(s.oil):
        k = s.oil == oil
        tk = s.temp_C[k] + ZERO_CELSIUS_K
        nu_p[k], _, rho_p[k] = get_oil(oil).properties(tk + h, 0.0)
        nu_m[k], _, rho_m[k] = get_oil(oil).properties(tk - h, 0.0)
    dP_dT = (sum(_by_hand(s, rig.case, rig.law, nu_p, rho_p))
             - sum(_by_hand(s, rig.case, rig.law, nu_m, rho_m))) / (2 * h)
    assert np.allclose(ctx.dpower_dtemp_W_K, dP_dT, rtol=1e-9)
    dP_dw = (3 + rig.law.beta) * p / s.omega
    want = dP_dw * s.domega_dt + dP_dT * s.dtemp_dt
    assert np.allclose(ctx.dpower_dt_W_s, want, rtol=1e-6, atol=1e-9 * np.abs(want).max())
    assert np.allclose(ctx.power_W, p, rtol=1e-13)


def test_subset_predicts_the_same_runs(rig):
    s = rig.samples
    m = ForwardModel(s, rig.case, rig.oils)
    coefs = {"seal_coulomb_friction": 0.02, "thermal_lag": 3.0, "sensor_delay": 0.3}
    full = m.power(rig.law, coefs)
    keep = s.run_code != 1
    sub = m.subset(keep)
    assert sub.samples.n == keep.sum() and sub.geometry.regions[0].gap_m.shape == (keep.sum(),)
    assert np.allclose(sub.power(rig.law, coefs), full[keep], rtol=1e-13)
