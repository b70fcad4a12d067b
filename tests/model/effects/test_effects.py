"""The candidate-effect library: each law against a hand calculation or a second
method (the exact solutions are in ``tests/validation/test_exact_solutions.py``)."""

import math

import casadi as ca
import numpy as np
import pytest

from oilgap.model import effects as fx
from oilgap.model.effects import laws as effect_laws
from oilgap.model.effects import plausibility as effect_plausibility
from oilgap.model.errors import InputError
from oilgap.model.oils import get_oil


def test_free_disc_matches_schlichting_torque_by_hand():
    # Schlichting: a disc wetted on both sides, 2M = 0.5 C_M rho w^2 R^5, C_M = 3.87 Re^-0.5.
    w, nu, rho, r = 300.0, 3.0e-4, 880.0, 0.0254
    re = w * r * r / nu  # 645.16
    cm = 3.87 / math.sqrt(re)
    p_hand = 0.5 * cm * rho * w**2 * r**5 * w  # torque (both faces) times omega
    assert fx.disc_reynolds(w, r, nu) == pytest.approx(645.16, rel=1e-4)
    assert fx.end_face_disc_power(w, nu, rho, r, 0.0) == pytest.approx(p_hand, rel=1e-12)
    # with a bore the D^5 - Di^5 of Pyrhönen's form
    p_bore = fx.end_face_disc_power(w, nu, rho, r, 0.01)
    assert p_bore == pytest.approx(p_hand * (1 - (0.01 / r) ** 5), rel=1e-12)


def test_free_disc_turbulent_branch():
    assert fx.free_disc_moment_coefficient(1.0e6) == pytest.approx(0.146 * 1e6**-0.2)
    assert fx.free_disc_moment_coefficient(1.0e5) == pytest.approx(3.87 * 1e5**-0.5)


def test_palmgren_moment_by_hand():
    # nu = 300 cSt, n = 3000 rpm: nu n = 9e5 >= 2000; d_m = 49 mm, f0 = 2
    m0 = 1e-7 * 2 * (9e5) ** (2 / 3) * 49.0**3  # N mm
    assert fx.palmgren_viscous_moment(300.0, 3000.0, 49.0, 2.0) == pytest.approx(m0, rel=1e-12)
    # below nu n = 2000 it is constant, within 1 % of Palmgren's 160e-7 f0 dm^3
    low = fx.palmgren_viscous_moment(10.0, 5.0, 49.0, 2.0)
    assert low == pytest.approx(160e-7 * 2 * 49.0**3, rel=0.01)
    assert fx.palmgren_viscous_moment(10.0, 1.0, 49.0, 2.0) == low
    # SI power: M0 [N m] * omega
    w = 3000 * 2 * math.pi / 60
    assert fx.ball_churning_power(w, 300e-6, 0.049, 2.0) == pytest.approx(m0 * 1e-3 * w, 1e-12)


def test_coulomb_power_is_torque_times_speed_magnitude():
    assert np.allclose(fx.coulomb_friction_power(np.array([-100.0, 0.0, 50.0]), 0.05),
                       [5.0, 0.0, 2.5])


def test_thermal_lag_first_order_against_exact_lag():
    # P(T) of a real oil's viscosity law; oil lags the measured temperature by tau
    oil = get_oil("VG320")
    t = np.arange(0, 200, 0.2)
    temp = 25 + 20 * (1 - np.exp(-t / 60.0))
    tau = 0.5

    def power(temp_c):  # any P ∝ mu: the viscous loss of a laminar clearance
        nu, mu, rho = oil.properties(temp_c + 273.15, 0.0)
        return 100.0 * mu

    exact = power(fx.first_order_lag(t, temp, tau)) - power(temp)
    dP_dT = (power(temp + 0.01) - power(temp - 0.01)) / 0.02
    first = fx.thermal_lag_power(dP_dT, np.gradient(temp, t), tau)
    settled = t > 5 * tau  # the exact lag starts in equilibrium, the warm-up does not
    assert np.max(np.abs(exact - first)[settled]) < 0.02 * np.max(np.abs(exact[settled]))


def test_taylor_excess_factor():
    ta_c = fx.CRITICAL_TAYLOR_NUMBER
    assert np.allclose(fx.taylor_excess_factor(np.array([0.0, 0.5 * ta_c, ta_c, 2 * ta_c])),
                       [0.0, 0.0, 0.0, 3.0])
    assert fx.taylor_vortex_power(10.0, 2 * ta_c, 0.5) == pytest.approx(15.0)


def test_taylor_excess_shape_exponent_by_hand():
    # (Ta/Ta_c)^m - 1 at Ta = 4 Ta_c: m = 0.5 (Wendt 1933): 2 - 1 = 1; m = 1: 3;
    # m = 2 (Stuart 1958, the default): 16 - 1 = 15; below onset 0 for every m
    ta_c = fx.CRITICAL_TAYLOR_NUMBER
    for m, want in ((0.5, 1.0), (1.0, 3.0), (2.0, 15.0)):
        got = fx.taylor_excess_factor(np.array([0.5 * ta_c, ta_c, 4 * ta_c]), exponent=m)
        assert np.allclose(got, [0.0, 0.0, want])
    # 2.25 Ta_c, m = 0.5: 1.5 - 1 = 0.5; power k P x 0.5 = 0.4 x 10 W x 0.5 = 2 W
    assert fx.taylor_vortex_power(10.0, 2.25 * ta_c, 0.4, exponent=0.5) == pytest.approx(2.0)


