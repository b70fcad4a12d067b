"""The façade's rig-data functions: ``og.Loop`` (``oilgap loop``: calibrate on measured
runs, find the missing effect), ``og.predict`` (``oilgap predict``), ``og.synth``
(``oilgap synth``) and ``og.read_measured``."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from oilgap._checks import (
    CASE,
    DATA,
    EFFECT_NAMES,
    FLAG,
    MODEL,
    NAMES,
    NUMBER,
    OILS,
    OUT,
    Arg,
    check_arg,
    checked,
    choice,
)
from oilgap._evaluate import as_case, oil_catalogue
from oilgap._results import ResultView, case_defaults, lazy
from oilgap.model.case import DesignCase
from oilgap.model.effects import EFFECTS
from oilgap.model.errors import ArgumentError, InputError, OilgapWarning, SolverError
from oilgap.model.io.defaults import gamma_fields
from oilgap.model.measured.data import MeasuredData, load_measured, read_table, validate
from oilgap.model.oils import Oil
from oilgap.optim.calibration.estimator import (
    DEFAULT_MARGIN,
    DEFAULT_MIN_EXPLAINED,
    LoopEstimator,
)
from oilgap.optim.calibration.model_io import (
    PREDICTED_POWER,
    PREDICTED_VISCOUS,
    REASON,
    FittedModel,
)
from oilgap.studies.io.result_folder import ResultFolder
from oilgap.studies.loop.figures import pages, plot_overview, plot_residuals, plot_windows
from oilgap.studies.loop.model_file import read_model
from oilgap.studies.loop.report import (
    format_summary,
    loop_json,
    unit_mistake,
    warn_unit_hints,
    write_report,
)
from oilgap.studies.loop.report_figures import FIGURE_CHOICES
from oilgap.studies.outputs import result_folder
from oilgap.studies.rigs.synth import SynthConfig, synthesize

STAGE = choice("without_T", "with_T", "with_effect", optional=False)
"""The ``stage`` of a prediction."""


@checked(path=DATA, oils=OILS)
def read_measured(path: str | Path, oils: dict[str, Oil] | str | Path | None = None
                  ) -> MeasuredData:
    """Rig data (CSV or Parquet) read and validated, every dropped row counted
    (:func:`oilgap.model.measured.data.load_measured`).

    Parameters
    ----------
    path : str, Path, DataFrame or MeasuredData
        The measured runs (a MeasuredData is returned as it is).
    oils : path or dict, optional
        Oils table, added to the built-in catalogue (:func:`oilgap._evaluate.read_oils`).

    Returns
    -------
    MeasuredData
    """
    if isinstance(path, MeasuredData):
        return path
    if not isinstance(path, (str, Path)):
        return validate(path, oil_catalogue(oils), _source(path))
    return load_measured(path, oil_catalogue(oils))


def _source(data: Any) -> str:
    return str(data) if isinstance(data, (str, Path)) else "data frame"


@checked(model=MODEL, data=DATA, stage=STAGE, oils=OILS)
def predict(model: FittedModel | LoopEstimator | str | Path, data: Any, *,
            stage: str = "with_effect", oils: dict[str, Oil] | str | Path | None = None,
            allow_incomplete: bool = False) -> pd.DataFrame:
    """The power of new rows with a model the loop fitted (``oilgap predict``).

    Parameters
    ----------
    model : path to loop.json, FittedModel or a fitted Loop
        The fitted model.
    data : path (CSV/Parquet), DataFrame or MeasuredData
        Rows in the loop's format without a power column (steady points without
        ``time_s``).
    stage : {"without_T", "with_T", "with_effect"}
        Which model.
    oils : path or dict, optional
        Oils for fluids the model does not hold.
    allow_incomplete : bool
        Use a loop.json from a folder still marked incomplete (a loop that failed or was
        killed), with a warning; refused otherwise.

    Returns
    -------
    DataFrame
        The input rows with ``predicted_viscous_power_W`` [W] (and ``predicted_power_W``
        [W] where a baseline was fitted) and ``prediction_note``; ``attrs``: ``stage``,
        ``gamma`` [-], ``predicted`` (rows with a prediction), ``columns``,
        ``thermal_mode`` (the mode recorded in the model: the loop's, not the design
        tool's default), and with ``film_heating`` in the model ``film_strength`` s [-]
        and ``wall_floating`` w [-].

    Raises
    ------
    InputError
        No row can be predicted (the reasons counted); bad data; a loop.json that fails
        its schema (the field named by its JSON path) or from a folder marked incomplete.
    """
    if isinstance(model, LoopEstimator):
        cat = model.data_.oils if hasattr(model, "data_") else None
        m = model.fitted_model()
    else:
        m, cat = (read_model(model, allow_incomplete) if isinstance(model, (str, Path))
                  else model), None
    cat = oil_catalogue(oils) or cat
    raw = data.frame if isinstance(data, MeasuredData) else (
        read_table(data) if isinstance(data, (str, Path)) else data)
    table = m.predict_table(raw, stage, cat, source=_source(data))
    ok = int(table[PREDICTED_VISCOUS].notna().sum())
    if ok == 0:
        reasons = "; ".join(f"{n} x {r}" for r, n in table[REASON].value_counts().items())
        raise InputError("data", _source(data), f"no row can be predicted ({reasons})")
    ext = table["outside_fitted_range"].to_numpy()
    if ext.any():
        lines = ", ".join(str(i + 2) for i in np.flatnonzero(ext)[:5])
        warnings.warn(OilgapWarning(f"{int(ext.sum())} row(s) outside the fitted range of "
                                    f"speed, temperature, viscosity, gap or T (lines {lines}"
                                    f"{', ...' if ext.sum() > 5 else ''}): extrapolated"),
                      stacklevel=2)
    res = raw.copy(deep=False)
    cols = [PREDICTED_VISCOUS] + ([PREDICTED_POWER] if PREDICTED_POWER in table else [])
    for c in cols + [REASON]:
        res[c] = table[c].to_numpy()
    res.attrs.update(stage=stage, gamma=float(m.laws[stage].gamma), predicted=ok,
                     columns=cols, thermal_mode=m.thermal_mode)
    if "film_heating" in m.effects:
        res.attrs.update(film_strength=float(m.effects["film_heating"]),
                         wall_floating=float(m.film_wall))
    return res


LOOP_PLOTS = ("windows", "overview", "residuals", "residuals_speed")
"""The figures :meth:`Loop.plot` draws."""


def _figures_check(name: str, value: Any) -> None:
    """``figures`` is a bool or one of :data:`FIGURE_CHOICES`."""
    if isinstance(value, str) and value not in FIGURE_CHOICES:
        raise ArgumentError(name, value, "True, False, \"summary\", \"all\" or \"none\"")


class Loop(LoopEstimator, ResultView):
    """The measured-data loop (``oilgap loop``): calibrate the model on measured runs,
    search the library for a missing effect, report before/after.

    A :class:`~oilgap.optim.calibration.estimator.LoopEstimator` (learned attributes end
    in ``_``) with the façade's views once fitted: :meth:`to_frame` (per run, measured
    against the model before and after), :meth:`plot`, :meth:`summary`, :meth:`to_dict`
    (``loop.json``), :meth:`report`.

    Parameters
    ----------
    case : DesignCase, path or None
        Rig geometry (None: the seed joint).
    oils : path or dict, optional
        Oils table (default: the built-in catalogue).
    effects : sequence of str or "a,b", optional
        Library effects to consider (default: all).
    margin : float
        Held-out RMSE fall an effect must bring [-].
    base : {"eq6", "auto", "power-law", "branches"}
        Base law (default ``"auto"``: each candidate base with its own effect search, chosen
        by held-out error, the table in ``base_selection_``); a named one forces it.
    cv_by : str
        Column whose values are the groups of leave-one-group-out validation.
    min_explained : float
        Share of the residual an effect must explain [-].
    max_effects : int
        Most effects accepted together.
    cv : {"one-step", "full"}
        Cross-validation of the effect search.

    Notes
    -----
    The constructor only stores its arguments (the scikit-learn convention); :meth:`fit`
    reads the case and the oils, checks every option and runs the loop. A method that
    needs the fit raises :class:`~oilgap.model.errors.NotFittedError` before it.
    """

    def __init__(self, case: DesignCase | str | Path | None = None, *,
                 oils: dict[str, Oil] | str | Path | None = None,
                 effects: str | list[str] | tuple[str, ...] | None = None,
                 margin: float = DEFAULT_MARGIN, base: str = "auto", cv_by: str = "run",
                 min_explained: float = DEFAULT_MIN_EXPLAINED, max_effects: int = 3,
                 cv: str = "one-step"):
        super().__init__(case=case, oils=oils, margin=margin, min_explained=min_explained,
                         effects=effects, max_effects=max_effects, cv=cv, base=base,
                         cv_by=cv_by)

    @property
    def raw(self) -> Loop:  # the estimator is its own result
        return self

    @property
    def defaults(self) -> list[dict]:
        """What the tool filled in for the rig case (after :meth:`fit`)."""
        return case_defaults(self.case_) if hasattr(self, "case_") else []

    @checked(data=DATA)
    def fit(self, data: Any) -> Loop:
        """Run the loop on measured data (path, DataFrame or MeasuredData); data in a wrong
        unit is refused naming the unit, not the solver. Returns ``self``."""
        given = self.case, self.oils, self.effects
        for name, spec in (("case", CASE), ("oils", OILS), ("effects", EFFECT_NAMES)):
            check_arg(name, getattr(self, name), spec)
        effects = self.effects
        if isinstance(effects, str):
            effects = [e.strip() for e in effects.split(",") if e.strip()] or None
        # the estimator reads its case and oils resolved; the arguments stay as given
        self.case = None if self.case is None else as_case(self.case)
        self.oils, self.effects = oil_catalogue(self.oils), effects
        try:
            with np.errstate(all="ignore"):  # trial fits at extreme values: not user news
                super().fit(data)
        except SolverError as e:
            refusal = unit_mistake(self, _source(data), e)
            if refusal is None:
                raise
            raise refusal from None
        finally:
            self.case, self.oils, self.effects = given
        warn_unit_hints(self)
        self.data_.warn_if_many_dropped()
        return self

    @checked(data=DATA, stage=STAGE)
    def predict(self, data: Any, stage: str = "with_effect") -> pd.DataFrame:
        """The input rows with the model's predictions (:func:`predict`)."""
        return predict(self, data, stage=stage)


    def to_dict(self) -> dict:
        """The ``loop.json`` document (:func:`~oilgap.studies.loop.report.loop_json`,
        which builds on the estimator's own ``to_dict``)."""
        self._check_fitted("to_dict()")
        return loop_json(self)

    def summary(self, defaults: bool = True) -> str:
        """What ``oilgap loop`` prints (without its ``wrote`` line): the held-out error
        before and after first (``defaults`` False: without gamma and the defaults filled
        in, ``-q``)."""
        self._check_fitted("summary()")
        return format_summary(self, defaults)

    def to_frame(self) -> pd.DataFrame:
        """Per run: oil, roughness, samples, mean measured and model viscous power [W]
        (without T, with T = before, with the effects = after) and their RMSE [W]."""
        self._check_fitted("to_frame()")
        s, p = self.samples_, self.pred_
        rows = []
        for r in self.per_run_:
            m = s.run_code == list(s.run_names).index(r["run"])
            rows.append({**{k: r[k] for k in ("run", "oil", "roughness_T", "n_samples")},
                         "measured_mean_W": float(np.mean(s.viscous_W[m])),
                         "model_without_T_mean_W": float(np.mean(p["without_T"][m])),
                         "model_before_mean_W": float(np.mean(p["with_T"][m])),
                         "model_after_mean_W": float(np.mean(p["with_effect"][m])),
                         **{k: v for k, v in r.items() if k.endswith("_W")}})
        return pd.DataFrame(rows).set_index("run")

    @checked(ax=Arg(("Axes", "Figure", "SubFigure"), "a matplotlib Axes or Figure, or None "
                    "(a new figure)", optional=True))
    def plot(self, ax: Any = None, kind: str = "windows") -> Any:
        """The loop's figures (:mod:`oilgap.studies.loop.figures`, the ones ``report``
        writes), drawn on ``ax`` (its place subdivided into panels; default a new pyplot
        figure): ``kind="windows"`` measured and modelled viscous power [W] over the last
        few speed cycles of each run, ``"overview"`` each whole run, ``"residuals"`` the
        residual before and after against time, ``"residuals_speed"`` against speed
        [rpm]. At most :data:`~oilgap.studies.loop.figures.PER_PAGE` runs (the first).
        Returns the first panel's axes (every panel is in ``ax.figure.axes``)."""
        self._check_fitted("plot()")
        if kind not in LOOP_PLOTS:
            raise InputError("kind", kind, f"one of {', '.join(LOOP_PLOTS)}")
        target = ax if ax is not None else lazy("matplotlib.pyplot").figure(figsize=(11, 7))
        runs = pages(len(self.samples_.run_names))[0]
        if kind == "windows":
            axs = plot_windows(self, runs, axes=target)
        elif kind == "overview":
            axs = plot_overview(self, runs, axes=target)
        else:
            axs = plot_residuals(self, "speed" if kind == "residuals_speed" else "time",
                                 axes=target)
        return axs[0]

    @checked(out=Arg(OUT.kinds, "a folder path (str or pathlib.Path)", check=OUT.check),
             figures=Arg((bool, "bool_", str), "True, False, \"summary\", \"all\" or "
                         "\"none\"", check=_figures_check), force=FLAG)
    def report(self, out: str | Path, figures: bool | str = True, force: bool = False,
               folder: ResultFolder | None = None) -> dict:
        """Write ``loop.json``, ``report.md`` and the figures into the folder ``out``
        (an earlier report refused unless ``force``; ``folder``: a result folder the
        caller already opened). Returns the paths (``json``, ``report``, ``figures``).

        ``figures``: True or ``"summary"`` (every run's figures up to 24 runs; above, the
        12 worst runs and a grid of small multiples), ``"all"`` (every run's pages,
        however many: ``oilgap loop --figures all``), False or ``"none"``."""
        self._check_fitted("report()")
        with result_folder("loop", out, force, folder=folder) as f:
            f.note(**gamma_fields(self.case_))  # the rig case as read, for provenance.json
            f.begin()
            paths = write_report(self, out, figures=figures)
            f.complete()
        return paths


