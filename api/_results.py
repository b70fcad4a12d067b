"""The façade's result views: one object per result of ``import oilgap as og``.

Every view wraps the module-level result (``.raw``: a CaseEvaluation, DesignResult,
ParetoResult...) and gives the same methods: :meth:`ResultView.to_dict` (plain, units in
the keys), :meth:`ResultView.to_json` (:func:`oilgap.model.io.serialize.dumps`, rounded),
:meth:`ResultView.to_frame` (pandas, units in the column names),
:meth:`ResultView.plot` (matplotlib axes), :meth:`ResultView.summary` (the text the
command line prints; ``str(view)`` too), ``_repr_html_`` (a notebook's display) and
:attr:`ResultView.defaults` (what the tool filled in).

This module holds the base class and the one light view, :class:`Evaluation`: ``oilgap
evaluate`` loads neither pandas nor matplotlib (``tests/cli/test_dispatch.py``), so the
base class loads them on first use (:func:`lazy`, the one import that is not at the top of
a module here, like the command line's dispatch table). The other views are in
:mod:`oilgap._results_design` and :mod:`oilgap._results_studies`.
"""

from __future__ import annotations

import html
import importlib
from pathlib import Path
from typing import Any

from oilgap._checks import AX, FLAG, Arg, check_arg, checked
from oilgap._results_linear import linear_rows
from oilgap.model.case import DesignCase
from oilgap.model.errors import ArgumentError
from oilgap.model.evaluation import CaseEvaluation
from oilgap.model.groove_band import GrooveBand, groove_band
from oilgap.model.io.defaults import case_defaults as model_case_defaults
from oilgap.model.io.defaults import defaults_block, gamma_fields, gamma_line
from oilgap.model.io.serialize import dumps
from oilgap.model.io.text import layout, wrapped
from oilgap.model.thermal_modes import (
    DEFAULT_MODE_WHY,
    THERMAL_MODE_TEXT,
    film_counterpart,
    uses_balance,
)
from oilgap.model.units import m_to_mm
from oilgap.studies.io.files import atomic_write_text, check_out_file

# ----------------------------------------------------------------------------- helpers


def lazy(module: str) -> Any:
    """``module`` imported on first use (pandas, matplotlib.pyplot): a light view's
    ``to_frame``/``plot`` load them only when called."""
    return importlib.import_module(module)


def new_axes(ax: Any = None) -> Any:
    """``ax`` (checked: a matplotlib Axes), or the axes of a new pyplot figure (shown
    inline by Jupyter) with constrained layout, so that long tick labels and titles are
    not clipped when it is shown or saved (issue 26: ``opt.plot()``)."""
    if ax is not None:
        return check_arg("ax", ax, AX)
    _, ax = lazy("matplotlib.pyplot").subplots(layout="constrained")
    return ax


def case_defaults(case: DesignCase) -> list[dict]:
    """What the tool filled in for ``case`` (:func:`oilgap.model.io.defaults.case_defaults`:
    the reader's record, gamma, the bearing's keys, the NLP's groove bounds), each as
    ``{field, value, unit, source}``."""
    return defaults_block(model_case_defaults(case))


# ----------------------------------------------------------------------------- base


def raw_field(name: str, doc: str) -> property:
    """A read-only property of a view: the field ``name`` of its module-level result
    (``view.<name>`` is ``view.raw.<name>``), declared on the view so that IDEs, type
    checkers and ``dir`` see it."""

    def get(self: ResultView) -> Any:
        return getattr(self.raw, name)

    get.__name__ = name
    return property(get, doc=doc)