def test_shear_models_small_rate_expansions():
    g = fx.couette_shear_rate(-314.16, 0.0254, 0.001)
    assert g == pytest.approx(314.16 * 25.4)
    for x in (1e-3, 1e-2):
        lam = x / g
        assert fx.cross_viscosity_ratio(g, lam) == pytest.approx(1 - x * x, abs=2 * x**4)
        assert fx.carreau_viscosity_ratio(g, lam, 0.5) == pytest.approx(1 - 0.25 * x * x,
                                                                         abs=x**4)
        assert fx.shear_thinning_power(10.0, g, lam * lam) == pytest.approx(-10 * x * x)
    assert fx.carreau_viscosity_ratio(g, 1e-3, 1.0) == 1.0


def test_sensor_delay_first_order_against_exact_shift():
    t = np.arange(0, 40, 0.01)
    p = 100 * np.sin(0.1 * np.pi * t) ** 2
    d = 0.05
    exact = 100 * np.sin(0.1 * np.pi * (t - d)) ** 2 - p
    first = fx.sensor_delay_power(np.gradient(p, t), d)
    # the neglected second-order term is d^2 P''/2: 1/2 * 0.05^2 * 100 * 2 (0.1 pi)^2 = 0.025
    assert np.max(np.abs(exact - first)) < 0.03


def test_casadi_and_numpy_agree():
    x = ca.SX.sym("x")
    cases = [
        (lambda v: fx.end_face_disc_power(v, 3e-4, 880.0, 0.0254, 0.01), 250.0),
        (lambda v: fx.ball_churning_power(v, 2e-4, 0.049, 1.5), 250.0),
        (lambda v: fx.taylor_vortex_power(5.0, v, 0.3), 60.0),
        (lambda v: fx.cross_viscosity_ratio(v, 5e-5), 8000.0),
        (lambda v: fx.coulomb_friction_power(v, 0.03), -120.0),
    ]
    for f, v in cases:
        sym = float(ca.Function("f", [x], [f(x)])(v))
        assert sym == pytest.approx(float(f(v)), rel=1e-12)


def test_library_entries_are_complete():
    assert set(fx.EFFECTS) == {"end_face_disc", "bearing_ball_churning", "bearing_ball_drag",
                               "seal_coulomb_friction", "oil_inertia", "thermal_lag",
                               "taylor_vortex_onset", "shear_thinning", "sensor_delay",
                               "film_heating"}
    for name, e in fx.EFFECTS.items():
        assert e.name == name and e.formula and e.reference and e.unit
        assert isinstance(e.nonnegative, bool)
        s = 3.0e-5
        assert e.strength_from_coefficient(e.coefficient_from_strength(s)) == pytest.approx(s)
    # dissipation and inertia are one-signed; a lag may go either way
    assert fx.EFFECTS["seal_coulomb_friction"].nonnegative
    assert not fx.EFFECTS["thermal_lag"].nonnegative
    with pytest.raises(InputError, match="library effects"):
        fx.get_effect("magic")


def _context(bearing=True):
    w = np.array([-300.0, 0.0, 150.0])
    reg = fx.RegionState(name="rotor-stator", radius_m=0.0254, gap_m=np.full(3, 1e-3),
                         length_m=0.01476, power_W=np.array([50.0, 0.0, 12.0]),
                         reynolds=np.array([30.0, 0.0, 15.0]),
                         taylor=np.array([60.0, 0.0, 20.0]))
    return fx.EffectContext(omega_rad_s=w, domega_dt_rad_s2=np.array([10.0, 98.0, -5.0]),
                            nu_m2_s=np.full(3, 3e-4), density_kg_m3=np.full(3, 880.0),
                            dtemp_dt_K_s=np.array([0.1, 0.0, 0.0]),
                            dpower_dt_W_s=np.array([2.0, 0.0, -1.0]),
                            dpower_dtemp_W_K=np.array([-3.0, -2.0, -1.0]), regions=(reg,),
                            disc_radii_m=(0.0254, 0.01),
                            bearing_pitch_diameter_m=0.049 if bearing else None)


def test_features_are_the_laws_with_unit_coefficient():
    c = _context()
    E = fx.EFFECTS
    assert np.allclose(E["seal_coulomb_friction"].feature_values(c), [300.0, 0.0, 150.0])
    assert np.allclose(E["oil_inertia"].feature_values(c), 880.0 * c.omega_rad_s * [10, 98, -5])
    assert np.allclose(E["thermal_lag"].feature_values(c), [0.3, 0.0, 0.0])
    assert np.allclose(E["sensor_delay"].feature_values(c), [-2.0, 0.0, 1.0])
    ta_c = fx.CRITICAL_TAYLOR_NUMBER
    assert np.allclose(E["taylor_vortex_onset"].feature_values(c),
                       [50.0 * ((60 / ta_c) ** 2 - 1), 0.0, 0.0])
    g = np.abs(c.omega_rad_s) * 25.4
    assert np.allclose(E["shear_thinning"].feature_values(c), -g * g * [50.0, 0.0, 12.0])
    assert E["bearing_ball_churning"].feature_values(_context(bearing=False)) is None


def test_library_module_re_exports_the_laws():
    for name in ("first_order_lag", "cross_viscosity_ratio", "couette_shear_rate",
                 "end_face_disc_power", "CRITICAL_TAYLOR_NUMBER"):
        assert getattr(fx, name) is getattr(effect_laws, name)
    assert set(effect_laws.__dict__) >= {n for n in fx.__all__ if n not in (
        "RegionState", "EffectContext", "Precomputed", "region_states", "effect_context",
        "cross_region_ratios", "Effect", "EFFECTS", "CONFOUNDED_FORMS", "get_effect",
        "film_temperature")  # the film's fixed point on a power callable: its own here
        and n not in effect_plausibility.__dict__}  # the plausible ranges: their own module
