"""The scalar balance polished to the root (model/thermal.py, issue 27 item 5).

The closed-form root of an exponential loss (Lambert W, from w e^w chosen here: no
solver) against ``steady_temperature`` with and without ``polish``; a loss with a
downward step and no root keeps the solver's answer (the step).
"""

from __future__ import annotations

import numpy as np

from oilgap.model.thermal import polish_roots, steady_temperature


def test_polish_reaches_the_closed_form_root_of_an_exponential_loss():
    # T = T_b + R c exp(-b T): root T_b + w/b where w e^w = b R c exp(-b T_b)
    w = np.array([1.3, 0.4, 2.0, 0.9])
    b, r, tb = np.array([0.05, 0.03, 0.08, 0.06]), 0.5, np.array([3.0, 5.0, 1.0, 2.0])
    c = w * np.exp(w) / (b * r) * np.exp(b * tb)
    root = tb + w / b

    def power_at(t):
        k = len(t) // len(tb)
        return np.tile(c, k) * np.exp(-np.tile(b, k) * t)

    rough, _ = steady_temperature(power_at, tb, r, len(tb), tol_K=1e-6)
    fine, p = steady_temperature(power_at, tb, r, len(tb), tol_K=1e-6, polish=True)
    assert np.max(np.abs(rough - root)) > 1e-12  # the solver alone stops near it
    np.testing.assert_allclose(fine, root, rtol=0, atol=1e-12)
    np.testing.assert_allclose(p, c * np.exp(-b * fine), rtol=1e-15)


def test_a_downward_step_without_a_root_keeps_the_step():
    # P falls by 4 W at 10 degC: g jumps from -1 to +1 there, no root; the solver's
    # answer is the step (within its last unevaluated step, 1e-4 K), and the polish,
    # whose chord steps jump across it, keeps that answer
    def power_at(t):
        return np.where(t < 10.0, 14.0, 10.0)

    t, p = steady_temperature(power_at, np.array([3.0]), 0.5, 1)
    t2, p2 = polish_roots(power_at, np.array([3.0]), 0.5, t, p)
    assert abs(t[0] - 10.0) < 1e-4 and t2[0] == t[0] and p2[0] == p[0]
