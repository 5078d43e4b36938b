"""One-point hexahedra in SIMD lanes: the 3D pass, in blocks of cells as the quads' pass.

The element is ``one_point.py``'s (Flanagan & Belytschko's four hourglass modes xi eta, eta zeta,
zeta xi, xi eta zeta, each with a 3-vector resultant); the structure is ``one_point_quads.py``'s:
gather a block of ``LANES`` cells into rows of one scratch array, the kinematics lanes, the material
update (the elastic trial in lanes, which is the update of elastic rows and of J2 points inside their
yield surface; the others cell by cell), the response lanes, scatter in cell order.  The same conditions make numba's LLVM vectorise the lanes (numpy error model, each
lane loop a function of its own called with the lane count); the lanes raise nothing, so a cell of
zero volume is reported as inverted or the state as non-finite, as for the quads.
"""
from __future__ import annotations

import math

from numba import njit

from ..materials.algebra import inverse_3x3
from ..materials.j2 import linear_hardening_return
from ..materials.objective import cayley_matrix
from ..materials.update import elastic_update_stress
from ..materials.viscosity import bulk_viscosity, viscous_step, viscous_stress_of
from .blocks import LaneElement, lane_passes, von_mises2
from .one_point import no_radius, row6, spin3, step_length, store6, unwalsh4, walsh8

# Cells a block: the scratch rows of 16 hexes (22 kB) stay in the first-level cache.
LANES = 16

# Rows of the scratch array.  Gathered: node positions x, y, z and velocities u, v, w (eight nodes
# each), the stress at t_n (11, 22, 33, 23, 13, 12), the hourglass resultants of the last step (mode-
# major, 3 components a mode), the row's constants, the orientation.
_X, _Y, _Z, _U, _V, _W, _S, _O = 0, 8, 16, 24, 32, 40, 48, 54
_LAM, _MU, _BETA, _RHO, _C, _Q1, _Q2, _SIGN = range(66, 74)   # ``one_point.block_constants``', the orientation
# Kinematics: J and Jv at the centre (row-major), hourglass projections h.x and rates h.v (mode-major),
# the strain rate and spin (W23, W13, W12) on the mid-step configuration; from the material update
# the stress at t_n+1 and the plastic work density.
_J, _JV, _HX, _HV, _D, _SPIN, _SN, _WP = 74, 83, 92, 104, 116, 122, 125, 131
# Response: nodal forces (x of the eight nodes, then y, then z), hourglass resultants, the volume (<= 0:
# inverted), the stresses' work, the hourglass, damping and bulk viscosity powers, the stable step,
# the plastic work (``one_point.add_cell_totals``'s order from the volume), the squared von Mises stress at
# t_n+1 (``blocks``: the totals' rows, then it).
_F, _Q, _VOL, _WORK, _HG, _DAMP, _VISC, _DT, _PLASTIC, _VM2 = 132, 156, 168, 169, 170, 171, 172, 173, 174, 175
# A J2 row of linear hardening (``materials.update.linear_hardening``) returns in lanes: the plastic strain
# at t_n in, at t_n+1 out, and its rate in the next row (``one_point.scatter_plastic_strain``)
_EPS, _RATE = 176, 177
ROWS = 178


# The lane loops hold no inner loops: LLVM vectorises innermost loops only, and a loop over a tuple's
# entries (a switch) is not unrolled before it; rows are read and written by these instead.
@njit(cache=True, fastmath=True, inline="always")
def _store3(S, row, B, k, a, b, c):
    S[row * B + k] = a
    S[(row + 1) * B + k] = b
    S[(row + 2) * B + k] = c


@njit(cache=True, fastmath=True, inline="always")
def _load3(S, row, B, k):
    return S[row * B + k], S[(row + 1) * B + k], S[(row + 2) * B + k]