class ResultView:
    """The methods every result of the façade shares; subclasses give ``to_dict``,
    ``to_frame``, ``plot`` and ``summary``.

    Attributes
    ----------
    raw : object
        The module-level result.
    case : DesignCase or None
        The case computed (overrides applied).
    """

    raw: Any = None
    case: DesignCase | None = None
    report_command: str | None = None
    """The command whose report folder :meth:`report` writes (None: the view has none;
    a study writes its own folder with ``out=``)."""

    def to_dict(self) -> dict:
        """Plain dict, units in the key names."""
        raise NotImplementedError

    def to_frame(self) -> Any:
        """pandas DataFrame, units in the column names."""
        raise NotImplementedError

    def plot(self, ax: Any = None) -> Any:
        """Draw on ``ax`` (default: a new pyplot figure); returns the axes."""
        raise NotImplementedError

    def summary(self, defaults: bool = True) -> str:
        """The text the command line prints: the answer first (``defaults`` False: without
        the assumptions and the defaults filled in, ``-q``)."""
        raise NotImplementedError

    @property
    def defaults(self) -> list[dict]:
        """What the tool filled in: ``{field, value, unit, source}`` each."""
        return case_defaults(self.case) if self.case is not None else []

    @checked(path=Arg((str, Path), "a file path (str or pathlib.Path) or None (the text "
                      "only)", optional=True), force=FLAG)
    def to_json(self, path: str | Path | None = None, force: bool = False) -> str:
        """The JSON text of :meth:`to_dict` (floats to 6 significant digits, NaN as
        null); with ``path`` also written there atomically (an existing file only with
        ``force``)."""
        text = dumps(self.to_dict())
        if path is not None:
            out = check_out_file(path, force, field="path", option="force=True")
            atomic_write_text(out, text + "\n")
        return text

    @checked(out=Arg((str, Path), "a folder path (str or pathlib.Path)"), force=FLAG)
    def report(self, out: str | Path, force: bool = False, folder: Any = None) -> list[Path]:
        """Write a report folder (``oilgap evaluate/optimize --report DIR``): ``summary.md``
        (the answer, the text, the table, the figure, the defaults), the JSON document,
        the table as CSV, the figure as PNG, ``provenance.json`` (an optimum: also the
        optimal case TOML with every digit); atomic, an earlier report refused unless
        ``force`` (:func:`oilgap._report.write_view_report`). Returns the files written."""
        if self.report_command is None:
            raise ArgumentError("report", type(self).__name__, "a report folder of evaluate or "
                                "optimize; a study writes its folder with out=")
        return lazy("oilgap._report").write_view_report(self, self.report_command, out,
                                                        force, folder)

    def header(self) -> list[str]:
        """The summary's lines up to its first blank line."""
        lines = self.summary().split("\n")
        return lines[:lines.index("")] if "" in lines else lines

    def _repr_html_(self) -> str:
        head = html.escape("\n".join(self.header()))
        table = self.to_frame().to_html(max_rows=60, float_format=lambda x: f"{x:.6g}")
        return f"<div><pre>{head}</pre>{table}</div>"

    def __str__(self) -> str:
        return self.summary()

    def __repr__(self) -> str:
        first = self.header()[0] if self.header() else ""
        return f"<{type(self).__name__}: {first.strip()}>"


# ----------------------------------------------------------------------------- evaluate

MODE_TEXT = THERMAL_MODE_TEXT
"""What each thermal mode computes, for the header line (the model's words)."""

BEARING_MODEL_TEXT = {
    "skf": "SKF frictional-moment model (rolling, sliding, drag)",
    "palmgren": "Palmgren (load-independent M0 + load-dependent M1)",
}
"""The rolling bearing's model, for the header line."""


