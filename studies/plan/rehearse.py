"""Rehearse a plan: simulate its runs, run the loop, compare the intervals with the plan's.

Each seed draws new noise on the planned runs (:func:`~.candidates.plan_data`); the loop
(:class:`~oilgap.optim.calibration.LoopEstimator`) fits them and reports its jackknife
interval of each base parameter. One delete-a-group jackknife over 8 runs scatters by
about +-30 % around its expectation (its variance has g - 1 degrees of freedom), so the
comparison is made on the root mean square of the widths over the seeds.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from oilgap.optim.calibration import LoopEstimator

from .candidates import plan_data
from .study import PlanEvaluation, PlanResult


def rehearse(res: PlanResult, seeds=(0, 1, 2), inject: dict | None = None,
             **loop_options) -> pd.DataFrame:
    """The loop's interval widths on simulated runs of the plan and the naive plan.

    Parameters
    ----------
    res : PlanResult
        A plan (:func:`~.study.make_plan`).
    seeds : sequence of int
        Noise seeds.
    inject : dict, optional
        Effects injected in the simulated runs (name -> strength or None).
    **loop_options
        Passed to :class:`LoopEstimator` (``effects=`` the library effects searched).

    Returns
    -------
    DataFrame
        Per plan and parameter: the predicted interval and width (the loop's expected
        jackknife interval, its lower end carried through the Couette floor's kink where
        it reaches it), the loop's estimate and interval width per seed, the widths' RMS
        and the ratio RMS / predicted.
    """
    rows = []
    for tag, ev in (("plan", res.plan), ("naive", res.naive)):
        widths = {k: [] for k in res.candidates.spec.free}
        values = {k: [] for k in widths}
        for seed in seeds:
            df = plan_data(res.settings, ev.runs, res.settings.case, inject, seed=seed)
            est = LoopEstimator(case=res.settings.case, **loop_options).fit(df)
            for k in widths:
                ci = est.calibration_ci_.get(k)
                widths[k].append(ci[1] - ci[0] if isinstance(ci, list) else math.nan)
                values[k].append(float(est.calibration_[k]))
        rows += _rows(tag, ev, widths, values)
    return pd.DataFrame(rows)


def _rows(tag: str, ev: PlanEvaluation, widths: dict, values: dict) -> list[dict]:
    out = []
    for k, w in widths.items():
        lo, hi = ev.interval[k]
        pred = hi - lo
        rms = float(np.sqrt(np.nanmean(np.square(w))))
        out.append({"plan": tag, "parameter": k, "predicted_lo": lo, "predicted_hi": hi,
                    "predicted_width": pred, "loop_values": values[k],
                    "loop_widths": [float(x) for x in w], "loop_rms_width": rms,
                    "ratio": rms / pred if pred > 0 else math.nan})
    return out
