"""Classical shock pulses: ideal shapes, which one a measured pulse is, and the tolerance band.

The three classical pulses of MIL-STD-810 Method 516 (and IEC 60068-2-27) for a peak P and a
nominal duration D starting at t0:

* half-sine: P sin(pi (t - t0) / D)
* terminal-peak sawtooth: rising linearly to P at t0 + D, then dropping to zero
* trapezoid: a linear rise, a flat top at P and a linear fall, D from foot to foot

A measured pulse is compared with each shape *fitted to it* (``fit``): the ideal's feet are
placed so that it crosses 10% of its peak where the measured pulse does, and its peak gives
the measured velocity change (area), so ringing on top of a pulse does not set its level.
The shape with the smallest RMS misfit names the pulse.

The tolerance band (``TOLERANCE``) follows the classical-pulse figures of MIL-STD-810
Method 516 as read for this project: the ideal pulse +/- 20% of P while it lasts, |a| <= 20%
of P in the monitoring window before and after it, and the velocity change within 10% of
the ideal's.  Steep edges are given a time slack of 5% of D (the ideal's extremes over
+/- 0.05 D), so a pulse is not failed for a sample that falls just beside a vertical drop.
The numbers sit in one table so a programme that tailors them changes one line.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..scene.specs import PULSE_SHAPES as SHAPES   # the shapes a scene's [shock.spec] may name
from .pulse import Pulse, integral

TOLERANCE = {
    "amplitude": 0.20,         # band half-width over the pulse, fraction of P
    "outside": 0.20,           # |a| limit before and after the pulse, fraction of P
    "before": 0.4,             # monitoring window before the pulse, fraction of D
    "after": 1.5,              # monitoring window after the pulse, fraction of D
    "time_slack": 0.05,        # fraction of D
    "velocity_change": 0.10,   # fraction of the ideal's velocity change
}
# A trapezoid has a flat top over at least half its duration (the MIL-STD-810 trapezoid has
# ramps of 10% of D); with less it is a triangle, and a sawtooth or a half-sine fits it better.
TRAPEZOID_MIN_TOP = 0.5
# A fitted shape whose RMS misfit exceeds this fraction of the peak is not called classical.
CLASSICAL_MISFIT = 0.15


@dataclass(frozen=True)
class IdealPulse:
    """An ideal classical pulse of magnitude ``peak`` (positive; the caller applies polarity)."""
    shape: str
    peak: float           # [m/s^2]
    duration: float       # D, foot to foot [s]
    start: float          # t0 [s]
    rise: float = 0.0     # trapezoid ramp up [s]
    fall: float = 0.0     # trapezoid ramp down; sawtooth drop after t0 + D [s]

    def __call__(self, t) -> np.ndarray:
        s = (np.asarray(t, dtype=float) - self.start)
        D, P = self.duration, self.peak
        out = np.zeros_like(s)
        if self.shape == "half-sine":
            on = (s >= 0) & (s <= D)
            out[on] = P * np.sin(np.pi * s[on] / D)
        elif self.shape == "terminal-peak sawtooth":
            on = (s >= 0) & (s <= D)
            out[on] = P * s[on] / D
            if self.fall > 0:
                drop = (s > D) & (s < D + self.fall)
                out[drop] = P * (1 - (s[drop] - D) / self.fall)
        elif self.shape == "trapezoid":
            r, f = max(self.rise, 1e-300), max(self.fall, 1e-300)
            out = P * np.clip(np.minimum(s / r, (D - s) / f), 0.0, 1.0)
        else:
            raise ValueError(f"unknown pulse shape {self.shape!r} (known: {', '.join(SHAPES)})")
        return out

    @property
    def velocity_change(self) -> float:
        """Area under the ideal pulse [m/s] (a magnitude)."""
        P, D = self.peak, self.duration
        if self.shape == "half-sine":
            return 2 * P * D / math.pi
        if self.shape == "terminal-peak sawtooth":
            return P * (D + self.fall) / 2
        return P * (D - (self.rise + self.fall) / 2)

    @property
    def end(self) -> float:
        return self.start + self.duration + (self.fall if self.shape == "terminal-peak sawtooth" else 0.0)

    def as_dict(self) -> dict:
        return {"shape": self.shape, "peak": self.peak, "duration": self.duration, "start": self.start,
                "rise": self.rise, "fall": self.fall, "velocity_change": self.velocity_change}


def specified(shape: str, peak: float, duration: float, start: float = 0.0) -> IdealPulse:
    """A specified test pulse; a trapezoid gets ramps of 10% of D each, a sawtooth an ideal drop."""
    ramp = 0.1 * duration if shape == "trapezoid" else 0.0
    return IdealPulse(shape, peak, duration, start, ramp, ramp)


def _centroid(t: np.ndarray, y: np.ndarray, t0: float, t1: float) -> float:
    area = integral(t, y, t0, t1)
    return integral(t, y * t, t0, t1) / area if area else 0.5 * (t0 + t1)


def place(ideal: IdealPulse, t: np.ndarray, y: np.ndarray, pulse: Pulse) -> IdealPulse:
    """``ideal`` (a specified pulse) moved onto a measured pulse: a half-sine centred on the
    pulse's centroid, a sawtooth's peak on the time of peak, a trapezoid's 10% up-crossing on
    the measured one."""
    if ideal.shape == "half-sine":
        start = _centroid(t, y, pulse.zero_start, pulse.zero_end) - ideal.duration / 2
    elif ideal.shape == "terminal-peak sawtooth":
        start = pulse.time_of_peak - ideal.duration
    else:
        start = pulse.start - 0.1 * ideal.rise
    return IdealPulse(ideal.shape, ideal.peak, ideal.duration, start, ideal.rise, ideal.fall)


# Where an ideal half-sine crosses 10% of its peak, as a fraction of D from either end.
_HALF_SINE_10 = math.asin(0.1) / math.pi


def fit(shape: str, pulse: Pulse) -> IdealPulse | None:
    """The ideal ``shape`` fitted to a measured pulse: its feet from the measured 10% crossings,
    its peak from the measured velocity change (area), so ringing on top of the pulse does not
    set the level.  None where the shape cannot have the measured edges (a trapezoid whose
    ramps leave less than ``TRAPEZOID_MIN_TOP`` of its duration flat)."""
    dv = abs(pulse.velocity_change)
    if shape == "half-sine":
        D = pulse.duration / (1 - 2 * _HALF_SINE_10)
        return IdealPulse(shape, math.pi * dv / (2 * D), D, pulse.start - _HALF_SINE_10 * D)
    if shape == "terminal-peak sawtooth":
        D = (pulse.end - pulse.start) / 0.9          # 10% of a linear rise is 0.1 D after its foot
        return IdealPulse(shape, 2 * dv / D, D, pulse.end - D)
    rise = pulse.rise_time / (1 - 2 * 0.1)           # 10-90% stretched to 0-100% of a linear ramp
    fall = pulse.fall_time / (1 - 2 * 0.1)
    start, end = pulse.start - 0.1 * rise, pulse.end + 0.1 * fall
    D = end - start
    if D - rise - fall < TRAPEZOID_MIN_TOP * D:
        return None
    return IdealPulse(shape, dv / (D - (rise + fall) / 2), D, start, rise, fall)


def misfit(t: np.ndarray, y: np.ndarray, ideal: IdealPulse) -> float:
    """RMS of (measured - ideal) over the ideal pulse and 20% of its duration either side,
    as a fraction of the ideal's peak."""
    span = ideal.end - ideal.start
    on = (t >= ideal.start - 0.2 * span) & (t <= ideal.end + 0.2 * span)
    return float(np.sqrt(np.mean((y[on] - ideal(t[on])) ** 2)) / ideal.peak)


