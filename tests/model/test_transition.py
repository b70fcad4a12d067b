"""The ``"taylor"`` transition (model/transition.py) against what it did not compute.

* Ta_c(eta): Esser & Grossmann's closed form against (a) a linear-stability eigenvalue
  solve written here (Chebyshev collocation of the axisymmetric Taylor problem) and (b) the
  published critical Reynolds numbers at three radius ratios (DiPrima & Swinney 1981,
  table of Re_c for the outer cylinder at rest: 68.19 at eta = 0.5, 118.16 at 0.875,
  184.98 at 0.95).
* Continuity at Re_c (both sides) and at the end of Donnelly & Simon's range, for floats,
  numpy arrays and CasADi symbols.
* The supercritical law against Donnelly & Simon's published observations (their form
  a/Omega + b Omega^1.36 near onset, G ~ Omega^1.51 well beyond it) and Wendt's data fit.
* The seed joint at 25 degC: exact Couette in region 1 under ``--transition taylor``.
"""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest
import scipy.linalg as sl
from scipy.optimize import minimize_scalar

from oilgap.model.errors import InputError
from oilgap.model.skin_friction import FrictionLaw, moment_coefficient
from oilgap.model.taylor_couette import couette_moment_coefficient
from oilgap.model.transition import (
    critical_reynolds_number,
    critical_taylor_number,
    donnelly_simon_coefficients,
    taylor_cm,
    taylor_cm_smooth,
    wendt_cm,
)

PUBLISHED_RE_C = {0.5: 68.19, 0.875: 118.16, 0.95: 184.98}
"""Linear-stability Re_c = Omega R1 d / nu, outer cylinder at rest (DiPrima & Swinney 1981)."""


def _cheb(n):
    x = np.cos(np.pi * np.arange(n + 1) / n)
    c = np.r_[2.0, np.ones(n - 1), 2.0] * (-1.0) ** np.arange(n + 1)
    dx = x[:, None] - x[None, :]
    d = np.outer(c, 1.0 / c) / (dx + np.eye(n + 1))
    return d - np.diag(d.sum(1)), x


def _stability_re(eta, k, n=24):
    """Smallest Re with a neutral axisymmetric mode of axial wavenumber k (units of d).

    Chandrasekhar's equations (Hydrodynamic and Hydromagnetic Stability, sec. 68):
    (DD* - k^2)^2 u = 2 k^2 Omega(r) v / nu, (DD* - k^2) v = 2 A u / nu, u = Du = v = 0
    on both walls; Omega(r) = A + B/r^2 with the outer cylinder at rest.
    """
    d, x = _cheb(n)
    r1, r2 = eta / (1 - eta), 1 / (1 - eta)
    r, d = (r1 + r2) / 2 + x / 2, 2 * d
    eye = np.eye(n + 1)
    lap = d @ d + np.diag(1 / r) @ d - np.diag(1 / r**2) - k * k * eye
    a = -eta**2 / (1 - eta**2) / r1  # A per unit Re (Omega1 = Re / r1, nu = d = 1)
    om = a + r1 / (1 - eta**2) / r**2
    z = np.zeros_like(eye)
    lhs = np.block([[lap @ lap, z], [z, lap]])
    rhs = np.block([[z, 2 * k * k * np.diag(om)], [2 * a * eye, z]])
    for row, rep in ((0, eye[0]), (n, eye[n]), (1, d[0]), (n - 1, d[n])):
        lhs[row], rhs[row] = 0.0, 0.0
        lhs[row, :n + 1] = rep
    for row in (n + 1, 2 * n + 1):
        lhs[row], rhs[row] = 0.0, 0.0
        lhs[row, row] = 1.0
    w = sl.eig(lhs, rhs, right=False)
    w = w[np.isfinite(w)]
    return w[(abs(w.imag) < 1e-6 * abs(w.real)) & (w.real > 0)].real.min()


@pytest.mark.parametrize("eta", sorted(PUBLISHED_RE_C))
def test_critical_reynolds_number_against_published_and_linear_stability(eta):
    x = (1 - eta) / eta
    lsa = minimize_scalar(lambda k: _stability_re(eta, k), bounds=(2.0, 4.5),
                          method="bounded", options={"xatol": 1e-4}).fun
    assert lsa == pytest.approx(PUBLISHED_RE_C[eta], rel=5e-4)  # the solve reproduces them
    eg = critical_reynolds_number(x)
    assert eg == pytest.approx(PUBLISHED_RE_C[eta], rel=0.035)  # E&G: within 3.1 %
    assert critical_taylor_number(x) == pytest.approx(eg * math.sqrt(x), rel=1e-12)


def test_critical_taylor_number_narrow_gap_limit_and_seed():
    # x -> 0: (2+x)^2 / (2 sqrt(4+3x) alpha^2) -> 1/alpha^2 = 41.30, the narrow-gap value
    assert critical_taylor_number(1e-9) == pytest.approx(1 / 0.1556**2, rel=1e-8)
    # seed region 1 (delta/R = 1/25.4): 2.0394^2 / (2 sqrt(4.1181) 0.1556^2) by hand
    x = 1 / 25.4
    hand = (2 + x) ** 2 / (2 * math.sqrt(4 + 3 * x) * 0.1556**2)
    assert critical_taylor_number(x) == pytest.approx(hand, rel=1e-12)
    assert 42.0 < hand < 42.6


