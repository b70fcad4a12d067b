"""The NLP's scaling: ln(mm) for R, delta, L and mm for the groove depths, by hand, and
its inverse."""

import math

import numpy as np
import pytest

from oilgap.optim.design import VARIABLE_LABELS, VARIABLES, from_nlp, to_nlp


def test_to_nlp_by_hand():
    y = to_nlp(np.array([0.020, 0.001, 0.0005, 0.00025, 0.010]))
    assert y == pytest.approx([math.log(20.0), 0.0, 0.5, 0.25, math.log(10.0)], rel=1e-14,
                              abs=1e-15)


def test_from_nlp_inverts_to_nlp():
    x = np.array([0.0231, 0.00087, 0.0, 0.0013, 0.0177])
    assert from_nlp(to_nlp(x)) == pytest.approx(x, rel=1e-14, abs=1e-18)
    y = np.array([3.1, -0.2, 0.7, 0.0, 2.9])
    assert to_nlp(from_nlp(y)) == pytest.approx(y, rel=1e-14, abs=1e-15)


def test_inputs_are_not_modified():
    x = np.array([0.02, 0.001, 0.0005, 0.0, 0.01])
    before = x.copy()
    to_nlp(x)
    from_nlp(x)
    assert np.array_equal(x, before)


def test_every_variable_has_its_labels():
    assert tuple(VARIABLE_LABELS) == VARIABLES
    assert [VARIABLE_LABELS[v][0] for v in VARIABLES] == [
        "R_mm", "delta_mm", "rotor_groove_depth_mm", "stator_groove_depth_mm", "L_mm"]
