"""The design NLP with the case's rolling bearing (issue 11): objective, totals, balance.

The bearing's friction and drag do not depend on the design variables (R, delta, d_r,
d_s, L): at a fixed oil temperature the optimum must be the one without the bearing,
with the total raised by exactly the bearing's mean power. Under ``full`` its heat goes
into the oil: the optimum's temperature must satisfy ``T = T_sea + R (P1 + P2 + P_b)``
with P_b computed here by a second method (the time mean over the cycle's 1500 samples
of :func:`oilgap.model.bearing.bearing_power`, not the NLP's speed-distribution
quadrature) at the oil's viscosity at T. The NLP's reported total must equal ``oilgap
evaluate``'s total of the optimal design in the same mode (the case's friction law is
the smooth one, the NLP's, so that the two compose the same laws).
"""

from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.bearing import bearing_power
from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.case import ThermalSpec
from oilgap.model.evaluation import evaluate_case
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import operating_temperature
from oilgap.model.oil_properties import seawater_gauge_pressure
from oilgap.model.units import celsius_to_kelvin
from oilgap.optim.design import DesignProblem, compare_heating

SPEC = ThermalSpec(sea_temp_C=2.0, resistance_K_W=0.5, heat_capacity_J_K=5e4)


@pytest.fixture(scope="module")
def cases():
    """The seed (smooth C_m, a heat path) with and without a 6809 (SKF model, defaults)."""
    seed = seed_case()
    plain = replace(seed, friction=seed.friction.smooth(), thermal=SPEC)
    return plain, replace(plain, bearing=bearing_spec_from({"designation": "6809"}))


def sample_mean_bearing_power(case, oil_temp_C):
    """Second method: the bearing's power averaged over the cycle's own samples [W]."""
    nu, _, _ = case.oil.properties(celsius_to_kelvin(oil_temp_C),
                                   seawater_gauge_pressure(case.operating.depth_m))
    cyc = case.duty_cycle
    p = np.asarray(bearing_power(case.bearing, cyc.omega_rad_s, float(nu)), dtype=float)
    return float(p @ cyc.sample_weights())


@pytest.mark.parametrize("mode", ["none", "film"])
def test_at_a_fixed_oil_temperature_the_bearing_shifts_the_total_not_the_optimum(cases, mode):
    plain, with_b = cases
    r0 = DesignProblem(plain, thermal=mode).solve()
    r1 = DesignProblem(with_b, thermal=mode).solve()
    pb = sample_mean_bearing_power(with_b, with_b.operating.oil_temp_C)
    assert 5.0 < pb < 15.0  # SKF, 61809 at 320 cSt: rolling 4.7 + drag 5.3 W (docs/notes)
    assert r1.optimal.bearing_power_W == pytest.approx(pb, rel=1e-9)
    np.testing.assert_allclose(r1.optimal.x_mm, r0.optimal.x_mm, rtol=1e-7, atol=1e-9)
    assert r1.optimal.mean_power_W == pytest.approx(r0.optimal.mean_power_W + pb, rel=1e-9)
    assert r1.active_constraints == r0.active_constraints
    for k, mu in r0.multipliers.items():  # dP*/d(bound): the constant does not move it
        assert r1.multipliers[k].value == pytest.approx(mu.value, rel=1e-5, abs=1e-9)
    ev = evaluate_case(r1.to_case(), thermal=mode)
    assert ev.total_mean_power_W == pytest.approx(r1.optimal.mean_power_W, rel=1e-9)
    assert ev.bearings[0].mean_power_W == pytest.approx(pb, rel=1e-9)
    d = r1.optimal.to_dict()
    assert d["mean_power_W"] == pytest.approx(
        d["region1_power_W"] + d["region2_power_W"] + d["bearing_power_W"], rel=1e-12)


def test_under_full_the_bearing_heat_is_in_the_balance(cases):
    plain, with_b = cases
    r0 = DesignProblem(plain, thermal="full").solve()
    r1 = DesignProblem(with_b, thermal="full").solve()
    t = r1.oil_temp_C
    pb = sample_mean_bearing_power(with_b, t)
    o = r1.optimal
    assert o.bearing_power_W == pytest.approx(pb, rel=1e-9)
    # T = T_sea + R (P1 + P2 + P_b + Q), P_b by the second method
    resid = t - SPEC.sea_temp_C - SPEC.resistance_K_W * (
        o.region1_power_W + o.region2_power_W + pb + SPEC.other_heat_W)
    assert abs(resid) < 1e-8
    assert o.mean_power_W == pytest.approx(o.region1_power_W + o.region2_power_W + pb,
                                           rel=1e-9)
    # its heat warms the oil: hotter than without the bearing, by less than R P_b
    # (a warmer oil loses less in the clearances)
    assert r0.oil_temp_C < t < r0.oil_temp_C + SPEC.resistance_K_W * pb
    # what oilgap evaluate solves for the optimal design: the same state
    op = operating_temperature(r1.to_case(), "full")
    assert op.oil_temp_C == pytest.approx(t, abs=1e-8)
    assert op.mean_power_W == pytest.approx(o.mean_power_W, rel=1e-9)
    assert op.bearing_mean_power_W == pytest.approx(pb, rel=1e-9)
    # the heating comparison lists the bearing beside the clearances
    ch = compare_heating(DesignProblem(with_b, thermal="full")).changes()
    assert ch["bearing_power_W"]["with_heating"] == pytest.approx(pb, rel=1e-9)
    assert ch["bearing_power_W"]["without_heating"] == pytest.approx(
        sample_mean_bearing_power(with_b, with_b.operating.oil_temp_C), rel=1e-9)


def test_a_case_without_bearing_reports_no_bearing(cases):
    plain, _ = cases
    r = DesignProblem(plain, thermal="film").solve()
    assert r.optimal.bearing_power_W is None
    assert "bearing_power_W" not in r.optimal.to_dict()
    assert r.optimal.mean_power_W == r.optimal.region1_power_W + r.optimal.region2_power_W
