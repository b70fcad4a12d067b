"""Stage 3c of the calibration: the physical range of each calibrated parameter, and findings.

Every parameter of the base model carries the range physics and published data
allow (:data:`PARAM_RANGES`, each with its basis and source). A fitted value
outside it, a parameter left on its numerical box, or data that show no viscous
loss at all, is a *finding*: reported in ``loop.json`` and the report, and,
for a range violation, used as evidence: the estimator holds the parameter at
its range bound and lets the effect search explain what the free parameter had
absorbed (:func:`held_values`).

References
----------
.. [1] E. Bilgen, R. Boulos, "Functional dependence of torque coefficient of
   coaxial cylinders on gap width and Reynolds numbers", ASME J. Fluids Eng.
   95(1):122-126, 1973 (the correlation of seed Eq. 6 against the smooth-cylinder
   torque data they compiled).
.. [2] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Eqs. 6-9 and Table 3 (gamma = 0.566).
.. [3] ``shared/reference/physics-notes.md``: published smooth-cylinder
   measurements disagree with Bilgen-Boulos by tens of percent at small delta/R;
   Helmholtz's minimum-dissipation bound on grooved clearances.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from oilgap.model.skin_friction import FrictionLaw

from .forward import ForwardModel
from .least_squares import ModelFit
from .spec import BaseSpec


@dataclass(frozen=True)
class ParamRange:
    """Physical range of a calibrated parameter.

    Attributes
    ----------
    low, high : float
        Range [-].
    basis : str
        Why.
    source : str
        Where the numbers come from.
    """

    low: float
    high: float
    basis: str
    source: str

    def to_dict(self) -> dict:
        """JSON form."""
        return {"range": [self.low, self.high], "basis": self.basis, "source": self.source}


@dataclass(frozen=True, kw_only=True)
class Finding:
    """A finding on a calibration: a parameter outside its range or on its box, an effect on
    its bound, or no viscous signal.

    Attributes
    ----------
    kind : str
        "out of range", "out of range without effects", "at numerical limit",
        "at bound" or "no viscous signal".
    message : str
        What it means, one sentence.
    parameter : str or None
        The parameter or effect (None for "no viscous signal").
    value : float or None
        Its value [-] (the calibrated power [W] RMS for "no viscous signal").
    range : tuple of float or None
        Its physical range [-] (range violations only).
    basis, source : str or None
        Why that range, and where its numbers come from (range violations only).
    held_at : float or None
        The bound it is held at for the evidence trial [-], or None.
    effective_scale : float or None
        The power-law base's effective scale [-] (a violation judged through it only).
    evidence : str or None
        What the evidence trial gave (None if it gave nothing).
    tried : bool
        Whether the finding went through the evidence trial (only then is
        ``evidence`` a key of :meth:`to_dict`).
    """

    kind: str
    message: str
    parameter: str | None = None
    value: float | None = None
    range: tuple[float, float] | None = None
    basis: str | None = None
    source: str | None = None
    held_at: float | None = None
    effective_scale: float | None = None
    evidence: str | None = None
    tried: bool = False

    def to_dict(self) -> dict:
        """JSON form: the keys a finding of its kind carries, in ``loop.json`` order."""
        out = {"kind": self.kind, "parameter": self.parameter, "value": self.value}
        if self.range is not None:
            out.update(range=list(self.range), basis=self.basis, source=self.source)
        out.update(message=self.message, held_at=self.held_at)
        if self.effective_scale is not None:
            out["effective_scale"] = self.effective_scale
        if self.tried:
            out["evidence"] = self.evidence
        return out


PARAM_RANGES = {
    "scale": ParamRange(
        0.7, 1.4, "factor on the published Eq. 6 within the scatter of smooth-cylinder torque "
        "data around the Bilgen-Boulos correlation (tens of percent at small delta/R)",
        "Bilgen & Boulos 1973 (their correlation against the data they compiled); "
        "physics notes"),
    "beta": ParamRange(
        -1.0, -0.2, "Reynolds slope within the Eq. 6 branches, laminar -1 to turbulent -0.2",
        "seed Eq. 6; Bilgen & Boulos 1973"),
    "gamma": ParamRange(
        0.0, 1.0, "grooves do not lower the loss (gamma >= 0, the seed's grooved runs lose "
        "more); above 1 the factor T^gamma would grow faster than T itself, about twice the "
        "one published fit (0.566), which no groove mechanism of the seed supports (in "
        "creeping flow grooves cannot raise the loss at all, so gamma > 0 is already a "
        "calibration proxy)", "seed Table 3 and Eq. 8; physics notes (Helmholtz bound)"),
    "alpha": ParamRange(
        0.0, 0.5, "gap-ratio exponent near the 0.3 of every Eq. 6 branch: 0 for the exact "
        "laminar Couette torque at narrow gaps, nothing in the compiled smooth-cylinder data "
        "above 0.5", "Bilgen & Boulos 1973; seed Eq. 6"),
}
# The branches base's alpha_k and beta_k take the ranges of alpha and beta (the range of
# beta spans every branch of Eq. 6; turbulent data give alpha_k near 0, inside [0, 0.5]).
"""Physical range of each calibrated parameter, with its basis and source. The power-law
base's C is judged through its effective scale on the data (:func:`effective_scale`)."""

