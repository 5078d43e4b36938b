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
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..materials.algebra import inverse_3x3
from ..materials.layout import P_BETA, P_LAMBDA, P_MU, P_Q_LINEAR, P_Q_QUADRATIC, P_RHO, P_WAVE_SPEED
from ..materials.objective import cayley_matrix
from ..materials.update import update_stress
from ..materials.viscosity import bulk_viscosity, viscous_step, viscous_stress

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


def _hex_kernel(elastic_only: bool):
    """``hex_one_point`` compiled for ``elastic_only``."""

    @njit(cache=True, fastmath=True)
    def hex_one_point(cells, dofmap, cell_material, cell_sign, x_np1, v_half, dt, hourglass_form,
                      hourglass_coefficient, params, curves, state, sigma, hourglass, f, body_energy):
        """One-point hexahedra: stress update and internal force (see ``one_point_quads.quad_one_point``).

        hourglass : (cells, 12) stiffness-form resultants, mode-major (xi eta, eta zeta, zeta xi,
        xi eta zeta), 3 components each.  Returns what ``one_point_quads.quad_one_point`` returns.
        """
        hdt = 0.5 * dt
        dt_stable = 1e300
        critical_cell = -1
        damping_power = 0.0
        viscosity_power = 0.0
        plastic_work = 0.0
        hourglass_power = 0.0
        bad_cell = -1
        for ci in range(cells.shape[0]):
            c = cells[ci]
            m = cell_material[c]
            lam = params[m, P_LAMBDA]
            mu = params[m, P_MU]
            beta = params[m, P_BETA]
            n0, n1, n2, n3 = dofmap[c, 0], dofmap[c, 1], dofmap[c, 2], dofmap[c, 3]
            n4, n5, n6, n7 = dofmap[c, 4], dofmap[c, 5], dofmap[c, 6], dofmap[c, 7]
            # transforms of x and v per component (tuples stay in registers; small arrays would not):
            # entries 1, 2, 4 are 4 J[i, :] (dN0_a = xi_a / 4); 3, 6, 5, 7 the hourglass projections
            tx = walsh8(x_np1[n0, 0], x_np1[n1, 0], x_np1[n2, 0], x_np1[n3, 0],
                         x_np1[n4, 0], x_np1[n5, 0], x_np1[n6, 0], x_np1[n7, 0])
            ty = walsh8(x_np1[n0, 1], x_np1[n1, 1], x_np1[n2, 1], x_np1[n3, 1],
                         x_np1[n4, 1], x_np1[n5, 1], x_np1[n6, 1], x_np1[n7, 1])
            tz = walsh8(x_np1[n0, 2], x_np1[n1, 2], x_np1[n2, 2], x_np1[n3, 2],
                         x_np1[n4, 2], x_np1[n5, 2], x_np1[n6, 2], x_np1[n7, 2])
            ux = walsh8(v_half[n0, 0], v_half[n1, 0], v_half[n2, 0], v_half[n3, 0],
                         v_half[n4, 0], v_half[n5, 0], v_half[n6, 0], v_half[n7, 0])
            uy = walsh8(v_half[n0, 1], v_half[n1, 1], v_half[n2, 1], v_half[n3, 1],
                         v_half[n4, 1], v_half[n5, 1], v_half[n6, 1], v_half[n7, 1])
            uz = walsh8(v_half[n0, 2], v_half[n1, 2], v_half[n2, 2], v_half[n3, 2],
                         v_half[n4, 2], v_half[n5, 2], v_half[n6, 2], v_half[n7, 2])
            j00, j01, j02 = 0.25 * tx[1], 0.25 * tx[2], 0.25 * tx[4]
            j10, j11, j12 = 0.25 * ty[1], 0.25 * ty[2], 0.25 * ty[4]
            j20, j21, j22 = 0.25 * tz[1], 0.25 * tz[2], 0.25 * tz[4]
            v00, v01, v02 = 0.25 * ux[1], 0.25 * ux[2], 0.25 * ux[4]
            v10, v11, v12 = 0.25 * uy[1], 0.25 * uy[2], 0.25 * uy[4]
            v20, v21, v22 = 0.25 * uz[1], 0.25 * uz[2], 0.25 * uz[4]
            # strain rate on the mid-step configuration: L = Jv J_mid^-1, J_mid = J - dt/2 Jv
            (det, i00, i01, i02, i10, i11, i12, i20, i21, i22) = inverse_3x3(
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
            d0, d1, d2 = l00, l11, l22
            d3 = 0.5 * (l12 + l21)
            d4 = 0.5 * (l02 + l20)
            d5 = 0.5 * (l01 + l10)
            w23 = 0.5 * (l12 - l21)
            w13 = 0.5 * (l02 - l20)
            w12 = 0.5 * (l01 - l10)
            # the material update at the centre (objective rotation, law)
            a = (sigma[c, 0, 0], sigma[c, 0, 1], sigma[c, 0, 2], sigma[c, 0, 3], sigma[c, 0, 4], sigma[c, 0, 5])
            s_np1, d, wp = update_stress(params, curves, m, state, c, 0, a, (d0, d1, d2, d3, d4, d5),
                                         (w23, w13, w12), dt, 0.0, elastic_only)
            (sigma[c, 0, 0], sigma[c, 0, 1], sigma[c, 0, 2], sigma[c, 0, 3], sigma[c, 0, 4],
             sigma[c, 0, 5]) = s_np1
            # end-of-step configuration
            (det, i00, i01, i02, i10, i11, i12, i20, i21, i22) = inverse_3x3(
                j00, j01, j02, j10, j11, j12, j20, j21, j22)
            vol = det * cell_sign[c]
            if vol <= 0.0:
                bad_cell = c
            plastic_work += vol * wp
            body_energy[m, 2] += vol * wp
            body_energy[m, 0] += 0.5 * dt * vol * (
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
            trd = d0 + d1 + d2
            # the viscosity's length is LS-DYNA's volume / largest face, sqrt(3) ls for a cube
            pq = bulk_viscosity(params[m, P_RHO], params[m, P_WAVE_SPEED], math.sqrt(3.0) * ls, trd,
                                params[m, P_Q_QUADRATIC], params[m, P_Q_LINEAR])
            (s0, s1, s2, s3, s4, s5), pd, pv = viscous_stress(params, m, s_np1, d, pq)
            damping_power += vol * pd
            viscosity_power += vol * pv
            # the stiffness-form resultants turn with the material, like the stress
            r00, r01, r02, r10, r11, r12, r20, r21, r22 = cayley_matrix(w23, w13, w12, dt)
            if hourglass_form == 1:
                coef = hourglass_coefficient * params[m, P_RHO] * params[m, P_WAVE_SPEED] * vol * math.sqrt(bb) / 8.0
            else:
                coef = hourglass_coefficient * (lam + 2.0 * mu) * vol * bb / 64.0
            # S = V sigma - sum_alpha Q^alpha (h^alpha.x)^T, accumulated mode by mode
            t00, t11, t22 = vol * s0, vol * s1, vol * s2
            t12 = t21 = vol * s3
            t02 = t20 = vol * s4
            t01 = t10 = vol * s5
            Q = (0.0, 0.0, 0.0)
            Qa = Qb = Qc = Qd = Q
            for al in range(4):
                w = (3, 6, 5, 7)[al]          # transform entry of mode al (xi eta, eta zeta, zeta xi, xi eta zeta)
                hx0, hx1, hx2 = tx[w], ty[w], tz[w]
                q0 = ux[w] - e00 * hx0 - e01 * hx1 - e02 * hx2
                q1 = uy[w] - e10 * hx0 - e11 * hx1 - e12 * hx2
                q2 = uz[w] - e20 * hx0 - e21 * hx1 - e22 * hx2
                o0 = hourglass[c, 3 * al]
                o1 = hourglass[c, 3 * al + 1]
                o2 = hourglass[c, 3 * al + 2]
                if hourglass_form == 1:
                    Q0 = coef * q0
                    Q1 = coef * q1
                    Q2 = coef * q2
                else:
                    Q0 = r00 * o0 + r01 * o1 + r02 * o2 + coef * dt * q0
                    Q1 = r10 * o0 + r11 * o1 + r12 * o2 + coef * dt * q1
                    Q2 = r20 * o0 + r21 * o1 + r22 * o2 + coef * dt * q2
                hourglass[c, 3 * al] = Q0
                hourglass[c, 3 * al + 1] = Q1
                hourglass[c, 3 * al + 2] = Q2
                cell_hourglass = 0.5 * ((o0 + Q0) * q0 + (o1 + Q1) * q1 + (o2 + Q2) * q2)
                hourglass_power += cell_hourglass
                body_energy[m, 1] += dt * cell_hourglass
                t00 -= Q0 * hx0
                t01 -= Q0 * hx1
                t02 -= Q0 * hx2
                t10 -= Q1 * hx0
                t11 -= Q1 * hx1
                t12 -= Q1 * hx2
                t20 -= Q2 * hx0
                t21 -= Q2 * hx1
                t22 -= Q2 * hx2
                if al == 0:
                    Qa = (Q0, Q1, Q2)
                elif al == 1:
                    Qb = (Q0, Q1, Q2)
                elif al == 2:
                    Qc = (Q0, Q1, Q2)
                else:
                    Qd = (Q0, Q1, Q2)
            # M = J^-1 S^T; the forces are the transposed transform of the coefficients
            # (0, M_0/4, M_1/4, Q_xieta, M_2/4, Q_zetaxi, Q_etazeta, Q_xietazeta), split by zeta layer
            for i in range(3):
                if i == 0:
                    ta, tb, tc = t00, t01, t02
                elif i == 1:
                    ta, tb, tc = t10, t11, t12
                else:
                    ta, tb, tc = t20, t21, t22
                m0 = 0.25 * (i00 * ta + i01 * tb + i02 * tc)
                m1 = 0.25 * (i10 * ta + i11 * tb + i12 * tc)
                m2 = 0.25 * (i20 * ta + i21 * tb + i22 * tc)
                lo = unwalsh4(-m2, m0 - Qc[i], m1 - Qb[i], Qa[i] - Qd[i])
                hi = unwalsh4(m2, m0 + Qc[i], m1 + Qb[i], Qa[i] + Qd[i])
                f[n0, i] += lo[0]
                f[n1, i] += lo[1]
                f[n2, i] += lo[2]
                f[n3, i] += lo[3]
                f[n4, i] += hi[0]
                f[n5, i] += hi[1]
                f[n6, i] += hi[2]
                f[n7, i] += hi[3]
            dtc = viscous_step(ls, params[m, P_WAVE_SPEED], math.sqrt(3.0) * ls, trd, params[m, P_Q_QUADRATIC],
                               params[m, P_Q_LINEAR], beta)
            if dtc < dt_stable:
                dt_stable = dtc
                critical_cell = c
        return dt_stable, critical_cell, damping_power, viscosity_power, plastic_work, hourglass_power, bad_cell

    return hex_one_point


# The hex kernel is compiled twice, with ``elastic_only`` a constant of the closure (numba caches the
# two apart: its cache key holds the closure's values).  For meshes of elastic rows without slots the
# loop then holds no call to a law: a call left in the loop, even one never taken, cost a third of
# the quad kernel's speed (docs/performance.md).  ``kernels.one_point_kernel`` picks a mesh's pass.
HEX_KERNELS = {flag: _hex_kernel(flag) for flag in (True, False)}
