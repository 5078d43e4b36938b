"""Compiled penalty contact: slave nodes against master facets or a rigid analytic surface.

For a slave node s penetrating a master (gap g < 0 along the master's outward normal n):

    f_n = max(0, -k g - c g_dot),   c = 2 zeta sqrt(k m*),   m* = m_s m_m / (m_s + m_m)

pushes s along +n and the master points back along -n (shared by the facet's shape
functions at the contact point).  k is the master's penalty stiffness, zeta the contact
damping as a fraction of critical (LS-DYNA's VDC), g_dot the normal closing rate; f_n >= 0,
so contact never pulls.  Only penetrations shallower than ``depth`` count, so that a node
is never caught by the far side of a thin part.  ``offset`` (per slave, <= 0) is a penetration
present at the start, taken as the node's zero and released as the node comes out
(LS-DYNA's IGNORE=1): initial overlaps are reported, not exploded.

Friction is Coulomb's law with an elastic stick zone (a tangential spring of the same k,
LS-DYNA's approach): each step the slave's tangential force is moved by -k dt v_t (v_t the
tangential sliding velocity) and capped at mu f_n, with
mu = mu_d + (mu_s - mu_d) exp(-decay |v_t|).  The force is history: ``ft`` keeps it per slave
(three components, z = 0 in 2D), turned onto the current tangent plane each step.

Every active spring adds to ``stiff`` the absolute row sums of its stiffness matrix
(k w_i (1 + sum of the master weights) at each node i it joins, w = 1 at the slave and the
shape-function weights at the master: 2 k w_i against a facet, k against a rigid surface;
doubled with friction, whose tangential spring has the same k): the pair turns them into the
Gershgorin bound of the contact's highest frequency, max_i stiff_i / m_i >= omega^2, which
stays right when many slaves lean on one master node.  A node still in front of the surface but
closing on it fast enough to cross within two steps adds its spring too (``_arriving``), so that
the step in which it touches is already short enough for it.

Master facets are segments (2 nodes, 2D), triangles (3) or bilinear quadrilaterals (4), their
nodes ordered so that the normal points out of the body.  Normal forces go to ``f``,
friction forces to ``ff``, so that the pair can report the two works apart.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

# rigid surface kinds (node_to_rigid)
PLANE, CYLINDER, TUNNEL = 0, 1, 2
NOT_ENTERED = -1e300          # a tunnel node's entry gap before it reaches the mouth
# friction coefficients: [mu_static, mu_dynamic, decay [s/m]]
MU_S, MU_D, DECAY = 0, 1, 2
_TOL = 1e-6        # parametric tolerance: a node on the edge between two facets belongs to both
# A node inside the master but behind a concave (dented) vertex projects just outside both facets
# that meet there; when no facet takes it, the facets it misses by less than this share of their
# size take it at their edge (a convex vertex is always covered by a facet that does take it)
_REACH_BEYOND_EDGE = 0.1
# The coordinates the per-node passes loop over, as a tuple: its length is part of its numba type, so a
# pass compiled for (0, 1, 2) has loops of three trips that unroll.  Read from an array's shape at run
# time, the trip count kept them loops: twice the time of a gather, a clear or the totals
# (docs/performance.md).  Each public pass picks the tuple from its arrays' width
# (``_dims_of``) and calls its body, which takes ``dims``.
D2, D3 = (0, 1), (0, 1, 2)


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
    when positive: contact never pulls), and the stiffness k used.

    soft_scale > 0 (``penalty = "soft"``, LS-DYNA's SOFT=1) raises k to at least
    soft_scale m* / (2 dt^2), the stiffness that stops the nodes whatever their elements.
    """
    if soft_scale > 0.0 and dt > 0.0:
        k = max(k, 0.5 * soft_scale * m_eff / (dt * dt))
    return -k * g - 2.0 * zeta * math.sqrt(k * m_eff) * g_dot, k


@njit(cache=True, fastmath=True, inline="always")
def _friction(ft, i, n, w, fn, k, dt, friction):
    """Update and return the tangential force on slave i (see the module docstring).

    n : unit normal (3); w : velocity of the slave relative to the master point (3);
    fn : normal force >= 0; k : tangential stiffness.
    """
    wn = w[0] * n[0] + w[1] * n[1] + w[2] * n[2]
    t0, t1, t2 = w[0] - wn * n[0], w[1] - wn * n[1], w[2] - wn * n[2]
    speed = math.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
    # last step's force, turned onto the current tangent plane with its size kept
    o0, o1, o2 = ft[i, 0], ft[i, 1], ft[i, 2]
    size = math.sqrt(o0 * o0 + o1 * o1 + o2 * o2)
    on = o0 * n[0] + o1 * n[1] + o2 * n[2]
    o0, o1, o2 = o0 - on * n[0], o1 - on * n[1], o2 - on * n[2]
    kept = math.sqrt(o0 * o0 + o1 * o1 + o2 * o2)
    if kept > 0.0:
        o0, o1, o2 = o0 * size / kept, o1 * size / kept, o2 * size / kept
    # elastic trial (stick), then the Coulomb cap (slip)
    a0, a1, a2 = o0 - k * dt * t0, o1 - k * dt * t1, o2 - k * dt * t2
    mu = friction[MU_D] + (friction[MU_S] - friction[MU_D]) * math.exp(-friction[DECAY] * speed)
    limit = mu * fn
    trial = math.sqrt(a0 * a0 + a1 * a1 + a2 * a2)
    if trial > limit:
        s = limit / trial
        a0, a1, a2 = a0 * s, a1 * s, a2 * s
    ft[i, 0], ft[i, 1], ft[i, 2] = a0, a1, a2
    return a0, a1, a2


