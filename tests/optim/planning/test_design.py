"""Optimal designs against closed-form answers, the Fisher information against finite
differences of the loop's own forward model, the jackknife prediction against simulation.

Closed forms (Pukelsheim, *Optimal Design of Experiments*, 1993, sec. 9.5; Atkinson,
Donev & Tobias, *Optimum Experimental Designs*, 2007, sec. 11.4):
* straight line on [a, b]: D-optimal weights 1/2 at a and at b;
* quadratic on [-1, 1]: D-optimal weights 1/3 at -1, 0 and 1;
* for the straight line on [-1, 1], the uniform design on {-1, 0, 1} has
  M = [[1, 0], [0, 2/3]], d(x) = 1 + 1.5 x^2, max d = 2.5 at x = +-1, so its
  equivalence-theorem gap is 2.5 - 2 = 0.5 and its efficiency bound 2/2.5 = 0.8.
"""

import numpy as np
import pytest

from oilgap.model.io.case_io import seed_case
from oilgap.model.measured.data import oil_samples
from oilgap.model.measured.validation import validate
from oilgap.model.oils import builtin_fluids
from oilgap.optim.calibration.forward import ForwardModel
from oilgap.optim.calibration.spec import decide_spec
from oilgap.optim.planning import (
    base_jacobian,
    confounding,
    detectable_sizes,
    efficient_rounding,
    equivalence_gap,
    jackknife_sd,
    optimal_weights,
)
from oilgap.studies.plan.candidates import Candidate, plan_data
from oilgap.studies.plan.settings import PlanSettings


def _moments(x, degree):
    F = np.vander(np.asarray(x, float), degree + 1, increasing=True)
    return np.einsum("ij,ik->ijk", F, F)


def test_straight_line_puts_half_at_each_end():
    x = np.linspace(2.0, 5.0, 13)
    d = optimal_weights(_moments(x, 1), "D")
    assert d.weights[0] == pytest.approx(0.5, abs=1e-4)
    assert d.weights[-1] == pytest.approx(0.5, abs=1e-4)
    assert d.weights[1:-1].sum() == pytest.approx(0.0, abs=1e-4)
    assert d.gap < 1e-3 and d.efficiency > 0.999


def test_quadratic_puts_thirds_at_minus_one_zero_one():
    x = np.linspace(-1.0, 1.0, 21)
    d = optimal_weights(_moments(x, 2), "D")
    for xi in (-1.0, 0.0, 1.0):
        assert d.weights[np.argmin(abs(x - xi))] == pytest.approx(1 / 3, abs=1e-3)
    assert d.weights.sum() == pytest.approx(1.0)
    assert d.gap < 1e-3


def test_equivalence_gap_of_a_uniform_three_point_design_by_hand():
    x = np.array([-1.0, 0.0, 1.0])
    gap, eff = equivalence_gap(_moments(x, 1), np.ones(3) / 3, "D")
    assert gap == pytest.approx(0.5)
    assert eff == pytest.approx(0.8)
    # and the true D-efficiency, (det M / det M*)^(1/p) = sqrt(2/3), is above the bound
    assert np.sqrt(2 / 3) >= eff


def test_t_optimal_discrimination_of_a_square_term():
    """Intercept as nuisance, x^2 the effect: S(w) = Var_w(x^2) is largest with half the
    weight where x^2 = 0 and half where x^2 = 1 (a Bernoulli variance, max at p = 1/2)."""
    x = np.linspace(-1.0, 1.0, 11)
    F = np.column_stack([np.ones_like(x), x * x])
    Ms = np.einsum("ij,ik->ijk", F, F)
    d = optimal_weights(Ms, "T", nuisance=1)
    assert d.weights[5] == pytest.approx(0.5, abs=1e-3)
    assert d.weights[0] + d.weights[-1] == pytest.approx(0.5, abs=1e-3)
    assert d.gap < 1e-4


def test_efficient_rounding_by_hand():
    # Pukelsheim & Rieder 1992: n_i = ceil((n - l/2) w_i) = ceil(5.5/3) = 2 each, sum 6,
    # one run added where n_i / w_i is smallest (a tie: the first)
    assert efficient_rounding(np.array([1, 1, 1]) / 3, 7).tolist() == [3, 2, 2]
    assert efficient_rounding(np.array([0.5, 0.0, 0.5]), 4).tolist() == [2, 0, 2]
    # fewer runs than support points: the largest weights
    assert efficient_rounding(np.array([0.5, 0.3, 0.2]), 2).tolist() == [1, 1, 0]


