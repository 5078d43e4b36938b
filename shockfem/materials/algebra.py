"""Small dense algebra the compiled kernels share, unrolled into scalars (no arrays in the hot loop)."""
from __future__ import annotations

from numba import njit


@njit(cache=True, fastmath=True, inline="always")
def inverse_3x3(a00, a01, a02, a10, a11, a12, a20, a21, a22):
    """(det A, A^-1 row by row) of a 3x3 matrix given row by row, by cofactors."""
    c00 = a11 * a22 - a12 * a21
    c01 = a02 * a21 - a01 * a22
    c02 = a01 * a12 - a02 * a11
    det = a00 * c00 + a10 * c01 + a20 * c02
    idet = 1.0 / det
    return (det, c00 * idet, c01 * idet, c02 * idet,
            (a12 * a20 - a10 * a22) * idet, (a00 * a22 - a02 * a20) * idet, (a02 * a10 - a00 * a12) * idet,
            (a10 * a21 - a11 * a20) * idet, (a01 * a20 - a00 * a21) * idet, (a00 * a11 - a01 * a10) * idet)