@njit(cache=True, fastmath=True, inline="always")
def _project(facet, x, s, w, n):
    """Projection of node s on a master facet: fills the facet nodes' weights ``w`` at the
    projection clamped to the facet and the unit outward normal ``n`` (3 components, z = 0 in 2D);
    returns (gap along n, how far outside the facet the projection falls in parametric units,
    0 when within)."""
    nf = facet.shape[0]
    if nf == 2:
        a, b = facet[0], facet[1]
        tx, ty = x[b, 0] - x[a, 0], x[b, 1] - x[a, 1]
        L2 = tx * tx + ty * ty
        xi = ((x[s, 0] - x[a, 0]) * tx + (x[s, 1] - x[a, 1]) * ty) / L2
        L = math.sqrt(L2)
        n[0], n[1], n[2] = ty / L, -tx / L, 0.0
        outside = max(-xi, xi - 1.0, 0.0)
        xi = min(max(xi, 0.0), 1.0)
        w[0], w[1] = 1.0 - xi, xi
        g = (x[s, 0] - x[a, 0]) * n[0] + (x[s, 1] - x[a, 1]) * n[1]
        return g, outside
    p0 = facet[0]
    if nf == 3:
        e10, e11, e12 = x[facet[1], 0] - x[p0, 0], x[facet[1], 1] - x[p0, 1], x[facet[1], 2] - x[p0, 2]
        e20, e21, e22 = x[facet[2], 0] - x[p0, 0], x[facet[2], 1] - x[p0, 1], x[facet[2], 2] - x[p0, 2]
        r0, r1, r2 = x[s, 0] - x[p0, 0], x[s, 1] - x[p0, 1], x[s, 2] - x[p0, 2]
        a11 = e10 * e10 + e11 * e11 + e12 * e12
        a12 = e10 * e20 + e11 * e21 + e12 * e22
        a22 = e20 * e20 + e21 * e21 + e22 * e22
        b1 = r0 * e10 + r1 * e11 + r2 * e12
        b2 = r0 * e20 + r1 * e21 + r2 * e22
        det = a11 * a22 - a12 * a12
        l1 = (a22 * b1 - a12 * b2) / det
        l2 = (a11 * b2 - a12 * b1) / det
        w[0], w[1], w[2] = 1.0 - l1 - l2, l1, l2
        c0, c1, c2 = e11 * e22 - e12 * e21, e12 * e20 - e10 * e22, e10 * e21 - e11 * e20
        outside = max(-w[0], -w[1], -w[2], 0.0)
        total = 0.0
        for j in range(3):
            w[j] = max(w[j], 0.0)
            total += w[j]
        for j in range(3):
            w[j] /= total
    else:
        # bilinear quadrilateral, corners at (xi, eta) = (-1,-1), (1,-1), (1,1), (-1,1):
        # Gauss-Newton on |x(xi, eta) - x_s|^2 (exact in one iteration on a flat parallelogram)
        xi = 0.0
        eta = 0.0
        c0 = c1 = c2 = 0.0
        for _ in range(6):
            N0, N1 = 0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta)
            N2, N3 = 0.25 * (1 + xi) * (1 + eta), 0.25 * (1 - xi) * (1 + eta)
            dx0 = dx1 = dx2 = de0 = de1 = de2 = r0 = r1 = r2 = 0.0
            for d in range(3):
                q0, q1, q2, q3 = x[facet[0], d], x[facet[1], d], x[facet[2], d], x[facet[3], d]
                dxi = 0.25 * ((q1 - q0) * (1 - eta) + (q2 - q3) * (1 + eta))
                deta = 0.25 * ((q3 - q0) * (1 - xi) + (q2 - q1) * (1 + xi))
                r = N0 * q0 + N1 * q1 + N2 * q2 + N3 * q3 - x[s, d]
                if d == 0:
                    dx0, de0, r0 = dxi, deta, r
                elif d == 1:
                    dx1, de1, r1 = dxi, deta, r
                else:
                    dx2, de2, r2 = dxi, deta, r
            a11 = dx0 * dx0 + dx1 * dx1 + dx2 * dx2
            a12 = dx0 * de0 + dx1 * de1 + dx2 * de2
            a22 = de0 * de0 + de1 * de1 + de2 * de2
            b1 = -(r0 * dx0 + r1 * dx1 + r2 * dx2)
            b2 = -(r0 * de0 + r1 * de1 + r2 * de2)
            det = a11 * a22 - a12 * a12
            dxi_step = (a22 * b1 - a12 * b2) / det
            deta_step = (a11 * b2 - a12 * b1) / det
            xi += dxi_step
            eta += deta_step
            c0, c1, c2 = dx1 * de2 - dx2 * de1, dx2 * de0 - dx0 * de2, dx0 * de1 - dx1 * de0
            if abs(dxi_step) + abs(deta_step) < 1e-10:
                break
            if abs(xi) > 2.0 or abs(eta) > 2.0:
                break                     # far outside: no need to converge
        outside = 0.5 * max(abs(xi) - 1.0, abs(eta) - 1.0, 0.0)      # in units of the facet's side
        xi = min(max(xi, -1.0), 1.0)
        eta = min(max(eta, -1.0), 1.0)
        w[0], w[1] = 0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta)
        w[2], w[3] = 0.25 * (1 + xi) * (1 + eta), 0.25 * (1 - xi) * (1 + eta)
    norm = math.sqrt(c0 * c0 + c1 * c1 + c2 * c2)
    n[0], n[1], n[2] = c0 / norm, c1 / norm, c2 / norm
    g = 0.0
    for d in range(3):
        point = 0.0
        for j in range(nf):
            point += w[j] * x[facet[j], d]
        g += (x[s, d] - point) * n[d]
    return g, outside


