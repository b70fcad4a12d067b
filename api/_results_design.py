"""The optimum of the design NLP as a façade view (``og.optimize``): :class:`Optimization`,
and the text ``oilgap optimize`` prints (:func:`format_result` for ``--thermal none``,
:func:`format_comparison` for the optimum with heating beside the one without)."""

from __future__ import annotations

from typing import Any

import pandas as pd

from oilgap._results import ResultView, case_defaults, new_axes
from oilgap.model.case import DesignCase
from oilgap.model.evaluation import oil_state
from oilgap.model.groove_band import GrooveBand, groove_band
from oilgap.model.io.defaults import gamma_fields, gamma_line
from oilgap.model.io.text import layout, wrapped
from oilgap.model.joint_loss import FilmBand
from oilgap.model.thermal_modes import DEFAULT_MODE_WHY, THERMAL_MODE_TEXT, ThermalMode
from oilgap.model.units import m2_s_to_cst
from oilgap.optim.design import DesignResult, HeatingComparison
from oilgap.optim.design.results import POINT_MEANINGS

MODE_TEXT = THERMAL_MODE_TEXT
"""What each thermal mode computes, for the header line (the model's words)."""


def _fmt(v: float) -> str:
    """A number of the tables: 5 significant digits below 1 (an inertia of 0.0012345 kg m^2
    shows its change, not 0.0012 twice; issue 26), 4 decimals to 100, 2 above."""
    a = abs(v)
    if 1e-3 <= a < 1:
        return f"{v:#.5g}"
    if v == 0 or 1 <= a < 1e5:
        return f"{v:.4f}" if a < 100 else f"{v:.2f}"
    return f"{v:.4e}"


def thermal_line(mode: str, default: bool) -> str:
    """The header line naming the thermal mode (as ``oilgap evaluate``'s)."""
    text = f"thermal     {mode} ("
    if default:
        text += f"default: {DEFAULT_MODE_WHY}; "
    text += MODE_TEXT[mode]
    if mode != ThermalMode.NONE:
        text += "; --thermal none for the seed paper's isothermal model"
    return text + ")"


def _rows(prm) -> list[tuple[str, str]]:
    """(key, meaning) of each quantity reported, the limits named where they bind."""
    bounds = {"torque_capability_Nm": f" (>= {prm.torque_min_Nm:.5g})",
              "inertia_kgm2": f" (<= {prm.inertia_max_kgm2:.5g})"}
    return [(k, m + bounds.get(k, "")) for k, m in POINT_MEANINGS.items()]


def _change(a: float, b: float) -> str:
    pct = 100 * (b - a) / a if a != 0 else None
    return "" if pct is None else ("0.0 %" if abs(pct) < 0.05 else f"{pct:+.1f} %")


def _costs(res: DesignResult) -> list[str]:
    """The active constraints with their multipliers, and the inactive ones."""
    prm = res.parameters
    lines = []
    act = [res.multipliers[n] for n in res.active_constraints]
    if not act:
        lines.append("  none (unconstrained optimum)")
    for mu in act:
        lines.append(f"  {mu.name:<25}{mu.constraint:<52}{mu.value:+.4g} {mu.unit}")
    tq = res.multipliers.get("torque_min")
    if tq is not None and tq.active:
        lines.append(f"  (1 % more required torque costs {tq.value * prm.torque_min_Nm / 100:+.4g}"
                     " W)")
    inactive = [n for n, mu in res.multipliers.items() if not mu.active]
    if inactive:
        lines.append("inactive: " + ", ".join(inactive))
    return lines


def band_lines(bands: tuple | None, grooves: tuple = ()) -> list[str]:
    """The film band of the initial and optimal designs, one line each (none without), and
    their groove bands where region 1 is laminar (:mod:`oilgap.model.groove_band`)."""
    films = [f"film band, {k} design: {b.line('.4g')}"
             for k, b in zip(("initial", "optimal"), bands or (), strict=True) if b is not None]
    return films + [f"groove band, {k} design: {g.line('.4g')}"
                    for k, g in zip(("initial", "optimal"), grooves, strict=False)
                    if g is not None]