@pytest.mark.parametrize("x", [0.01, 1 / 25.4, 0.2])
def test_exact_couette_below_and_continuous_at_onset(x):
    re_c = critical_reynolds_number(x)
    below = np.array([0.1, 0.5, 0.9, 1 - 1e-9]) * re_c
    np.testing.assert_allclose(taylor_cm(below, x), couette_moment_coefficient(below, x),
                               rtol=1e-14)
    above = taylor_cm(re_c * (1 + 1e-9), x) / couette_moment_coefficient(re_c * (1 + 1e-9), x)
    assert above == pytest.approx(1.0, abs=1e-7)  # C0 at Ta_c from above
    re_b = 10 * re_c  # the end of Donnelly & Simon's range
    lo, hi = taylor_cm(re_b * (1 - 1e-9), x), taylor_cm(re_b * (1 + 1e-9), x)
    assert lo == pytest.approx(hi, rel=1e-7)


def test_casadi_and_smooth_forms_agree_with_the_exact_one():
    re, xs = ca.SX.sym("re"), ca.SX.sym("x")
    f = ca.Function("f", [re, xs], [taylor_cm(re, xs)])
    fs = ca.Function("fs", [re, xs], [taylor_cm_smooth(re, xs)])
    g = ca.Function("g", [re, xs], [ca.gradient(taylor_cm_smooth(re, xs), re)])
    x = 1 / 25.4
    re_c = critical_reynolds_number(x)
    for r in (0.5 * re_c, re_c * (1 - 1e-9), re_c * (1 + 1e-9), 3 * re_c, 50 * re_c):
        assert float(f(r, x)) == pytest.approx(float(taylor_cm(r, x)), rel=1e-12)
        assert np.isfinite(float(g(r, x)))
    grid = np.geomspace(0.05, 100, 200) * re_c
    far = (abs(np.log(grid / re_c)) > 0.15) & (abs(np.log(grid / (10 * re_c))) > 0.15)
    exact, smooth = taylor_cm(grid, x), taylor_cm_smooth(grid, x)
    np.testing.assert_allclose(smooth[far], exact[far], rtol=0.01)
    assert np.all(smooth >= exact * (1 - 1e-3))  # a smooth max: never below Couette
    # at onset the smooth max is 1 + width/2 = 1 % above Couette, and stays continuous
    assert float(fs(re_c, x)) / couette_moment_coefficient(re_c, x) == pytest.approx(1.01,
                                                                                    abs=1e-3)


def test_supercritical_law_against_donnelly_simon_and_wendt():
    x = 1 / 25.4
    re_c = critical_reynolds_number(x)
    # Donnelly & Simon's form: G = a/Omega + b Omega^1.36, so G Omega is affine in
    # Omega^2.36 (G* = C_m Re^2 pi / (2 x^2), seed Eq. 5)
    re = np.linspace(1.2, 9.5, 8) * re_c
    g = taylor_cm(re, x) * re**2
    slope, icpt = np.polyfit(re**2.36, g * re, 1)
    np.testing.assert_allclose(slope * re**2.36 + icpt, g * re, rtol=1e-10)
    a, b = donnelly_simon_coefficients(x)
    assert a < 0 < b and a + b == pytest.approx(1.0, rel=1e-12)  # Stuart-like onset
    # anchored to Wendt's data fit at ten times the critical speed
    assert taylor_cm(10 * re_c, x) == pytest.approx(wendt_cm(10 * re_c, x), rel=1e-9)
    # "well beyond critical G varies approximately as Omega^1.51" (Donnelly & Simon)
    r2, r3 = 12 * re_c, 40 * re_c
    n = 2 + math.log(taylor_cm(r3, x) / taylor_cm(r2, x)) / math.log(r3 / r2)
    assert n == pytest.approx(1.51, abs=0.03)
    # torque rises monotonically through onset and the vortex range
    grid = np.geomspace(0.5, 100, 300) * re_c
    assert np.all(np.diff(taylor_cm(grid, x) * grid**2) > 0)


def test_wendt_ranges_meet_at_1e4_by_hand():
    # 1.45 Re^1.5 = 0.23 Re^1.7 at Re = (1.45/0.23)^5 = 9.99e3: the published break
    assert (1.45 / 0.23) ** 5 == pytest.approx(1e4, rel=0.01)
    x = 0.1
    lo, hi = wendt_cm(1e4 * 0.999, x), wendt_cm(1e4 * 1.001, x)
    assert lo == pytest.approx(hi, rel=0.005)


def test_law_refuses_taylor_where_it_does_not_apply():
    with pytest.raises(InputError, match="transition"):
        FrictionLaw(transition="vortex")
    with pytest.raises(InputError, match="form"):
        FrictionLaw(form="power-law", transition="taylor")
    with pytest.raises(InputError, match="laminar_law"):
        FrictionLaw(laminar_law="bilgen-boulos", transition="taylor")


def test_moment_coefficient_under_taylor_is_couette_times_groove_factor():
    x, re = 1 / 25.4, 27.0
    law = FrictionLaw(transition="taylor", gamma=0.566)
    hand = 8 * (1 + x) ** 2 / ((2 + x) * re) * 4.0**0.566
    assert moment_coefficient(re, x, law, 4.0) == pytest.approx(hand, rel=1e-12)


@pytest.mark.parametrize("x", [1e-3, 0.01, 0.227, 1.0])
def test_torque_rises_through_onset_at_every_gap(x):
    # a < 0 (Stuart-like onset, no dip below Couette) and G monotone from 0.2 to 300 Re_c
    a, b = donnelly_simon_coefficients(x)
    assert a < 0 < b
    re = np.geomspace(0.2, 300, 2000) * critical_reynolds_number(x)
    assert np.all(np.diff(taylor_cm(re, x) * re**2) > 0)
    assert np.all(taylor_cm(re, x) >= couette_moment_coefficient(re, x) * (1 - 1e-12))
