"""The band of bearing models and the balls-in-still-oil estimate against hand calculations.

The inputs are those of test_bearing_hand.py: 61809 (d = 45, D = 58, dm = 51.5 mm),
F_r = 50 N, 618 constants (R1 = 4.7e-7, S1 = 6.5e-3, K_Z = 3.1), submerged, nu = 320
mm^2/s, with rho = 880 kg/m^3 and the estimated ball set 24 x 3.96875 mm, on the seed's
sine (3000 rpm sin(0.1 pi t)). Each member of the band is written out below from the
published formula and averaged over the sine by a second method: the closed form
``peak power x E|sin|^(1+a)`` for a pure power law, an adaptive quadrature (scipy's
``quad``) of the hand formula over the half period otherwise. The code averages over
the duty cycle's nodes.

The spheres: Schiller & Naumann's C_D = 24/Re (1 + 0.15 Re^0.687) (Z. VDI 77, 1933;
Clift, Grace & Weber 1978, ch. 5), each ball at the cage's pitch speed
omega/2 (1 - D_w/d_m) d_m/2 through still oil. At the seed's rated point the issue's
independent estimate is 4.8 W against the V_M term's 5.3 W.
"""

import math
import re
import warnings

import pytest
from scipy.integrate import quad

from oilgap.model.bearing import BearingSpec, bearing_moment_terms
from oilgap.model.bearing.band import bearing_model_band
from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.bearing.laws import balls_in_still_oil_power, sphere_drag_force
from oilgap.model.duty_cycle import DutyCycle
from oilgap.model.errors import OilgapWarning
from oilgap.model.io.case_bearing import bearing_from_doc

N, NU, RHO, D_IN, D_OUT, FR = 3000.0, 320.0, 880.0, 45.0, 58.0, 50.0
DM = 0.5 * (D_IN + D_OUT)
R1, S1, KZ, C0 = 4.7e-7, 6.5e-3, 3.1, 6100.0
Z, DW = 24, 3.96875  # the ball-set estimate of docs/bearing.md [-], [mm]
OMEGA = 2 * math.pi * N / 60
CYCLE = DutyCycle.sine(duration_s=20.0, sample_interval_s=0.002)  # one period, 1e4 samples


def spec(**kw):
    return bearing_spec_from({"designation": "61809", "radial_load_N": FR, **kw})


def band(s=None, nu=NU, rho=RHO):
    nodes, w = CYCLE.speed_distribution()
    return bearing_model_band(s or spec(), nodes, w, nu * 1e-6, rho)


def e_sin(p):
    """E|sin t|^p over a period [-] (Gamma-function closed form)."""
    return math.gamma((p + 1) / 2) / (math.sqrt(math.pi) * math.gamma(p / 2 + 1))


def sine_mean(power_at_omega):
    """Mean of P(omega_peak sin t) over a half period, by adaptive quadrature [W]."""
    return quad(lambda t: power_at_omega(OMEGA * math.sin(t)), 0.0, math.pi,
                epsabs=1e-10, epsrel=1e-10, limit=200)[0] / math.pi


# --------------------------------------------------------------------------- hand formulas


def rolling_sliding_W(omega):
    """SKF M_rr (phi_rs = 1) + M_sl at |omega| [W], from the catalogue's formulas."""
    n = omega * 30 / math.pi
    if n == 0.0:
        return 0.0
    phi_ish = 1 / (1 + 1.84e-9 * (n * DM) ** 1.28 * NU**0.64)
    m_rr = phi_ish * R1 * DM**1.96 * FR**0.54 * (NU * n) ** 0.6
    phi_bl = math.exp(-2.6e-8 * (n * NU) ** 1.4 * DM)
    mu_sl = phi_bl * 0.12 + (1 - phi_bl) * 0.05
    m_sl = S1 * DM**-0.26 * FR ** (5 / 3) * mu_sl
    return (m_rr + m_sl) * 1e-3 * omega


def spheres_W(omega, nu=NU, rho=RHO):
    """Z balls as spheres in still oil at the cage's pitch speed [W], by hand."""
    u = omega / 2 * (1 - DW / DM) * DM * 1e-3 / 2
    if u == 0.0:
        return 0.0
    re = u * DW * 1e-3 / (nu * 1e-6)
    c_d = 24 / re * (1 + 0.15 * re**0.687)
    return Z * 0.5 * rho * c_d * math.pi / 4 * (DW * 1e-3) ** 2 * u**3


