"""Nearly incompressible rubber: Mooney-Rivlin hyperelasticity with a volumetric penalty (LS-DYNA's
*MAT_MOONEY-RIVLIN_RUBBER, MAT_027; Neo-Hookean when C01 = 0), for rubber programmers.

A law of the total deformation: the point carries its deformation gradient F (as F - I, so that a
zero state is the undeformed one) and updates it with the step's velocity gradient L = d + W on
the mid-step configuration by the midpoint rule

    F_n+1 = (I - dt/2 L)^-1 (I + dt/2 L) F_n

(a rigid spin turns F by the same Cayley rotation as ``objective.py`` turns stresses, so rotation is
exact), then the stress is the hyperelastic one of F, whatever the stress was:

    W     = C10 (I1b - 3) + C01 (I2b - 3) + K/2 (J - 1)^2,    Bb = J^(-2/3) F F^T,  I1b = tr Bb
    sigma = (2 / J) dev[(C10 + C01 I1b) Bb - C01 Bb^2] + K (J - 1) I

(Holzapfel, *Nonlinear Solid Mechanics*, 2000, sec. 6.5).  The small-strain shear modulus is
mu = 2 (C10 + C01) and K the bulk modulus, so the row's Lame constants (lambda = K - 2 mu / 3) give
the stable step.  No work is dissipated: the strain energy is the internal energy of the balance.
"""
from __future__ import annotations

from numba import njit

from .algebra import inverse_3x3
from .layout import P_C01, P_LAMBDA, P_MU, S_DEFORMATION


@njit(cache=True, fastmath=True)
def rubber_update(row, point, d, w, dt):
    """The Mooney-Rivlin rubber over one step (module docstring): F updated in ``point`` in place;
    returns the Cauchy stress and no dissipated work."""
    d0, d1, d2, d3, d4, d5 = d
    # L = d + W, W from the spin (W23, W13, W12) = w
    l01, l10 = d5 + w[2], d5 - w[2]
    l02, l20 = d4 + w[1], d4 - w[1]
    l12, l21 = d3 + w[0], d3 - w[0]
    h = 0.5 * dt
    _, i00, i01, i02, i10, i11, i12, i20, i21, i22 = inverse_3x3(1.0 - h * d0, -h * l01, -h * l02, -h * l10,
                                                                 1.0 - h * d1, -h * l12, -h * l20, -h * l21,
                                                                 1.0 - h * d2)
    # M = (I - h L)^-1 (I + h L)
    b00, b01, b02, b10, b11, b12, b20, b21, b22 = (1.0 + h * d0, h * l01, h * l02, h * l10, 1.0 + h * d1, h * l12,
                                                   h * l20, h * l21, 1.0 + h * d2)
    m00 = i00 * b00 + i01 * b10 + i02 * b20
    m01 = i00 * b01 + i01 * b11 + i02 * b21
    m02 = i00 * b02 + i01 * b12 + i02 * b22
    m10 = i10 * b00 + i11 * b10 + i12 * b20
    m11 = i10 * b01 + i11 * b11 + i12 * b21
    m12 = i10 * b02 + i11 * b12 + i12 * b22
    m20 = i20 * b00 + i21 * b10 + i22 * b20
    m21 = i20 * b01 + i21 * b11 + i22 * b21
    m22 = i20 * b02 + i21 * b12 + i22 * b22
    k = S_DEFORMATION
    f00, f01, f02 = point[k] + 1.0, point[k + 1], point[k + 2]
    f10, f11, f12 = point[k + 3], point[k + 4] + 1.0, point[k + 5]
    f20, f21, f22 = point[k + 6], point[k + 7], point[k + 8] + 1.0
    g00 = m00 * f00 + m01 * f10 + m02 * f20
    g01 = m00 * f01 + m01 * f11 + m02 * f21
    g02 = m00 * f02 + m01 * f12 + m02 * f22
    g10 = m10 * f00 + m11 * f10 + m12 * f20
    g11 = m10 * f01 + m11 * f11 + m12 * f21
    g12 = m10 * f02 + m11 * f12 + m12 * f22
    g20 = m20 * f00 + m21 * f10 + m22 * f20
    g21 = m20 * f01 + m21 * f11 + m22 * f21
    g22 = m20 * f02 + m21 * f12 + m22 * f22
    (point[k], point[k + 1], point[k + 2], point[k + 3], point[k + 4], point[k + 5], point[k + 6], point[k + 7],
     point[k + 8]) = (g00 - 1.0, g01, g02, g10, g11 - 1.0, g12, g20, g21, g22 - 1.0)
    return mooney_rivlin_stress((g00, g01, g02, g10, g11, g12, g20, g21, g22), row), 0.0


@njit(cache=True, fastmath=True)
def mooney_rivlin_stress(F, row):
    """Cauchy stress (11, 22, 33, 23, 13, 12) of the deformation gradient F (row-major 9-tuple)."""
    f00, f01, f02, f10, f11, f12, f20, f21, f22 = F
    mu = row[P_MU]
    K = row[P_LAMBDA] + 2.0 * mu / 3.0
    c01 = row[P_C01]
    c10 = 0.5 * mu - c01
    J = f00 * (f11 * f22 - f12 * f21) - f01 * (f10 * f22 - f12 * f20) + f02 * (f10 * f21 - f11 * f20)
    s = J ** (-2.0 / 3.0)
    # Bb = J^(-2/3) F F^T (symmetric)
    b00 = s * (f00 * f00 + f01 * f01 + f02 * f02)
    b11 = s * (f10 * f10 + f11 * f11 + f12 * f12)
    b22 = s * (f20 * f20 + f21 * f21 + f22 * f22)
    b12 = s * (f10 * f20 + f11 * f21 + f12 * f22)
    b02 = s * (f00 * f20 + f01 * f21 + f02 * f22)
    b01 = s * (f00 * f10 + f01 * f11 + f02 * f12)
    i1 = b00 + b11 + b22
    a = c10 + c01 * i1
    # T = a Bb - C01 Bb^2
    t00 = a * b00 - c01 * (b00 * b00 + b01 * b01 + b02 * b02)
    t11 = a * b11 - c01 * (b01 * b01 + b11 * b11 + b12 * b12)
    t22 = a * b22 - c01 * (b02 * b02 + b12 * b12 + b22 * b22)
    t12 = a * b12 - c01 * (b01 * b02 + b11 * b12 + b12 * b22)
    t02 = a * b02 - c01 * (b00 * b02 + b01 * b12 + b02 * b22)
    t01 = a * b01 - c01 * (b00 * b01 + b01 * b11 + b02 * b12)
    mean = (t00 + t11 + t22) / 3.0
    p = K * (J - 1.0)
    k = 2.0 / J
    return (k * (t00 - mean) + p, k * (t11 - mean) + p, k * (t22 - mean) + p, k * t12, k * t02, k * t01)


def pack_rubber(row, curve, rubber) -> None:
    """Write a material's ``rubber`` (the scene's ``Rubber``: c01) into its parameter ``row`` (mu and
    lambda, the shared columns, hold 2 (C10 + C01) and K - 2 mu / 3)."""
    row[P_C01] = rubber.c01
