"""Linear tetrahedra in SIMD lanes: the constant-strain tet's pass, in blocks of cells as the one-point passes.

A P1 tetrahedron has one strain rate over the cell, so its one Gauss point is exact and it needs no
hourglass control.  ``full_integration.stress_divergence`` runs it as it runs any cell: shape-function
gradients through loops over scratch arrays, the characteristic length in a called function, the
material update cell by cell: 400-700 ns a tet on this machine, 65% of a 3D yawed fixture run and
most of the penetration study's lateral-pulse runs (``docs/performance.md``).  This pass
is the same element, formula for formula (``tests/unit/elements/test_linear_tets.py`` holds the two to
round-off, elastic and plastic), laid out as ``one_point_hexes.py``:

1. gather (scalar, through the dofmap) each cell's node positions and velocities, its stress and its
   row's constants into rows of one scratch array ``S``, row ``r`` of lane k at ``S[r * LANES + k]``;
2. kinematics lanes (``_rates``): the mid-step configuration x - dt/2 v, its gradients, the strain rate
   and spin on it (``cells.py``: a rigid rotation then gives an exactly skew velocity gradient), the
   mid-step volume, and the end-of-step Jacobian;
3. the material update (``materials.update``): every cell's elastic trial in lanes, which is the update
   of elastic rows and of J2 points inside their yield surface; a block of one J2 row of linear hardening
   returns in lanes too; the others cell by cell from their trial;
4. response lanes (``_response``): the end-of-step volume and gradients, LS-DYNA's length 3 V / largest
   face for the bulk viscosity and the stable step, the viscous stresses, the nodal forces, the energies;
5. scatter (scalar), in cell order: forces, stresses, the energy sums and the smallest step.

As ``stress_divergence`` does, the stresses' work, the plastic work and the viscous powers take the
mid-step volume, and the forces the end-of-step one.  The reference tet is basix's, vertices (0,0,0),
(1,0,0), (0,1,0), (0,0,1): dN_0 = (-1, -1, -1) and dN_k = e_k, so J's columns are x_k - x_0 and the
spatial gradients are J^-1's rows (node k) and minus their sum (node 0).  The lanes raise nothing
(numpy's error model, as ``one_point_quads.py`` explains): a flat cell gives infinite forces, reported
as an inverted cell (its volume is not positive) or as a non-finite state by the nodal pass.
"""
from __future__ import annotations

import math

from numba import njit

from ..materials.algebra import inverse_3x3
from ..materials.j2 import linear_hardening_return
from ..materials.update import elastic_update_stress
from ..materials.viscosity import bulk_viscosity, viscous_step, viscous_stress_of
from .blocks import LaneElement, lane_passes, von_mises2
from .one_point import no_radius, row6, spin3, store6

# Cells a block: the scratch rows of 32 tets (23 kB) stay in the first-level cache.
LANES = 32

# Rows of the scratch array.  Gathered: node positions x, y, z and velocities u, v, w (four nodes each),
# the stress at t_n (11, 22, 33, 23, 13, 12), the row's constants (``one_point.block_constants``), the
# orientation.
_X, _Y, _Z, _U, _V, _W, _S = 0, 4, 8, 12, 16, 20, 24
_LAM, _MU, _BETA, _RHO, _C, _Q1, _Q2, _SIGN = range(30, 38)
# Kinematics: the end-of-step Jacobian (row-major), the strain rate and spin (W23, W13, W12) on the
# mid-step configuration and its volume; from the material update the stress at t_n+1 and the plastic
# work density.
_J, _D, _SPIN, _VMID, _SN, _WP = 38, 47, 53, 56, 57, 63
# Response: nodal forces (x of the four nodes, then y, then z), then ``one_point.add_cell_totals``' seven
# rows: the end-of-step volume (<= 0: inverted), the stresses' work, the hourglass power (none: 0), the
# damping and bulk viscosity powers, the stable step, the plastic work; then the squared von Mises stress at
# t_n+1 (``blocks``).
_F, _VOL, _WORK, _HG, _DAMP, _VISC, _DT, _PLASTIC, _VM2 = 64, 76, 77, 78, 79, 80, 81, 82, 83
# A J2 row of linear hardening returns in lanes: the plastic strain at t_n in, at t_n+1 out, its rate next
_EPS, _RATE = 84, 85
ROWS = 86


