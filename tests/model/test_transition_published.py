"""The supercritical law of ``transition = "taylor"`` against near-onset torque it did not use.

:func:`~oilgap.model.transition.taylor_cm` divided by Couette at the same Re and gap ratio
is the torque ratio G/G_Couette, which the Taylor-Couette literature calls Nu_omega
(Eckhardt, Grossmann & Lohse, J. Fluid Mech. 581:221, 2007). Near onset it is compared with:

* **Published:** Nu_omega = 1.1375 at eta = 0.5, Re = Omega R1 d / nu = 80, outer
  cylinder at rest, axially periodic with wavelength 2d: the direct numerical simulation
  of Ostilla-Monico, Stevens, Grossmann, Verzicco & Lohse (J. Fluid Mech. 719:14, 2013),
  as quoted by the validation case of the open-source SimpleTCSolver
  (github.com/NaokiHori/SimpleTCSolver, docs/source/example/typical: r_i = 1, d = 1,
  L_z = 2, Re = 80, reference line 1.1375). Donnelly's (1958) and Donnelly & Simon's
  (1960) tables could not be retrieved here.
* **A second method, written here:** steady axisymmetric Taylor-vortex flow solved by
  Newton's method (streamfunction and swirl, Chebyshev in r, sines and cosines in z,
  the Reynolds number found for a prescribed vortex amplitude, so Couette flow is
  excluded). At small amplitude it reproduces DiPrima & Swinney's linear-stability Re_c,
  and at Re = 80 the published 1.1375 to 0.1 %; it then gives the ratio from onset to
  about 1.9 Re_c at eta = 0.5 and 1.3-1.5 Re_c at Donnelly's eta = 0.95 and at the
  seed's region 1 (eta = 0.962), where 12 x 3 modes are within 1 % of 20 x 6.

Tolerances. Ratio, 6 %: the law starts at Esser & Grossmann's Re_c, 3.0 % above linear
stability at eta = 0.5 (0.5 % at 0.95), which alone lowers the ratio near onset by about
slope x 3 % = 3 %; as much again for the form's shape (Donnelly & Simon state a range,
onset to about 10 Re_c, not a scatter); the solve's own error is under 1 %. Initial
slope dNu/d(Re/Re_c), 20 %: the form's slope -2A + 0.36B is set by its two anchors, not
fitted to the weakly nonlinear (Stuart) slope, which Donnelly & Simon credit with the
first few per cent above onset. Measured: 4.5 % and 14 % at eta = 0.5, under 1.5 % and
5.5 % at the narrow gaps. A wrong exponent (1.0, 1.2, 1.51), the narrow-gap onset
instead of Esser & Grossmann's, or Eq. 6's turbulent branches instead of Wendt's as the
upper anchor fail the same checks (test_a_wrong_exponent_or_anchor_fails).
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
from test_transition import _cheb  # the Chebyshev matrix of the linear-stability check

import oilgap.model.transition as tr
from oilgap.model.taylor_couette import couette_moment_coefficient

OSTILLA_2013 = {"eta": 0.5, "re": 80.0, "wavelength": 2.0, "nu_omega": 1.1375}
"""Published DNS point (Ostilla-Monico et al. 2013, as quoted by SimpleTCSolver)."""

LSA_RE_C = {0.5: 68.19, 0.95: 184.98}
"""Linear-stability Re_c, outer cylinder at rest (DiPrima & Swinney 1981)."""

SEED_ETA = 1.0 / (1.0 + 1.0 / 25.4)
"""The seed's region 1 (delta/R1 = 1/25.4)."""

RATIO_TOL, SLOPE_TOL = 0.06, 0.20

_EG_RE_C = tr.critical_reynolds_number  # captured before any test patches the module