def _answer(res: DesignResult, exact_initial: float, exact_optimal: float,
            heating: str = "") -> list[str]:
    """The optimum in two lines: its loss against the initial design's, and its
    geometry."""
    i, o = res.initial.to_dict(), res.optimal.to_dict()
    a, b = i["mean_power_W"], o["mean_power_W"]
    return [f"optimum     {b:.4f} W mean viscous power{heating} (initial {a:.4f} W, "
            f"{_change(a, b)}); {exact_optimal:.4f} W with the case's exact C_m as "
            f"oilgap evaluate (initial {exact_initial:.4f} W)",
            f"design      delta {o['delta_mm']:.4f} mm, R {o['R_mm']:.4f} mm, "
            f"L {o['L_mm']:.4f} mm, T {o['T']:.4f}; IPOPT {res.status}"]


def format_result(res: DesignResult, exact: tuple | None = None,
                  thermal: str | None = None, bands: tuple | None = None,
                  gamma: str | None = None, defaults: bool = True,
                  grooves: tuple = ()) -> str:
    """The optimum first, then the side-by-side table of the initial and optimal designs
    with the multipliers, then the case, mode, oil, gamma and solver lines (``thermal``:
    the line naming the mode; ``bands``: the designs' film bands; ``grooves``: their
    groove bands; ``defaults`` False leaves the last lines out, ``-q``)."""
    prm = res.parameters
    i, o = res.initial.to_dict(), res.optimal.to_dict()
    lines = [f"{'quantity':<24}{'initial':>13}{'optimal':>13}{'change':>11}  meaning"]
    for key, meaning in (r for r in _rows(prm) if r[0] in o):  # bearing only with one
        a, b = i[key], o[key]
        lines.append(f"{key:<24}{_fmt(a):>13}{_fmt(b):>13}{_change(a, b):>11}  {meaning}")
    if exact is not None:
        a, b = exact[0].total_mean_power_W, exact[1].total_mean_power_W
        lines.append(f"{'mean_power_exact_W':<24}{_fmt(a):>13}{_fmt(b):>13}"
                     f"{100 * (b - a) / a:>+9.1f} %  same, case's exact C_m (oilgap evaluate)")
    lines += wrapped(band_lines(bands, grooves))
    lines += ["", "active constraints and what they cost (d optimal power / d bound):"]
    head = [f"case        {res.case.name}"] + ([thermal] if thermal else []) + [
        f"oil         {prm.oil} at {prm.oil_temp_C:g} degC, {prm.depth_m:g} m: "
        f"nu = {m2_s_to_cst(prm.nu_m2_s):.4g} cSt, rho = {prm.rho_kg_m3:.1f} kg/m^3",
        *([gamma] if gamma else []),
        f"solver      IPOPT {res.status} in {res.iterations} iterations, "
        f"{res.solve_time_s * 1e3:.1f} ms" + (f" (best of {res.starts} starts)"
                                               if res.starts > 1 else "")]
    answer = _answer(res, *((exact[0].total_mean_power_W, exact[1].total_mean_power_W)
                            if exact is not None else (i["mean_power_W"], o["mean_power_W"])))
    return layout(answer, lines + wrapped(_costs(res)), head, defaults=defaults)


def _oil_lines(cmp: HeatingComparison) -> list[str]:
    """The balance and oil lines of a comparison's header."""
    h, prm = cmp.heated, cmp.heated.parameters
    case = h.case
    nu_h = m2_s_to_cst(float(oil_state(case, h.oil_temp_C, prm.depth_m)[0]))
    lines = []
    if h.thermal is not None:
        s = h.thermal
        lines.append(f"balance     sea {s.sea_temp_C:g} degC, R = {s.resistance_K_W:g} K/W, "
                     f"Q = {s.other_heat_W:g} W: oil at {h.oil_temp_C:.2f} degC at the "
                     f"optimum ({h.initial_oil_temp_C:.2f} degC at the initial design)")
        where = f"{h.oil_temp_C:.2f} degC (heat balance at the optimum)"
    else:
        where = f"{h.oil_temp_C:g} degC"
    lines.append(f"oil         {prm.oil}, {prm.depth_m:g} m: at {where} nu = {nu_h:.4g} cSt; "
                 f"without heating at {cmp.isothermal_oil_temp_C:g} degC nu = "
                 f"{m2_s_to_cst(cmp.isothermal.parameters.nu_m2_s):.4g} cSt")
    return lines