@njit(cache=True, fastmath=True, inline="always")
def _forget(ft, i):
    """Slave i is out of contact: its friction history goes."""
    ft[i, 0] = ft[i, 1] = ft[i, 2] = 0.0


@njit(cache=True, fastmath=True, inline="always")
def _arriving(g, g_dot, dt):
    """A node still outside (g >= 0) that closes fast enough to cross the surface within two steps.
    Its spring counts in the stable step already: the solver takes each step at the limit of the
    springs it found at the end of the last one, so a spring that appears unannounced is first
    integrated, at full penalty, with a step that may be too long for it.  Once is harmless, but
    a part that chatters against another (a split cone's free segment on its clamp ring) meets
    it every bounce and gains energy each time."""
    return g + 2.0 * dt * g_dot < 0.0


@njit(cache=True, fastmath=True, inline="always")
def _row(w, nm, k, has_friction):
    """A spring's absolute stiffness row sum at the slave, k (1 + sum w); at master node q it is that
    times w_q.  Doubled with friction (a tangential spring of the same k)."""
    weight_sum = 0.0
    for q in range(nm):
        weight_sum += w[q]
    return (2.0 if has_friction else 1.0) * (1.0 + weight_sum) * k


# Compiled once and called (LLVM may still inline it), not inlined into each caller at numba's IR level:
# inlined at its three call sites it took node_to_rigid's compile to 204 s and facet_springs' to 100 s
# (numba's compile events; the warm-up's axisymmetric group from an empty cache 484 s, against 253 s with
# the ordinary call).
@njit(cache=True, fastmath=True)
def _response(i, g, n, rel, m_eff, k, w, nm, zeta, soft_scale, dt, friction, ft, gap, offset):
    """Penalty and friction response of slave i found at gap g (|g| < depth checked by the caller)
    along the unit normal n, with velocity ``rel`` relative to the contact point and effective mass
    m_eff, against ``nm`` master nodes of weights ``w`` (none for a rigid surface).  Updates the
    slave's own state (gap, offset, friction history) and returns (active, row, fn, t0, t1, t2): 1 if
    the spring is active; its stiffness row sum (``_row``; 0 if it does not count: a node in front
    that is not arriving); the normal force (0 if none: a node in front takes none, and contact never
    pulls); the friction force.  The caller adds them to the nodes (``_add_response``)."""
    gap[i] = g
    g = _beyond_initial(g, offset, i)
    g_dot = rel[0] * n[0] + rel[1] * n[1] + rel[2] * n[2]
    has_friction = friction[MU_S] > 0.0 or friction[MU_D] > 0.0
    if g >= 0.0:
        _forget(ft, i)
        if _arriving(g, g_dot, dt):
            return 0, _row(w, nm, _spring(k, -1.0, 0.0, m_eff, 0.0, soft_scale, dt)[1], has_friction), 0.0, \
                0.0, 0.0, 0.0
        return 0, 0.0, 0.0, 0.0, 0.0, 0.0
    fn, k = _spring(k, g, g_dot, m_eff, zeta, soft_scale, dt)
    row = _row(w, nm, k, has_friction)
    if fn <= 0.0:
        _forget(ft, i)
        return 1, row, 0.0, 0.0, 0.0, 0.0
    t0 = t1 = t2 = 0.0
    if has_friction:
        t0, t1, t2 = _friction(ft, i, n, rel, fn, k, dt, friction)
    return 1, row, fn, t0, t1, t2


# A facet spring's record (``facet_springs`` -> ``add_springs``), one row of doubles: the order key
# (the pair's slave number: pass 0's slaves first), the slave node, the normal force fn >= 0, the
# stiffness row sum, the unit normal (3), the friction force (3), then the facet's nodes and their
# weights (nf each).  Under MPI a record travels to the ranks owning its facet's nodes (node
# numbers are exact as doubles), and each rank adds the records it holds in key order: the order in
# which one process adds them, so a node's force is the same sum on any number of ranks.
R_KEY, R_SLAVE, R_FORCE, R_ROW, R_NORMAL, R_FRICTION, R_MASTER = 0, 1, 2, 3, 4, 7, 10


def record_width(nf: int) -> int:
    """Doubles in the record of a spring on a facet of ``nf`` nodes."""
    return R_MASTER + 2 * nf


@njit(cache=True, fastmath=True, inline="always")
def _add_to_node(node, share, n, row, fn, t0, t1, t2, has_friction, f, ff, stiff, dims):
    """Add a spring's response (``_response``) to one of its nodes, ``share`` of it: 1 at the slave,
    -w_q at master node q (the reaction, shared by the facet's shape functions)."""
    if row > 0.0:
        stiff[node] += row * abs(share)
    if fn > 0.0:
        for d in range(len(dims)):
            f[node, d] += share * fn * n[d]
        if has_friction:
            t = (t0, t1, t2)
            for d in range(len(dims)):
                ff[node, d] += share * t[d]


