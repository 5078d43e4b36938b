"""Channel frequency class (CFC) filters of SAE J211-1 / ISO 6487.

A CFC filter is a two-pole Butterworth low pass run forward and then backward over the
record, so it has no phase shift and its gain is the square of one pass.  SAE J211-1
(Appendix C) gives the digital form: with T the sample interval,

    wd = 2 pi CFC 2.0775,   wa = tan(wd T / 2)
    a0 = wa^2 / (1 + sqrt(2) wa + wa^2),  a1 = 2 a0,  a2 = a0
    b1 = -2 (wa^2 - 1) / (1 + sqrt(2) wa + wa^2)
    b2 = (-1 + sqrt(2) wa - wa^2) / (1 + sqrt(2) wa + wa^2)
    y_n = a0 x_n + a1 x_{n-1} + a2 x_{n-2} + b1 y_{n-1} + b2 y_{n-2}

The factor 2.0775 places the -3 dB point of the two passes together at about 1.65 CFC
(100, 300, 1000 and 1650 Hz for CFC 60, 180, 600 and 1000).
"""
from __future__ import annotations

import math

import numpy as np


# J211-1 asks for a sample rate of at least 10 times the class frequency (CFC 1000: 10 kHz).
MIN_SAMPLES_PER_CFC = 10


def cfc_coefficients(cfc: float, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """(b, a) of one pass of the CFC filter in scipy's convention (a[0] = 1)."""
    wd = 2 * math.pi * cfc * 2.0775
    wa = math.tan(wd * dt / 2)
    den = 1 + math.sqrt(2) * wa + wa * wa
    a0 = wa * wa / den
    b1 = -2 * (wa * wa - 1) / den
    b2 = (-1 + math.sqrt(2) * wa - wa * wa) / den
    return np.array([a0, 2 * a0, a0]), np.array([1.0, -b1, -b2])


def above_nyquist(cfc: float, dt: float) -> bool:
    """True when the filter cannot be built at this sample interval: its prewarped cutoff
    wd T / 2 reaches pi / 2."""
    return cfc * 2.0775 * dt >= 0.5


def check_sampling(cfc: float, dt: float) -> str | None:
    """A warning when the sample rate is below what J211-1 asks for, else None."""
    if above_nyquist(cfc, dt):
        return f"CFC {cfc:g} is above the Nyquist frequency of a {1 / dt:.4g} Hz record"
    if 1.0 / dt < MIN_SAMPLES_PER_CFC * cfc:
        return (f"sample rate {1 / dt:.4g} Hz is below {MIN_SAMPLES_PER_CFC} x CFC {cfc:g}: "
                f"record the history more often (outputs.history_interval <= {1 / (MIN_SAMPLES_PER_CFC * cfc):.3g} s)")
    return None


def cfc_filter(a: np.ndarray, dt: float, cfc: float) -> np.ndarray:
    """Filter a uniformly sampled history forward and backward with the CFC filter.

    The record is extended at both ends by its odd reflection for about three time constants
    of the filter, so a record that starts or ends in motion is not given a step.

    Parameters
    ----------
    a : samples (any unit), uniform interval ``dt`` [s]
    cfc : channel frequency class [Hz], e.g. 1000
    """
    a = np.asarray(a, dtype=float)
    if above_nyquist(cfc, dt):
        raise ValueError(check_sampling(cfc, dt))
    b, den = cfc_coefficients(cfc, dt)
    pad = min(len(a) - 1, int(math.ceil(3.0 / (2 * math.pi * cfc * 2.0775 * dt))))
    from scipy import signal      # here: 0.35-0.39 s of import (scipy.stats with it), for runs with a channel
    return signal.sosfiltfilt(signal.tf2sos(b, den), a, padtype="odd", padlen=max(pad, 0))


def gain_db(cfc: float, dt: float, frequency: float, periods: int = 40) -> float:
    """Gain [dB] of the forward-backward filter at ``frequency``, measured by filtering a
    sinusoid (the implemented code path, not the transfer function) and comparing the
    amplitude in the middle of the record."""
    n = int(periods / (frequency * dt))
    t = np.arange(n) * dt
    x = np.sin(2 * np.pi * frequency * t)
    y = cfc_filter(x, dt, cfc)
    mid = slice(n // 4, 3 * n // 4)
    return 20 * math.log10(np.sqrt(2 * np.mean(y[mid] ** 2)) / np.sqrt(2 * np.mean(x[mid] ** 2)))
