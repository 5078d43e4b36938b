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
have closed in the point's state (``layout.S_SLOT``).  ``update.update_stress`` calls it before the
metal's law (elastic or J2), which then steps with this rate in place of v_r / r, so the stress power
sigma : d is the metal's and the open slots do no work.  For a plastic material the
hoop rate of zero hoop stress is found by the secant method through the metal's law (as
plane-stress shells find their thickness strain), on a copy of the point's state.

Approximations (stated in the run log): the segments are a continuum in hoop (a slot is smeared
round the circumference, so a segment's own bending as an arch is not there).
"""
from __future__ import annotations

import math

from numba import njit

from .elastic import elastic_update
from .laws import law_update
from .layout import ELASTIC, P_LAMBDA, P_LAW, P_MU, P_SLOT_WIDTH, S_SLOT, STATE_SIZE

_SECANT_ITERATIONS = 30


@njit(cache=True, fastmath=True)
def _hoop_stress(params, curves, m, state, c, p, s, d, w, dt):
    """The hoop stress after the step with strain rate ``d`` and spin ``w`` (the point's state left as it was)."""
    if params[m, P_LAW] == ELASTIC:                    # no state to keep
        return elastic_update(params[m], s, d, dt)[0][2]
    saved = state[c, p].copy()
    r = law_update(params, curves, m, state, c, p, s, d, w, dt)[0]
    for k in range(STATE_SIZE):
        state[c, p, k] = saved[k]
    return r[2]


@njit(cache=True, fastmath=True)
def slotted_hoop_rate(params, curves, m, state, c, p, s, d, w, dt, r):
    """The hoop strain rate the metal of a slotted ring takes this step, given the ring's d[2].

    s: the point's stress at the start of the step (rotated); d, w: its strain rate and spin; r: its radius.
    Updates how much the slots have closed, ``state[c, p, S_SLOT]`` [m].
    """
    d0, d1, d2, d3, d4, d5 = d
    elastic = params[m, P_LAW] == ELASTIC
    width = params[m, P_SLOT_WIDTH]
    closed = state[c, p, S_SLOT]                       # of the slots' total width
    lam = params[m, P_LAMBDA]
    mu = params[m, P_MU]
    stiffness = lam + 2.0 * mu
    if dt <= 0.0:                                      # the forces at t = 0: no step, rates only
        return d2 if closed >= width else -lam * (d0 + d1) / stiffness
    if closed >= width and _hoop_stress(params, curves, m, state, c, p, s, d, w, dt) <= 0.0:
        return d2                                      # closed, and staying in compression
    # open: the hoop rate of zero hoop stress (exact for an elastic material)
    x0 = -(s[2] / dt + lam * (d0 + d1)) / stiffness
    if not elastic:
        f0 = _hoop_stress(params, curves, m, state, c, p, s, (d0, d1, x0, d3, d4, d5), w, dt)
        scale = abs(s[0]) + abs(s[1]) + abs(s[5]) + abs(s[3]) + abs(s[4]) + 1e-6 * mu
        x1 = x0 - f0 / (dt * stiffness)
        for _ in range(_SECANT_ITERATIONS):
            if abs(f0) <= 1e-10 * scale:
                break
            f1 = _hoop_stress(params, curves, m, state, c, p, s, (d0, d1, x1, d3, d4, d5), w, dt)
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
