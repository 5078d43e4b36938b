"""J2 (von Mises) plasticity with radial return, mixed hardening and Cowper-Symonds rate effects.

The law ``J2`` of ``laws.py``: after the objective rotation (``objective.py``, done by
``update.update_stress`` for every law) the elastic trial step, then the return:

    sigma_trial = Q sigma_n Q^T + dt C : d          (objective.py, elastic.py)
    xi_trial    = dev(sigma_trial) - alpha_n        alpha: back stress (kinematic hardening)
    q_trial     = sqrt(3/2 xi_trial : xi_trial)

If q_trial exceeds the current yield stress the point flows along n = xi_trial / q_trial by
an equivalent plastic strain increment de solving the scalar consistency condition

    q_trial - (3 mu + H_k) de = R(rate) sigma_iso(eps_p + de)

(Simo & Hughes, *Computational Inelasticity*, Box 3.2, with the rate factor added), then

    sigma = sigma_trial - 3 mu de n,    alpha += H_k de n,    eps_p += de.

Hardening, as LS-DYNA's MAT_003 and MAT_024 define it:

* ``sigma_iso`` is a piecewise-linear curve of the plastic strain (MAT_024's table; extended
  with its last slope).  A bilinear material (yield sigma_0, tangent modulus E_t, MAT_003) is the
  two-point curve sigma_0 + beta H eps_p with the plastic modulus H = E E_t / (E - E_t);
* the kinematic modulus ``H_k = (1 - beta) H`` (MAT_003's beta: 1 isotropic, 0 kinematic).

Rate factor ``R = 1 + (rate / D)^(1/q)`` (Cowper-Symonds), in one of LS-DYNA's two forms:

* viscoplastic (VP = 1, the default): rate = de / dt, the plastic strain rate, so R is part of
  the consistency condition.  It is solved for z = (de / (dt D))^(1/q), in which the
  condition is smooth and concave (de = dt D z^q; the rate factor's infinite slope at zero
  plastic rate disappears), by Newton's method kept inside a bracket;
* yield scaling (VP = 0): rate = the total effective strain rate sqrt(2/3 d':d') of the step,
  so R is known before the return.

The state of a point (``layout.py``): equivalent plastic strain ``S_EPS``, plastic strain rate
``S_RATE`` and the back stress ``S_BACK``.. (6 components, order 11 22 33 23 13 12 like the stress).
"""
from __future__ import annotations

import math

from numba import njit

from .curves import piecewise_linear, rate_factor
from .elastic import elastic_update
from .layout import (P_CURVE_POINTS, P_KINEMATIC, P_MU, P_RATE_D, P_RATE_FORM, P_RATE_Q, S_BACK, S_EPS,
                     S_RATE, VISCOPLASTIC, YIELD_SCALING)

# the scene's names of the two rate forms (``rate_form``), LS-DYNA's VP = 1 and VP = 0
RATE_FORMS = {"plastic-strain-rate": VISCOPLASTIC, "total-strain-rate": YIELD_SCALING}

_NEWTON_ITERATIONS = 60
_TOLERANCE = 1e-12     # of the consistency residual, relative to q_trial


@njit(cache=True, fastmath=True, inline="always")
def _flow_increment(q_trial, eps, stiffness, curve, npts, dt, D, q, viscoplastic, scale):
    """The equivalent plastic strain increment de > 0 of a point that yields (see module docstring).

    stiffness = 3 mu + H_k; scale = the known rate factor of the yield-scaling form (1 otherwise).
    Newton's method on g(y) = q_trial - stiffness de(y) - R(y) sigma_iso(eps + de(y)) with y = de
    (rate independent, yield scaling) or y = z (viscoplastic), safeguarded by bisection on the
    bracket [0, y_max] where g(0) > 0 >= g(y_max).
    """
    if viscoplastic:
        dtD = dt * D
        hi = (q_trial / (stiffness * dtD)) ** (1.0 / q)
    else:
        dtD = 1.0
        hi = q_trial / stiffness
    lo = 0.0
    y = 0.0
    for _ in range(_NEWTON_ITERATIONS):
        if viscoplastic:
            yq1 = y ** (q - 1.0) if y > 0.0 else 0.0
            de = dtD * yq1 * y
            dde = dtD * q * yq1
            factor = 1.0 + y
        else:
            de = y
            dde = 1.0
            factor = scale
        s, h = piecewise_linear(curve, npts, eps + de)
        g = q_trial - stiffness * de - factor * s
        if abs(g) <= _TOLERANCE * q_trial:
            break
        if g > 0.0:
            lo = y
        else:
            hi = y
        dg = -(stiffness + factor * h) * dde - (s if viscoplastic else 0.0)
        step = y - g / dg if dg < 0.0 else 0.5 * (lo + hi)
        y = step if lo < step < hi else 0.5 * (lo + hi)
    if viscoplastic:
        return dtD * y ** q
    return y


