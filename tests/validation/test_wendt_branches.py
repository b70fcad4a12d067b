"""Leave-one-gap-out on Wendt's (1933) torque correlations: the ``"branches"`` form
fitted on two gaps predicts the third; Eq. 6 with a shared gap exponent does not.

Source. F. Wendt, "Turbulente Strömungen zwischen zwei rotierenden konaxialen
Zylindern", Ingenieur-Archiv 4:577-595 (1933), measured the torque on the inner of
two cylinders (outer at rest) at radius ratios eta = 0.68, 0.85 and 0.935 and fitted

    G = 1.45 eta^1.5 / (1 - eta)^1.75 Re^1.5     for 4e2 < Re < 1e4  (vortex flow)
    G = 0.23 eta^1.5 / (1 - eta)^1.75 Re^1.7     for 1e4 < Re < 1e5  (turbulent flow)

with G = T / (rho nu^2 L) (T the torque on a length L) and Re = omega r1 d / nu, the
seed's Couette Reynolds number (Eq. 4). These are the coefficients as commonly quoted
from Wendt (Lathrop, Fineberg & Swinney, Phys. Rev. A 46:6390, 1992; Dubrulle et al.,
Phys. Fluids 17:095103, 2005), written from that quotation; neither the original nor
those papers' text could be retrieved. Two checks on the quote: the turbulent exponent
is 1.7, not 1.5 (with 1.5 in both ranges the two laws would differ 6.3-fold at Re = 1e4;
with 1.7 they meet within 0.1 %: 1.45e6 against 0.23 * 1e4^1.7 = 1.4512e6), and the
abstract of Donnelly & Simon (J. Fluid Mech. 7:401, 1960; retrieved from
scilit.net/publications/e3f053d5443a0850dd75dda5e6998366), fitting Wendt's, Taylor's and
Donnelly's data, gives G ~ Omega^1.51 well above onset and a gap power of about 0.31.

Conversion to the seed's C_m (Eq. 5, ``P = T omega = 0.5 pi C_m rho omega^3 R^4 L``, see
``model/viscous_loss.py``): ``C_m = 2 T / (pi rho omega^2 R^4 L) = (2/pi) G nu^2 /
(omega^2 R^4)``, and with ``omega = Re nu / (R d)``: ``C_m = (2/pi) G x^2 / Re^2`` (x =
d/R). With eta = 1/(1+x), ``eta^1.5 / (1-eta)^1.75 = x^-1.75 (1+x)^0.25``, so
``C_m = (2A/pi) x^0.25 (1+x)^0.25 Re^(n-2)``: 0.9231 x^0.25 (1+x)^0.25 Re^-0.5 in the
vortex range, 0.14642 x^0.25 (1+x)^0.25 Re^-0.3 in the turbulent one.

The gaps are Wendt's own three (x = 0.0695, 0.176, 0.471), Re 1e3-1e5 (24 speeds per
gap). Wendt's gap dependence is the same in both ranges (x^0.25 (1+x)^0.25), so this
checks the per-regime machinery and the free beta_k (his turbulent slope is -0.3, Eq.
6's -0.2), not a regime-dependent gap exponent.
"""

import math

import numpy as np
import pytest
from scipy.optimize import least_squares

from oilgap.model.skin_friction import FrictionLaw, moment_coefficient
from oilgap.optim.calibration.spec import branch_identifiability

ETAS = (0.935, 0.85, 0.68)
RE = np.logspace(3, 5, 24)


def wendt_G(re, eta):
    re = np.asarray(re, float)
    geo = eta**1.5 / (1 - eta) ** 1.75
    return np.where(re < 1e4, 1.45 * geo * re**1.5, 0.23 * geo * re**1.7)


def wendt_cm(re, x):
    """Wendt's G as the seed's C_m: (2/pi) G x^2 / Re^2."""
    return 2 / math.pi * wendt_G(re, 1 / (1 + x)) * x**2 / np.asarray(re, float) ** 2


