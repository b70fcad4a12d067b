"""The calibration's forward model takes the friction transition as a law parameter (a
candidate base of the loop): each law's power is its own, by hand, whatever was asked
before (the kept shapes are keyed by the transition)."""

import numpy as np

from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.viscous_loss import clearance_power
from oilgap.optim.calibration import ForwardModel


def _by_hand(s, case, law):
    r1, r2 = case.region1, case.region2
    p1 = clearance_power(s.omega, s.nu_m2_s, s.density_kg_m3, r1.T2, r1.T3 - r1.T2,
                         r1.length, law, s.roughness_T)
    p2 = clearance_power(s.omega, s.nu_m2_s, s.density_kg_m3, r2.radius, r2.gap,
                         r2.length, law, 1.0)
    return p1 + p2


def test_forward_model_takes_either_transition(rig):
    s, case = rig.samples, rig.case
    m = ForwardModel(s, case, rig.oils)
    laws = [FrictionLaw(form="smooth", gamma=0.5, transition=t) for t in ("reynolds", "taylor")]
    got = [m.base_power(law) for law in laws]  # reynolds first: taylor must not reuse it
    for law, p in zip(laws, got, strict=True):
        np.testing.assert_allclose(p, _by_hand(s, case, law), rtol=1e-12, atol=0)
    assert not np.allclose(got[0], got[1], rtol=1e-3)