@checked(case=CASE, roughness=NAMES, effect=Arg((str,), "a library effect's name",
                                              optional=True),
         strength=NUMBER, viscous=FLAG)
def synth(case: DesignCase | str | Path | None = None, *,
          roughness: tuple[float, ...] = (4.0, 2.0), effect: str | None = None,
          strength: float | None = None, seed: int = 0, viscous: bool = False
          ) -> pd.DataFrame:
    """Synthetic rig data in the measured-data format (``oilgap synth``): the seed's
    experiment simulated, optionally with one library effect.

    Parameters
    ----------
    case : DesignCase, path or None
        Rig geometry (None: the seed joint).
    roughness : tuple of float
        Roughness T of the rotor builds [-].
    effect : str, optional
        A library effect to inject (:data:`oilgap.model.effects.EFFECTS`).
    strength : float, optional
        Its strength in its unit (default: its test strength).
    seed : int
        Noise seed (>= 0).
    viscous : bool
        ``viscous_power_W`` (a torque balance, no oil-free runs) instead of ``power_W``.

    Returns
    -------
    DataFrame
        The rows; ``attrs``: ``effect``, ``strength``, ``strength_unit``,
        ``noise_power_W`` [W], ``power_column``.
    """
    if strength is not None and effect is None:
        raise InputError("strength", strength, "needs effect=NAME")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError("seed", seed, "an integer >= 0 is required (the noise seed)")
    try:
        rough = tuple(float(x) for x in roughness)
    except (TypeError, ValueError):
        raise InputError("roughness", roughness, "numbers >= 1, e.g. (4, 2)") from None
    cfg = SynthConfig(case=None if case is None else as_case(case), roughness=rough,
                      effect=effect, strength=strength,
                      kind="viscous_power_W" if viscous else "power_W")
    df = synthesize(cfg, seed=int(seed))
    df.attrs.update(effect=effect, power_column=cfg.kind, noise_power_W=cfg.noise_power_W,
                    strength=cfg.resolved().strength if effect else None,
                    strength_unit=EFFECTS[effect].strength_unit if effect else None)
    return df


__all__ = ["Loop", "predict", "read_measured", "synth"]
