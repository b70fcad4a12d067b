"""The oil-grade study with a rolling bearing: its drag changes which grade is best.

A constructed case, reasoned by hand. The seed joint at 0 m and 40 degC with two oils
that pass both limits there:

* ``DENSE600``: nu = 600 cSt, density 1900 kg/m^3 at 15 degC (a perfluoropolyether-like
  oil: thin but heavy);
* ``LIGHT1200``: nu = 1200 cSt, density 850 kg/m^3 (a thick mineral oil).

**Clearances.** At 40 degC and 0 m nu is the grade's nu40 exactly (Walther line through
it, gauge pressure 0). Every node of the cycle is laminar: at the 3000 rpm peak
(314.16 rad/s) Re1 = omega R delta/nu = 314.16 x 0.0254 x 0.001/6e-4 = 13.3 and
Re2 = 314.16 x 0.022 x 0.005/6e-4 = 57.6 < 64 for DENSE600 (half that for LIGHT1200).
Laminar Couette loss is proportional to mu = rho nu at fixed geometry and cycle, and
both densities follow the same expansion law, so
``P_LIGHT / P_DENSE = (1200 x 850)/(600 x 1900) = 0.8947``: **without a bearing the
thick, light oil loses 10.5 % less and is recommended** (the study's own powers:
about 212 and 190 W).

**Bearing.** A 6809 (61809, dm = 51.5 mm) with Palmgren's model at f0 = 2 (oil bath).
Its load-independent moment ``M0 = 1e-7 f0 (nu n)^(2/3) dm^3`` scales as nu^(2/3), the
load term (0.02 W at 50 N) not at all, so ``P_b,LIGHT / P_b,DENSE = 2^(2/3) = 1.587``.
Over the sine cycle ``mean(M0 |omega|) = peak x E|sin|^(5/3)``,
``E|sin|^p = Gamma((p+1)/2)/(sqrt(pi) Gamma(p/2+1)) = 0.5356``; at 600 cSt the peak is
2e-7 x (600 x 3000)^(2/3) x 51.5^3 N mm = 404.3 N mm x 314.16 rad/s = 127.0 W, so
P_b,DENSE = 68.0 W and P_b,LIGHT = 108.0 W. Totals: DENSE 212 + 68 = 280 W, LIGHT
190 + 108 = 298 W: **with the bearing the thin, heavy oil wins**. The flip needs
``P_b,DENSE > (P_DENSE - P_LIGHT)/(2^(2/3) - 1) = 22.3/0.587 = 38 W``: 68 W is well past it.
"""

import math
from dataclasses import replace

import numpy as np
import pytest

from oilgap.model.bearing.catalogue import bearing_spec_from
from oilgap.model.case import OperatingPoint, ThermalSpec
from oilgap.model.io.case_io import seed_case
from oilgap.model.joint_loss import operating_temperature
from oilgap.studies.grid.evaluate import evaluate_cases
from oilgap.studies.oil_grade import study as oil_grade
from oilgap.studies.settings import OilGradeSettings, split_keywords


def run(out_dir=None, case=None, mission=None, **keywords):
    """The study from keywords, as the façade builds its records."""
    return oil_grade.run(out_dir, case, mission, *split_keywords(keywords, OilGradeSettings))

OILS = "oil,nu40_cSt,nu100_cSt,density_kg_m3\nDENSE600,600,45,1900\nLIGHT1200,1200,60,850\n"
STUDY = dict(grades=["DENSE600", "LIGHT1200"], depth_range_m=(0.0, 0.0),
             temp_range_C=(40.0, 40.0), n_depth=2, n_temp=2, mission=[(0.0, 40.0, 1.0)],
             rated_temps_C=[40.0], nu_max_cSt=5000.0, thermal="none", workers=1)


@pytest.fixture(scope="module")
def case(tmp_path_factory):
    path = tmp_path_factory.mktemp("oils") / "oils.csv"
    path.write_text(OILS)
    return replace(seed_case(), oils_csv=str(path), operating=OperatingPoint(0.0, 40.0))


