"""Compiled nodal phases of the central-difference step, each one pass over the nodes.

Nodal arrays are (nodes, gdim) with the ``num_owned`` nodes this rank owns first; sums
(energies, work) run over owned nodes only and are reduced over ranks by the caller.
Separate numpy expressions did the same at about a third of the speed, each one a pass
over memory with a temporary (measured on the bench's cases).
"""
from __future__ import annotations

import math

import numpy as np

from numba import njit

# fastmath without its "no NaN / no Inf" assumptions: with them LLVM folds math.isfinite to True and the
# non-finite guard of ``finish_step`` never fires (a NaN run ended "completed")
FINITE_SAFE_FASTMATH = {"nsz", "arcp", "contract", "afn", "reassoc"}


# The passes run over the dofs as one flat loop (the arrays are C-contiguous (nodes, gdim)), the owned ones
# first and without a test of ownership inside, and with the masses given per dof (``ExplicitSolver``'s
# ``*_mass_dofs``): a loop over the nodes with one over the gdim components inside, a test of ownership in
# it, or a node's mass looked up as ``mass[k // gdim]`` (an integer division by a number known only at run
# time) each kept LLVM from vectorising the pass (finish_step on 3,362 nodes: 27.5 -> 19.0 us for the flat
# loop; 50,000 nodes: 276 -> 52 us for the masses per dof).

@njit(cache=True, fastmath=True)
def update_velocity(v, a, dt_avg, alpha, mass_dofs, num_owned):
    """v_{n+1/2} = v_{n-1/2} + dt_avg a_n, with mass-proportional damping alpha taken implicitly:

        v_new = ((1 - c) v_old + dt_avg a) / (1 + c),  c = alpha dt_avg / 2

    (unconditionally stable).  ``mass_dofs``: the nodal mass of each dof, shaped as ``v``.  Returns the
    energy the damping dissipated over the step, alpha dt_avg sum m |v_n|^2 with v_n = (v_old + v_new) / 2.
    """
    vf, af, mf = v.reshape(-1), a.reshape(-1), mass_dofs.reshape(-1)
    if alpha == 0.0:
        for k in range(vf.shape[0]):
            vf[k] += dt_avg * af[k]
        return 0.0
    c = 0.5 * alpha * dt_avg
    scale = 1.0 / (1.0 + c)
    owned = num_owned * v.shape[1]
    dissipated = 0.0
    for k in range(owned):
        old = vf[k]
        new = ((1.0 - c) * old + dt_avg * af[k]) * scale
        vf[k] = new
        mid = 0.5 * (old + new)
        dissipated += mf[k] * mid * mid
    for k in range(owned, vf.shape[0]):
        vf[k] = ((1.0 - c) * vf[k] + dt_avg * af[k]) * scale
    return alpha * dt_avg * dissipated


@njit(cache=True, fastmath=True)
def update_position(x, u, v, dt, f_int, f_ext, f_con, applied, num_owned):
    """x_{n+1} = x_n + dt v_{n+1/2} (and u likewise).

    Returns the first halves of the trapezoidal work increments over the step,
    (1/2 du . f_int_n, 1/2 du . f_ext_n, 1/2 du . f_con_n) summed over owned nodes (f_con: contact
    forces); ``finish_step`` adds the halves with the forces at t_{n+1}.  ``applied`` False says f_ext
    and f_con are zero (no loads, gravity, contact, springs, liquids or target): they are not read.
    """
    gdim = v.shape[1]
    xf, uf, vf = x.reshape(-1), u.reshape(-1), v.reshape(-1)
    fi, fe, fc = f_int.reshape(-1), f_ext.reshape(-1), f_con.reshape(-1)
    w_int = 0.0
    w_ext = 0.0
    w_con = 0.0
    if applied:
        for k in range(num_owned * gdim):
            du = dt * vf[k]
            xf[k] += du
            uf[k] += du
            w_int += du * fi[k]
            w_ext += du * fe[k]
            w_con += du * fc[k]
    else:
        # two arrays fewer through memory: this pass is bandwidth-bound
        for k in range(num_owned * gdim):
            du = dt * vf[k]
            xf[k] += du
            uf[k] += du
            w_int += du * fi[k]
    for k in range(num_owned * gdim, vf.shape[0]):
        du = dt * vf[k]
        xf[k] += du
        uf[k] += du
    return 0.5 * w_int, 0.5 * w_ext, 0.5 * w_con


