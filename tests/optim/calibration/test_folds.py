"""The loop's cross-validation folds: whole runs, at most 10 folds, deterministic (issue 20).

The rule (docs/loop.md, :mod:`oilgap.optim.calibration.folds`): up to ``k`` groups, one
fold per group (leave-one-run-out, the fold codes are the run codes); above, the groups
in sorted order dealt round-robin, rank ``i`` in fold ``i mod k``. The expected folds
below are written out by hand from that rule.
"""

from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from oilgap.model.errors import InputError
from oilgap.model.skin_friction import FrictionLaw
from oilgap.optim.calibration import LoopEstimator
from oilgap.optim.calibration.folds import MAX_FOLDS, cv_folds, cv_scheme, grouped_folds
from oilgap.studies.loop.report import cv_sentence, report_markdown
from oilgap.studies.rigs.synth import SynthConfig, synthesize


def _runs(sizes):
    """Group code per sample: run c repeated sizes[c] times (contiguous, like a file)."""
    return np.repeat(np.arange(len(sizes)), sizes)


def _fold_of_group(groups, folds):
    """Group -> its one fold; fails if a group is split over two folds."""
    out = {}
    for g in np.unique(groups):
        f = np.unique(folds[groups == g])
        assert len(f) == 1, f"group {g} split over folds {f}"
        out[int(g)] = int(f[0])
    return out


@pytest.mark.parametrize("n_groups", [2, 7, 10])
def test_up_to_k_groups_is_leave_one_group_out_unchanged(n_groups):
    groups = _runs([5 + g for g in range(n_groups)])
    folds = grouped_folds(groups, k=10)
    assert np.array_equal(folds, groups)  # the run codes themselves: today's folds


def test_thirteen_runs_in_ten_folds_by_hand():
    # ranks 0..12; fold = rank mod 10: runs 10, 11, 12 join runs 0, 1, 2
    groups = _runs([3] * 13)
    m = _fold_of_group(groups, grouped_folds(groups, k=10))
    assert m == {0: 0, 1: 1, 2: 2, 3: 3, 4: 4, 5: 5, 6: 6, 7: 7, 8: 8, 9: 9,
                 10: 0, 11: 1, 12: 2}


@pytest.mark.parametrize("n_groups,k", [(11, 10), (80, 10), (100, 10), (1000, 10), (25, 4)])
def test_many_groups_whole_in_exactly_k_balanced_folds(n_groups, k):
    rng = np.random.default_rng(n_groups)
    groups = _runs(rng.integers(1, 6, n_groups))
    folds = grouped_folds(groups, k=k)
    m = _fold_of_group(groups, folds)              # every run whole in one fold
    per_fold = np.bincount(list(m.values()), minlength=k)
    assert len(np.unique(folds)) == k              # bounded: k folds, not one per run
    assert per_fold.max() - per_fold.min() <= 1    # runs dealt evenly


def test_folds_depend_on_the_groups_only_not_on_sample_order_or_codes():
    groups = _runs([4, 2, 7, 1, 3, 5, 2, 6, 3, 2, 4, 1, 5, 2, 3])
    ref = _fold_of_group(groups, grouped_folds(groups))
    perm = np.random.default_rng(1).permutation(len(groups))
    shuffled = groups[perm]
    assert _fold_of_group(shuffled, grouped_folds(shuffled)) == ref
    assert np.array_equal(grouped_folds(groups), grouped_folds(groups.copy()))
    gapped = groups * 3 + 100                      # codes with gaps: ranks decide
    assert _fold_of_group(gapped, grouped_folds(gapped)) == {
        3 * g + 100: f for g, f in ref.items()}


def test_fewer_than_two_folds_refused():
    with pytest.raises(InputError, match="max_folds"):
        grouped_folds(_runs([2, 2, 2]), k=1)


def _samples(n_groups, by="run"):
    code = _runs([2] * n_groups)
    return SimpleNamespace(run_code=code, cv_group=code, cv_by=by)


def test_scheme_text_names_the_folds_and_the_groups():
    few, many = cv_scheme(_samples(8)), cv_scheme(_samples(80))
    assert few["text"] == "held-out error by leave-one-run-out over 8 oil runs"
    assert (few["scheme"], few["folds"], few["groups"]) == ("leave-one-group-out", 8, 8)
    assert many["text"] == ("held-out error by grouped 10-fold cross-validation over 80 "
                            "oil runs")
    assert (many["scheme"], many["folds"], many["groups"]) == ("grouped k-fold", 10, 80)
    assert "jackknife over the 10 folds" in many["jackknife"]
    by_oil = cv_scheme(_samples(4, by="oil"))
    assert by_oil["text"] == "held-out error by leave-one-group-out over 4 groups of oil"
    assert MAX_FOLDS == 10
    assert len(np.unique(cv_folds(_samples(80)))) == 10


def test_loop_on_sixteen_oil_runs_uses_ten_folds_and_says_so():
    cfg = SynthConfig(kind="viscous_power_W", n_samples=40, sample_interval_s=7.5)
    frames = []
    for k in range(2):  # two campaigns of the rig's 8 oil runs: 16 runs, renamed
        df = synthesize(cfg, seed=k)
        df["run"] = df["run"] + f"_r{k}"
        frames.append(df)
    est = LoopEstimator(base="eq6", effects=["seal_coulomb_friction"]).fit(
        pd.concat(frames, ignore_index=True))
    cv = est.to_dict()["cross_validation"]
    assert (cv["scheme"], cv["groups"], cv["folds"]) == ("grouped k-fold", 16, 10)
    assert len(est.search_.final.before.folds) == 10   # ten refits, not sixteen
    text = "Held-out error by grouped 10-fold cross-validation over 16 oil runs"
    assert text in cv_sentence(est)
    assert text in report_markdown(est, figures=False)
    assert "delete-a-group jackknife over the 10 folds" in report_markdown(est, figures=False)


def test_film_state_at_a_moved_lag_warm_started_equals_a_cold_solve(rig):
    # each fold and fit iteration moves the thermal lag; the film-heated state there starts
    # from the nearest lag's film rise: it must be the root a fresh model finds from scratch
    from oilgap.optim.calibration.forward import ForwardModel

    s, law = rig.samples, FrictionLaw(form="smooth", gamma=0.5)
    warm = ForwardModel(s, rig.case, rig.oils)
    for tau in (4.0, 4.3, 3.7, 5.0, 4.1, 2.5):  # more lags than the start cache holds
        got = warm.oil_state(law, {"thermal_lag": tau, "film_heating": 2.0}).temp_film_K
        cold = ForwardModel(s, rig.case, rig.oils).oil_state(
            law, {"thermal_lag": tau, "film_heating": 2.0})
        assert np.all(got > cold.temp_lagged_K)  # the film is heated above its base
        assert np.allclose(got, cold.temp_film_K, rtol=0.0, atol=1e-9)
    assert len(warm._film_start) <= 4 and len(warm._film_rise) <= 4
