"""The studies' results as façade views: :class:`Pareto`, :class:`OilGrade`,
:class:`Smoothing` (``og.pareto``, ``og.oil_grade``, ``og.smoothing``; the sweep's view is
in :mod:`oilgap._results_sweep`).

``summary()`` is the text ``oilgap study ...`` prints (the command prints it and nothing
else; with the ``wrote`` lines when the study wrote its files), ``to_json()`` what
``--json`` prints. ``plot()`` draws the study's own figure (the one written into ``out``)
on the caller's axes: one drawing function per figure, used by both.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from oilgap._checks import checked, choice
from oilgap._results import ResultView, new_axes, raw_field
from oilgap.model.case import DesignCase
from oilgap.model.groove_band import GrooveBand, groove_band
from oilgap.model.io.case_io import seed_case
from oilgap.model.io.defaults import defaults_block, defaults_lines, gamma_fields, gamma_line
from oilgap.model.io.text import layout, wrap, wrapped
from oilgap.model.thermal_modes import DEFAULT_MODE_WHY, uses_balance
from oilgap.studies.grid.evaluate import band_text, thermal_description
from oilgap.studies.oil_grade.report import draw_heatmap, draw_vs_grade, result_json
from oilgap.studies.pareto import draw_gap_front, draw_inertia_front, marked_cases
from oilgap.studies.smoothing.case import NO_TABLE4, draw_case, saving_lines
from oilgap.studies.smoothing.evidence import evidence_dict, evidence_lines
from oilgap.studies.smoothing.laminar import LaminarShare, laminar_share
from oilgap.studies.smoothing.report import draw_loss_vs_T, thermal_line


def records(df: pd.DataFrame | None) -> list[dict] | None:
    """A frame's rows as dicts (None for no frame)."""
    return None if df is None else df.to_dict(orient="records")


def file_names(raw: Any) -> list[str]:
    """The files a study wrote, as strings."""
    return [str(f) for f in getattr(raw, "files", ())]


def wrote_lines(out: str | Path | None, files: Any) -> list[str]:
    """``wrote OUT/:`` and one indented line per file (nothing when no file was
    written)."""
    files = list(files)
    if out is None or not files:
        return []
    return [f"wrote {out}/:", *(f"  {f}" for f in files)]


class StudyView(ResultView):
    """A study's view: the result, its case, the folder it wrote into (``out``).

    Parameters
    ----------
    raw : object
        The study's result (its ``defaults`` and ``files``).
    case : DesignCase
    out : path, optional
        The folder given to the study (named in the summary's ``wrote`` line).
    """

    def __init__(self, raw: Any, case: DesignCase, out: str | Path | None = None):
        self.raw = raw
        self.case = case
        self.out = out

    @property
    def defaults(self) -> list[dict]:
        """What the tool filled in for this study (the case's and the study's own)."""
        return defaults_block(getattr(self.raw, "defaults", ()))

    def wrote(self) -> list[str]:
        """The summary's ``wrote`` lines."""
        return wrote_lines(self.out, self.raw.files)


