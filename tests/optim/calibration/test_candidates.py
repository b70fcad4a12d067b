"""Stage 5a, candidates: screening statuses, exact-form variants, column bookkeeping."""

from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.effects import EFFECTS
from oilgap.optim.calibration import (
    BaseSpec,
    Candidates,
    ForwardModel,
    exact_form_variants,
    fit_model,
    screen_candidates,
)

SPEC = BaseSpec(("C", "gamma"), {"alpha": 0.3, "beta": -1.0})


def _calibrated(rig, samples_factory, case=None, **kw):
    case = case or rig.case
    s0 = samples_factory(**kw)
    rng = np.random.default_rng(0)
    y = ForwardModel(s0, case, rig.oils).power(rig.law) + rng.normal(0, 0.3, s0.n)
    m = ForwardModel(samples_factory(power=y, **kw), case, rig.oils)
    return m, fit_model(m, SPEC, SPEC.start({"C": 10.0, "gamma": 0.0}))


def test_exact_form_variants(rig):
    s = rig.samples
    m = ForwardModel(s, rig.case, rig.oils)
    gmax = np.max(np.abs(s.omega)) * rig.case.region1.radius / rig.case.region1.gap
    lam2 = exact_form_variants("shear_thinning", s, m.geometry)
    assert lam2 == pytest.approx([(0.5 / gmax) ** 2, (1 / gmax) ** 2, (2 / gmax) ** 2],
                                 rel=1e-12)
    assert exact_form_variants("sensor_delay", s, m.geometry) == (0.5, 1.0, 2.0, 5.0)
    assert -30.0 in exact_form_variants("thermal_lag", s, m.geometry)
    assert exact_form_variants("seal_coulomb_friction", s, m.geometry) == ()


def test_every_effect_gets_a_status_and_candidates_get_columns(rig, samples_factory):
    m, base = _calibrated(rig, samples_factory)
    c = screen_candidates(m, SPEC, base, list(EFFECTS))
    assert [d["name"] for d in c.info] == list(EFFECTS)
    status = {d["name"]: d["status"] for d in c.info}
    assert all(status[n] == "candidate" for n in c.usable)
    # the seal column is tau = 1 N m: |omega| itself
    j = c.name.index("seal_coulomb_friction")
    assert c.variant[j] is None and np.allclose(c.columns[:, j], np.abs(m.samples.omega))
    # an exact-form column is the exact model minus the calibration
    assert "sensor_delay" in c.usable
    k = next(i for i, n in enumerate(c.name) if n == "sensor_delay" and c.variant[i] == 1.0)
    want = m.power(base.law, {"sensor_delay": 1.0}) - m.power(base.law)
    assert np.allclose(c.columns[:, k], want) and c.nonneg[k]
    assert c.label(k) == "sensor_delay (exact form, 1)"
    assert c.columns.shape == (m.samples.n, len(c.name))
    assert list(c.group) == [c.usable.index(n) for n in c.name]


def test_rig_without_bearing_and_data_without_temperature_change(rig, samples_factory):
    case = replace(rig.case, region2=None)
    m, base = _calibrated(rig, samples_factory, case=case, temp_rate_K_s=0.0)
    status = {d["name"]: d["status"] for d in screen_candidates(
        m, SPEC, base, ["bearing_ball_churning", "bearing_ball_drag", "thermal_lag"]).info}
    assert status["bearing_ball_churning"] == "not applicable: the rig has no bearing region"
    assert status["bearing_ball_drag"].startswith("not applicable: the case has no [bearing]")
    assert status["thermal_lag"] == "inactive on these data: no temperature law for dP/dT"


def test_feature_scale_is_the_rms_of_the_linear_column():
    F = np.array([[3.0, 1.0, 0.0], [4.0, 1.0, 2.0]])
    c = Candidates(info=[], usable=["a", "b"], columns=F, name=["a", "a", "b"],
                   variant=[None, 2.0, None], nonneg=[True, True, False])
    assert c.feature_scale() == pytest.approx({"a": np.sqrt(12.5), "b": np.sqrt(2.0)})
    assert c.columns_of("a") == [0, 1] and c.label(1) == "a (exact form, 2)"


def test_a_variant_that_leaves_the_fluids_law_is_set_aside(rig, samples_factory):
    # temperature falling 12 K/s: the exact form of a -30 s lag puts the oil at
    # T + 30 * (-12) = about -330 degC, below absolute zero, where the oil's law has no value
    m, base = _calibrated(rig, samples_factory, dt=0.01, temp_rate_K_s=-12.0)
    assert not np.all(np.isfinite(m.power(base.law, {"thermal_lag": -30.0})))
    c = screen_candidates(m, SPEC, base, list(EFFECTS))
    assert np.all(np.isfinite(c.columns))
    lags = [c.variant[j] for j, n in enumerate(c.name) if n == "thermal_lag"]
    assert -30.0 not in lags
