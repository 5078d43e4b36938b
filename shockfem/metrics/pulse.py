"""The main pulse of an acceleration history: peak, timing, velocity change.

Definitions (the ones shock-test reports use):

* polarity: the sign of the largest |a|; the metrics below are for that sign
* peak and time of peak
* duration: the time the pulse stays above 10% of the peak, from the last up-crossing of
  10% before the peak to the first down-crossing after it (linear interpolation between samples)
* rise time: from the 10% up-crossing to the first 90% crossing after it (fall time: from
  the last 90% crossing to the 10% down-crossing)
* velocity change: the integral of the acceleration between the zero crossings that bound
  the pulse (the whole pulse, not only its part above 10%)
* mean acceleration: the integral over the 10% duration divided by the duration
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from .signals import crossing_time

LOW_FRACTION = 0.10     # duration threshold and rise-time start
HIGH_FRACTION = 0.90    # rise-time end


@dataclass
class Pulse:
    sign: float                # +1 or -1: polarity of the main pulse
    peak: float                # [m/s^2] (a magnitude)
    time_of_peak: float        # [s]
    start: float               # 10% up-crossing [s]
    end: float                 # 10% down-crossing [s]
    rise_time: float           # 10% -> 90% before the peak [s]
    fall_time: float           # 90% -> 10% after the peak [s]
    zero_start: float          # zero crossings bounding the pulse [s]
    zero_end: float
    velocity_change: float     # signed, over the zero-bounded pulse [m/s]
    mean_acceleration: float   # over the 10% duration, magnitude [m/s^2]

    @property
    def duration(self) -> float:
        return self.end - self.start

    def as_dict(self) -> dict:
        return {**asdict(self), "duration": self.duration}


def integral(t: np.ndarray, a: np.ndarray, t0: float, t1: float) -> float:
    """Trapezoidal integral of the piecewise-linear a(t) from t0 to t1."""
    inside = (t > t0) & (t < t1)
    ts = np.concatenate([[t0], t[inside], [t1]])
    return float(np.trapz(np.interp(ts, t, a), ts))


def _walk(y: np.ndarray, i: int, step: int, level: float) -> int:
    """From index i, the last index (walking by ``step``) at which y is still >= level."""
    n = len(y)
    while 0 <= i + step < n and y[i + step] >= level:
        i += step
    return i


def pulse_metrics(t: np.ndarray, a: np.ndarray) -> Pulse:
    """Metrics of the main pulse of ``a(t)`` (uniform or not; [s], [m/s^2])."""
    t = np.asarray(t, dtype=float)
    a = np.asarray(a, dtype=float)
    if len(t) < 3 or not np.any(a):
        raise ValueError("no pulse: the acceleration is zero (or the record has fewer than 3 samples)")
    k = int(np.argmax(np.abs(a)))
    sign = 1.0 if a[k] > 0 else -1.0
    y = sign * a
    peak = float(y[k])

    def up(level: float) -> float:
        i = _walk(y, k, -1, level)
        return float(t[0]) if i == 0 else crossing_time(t, y, i - 1, level)

    def down(level: float) -> float:
        i = _walk(y, k, +1, level)
        return float(t[-1]) if i == len(y) - 1 else crossing_time(t, y, i, level)

    low, high = LOW_FRACTION * peak, HIGH_FRACTION * peak
    i_start, i_end = _walk(y, k, -1, low), _walk(y, k, +1, low)
    start, end = up(low), down(low)
    z0, z1 = up(1e-9 * peak), down(1e-9 * peak)     # just above zero: flat zeros are not the pulse
    # the first 90% crossing after the start and the last before the end: ringing on a
    # plateau does not move them
    i90 = i_start + int(np.argmax(y[i_start:k + 1] >= high))
    rise = (crossing_time(t, y, i90 - 1, high) if i90 > i_start else float(t[i90])) - start
    j90 = i_end - int(np.argmax(y[k:i_end + 1][::-1] >= high))
    fall = end - (crossing_time(t, y, j90, high) if j90 < i_end else float(t[j90]))
    dv = integral(t, a, z0, z1)
    mean = abs(integral(t, a, start, end)) / (end - start) if end > start else peak
    return Pulse(sign, peak, float(t[k]), start, end, rise, fall, z0, z1, dv, mean)
