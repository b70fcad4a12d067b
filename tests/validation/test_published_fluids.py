"""The built-in gases against published property tables.

Sources:
* U.S. Standard Atmosphere, 1976 (NOAA/NASA/USAF, NOAA-S/T 76-1562), sea-level values:
  T = 288.15 K, p = 101325 Pa, rho = 1.2250 kg/m^3, mu = 1.7894e-5 Pa s,
  nu = 1.4607e-5 m^2/s.
* F. P. Incropera, D. P. DeWitt, T. L. Bergman, A. S. Lavine, *Fundamentals of Heat and
  Mass Transfer*, 6th ed., Wiley 2007, Table A.4 (gases at 1 atm): air mu = 159.6e-7 and
  184.6e-7 N s/m^2 at 250 and 300 K; nitrogen mu = 178.2e-7 N s/m^2 at 300 K.
* Dry air at 20 degC and 101.325 kPa: rho = 1.2041 kg/m^3, nu = 15.1 cSt (standard
  dry-air tables, e.g. the same Table A.4 interpolated in 1/T).

Sutherland's constants are White's (*Viscous Fluid Flow*, 3rd ed., Table 1-2), so these
are checks of independent measurements, not of the constants' own source.
"""

import pytest

from oilgap.model.oils import get_oil


def test_air_at_sea_level_us_standard_atmosphere_1976():
    nu, mu, rho = get_oil("air").properties(288.15, 0.0)
    # oilgap's M = 28.97 g/mol against the standard's 28.9644: rho +0.02 %
    assert rho == pytest.approx(1.2250, rel=5e-4)
    assert mu == pytest.approx(1.7894e-5, rel=1e-3)
    assert nu == pytest.approx(1.4607e-5, rel=1e-3)


def test_air_at_20C_and_1_atm():
    nu, mu, rho = get_oil("air").properties(293.15, 0.0)
    # Incropera Table A.4, linear between 250 and 300 K at 293.15 K:
    # 159.6 + (184.6 - 159.6) * 43.15 / 50 = 181.2e-7 N s/m^2
    assert mu == pytest.approx(1.812e-5, rel=5e-3)
    assert mu == pytest.approx(1.81e-5, rel=1e-2)
    assert rho == pytest.approx(1.2041, rel=1e-3)
    assert nu * 1e6 == pytest.approx(15.1, rel=1e-2)


def test_nitrogen_at_300K():
    _, mu, _ = get_oil("nitrogen").properties(300.0, 0.0)
    assert mu == pytest.approx(178.2e-7, rel=5e-3)  # Incropera Table A.4