class Pareto(StudyView):
    """The gap-loss and loss-inertia fronts (:class:`oilgap.studies.pareto.ParetoResult`)."""

    gap_front = raw_field("gap_front", "The gap front: delta against mean loss (DataFrame).")
    inertia_front = raw_field("inertia_front", "The inertia front (DataFrame).")
    seeds = raw_field("seeds", "The front's seed designs.")
    reference_point = raw_field("reference_point", "The hypervolume's reference point.")
    hypervolume = raw_field("hypervolume", "Hypervolume of the gap front [mm W].")
    sweep_time_s = raw_field("sweep_time_s", "Wall time of the sweep [s].")
    files = raw_field("files", "The files written (with ``out``).")
    is_seed = raw_field("is_seed", "Whether the case is the seed joint.")
    case_name = raw_field("case_name", "The case's name.")
    thermal_mode = raw_field("thermal_mode", "The thermal mode the fronts were computed under.")
    thermal_default = raw_field("thermal_default", "Whether the mode is the default.")

    def to_frame(self) -> pd.DataFrame:
        """Both fronts, one row per point, ``front`` = ``"gap"`` or ``"inertia"``
        (``delta_mm``, ``mean_power_W``, ``inertia_ratio``...)."""
        return pd.concat([self.raw.gap_front.assign(front="gap"),
                          self.raw.inertia_front.assign(front="inertia")], ignore_index=True)

    def to_dict(self) -> dict:
        """Hypervolume [mm W], its reference point, both fronts, the marked designs, the
        files written and the defaults (``oilgap study pareto --json``)."""
        r = self.raw
        return {"case": self.case.name, **gamma_fields(self.case),
                "thermal_mode": r.thermal_mode, "thermal_default": r.thermal_default,
                "points": len(r.gap_front), "hypervolume_mm_W": r.hypervolume,
                "reference_point": {"delta_mm": r.reference_point[0],
                                    "mean_power_W": r.reference_point[1]},
                "sweep_time_s": r.sweep_time_s, "designs": records(r.seeds),
                "gap_front": records(r.gap_front), "inertia_front": records(r.inertia_front),
                "files": file_names(r), "defaults": self.defaults,
                "groove_bands": {label: None if g is None else g.to_dict()
                                 for label, g in self.groove_bands()}}

    def groove_bands(self) -> list[tuple[str, GrooveBand | None]]:
        """The marked designs' groove bands (label, band; None where region 1 is not
        laminar or smooth; :func:`~oilgap.model.groove_band.groove_band`).

        Returns
        -------
        list of tuple
            (design label, GrooveBand or None), losses [W].
        """
        if not hasattr(self, "_grooves"):
            self._grooves = [(label, groove_band(c, self.raw.thermal_mode))
                             for label, c in marked_cases(self.case)]
        return self._grooves

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap study pareto`` prints: the fronts first, the designs, then the
        thermal mode, gamma and the defaults (``defaults`` False leaves these out,
        ``-q``), the files written."""
        r = self.raw
        g, i = r.gap_front, r.inertia_front
        gok, iok = g[g["status"] == "ok"], i[i["status"] == "ok"]
        thermal = thermal_description(self.case, r.thermal_mode, r.thermal_default)
        answer = [f"gap front: {len(gok)}/{len(g)} points, delta {gok['delta_mm'].min():.3f}.."
                  f"{gok['delta_mm'].max():.3f} mm, loss {gok['mean_power_W'].max():.2f}.."
                  f"{gok['mean_power_W'].min():.2f} W; sweep {r.sweep_time_s:.2f} s "
                  f"(median solve {1e3 * gok['solve_time_s'].median():.1f} ms)",
                  f"  hypervolume {r.hypervolume:.4f} mm W, reference point "
                  f"(delta {r.reference_point[0]:g} mm, P {r.reference_point[1]:.3f} W)",
                  f"inertia front: {len(iok)}/{len(i)} points, inertia "
                  f"{iok['inertia_ratio'].min():.3f}..{iok['inertia_ratio'].max():.3f} x the "
                  f"case's rotor, loss {iok['mean_power_W'].max():.2f}.."
                  f"{iok['mean_power_W'].min():.2f} W"]
        width = max(22, *(len(d) for d in r.seeds["design"]))
        lines = [f"  {s['design']:<{width}} delta {s['delta_mm']:.3f} mm  T {s['T']:.2f}  "
                 f"P {s['mean_power_W']:.2f} W  inertia {s['inertia_ratio']:.3f} x"
                 for _, s in r.seeds.iterrows()]
        lines += wrapped(f"  film band of {s['design']} (exact C_m "
                         f"{s['mean_power_exact_W']:.4g} W): {band_text(s)}"
                         for _, s in r.seeds.iterrows())
        lines += wrapped(f"  groove band of {label}: {band.line()}"
                         for label, band in self.groove_bands() if band is not None)
        bad = pd.concat([g[g["status"] != "ok"], i[i["status"] != "ok"]])
        if len(bad):
            lines += wrap(f"{len(bad)} points failed (rows kept with their error); first: "
                          f"{bad['error'].iloc[0]}")
        return layout(answer, lines, [f"thermal     {thermal}", gamma_line(self.case),
                                      *defaults_lines(r.defaults)],
                      self.wrote(), defaults)

    @checked(front=choice("gap", "inertia", optional=False))
    def plot(self, ax: Any = None, front: str = "gap") -> Any:
        """The study's figure of one front (``pareto_gap.png`` for ``front="gap"``:
        loss [W] against delta [mm]; ``pareto_inertia.png`` for ``"inertia"``: loss
        against rotor inertia [kg m^2]), the case's designs marked."""
        ax = new_axes(ax)
        (draw_gap_front if front == "gap" else draw_inertia_front)(self.raw, ax)
        return ax