@njit(cache=True, fastmath=True, inline="always")
def _walsh8_rows(S, row, B, k):
    """``one_point.walsh8`` of the eight nodes' values in rows ``row``..``row`` + 7 of lane k."""
    return walsh8(S[row * B + k], S[(row + 1) * B + k], S[(row + 2) * B + k], S[(row + 3) * B + k],
                  S[(row + 4) * B + k], S[(row + 5) * B + k], S[(row + 6) * B + k], S[(row + 7) * B + k])


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _rates(S, nb, dt):
    """The kinematics lanes (module docstring)."""
    B = LANES
    hdt = 0.5 * dt
    for k in range(nb):
        # transforms of x and v per component: entries 1, 2, 4 are 4 J[i, :] (dN0_a = xi_a / 4);
        # 3, 6, 5, 7 the hourglass projections
        tx, ty, tz = _walsh8_rows(S, _X, B, k), _walsh8_rows(S, _Y, B, k), _walsh8_rows(S, _Z, B, k)
        ux, uy, uz = _walsh8_rows(S, _U, B, k), _walsh8_rows(S, _V, B, k), _walsh8_rows(S, _W, B, k)
        j00, j01, j02 = 0.25 * tx[1], 0.25 * tx[2], 0.25 * tx[4]
        j10, j11, j12 = 0.25 * ty[1], 0.25 * ty[2], 0.25 * ty[4]
        j20, j21, j22 = 0.25 * tz[1], 0.25 * tz[2], 0.25 * tz[4]
        v00, v01, v02 = 0.25 * ux[1], 0.25 * ux[2], 0.25 * ux[4]
        v10, v11, v12 = 0.25 * uy[1], 0.25 * uy[2], 0.25 * uy[4]
        v20, v21, v22 = 0.25 * uz[1], 0.25 * uz[2], 0.25 * uz[4]
        _store3(S, _J, B, k, j00, j01, j02)
        _store3(S, _J + 3, B, k, j10, j11, j12)
        _store3(S, _J + 6, B, k, j20, j21, j22)
        _store3(S, _JV, B, k, v00, v01, v02)
        _store3(S, _JV + 3, B, k, v10, v11, v12)
        _store3(S, _JV + 6, B, k, v20, v21, v22)
        # the hourglass modes xi eta, eta zeta, zeta xi, xi eta zeta are the transforms' entries 3, 6, 5, 7
        _store3(S, _HX, B, k, tx[3], ty[3], tz[3])
        _store3(S, _HX + 3, B, k, tx[6], ty[6], tz[6])
        _store3(S, _HX + 6, B, k, tx[5], ty[5], tz[5])
        _store3(S, _HX + 9, B, k, tx[7], ty[7], tz[7])
        _store3(S, _HV, B, k, ux[3], uy[3], uz[3])
        _store3(S, _HV + 3, B, k, ux[6], uy[6], uz[6])
        _store3(S, _HV + 6, B, k, ux[5], uy[5], uz[5])
        _store3(S, _HV + 9, B, k, ux[7], uy[7], uz[7])
        # strain rate on the mid-step configuration: L = Jv J_mid^-1, J_mid = J - dt/2 Jv
        (_, i00, i01, i02, i10, i11, i12, i20, i21, i22) = inverse_3x3(
            j00 - hdt * v00, j01 - hdt * v01, j02 - hdt * v02, j10 - hdt * v10, j11 - hdt * v11,
            j12 - hdt * v12, j20 - hdt * v20, j21 - hdt * v21, j22 - hdt * v22)
        l00 = v00 * i00 + v01 * i10 + v02 * i20
        l01 = v00 * i01 + v01 * i11 + v02 * i21
        l02 = v00 * i02 + v01 * i12 + v02 * i22
        l10 = v10 * i00 + v11 * i10 + v12 * i20
        l11 = v10 * i01 + v11 * i11 + v12 * i21
        l12 = v10 * i02 + v11 * i12 + v12 * i22
        l20 = v20 * i00 + v21 * i10 + v22 * i20
        l21 = v20 * i01 + v21 * i11 + v22 * i21
        l22 = v20 * i02 + v21 * i12 + v22 * i22
        S[_D * B + k] = l00
        S[(_D + 1) * B + k] = l11
        S[(_D + 2) * B + k] = l22
        S[(_D + 3) * B + k] = 0.5 * (l12 + l21)
        S[(_D + 4) * B + k] = 0.5 * (l02 + l20)
        S[(_D + 5) * B + k] = 0.5 * (l01 + l10)
        S[_SPIN * B + k] = 0.5 * (l12 - l21)
        S[(_SPIN + 1) * B + k] = 0.5 * (l02 - l20)
        S[(_SPIN + 2) * B + k] = 0.5 * (l01 - l10)


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _j2_lanes(S, nb, dt, mu, y0, eps0, slope):
    """Every cell's J2 return from its elastic trial, in lanes, for a block of one J2 row of linear hardening
    (``one_point_quads._j2_lanes``, which says more)."""
    B = LANES
    for k in range(nb):
        s, eps, rate, work = linear_hardening_return(row6(S, _SN, B, k), S[_EPS * B + k], mu, y0, eps0, slope, dt)
        _store3(S, _SN, B, k, s[0], s[1], s[2])
        _store3(S, _SN + 3, B, k, s[3], s[4], s[5])
        S[_EPS * B + k] = eps
        S[_RATE * B + k] = rate
        S[_WP * B + k] = work


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _elastic(S, nb, dt):
    """Every cell's elastic trial stress, in lanes (``materials.update.elastic_update_stress``): the update
    of elastic rows without slots, and of the points ``materials.update.elastic_trial_holds`` accepts."""
    B = LANES
    for k in range(nb):
        s = elastic_update_stress(row6(S, _S, B, k), row6(S, _D, B, k),
                                  (S[_SPIN * B + k], S[(_SPIN + 1) * B + k], S[(_SPIN + 2) * B + k]), dt,
                                  S[_LAM * B + k], S[_MU * B + k])
        _store3(S, _SN, B, k, s[0], s[1], s[2])
        _store3(S, _SN + 3, B, k, s[3], s[4], s[5])
        S[_WP * B + k] = 0.0


