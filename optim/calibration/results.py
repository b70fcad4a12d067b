"""Stage 8 of the calibration: the results as tables and records.

The accepted effects with their coefficients and intervals, the final status of
every candidate, the error of each run, the seed's Table 3 comparison (RMSE
without and with T per oil and T), and the JSON pieces of ``loop.json``.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power
   for a Deep-Sea Electric Manipulator*, Table 3.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from oilgap.model.effects import EFFECTS
from oilgap.model.measured.data import Samples
from oilgap.model.skin_friction import BRANCH_KEYS, FrictionLaw

from .candidates import Candidates
from .forward import ForwardModel
from .refit import FinalModel, rmse
from .selection import Selection


@dataclass(frozen=True, kw_only=True)
class EffectResult:
    """An accepted effect with its fitted coefficient and confidence interval.

    Attributes
    ----------
    name, title, formula, reference : str
        From the library.
    coefficient : float
        Fitted coefficient [``unit``].
    ci_low, ci_high : float
        Its 95 % interval [``unit``].
    unit : str
        Unit of the coefficient.
    strength : float
        The coefficient as the synthetic rig's strength [``strength_unit``].
    strength_unit : str
    heldout_gain_pct : float
        Held-out RMSE fall it brings in the final model [%].
    rms_power_W : float
        RMS of its power over the samples [W].
    shape : dict or None
        Chosen shape parameter (Taylor-vortex onset: ``{"exponent": m}`` [-]); for
        ``film_heating`` (whose coefficient is the film strength s [-]) the
        :func:`film_shape` record: s, its interval, the wall condition w and the film
        coefficient c = s c_theory(w) [K/W] as a diagnostic (docs/thermal.md#evidence).
    """

    name: str
    title: str
    formula: str
    reference: str
    coefficient: float
    ci_low: float
    ci_high: float
    unit: str
    strength: float
    strength_unit: str
    heldout_gain_pct: float
    rms_power_W: float
    shape: dict | None = None

    def coefficient_label(self) -> str:
        """Symbol of the coefficient (e.g. ``tau_c``)."""
        return EFFECTS[self.name].coefficient.split(" (")[0]

    def to_dict(self) -> dict:
        """JSON form (the issue's keys first)."""
        return {"name": self.name, "formula": self.formula, "coefficient": self.coefficient,
                "ci_low": self.ci_low, "ci_high": self.ci_high,
                "heldout_gain_pct": self.heldout_gain_pct, "title": self.title,
                "symbol": self.coefficient_label(),
                "reference": self.reference, "unit": self.unit, "strength": self.strength,
                "strength_unit": self.strength_unit, "rms_power_W": self.rms_power_W,
                **({"shape": self.shape} if self.shape else {})}


def effect_results(model: ForwardModel, final: FinalModel, ci: tuple[np.ndarray, np.ndarray],
                   gains: dict[str, float]) -> list[EffectResult]:
    """The accepted effects as records.

    Parameters
    ----------
    model : ForwardModel
        All oil runs.
    final : FinalModel
    ci : (lo, hi)
        Interval of each coefficient (library units).
    gains : dict
        Effect -> held-out gain [%].

    Returns
    -------
    list of EffectResult
        With each effect's own power: the final model minus the final model
        without it [W RMS].
    """
    fit = final.fit
    coefs = dict(zip(final.accepted, map(float, fit.theta), strict=True))
    out = []
    for i, n in enumerate(final.accepted):
        eff = EFFECTS[n]
        c = float(fit.theta[i])
        only = model.power(fit.law, dict(coefs)) - model.power(
            fit.law, {m: v for m, v in coefs.items() if m != n})
        formula, shape = eff.formula, None
        if n == "taylor_vortex_onset":
            m = final.taylor_exponent
            shape = {"exponent": m}
            formula = formula.replace(")^2 - 1)", f")^{m:g} - 1)")
        lo, hi = float(ci[0][i]), min(float(ci[1][i]), eff.upper)  # within the fit's bound
        if n == "film_heating":
            shape = film_shape(model, c, (lo, hi))
        out.append(EffectResult(
            name=n, title=eff.title, formula=formula, reference=eff.reference, coefficient=c,
            ci_low=lo, ci_high=hi,
            unit=eff.unit, strength=float(eff.strength_from_coefficient(c)),
            strength_unit=eff.strength_unit, heldout_gain_pct=gains[n],
            rms_power_W=rmse(only), shape=shape))
    return out


FILM_BOUND_TOL = 1e-3
"""A film strength within this of 1, or whose interval reaches 1, is at the smooth-film
theory's bound [-] (the bounded solver stops just short of a bound)."""


def film_shape(model: ForwardModel, s: float, ci: tuple[float, float]) -> dict:
    """The ``film_heating`` effect's record: the film strength s, its interval, the wall
    condition w it was fitted at, and the film coefficient ``c = s c_theory(w)`` [K/W].

    Parameters
    ----------
    model : ForwardModel
        The final forward model (its :attr:`~.forward.ForwardModel.film_wall` and
        :attr:`~.forward.ForwardModel.film_theory_K_W`).
    s : float
        Fitted film strength [-] (bounded to [0, 1] in the fit).
    ci : (float, float)
        Its 95 % interval, the upper end at most 1 [-].

    Returns
    -------
    dict
        ``film_strength``, ``film_strength_ci`` [-], ``wall_floating`` w [-],
        ``film_theory_K_W`` (c at s = 1) [K/W], ``film_heating_K_W`` and its interval
        ``film_heating_K_W_ci`` [K/W], ``at_bound`` (the statement when s or its interval
        reaches 1, else None).

    References
    ----------
    R. Nahme, Ingenieur-Archiv 11:191-209, 1940 (the smooth film at s = 1, through
    :func:`oilgap.model.film_heating.film_theory_coefficient`).
    """
    theory = model.film_theory_K_W
    bound = None
    if s >= 1.0 - FILM_BOUND_TOL or ci[1] >= 1.0:
        bound = (f"film strength s = {s:.3g}, its interval reaching {ci[1]:.3g}: at the "
                 "smooth-film theory's bound s = 1 (or not told from it): the data may ask for "
                 "a film as hot as the theory gives at the wall condition w = "
                 f"{model.film_wall:g} or hotter; a hotter film (walls above the sensor, or a "
                 "heating the film law does not hold) is not explained by it and may be taken "
                 "up by other effects")
    return {"film_strength": s, "film_strength_ci": list(ci),
            "wall_floating": model.film_wall, "film_theory_K_W": theory,
            "film_heating_K_W": s * theory,
            "film_heating_K_W_ci": [ci[0] * theory, ci[1] * theory],
            "at_bound": bound}


def _set_rejection(selection: Selection, final: FinalModel, margin: float,
                   min_explained: float) -> tuple[list[str], str] | None:
    """Effects a set-level rule rejected (structure check, nonlinear check) and the rule."""
    for rec in selection.log:
        if rec.step == "structure" and not rec.accepted:
            return ([e.split(" (")[0] for e in rec.effects],
                    f"the effects selected together ({', '.join(rec.effects)}) explain only "
                    f"{100 * rec.explained_total:.0f} % of the held-out structure above the "
                    f"noise (< {100 * min_explained:.0f} %)")
    for rec in final.log:
        if rec.step == "nonlinear check":
            return (list(rec.rejected),
                    f"the nonlinear refit of {', '.join(rec.rejected)} lowers the held-out "
                    f"RMSE by only {rec.gain_pct:.1f} % (< margin {100 * margin:.0f} %)")
    return None


def candidate_statuses(cands: Candidates, selection: Selection, final: FinalModel,
                       noise_W: float, margin: float, min_explained: float,
                       implausible: dict[str, str] | None = None) -> list[dict]:
    """Final status of every library effect considered, with the rule that decided it.

    Parameters
    ----------
    cands : Candidates
    selection : Selection
        Its ``candidates`` (records with the held-out scores alone) and its log.
    final : FinalModel
    noise_W : float
        Noise level [W].
    margin, min_explained : float
        Acceptance thresholds [-].
    implausible : dict, optional
        Effect -> why its fitted coefficient is implausible.

    Returns
    -------
    list of dict
        Records with status "accepted", "implausible: ..." (fitted outside its
        plausible range, not accepted), the reason a candidate was rejected (the
        rule that actually rejected it; with an accepted set, the held-out gain
        it adds to it [%]), or the screening status.
    """
    sel, e0, accepted = selection.selector, selection.heldout_before_W, final.accepted
    implausible = implausible or {}
    e_acc = sel.cv(final.chosen)
    set_rule = _set_rejection(selection, final, margin, min_explained)
    out = []
    for info in selection.candidates:
        name = info["name"]
        if name in accepted:
            info = {**info, "status": "accepted"}
        elif name in implausible:
            info = {**info, "status": f"implausible: {implausible[name]}"}
        elif info["status"] != "candidate":
            pass
        elif e0 * e0 - noise_W * noise_W <= 0:
            info = {**info, "status": "rejected: no structure above the noise"}
        elif accepted:
            add = min(sel.cv(final.chosen + (j,)) for j in cands.columns_of(name))
            gain = 100.0 * (1.0 - add / e_acc)
            info = {**info, "heldout_gain_added_pct": gain,
                    "status": (f"rejected: adds {gain:.1f} % to {', '.join(accepted)} "
                               f"(margin {100 * margin:.0f} %)")}
        else:
            info = {**info, "status": _alone_status(info, set_rule, margin, min_explained)}
        out.append(info)
    return out


def _alone_status(info: dict, set_rule, margin: float, min_explained: float) -> str:
    """Why a candidate was rejected when no effect was accepted."""
    g, x = info["heldout_gain_alone_pct"], info["explained_structure_alone"]
    if set_rule is not None and info["name"] in set_rule[0]:
        return f"rejected: held-out gain {g:.1f} % alone, but {set_rule[1]}"
    if g < 100 * margin:
        return f"rejected: held-out gain {g:.1f} % < margin {100 * margin:.0f} %"
    if set_rule is not None:
        return f"rejected: held-out gain {g:.1f} % alone; not selected ({set_rule[1]})"
    return (f"rejected: held-out gain {g:.1f} % but explains only {100 * x:.0f} % of the "
            f"structure (< {100 * min_explained:.0f} %)")


def table3_rows(s: Samples, p_without: np.ndarray, p_with: np.ndarray) -> list[dict]:
    """The seed's Table 3 [1]: RMSE without and with T per oil and T.

    Parameters
    ----------
    s : Samples
        Oil-run samples (measured viscous power [W]).
    p_without, p_with : arrays
        Model power without T (published law) and with T (fitted Eq. 8) [W].

    Returns
    -------
    list of dict
        oil, roughness_T [-], rmse_without_T_W, rmse_with_T_W [W], reduction_pct [%];
        sorted by the oil's median viscosity, then T.
    """
    y = s.viscous_W
    rows = []
    keys = pd.DataFrame({"oil": s.oil, "T": s.roughness_T})
    for (oil, T), g in keys.groupby(["oil", "T"], sort=False):
        m = g.index.to_numpy()
        wo, wt = rmse((y - p_without)[m]), rmse((y - p_with)[m])
        rows.append({"oil": oil, "roughness_T": float(T), "rmse_without_T_W": wo,
                     "rmse_with_T_W": wt, "reduction_pct": 100.0 * (1.0 - wt / wo)
                     if wo > 0 else float("nan")})
    order = {o: float(np.median(s.nu_m2_s[s.oil == o])) for o in set(s.oil)}
    return sorted(rows, key=lambda r: (order[r["oil"]], r["roughness_T"]))


def per_run_rows(s: Samples, pred: dict[str, np.ndarray], final: FinalModel,
                 table3: list[dict]) -> list[dict]:
    """Error of each run, in the order of Table 3 (then by run name).

    Parameters
    ----------
    s : Samples
    pred : dict
        ``without_T``, ``with_T``, ``with_effect`` model power per sample [W].
    final : FinalModel
        Its held-out predictions before and after [W].
    table3 : list of dict
        From :func:`table3_rows`.

    Returns
    -------
    list of dict
        run, oil, roughness_T [-], n_samples and RMSE in-sample and held out [W].
    """
    y = s.viscous_W
    res = {k: y - p for k, p in (("without_T", pred["without_T"]), ("with_T", pred["with_T"]),
                                 ("with_effect", pred["with_effect"]),
                                 ("before", final.before.pred), ("after", final.after.pred))}
    code = np.asarray(s.run_code)
    order = np.argsort(code, kind="stable")  # each run's samples in their order, one pass
    bounds = np.searchsorted(code[order], np.arange(len(s.run_names) + 1))
    rows = []
    for c, name in enumerate(s.run_names):
        m = order[bounds[c]:bounds[c + 1]]
        if not len(m):
            continue
        rows.append({
            "run": name, "oil": str(s.oil[m[0]]), "roughness_T": float(s.roughness_T[m[0]]),
            "n_samples": len(m), "rmse_without_T_W": rmse(res["without_T"][m]),
            "rmse_with_T_W": rmse(res["with_T"][m]),
            "rmse_with_effect_W": rmse(res["with_effect"][m]),
            "heldout_rmse_before_W": rmse(res["before"][m]),
            "heldout_rmse_after_W": rmse(res["after"][m])})
    rank = {(r["oil"], r["roughness_T"]): i for i, r in enumerate(table3)}
    rows.sort(key=lambda r: (rank[(r["oil"], r["roughness_T"])], r["run"]))
    return rows


def strip_bins(rs: dict) -> dict:
    """A residual structure without its bins (for JSON).

    Parameters
    ----------
    rs : dict
        From :func:`~oilgap.optim.calibration.residuals.residual_structure`.

    Returns
    -------
    dict
        The same with only Pearson r and eta^2 [-] per variable.
    """
    out = {k: v for k, v in rs.items() if k != "variables"}
    out["variables"] = {k: {"pearson_r": v["pearson_r"], "eta2": v["eta2"]}
                        for k, v in rs["variables"].items()}
    return out


def law_dict(law: FrictionLaw) -> dict:
    """JSON form of a friction law.

    Parameters
    ----------
    law : FrictionLaw

    Returns
    -------
    dict
        form, laminar_law, gamma, scale, C, alpha, beta [-].
    """
    out = {"form": law.form, "laminar_law": law.laminar_law, "gamma": law.gamma,
           "scale": law.scale, "C": law.C, "alpha": law.alpha, "beta": law.beta}
    if law.form == "branches":
        out.update({k: list(getattr(law, k)) for k in BRANCH_KEYS})
    return out
