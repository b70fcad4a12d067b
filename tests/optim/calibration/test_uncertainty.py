"""Stage 7, uncertainty: the jackknife by hand, the baseline's variance by hand and by sampling."""

import math

import numpy as np
import pytest

from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration import (
    BaselineFit,
    BaseSpec,
    ModelFit,
    baseline_variance,
    effect_ci,
    jackknife_ci,
    parameter_ci,
)
from oilgap.optim.calibration.baseline import BASELINE_TERMS

T_975_3 = 3.182446305284263
"""Student's t, 97.5 % quantile, 3 degrees of freedom (statistical tables)."""

LAW = FrictionLaw(form="power-law")


def test_jackknife_by_hand():
    folds = np.array([[1.0], [2.0], [3.0], [6.0]])
    # mean 3, squared deviations 4 + 1 + 0 + 9 = 14, variance (g - 1)/g * 14 = 10.5
    lo, hi = jackknife_ci(np.array([3.5]), folds)
    assert lo[0] == pytest.approx(3.5 - T_975_3 * math.sqrt(10.5), rel=1e-12)
    assert hi[0] == pytest.approx(3.5 + T_975_3 * math.sqrt(10.5), rel=1e-12)
    lo, hi = jackknife_ci(np.array([3.5]), folds, np.array([1.5]))
    assert hi[0] - lo[0] == pytest.approx(2 * T_975_3 * math.sqrt(12.0), rel=1e-12)
    lo, hi = jackknife_ci(np.array([1.0, 2.0]), np.ones((2, 2)))
    assert np.all(np.isnan(lo)) and np.all(np.isnan(hi))  # fewer than 3 runs


def _baseline(T, cov):
    return BaselineFit(roughness_T=T, terms=BASELINE_TERMS, coef=np.zeros(6), temp_ref_C=30.0,
                       rmse_W=0.5, n_samples=100, temp_range_C=(25.0, 35.0), speed_max_rpm=3000.0,
                       notes=(), cov=cov)


def _design(s, rows):
    w, a = s.omega[rows], s.domega_dt[rows]
    return np.column_stack([np.ones_like(w), np.abs(w), w * w, w * a, np.sign(w) * a, a * a])


COV = np.diag([0.04, 1e-6, 1e-12, 1e-9, 1e-8, 1e-12])


def test_baseline_variance_of_an_effect_coefficient(samples_factory):
    # one effect (seal, column |w|) in the solver's scaled unknown z = theta * scale
    s = samples_factory()
    f = np.abs(s.omega)
    scale = float(np.sqrt(np.mean(f * f)))
    fit = ModelFit(np.zeros(0), np.array([0.02]), LAW, np.zeros(s.n), np.zeros((s.n, 0)),
                   (f / scale)[:, None], np.array([scale]), ("seal_coulomb_friction",),
                   np.zeros(1))
    spec = BaseSpec((), {"C": 10.0, "alpha": 0.3, "beta": -1.0, "gamma": 0.0})
    baselines = {4.0: _baseline(4.0, COV), 2.0: _baseline(2.0, None)}
    got = baseline_variance(fit, spec, s, baselines)
    rows = s.roughness_T == 4.0
    # by hand: d theta = (f' dy) / (f' f), dy = -X dc on the T = 4 rows
    a = f[rows] @ _design(s, rows) / (f @ f)
    assert got[0] == pytest.approx(a @ COV @ a, rel=1e-10)
    # by sampling: refit theta on perturbed data
    rng = np.random.default_rng(0)
    dc = rng.multivariate_normal(np.zeros(6), COV, size=4000)
    dy = np.zeros((4000, s.n))
    dy[:, rows] = -dc @ _design(s, rows).T
    dtheta = dy @ f / (f @ f)
    assert got[0] == pytest.approx(np.var(dtheta), rel=0.08)
    assert baseline_variance(fit, spec, s, {}).tolist() == [0.0]


def test_baseline_variance_of_C_through_ln_C(samples_factory):
    # P = C g: the solver fits ln C (Jacobian column P); the variance is reported for C
    s = samples_factory()
    g = 1.0 + np.abs(s.omega) ** 2 * 1e-3
    C = 12.0
    spec = BaseSpec(("C",), {"alpha": 0.3, "beta": -1.0, "gamma": 0.0})
    fit = ModelFit(np.array([math.log(C)]), np.zeros(0), spec.law(np.array([math.log(C)])),
                   C * g, (C * g)[:, None], (C * g)[:, None], np.ones(0), (), np.zeros(0))
    got = baseline_variance(fit, spec, s, {4.0: _baseline(4.0, COV)})
    rows = s.roughness_T == 4.0
    a = g[rows] @ _design(s, rows) / (g @ g)  # dC = g' dy / g' g
    assert got[0] == pytest.approx(a @ COV @ a, rel=1e-10)


def test_parameter_and_effect_intervals(samples_factory):
    s = samples_factory()
    spec = BaseSpec(("C",), {"alpha": 0.3, "beta": -1.0, "gamma": 0.0})

    def fit_at(C):
        x = np.array([math.log(C)])
        return ModelFit(x, np.zeros(0), spec.law(x), np.zeros(s.n), np.ones((s.n, 1)),
                        np.ones((s.n, 1)), np.ones(0), (), np.zeros(0))

    folds = [fit_at(c) for c in (9.0, 10.0, 11.0, 14.0)]
    ci = parameter_ci(spec, fit_at(10.5), folds, s, {})
    # C must be positive: the jackknife is taken on ln C, the bounds exponentiated.
    # ln 9, ln 10, ln 11, ln 14: mean m, variance (g - 1)/g sum (ln C_i - m)^2, g = 4
    logs = [math.log(c) for c in (9.0, 10.0, 11.0, 14.0)]
    m = sum(logs) / 4
    var = 3 / 4 * sum((v - m) ** 2 for v in logs)
    half = T_975_3 * math.sqrt(var)
    assert ci["C"] == pytest.approx([10.5 * math.exp(-half), 10.5 * math.exp(half)], rel=1e-12)
    # the linear-space interval would reach below zero here; the log-space one cannot
    assert 10.5 - T_975_3 * math.sqrt(10.5) < 0.2 and ci["C"][0] > 4.0
    assert ci["alpha"] == ci["beta"] == ci["gamma"] == "fixed"
    lo, hi = effect_ci(spec, fit_at(10.5), folds, s, {})
    assert lo.size == 0 and hi.size == 0