def palmgren_mean_W(nu_cSt, f0=2.0, dm_mm=51.5, peak_rpm=3000.0):
    """Hand calculation: Palmgren's M0 over the sine cycle (M1 left out: 0.02 W)."""
    p = 5.0 / 3.0
    e_sin = math.gamma((p + 1) / 2) / (math.sqrt(math.pi) * math.gamma(p / 2 + 1))
    peak_Nmm = 1e-7 * f0 * (nu_cSt * peak_rpm) ** (2.0 / 3.0) * dm_mm**3
    return peak_Nmm * 1e-3 * peak_rpm * 2 * math.pi / 60 * e_sin


def test_a_viscosity_dependent_bearing_changes_the_recommended_grade(case):
    plain = run(case=case, **STUDY)
    bearing = bearing_spec_from({"designation": "6809", "model": "palmgren", "f0": 2.0})
    with_b = run(case=replace(case, bearing=bearing), **STUDY)
    t0, t1 = (r.table.set_index("oil") for r in (plain, with_b))
    assert t0.loc[:, "passes_lubrication"].all() and t0.loc[:, "passes_cold"].all()
    # clearances alone: laminar, P ~ mu, the thick light oil loses less
    p0 = t0["mission_mean_power_W"]
    assert p0["LIGHT1200"] / p0["DENSE600"] == pytest.approx(1200 * 850 / (600 * 1900),
                                                             rel=1e-6)
    assert plain.recommended == "LIGHT1200"
    assert "rated_bearing_power_W" not in t0.columns
    # the bearing's share: the hand calculation, and the 2^(2/3) ratio
    pb = t1["mission_bearing_power_W"]
    assert pb["DENSE600"] == pytest.approx(palmgren_mean_W(600.0), rel=2e-3)
    assert pb["LIGHT1200"] == pytest.approx(palmgren_mean_W(1200.0), rel=2e-3)
    assert pb["LIGHT1200"] / pb["DENSE600"] == pytest.approx(2 ** (2 / 3), rel=1e-3)
    np.testing.assert_allclose(t1["mission_mean_power_W"], p0 + pb, rtol=1e-12)
    np.testing.assert_allclose(t1["rated_bearing_power_W"], pb, rtol=1e-12)
    assert pb["DENSE600"] > (p0["DENSE600"] - p0["LIGHT1200"]) / (2 ** (2 / 3) - 1)
    assert with_b.recommended == "DENSE600"
    assert with_b.runner_up == "LIGHT1200"


@pytest.mark.parametrize("mode", ["none", "film", "full"])
def test_the_grid_the_study_runs_on_includes_the_bearing_row_by_row(mode):
    # cases with different bearings (and none) in one call: grouped apart, each row the
    # joint's operating state of oilgap evaluate (joint_loss.operating_temperature)
    seed = replace(seed_case(), thermal=ThermalSpec(2.0, 0.5, 5e4))
    cases = [replace(seed, bearing=bearing_spec_from({"designation": "6809", "model": m}),
                     operating=OperatingPoint(d, 2.0))
             for m in ("skf", "palmgren") for d in (0.0, 3000.0)] + [seed]
    df = evaluate_cases(cases, mode)
    for c, (_, r) in zip(cases, df.iterrows(), strict=True):
        op = operating_temperature(c, mode)
        assert r["oil_temp_op_C"] == pytest.approx(op.oil_temp_C, abs=1e-9)
        assert r["mean_power_W"] == pytest.approx(op.mean_power_W, rel=1e-10)
        assert r["mean_power_W"] - r["region1_power_W"] - r["region2_power_W"] == \
            pytest.approx(op.bearing_mean_power_W, abs=1e-9)
    assert (df["mean_power_W"][[1, 3]] > df["mean_power_W"][4]).all()  # same 3000 m
