"""The viscous stresses added to a point's stress for the forces (never stored), and the stable
step they leave an element.

* Stiffness-proportional (Rayleigh) damping: sigma_v = beta C : d, beta [s] per material row.
* Artificial bulk viscosity (LS-DYNA's): a pressure q = rho l (Q1 l tr(d)^2 - Q2 c tr(d)) in
  compression only, which spreads a shock over a few elements instead of letting it ring
  (von Neumann & Richtmyer; Q1 the quadratic, Q2 the linear coefficient, defaults 1.5 and 0.06).
  It depends on the element's length l and dilatation rate, so the element kernel computes q once
  per cell (``bulk_viscosity``) and ``viscous_stress`` adds it at each point.
"""
from __future__ import annotations

import math

from numba import njit

from .elastic import hooke
from .layout import P_BETA, P_LAMBDA, P_MU


@njit(cache=True, fastmath=True, inline="always")
def bulk_viscosity(rho, c, length, trd, q1, q2):
    """The bulk viscosity pressure q [Pa] of an element of length ``length`` [m] and dilatation rate
    ``trd`` [1/s], wave speed ``c`` [m/s] (module docstring)."""
    if trd >= 0.0:
        return 0.0
    return rho * length * (q1 * length * trd * trd - q2 * c * trd)


@njit(cache=True, fastmath=True, inline="always")
def damped_step(dtc, beta):
    """The stable step dtc of an element shortened by stiffness-proportional damping beta:
    dt <= (2/w)(sqrt(1 + xi^2) - xi), xi = beta w / 2, w = 2 / dtc the element's highest
    frequency (Belytschko et al., eq. 6.2.28)."""
    if beta > 0.0:
        xi = beta / dtc
        dtc *= math.sqrt(1.0 + xi * xi) - xi
    return dtc


@njit(cache=True, fastmath=True, inline="always")
def viscous_step(step_length, c, length, trd, q1, q2, beta):
    """An element's stable step: step_length / c, shortened in compression by the bulk viscosity to
    step_length / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 l |tr(d)| (LS-DYNA), and by stiffness-
    proportional damping (``damped_step``)."""
    if trd < 0.0:
        Q = q2 * c - q1 * length * trd
        dtc = step_length / (Q + math.sqrt(Q * Q + c * c))
    else:
        dtc = step_length / c
    return damped_step(dtc, beta)


@njit(cache=True, fastmath=True)
def viscous_stress(params, m, s, d, q):
    """The stress the forces see: ``s`` + beta C : d - q I, with the power densities [W/m^3] of the
    damping (beta C : d) : d and of the bulk viscosity -q tr(d) (``viscous_stress_of`` with row ``m``'s
    constants)."""
    return viscous_stress_of(s, d, q, params[m, P_LAMBDA], params[m, P_MU], params[m, P_BETA])


@njit(cache=True, fastmath=True, inline="always")
def viscous_stress_of(s, d, q, lam, mu, beta):
    """``viscous_stress`` of a material with Lame constants ``lam``, ``mu`` and damping ``beta`` [s].

    Inlined (numba IR) so that the lanes of ``elements.one_point_quads`` compile it under their error model."""
    s0, s1, s2, s3, s4, s5 = s
    damping = 0.0
    if beta > 0.0:
        v0, v1, v2, v3, v4, v5 = hooke(d, lam, mu)
        v0, v1, v2, v3, v4, v5 = beta * v0, beta * v1, beta * v2, beta * v3, beta * v4, beta * v5
        damping = v0 * d[0] + v1 * d[1] + v2 * d[2] + 2.0 * (v3 * d[3] + v4 * d[4] + v5 * d[5])
        s0, s1, s2, s3, s4, s5 = s0 + v0, s1 + v1, s2 + v2, s3 + v3, s4 + v4, s5 + v5
    viscosity = 0.0
    if q > 0.0:
        viscosity = -q * (d[0] + d[1] + d[2])
        s0, s1, s2 = s0 - q, s1 - q, s2 - q
    return (s0, s1, s2, s3, s4, s5), damping, viscosity
