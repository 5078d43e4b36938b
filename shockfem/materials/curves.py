"""The two scalar functions the laws read their hardening from: a piecewise-linear table and the
Cowper-Symonds rate factor (J2's flow stress, the crushable foam's crush stress)."""
from __future__ import annotations

from numba import njit


@njit(cache=True, fastmath=True, inline="always")
def piecewise_linear(curve, npts, x):
    """y(x) and its slope on a piecewise-linear curve (x_k, y_k), k < npts, extended beyond either
    end with the end segment's slope (flat for a single point)."""
    if npts == 1:
        return curve[0, 1], 0.0
    k = 0
    while k < npts - 2 and x > curve[k + 1, 0]:
        k += 1
    slope = (curve[k + 1, 1] - curve[k, 1]) / (curve[k + 1, 0] - curve[k, 0])
    return curve[k, 1] + slope * (x - curve[k, 0]), slope


@njit(cache=True, fastmath=True, inline="always")
def rate_factor(rate, D, q):
    """Cowper-Symonds 1 + (rate / D)^(1/q); 1 when D = 0 (rate independent)."""
    if D <= 0.0 or rate <= 0.0:
        return 1.0
    return 1.0 + (rate / D) ** (1.0 / q)
