"""The film over a duty cycle (oilgap.model.film_cycle) against a transient
finite-difference solution of the heated film under a periodic speed.

The transient is written here. A plane laminar film of gap h (stator at y = 0, rotor at
y = h moving at U(t)), viscosity mu0 exp(-b (T - T0)), momentum quasi-steady (its time
h^2/nu is milliseconds), energy transient:

    rho c dT/dt = k T_yy + tau^2/mu(T),      tau(t) = mu0 U(t) / (h int_0^1 e^theta d eta)

With theta = b (T - T0), eta = y/h, s = t alpha/h^2 and Na(t) = b mu0 U(t)^2/k:

    theta_s = theta_eta,eta + Na(t) Phi(t)^2 e^theta,      Phi(t) = 1 / int_0^1 e^theta d eta

theta = 0 at the stator; at the rotor theta = 0 (isothermal walls) or theta_eta = 0
(insulated rotor, ghost node). Method of lines: second-order central differences on N
intervals, trapezoid rule for the integral, scipy's BDF with the exact Jacobian, from a
cold film over four cycles (the slowest mode decays by exp(-P/t1) <= exp(-3.9) = 0.02
a cycle, so the last cycle is periodic to 0.02 times its change from the one before);
the cycle-mean power factor <Phi U^2>/<U^2> of the last cycle (periodic trapezoid on
256 points) on N = 10 and 20, Richardson-extrapolated (error ~ N^-2; N = 20/40 agrees
to 2e-7).

film_cycle's prediction is what the model computes for a clearance: the heating spectrum
of the cycle's omega (``film_heating_for``), ``film_factors`` at its speed distribution,
weighted by the laminar power ~ omega^2. The clearance is a plane film (R = 1000 m,
delta/R = 1e-6: no curvature correction, Taylor number ~ 0).
"""

import dataclasses
import math
from functools import cache

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from oilgap.model.case import ThermalSpec
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.film_cycle import film_factors, film_heating_for
from oilgap.model.film_heating import MINERAL_OIL_DIFFUSIVITY_M2_S, film_factor

H, R = 1.0e-3, 1.0e3                      # gap, radius [m]: a plane film
MU, RHO, K, B = 0.26, 870.0, 0.13, 0.05   # Pa s, kg/m^3, W/(m K), 1/K
ALPHA = MINERAL_OIL_DIFFUSIVITY_M2_S      # m^2/s: t1 = 1.27 s (5.1 s insulated rotor)
PERIOD = 20.0                             # s
SHAPES = {  # U(t)/U_max as a function of the phase 2 pi t/P
    "sine": np.sin,
    "offset-sine": lambda x: 0.5 + 0.5 * np.sin(x),
}
WALLS = ("isothermal-walls", "adiabatic-rotor")
NA_PEAKS = (1.0, 8.0)
CASES = [(w, s, n) for w in WALLS for s in SHAPES for n in NA_PEAKS]
TOLERANCE = 0.015
"""Largest relative error of film_cycle's cycle-mean factor against the transient [-]."""


def _transient(shape, na_peak, walls, n, cycles=4, m_out=256):
    """Cycle-mean power factor of the last two cycles of the transient film [-]."""
    per = PERIOD * ALPHA / H ** 2                  # the period in units of h^2/alpha
    iso = walls == "isothermal-walls"
    d = 1.0 / n
    m_ = n - 1 if iso else n                       # unknown nodes 1..m_
    lap = (np.diag(np.full(m_, -2.0)) + np.diag(np.ones(m_ - 1), 1)
           + np.diag(np.ones(m_ - 1), -1)) / d ** 2
    wts = np.full(m_, d)
    if not iso:
        lap[-1, -2] = 2.0 / d ** 2                 # ghost node theta_{N+1} = theta_{N-1}
        wts[-1] = d / 2
    c0 = d if iso else d / 2                       # trapezoid weight of the theta = 0 ends

    def na(s):
        return na_peak * shape(2.0 * math.pi * s / per) ** 2

    def rhs(s, th):
        e = np.exp(th)
        phi = 1.0 / (c0 + wts @ e)
        return lap @ th + na(s) * phi ** 2 * e

    def jac(s, th):
        e = np.exp(th)
        phi = 1.0 / (c0 + wts @ e)
        a = na(s)
        return lap + np.diag(a * phi ** 2 * e) - 2.0 * a * phi ** 3 * np.outer(e, wts * e)

    t_out = per * (cycles - 2 + np.arange(2 * m_out) / m_out)
    sol = solve_ivp(rhs, (0.0, cycles * per), np.zeros(m_), method="BDF", jac=jac,
                    t_eval=t_out, rtol=1e-7, atol=1e-9)
    assert sol.success
    phi = 1.0 / (c0 + wts @ np.exp(sol.y))
    heat = na(sol.t)
    return tuple(float(np.mean((phi * heat)[k]) / np.mean(heat[k]))
                 for k in (slice(0, m_out), slice(m_out, 2 * m_out)))


