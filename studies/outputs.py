"""The files each folder command writes: the one list that ``--force`` / ``force=True``
removes before a new run writes (never anything else in the folder), shared by the
façade's studies (:mod:`oilgap._studies`, :mod:`oilgap._loop`)
and the command line (:mod:`oilgap.cli.outputs`)."""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import Any

from oilgap.studies.grid.store import store_files
from oilgap.studies.io.result_folder import PROVENANCE_NAME, ResultFolder

OUTPUTS: dict[str, tuple[str, ...]] = {
    "loop": ("loop.json", "report.md", "measured_vs_model.png", "residual_vs_speed.png",
             "residual_vs_time.png", "measured_vs_model_*.png", PROVENANCE_NAME),
    "study sweep": ("summary.md", "sweep.png", *store_files(), PROVENANCE_NAME),
    "study smoothing": ("smoothing_table4.csv", "smoothing_fits.csv",
                        "smoothing_loss_vs_T.csv", "smoothing_plateau.csv",
                        "smoothing_run_temps.csv", "smoothing_table4.png",
                        "smoothing_loss_vs_T.png", "summary.md", *store_files("grid/"),
                        PROVENANCE_NAME),
    "study pareto": ("pareto_gap.csv", "pareto_inertia.csv", "pareto_seeds.csv",
                     "pareto_design.csv",
                     "pareto_gap.png", "pareto_inertia.png", "summary.md",
                     "lead_front.csv", "lead_front.png",  # a linear actuator's front
                     *store_files("grid_gap/"), *store_files("grid_inertia/"), PROVENANCE_NAME),
    "study oil-grade": ("oil_grade_table.csv", "oil_grade_envelope.csv",
                        "oil_grade_rated.csv", "oil_grade_isothermal_table.csv",
                        "oil_grade_thermal_comparison.csv", "oil_grade.json",
                        "oil_grade_heatmap.png", "oil_grade_loss_vs_grade.png",
                        "oil_grade_thermal.png", "summary.md", *store_files("grid/"),
                        *store_files("grid_isothermal/"), PROVENANCE_NAME),
    "plan": ("plan.csv", "naive.csv", "parameters.csv", "effects.csv", "plan.json",
             "plan_runs.png", "summary.md", PROVENANCE_NAME),
    "study uncertainty": ("uncertainty_samples.csv", "uncertainty_statistics.csv",
                          "uncertainty_inputs.csv", "uncertainty_histogram.png",
                          "uncertainty_tornado.png", "summary.md", PROVENANCE_NAME),
}
"""The files each folder command writes (names or glob patterns relative to ``--out``);
each writes :data:`~oilgap.studies.io.provenance.PROVENANCE_NAME` (version, date, command,
inputs with their SHA-256) when it starts writing."""

REPORT_FILES: dict[str, dict[str, str]] = {
    "evaluate": {"summary": "summary.md", "json": "evaluate.json",
                 "table": "evaluate_regions.csv", "figure": "evaluate_power.png"},
    "optimize": {"summary": "summary.md", "json": "optimize.json",
                 "table": "optimize_designs.csv", "figure": "optimize_change.png",
                 "case": "optimum.toml"},
}
"""The report folder of ``evaluate --report`` and ``optimize --report`` (role -> file)."""
OUTPUTS.update({k: (*v.values(), PROVENANCE_NAME) for k, v in REPORT_FILES.items()})


def result_folder(command: str, out: str | Path | None, force: bool = False,
                  resume: bool = False, folder: ResultFolder | None = None) -> Any:
    """The context of a façade study or loop report writing into ``out``.

    Parameters
    ----------
    command : str
        The command whose outputs :data:`OUTPUTS` lists (``"loop"``, ``"study sweep"``...).
    out : str, Path or None
        The folder; None: the study writes no file.
    force, resume : bool
        Replace the earlier outputs; continue an unfinished sweep.
    folder : ResultFolder, optional
        A folder the caller already opened (the command line's).

    Returns
    -------
    context manager
        ``folder`` if given, a new :class:`ResultFolder` (refusals naming ``out`` and
        ``force=True``/``resume=True``), or one yielding None.
    """
    if folder is not None:
        return contextlib.nullcontext(folder)
    if out is None:
        return contextlib.nullcontext(None)
    hint = ("pass resume=True to continue it or force=True to start over"
            if command == "study sweep" else "pass force=True to replace them")
    return ResultFolder(out, OUTPUTS[command], force=force, resume=resume,
                        command=f"oilgap {command}", field="out", hint=hint)


__all__ = ["OUTPUTS", "REPORT_FILES", "result_folder"]