@njit(cache=True, fastmath=True, inline="always")
def relative_deviator(s, point):
    """xi = dev(s) - alpha (alpha the point's back stress) and its size q = sqrt(3/2 xi : xi)."""
    s0, s1, s2, s3, s4, s5 = s
    b = S_BACK
    mean = (s0 + s1 + s2) / 3.0
    x0 = s0 - mean - point[b]
    x1 = s1 - mean - point[b + 1]
    x2 = s2 - mean - point[b + 2]
    x3 = s3 - point[b + 3]
    x4 = s4 - point[b + 4]
    x5 = s5 - point[b + 5]
    return (x0, x1, x2, x3, x4, x5), math.sqrt(1.5 * (x0 * x0 + x1 * x1 + x2 * x2 + 2.0 * (x3 * x3 + x4 * x4 + x5 * x5)))


@njit(cache=True, fastmath=True, inline="always")
def inside_static_yield(curve, npts, point, s):
    """Whether the trial stress ``s`` lies inside the yield surface of the point's plastic strain without
    a rate factor.  Such a point takes no return in either rate form (the factor only raises the yield
    stress): the trial is the law's answer."""
    _, q_trial = relative_deviator(s, point)
    sy, _ = piecewise_linear(curve, npts, point[S_EPS])
    return q_trial <= sy


@njit(cache=True, fastmath=True, inline="always")
def radial_return(row, curve, point, s, d, dt):
    """Return the trial stress ``s`` to the yield surface of the material whose parameter row is
    ``row`` (hardening ``curve``), at the point whose state is ``point`` (updated in place).

    ``d`` is the step's strain rate (for the yield-scaling rate form).  Returns the stress and the
    plastic work density of the step sigma : d eps_p [J/m^3].
    """
    s0, s1, s2, s3, s4, s5 = s
    d0, d1, d2, d3, d4, d5 = d
    mu = row[P_MU]
    hk = row[P_KINEMATIC]
    D = row[P_RATE_D]
    qexp = row[P_RATE_Q]
    npts = int(row[P_CURVE_POINTS])
    eps = point[S_EPS]
    b = S_BACK
    (x0, x1, x2, x3, x4, x5), q_trial = relative_deviator(s, point)
    viscoplastic = D > 0.0 and row[P_RATE_FORM] == VISCOPLASTIC
    scale = 1.0
    if D > 0.0 and not viscoplastic:
        dm = (d0 + d1 + d2) / 3.0
        e0, e1, e2 = d0 - dm, d1 - dm, d2 - dm
        rate = math.sqrt(2.0 / 3.0 * (e0 * e0 + e1 * e1 + e2 * e2 + 2.0 * (d3 * d3 + d4 * d4 + d5 * d5)))
        scale = rate_factor(rate, D, qexp)
    sy, _ = piecewise_linear(curve, npts, eps)
    if q_trial <= scale * sy:
        point[S_RATE] = 0.0
        return s, 0.0
    de = _flow_increment(q_trial, eps, 3.0 * mu + hk, curve, npts, dt, D, qexp, viscoplastic, scale)
    k = 1.5 * de / q_trial                       # d eps_p = k xi_trial (tensor), |.|_eq = de
    r = 2.0 * mu * k
    s0 -= r * x0
    s1 -= r * x1
    s2 -= r * x2
    s3 -= r * x3
    s4 -= r * x4
    s5 -= r * x5
    if hk > 0.0:
        a = 2.0 / 3.0 * hk * k
        point[b] += a * x0
        point[b + 1] += a * x1
        point[b + 2] += a * x2
        point[b + 3] += a * x3
        point[b + 4] += a * x4
        point[b + 5] += a * x5
    point[S_EPS] = eps + de
    point[S_RATE] = de / dt
    work = k * (s0 * x0 + s1 * x1 + s2 * x2 + 2.0 * (s3 * x3 + s4 * x4 + s5 * x5))
    return (s0, s1, s2, s3, s4, s5), work


