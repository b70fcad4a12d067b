"""The ``"branches"`` friction form: a smooth maximum of power-law branches.

Its defaults are checked against Eq. 6 written out by hand (Bilgen & Boulos 1973 as
printed in the seed paper), its derivatives against finite differences, its input
checks against the ranges of FRICTION_RANGES."""

import math

import casadi as ca
import numpy as np
import pytest

from oilgap.model.errors import InputError
from oilgap.model.skin_friction import (
    BRANCHES_WIDTH,
    FrictionLaw,
    check_friction_ranges,
    moment_coefficient,
)

BB = FrictionLaw(form="branches", laminar_law="bilgen-boulos")


def eq6_by_hand(re, x):
    """Seed Eq. 6 as printed: (C, beta) by range, times x^0.3."""
    if re < 64:
        c, b = 10.0, -1.0
    elif re < 500:
        c, b = 2.0, -0.6
    elif re < 1e4:
        c, b = 1.03, -0.5
    else:
        c, b = 0.065, -0.2
    return c * x**0.3 * re**b


@pytest.mark.parametrize("re, x", [(10.0, 0.01), (30.0, 0.05), (150.0, 0.01), (300.0, 0.1),
                                   (1500.0, 0.01), (4000.0, 0.03), (3e4, 0.01), (1e5, 0.2)])
def test_defaults_equal_eq6_away_from_crossings(re, x):
    # e.g. Re 1500, x 0.01: 1.03 * 0.01^0.3 / sqrt(1500) = 1.03 * 0.251189 / 38.7298
    #   = 6.6804e-3; the next branch (2 Re^-0.6 = 2 * 0.251189 * 0.012449 = 6.254e-3) is
    #   6.6 % lower, so the log-sum-exp adds 0.02 * ln(1 + exp(-0.0659 / 0.02)) = 0.07 %.
    if (re, x) == (1500.0, 0.01):
        assert eq6_by_hand(re, x) == pytest.approx(6.6804e-3, rel=1e-4)
    assert moment_coefficient(re, x, BB) == pytest.approx(eq6_by_hand(re, x), rel=2e-3)


def test_crossings_of_the_published_branches():
    # 10/Re = 2 Re^-0.6 at Re = 5^2.5 = 55.90; 2 Re^-0.6 = 1.03 Re^-0.5 at
    # Re = (2/1.03)^10 = 762.0; 1.03 Re^-0.5 = 0.065 Re^-0.2 at Re = (1.03/0.065)^(1/0.3)
    # = 9996: at a crossing the log-sum-exp is the branch times exp(width ln 2) (the other
    # branches, >= 10 % lower there, add < 1e-6).
    x = 0.02
    for re, (c, b) in ((5**2.5, (10.0, -1.0)), ((2 / 1.03) ** 10, (2.0, -0.6)),
                       ((1.03 / 0.065) ** (1 / 0.3), (1.03, -0.5))):
        branch = c * x**0.3 * re**b
        assert moment_coefficient(re, x, BB) == pytest.approx(
            branch * math.exp(BRANCHES_WIDTH * math.log(2.0)), rel=1e-6)
    assert (2 / 1.03) ** 10 == pytest.approx(762.0, rel=1e-3)
    assert (1.03 / 0.065) ** (1 / 0.3) == pytest.approx(9996, rel=1e-3)


def test_deviation_from_eq6_where_its_breaks_are_not_crossings():
    # Between 55.9 and 64 Eq. 6 keeps 10/Re though 2 Re^-0.6 is larger: at Re = 63.9 the
    # ratio is 0.2 * 63.9^0.4 = 1.0549; between 500 and 762 it takes 1.03 Re^-0.5 though
    # 2 Re^-0.6 is larger: at 500 the ratio is (2/1.03) 500^-0.1 = 1.0431.
    x = 0.01
    r64 = moment_coefficient(63.9, x, BB) / eq6_by_hand(63.9, x)
    r500 = moment_coefficient(500.0, x, BB) / eq6_by_hand(500.0, x)
    assert 0.2 * 63.9**0.4 == pytest.approx(1.0549, abs=1e-4)
    assert r64 == pytest.approx(1.0549, abs=0.004)
    assert r500 == pytest.approx(1.0431, abs=0.004)
    re = np.logspace(0, 6, 4001)
    ratio = moment_coefficient(re, x, BB) / np.array([eq6_by_hand(r, x) for r in re])
    assert ratio.min() > 1 - 1e-12           # never below Eq. 6 (a max of its branches)
    assert ratio.max() < 1.058   # 5.5 % + the smoothing (measured 5.68 %)
    # within 0.1 % wherever the next branch is 6 % (0.06 in ln C_m) or more below the
    # largest: width * exp(-0.06 / width) = 0.02 * e^-3 = 0.001. The slopes differ by 0.4,
    # 0.1 and 0.3 at the crossings 55.9, 762 and 9996: a factor exp(0.06 / 0.4) = 1.16,
    # exp(0.6) = 1.82 and exp(0.2) = 1.22 in Re (1.25, 1.9, 1.25 taken).
    near = (re > 55.9 / 1.25) & (re < 64.0 * 1.25)
    near |= (re > 500.0 / 1.25) & (re < 762.0 * 1.9)
    near |= np.abs(np.log(re / 9996.0)) < math.log(1.25)
    assert np.abs(ratio[~near] - 1).max() < 1e-3


