"""Where a residual no library effect explains sits, how it scales, and what that points to
(issue 25 item 4).

* **Where**: the residual's mean square split by the categorical variables (oil, run,
  roughness T): the share each variable's group means carry,
  ``sum_g n_g m_g^2 / sum r^2`` (the part of the mean square a per-group offset would
  remove), each group's mean and RMS, and the runs that stand out (RMS above
  :data:`STANDOUT` times the median run's and above twice the noise).
* **How it scales**: the residual fitted as ``r = k |omega|^a nu^b rho^c`` by
  nonlinear least squares (k by variable projection), with 95 % intervals from the
  Jacobian (t quantile); an exponent whose variable hardly varies (sd of its log
  below :data:`MIN_LOG_SPREAD`) is not fitted and said so.
* **What it points to**: one sentence. A residual concentrated in one oil
  (:data:`OIL_SHARE` of the mean square) points to that oil's viscosity; otherwise the
  exponents are compared with the signatures of :data:`SIGNATURES` (power laws of the
  dissipation of known mechanisms: P ~ omega^a nu^b), the nearest within two standard
  errors named.

References
----------
.. [1] K. Pearson (1905), the correlation ratio (between-group share of variance).
.. [2] G. H. Golub, V. Pereyra, "The differentiation of pseudo-inverses and nonlinear
   least squares problems whose variables separate", SIAM J. Numer. Anal. 10:413-432,
   1973 (variable projection).
.. [3] H. Schlichting, K. Gersten, *Boundary-Layer Theory*, 9th ed., Springer 2017
   (laminar boundary layer ~ Re^-1/2, turbulent skin friction ~ Re^-1/5).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import stats
from scipy.optimize import least_squares

from oilgap.model.measured.data import Samples

STANDOUT = 2.0
"""A run stands out when its residual RMS exceeds this many times the median run's."""

OIL_SHARE = 0.5
"""Share of the residual's mean square one oil's mean must carry to be named."""

MIN_LOG_SPREAD = 0.05
"""Standard deviation of ln(variable) below which its exponent is not fitted [-]."""

SIGNATURES = (
    (3.0, 0.0, "an inertial loss (churning, windage): grows as omega^3 and does not depend "
               "on nu"),
    (1.0, 0.0, "a torque independent of speed and oil (dry or seal friction, a Coulomb "
               "torque): grows as omega and does not depend on nu"),
    (2.0, 1.0, "a laminar viscous shear the model misses or mis-sizes (a clearance, a "
               "film): grows as omega^2 nu"),
    (2.5, 0.5, "a laminar boundary layer (an end face, a disc): grows as omega^2.5 "
               "nu^0.5"),
    (2.8, 0.2, "a turbulent skin friction (C ~ Re^-0.2): grows as omega^2.8 nu^0.2"),
)
"""(a, b, mechanism) of P ~ omega^a nu^b for the mechanisms a residual is compared with [3]."""


def _shares(res: np.ndarray, labels: np.ndarray, ss: float) -> list[dict]:
    out = []
    for g in np.unique(labels):
        r = res[labels == g]
        m = float(r.mean())
        out.append({"group": str(g), "n": int(r.size), "mean_W": m,
                    "rms_W": float(np.sqrt(np.mean(r * r))),
                    "share": float(r.size * m * m / ss) if ss > 0 else 0.0})
    return sorted(out, key=lambda d: -d["share"])


def where_it_sits(res: np.ndarray, s: Samples, noise_W: float) -> dict:
    """The residual split by oil, run and roughness, and the runs that stand out.

    Parameters
    ----------
    res : array
        Residual (measured - model) per sample [W].
    s : Samples
    noise_W : float
        Noise level [W].

    Returns
    -------
    dict
        ``by`` (variable -> ``share`` [-] and ``groups``: group, n, mean_W, rms_W,
        share) and ``standout_runs`` (names).
    """
    ss = float(np.sum(res * res))
    runs = np.asarray(s.run_names)[s.run_code]
    by = {}
    for name, labels in (("oil", np.asarray(s.oil)), ("run", runs),
                         ("roughness_T", np.asarray(s.roughness_T))):
        groups = _shares(res, labels, ss)
        by[name] = {"share": float(sum(g["share"] for g in groups)), "groups": groups}
    rms = {g["group"]: g["rms_W"] for g in by["run"]["groups"]}
    med = float(np.median(list(rms.values()))) if rms else 0.0
    standout = sorted((r for r, v in rms.items() if v > STANDOUT * med and v > 2 * noise_W),
                      key=lambda r: -rms[r])
    return {"by": by, "standout_runs": standout}