@njit(cache=True, fastmath=True, inline="always")
def linear_hardening_return(s, eps, mu, y0, eps0, slope, dt):
    """``radial_return`` of a point whose flow stress is linear in its plastic strain, sigma_y = y0 + slope
    (eps - eps0) at every eps: a J2 row with a one- or two-point curve (perfectly plastic or bilinear,
    extended with its slope), rate independent, without kinematic hardening.  Its consistency condition
    is then linear in de and Newton's first step from de = 0 solves it,

        de = (q_trial - sigma_y(eps)) / (3 mu + slope)   where q_trial > sigma_y(eps), else 0,

    the step ``radial_return`` takes (its second iteration finds the residual at round-off and stops).
    Written without calls or early returns so that the one-point elements run it in SIMD lanes over a
    block of cells.  ``s``: the elastic trial (11, 22, 33, 23, 13, 12); returns the stress, the plastic
    strain and its rate at t_n+1, and the plastic work density of the step sigma : d eps_p [J/m^3]."""
    s0, s1, s2, s3, s4, s5 = s
    mean = (s0 + s1 + s2) / 3.0
    xi0 = s0 - mean
    xi1 = s1 - mean
    xi2 = s2 - mean
    q_trial = math.sqrt(1.5 * (xi0 * xi0 + xi1 * xi1 + xi2 * xi2 + 2.0 * (s3 * s3 + s4 * s4 + s5 * s5)))
    excess = q_trial - (y0 + slope * (eps - eps0))
    flows = excess > 0.0
    de = excess / (3.0 * mu + slope) if flows else 0.0
    k = 1.5 * de / q_trial if flows else 0.0       # d eps_p = k xi_trial (tensor), |.|_eq = de
    r = 2.0 * mu * k
    n0 = s0 - r * xi0
    n1 = s1 - r * xi1
    n2 = s2 - r * xi2
    n3 = s3 - r * s3
    n4 = s4 - r * s4
    n5 = s5 - r * s5
    work = k * (n0 * xi0 + n1 * xi1 + n2 * xi2 + 2.0 * (n3 * s3 + n4 * s4 + n5 * s5))
    return (n0, n1, n2, n3, n4, n5), eps + de, de / dt, work


@njit(cache=True, fastmath=True)
def j2_return(row, curve, point, trial, d, dt):
    """The return from an elastic trial already made (``radial_return``).  The one-point elements compute every
    cell's trial in lanes (``update.elastic_update_stress``, the same rotation and Hooke's law as
    ``update_stress`` and ``j2_update`` make) and hand a yielding point's trial here (``update.update_from_trial``),
    rather than rotate and step it a second time.  A called function, compiled once: the return mapping
    inlined into every element kernel made numba's compile of the first plastic run several times longer."""
    return radial_return(row, curve, point, trial, d, dt)


@njit(cache=True, fastmath=True)
def j2_update(row, curve, point, s, d, dt):
    """The J2 law over one step in the rotated frame: elastic trial, then the return (``j2_return``, called,
    so that the return is compiled once for both).

    ``row``: the material's parameter row; ``curve``: its hardening curve; ``point``: the point's
    state, updated in place.
    """
    trial, _ = elastic_update(row, s, d, dt)
    return j2_return(row, curve, point, trial, d, dt)


def pack_j2(row, curve, plasticity) -> None:
    """Write the J2 constants of a material's ``plasticity`` (the scene's ``Plasticity``: curve,
    kinematic_modulus, rate_D, rate_q, rate_form) into its parameter ``row`` and hardening ``curve``."""
    row[P_KINEMATIC] = plasticity.kinematic_modulus
    row[P_RATE_D] = plasticity.rate_D
    row[P_RATE_Q] = plasticity.rate_q
    row[P_RATE_FORM] = RATE_FORMS[plasticity.rate_form]
    row[P_CURVE_POINTS] = len(plasticity.curve)
    curve[:len(plasticity.curve)] = plasticity.curve