def node_to_facets(slaves, facets, facet_stiffness, cand_ptr, cand_seg, x, v, mass, zeta, soft_scale, dt,
                   depth, friction, f, ff, ft, gap, offset, stiff):
    """One pass of node-to-facet contact in one process; normal forces are added to ``f``, friction to ``ff``.

    slaves : (ns,) slave node numbers; facets : (nm, 2|3|4) master facets, outward order;
    facet_stiffness : (nm,) penalty stiffness [N/m]; cand_ptr, cand_seg : CSR candidate facets
    of each slave (from the search); soft_scale, dt : see ``_spring``; friction : [mu_s, mu_d,
    decay]; ft : (ns, 3) tangential force history; gap : (ns,) out, the signed gap of each slave
    (0 if none); stiff : (nodes,) in/out, row sums of the active springs (see the module docstring).

    The pair runs the three halves apart: ``closest_facets`` (the search's candidates narrowed to the
    facet that takes each slave: the work, which MPI ranks divide by slave), ``facet_springs`` (each
    slave's spring, as a record) and ``add_springs`` (the records added to the nodes in slave order).
    Returns the number of active slaves.
    """
    rows = np.arange(slaves.shape[0])
    best = np.empty(slaves.shape[0], dtype=np.int64)
    best_g = np.empty(slaves.shape[0])
    closest_facets(slaves, rows, facets, candidate_facets(cand_seg), cand_ptr, cand_seg, x, depth, best, best_g)
    records = np.empty((slaves.shape[0], record_width(facets.shape[1])))
    active, count = facet_springs(slaves, rows, facets, facet_stiffness, best, best_g, x, v, mass, zeta, soft_scale,
                                  dt, friction, ft, gap, offset, 0, records)
    add_springs(records[:count], np.ones(x.shape[0], dtype=np.bool_), facets.shape[1],
                friction[MU_S] > 0.0 or friction[MU_D] > 0.0, f, ff, stiff)
    return active


def candidate_facets(cand_seg):
    """The facets some candidate list holds (``closest_facets``' ``near``)."""
    return np.unique(cand_seg).astype(np.int64)


@njit(cache=True, fastmath=True)
def closest_facets(slaves, rows, facets, near, cand_ptr, cand_seg, x, depth, best_out, best_g_out):
    """For each slave of ``rows`` (indices into ``slaves``: all of them in one process, a rank's own
    under MPI), the master facet that takes it and its signed gap: ``best_out[i]`` (-1 if none) and
    ``best_g_out[i]``.  ``near``: the facets the candidate lists of ``rows`` hold (their bounding spheres
    are computed, not the whole surface's)."""
    gdim = x.shape[1]
    nf = facets.shape[1]
    w = np.zeros(4)
    n = np.zeros(3)
    # a bounding sphere of every facet: a candidate further from its centre than the sphere, widened by
    # the reach beyond an edge and the depth, can take the node neither within, nor beyond its edge, nor
    # ahead of it, so its projection (a Newton solve on a bilinear quad) is skipped.  In 3D the search
    # lists ~26 candidates a node, of which a few are near: the 3D two-rod case at 3.5 mm, 1.26 -> 0.66 ms a step
    centre = np.zeros((facets.shape[0], gdim))
    cull2 = np.zeros(facets.shape[0])
    for j in near:
        for d in range(gdim):
            for q in range(nf):
                centre[j, d] += x[facets[j, q], d] / nf
        r2 = 0.0
        for q in range(nf):
            e2 = 0.0
            for d in range(gdim):
                e2 += (x[facets[j, q], d] - centre[j, d]) ** 2
            r2 = max(r2, e2)
        reach = (1.0 + 5.0 * _REACH_BEYOND_EDGE) * math.sqrt(r2) + depth
        cull2[j] = reach * reach
    for i in rows:
        s = slaves[i]
        best = -1
        best_g = -1e300
        near_within = False          # some facet takes the node's projection and is near it
        beyond = -1                  # fallback: the shallowest penetration just beyond a facet edge
        beyond_g = -1e300
        ahead = -1                   # not in: the nearest facet the node is in front of
        ahead_g = 1e300
        for jj in range(cand_ptr[i], cand_ptr[i + 1]):
            j = cand_seg[jj]
            mine = False
            for q in range(nf):
                mine = mine or facets[j, q] == s
            if mine:
                continue
            dist2 = 0.0
            for d in range(gdim):
                dist2 += (x[s, d] - centre[j, d]) ** 2
            if dist2 > cull2[j]:
                continue
            g, outside = _project(facets[j], x, s, w, n)
            if g <= -depth or g >= depth:
                continue
            if outside <= _TOL:
                near_within = True
                # among the facets the node is behind, the shallowest (a node in a concave corner
                # belongs to the face it just crossed, not to the one it is deep behind)
                if g < 0.0 and g > best_g:
                    best, best_g = j, g
                elif g >= 0.0 and g < ahead_g:
                    ahead, ahead_g = j, g
            elif outside < _REACH_BEYOND_EDGE and g < 0.0 and g > beyond_g:
                beyond, beyond_g = j, g
        if best < 0 and not near_within and beyond >= 0:
            best, best_g = beyond, beyond_g
        if best < 0 and ahead >= 0:
            best, best_g = ahead, ahead_g     # _response counts its spring if it is arriving
        best_out[i] = best
        best_g_out[i] = best_g