WHAT_IT_MEANS = {
    ("scale", "high"): "an effect that scales like the laminar loss may be absorbed",
    ("scale", "low"): "the loss is below the published law: a wrong viscosity, a baseline "
                      "that takes too much, or a loss-reducing effect may be absorbed",
    ("beta", "high"): "the free slope makes the loss grow faster with speed than any Eq. 6 "
                      "branch: an effect growing faster with speed may be absorbed",
    ("beta", "low"): "the free slope is steeper than the laminar branch: an effect that "
                     "grows slower with speed (e.g. Coulomb friction) may be absorbed",
    ("gamma", "high"): "a loss that grows with the roughness build may be absorbed by T^gamma",
    ("gamma", "low"): "the grooved build loses less than the smooth one: the T factor may be "
                      "absorbing a difference between the builds' runs",
    ("alpha", "high"): "the gap dependence is steeper than the smooth-cylinder data: a loss "
                       "that differs between gaps may be absorbed",
    ("alpha", "low"): "the loss falls with a wider gap faster than laminar Couette flow: a "
                      "loss that differs between gaps may be absorbed",
}
"""What a parameter outside its range may mean (parameter, side) -> text."""


def effective_scale(model: ForwardModel, fit_law: FrictionLaw, laminar_law: str) -> float:
    """Least-squares ratio of a fitted law's power to the published Eq. 6 power [-].

    ``p_fit' p_pub / p_pub' p_pub`` with p_pub the smooth Eq. 6 (case's laminar
    law, scale 1, alpha 0.3) at the fitted gamma: the scale a power-law fit
    amounts to on these data.

    Parameters
    ----------
    model : ForwardModel
    fit_law : FrictionLaw
        The fitted law.
    laminar_law : str
        The case's laminar law.

    Returns
    -------
    float
        Effective scale [-] (NaN if the published power vanishes).
    """
    p_fit = model.base_power(fit_law)
    p_pub = model.base_power(FrictionLaw(form="smooth", laminar_law=laminar_law,
                                         gamma=fit_law.gamma))
    den = float(p_pub @ p_pub)
    return float(p_fit @ p_pub) / den if den > 0 else float("nan")


def _finding(name: str, value: float, shown: str, rng: ParamRange,
             held: float | None) -> Finding:
    side = "high" if value > rng.high else "low"
    txt = (f"{shown} outside its physical range {rng.low:g}..{rng.high:g} ({rng.basis}; "
           f"{rng.source}): {WHAT_IT_MEANS[(name, side)]}")
    return Finding(kind="out of range", parameter=name, value=value, range=(rng.low, rng.high),
                   basis=rng.basis, source=rng.source, message=txt, held_at=held)


