"""The fitted loop model as a document (``loop.json``'s ``model`` block): read back, predict.

:class:`FittedModel` holds what prediction needs and nothing else: the rig
(the case's geometry and friction law; each row's fluid comes from the data),
the friction law of each stage (published without T, calibrated, calibrated
with the accepted effects), the effect coefficients, the oil-free baselines of
each roughness T, and the fluids the fit used (so a custom oils table is not
needed again). :meth:`FittedModel.to_dict` is the ``model`` block of
``loop.json``; :func:`load_model` reads it back (from ``loop.json`` or a bare
model document); :meth:`FittedModel.predict_table` predicts the viscous power
(and, where a baseline was fitted, the electrical power) of new rows: new
operating conditions need no power column and no oil-free runs.

Prediction is the calibration's forward model
(:class:`~oilgap.optim.calibration.forward.ForwardModel`, seed Eqs. 5-9 with
the library's effects) on the rows, so a model read back predicts what the fit
predicted. Steady rows (no ``time_s``) have no rates: the effects that act
through time (thermal lag, sensor delay, oil inertia) contribute nothing there.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 5-9.
.. [2] ECMA-404, *The JSON data interchange syntax*, 2nd ed., 2017 (non-finite
   numbers are written as the strings "inf", "-inf", "nan").
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, fields, replace
from pathlib import Path

import numpy as np
import pandas as pd

from oilgap.model.case import DesignCase
from oilgap.model.effects import EFFECTS, FluidFacts, RigFacts
from oilgap.model.errors import InputError
from oilgap.model.fluid_table import TableFluid
from oilgap.model.fluids import GasFluid
from oilgap.model.io.case_io import case_from_dict
from oilgap.model.io.case_write import case_to_dict
from oilgap.model.io.inputs import file_kind
from oilgap.model.linear.report import rod_rows_as_motor_speed
from oilgap.model.measured.data import (
    MeasuredData,
    add_kinematics,
    predict_samples,
    read_table,
    validate,
)
from oilgap.model.oils import Oil, builtin_fluids, normalize_oil_name
from oilgap.model.regions import joint_geometry
from oilgap.model.skin_friction import BRANCH_KEYS, FrictionLaw
from oilgap.model.taylor_couette import couette_reynolds, taylor_number
from oilgap.model.units import m2_s_to_cst, m_to_mm

from .baseline import BASELINE_TERMS, BaselineFit
from .film_wall import film_wall_of_doc, model_shapes
from .forward import ForwardModel
from .model_schema import (
    STAGES,
    check_model_doc,
    check_model_ranges,
    decode,
    encode,
    nested,
    parse_model_json,
    refuse_literals,
)

MODEL_FORMAT = "oilgap-loop-model"
MODEL_VERSION = 1
PREDICTED_VISCOUS = "predicted_viscous_power_W"
PREDICTED_POWER = "predicted_power_W"
REASON = "prediction_note"
"""Column of :meth:`FittedModel.predict_table` saying why a prediction is missing."""
FLUID_CLASSES = {"mineral": Oil, "gas": GasFluid, "table": TableFluid}
"""Fluid kind -> dataclass (the fluid's fields are written out in full)."""

RANGE_SLACK = 0.01
"""Share of a variable's fitted span a row may lie beyond it before it counts as extrapolated."""

def fluid_to_dict(fluid) -> dict:
    """A fluid's kind and every field of its dataclass (JSON-safe).

    Parameters
    ----------
    fluid : Oil, GasFluid or TableFluid
        The fluid (SI inside; nu [cSt] where the field name says so).

    Returns
    -------
    dict
        ``kind`` and the fields by name.
    """
    return {"kind": fluid.kind, **encode({f.name: getattr(fluid, f.name) for f in fields(fluid)})}


def fluid_from_dict(doc: dict):
    """Rebuild a fluid written by :func:`fluid_to_dict`.

    Parameters
    ----------
    doc : dict
        ``kind`` and the fields.

    Returns
    -------
    Oil, GasFluid or TableFluid
        The fluid, validated by its own class (SI inside; nu [cSt] where named so).

    Raises
    ------
    InputError
        Unknown kind or fields.
    """
    kind = doc.get("kind")
    if kind not in FLUID_CLASSES:
        raise InputError("model.fluids.kind", kind, f"allowed: {', '.join(FLUID_CLASSES)}")
    cls = FLUID_CLASSES[kind]
    kw = {k: v for k, v in decode(doc).items() if k != "kind"}
    try:
        return cls(**kw)
    except TypeError as e:
        raise InputError("model.fluids", sorted(kw), f"not the fields of a {kind} fluid "
                         f"({e})") from None


def _law_to_dict(law: FrictionLaw) -> dict:
    return encode({f.name: getattr(law, f.name) for f in fields(law)
                   if (law.form == "branches" or f.name not in BRANCH_KEYS)
                   and (f.name != "transition" or law.transition != "reynolds")})


def _baseline_to_dict(b: BaselineFit) -> dict:
    return encode({"roughness_T": b.roughness_T, "terms": list(b.terms), "coef": b.coef,
                 "temp_ref_C": b.temp_ref_C, "rmse_W": b.rmse_W, "n_samples": b.n_samples,
                 "temp_range_C": b.temp_range_C, "speed_max_rpm": b.speed_max_rpm})


def _baseline_from_dict(d: dict) -> BaselineFit:
    d = decode(d)
    return BaselineFit(roughness_T=float(d["roughness_T"]), terms=tuple(d["terms"]),
                       coef=np.array(d["coef"], float),
                       temp_ref_C=float(d["temp_ref_C"]), rmse_W=float(d["rmse_W"]),
                       n_samples=int(d["n_samples"]),
                       temp_range_C=tuple(d["temp_range_C"]),
                       speed_max_rpm=float(d["speed_max_rpm"]), notes=())


def _case_doc(case: DesignCase) -> dict:
    """The case's geometry, motor and friction as a case document (no fluid, no duty cycle:
    prediction takes each row's fluid from the data)."""
    try:
        doc = case_to_dict(case)
    except InputError:  # a fluid that cannot be written (e.g. a table read from no file)
        doc = case_to_dict(replace(case, oil=builtin_fluids()["VG22"], oils_csv=None))
    return {k: v for k, v in doc.items() if k not in ("oil", "duty_cycle", "mission")}


def baseline_extrapolated(b: BaselineFit, speed_rpm: np.ndarray, temp_C: np.ndarray
                          ) -> np.ndarray:
    """Rows where an oil-free baseline is extrapolated (the limits of its own notes).

    Parameters
    ----------
    b : BaselineFit
        The baseline (its oil-free runs' largest speed [rpm] and temperatures [degC]).
    speed_rpm, temp_C : ndarray
        Rows' speed [rpm] and temperature [degC].

    Returns
    -------
    ndarray of bool
        Speed beyond 1.05 x the oil-free runs' largest, or (a baseline with temperature
        terms) temperature more than 1 K outside their range [-].
    """
    out = np.abs(speed_rpm) > 1.05 * b.speed_max_rpm
    if len(b.terms) > len(BASELINE_TERMS):
        lo, hi = b.temp_range_C
        out |= (temp_C < lo - 1.0) | (temp_C > hi + 1.0)
    return out


def sample_ranges(s, radius_m: float | None = None) -> dict:
    """Range of the operating variables of a sample set (for extrapolation flags).

    Parameters
    ----------
    s : Samples
        Samples (speed [rpm], temperature [degC], nu [m^2/s], gap [m], T [-]).
    radius_m : float, optional
        Region 1's rotor radius R [m]: with it, the region-1 Couette Reynolds number
        ``Re = |omega| R delta / nu`` (seed Eq. 4) and Taylor number
        ``Ta = Re (delta/R)^0.5`` (seed Eq. 3) ranges too.

    Returns
    -------
    dict
        Variable -> [min, max] in the unit of its name (``reynolds``, ``taylor`` [-]).
    """
    vals = {"abs_speed_rpm": np.abs(s.speed_rpm), "temp_C": s.temp_C,
            "nu_cSt": m2_s_to_cst(s.nu_m2_s), "gap_mm": m_to_mm(s.gap1_m),
            "roughness_T": s.roughness_T}
    if radius_m is not None:
        re = couette_reynolds(s.omega, radius_m, s.gap1_m, s.nu_m2_s)
        vals |= {"reynolds": re, "taylor": taylor_number(re, s.gap1_m, radius_m)}
    return {k: [float(np.min(v)), float(np.max(v))] for k, v in vals.items() if len(v)}


@dataclass(kw_only=True)
class FittedModel:
    """What a fitted loop predicts with: rig, laws, effects, baselines, fluids.

    Attributes
    ----------
    case : DesignCase
        Rig geometry (regions, end-face radii) and published friction law.
    laws : dict
        Stage (:data:`STAGES`) -> FrictionLaw.
    effects : dict
        Accepted effect -> coefficient [library unit].
    baselines : dict
        Roughness T [-] -> BaselineFit (empty for viscous-power data).
    fluids : dict
        Canonical name -> fluid the fit used.
    region1_gap_m : float
        Region-1 clearance of rows without ``gap_mm`` [m].
    pressure_gauge_Pa : float
        Oil pressure above atmospheric of the fit [Pa].
    kind : str
        Power column of the fitted data (``power_W`` or ``viscous_power_W``).
    has_time : bool
        Whether the fitted data were time series.
    cv_by : str
        Column of the fit's cross-validation groups.
    ranges : dict
        Fitted range of each operating variable (:func:`sample_ranges`).
    taylor_exponent : float
        Shape exponent m of the Taylor-vortex excess ``(Ta/Ta_c)^m - 1`` [-]
        (written as ``shapes`` when the effect is in the model).
    film_wall : float
        Wall condition w [-] of ``film_heating`` (its coefficient: the film strength s).
    """

    case: DesignCase
    laws: dict
    effects: dict
    baselines: dict = field(default_factory=dict)
    fluids: dict = field(default_factory=dict)
    region1_gap_m: float = float("nan")
    pressure_gauge_Pa: float = 0.0
    kind: str = "viscous_power_W"
    has_time: bool = True
    cv_by: str = "run"
    ranges: dict = field(default_factory=dict)
    taylor_exponent: float = 2.0
    film_wall: float = 0.0

    @property
    def thermal_mode(self) -> str:
        """The thermal mode the calibrated model predicts with (recorded in ``loop.json``).

        ``"none"``: every term at the measured oil temperature (the isothermal film of
        the design tool's default); ``"film"``: the calibrated ``film_heating`` effect
        heats the film above it. ``thermal_lag`` (an effect of its own) moves the oil
        state under either.

        Returns
        -------
        str
            ``"none"`` or ``"film"`` [-].
        """
        return "film" if "film_heating" in self.effects else "none"

    @classmethod
    def from_estimator(cls, est) -> FittedModel:
        """The model of a fitted :class:`~oilgap.optim.calibration.estimator.LoopEstimator`.

        Parameters
        ----------
        est : LoopEstimator
            After ``fit``.

        Returns
        -------
        FittedModel
        """
        s = est.samples_
        keys = {normalize_oil_name(str(o)) for o in pd.unique(s.oil)}
        fluids = {k: f for k, f in est.data_.oils.items() if k in keys}
        laws = dict(zip(STAGES, (est.law_without_T_, est.law_with_T_, est.law_), strict=True))
        return cls(case=est.case_, laws=laws,
                   effects={k: float(v) for k, v in est.effect_coef_.items()},
                   baselines=dict(est.baselines_), fluids=fluids,
                   region1_gap_m=float(est.geometry_.regions[0].gap_m), pressure_gauge_Pa=0.0,
                   kind=est.data_.kind, has_time=bool(s.has_time), cv_by=str(s.cv_by),
                   ranges=sample_ranges(s, float(est.geometry_.regions[0].radius_m)),
                   taylor_exponent=float(getattr(est, "taylor_exponent_", 2.0)),
                   film_wall=est.forward_model_.film_wall)

    def to_dict(self) -> dict:
        """The ``model`` block of ``loop.json`` (JSON-safe; units in key names).

        Returns
        -------
        dict
            format, version, case (TOML keys: mm, degC), laws, effects, baselines
            [W per basis function], fluids, region1_gap_m [m], pressure_gauge_Pa
            [Pa], kind, has_time, cv_by, thermal_mode (:attr:`thermal_mode`),
            fitted_range; ``shapes`` (the Taylor-vortex exponent m [-], the film's wall
            condition w [-]) when those effects are in the model.
        """
        return {"format": MODEL_FORMAT, "version": MODEL_VERSION,
                "case": encode(_case_doc(self.case)),
                "laws": {k: _law_to_dict(v) for k, v in self.laws.items()},
                "effects": encode(self.effects),
                **model_shapes(self.effects, self.taylor_exponent, self.film_wall),
                "baselines": [_baseline_to_dict(b) for b in self.baselines.values()],
                "fluids": {k: fluid_to_dict(f) for k, f in self.fluids.items()},
                "region1_gap_m": encode(self.region1_gap_m),
                "pressure_gauge_Pa": self.pressure_gauge_Pa, "kind": self.kind,
                "has_time": self.has_time, "cv_by": self.cv_by,
                "thermal_mode": self.thermal_mode,
                "fitted_range": encode(self.ranges)}

    @classmethod
    def from_dict(cls, doc: dict) -> FittedModel:
        """Rebuild a model from :meth:`to_dict`'s document, checked against its schema and
        ranges first (:mod:`~oilgap.optim.calibration.model_schema`).

        Parameters
        ----------
        doc : dict
            The ``model`` block.

        Returns
        -------
        FittedModel

        Raises
        ------
        InputError
            Not a model document, a version this code does not read, a field that fails
            the schema or its range (named by its JSON path, e.g.
            ``model.laws.with_effect.gamma``) [-].
        """
        if not isinstance(doc, dict) or doc.get("format") != MODEL_FORMAT:
            raise InputError("model", type(doc).__name__, f"a {MODEL_FORMAT!r} document (the "
                             "'model' block of loop.json) is required")
        if doc.get("version") != MODEL_VERSION:
            raise InputError("model.version", doc.get("version"), f"this oilgap reads version "
                             f"{MODEL_VERSION}")
        check_model_doc(doc)
        case = nested("model.case", case_from_dict, dict(doc["case"]))
        fluids = {k: nested(f"model.fluids.{k}", fluid_from_dict, v)
                  for k, v in doc.get("fluids", {}).items()}
        geometry = joint_geometry(case)
        check_model_ranges(doc, RigFacts.of(geometry, [FluidFacts(
            k, str(getattr(f, "kind", "mineral")), bool(getattr(f, "polymer_thickened",
                                                                  False)))
            for k, f in fluids.items()]))
        gap, r1 = float(doc["region1_gap_m"]), geometry.regions[0].radius_m
        if gap >= r1:
            raise InputError("model.region1_gap_m", gap, f"< the rotor radius {r1:g} m of "
                             "model.case (a clearance)")
        effects = {str(k): float(v) for k, v in doc["effects"].items()}
        m = float(doc.get("shapes", {}).get("taylor_vortex_onset", {}).get("exponent", 2.0))
        model = cls(case=case, laws={k: FrictionLaw(**decode(v)) for k, v in doc["laws"].items()},
                    effects=effects,
                    baselines={b.roughness_T: b for b in map(_baseline_from_dict,
                                                             doc.get("baselines", []))},
                    fluids=fluids, region1_gap_m=gap,
                    pressure_gauge_Pa=float(doc.get("pressure_gauge_Pa", 0.0)),
                    kind=doc["kind"], has_time=doc.get("has_time", True),
                    cv_by=doc.get("cv_by", "run"),
                    ranges={k: [float(x) for x in v]
                            for k, v in doc.get("fitted_range", {}).items()},
                    taylor_exponent=m, film_wall=film_wall_of_doc(doc, effects))
        recorded = doc.get("thermal_mode", model.thermal_mode)
        if recorded != model.thermal_mode:
            raise InputError("model.thermal_mode", recorded, f"{model.thermal_mode!r}, the "
                             "mode its effects calibrate (film only with film_heating)")
        return model

    # ------------------------------------------------------------------ predict
    def _data(self, data, oils, source: str | None) -> tuple[MeasuredData, pd.Index, dict]:
        """Validated rows to predict, the caller's index, and the fluids catalogue."""
        cat = {**builtin_fluids(), **self.fluids, **(oils or {})}
        if isinstance(data, MeasuredData):
            return data, pd.RangeIndex(data.n_read), {**cat, **data.oils}
        if isinstance(data, (str, Path)):
            df, source = read_table(data), str(data)
        elif isinstance(data, pd.DataFrame):
            df, source = data, source or "data frame"
        else:
            raise InputError("data", type(data).__name__, "a path, a pandas DataFrame or "
                             "MeasuredData is required")
        if getattr(self.case, "linear", None) is not None:  # rod_velocity_m_s -> speed_rpm
            df = rod_rows_as_motor_speed(df, self.case.linear)
        return validate(df, cat, source, purpose="predict"), df.index, cat

    def predict_table(self, data, stage: str = "with_effect", oils: dict | None = None,
                      source: str | None = None) -> pd.DataFrame:
        """Predicted power of every row of ``data``, aligned with the caller's rows.

        Parameters
        ----------
        data : path, DataFrame or MeasuredData
            Rows to predict (the loop's data format; no power column needed).
        stage : {"without_T", "with_T", "with_effect"}
            Which model.
        oils : dict, optional
            Extra fluids by canonical name (before the model's and the built-in ones).
        source : str, optional
            Name of a DataFrame's origin in messages (e.g. its file).

        Returns
        -------
        pandas.DataFrame
            Indexed like the caller's rows: ``predicted_viscous_power_W`` [W],
            ``predicted_power_W`` [W] (baseline + viscous; only when baselines were
            fitted), ``prediction_note`` (why a value is missing, ``""`` otherwise) and
            ``outside_fitted_range`` (bool: beyond the fitted operating range, or the
            baseline extrapolated).
        """
        if stage not in STAGES:
            raise InputError("stage", stage, f"allowed: {', '.join(STAGES)}")
        md, index, cat = self._data(data, oils, source)
        kin = add_kinematics(md.frame, md.has_time)
        n = md.n_read
        note = md.row_reasons().astype(object)
        free = kin["oil_free"].to_numpy()
        note[kin["line"].to_numpy()[free] - 2] = "oil-free row (no viscous loss to predict)"
        visc = np.full(n, np.nan)
        total = np.full(n, np.nan)
        outside = np.zeros(n, bool)
        s = predict_samples(md, self.region1_gap_m, self.pressure_gauge_Pa, frame=kin)
        r1 = joint_geometry(self.case).regions[0].radius_m
        bad = ~((s.gap1_m > 0) & (s.gap1_m < r1))
        if bad.any():
            note[kin["line"].to_numpy()[s.index[bad]] - 2] = \
                f"gap_mm outside (0, rotor radius {m_to_mm(r1):g} mm)"
            s = s.subset(~bad)
        if s.n:
            rows = kin["line"].to_numpy()[s.index] - 2
            p = self.power(s, stage, cat)
            visc[rows] = p
            outside[rows] = self.outside_range(s)
            for T, b in self.baselines.items():
                sel = s.roughness_T == T
                total[rows[sel]] = b.predict(s.omega[sel], s.domega_dt[sel], s.temp_C[sel]) \
                    + p[sel]
                outside[rows[sel]] |= baseline_extrapolated(b, s.speed_rpm[sel], s.temp_C[sel])
            if self.baselines:
                miss = ~np.isin(s.roughness_T, list(self.baselines))
                for T in np.unique(s.roughness_T[miss]):
                    note[rows[s.roughness_T == T]] = (f"no oil-free baseline fitted for "
                                                      f"roughness_T = {T:g}: no {PREDICTED_POWER}")
        out = {PREDICTED_VISCOUS: visc}
        if self.baselines:
            out[PREDICTED_POWER] = total
        out[REASON] = note
        out["outside_fitted_range"] = outside
        return pd.DataFrame(out, index=index)

    def predict(self, data, stage: str = "with_effect", oils: dict | None = None) -> pd.Series:
        """Predicted viscous power [W] per row, aligned with the caller's rows.

        Parameters
        ----------
        data : path, DataFrame or MeasuredData
            Rows to predict.
        stage : {"without_T", "with_T", "with_effect"}
            Which model.
        oils : dict, optional
            Extra fluids by canonical name.

        Returns
        -------
        pandas.Series
            Power [W]; NaN where a row cannot be predicted, the reason in
            ``series.attrs["reason"]`` (a Series aligned the same way).
        """
        t = self.predict_table(data, stage, oils)
        out = t[PREDICTED_VISCOUS].rename(f"viscous_power_W_{stage}")
        out.attrs["reason"] = t[REASON]
        return out

    def power(self, s, stage: str, oils: dict) -> np.ndarray:
        """Model viscous power [W] of samples under one stage's law (and effects) [1].

        Parameters
        ----------
        s : Samples
            Samples to predict (SI).
        stage : str
            Which model (:data:`STAGES`).
        oils : dict
            Fluids by canonical name (temperature laws of the thermal lag).

        Returns
        -------
        ndarray
            Power per sample [W].
        """
        coefs = dict(self.effects) if stage == "with_effect" else {}
        if not s.has_time:  # steady rows: no rates, no lag, no delay
            coefs = {k: v for k, v in coefs.items() if not EFFECTS[k].time_dependent}
        model = ForwardModel(s, self.case, oils, self.taylor_exponent, self.film_wall)
        return np.asarray(model.power(self.laws[stage], coefs), dtype=float)

    def outside_range(self, s) -> np.ndarray:
        """Samples beyond the fitted range of any operating variable by more than
        :data:`RANGE_SLACK` of its span.

        Parameters
        ----------
        s : Samples
            Samples to predict.

        Returns
        -------
        ndarray of bool
            True where extrapolated [-].
        """
        vals = {"abs_speed_rpm": np.abs(s.speed_rpm), "temp_C": s.temp_C,
                "nu_cSt": m2_s_to_cst(s.nu_m2_s), "gap_mm": m_to_mm(s.gap1_m),
                "roughness_T": s.roughness_T}
        out = np.zeros(s.n, bool)
        for k, (lo, hi) in self.ranges.items():
            if k in vals:
                tol = RANGE_SLACK * (hi - lo) + 1e-9 * max(abs(lo), abs(hi), 1.0)
                out |= (vals[k] < lo - tol) | (vals[k] > hi + tol)
        return out


def load_model(path: str | Path) -> FittedModel:
    """Read a model from ``loop.json`` (its ``model`` block) or a bare model document,
    checked against its schema and ranges (:meth:`FittedModel.from_dict`).

    Parameters
    ----------
    path : str or Path
        JSON file.

    Returns
    -------
    FittedModel
        Laws [-], effect coefficients [library unit], baselines [W], fluids.

    Raises
    ------
    InputError
        Missing or unreadable file, not JSON (cut short), no model block, a field that
        fails the schema (named by its JSON path; ``where`` is the file).
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("--model", str(p), "must be an existing loop.json (written by "
                         "oilgap loop)")
    try:
        doc = parse_model_json(p.read_text(encoding="utf-8"))
    except json.JSONDecodeError as e:
        kind = file_kind(p, e.doc)
        if kind in ("CSV", "TOML"):
            raise InputError("--model", str(p), f"is a {kind} file where the loop.json "
                             "written by oilgap loop is expected (run oilgap loop on the "
                             "rig data to write one)") from None
        raise InputError("--model", str(p), f"is not JSON ({e}; cut short or edited? run "
                         "oilgap loop again)") from None
    except UnicodeDecodeError as e:
        raise InputError("--model", str(p), f"is not JSON ({e}; cut short or edited? run "
                         "oilgap loop again)") from None
    except (OSError, RecursionError) as e:
        raise InputError("--model", str(p), f"cannot be read ({type(e).__name__})") from None
    if not isinstance(doc, dict):
        raise InputError("--model", str(p), f"holds a JSON {type(doc).__name__}, not the "
                         "object oilgap loop writes (run oilgap loop again)")
    try:
        refuse_literals(doc, "" if "model" in doc else "model")
    except InputError as e:
        raise InputError(e.field, e.value, e.allowed, str(p)) from None
    if "model" in doc and doc.get("format") != MODEL_FORMAT:
        doc = doc["model"]
    elif doc.get("format") != MODEL_FORMAT:
        raise InputError("--model", str(p), "holds no 'model' block (written by oilgap loop "
                         "since issue 9; run the loop again)")
    try:
        return FittedModel.from_dict(doc)
    except InputError as e:
        raise InputError(e.field, e.value, e.allowed, str(p)) from None


__all__ = ["FittedModel", "baseline_extrapolated", "fluid_from_dict", "fluid_to_dict",
           "load_model", "sample_ranges"]
