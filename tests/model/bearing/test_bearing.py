"""oilgap.model.bearing: limits (zero speed, zero load), numpy shapes, CasADi against
numpy and finite differences, the one Palmgren law shared with the loop's effect, the
spec's validation naming the TOML key, the validity notes."""

import dataclasses
import math

import casadi as ca
import numpy as np
import pytest

from oilgap.model.bearing import (
    BearingSpec,
    bearing_mean_power,
    bearing_moment_terms,
    bearing_power,
    bearing_torque,
    bearing_validity,
)
from oilgap.model.bearing.laws import (
    V_M_SUBMERGED,
    drag_loss_factor,
    iso_static_load_rating,
    palmgren_viscous_moment,
    rated_viscosity,
)
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.effects.laws import ball_churning_power
from oilgap.model.errors import InputError

BASE = dict(name="61809", series="618", bore_m=0.045, outside_m=0.058, balls=24,
            ball_diameter_m=3.969e-3, radial_load_N=50.0, static_load_rating_N=6100.0)
SKF = BearingSpec(**BASE)
SKF_RS = BearingSpec(**BASE, drag="skf-full")
SKF_AXIAL = BearingSpec(**BASE, axial_load_N=20.0)
SKF_NO_DRAG = BearingSpec(**BASE, drag="none")
PALM = BearingSpec(**{**BASE, "model": "palmgren"})
ALL = (SKF, SKF_RS, SKF_AXIAL, SKF_NO_DRAG, PALM)
W = 2 * math.pi * 3000 / 60
NODES, WEIGHTS = DutyCycle.sine().speed_distribution()


def test_defaults_by_lubrication():
    assert SKF.f0 == 4.0 and SKF.k_rs == 0.0 and SKF.submerged
    bath = BearingSpec(**BASE, submerged=False, oil_level_m=0.01)
    assert bath.f0 == 2.0 and bath.k_rs == 3e-8
    assert SKF.pitch_diameter_m == pytest.approx(0.0515)
    assert SKF.oil_level_ratio == 1.2
    assert bath.oil_level_ratio == pytest.approx(10 / 51.5)


@pytest.mark.parametrize("spec", ALL, ids=lambda s: f"{s.model}-{s.drag}-{s.axial_load_N}")
def test_zero_speed_gives_zero_power_and_torque(spec):
    assert float(bearing_power(spec, 0.0, 320e-6)) == 0.0
    assert float(bearing_torque(spec, 0.0, 320e-6)) == 0.0
    p = bearing_power(spec, np.array([0.0, 10.0, -10.0]), 320e-6)
    assert p[0] == 0.0 and p[1] == p[2] > 0
    t = bearing_torque(spec, np.array([-10.0, 10.0]), 320e-6)
    assert t[0] == -t[1] and t[1] > 0  # it opposes the rotation
    terms = bearing_moment_terms(spec, 0.0, 320e-6)
    for name in ("rolling", "drag_vm", "drag_rs"):
        assert terms.get(name, 0.0) == 0.0


@pytest.mark.parametrize("base", [SKF_RS, PALM], ids=["skf", "palmgren"])
def test_zero_load_gives_zero_load_terms_and_no_nan(base):
    spec = dataclasses.replace(base, radial_load_N=0.0, axial_load_N=0.0)
    terms = bearing_moment_terms(spec, np.array([0.0, 100.0, 300.0]), 320e-6)
    for name, v in terms.items():
        assert np.all(np.isfinite(v)), name
    for name in ("rolling", "sliding", "load_dependent"):
        if name in terms:
            assert np.all(terms[name] == 0.0)
    full = bearing_moment_terms(base, 300.0, 320e-6)
    for name in ("drag_vm", "drag_rs", "load_independent"):
        if name in terms:
            assert terms[name][2] == pytest.approx(float(full[name]), rel=1e-14)
    # axial load alone (the F_a > 0 branch with F_r = 0) stays finite and positive
    axial = dataclasses.replace(base, radial_load_N=0.0, axial_load_N=30.0)
    t = bearing_moment_terms(axial, 300.0, 320e-6)
    assert all(np.isfinite(float(v)) and float(v) >= 0 for v in t.values())


def test_shapes_nodes_along_the_last_axis():
    nus = np.array([100e-6, 320e-6, 1000e-6])[:, None]
    for spec in ALL:
        terms = bearing_moment_terms(spec, NODES, nus)
        assert all(np.shape(v) == (3, NODES.size) for v in terms.values())
        mean = bearing_mean_power(spec, NODES, WEIGHTS, nus)
        assert mean.shape == (3,)
        for k, nu in enumerate(nus[:, 0]):
            assert mean[k] == pytest.approx(
                bearing_mean_power(spec, NODES, WEIGHTS, nu), rel=1e-13)
        # the mean is the sample mean of the seed's 1500 samples
        cyc = DutyCycle.sine()
        samples = bearing_power(spec, cyc.omega_rad_s, nus[1, 0])
        assert mean[1] == pytest.approx(samples.mean(), rel=1e-12)