@njit(cache=True)
def take_dofs(v, dofs, out):
    """``out[j] = v.flat[dofs[j]]``: the constrained dofs' velocities before the step changes them."""
    vf = v.reshape(-1)
    for j in range(dofs.shape[0]):
        out[j] = vf[dofs[j]]


@njit(cache=True)
def hold_dofs(v, dofs, held, mass, owned, v_before):
    """The constrained dofs ``dofs`` (flat) set to their prescribed velocities ``held`` (v_{n+1/2}), after
    ``update_velocity`` gave them a free one; ``v_before``: their v_{n-1/2} (``take_dofs``), ``mass``: the
    mass behind each, ``owned``: whether this rank owns it.  Returns the work of the reactions over the
    step on the owned dofs, m (v - v_free) (v_before + v) / 2: the impulse that holds the dof times its
    mean velocity."""
    vf = v.reshape(-1)
    work = 0.0
    for j in range(dofs.shape[0]):
        k = dofs[j]
        free = vf[k]
        new = held[j]
        vf[k] = new
        if owned[j]:
            work += mass[j] * (new - free) * 0.5 * (v_before[j] + new)
    return work


@njit(cache=True, fastmath=FINITE_SAFE_FASTMATH)
def finish_step(a, v, f_int, f_ext, f_con, applied, inv_mass_dofs, kinetic_mass_dofs, constrained, dt, num_owned):
    """a_{n+1} = M^-1 (f_ext + f_con - f_int), the second halves of the work increments, and the
    kinetic energy 1/2 m |v_{n+1}|^2 with v_{n+1} = v_{n+1/2} + dt/2 a_{n+1} (constrained dofs,
    flagged in ``constrained`` (nodes, gdim), keep their prescribed velocity).  ``inv_mass_dofs`` and
    ``kinetic_mass_dofs``: 1/m (0 where m = 0) and the mass the kinetic energy counts, per dof, shaped as
    ``v``.  ``applied`` as in ``update_position`` (False: f_ext and f_con are zero and not read; the same
    numbers).

    Returns (half internal, external and contact work, kinetic energy, first non-finite node or -1).
    """
    gdim = v.shape[1]
    af, vf, cf = a.reshape(-1), v.reshape(-1), constrained.reshape(-1)
    fi, fe, fc = f_int.reshape(-1), f_ext.reshape(-1), f_con.reshape(-1)
    inv, mk = inv_mass_dofs.reshape(-1), kinetic_mass_dofs.reshape(-1)
    owned = num_owned * gdim
    w_int = 0.0
    w_ext = 0.0
    w_con = 0.0
    kinetic = 0.0
    # counted, not located, inside the passes (a sum vectorises, "the first one" does not); located after
    non_finite = 0
    if applied:
        for k in range(owned):
            an = (fe[k] + fc[k] - fi[k]) * inv[k]
            af[k] = an
            non_finite += not math.isfinite(an)
            du = dt * vf[k]
            w_int += du * fi[k]
            w_ext += du * fe[k]
            w_con += du * fc[k]
            vn = vf[k] if cf[k] else vf[k] + 0.5 * dt * an
            kinetic += mk[k] * vn * vn
    else:
        for k in range(owned):
            an = -fi[k] * inv[k]
            af[k] = an
            non_finite += not math.isfinite(an)
            du = dt * vf[k]
            w_int += du * fi[k]
            vn = vf[k] if cf[k] else vf[k] + 0.5 * dt * an
            kinetic += mk[k] * vn * vn
    for k in range(owned, vf.shape[0]):
        an = (fe[k] + fc[k] - fi[k]) * inv[k]
        af[k] = an
        non_finite += not math.isfinite(an)
    bad = -1
    if non_finite:
        for k in range(vf.shape[0]):
            if not math.isfinite(af[k]):
                bad = k // gdim
                break
    return 0.5 * w_int, 0.5 * w_ext, 0.5 * w_con, 0.5 * kinetic, bad


