"""The feasibility check before IPOPT: its premises (monotonicity of the torque and the
inertia), the constraint it names when a problem is infeasible, and the boundary it draws
(just inside, IPOPT solves; just outside, it raises)."""

import numpy as np
import pytest
from scipy.optimize import brentq

from oilgap.model.errors import InfeasibleError
from oilgap.model.motor import motor_torque, rotor_inertia
from oilgap.optim.design import check_feasible


def test_feasibility_check_premises(prob):
    """check_feasible assumes: torque falls with delta and rises with R (and is linear in
    L); inertia rises with R and L and falls as the rotor grooves open (less epoxy)."""
    m, b = prob.case.motor, prob.case.bounds
    d = np.linspace(1e-5, 3 * b.gap_max, 400)
    R = np.linspace(0.8 * b.radius_min, 1.2 * b.radius_max, 400)
    assert np.all(np.diff(motor_torque(m, b.radius_min, d, b.length_min)[0]) < 0)
    assert np.all(np.diff(motor_torque(m, R, b.gap_max, b.length_min)[0]) > 0)
    d0 = prob.machined_rotor_groove_m
    assert np.all(np.diff(rotor_inertia(m, R, 0.0, b.length_min, d0)) > 0)
    assert np.all(np.diff(rotor_inertia(m, b.radius_min, np.linspace(0, d0, 50),
                                        b.length_min, d0)) < 0)


def test_infeasible_torque_names_delta(prob):
    with pytest.raises(InfeasibleError) as e:
        prob.solve(torque_min_Nm=0.9, gap_min_m=1.5e-3)
    msg = str(e.value)
    assert "torque >= 0.9 N m needs delta <=" in msg and "delta_min = 1.5 mm" in msg
    # the delta it names gives exactly tau_min at R_max, L_max (independent check)
    d_need = float(msg.split("needs delta <= ")[1].split(" mm")[0]) * 1e-3
    b = prob.case.bounds
    tau = motor_torque(prob.case.motor, b.radius_max, d_need, b.length_max)[0]
    assert tau == pytest.approx(0.9, rel=1e-3)
    assert e.value.exit_code == 3


def test_infeasible_inertia_and_joint_conflict(prob):
    with pytest.raises(InfeasibleError, match="inertia <= .* is below the lightest rotor"):
        prob.solve(inertia_max_ratio=0.3)
    # each constraint alone is feasible, together they are not
    with pytest.raises(InfeasibleError, match="conflict") as e:
        prob.solve(torque_min_Nm=0.5, inertia_max_ratio=0.6)
    assert "torque >=" in str(e.value) and "inertia <=" in str(e.value)
    prob.solve(torque_min_Nm=0.5)  # feasible alone
    prob.solve(torque_min_Nm=0.3, inertia_max_ratio=0.6)
    # just inside the limit the check lets IPOPT solve it, and IPOPT finds both active
    r = prob.solve(torque_min_Nm=0.48, inertia_max_ratio=0.6)
    assert {"torque_min", "inertia_max"} <= set(r.active_constraints)



def test_torque_boundary_is_exact(prob):
    """With only the torque limit binding, the largest feasible torque_min is the torque
    at (R_max, delta_min, L_max); just below it the check passes, just above it raises."""
    b = prob.case.bounds
    t_max = float(motor_torque(prob.case.motor, b.radius_max, b.gap_min, b.length_max)[0])
    m, d0 = prob.case.motor, prob.machined_rotor_groove_m
    big = 10.0  # no inertia limit in the way
    check_feasible(m, d0, prob.parameters(torque_min_Nm=t_max * (1 - 1e-9),
                                          inertia_max_ratio=big))
    with pytest.raises(InfeasibleError, match="needs delta <="):
        check_feasible(m, d0, prob.parameters(torque_min_Nm=t_max * (1 + 1e-6),
                                              inertia_max_ratio=big))


def test_inertia_boundary_is_exact(prob):
    """The lightest rotor within the bounds: R_min, L_min, grooves as open as allowed."""
    b = prob.case.bounds
    d0 = prob.machined_rotor_groove_m
    j_min = float(rotor_inertia(prob.case.motor, b.radius_min, d0, b.length_min, d0))
    small = 1e-3  # no torque limit in the way
    ratio = j_min / prob.inertia_ref_kgm2
    prob.check_feasible(prob.parameters(torque_min_Nm=small, inertia_max_ratio=ratio
                                        * (1 + 1e-9)))
    with pytest.raises(InfeasibleError, match="below the lightest rotor"):
        prob.check_feasible(prob.parameters(torque_min_Nm=small,
                                            inertia_max_ratio=ratio * (1 - 1e-6)))


def test_conflict_boundary_by_bisection(prob):
    """torque_min = 0.5 N m: the smallest feasible inertia limit found by brentq on the
    1-D condition of the check's premise (some R has L_need(R) <= L_allow(R)), computed
    here on a fine grid in R (independent of the check's refinement)."""
    m, d0, b = prob.case.motor, prob.machined_rotor_groove_m, prob.case.bounds
    tmin = 0.5
    R = np.linspace(b.radius_min, b.radius_max, 200001)

    def gap(ratio):
        jmax = ratio * prob.inertia_ref_kgm2
        need = np.maximum(b.length_min, tmin / motor_torque(m, R, b.gap_min, 1.0)[0])
        allow = np.minimum(b.length_max, jmax / rotor_inertia(m, R, d0, 1.0, d0))
        return float(np.max(allow - need))

    r_star = brentq(gap, 0.3, 1.0, xtol=1e-12)
    prob.check_feasible(prob.parameters(torque_min_Nm=tmin, inertia_max_ratio=r_star
                                        * (1 + 1e-6)))
    with pytest.raises(InfeasibleError, match="conflict"):
        prob.check_feasible(prob.parameters(torque_min_Nm=tmin,
                                            inertia_max_ratio=r_star * (1 - 1e-6)))