class _TaylorVortex:
    """Steady axisymmetric Taylor-vortex flow, d = 1, inner wall speed 1, outer at rest.

    u = -psi_z / r, w = psi_r / r, swirl V = V_Couette + v; psi = sum psi_n(r) sin(n k z),
    v = sum v_n(r) cos(n k z). Azimuthal momentum and azimuthal vorticity
    omega = -(psi_rr - psi_r / r + psi_zz) / r (e.g. Batchelor, An Introduction to Fluid
    Dynamics, sec. 7.5):
    u V_r + w V_z + u V / r = (1/Re) (lap - 1/r^2) V,
    u omega_r + w omega_z - u omega / r = 2 V V_z / r + (1/Re) (lap - 1/r^2) omega,
    psi = psi_r = v = 0 on both walls; the products are formed on a z grid of 3 n_m + 3
    points and projected back. Unknowns: the coefficients and Re, with psi_1 at mid-gap
    prescribed (the amplitude).
    """

    def __init__(self, eta, wavelength=2.0, n_r=12, n_m=3):
        d, x = _cheb(n_r)
        self.r1 = eta / (1 - eta)
        self.r = self.r1 + 0.5 + x / 2  # index 0 the outer wall, n_r the inner
        self.d1 = 2 * d
        self.d2 = self.d1 @ self.d1
        self.n_r, self.n_m = n_r, n_m
        k = 2 * np.pi / wavelength
        z = np.arange(3 * n_m + 3) * wavelength / (3 * n_m + 3)
        self.nk = np.arange(n_m + 1) * k
        self.cos, self.sin = np.cos(np.outer(self.nk, z)), np.sin(np.outer(self.nk, z))
        w = np.full(n_m + 1, 2.0 / z.size)
        w[0] = 1.0 / z.size
        self.proj_cos, self.proj_sin = (self.cos * w[:, None]).T, (self.sin * w[:, None]).T
        self.a = -(eta**2) / (1 - eta**2) / self.r1  # V = a r + b / r
        self.b = self.r1 / (1 - eta**2)
        self.n_psi, self.n_v = (n_r + 1) * n_m, (n_r + 1) * (n_m + 1)

    def _unpack(self, xs):
        m = xs.shape[0]
        psi = np.zeros((m, self.n_r + 1, self.n_m + 1))
        psi[:, :, 1:] = xs[:, :self.n_psi].reshape(m, self.n_r + 1, self.n_m)
        v = xs[:, self.n_psi:self.n_psi + self.n_v].reshape(m, self.n_r + 1, self.n_m + 1)
        return psi, v, xs[:, -1]

    def residual(self, xs, amplitude):
        """Residuals of a batch of states (rows of ``xs``)."""
        psi, v, re = self._unpack(xs)
        r, nk, d1, d2 = self.r[None, :, None], self.nk[None, None, :], self.d1, self.d2
        psi_r = d1 @ psi
        om = -(d2 @ psi - psi_r / r - nk**2 * psi) / r
        v_r = d1 @ v
        u, w = -(psi * nk) @ self.cos / r, psi_r @ self.sin / r
        vg, vg_r, vg_z = v @ self.cos, v_r @ self.cos, -(v * nk) @ self.sin
        swirl = self.a * r + self.b / r + vg
        adv_v = u * 2 * self.a + u * vg_r + w * vg_z + u * vg / r
        adv_o = u * ((d1 @ om) @ self.sin) + w * ((om * nk) @ self.cos) - u * (om @ self.sin) / r
        nu = (1 / re)[:, None, None]
        res_v = nu * (d2 @ v + v_r / r - v / r**2 - nk**2 * v) - adv_v @ self.proj_cos
        res_o = (nu * (d2 @ om + (d1 @ om) / r - om / r**2 - nk**2 * om)
                 + (2 * swirl * vg_z / r - adv_o) @ self.proj_sin)
        n = self.n_r
        res_o[:, [0, n]], res_o[:, [1, n - 1]] = psi[:, [0, n]], psi_r[:, [0, n]]
        res_v[:, [0, n]] = v[:, [0, n]]
        pin = psi[:, n // 2, 1] - amplitude
        return np.concatenate([res_o[:, :, 1:].reshape(len(xs), -1),
                               res_v.reshape(len(xs), -1), pin[:, None]], axis=1)

    def solve(self, xs, amplitude):
        """Newton's method; the residual is quadratic, so central differences are exact."""
        for _ in range(30):
            f = self.residual(xs[None], amplitude)[0]
            h = 1e-6 * np.maximum(1.0, abs(xs))
            jac = (self.residual(xs + np.diag(h), amplitude)
                   - self.residual(xs - np.diag(h), amplitude)).T / (2 * h)
            step = np.linalg.solve(jac, -f)
            xs = xs + step
            if np.max(abs(step)) < 1e-10 * max(1.0, np.max(abs(xs))):
                return xs
        raise RuntimeError("Newton did not converge")

    def start(self, amplitude, re):
        """A guess near onset: psi_1 ~ (r - r1)^2 (r2 - r)^2, v_1 ~ sin(pi (r - r1))."""
        s = (self.r - self.r1) * (self.r1 + 1 - self.r)
        psi = np.zeros((self.n_r + 1, self.n_m))
        psi[:, 0] = amplitude * s**2 / s[self.n_r // 2] ** 2
        v = np.zeros((self.n_r + 1, self.n_m + 1))
        v[:, 1] = amplitude * np.sin(np.pi * (self.r - self.r1))
        return self.solve(np.concatenate([psi.ravel(), v.ravel(), [re]]), amplitude)

    def torque_ratio(self, xs):
        """(Nu_omega at the inner wall, at the outer wall, Re): G / G_Couette from v_0."""
        v0_r = self.d1 @ self._unpack(xs[None])[1][0, :, 0]
        r2 = self.r1 + 1
        return (1 - self.r1**2 * v0_r[-1] / (2 * self.b), 1 - r2**2 * v0_r[0] / (2 * self.b),
                xs[-1])


@functools.cache
def _vortex_curve(eta):
    """Re_c and (Re, Nu_omega) along the Taylor-vortex branch, from onset to 1.5-2 Re_c.

    Re_c is extrapolated from the two smallest amplitudes (Re - Re_c grows as the
    amplitude squared at a supercritical onset).
    """
    tv = _TaylorVortex(eta)
    amps = np.array([0.004, 0.006, 0.01, 0.02, 0.03, 0.045, 0.06]) * (1 if eta < 0.7 else 5)
    xs = tv.start(amps[0], float(_EG_RE_C(1 / eta - 1)))
    out = []
    for amp in amps:
        xs = tv.solve(xs, amp)
        nu_in, nu_out, re = tv.torque_ratio(xs)
        assert nu_in == pytest.approx(nu_out, rel=5e-4)  # angular momentum is conserved
        out.append((re, nu_in))
    (re0, _), (re1, _) = out[:2]
    return re0 - (re1 - re0) * amps[0] ** 2 / (amps[1] ** 2 - amps[0] ** 2), np.array(out)


def _law_ratio(re, eta):
    x = 1 / eta - 1
    return np.asarray(tr.taylor_cm(re, x) / couette_moment_coefficient(re, x), dtype=float)


def _law_slope(eta, re_c):
    """dNu/d(Re/Re_c) of the law just above its onset, per the true Re_c [-]."""
    a, b = tr.donnelly_simon_coefficients(1 / eta - 1)
    n = tr.DONNELLY_SIMON_EXPONENT - 1
    return float(-2 * a + n * b) * re_c / float(tr.critical_reynolds_number(1 / eta - 1))


def _worst(eta):
    """Largest relative miss of the law against the vortex curve, and of its slope."""
    re_c, curve = _vortex_curve(eta)
    miss = np.max(abs(_law_ratio(curve[:, 0], eta) / curve[:, 1] - 1))
    slope = (curve[1, 1] - curve[0, 1]) / (curve[1, 0] - curve[0, 0]) * re_c
    return miss, abs(_law_slope(eta, re_c) / slope - 1)


def test_vortex_solve_reproduces_linear_stability_and_the_published_dns():
    tv = _TaylorVortex(0.5, wavelength=OSTILLA_2013["wavelength"])
    xs = tv.start(1e-3, 70.0)
    assert tv.torque_ratio(xs)[2] == pytest.approx(LSA_RE_C[0.5], rel=2e-4)  # k = pi
    lo, hi = 0.03, 0.04  # bracket Re = 80 in amplitude, then the secant
    res = {}
    for amp in (lo, hi):
        xs = tv.solve(xs, amp)
        res[amp] = tv.torque_ratio(xs)[2]
    for _ in range(8):
        amp = hi + (80.0 - res[hi]) * (hi - lo) / (res[hi] - res[lo])
        xs = tv.solve(xs, amp)
        lo, hi, res[amp] = hi, amp, tv.torque_ratio(xs)[2]
    nu_in, nu_out, re = tv.torque_ratio(xs)
    assert re == pytest.approx(80.0, rel=1e-8)
    assert nu_in == pytest.approx(OSTILLA_2013["nu_omega"], rel=1e-3)
    assert nu_out == pytest.approx(nu_in, rel=1e-4)  # angular momentum, 12 x 3 modes


def test_taylor_law_against_the_published_dns_point():
    p = OSTILLA_2013
    assert _law_ratio(p["re"], p["eta"]) == pytest.approx(p["nu_omega"], rel=RATIO_TOL)
    # and below the published onset the DNS is laminar: Nu_omega = 1, as the law
    assert _law_ratio(0.99 * LSA_RE_C[0.5], 0.5) == 1.0


@pytest.mark.parametrize("eta", [0.5, 0.95, SEED_ETA])
def test_taylor_law_against_the_taylor_vortex_torque(eta):
    re_c, curve = _vortex_curve(eta)
    if eta in LSA_RE_C:  # the solve's onset is linear stability's (wavelength 2d)
        assert re_c == pytest.approx(LSA_RE_C[eta], rel=5e-4)
    assert curve[0, 0] / re_c < 1.005 and curve[-1, 0] / re_c > 1.3  # onset to beyond
    miss, slope_miss = _worst(eta)
    assert miss < RATIO_TOL
    assert slope_miss < SLOPE_TOL


@pytest.mark.parametrize("mutant", ["exponent 1.0", "exponent 1.2", "exponent 1.3",
                                    "exponent 1.51",
                                    "narrow-gap onset", "Eq. 6 upper anchor"])
def test_a_wrong_exponent_or_anchor_fails(monkeypatch, mutant):
    if mutant.startswith("exponent"):
        monkeypatch.setattr(tr, "DONNELLY_SIMON_EXPONENT", float(mutant.split()[1]))
    elif mutant == "narrow-gap onset":  # Ta_c = 1/alpha^2 = 41.3 at every gap ratio
        monkeypatch.setattr(tr, "critical_reynolds_number",
                            lambda x: x**-0.5 / tr.ESSER_GROSSMANN_ALPHA**2)
    else:
        monkeypatch.setattr(tr, "WENDT_COEFFICIENTS", ((0.0, 1.5), (0.0, 1.7)))
    worst = [_worst(eta) for eta in (0.5, 0.95, SEED_ETA)]
    assert max(m for m, _ in worst) > RATIO_TOL or max(s for _, s in worst) > SLOPE_TOL
