"""The physical domain of each library effect (issue 25 item 4): an effect whose domain the
data never reach is not a candidate, and the status says why with the number.

The domain quantity is computed here by hand from the runs: the Taylor number of seed
Eq. 3, ``Ta = Re (delta/R)^0.5`` with ``Re = omega R delta / nu`` (R = 0.1 m, the rig's
rotor radius, delta the run's gap and nu its viscosity, both columns of the data).
"""

import math
import tomllib

import numpy as np
import pandas as pd
import pytest

from oilgap.model.effects import EFFECTS
from oilgap.model.effects.domains import DOMAINS, Domain
from oilgap.model.io.case_io import case_from_dict
from oilgap.optim.calibration import LoopEstimator

RIG = """
name = "smooth-cylinder oil rig"
[region1]
T1_mm = 99.0
T2_mm = 100.0
T3_mm = 100.5
T4_mm = 101.5
length_mm = 60.0
[friction]
form = "bilgen-boulos"
laminar_law = "couette"
[motor]
shaft_bore_radius_mm = 15.0
"""
R, L = 0.1, 0.06
NU, RHO = 100e-6, 870.0   # a 100 cSt oil [m^2/s], [kg/m^3]


def laminar_runs(gaps_mm=(0.5, 1.0), rpm_max=3000.0, seed=0):
    """Exact Couette power (1 % noise) of an oil given by its nu and rho columns."""
    rng = np.random.default_rng(seed)
    rows = []
    for g in gaps_mm:
        rpm = np.linspace(100.0, rpm_max, 15)
        w = rpm * math.pi / 30
        x = g * 1e-3 / R
        re = w * R * g * 1e-3 / NU
        cm = 8 * (1 + x) ** 2 / ((2 + x) * re)          # exact Couette C_m
        p = 0.5 * math.pi * cm * RHO * w**3 * R**4 * L * (1 + 0.01 * rng.standard_normal(w.size))
        rows.append(pd.DataFrame({"run": f"gap {g}", "speed_rpm": rpm, "temp_C": 20.0,
                                  "oil": "test oil", "roughness_T": 1.0,
                                  "viscous_power_W": p, "nu_cSt": NU * 1e6,
                                  "density_kg_m3": RHO, "gap_mm": g}))
    return pd.concat(rows, ignore_index=True)


def hand_max_taylor(df):
    w = df.speed_rpm.to_numpy() * math.pi / 30
    d = df.gap_mm.to_numpy() * 1e-3
    nu = df.nu_cSt.to_numpy() * 1e-6
    return float(np.max(w * R * d / nu * np.sqrt(d / R)))


@pytest.fixture(scope="module")
def fit():
    df = laminar_runs()
    est = LoopEstimator(case=case_from_dict(tomllib.loads(RIG)), base="eq6",
                        cv_by="gap_mm").fit(df)
    return df, est


def test_every_effect_declares_its_domain():
    assert set(DOMAINS) == set(EFFECTS)
    for name, eff in EFFECTS.items():
        assert isinstance(eff.domain, Domain) and eff.domain.statement, name


def test_taylor_onset_is_not_a_candidate_below_critical_with_the_max_ta(fit):
    df, est = fit
    ta = hand_max_taylor(df)   # 3000 rpm, 1 mm, 100 cSt: 314.2 * 0.1 = 31.4
    assert ta == pytest.approx(31.416, rel=1e-4) and ta < 41.3
    st = {c["name"]: c["status"] for c in est.candidates_}
    assert st["taylor_vortex_onset"] == ("not a candidate: the data never reach Ta > Ta_c = "
                                         f"41.3 (max Ta {ta:.3g})")
    assert "taylor_vortex_onset" not in [e.name for e in est.effects_]


def test_shear_thinning_needs_a_polymer_thickened_liquid(fit):
    _, est = fit
    st = {c["name"]: c["status"] for c in est.candidates_}
    assert st["shear_thinning"] == ("not a candidate: no polymer-thickened liquid among the "
                                    "fluids of the oil runs (test oil: Newtonian)")


def test_report_shows_the_domain(fit):
    from oilgap.studies.loop.report import report_markdown
    _, est = fit
    md = report_markdown(est, figures=False)
    assert "not a candidate: the data never reach Ta > Ta_c = 41.3" in md


def test_above_critical_the_taylor_domain_is_reached():
    # the same rig 2x faster: Ta = 62.8 > 41.3 at the 1 mm gap, so the domain is reached
    df = laminar_runs(gaps_mm=(0.8, 1.0), rpm_max=6000.0)
    assert hand_max_taylor(df) == pytest.approx(62.83, rel=1e-3)
    est = LoopEstimator(case=case_from_dict(tomllib.loads(RIG)), base="eq6", cv_by="gap_mm",
                        effects=["taylor_vortex_onset"]).fit(df)
    st = {c["name"]: c["status"] for c in est.candidates_}
    assert not st["taylor_vortex_onset"].startswith("not a candidate")
