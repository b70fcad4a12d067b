"""Held-out check of the calibrated model on real published measurements: the seed's Table 4.

Table 4 of the seed paper (*Modeling and Optimization of Compensating Oil Viscous
Power for a Deep-Sea Electric Manipulator*, Sec. IV.C.2) is the one set of
measured viscous power of a rotor turning in liquid that oilgap ships: four oils
(ISO VG 150, 320, 680, 1000, i.e. four decades of Reynolds number at the rig's
temperature) and two rotor builds (T = 4 grooved, T = 2 smoothed), eight mean
powers over the rig's sine cycle.

Leave-one-oil-out: for each oil, the model is calibrated on the other three oils
(gamma of Eq. 8 and the rig's steady heat balance ``T = T_base + R_th P(T)``, one
``T_base`` and one ``R_th`` for all runs: :func:`~oilgap.studies.smoothing.fit.fit_smoothing`
with ``method="shared"``) and predicts the held-out oil's two runs. The
uncalibrated model is the published law as the seed states it before its
correction: Eq. 6 with gamma = 0, the oil at its nominal 40 degC. The held-out
errors of the two are the honest measure of what calibration buys on data the
fit has not seen.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.io.case_io import seed_case

from .fit import (
    T_GROOVED,
    T_SMOOTHED,
    fit_smoothing,
    load_table4,
    rig_case,
    steady_temperatures,
)

NOMINAL_TEMP_C = 40.0
"""Temperature at which the seed states its oils' viscosities (Table 2) [degC]."""


def leave_one_oil_out(base: DesignCase | None = None,
                      table4: pd.DataFrame | None = None) -> pd.DataFrame:
    """Held-out predictions of Table 4, one oil left out at a time.

    Parameters
    ----------
    base : DesignCase, optional
        The rig's joint (default: the seed joint).
    table4 : DataFrame, optional
        Table 4 (default: the shipped copy, :func:`load_table4`).

    Returns
    -------
    DataFrame
        One row per held-out run: ``oil``, ``roughness_T``, ``measured_W``,
        ``uncalibrated_W`` (Eq. 6, gamma = 0, 40 degC), ``calibrated_W`` (fitted
        on the other oils), ``gamma`` and ``base_temp_C``, ``resistance_K_W`` of
        that fit, ``oil_temp_C`` (the predicted steady temperature).
    """
    base = base if base is not None else seed_case()
    table4 = table4 if table4 is not None else load_table4()
    oils = table4[table4["group"] > 0]
    rows = []
    for _, held in oils.iterrows():
        fit = fit_smoothing("shared", base=base, table4=table4[table4["group"] != held["group"]])
        oil = str(held["oil"])
        measured = (float(held["measured_before_W"]), float(held["measured_after_W"]))
        cal = [rig_case(oil, T, fit.gamma, base) for T in (T_GROOVED, T_SMOOTHED)]
        temps, p_cal = steady_temperatures(cal, fit.base_temp_C["all"], fit.resistance_K_W)
        unc = [rig_case(oil, T, 0.0, base) for T in (T_GROOVED, T_SMOOTHED)]
        _, p_unc = steady_temperatures(unc, NOMINAL_TEMP_C, 0.0)
        for k, T in enumerate((T_GROOVED, T_SMOOTHED)):
            rows.append({"oil": oil, "roughness_T": T, "measured_W": measured[k],
                         "uncalibrated_W": float(p_unc[k]), "calibrated_W": float(p_cal[k]),
                         "gamma": fit.gamma, "base_temp_C": fit.base_temp_C["all"],
                         "resistance_K_per_W": fit.resistance_K_W,
                         "oil_temp_C": float(temps[k])})
    return pd.DataFrame(rows)


def heldout_errors(table: pd.DataFrame) -> dict[str, float]:
    """RMS and worst held-out error [W] of the uncalibrated and the calibrated model.

    Parameters
    ----------
    table : DataFrame
        The output of :func:`leave_one_oil_out`.

    Returns
    -------
    dict
        ``rms_uncalibrated_W``, ``rms_calibrated_W``, ``max_uncalibrated_W``,
        ``max_calibrated_W``.
    """
    out = {}
    for key in ("uncalibrated", "calibrated"):
        err = table[f"{key}_W"].to_numpy() - table["measured_W"].to_numpy()
        out[f"rms_{key}_W"] = float(np.sqrt(np.mean(err * err)))
        out[f"max_{key}_W"] = float(np.max(np.abs(err)))
    return out
