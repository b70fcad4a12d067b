"""The bearing models against calculations written out by hand from the published formulas.

The inputs are those of docs/notes/bearing-friction-models.md, section 4: 61809 (d = 45,
D = 58, dm = 51.5 mm), F_r = 50 N, F_a = 0, n = 3000 r/min, nu = 320 mm^2/s, 618 series
constants (R1 = 4.7e-7, R2 = 1.7, S1 = 6.5e-3, S2 = 0.78, K_Z = 3.1), fully submerged.
Each term is written below from SKF's formula (catalogue units: N mm, r/min, mm^2/s, mm)
and compared with the notes' number, then the code with the hand value. Further:

* the F_a > 0 branch, the K_rs = 3e-8 variant and a half-full oil level by hand;
* the cycle means of the seed's duty cycle against the notes' independent prototype (its
  section 5 tables);
* the SKF/Palmgren comparison over 10-1000 cSt and the elasticities printed for
  docs/bearing.md (``python tests/validation/test_bearing_hand.py`` prints both tables);
  the elasticities of the pure power-law terms against their exponents.
"""

import math

import numpy as np
import pytest

from oilgap.model.bearing import bearing_mean_power, bearing_moment_terms, bearing_power
from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.duty_cycle import DutyCycle

N, NU, D_IN, D_OUT, FR = 3000.0, 320.0, 45.0, 58.0, 50.0
DM = 0.5 * (D_IN + D_OUT)
R1, R2, S1, S2, KZ = 4.7e-7, 1.7, 6.5e-3, 0.78, 3.1
C0 = 6100.0
OMEGA = 2 * math.pi * N / 60  # 314.16 rad/s
NU_SI = NU * 1e-6


def spec(**kw):
    return bearing_spec_from({"designation": "61809", "radial_load_N": FR, **kw})


def terms_Nmm(s, omega=OMEGA, nu=NU_SI):
    return {k: 1e3 * float(v) for k, v in bearing_moment_terms(s, omega, nu).items()}


# --------------------------------------------------------------------------- SKF, section 4


def test_rolling_moment_by_hand():
    g_rr = R1 * DM**1.96 * FR**0.54
    assert DM**1.96 == pytest.approx(2265.39, rel=1e-5)
    assert FR**0.54 == pytest.approx(8.2688, rel=1e-5)
    assert g_rr == pytest.approx(8.8041e-3, rel=1e-4)
    nn06 = (NU * N) ** 0.6
    assert nn06 == pytest.approx(3884.75, rel=1e-5)
    assert g_rr * nn06 == pytest.approx(34.202, rel=1e-4)
    x = 1.84e-9 * (N * DM) ** 1.28 * NU**0.64
    assert (N * DM) ** 1.28 == pytest.approx(4.3836e6, rel=1e-4)
    assert NU**0.64 == pytest.approx(40.114, rel=1e-4)
    assert x == pytest.approx(0.32355, rel=1e-4)
    phi_ish = 1 / (1 + x)
    assert phi_ish == pytest.approx(0.75554, rel=1e-4)
    m_rr = phi_ish * 1.0 * g_rr * nn06  # phi_rs = 1: flooded (K_rs = 0, submerged default)
    assert m_rr == pytest.approx(25.841, rel=1e-4)
    assert terms_Nmm(spec())["rolling"] == pytest.approx(m_rr, rel=1e-12)


def test_rolling_moment_with_replenishment_by_hand():
    expo = 3e-8 * NU * N * (D_IN + D_OUT) * math.sqrt(KZ / (2 * (D_OUT - D_IN)))
    assert expo == pytest.approx(1.02429, rel=1e-5)
    phi_rs = math.exp(-expo)
    assert phi_rs == pytest.approx(0.35905, rel=1e-4)
    phi_ish = 1 / (1 + 1.84e-9 * (N * DM) ** 1.28 * NU**0.64)
    m_rr = phi_ish * phi_rs * R1 * DM**1.96 * FR**0.54 * (NU * N) ** 0.6
    assert m_rr == pytest.approx(9.278, rel=1e-3)
    assert terms_Nmm(spec(k_rs=3e-8))["rolling"] == pytest.approx(m_rr, rel=1e-12)


