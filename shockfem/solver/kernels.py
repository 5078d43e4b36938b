"""Compiled element kernels: the hot loop of the explicit solver.

The internal force of every deformable cell is the stress divergence

    f_a = int_Omega sigma : grad(N_a) dV      (+ sigma_tt N_a / r  in axisymmetry)

which is exactly the UFL form ``shockfem.model.kinematics.internal_force_form``.
dolfinx 0.5.2 assembles that form at about 7.7 million Q1 cells per second on the
reference machine; this numba twin computes the strain rate, updates the stress
and assembles the force in one pass over the cells at several times that rate
(``docs/performance.md``).  The unit test ``tests/unit/solver/test_kernels.py``
checks it against the dolfinx assembly of the UFL form to round-off.

Conventions
-----------
* Nodal arrays are in dolfinx P1 *block* order (one block = one node), shape
  ``(num_nodes, gdim)``; ``dofmap`` is the P1 dofmap, ``(num_cells, nodes_per_cell)``.
* Stress is stored per quadrature point as 6 components
  ``[s11, s22, s33, s23, s13, s12]``; in 2D, index 2 is the out-of-plane (plane
  strain) or hoop (axisymmetric, coordinates (r, z)) component.
* Kinematics codes: 0 plane strain, 1 axisymmetric, 2 three-dimensional.

Strain rates are taken on the mid-step configuration x_{n+1/2}: with central
differences this makes the velocity gradient of a rigid rotation exactly skew
(Cayley transform), so together with the Hughes-Winget rotation below a spinning
body keeps zero stress (Hughes & Winget 1980, IJNME 15:1862).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

PLANE_STRAIN, AXISYMMETRIC, THREE_D = 0, 1, 2

from .plasticity import radial_return
from .columns import (NUM_PARAMS, P_BETA, P_KINEMATIC, P_LAMBDA, P_MODEL, P_MU, P_Q_LINEAR, P_Q_QUADRATIC,  # noqa: F401
                      P_RHO, P_WAVE_SPEED, PLASTIC)


@njit(cache=True, fastmath=True, inline="always")
def _cayley_matrix(w23, w13, w12, dt):
    """The rotation Q = (I - A)^-1 (I + A), A = dt W / 2, as 9 numbers (row-major).

    Closed form Q = I + 2/(1 + a.a) (A + A^2), a the axial vector of A; Q is orthogonal
    for any step, so rotated stresses keep their invariants exactly.
    """
    a1 = 0.5 * dt * w23
    a2 = 0.5 * dt * w13
    a3 = 0.5 * dt * w12
    # A = [[0, a3, a2], [-a3, 0, a1], [-a2, -a1, 0]] (W_ij = (L_ij - L_ji)/2); A^2 written out.
    k = 2.0 / (1.0 + a1 * a1 + a2 * a2 + a3 * a3)
    return (1.0 + k * (-a3 * a3 - a2 * a2), k * (a3 - a2 * a1), k * (a2 + a3 * a1),
            k * (-a3 - a1 * a2), 1.0 + k * (-a3 * a3 - a1 * a1), k * (a1 - a3 * a2),
            k * (-a2 + a1 * a3), k * (-a1 - a2 * a3), 1.0 + k * (-a2 * a2 - a1 * a1))


@njit(cache=True, fastmath=True, inline="always")
def _rotate_symmetric(s00, s11, s22, s12, s02, s01, q00, q01, q02, q10, q11, q12, q20, q21, q22):
    """Q S Q^T for a symmetric S given and returned as (11, 22, 33, 23, 13, 12)."""
    t00 = q00 * s00 + q01 * s01 + q02 * s02      # T = Q S
    t01 = q00 * s01 + q01 * s11 + q02 * s12
    t02 = q00 * s02 + q01 * s12 + q02 * s22
    t10 = q10 * s00 + q11 * s01 + q12 * s02
    t11 = q10 * s01 + q11 * s11 + q12 * s12
    t12 = q10 * s02 + q11 * s12 + q12 * s22
    t20 = q20 * s00 + q21 * s01 + q22 * s02
    t21 = q20 * s01 + q21 * s11 + q22 * s12
    t22 = q20 * s02 + q21 * s12 + q22 * s22
    return (t00 * q00 + t01 * q01 + t02 * q02, t10 * q10 + t11 * q11 + t12 * q12,
            t20 * q20 + t21 * q21 + t22 * q22, t10 * q20 + t11 * q21 + t12 * q22,
            t00 * q20 + t01 * q21 + t02 * q22, t00 * q10 + t01 * q11 + t02 * q12)


@njit(cache=True, fastmath=True, inline="always")
def _rotate_hughes_winget(s, w23, w13, w12, dt):
    """Rotate the symmetric stress ``s`` (6,) in place: S <- Q S Q^T, Q = ``_cayley_matrix``."""
    if w23 == 0.0 and w13 == 0.0 and w12 == 0.0:
        return
    q00, q01, q02, q10, q11, q12, q20, q21, q22 = _cayley_matrix(w23, w13, w12, dt)
    s[0], s[1], s[2], s[3], s[4], s[5] = _rotate_symmetric(s[0], s[1], s[2], s[3], s[4], s[5], q00, q01, q02,
                                                           q10, q11, q12, q20, q21, q22)


@njit(cache=True, fastmath=True, inline="always")
def _hooke(d0, d1, d2, d3, d4, d5, lam, mu):
    """C : d = lam tr(d) I + 2 mu d for a symmetric d given as (11, 22, 33, 23, 13, 12).

    The one place of Hooke's law: the elastic stress rate, and (times beta) the viscous
    stress of stiffness-proportional damping.
    """
    ltr = lam * (d0 + d1 + d2)
    return (ltr + 2.0 * mu * d0, ltr + 2.0 * mu * d1, ltr + 2.0 * mu * d2,
            2.0 * mu * d3, 2.0 * mu * d4, 2.0 * mu * d5)


@njit(cache=True, fastmath=True, inline="always")
def _damped_step(dtc, beta):
    """The stable step dtc of an element shortened by stiffness-proportional damping beta:
    dt <= (2/w)(sqrt(1 + xi^2) - xi), xi = beta w / 2, w = 2 / dtc the element's highest
    frequency (Belytschko et al., eq. 6.2.28)."""
    if beta > 0.0:
        xi = beta / dtc
        dtc *= math.sqrt(1.0 + xi * xi) - xi
    return dtc


@njit(cache=True, fastmath=True, inline="always")
def bulk_viscosity(rho, c, length, trd, q1, q2):
    """LS-DYNA's artificial bulk viscosity q = rho l (Q1 l tr(d)^2 - Q2 c tr(d)), in compression only.

    A pressure [Pa] added to the force stress (never stored): it spreads a shock over a few
    elements instead of letting it ring (von Neumann & Richtmyer; Q1 the quadratic, Q2 the
    linear coefficient, defaults 1.5 and 0.06)."""
    if trd >= 0.0:
        return 0.0
    return rho * length * (q1 * length * trd * trd - q2 * c * trd)


@njit(cache=True, fastmath=True, inline="always")
def viscous_step(step_length, c, length, trd, q1, q2, beta):
    """An element's stable step: step_length / c, shortened in compression by the bulk viscosity to
    step_length / (Q + sqrt(Q^2 + c^2)), Q = Q2 c + Q1 l |tr(d)| (LS-DYNA), and by stiffness-
    proportional damping (``_damped_step``)."""
    if trd < 0.0:
        Q = q2 * c - q1 * length * trd
        dtc = step_length / (Q + math.sqrt(Q * Q + c * c))
    else:
        dtc = step_length / c
    return _damped_step(dtc, beta)


@njit(cache=True, fastmath=True, inline="always")
def rotate_back_stress(state, c, p, w23, w13, w12, dt):
    """Kinematic hardening's back stress (state columns 2..7) turns with the material like the stress."""
    q00, q01, q02, q10, q11, q12, q20, q21, q22 = _cayley_matrix(w23, w13, w12, dt)
    (state[c, p, 2], state[c, p, 3], state[c, p, 4], state[c, p, 5], state[c, p, 6],
     state[c, p, 7]) = _rotate_symmetric(state[c, p, 2], state[c, p, 3], state[c, p, 4], state[c, p, 5],
                                         state[c, p, 6], state[c, p, 7], q00, q01, q02, q10, q11, q12,
                                         q20, q21, q22)


