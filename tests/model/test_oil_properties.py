"""Oil properties: Walther, Barus, density, sea-water pressure, the oil catalogue.

The published checks (the seed's 857 cSt, ISO 3448 grades) are in
``tests/validation/test_published_values.py``."""

import math

import numpy as np
import pytest

from oilgap.model import oil_properties as op
from oilgap.model.errors import InputError
from oilgap.model.oils import get_oil, read_oils_csv


def test_walther_line_passes_through_both_points():
    A, B = op.walther_coefficients(22.0, 313.15, 4.5, 373.15)
    assert op.walther_viscosity_cSt(313.15, A, B) == pytest.approx(22.0, rel=1e-12)
    assert op.walther_viscosity_cSt(373.15, A, B) == pytest.approx(4.5, rel=1e-12)


def test_walther_coefficients_by_hand():
    # log10(log10(22.7)) = log10(1.356026) = 0.132268; log10(log10(5.2)) = log10(0.716003)
    # = -0.145084; B = (0.132268 + 0.145084) / (log10 373.15 - log10 313.15)
    z1 = math.log10(math.log10(22.7))
    z2 = math.log10(math.log10(5.2))
    assert z1 == pytest.approx(0.132268, abs=2e-6)
    assert z2 == pytest.approx(-0.145084, abs=2e-6)
    b_hand = (0.132268 + 0.145084) / (2.571884 - 2.495752)
    A, B = op.walther_coefficients(22.0, 313.15, 4.5, 373.15)
    assert B == pytest.approx(b_hand, rel=1e-4)
    assert A == pytest.approx(0.132268 + b_hand * 2.495752, rel=1e-4)


def test_walther_inverse():
    A, B = op.walther_coefficients(150.0, 313.15, 14.5, 373.15)
    t = op.walther_temperature_K(1000.0, A, B)
    assert op.walther_viscosity_cSt(t, A, B) == pytest.approx(1000.0, rel=1e-10)


def test_barus_factor_by_hand():
    # 17 /GPa at 70 MPa: exp(0.017 * 70) = exp(1.19) = 3.2871 (physics notes: "x3.3 at 70 MPa")
    assert op.barus_factor(70e6, 17e-9) == pytest.approx(3.2871, rel=1e-4)
    assert op.barus_factor(0.0, 17e-9) == 1.0


def test_barus_coefficient_equals_reference_at_reference_viscosity_and_grows_colder():
    assert op.barus_coefficient(17e-9, 0.02, 0.02) == pytest.approx(17e-9, rel=1e-14)
    # Roelands slope ratio: ln(0.2/6.31e-5)/ln(0.02/6.31e-5) = 8.0613/5.7587 = 1.39985
    assert op.barus_coefficient(17e-9, 0.2, 0.02) == pytest.approx(17e-9 * 1.39985, rel=1e-4)


def test_density_laws_by_hand():
    assert op.oil_density(870.0, 288.15) == pytest.approx(870.0, rel=1e-14)
    # +25 K at 6.5e-4 /K: 870 exp(-0.01625) = 855.976
    assert op.oil_density(870.0, 313.15) == pytest.approx(855.976, rel=1e-5)
    # 18 MPa at K = 1.8 GPa: 870 exp(0.01) = 878.744
    assert op.oil_density(870.0, 288.15, 18e6) == pytest.approx(878.744, rel=1e-5)


def test_seawater_pressure_by_hand():
    # 1030 kg/m^3 * 9.80665 m/s^2 * 7000 m = 70.708 MPa
    assert op.seawater_gauge_pressure(7000.0) == pytest.approx(70.708e6, rel=1e-4)
    assert op.seawater_absolute_pressure(0.0) == pytest.approx(101325.0)


def test_kinematic_and_dynamic_viscosity_relation():
    o = get_oil("VG68")
    nu, mu, rho = o.properties(np.array([275.0, 300.0]), np.array([0.0, 3e7]))
    assert np.allclose(mu, nu * rho, rtol=1e-14)


def test_unknown_oil_names_field_and_known_values():
    with pytest.raises(InputError) as e:
        get_oil("VG99")
    assert "oil" in str(e.value) and "VG99" in str(e.value) and "VG22" in str(e.value)


def test_user_oils_csv(tmp_path):
    p = tmp_path / "oils.csv"
    p.write_text("oil,nu40_cSt,nu100_cSt,density_kg_m3,barus_1_GPa\nSilicone 50,50,20,960,8\n")
    cat = read_oils_csv(p)
    o = get_oil("silicone 50", cat)
    assert o.barus_1_Pa == pytest.approx(8e-9)
    assert o.kinematic_viscosity_cSt(100.0) == pytest.approx(20.0, rel=1e-10)


@pytest.mark.parametrize("text,field", [
    ("oil,nu40_cSt,density_kg_m3\nA,10,900\n", "columns"),
    ("oil,nu40_cSt,nu100_cSt,density_kg_m3,colour\nA,10,3,900,red\n", "columns"),
    ("oil,nu40_cSt,nu100_cSt,density_kg_m3\nA,ten,3,900\n", "nu40_cSt"),
    ("oil,nu40_cSt,nu100_cSt,density_kg_m3\nA,10,3,-900\n", "density_kg_m3"),
    ("oil,nu40_cSt,nu100_cSt,density_kg_m3\nA,10,30,900\n", "nu100_cSt"),
    ("oil,nu40_cSt,nu100_cSt,density_kg_m3\nA,nan,3,900\n", "nu40_cSt"),
    ("oil,nu40_cSt,nu100_cSt,density_kg_m3\nA,10,3,900\na,11,3,900\n", "oil"),
])
def test_bad_oils_csv(tmp_path, text, field):
    p = tmp_path / "oils.csv"
    p.write_text(text)
    with pytest.raises(InputError) as e:
        read_oils_csv(p)
    assert e.value.field == field
