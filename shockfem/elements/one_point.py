"""One-point (reduced) integration of quadrilaterals and hexahedra, with hourglass control.

This is the default solid of explicit codes (LS-DYNA's ELFORM=1, type 15 in axisymmetry):
stress at the cell centre only, so one strain-rate evaluation, one material update and one
force assembly per cell instead of four (eight), and no shear or volumetric locking.
The price is the hourglass modes, the nodal velocity patterns the centre point cannot see
(for a quad, u_a = s * xi_a * eta_a).  They are resisted as Flanagan & Belytschko (1981,
IJNME 17:679) prescribe, with the hourglass shape vectors made orthogonal to every linear
field so that the control never resists a real deformation:

    gamma^alpha_a = h^alpha_a - (sum_b h^alpha_b x_bi) b_ai,   b_ai = dN_a/dx_i at the centre
    q^alpha_i     = sum_a gamma^alpha_a v_ai                   hourglass rate
    f_ai         += sum_alpha gamma^alpha_a Q^alpha_i          Q the hourglass resultant

with h^alpha the products of the reference coordinates (xi eta for a quad; xi eta, eta zeta,
zeta xi, xi eta zeta for a hex), and Q either

* stiffness form:  Q += k dt q, k = eps (lambda + 2 mu) V (b:b) / n^2, rotated with the
  material like the stress (objective), energy stored and given back; or
* viscous form:    Q  = c q,    c = eps rho c_d V sqrt(b:b) / n, energy dissipated;

n the number of nodes and eps the user's coefficient (LS-DYNA's QH; 0.05 to 0.15 is usual).
For a square (cube) the stiffness form gives an hourglass mode 1.5 eps (1.1 eps) times the
stiffness a fully integrated element has for it (``docs/theory.md``).  The power of the
hourglass forces, Q . q per cell, is returned so that the hourglass energy is reported as
LS-DYNA reports it, and a run can be judged by its hourglass-to-internal energy ratio.

Axisymmetric quads carry the ring volume V = 2 pi r_c A and the hoop term sigma_tt N_a / r_c
with N_a = 1/4 at the centre; the hoop strain rate is v_r / r at the centre (of which a slotted
ring's metal takes what its slots leave, ``shockfem.materials.slotted``).  The stress update at the
centre is ``shockfem.materials.update.update_stress``, as in every element.

This module holds what the element's passes share (hourglass vectors, vertex order, the Walsh
transforms); the passes are ``one_point_quads.py`` and ``one_point_hexes.py``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..materials.layout import (P_BETA, P_LAMBDA, P_MU, P_Q_LINEAR, P_Q_QUADRATIC, P_RHO, P_WAVE_SPEED, S_EPS,
                                S_RATE)

HOURGLASS_FORMS = {"stiffness": 0, "viscous": 1}


def hourglass_vectors(vertices: np.ndarray) -> np.ndarray:
    """The base hourglass vectors h^alpha (modes, nodes) of a reference quad or hex.

    ``vertices`` are the reference vertex coordinates in [0, 1]^d in the mesh's vertex
    order; rows: xi eta (quad); xi eta, eta zeta, zeta xi, xi eta zeta (hex), xi = 2 X - 1.
    """
    xi = 2.0 * np.asarray(vertices, dtype=float) - 1.0
    if xi.shape[1] == 2:
        return np.ascontiguousarray((xi[:, 0] * xi[:, 1])[None, :])
    return np.ascontiguousarray(np.stack([xi[:, 0] * xi[:, 1], xi[:, 1] * xi[:, 2],
                                          xi[:, 2] * xi[:, 0], xi[:, 0] * xi[:, 1] * xi[:, 2]]))


def check_vertex_order(vertices: np.ndarray):
    """The kernels assume dolfinx's tensor-product vertex order, vertex a = i + 2 j (+ 4 k)."""
    v = np.asarray(vertices)
    d = v.shape[1]
    expected = np.array([[(a >> k) & 1 for k in range(d)] for a in range(2 ** d)], dtype=float)
    if not np.array_equal(v, expected):
        raise ValueError(f"one-point kernels need the tensor-product vertex order, got {v.tolist()}")


# Walsh transforms.  For vertex values y_a of a quad (hex) in tensor order, the signed sums
# sum_a y_a chi_m(a), chi = (1, xi, eta, xi eta[, zeta, xi zeta, eta zeta, xi eta zeta]),
# take 8 (24) additions.  At the centre of the [0, 1]^d reference cell dN_a/dX_k = xi_ak / 2
# (quad) or xi_ak / 4 (hex), so the Jacobian columns, the hourglass projections h.x and the
# hourglass rates h.v of a cell are all entries of these transforms; the nodal forces are the
# transposed transform of the cell's force coefficients.