@njit(cache=True, fastmath=True)
def facet_springs(slaves, rows, facets, facet_stiffness, best, best_g, x, v, mass, zeta, soft_scale, dt, friction,
                  ft, gap, offset, key0, records):
    """The spring of each slave of ``rows`` on the facet ``closest_facets`` found for it (``best``, its gap
    ``best_g``), written to ``records`` (one row a spring that acts or counts, key ``key0`` + slave index;
    see ``R_KEY``); the slaves' own state (gap, offset, friction history) is updated here.  Returns the
    number of active slaves and of records written."""
    gdim = x.shape[1]
    nf = facets.shape[1]
    bw = np.zeros(4)
    bn = np.zeros(3)
    rel = np.zeros(3)
    active = 0
    count = 0
    for i in rows:
        s = slaves[i]
        gap[i] = 0.0
        b = best[i]
        if b < 0:
            offset[i] = 0.0
            _forget(ft, i)
            continue
        _project(facets[b], x, s, bw, bn)
        mm = 0.0
        for q in range(nf):
            mm += bw[q] * mass[facets[b, q]]
        ms = mass[s]
        m_eff = ms * mm / (ms + mm)
        rel[2] = 0.0
        for d in range(gdim):
            rel[d] = v[s, d]
            for q in range(nf):
                rel[d] -= bw[q] * v[facets[b, q], d]
        act, row, fn, t0, t1, t2 = _response(i, best_g[i], bn, rel, m_eff, facet_stiffness[b], bw, nf, zeta,
                                             soft_scale, dt, friction, ft, gap, offset)
        active += act
        if row > 0.0:
            r = records[count]
            r[R_KEY] = key0 + i
            r[R_SLAVE] = s
            r[R_FORCE] = fn
            r[R_ROW] = row
            for d in range(3):
                r[R_NORMAL + d] = bn[d]
            r[R_FRICTION], r[R_FRICTION + 1], r[R_FRICTION + 2] = t0, t1, t2
            for q in range(nf):
                r[R_MASTER + q] = facets[b, q]
                r[R_MASTER + nf + q] = bw[q]
            count += 1
    return active, count


@njit(cache=True, fastmath=True)
def add_springs(records, owned, nf, has_friction, f, ff, stiff):
    """Add facet springs' records (``facet_springs``), in their order, to the nodes of ``owned``."""
    if f.shape[1] == 3:
        _add_springs(records, owned, nf, has_friction, f, ff, stiff, D3)
    else:
        _add_springs(records, owned, nf, has_friction, f, ff, stiff, D2)


@njit(cache=True, fastmath=True)
def _add_springs(records, owned, nf, has_friction, f, ff, stiff, dims):
    """``add_springs`` for the coordinates ``dims``."""
    master = np.zeros(nf, dtype=np.int64)
    w = np.zeros(nf)
    n = np.zeros(3)
    for j in range(records.shape[0]):
        r = records[j]
        for q in range(nf):
            master[q] = np.int64(r[R_MASTER + q])
            w[q] = r[R_MASTER + nf + q]
        for d in range(3):
            n[d] = r[R_NORMAL + d]
        row, fn, t0, t1, t2 = r[R_ROW], r[R_FORCE], r[R_FRICTION], r[R_FRICTION + 1], r[R_FRICTION + 2]
        s = np.int64(r[R_SLAVE])
        if owned[s]:
            _add_to_node(s, 1.0, n, row, fn, t0, t1, t2, has_friction, f, ff, stiff, dims)
        for q in range(nf):
            if owned[master[q]]:
                _add_to_node(master[q], -w[q], n, row, fn, t0, t1, t2, has_friction, f, ff, stiff, dims)


@njit(cache=True, fastmath=True)
def _rigid_response(i, s, g, n, rel, m, k, zeta, soft_scale, dt, friction, f, ff, ft, gap, offset, stiff, dims):
    """Slave i (node s) against a rigid surface: ``_response`` added to the slave alone; 1 if active."""
    act, row, fn, t0, t1, t2 = _response(i, g, n, rel, m, k, n, 0, zeta, soft_scale, dt, friction, ft, gap, offset)
    _add_to_node(s, 1.0, n, row, fn, t0, t1, t2, friction[MU_S] > 0.0 or friction[MU_D] > 0.0, f, ff, stiff, dims)
    return act


@njit(cache=True, fastmath=True)
def rigid_gaps(slaves, rows, kind, point, direction, radius, inside, x, out):
    """The gaps of the slaves ``rows`` to a rigid surface (``node_to_rigid``'s), into ``out``: along the plane's
    normal, or the distance to the cylinder's wall (positive on the allowed side); a tunnel's nodes not yet
    past its mouth have none (inf)."""
    if x.shape[1] == 3:
        return _rigid_gaps(slaves, rows, kind, point, direction, radius, inside, x, out, D3)
    return _rigid_gaps(slaves, rows, kind, point, direction, radius, inside, x, out, D2)


@njit(cache=True, fastmath=True)
def _rigid_gaps(slaves, rows, kind, point, direction, radius, inside, x, out, dims):
    """``rigid_gaps`` for the coordinates ``dims``."""
    gdim = len(dims)
    for k in range(rows.shape[0]):
        s = slaves[rows[k]]
        along = 0.0
        for d in range(gdim):
            along += (x[s, d] - point[d]) * direction[d]
        if kind == PLANE:
            out[k] = along
            continue
        dist = 0.0
        for d in range(gdim):
            r = x[s, d] - point[d] - along * direction[d]
            dist += r * r
        dist = math.sqrt(dist)
        out[k] = radius - dist if inside else dist - radius
        if kind == TUNNEL and along < 0.0:
            out[k] = np.inf
    return out