def test_sliding_moment_by_hand():
    g_sl = S1 * DM**-0.26 * FR ** (5 / 3)
    assert DM**-0.26 == pytest.approx(0.35886, rel=1e-4)
    assert FR ** (5 / 3) == pytest.approx(678.60, rel=1e-4)
    assert g_sl == pytest.approx(1.5829, rel=1e-4)
    phi_bl = math.exp(-2.6e-8 * (N * NU) ** 1.4 * DM)
    assert math.log(phi_bl) == pytest.approx(-317.7, rel=1e-3)
    mu_sl = phi_bl * 0.12 + (1 - phi_bl) * 0.05  # mu_bl 0.12, mu_EHL 0.05 (mineral oil)
    assert g_sl * mu_sl == pytest.approx(0.0791, rel=1e-3)
    assert terms_Nmm(spec())["sliding"] == pytest.approx(g_sl * mu_sl, rel=1e-12)
    # at rest phi_bl = 1: the boundary coefficient alone
    assert terms_Nmm(spec(), 0.0)["sliding"] == pytest.approx(g_sl * 0.12, rel=1e-12)


def test_drag_vm_moment_by_hand():
    k_ball = 1 * KZ * (D_IN + D_OUT) / (D_OUT - D_IN) * 1e-12
    assert k_ball == pytest.approx(2.4562e-11, rel=1e-4)
    assert DM**5 == pytest.approx(3.6227e8, rel=1e-4)
    m_vm = 0.4 * 1.25e-3 * k_ball * DM**5 * N**2  # V_M = 1.25e-3: submerged plateau
    assert m_vm == pytest.approx(40.041, rel=1e-4)
    assert terms_Nmm(spec())["drag_vm"] == pytest.approx(m_vm, rel=1e-12)


def test_drag_rs_moment_by_hand():
    f_a = 0.05 * KZ * (D_OUT + D_IN) / (D_OUT - D_IN)
    assert f_a == pytest.approx(1.22808, rel=1e-5)
    r_s = 0.36 * DM**2 * 2 * math.pi * f_a  # t = 2 pi: submerged, f_t = 1
    assert r_s == pytest.approx(7367.5, rel=1e-4)
    arg = N * DM**2 / NU
    assert arg == pytest.approx(24864.8, rel=1e-5)
    assert arg**-1.379 == pytest.approx(8.6794e-7, rel=1e-4)
    m_rs = 1.093e-7 * N**2 * DM**3 * arg**-1.379 * r_s
    assert m_rs == pytest.approx(859.20, rel=1e-4)
    assert terms_Nmm(spec(drag="skf-full"))["drag_rs"] == pytest.approx(m_rs, rel=1e-12)
    assert terms_Nmm(spec())["drag_rs"] == 0.0  # the default drag = "skf-vm-term" leaves it out


def test_peak_powers_by_hand():
    assert OMEGA == pytest.approx(314.16, rel=1e-5)
    t = terms_Nmm(spec(drag="skf-full"))
    for term, watts in (("rolling", 8.12), ("drag_vm", 12.58), ("drag_rs", 269.9)):
        assert t[term] * 1e-3 * OMEGA == pytest.approx(watts, rel=1e-3)
    total = sum(t.values()) * 1e-3 * OMEGA
    assert float(bearing_power(spec(drag="skf-full"), OMEGA, NU_SI)) == pytest.approx(total, 1e-12)


def test_axial_load_branch_by_hand():
    fa = 20.0
    alpha = 24.6 * (fa / C0) ** 0.24  # degrees
    s = math.sin(math.radians(alpha))
    g_rr = R1 * DM**1.96 * (FR + R2 / s * fa) ** 0.54
    g_sl = S1 * DM**-0.145 * (FR**5 + S2 * DM**1.5 / s * fa**4) ** (1 / 3)
    phi_ish = 1 / (1 + 1.84e-9 * (N * DM) ** 1.28 * NU**0.64)
    t = terms_Nmm(spec(axial_load_N=fa))
    assert t["rolling"] == pytest.approx(phi_ish * g_rr * (NU * N) ** 0.6, rel=1e-12)
    assert t["sliding"] == pytest.approx(0.05 * g_sl, rel=1e-9)
    # the rolling branch joins at F_a -> 0; the sliding one jumps by dm^0.115 (the SKF
    # branches' dm exponents -0.26 and -0.145 differ)
    tiny = terms_Nmm(spec(axial_load_N=1e-9))
    zero = terms_Nmm(spec())
    assert tiny["rolling"] == pytest.approx(zero["rolling"], rel=1e-4)
    assert tiny["sliding"] / zero["sliding"] == pytest.approx(DM**0.115, rel=1e-6)