MOVED = 0.05
"""Relative change from its prior (at least 0.1 absolute x this) above which a parameter
counts as moved in a scale finding [-]."""


def _scale_text(spec: BaseSpec, vals: dict, model: ForwardModel, fit: ModelFit) -> str:
    """A scale finding that names everything that moved from its prior (issue 25): with
    alpha or gamma moved too, the scale alone is not the loss's level on these data."""
    prior = spec.prior_values()
    moved = [f"{j} = {vals[j]:.3g} (prior {prior[j]:.3g})" for j in spec.free
             if j != "scale" and abs(vals[j] - prior[j]) > MOVED * max(abs(prior[j]), 0.1)]
    text = f"the scale is {vals['scale']:.3g}x the published law"
    if not moved:
        return text
    eff = effective_scale(model, fit.law, spec.laminar_law)
    level = (f"; on these data the loss is {eff:.3g}x the published law's "
             f"({'below' if eff < 1 else 'above'} it)" if np.isfinite(eff) else "")
    return f"{text}, with {', '.join(moved)} moved as well{level}"


def parameter_findings(spec: BaseSpec, fit: ModelFit, model: ForwardModel) -> list[Finding]:
    """Findings on a calibration: parameters outside their range or on their box.

    Parameters
    ----------
    spec : BaseSpec
    fit : ModelFit
        The calibration (free parameters and law).
    model : ForwardModel
        The samples (for the power-law base's effective scale).

    Returns
    -------
    list of Finding
        Kind "out of range" (with ``range`` [-], ``basis``, ``source`` and
        ``held_at``, the bound it is held at for the evidence trial) or "at
        numerical limit".
    """
    vals = spec.values(fit.x)
    out = []
    limit = spec.at_limit(fit.x)
    for k in limit:
        out.append(Finding(kind="at numerical limit", parameter=k, value=vals[k],
                           message=f"{k} = {vals[k]:.3g} ran to the edge of the solver's box: "
                                   "the data do not identify it (no interval is given)"))
    for k in spec.free:
        if k in limit or (spec.base == "branches" and k.startswith("C")):
            continue  # a branch's C_k: its level is judged by the loss, not one number
        if k == "C":
            eff = effective_scale(model, fit.law, spec.laminar_law)
            rng = PARAM_RANGES["scale"]
            if np.isfinite(eff) and not rng.low <= eff <= rng.high:
                bound = rng.high if eff > rng.high else rng.low
                f = _finding("scale", eff, f"the fitted power law is {eff:.3g}x the published "
                             "law's power on these data (effective scale)", rng,
                             vals["C"] * bound / eff)
                out.append(replace(f, parameter="C", effective_scale=eff))
            continue
        kind = k.rstrip("0123456789")  # alpha3 -> alpha: a branch's exponent, same range
        rng = PARAM_RANGES[kind]
        v = vals[k]
        if not rng.low <= v <= rng.high:
            shown = (_scale_text(spec, vals, model, fit) if k == "scale"
                     else f"{k} = {v:.3g}")
            f = _finding(kind, v, shown, rng, rng.high if v > rng.high else rng.low)
            out.append(replace(f, parameter=k))
    return out


def no_signal_finding(y: np.ndarray, pred: np.ndarray, noise_W: float) -> Finding | None:
    """A finding if the data show no viscous loss the base model can describe.

    The calibrated power is below a tenth of the noise (RMS), or the measured
    viscous power is not above a tenth of the noise on average (with the Couette floor a
    calibrated loss never falls to zero, so the data's own mean decides): the level is
    then pinned by the noise, not identified, and no interval is given.

    Parameters
    ----------
    y : array
        Measured viscous power [W].
    pred : array
        Calibrated model power [W].
    noise_W : float
        Noise level [W].

    Returns
    -------
    Finding or None
        Kind "no viscous signal"; None if there is a signal.
    """
    p = float(np.sqrt(np.mean(pred * pred))) if len(pred) else 0.0
    m = float(np.mean(y)) if len(y) else 0.0
    if p >= 0.1 * noise_W and m > 0.1 * noise_W and p > 0:  # a mean within the noise: none
        return None
    return Finding(kind="no viscous signal", value=p,
                   message=f"no viscous signal: the calibrated loss is {p:.3g} W RMS against a "
                           f"noise of {noise_W:.3g} W (mean measured viscous power {m:.3g} W); "
                           "the calibration is not identified and no interval is given")