def format_comparison(cmp: HeatingComparison, exact: tuple, thermal: str,
                      bands: tuple | None = None, gamma: str | None = None,
                      defaults: bool = True, grooves: tuple = ()) -> str:
    """The optimum with heating first, then beside the one without, what changed, and the
    costs, then the case, mode, oil, gamma and solver lines (``defaults`` False leaves
    these out, ``-q``; ``grooves``: the designs' groove bands).

    ``exact``: (initial, optimal) OperatingTemperature of the heated designs with the
    case's exact C_m, and the isothermal optimum's CaseEvaluation; ``bands``: the
    heated designs' film bands."""
    h, iso = cmp.heated, cmp.isothermal
    prm = h.parameters
    i, o, n = h.initial.to_dict(), h.optimal.to_dict(), iso.optimal.to_dict()
    starts = f" (best of {h.starts} starts)" if h.starts > 1 else ""
    head = [f"case        {h.case.name}", thermal] + _oil_lines(cmp) + [
        *([gamma] if gamma else []),
        f"solver      IPOPT {h.status} in {h.iterations} iterations, "
        f"{h.solve_time_s * 1e3:.1f} ms{starts}; without heating {iso.status} in "
        f"{iso.iterations} iterations, {iso.solve_time_s * 1e3:.1f} ms"]
    lines = [
        f"{'quantity':<24}{'initial':>12}{'optimal':>12}{'change':>9}{'no heating':>12}"
        f"{'heating':>10}  meaning",
        f"{'':<24}{'(' + h.thermal_mode + ')':>12}{'(' + h.thermal_mode + ')':>12}{'':>9}"
        f"{'(none)':>12}{'vs none':>10}",
    ]
    for key, meaning in (r for r in _rows(prm) if r[0] in o):  # bearing only with one
        a, b, c = i[key], o[key], n[key]
        lines.append(f"{key:<24}{_fmt(a):>12}{_fmt(b):>12}{_change(a, b):>9}{_fmt(c):>12}"
                     f"{_change(c, b):>10}  {meaning}")
    t0, t1, tn = h.initial_oil_temp_C, h.oil_temp_C, cmp.isothermal_oil_temp_C
    lines.append(f"{'oil_temp_C':<24}{_fmt(t0):>12}{_fmt(t1):>12}{t1 - t0:>+7.2f} K"
                 f"{_fmt(tn):>12}{t1 - tn:>+8.2f} K  bulk oil temperature")
    a, b, c = exact[0].mean_power_W, exact[1].mean_power_W, exact[2].total_mean_power_W
    lines.append(f"{'mean_power_exact_W':<24}{_fmt(a):>12}{_fmt(b):>12}{_change(a, b):>9}"
                 f"{_fmt(c):>12}{_change(c, b):>10}  same, case's exact C_m (oilgap evaluate)")
    lines += wrapped(band_lines(bands, grooves))
    lines += ["", f"active constraints with heating ({h.thermal_mode}) and what they cost "
              "(d optimal power / d bound):"] + wrapped(_costs(h))
    prose = []
    act = cmp.active()
    if act["only_with_heating"] or act["only_without_heating"]:
        prose.append("heating changes the active set: "
                     f"only with heating: {', '.join(act['only_with_heating']) or '-'}; "
                     f"only without: {', '.join(act['only_without_heating']) or '-'}")
    else:
        prose.append("the same constraints are active without heating")
    if h.sea_temp_cost_W_per_K is not None:
        c = h.sea_temp_cost_W_per_K
        prose.append(f"sea temperature: dP*/dT_sea = {c:+.4g} W/K (the heat balance's "
                     f"multiplier): a sea 1 K warmer {'saves' if c < 0 else 'costs'} "
                     f"{abs(c):.4g} W at the optimum")
    if h.oil_temp_cost_W_per_K is not None:
        c = h.oil_temp_cost_W_per_K
        prose.append(f"oil temperature: dP*/dT_oil = {c:+.4g} W/K at the fixed oil "
                     "temperature (its bound's multiplier)")
    answer = _answer(h, a, b, f" with heating ({h.thermal_mode}, oil at {t1:.2f} degC)")
    answer.append(f"no heating  {n['mean_power_W']:.4f} W at the optimum without heating "
                  f"(oil at {tn:g} degC; exact C_m {exact[2].total_mean_power_W:.4f} W)")
    return layout(answer, lines + wrapped(prose), head, defaults=defaults)


