"""Principal values and directions of a symmetric 3x3 tensor, for laws that act on principal stresses
(the crushable foam caps each principal stress at its crush stress).

Cyclic Jacobi rotations (Numerical Recipes, 2nd ed., section 11.1): each rotation zeroes one
off-diagonal entry; a sweep over the three converges quadratically, to round-off in 3-5 sweeps, and
repeated eigenvalues need no special case.  Written in scalars so that nothing is allocated per
point.  Tensors are 6-tuples (11, 22, 33, 23, 13, 12).
"""
from __future__ import annotations

import math

from numba import njit

_SWEEPS = 30


@njit(cache=True, fastmath=True, inline="always")
def _rotation(app, aqq, apq):
    """(c, s, t) of the Jacobi rotation that zeroes a_pq: t = tan of the angle, |angle| <= pi/4."""
    if abs(apq) <= 1e-18 * (abs(app) + abs(aqq)):
        return 1.0, 0.0, 0.0
    theta = (aqq - app) / (2.0 * apq)
    if theta >= 0.0:
        t = 1.0 / (theta + math.sqrt(theta * theta + 1.0))
    else:
        t = -1.0 / (-theta + math.sqrt(theta * theta + 1.0))
    c = 1.0 / math.sqrt(t * t + 1.0)
    return c, t * c, t


@njit(cache=True, fastmath=True, inline="always")
def _jacobi_step(app, aqq, apq, arp, arq, v0p, v0q, v1p, v1q, v2p, v2q):
    """One rotation in the (p, q) plane, r the third index: the new a_pp, a_qq, a_rp, a_rq (a_pq is
    then 0) and the new columns p and q of V (Numerical Recipes eq. 11.1.14-11.1.20)."""
    c, sn, t = _rotation(app, aqq, apq)
    return (app - t * apq, aqq + t * apq, c * arp - sn * arq, sn * arp + c * arq,
            c * v0p - sn * v0q, sn * v0p + c * v0q, c * v1p - sn * v1q, sn * v1p + c * v1q,
            c * v2p - sn * v2q, sn * v2p + c * v2q)


@njit(cache=True, fastmath=True)
def principal_stresses(s):
    """((l0, l1, l2), (v00, v01, v02, v10, v11, v12, v20, v21, v22)): the principal values of the
    symmetric ``s`` and the matrix V (row-major) whose column k is the unit direction of l_k."""
    a00, a11, a22, a12, a02, a01 = s
    v00, v01, v02 = 1.0, 0.0, 0.0
    v10, v11, v12 = 0.0, 1.0, 0.0
    v20, v21, v22 = 0.0, 0.0, 1.0
    size = a00 * a00 + a11 * a11 + a22 * a22 + 2.0 * (a01 * a01 + a02 * a02 + a12 * a12)
    for _ in range(_SWEEPS):
        if a01 * a01 + a02 * a02 + a12 * a12 <= 1e-30 * size:
            break
        # (p, q, r) = (0, 1, 2), (0, 2, 1), (1, 2, 0)
        a00, a11, a02, a12, v00, v01, v10, v11, v20, v21 = _jacobi_step(a00, a11, a01, a02, a12,
                                                                        v00, v01, v10, v11, v20, v21)
        a01 = 0.0
        a00, a22, a01, a12, v00, v02, v10, v12, v20, v22 = _jacobi_step(a00, a22, a02, a01, a12,
                                                                        v00, v02, v10, v12, v20, v22)
        a02 = 0.0
        a11, a22, a01, a02, v01, v02, v11, v12, v21, v22 = _jacobi_step(a11, a22, a12, a01, a02,
                                                                        v01, v02, v11, v12, v21, v22)
        a12 = 0.0
    return (a00, a11, a22), (v00, v01, v02, v10, v11, v12, v20, v21, v22)


@njit(cache=True, fastmath=True, inline="always")
def spectral_sum(k, v):
    """sum_k c_k n_k n_k^T as a 6-tuple, n_k the columns of ``v`` (from ``principal_stresses``)."""
    c0, c1, c2 = k
    v00, v01, v02, v10, v11, v12, v20, v21, v22 = v
    return (c0 * v00 * v00 + c1 * v01 * v01 + c2 * v02 * v02,
            c0 * v10 * v10 + c1 * v11 * v11 + c2 * v12 * v12,
            c0 * v20 * v20 + c1 * v21 * v21 + c2 * v22 * v22,
            c0 * v10 * v20 + c1 * v11 * v21 + c2 * v12 * v22,
            c0 * v00 * v20 + c1 * v01 * v21 + c2 * v02 * v22,
            c0 * v00 * v10 + c1 * v01 * v11 + c2 * v02 * v12)
