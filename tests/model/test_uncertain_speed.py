"""The vectorised balance's cheaper losses (issue 27 item 5): the same numbers.

What is compared: Eq. 6's numpy path (``Re^beta`` as ``exp(beta ln Re)``) against the
branches written out here with Python's ``**`` on floats; SKF's inlet-shear and
boundary-film factors against their catalogue formulas written out here, with and without
the speed parts evaluated beforehand (:func:`skf_speed_terms`, bit for bit); and the rows'
friction scale carried in the law against the scalar path (``apply_inputs``), a scale
below 1 floored at exact Couette node by node. The loss evaluated in calls of
:data:`EVAL_ROWS` rows equals one call to a rounding unit (the cycle mean's
matrix-vector product may round a row by its place in a call).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from oilgap.model.bearing.friction import bearing_moment_terms, skf_moments, skf_speed_terms
from oilgap.model.bearing.laws import inlet_shear_factor, sliding_friction_coefficient
from oilgap.model.io.case_io import read_case_toml
from oilgap.model.joint_loss import operating_temperature
from oilgap.model.skin_friction import bilgen_boulos_cm
from oilgap.model.uncertain import arrays
from oilgap.model.uncertain.arrays import joint_loss_arrays
from oilgap.model.uncertain.inputs import apply_inputs
from oilgap.model.units import rad_s_to_rpm

SEED_THERMAL = Path(__file__).resolve().parents[1] / "golden" / "data" / "seed_thermal.toml"


@pytest.fixture(scope="module")
def bearing_case(tmp_path_factory):
    p = tmp_path_factory.mktemp("speed") / "bearing.toml"
    p.write_text(SEED_THERMAL.read_text() + '\n[bearing]\ndesignation = "6809"\n')
    return read_case_toml(p)


def test_eq6_numpy_path_equals_the_branches_written_out():
    # Eq. 6: C_m = C x^0.3 Re^beta, (C, beta) = (10, -1) below 64, (2, -0.6) to 500,
    # (1.03, -0.5) to 1e4, (0.065, -0.2) above; each point by Python floats
    rng = np.random.default_rng(3)
    re = np.concatenate([np.exp(rng.uniform(np.log(0.5), np.log(1e6), 4000)),
                         [64.0, 500.0, 1e4, np.nextafter(64.0, 0), np.nextafter(1e4, 0)]])
    x = 0.0213

    def eq6(r):
        c, b = ((10.0, -1.0) if r < 64 else (2.0, -0.6) if r < 500
                else (1.03, -0.5) if r < 1e4 else (0.065, -0.2))
        return c * x**0.3 * r**b
    want = np.array([eq6(float(r)) for r in re])
    got = bilgen_boulos_cm(re, x)
    np.testing.assert_allclose(got, want, rtol=2e-15, atol=0)


def test_skf_factors_with_speed_parts_given_are_the_catalogue_formulas(bearing_case):
    spec = bearing_case.bearing
    n = np.array([[10.0, 700.0, 3500.0]])
    nu = np.array([[4.0], [22.0], [310.0]])
    dm = 0.5 * (45.0 + 58.0)  # 61809: d 45, D 58 mm
    # phi_ish = 1/(1 + 1.84e-9 (n dm)^1.28 nu^0.64); phi_bl = exp(-2.6e-8 (n nu)^1.4 dm)
    ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_bl = np.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    np.testing.assert_allclose(inlet_shear_factor(n, nu, dm), ish, rtol=1e-14)
    np.testing.assert_allclose(sliding_friction_coefficient(n, nu, dm, 0.12, 0.05),
                               phi_bl * 0.12 + (1 - phi_bl) * 0.05, rtol=1e-14)
    w = n * np.pi / 30.0  # [rad/s]; the speed terms at the rpm bearing_moment_terms uses
    for a, b in ((skf_moments(spec, n, nu, skf_speed_terms(spec, n)), skf_moments(spec, n, nu)),
                 (bearing_moment_terms(spec, w, nu * 1e-6,
                                       skf_speed_terms(spec, rad_s_to_rpm(np.abs(w)))),
                  bearing_moment_terms(spec, w, nu * 1e-6))):
        assert a.keys() == b.keys()
        for k in a:
            assert np.array_equal(a[k], b[k]), k  # the same operations: the same bits


def test_losses_in_calls_of_eval_rows_equal_one_call(bearing_case, monkeypatch):
    rng = np.random.default_rng(5)
    x = {"oil_temp_C": rng.uniform(0, 6, 300), "peak_speed_rpm": rng.uniform(2500, 3500, 300),
         "bearing_drag_scale": rng.uniform(0.5, 2.0, 300)}
    one = joint_loss_arrays(bearing_case, x, "none")
    monkeypatch.setattr(arrays, "EVAL_ROWS", 7)  # each row's loss is its own (the cycle
    # mean's matrix-vector product may round a row by its place in a call: 1 ulp)
    np.testing.assert_allclose(joint_loss_arrays(bearing_case, x, "none"), one,
                               rtol=4e-16, atol=0)
    bulk = joint_loss_arrays(bearing_case, x, "bulk", block_rows=100)
    monkeypatch.setattr(arrays, "EVAL_ROWS", 2048)
    np.testing.assert_allclose(joint_loss_arrays(bearing_case, x, "bulk", block_rows=100),
                               bulk, rtol=1e-13, atol=0)


def test_row_friction_scales_in_the_law_equal_the_scalar_path(bearing_case):
    # scales 0.3-1.2: below 1 the laminar nodes are floored at Couette (the scalar path's
    # law.scale * fs, floored by moment_coefficient), at or above 1 scale * C_m
    fs = np.array([0.3, 0.7, 0.999, 1.0, 1.05, 1.2])
    x = {"friction_scale": fs, "oil_temp_C": np.linspace(0.0, 6.0, fs.size)}
    for mode in ("none", "bulk"):
        got = joint_loss_arrays(bearing_case, x, mode)
        want = [operating_temperature(apply_inputs(bearing_case, {
            k: float(v[i]) for k, v in x.items()}), mode).mean_power_W for i in range(fs.size)]
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=0)
    assert got[0] > 0.3 / 0.7 * got[1]  # the floor: not linear in the scale below 1
