"""Sample sets of the calibration-stage tests, built by hand (no synthetic rig, no files).

``make_samples`` writes a :class:`~oilgap.model.measured.data.Samples` out field by
field: a sine speed, a temperature ramp, nu and rho from each oil's own laws at the
sample temperature and at +-TEMP_STEP_K, the case's gap, and the viscous power
given by the caller (default zero).
"""

from types import SimpleNamespace

import numpy as np
import pytest

from oilgap.model.io.case_io import seed_case
from oilgap.model.measured.data import TEMP_STEP_K, Samples
from oilgap.model.oils import builtin_oils, get_oil
from oilgap.model.skin_friction import FrictionLaw
from oilgap.model.units import ZERO_CELSIUS_K

RUNS = (("a", "VG150", 4.0), ("b", "VG320", 4.0), ("c", "VG150", 2.0), ("d", "VG680", 2.0))
"""(run, oil, T) of the default sample set."""


def make_samples(runs=RUNS, n=120, dt=0.2, gap_m=None, temp_rate_K_s=0.05, power=None,
                 peak_rpm=3000.0, offset_rpm=None):
    """Samples of ``runs`` with ``n`` samples each (power [W] per sample or None = 0).

    Speed ``offset + peak sin(4 pi t / (n dt))`` [rpm] (offset default 0.3 peak).
    """
    offset = 0.3 * peak_rpm if offset_rpm is None else offset_rpm
    case = seed_case()
    gap = case.region1.gap if gap_m is None else gap_m
    cols = {k: [] for k in ("run", "code", "oil", "T", "t", "rpm", "w", "a", "temp", "dtemp",
                            "nu", "rho", "nu_m", "nu_p", "rho_m", "rho_p", "gap")}
    for code, (name, oil, T) in enumerate(runs):
        t = np.arange(n) * dt
        rpm = peak_rpm * np.sin(2 * np.pi * t / (n * dt / 2)) + offset
        w = rpm * 2 * np.pi / 60
        a = np.gradient(w, t)
        temp = 30.0 + 3 * code + temp_rate_K_s * t
        o = get_oil(oil)
        nu, _, rho = o.properties(temp + ZERO_CELSIUS_K, 0.0)
        nu_m, _, rho_m = o.properties(temp + ZERO_CELSIUS_K - TEMP_STEP_K, 0.0)
        nu_p, _, rho_p = o.properties(temp + ZERO_CELSIUS_K + TEMP_STEP_K, 0.0)
        for k, v in zip(cols, (np.full(n, name), np.full(n, code), np.full(n, oil),
                               np.full(n, T), t, rpm, w, a, temp, np.full(n, temp_rate_K_s),
                               nu, rho, nu_m, nu_p, rho_m, rho_p, np.full(n, gap)),
                        strict=True):
            cols[k].append(v)
    c = {k: np.concatenate(v) for k, v in cols.items()}
    total = len(c["t"])
    y = np.zeros(total) if power is None else np.asarray(power, float)
    return Samples(c["run"], c["code"], tuple(r[0] for r in runs), c["oil"], c["T"], c["t"],
                   c["rpm"], c["w"], c["a"], c["temp"], c["dtemp"], c["nu"], c["rho"],
                   (c["nu_m"], c["nu_p"]), (c["rho_m"], c["rho_p"]), c["gap"], y,
                   np.arange(total))


@pytest.fixture(scope="module")
def rig():
    """The seed joint, the built-in oils, a true law and the default sample set."""
    return SimpleNamespace(case=seed_case(), oils=builtin_oils(), samples=make_samples(),
                           law=FrictionLaw(form="power-law", C=10.0, alpha=0.3, beta=-1.0,
                                           gamma=-0.3))


@pytest.fixture(scope="session")
def samples_factory():
    """:func:`make_samples`, for tests that need their own sample set."""
    return make_samples
