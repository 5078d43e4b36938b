"""Compiled penalty contact: slave nodes against master segments (2D) or a rigid plane.

For a slave node s penetrating a master (gap g < 0 along the master's outward normal n):

    f_n = max(0, -k g - c g_dot),   c = 2 zeta sqrt(k m*),   m* = m_s m_m / (m_s + m_m)

pushes s along +n and the master points back along -n (shared by the segment's shape
functions at the contact point).  k is the master's penalty stiffness, zeta the contact
damping as a fraction of critical (LS-DYNA's VDC), g_dot the normal closing rate; f_n >= 0,
so contact never pulls.  Only penetrations shallower than ``depth`` count, so that a node
is never caught by the far side of a thin part.  ``offset`` (per slave, <= 0) is a penetration
present at the start, taken as the node's zero and released as the node comes out
(LS-DYNA's IGNORE=1): initial overlaps are reported, not exploded.
"""
from __future__ import annotations

import math

from numba import njit


@njit(cache=True, fastmath=True, inline="always")
def _beyond_initial(g, offset, i):
    """The penetration that counts: the gap g less the slave's initial penetration offset[i] (<= 0),
    which is released as far as the node comes back out."""
    if g > offset[i]:
        offset[i] = min(g, 0.0)
    return g - offset[i]


@njit(cache=True, fastmath=True, inline="always")
def _spring(k, g, g_dot, m_eff, zeta, soft_scale, dt):
    """Normal force -k g - 2 zeta sqrt(k m*) g_dot of a penetration g < 0 (the caller applies it only
    when positive: contact never pulls) and the stable step sqrt(2 m*/k) of the spring.

    soft_scale > 0 (``penalty = "soft"``, LS-DYNA's SOFT=1) raises k to at least
    soft_scale m* / (2 dt^2), the stiffness that stops the nodes whatever their elements.
    """
    if soft_scale > 0.0 and dt > 0.0:
        k = max(k, 0.5 * soft_scale * m_eff / (dt * dt))
    return -k * g - 2.0 * zeta * math.sqrt(k * m_eff) * g_dot, math.sqrt(2.0 * m_eff / k)


@njit(cache=True, fastmath=True)
def node_to_segment_2d(slaves, segments, seg_stiffness, cand_ptr, cand_seg, x, v, mass, zeta, soft_scale, dt,
                       depth, f, gap, offset):
    """One pass of 2D node-to-segment contact; forces are added to ``f`` (nodes, 2).

    slaves : (ns,) slave node numbers; segments : (nm, 2) master segments, outward order;
    seg_stiffness : (nm,) penalty stiffness [N/m]; soft_scale, dt : see ``_spring``; cand_ptr, cand_seg : CSR candidate segments
    of each slave (from the search); gap : (ns,) out, the signed gap of each slave (0 if none).

    Returns (active slaves, smallest stable step sqrt(2 m*/k) of the active springs).
    """
    active = 0
    dt_min = 1e300
    for i in range(slaves.shape[0]):
        s = slaves[i]
        gap[i] = 0.0
        best = -1
        best_g = -1e300
        best_xi = 0.0
        best_nx = 0.0
        best_ny = 0.0
        for jj in range(cand_ptr[i], cand_ptr[i + 1]):
            j = cand_seg[jj]
            a = segments[j, 0]
            b = segments[j, 1]
            if a == s or b == s:
                continue
            tx = x[b, 0] - x[a, 0]
            ty = x[b, 1] - x[a, 1]
            L2 = tx * tx + ty * ty
            xi = ((x[s, 0] - x[a, 0]) * tx + (x[s, 1] - x[a, 1]) * ty) / L2
            if xi < -1e-6 or xi > 1.0 + 1e-6:
                continue
            L = math.sqrt(L2)
            nx = ty / L
            ny = -tx / L
            g = (x[s, 0] - x[a, 0]) * nx + (x[s, 1] - x[a, 1]) * ny
            if g < 0.0 and g > -depth and g > best_g:
                best, best_g, best_xi, best_nx, best_ny = j, g, min(max(xi, 0.0), 1.0), nx, ny
        if best < 0:
            offset[i] = 0.0
            continue
        gap[i] = best_g
        best_g = _beyond_initial(best_g, offset, i)
        if best_g >= 0.0:
            continue
        a = segments[best, 0]
        b = segments[best, 1]
        w0 = 1.0 - best_xi
        w1 = best_xi
        k = seg_stiffness[best]
        mm = w0 * mass[a] + w1 * mass[b]
        ms = mass[s]
        m_eff = ms * mm / (ms + mm)
        g_dot = ((v[s, 0] - w0 * v[a, 0] - w1 * v[b, 0]) * best_nx
                 + (v[s, 1] - w0 * v[a, 1] - w1 * v[b, 1]) * best_ny)
        fn, dt_spring = _spring(k, best_g, g_dot, m_eff, zeta, soft_scale, dt)
        active += 1
        dt_min = min(dt_min, dt_spring)
        if fn <= 0.0:
            continue
        f[s, 0] += fn * best_nx
        f[s, 1] += fn * best_ny
        f[a, 0] -= w0 * fn * best_nx
        f[a, 1] -= w0 * fn * best_ny
        f[b, 0] -= w1 * fn * best_nx
        f[b, 1] -= w1 * fn * best_ny
    return active, dt_min


@njit(cache=True, fastmath=True)
def node_to_plane(slaves, node_stiffness, point, normal, wall_velocity, x, v, mass, zeta, soft_scale, dt, depth, f,
                  gap, offset):
    """Slave nodes against a rigid plane through ``point`` with unit ``normal`` (pointing to the
    allowed side), moving at ``wall_velocity``.  Returns (active slaves, smallest sqrt(2 m/k))."""
    gdim = x.shape[1]
    active = 0
    dt_min = 1e300
    for i in range(slaves.shape[0]):
        s = slaves[i]
        g = 0.0
        g_dot = 0.0
        for d in range(gdim):
            g += (x[s, d] - point[d]) * normal[d]
            g_dot += (v[s, d] - wall_velocity[d]) * normal[d]
        gap[i] = 0.0
        if g >= 0.0 or g <= -depth:
            offset[i] = 0.0
            continue
        gap[i] = g
        g = _beyond_initial(g, offset, i)
        if g >= 0.0:
            continue
        fn, dt_spring = _spring(node_stiffness[i], g, g_dot, mass[s], zeta, soft_scale, dt)
        active += 1
        dt_min = min(dt_min, dt_spring)
        if fn <= 0.0:
            continue
        for d in range(gdim):
            f[s, d] += fn * normal[d]
    return active, dt_min
