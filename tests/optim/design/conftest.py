"""Fixtures of the design-NLP tests: the seed case's problem, built once per module, and
its optimum."""

import pytest

from oilgap.model.io.case_io import seed_case
from oilgap.optim.design import DesignProblem


@pytest.fixture(scope="module")
def prob():
    return DesignProblem(seed_case())


@pytest.fixture(scope="module")
def seed_opt(prob):
    return prob.solve()
