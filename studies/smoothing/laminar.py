"""How much of the smoothing study's saving lies in laminar flow.

Below the critical Taylor number creeping-flow theory allows grooves no extra loss
(Helmholtz-Korteweg, :mod:`oilgap.model.groove_band`), so a saving modelled there rests on
the seed rig's empirical T^gamma alone. Each of the study's savings (the Table 4 runs, the
rated point's 4 -> 2) is classed by region 1's Taylor number at the peak speed against
Ta_c of its gap ratio (:func:`oilgap.model.groove_band.region1_taylor`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase, OperatingPoint
from oilgap.model.groove_band import region1_taylor
from oilgap.model.oils import get_oil


@dataclass(frozen=True)
class LaminarShare:
    """The study's savings split by flow regime.

    Attributes
    ----------
    rows : pandas.DataFrame
        One row per saving: ``what``, ``oil``, ``oil_temp_C`` [degC], ``depth_m`` [m],
        ``saving_W`` [W] (positive: less loss smoothed), ``Ta_peak``,
        ``Ta_critical`` [-], ``laminar`` (bool).
    """

    rows: pd.DataFrame

    @property
    def laminar_W(self) -> float:
        """Sum of the savings in laminar flow [W]."""
        return float(self.rows.loc[self.rows["laminar"], "saving_W"].sum())

    @property
    def total_W(self) -> float:
        """Sum of all savings [W]."""
        return float(self.rows["saving_W"].sum())

    @property
    def share_pct(self) -> float:
        """The laminar part of the savings [%]."""
        return 100.0 * self.laminar_W / self.total_W if self.total_W > 0 else float("nan")

    def line(self) -> str:
        """One summary line: the share and where it comes from."""
        n = int(self.rows["laminar"].sum())
        return (f"laminar share: {self.share_pct:.0f} % of the modelled savings "
                f"({self.laminar_W:.2f} of {self.total_W:.2f} W; {n} of {len(self.rows)} "
                "points below Ta_c) lie in laminar flow, where only the seed rig's fit "
                "T^gamma supports them: creeping-flow theory allows grooves no extra loss "
                "(docs/model.md#the-groove-factor-in-creeping-flow)")

    def to_dict(self) -> dict:
        """Plain-dict form (``laminar_share`` of the study's JSON): ``share_pct`` [%],
        ``laminar_W``, ``total_W`` [W] and the rows."""
        return {"share_pct": self.share_pct, "laminar_W": self.laminar_W,
                "total_W": self.total_W, "rows": self.rows.to_dict(orient="records")}


def _at(case: DesignCase, oil: str | None, temp_C: float, depth_m: float) -> DesignCase:
    c = case if oil is None or oil == case.oil.name else replace(case, oil=get_oil(oil))
    return replace(c, operating=OperatingPoint(depth_m, temp_C))


def _row(case: DesignCase, what: str, oil: str, temp_C: float, depth_m: float,
         saving_W: float) -> dict:
    ta, ta_c = region1_taylor(_at(case, oil, temp_C, depth_m))
    return {"what": what, "oil": oil, "oil_temp_C": float(temp_C), "depth_m": float(depth_m),
            "saving_W": float(saving_W), "Ta_peak": ta, "Ta_critical": ta_c,
            "laminar": bool(ta < ta_c)}


def laminar_share(case: DesignCase, table: pd.DataFrame | None,
                  curves: pd.DataFrame) -> LaminarShare:
    """The savings of a smoothing study classed laminar or not.

    Parameters
    ----------
    case : DesignCase
        The study's base case (the seed joint on the rig, or the user's case).
    table : pandas.DataFrame or None
        The Table 4 comparison (seed rig; ``group``, ``oil``, ``oil_temp_before_C``,
        ``oil_temp_after_C``, ``model_change_W``), None on a case.
    curves : pandas.DataFrame
        The loss against T (``curve``, ``oil``, ``T``, ``oil_temp_C``, ``depth_m``,
        ``mean_power_W``).

    Returns
    -------
    LaminarShare
        The savings [W] with their Taylor numbers and regime; a Table 4 run is checked at
        the hotter of its two temperatures (the larger Ta).

    References
    ----------
    Seed paper (Table 4); Esser & Grossmann (Ta_c).
    """
    rows = []
    if table is not None:
        for _, r in table[table["group"] > 0].iterrows():
            t = float(np.nanmax([r["oil_temp_before_C"], r["oil_temp_after_C"]]))
            rows.append(_row(case, "Table 4 run", r["oil"], t, 0.0, -r["model_change_W"]))
    for name, c in curves.groupby("curve", sort=False):
        if "on the rig" in str(name) and table is not None:
            continue  # the Table 4 runs above
        p = c.set_index("T")["mean_power_W"]
        hi = 4.0 if 4.0 in p.index else float(p.index.max())
        lo = 2.0 if 2.0 in p.index and hi > 2.0 else float(p.index.min())
        first = c.iloc[0]
        rows.append(_row(case, f"{name}: T {hi:g} -> {lo:g}", first["oil"],
                         first["oil_temp_C"], first["depth_m"], p[hi] - p[lo]))
    return LaminarShare(pd.DataFrame(rows))