def test_detectable_size_is_the_noncentrality_over_the_adjusted_information():
    """Intercept and one column f on n = 4 runs, f = (0, 0, 1, 1): S = sum (f - mean)^2 = 1,
    so the smallest detectable coefficient is sqrt(7.849) = 2.8016."""
    f = np.array([0.0, 0.0, 1.0, 1.0])
    F = np.column_stack([np.ones(4), f])
    size, r2 = detectable_sizes(F.T @ F, 1)
    assert size[0] == pytest.approx(np.sqrt((1.959964 + 0.841621) ** 2), rel=1e-5)
    assert r2[0] == pytest.approx(1 - 1.0 / 2.0)  # S / m_kk = 1 / 2


def test_jackknife_prediction_against_simulated_jackknives():
    """Straight line, six runs of unequal leverage: the expected delete-one-run jackknife
    variance of the slope against 1500 simulated jackknives (numpy least squares)."""
    rng = np.random.default_rng(0)
    xs = [np.linspace(-1, 1, 5) * s for s in (0.2, 0.4, 0.6, 0.8, 1.0, 1.2)]
    X = [np.column_stack([np.ones(5), x]) for x in xs]
    As = np.array([x.T @ x for x in X])
    pred = jackknife_sd(As, As, np.arange(6))
    Xa = np.vstack(X)
    var = []
    for _ in range(1500):
        y = [rng.normal(size=5) for _ in X]
        folds = np.array([np.linalg.lstsq(np.vstack([X[j] for j in range(6) if j != i]),
                                          np.concatenate([y[j] for j in range(6) if j != i]),
                                          rcond=None)[0] for i in range(6)])
        var.append(5 / 6 * ((folds - folds.mean(0)) ** 2).sum(0))
    sim = np.sqrt(np.mean(var, axis=0))
    assert pred == pytest.approx(sim, rel=0.04)
    assert pred[1] > np.sqrt(np.linalg.inv(Xa.T @ Xa)[1, 1])  # the jackknife is conservative


@pytest.fixture(scope="module")
def two_runs():
    st = PlanSettings(oils=("VG320",), roughness=(4.0, 2.0), bath_C=(30.0,),
                      profiles=("trapezoid",), duration_s=20.0, sample_interval_s=0.5)
    runs = [Candidate("VG320", 4.0, 30.0, "trapezoid"), Candidate("VG320", 2.0, 30.0,
                                                                  "trapezoid")]
    data = validate(plan_data(st, runs), builtin_fluids(), "test", "fit")
    return seed_case(), data


def test_fisher_columns_match_finite_differences_of_the_forward_model(two_runs):
    """The AD Jacobian (ln scale, gamma) against central differences of the loop's own
    ForwardModel.power (its numpy path), and the pressure-viscosity column against
    differences of the model with nu exp(d_alpha p) at 20 MPa."""
    case, data = two_runs
    p = 20e6
    s = oil_samples(data, case.region1.gap, pressure_gauge_Pa=p)
    model = ForwardModel(s, case, data.oils)
    spec, _ = decide_spec(s, model.geometry, case, "eq6")
    assert spec.free == ("scale", "gamma")
    x = np.array([0.1, 0.5])
    jac, _ = base_jacobian(model, spec, x, np.full(s.n, p))
    h = 1e-6
    for j in range(2):
        xp, xm = x.copy(), x.copy()
        xp[j] += h
        xm[j] -= h
        fd = (model.power(spec.law(xp)) - model.power(spec.law(xm))) / (2 * h)
        assert jac[:, j] == pytest.approx(fd, rel=1e-6, abs=1e-7 * np.abs(fd).max())
    da = 1e-3  # 1/GPa
    nu = s.nu_m2_s

    def at(d):  # Barus: nu(p) = nu_0 exp(alpha p), alpha moved by d [1/GPa]
        return sum(model.region_powers(spec.law(x), nu=nu * np.exp(d * 1e-9 * p)))
    fd = (at(da) - at(-da)) / (2 * da)
    assert jac[:, 2] == pytest.approx(fd, rel=1e-5, abs=1e-6 * np.abs(fd).max())
    assert np.abs(jac[:, 2]).max() > 0


def test_confounding_names_zero_parallel_and_near_singular_columns():
    """Columns a, b = 2a (parallel), c = a + 0.01 d (condition index sqrt(lmax/lmin) >> 30
    with a), d independent, e = 0 (no information)."""
    rng = np.random.default_rng(1)
    a, d = rng.normal(size=200), rng.normal(size=200)
    J = np.column_stack([a, 2 * a, d, a + 0.01 * d, np.zeros(200)])
    out = confounding(J.T @ J, ("a", "b", "d", "c", "e"))
    assert out["uninformed"] == ["e"]
    assert ("a", "b", pytest.approx(1.0)) in [(x, y, c) for x, y, c in out["pairs"]]
    assert ("a", "c") in [(x, y) for x, y, _ in out["pairs"]]
    assert all(dd["condition_index"] > 30 for dd in out["directions"])
    assert {"a", "b", "c"} >= set().union(*[dd["loadings"] for dd in out["directions"]])
