"""Duty cycles: speed against time, and their exact reduction to a speed distribution.

The seed's cycle is ``3000 rpm * sin(0.1 pi t)`` over 300 s sampled every
0.2 s (1500 samples). A user cycle is a CSV ``time_s,speed_rpm``.

Where the operating condition (oil temperature, depth) is steady over the
cycle, the viscous power depends only on |omega|, so the sample mean of any
loss equals a weighted sum over the distinct |omega| values: for the seed's
cycle 1500 samples reduce to 26 nodes (periodicity, sign symmetry and the
mirror symmetry of the sine), with the same mean to rounding error.

References
----------
.. [1] Seed paper, *Modeling and Optimization of Compensating Oil Viscous Power for a
   Deep-Sea Electric Manipulator*, Sec. IV.B (the cycle ``3000 sin(0.1 pi t)`` rpm,
   5 min sampled every 200 ms, 1500 samples).
"""

from __future__ import annotations

import csv
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .errors import InputError, check_finite, check_positive
from .units import rpm_to_rad_s

NODE_MERGE_RTOL = 1e-12
"""Relative tolerance (of the peak |omega|) within which samples share a node."""


@dataclass(frozen=True, eq=False)
class DutyCycle:
    """Speed against time.

    Attributes
    ----------
    time_s : ndarray
        Sample times [s], strictly increasing.
    omega_rad_s : ndarray
        Signed rotor speed at each sample [rad/s].
    description : str
        One line for reports ("3000 rpm * sin(...), 1500 samples every 0.2 s").
    spec : dict
        How the cycle was made, in the units of the case file (``kind``,
        ``peak_speed_rpm`` [rpm], ``frequency_hz`` [Hz], ``duration_s`` [s],
        ``sample_interval_s`` [s], or ``csv``); written back by the TOML writer.
    """

    time_s: np.ndarray
    omega_rad_s: np.ndarray
    description: str = ""
    spec: dict = field(default_factory=dict, repr=False)

    @classmethod
    def sine(cls, peak_speed_rpm: float = 3000.0, frequency_hz: float = 0.05,
             duration_s: float = 300.0, sample_interval_s: float = 0.2) -> DutyCycle:
        """``peak * sin(2 pi f t)`` sampled at ``t = k dt``, ``k = 0 .. duration/dt - 1``.

        The defaults are the seed's cycle [1].

        Parameters
        ----------
        peak_speed_rpm : float
            Peak speed [rpm], > 0.
        frequency_hz : float
            Frequency of the sine [Hz], > 0.
        duration_s : float
            Duration [s], > 0.
        sample_interval_s : float
            Sample interval dt [s], > 0; at least two samples.

        Returns
        -------
        DutyCycle
            Times [s] and speeds [rad/s].

        Raises
        ------
        InputError
            A non-positive value or fewer than two samples.
        """
        where = "duty_cycle"
        peak = check_positive("peak_speed_rpm", peak_speed_rpm, where)
        f = check_positive("frequency_hz", frequency_hz, where)
        dur = check_positive("duration_s", duration_s, where)
        dt = check_positive("sample_interval_s", sample_interval_s, where)
        n = int(round(dur / dt))
        if n < 2:
            raise InputError("duration_s", duration_s,
                             f"must hold at least 2 samples of {dt:g} s", where)
        t = np.arange(n) * dt
        w = rpm_to_rad_s(peak) * np.sin(2.0 * np.pi * f * t)
        return cls(t, w, f"{peak:g} rpm * sin(2 pi {f:g} Hz t), {n} samples every {dt:g} s",
                   {"kind": "sine", "peak_speed_rpm": peak, "frequency_hz": f,
                    "duration_s": dur, "sample_interval_s": dt})

    @classmethod
    def from_csv(cls, path: str | Path) -> DutyCycle:
        """Read a ``time_s,speed_rpm`` CSV (time strictly increasing, all values finite).

        Parameters
        ----------
        path : str or Path
            CSV with columns ``time_s`` [s] and ``speed_rpm`` [rpm] (signed).

        Returns
        -------
        DutyCycle
            Times [s] and speeds [rad/s].

        Raises
        ------
        InputError
            Missing file or column, non-finite values, time not strictly increasing,
            fewer than two rows.
        """
        path = Path(path)
        where = str(path)
        if not path.is_file():
            raise InputError("duty_cycle.csv", str(path), "must be an existing CSV file")
        with path.open(newline="", encoding="utf-8") as fh:
            reader = csv.DictReader(fh)
            cols = reader.fieldnames or []
            missing = [c for c in ("time_s", "speed_rpm") if c not in cols]
            if missing:
                raise InputError("columns", cols, f"missing {missing}; required "
                                 "['time_s', 'speed_rpm']", where)
            t, s = [], []
            for i, row in enumerate(reader, start=2):
                t.append(check_finite("time_s", _num(row["time_s"]), f"{where} line {i}"))
                s.append(check_finite("speed_rpm", _num(row["speed_rpm"]), f"{where} line {i}"))
        if len(t) < 2:
            raise InputError("rows", len(t), "a duty cycle needs at least 2 samples", where)
        t_arr = np.asarray(t)
        bad = np.nonzero(np.diff(t_arr) <= 0)[0]
        if bad.size:
            i = int(bad[0]) + 1
            raise InputError("time_s", t[i], f"must increase strictly (line {i + 2} follows "
                             f"{t[i - 1]:g})", where)
        return cls(t_arr, rpm_to_rad_s(np.asarray(s)), f"{path.name}, {len(t)} samples",
                   {"kind": "csv", "csv": str(path)})

    @property
    def peak_omega_rad_s(self) -> float:
        """Largest |omega| over the cycle [rad/s]."""
        return float(np.max(np.abs(self.omega_rad_s)))

    @property
    def duration_s(self) -> float:
        """Duration [s]: the sample span plus one interval (samples stand for equal slots)."""
        t = self.time_s
        return float(t[-1] - t[0] + (t[-1] - t[0]) / (len(t) - 1))

    def sample_weights(self) -> np.ndarray:
        """Time weight of each sample (sum 1): its interval to the next sample, the last
        sample taking the one before it. Uniform sampling gives equal weights.

        Returns
        -------
        ndarray
            Weights [-], one per sample.
        """
        dt = np.diff(self.time_s)
        w = np.append(dt, dt[-1])
        return w / w.sum()

    def speed_distribution(self) -> tuple[np.ndarray, np.ndarray]:
        """Distinct |omega| values [rad/s] and their weights (sum 1).

        For any f, ``f(nodes) @ weights`` equals the time-weighted mean of
        ``f(|omega|)`` over the samples up to rounding (samples closer than
        :data:`NODE_MERGE_RTOL` of the peak share a node). Computed once per
        cycle and cached (the cycle is immutable); the arrays must not be modified.

        Returns
        -------
        nodes_rad_s : ndarray
            Distinct |omega| [rad/s].
        weights : ndarray
            Time fraction of each node [-] (sum 1).
        """
        cached = self.__dict__.get("_speed_distribution")
        if cached is not None:
            return cached
        a = np.abs(self.omega_rad_s)
        peak = a.max() if a.max() > 0 else 1.0
        keys = np.round(a / peak / NODE_MERGE_RTOL).astype(np.int64)
        _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
        weights = np.bincount(inverse, weights=self.sample_weights())
        dist = (a[first], weights)
        object.__setattr__(self, "_speed_distribution", dist)
        return dist


def _num(raw):
    try:
        return float(raw)
    except (TypeError, ValueError):
        return raw