@njit(cache=True, fastmath=True, inline="always")
def _edges(S, row, B, k, hdt, vrow):
    """The three edges x_1 - x_0, x_2 - x_0, x_3 - x_0 of one component (rows ``row``..+3 of lane k), of the
    configuration x - hdt v (velocities in rows ``vrow``..+3; hdt = 0: the end of the step)."""
    y0 = S[row * B + k] - hdt * S[vrow * B + k]
    return (S[(row + 1) * B + k] - hdt * S[(vrow + 1) * B + k] - y0,
            S[(row + 2) * B + k] - hdt * S[(vrow + 2) * B + k] - y0,
            S[(row + 3) * B + k] - hdt * S[(vrow + 3) * B + k] - y0)


@njit(cache=True, fastmath=True, inline="always")
def _velocity_gradient(S, vrow, B, k, i):
    """Row i of L = sum_a v_a dN_a/dx (velocities of one component in rows ``vrow``..+3 of lane k; ``i`` the
    inverse Jacobian's rows): node k's gradient is J^-1's row k - 1, node 0's minus their sum."""
    u0 = S[vrow * B + k]
    u1, u2, u3 = S[(vrow + 1) * B + k] - u0, S[(vrow + 2) * B + k] - u0, S[(vrow + 3) * B + k] - u0
    return (u1 * i[0] + u2 * i[3] + u3 * i[6], u1 * i[1] + u2 * i[4] + u3 * i[7], u1 * i[2] + u2 * i[5] + u3 * i[8])


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _rates(S, nb, dt, wq):
    """The kinematics lanes (module docstring)."""
    B = LANES
    hdt = 0.5 * dt
    for k in range(nb):
        ax, bx, cx = _edges(S, _X, B, k, hdt, _U)
        ay, by, cy = _edges(S, _Y, B, k, hdt, _V)
        az, bz, cz = _edges(S, _Z, B, k, hdt, _W)
        det, i00, i01, i02, i10, i11, i12, i20, i21, i22 = inverse_3x3(ax, bx, cx, ay, by, cy, az, bz, cz)
        inv = (i00, i01, i02, i10, i11, i12, i20, i21, i22)
        l00, l01, l02 = _velocity_gradient(S, _U, B, k, inv)
        l10, l11, l12 = _velocity_gradient(S, _V, B, k, inv)
        l20, l21, l22 = _velocity_gradient(S, _W, B, k, inv)
        S[_VMID * B + k] = wq * det * S[_SIGN * B + k]
        store6(S, _D, B, k, (l00, l11, l22, 0.5 * (l12 + l21), 0.5 * (l02 + l20), 0.5 * (l01 + l10)))
        S[_SPIN * B + k] = 0.5 * (l12 - l21)
        S[(_SPIN + 1) * B + k] = 0.5 * (l02 - l20)
        S[(_SPIN + 2) * B + k] = 0.5 * (l01 - l10)
        ax, bx, cx = _edges(S, _X, B, k, 0.0, _U)
        ay, by, cy = _edges(S, _Y, B, k, 0.0, _V)
        az, bz, cz = _edges(S, _Z, B, k, 0.0, _W)
        store6(S, _J, B, k, (ax, bx, cx, ay, by, cy))
        S[(_J + 6) * B + k] = az
        S[(_J + 7) * B + k] = bz
        S[(_J + 8) * B + k] = cz


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _elastic(S, nb, dt):
    """Every cell's elastic trial stress, in lanes (``materials.update.elastic_update_stress``)."""
    B = LANES
    for k in range(nb):
        s = elastic_update_stress(row6(S, _S, B, k), row6(S, _D, B, k),
                                  (S[_SPIN * B + k], S[(_SPIN + 1) * B + k], S[(_SPIN + 2) * B + k]), dt,
                                  S[_LAM * B + k], S[_MU * B + k])
        store6(S, _SN, B, k, s)
        S[_WP * B + k] = 0.0


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _j2_lanes(S, nb, dt, mu, y0, eps0, slope):
    """Every cell's J2 return from its elastic trial, in lanes, for a block of one J2 row of linear hardening
    (``one_point_quads._j2_lanes``, which says more)."""
    B = LANES
    for k in range(nb):
        s, eps, rate, work = linear_hardening_return(row6(S, _SN, B, k), S[_EPS * B + k], mu, y0, eps0, slope, dt)
        store6(S, _SN, B, k, s)
        S[_EPS * B + k] = eps
        S[_RATE * B + k] = rate
        S[_WP * B + k] = work


