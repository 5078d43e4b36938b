"""The objective stress rate: stresses turn with the material over a step (Hughes & Winget 1980).

With the spin W = (L - L^T)/2 of the step, the stress at t_n is first rotated by

    Q = (I - A)^-1 (I + A),   A = dt W / 2        (the Cayley transform of dt W)

and then the law adds its increment in that frame.  Q is orthogonal for any step, so a rotated
stress keeps its invariants exactly, and because the element kernels take the velocity gradient on
the mid-step configuration the spin of a rigid rotation is exactly skew: a spinning body keeps zero
stress (Hughes & Winget, IJNME 15:1862).  Symmetric tensors are 6-tuples (11, 22, 33, 23, 13, 12);
the spin is (W23, W13, W12).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from .layout import S_BACK


@njit(cache=True, fastmath=True, inline="always")
def cayley_matrix(w23, w13, w12, dt):
    """Q = (I - A)^-1 (I + A), A = dt W / 2, as 9 numbers (row-major).

    Closed form Q = I + 2/(1 + a.a) (A + A^2), a the axial vector of A.
    """
    a1 = 0.5 * dt * w23
    a2 = 0.5 * dt * w13
    a3 = 0.5 * dt * w12
    # A = [[0, a3, a2], [-a3, 0, a1], [-a2, -a1, 0]] (W_ij = (L_ij - L_ji)/2); A^2 written out.
    k = 2.0 / (1.0 + a1 * a1 + a2 * a2 + a3 * a3)
    return (1.0 + k * (-a3 * a3 - a2 * a2), k * (a3 - a2 * a1), k * (a2 + a3 * a1),
            k * (-a3 - a1 * a2), 1.0 + k * (-a3 * a3 - a1 * a1), k * (a1 - a3 * a2),
            k * (-a2 + a1 * a3), k * (-a1 - a2 * a3), 1.0 + k * (-a2 * a2 - a1 * a1))


@njit(cache=True, fastmath=True, inline="always")
def rotate_symmetric(s, q):
    """Q S Q^T for a symmetric S given and returned as (11, 22, 33, 23, 13, 12); q from ``cayley_matrix``."""
    s00, s11, s22, s12, s02, s01 = s
    q00, q01, q02, q10, q11, q12, q20, q21, q22 = q
    t00 = q00 * s00 + q01 * s01 + q02 * s02      # T = Q S
    t01 = q00 * s01 + q01 * s11 + q02 * s12
    t02 = q00 * s02 + q01 * s12 + q02 * s22
    t10 = q10 * s00 + q11 * s01 + q12 * s02
    t11 = q10 * s01 + q11 * s11 + q12 * s12
    t12 = q10 * s02 + q11 * s12 + q12 * s22
    t20 = q20 * s00 + q21 * s01 + q22 * s02
    t21 = q20 * s01 + q21 * s11 + q22 * s12
    t22 = q20 * s02 + q21 * s12 + q22 * s22
    return (t00 * q00 + t01 * q01 + t02 * q02, t10 * q10 + t11 * q11 + t12 * q12,
            t20 * q20 + t21 * q21 + t22 * q22, t10 * q20 + t11 * q21 + t12 * q22,
            t00 * q20 + t01 * q21 + t02 * q22, t00 * q10 + t01 * q11 + t02 * q12)


@njit(cache=True, fastmath=True)
def rotate_back_stress(state, c, p, q):
    """Kinematic hardening's back stress (state columns ``S_BACK``..+5) turns with the material like the stress."""
    b = S_BACK
    (state[c, p, b], state[c, p, b + 1], state[c, p, b + 2], state[c, p, b + 3], state[c, p, b + 4],
     state[c, p, b + 5]) = rotate_symmetric((state[c, p, b], state[c, p, b + 1], state[c, p, b + 2],
                                             state[c, p, b + 3], state[c, p, b + 4], state[c, p, b + 5]), q)


def rotation_of_angular_velocity(omega, dt: float):
    """The 3x3 rotation (numpy) a body spinning at angular velocity ``omega`` [rad/s] turns through over
    ``dt``: the same Cayley transform, with the spin W = skew(omega) (W12 = -omega_3, W13 = omega_2,
    W23 = -omega_1), i.e. a turn by 2 atan(|omega| dt / 2) about omega.  Rigid bodies use it."""
    return np.array(cayley_matrix(-float(omega[0]), float(omega[1]), -float(omega[2]), dt)).reshape(3, 3)