# --------------------------------------------------------------------------- spheres


def test_sphere_estimate_at_the_peak_by_hand():
    assert DW / DM == pytest.approx(0.0770631, rel=1e-6)
    omega_c = OMEGA / 2 * (1 - 0.0770631)
    assert omega_c == pytest.approx(144.9746, rel=1e-6)
    u = omega_c * 0.02575
    assert u == pytest.approx(3.733096, rel=1e-6)
    re = u * 3.96875e-3 / 320e-6
    assert re == pytest.approx(46.2991, rel=1e-5)
    assert re**0.687 == pytest.approx(13.9395, rel=1e-5)
    c_d = 24 / 46.2991 * (1 + 0.15 * 13.9395)
    assert c_d == pytest.approx(1.60224, rel=1e-5)
    area = math.pi / 4 * 3.96875e-3**2
    assert area == pytest.approx(1.237079e-5, rel=1e-6)
    force = 0.5 * 880 * 1.60224 * 1.237079e-5 * 3.733096**2
    assert force == pytest.approx(0.121539, rel=1e-5)
    assert 24 * force * 3.733096 == pytest.approx(10.8892, rel=1e-5)
    assert float(sphere_drag_force(u, DW * 1e-3, NU * 1e-6, RHO)) == pytest.approx(
        0.121539, rel=1e-5)
    assert float(balls_in_still_oil_power(OMEGA, Z, DW * 1e-3, DM * 1e-3, NU * 1e-6, RHO)) \
        == pytest.approx(10.8892, rel=1e-5)


def test_sphere_drag_limits():
    """Stokes' drag 3 pi mu D U as Re -> 0 (exact); C_D = 0.44 in the Newton range."""
    mu = RHO * NU * 1e-6
    u = 1e-9  # Re = 1.2e-8
    assert float(sphere_drag_force(u, 4e-3, NU * 1e-6, RHO)) == pytest.approx(
        3 * math.pi * mu * 4e-3 * u, rel=1e-5)
    assert float(sphere_drag_force(0.0, 4e-3, NU * 1e-6, RHO)) == 0.0
    u, nu = 10.0, 1e-6  # Re = 4e4
    assert float(sphere_drag_force(u, 4e-3, nu, 1000.0)) == pytest.approx(
        0.5 * 1000.0 * 0.44 * math.pi / 4 * 4e-3**2 * u**2, rel=1e-12)
    at = 1000.0 * nu / 4e-3  # Re = 1000 from either side: within 0.5 %
    below = float(sphere_drag_force(at * (1 - 1e-9), 4e-3, nu, 1000.0))
    above = float(sphere_drag_force(at * (1 + 1e-9), 4e-3, nu, 1000.0))
    assert below == pytest.approx(above, rel=5e-3)


def test_sphere_estimate_over_the_cycle_by_quadrature():
    b = band()
    assert b.parts_W["drag_spheres_still_oil"] == pytest.approx(sine_mean(spheres_W), rel=1e-6)


def test_sphere_estimate_at_the_seed_rated_point_is_the_issue_number():
    """The issue's independent estimate: 24 balls in still oil, 4.8 W (VG22, 2 degC,
    3000 m: nu = 290.25 cSt, rho = 882.0 kg/m^3 from the oil model)."""
    nu, rho = 290.25, 882.0
    b = band(nu=nu, rho=rho)
    got = b.parts_W["drag_spheres_still_oil"]
    assert got == pytest.approx(sine_mean(lambda w: spheres_W(w, nu, rho)), rel=1e-6)
    assert got == pytest.approx(4.8, abs=0.05)
    assert b.parts_W["drag_vm_term"] == pytest.approx(5.3, abs=0.05)  # the issue's 5.3 W


# --------------------------------------------------------------------------- the band