@njit(cache=True, fastmath=True)
def node_to_rigid(slaves, rows, node_stiffness, kind, point, direction, radius, inside, velocity, x, v, mass, zeta,
                  soft_scale, dt, depth, friction, f, ff, ft, gap, offset, stiff):
    """Slave nodes against a rigid surface moving at ``velocity``: a plane (kind PLANE) through
    ``point`` with unit normal ``direction`` toward the allowed side, or a cylinder (kind CYLINDER)
    of ``radius`` about the axis through ``point`` along the unit ``direction`` (a zero direction
    in 2D makes it the circle about ``point``), the nodes staying ``inside`` or outside it, or a
    tunnel (kind TUNNEL): that cylinder from ``point`` on along ``direction`` only, nodes inside, each
    node's wall where it entered (a node entering outside the radius, as the tail of a yawed body
    does, is held from going further out, not pushed in: the hole is as wide as it found it).
    ``rows``: the slaves to take (all of them in one process, a rank's own under MPI: a rigid surface has
    no nodes, so each slave's force is its rank's alone).  Returns the number of active slaves (``stiff``
    as in ``node_to_facets``)."""
    if x.shape[1] == 3:
        return _node_to_rigid(slaves, rows, node_stiffness, kind, point, direction, radius, inside, velocity, x, v,
                              mass, zeta, soft_scale, dt, depth, friction, f, ff, ft, gap, offset, stiff, D3)
    return _node_to_rigid(slaves, rows, node_stiffness, kind, point, direction, radius, inside, velocity, x, v, mass,
                          zeta, soft_scale, dt, depth, friction, f, ff, ft, gap, offset, stiff, D2)


@njit(cache=True, fastmath=True)
def _node_to_rigid(slaves, rows, node_stiffness, kind, point, direction, radius, inside, velocity, x, v, mass, zeta,
                   soft_scale, dt, depth, friction, f, ff, ft, gap, offset, stiff, dims):
    """``node_to_rigid`` for the coordinates ``dims``."""
    gdim = len(dims)
    n = np.zeros(3)
    rel = np.zeros(3)
    free = np.zeros(slaves.shape[0])                # a tunnel's nodes: no initial penetration to release
    active = 0
    for i in rows:
        s = slaves[i]
        g = 0.0
        if kind == PLANE:
            for d in range(gdim):
                n[d] = direction[d]
                g += (x[s, d] - point[d]) * n[d]
        else:
            along = 0.0
            for d in range(gdim):
                along += (x[s, d] - point[d]) * direction[d]
            dist = 0.0
            for d in range(gdim):
                n[d] = x[s, d] - point[d] - along * direction[d]
                dist += n[d] * n[d]
            dist = math.sqrt(dist)
            sign = -1.0 if inside else 1.0
            for d in range(gdim):
                n[d] = sign * n[d] / dist if dist > 0.0 else 0.0
            g = sign * (dist - radius)
            if kind == TUNNEL:
                if along < 0.0:
                    # not yet in: its wall will be where it enters (``offset`` holds that entry gap)
                    offset[i] = NOT_ENTERED
                    gap[i] = 0.0
                    _forget(ft, i)
                    continue
                if offset[i] == NOT_ENTERED:
                    offset[i] = min(g, 0.0)
                # the hole is as wide as the node found it, and stays so (no release as it moves in)
                g -= offset[i]
                free[i] = 0.0
                if g >= depth:
                    gap[i] = 0.0
                    _forget(ft, i)
                    continue
                for d in range(gdim):
                    rel[d] = v[s, d] - velocity[d]
                active += _rigid_response(i, s, g, n, rel, mass[s], node_stiffness[i], zeta, soft_scale, dt, friction,
                                          f, ff, ft, gap, free, stiff, dims)
                continue
        gap[i] = 0.0
        if g >= depth or g <= -depth:
            offset[i] = 0.0
            _forget(ft, i)
            continue
        for d in range(gdim):
            rel[d] = v[s, d] - velocity[d]
        active += _rigid_response(i, s, g, n, rel, mass[s], node_stiffness[i], zeta, soft_scale, dt, friction, f,
                                  ff, ft, gap, offset, stiff, dims)
    return active


# ------------------------------------------------------------------ the pair's bookkeeping, compiled
# A pair's step around its passes was some twenty numpy expressions on the surface nodes (gathers,
# box test, refresh test, sums, work, copies, the step limit, the scatter): 60 us a step on a
# 3,200-element contact case whose element pass takes 170 us.  These five passes do the same (31 us).

@njit(cache=True)
def gather_local(values, local, slot, out):
    """out[slot[i]] = values[local[i]]: a rank's owned surface nodes into the compact array (positions,
    velocities; any other width too: a node's mass, its body)."""
    _move_rows(values, local, out, slot, False)


@njit(cache=True)
def add_local(compact, slot, local, out):
    """out[local[i]] += compact[slot[i]]: compact forces onto the rank's owned nodes."""
    _move_rows(compact, slot, out, local, True)


@njit(cache=True)
def _move_rows(source, source_rows, target, target_rows, add):
    """target[target_rows[i]] = (or +=, ``add``) source[source_rows[i]], row by row."""
    width = source.shape[1]
    if width == 3:
        _move_columns(source, source_rows, target, target_rows, add, D3)
    elif width == 2:
        _move_columns(source, source_rows, target, target_rows, add, D2)
    else:
        _move_columns(source, source_rows, target, target_rows, add, np.arange(width))


