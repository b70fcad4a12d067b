"""The plan's information under the Couette floor, against hand calculations and the
loop's own numpy forward model.

* Where the floor's kink lies, by hand: in a laminar annulus the smooth Eq. 6 of the
  Couette laminar law is ``ln C_m = ln C_c + smooth_relu(d, 0.02)``, ``d = ln(C_bb /
  C_c)`` with Eq. 6's laminar branch ``C_bb = 10 x^0.3 / Re`` and exact Couette
  ``C_c = 8 (1 + x)^2 / ((2 + x) Re)`` (seed Eq. 5, x = delta/R), ``smooth_relu(d, w) =
  (d + sqrt(d^2 + w^2)) / 2``: a scale s multiplies C_m and the floor binds below
  ``ln s = -smooth_relu(d, w)`` (Re cancels).
* Below the kink the annulus is floored: its power no longer depends on the scale, so
  ``dP / d ln s`` is exactly the power of region 2 (``s`` times its shape), the only
  region still above Couette; CasADi's derivative through ``fmax`` against central
  differences of ``ForwardModel.power`` (the loop's numpy path, ``np.maximum``).
* The lower half-width carried through the kink, by hand.
"""

import math

import numpy as np
import pytest

from oilgap.model.io.case_io import seed_case
from oilgap.model.measured.data import oil_samples
from oilgap.model.measured.validation import validate
from oilgap.model.oils import builtin_fluids
from oilgap.optim.calibration.forward import ForwardModel
from oilgap.optim.calibration.spec import decide_spec
from oilgap.optim.planning import base_jacobian
from oilgap.optim.planning.floor import below_floor, floor_gaps, floored_half_width
from oilgap.studies.plan.candidates import Candidate, plan_data
from oilgap.studies.plan.settings import PlanSettings


@pytest.fixture(scope="module")
def laminar_runs():
    """Two short VG1000 runs at 25 degC (Re of region 1 below 1: laminar throughout)."""
    st = PlanSettings(oils=("VG1000",), roughness=(4.0, 2.0), bath_C=(25.0,),
                      profiles=("sine",), duration_s=20.0, sample_interval_s=0.5)
    runs = [Candidate("VG1000", 4.0, 25.0, "sine"), Candidate("VG1000", 2.0, 25.0, "sine")]
    case = seed_case()
    data = validate(plan_data(st, runs), builtin_fluids(), "test", "fit")
    model = ForwardModel(oil_samples(data, case.region1.gap), case, data.oils)
    spec, _ = decide_spec(model.samples, model.geometry, case, "eq6")
    return model, spec


def test_kink_of_the_laminar_annulus_by_hand(laminar_runs):
    model, spec = laminar_runs
    r1 = model.geometry.regions[0]
    x = float(np.median(model.samples.gap1_m)) / r1.radius_m
    d = math.log(10.0 * x ** 0.3 * (2.0 + x) / (8.0 * (1.0 + x) ** 2))
    kink = -0.5 * (d + math.sqrt(d * d + 0.02 ** 2))
    gaps = floor_gaps(model, spec, np.array([0.0, 0.5]))
    assert gaps == pytest.approx([-kink, -kink], rel=1e-6)
    assert math.exp(-gaps[0]) == pytest.approx(1 / 1.0009, abs=2e-5)  # 0.09 % above Couette
    # from scale 1.1 the first kink is ln 1.1 further down
    assert floor_gaps(model, spec, np.array([math.log(1.1), 0.5])) == pytest.approx(
        -kink + math.log(1.1), rel=1e-6)


def test_jacobian_below_the_kink_is_region_2_alone(laminar_runs):
    model, spec = laminar_runs
    x = np.array([0.0, 0.5])
    gaps = floor_gaps(model, spec, x)
    at = below_floor(x, spec, gaps, model.samples.run_code)
    xb = at[0]
    assert at == pytest.approx(np.repeat(xb[None], len(at), axis=0), abs=1e-12)
    assert xb[0] < -gaps.max()  # just below the kink, both runs
    jac, _ = base_jacobian(model, spec, at)
    h = 1e-6
    for j in range(2):
        xp, xm = xb.copy(), xb.copy()
        xp[j] += h
        xm[j] -= h
        fd = (model.power(spec.law(xp)) - model.power(spec.law(xm))) / (2 * h)
        assert jac[:, j] == pytest.approx(fd, rel=1e-6, abs=1e-7 * np.abs(fd).max())
    p1, p2 = model.region_powers(spec.law(xb))
    assert jac[:, 0] == pytest.approx(p2, rel=1e-9)  # the annulus is floored: no scale
    above, _ = base_jacobian(model, spec, x)
    assert above[:, 0] == pytest.approx(sum(model.region_powers(spec.law(x))), rel=1e-9)
    assert jac[:, 0].sum() / above[:, 0].sum() < 0.2  # region 2: 14 % of the power


def test_floored_half_width_by_hand():
    # t sd_a = 3 reaches 2 past a kink at 1; below it the sd is 5 times larger: 1 + 2 x 5
    assert floored_half_width(3.0, 1.0, 1.0, 5.0) == pytest.approx(11.0)
    assert floored_half_width(0.8, 1.0, 1.0, 5.0) == 0.8  # the kink is never reached
    assert floored_half_width(3.0, math.inf, 1.0, 5.0) == 3.0  # no kink
    assert floored_half_width(3.0, 1.0, 1.0, math.inf) == math.inf  # nothing below it