def held_values(findings: list[Finding]) -> dict[str, float]:
    """Parameters to hold at their range bound for the evidence trial.

    Parameters
    ----------
    findings : list of Finding
        From :func:`parameter_findings`.

    Returns
    -------
    dict
        Parameter -> bound [-]. The level (the scale; C for the power-law base:
        the C whose effective scale is the bound) is held only if no exponent
        is: with an exponent held, the level is refitted.
    """
    out = {f.parameter: float(f.held_at) for f in findings
           if f.kind == "out of range" and f.held_at is not None}
    if set(out) - {"C", "scale"}:
        out = {k: v for k, v in out.items() if k not in ("C", "scale")}
    return out


def explained_findings(before: list[Finding], after: list[Finding], values_after: dict,
                       accepted: list[str]) -> list[Finding]:
    """Range violations of the calibration without effects that the accepted effects resolve.

    Parameters
    ----------
    before : list of Finding
        Findings on the calibration without effects.
    after : list of Finding
        Findings on the calibration with the accepted effects.
    values_after : dict
        Parameters with the effects [-].
    accepted : list of str
        The accepted effects.

    Returns
    -------
    list of Finding
        The ``before`` range violations whose parameter is in range after, kind
        "out of range without effects", with what the refit gives.
    """
    if not accepted:
        return []
    still = {f.parameter for f in after}
    out = []
    for f in before:
        k = f.parameter
        if f.kind != "out of range" or k in still:
            continue
        v = values_after.get(k)
        now = f"{v:.3g}" if v is not None else "within range"
        out.append(replace(f, kind="out of range without effects", held_at=None,
                           message=f"{f.message}; refitted with {', '.join(accepted)} it is "
                                   f"{now}, within its range: the accepted effects explain it"))
    return out


BELOW_COUETTE_RATIO = 0.95
"""Median measured / Couette-minimum power below which the data lie below the floor [-]."""


def below_couette_finding(y: np.ndarray, couette_W: np.ndarray, noise_W: float
                          ) -> Finding | None:
    """A finding if the measured loss lies below the exact Couette loss of the geometry.

    No flow in the clearance dissipates less than laminar Couette flow
    (Helmholtz-Korteweg minimum dissipation), and the calibrated law never goes below
    it (:func:`oilgap.model.taylor_couette.couette_floor_applies`). Data below it say
    the oil-free baseline took too much away or the oil was warmer (thinner) than the
    temperature recorded. The test: over the samples whose Couette loss stands above
    three noise levels, the median of measured / Couette is below
    :data:`BELOW_COUETTE_RATIO`.

    Parameters
    ----------
    y : array
        Measured viscous power [W].
    couette_W : array
        Exact laminar Couette power of the rig's regions at each sample [W].
    noise_W : float
        Noise level [W].

    Returns
    -------
    Finding or None
        Kind "below couette" (value: the median ratio [-]); None otherwise.
    """
    sel = np.isfinite(couette_W) & (couette_W > 3.0 * max(noise_W, 0.0)) & (couette_W > 0)
    if sel.sum() < 3:
        return None
    ratio = float(np.median(y[sel] / couette_W[sel]))
    if ratio >= BELOW_COUETTE_RATIO:
        return None
    return Finding(kind="below couette", parameter="scale", value=ratio,
                   message=f"the data lie below the Couette minimum: check the baseline or the "
                           f"temperature (measured / exact laminar Couette loss, median "
                           f"{ratio:.3g} over {int(sel.sum())} samples; no clearance flow "
                           "dissipates less, so the calibrated law stops at Couette)")
