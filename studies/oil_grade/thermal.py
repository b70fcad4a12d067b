"""The oil grade with and without viscous heating: does the recommendation change, and why.

The oil-grade study (:mod:`oilgap.studies.oil_grade.study`) under the thermal mode ``bulk``,
``film`` or ``full`` runs the isothermal study over the same temperatures as well; this
module sets the two answers side by side, grade by grade, and says in words what moved:

* ``film``: the bulk oil is at the given temperature, so the limits are the
  isothermal ones; only the losses change (the film's own shear heating lowers them,
  and more for thicker grades, whose Nahme number ``Na = b mu U^2 / k`` is larger).
  The recommendation can change only through the mission-energy order.
* ``bulk``/``full``: every grade runs above the sea by ``R (P + Q)``. A thicker grade
  loses more, runs hotter, and its operating viscosity falls (the lubrication check uses
  it); a cold start is the oil at the sea temperature before it warms, unchanged.
  So a thin grade that passed the lubrication limit at the sea temperature can fail
  it at its operating temperature, and the energy order can change.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

from oilgap.model.thermal_modes import ThermalMode, uses_balance

if TYPE_CHECKING:  # pragma: no cover - typing only
    from oilgap.model.case import DesignCase
    from oilgap.studies.oil_grade.study import OilGradeEnvelope

_PER_GRADE = {  # comparison column -> (table column, from the isothermal table?)
    "verdict_isothermal": ("verdict", True), "verdict": ("verdict", False),
    "feasible_isothermal": ("feasible", True), "feasible": ("feasible", False),
    "nu_min_isothermal_cSt": ("nu_min_envelope_cSt", True),
    "nu_min_cSt": ("nu_min_envelope_cSt", False), "nu_min_at_C": ("nu_min_at_C", False),
    "oil_temp_op_max_C": ("oil_temp_op_max_C", False),
    "rated_oil_temp_op_C": ("rated_oil_temp_op_C", False),
    "rated_power_isothermal_W": ("rated_power_W", True), "rated_power_W": ("rated_power_W", False),
    "mission_energy_isothermal_Wh": ("mission_energy_Wh", True),
    "mission_energy_Wh": ("mission_energy_Wh", False),
}


def per_grade(table: pd.DataFrame, t_iso: pd.DataFrame) -> pd.DataFrame:
    """Both answers grade by grade: verdicts, lowest (operating) viscosity, operating
    temperatures, rated power and mission energy, and the energy change [%]."""
    a, b = t_iso.set_index("oil"), table.set_index("oil")
    out = pd.DataFrame({"oil": list(table["oil"])})
    for col, (src, iso) in _PER_GRADE.items():
        out[col] = (a if iso else b).loc[out["oil"], src].to_numpy()
    out["mission_energy_change_pct"] = 100.0 * (out["mission_energy_Wh"]
                                                / out["mission_energy_isothermal_Wh"] - 1.0)
    return out


def _physics(per: pd.DataFrame, mode: str, base: DesignCase, settings: OilGradeEnvelope,
             shown_grades: tuple = ()) -> str:
    """What the mode does to every grade, with the rated point's numbers (the operating
    temperature of ``shown_grades``, the case's oil and the thickest grade)."""
    if mode == ThermalMode.FILM:
        return ("Under film the bulk oil is at the given temperature, so both limits are "
                "the isothermal ones; only the losses change: the film's shear heating "
                "lowers them, more for thicker grades (Na = b mu U^2/k grows with mu).")
    th = base.thermal
    names = [g for g in (*shown_grades, base.oil.name, per["oil"].iloc[-1])
             if g is not None and g in set(per["oil"])]
    shown = per.set_index("oil").loc[list(dict.fromkeys(names))]
    temps = ", ".join(f"{g} {r.rated_oil_temp_op_C:.1f} degC" for g, r in shown.iterrows())
    return (f"Under {mode} every grade runs above the sea by R (P + Q) (R "
            f"{th.resistance_K_W:g} K/W, Q {th.other_heat_W:g} W): at the rated point "
            f"({settings.rated_depth_m:g} m, sea {settings.rated_temp_C:g} degC) {temps}. "
            "A thicker grade loses more and runs hotter, so its operating viscosity falls; the "
            "lubrication check uses the operating viscosity, the cold-start check the oil at the "
            "sea temperature before it warms (unchanged).")


def _row(per: pd.DataFrame, oil: str) -> pd.Series:
    return per.set_index("oil").loc[oil]