@njit(cache=True, fastmath=True, inline="always")
def walsh4(y0, y1, y2, y3):
    a0 = y0 + y1
    a1 = y1 - y0
    a2 = y2 + y3
    a3 = y3 - y2
    return a0 + a2, a1 + a3, a2 - a0, a3 - a1


@njit(cache=True, fastmath=True, inline="always")
def unwalsh4(c0, c1, c2, c3):
    """f_a = c0 + c1 xi_a + c2 eta_a + c3 xi_a eta_a at the four vertices."""
    lo = c0 - c2
    dlo = c1 - c3
    hi = c0 + c2
    dhi = c1 + c3
    return lo - dlo, lo + dlo, hi - dhi, hi + dhi


@njit(cache=True, fastmath=True, inline="always")
def walsh8(y0, y1, y2, y3, y4, y5, y6, y7):
    a0, a1, a2, a3 = walsh4(y0, y1, y2, y3)
    b0, b1, b2, b3 = walsh4(y4, y5, y6, y7)
    return a0 + b0, a1 + b1, a2 + b2, a3 + b3, b0 - a0, b1 - a1, b2 - a2, b3 - a3


@njit(cache=True, fastmath=True, inline="always")
def inverse_2x2(j00, j01, j10, j11):
    det = j00 * j11 - j01 * j10
    idet = 1.0 / det
    return det, j11 * idet, -j01 * idet, -j10 * idet, j00 * idet


@njit(cache=True, fastmath=True, inline="always")
def step_length(nodes, bb):
    """c times the stable step of a uniform-strain element with lumped mass, 2 / sqrt(n b:b), from
    Flanagan & Belytschko's bound omega_max^2 <= n c^2 b:b (a square of side h: h / sqrt(2),
    LS-DYNA's area / longest diagonal; a cube: h / sqrt(3))."""
    return 2.0 / math.sqrt(nodes * bb)


# What the passes (``one_point_quads.py``, ``one_point_hexes.py``) share around their lanes.  Each keeps
# a cell's row constants in 7 consecutive scratch rows (lambda, mu, beta, rho, wave speed, the bulk
# viscosity's quadratic and linear coefficients; ``block_constants``) and its orientation in the next,
# and reports 7 consecutive rows per cell (signed volume, for a quad its signed area factor; the
# stresses' work; hourglass, damping and bulk viscosity powers; stable step; plastic work); lane k of
# row r is ``S[r * B + k]``.

@njit(cache=True, fastmath=True, inline="always")
def row6(S, row, B, k):
    """The 6-tuple (a stress or strain rate) in rows ``row``..``row`` + 5 of lane k."""
    return (S[row * B + k], S[(row + 1) * B + k], S[(row + 2) * B + k], S[(row + 3) * B + k],
            S[(row + 4) * B + k], S[(row + 5) * B + k])


@njit(cache=True, fastmath=True, inline="always")
def store6(S, row, B, k, s):
    """The 6-tuple ``s`` into rows ``row``..``row`` + 5 of lane k."""
    S[row * B + k] = s[0]
    S[(row + 1) * B + k] = s[1]
    S[(row + 2) * B + k] = s[2]
    S[(row + 3) * B + k] = s[3]
    S[(row + 4) * B + k] = s[4]
    S[(row + 5) * B + k] = s[5]


@njit(cache=True, fastmath=True, inline="always")
def gather_plastic_strain(S, row, B, cells, start, count, state):
    """The plastic strain at t_n of the block's cells ``cells[start:start + count]`` into row ``row``, for a
    J2 row's returns in lanes (the passes' ``_j2_lanes``)."""
    for k in range(count):
        S[row * B + k] = state[np.uint32(cells[start + k]), 0, S_EPS]


@njit(cache=True, fastmath=True, inline="always")
def scatter_plastic_strain(S, row, B, cells, start, count, state):
    """``_j2_lanes``' plastic strain at t_n+1 (row ``row``) and its rate (row ``row`` + 1) back into the
    block's cells' state."""
    for k in range(count):
        c = np.uint32(cells[start + k])
        state[c, 0, S_EPS] = S[row * B + k]
        state[c, 0, S_RATE] = S[(row + 1) * B + k]