@njit(cache=True, fastmath=True, inline="always")
def _gradients_2d(xe, dNq, nn, dNdx):
    """Spatial shape-function gradients dNdx (nn, 2) at one point; returns det(J)."""
    j00 = 0.0
    j01 = 0.0
    j10 = 0.0
    j11 = 0.0
    for a in range(nn):
        j00 += xe[a, 0] * dNq[a, 0]
        j01 += xe[a, 0] * dNq[a, 1]
        j10 += xe[a, 1] * dNq[a, 0]
        j11 += xe[a, 1] * dNq[a, 1]
    det = j00 * j11 - j01 * j10
    idet = 1.0 / det
    i00 = j11 * idet
    i01 = -j01 * idet
    i10 = -j10 * idet
    i11 = j00 * idet
    for a in range(nn):
        g0 = dNq[a, 0]
        g1 = dNq[a, 1]
        dNdx[a, 0] = g0 * i00 + g1 * i10
        dNdx[a, 1] = g0 * i01 + g1 * i11
    return det


@njit(cache=True, fastmath=True, inline="always")
def _gradients_3d(xe, dNq, nn, dNdx):
    """Spatial shape-function gradients dNdx (nn, 3) at one point; returns det(J)."""
    j00 = j01 = j02 = j10 = j11 = j12 = j20 = j21 = j22 = 0.0
    for a in range(nn):
        g0 = dNq[a, 0]
        g1 = dNq[a, 1]
        g2 = dNq[a, 2]
        j00 += xe[a, 0] * g0
        j01 += xe[a, 0] * g1
        j02 += xe[a, 0] * g2
        j10 += xe[a, 1] * g0
        j11 += xe[a, 1] * g1
        j12 += xe[a, 1] * g2
        j20 += xe[a, 2] * g0
        j21 += xe[a, 2] * g1
        j22 += xe[a, 2] * g2
    c00 = j11 * j22 - j12 * j21
    c01 = j02 * j21 - j01 * j22
    c02 = j01 * j12 - j02 * j11
    det = j00 * c00 + j10 * c01 + j20 * c02
    idet = 1.0 / det
    i00 = c00 * idet
    i01 = c01 * idet
    i02 = c02 * idet
    i10 = (j12 * j20 - j10 * j22) * idet
    i11 = (j00 * j22 - j02 * j20) * idet
    i12 = (j02 * j10 - j00 * j12) * idet
    i20 = (j10 * j21 - j11 * j20) * idet
    i21 = (j01 * j20 - j00 * j21) * idet
    i22 = (j00 * j11 - j01 * j10) * idet
    for a in range(nn):
        g0 = dNq[a, 0]
        g1 = dNq[a, 1]
        g2 = dNq[a, 2]
        dNdx[a, 0] = g0 * i00 + g1 * i10 + g2 * i20
        dNdx[a, 1] = g0 * i01 + g1 * i11 + g2 * i21
        dNdx[a, 2] = g0 * i02 + g1 * i12 + g2 * i22
    return det


