"""The one material update every element kernel calls, per integration point and step:

    update_stress(params, curves, m, state, c, p, sigma_n, d, w, dt, r, elastic_only)
        -> (sigma_np1, d_metal, plastic work density)

1. the objective rotation of the stress (and of a J2 back stress) by the step's spin w
   (``objective.py``, Hughes-Winget);
2. for a slotted ring (row with ``P_SLOT_WIDTH`` > 0, axisymmetric, r > 0), the hoop rate its
   open slots leave the metal (``slotted.py``), which replaces d[2];
3. the row's law in the rotated frame (``laws.law_update``: elastic, J2, ...).

``state[c, p]`` is updated in place (state_n -> state_np1).  The element adds the viscous
stresses for its forces with ``viscosity.viscous_stress(params, m, sigma_np1, d_metal, q)``.
Tensors are 6-tuples (11, 22, 33, 23, 13, 12) [Pa, 1/s], the spin is (W23, W13, W12) [1/s], r the
point's radius in axisymmetry [m] (0 otherwise).  ``elastic_only`` (a compile-time constant in the
one-point kernels, ``is_elastic_only``) says every row is elastic without slots: steps 2 and 3 are
then the elastic law alone, with no call.  ``shockfem verify material_point`` and the unit tests
drive this very function.

The elements compute every cell's elastic trial in SIMD lanes (``elastic_update_stress``: rotate, then
Hooke) and ask ``elastic_trial_holds`` whether it is the answer (elastic rows; J2 points without kinematic
hardening inside their static yield surface); ``update_from_trial`` runs for the others: the J2 return
from that trial, or ``update_stress``.

Compiled code: ``update_stress``, the dispatch ``laws.law_update`` and the rotation are inlined into
each element kernel (numba ``inline="always"``); the laws and the slotted ring are called functions,
each compiled once.  Numba inlines at its IR level and the cost grows steeply with nesting: with the
return mapping inlined through update -> dispatch -> law, the cold compile of the first plastic run
took 107-254 s against 73 s before this layer; as it is, 49-65 s (``docs/performance.md``).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from .curves import piecewise_linear
from .elastic import elastic_step, elastic_step_inlined
from .j2 import inside_static_yield, j2_return
from .laws import law_update
from .layout import ELASTIC, J2, P_CURVE_POINTS, P_KINEMATIC, P_LAMBDA, P_LAW, P_MU, P_RATE_D, P_SLOT_WIDTH, S_RATE
from .objective import cayley_matrix, rotate_back_stress, rotate_symmetric
from .slotted import slotted_hoop_rate


@njit(cache=True, fastmath=True, inline="always")
def update_stress(params, curves, m, state, c, p, s, d, w, dt, r, elastic_only):
    """One point of material row ``m`` over one step (module docstring)."""
    q = cayley_matrix(w[0], w[1], w[2], dt)
    s = rotate_symmetric(s, q)
    if elastic_only:
        # the constants by index, not through the row view params[m]: a view costs an atomic
        # reference count up and down per call, 5% of the elastic quad kernel (measured)
        return elastic_step(s, d, params[m, P_LAMBDA], params[m, P_MU], dt), d, 0.0
    if params[m, P_LAW] == J2 and params[m, P_KINEMATIC] > 0.0:
        rotate_back_stress(state, c, p, q)
    if r > 0.0 and params[m, P_SLOT_WIDTH] > 0.0:
        # int64 indices whatever the kernel's, so that the called hoop law is compiled once
        d = (d[0], d[1], slotted_hoop_rate(params, curves, int(m), state, int(c), int(p), s, d, w, dt, r), d[3],
             d[4], d[5])
    s, work = law_update(params, curves, m, state, c, p, s, d, w, dt)
    return s, d, work


@njit(cache=True, fastmath=True, inline="always")
def elastic_update_stress(s, d, w, dt, lam, mu):
    """``update_stress`` of an elastic row without slots, from its Lame constants: rotate, then Hooke
    (the inlined ``elastic.elastic_step``: the elements' lanes call this, and vectorise only with every
    line inlined)."""
    return elastic_step_inlined(rotate_symmetric(s, cayley_matrix(w[0], w[1], w[2], dt)), d, lam, mu, dt)


@njit(cache=True, fastmath=True, inline="always")
def elastic_trial_holds(params, curves, m, state, c, p, trial):
    """Whether the elastic trial ``trial`` (``elastic_update_stress``, which the elements' lanes compute for
    every cell) is ``update_stress``'s answer for row ``m`` at point (c, p), with no plastic work: an
    elastic row without slots, or a J2 row without kinematic hardening or slots whose trial lies inside
    the static yield surface (``j2.inside_static_yield``; its plastic strain rate is then set to 0, as
    the return would).  Otherwise the element runs ``update_stress``."""
    if params[m, P_SLOT_WIDTH] > 0.0:
        return False
    law = params[m, P_LAW]
    if law == ELASTIC:
        return True
    if law == J2 and params[m, P_KINEMATIC] == 0.0:
        if inside_static_yield(curves[m], int(params[m, P_CURVE_POINTS]), state[c, p], trial):
            state[c, p, S_RATE] = 0.0
            return True
    return False


@njit(cache=True, fastmath=True, inline="always")
def _isotropic_j2(params, m):
    """Whether row ``m`` is J2 without kinematic hardening or slots: its return needs no rotated back stress
    and no hoop constraint, only the trial (``update_from_trial``, ``linear_hardening``)."""
    return params[m, P_LAW] == J2 and params[m, P_KINEMATIC] == 0.0 and params[m, P_SLOT_WIDTH] == 0.0


@njit(cache=True, fastmath=True, inline="always")
def update_from_trial(params, curves, m, state, c, p, s, trial, d, w, dt, r):
    """``update_stress`` of a point whose elastic trial ``trial`` (``elastic_update_stress`` of ``s``, ``d``,
    ``w``) is made already and is not the answer (``elastic_trial_holds``).  A J2 row without kinematic
    hardening or slots returns from that trial (``j2.j2_return``): ``update_stress`` would rotate the stress
    and step it again to the same trial, up to the compiler's order of operations, and reach the law
    through its dispatch.  On the plastic Taylor bar at 30 us (1,178 of 2,592 cells yielding) the
    quad pass took 107 ns a cell against 122 (medians of 60 interleaved calls).  Other rows go through
    ``update_stress``.  Returns what ``update_stress`` returns."""
    if _isotropic_j2(params, m):
        s_np1, work = j2_return(params[m], curves[m], state[c, p], trial, d, dt)
        return s_np1, d, work
    return update_stress(params, curves, m, state, c, p, s, d, w, dt, r, False)


@njit(cache=True, fastmath=True, inline="always")
def linear_hardening(params, curves, m):
    """Whether row ``m`` is a J2 row whose return is ``j2.linear_hardening_return`` (a one- or two-point
    curve, rate independent, no kinematic hardening, no slots), and its flow stress line (y0, eps0, slope):
    sigma_y(eps) = y0 + slope (eps - eps0), the curve's first point and first segment's slope
    (``curves.piecewise_linear`` there; 0 for one point)."""
    npts = int(params[m, P_CURVE_POINTS])
    if not (_isotropic_j2(params, m) and params[m, P_RATE_D] == 0.0 and npts <= 2):
        return False, 0.0, 0.0, 0.0
    y0, slope = piecewise_linear(curves[m], npts, curves[m, 0, 0])
    return True, y0, curves[m, 0, 0], slope


def is_elastic_only(params: np.ndarray) -> bool:
    """Whether every row of ``params`` is elastic without slots: the kernels then run their loop that
    calls no law with state (``update_stress``'s ``elastic_only``)."""
    return bool(np.all(params[:, P_LAW] == ELASTIC) and np.all(params[:, P_SLOT_WIDTH] == 0.0))