@njit(cache=True)
def _move_columns(source, source_rows, target, target_rows, add, dims):
    """``_move_rows`` for the columns ``dims`` (a tuple, or an array for other widths)."""
    for i in range(len(source_rows)):
        for c in range(len(dims)):
            if add:
                target[target_rows[i], c] += source[source_rows[i], c]
            else:
                target[target_rows[i], c] = source[source_rows[i], c]


@njit(cache=True)
def extent(x, nodes):
    """The bounding box (lo, hi) of the nodes ``nodes`` of ``x`` (lo = +inf, hi = -inf if none)."""
    if x.shape[1] == 3:
        return _extent(x, nodes, D3)
    return _extent(x, nodes, D2)


@njit(cache=True)
def _extent(x, nodes, dims):
    """``extent`` for the coordinates ``dims``."""
    lo = np.full(len(dims), np.inf)
    hi = np.full(len(dims), -np.inf)
    for s in nodes:
        for c in range(len(dims)):
            lo[c] = min(lo[c], x[s, c])
            hi[c] = max(hi[c], x[s, c])
    return lo, hi


@njit(cache=True)
def travel(x, x_before, nodes):
    """The largest coordinate change of the nodes ``nodes`` between ``x_before`` and ``x``."""
    if x.shape[1] == 3:
        return _travel(x, x_before, nodes, D3)
    return _travel(x, x_before, nodes, D2)


@njit(cache=True)
def _travel(x, x_before, nodes, dims):
    """``travel`` for the coordinates ``dims``."""
    most = 0.0
    for i in nodes:
        for c in range(len(dims)):
            most = max(most, abs(x[i, c] - x_before[i, c]))
    return most


@njit(cache=True)
def clear(nodes, f, ff, stiff):
    """Zero the forces and stiffness row sums of the nodes ``nodes``."""
    if f.shape[1] == 3:
        _clear(nodes, f, ff, stiff, D3)
    else:
        _clear(nodes, f, ff, stiff, D2)


@njit(cache=True)
def _clear(nodes, f, ff, stiff, dims):
    """``clear`` for the coordinates ``dims``."""
    for i in nodes:
        stiff[i] = 0.0
        for c in range(len(dims)):
            f[i, c] = 0.0
            ff[i, c] = 0.0


@njit(cache=True)
def totals(f, ff, f_old, ff_old, v, stiff, mass, nodes_a, area_a, nodes, active, deepest):
    """After the passes, over the nodes ``nodes`` (a rank's own; the pair sums the ranks'): the normal
    and friction forces on surface a (its nodes among them: ``nodes_a``, their areas ``area_a``), the work
    of each over the step (trapezoidal with the last step's forces, at v_{n+1/2}), omega^2 of the active
    springs (max stiff / m, 0 if none), and on a the largest node pressure |f_i| / A_i, the summed |f_i|
    and the loaded area.  Keeps this step's forces as the next one's old ones.  Returns what the pair
    reduces over the ranks: ``sums`` = [force on a (gdim), friction on a (gdim), work, friction work,
    summed |f_i|, loaded area, ``active``] and ``peaks`` = [omega^2, largest pressure, ``deepest``]."""
    if f.shape[1] == 3:
        return _totals(f, ff, f_old, ff_old, v, stiff, mass, nodes_a, area_a, nodes, active, deepest, D3)
    return _totals(f, ff, f_old, ff_old, v, stiff, mass, nodes_a, area_a, nodes, active, deepest, D2)


@njit(cache=True)
def _totals(f, ff, f_old, ff_old, v, stiff, mass, nodes_a, area_a, nodes, active, deepest, dims):
    """``totals`` for the coordinates ``dims``."""
    gdim = len(dims)
    sums = np.zeros(2 * gdim + 5)
    max_pressure = 0.0
    for j in range(len(nodes_a)):
        i = nodes_a[j]
        size2 = 0.0
        for c in range(gdim):
            sums[c] += f[i, c]
            sums[gdim + c] += ff[i, c]
            size2 += f[i, c] * f[i, c]
        if size2 > 0.0:
            size = np.sqrt(size2)
            max_pressure = max(max_pressure, size / area_a[j])
            sums[2 * gdim + 2] += size
            sums[2 * gdim + 3] += area_a[j]
    work = 0.0
    friction_work = 0.0
    omega2 = 0.0
    for i in nodes:
        for c in range(gdim):
            work += (f_old[i, c] + f[i, c]) * v[i, c]
            friction_work += (ff_old[i, c] + ff[i, c]) * v[i, c]
            f_old[i, c] = f[i, c]
            ff_old[i, c] = ff[i, c]
        if stiff[i] > 0.0:
            omega2 = max(omega2, stiff[i] / mass[i])
    sums[2 * gdim] = work
    sums[2 * gdim + 1] = friction_work
    sums[2 * gdim + 4] = active
    return sums, np.array([omega2, max_pressure, deepest])


@njit(cache=True)
def survey(x, own_a, own_b, x_search, own_nodes, searched, least):
    """What ``ContactPair._survey`` reduces over the ranks, into ``least`` (its minima, so that one
    reduction does): the bounding boxes' lower corners of this rank's slaves of each pass (``own_a``,
    ``own_b``), their upper corners negated, and the largest travel of this rank's nodes since the last
    search negated (-inf if there was none: ``searched`` False)."""
    g = x.shape[1]
    lo_a, hi_a = extent(x, own_a)
    lo_b, hi_b = extent(x, own_b)
    for c in range(g):
        least[c] = lo_a[c]
        least[g + c] = lo_b[c]
        least[2 * g + c] = -hi_a[c]
        least[3 * g + c] = -hi_b[c]
    least[4 * g] = -travel(x, x_search, own_nodes) if searched else -np.inf