def how_it_scales(res: np.ndarray, s: Samples) -> dict:
    """Power-law fit ``r = k |omega|^a nu^b rho^c`` of the residual with 95 % intervals.

    Parameters
    ----------
    res : array
        Residual [W].
    s : Samples
        Speed [rad/s], nu [m^2/s], rho [kg/m^3].

    Returns
    -------
    dict
        ``k`` [W], ``exponents`` (variable -> value, ci95 [lo, hi] or a "not fitted"
        reason), ``r2`` [-] (share of the residual's mean square the power law takes).
    """
    w = np.abs(np.asarray(s.omega, float))
    ok = w > 0
    logs = {"omega": np.log(w[ok]), "nu": np.log(np.asarray(s.nu_m2_s)[ok]),
            "rho": np.log(np.asarray(s.density_kg_m3)[ok])}
    free = [k for k, v in logs.items() if float(np.std(v)) >= MIN_LOG_SPREAD]
    r = res[ok]
    if not free or r.size <= len(free) + 2:
        return {"k": float("nan"), "exponents": {}, "r2": 0.0}
    centre = {k: float(np.mean(logs[k])) for k in free}
    X = np.column_stack([logs[k] - centre[k] for k in free])

    def shape(p):
        return np.exp(np.clip(X @ p, -700, 700))

    def resid(p):
        f = shape(p)
        k = float(f @ r / max(f @ f, 1e-300))
        return r - k * f

    start = np.array([2.0 if k == "omega" else 0.0 for k in free])
    sol = least_squares(resid, start, method="lm", xtol=1e-12, ftol=1e-12)
    f = shape(sol.x)
    k = float(f @ r / max(f @ f, 1e-300))
    J = np.column_stack([f, *(k * f * X[:, i] for i in range(len(free)))])
    dof = max(1, r.size - J.shape[1])
    sse = float(np.sum((r - k * f) ** 2))
    try:
        cov = np.linalg.inv(J.T @ J) * sse / dof
        half = stats.t.ppf(0.975, dof) * np.sqrt(np.maximum(np.diag(cov)[1:], 0.0))
    except np.linalg.LinAlgError:
        half = np.full(len(free), np.nan)
    exps = {v: {"value": float(sol.x[i]), "ci95": [float(sol.x[i] - half[i]),
                                                   float(sol.x[i] + half[i])]}
            for i, v in enumerate(free)}
    for v in logs:
        if v not in exps:
            exps[v] = {"value": None, "ci95": None,
                       "note": f"not fitted: {v} hardly varies in the data"}
    ss = float(np.sum(r * r))
    return {"k": k, "exponents": exps, "r2": float(1.0 - sse / ss) if ss > 0 else 0.0}


def mechanism(where: dict, scaling: dict) -> str:
    """One sentence on the mechanism the residual's signature points to.

    Parameters
    ----------
    where : dict
        :func:`where_it_sits` (shares [-] by oil, run, roughness).
    scaling : dict
        :func:`how_it_scales` (exponents of ``|omega|``, nu, rho [-] with intervals).

    Returns
    -------
    str
        The oil a residual concentrates in, or the nearest signature of
        :data:`SIGNATURES` within two standard errors, or that none matches.
    """
    oil = where["by"]["oil"]
    if len(oil["groups"]) > 1 and oil["groups"][0]["share"] >= OIL_SHARE:
        g = oil["groups"][0]
        return (f"concentrated in the runs of {g['group']} ({100 * g['share']:.0f} % of the "
                f"residual's mean square, mean {g['mean_W']:+.3g} W): that oil's viscosity "
                "may be off its grade")
    e = scaling.get("exponents", {})
    a, b = e.get("omega", {}), e.get("nu", {})
    if a.get("value") is None:
        return "the residual shows no power law in the speed"
    se_a = max((a["ci95"][1] - a["ci95"][0]) / 3.92, 1e-9)
    text = f"grows as |omega|^{a['value']:.2f}"
    if b.get("value") is not None:
        se_b = max((b["ci95"][1] - b["ci95"][0]) / 3.92, 1e-9)
        text += f" nu^{b['value']:.2f}"
        z = [(((a["value"] - a0) / se_a) ** 2 + ((b["value"] - b0) / se_b) ** 2, why)
             for a0, b0, why in SIGNATURES]
        lim = 2 * 2.0 ** 2
    else:
        z = [(((a["value"] - a0) / se_a) ** 2, why) for a0, _, why in SIGNATURES]
        lim = 2.0 ** 2
    best = min(z)
    if best[0] <= lim:
        return f"{text}: {best[1]}"
    return f"{text}: no known signature within its intervals"


def describe_residual(res: np.ndarray, s: Samples, noise_W: float) -> dict:
    """Where the residual sits, how it scales and the mechanism sentence.

    Parameters
    ----------
    res : array
        Residual of the final model [W].
    s : Samples
    noise_W : float
        Noise level [W].

    Returns
    -------
    dict
        ``where`` (:func:`where_it_sits`), ``scaling`` (:func:`how_it_scales`),
        ``mechanism`` (one sentence) and ``text`` (the lines of the summary).
    """
    where = where_it_sits(res, s, noise_W)
    scaling = how_it_scales(res, s)
    mech = mechanism(where, scaling)
    parts = [f"{v} {100 * d['share']:.0f} %" for v, d in where["by"].items()]
    lines = ["where: share of the residual's mean square carried by " + ", ".join(parts)
             + (f"; runs that stand out: {', '.join(where['standout_runs'])}"
                if where["standout_runs"] else "")]
    ex = scaling["exponents"]
    if ex:
        lines.append("scaling: residual ~ " + " ".join(
            f"{v}^{d['value']:.2f} [{d['ci95'][0]:.2f}, {d['ci95'][1]:.2f}]"
            if d.get("value") is not None and all(map(math.isfinite, d["ci95"]))
            else f"{v}: {d.get('note', 'no interval')}" for v, d in ex.items())
            + f" (R^2 {scaling['r2']:.2f})")
    lines.append("points to: " + mech)
    return {"where": where, "scaling": scaling, "mechanism": mech, "text": lines}
