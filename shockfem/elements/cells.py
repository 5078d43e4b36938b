"""Cell geometry the element kernels share: kinematics codes, shape-function gradients, the
characteristic length that sets an element's stable step, and cell orientation.

Conventions of every element kernel (``full_integration.py``, ``one_point.py``):

* Nodal arrays are in dolfinx P1 *block* order (one block = one node), shape
  ``(num_nodes, gdim)``; ``dofmap`` is the P1 dofmap, ``(num_cells, nodes_per_cell)``.
* Stress is stored per quadrature point as 6 components ``[s11, s22, s33, s23, s13, s12]``; in 2D,
  index 2 is the out-of-plane (plane strain) or hoop (axisymmetric, coordinates (r, z)) component.
* Kinematics codes: 0 plane strain, 1 axisymmetric, 2 three-dimensional.
* Strain rates are taken on the mid-step configuration x_{n+1/2}: with central differences this
  makes the velocity gradient of a rigid rotation exactly skew (Cayley transform), so together with
  the objective update of ``shockfem.materials.objective`` a spinning body keeps zero stress.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

PLANE_STRAIN, AXISYMMETRIC, THREE_D = 0, 1, 2
# cell kinds, as ``characteristic_length`` and the passes take them
TRIANGLE, QUADRILATERAL, TETRAHEDRON, HEXAHEDRON = 0, 1, 2, 3


@njit(cache=True, fastmath=True, inline="always")
def gradients_2d(xe, dNq, nn, dNdx):
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
def gradients_3d(xe, dNq, nn, dNdx):
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
def gradients(xe, dNq, gdim, nn, dNdx):
    if gdim == 2:
        return gradients_2d(xe, dNq, nn, dNdx)
    return gradients_3d(xe, dNq, nn, dNdx)


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


def cell_orientation(dofmap, x, dN):
    """+1 or -1 per cell: the sign of det(J) at the first point in the reference configuration.

    Meshes may list a cell's vertices clockwise (det J < 0); integrals use |det J|, and a cell
    has inverted when det J changes sign from this one.  In numpy, over all cells at once, with
    ``gradients``' sums in its order (node by node) and its determinant: it runs once a model, and compiled
    it would add 2-3 s to every first run's compile (docs/performance.md, "Compile time").
    """
    nn = dofmap.shape[1]
    gdim = x.shape[1]
    dN0 = dN[0]
    J = np.zeros((gdim, gdim, dofmap.shape[0]))       # J[i, k] = sum_a x_a,i dN_a,k
    for a in range(nn):
        xa = x[dofmap[:, a]]
        for i in range(gdim):
            for k in range(gdim):
                J[i, k] += xa[:, i] * dN0[a, k]
    if gdim == 2:
        det = J[0, 0] * J[1, 1] - J[0, 1] * J[1, 0]
    else:
        det = (J[0, 0] * (J[1, 1] * J[2, 2] - J[1, 2] * J[2, 1]) + J[1, 0] * (J[0, 2] * J[2, 1] - J[0, 1] * J[2, 2])
               + J[2, 0] * (J[0, 1] * J[1, 2] - J[0, 2] * J[1, 1]))
    return np.where(det > 0, 1.0, -1.0)