def test_band_members_by_hand():
    b = band()
    rs = rolling_sliding_W  # by quadrature below
    no_drag = sine_mean(rs)
    k_ball = KZ * (D_IN + D_OUT) / (D_OUT - D_IN) * 1e-12
    vm_peak_W = 0.4 * 1.25e-3 * k_ball * DM**5 * N**2 * 1e-3 * OMEGA  # 12.579 W
    assert vm_peak_W == pytest.approx(12.579, rel=1e-4)
    vm = vm_peak_W * e_sin(3)  # M ~ n^2: P ~ |sin|^3
    f_a = 0.05 * KZ * (D_OUT + D_IN) / (D_OUT - D_IN)
    rs_peak_W = (1.093e-7 * N**2 * DM**3 * (N * DM**2 / NU) ** -1.379
                 * 0.72 * math.pi * DM**2 * f_a * 1e-3 * OMEGA)  # 269.9 W
    assert rs_peak_W == pytest.approx(269.92, rel=1e-4)
    r_s = rs_peak_W * e_sin(1.621)
    m0_peak_W = 1e-7 * (NU * N) ** (2 / 3) * DM**3 * 1e-3 * OMEGA  # per unit f0: 41.76 W
    m1_W = 5e-4 * (FR / C0) ** 0.55 * FR * DM * 1e-3 * OMEGA * e_sin(1)

    def palmgren(f0):
        return f0 * m0_peak_W * e_sin(5 / 3) + m1_W

    hand = {"skf_vm_term": no_drag + vm, "skf_full": no_drag + vm + r_s,
            "skf_no_drag_plus_spheres": no_drag + sine_mean(spheres_W),
            "palmgren_f0_2": palmgren(2.0), "palmgren_f0_4": palmgren(4.0)}
    assert set(b.members_W) == set(hand)
    for k, v in hand.items():
        assert b.members_W[k] == pytest.approx(v, rel=2e-6), k
    assert b.parts_W["skf_no_drag"] == pytest.approx(no_drag, rel=2e-6)
    assert b.parts_W["drag_vm_term"] == pytest.approx(vm, rel=2e-6)
    assert (b.min_W, b.max_W) == (min(b.members_W.values()), max(b.members_W.values()))
    assert b.max_W == pytest.approx(hand["skf_full"], rel=2e-6)
    assert b.chosen == "skf, drag skf-vm-term"
    assert b.chosen_W == pytest.approx(hand["skf_vm_term"], rel=2e-6)
    assert b.f0_range == (2.0, 4.0)


def test_band_of_a_palmgren_case_names_its_f0_and_keeps_the_skf_members():
    b = band(spec(model="palmgren", f0=3.0))
    assert b.chosen == "palmgren, f0 3"
    lo, hi = b.members_W["palmgren_f0_2"], b.members_W["palmgren_f0_4"]
    assert b.chosen_W == pytest.approx(0.5 * (lo + hi), rel=1e-12)  # M_0 linear in f0
    assert b.members_W["skf_vm_term"] == pytest.approx(band().members_W["skf_vm_term"],
                                                       rel=1e-14)


def test_band_without_a_series_has_palmgren_and_spheres_only():
    s = BearingSpec(name="b", bore_m=0.045, outside_m=0.058, balls=Z,
                    ball_diameter_m=DW * 1e-3, radial_load_N=FR, model="palmgren",
                    static_load_rating_N=C0)
    b = band(s)
    assert set(b.members_W) == {"palmgren_f0_2", "palmgren_f0_4"}
    assert set(b.parts_W) == {"drag_spheres_still_oil"}
    d = b.to_dict()
    assert d["f0_range"] == [2.0, 4.0] and d["members_W"] == b.members_W


# --------------------------------------------------------------------------- drag names


@pytest.mark.parametrize(("old", "new"), [("vm", "skf-vm-term"), ("vm+rs", "skf-full")])
def test_former_drag_names_read_with_a_warning(old, new):
    with pytest.warns(OilgapWarning, match=re.escape(f"drag = '{old}' is deprecated; it "
                                                     f"reads as drag = '{new}'")):
        b = bearing_from_doc({"bearing": {"designation": "6809", "drag": old}})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert b == bearing_from_doc({"bearing": {"designation": "6809", "drag": new}})
    assert b.drag == new


def test_drag_none_is_rolling_and_sliding_only():
    t = bearing_moment_terms(spec(drag="none"), OMEGA, NU * 1e-6)
    assert float(t["drag_vm"]) == 0.0 and float(t["drag_rs"]) == 0.0
    assert float(t["rolling"] + t["sliding"]) * OMEGA == pytest.approx(
        rolling_sliding_W(OMEGA), rel=1e-12)
