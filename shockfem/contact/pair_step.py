"""A two-surface contact pair's step in one process, in two compiled calls.

``ContactPair.compute`` is a dozen compiled passes over a few dozen surface nodes (gathers, the box
and refresh tests, each pass's search narrowing and springs, the records added, the totals). On the
two-rod case at 1.25 mm (two faces of 21 slaves each) their work is a few microseconds, and the
calls themselves (numba unboxes every argument, 0.1-0.2 us an array) and the Python between them
took the rest: 56 us a step against the element pass's 220 (docs/performance.md).

In one process, where no halo has to be exchanged between the passes, the step is therefore two
calls of the same kernels in the same order, so the forces are the same to the bit:

- ``open_step``: the surface nodes' positions and velocities gathered, last step's forces cleared,
  the box and refresh tests (``kernels.survey``, ``kernels.verdict``);
- (a search, in Python, when one is due: ``ContactPair._search``);
- ``close_step``: both passes' facets and springs (``kernels.closest_facets``,
  ``kernels.facet_springs``), the records added in slave order (``kernels.add_springs``), the deepest
  penetration and the totals (``kernels.totals``).

A pair with a rigid surface (a plane, a cylinder, a penetration's tunnel) has no search, so in one
process its step is one call, ``rigid_step``: the gather, the clear, the gaps and the box test
(``kernels.rigid_gaps``), the springs (``kernels.node_to_rigid``) and the totals.  A penetration run's
tunnel (1,535 surface nodes) took 232 us a step in the separate calls and the numpy between them.

Under MPI the pair keeps its separate calls: the halo's exchanges (and a rigid pair's reduction of its
nearest gap) come between them.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from .kernels import (add_springs, clear, closest_facets, facet_springs, gather_local, node_to_rigid, rigid_gaps,
                      survey, totals, verdict)


@njit(cache=True)
def open_step(x, v, local, slot, cx, cv, own_nodes, f, ff, stiff, own_a, own_b, x_search, searched, least, margin):
    """The pair's nodes' x and v into its compact arrays ``cx``, ``cv``; its forces and stiffness row sums
    cleared; returns (the surfaces are further apart than ``margin``, a search is due)."""
    gather_local(x, local, slot, cx)
    gather_local(v, local, slot, cv)
    clear(own_nodes, f, ff, stiff)
    survey(cx, own_a, own_b, x_search, own_nodes, searched, least)
    return verdict(least, margin)


@njit(cache=True)
def close_step(apart, dt,
               slaves_a, rows_a, facets_a, near_a, ptr_a, seg_a, k_a, best_a, best_g_a, ft_a, gap_a, offset_a,
               key_a, records_a,
               slaves_b, rows_b, facets_b, near_b, ptr_b, seg_b, k_b, best_b, best_g_b, ft_b, gap_b, offset_b,
               key_b, records_b,
               x, v, mass, zeta, soft_scale, depth, friction, owned, has_friction, f, ff, stiff, f_old, ff_old,
               own_a, own_area_a, own_nodes):
    """Both passes of the pair (``_a``: a's nodes on b's facets, ``_b`` the other way) as
    ``ContactPair._springs`` runs them in one process, or, if ``apart``, their friction histories
    forgotten; then ``kernels.totals``.  Returns (sums, peaks) as ``totals`` does, and the records each
    pass wrote."""
    active = 0
    deepest = 0.0
    count_a = count_b = 0
    if apart:
        ft_a[:] = 0.0
        ft_b[:] = 0.0
    else:
        closest_facets(slaves_a, rows_a, facets_a, near_a, ptr_a, seg_a, x, depth, best_a, best_g_a)
        active_a, count_a = facet_springs(slaves_a, rows_a, facets_a, k_a, best_a, best_g_a, x, v, mass, zeta,
                                          soft_scale, dt, friction, ft_a, gap_a, offset_a, key_a, records_a)
        closest_facets(slaves_b, rows_b, facets_b, near_b, ptr_b, seg_b, x, depth, best_b, best_g_b)
        active_b, count_b = facet_springs(slaves_b, rows_b, facets_b, k_b, best_b, best_g_b, x, v, mass, zeta,
                                          soft_scale, dt, friction, ft_b, gap_b, offset_b, key_b, records_b)
        nf = facets_a.shape[1]
        add_springs(records_a[:count_a], owned, nf, has_friction, f, ff, stiff)
        add_springs(records_b[:count_b], owned, nf, has_friction, f, ff, stiff)
        active = active_a + active_b
        # as Python's max(deepest, -gap.min()) over the passes: a later value only if strictly greater
        for deeper in (-gap_a.min(), -gap_b.min()):
            if deeper > deepest:
                deepest = deeper
    sums, peaks = totals(f, ff, f_old, ff_old, v, stiff, mass, own_a, own_area_a, own_nodes, active, deepest)
    return sums, peaks, count_a, count_b


@njit(cache=True)
def rigid_step(x, v, local, slot, cx, cv, own_nodes, f, ff, stiff, margin, dt,
               slaves, rows, node_stiffness, kind, point, direction, radius, inside, velocity, gaps, ft, gap, offset,
               mass, zeta, soft_scale, depth, friction, f_old, ff_old, own_a, own_area_a):
    """A rigid pair's step in one process, as ``ContactPair._step`` runs it: the surface nodes' x and v into
    ``cx``, ``cv``, the forces cleared; if the nearest gap is beyond ``margin`` the friction histories
    forgotten, else the springs and the deepest penetration; then ``kernels.totals``.  Returns (sums, peaks)
    as ``totals`` does."""
    gather_local(x, local, slot, cx)
    gather_local(v, local, slot, cv)
    clear(own_nodes, f, ff, stiff)
    rigid_gaps(slaves, rows, kind, point, direction, radius, inside, cx, gaps)
    nearest = gaps.min() if gaps.shape[0] else np.inf
    active = 0
    deepest = 0.0
    if nearest > margin:
        ft[:] = 0.0
    else:
        active = node_to_rigid(slaves, rows, node_stiffness, kind, point, direction, radius, inside, velocity, cx,
                               cv, mass, zeta, soft_scale, dt, depth, friction, f, ff, ft, gap, offset, stiff)
        # as Python's max(deepest, -gap.min()): the later value only if strictly greater
        if gap.shape[0] and -gap.min() > deepest:
            deepest = -gap.min()
    return totals(f, ff, f_old, ff_old, cv, stiff, mass, own_a, own_area_a, own_nodes, active, deepest)