DESIGN_KEYS = ("delta_mm", "R_mm", "L_mm", "T", "mean_power_W", "torque_capability_Nm",
               "inertia_ratio")
"""The quantities :meth:`Optimization.plot` compares (initial -> optimal)."""


class Optimization(ResultView):
    """The optimal region-1 geometry of a joint (``og.optimize``).

    Parameters
    ----------
    raw : DesignResult or HeatingComparison
        The isothermal optimum (``thermal`` ``none``), or the optimum with heating beside
        the one without (``film``, ``full``).
    case : DesignCase
        The case solved (overrides applied).
    exact : tuple
        The designs with the case's own (exact) C_m: (initial, optimal) CaseEvaluation
        under ``none``; (initial, optimal) OperatingTemperature and the isothermal
        optimum's CaseEvaluation under a thermal mode.
    thermal_header : str
        The header line naming the thermal mode (:func:`thermal_line`).
    limits : dict, optional
        The limits given to the solve (``torque_min_Nm`` [N m], ``inertia_max_ratio``
        [-]; None where not given).
    bands : tuple of FilmBand, optional
        The film bands of the initial and optimal designs (exact C_m;
        :func:`~oilgap.model.joint_loss.film_band`).
    """

    report_command = "optimize"

    def __init__(self, raw: DesignResult | HeatingComparison, case: DesignCase, exact: tuple,
                 thermal_header: str, limits: dict | None = None,
                 bands: tuple[FilmBand | None, ...] | None = None):
        self.bands = tuple(bands or ())
        self.raw = raw
        self.case = case
        self.exact = exact
        self.thermal_header = thermal_header
        self.limits = dict(limits or {})
        self._grooves: tuple | None = None

    def groove_bands(self) -> tuple[GrooveBand | None, ...]:
        """The groove bands of the initial and optimal designs (exact C_m; None where region
        1 is not laminar or has no grooves; :func:`~oilgap.model.groove_band.groove_band`)."""
        if self._grooves is None:
            ex = self.exact
            powers = ((ex[0].total_mean_power_W, ex[1].total_mean_power_W)
                      if not isinstance(self.raw, HeatingComparison)
                      else (ex[0].mean_power_W, ex[1].mean_power_W))
            designs = (self.result.case, self.to_case())
            self._grooves = tuple(groove_band(c, self.thermal_mode, mean_power_W=p)
                                  for c, p in zip(designs, powers, strict=True))
        return self._grooves

    @property
    def result(self) -> DesignResult:
        """The optimum (with heating under a thermal mode)."""
        return self.raw.heated if isinstance(self.raw, HeatingComparison) else self.raw

    @property
    def thermal_mode(self) -> str:
        """``"none"``, ``"bulk"``, ``"film"`` or ``"full"``."""
        return self.raw.mode if isinstance(self.raw, HeatingComparison) else "none"

    @property
    def status(self) -> str:
        """IPOPT's return status of the optimum."""
        return self.result.status

    @property
    def success(self) -> bool:
        """Whether the solve converged."""
        return self.result.success

    @property
    def iterations(self) -> int:
        """IPOPT iterations of the optimum's start."""
        return self.result.iterations

    @property
    def solve_time_s(self) -> float:
        """Solver wall time [s]."""
        return self.result.solve_time_s

    @property
    def initial(self) -> Any:
        """The case's own design (a DesignPoint)."""
        return self.result.initial

    @property
    def optimal(self) -> Any:
        """The optimal design (a DesignPoint)."""
        return self.result.optimal

    @property
    def active_constraints(self) -> Any:
        """The constraints active at the optimum."""
        return self.result.active_constraints

    @property
    def multipliers(self) -> Any:
        """What each active constraint costs (Multiplier records)."""
        return self.result.multipliers

    @property
    def starts(self) -> Any:
        """The multi-start's starts."""
        return self.result.starts

    def to_case(self, name: str | None = None) -> DesignCase:
        """The optimal design as a case (:meth:`DesignResult.to_case`)."""
        return self.result.to_case(name)

    @property
    def defaults(self) -> list[dict]:
        """The case's defaults and the limits the solve filled in (torque, inertia)."""
        prm = self.result.parameters
        out = case_defaults(self.result.case)
        if self.limits.get("torque_min_Nm") is None and self.case.bounds.torque_min_Nm is None:
            out.append({"field": "torque_min_Nm", "value": float(prm.torque_min_Nm),
                        "unit": "N m", "source": "the initial design's torque capability"})
        return out

    def to_dict(self) -> dict:
        """The ``oilgap optimize --json`` document (without its ``out``)."""
        ex = self.exact
        if isinstance(self.raw, HeatingComparison):
            d = self.raw.to_dict()
            for k, e in (("initial", ex[0]), ("optimal", ex[1])):
                d[k]["mean_power_exact_W"] = e.mean_power_W
                d[k]["oil_temp_exact_C"] = e.oil_temp_C
            d["without_heating"]["optimal"]["mean_power_exact_W"] = ex[2].total_mean_power_W
            d.update(gamma_fields(self.raw.heated.case))
        else:
            res = self.raw
            d = res.to_dict()
            d["initial"]["mean_power_exact_W"] = ex[0].total_mean_power_W
            d["optimal"]["mean_power_exact_W"] = ex[1].total_mean_power_W
            d.update(thermal_mode="none", oil_temp_C=res.parameters.oil_temp_C,
                     sea_temp_C=None, sea_temp_cost_W_per_K=None, without_heating=None,
                     **gamma_fields(res.case))
        for k, b in zip(("initial", "optimal"), self.bands, strict=False):
            d[k]["film_band"] = None if b is None else b.to_dict()
        for k, g in zip(("initial", "optimal"), self.groove_bands(), strict=True):
            d[k]["groove_band"] = None if g is None else g.to_dict()
        d["defaults"] = self.defaults
        return d

    def to_frame(self) -> pd.DataFrame:
        """One row per design (``initial``, ``optimal``; ``optimal_without_heating`` under
        a thermal mode), the quantities as columns (``delta_mm``, ``mean_power_W``...)."""
        d = self.to_dict()
        rows = {"initial": d["initial"], "optimal": d["optimal"]}
        if d.get("without_heating"):
            rows["optimal_without_heating"] = d["without_heating"]["optimal"]
        frame = pd.DataFrame.from_dict(rows, orient="index")
        frame.index.name = "design"
        return frame

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap optimize`` prints (without the ``wrote`` line of ``--out``): the
        optimum first (``defaults`` False: without the case, mode, oil, gamma and solver
        lines, ``-q``)."""
        if isinstance(self.raw, HeatingComparison):
            return format_comparison(self.raw, self.exact, self.thermal_header, self.bands,
                                     gamma_line(self.raw.heated.case), defaults,
                                     self.groove_bands())
        return format_result(self.raw, self.exact, self.thermal_header, self.bands,
                             gamma_line(self.raw.case), defaults, self.groove_bands())

    def plot(self, ax: Any = None) -> Any:
        """Change of each design quantity from the initial to the optimal design [%]."""
        ax = new_axes(ax)
        i, o = self.result.initial.to_dict(), self.result.optimal.to_dict()
        keys = [k for k in DESIGN_KEYS if i.get(k)]
        pct = [100 * (o[k] - i[k]) / i[k] for k in keys]
        ax.barh(keys, pct, color=["tab:green" if p <= 0 else "tab:red" for p in pct])
        ax.axvline(0, color="k", lw=0.8)
        ax.set_xlabel("optimal vs initial design [%]")
        ax.set_title(f"{self.case.name}\n{i['mean_power_W']:.2f} -> {o['mean_power_W']:.2f} W "
                     f"(thermal {self.thermal_mode})")  # two lines: a long name is not clipped
        ax.grid(axis="x", alpha=0.3)
        return ax


__all__ = ["Optimization", "format_comparison", "format_result", "thermal_line"]
