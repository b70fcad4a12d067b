"""The one numpy objective of the design problem (DesignObjective): one design or the rows
of an array give the same numbers, the CasADi path gives the same numbers (a second
evaluation), the inertia equals a hand calculation, the loss equals the duty-cycle sum of
the clearance power with T from Eq. 9 written out, and the SciPy reference's functions of
x in mm are the same functions."""

import numpy as np
import pytest

from oilgap.model.viscous_loss import clearance_power
from oilgap.optim.design import DesignObjective
from oilgap.optim.scipy_reference import numpy_functions


@pytest.fixture(scope="module")
def designs(prob):
    """The case's design and 20 random designs within the bounds (n, 5) [m]."""
    prm = prob.parameters()
    rng = np.random.default_rng(8)
    lo, hi = np.array(prm.lower_m), np.array(prm.upper_m)
    return np.vstack([prob.x_case_m, rng.uniform(lo, hi, size=(20, 5))])


def test_rows_equal_single_designs(prob, designs):
    obj = prob.objective()
    p1, tau, J = obj(designs)
    assert p1.shape == tau.shape == J.shape == (len(designs),)
    for k, x in enumerate(designs):
        one = obj(x)
        assert np.ndim(one[0]) == 0
        assert p1[k] == pytest.approx(float(one[0]), rel=1e-13)
        assert tau[k] == pytest.approx(float(one[1]), rel=1e-14)  # array and scalar
        assert J[k] == pytest.approx(float(one[2]), rel=1e-14)  # powers: last-bit noise


def test_numpy_path_equals_the_casadi_path(prob, designs):
    """DesignProblem.point evaluates the CasADi expressions the NLP is built from."""
    obj = prob.objective()
    p1, tau, J = obj(designs)
    for k, x in enumerate(designs):
        pt = prob.point(x)
        assert pt.region1_power_W == pytest.approx(p1[k], rel=1e-12)
        assert pt.torque_capability_Nm == pytest.approx(tau[k], rel=1e-12)
        assert pt.inertia_kgm2 == pytest.approx(J[k], rel=1e-12)


def test_inertia_by_hand(prob):
    """Core (bore to the machined groove bottom), the grooved layer at its solid fraction,
    and epoxy from the machined bottom up to R - d_r; each (pi/2) rho L (ro^4 - ri^4)."""
    m, d0 = prob.case.motor, prob.machined_rotor_groove_m
    R, d_r, L = 0.024, 0.4 * d0, 0.017
    f = m.rotor_groove_solid_fraction

    def cyl(rho, ro, ri):
        return np.pi / 2 * rho * L * (ro**4 - ri**4)

    bottom = R - d0
    hand = (cyl(m.rotor_density_kg_m3, bottom, m.shaft_bore_radius)
            + f * cyl(m.rotor_density_kg_m3, R, bottom)
            + (1 - f) * cyl(m.epoxy_density_kg_m3, R - d_r, bottom))
    obj = prob.objective()
    assert float(obj.inertia(np.array([R, 1e-3, d_r, 0.0, L]))) == pytest.approx(hand,
                                                                                rel=1e-13)


def test_mean_power_is_the_weighted_sum_with_T_of_eq9(prob):
    """sum_i w_i P(omega_i) with T = 1 + (d_r + d_s)/delta (seed paper, Eq. 9)."""
    R, delta, d_r, d_s, L = 0.021, 0.9e-3, 0.6e-3, 0.3e-3, 0.015
    T = 1.0 + (d_r + d_s) / delta
    nu, rho = 3e-5, 860.0
    hand = sum(w * clearance_power(om, nu, rho, R, delta, L, prob.law, T)
               for om, w in zip(prob.nodes_rad_s, prob.weights, strict=True))
    obj = DesignObjective(nodes_rad_s=prob.nodes_rad_s, weights=prob.weights, law=prob.law,
                          motor=prob.case.motor,
                          machined_rotor_groove_m=prob.machined_rotor_groove_m, nu_m2_s=nu,
                          rho_kg_m3=rho)
    assert float(obj.mean_power(np.array([R, delta, d_r, d_s, L]))) == pytest.approx(
        float(hand), rel=1e-12)


def test_objective_takes_the_solve_oil_state(prob):
    prm = prob.parameters(nu_m2_s=4e-5, rho_kg_m3=880.0)
    obj = prob.objective(prm)
    assert (obj.nu_m2_s, obj.rho_kg_m3) == (4e-5, 880.0)
    default = prob.objective()
    assert (default.nu_m2_s, default.rho_kg_m3) == (prob.nu_m2_s, prob.rho_kg_m3)


def test_scipy_reference_functions_are_the_objective_in_mm(prob, designs):
    prm = prob.parameters()
    power, torque, inertia = numpy_functions(prob, prm)
    obj = prob.objective(prm)
    x = designs[3]
    assert power(x * 1e3) == pytest.approx(float(obj.mean_power(x)), rel=1e-14)
    assert torque(x * 1e3) == pytest.approx(float(obj.torque(x)), rel=1e-14)
    assert inertia(x * 1e3) == pytest.approx(float(obj.inertia(x)), rel=1e-14)