def test_casadi_matches_numpy_and_finite_differences():
    nu = ca.SX.sym("nu")
    for spec in (*ALL, BearingSpec(**BASE, submerged=False, oil_level_m=0.02)):
        p = bearing_mean_power(spec, NODES, WEIGHTS, nu)
        f = ca.Function("f", [nu], [p, ca.gradient(p, nu)])
        for v in (30e-6, 320e-6, 900e-6):
            val, grad = (float(x) for x in f(v))
            assert val == pytest.approx(float(bearing_mean_power(spec, NODES, WEIGHTS, v)),
                                        rel=1e-12)
            h = 1e-5 * v
            fd = (bearing_mean_power(spec, NODES, WEIGHTS, v + h)
                  - bearing_mean_power(spec, NODES, WEIGHTS, v - h)) / (2 * h)
            assert grad == pytest.approx(fd, rel=1e-6)


def test_casadi_speed_derivative_finite_at_rest():
    om, nu = ca.SX.sym("om"), ca.SX.sym("nu")
    for spec in ALL:
        p = bearing_power(spec, om, nu)
        jac = ca.Function("j", [om, nu], [ca.jacobian(p, ca.vertcat(om, nu))])
        assert np.all(np.asarray(jac(0.0, 320e-6)) == 0.0)
        g = np.asarray(jac(150.0, 320e-6)).ravel()
        h = 1e-6 * 150.0
        fd = (float(bearing_power(spec, 150.0 + h, 320e-6))
              - float(bearing_power(spec, 150.0 - h, 320e-6))) / (2 * h)
        assert g[0] == pytest.approx(fd, rel=1e-6)


def test_one_palmgren_law_for_the_loop_effect():
    # the loop's bearing_ball_churning feature is the palmgren model's M0 |omega|
    spec = dataclasses.replace(PALM, radial_load_N=0.0, f0=1.0)
    w = np.array([0.0, 1.0, 50.0, 314.0])
    for nu in (10e-6, 320e-6):
        assert np.allclose(ball_churning_power(w, nu, spec.pitch_diameter_m, 1.0),
                           bearing_power(spec, w, nu), rtol=1e-13, atol=0)
    # the floor: nu n below 2000 keeps the value at 2000 (continuous)
    assert palmgren_viscous_moment(10.0, 199.0, 51.5) == palmgren_viscous_moment(10.0, 200.0,
                                                                                 51.5)
    assert palmgren_viscous_moment(10.0, 201.0, 51.5) > palmgren_viscous_moment(10.0, 200.0,
                                                                                51.5)


def test_drag_loss_factor_table():
    assert drag_loss_factor(1.2) == V_M_SUBMERGED == drag_loss_factor(3.0)
    assert drag_loss_factor(0.0) == 0.0
    assert drag_loss_factor(0.4) == pytest.approx(0.5 * (3.9e-4 + 5.6e-4))


def test_iso_rating_and_rated_viscosity():
    # ISO 76 C0 = f0 Z Dw^2 with f0(Dw/dm) from the (recalled) table, against the catalogue
    assert iso_static_load_rating(24, 3.969, 51.5) == pytest.approx(6100, rel=0.01)  # 61809
    assert iso_static_load_rating(8, 17.462, 72.5) == pytest.approx(31500, rel=0.01)  # 6309
    # ISO 281 form: continuous within 2 % at 1000 r/min, slope -0.5 above
    assert rated_viscosity(999.9, 51.5) == pytest.approx(rated_viscosity(1000, 51.5), rel=0.03)
    assert rated_viscosity(3000, 51.5) == pytest.approx(4500 / math.sqrt(3000 * 51.5))


def test_validity_notes():
    v = bearing_validity(SKF_RS, W, 320e-6)
    assert v.kappa == pytest.approx(320 / (4500 / math.sqrt(3000 * 51.5)))
    assert v.speed_factor_mm_rpm == pytest.approx(3000 * 51.5)
    assert any("kappa" in n for n in v.notes)
    assert any("R_s" in n for n in v.notes)
    assert not any("R_s" in n for n in bearing_validity(SKF, W, 320e-6).notes)
    assert bearing_validity(SKF, W, 20e-6).notes == ()  # kappa = 1.75
    assert any("floor" in n for n in bearing_validity(PALM, 0.5, 10e-6).notes)


@pytest.mark.parametrize("change, key", [
    ({"model": "ball"}, "model"),
    ({"kind": "taper"}, "type"),
    ({"drag": "rs"}, "drag"),
    ({"series": "NU2"}, "series"),
    ({"bore_m": -0.01}, "bore_mm"),
    ({"outside_m": 0.04}, "outside_mm"),
    ({"width_m": 0.0}, "width_mm"),
    ({"balls": 0}, "balls"),
    ({"balls": 24.0}, "balls"),
    ({"ball_diameter_m": 0.0}, "ball_diameter_mm"),
    ({"radial_load_N": -1.0}, "radial_load_N"),
    ({"axial_load_N": math.nan}, "axial_load_N"),
    ({"static_load_rating_N": 0.0}, "static_load_rating_N"),
    ({"f0": 0.0}, "f0"),
    ({"k_rs": -1e-8}, "k_rs"),
    ({"mu_ehl": -0.1}, "mu_ehl"),
    ({"oil_level_m": 0.01}, "oil_level_mm"),
    ({"submerged": False}, "oil_level_mm"),
    ({"submerged": "yes"}, "submerged"),
])
def test_spec_validation_names_the_toml_key(change, key):
    with pytest.raises(InputError) as e:
        BearingSpec(**{**BASE, **change})
    assert e.value.field == key


def test_palmgren_needs_no_series():
    spec = BearingSpec(**{**BASE, "series": None, "model": "palmgren"})
    assert float(bearing_power(spec, W, 320e-6)) > 0