def test_conversion_by_hand():
    # eta 0.85 (x = 0.15/0.85 = 0.176471): eta^1.5 = 0.783661, 0.15^1.75 = 0.0361543,
    # ratio 21.6755. Re 2000: Re^1.5 = 89442.7, G = 1.45 * 21.6755 * 89442.7 = 2.81113e6,
    # C_m = (2/pi) 2.81113e6 * 0.0311419 / 4e6 = 0.0139331.
    # Re 3e4: Re^1.7 = 4.08419e7, G = 0.23 * 21.6755 * 4.08419e7 = 2.03612e8,
    # C_m = (2/pi) 2.03612e8 * 0.0311419 / 9e8 = 4.48523e-3.
    x = 0.15 / 0.85
    assert wendt_cm(2000.0, x) == pytest.approx(0.0139331, rel=1e-5)
    assert wendt_cm(3e4, x) == pytest.approx(4.48523e-3, rel=1e-5)
    # closed form (2A/pi) x^0.25 (1+x)^0.25 Re^(n-2): 0.923099 * 0.648143 * 1.041523 / 44.7214
    assert 0.923099 * x**0.25 * (1 + x) ** 0.25 / math.sqrt(2000) == pytest.approx(
        0.0139331, rel=1e-5)
    # the two ranges meet at Re = 1e4 within 0.1 %
    assert 0.23 * 1e4**1.7 / 1.45e6 == pytest.approx(1.0008, abs=1e-4)


def _data(etas):
    xs = np.concatenate([np.full(RE.size, 1 / e - 1) for e in etas])
    res = np.tile(RE, len(etas))
    return res, xs, wendt_cm(res, xs)


def _log_rmse(law, re, x, cm):
    return float(np.sqrt(np.mean((np.log(moment_coefficient(re, x, law)) - np.log(cm)) ** 2)))


def fit_branches(re, x, cm):
    """Fit the identified C_k, alpha_k, beta_k of the branches form (the rest held)."""
    pub = FrictionLaw(form="branches")
    ident = branch_identifiability(re, x, pub)
    free = [k for k, (ok, _) in ident.items() if ok]
    vals = {f"{n}{k + 1}": v for n, arr in (("C", pub.branch_C), ("alpha", pub.branch_alpha),
                                            ("beta", pub.branch_beta))
            for k, v in enumerate(arr)}

    def law_of(p):
        v = dict(vals)
        for k, val in zip(free, p, strict=True):
            v[k] = math.exp(val) if k.startswith("C") else val
        n = len(pub.branch_C)
        return FrictionLaw(form="branches", branch_C=tuple(v[f"C{i + 1}"] for i in range(n)),
                           branch_alpha=tuple(v[f"alpha{i + 1}"] for i in range(n)),
                           branch_beta=tuple(v[f"beta{i + 1}"] for i in range(n)))

    p0 = [math.log(vals[k]) if k.startswith("C") else vals[k] for k in free]
    sol = least_squares(lambda p: np.log(moment_coefficient(re, x, law_of(p))) - np.log(cm),
                        p0, x_scale=1.0, xtol=1e-12, ftol=1e-12)
    return law_of(sol.x), ident


def fit_shared_alpha(re, x, cm):
    """Eq. 6 (its smooth form, the loop's eq6 base) with free scale and shared alpha."""
    def law_of(p):
        return FrictionLaw(form="smooth", scale=math.exp(p[0]), alpha=p[1])
    sol = least_squares(lambda p: np.log(moment_coefficient(re, x, law_of(p))) - np.log(cm),
                        [0.0, 0.3], xtol=1e-12, ftol=1e-12)
    return law_of(sol.x)


def leave_one_gap_out():
    rows = []
    for held in ETAS:
        train = [e for e in ETAS if e != held]
        law, ident = fit_branches(*_data(train))
        shared = fit_shared_alpha(*_data(train))
        test = _data([held])
        rows.append((held, _log_rmse(law, *test), _log_rmse(shared, *test), law, ident))
    return rows


@pytest.fixture(scope="module")
def logo():
    return leave_one_gap_out()


def test_branches_predict_each_held_out_gap_within_0_05(logo):
    for eta, err_branches, err_shared, _, _ in logo:
        assert err_branches < 0.05, (eta, err_branches)
        assert err_branches < err_shared, (eta, err_branches, err_shared)


def test_shared_alpha_form_misses(logo):
    # Eq. 6's turbulent slope -0.2 against Wendt's -0.3 over a decade of Re: 0.1 * ln 10 =
    # 0.23 in ln C_m, which a fitted scale and shared alpha cannot absorb (0.08 found).
    worst = max(r[2] for r in logo)
    assert worst > 0.05