@njit(cache=True, fastmath=True, inline="always")
def _hourglass_mode(S, B, k, m, e, rot, coef, dt, hourglass_form):
    """Hourglass mode at offset ``m`` (0, 3, 6, 9) of lane k: its rate q = h.v - L_end (h.x), its resultant
    Q (stored), and (Q, the trapezoidal power (Q_n + Q_n+1)/2 . q, h.x) returned."""
    hx0, hx1, hx2 = _load3(S, _HX + m, B, k)
    hv0, hv1, hv2 = _load3(S, _HV + m, B, k)
    o0, o1, o2 = _load3(S, _O + m, B, k)
    q0 = hv0 - e[0] * hx0 - e[1] * hx1 - e[2] * hx2
    q1 = hv1 - e[3] * hx0 - e[4] * hx1 - e[5] * hx2
    q2 = hv2 - e[6] * hx0 - e[7] * hx1 - e[8] * hx2
    if hourglass_form == 1:
        Q0 = coef * q0
        Q1 = coef * q1
        Q2 = coef * q2
    else:
        Q0 = rot[0] * o0 + rot[1] * o1 + rot[2] * o2 + coef * dt * q0
        Q1 = rot[3] * o0 + rot[4] * o1 + rot[5] * o2 + coef * dt * q1
        Q2 = rot[6] * o0 + rot[7] * o1 + rot[8] * o2 + coef * dt * q2
    _store3(S, _Q + m, B, k, Q0, Q1, Q2)
    return Q0, Q1, Q2, 0.5 * ((o0 + Q0) * q0 + (o1 + Q1) * q1 + (o2 + Q2) * q2), hx0, hx1, hx2