def test_partial_oil_level_by_hand():
    h = 0.6 * DM  # level at the pitch circle: t = pi, f_t = sin(pi/2) = 1
    t_ = 2 * math.acos((0.6 * DM - h) / (0.6 * DM))
    assert t_ == pytest.approx(math.pi)
    f_a = 0.05 * KZ * (D_OUT + D_IN) / (D_OUT - D_IN)
    r_s = 0.36 * DM**2 * (t_ - math.sin(t_)) * f_a
    m_rs = 1.093e-7 * N**2 * DM**3 * (N * DM**2 * 1.0 / NU) ** -1.379 * r_s
    v_m = 5.6e-4 + (7.9e-4 - 5.6e-4) * (0.6 - 0.5) / (0.8 - 0.5)  # diagram, H/dm = 0.6
    k_ball = KZ * (D_IN + D_OUT) / (D_OUT - D_IN) * 1e-12
    t = terms_Nmm(spec(submerged=False, oil_level_mm=h, drag="skf-full", k_rs=0.0))
    assert t["drag_rs"] == pytest.approx(m_rs, rel=1e-12)
    assert t["drag_vm"] == pytest.approx(0.4 * v_m * k_ball * DM**5 * N**2, rel=1e-12)


# --------------------------------------------------------------------------- Palmgren


def test_palmgren_by_hand():
    assert (NU * N) ** (2 / 3) == pytest.approx(9731.5, rel=1e-5)
    assert DM**3 == pytest.approx(136590.9, rel=1e-6)
    m0_per_f0 = 1e-7 * (NU * N) ** (2 / 3) * DM**3
    assert m0_per_f0 == pytest.approx(132.92, rel=1e-4)
    assert 2 * m0_per_f0 * 1e-3 * OMEGA == pytest.approx(83.52, rel=1e-4)
    p0, p1 = max(0.6 * FR, FR), max(-0.1 * FR, FR)  # ISO 76 P0; Palmgren's P1
    m1 = 5e-4 * (p0 / C0) ** 0.55 * p1 * DM  # z = 5e-4, y = 0.55
    assert m1 == pytest.approx(0.092, rel=5e-3)
    t = terms_Nmm(spec(model="palmgren", f0=2.0))
    assert t["load_independent"] == pytest.approx(2 * m0_per_f0, rel=1e-12)
    assert t["load_dependent"] == pytest.approx(m1, rel=1e-12)
    fa = 60.0  # axial load: P1 = 3 Fa - 0.1 Fr = 175, P0 = 0.6 Fr + 0.5 Fa = 60 N
    t = terms_Nmm(spec(model="palmgren", f0=2.0, axial_load_N=fa))
    hand = 5e-4 * ((0.6 * FR + 0.5 * fa) / C0) ** 0.55 * (3 * fa - 0.1 * FR) * DM
    assert t["load_dependent"] == pytest.approx(hand, rel=1e-12)


# --------------------------------------------------------------------------- the seed's cycle

SEED_CYCLE = DutyCycle.sine()  # 3000 rpm sin(0.1 pi t), 1500 samples


def cycle_mean(s, nu_cSt, cycle=SEED_CYCLE):
    nodes, w = cycle.speed_distribution()
    return float(bearing_mean_power(s, nodes, w, nu_cSt * 1e-6))


def term_means(s, nu_cSt, cycle=SEED_CYCLE):
    nodes, w = cycle.speed_distribution()
    t = bearing_moment_terms(s, nodes, nu_cSt * 1e-6)
    return {k: float((np.asarray(v) * nodes) @ w) for k, v in t.items()}


