"""oilgap.model.film_cycle piece by piece: the heating spectrum against Fourier series
written out by hand, the Taylor fade, the factor of a constant speed by hand, and the
CasADi forms against the numpy ones and central differences. (The cycle-mean factor
against a transient finite-difference film: tests/validation/test_film_cycle.py.)"""

import math

import casadi as ca
import numpy as np
import pytest

from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.film_cycle import (
    LAMINAR_FADE_WIDTH,
    FilmHeating,
    cycle_gain,
    film_factors,
    film_heating_for,
    heating_spectrum,
    laminar_weight,
)
from oilgap.model.film_heating import film_factor, film_time_constant_s
from oilgap.model.regions import region_mean_power, rotor_stator_region
from oilgap.model.skin_friction import FrictionLaw

PERIOD = 20.0
W0 = 2.0 * math.pi / PERIOD        # fundamental [rad/s]


def one_period(n=400):
    return PERIOD * np.arange(n) / n


# --------------------------------------------------------------------------- spectrum


def test_a_sine_speed_heats_at_twice_its_frequency_only():
    # omega = W sin(w0 t): omega^2 = W^2/2 (1 - cos 2 w0 t), one line at 2 w0
    t = one_period()
    freqs, weights = heating_spectrum(t, 300.0 * np.sin(W0 * t))
    np.testing.assert_allclose(freqs, [2.0 * W0], rtol=1e-14)
    np.testing.assert_allclose(weights, [1.0], rtol=1e-14)
    # the seed's cycle: 15 periods of a 0.05 Hz sine in 300 s, the same line at 4 pi/20 s
    seed = DutyCycle.sine()
    freqs, weights = heating_spectrum(seed.time_s, seed.omega_rad_s)
    np.testing.assert_allclose(freqs, [4.0 * math.pi * 0.05], rtol=1e-14)
    np.testing.assert_allclose(weights, [1.0], rtol=1e-14)


def test_a_constant_speed_has_no_heating_spectrum_and_gain_one():
    t = one_period()
    for omega in (np.full(t.size, 250.0), np.full(t.size, -80.0), np.zeros(t.size)):
        freqs, weights = heating_spectrum(t, omega)
        assert freqs.size == 0 and weights.size == 0
        assert cycle_gain(1.3, freqs, weights) == 1.0
    # a sign change at constant |omega| does not heat unevenly either
    freqs, _ = heating_spectrum(t, 250.0 * np.sign(np.sin(W0 * t) + 1e-9))
    assert freqs.size == 0


def test_two_tone_speed_gives_the_variance_fractions_by_hand():
    # omega = a cos(3 w0 t) + b cos(5 w0 t), a = 1, b = 2 (times 100 rad/s):
    # omega^2 = (a^2 + b^2)/2 + a^2/2 cos 6w0t + b^2/2 cos 10w0t + ab cos 8w0t + ab cos 2w0t
    # Parseval: var = sum c_k^2/2 = a^4/8 + b^4/8 + a^2 b^2/2 + a^2 b^2/2 = 0.125 + 2 + 2 + 2
    t = one_period()
    a, b = 1.0, 2.0
    freqs, weights = heating_spectrum(t, 100.0 * (a * np.cos(3 * W0 * t)
                                                  + b * np.cos(5 * W0 * t)))
    np.testing.assert_allclose(freqs, W0 * np.array([2.0, 6.0, 8.0, 10.0]), rtol=1e-13)
    np.testing.assert_allclose(weights, np.array([2.0, 0.125, 2.0, 2.0]) / 6.125, rtol=1e-12)
    # and the in-phase gain of a lag of t1 on it, term by term
    t1 = 1.3
    hand = sum(p / (1.0 + (k * W0 * t1) ** 2)
               for k, p in ((2, 2 / 6.125), (6, 0.125 / 6.125), (8, 2 / 6.125),
                            (10, 2 / 6.125)))
    assert cycle_gain(t1, freqs, weights) == pytest.approx(hand, rel=1e-12)


def test_offset_speed_variance_fractions_by_hand():
    # omega = A + B cos(w0 t): omega^2 - mean = 2AB cos w0t + B^2/2 cos 2w0t,
    # var = 2 A^2 B^2 + B^4/8: fractions 16 A^2/(16 A^2 + B^2), B^2/(16 A^2 + B^2) = 0.8, 0.2
    t = one_period()
    freqs, weights = heating_spectrum(t, 50.0 * (1.0 + 2.0 * np.cos(W0 * t)))
    np.testing.assert_allclose(freqs, [W0, 2.0 * W0], rtol=1e-13)
    np.testing.assert_allclose(weights, [0.8, 0.2], rtol=1e-12)


