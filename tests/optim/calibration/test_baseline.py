"""Stage 1, the oil-free baseline: exact recovery, temperature terms, coefficient covariance."""

import numpy as np
import pandas as pd

from oilgap.model.measured.data import add_kinematics, validate
from oilgap.optim.calibration.baseline import BASELINE_TEMP_TERMS, BASELINE_TERMS, fit_baselines


def _run(name, oil, T, n=40, dt=0.2, power="power_W", **extra):
    t = np.arange(n) * dt
    d = {"run": name, "time_s": t, "speed_rpm": 3000 * np.sin(0.1 * np.pi * t),
         "temp_C": 30.0 + 0.01 * t, "oil": oil, "roughness_T": T, power: 20 + t}
    d.update(extra)
    return pd.DataFrame(d)


def _basis(om, al, dT=None):
    cols = [np.ones_like(om), np.abs(om), om * om, om * al, np.sign(om) * al, al * al]
    if dT is not None:
        cols += [dT, dT * np.abs(om), dT * om * om]
    return np.column_stack(cols)


def _kinematic_frame(n=600, temp_span=0.0, seed=0):
    """A frame as add_kinematics leaves it, written out by hand (one oil-free run, T = 4)."""
    t = np.arange(n) * 0.2
    om = 314.16 * np.sin(0.1 * np.pi * t) * (1 + 0.3 * np.sin(0.013 * t))
    al = np.gradient(om, t)
    temp = 25.0 + temp_span * t / t[-1]
    return pd.DataFrame({"run": "f", "time_s": t, "speed_rpm": om * 60 / (2 * np.pi),
                         "omega": om, "domega_dt": al, "temp_C": temp, "oil": "none",
                         "roughness_T": 4.0, "oil_free": True, "power_W": 0.0})


def test_baseline_recovers_a_known_combination_exactly():
    # oil-free power built from the basis itself (no noise): the fit must reproduce it
    t = np.arange(0, 120, 0.2)
    w = 314.16 * np.sin(0.1 * np.pi * t) * (1 + 0.3 * np.sin(0.013 * t))  # not a pure sine
    df = pd.DataFrame({"run": "f", "time_s": t, "speed_rpm": w * 60 / (2 * np.pi),
                       "temp_C": 25.0, "oil": "none", "roughness_T": 4.0, "power_W": 0.0})
    df = pd.concat([df, _run("a", "VG150", 4.0)], ignore_index=True)
    f = add_kinematics(validate(df).frame)
    free = f[f["oil_free"]]
    om, al = free["omega"].to_numpy(), free["domega_dt"].to_numpy()
    coef = np.array([4.0, 0.09, 1.5e-5, 2e-4, 1e-3, 5e-5])
    f.loc[f["oil_free"], "power_W"] = _basis(om, al) @ coef
    b = fit_baselines(f)[4.0]
    assert b.terms == BASELINE_TERMS  # no temperature span: no temperature terms
    assert np.allclose(b.predict(om, al, 25.0), _basis(om, al) @ coef, atol=1e-9)
    assert b.rmse_W < 1e-9 and "independent of temperature" in b.notes[0]


def test_temperature_terms_when_the_runs_span_enough_kelvin():
    f = _kinematic_frame(temp_span=8.0)
    om, al, temp = f["omega"].to_numpy(), f["domega_dt"].to_numpy(), f["temp_C"].to_numpy()
    tref = temp.mean()
    coef = np.array([4.0, 0.09, 1.5e-5, 2e-4, 1e-3, 5e-5, -0.2, -1e-3, -2e-7])
    f["power_W"] = _basis(om, al, temp - tref) @ coef
    b = fit_baselines(f)[4.0]
    assert b.terms == BASELINE_TERMS + BASELINE_TEMP_TERMS
    assert b.temp_ref_C == tref and b.temp_range_C == (25.0, 33.0)
    assert np.allclose(b.coef, coef, rtol=1e-6, atol=1e-12)
    assert b.notes == ()


def test_covariance_matches_the_scatter_of_repeated_fits():
    # the stated coefficient covariance against the spread over 400 noise realisations
    f = _kinematic_frame(n=300)
    X = _basis(f["omega"].to_numpy(), f["domega_dt"].to_numpy())
    truth = np.array([4.0, 0.09, 1.5e-5, 2e-4, 1e-3, 5e-5])
    rng = np.random.default_rng(5)
    coefs, covs = [], []
    for _ in range(400):
        f["power_W"] = X @ truth + rng.normal(0.0, 0.5, len(f))
        b = fit_baselines(f)[4.0]
        coefs.append(b.coef)
        covs.append(np.diag(b.cov))
    scatter = np.var(np.array(coefs), axis=0, ddof=1)
    stated = np.mean(np.array(covs), axis=0)
    # the sample variance of 400 draws is within ~15 % of the truth (chi^2, 3 sigma)
    assert np.allclose(scatter, stated, rtol=0.2)
    assert np.allclose(np.mean(coefs, axis=0), truth, atol=4 * np.sqrt(stated / 400))


def test_speed_extrapolation_is_noted():
    free = _kinematic_frame()
    oil = free.iloc[:50].copy()
    oil["oil_free"] = False
    oil["oil"] = "VG150"
    oil["speed_rpm"] = 2 * free["speed_rpm"].abs().max()
    b = fit_baselines(pd.concat([free, oil], ignore_index=True))[4.0]
    assert any("baseline extrapolated in speed" in n for n in b.notes)
