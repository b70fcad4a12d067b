"""The façade's uncertainty study: ``og.uncertainty`` (``oilgap study uncertainty``) and its
view :class:`Uncertainty`.

The study (:func:`oilgap.studies.uncertainty.run`) propagates the case's uncertain inputs
(its ``[uncertainty]`` table, the documented defaults, or a calibrated ``loop.json``'s fit
with ``model=``) through the joint's loss: the loss's percentiles, a tornado and the
Sobol' indices (SALib). With ``out`` it writes its files into that folder as the command
does (checked and locked before any computation).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pandas as pd

from oilgap._checks import AX, PATH_KINDS, Arg, checked, choice
from oilgap._evaluate import as_case
from oilgap._results import new_axes, raw_field
from oilgap._results_studies import StudyView, file_names, records
from oilgap._studies import STUDY
from oilgap.model.case import DesignCase
from oilgap.model.io.defaults import defaults_lines, gamma_fields, gamma_line
from oilgap.model.io.text import layout, wrapped
from oilgap.model.uncertain.distributions import UncertaintySpec
from oilgap.studies.grid.evaluate import thermal_description
from oilgap.studies.io.result_folder import ResultFolder
from oilgap.studies.outputs import result_folder
from oilgap.studies.settings import UncertaintySettings, split_keywords
from oilgap.studies.uncertainty import study as uncertainty_study
from oilgap.studies.uncertainty.from_loop import loop_uncertainty
from oilgap.studies.uncertainty.report import (
    draw_histogram,
    draw_tornado,
    input_lines,
    inputs_table,
    sobol_lines,
    statistics_lines,
)
from oilgap.studies.uncertainty.study import mode_why


class Uncertainty(StudyView):
    """The loss under uncertain inputs (:class:`oilgap.studies.uncertainty.UncertaintyResult`).

    ``to_frame()`` is the per-input table (law, tornado, Sobol' indices); the loss's
    statistics are :attr:`statistics`, the quasi-random sample :attr:`samples`.
    """

    spec = raw_field("spec", "The uncertain inputs' joint law used (UncertaintySpec).")
    samples = raw_field("samples", "The quasi-random sample: inputs and loss_W (DataFrame).")
    statistics = raw_field("statistics", "Mean, sd, p5, p50, p95, nominal loss [W].")
    tornado = raw_field("tornado", "Per input: the loss at its p5 and p95 [W].")
    sobol = raw_field("sobol", "Per input: Sobol' S1 and ST with intervals (or None).")
    nominal_W = raw_field("nominal_W", "The loss at the case's own inputs [W].")
    thermal_mode = raw_field("thermal_mode", "The thermal mode of the study.")
    thermal_default = raw_field("thermal_default", "Whether the mode is the default.")
    elapsed_s = raw_field("elapsed_s", "Wall time of the study [s].")
    files = raw_field("files", "The files written (with ``out``).")

    def statistic(self, name: str) -> float:
        """One statistic of the loss [W]: ``"p5"``, ``"p50"``, ``"p95"``, ``"mean"``,
        ``"sd"``, ``"nominal"``."""
        return self.raw.statistic(name)

    def to_frame(self) -> pd.DataFrame:
        """Per input (largest tornado swing first): ``law``, ``value_low``/``value_high``
        (its p5 and p95 [its unit]), ``loss_low_W``/``loss_high_W``, ``swing_W`` [W]
        and ``S1``, ``ST`` with their interval bounds [-]."""
        return inputs_table(self.raw)

    def to_dict(self) -> dict:
        """Thermal mode, the inputs' laws, the nu40/nu100 bands carried to the oil's
        temperature (``viscosity_carried``, text), the loss's statistics [W], the
        per-input table, settings, the files written and the defaults (``--json``)."""
        r = self.raw
        return {"case": self.case.name, **gamma_fields(self.case),
                "thermal_mode": r.thermal_mode, "thermal_default": r.thermal_default,
                "uncertainty": r.spec.to_dict(), "viscosity_carried": list(r.carried),
                "settings": r.settings.to_dict(),
                "statistics_W": dict(zip(r.statistics["statistic"], r.statistics["loss_W"],
                                         strict=True)),
                "failed": r.failed, "inputs": records(self.to_frame()),
                "elapsed_s": r.elapsed_s, "files": file_names(r), "defaults": self.defaults}

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap study uncertainty`` prints: the percentiles first (p5, p50, p95),
        the inputs with their sources, the Sobol' and tornado table, then the thermal
        mode, gamma and the defaults (``defaults`` False leaves these out, ``-q``), the
        files written."""
        r = self.raw
        thermal = thermal_description(self.case, r.thermal_mode, r.thermal_default,
                                      mode_why(self.case, r.spec, r.thermal_mode,
                                               r.thermal_default))
        body = [*wrapped(input_lines(r.spec)), "", *sobol_lines(r), "",
                f"wall time {r.elapsed_s:.1f} s"]
        return layout(statistics_lines(r), body, [f"thermal     {thermal}",
                                                  gamma_line(self.case),
                                                  *defaults_lines(r.defaults)],
                      self.wrote(), defaults)

    @checked(ax=AX, kind=choice("histogram", "tornado", optional=False))
    def plot(self, ax: Any = None, kind: str = "histogram") -> Any:
        """The study's figure: ``kind="histogram"`` the loss's histogram [W] with its
        percentiles (``uncertainty_histogram.png``), ``"tornado"`` the loss with each
        input at its p5 and p95 (``uncertainty_tornado.png``)."""
        ax = new_axes(ax)
        (draw_tornado if kind == "tornado" else draw_histogram)(self.raw, ax)
        return ax


@checked(**STUDY, model=Arg(PATH_KINDS, "a path to a loop.json (str or pathlib.Path) or None",
                            optional=True),
         spec=Arg(("UncertaintySpec",), "an UncertaintySpec or None", optional=True))
def uncertainty(case: DesignCase | str | Path | None = None, *,
                model: str | Path | None = None, spec: UncertaintySpec | None = None,
                out: str | Path | None = None, force: bool = False,
                folder: ResultFolder | None = None, **keywords: Any) -> Uncertainty:
    """The joint's loss under uncertain inputs (``oilgap study uncertainty``;
    :func:`oilgap.studies.uncertainty.run`): percentiles, tornado, Sobol' indices.

    Parameters
    ----------
    case : DesignCase, path or None
        The joint (None: the seed joint); its ``[uncertainty]`` table, else the defaults
        (ISO 3448's +-10 % on nu40, nu100 +-5 %, gamma 0.566 +- 0.041 from the seed fit).
    model : path, optional
        A calibrated ``loop.json``: its fitted gamma, friction scale and film strength
        with their intervals and correlation replace the case's laws
        (:func:`oilgap.studies.uncertainty.from_loop.loop_uncertainty`).
    spec : UncertaintySpec, optional
        The inputs' joint law given whole (instead of the case's or ``model``'s).
    out : path, optional
        Folder for the CSVs, figures and ``summary.md``.
    force : bool
        Replace earlier outputs in ``out``.
    folder : ResultFolder, optional
        A result folder the caller already opened.
    **keywords
        The fields of :class:`~oilgap.studies.settings.UncertaintySettings` (``samples``:
        Sobol' points of the percentiles, a power of 2, default 8192; ``sobol_samples``:
        Saltelli base points, default 2048; ``seed``; ``thermal``; ``confidence``;
        ``sobol``: False skips the indices), or ``settings=``, the record whole.

    Returns
    -------
    Uncertainty
    """
    base = as_case(case)
    settings, _ = split_keywords(keywords, UncertaintySettings, run_options=False)
    if spec is not None and model is not None:
        raise TypeError("give spec or model, not both")
    if model is not None:
        spec = loop_uncertainty(model, base)
    with result_folder("study uncertainty", out, force, folder=folder) as f:
        if f is not None:
            f.note(**gamma_fields(base))
            f.begin()
        r = uncertainty_study.run(out, base, settings, spec)
        if f is not None:
            f.note(thermal_mode=r.thermal_mode, thermal_mode_default=bool(r.thermal_default))
    return Uncertainty(r, base, None if out is None else Path(out))


__all__ = ["Uncertainty", "uncertainty"]