@njit(cache=True, fastmath=True, inline="always")
def _gradients(xe, dNq, gdim, nn, dNdx):
    if gdim == 2:
        return _gradients_2d(xe, dNq, nn, dNdx)
    return _gradients_3d(xe, dNq, nn, dNdx)


@njit(cache=True, fastmath=True, inline="always")
def _half_cross_norm(xe, p, q, r, s):
    """|(x_q - x_p) x (x_s - x_r)| / 2: a triangle's area (r = p) or a quadrilateral's from its diagonals."""
    ux = xe[q, 0] - xe[p, 0]
    uy = xe[q, 1] - xe[p, 1]
    uz = xe[q, 2] - xe[p, 2]
    wx = xe[s, 0] - xe[r, 0]
    wy = xe[s, 1] - xe[r, 1]
    wz = xe[s, 2] - xe[r, 2]
    cx = uy * wz - uz * wy
    cy = uz * wx - ux * wz
    cz = ux * wy - uy * wx
    return 0.5 * math.sqrt(cx * cx + cy * cy + cz * cz)


@njit(cache=True, fastmath=True)
def characteristic_length(xe, cell_kind, nn):
    """Length l_e that sets the element's stable step l_e / c (LS-DYNA conventions).

    cell_kind: 0 triangle (2 area / longest edge = smallest altitude), 1 quadrilateral
    (area / longest diagonal), 2 tetrahedron (3 volume / largest face = smallest
    altitude), 3 hexahedron (volume / largest face area / sqrt(3): a cube of side h with
    2x2x2 Gauss points and lumped mass has omega_max = 2 sqrt(3) c / h).
    Vertex order is dolfinx's (quad: 0-1-3-2 around; hex: bottom 0,1,2,3 as a tensor grid).
    """
    if cell_kind == 0:
        ax = xe[1, 0] - xe[0, 0]
        ay = xe[1, 1] - xe[0, 1]
        bx = xe[2, 0] - xe[0, 0]
        by = xe[2, 1] - xe[0, 1]
        area = 0.5 * abs(ax * by - ay * bx)
        e2 = 0.0
        for (p, q) in ((0, 1), (1, 2), (2, 0)):
            dx = xe[p, 0] - xe[q, 0]
            dy = xe[p, 1] - xe[q, 1]
            e2 = max(e2, dx * dx + dy * dy)
        return 2.0 * area / math.sqrt(e2)
    if cell_kind == 1:
        d1x = xe[3, 0] - xe[0, 0]
        d1y = xe[3, 1] - xe[0, 1]
        d2x = xe[2, 0] - xe[1, 0]
        d2y = xe[2, 1] - xe[1, 1]
        area = 0.5 * abs(d1x * d2y - d1y * d2x)
        dmax = math.sqrt(max(d1x * d1x + d1y * d1y, d2x * d2x + d2y * d2y))
        return area / dmax
    if cell_kind == 2:
        ax = xe[1, 0] - xe[0, 0]
        ay = xe[1, 1] - xe[0, 1]
        az = xe[1, 2] - xe[0, 2]
        bx = xe[2, 0] - xe[0, 0]
        by = xe[2, 1] - xe[0, 1]
        bz = xe[2, 2] - xe[0, 2]
        qx = xe[3, 0] - xe[0, 0]
        qy = xe[3, 1] - xe[0, 1]
        qz = xe[3, 2] - xe[0, 2]
        vol = abs(ax * (by * qz - bz * qy) - ay * (bx * qz - bz * qx) + az * (bx * qy - by * qx)) / 6.0
        amax = 0.0
        for (p, q, r) in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
            amax = max(amax, _half_cross_norm(xe, p, q, p, r))
        return 3.0 * vol / amax
    # hexahedron, dolfinx vertex order (tensor-product): faces by vertex quadruples, each
    # listed around its boundary so that diagonals are (p, r) and (q, s).
    vol = 0.0
    amax = 0.0
    faces = ((0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5))
    for (p, q, r, s) in faces:
        amax = max(amax, _half_cross_norm(xe, p, r, q, s))
    # volume as the sum of the 12 tetrahedra joining the centroid to the face triangles
    cx0 = 0.0
    cy0 = 0.0
    cz0 = 0.0
    for a in range(8):
        cx0 += xe[a, 0] / 8.0
        cy0 += xe[a, 1] / 8.0
        cz0 += xe[a, 2] / 8.0
    for (p, q, r, s) in faces:
        for (i0, i1, i2) in ((p, q, r), (p, r, s)):
            ax = xe[i0, 0] - cx0
            ay = xe[i0, 1] - cy0
            az = xe[i0, 2] - cz0
            bx = xe[i1, 0] - cx0
            by = xe[i1, 1] - cy0
            bz = xe[i1, 2] - cz0
            qx = xe[i2, 0] - cx0
            qy = xe[i2, 1] - cy0
            qz = xe[i2, 2] - cz0
            vol += abs(ax * (by * qz - bz * qy) - ay * (bx * qz - bz * qx) + az * (bx * qy - by * qx))
    vol = vol / 6.0
    return vol / amax / math.sqrt(3.0)