@njit(cache=True, fastmath=True, inline="always")
def _half_cross_norm(ax, ay, az, bx, by, bz):
    """|a x b| / 2: the area of the triangle on edges a and b."""
    cx = ay * bz - az * by
    cy = az * bx - ax * bz
    cz = ax * by - ay * bx
    return 0.5 * math.sqrt(cx * cx + cy * cy + cz * cz)


@njit(cache=True, fastmath=True, inline="always")
def _store_forces(S, row, B, k, g):
    """One component's forces on the four nodes into rows ``row``..+3 of lane k, from nodes 1-3's (``g``):
    node 0's gradient is minus the others' sum, and so is its force."""
    S[row * B + k] = -(g[0] + g[1] + g[2])
    S[(row + 1) * B + k] = g[0]
    S[(row + 2) * B + k] = g[1]
    S[(row + 3) * B + k] = g[2]


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _response(S, nb, dt, wq):
    """The response lanes: end-of-step gradients, viscous stresses, nodal forces, energies, stable step."""
    B = LANES
    for k in range(nb):
        j = (S[_J * B + k], S[(_J + 1) * B + k], S[(_J + 2) * B + k], S[(_J + 3) * B + k], S[(_J + 4) * B + k],
             S[(_J + 5) * B + k], S[(_J + 6) * B + k], S[(_J + 7) * B + k], S[(_J + 8) * B + k])
        det, i00, i01, i02, i10, i11, i12, i20, i21, i22 = inverse_3x3(j[0], j[1], j[2], j[3], j[4], j[5], j[6],
                                                                        j[7], j[8])
        vol = wq * det * S[_SIGN * B + k]
        S[_VOL * B + k] = vol
        # LS-DYNA's length of a tet, 3 V / its largest face (``cells.characteristic_length``): the faces
        # (0,1,2), (0,1,3), (0,2,3) on the edges from node 0, J's columns, and (1,2,3) on x_2 - x_1, x_3 - x_1
        area = max(max(_half_cross_norm(j[0], j[3], j[6], j[1], j[4], j[7]),
                       _half_cross_norm(j[0], j[3], j[6], j[2], j[5], j[8])),
                   max(_half_cross_norm(j[1], j[4], j[7], j[2], j[5], j[8]),
                       _half_cross_norm(j[1] - j[0], j[4] - j[3], j[7] - j[6], j[2] - j[0], j[5] - j[3],
                                        j[8] - j[6])))
        length = 0.5 * abs(det) / area
        w_mid = S[_VMID * B + k]
        a = row6(S, _S, B, k)
        s_np1 = row6(S, _SN, B, k)
        S[_VM2 * B + k] = von_mises2(s_np1)
        d = row6(S, _D, B, k)
        lam, mu, rho, wave_speed = S[_LAM * B + k], S[_MU * B + k], S[_RHO * B + k], S[_C * B + k]
        q_quadratic, q_linear, beta = S[_Q1 * B + k], S[_Q2 * B + k], S[_BETA * B + k]
        S[_PLASTIC * B + k] = w_mid * S[_WP * B + k]
        S[_WORK * B + k] = 0.5 * dt * w_mid * (
            (a[0] + s_np1[0]) * d[0] + (a[1] + s_np1[1]) * d[1] + (a[2] + s_np1[2]) * d[2]
            + 2.0 * ((a[3] + s_np1[3]) * d[3] + (a[4] + s_np1[4]) * d[4] + (a[5] + s_np1[5]) * d[5]))
        S[_HG * B + k] = 0.0
        trd = d[0] + d[1] + d[2]
        pq = bulk_viscosity(rho, wave_speed, length, trd, q_quadratic, q_linear)
        (s0, s1, s2, s3, s4, s5), pd, pv = viscous_stress_of(s_np1, d, pq, lam, mu, beta)
        S[_DAMP * B + k] = w_mid * pd
        S[_VISC * B + k] = w_mid * pv
        # f_a = V sigma grad N_a: node k's gradient J^-1's row k - 1, node 0's minus their sum
        for_x = (vol * (s0 * i00 + s5 * i01 + s4 * i02), vol * (s0 * i10 + s5 * i11 + s4 * i12),
                 vol * (s0 * i20 + s5 * i21 + s4 * i22))
        for_y = (vol * (s5 * i00 + s1 * i01 + s3 * i02), vol * (s5 * i10 + s1 * i11 + s3 * i12),
                 vol * (s5 * i20 + s1 * i21 + s3 * i22))
        for_z = (vol * (s4 * i00 + s3 * i01 + s2 * i02), vol * (s4 * i10 + s3 * i11 + s2 * i12),
                 vol * (s4 * i20 + s3 * i21 + s2 * i22))
        _store_forces(S, _F, B, k, for_x)
        _store_forces(S, _F + 4, B, k, for_y)
        _store_forces(S, _F + 8, B, k, for_z)
        S[_DT * B + k] = viscous_step(length, wave_speed, length, trd, q_quadratic, q_linear, beta)


