"""Shared test set-up: figures on the Agg backend; hypothesis derandomized (the same
examples on every run and machine, no example database: a property test fails in CI
exactly when it fails here); the test joint's TOML and a writer."""

import matplotlib
import pytest
from hypothesis import settings

matplotlib.use("Agg")
settings.register_profile("oilgap", derandomize=True, database=None)
settings.load_profile("oilgap")

TEST_JOINT_TOML = """
name = "test joint"
[region1]
T1_mm = 23.9
T2_mm = 25.4
T3_mm = 26.4
T4_mm = 27.9
length_mm = 14.76
[region2]
radius_mm = 22.0
length_mm = 14.24
gap_mm = 5.0
[oil]
name = "VG22"
[operating]
depth_m = 0.0
oil_temp_C = 40.0
[friction]
gamma = 0.5
"""
"""The seed joint's geometry (Table 1, T = 4) at 40 degC and the surface, gamma = 0.5."""


@pytest.fixture(scope="session")
def seed_toml() -> str:
    """TOML text of the test joint (:data:`TEST_JOINT_TOML`)."""
    return TEST_JOINT_TOML


@pytest.fixture
def write_file(tmp_path):
    """Write text to a file in the test's temporary folder and return its path."""
    def write(text: str, name: str = "case.toml"):
        p = tmp_path / name
        p.write_text(text)
        return p
    return write
