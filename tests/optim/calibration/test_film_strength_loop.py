"""The loop's film_heating coefficient reported as the film strength s of the Nahme film:
s = c / (delta/(12 k 2 pi R L)) on the rotor-stator clearance (docs/thermal.md#evidence)."""

import math

import pytest

from oilgap.optim.calibration import LoopEstimator
from oilgap.studies.synth import DEFAULT_STRENGTH, SynthConfig, synthesize


def test_accepted_film_heating_carries_its_film_strength_and_interval():
    c_true = DEFAULT_STRENGTH["film_heating"]
    est = LoopEstimator().fit(synthesize(SynthConfig(effect="film_heating", strength=c_true), 0))
    assert [e.name for e in est.effects_] == ["film_heating"]
    e = est.effects_[0]
    # hand: the seed's clearance, delta 1 mm, R 25.4 mm, L 14.76 mm, k 0.13 W/(m K)
    theory = 1e-3 / (12 * 0.13 * 2 * math.pi * 0.0254 * 0.01476)
    s = e.shape["film_strength"]
    assert s == pytest.approx(c_true / theory, rel=0.03)
    lo, hi = e.shape["film_strength_ci"]
    assert lo == pytest.approx(e.ci_low / theory) and hi == pytest.approx(e.ci_high / theory)
    assert lo < s < hi