@njit(cache=True, fastmath=True, inline="always")
def block_constants(S, row, B, cells, start, count, cell_material, params, one_row, block_material):
    """The row constants of the block's cells ``cells[start:start + count]`` into rows ``row``..``row`` + 6
    of lanes 0..count-1.  A block of one row's cells (``one_row``, all on ``block_material``: the usual
    block, a body's cells are numbered together) takes that row's 7 constants once; a mixed block takes
    each cell's own."""
    if one_row:
        m = block_material
        lam, mu, beta = params[m, P_LAMBDA], params[m, P_MU], params[m, P_BETA]
        rho, wave_speed = params[m, P_RHO], params[m, P_WAVE_SPEED]
        q_quadratic, q_linear = params[m, P_Q_QUADRATIC], params[m, P_Q_LINEAR]
        for k in range(count):
            S[row * B + k] = lam
            S[(row + 1) * B + k] = mu
            S[(row + 2) * B + k] = beta
            S[(row + 3) * B + k] = rho
            S[(row + 4) * B + k] = wave_speed
            S[(row + 5) * B + k] = q_quadratic
            S[(row + 6) * B + k] = q_linear
    else:
        for k in range(count):
            m = cell_material[cells[start + k]]
            S[row * B + k] = params[m, P_LAMBDA]
            S[(row + 1) * B + k] = params[m, P_MU]
            S[(row + 2) * B + k] = params[m, P_BETA]
            S[(row + 3) * B + k] = params[m, P_RHO]
            S[(row + 4) * B + k] = params[m, P_WAVE_SPEED]
            S[(row + 5) * B + k] = params[m, P_Q_QUADRATIC]
            S[(row + 6) * B + k] = params[m, P_Q_LINEAR]


@njit(cache=True, fastmath=True, inline="always")
def lane_index(row, B, k):
    """The index in ``S`` of row ``row`` of lane k, unsigned: numba wraps a signed index around (a compare and
    an add on every load and store), and in the gather and scatter below, loops over the nodes and their
    components, LLVM packs those wrap-arounds into vector registers and takes each index out of them again
    (docs/performance.md, "The element passes' block driver")."""
    return np.uint64(row * B) + np.uint64(k)


@njit(cache=True, fastmath=True, inline="always")
def gather_nodes(S, B, k, c, nodes, gdim, x_row, v_row, dofmap, x_np1, v_half):
    """Cell c's node positions and velocities into lane k: component i of node a at rows
    ``x_row + i * nodes + a`` and ``v_row + i * nodes + a``."""
    for a in range(nodes):
        node = np.uint32(dofmap[c, a])
        for i in range(gdim):
            S[lane_index(x_row + i * nodes + a, B, k)] = x_np1[node, i]
            S[lane_index(v_row + i * nodes + a, B, k)] = v_half[node, i]


@njit(cache=True, fastmath=True, inline="always")
def scatter_forces(S, B, k, c, nodes, gdim, f_row, dofmap, f):
    """Cell c's nodal forces (component i of node a at row ``f_row + i * nodes + a`` of lane k) added into
    ``f``."""
    for a in range(nodes):
        node = np.uint32(dofmap[c, a])
        for i in range(gdim):
            f[node, i] += S[lane_index(f_row + i * nodes + a, B, k)]


@njit(cache=True, fastmath=True, inline="always")
def spin3(S, row, B, k):
    """The spin (W23, W13, W12) in rows ``row``..``row`` + 2 of lane k."""
    return S[row * B + k], S[(row + 1) * B + k], S[(row + 2) * B + k]


@njit(cache=True, fastmath=True, inline="always")
def no_radius(S, B, k, kinematics):
    """A 3D cell's point has no radius (``blocks.LaneElement``'s ``radius``)."""
    return 0.0


# (dt_stable, critical_cell, damping_power, viscosity_power, plastic_work, hourglass_power, bad_cell)
# before the first cell: what a pass returns
NO_TOTALS = (1e300, -1, 0.0, 0.0, 0.0, 0.0, -1)


@njit(cache=True, fastmath=True, inline="always")
def add_cell_totals(totals, S, row, B, k, c, m, dt, body_energy):
    """``totals`` with cell c's reported rows (``row``..``row`` + 6 of lane k) added, in cell order, and its
    row ``m``'s energies into ``body_energy`` (the stresses' work, the hourglass work, the plastic work)."""
    dt_stable, critical_cell, damping_power, viscosity_power, plastic_work, hourglass_power, bad_cell = totals
    if S[row * B + k] <= 0.0:
        bad_cell = int(c)
    cell_hourglass = S[(row + 2) * B + k]
    cell_plastic = S[(row + 6) * B + k]
    body_energy[m, 0] += S[(row + 1) * B + k]
    body_energy[m, 1] += dt * cell_hourglass
    body_energy[m, 2] += cell_plastic
    dtc = S[(row + 5) * B + k]
    if dtc < dt_stable:
        dt_stable = dtc
        critical_cell = int(c)
    return (dt_stable, critical_cell, damping_power + S[(row + 3) * B + k], viscosity_power + S[(row + 4) * B + k],
            plastic_work + cell_plastic, hourglass_power + cell_hourglass, bad_cell)
