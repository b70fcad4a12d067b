"""A report folder of one evaluation or optimum (``oilgap evaluate/optimize --report DIR``,
``og.evaluate(...).report(DIR)``): what a design review files, like the studies' folders.

The folder holds ``summary.md`` (the answer and the text the command prints, the tables as
Markdown, the figure, the defaults the tool filled in), the JSON document of ``--json``,
the table as CSV, the figure as PNG, ``provenance.json`` and, for an optimum, the optimal
design as a case TOML with every digit (:func:`~oilgap.studies.io.case_write.write_case_toml`
``exact``). It is written as the studies' are (:mod:`oilgap.studies.outputs`,
:class:`~oilgap.studies.io.result_folder.ResultFolder`): checked and locked before
anything is written, each file atomically, an earlier report refused unless ``force``,
the folder marked incomplete while it is written.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from oilgap.model.io.serialize import round_sig
from oilgap.studies.io.case_write import write_case_toml
from oilgap.studies.io.files import atomic_savefig, atomic_to_csv
from oilgap.studies.io.result_folder import ResultFolder
from oilgap.studies.outputs import REPORT_FILES, result_folder
from oilgap.studies.reporting import DPI, markdown_table, new_figure, write_text

TITLES = {"evaluate": "Viscous loss of the joint", "optimize": "Optimal clearance geometry"}
"""The heading of each command's ``summary.md``."""


def _defaults_markdown(defaults: list[dict]) -> list[str]:
    """The defaults section of ``summary.md`` from a view's ``defaults`` records."""
    if not defaults:
        return ["## Defaults the tool filled in", "", "None: every value was given."]
    out = ["## Defaults the tool filled in", ""]
    for d in defaults:
        v = d.get("value")
        v = round_sig(v) if isinstance(v, float) else v
        unit = "" if d.get("unit") in (None, "", "-") else f" {d['unit']}"
        out.append(f"- `{d['field']} = {v}{unit}` ({d.get('source', '')})")
    return out


def _write_files(view: Any, command: str, out: Path, run: Any) -> list[Path]:
    """The report's files in ``out`` (summary.md last: it names the others)."""
    names = REPORT_FILES[command]
    frame = view.to_frame()
    files = [write_text(out / names["json"], view.to_json() + "\n"),
             atomic_to_csv(frame, out / names["table"])]
    fig, ax = new_figure()
    view.plot(ax=ax)
    fig.tight_layout()
    files.append(atomic_savefig(fig, out / names["figure"], dpi=DPI))
    if "case" in names:
        files.append(write_case_toml(view.to_case(), out / names["case"], run=run,
                                     exact=True))
    text = view.summary()
    md = [f"# {TITLES[command]}: {view.case.name}", "",
          "What `oilgap " + command + "` prints, the answer first:", "", "```text", text, "```",
          "", "## Table", "", markdown_table(frame.reset_index(), digits=6), "",
          f"![{names['figure']}]({names['figure']})", "",
          *_defaults_markdown(view.defaults), "", "## Files", "",
          *(f"- `{p.name}`" for p in files),
          *([f"- The optimum as a case with every digit: `oilgap evaluate "
             f"{names['case']}` gives the loss above."] if "case" in names else []), ""]
    files.append(write_text(out / names["summary"], "\n".join(md)))
    return files


def write_view_report(view: Any, command: str, out: str | Path, force: bool = False,
                      folder: ResultFolder | None = None) -> list[Path]:
    """Write the report folder of ``view`` (an evaluation or an optimum).

    Parameters
    ----------
    view : ResultView
        :class:`~oilgap._results.Evaluation`, :class:`~oilgap._results_design.Optimization`
        or :class:`~oilgap._results_robust.RobustOptimization`.
    command : {"evaluate", "optimize"}
        Whose files (:data:`oilgap.studies.outputs.REPORT_FILES`).
    out : str or Path
        The folder.
    force : bool
        Replace an earlier report there.
    folder : ResultFolder, optional
        The folder the caller already opened (the command line, before computing).

    Returns
    -------
    list of Path
        The files written (``provenance.json`` besides).
    """
    with result_folder(command, out, force, folder=folder) as f:
        f.begin()
        files = _write_files(view, command, Path(out), getattr(f, "run", None))
        f.complete()
    return files


__all__ = ["TITLES", "write_view_report"]