def _header(ev: CaseEvaluation) -> list[str]:
    """The case, thermal-mode, balance, oil and friction lines."""
    if ev.thermal_mode_default:
        mode = (f"thermal     {ev.thermal_mode} (default: {DEFAULT_MODE_WHY}; "
                f"{MODE_TEXT[ev.thermal_mode]}")
    else:
        mode = f"thermal     {ev.thermal_mode} ({MODE_TEXT[ev.thermal_mode]}"
    lines = [f"case        {ev.case_name}", mode + ")"]
    temp = f"{ev.oil_temp_C:g} degC"
    if ev.sea_temp_C is not None:
        temp = f"{ev.oil_temp_C:.2f} degC (heat balance)"
        lines.append(
            f"balance     sea {ev.sea_temp_C:g} degC, R_th = {ev.resistance_K_per_W:g} K/W, "
            f"Q = {ev.other_heat_W:g} W: oil at {ev.oil_temp_C:.2f} degC, "
            f"{ev.oil_temp_C - ev.sea_temp_C:.2f} K above the sea")
    lines += [
        f"oil         {ev.oil} at {temp}, {ev.depth_m:g} m: "
        f"nu = {ev.nu_cSt:.4g} cSt, rho = {ev.density_kg_m3:.1f} kg/m^3",
        f"friction    C_m form {ev.form}, laminar law {ev.laminar_law}; "
        f"peak speed {ev.peak_speed_rpm:g} rpm",
    ]
    lines += [f"rolling brg {b.name} ({b.kind}, d_m = {m_to_mm(b.pitch_diameter_m):g} mm): "
              f"{BEARING_MODEL_TEXT.get(b.model, b.model)}, at the bulk oil's viscosity"
              for b in ev.bearings]
    return lines


def _bearing_rows(ev: CaseEvaluation) -> list[str]:
    """The rolling bearing's own rows below the regions (none without a bearing)."""
    if not ev.bearings:
        return []
    lines = ["", f"{'rolling bearing':<16}{'model':<10}{'mean W':>9}{'torque Nm':>11}"
                 "  mean W per term"]
    for b in ev.bearings:
        terms = ", ".join(f"{k} {v:.3g}" for k, v in b.terms.items())
        lines.append(f"{b.name:<16}{b.model:<10}{b.mean_power_W:>9.3f}"
                     f"{b.torque_peak_Nm:>11.4f}  {terms}")
        lines += _bearing_band_lines(b)
    return lines


BAND_LABELS = {"skf_vm_term": "SKF V_M drag term", "skf_full": "SKF full drag",
               "skf_no_drag_plus_spheres": "SKF no drag + balls as spheres in still oil"}
"""The bearing-model band's members, for the text (Palmgren's are named by f0)."""


def _bearing_band_lines(b) -> list[str]:
    """The band of bearing models beside the chosen one (none without a band)."""
    band = b.model_band
    if band is None:
        return []
    members = ", ".join(
        f"{BAND_LABELS.get(k, k.replace('palmgren_f0_', 'Palmgren f0 '))} {v:.3g}"
        for k, v in band.members_W.items())
    parts = band.parts_W
    lines = [f"  bearing models {band.min_W:.3g}-{band.max_W:.3g} W at this oil beside the "
             f"chosen {band.chosen_W:.3g} W ({band.chosen}); "
             "see docs/bearing.md#the-bearing-model-band", f"    {members} W"]
    if "drag_vm_term" in parts:
        lines.append(f"    drag alone: SKF V_M term {parts['drag_vm_term']:.3g} W, balls as "
                     f"spheres in still oil {parts['drag_spheres_still_oil']:.3g} W; SKF "
                     f"without drag {parts['skf_no_drag']:.3g} W")
    return lines


def _bearing_notes(ev: CaseEvaluation) -> list[str]:
    """What the bearing's row is, where it lies against its model's range, and every
    default the tool filled in."""
    notes = []
    for b in ev.bearings:
        notes.append(f"rolling bearing {b.name}: its friction and drag at the bulk oil's "
                     "viscosity under every thermal mode (not a film: no film factor); "
                     "region 2 'bearing' is the oil annulus beside it, a separate term")
        notes.append(f"  at the peak speed: kappa = nu/nu_1 = {b.kappa_peak:.3g}, "
                     f"n d_m = {b.speed_factor_peak_mm_rpm:.4g} mm rpm")
        notes += [f"  {v}" for v in b.validity_notes]
        if b.default_notes:
            notes.append("  defaults the tool filled in (give the key in [bearing] to "
                         "change one):")
            notes += [f"    {v}" for v in b.default_notes]
    return notes


