"""Stage 3c, ranges: findings by hand, the effective scale, the rules of the evidence trial;
the plausibility facts of the data's fluids."""

import math
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from oilgap.model.effects import EFFECTS, FluidFacts, RigFacts
from oilgap.model.oils import builtin_fluids, get_oil
from oilgap.model.regions import joint_geometry
from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration import (
    PARAM_RANGES,
    BaseSpec,
    ForwardModel,
    ModelFit,
    fluid_facts,
    held_values,
    parameter_findings,
)
from oilgap.optim.calibration.ranges import effective_scale, no_signal_finding


def _fit(spec, values, n=1):
    x = spec.start(values)
    return ModelFit(x, np.zeros(0), spec.law(x), np.zeros(n), np.zeros((n, len(x))))


def test_every_range_has_a_basis_and_a_source():
    assert PARAM_RANGES["scale"].low == 0.7 and PARAM_RANGES["scale"].high == 1.4
    assert (PARAM_RANGES["beta"].low, PARAM_RANGES["beta"].high) == (-1.0, -0.2)
    assert PARAM_RANGES["gamma"].low == 0.0 and PARAM_RANGES["alpha"].low <= 0.3
    for r in PARAM_RANGES.values():
        assert r.basis and r.source and r.low < r.high


def test_findings_by_hand(rig, samples_factory):
    m = ForwardModel(samples_factory(), rig.case, rig.oils)
    spec = BaseSpec(("scale", "gamma"), {"alpha": 0.3}, "eq6")
    assert parameter_findings(spec, _fit(spec, {"scale": 1.1, "gamma": 0.5}), m) == []
    out = parameter_findings(spec, _fit(spec, {"scale": 1.6, "gamma": -0.3}), m)
    by = {f.parameter: f for f in out}
    assert by["scale"].held_at == 1.4 and by["scale"].value == pytest.approx(1.6)
    assert by["scale"].message.startswith("the scale is 1.6x the published law")
    assert by["gamma"].held_at == 0.0
    assert "the grooved build loses less than the smooth one" in by["gamma"].message
    # with an exponent held, the level is refitted rather than held
    assert held_values(out) == {"gamma": 0.0}
    assert held_values([by["scale"]]) == {"scale": 1.4}


def test_power_law_level_is_judged_by_its_effective_scale(rig, samples_factory):
    m = ForwardModel(samples_factory(), rig.case, rig.oils)
    pub = FrictionLaw(form="smooth", gamma=0.2)
    # a law giving exactly 1.8x the published power: the smooth Eq. 6 at scale 1.8
    assert effective_scale(m, FrictionLaw(form="smooth", gamma=0.2, scale=1.8),
                           "couette") == pytest.approx(1.8, rel=1e-12)
    spec = BaseSpec(("C", "beta"), {"alpha": 0.3, "gamma": 0.2})
    fit = _fit(spec, {"C": 10.0, "beta": -0.1})
    eff = effective_scale(m, fit.law, "couette")
    p_fit, p_pub = m.base_power(fit.law), m.base_power(pub)
    assert eff == pytest.approx(float(p_fit @ p_pub / (p_pub @ p_pub)), rel=1e-12)
    out = {f.parameter: f for f in parameter_findings(spec, fit, m)}
    assert out["beta"].held_at == -0.2
    if not 0.7 <= eff <= 1.4:
        assert out["C"].effective_scale == pytest.approx(eff)
        bound = 1.4 if eff > 1.4 else 0.7
        assert out["C"].held_at == pytest.approx(10.0 * bound / eff)


def test_a_parameter_on_its_box_is_reported_not_used():
    spec = BaseSpec(("C",), {"alpha": 0.3, "beta": -1.0, "gamma": 0.0})
    fit = ModelFit(np.array([-50.0]), np.zeros(0), spec.law(np.array([-50.0])), np.zeros(3),
                   np.zeros((3, 1)))
    m = SimpleNamespace(base_power=lambda law: np.ones(3))
    (f,) = parameter_findings(spec, fit, m)
    assert f.kind == "at numerical limit" and f.held_at is None
    assert f.value == pytest.approx(math.exp(-50))


def test_no_signal_finding():
    y = np.array([0.5, -0.5, 0.4, -0.6])
    assert no_signal_finding(y + 10.0, np.full(4, 10.0), 0.5) is None
    f = no_signal_finding(y, np.full(4, 1e-6), 0.5)
    assert f.kind == "no viscous signal" and f.message.startswith("no viscous signal")
    # in loop.json: parameter and held_at as null, no range keys, no evidence key
    assert list(f.to_dict()) == ["kind", "parameter", "value", "message", "held_at"]
    assert f.to_dict()["parameter"] is None and f.to_dict()["held_at"] is None


def test_fluid_facts_of_the_data():
    s = SimpleNamespace(oil=np.array(["VG320", "VG320", "air", "mystery"]))
    assert fluid_facts(s, builtin_fluids())[0] == FluidFacts("VG320", "mineral", False)
    thick = {**builtin_fluids(), "VG320": replace(get_oil("VG320"), polymer_thickened=True)}
    facts = {f.name: f for f in fluid_facts(s, thick)}
    assert facts["VG320"] == FluidFacts("VG320", "mineral", True)
    assert facts["air"].kind == "gas" and not facts["air"].polymer_thickened
    # a per-row fluid the table does not hold counts as Newtonian
    assert facts["mystery"] == FluidFacts("mystery", "unknown", False)


def test_plausibility_rules_by_hand(rig):
    geom = joint_geometry(rig.case)
    oil = FluidFacts("VG320", "mineral", False)
    f = RigFacts.of(geom, [oil])
    # largest wetted radius: region 1 25.4 + 1 mm, region 2 (bearing) 22 + 5 mm = 27 mm
    assert f.radius_max_m == pytest.approx(0.027)
    assert f.wetted_length_m == pytest.approx(rig.case.region1.length + rig.case.region2.length)
    # seal: 0.5 N/mm over the circumference at that radius, tau = f 2 pi r^2
    tau_max = 500.0 * 2 * math.pi * f.radius_max_m ** 2
    seal = EFFECTS["seal_coulomb_friction"]
    assert seal.plausible.range(f) == pytest.approx((0.0, tau_max))
    assert seal.implausibility(0.9 * tau_max, f) is None
    assert "outside the plausible" in seal.implausibility(1.1 * tau_max, f)
    # shear thinning: a mineral oil rules it out at any coefficient; thickened, its range
    thin = EFFECTS["shear_thinning"]
    assert "needs a polymer-thickened liquid: VG320 is a straight mineral oil" in \
        thin.implausibility(1e-10, f)
    g = RigFacts.of(geom, [FluidFacts("VG320", "mineral", True)])
    assert thin.implausibility(1e-10, g) is None
    assert "outside the plausible" in thin.implausibility(1e-5, g)
    assert "sensor" not in EFFECTS["sensor_delay"].implausibility(5.0, f)
    assert EFFECTS["sensor_delay"].time_dependent and not seal.time_dependent
