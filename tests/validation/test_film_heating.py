"""The film-heating closed form (oilgap.model.film_heating) against an independent
numerical solution of the same two-point problem, hand calculations and limits.

The numerical solution is written here, dimensionally: a plane film of gap h, stator at
y = 0 (u = 0, T = T0), rotor at y = h (u = U; T = T0 or dT/dy = 0), with
mu(T) = mu0 exp(-b (T - T0)) and unknowns the nodal temperatures and the uniform shear
stress tau:

    momentum   d/dy(mu du/dy) = 0          -> tau uniform, U = int_0^h tau/mu(T) dy
    energy     k T'' + tau^2/mu(T) = 0

Second-order central differences (ghost node at an insulated rotor), trapezoid rule
for the speed, Newton with the exact Jacobian and continuation in U^2, three grids
(N, 2N, 4N) and Richardson extrapolation (errors in even powers of the spacing).
"""

import math

import casadi as ca
import numpy as np
import pytest

from oilgap.model import film_heating as fh
from oilgap.model import oil_properties as op
from oilgap.model.errors import InputError
from oilgap.model.io.case_io import seed_case
from oilgap.model.units import celsius_to_kelvin

MU0, K, B, H = 0.26, 0.13, 0.05, 1.0e-3      # Pa s, W/(m K), 1/K, m
NAS = (0.1, 1.0, 4.5, 9.0, 30.0)


def _newton(U, walls, n, dT, tau):
    """Newton on (T_i - T0, tau) for one speed; returns tau and the full profile [K]."""
    d = H / n
    iso = walls == "isothermal-walls"
    m_ = n - 1 if iso else n                      # unknown nodes 1..m_
    wts = np.full(n + 1, d)
    wts[[0, -1]] = d / 2
    lap = (np.diag(np.full(m_, -2.0)) + np.diag(np.ones(m_ - 1), 1)
           + np.diag(np.ones(m_ - 1), -1)) * K / d ** 2
    if not iso:
        lap[-1, -2] = 2.0 * K / d ** 2            # ghost node T_{n+1} = T_{n-1}
    for _ in range(50):
        full = np.zeros(n + 1)
        full[1:m_ + 1] = dT
        fluidity = np.exp(B * full) / MU0         # 1/mu
        f = fluidity[1:m_ + 1]
        res = np.append(lap @ dT + tau ** 2 * f, tau * (wts @ fluidity) - U)
        jac = np.zeros((m_ + 1, m_ + 1))
        jac[:m_, :m_] = lap + np.diag(tau ** 2 * B * f)
        jac[:m_, m_] = 2.0 * tau * f
        jac[m_, :m_] = tau * wts[1:m_ + 1] * B * f
        jac[m_, m_] = wts @ fluidity
        step = np.linalg.solve(jac, -res)
        dT, tau = dT + step[:m_], tau + step[m_]
        # quadratic convergence: after a step below 1e-10 the error is ~1e-20
        if np.max(np.abs(step[:m_])) < 1e-10 * (1.0 + np.max(np.abs(dT))) \
                and abs(step[m_]) < 1e-10 * tau:
            full = np.zeros(n + 1)
            full[1:m_ + 1] = dT
            return tau, full
    raise AssertionError("Newton did not converge")


def _solve(nahme, walls, n):
    """tau [Pa], profile [K] at Na, by continuation in U^2 from a cold film."""
    m_ = n - 1 if walls == "isothermal-walls" else n
    dT, tau = np.zeros(m_), 0.0
    steps = [nahme * 0.5 ** j for j in range(int(math.ceil(math.log2(max(nahme, 1.0)))), -1, -1)]
    for na in steps:
        U = math.sqrt(na * K / (B * MU0))
        tau, full = _newton(U, walls, n, dT, tau if tau else MU0 * U / H)
        dT = full[1:m_ + 1]
    return tau, full, U