def _film_notes(ev: CaseEvaluation) -> list[str]:
    """What the film columns mean under the mode."""
    notes = ["at the peak speed: Na_peak raw Nahme number, Na_eff the effective "
             "(curvature-corrected, lagged) one the film modes use, Phi_st the steady "
             "heated/isothermal torque at Na_peak, Phi_app the factor applied, rise K the "
             "film's hottest point above the bulk at Na_eff"]
    if not ev.film_applied:
        notes.append(f"film_applied: false under --thermal {ev.thermal_mode}: Na and Phi_st "
                     "are diagnostics of the film heating the model leaves out, not applied "
                     "(Phi_app 1; "
                     f"--thermal {film_counterpart(ev.thermal_mode)} applies it)")
    else:
        notes.append(f"film_applied: true under --thermal {ev.thermal_mode}: Phi_app is Phi at "
                     "Na_eff, faded out above Taylor onset")
    if any(r.film_temp_rise_peak_K is None for r in ev.regions):
        notes.append("rise K '-': Taylor vortices at the peak speed (the film correction is "
                     "laminar-only and fades out there)")
    return notes


def format_evaluation(ev: CaseEvaluation, gamma: str | None = None,
                      defaults: bool = True, groove: GrooveBand | None = None,
                      transition: str = "reynolds") -> str:
    """Human-readable text of an evaluation: the total first, the table, the notes, then
    the case, thermal mode, oil and friction (``gamma``: the line naming the groove
    exponent and its source, :func:`~oilgap.model.io.defaults.gamma_line`; ``defaults``
    False leaves these last lines out, ``-q``; ``groove``: the groove band,
    :func:`~oilgap.model.groove_band.groove_band`; ``transition`` named when not the
    default)."""
    head = _header(ev)
    if transition != "reynolds":
        head = [h + f"; transition {transition} (exact Couette below Ta_c)"
                if h.startswith("friction ") else h for h in head]
    lines = [
        f"{'region':<14}{'R mm':>7}{'gap mm':>8}{'L mm':>7}{'T':>6}{'Re_peak':>10}"
        f"{'Ta_peak':>10}{'Cm_peak':>11}{'mean W':>9}{'Na_peak':>9}{'Na_eff':>8}"
        f"{'Phi_st':>8}{'Phi_app':>8}{'rise K':>8}  regimes visited",
    ]
    for r in ev.regions:
        rise = "-" if r.film_temp_rise_peak_K is None else f"{r.film_temp_rise_peak_K:.2f}"
        lines.append(
            f"{r.name:<14}{m_to_mm(r.radius_m):>7.2f}{m_to_mm(r.gap_m):>8.3f}"
            f"{m_to_mm(r.length_m):>7.2f}"
            f"{r.roughness_T:>6.2f}{r.Re_peak:>10.4g}{r.Ta_peak:>10.4g}{r.Cm_peak:>11.4g}"
            f"{r.mean_power_W:>9.3f}{r.nahme_peak:>9.3g}{r.nahme_effective_peak:>8.3g}"
            f"{r.film_factor_steady_peak:>8.3f}{r.film_factor_applied_peak:>8.3f}{rise:>8}"
            f"  {', '.join(r.regimes)}")
    lines += _bearing_rows(ev) + linear_rows(ev)
    notes = wrapped(_film_notes(ev) + _bearing_notes(ev))
    return layout(_total_lines(ev, groove), lines + [""] + notes,
                  head + ([gamma] if gamma else []), defaults=defaults)