# Notes section 5: the prototype's cycle means [W] (an independent implementation).
NOTES_SEED = {  # nu: (M_rr phi_rs=1, M_rr K_rs=3e-8, drag V_M, drag R_s, Palmgren f0 1.5, 2, 4)
    150: (3.21, 2.17, 5.34, 51.4, 20.3, 27.0, 54.0),
    320: (4.66, 2.06, 5.34, 146.0, 33.6, 44.8, 89.5),
    680: (6.53, 1.25, 5.34, 413.0, 55.5, 74.0, 147.9),
    1000: (7.63, 0.75, 5.34, 702.9, 71.7, 95.6, 191.2),
}


@pytest.mark.parametrize("nu", sorted(NOTES_SEED))
def test_seed_cycle_means_against_the_notes_prototype(nu):
    rr, rr_krs, vm, rs, *palm = NOTES_SEED[nu]
    t = term_means(spec(drag="skf-full"), nu)
    assert t["rolling"] == pytest.approx(rr, rel=6e-3)
    assert t["drag_vm"] == pytest.approx(vm, rel=6e-3)
    assert t["drag_rs"] == pytest.approx(rs, rel=6e-3)
    assert t["sliding"] == pytest.approx(0.02, abs=0.005)
    assert term_means(spec(k_rs=3e-8), nu)["rolling"] == pytest.approx(rr_krs, rel=0.02)
    for f0, watts in zip((1.5, 2.0, 4.0), palm, strict=True):
        assert cycle_mean(spec(model="palmgren", f0=f0), nu) == pytest.approx(watts, rel=6e-3)


# --------------------------------------------------------------------------- docs tables

COMPARISON_NU = (10, 22, 46, 100, 150, 220, 320, 460, 680, 1000)


def comparison_rows():
    """Seed cycle means [W] of 61809 at F_r = 50 N: SKF (V_M term), SKF (full drag), Palmgren."""
    rows = []
    for nu in COMPARISON_NU:
        skf = cycle_mean(spec(), nu)
        skf_rs = cycle_mean(spec(drag="skf-full"), nu)
        p2 = cycle_mean(spec(model="palmgren", f0=2.0), nu)
        p4 = cycle_mean(spec(model="palmgren"), nu)  # default f0 = 4 (submerged)
        rows.append((nu, skf, skf_rs, p2, p4, p4 / skf))
    return rows


SENSITIVITY_INPUTS = ("nu", "n", "dm", "Fr", "f0")


def mean_powers(nu=NU, peak=N, scale=1.0, fr=FR, f0=4.0):
    """Cycle-mean powers [W] per SKF term, SKF totals and Palmgren, for the elasticities."""
    cycle = DutyCycle.sine(peak_speed_rpm=peak, duration_s=20.0, sample_interval_s=0.01)
    geo = {"bore_mm": D_IN * scale, "outside_mm": D_OUT * scale, "series": "618",
           "radial_load_N": fr, "static_load_rating_N": C0}
    skf = term_means(bearing_spec_from({**geo, "drag": "skf-full"}), nu, cycle)
    palm = cycle_mean(bearing_spec_from({**geo, "model": "palmgren", "f0": f0}), nu, cycle)
    return {**skf, "skf (V_M term)": skf["rolling"] + skf["sliding"] + skf["drag_vm"],
            "skf (full drag)": sum(skf.values()), "palmgren": palm}


def elasticities(h=0.01):
    """d ln P / d ln x by central differences (x * (1 +- h)) at the seed point."""
    base = {"nu": NU, "peak": N, "scale": 1.0, "fr": FR, "f0": 4.0}
    key = {"nu": "nu", "n": "peak", "dm": "scale", "Fr": "fr", "f0": "f0"}
    out = {}
    for name in SENSITIVITY_INPUTS:
        hi = mean_powers(**{**base, key[name]: base[key[name]] * (1 + h)})
        lo = mean_powers(**{**base, key[name]: base[key[name]] * (1 - h)})
        d = math.log((1 + h) / (1 - h))
        out[name] = {k: (math.log(hi[k] / lo[k]) / d if lo[k] > 0 else 0.0) for k in hi}
    return out


