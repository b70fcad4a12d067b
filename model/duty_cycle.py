"""Duty cycles: speed against time, and their exact reduction to a speed distribution.

The seed's cycle is ``3000 rpm * sin(0.1 pi t)`` over 300 s sampled every
0.2 s (1500 samples). A user cycle is a CSV ``time_s,speed_rpm``.

Where the operating condition (oil temperature, depth) is steady over the
cycle, the viscous power depends only on ``|omega|``, so the sample mean of any
loss equals a weighted sum over the distinct ``|omega|`` values: for the seed's
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
import io
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .errors import InputError, check_finite, check_positive
from .io.inputs import cell_for_message, check_physical, header_error, read_input_text
from .units import rpm_to_rad_s

NODE_MERGE_RTOL = 1e-12
"""Relative tolerance (of the peak |omega|) within which samples share a node."""

MAX_SAMPLES = 10_000_000
"""Most samples a duty cycle may have [-]: a day sampled every 10 ms is 8.6e6. A cycle
this long takes about 0.8 GB and a few seconds to reduce to its speed distribution; a
longer record adds nothing to a mean over |omega| (resample it). Checked before the
arrays are allocated."""

SAMPLES_REASON = ("a day sampled every 10 ms is 8.6e6 samples; a longer record only "
                  "costs memory, resample it")

MAX_SPEED_RPM = 100_000.0
"""Largest ``|speed|`` of a duty cycle [rpm]: above the fastest electric machines
(high-speed spindles and turbo-compressor drives reach ~1e5 rpm); a larger number is a
unit slip (rad/s x 100, rpm x 60)."""

SPEED_REASON = ("faster than any electric machine (high-speed spindles reach ~1e5 rpm); "
                "a larger number is a unit slip")

MIN_PEAK_SPEED_RPM = 1.0e-3
"""Slowest peak speed of a sine duty cycle [rpm]: one turn in 11.6 days; slower, the joint
is at rest for its viscous loss (below 1e-10 W for the seed joint), and a denormal number
(5e-324) would underflow to a cycle at rest."""


def check_peak_speed(value: Any, where: str = "duty_cycle") -> float:
    """A peak speed [rpm] in [:data:`MIN_PEAK_SPEED_RPM`, :data:`MAX_SPEED_RPM`], or an
    InputError saying which side it is on and why.

    Parameters
    ----------
    value : Any
        The peak ``|speed|`` as written [rpm].
    where : str
        Where it came from, for the message [-].

    Returns
    -------
    float
        ``float(value)`` [rpm].

    Raises
    ------
    InputError
        Not finite; negative or zero (a peak is a magnitude); below the slowest or above
        the fastest peak.
    """
    peak = check_finite("peak_speed_rpm", value, where)
    if peak <= 0.0:
        raise InputError("peak_speed_rpm", value, "must be positive: the peak is the "
                         "magnitude |speed| of the sine (a negative speed only turns the "
                         "other way)", where)
    if peak < MIN_PEAK_SPEED_RPM:
        raise InputError("peak_speed_rpm", value, f"at least {MIN_PEAK_SPEED_RPM:g} rpm (one "
                         "turn in 11.6 days): slower, the joint is at rest and has no loss "
                         "to evaluate", where)
    return check_physical("peak_speed_rpm", peak, 0.0, MAX_SPEED_RPM, SPEED_REASON, where,
                          lo_open=True)


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
    cache : dict
        Results computed once per cycle (not an input; see the field's note).
    """

    time_s: np.ndarray
    omega_rad_s: np.ndarray
    description: str = ""
    spec: dict = field(default_factory=dict, repr=False)
    cache: dict = field(default_factory=dict, init=False, repr=False, compare=False)
    """What is computed once per cycle (the cycle is immutable): the speed distribution,
    the film settings per ``[thermal]`` (:func:`oilgap.model.joint_loss.case_film`). A
    copy made with :func:`dataclasses.replace` starts with an empty one."""

    @classmethod
    def sine(cls, peak_speed_rpm: float = 3000.0, frequency_hz: float = 0.05,
             duration_s: float = 300.0, sample_interval_s: float = 0.2) -> DutyCycle:
        """``peak * sin(2 pi f t)`` sampled at ``t = k dt``, ``k = 0 .. duration/dt - 1``.

        The defaults are the seed's cycle [1].

        Parameters
        ----------
        peak_speed_rpm : float
            Peak speed [rpm], in (0, :data:`MAX_SPEED_RPM`].
        frequency_hz : float
            Frequency of the sine [Hz], > 0 and below the Nyquist frequency 1/(2 dt).
        duration_s : float
            Duration [s], > 0.
        sample_interval_s : float
            Sample interval dt [s], > 0; at least two and at most :data:`MAX_SAMPLES`
            samples.

        Returns
        -------
        DutyCycle
            Times [s] and speeds [rad/s].

        Raises
        ------
        InputError
            A value out of range, fewer than two or more than :data:`MAX_SAMPLES`
            samples (refused before anything is allocated), a frequency the samples
            cannot represent, or a cycle whose samples are all at rest.
        """
        where = "duty_cycle"
        peak = check_peak_speed(peak_speed_rpm, where)
        f = check_positive("frequency_hz", frequency_hz, where)
        dur = check_positive("duration_s", duration_s, where)
        dt = check_positive("sample_interval_s", sample_interval_s, where)
        ratio = dur / dt
        if not ratio <= MAX_SAMPLES:  # also inf: checked before anything is allocated
            raise InputError("duration_s", duration_s, f"with sample_interval_s = {dt:g} s "
                             f"this is {ratio:.3g} samples; at most {MAX_SAMPLES:.0e} "
                             f"({SAMPLES_REASON})", where)
        n = int(round(ratio))
        if n < 2:
            raise InputError("duration_s", duration_s,
                             f"must hold at least 2 samples of {dt:g} s", where)
        if not 2.0 * f * dt < 1.0:
            raise InputError("frequency_hz", frequency_hz, f"must be below 1/(2 "
                             f"sample_interval_s) = {0.5 / dt:g} Hz: samples every {dt:g} s "
                             "cannot represent a faster sine (Nyquist)", where)
        t = np.arange(n) * dt
        w = rpm_to_rad_s(peak) * np.sin(2.0 * np.pi * f * t)
        _refuse_at_rest(w, "frequency_hz", f, where)
        return cls(t, w, f"{peak:g} rpm * sin(2 pi {f:g} Hz t), {n} samples every {dt:g} s",
                   {"kind": "sine", "peak_speed_rpm": peak, "frequency_hz": f,
                    "duration_s": dur, "sample_interval_s": dt})

    @classmethod
    def from_csv(cls, path: str | Path) -> DutyCycle:
        """Read a ``time_s,speed_rpm`` CSV (time strictly increasing, all values finite).

        Parameters
        ----------
        path : str or Path
            UTF-8 CSV with columns ``time_s`` [s] and ``speed_rpm`` [rpm] (signed,
            |speed| <= :data:`MAX_SPEED_RPM`), 2 to :data:`MAX_SAMPLES` rows.

        Returns
        -------
        DutyCycle
            Times [s] and speeds [rad/s].

        Raises
        ------
        InputError
            A file that cannot be read (missing, a directory, unreadable, not UTF-8),
            missing columns, non-finite or out-of-range values, time not strictly
            increasing, fewer than two or more than :data:`MAX_SAMPLES` rows, or every
            speed 0. No message repeats the file's content but a bad cell.
        """
        path = Path(path)
        where = str(path)
        text = read_input_text(path, "duty_cycle.csv", "CSV file")
        reader = csv.DictReader(io.StringIO(text, newline=""))
        cols = [c.strip() for c in (reader.fieldnames or [])]
        err = header_error(path, cols, ("time_s", "speed_rpm"))
        if err is not None:
            raise err
        reader.fieldnames = cols
        t, s = [], []
        for i, row in enumerate(reader, start=2):
            if len(t) >= MAX_SAMPLES:
                raise InputError("rows", f"more than {MAX_SAMPLES:.0e}", f"at most "
                                 f"{MAX_SAMPLES:.0e} samples ({SAMPLES_REASON})", where)
            rw = f"{where} line {i}"
            t.append(check_finite("time_s", cell_for_message(row["time_s"]), rw))
            s.append(check_physical("speed_rpm", cell_for_message(row["speed_rpm"]),
                                    -MAX_SPEED_RPM, MAX_SPEED_RPM, SPEED_REASON, rw))
        if len(t) < 2:
            raise InputError("rows", len(t), "a duty cycle needs at least 2 samples", where)
        t_arr = np.asarray(t)
        bad = np.nonzero(np.diff(t_arr) <= 0)[0]
        if bad.size:
            i = int(bad[0]) + 1
            raise InputError("time_s", t[i], f"must increase strictly (line {i + 2} follows "
                             f"{t[i - 1]:g})", where)
        w = rpm_to_rad_s(np.asarray(s))
        _refuse_at_rest(w, "speed_rpm", 0.0, where)
        return cls(t_arr, w, f"{path.name}, {len(t)} samples", {"kind": "csv", "csv": str(path)})

    def with_peak_speed(self, peak_speed_rpm: float) -> DutyCycle:
        """The same cycle with every speed scaled so that its peak is ``peak_speed_rpm``.

        Parameters
        ----------
        peak_speed_rpm : float
            New peak |speed| [rpm], in (0, :data:`MAX_SPEED_RPM`].

        Returns
        -------
        DutyCycle
            Times unchanged [s], speeds times ``peak / old peak`` [rad/s]; its ``spec``
            records the new peak.
        """
        peak = check_peak_speed(peak_speed_rpm)
        factor = self.speed_factor(peak)
        spec = dict(self.spec, peak_speed_rpm=peak)
        return DutyCycle(self.time_s, self.omega_rad_s * factor,
                         f"{self.description} (peak scaled to {peak:g} rpm)", spec)

    def speed_factor(self, peak_speed_rpm):
        """The factor on every speed that makes the cycle's peak ``peak_speed_rpm``.

        Parameters
        ----------
        peak_speed_rpm : float or array
            New peak |speed| [rpm].

        Returns
        -------
        float or array
            ``peak / old peak`` [-] (:meth:`with_peak_speed` scales by it).
        """
        return rpm_to_rad_s(peak_speed_rpm) / self.peak_omega_rad_s

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
        cached = self.cache.get("speed_distribution")
        if cached is not None:
            return cached
        a = np.abs(self.omega_rad_s)
        peak = a.max() if a.max() > 0 else 1.0
        keys = np.round(a / peak / NODE_MERGE_RTOL).astype(np.int64)
        _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
        weights = np.bincount(inverse, weights=self.sample_weights())
        dist = (a[first], weights)
        self.cache["speed_distribution"] = dist
        return dist


def _refuse_at_rest(omega_rad_s: np.ndarray, field: str, value: float, where: str) -> None:
    """Refuse a cycle whose every sample is at rest: it has no loss to average."""
    if not np.any(omega_rad_s != 0.0):
        raise InputError(field, value, "the speed is 0 at every sample: the joint never "
                         "turns, so there is no loss to evaluate", where)