def test_only_what_the_training_gaps_identify_is_freed(logo):
    for _, _, _, law, ident in logo:
        # Re 1e3-1e5: branches 3 (vortex) and 4 (turbulent) govern; 1 and 2 never do
        for k in (1, 2):
            assert not ident[f"C{k}"][0] and not ident[f"alpha{k}"][0]
            assert not ident[f"beta{k}"][0]
        assert law.branch_C[:2] == (10.0, 2.0) and law.branch_beta[:2] == (-1.0, -0.6)
        for k in (3, 4):
            assert ident[f"C{k}"][0] and ident[f"alpha{k}"][0] and ident[f"beta{k}"][0]
        # the fitted slopes are Wendt's: n - 2 = -0.5 and -0.3
        assert law.branch_beta[2] == pytest.approx(-0.5, abs=0.02)
        assert law.branch_beta[3] == pytest.approx(-0.3, abs=0.02)
        # gap exponent of x^0.25 (1+x)^0.25 over x = 0.07..0.47: 0.25 + 0.25 x/(1+x)
        assert 0.25 < law.branch_alpha[2] < 0.34 and 0.25 < law.branch_alpha[3] < 0.34


def test_one_gap_frees_no_alpha():
    re, x, _ = _data([0.85])
    ident = branch_identifiability(re, x, FrictionLaw(form="branches"))
    assert not any(ident[f"alpha{k}"][0] for k in range(1, 5))
    assert ident["beta3"][0] and ident["beta4"][0]


def test_one_regime_frees_no_other_regimes_beta():
    # Re 2e3-8e3 only: inside branch 3 (762 < Re < 9996) at three gaps
    re = np.tile(np.logspace(math.log10(2e3), math.log10(8e3), 8), 3)
    x = np.repeat([0.0695, 0.176, 0.471], 8)
    ident = branch_identifiability(re, x, FrictionLaw(form="branches"))
    assert ident["beta3"][0] and ident["alpha3"][0] and ident["C3"][0]
    for k in (1, 2, 4):
        assert not ident[f"beta{k}"][0] and not ident[f"alpha{k}"][0]
        assert "held at" in ident[f"beta{k}"][1]


def test_narrow_speed_range_frees_no_beta():
    # three gaps, each at Re 3000-4000 (ln span 0.29 < 0.5): alpha_3 yes, beta_3 no
    re = np.tile(np.linspace(3000, 4000, 5), 3)
    x = np.repeat([0.0695, 0.176, 0.471], 5)
    ident = branch_identifiability(re, x, FrictionLaw(form="branches"))
    assert ident["alpha3"][0] and not ident["beta3"][0]


def test_recovers_a_gap_exponent_that_differs_by_regime():
    # Not a validation (the data come from the form itself): the behaviour the issue reports
    # for air at three gaps (delta/R 0.009-0.039), a vortex branch with alpha 0.27 and a
    # turbulent one with alpha 0 (C_m Re^0.2 the same at every gap), so the vortex/turbulent
    # crossing moves with the gap: Re = (1.03 x^0.27 / 0.0226)^(1/0.3) = 4.9e3 at x = 0.009,
    # 1.8e4 at 0.039. Fitted on two gaps, the branches form finds both exponents and
    # predicts the third; Eq. 6 with one shared alpha cannot (log-RMSE ~0.1 at the end gaps).
    truth = FrictionLaw(form="branches", branch_C=(10.0, 2.0, 1.03, 0.0226),
                        branch_alpha=(0.3, 0.3, 0.27, 0.0))
    xs = (0.009, 0.02, 0.039)

    def data(gaps):
        x = np.repeat(gaps, RE.size)
        re = np.tile(RE, len(gaps))
        return re, x, moment_coefficient(re, x, truth)

    for held in xs:
        law, _ = fit_branches(*data([g for g in xs if g != held]))
        assert law.branch_alpha[2] == pytest.approx(0.27, abs=1e-3)
        assert law.branch_alpha[3] == pytest.approx(0.0, abs=1e-3)
        assert _log_rmse(law, *data([held])) < 0.01
        if held != 0.02:  # the middle gap is interpolated; the end gaps are not
            shared = fit_shared_alpha(*data([g for g in xs if g != held]))
            assert _log_rmse(shared, *data([held])) > 0.07