def test_couette_law_enters_the_maximum():
    # x = 0.01, Re = 20: Couette 8 (1.01)^2 / (2.01 * 20) = 0.20300; Eq. 6 laminar branch
    # 10 * 0.01^0.3 / 20 = 0.12559, 37 % lower: the maximum is Couette (+ ~0 from the LSE)
    law = FrictionLaw(form="branches")
    assert moment_coefficient(20.0, 0.01, law) == pytest.approx(0.20300, rel=1e-4)
    assert moment_coefficient(20.0, 0.01, BB) == pytest.approx(0.12559, rel=1e-4)


def test_own_gap_exponent_per_branch_and_scale_and_gamma():
    # turbulent branch with alpha 0: C_m = 0.065 * 1e5^-0.2 = 0.065 * 0.1 = 6.5e-3 at any gap;
    # scale 1.2 and T = 2, gamma 0.5 multiply: 6.5e-3 * 1.2 * sqrt(2) = 1.10309e-2
    law = FrictionLaw(form="branches", branch_alpha=(0.3, 0.3, 0.3, 0.0), scale=1.2,
                      gamma=0.5)
    for x in (0.005, 0.02, 0.05):
        assert moment_coefficient(1e5, x, law, roughness_T=2.0) == pytest.approx(
            1.10309e-2, rel=1e-4)


def test_casadi_gradient_matches_finite_differences():
    law = FrictionLaw(form="branches", branch_alpha=(0.1, 0.25, 0.3, 0.05), gamma=0.4)
    re, x, t = ca.SX.sym("re"), ca.SX.sym("x"), ca.SX.sym("t")
    cm = ca.log(moment_coefficient(re, x, law, roughness_T=t))
    f = ca.Function("f", [re, x, t], [cm, ca.gradient(cm, ca.vertcat(re, x, t))])
    for p in ((30.0, 0.01, 1.0), (58.0, 0.02, 1.5), (700.0, 0.03, 1.2), (9990.0, 0.01, 2.0),
              (5e4, 0.04, 1.0)):
        val, grad = f(*p)
        assert float(val) == pytest.approx(math.log(moment_coefficient(*p[:2], law, p[2])),
                                           rel=1e-12)
        for i in range(3):
            h = 1e-6 * p[i]
            up, dn = list(p), list(p)
            up[i] += h
            dn[i] -= h
            fd = (math.log(moment_coefficient(up[0], up[1], law, up[2]))
                  - math.log(moment_coefficient(dn[0], dn[1], law, dn[2]))) / (2 * h)
            assert float(grad[i]) == pytest.approx(fd, rel=1e-6, abs=1e-9)


def test_no_overflow_at_extreme_reynolds():
    law = FrictionLaw(form="branches")
    v = moment_coefficient(np.array([1e-12, 1e-3, 1e9]), 0.01, law)
    assert np.all(np.isfinite(v)) and np.all(v > 0)


@pytest.mark.parametrize("kw, field", [
    ({"branch_C": (10.0, 2.0, 1.03)}, "branch_alpha"),
    ({"branch_C": (10.0, 2.0, -1.0, 0.065)}, "branch_C"),
    ({"branch_beta": (-1.0, -0.6, float("nan"), -0.2)}, "branch_beta"),
    ({"branch_alpha": "0.3"}, "branch_alpha"),
])
def test_bad_branches_name_the_key(kw, field):
    with pytest.raises(InputError) as e:
        FrictionLaw(form="branches", **kw)
    assert field in str(e.value)


def test_ranges_apply_per_branch():
    law = FrictionLaw(form="branches", branch_alpha=(0.3, 0.3, 2.5, 0.3))
    with pytest.raises(InputError, match=r"branch_alpha\[3\]"):
        check_friction_ranges(law)
    assert check_friction_ranges(FrictionLaw(form="branches")).form == "branches"
