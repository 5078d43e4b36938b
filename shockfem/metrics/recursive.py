"""Second-order recursive (IIR) filters, compiled: what the CFC filter and the SRS oscillators need of
``scipy.signal`` (``lfilter`` of one section, ``sosfiltfilt`` of one section with odd padding), without
importing it: ``scipy.signal`` brings ``scipy.stats`` and costs every run 0.27 s of start-up for two
loops of five multiplications (``docs/performance.md``).

A section is ``b = (b0, b1, b2)``, ``a = (1, a1, a2)``, run in scipy's direct form II transposed:

    y_n = b0 x_n + z0,   z0 <- b1 x_n - a1 y_n + z1,   z1 <- b2 x_n - a2 y_n

``tests/unit/metrics/test_recursive.py`` checks both against scipy's to round-off.
"""
from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def _run_section(b0, b1, b2, a1, a2, x, z0, z1, out):
    for n in range(x.shape[0]):
        xn = x[n]
        yn = b0 * xn + z0
        z0 = b1 * xn - a1 * yn + z1
        z1 = b2 * xn - a2 * yn
        out[n] = yn


def _normalised(b, a) -> tuple[float, float, float, float, float]:
    b = np.asarray(b, dtype=float)
    a = np.asarray(a, dtype=float)
    if b.shape != (3,) or a.shape != (3,) or a[0] == 0.0:
        raise ValueError(f"one second-order section needs b and a of 3 coefficients with a[0] != 0, got {b}, {a}")
    return b[0] / a[0], b[1] / a[0], b[2] / a[0], a[1] / a[0], a[2] / a[0]


def lfilter(b, a, x: np.ndarray) -> np.ndarray:
    """``scipy.signal.lfilter(b, a, x)`` for one section, starting at rest."""
    x = np.ascontiguousarray(x, dtype=float)
    out = np.empty_like(x)
    _run_section(*_normalised(b, a), x, 0.0, 0.0, out)
    return out


def _steady_state(b0, b1, b2, a1, a2) -> tuple[float, float]:
    """The section's state for a unit input held forever (``scipy.signal.lfilter_zi``): (I - A^T) z = B
    with A the companion matrix of a, B = b[1:] - a[1:] b0, solved in closed form."""
    r0, r1 = b1 - a1 * b0, b2 - a2 * b0
    # [[1 + a1, -1], [a2, 1]] z = (r0, r1)
    det = 1.0 + a1 + a2
    z0 = (r0 + r1) / det
    return z0, r1 - a2 * z0


def filtfilt(b, a, x: np.ndarray, padlen: int) -> np.ndarray:
    """``scipy.signal.sosfiltfilt`` of one section with ``padtype="odd"``: the record extended at each end by
    ``padlen`` samples of its odd reflection, run forward from the steady state of its first sample, then
    backward from that of the forward run's last, and the extension cut off again."""
    x = np.asarray(x, dtype=float)
    coefficients = _normalised(b, a)
    zi0, zi1 = _steady_state(*coefficients)
    if padlen > 0:
        if padlen >= len(x):
            raise ValueError(f"padlen {padlen} must be less than the record's {len(x)} samples")
        ext = np.concatenate((2 * x[0] - x[padlen:0:-1], x, 2 * x[-1] - x[-2:-(padlen + 2):-1]))
    else:
        ext = np.ascontiguousarray(x)
    forward = np.empty_like(ext)
    _run_section(*coefficients, ext, zi0 * ext[0], zi1 * ext[0], forward)
    backward = np.empty_like(ext)
    reversed_forward = np.ascontiguousarray(forward[::-1])
    last = reversed_forward[0]
    _run_section(*coefficients, reversed_forward, zi0 * last, zi1 * last, backward)
    y = backward[::-1]
    return np.ascontiguousarray(y[padlen:len(y) - padlen] if padlen > 0 else y)
