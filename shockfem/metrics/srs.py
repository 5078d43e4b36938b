"""Shock response spectrum: the peak absolute acceleration of single-degree-of-freedom
oscillators on the measured base motion, against their natural frequency.

Each oscillator is the ramp-invariant recursive filter of Smallwood (1981), adopted by
ISO 18431-4: exact for a base acceleration that is linear between samples.  With
wn = 2 pi f, zeta = 1 / (2 Q), wd = wn sqrt(1 - zeta^2), E = exp(-zeta wn T), K = wd T,
C = E cos K, S = E sin K, S' = S / K:

    y_n = (1 - S') x_n + 2 (S' - C) x_{n-1} + (E^2 - S') x_{n-2} + 2 C y_{n-1} - E^2 y_{n-2}

The response is evaluated at ``samples_per_cycle`` points per natural period at least (the
record is refined by linear interpolation, which the ramp-invariant filter treats exactly,
so only the peak-finding grid changes), its extremes refined by a parabola through the
three samples about them, and continued past the end of the record for one
natural period with the base at rest, so residual peaks are caught (maximax spectrum).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


# Smallwood's and ISO 18431-4's advice: about 10 samples per cycle at the highest frequency.
SAMPLES_PER_CYCLE = 10


@dataclass
class Spectrum:
    frequency: np.ndarray      # [Hz]
    positive: np.ndarray       # largest positive response, same unit as the input
    negative: np.ndarray       # largest negative response (a positive number)
    q: float

    @property
    def maximax(self) -> np.ndarray:
        return np.maximum(self.positive, self.negative)


# the band of a pulse's spectrum unless the scene gives one: the default shock-test band, widened to
# take in the pulse's knee and high-frequency plateau (a pulse of duration T reaches the plateau, its
# peak acceleration, by about 10 / T: a 20 us pulse's knee is near 40 kHz) and, for long pulses, its
# low-frequency slope 2 pi f dv (below about 0.05 / T)
DEFAULT_BAND = (10.0, 10000.0)      # [Hz]
PLATEAU_CYCLES = 10.0
SLOPE_CYCLES = 0.05


def pulse_band(duration: float, dt: float) -> tuple[float, float]:
    """The SRS band [Hz] for a pulse of ``duration`` [s] in a record sampled every ``dt`` [s]: the
    default band, reaching up to 10 / duration (never past the record's Nyquist frequency) and down to
    0.05 / duration."""
    high = max(DEFAULT_BAND[1], min(PLATEAU_CYCLES / duration, 0.5 / dt))
    low = min(DEFAULT_BAND[0], SLOPE_CYCLES / duration)
    return low, high


def log_frequencies(f_low: float, f_high: float, per_octave: int = 12) -> np.ndarray:
    """A logarithmic grid from ``f_low`` to ``f_high`` [Hz] with ``per_octave`` points per octave."""
    n = int(math.ceil(per_octave * math.log2(f_high / f_low))) + 1
    return f_low * 2.0 ** (np.arange(n) / per_octave)


def smallwood_coefficients(frequency: float, q: float, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """(b, a) of the absolute-acceleration oscillator; ``q = inf`` for no damping."""
    zeta = 0.0 if math.isinf(q) else 1.0 / (2.0 * q)
    wn = 2 * math.pi * frequency
    wd = wn * math.sqrt(1 - zeta * zeta)
    E = math.exp(-zeta * wn * dt)
    K = wd * dt
    C = E * math.cos(K)
    Sp = E * math.sin(K) / K
    return np.array([1 - Sp, 2 * (Sp - C), E * E - Sp]), np.array([1.0, -2 * C, E * E])


def oscillator_response(a: np.ndarray, dt: float, frequency: float, q: float,
                        samples_per_cycle: int = SAMPLES_PER_CYCLE) -> tuple[np.ndarray, float]:
    """Absolute acceleration of one oscillator over the record and one period after it,
    and the sample interval it is given on."""
    refine = max(1, int(math.ceil(samples_per_cycle * frequency * dt)))
    x = np.asarray(a, dtype=float)
    if refine > 1:
        fine = np.arange((len(x) - 1) * refine + 1) / refine
        x = np.interp(fine, np.arange(len(x)), x)
    h = dt / refine
    tail = int(math.ceil(1.0 / (frequency * h))) + 1
    x = np.concatenate([x, np.zeros(tail)])
    b, den = smallwood_coefficients(frequency, q, h)
    from scipy import signal      # here: 0.35-0.39 s of import (scipy.stats with it), for runs with a channel
    return signal.lfilter(b, den, x), h


def shock_response_spectrum(a: np.ndarray, dt: float, frequencies, q: float = 10.0,
                            samples_per_cycle: int = SAMPLES_PER_CYCLE) -> Spectrum:
    """Maximax absolute-acceleration SRS of a uniformly sampled base acceleration.

    Parameters
    ----------
    a : base acceleration samples (any unit; the spectrum has the same unit), interval dt [s]
    frequencies : natural frequencies [Hz]
    q : quality factor 1 / (2 zeta); 10 is the shock-test convention, ``math.inf`` undamped
    """
    f = np.asarray(frequencies, dtype=float)
    pos = np.zeros(len(f))
    neg = np.zeros(len(f))
    for i, fi in enumerate(f):
        y, _ = oscillator_response(a, dt, fi, q, samples_per_cycle)
        pos[i] = max(interpolated_peak(y), 0.0)
        neg[i] = max(interpolated_peak(-y), 0.0)
    return Spectrum(f, pos, neg, q)


def interpolated_peak(y: np.ndarray) -> float:
    """The largest value of a sampled oscillation, refined by the parabola through the largest
    sample and its neighbours: at 10 samples per cycle the largest sample of a sinusoid can be
    4.9% low (1 - cos(pi / 10)); the parabola brings that below 0.1%."""
    i = int(np.argmax(y))
    if 0 < i < len(y) - 1:
        y0, y1, y2 = y[i - 1], y[i], y[i + 1]
        curvature = y0 - 2 * y1 + y2
        if curvature < 0:
            return float(y1 - (y2 - y0) ** 2 / (8 * curvature))
    return float(y[i])