def _unchanged(per: pd.DataFrame, rec: str | None, mode: str, settings: OilGradeEnvelope) -> str:
    """Why the recommendation stays."""
    if rec is None:
        return f"No grade passes both limits, isothermal or under {mode}."
    r = _row(per, rec)
    tol = settings.iso_tolerance
    return (f"The recommendation does not change: {rec} still passes both limits (lowest "
            f"viscosity {r['nu_min_cSt']:.1f} cSt at {r['nu_min_at_C']:.1f} degC against "
            f"{r['nu_min_isothermal_cSt']:.1f} cSt isothermal; {(1 - tol) * r['nu_min_cSt']:.1f}"
            f" cSt at the -{100 * tol:g} % tolerance against the {settings.nu_min_cSt:g} "
            f"cSt limit) and still has the lowest mission energy of the passing grades "
            f"({r['mission_energy_Wh']:.0f} Wh against {r['mission_energy_isothermal_Wh']:.0f}"
            f" Wh isothermal, {r['mission_energy_change_pct']:+.0f} %).")


def _changed(per: pd.DataFrame, table: pd.DataFrame, rec: str | None, rec_iso: str | None,
             mode: str) -> str:
    """Why the recommendation moves from ``rec_iso`` to ``rec``."""
    reasons = table.set_index("oil")["reason"]
    nxt = (f" {rec} is now the passing grade with the lowest mission energy "
           f"({_row(per, rec)['mission_energy_Wh']:.0f} Wh)." if rec is not None
           else " No other grade passes both limits.")
    if rec_iso is None:
        return f"No grade passes isothermally; under {mode} {rec} does.{nxt}"
    r = _row(per, rec_iso)
    if not r["feasible"]:
        return (f"The recommendation changes: {rec_iso}, the isothermal choice, fails under "
                f"{mode}: {reasons[rec_iso]}.{nxt}")
    n = _row(per, rec)
    return (f"The recommendation changes: {rec_iso} still passes, but {rec} now has the lower "
            f"mission energy ({n['mission_energy_Wh']:.0f} Wh against {r['mission_energy_Wh']:.0f}"
            f" Wh): heating lowers {rec}'s by {-n['mission_energy_change_pct']:.0f} % and "
            f"{rec_iso}'s by {-r['mission_energy_change_pct']:.0f} %.")


def _verdict_changes(per: pd.DataFrame) -> str:
    moved = per[per["verdict"] != per["verdict_isothermal"]]
    if not len(moved):
        return "No grade's verdict changes."
    return "Verdicts that change: " + "; ".join(
        f"{r.oil} {r.verdict_isothermal} -> {r.verdict}" for r in moved.itertuples()) + "."


def compare_recommendations(table: pd.DataFrame, t_iso: pd.DataFrame,
                            recommended: tuple[str | None, str | None],
                            runner_up: tuple[str | None, str | None], mode: str,
                            base: DesignCase, settings: OilGradeEnvelope) -> dict:
    """The recommendation under ``mode`` beside the isothermal one, and why.

    ``recommended`` and ``runner_up`` are (under ``mode``, isothermal) pairs of grade names.

    Returns
    -------
    dict
        ``thermal_mode``, ``recommended``, ``runner_up``, ``recommended_isothermal``,
        ``runner_up_isothermal``, ``changed`` (bool), ``why`` (sentences with the
        numbers), ``grades`` (:func:`per_grade`, a DataFrame) and under ``bulk``/``full``
        the heat path (``sea_temp_range_C``, ``resistance_K_per_W``, ``other_heat_W``,
        ``heat_capacity_J_per_K``, the case's ``sea_temp_C``).
    """
    (rec, rec_iso), (runner_up, runner_up_iso) = recommended, runner_up
    per = per_grade(table, t_iso)
    changed = rec != rec_iso
    why = " ".join([_physics(per, mode, base, settings, (rec_iso, rec)),
                    _changed(per, table, rec, rec_iso, mode) if changed
                    else _unchanged(per, rec, mode, settings),
                    _verdict_changes(per)])
    out = {"thermal_mode": mode, "recommended": rec, "runner_up": runner_up,
           "recommended_isothermal": rec_iso, "runner_up_isothermal": runner_up_iso,
           "changed": changed, "why": why, "grades": per}
    if uses_balance(mode):
        th = base.thermal
        out.update(sea_temp_C=th.sea_temp_C, sea_temp_range_C=list(settings.temp_range_C),
                   resistance_K_per_W=th.resistance_K_W, other_heat_W=th.other_heat_W,
                   heat_capacity_J_per_K=th.heat_capacity_J_K)
    return out


__all__ = ["compare_recommendations", "per_grade"]