@njit(cache=True)
def body_sums(v, a, dt, alpha, mass, kinetic_mass, constrained, node_body, num_bodies, num_owned, dofs, v_held,
              a_held):
    """Per body, over the owned nodes, in one pass (what the history records at every sample):
    momentum sum m v and force sum m a of the motion at t (``ExplicitSolver.motion``: v_{n+1/2} + dt/2 a,
    a - alpha v where free; the prescribed ``v_held`` / ``a_held`` at the constrained ``dofs``, flat, sorted),
    and the kinetic energy as ``finish_step`` counts it (a constrained dof at its velocity v).
    Returns (mv, ma, kinetic): (bodies, gdim), (bodies, gdim), (bodies,)."""
    gdim = v.shape[1]
    mv = np.zeros((num_bodies, gdim))
    ma = np.zeros((num_bodies, gdim))
    kinetic = np.zeros(num_bodies)
    # sums kept in registers while the body stays the same (a body's nodes mostly come in runs), stored
    # when it changes: a store into mv[b] per node made each node wait for the last one (45 -> 22 us on
    # 3,362 nodes)
    sv = np.zeros(3)
    sa = np.zeros(3)
    h = 0.5 * dt
    n = 0
    while n < num_owned:
        b = node_body[n]
        sv0 = sv1 = sv2 = sa0 = sa1 = sa2 = ke = 0.0
        while n < num_owned and node_body[n] == b:
            m = mass[n]
            vv = 0.0
            v_t = v[n, 0] + h * a[n, 0]
            sv0 += m * v_t
            sa0 += m * (a[n, 0] - alpha * v_t)
            vk = v[n, 0] if constrained[n, 0] else v_t
            vv += vk * vk
            v_t = v[n, 1] + h * a[n, 1]
            sv1 += m * v_t
            sa1 += m * (a[n, 1] - alpha * v_t)
            vk = v[n, 1] if constrained[n, 1] else v_t
            vv += vk * vk
            if gdim == 3:
                v_t = v[n, 2] + h * a[n, 2]
                sv2 += m * v_t
                sa2 += m * (a[n, 2] - alpha * v_t)
                vk = v[n, 2] if constrained[n, 2] else v_t
                vv += vk * vk
            ke += 0.5 * kinetic_mass[n] * vv
            n += 1
        sv[0], sv[1], sv[2], sa[0], sa[1], sa[2] = sv0, sv1, sv2, sa0, sa1, sa2
        for i in range(gdim):
            mv[b, i] += sv[i]
            ma[b, i] += sa[i]
        kinetic[b] += ke
    for k in range(len(dofs)):         # the held dofs: their prescribed motion replaces the free one
        n = dofs[k] // gdim
        if n >= num_owned:
            break
        i = dofs[k] % gdim
        b = node_body[n]
        v_t = v[n, i] + 0.5 * dt * a[n, i]
        mv[b, i] += mass[n] * (v_held[k] - v_t)
        ma[b, i] += mass[n] * (a_held[k] - (a[n, i] - alpha * v_t))
    return mv, ma, kinetic


@njit(cache=True)
def rigid_resultant(f_ext, f_con, f_int, x, center, nodes, num_owned_nodes, force, torque):
    """A rigid body's resultant force f_ext + f_con - f_int over its owned nodes (``nodes``' first
    ``num_owned_nodes``) into ``force``, and in 3D its moment about ``center``, the sum of
    (x - center) x f, into ``torque``; both summed node after node."""
    gdim = f_ext.shape[1]
    force[:] = 0.0
    torque[:] = 0.0
    for i in range(num_owned_nodes):
        a = nodes[i]
        f0 = f_ext[a, 0] + f_con[a, 0] - f_int[a, 0]
        f1 = f_ext[a, 1] + f_con[a, 1] - f_int[a, 1]
        force[0] += f0
        force[1] += f1
        if gdim == 3:
            f2 = f_ext[a, 2] + f_con[a, 2] - f_int[a, 2]
            force[2] += f2
            r0, r1, r2 = x[a, 0] - center[0], x[a, 1] - center[1], x[a, 2] - center[2]
            torque[0] += r1 * f2 - r2 * f1
            torque[1] += r2 * f0 - r0 * f2
            torque[2] += r0 * f1 - r1 * f0


@njit(cache=True)
def translate_rigid(x, v, nodes, velocity, dt):
    """A translating rigid body's node velocities over the step: those that carry each node from x to
    x + dt velocity, ((x + dt velocity) - x) / dt, so that every node lands where the body puts it."""
    for i in range(len(nodes)):
        a = nodes[i]
        for j in range(x.shape[1]):
            v[a, j] = (x[a, j] + dt * velocity[j] - x[a, j]) / dt