def _total_lines(ev: CaseEvaluation, groove: GrooveBand | None = None) -> list[str]:
    """The answer: the total mean power and its shares, the film band, the groove band
    (``groove``, where region 1 is laminar), the loss without the heat balance, the torque
    at the peak and the energy per cycle."""
    parts = [(r.name, r.mean_power_W) for r in ev.regions]
    parts += [(f"rolling bearing {b.name}", b.mean_power_W) for b in ev.bearings]
    parts += [(e.name, e.mean_power_W) for e in ev.linear_elements]
    share = ", ".join(f"{n} {100 * p / ev.total_mean_power_W:.0f} %"
                      for n, p in parts) if ev.total_mean_power_W > 0 else ""
    label = ("total mean power          " if ev.bearings or ev.linear
             else "total mean viscous power  ")
    lines = [f"{label} {ev.total_mean_power_W:.3f} W   ({share})"]
    if ev.film_band is not None:
        lines.append(f"film band                  {ev.film_band.line('.4g')}")
    if groove is not None:
        lines.append(f"groove band                {groove.line('.4g')}")
    if uses_balance(ev.thermal_mode):
        iso = ev.isothermal_total_mean_power_W
        change = (f"; the heating changes the loss by "
                  f"{100 * (ev.total_mean_power_W / iso - 1):+.1f} %") if iso > 0 else ""
        lines.append(f"no heat balance            {iso:.3f} W   (--thermal none at "
                     f"[operating] oil_temp_C{change})")
    return lines + [f"viscous torque at peak     {ev.viscous_torque_peak_Nm:.4f} N m",
                    f"energy per cycle           {ev.cycle_energy_J:.1f} J"]


def evaluation_rows(ev: CaseEvaluation) -> list[dict]:
    """One row per region, then per rolling bearing: geometry [mm], flow numbers at the
    peak speed [-], mean power [W], torque at the peak [N m], the film at the peak."""
    rows = [{"region": r.name, "kind": "clearance", "radius_mm": m_to_mm(r.radius_m),
             "gap_mm": m_to_mm(r.gap_m), "length_mm": m_to_mm(r.length_m),
             "roughness_T": r.roughness_T, "Re_peak": r.Re_peak, "Ta_peak": r.Ta_peak,
             "Cm_peak": r.Cm_peak, "mean_power_W": r.mean_power_W,
             "torque_peak_Nm": r.torque_peak_Nm, "nahme_peak": r.nahme_peak,
             "nahme_effective_peak": r.nahme_effective_peak,
             "film_factor_steady_peak": r.film_factor_steady_peak,
             "film_factor_applied_peak": r.film_factor_applied_peak,
             "film_applied": r.film_applied,
             "film_temp_rise_peak_K": (float("nan") if r.film_temp_rise_peak_K is None
                                       else r.film_temp_rise_peak_K),
             "regimes": ", ".join(r.regimes)} for r in ev.regions]
    rows += [{"region": f"rolling bearing {b.name}", "kind": f"rolling bearing ({b.model})",
              "mean_power_W": b.mean_power_W, "torque_peak_Nm": b.torque_peak_Nm}
             for b in ev.bearings]
    rows += [{"region": e.name, "kind": "linear drive element", "mean_power_W": e.mean_power_W}
             for e in ev.linear_elements]
    return rows