@njit(cache=True, fastmath=True, inline="always")
def _rates_phase(S, count, dt, kinematics, weight):
    """The kinematics lanes, with the rule's weight (1/6, the reference tet's volume)."""
    _rates(S, count, dt, weight)


@njit(cache=True, fastmath=True, inline="always")
def _response_phase(S, count, dt, kinematics, thickness, weight, hourglass_form, hourglass_coefficient):
    """The response lanes, with the rule's weight."""
    _response(S, count, dt, weight)


# Linear tetrahedra for ``blocks.lane_pass``, with ``full_integration.stress_divergence``'s arguments and
# returns (its hourglass power 0), so that a solver calls either.  Of the rule it takes the weight ``wq[0]``
# (1/6, the reference tet's volume); ``N``, ``dN``, ``kinematics`` (3D), ``thickness``, ``cell_kind``,
# ``mean_dilatation`` (one point: nothing to average), ``hourglass_form``, ``hourglass_coefficient`` and
# ``hourglass`` say nothing a tet does not fix.
TETS = LaneElement(name="tet", source=__file__, lanes=LANES, nodes=4, gdim=3, rows=ROWS,
                   x_row=_X, v_row=_U, s_row=_S, stress_components=(0, 1, 2, 3, 4, 5), o_row=0,
                   hourglass_modes=0, constants_row=_LAM, sn_row=_SN, f_row=_F, q_row=0,
                   totals_row=_VOL, eps_row=_EPS, d_row=_D, spin_row=_SPIN, wp_row=_WP, rates=_rates_phase,
                   elastic=_elastic, j2=_j2_lanes, response=_response_phase, tensor6=row6, store_stress=store6,
                   spin3=spin3, radius=no_radius)
TET_KERNELS = lane_passes(TETS)