def _richardson(f1, f2, f4):
    """Eliminate the h^2 and h^4 error terms of three results on grids N, 2N, 4N."""
    g1, g2 = (4.0 * f2 - f1) / 3.0, (4.0 * f4 - f2) / 3.0
    return (16.0 * g2 - g1) / 15.0


def _fd_film(nahme, walls, n=64):
    """Richardson-extrapolated Phi, peak rise [K], heat to stator and rotor / (tau U)."""
    out = []
    for k in (n, 2 * n, 4 * n):
        tau, T, U = _solve(nahme, walls, k)
        d = H / k
        q_stator = K * (-3.0 * T[0] + 4.0 * T[1] - T[2]) / (2.0 * d)   # k dT/dy(0): into stator
        q_rotor = K * (-3.0 * T[-1] + 4.0 * T[-2] - T[-3]) / (2.0 * d)  # into rotor
        out.append(np.array([tau / (MU0 * U / H), T.max(), q_stator / (tau * U),
                             q_rotor / (tau * U)]))
    return _richardson(*out)


@pytest.fixture(scope="module")
def fd_results():
    return {(w, na): _fd_film(na, w) for w in fh.WALL_CONDITIONS for na in NAS}


@pytest.mark.parametrize("walls", fh.WALL_CONDITIONS)
@pytest.mark.parametrize("nahme", NAS)
def test_closed_form_against_finite_differences(fd_results, nahme, walls):
    phi_fd, rise_fd, _, _ = fd_results[(walls, nahme)]
    assert fh.film_factor(nahme, walls) == pytest.approx(phi_fd, rel=1e-6)
    assert fh.film_temperature_rise(nahme, B, walls) == pytest.approx(rise_fd, rel=1e-6)


@pytest.mark.parametrize("walls,split", [("isothermal-walls", (0.5, 0.5)),
                                         ("adiabatic-rotor", (1.0, 0.0))])
@pytest.mark.parametrize("nahme", (1.0, 9.0, 30.0))
def test_energy_balance_shear_work_leaves_through_the_walls(fd_results, nahme, walls, split):
    # tau U = heat conducted into stator + rotor; symmetric theta -> half each with both
    # walls isothermal (although u(y) is not symmetric), all to the stator otherwise.
    _, _, to_stator, to_rotor = fd_results[(walls, nahme)]
    assert to_stator + to_rotor == pytest.approx(1.0, abs=1e-6)
    assert (to_stator, to_rotor) == pytest.approx(split, abs=1e-6)


def test_hand_values_at_na_4_5():
    # isothermal: sinh^2 a = 4.5/8 -> sinh a = 0.75, cosh a = 1.25, a = ln 2
    # (the shifted evaluation in film_factor is exact to <= 1e-11)
    assert fh.film_factor(4.5) == pytest.approx(math.log(2.0) / (0.75 * 1.25), abs=1e-11)
    # adiabatic rotor: sinh a = 1.5, cosh a = sqrt(3.25), a = ln(1.5 + sqrt(3.25))
    c = math.sqrt(3.25)
    assert fh.film_factor(4.5, "adiabatic-rotor") == pytest.approx(
        math.log(1.5 + c) / (1.5 * c), abs=1e-11)
    # peak rise 2 ln cosh a / b: isothermal 2 ln 1.25 / b
    assert fh.film_temperature_rise(4.5, B) == pytest.approx(2 * math.log(1.25) / B, rel=1e-14)


@pytest.mark.parametrize("walls,c1,c2,c3", [("isothermal-walls", 1 / 12, 1 / 120, 1 / 2240),
                                            ("adiabatic-rotor", 1 / 3, 2 / 15, 2 / 35)])