@dataclass
class Classification:
    shape: str                      # the best-fitting shape, or "irregular"
    ideal: IdealPulse | None        # that shape fitted to the pulse
    misfits: dict[str, float]       # RMS misfit of every shape, fraction of peak


def classify(t: np.ndarray, a: np.ndarray, pulse: Pulse) -> Classification:
    y = pulse.sign * np.asarray(a, dtype=float)
    fits = {s: fit(s, pulse) for s in SHAPES}
    misfits = {s: misfit(t, y, f) for s, f in fits.items() if f is not None}
    best = min(misfits, key=misfits.get)
    shape = best if misfits[best] <= CLASSICAL_MISFIT else "irregular"
    return Classification(shape, fits[best], misfits)


def tolerance_band(ideal: IdealPulse, t: np.ndarray, margin: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lower, upper, monitored) limits of the band at times ``t`` (magnitudes, polarity of the
    ideal); ``monitored`` marks the samples inside the monitoring window.  ``margin`` (a fraction of
    P) narrows the band on both sides: a designer's margin, 0 for the standard's band."""
    P, D = ideal.peak, ideal.duration
    slack = TOLERANCE["time_slack"] * D
    shifted = np.stack([ideal(t + s) for s in np.linspace(-slack, slack, 11)])
    lo, hi = shifted.min(axis=0), shifted.max(axis=0)
    on = (t >= ideal.start - slack) & (t <= ideal.end + slack)
    width = TOLERANCE["amplitude"] - margin
    lower = np.where(on, lo - width * P, -(TOLERANCE["outside"] - margin) * P)
    upper = np.where(on, hi + width * P, (TOLERANCE["outside"] - margin) * P)
    monitored = (t >= ideal.start - TOLERANCE["before"] * D) & (t <= ideal.end + TOLERANCE["after"] * D)
    return lower, upper, monitored


@dataclass
class BandCheck:
    passed: bool
    worst_excess: float             # largest excursion outside the band, fraction of P (0: inside)
    time_of_worst: float            # [s]
    worst_deviation: float          # largest |measured - ideal| in the window, fraction of P
    velocity_change_error: float    # (measured - ideal) / ideal over the monitoring window
    window_complete: bool           # the record covers the whole monitoring window

    def as_dict(self) -> dict:
        return dict(self.__dict__)


def band_check(t: np.ndarray, y: np.ndarray, ideal: IdealPulse, margin: float = 0.0) -> BandCheck:
    """Check a measured pulse ``y`` (polarity applied, [m/s^2]) against the tolerance band, narrowed by
    ``margin`` of the peak on each side (and the velocity change's tolerance by as much)."""
    lower, upper, monitored = tolerance_band(ideal, t, margin)
    P, D = ideal.peak, ideal.duration
    t_on, y_on = t[monitored], y[monitored]
    excess = np.maximum(y_on - upper[monitored], lower[monitored] - y_on) / P
    worst = int(np.argmax(excess)) if len(excess) else 0
    deviation = np.abs(y_on - ideal(t_on)) / P
    t0 = max(ideal.start - TOLERANCE["before"] * D, float(t[0]))
    t1 = min(ideal.end + TOLERANCE["after"] * D, float(t[-1]))
    dv_error = (integral(t, y, t0, t1) - ideal.velocity_change) / ideal.velocity_change
    complete = t[0] <= ideal.start - TOLERANCE["before"] * D and t[-1] >= ideal.end + TOLERANCE["after"] * D
    worst_excess = max(float(excess[worst]), 0.0) if len(excess) else 0.0
    passed = worst_excess == 0.0 and abs(dv_error) <= TOLERANCE["velocity_change"] - margin
    return BandCheck(passed, worst_excess, float(t_on[worst]) if len(t_on) else float("nan"),
                     float(deviation.max()) if len(deviation) else float("nan"), float(dv_error), bool(complete))