class Evaluation(ResultView):
    """A joint evaluated region by region over its duty cycle (``og.evaluate``).

    Parameters
    ----------
    raw : CaseEvaluation
        :func:`oilgap.model.evaluation.evaluate_case`'s result.
    case : DesignCase
        The case evaluated (overrides applied).
    """

    report_command = "evaluate"

    def __init__(self, raw: CaseEvaluation, case: DesignCase):
        self.raw = raw
        self.case = case
        self._groove: tuple[GrooveBand | None] | None = None

    def groove_band(self) -> GrooveBand | None:
        """The groove band beside the loss where region 1 is laminar (None elsewhere;
        :func:`~oilgap.model.groove_band.groove_band`)."""
        if self._groove is None:
            self._groove = (groove_band(self.case, self.raw.thermal_mode, self.raw.depth_m,
                                        self.raw.total_mean_power_W),)
        return self._groove[0]

    @property
    def total_mean_power_W(self) -> float:
        """Mean power of the whole joint over the cycle [W]."""
        return self.raw.total_mean_power_W

    case_name = raw_field("case_name", "The case's name.")
    oil = raw_field("oil", "The oil's name.")
    thermal_mode = raw_field("thermal_mode", "The thermal mode evaluated under.")
    thermal_mode_default = raw_field("thermal_mode_default",
                                     "Whether the mode is the default (not given).")
    oil_temp_C = raw_field("oil_temp_C", "Oil temperature [degC] (the balance's under one).")
    sea_temp_C = raw_field("sea_temp_C", "Sea temperature [degC] (None without a balance).")
    resistance_K_per_W = raw_field("resistance_K_per_W", "Thermal resistance [K/W].")
    other_heat_W = raw_field("other_heat_W", "Heat from other sources [W].")
    depth_m = raw_field("depth_m", "Depth [m].")
    nu_cSt = raw_field("nu_cSt", "Kinematic viscosity at the operating point [cSt].")
    density_kg_m3 = raw_field("density_kg_m3", "Oil density [kg/m^3].")
    laminar_law = raw_field("laminar_law", "The laminar law of the skin friction.")
    form = raw_field("form", "The skin-friction form.")
    peak_speed_rpm = raw_field("peak_speed_rpm", "Peak speed of the duty cycle [rpm].")
    regions = raw_field("regions", "Per clearance region: its evaluation.")
    isothermal_total_mean_power_W = raw_field(
        "isothermal_total_mean_power_W", "Mean loss without heating [W].")
    viscous_torque_peak_Nm = raw_field("viscous_torque_peak_Nm",
                                       "Viscous torque at the peak speed [N m].")
    cycle_energy_J = raw_field("cycle_energy_J", "Energy lost per duty cycle [J].")
    bearings = raw_field("bearings", "Per rolling bearing: its evaluation.")
    film_applied = raw_field("film_applied", "Whether film heating was applied.")
    film_band = raw_field("film_band", "The film band beside the loss.")

    def to_dict(self) -> dict:
        """The ``oilgap evaluate --json`` document: the evaluation, gamma and its source,
        the defaults filled in, the groove band (``groove_band``, None where region 1 is not
        laminar) and ``transition`` when it is not the default ``"reynolds"``."""
        g, t = self.groove_band(), self.case.friction.transition
        return {**self.raw.to_dict(), **gamma_fields(self.case), "defaults": self.defaults,
                **({} if t == "reynolds" else {"transition": t}),  # default: as before
                "groove_band": None if g is None else g.to_dict()}

    def to_frame(self) -> Any:
        """One row per region (and rolling bearing), indexed by its name."""
        return lazy("pandas").DataFrame(evaluation_rows(self.raw)).set_index("region")

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap evaluate`` prints: the total first (``defaults`` False: without
        the case, thermal-mode, oil and gamma lines, ``-q``)."""
        return format_evaluation(self.raw, gamma_line(self.case), defaults,
                                 self.groove_band(), self.case.friction.transition)

    def plot(self, ax: Any = None) -> Any:
        """Mean power of each region (and bearing) over the cycle, a bar each [W]."""
        ax = new_axes(ax)
        rows = evaluation_rows(self.raw)
        ax.bar([r["region"] for r in rows], [r["mean_power_W"] for r in rows],
               color="tab:blue")
        ax.set_ylabel("mean power over the duty cycle [W]")
        ax.set_title(f"{self.raw.case_name}: {self.raw.total_mean_power_W:.3f} W "
                     f"(thermal {self.raw.thermal_mode})")
        ax.grid(axis="y", alpha=0.3)
        return ax


__all__ = ["Evaluation", "ResultView", "case_defaults", "evaluation_rows",
           "format_evaluation", "lazy", "new_axes"]
