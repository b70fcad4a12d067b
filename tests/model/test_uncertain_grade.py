"""ISO 3448's grade tolerance on nu40 carried to the joint's temperature (issue 27 item 3).

The carried-through factor of VG22 at 2 degC against the Walther equation (ASTM D341)
written out here by hand: ``log10(log10(nu + 0.7)) = A - B log10(T)`` through (nu40, 100)
and (f nu40, nu100); the ratio of the two lines' nu at 275.15 K.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.errors import InputError
from oilgap.model.fluids import ScaledFluid
from oilgap.model.io.case_io import seed_case
from oilgap.model.oils import get_oil
from oilgap.model.uncertain.arrays import joint_loss_arrays
from oilgap.model.uncertain.distributions import default_uncertainty
from oilgap.model.uncertain.grade import carried_factor, walther_rebuilt
from oilgap.model.uncertain.inputs import apply_inputs


def walther_nu_cSt(nu40: float, nu100: float, temp_C: float) -> float:
    """nu [cSt] at temp_C on the line through (40 degC, nu40) and (100 degC, nu100)."""
    z40, z100 = (math.log10(math.log10(v + 0.7)) for v in (nu40, nu100))
    x40, x100, x = (math.log10(t + 273.15) for t in (40.0, 100.0, temp_C))
    z = z40 + (z100 - z40) * (x - x40) / (x100 - x40)  # the straight line in (x, z)
    return 10.0 ** (10.0 ** z) - 0.7


@pytest.mark.parametrize(("f40", "f100"), [(0.9, 1.0), (1.1, 1.0), (1.0, 0.95),
                                           (1.1, 1.05)])
def test_carried_factor_of_vg22_at_2_degC_against_the_walther_equation(f40, f100):
    oil = get_oil("VG22")
    want = walther_nu_cSt(22.0 * f40, 4.5 * f100, 2.0) / walther_nu_cSt(22.0, 4.5, 2.0)
    assert carried_factor(oil, 2.0, f40, f100) == pytest.approx(want, rel=1e-12)


def test_ten_percent_at_40_degC_is_plus_30_minus_25_percent_at_2_degC():
    oil = get_oil("VG22")  # the numbers: +30/-25 % at nominal nu100
    assert carried_factor(oil, 2.0, 1.1) == pytest.approx(1.30, abs=0.005)
    assert carried_factor(oil, 2.0, 0.9) == pytest.approx(0.754, abs=0.005)
    assert carried_factor(oil, 40.0, 1.1) == pytest.approx(1.1, rel=1e-12)  # its definition
    assert carried_factor(oil, 100.0, 1.1) == pytest.approx(1.0, rel=1e-12)


def test_the_uniform_factor_stays_an_option_and_the_two_compose():
    case = seed_case()
    uniform = apply_inputs(case, {"nu_factor_all_temperatures": 1.1}).oil
    assert isinstance(uniform, ScaledFluid) and uniform.factor == 1.1
    both = apply_inputs(case, {"nu40_factor": 1.1, "nu_factor_all_temperatures": 1.2}).oil
    assert both.factor == 1.2 and both.base.nu40_cSt == pytest.approx(24.2, rel=1e-15)
    assert apply_inputs(case, {"nu40_factor": 1.0}).oil is case.oil


def test_a_fluid_without_a_walther_line_refuses_nu40_factor_and_defaults_to_the_uniform():
    case = replace(seed_case(), oil=get_oil("air"))
    with pytest.raises(InputError, match="nu_factor_all_temperatures"):
        apply_inputs(case, {"nu40_factor": 1.1})
    with pytest.raises(InputError, match="nu40_factor"):
        joint_loss_arrays(case, {"nu40_factor": [1.1]}, "none")
    assert default_uncertainty(case).names[0] == "nu_factor_all_temperatures"
    with pytest.raises(InputError, match="nu100_factor"):
        walther_rebuilt(get_oil("VG22"), 1.0, -0.5)
    with pytest.raises(InputError, match=r"nu100_factor = 6.*below 4.889"):
        apply_inputs(seed_case(), {"nu100_factor": 6.0})  # 27 cSt at 100 degC > 22 at 40


def test_vector_rows_follow_the_rebuilt_line():
    case = seed_case()
    rng = np.random.default_rng(4)
    rows = {"nu40_factor": rng.uniform(0.9, 1.1, 40), "nu100_factor": rng.uniform(0.95, 1.05, 40)}
    got = joint_loss_arrays(case, rows, "none")
    want = [joint_loss_arrays(apply_inputs(case, {k: float(v[i]) for k, v in rows.items()}),
                              {}, "none") for i in range(40)]
    np.testing.assert_allclose(got, np.array(want, dtype=float), rtol=1e-12, atol=0)