@njit(cache=True)
def pack_rows(x, v, nodes, out):
    """out[i] = [x[nodes[i]], v[nodes[i]]]: the positions and velocities a rank sends."""
    g = x.shape[1]
    for i in range(len(nodes)):
        for c in range(g):
            out[i, c] = x[nodes[i], c]
            out[i, g + c] = v[nodes[i], c]


@njit(cache=True)
def unpack_rows(rows, nodes, x, v):
    """x[nodes[i]], v[nodes[i]] = rows[i] (``pack_rows``' other end)."""
    g = x.shape[1]
    for i in range(len(nodes)):
        for c in range(g):
            x[nodes[i], c] = rows[i, c]
            v[nodes[i], c] = rows[i, g + c]


@njit(cache=True, inline="always")
def _goes_to(records, j, owner, nf, r):
    """Whether record j acts on a node that rank r owns (one of its facet's nodes)."""
    for q in range(nf):
        if owner[np.int64(records[j, R_MASTER + q])] == r:
            return True
    return False


@njit(cache=True)
def records_by_rank(records, owner, nf, rank, size):
    """The records (``R_KEY``) to send to each other rank, one after the other by rank: those with a facet
    node the rank owns (a record may go to several).  Returns the rows and the count for each rank."""
    counts = np.zeros(size, dtype=np.int64)
    for j in range(records.shape[0]):
        for r in range(size):
            if r != rank and _goes_to(records, j, owner, nf, r):
                counts[r] += 1
    out = np.empty((counts.sum(), records.shape[1]))
    start = np.zeros(size, dtype=np.int64)
    for r in range(1, size):
        start[r] = start[r - 1] + counts[r - 1]
    for j in range(records.shape[0]):
        for r in range(size):
            if r != rank and _goes_to(records, j, owner, nf, r):
                out[start[r]] = records[j]
                start[r] += 1
    return out, counts


@njit(cache=True)
def verdict(least, margin):
    """From ``survey``'s reduced minima: (the two slave sets' bounding boxes are further apart than
    ``margin``, some node has travelled a quarter of it since the last search)."""
    g = (least.shape[0] - 1) // 4
    gap = -np.inf
    for c in range(g):
        # lo_a - hi_b and lo_b - hi_a (the upper corners are stored negated)
        gap = max(gap, least[c] + least[3 * g + c], least[g + c] + least[2 * g + c])
    return gap > margin, -least[4 * g] >= 0.25 * margin


@njit(cache=True)
def hold_on_plane(x, v, v_before, nodes, mass, area, point, normal, dt, impulse):
    """A rigid plane as a constraint (LS-DYNA's *RIGIDWALL_PLANAR, frictionless): each of ``nodes`` whose
    step x + dt v would end behind the plane through ``point`` (its place at the step's end) with unit
    ``normal`` toward the allowed side gets the normal velocity that puts it on the plane at the step's
    end; its tangential velocity stays.  ``v`` is v_{n+1/2} after the free update, changed in place.
    ``v_before``: the nodes' v_{n-1/2}; ``mass`` and ``area`` (the node's share of the surface): per node.
    ``impulse`` (gdim) is set to the sum of m (v - v_free), the wall's impulse on the nodes.  Returns (the
    work of that impulse, m (v - v_free) . (v_before + v) / 2 summed, the impulse times the node's mean
    velocity at t_n, as the reactions' work of a held dof is counted (``nodal.hold_dofs``: a node resting
    on the wall, at 0 before and after, takes none); the number of nodes held; the sum of the nodes'
    impulses' sizes; the largest impulse per area; the area of the nodes held).  A node
    the plane does not stop is left alone: a node is held only while it presses on the wall, and leaves it
    as soon as its free step does."""
    if x.shape[1] == 3:
        return _hold_on_plane(x, v, v_before, nodes, mass, area, point, normal, dt, impulse, D3)
    return _hold_on_plane(x, v, v_before, nodes, mass, area, point, normal, dt, impulse, D2)


@njit(cache=True)
def _hold_on_plane(x, v, v_before, nodes, mass, area, point, normal, dt, impulse, dims):
    """``hold_on_plane`` for the coordinates ``dims``."""
    gdim = len(dims)
    for d in range(gdim):
        impulse[d] = 0.0
    work = 0.0
    held = 0
    total = 0.0
    largest = 0.0
    loaded = 0.0
    for j in range(nodes.shape[0]):
        n = nodes[j]
        gap = 0.0
        for d in range(gdim):
            gap += (x[n, d] + dt * v[n, d] - point[d]) * normal[d]
        if gap >= 0.0:
            continue
        dv = -gap / dt                      # along the normal: the node ends on the plane
        for d in range(gdim):
            free = v[n, d]
            new = free + dv * normal[d]
            v[n, d] = new
            change = mass[j] * (new - free)
            impulse[d] += change
            work += change * 0.5 * (v_before[j, d] + new)
        held += 1
        total += mass[j] * dv
        loaded += area[j]
        if area[j] > 0.0:
            largest = max(largest, mass[j] * dv / area[j])
    return work, held, total, largest, loaded
