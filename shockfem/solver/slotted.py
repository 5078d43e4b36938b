"""The hoop response of a slotted ring in axisymmetry (the split cone's segments).

An axisymmetric section cannot hold the axial slots of a split cone, but it can hold what they
do: a hoop force cannot cross an open slot, so the segments carry no hoop stress, and the ring's
hoop strain rate v_r / r goes into opening or closing the slots instead of the metal.  Once the
slots have closed (the circumference has shrunk by their total width W more than the metal
has) the segments bear on each other and the ring acts whole, until its hoop stress would turn tensile
and the slots open again:

    open:    sigma_tt = 0; the metal takes the hoop rate d_tt that keeps it so, the slots the rest
    closed:  the metal takes the ring's hoop rate, while sigma_tt <= 0

``slotted_hoop_rate`` returns the metal's hoop rate for one point and keeps how far the slots
have closed in the point's state (``plasticity.S_SLOT``).  The rest of the step (Hooke, the plastic
return, viscosities, forces) is the element kernel's, with this rate in place of v_r / r, so the
stress power sigma : d is the metal's and the open slots do no work.  For a plastic material the
hoop rate of zero hoop stress is found by the secant method through the plastic return (as
plane-stress shells find their thickness strain), on a copy of the point's state.

Approximations (stated in the run log): the segments are a continuum in hoop (a slot is smeared
round the circumference, so a segment's own bending as an arch is not there).
"""
from __future__ import annotations

import math

from numba import njit

from .columns import P_LAMBDA, P_MODEL, P_MU, P_SLOT_WIDTH, PLASTIC
from .kernels import _hooke
from .plasticity import S_SLOT, STATE_SIZE, radial_return

_SECANT_ITERATIONS = 30

# The plastic return as a called function, not inlined like the element kernels' own call:
# numba inlines at the IR level, and a second inlined copy here tripled the kernel's compile time.
_radial_return_call = njit(cache=True, fastmath=True)(radial_return.py_func)


@njit(cache=True, fastmath=True)
def _hoop_stress(params, curves, m, state, c, p, s0, s1, s2, s3, s4, s5, d0, d1, d2, d3, d4, d5, dt, plastic):
    """The hoop stress after the step with hoop rate d2 (the point's plastic state left as it was)."""
    c0, c1, c2, c3, c4, c5 = _hooke(d0, d1, d2, d3, d4, d5, params[m, P_LAMBDA], params[m, P_MU])
    if not plastic:
        return s2 + dt * c2
    saved = state[c, p].copy()
    r = _radial_return_call(params, curves, m, state, c, p, s0 + dt * c0, s1 + dt * c1, s2 + dt * c2,
                            s3 + dt * c3, s4 + dt * c4, s5 + dt * c5, d0, d1, d2, d3, d4, d5, dt)
    for k in range(STATE_SIZE):
        state[c, p, k] = saved[k]
    return r[2]


@njit(cache=True, fastmath=True)
def slotted_hoop_rate(params, curves, m, state, c, p, s0, s1, s2, s3, s4, s5, d0, d1, d2, d3, d4, d5, dt, r):
    """The hoop strain rate the metal of a slotted ring takes this step, given the ring's d2.

    s0..s5: the point's stress at the start of the step (rotated); d0..d5 its strain rate;
    r: its radius.  Updates how much the slots have closed, ``state[c, p, S_SLOT]`` [m].
    """
    plastic = params[m, P_MODEL] == PLASTIC
    width = params[m, P_SLOT_WIDTH]
    closed = state[c, p, S_SLOT]                       # of the slots' total width
    lam = params[m, P_LAMBDA]
    mu = params[m, P_MU]
    stiffness = lam + 2.0 * mu
    if dt <= 0.0:                                      # the forces at t = 0: no step, rates only
        return d2 if closed >= width else -lam * (d0 + d1) / stiffness
    if closed >= width and _hoop_stress(params, curves, m, state, c, p, s0, s1, s2, s3, s4, s5,
                                        d0, d1, d2, d3, d4, d5, dt, plastic) <= 0.0:
        return d2                                      # closed, and staying in compression
    # open: the hoop rate of zero hoop stress (exact for an elastic material)
    x0 = -(s2 / dt + lam * (d0 + d1)) / stiffness
    if plastic:
        f0 = _hoop_stress(params, curves, m, state, c, p, s0, s1, s2, s3, s4, s5, d0, d1, x0, d3, d4, d5, dt, True)
        scale = abs(s0) + abs(s1) + abs(s5) + abs(s3) + abs(s4) + 1e-6 * mu
        x1 = x0 - f0 / (dt * stiffness)
        for _ in range(_SECANT_ITERATIONS):
            if abs(f0) <= 1e-10 * scale:
                break
            f1 = _hoop_stress(params, curves, m, state, c, p, s0, s1, s2, s3, s4, s5, d0, d1, x1, d3, d4, d5, dt,
                              True)
            if f1 == f0:
                x0, f0 = x1, f1
                break
            x0, x1, f0 = x1, x1 - f1 * (x1 - x0) / (f1 - f0), f1
    # the circumference 2 pi r is the metal's length (stretching at the metal's rate) plus the open
    # slots, width - closed: d(closed)/dt = -(2 pi r (d2 - metal) + (width - closed) metal)
    circumference = 2.0 * math.pi * r
    opening = width - closed
    metal = x0
    closed_new = closed - dt * (circumference * (d2 - metal) + opening * metal)
    if closed_new > width:
        # the slots close within the step: the metal takes what is left after they have
        metal = (opening / dt + circumference * d2) / (circumference - opening)
        closed_new = width
    state[c, p, S_SLOT] = closed_new
    return metal