class OilGrade(StudyView):
    """The grade table and recommendation (:class:`oilgap.studies.oil_grade.OilGradeResult`)."""

    table = raw_field("table", "One row per grade: limits, mission energy, rank, verdict.")
    envelope = raw_field("envelope", "The grid over depth x temperature for every grade.")
    rated = raw_field("rated", "Loss against grade at the rated depth.")
    runner_up = raw_field("runner_up", "The second grade (None if no grade passes).")
    mission = raw_field("mission", "The mission profile used.")
    mission_source = raw_field("mission_source", "Where the mission came from.")
    settings = raw_field("settings", "The limits, ranges and thermal mode used.")
    files = raw_field("files", "The files written (with ``out``).")
    thermal_mode = raw_field("thermal_mode", "The thermal mode of the study.")
    isothermal_table = raw_field("isothermal_table", "The table without heating (or None).")
    recommended_isothermal = raw_field("recommended_isothermal",
                                       "The recommendation without heating (or None).")
    runner_up_isothermal = raw_field("runner_up_isothermal",
                                     "The runner-up without heating (or None).")
    comparison = raw_field("comparison", "With heating against without (or None).")
    is_seed = raw_field("is_seed", "Whether the case is the seed joint.")
    film_band = raw_field("film_band", "The rated point's film band.")

    @property
    def recommended(self) -> str | None:
        """The recommended grade (None if no grade passes both limits)."""
        return self.raw.recommended

    def to_frame(self) -> pd.DataFrame:
        """One row per grade: limits over the envelope [cSt], mission power [W] and energy
        [Wh], rank and verdict."""
        return self.raw.table.copy()

    def to_dict(self) -> dict:
        """The study's ``oil_grade.json`` document (thermal mode, recommendation, grades,
        mission, defaults) with gamma and the files written (``--json``)."""
        g = self.groove_band()
        return {**result_json(self.raw, self.case), **gamma_fields(self.case),
                "groove_band": None if g is None else g.to_dict(),
                "files": file_names(self.raw)}

    def groove_band(self) -> GrooveBand | None:
        """The rated point's groove band where region 1 is laminar (None elsewhere;
        :func:`~oilgap.model.groove_band.groove_band`)."""
        if not hasattr(self, "_groove"):
            self._groove = groove_band(self.case, self.raw.thermal_mode)
        return self._groove

    def _table(self) -> list[str]:
        r = self.raw
        full = uses_balance(r.thermal_mode)
        lines = [f"{'oil':<8}{'nu min':>9}" + (f"{'T oil max':>10}" if full else "")
                 + f"{'nu max':>10}{'mission W':>11}{'energy Wh':>11}  verdict"]
        for _, row in r.table.iterrows():
            lines.append(f"{row['oil']:<8}{row['nu_min_envelope_cSt']:>9.1f}"
                         + (f"{row['oil_temp_op_max_C']:>10.1f}" if full else "")
                         + f"{row['nu_max_envelope_cSt']:>10.0f}"
                         f"{row['mission_mean_power_W']:>11.2f}"
                         f"{row['mission_energy_Wh']:>11.1f}  {row['verdict']}: {row['reason']}")
        return lines

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap study oil-grade`` prints: the recommendation first, the grade
        table, the mission, then the thermal mode, gamma, the defaults and the envelope
        (``defaults`` False leaves these out, ``-q``), the files written."""
        r, s = self.raw, self.raw.settings
        axis = "sea" if uses_balance(r.thermal_mode) else "oil"
        thermal = thermal_description(self.case, r.thermal_mode, s.thermal_default)
        answer = [f"recommended: {r.recommended}   runner-up: {r.runner_up or 'none'}"
                  if r.recommended is not None else
                  "recommended: none (no grade passes both limits; see the verdicts)"]
        if r.film_band is not None:
            answer.append(f"rated point {self.case.oil.name}: {r.film_band.mean_power_W:.4g} W; "
                          f"film band: {r.film_band.line()}")
        if self.groove_band() is not None:
            answer.append(f"groove band at the rated point: {self.groove_band().line()}")
        lines = self._table()
        lines += ["", *wrap(f"mission: {r.mission_source}; " + ", ".join(
            f"{m.depth_m:g} m/{'sea ' if axis == 'sea' else ''}{m.oil_temp_C:g} degC/"
            f"{m.fraction:g}" for m in r.mission))]
        if r.comparison is not None:
            c = r.comparison
            lines += ["", *wrapped([
                f"isothermal recommendation: {c['recommended_isothermal'] or 'none'}; "
                f"under {r.thermal_mode}: {c['recommended'] or 'none'} "
                f"({'changed' if c['changed'] else 'unchanged'})", f"why: {c['why']}"])]
        head = [f"thermal     {thermal}", gamma_line(self.case), *defaults_lines(r.defaults),
                f"envelope    {s.depth_range_m[0]:g}-{s.depth_range_m[1]:g} m x {axis} "
                f"{s.temp_range_C[0]:g}-{s.temp_range_C[1]:g} degC"]
        return layout(answer, lines, head, self.wrote(), defaults)

    @checked(kind=choice("grade", "envelope", optional=False))
    def plot(self, ax: Any = None, kind: str = "grade") -> Any:
        """The study's figure: ``kind="grade"`` the loss [W] against grade at the rated
        depth (``oil_grade_loss_vs_grade.png``), ``"envelope"`` the chosen grade's loss
        over the envelope (``oil_grade_heatmap.png``)."""
        ax = new_axes(ax)
        (draw_heatmap if kind == "envelope" else draw_vs_grade)(self.raw, self.case, ax)
        return ax


class Smoothing(StudyView):
    """The smoothing study (:class:`oilgap.studies.smoothing.SmoothingResult`): on the
    seed rig the fit against Table 4 and the loss against T; on another case what
    smoothing its grooves would save.

    Parameters
    ----------
    raw : SmoothingResult
    case : DesignCase
    plateau_tol : float
        Its plateau criterion [-].
    out : path, optional
    """

    table = raw_field("table", "Table 4 with the model next to the paper (seed rig).")
    fit = raw_field("fit", "The fit used (None off the seed rig).")
    checks = raw_field("checks", "The paper's model against every fit.")
    loss_vs_T = raw_field("loss_vs_T", "Mean loss against roughness T (DataFrame).")
    plateau = raw_field("plateau", "Per curve, where the loss stops falling.")
    files = raw_field("files", "The files written (with ``out``).")
    run_temps = raw_field("run_temps", "Each fit's run temperatures and powers.")
    thermal_default = raw_field("thermal_default", "Whether the mode is the default.")
    seed_rig = raw_field("seed_rig", "Whether the case is the seed rig.")
    case_name = raw_field("case_name", "The case's name.")
    thermal_mode = raw_field("thermal_mode", "The thermal mode of the loss.")

    def __init__(self, raw: Any, case: DesignCase, plateau_tol: float,
                 out: str | Path | None = None):
        super().__init__(raw, case, out)
        self.plateau_tol = plateau_tol
        self._laminar: LaminarShare | None = None

    def laminar_share(self) -> LaminarShare:
        """How much of the modelled saving lies in laminar flow, where only the seed rig's
        T^gamma supports it (:func:`oilgap.studies.smoothing.laminar.laminar_share`)."""
        if self._laminar is None:
            self._laminar = laminar_share(self.case, self.raw.table, self.raw.loss_vs_T)
        return self._laminar

    def to_frame(self) -> pd.DataFrame:
        """Mean loss against roughness T, one row per (curve, T): ``T``,
        ``oil_temp_C``, ``depth_m``, ``mean_power_W``, ``dP_dT_W``."""
        return self.raw.loss_vs_T.copy()

    def to_dict(self) -> dict:
        """Thermal mode, the plateau (on a case: the savings [W], [%]), on the seed rig
        the fit (gamma, its standard error, method, RMS [W]), Table 4 with the model and
        the fits compared; the files written and the defaults (``--json``)."""
        r, f = self.raw, self.raw.fit
        fit = None if f is None else {
            "gamma": f.gamma, "gamma_se": f.gamma_se, "method": f.method,
            "thermal_mode": f.thermal_mode, "rms_W": f.rms_W,
            "reduction_rms_W": f.reduction_rms_W}
        return {"case": self.case.name, **gamma_fields(self.case),
                "thermal_mode": r.thermal_mode, "thermal_default": r.thermal_default,
                "seed_rig": r.seed_rig, "plateau_tol": self.plateau_tol, "fit": fit,
                "plateau": records(r.plateau), "table4": records(r.table),
                "fits_compared": records(r.checks), "files": file_names(r),
                "defaults": self.defaults, "laminar_share": self.laminar_share().to_dict(),
                **({} if r.film_evidence is None
                   else {"film_evidence": evidence_dict(r.film_evidence)})}

    @property
    def film_evidence(self) -> Any:
        """Table 4's evidence on the film strength
        (:class:`oilgap.studies.smoothing.evidence.FilmEvidence`), or None when not asked
        (``film_evidence=True``)."""
        return self.raw.film_evidence

    def _comparison(self) -> list[str]:
        """The thermal models side by side: parameters, errors of powers and reductions."""
        lines = [f"{'fit':<26}{'params':>7}{'powers RMS':>12}{'worst':>7}"
                 f"{'reductions RMS':>16}{'worst':>7}{'gamma':>8}  run temperatures"]
        for _, c in self.raw.checks.iterrows():
            gamma = "" if np.isnan(c["gamma"]) else f"{c['gamma']:.3f}"
            lines.append(f"{c['variant'][:25]:<26}{c['n_params']:>7d}{c['rms_W']:>12.2f}"
                         f"{c['max_abs_W']:>7.2f}{c['reduction_rms_W']:>16.2f}"
                         f"{c['reduction_max_abs_W']:>7.2f}{gamma:>8}  {c['temperatures']}")
        return lines

    def _seed_text(self, defaults: bool) -> str:
        """On the seed rig: the fitted gamma and the reductions first, Table 4 with the
        model, the fits compared, the plateau, then the assumptions."""
        r, f = self.raw, self.raw.fit
        t = r.table[r.table["group"] > 0]
        d = t["model_minus_measured_change_W"].abs()
        answer = [f"fitted gamma = {f.gamma:.3f} +- {f.gamma_se:.3f}"
                  + ("   <- candidate calibrated default for the seed case"
                     if (f.method, f.thermal_mode, f.resistance_K_W) == ("per-oil", "none", 0.0)
                     else ""),
                  f"reductions within {d.max():.2f} W of measured (paper's model: "
                  f"{t['paper_model_minus_measured_change_W'].abs().max():.2f} W)"]
        lines = [*wrap(f"effective temperature: {f.describe()}"), "",
                 f"{'oil':<8}{'T_oil':>7}{'model T=4':>11}{'T=2':>8}{'change':>9}"
                 f"{'measured T=4':>14}{'T=2':>8}{'change':>9}{'paper model':>13}{'diff':>8}"]
        for _, row in t.iterrows():
            lines.append(
                f"{row['oil']:<8}{row['oil_temp_before_C']:>7.1f}{row['model_before_W']:>11.2f}"
                f"{row['model_after_W']:>8.2f}{row['model_change_W']:>9.2f}"
                f"{row['measured_before_W']:>14.2f}{row['measured_after_W']:>8.2f}"
                f"{row['measured_change_W']:>9.2f}{row['paper_model_change_W']:>13.2f}"
                f"{row['model_minus_measured_change_W']:>8.2f}")
        pl = r.plateau
        evidence = [] if r.film_evidence is None else ["", *wrapped(evidence_lines(
            r.film_evidence))]
        lines += ["", *self._comparison(), *evidence, "", *wrap(
            f"loss vs T: within {100 * self.plateau_tol:g} % of P(T=1) only for T <= "
            f"{pl['T_stop'].min():.2f}..{pl['T_stop'].max():.2f}; 4 -> 2 takes "
            f"{100 * pl['share_of_possible_saving_4_to_2'].mean():.0f} % of the possible "
            "saving"), *wrap(self.laminar_share().line())]
        head = [f"thermal     {thermal_line(f, r.thermal_default)}",
                f"{gamma_line(seed_case())}; this study fits its own above",
                *defaults_lines(r.defaults)]
        return layout(answer, lines, head, self.wrote(), defaults)

    def _case_text(self, defaults: bool) -> str:
        """On a case: what smoothing saves first, then the assumptions."""
        r = self.raw
        head = [f"thermal     {r.thermal_mode}" + (f" (default: {DEFAULT_MODE_WHY})"
                                                   if r.thermal_default else ""),
                gamma_line(self.case), *defaults_lines(r.defaults)]
        return layout(saving_lines(self.case, r.plateau, r.thermal_mode)
                      + wrap(self.laminar_share().line()), wrap(NO_TABLE4),
                      head, self.wrote(), defaults)

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap study smoothing`` prints: on the seed rig the fitted gamma and the
        reductions first, Table 4, the fits compared and the plateau; on a case the
        savings; then the thermal mode, gamma and the defaults (``defaults`` False
        leaves these out, ``-q``); the files written."""
        return self._seed_text(defaults) if self.raw.seed_rig else self._case_text(defaults)

    def plot(self, ax: Any = None) -> Any:
        """The study's ``smoothing_loss_vs_T.png``: mean loss [W] against roughness T
        [-] (a curve per oil on the seed rig; the case's with its own T marked)."""
        ax = new_axes(ax)
        r = self.raw
        if r.seed_rig:
            draw_loss_vs_T(r.loss_vs_T, r.plateau, r.fit, ax)
        else:
            draw_case(self.case, r.loss_vs_T, r.plateau, r.thermal_mode, ax)
        return ax


__all__ = ["OilGrade", "Pareto", "Smoothing", "StudyView", "file_names", "records",
           "wrote_lines"]
