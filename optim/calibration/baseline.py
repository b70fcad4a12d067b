"""Stage 1 of the calibration: the oil-free baseline of each roughness T.

The baseline is a linear least-squares model of the oil-free runs of each T in
speed, acceleration and (if the oil-free runs span enough of it) temperature;
the runs are not synchronised sample by sample, so the model, not the samples,
is subtracted from the oil runs' electrical power.

References
----------
.. [1] G. H. Golub, C. F. Van Loan, *Matrix Computations*, 4th ed., Johns
   Hopkins 2013, sec. 5.5 (least squares, coefficient covariance
   ``s^2 (X'X)^+``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

BASELINE_TEMP_SPAN_K = 5.0
"""Oil-free runs must span this many kelvin for the baseline to carry temperature terms."""

BASELINE_TERMS = ("1", "|w|", "w^2", "w dw/dt", "sign(w) dw/dt", "(dw/dt)^2")
BASELINE_TEMP_TERMS = ("dT", "dT |w|", "dT w^2")


def _baseline_matrix(omega, alpha, dtemp, with_temp: bool) -> np.ndarray:
    cols = [np.ones_like(omega), np.abs(omega), omega * omega, omega * alpha,
            np.sign(omega) * alpha, alpha * alpha]
    if with_temp:
        cols += [dtemp, dtemp * np.abs(omega), dtemp * omega * omega]
    return np.column_stack(cols)


@dataclass(frozen=True, kw_only=True)
class BaselineFit:
    """Oil-free baseline of one roughness T: ``P = sum_j c_j f_j(w, dw/dt, T)`` [W].

    Parameters
    ----------
    roughness_T : float
        Roughness T of the runs [-].
    terms : tuple of str
        Names of the basis functions f_j (w [rad/s], dw/dt [rad/s^2], dT =
        temp - ``temp_ref_C`` [K]).
    coef : array
        Their least-squares coefficients [W per unit basis function].
    temp_ref_C : float
        Reference temperature of dT [degC].
    rmse_W : float
        RMS residual of the fit [W].
    n_samples : int
        Oil-free samples fitted.
    temp_range_C : (float, float)
        Temperature range of the oil-free runs [degC].
    speed_max_rpm : float
        Largest ``|speed|`` of the oil-free runs [rpm].
    notes : tuple of str
        Warnings (temperature independence, extrapolation).
    cov : array, optional
        Covariance of ``coef`` [1].
    """

    roughness_T: float
    terms: tuple[str, ...]
    coef: np.ndarray
    temp_ref_C: float
    rmse_W: float
    n_samples: int
    temp_range_C: tuple[float, float]
    speed_max_rpm: float
    notes: tuple[str, ...]
    cov: np.ndarray | None = None

    def design(self, omega, domega_dt, temp_C) -> np.ndarray:
        """Basis matrix f_j at the samples.

        Parameters
        ----------
        omega : array
            Speed [rad/s].
        domega_dt : array
            Acceleration [rad/s^2].
        temp_C : array
            Temperature [degC].

        Returns
        -------
        array, shape (n, len(terms))
            The basis functions [W per unit coefficient].
        """
        return _baseline_matrix(np.asarray(omega, float), np.asarray(domega_dt, float),
                                np.asarray(temp_C, float) - self.temp_ref_C,
                                len(self.terms) > len(BASELINE_TERMS))

    def predict(self, omega, domega_dt, temp_C) -> np.ndarray:
        """Baseline power at the samples.

        Parameters
        ----------
        omega : array
            Speed [rad/s].
        domega_dt : array
            Acceleration [rad/s^2].
        temp_C : array
            Temperature [degC].

        Returns
        -------
        array
            Power [W].
        """
        return self.design(omega, domega_dt, temp_C) @ self.coef

    def to_dict(self) -> dict:
        """JSON form."""
        return {"roughness_T": self.roughness_T,
                "terms": dict(zip(self.terms, map(float, self.coef), strict=True)),
                "temp_ref_C": self.temp_ref_C, "rmse_W": self.rmse_W,
                "n_samples": self.n_samples, "temp_range_C": list(self.temp_range_C),
                "speed_max_rpm": self.speed_max_rpm, "notes": list(self.notes)}


def fit_baselines(frame: pd.DataFrame) -> dict[float, BaselineFit]:
    """Least-squares baseline per roughness T from the oil-free runs [1].

    Temperature terms are used only if the oil-free runs of that T span at least
    :data:`BASELINE_TEMP_SPAN_K`; otherwise the baseline is taken as independent
    of temperature and a note says so.

    Parameters
    ----------
    frame : pandas.DataFrame
        Validated data with kinematics
        (:func:`oilgap.model.measured.data.add_kinematics`): omega [rad/s],
        domega_dt [rad/s^2], temp_C [degC], power_W [W], speed_rpm [rpm].

    Returns
    -------
    dict
        T [-] -> BaselineFit.
    """
    out = {}
    free = frame[frame["oil_free"]]
    oil = frame[~frame["oil_free"]]
    for T, g in free.groupby("roughness_T"):
        w, a, temp = (g[c].to_numpy() for c in ("omega", "domega_dt", "temp_C"))
        span = float(temp.max() - temp.min())
        with_temp = span >= BASELINE_TEMP_SPAN_K
        tref = float(temp.mean())
        X = _baseline_matrix(w, a, temp - tref, with_temp)
        coef, _, rank, _ = np.linalg.lstsq(X, g["power_W"].to_numpy(), rcond=None)
        rmse = float(np.sqrt(np.mean((X @ coef - g["power_W"].to_numpy()) ** 2)))
        # coefficient covariance (pseudo-inverse: the basis can be degenerate on one profile)
        dof = max(1, len(g) - int(rank))
        s2 = rmse * rmse * len(g) / dof
        cov = s2 * np.linalg.pinv(X.T @ X)
        notes = []
        o = oil[oil["roughness_T"] == T]
        if not with_temp:
            notes.append(f"oil-free runs span {span:.1f} K (< {BASELINE_TEMP_SPAN_K:g} K): "
                         "baseline taken as independent of temperature")
        elif len(o) and (o["temp_C"].max() > temp.max() + 1 or o["temp_C"].min() < temp.min() - 1):
            notes.append(f"oil runs reach {o['temp_C'].min():.1f}..{o['temp_C'].max():.1f} degC, "
                         f"the baseline is fitted on {temp.min():.1f}..{temp.max():.1f} degC: "
                         "its temperature terms are extrapolated")
        smax = float(np.abs(g["speed_rpm"]).max())
        if len(o) and np.abs(o["speed_rpm"]).max() > 1.05 * smax:
            notes.append(f"oil runs reach {np.abs(o['speed_rpm']).max():.0f} rpm, beyond the "
                         f"oil-free runs' {smax:.0f} rpm: baseline extrapolated in speed")
        terms = BASELINE_TERMS + (BASELINE_TEMP_TERMS if with_temp else ())
        out[float(T)] = BaselineFit(roughness_T=float(T), terms=terms, coef=coef, temp_ref_C=tref,
                                    rmse_W=rmse, n_samples=len(g),
                                    temp_range_C=(float(temp.min()), float(temp.max())),
                                    speed_max_rpm=smax, notes=tuple(notes),
                                    cov=cov)
    return out