def test_small_nahme_limit(walls, c1, c2, c3):
    # first order: 1 - Phi = mean film rise * b = Na/12 (isothermal) or Na/3 (insulated)
    for na in (1e-3, 1e-2):
        phi = fh.film_factor(na, walls)
        assert (1.0 - phi) / na == pytest.approx(c1, rel=2 * c2 / c1 * na)
        # series of acosh(1+z)/sqrt(z(2+z)) = 1 - z/3 + 2z^2/15 - 2z^3/35 + ...
        assert phi == pytest.approx(1.0 - c1 * na + c2 * na ** 2 - c3 * na ** 3, abs=1e-9)
    # small-Na peak rise: mu U^2/(8k) (Bird-Stewart-Lightfoot 10.4) or mu U^2/(2k)
    U = 0.1
    na = fh.nahme_number(B, MU0, U, K)
    expect = MU0 * U ** 2 / K / (8.0 if walls == "isothermal-walls" else 2.0)
    assert fh.film_temperature_rise(na, B, walls) == pytest.approx(expect, rel=1e-3)


def test_exact_to_1e_9_over_the_whole_range():
    # against the (a, sinh a) form evaluated where it is well conditioned (Na >= 1e-3)
    nas = np.geomspace(1e-3, 1e4, 200)
    for walls, div in (("isothermal-walls", 8.0), ("adiabatic-rotor", 2.0)):
        a = np.arcsinh(np.sqrt(nas / div))
        assert np.max(np.abs(fh.film_factor(nas, walls) - a / (np.sinh(a) * np.cosh(a)))) < 1e-9
    assert abs(fh.film_factor(0.0) - 1.0) < 1e-10


@pytest.mark.parametrize("walls,slope0", [("isothermal-walls", -1 / 12),
                                          ("adiabatic-rotor", -1 / 3)])
@pytest.mark.parametrize("nahme", (0.0, 4.5))
def test_casadi_value_and_gradient(nahme, walls, slope0):
    x = ca.SX.sym("na")
    phi = fh.film_factor(x, walls)
    f = ca.Function("f", [x], [phi, ca.gradient(phi, x)])
    val, grad = (float(v) for v in f(nahme))
    assert np.isfinite(grad)
    assert val == pytest.approx(float(fh.film_factor(nahme, walls)), abs=1e-15)
    h = 1e-5
    fd = (fh.film_factor(nahme + h, walls) - fh.film_factor(nahme - h, walls)) / (2 * h)
    assert grad == pytest.approx(fd, rel=1e-7)
    if nahme == 0.0:
        assert grad == pytest.approx(slope0, rel=1e-9)
    # the rise and Na are CasADi-safe too
    bsym = ca.SX.sym("b")
    rise = ca.Function("r", [x, bsym], [fh.film_temperature_rise(x, bsym, walls)])
    assert float(rise(nahme, B)) == pytest.approx(fh.film_temperature_rise(nahme, B, walls))


def test_seed_rated_point():
    # VG22, 2 degC, 3000 m, rotor 25.4 mm at 3000 rpm peak (sine cycle), k = 0.13
    case = seed_case()
    temp_K = celsius_to_kelvin(case.operating.oil_temp_C)
    p = op.seawater_gauge_pressure(case.operating.depth_m)
    _, mu, _ = case.oil.properties(temp_K, p)
    b = case.oil.temperature_slope(temp_K, p)
    w = case.duty_cycle.sample_weights()
    omega = case.duty_cycle.omega_rad_s
    R = case.region1.radius
    peak = case.duty_cycle.peak_omega_rad_s * R
    rms = math.sqrt(float(w @ omega ** 2)) * R
    assert peak == pytest.approx(7.98, abs=0.01)
    assert rms == pytest.approx(peak / math.sqrt(2.0), rel=1e-3)
    k = fh.MINERAL_OIL_CONDUCTIVITY_W_MK
    assert mu == pytest.approx(0.26, abs=0.01)
    na_peak = fh.nahme_number(b, mu, peak, k)
    assert na_peak == pytest.approx(9.0, abs=0.5)
    na_rms = fh.nahme_number(b, mu, rms, k)
    assert fh.film_factor(na_rms) == pytest.approx(0.74, abs=0.01)
    assert fh.film_factor(na_rms, "adiabatic-rotor") == pytest.approx(0.44, abs=0.01)
    # laminar: Re = U delta / nu ~ 27, far below Taylor onset (Ta = Re sqrt(delta/R) = 41.3)
    nu = mu / case.oil.properties(temp_K, p)[2]
    assert peak * case.region1.gap / nu < 41.3 * math.sqrt(R / case.region1.gap) / 5