def test_elasticities_of_the_power_law_terms_are_their_exponents():
    e = elasticities()
    # drag V_M: 0.4 V_M K_ball dm^5 n^2 (K_ball scale-free): P ~ nu^0 n^3 dm^5 Fr^0
    assert [e[x]["drag_vm"] for x in ("nu", "n", "dm", "Fr")] == pytest.approx(
        [0, 3, 5, 0], abs=1e-6)
    # drag R_s: n^0.621 dm^0.242 nu^1.379 R_s, R_s ~ dm^2: P ~ nu^1.379 n^1.621 dm^2.242
    assert [e[x]["drag_rs"] for x in ("nu", "n", "dm")] == pytest.approx(
        [1.379, 1.621, 2.242], abs=1e-6)
    assert e["Fr"]["rolling"] == pytest.approx(0.54, abs=1e-6)  # G_rr ~ Fr^0.54
    assert e["Fr"]["sliding"] == pytest.approx(5 / 3, abs=1e-6)  # G_sl ~ Fr^(5/3)
    # Palmgren (M0 dominates): nu^(2/3) n^(5/3) dm^3 f0
    assert [e[x]["palmgren"] for x in ("nu", "n", "dm", "f0")] == pytest.approx(
        [2 / 3, 5 / 3, 3, 1], abs=2e-3)


def test_cycle_means_of_pure_power_laws_match_the_closed_form():
    """A term M ~ |n|^a gives mean(M |omega|) = peak power * E|sin|^(1+a)."""
    cycle = DutyCycle.sine(duration_s=20.0, sample_interval_s=0.002)  # one period, 1e4 samples

    def e_sin(p):
        return math.gamma((p + 1) / 2) / (math.sqrt(math.pi) * math.gamma(p / 2 + 1))

    assert e_sin(3) == pytest.approx(4 / (3 * math.pi))  # the closed form itself, p = 3
    s = spec(drag="skf-full")
    peak = terms_Nmm(s)
    means = term_means(s, NU, cycle)
    for term, p in (("drag_vm", 3.0), ("drag_rs", 1.621)):
        assert means[term] == pytest.approx(peak[term] * 1e-3 * OMEGA * e_sin(p), rel=1e-7)
    palm = spec(model="palmgren")
    peak = terms_Nmm(palm)
    means = term_means(palm, NU, cycle)
    assert means["load_independent"] == pytest.approx(  # the nu n < 2000 floor: < 1e-6
        peak["load_independent"] * 1e-3 * OMEGA * e_sin(5 / 3), rel=1e-6)
    assert means["load_dependent"] == pytest.approx(
        peak["load_dependent"] * 1e-3 * OMEGA * e_sin(1.0), rel=1e-7)


def test_comparison_table_ratio():
    rows = comparison_rows()
    by_nu = {r[0]: r for r in rows}
    nu, skf, skf_rs, p2, p4, ratio = by_nu[320]
    assert skf == pytest.approx(4.66 + 0.02 + 5.34, rel=5e-3)  # notes section 5
    assert skf_rs == pytest.approx(156.1, rel=5e-3)
    assert ratio == pytest.approx(89.5 / 10.02, rel=5e-3)
    # Palmgren grows as nu^(2/3), SKF (V_M term) more slowly: the ratio rises with nu
    assert all(a[5] < b[5] for a, b in zip(rows, rows[1:], strict=False))


if __name__ == "__main__":  # the tables of docs/bearing.md
    print("| nu cSt | SKF V_M term W | SKF full drag W | Palmgren f0=2 W | Palmgren f0=4 W | "
          "Palmgren(4)/SKF(V_M term) |")
    print("|---|---|---|---|---|---|")
    for nu, skf, skf_rs, p2, p4, ratio in comparison_rows():
        print(f"| {nu} | {skf:.2f} | {skf_rs:.1f} | {p2:.1f} | {p4:.1f} | {ratio:.2f} |")
    e = elasticities()
    cols = list(e["nu"])
    print("\n| x | " + " | ".join(cols) + " |")
    print("|---|" + "---|" * len(cols))
    for x in SENSITIVITY_INPUTS:
        print(f"| {x} | " + " | ".join(f"{e[x][c]:.3f}" for c in cols) + " |")
    base = mean_powers()
    print("\nbase [W]: " + ", ".join(f"{k} {v:.3f}" for k, v in base.items()))