def test_non_uniform_sampling_is_resampled_not_miscounted():
    # the first fifth of the period sampled twice as densely: the samples are not equally
    # spaced in time, so a plain FFT of them is wrong; resampled on the median interval
    # (the coarse one, whose grid holds every original coarse sample) it is exact
    t = one_period(400)
    dense = np.union1d(t, t[:80] + 0.5 * (t[1] - t[0]))
    omega = lambda tt: 50.0 * (1.0 + 2.0 * np.cos(W0 * tt))  # noqa: E731
    freqs, weights = heating_spectrum(dense, omega(dense))
    np.testing.assert_allclose(freqs, [W0, 2.0 * W0], rtol=1e-13)
    np.testing.assert_allclose(weights, [0.8, 0.2], rtol=1e-12)
    naive = np.abs(np.fft.rfft(omega(dense) ** 2 - np.mean(omega(dense) ** 2))) ** 2
    assert np.sort(naive)[-3] / naive.sum() > 1e-3  # the plain FFT smears the lines
    # jittered sample times (+-20 % of the interval): the lines stay within the
    # resampling error of a linear interpolant
    rng = np.random.default_rng(1)
    jit = t + (t[1] - t[0]) * rng.uniform(-0.2, 0.2, t.size)
    jit[0], jit[-1] = t[0], t[-1]
    freqs, weights = heating_spectrum(jit, omega(jit))
    np.testing.assert_allclose(freqs[:2], [W0, 2.0 * W0], rtol=2e-3)
    np.testing.assert_allclose(weights[:2], [0.8, 0.2], atol=1e-3)


# --------------------------------------------------------------------------- Taylor fade


def test_laminar_weight_fades_across_taylor_onset():
    ta_c = 41.3
    assert laminar_weight(ta_c) == pytest.approx(0.5, abs=1e-15)
    assert laminar_weight(0.3 * ta_c) > 1.0 - 1e-5     # 1 - 1/(1 + 0.3^-10) = 1 - 6e-6
    assert laminar_weight(3.0 * ta_c) < 1e-4           # 1/(1 + 3^10) = 1.7e-5
    assert laminar_weight(0.0) == pytest.approx(1.0, abs=1e-15)
    # one width above onset: 1 - 1/(1 + e^-1)
    x = ta_c * math.exp(LAMINAR_FADE_WIDTH)
    assert laminar_weight(x) == pytest.approx(1.0 - 1.0 / (1.0 + math.exp(-1.0)), rel=1e-12)
    ta = np.geomspace(1.0, 1e3, 50)
    assert np.all(np.diff(laminar_weight(ta)) < 0)


# --------------------------------------------------------------------------- film factors

R, DELTA, NU, RHO, BETA = 0.0254, 1.0e-3, 3.0e-4, 860.0, 0.073   # m, m, m^2/s, kg/m^3, 1/K


def test_constant_speed_factor_by_hand():
    omega = 314.159
    film = FilmHeating("isothermal-walls", 0.13)
    # Na = b mu (omega R)^2 / k, times (1 + delta/R) for the curved film
    na = BETA * NU * RHO * (omega * R) ** 2 / 0.13 * (1.0 + DELTA / R)
    # Re = omega R delta / nu = 26.6, Ta = Re sqrt(delta/R) = 5.28: laminar
    ta = omega * R * DELTA / NU * math.sqrt(DELTA / R)
    s = 1.0 - 1.0 / (1.0 + math.exp(-math.log(ta / 41.3) / LAMINAR_FADE_WIDTH))
    hand = 1.0 - s * (1.0 - float(film_factor(na)))
    got = film_factors(np.array([omega]), np.array([1.0]), R, DELTA, NU, RHO, BETA, film)
    assert got[0] == pytest.approx(hand, rel=1e-13)
    assert hand == pytest.approx(float(film_factor(na)), rel=1e-8)  # s = 1 - 4e-9
    # a constant-speed cycle has no spectrum; any spectrum leaves a single node unchanged
    cycle = DutyCycle(one_period(), np.full(400, omega))
    nodes, w = cycle.speed_distribution()
    lagged = FilmHeating("isothermal-walls", 0.13, 8.1e-8, (0.6,), (1.0,))
    for f in (film_heating_for(cycle), lagged):
        np.testing.assert_allclose(film_factors(nodes, w, R, DELTA, NU, RHO, BETA, f),
                                   [hand], rtol=1e-13)