@cache
def transient_factor(walls, shape, na_peak):
    """Richardson extrapolation (N = 10, 20) of the periodic cycle-mean factor [-]."""
    coarse = _transient(SHAPES[shape], na_peak, walls, 10)
    fine = _transient(SHAPES[shape], na_peak, walls, 20)
    assert abs(fine[1] - fine[0]) < 1e-5          # periodic: the last two cycles agree
    assert abs(fine[1] - coarse[1]) < 5e-4         # in the asymptotic range
    return (4.0 * fine[1] - coarse[1]) / 3.0


def _cycle(shape, na_peak, samples=2000):
    """One period of the speed, sampled uniformly; U_max gives Na_peak."""
    t = PERIOD * np.arange(samples) / samples
    u_max = math.sqrt(na_peak * K / (B * MU))
    return DutyCycle(t, u_max / R * SHAPES[shape](2.0 * math.pi * t / PERIOD))


def predicted_factor(walls, shape, na_peak, gain="film_cycle"):
    """film_cycle's cycle-mean factor; gain 'quasi-steady' (g = 1) or 'frozen' (g -> 0)."""
    cycle = _cycle(shape, na_peak)
    film = film_heating_for(cycle, ThermalSpec(2.0, 1.0, 1.0, walls=walls,
                                               conductivity_W_mK=K))
    if gain == "quasi-steady":   # no spectrum: g = 1
        film = dataclasses.replace(film, frequencies_rad_s=(), spectral_weights=())
    elif gain == "frozen":       # t1 = 1e22 s: g = 0 to double precision
        film = dataclasses.replace(film, diffusivity_m2_s=1e-29)
    nodes, w = cycle.speed_distribution()
    f = film_factors(nodes, w, R, H, MU / RHO, RHO, B, film)
    return float((f * nodes ** 2) @ w / (nodes ** 2 @ w))


def test_the_transient_solver_reaches_the_exact_steady_film():
    # a constant speed: the transient's end state is the steady film, Phi = film_factor
    for walls in WALLS:
        got = [_transient(lambda x: np.ones_like(x), 8.0, walls, n, cycles=8)[1]
               for n in (20, 40)]
        assert (4.0 * got[1] - got[0]) / 3.0 == pytest.approx(
            float(film_factor(8.0, walls)), rel=1e-6)


@pytest.mark.parametrize("walls, shape, na_peak", CASES)
def test_cycle_mean_factor_matches_the_transient(walls, shape, na_peak):
    exact = transient_factor(walls, shape, na_peak)
    got = predicted_factor(walls, shape, na_peak)
    assert got == pytest.approx(exact, rel=TOLERANCE)
    # and better than either limit of the lag
    err = abs(got / exact - 1.0)
    for limit in ("quasi-steady", "frozen"):
        assert err < abs(predicted_factor(walls, shape, na_peak, limit) / exact - 1.0)


def test_either_limit_alone_fails_the_tolerance():
    # without the gain the cycle correction errs far beyond TOLERANCE: quasi-steady by
    # -14 % (insulated rotor, offset sine, Na_peak 8), frozen by +13 % (isothermal
    # walls, offset sine, Na_peak 8); film_cycle by at most 0.9 %
    for limit in ("quasi-steady", "frozen"):
        worst = max(abs(predicted_factor(*c, gain=limit) / transient_factor(*c) - 1.0)
                    for c in CASES)
        assert worst > 5.0 * TOLERANCE, limit


def test_fast_film_is_quasi_steady_and_slow_film_frozen():
    # exact limits of Na_eff = <Na> + g (Na - <Na>), g = sum p/(1 + (w t1)^2): t1 -> 0
    # gives Phi(Na_i) node by node, t1 -> oo gives Phi(<Na>) at every node
    cycle = _cycle("offset-sine", 8.0, samples=400)
    nodes, w = cycle.speed_distribution()
    film = film_heating_for(cycle, ThermalSpec(2.0, 1.0, 1.0, conductivity_W_mK=K))
    na = B * MU * (nodes * R) ** 2 / K * (1.0 + H / R)   # curvature-corrected Na_i
    fast = dataclasses.replace(film, diffusivity_m2_s=1e30)
    slow = dataclasses.replace(film, diffusivity_m2_s=1e-30)
    np.testing.assert_allclose(film_factors(nodes, w, R, H, MU / RHO, RHO, B, fast),
                               film_factor(na), rtol=1e-13)
    np.testing.assert_allclose(film_factors(nodes, w, R, H, MU / RHO, RHO, B, slow),
                               film_factor(na @ w), rtol=1e-13)