def test_curvature_correction_matches_the_circular_first_order_coefficient():
    # O(Na) coefficient of the circular film (inner rotor), kappa = R2/R1:
    # isothermal: c1 = k^2[(k^2+1) ln k - (k^2-1)]/[2 (k^2-1)^2 ln k] -> 1/12 as k -> 1
    # adiabatic:  c1 = [4k^6 ln k - 3k^6 + 4k^4 - k^2]/[2 (k^2-1)^3] -> 1/3
    for eps in (0.01, 0.04):
        kap = 1.0 + eps
        lk, k2 = math.log(kap), kap ** 2
        c_iso = k2 * ((k2 + 1) * lk - (k2 - 1)) / (2 * (k2 - 1) ** 2 * lk) * 12
        c_ad = (4 * k2 ** 3 * lk - 3 * k2 ** 3 + 4 * k2 ** 2 - k2) / (2 * (k2 - 1) ** 3) * 3
        assert fh.curvature_corrected_nahme(1.0, eps) == pytest.approx(c_iso, abs=0.3 * eps ** 2)
        assert fh.curvature_corrected_nahme(1.0, eps, "adiabatic-rotor") == pytest.approx(
            c_ad, abs=0.3 * eps ** 2)


@pytest.mark.parametrize("walls", fh.WALL_CONDITIONS)
def test_film_time_constant_is_the_slowest_discrete_mode(walls):
    # smallest eigenvalue of -alpha d^2/dy^2 on the film (Dirichlet at the stator;
    # Dirichlet or Neumann at the rotor), second-order FD on 400 cells
    n, d = 400, H / 400
    m_ = n - 1 if walls == "isothermal-walls" else n
    A = (np.diag(np.full(m_, 2.0)) - np.diag(np.ones(m_ - 1), 1) - np.diag(np.ones(m_ - 1), -1))
    if walls != "isothermal-walls":
        A[-1, -2] = -2.0
    lam = np.min(np.linalg.eigvals(A).real) / d ** 2
    alpha = fh.MINERAL_OIL_DIFFUSIVITY_M2_S
    assert fh.film_time_constant_s(H, alpha, walls) == pytest.approx(1.0 / (alpha * lam),
                                                                      rel=1e-4)
    # hand value: 1 mm, 8.1e-8 m^2/s -> 1e-6/(9.8696 * 8.1e-8) = 1.2509 s (x4 insulated)
    assert fh.film_time_constant_s(H) == pytest.approx(1.2509, abs=1e-4)


def test_properties_from_cragoe():
    # k = 0.1167/d (1 - 0.00054 t), c_p = (1.685 + 0.00339 t)/sqrt(d) kJ/(kg K); d = 0.87
    d = 0.87
    assert fh.MINERAL_OIL_CONDUCTIVITY_W_MK == pytest.approx(0.1167 / d * (1 - 0.00054 * 20),
                                                             abs=0.005)
    cp = (1.685 + 0.00339 * 20) / math.sqrt(d) * 1e3
    k20 = 0.1167 / d * (1 - 0.00054 * 20)
    assert fh.MINERAL_OIL_DIFFUSIVITY_M2_S == pytest.approx(k20 / (870.0 * cp), rel=0.02)


def test_unknown_wall_condition_is_an_input_error():
    with pytest.raises(InputError, match="walls"):
        fh.film_factor(1.0, "hot-rotor")
    with pytest.raises(InputError, match="walls"):
        fh.film_time_constant_s(H, walls="hot-rotor")