@njit(cache=True)
def characteristic_lengths(xc, cell_kind):
    """``characteristic_length`` of every cell; xc (cells, vertices, 3) vertex coordinates."""
    out = np.empty(xc.shape[0])
    for c in range(xc.shape[0]):
        out[c] = characteristic_length(xc[c], cell_kind, xc.shape[1])
    return out


@njit(cache=True)
def cell_orientation(dofmap, x, dN):
    """+1 or -1 per cell: the sign of det(J) at the first point in the reference configuration.

    Meshes may list a cell's vertices clockwise (det J < 0); integrals use |det J|, and a cell
    has inverted when det J changes sign from this one.
    """
    nn = dofmap.shape[1]
    gdim = x.shape[1]
    sign = np.empty(dofmap.shape[0])
    xe = np.empty((nn, 3))
    dNdx = np.empty((nn, 3))
    for c in range(dofmap.shape[0]):
        for a in range(nn):
            for i in range(gdim):
                xe[a, i] = x[dofmap[c, a], i]
        sign[c] = 1.0 if _gradients(xe, dN[0], gdim, nn, dNdx) > 0 else -1.0
    return sign


@njit(cache=True, fastmath=True)
def stress_divergence(cells, dofmap, cell_material, cell_sign, x_np1, v_half, dt, N, dN, wq, kinematics,
                      thickness, cell_kind, mean_dilatation, params, curves, state, sigma, f):
    """Update the stress of ``cells`` over one step and add their internal force to ``f``.

    Parameters
    ----------
    cells : (nc,) int32, the deformable cells this rank owns.
    dofmap : (num_cells, nn) int32, P1 node numbers of every cell.
    cell_material : (num_cells,) int32, row of ``params`` for every cell.
    cell_sign : (num_cells,) float64, ``cell_orientation`` of the reference mesh.
    x_np1 : (num_nodes, gdim) positions at t_{n+1} [m].
    v_half : (num_nodes, gdim) velocities at t_{n+1/2} [m/s].
    dt : step t_n -> t_{n+1} [s].
    N, dN : shape functions (nq, nn) and reference gradients (nq, nn, tdim) at the points.
    wq : (nq,) quadrature weights on the reference cell.
    kinematics : 0 plane strain, 1 axisymmetric, 2 3D.
    thickness : out-of-plane depth for plane strain [m] (ignored otherwise).
    cell_kind : 0 tri, 1 quad, 2 tet, 3 hex (for the characteristic length).
    mean_dilatation : replace each point's volumetric strain rate by the cell average
        (Nagtegaal, Parks & Rice 1974), which removes volumetric locking.
    params : (num_materials, NUM_PARAMS) material table (``columns.py``).
    curves : (num_materials, points, 2) hardening curves (plastic strain, stress) of plastic materials.
    state : (num_cells, nq, plasticity.STATE_SIZE) plastic state, updated in place (unused by
        elastic materials; may then be (1, 1, STATE_SIZE)).
    sigma : (num_cells, nq, 6) Cauchy stress, updated in place from t_n to t_{n+1}.
    f : (num_nodes, gdim) internal force, accumulated (caller zeroes it).

    Returns
    -------
    dt_stable : smallest stable step over ``cells`` at t_{n+1} (before the safety factor).
    critical_cell : the cell that sets it.
    damping_power : int sigma_visc : d dV, power of the stiffness-proportional damping [W].
    viscosity_power : int -q tr(d) dV, power of the bulk viscosity [W].
    plastic_work : int sigma : d eps_p dV over the step [J].
    bad_cell : a cell whose Jacobian changed sign (inverted) at t_{n+1}, or -1.
    """
    nq = wq.shape[0]
    nn = dofmap.shape[1]
    gdim = x_np1.shape[1]
    xe = np.empty((nn, 3))
    xm = np.empty((nn, 3))
    ve = np.empty((nn, 3))
    dNdx = np.empty((nn, 3))
    L = np.zeros((nq, 3, 3))
    wmid = np.empty(nq)
    d = np.empty(6)
    s = np.empty(6)
    two_pi = 2.0 * math.pi
    dt_stable = 1e300
    critical_cell = -1
    damping_power = 0.0
    viscosity_power = 0.0
    plastic_work = 0.0
    bad_cell = -1
    for ci in range(cells.shape[0]):
        c = cells[ci]
        m = cell_material[c]
        plastic = params[m, P_MODEL] == PLASTIC
        sgn = cell_sign[c]
        lam = params[m, P_LAMBDA]
        mu = params[m, P_MU]
        beta = params[m, P_BETA]
        for a in range(nn):
            node = dofmap[c, a]
            for i in range(gdim):
                xe[a, i] = x_np1[node, i]
                ve[a, i] = v_half[node, i]
                xm[a, i] = x_np1[node, i] - 0.5 * dt * v_half[node, i]
        # Pass 1: velocity gradient on the mid-step configuration.
        vol = 0.0
        div = 0.0
        for q in range(nq):
            det = _gradients(xm, dN[q], gdim, nn, dNdx) * sgn
            for i in range(3):
                for k in range(3):
                    L[q, i, k] = 0.0
            for i in range(gdim):
                for k in range(gdim):
                    t = 0.0
                    for a in range(nn):
                        t += ve[a, i] * dNdx[a, k]
                    L[q, i, k] = t
            w = wq[q] * det
            if kinematics == AXISYMMETRIC:
                r = 0.0
                vr = 0.0
                for a in range(nn):
                    r += N[q, a] * xm[a, 0]
                    vr += N[q, a] * ve[a, 0]
                L[q, 2, 2] = vr / r
                w *= two_pi * r
            wmid[q] = w
            vol += w
            div += w * (L[q, 0, 0] + L[q, 1, 1] + L[q, 2, 2])
        div_avg = div / vol
        le = characteristic_length(xe, cell_kind, nn)
        c_m = params[m, P_WAVE_SPEED]
        pq = bulk_viscosity(params[m, P_RHO], c_m, le, div_avg, params[m, P_Q_QUADRATIC], params[m, P_Q_LINEAR])
        # Pass 2: stress update and force on the end-of-step configuration.
        for q in range(nq):
            d[0] = L[q, 0, 0]
            d[1] = L[q, 1, 1]
            d[2] = L[q, 2, 2]
            d[3] = 0.5 * (L[q, 1, 2] + L[q, 2, 1])
            d[4] = 0.5 * (L[q, 0, 2] + L[q, 2, 0])
            d[5] = 0.5 * (L[q, 0, 1] + L[q, 1, 0])
            if mean_dilatation:
                shift = (div_avg - (d[0] + d[1] + d[2])) / 3.0
                d[0] += shift
                d[1] += shift
                d[2] += shift
            for k in range(6):
                s[k] = sigma[c, q, k]
            w23 = 0.5 * (L[q, 1, 2] - L[q, 2, 1])
            w13 = 0.5 * (L[q, 0, 2] - L[q, 2, 0])
            w12 = 0.5 * (L[q, 0, 1] - L[q, 1, 0])
            _rotate_hughes_winget(s, w23, w13, w12, dt)
            cd = _hooke(d[0], d[1], d[2], d[3], d[4], d[5], lam, mu)        # C : d
            for k in range(6):
                s[k] += dt * cd[k]
            if plastic:
                if params[m, P_KINEMATIC] > 0.0:
                    rotate_back_stress(state, c, q, w23, w13, w12, dt)
                s[0], s[1], s[2], s[3], s[4], s[5], wp = radial_return(
                    params, curves, m, state, c, q, s[0], s[1], s[2], s[3], s[4], s[5],
                    d[0], d[1], d[2], d[3], d[4], d[5], dt)
                plastic_work += wmid[q] * wp
            for k in range(6):
                sigma[c, q, k] = s[k]
            if beta > 0.0:
                # Stiffness-proportional (Rayleigh) damping: viscous stress beta * C : d.
                for k in range(6):
                    sv = beta * cd[k]
                    damping_power += wmid[q] * sv * d[k] * (1.0 if k < 3 else 2.0)
                    s[k] += sv
            if pq > 0.0:
                viscosity_power -= wmid[q] * pq * (d[0] + d[1] + d[2])
                s[0] -= pq
                s[1] -= pq
                s[2] -= pq
            det = _gradients(xe, dN[q], gdim, nn, dNdx) * sgn
            if det <= 0.0:
                bad_cell = c
            w = wq[q] * det
            if gdim == 2:
                if kinematics == AXISYMMETRIC:
                    r = 0.0
                    for a in range(nn):
                        r += N[q, a] * xe[a, 0]
                    w *= two_pi * r
                    hoop = s[2] / r
                    for a in range(nn):
                        node = dofmap[c, a]
                        f[node, 0] += w * (s[0] * dNdx[a, 0] + s[5] * dNdx[a, 1] + hoop * N[q, a])
                        f[node, 1] += w * (s[5] * dNdx[a, 0] + s[1] * dNdx[a, 1])
                else:
                    w *= thickness
                    for a in range(nn):
                        node = dofmap[c, a]
                        f[node, 0] += w * (s[0] * dNdx[a, 0] + s[5] * dNdx[a, 1])
                        f[node, 1] += w * (s[5] * dNdx[a, 0] + s[1] * dNdx[a, 1])
            else:
                for a in range(nn):
                    node = dofmap[c, a]
                    f[node, 0] += w * (s[0] * dNdx[a, 0] + s[5] * dNdx[a, 1] + s[4] * dNdx[a, 2])
                    f[node, 1] += w * (s[5] * dNdx[a, 0] + s[1] * dNdx[a, 1] + s[3] * dNdx[a, 2])
                    f[node, 2] += w * (s[4] * dNdx[a, 0] + s[3] * dNdx[a, 1] + s[2] * dNdx[a, 2])
        dtc = viscous_step(le, c_m, le, div_avg, params[m, P_Q_QUADRATIC], params[m, P_Q_LINEAR], beta)
        if dtc < dt_stable:
            dt_stable = dtc
            critical_cell = c
    return dt_stable, critical_cell, damping_power, viscosity_power, plastic_work, bad_cell
