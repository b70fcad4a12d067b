"""The measured-data loop on data from outside its family (issue 9, "How to verify").

The data come from the out-of-family rig (``oilgap.studies.rigs.outside_rig``): truth from
the piecewise Eq. 6 with a Couette floor (not a power law), a gearbox loss
``k |tau w|^1.3`` and a constant-torque load outside the loop's baseline basis, AR(1)
noise on power (phi = 0.8, 1 W), the trapezoid speed profile, and each effect by a law
of its own (Daily & Nece enclosed discs, Palmgren, Coulomb + Stribeck, Wendt-shaped
Taylor excess, Carreau, a real time shift, a first-order lag of the oil temperature).

The rig (the default ``OutsideConfig``): the seed joint (regions 1 and 2), ISO VG 22, 68,
220 and 680, T = 4 and 2, oil-free runs, 300 samples every 0.2 s per run. The loop gets
the rig's geometry as its case and the rig's oils table (which says whether the oils
are polymer-thickened), nothing about the effects. Acceptance criteria:

* each library effect, alone at its stated strength (``TEST_STRENGTH``, listed below),
  is named, alone, with a held-out (leave-one-run-out) RMSE cut of at least 50 %, on
  seeds 0 and 1;
* two effects at once: both named, nothing else;
* clean data: no effect named on at least 19 of 20 noise seeds;
* a Newtonian fluid (silicone oil, per-row nu and density, smooth clearances, torque
  measured directly, the rig without a bearing region): no effect named.

Stated strengths (effect on the oil runs' reading, RMS): end-face discs k = 0.5 x the
Daily & Nece regime II value (4.5 W); ball churning f0 = 0.25 (4.9 W); seal tau_c =
0.025 N m (4.9 W); oil inertia I_V = 4e-7 m^5 (5.1 W); thermal lag 1 s (5.2 W); Taylor
excess k = 2 (5.6 W); Carreau shear thinning lambda = 0.3 ms, n = 0.6 (18 W, mostly
absorbed by the calibration); sensor delay 0.1 s (4.5 W).

Criteria the current loop fails are marked ``xfail(strict=True)`` with the reason: the
test stays as it is, and passes (then fails as XPASS) once the loop meets it.
"""

import tempfile
from functools import cache
from pathlib import Path

import pytest

from oilgap.model.io.case_io import case_from_dict
from oilgap.model.oils import read_oils_csv
from oilgap.optim.calibration import LoopEstimator
from oilgap.studies.rigs.outside_rig import (
    EFFECT_LAWS,
    NEWTONIAN,
    TEST_STRENGTH,
    OutsideConfig,
    effect_size_W,
    inject,
    synthesize,
    write_oils_csv,
)

CLEAN = OutsideConfig()


@cache
def loop(cfg: OutsideConfig, seed: int) -> tuple[tuple[str, ...], float]:
    """(effects the loop names, held-out RMSE cut [%]) on the rig's data of this seed."""
    with tempfile.TemporaryDirectory() as d:
        oils = read_oils_csv(write_oils_csv(cfg, Path(d) / "oils.csv"))
    case = case_from_dict(cfg.geometry.case_document())
    est = LoopEstimator(base="eq6", case=case, oils=oils).fit(synthesize(cfg, seed))
    h = est.heldout_rmse_
    return tuple(sorted(e.name for e in est.effects_)), 100.0 * (1.0 - h["after"] / h["before"])


def _xfail(reason: str):
    return pytest.mark.xfail(strict=True, reason=reason)


SINGLE_XFAIL: dict[str, str] = {}
"""Effects the current loop does not name alone with a 50 % cut, and why."""


@pytest.mark.parametrize("effect", [pytest.param(e, marks=_xfail(SINGLE_XFAIL[e]))
                                    if e in SINGLE_XFAIL else e for e in EFFECT_LAWS])
def test_each_effect_named_alone_with_half_the_heldout_error_cut(effect):
    cfg = inject(CLEAN, **{effect: TEST_STRENGTH[effect]})
    assert effect_size_W(cfg) > 4.0  # the stated strengths are well above the 1 W noise
    for seed in (0, 1):
        named, cut = loop(cfg, seed)
        assert named == (effect,), f"seed {seed}: named {named}, cut {cut:.0f} %"
        assert cut >= 50.0, f"seed {seed}: held-out cut {cut:.1f} %"


PAIRS = [
    pytest.param(("bearing_ball_churning", "sensor_delay"), id="churning+delay"),
    # neither alone gains the margin (seal 3.9 %, lag 0.0 %: the calibration absorbs part of
    # both); the forward selection's pair look-ahead names them together
    pytest.param(("seal_coulomb_friction", "thermal_lag"), id="seal+lag"),
]


@pytest.mark.parametrize("effects", PAIRS)
def test_two_effects_at_once_both_named(effects):
    cfg = inject(CLEAN, **{e: TEST_STRENGTH[e] for e in effects})
    named, cut = loop(cfg, 0)
    assert named == tuple(sorted(effects)), f"named {named}, cut {cut:.0f} %"


def test_clean_data_no_effect_in_19_of_20_seeds():
    # one noise-free simulation (cached), twenty draws of the noise
    named = [loop(CLEAN, seed)[0] for seed in range(20)]
    false = [(seed, n) for seed, n in enumerate(named) if n]
    assert len(false) <= 1, f"effects named on clean data: {false}"


def test_no_false_effect_on_a_newtonian_fluid():
    for seed in (0, 1, 2):
        named, cut = loop(NEWTONIAN, seed)
        assert named == (), f"seed {seed}: named {named} on a Newtonian fluid (cut {cut:.0f} %)"