@njit(cache=True, fastmath=True, inline="always")
def _component_forces(S, B, k, row, ta, tb, tc, inv, qa, qb, qc, qd):
    """One component's forces on the eight nodes (rows ``row``..+7) from its row (ta, tb, tc) of S and
    the component of the four resultants."""
    m0 = 0.25 * (inv[0] * ta + inv[1] * tb + inv[2] * tc)
    m1 = 0.25 * (inv[3] * ta + inv[4] * tb + inv[5] * tc)
    m2 = 0.25 * (inv[6] * ta + inv[7] * tb + inv[8] * tc)
    lo0, lo1, lo2, lo3 = unwalsh4(-m2, m0 - qc, m1 - qb, qa - qd)
    hi0, hi1, hi2, hi3 = unwalsh4(m2, m0 + qc, m1 + qb, qa + qd)
    S[row * B + k] = lo0
    S[(row + 1) * B + k] = lo1
    S[(row + 2) * B + k] = lo2
    S[(row + 3) * B + k] = lo3
    S[(row + 4) * B + k] = hi0
    S[(row + 5) * B + k] = hi1
    S[(row + 6) * B + k] = hi2
    S[(row + 7) * B + k] = hi3


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _response(S, nb, dt, hourglass_form, hourglass_coefficient):
    """The response lanes: viscous stresses, hourglass resultants, nodal forces, energies, stable step."""
    B = LANES
    for k in range(nb):
        j = (S[_J * B + k], S[(_J + 1) * B + k], S[(_J + 2) * B + k], S[(_J + 3) * B + k], S[(_J + 4) * B + k],
             S[(_J + 5) * B + k], S[(_J + 6) * B + k], S[(_J + 7) * B + k], S[(_J + 8) * B + k])
        v00, v01, v02 = S[_JV * B + k], S[(_JV + 1) * B + k], S[(_JV + 2) * B + k]
        v10, v11, v12 = S[(_JV + 3) * B + k], S[(_JV + 4) * B + k], S[(_JV + 5) * B + k]
        v20, v21, v22 = S[(_JV + 6) * B + k], S[(_JV + 7) * B + k], S[(_JV + 8) * B + k]
        a = row6(S, _S, B, k)
        s_np1 = row6(S, _SN, B, k)
        S[_VM2 * B + k] = von_mises2(s_np1)
        d = row6(S, _D, B, k)
        lam, mu, rho, wave_speed = S[_LAM * B + k], S[_MU * B + k], S[_RHO * B + k], S[_C * B + k]
        q_quadratic, q_linear, beta = S[_Q1 * B + k], S[_Q2 * B + k], S[_BETA * B + k]
        # end-of-step configuration
        (det, i00, i01, i02, i10, i11, i12, i20, i21, i22) = inverse_3x3(j[0], j[1], j[2], j[3], j[4], j[5], j[6],
                                                                          j[7], j[8])
        vol = det * S[_SIGN * B + k]
        S[_VOL * B + k] = vol
        S[_PLASTIC * B + k] = vol * S[_WP * B + k]
        S[_WORK * B + k] = 0.5 * dt * vol * (
            (a[0] + s_np1[0]) * d[0] + (a[1] + s_np1[1]) * d[1] + (a[2] + s_np1[2]) * d[2]
            + 2.0 * ((a[3] + s_np1[3]) * d[3] + (a[4] + s_np1[4]) * d[4] + (a[5] + s_np1[5]) * d[5]))
        # hourglass: q^alpha = h^alpha.v - L_end (h^alpha.x), L_end = Jv J^-1, resultants Q^alpha
        e00 = v00 * i00 + v01 * i10 + v02 * i20
        e01 = v00 * i01 + v01 * i11 + v02 * i21
        e02 = v00 * i02 + v01 * i12 + v02 * i22
        e10 = v10 * i00 + v11 * i10 + v12 * i20
        e11 = v10 * i01 + v11 * i11 + v12 * i21
        e12 = v10 * i02 + v11 * i12 + v12 * i22
        e20 = v20 * i00 + v21 * i10 + v22 * i20
        e21 = v20 * i01 + v21 * i11 + v22 * i21
        e22 = v20 * i02 + v21 * i12 + v22 * i22
        bb = 0.5 * (i00 * i00 + i01 * i01 + i02 * i02 + i10 * i10 + i11 * i11 + i12 * i12
                    + i20 * i20 + i21 * i21 + i22 * i22)          # b:b, sum_a dN0_a dN0_a^T = I / 2
        ls = step_length(8.0, bb)
        trd = d[0] + d[1] + d[2]
        # the viscosity's length is LS-DYNA's volume / largest face, sqrt(3) ls for a cube
        pq = bulk_viscosity(rho, wave_speed, math.sqrt(3.0) * ls, trd, q_quadratic, q_linear)
        (s0, s1, s2, s3, s4, s5), pd, pv = viscous_stress_of(s_np1, d, pq, lam, mu, beta)
        S[_DAMP * B + k] = vol * pd
        S[_VISC * B + k] = vol * pv
        # the stiffness-form resultants turn with the material, like the stress
        r00, r01, r02, r10, r11, r12, r20, r21, r22 = cayley_matrix(S[_SPIN * B + k], S[(_SPIN + 1) * B + k],
                                                                    S[(_SPIN + 2) * B + k], dt)
        if hourglass_form == 1:
            coef = hourglass_coefficient * rho * wave_speed * vol * math.sqrt(bb) / 8.0
        else:
            coef = hourglass_coefficient * (lam + 2.0 * mu) * vol * bb / 64.0
        # S = V sigma - sum_alpha Q^alpha (h^alpha.x)^T, accumulated mode by mode
        t00, t11, t22 = vol * s0, vol * s1, vol * s2
        t12 = t21 = vol * s3
        t02 = t20 = vol * s4
        t01 = t10 = vol * s5
        e = (e00, e01, e02, e10, e11, e12, e20, e21, e22)
        rot = (r00, r01, r02, r10, r11, r12, r20, r21, r22)
        qa0, qa1, qa2, ha, hxa0, hxa1, hxa2 = _hourglass_mode(S, B, k, 0, e, rot, coef, dt, hourglass_form)
        qb0, qb1, qb2, hb, hxb0, hxb1, hxb2 = _hourglass_mode(S, B, k, 3, e, rot, coef, dt, hourglass_form)
        qc0, qc1, qc2, hc, hxc0, hxc1, hxc2 = _hourglass_mode(S, B, k, 6, e, rot, coef, dt, hourglass_form)
        qd0, qd1, qd2, hd, hxd0, hxd1, hxd2 = _hourglass_mode(S, B, k, 9, e, rot, coef, dt, hourglass_form)
        S[_HG * B + k] = ha + hb + hc + hd
        t00 = t00 - qa0 * hxa0 - qb0 * hxb0 - qc0 * hxc0 - qd0 * hxd0
        t01 = t01 - qa0 * hxa1 - qb0 * hxb1 - qc0 * hxc1 - qd0 * hxd1
        t02 = t02 - qa0 * hxa2 - qb0 * hxb2 - qc0 * hxc2 - qd0 * hxd2
        t10 = t10 - qa1 * hxa0 - qb1 * hxb0 - qc1 * hxc0 - qd1 * hxd0
        t11 = t11 - qa1 * hxa1 - qb1 * hxb1 - qc1 * hxc1 - qd1 * hxd1
        t12 = t12 - qa1 * hxa2 - qb1 * hxb2 - qc1 * hxc2 - qd1 * hxd2
        t20 = t20 - qa2 * hxa0 - qb2 * hxb0 - qc2 * hxc0 - qd2 * hxd0
        t21 = t21 - qa2 * hxa1 - qb2 * hxb1 - qc2 * hxc1 - qd2 * hxd1
        t22 = t22 - qa2 * hxa2 - qb2 * hxb2 - qc2 * hxc2 - qd2 * hxd2
        # M = J^-1 S^T; the forces are the transposed transform of the coefficients
        # (0, M_0/4, M_1/4, Q_xieta, M_2/4, Q_zetaxi, Q_etazeta, Q_xietazeta), split by zeta layer
        inv = (i00, i01, i02, i10, i11, i12, i20, i21, i22)
        _component_forces(S, B, k, _F, t00, t01, t02, inv, qa0, qb0, qc0, qd0)
        _component_forces(S, B, k, _F + 8, t10, t11, t12, inv, qa1, qb1, qc1, qd1)
        _component_forces(S, B, k, _F + 16, t20, t21, t22, inv, qa2, qb2, qc2, qd2)
        S[_DT * B + k] = viscous_step(ls, wave_speed, math.sqrt(3.0) * ls, trd, q_quadratic, q_linear, beta)