def test_adiabatic_rotor_constant_speed_by_hand():
    omega = 100.0
    film = FilmHeating("adiabatic-rotor", 0.14)
    na = BETA * NU * RHO * (omega * R) ** 2 / 0.14 * (1.0 + 1.5 * DELTA / R)
    phi = math.acosh(1.0 + na) / math.sqrt(na * (2.0 + na))   # the closed form, z = Na
    got = film_factors(np.array([omega]), np.array([1.0]), R, DELTA, NU, RHO, BETA, film)
    assert got[0] == pytest.approx(phi, rel=1e-8)


def test_two_speed_cycle_lagged_by_hand():
    # nodes omega_1, omega_2 with weights 0.25, 0.75 and one heating line at w:
    # g = 1/(1 + (w t1)^2), Na_eff,i = <Na> + g (Na_i - <Na>)
    nodes, w = np.array([50.0, 200.0]), np.array([0.25, 0.75])
    film = FilmHeating("isothermal-walls", 0.13, 8.1e-8, (0.5,), (1.0,))
    t1 = DELTA ** 2 / (math.pi ** 2 * 8.1e-8)
    g = 1.0 / (1.0 + (0.5 * t1) ** 2)
    na = BETA * NU * RHO * (nodes * R) ** 2 / 0.13 * (1.0 + DELTA / R)
    eff = na @ w + g * (na - na @ w)
    ta = nodes * R * DELTA / NU * math.sqrt(DELTA / R)
    s = 1.0 - 1.0 / (1.0 + (ta / 41.3) ** (-1.0 / LAMINAR_FADE_WIDTH))
    hand = 1.0 - s * (1.0 - film_factor(eff))
    np.testing.assert_allclose(film_factors(nodes, w, R, DELTA, NU, RHO, BETA, film), hand,
                               rtol=1e-13)
    assert t1 == pytest.approx(film_time_constant_s(DELTA, 8.1e-8), rel=1e-15)


# --------------------------------------------------------------------------- CasADi


def _central_gradient(f, x, rel=1e-6):
    g = np.empty(x.size)
    for i in range(x.size):
        h = rel * abs(x[i])
        up, dn = x.copy(), x.copy()
        up[i] += h
        dn[i] -= h
        g[i] = (f(up) - f(dn)) / (2.0 * h)
    return g


NODES = np.array([40.0, 120.0, 250.0, 314.0])
WEIGHTS = np.array([0.1, 0.2, 0.3, 0.4])
FILM = FilmHeating("isothermal-walls", 0.13, 8.1e-8, (0.63, 1.26), (0.7, 0.3))
X0 = np.array([R, DELTA, NU, RHO, BETA])


def test_film_factors_in_casadi_match_numpy_and_differences():
    x = ca.SX.sym("x", 5)
    expr = film_factors(ca.DM(NODES), WEIGHTS, x[0], x[1], x[2], x[3], x[4], FILM)
    f = ca.Function("f", [x], [expr, ca.jacobian(ca.dot(ca.DM(WEIGHTS), expr), x)])
    val, grad = (np.asarray(v).ravel() for v in f(X0))
    np.testing.assert_allclose(val, film_factors(NODES, WEIGHTS, *X0, FILM), rtol=1e-13)
    mean = lambda z: float(film_factors(NODES, WEIGHTS, *z, FILM) @ WEIGHTS)  # noqa: E731
    np.testing.assert_allclose(grad, _central_gradient(mean, X0), rtol=1e-6)
    assert np.all(np.abs(grad) > 0)


def test_region_mean_power_with_film_in_casadi_matches_differences():
    # region 1 of the seed with symbolic R, delta (grooves 0.5 and 1 mm, L 14.76 mm),
    # the oil state nu, rho, b at the bulk temperature symbolic too
    law = FrictionLaw().smooth()

    def power(z, sym=False):
        reg = rotor_stator_region(z[0], z[1], 0.5e-3, 1.0e-3, 14.76e-3)
        nodes = ca.DM(NODES) if sym else NODES
        return region_mean_power(reg, nodes, WEIGHTS, z[2], z[3], law, FILM, z[4])

    x = ca.SX.sym("x", 5)
    expr = power([x[i] for i in range(5)], sym=True)
    f = ca.Function("f", [x], [expr, ca.gradient(expr, x)])
    val, grad = f(X0)
    assert float(val) == pytest.approx(power(X0), rel=1e-13)
    isothermal = region_mean_power(rotor_stator_region(R, DELTA, 0.5e-3, 1.0e-3, 14.76e-3),
                                   NODES, WEIGHTS, NU, RHO, law)
    assert power(X0) < isothermal   # the heated film loses less
    np.testing.assert_allclose(np.asarray(grad).ravel(),
                               _central_gradient(lambda z: float(power(z)), X0), rtol=1e-6)