@njit(cache=True, fastmath=True, inline="always")
def _rates_phase(S, count, dt, kinematics, weight):
    """The kinematics lanes (3D, one point: nothing to choose)."""
    _rates(S, count, dt)


@njit(cache=True, fastmath=True, inline="always")
def _response_phase(S, count, dt, kinematics, thickness, weight, hourglass_form, hourglass_coefficient):
    """The response lanes."""
    _response(S, count, dt, hourglass_form, hourglass_coefficient)


# One-point hexahedra for ``blocks.lane_pass`` (the quads' arguments, ``one_point_quads.QUADS``):
# ``hourglass`` (cells, 12) the stiffness-form resultants, mode-major (xi eta, eta zeta, zeta xi, xi eta zeta),
# 3 components each; ``kinematics`` and ``thickness`` say nothing a hexahedron does not fix.
HEXES = LaneElement(name="hex", source=__file__, lanes=LANES, nodes=8, gdim=3, rows=ROWS,
                    x_row=_X, v_row=_U, s_row=_S, stress_components=(0, 1, 2, 3, 4, 5), o_row=_O,
                    hourglass_modes=12, constants_row=_LAM, sn_row=_SN, f_row=_F, q_row=_Q,
                    totals_row=_VOL, eps_row=_EPS, d_row=_D, spin_row=_SPIN, wp_row=_WP, rates=_rates_phase,
                    elastic=_elastic, j2=_j2_lanes, response=_response_phase, tensor6=row6, store_stress=store6,
                    spin3=spin3, radius=no_radius)
HEX_KERNELS = lane_passes(HEXES)
