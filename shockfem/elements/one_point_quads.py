"""One-point quads (plane strain and axisymmetric) in SIMD lanes: several cells at once.

The element is ``one_point.py``'s (Flanagan & Belytschko's hourglass control, the ring volume and
hoop term in axisymmetry).  Per cell it takes two 2x2 inverses, two Cayley rotations, Hooke's law,
the bulk viscosity, square roots and divisions, one after the other: scalar code leaves most of a
CPU's vector units idle.  A CPU does four of each at once (AVX: four doubles a register) if the
compiler sees the same arithmetic over consecutive array entries, so the pass runs in blocks of
``LANES`` cells:

1. gather (scalar, indirect through the dofmap): each cell's node positions and velocities, its
   stress and hourglass resultant and its row's constants into rows of one scratch array ``S``, row
   ``r`` of lane k at ``S[r * LANES + k]``;
2. kinematics lanes (vectorised, ``_rates_lanes``): Jacobians, the mid-step strain rate and spin, the
   hourglass projections, into further rows;
3. the material update at the centre (``materials.update``): every cell's elastic trial in lanes too
   (``_elastic``), which is the update of elastic rows without slots and of J2 points inside their yield
   surface (``elastic_trial_holds``); in a block of one J2 row of linear hardening every cell's return
   in lanes as well (``_j2_lanes``); the others cell by cell from that trial (``update_from_trial``,
   scalar: the laws hold state and branches);
4. response lanes (vectorised, ``_response_lanes``): the viscous stresses, the hourglass resultant,
   the nodal forces, the energies, the stable step and the squared von Mises stress, into further rows;
5. scatter (scalar): forces into the nodes, stresses and resultants into their arrays, the energy
   sums, the smallest step and each body's peak stress in cell order.

The loop over the blocks is ``blocks.py``'s, shared with the hexes and tets: this module gives it the
quads' rows and phases (``QUADS``).

Numba's LLVM vectorises a lane loop only when (found with its vectorizer's remarks,
``llvmlite.binding.set_option('', '-pass-remarks-missed=loop-vectorize')``): numba's Python error model is off (``error_model="numpy"``: otherwise every
division carries a zero test that raises); the loop is in a function of its own, not inlined, called
once a block; its trip count is an argument (a constant 32 gets the loop unrolled first, and the
unrolled loop is not vectorised); it holds no inner loop (LLVM vectorises innermost loops); and it
reads and writes one array (no runtime alias checks to fail).  The lanes therefore raise nothing: a
cell of zero area gives infinite forces and NaNs, which the pass reports as an inverted cell (its
volume is not positive) or the nodal pass as a non-finite state (``solver.nodal``).  The lane bodies
are the element's formulas written once, for both the elastic and the general copy.
"""
from __future__ import annotations

import math

from numba import njit

from ..materials.j2 import linear_hardening_return
from ..materials.objective import cayley_matrix
from ..materials.update import elastic_update_stress
from ..materials.viscosity import bulk_viscosity, viscous_step, viscous_stress_of
from .blocks import LaneElement, lane_passes, von_mises2
from .cells import AXISYMMETRIC
from .one_point import inverse_2x2, step_length, unwalsh4, walsh4

# Cells a block: 32-64 ran fastest on the bench's 50k quads (``shockfem bench``); at 256 the scratch
# arrays leave the first-level cache and the pass runs at half the scalar code's speed.
LANES = 32

# Rows of W, gathered: node positions x, y and velocities u, w (four nodes each), the stress at t_n
# (11, 22, 33, 12), the hourglass resultant of the last step, the row's constants, the orientation.
_X, _Y, _U, _W, _S, _O = 0, 4, 8, 12, 16, 20
_LAM, _MU, _BETA, _RHO, _C, _Q1, _Q2, _SIGN = range(22, 30)   # ``one_point.block_constants``', the orientation
W_ROWS = 30
# Rows of K: Jacobian J and velocity Jacobian Jv at the centre (row-major), hourglass projections h.x
# and rates h.v, the centre's radius, the strain rate (11, 22, 33, 12) and spin W12 on the mid-step
# configuration, then from the material update the stress at t_n+1 (11, 22, 33, 12) and plastic work
# density.  (The update may change the hoop rate: a slotted ring's metal takes what its slots leave.)
_J, _JV, _HX, _HV, _R, _D, _SPIN, _SN, _WP = (W_ROWS + r for r in (0, 4, 8, 10, 12, 13, 17, 18, 22))
K_ROWS = 23
# Response rows: nodal forces (x of the four nodes, then y), the hourglass resultant, the signed volume
# factor (<= 0: inverted), the stresses' work over the step, the hourglass, damping and bulk viscosity
# powers, the cell's stable step and its plastic work (``one_point.add_cell_totals``'s order from _DET),
# the squared von Mises stress at t_n+1 (``blocks``: the totals' rows, then it).
_FX, _FY, _Q, _DET, _WORK, _HG, _DAMP, _VISC, _DT, _PLASTIC, _VM2 = (W_ROWS + K_ROWS + r for r in
                                                                      (0, 4, 8, 10, 11, 12, 13, 14, 15, 16, 17))
V_ROWS = 18
# A J2 row of linear hardening (``materials.update.linear_hardening``) returns in lanes: the plastic strain
# at t_n in, at t_n+1 out, and its rate in the next row (``one_point.scatter_plastic_strain``)
_EPS, _RATE = W_ROWS + K_ROWS + V_ROWS, W_ROWS + K_ROWS + V_ROWS + 1
ROWS = W_ROWS + K_ROWS + V_ROWS + 2


def _lane_function(py_func, name: str, axisymmetric: bool):
    """``py_func`` compiled as a lane function, named for its kinematics.  The two copies of a closure
    would otherwise share a name, and numba's symbol for a function called from another is its name
    and a per-process counter: a kernel compiled in one process and linking a copy loaded from the
    cache that another process compiled could call the other kinematics' copy (seen: plane-strain
    forces from the axisymmetric lanes)."""
    py_func.__name__ = py_func.__qualname__ = f"quad_{name}_{'axisymmetric' if axisymmetric else 'plane'}"
    return njit(cache=True, fastmath=True, error_model="numpy", inline="never")(py_func)


def _rates_lanes(axisymmetric: bool):
    """The kinematics lanes for ``axisymmetric`` (a constant of the closure)."""

    def rates(S, nb, dt):
        B = LANES
        hdt = 0.5 * dt
        for k in range(nb):
            # transforms of x and v: (sum, sum xi ., sum eta ., sum xi eta .) per component
            sx, j00, j01, hx0 = walsh4(S[_X * B + k], S[(_X + 1) * B + k], S[(_X + 2) * B + k], S[(_X + 3) * B + k])
            sy, j10, j11, hx1 = walsh4(S[_Y * B + k], S[(_Y + 1) * B + k], S[(_Y + 2) * B + k], S[(_Y + 3) * B + k])
            su, v00, v01, hv0 = walsh4(S[_U * B + k], S[(_U + 1) * B + k], S[(_U + 2) * B + k], S[(_U + 3) * B + k])
            sw, v10, v11, hv1 = walsh4(S[_W * B + k], S[(_W + 1) * B + k], S[(_W + 2) * B + k], S[(_W + 3) * B + k])
            # J = sum_a x_a dN0_a^T with dN0_a = xi_a / 2; Jv likewise from v
            j00, j01, j10, j11 = 0.5 * j00, 0.5 * j01, 0.5 * j10, 0.5 * j11
            v00, v01, v10, v11 = 0.5 * v00, 0.5 * v01, 0.5 * v10, 0.5 * v11
            r = 0.25 * sx
            vr = 0.25 * su
            # strain rate on the mid-step configuration: L = Jv J_mid^-1, J_mid = J - dt/2 Jv
            _, i00, i01, i10, i11 = inverse_2x2(j00 - hdt * v00, j01 - hdt * v01, j10 - hdt * v10, j11 - hdt * v11)
            l00 = v00 * i00 + v01 * i10
            l01 = v00 * i01 + v01 * i11
            l10 = v10 * i00 + v11 * i10
            l11 = v10 * i01 + v11 * i11
            S[_J * B + k] = j00
            S[(_J + 1) * B + k] = j01
            S[(_J + 2) * B + k] = j10
            S[(_J + 3) * B + k] = j11
            S[_JV * B + k] = v00
            S[(_JV + 1) * B + k] = v01
            S[(_JV + 2) * B + k] = v10
            S[(_JV + 3) * B + k] = v11
            S[_HX * B + k] = hx0
            S[(_HX + 1) * B + k] = hx1
            S[_HV * B + k] = hv0
            S[(_HV + 1) * B + k] = hv1
            S[_R * B + k] = r
            S[_D * B + k] = l00
            S[(_D + 1) * B + k] = l11
            S[(_D + 2) * B + k] = vr / (r - hdt * vr) if axisymmetric else 0.0
            S[(_D + 3) * B + k] = 0.5 * (l01 + l10)
            S[_SPIN * B + k] = 0.5 * (l01 - l10)

    return _lane_function(rates, "rates", axisymmetric)


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _elastic(S, nb, dt):
    """Every cell's elastic trial stress, in lanes (``materials.update.elastic_update_stress``): the update
    of elastic rows without slots, and of the points ``materials.update.elastic_trial_holds`` accepts."""
    B = LANES
    for k in range(nb):
        s = elastic_update_stress(
            (S[_S * B + k], S[(_S + 1) * B + k], S[(_S + 2) * B + k], 0.0, 0.0, S[(_S + 3) * B + k]),
            (S[_D * B + k], S[(_D + 1) * B + k], S[(_D + 2) * B + k], 0.0, 0.0, S[(_D + 3) * B + k]),
            (0.0, 0.0, S[_SPIN * B + k]), dt, S[_LAM * B + k], S[_MU * B + k])
        S[_SN * B + k], S[(_SN + 1) * B + k], S[(_SN + 2) * B + k], S[(_SN + 3) * B + k] = s[0], s[1], s[2], s[5]
        S[_WP * B + k] = 0.0


@njit(cache=True, fastmath=True, error_model="numpy", inline="never")
def _j2_lanes(S, nb, dt, mu, y0, eps0, slope):
    """Every cell's J2 return from its elastic trial, in lanes, for a block of one J2 row of linear hardening
    (``materials.j2.linear_hardening_return``; ``materials.update.linear_hardening`` says which rows and gives
    the line y0, eps0, slope): the stress, plastic strain, its rate and the plastic work density.  A cell
    inside its yield surface keeps its trial, plastic strain and no rate, as ``elastic_trial_holds`` leaves
    it."""
    B = LANES
    for k in range(nb):
        s, eps, rate, work = linear_hardening_return(
            (S[_SN * B + k], S[(_SN + 1) * B + k], S[(_SN + 2) * B + k], 0.0, 0.0, S[(_SN + 3) * B + k]),
            S[_EPS * B + k], mu, y0, eps0, slope, dt)
        S[_SN * B + k], S[(_SN + 1) * B + k], S[(_SN + 2) * B + k], S[(_SN + 3) * B + k] = s[0], s[1], s[2], s[5]
        S[_EPS * B + k] = eps
        S[_RATE * B + k] = rate
        S[_WP * B + k] = work


def _response_lanes(axisymmetric: bool):
    """The response lanes for ``axisymmetric`` (a constant of the closure)."""

    def response(S, nb, dt, thickness, hourglass_form, hourglass_coefficient):
        B = LANES
        for k in range(nb):
            j00, j01, j10, j11 = S[_J * B + k], S[(_J + 1) * B + k], S[(_J + 2) * B + k], S[(_J + 3) * B + k]
            v00, v01, v10, v11 = S[_JV * B + k], S[(_JV + 1) * B + k], S[(_JV + 2) * B + k], S[(_JV + 3) * B + k]
            hx0, hx1 = S[_HX * B + k], S[(_HX + 1) * B + k]
            r = S[_R * B + k]
            d = (S[_D * B + k], S[(_D + 1) * B + k], S[(_D + 2) * B + k], 0.0, 0.0, S[(_D + 3) * B + k])
            a0, a1, a2, a5 = S[_S * B + k], S[(_S + 1) * B + k], S[(_S + 2) * B + k], S[(_S + 3) * B + k]
            s_np1 = (S[_SN * B + k], S[(_SN + 1) * B + k], S[(_SN + 2) * B + k], 0.0, 0.0, S[(_SN + 3) * B + k])
            S[_VM2 * B + k] = von_mises2(s_np1)
            o0, o1 = S[_O * B + k], S[(_O + 1) * B + k]
            lam, mu, rho, wave_speed = S[_LAM * B + k], S[_MU * B + k], S[_RHO * B + k], S[_C * B + k]
            q_quadratic, q_linear, beta = S[_Q1 * B + k], S[_Q2 * B + k], S[_BETA * B + k]
            # end-of-step configuration: volume and J^-1
            det, i00, i01, i10, i11 = inverse_2x2(j00, j01, j10, j11)
            det *= S[_SIGN * B + k]
            vol = det * (2.0 * math.pi * r if axisymmetric else thickness)
            S[_DET * B + k] = det
            S[_PLASTIC * B + k] = vol * S[_WP * B + k]
            S[_WORK * B + k] = 0.5 * dt * vol * ((a0 + s_np1[0]) * d[0] + (a1 + s_np1[1]) * d[1]
                                                 + (a2 + s_np1[2]) * d[2] + 2.0 * (a5 + s_np1[5]) * d[5])
            # hourglass rate q = h.v - L_end (h.x), and resultant Q
            e00 = v00 * i00 + v01 * i10
            e01 = v00 * i01 + v01 * i11
            e10 = v10 * i00 + v11 * i10
            e11 = v10 * i01 + v11 * i11
            q0 = S[_HV * B + k] - e00 * hx0 - e01 * hx1
            q1 = S[(_HV + 1) * B + k] - e10 * hx0 - e11 * hx1
            bb = i00 * i00 + i01 * i01 + i10 * i10 + i11 * i11      # b:b = sum_a |J^-T dN0_a|^2
            ls = step_length(4.0, bb)
            trd = d[0] + d[1] + d[2]
            pq = bulk_viscosity(rho, wave_speed, ls, trd, q_quadratic, q_linear)
            (s0, s1, s2, _, _, s5), pd, pv = viscous_stress_of(s_np1, d, pq, lam, mu, beta)
            S[_DAMP * B + k] = vol * pd
            S[_VISC * B + k] = vol * pv
            if hourglass_form == 1:
                cv = hourglass_coefficient * rho * wave_speed * vol * math.sqrt(bb) / 4.0
                Q0 = cv * q0
                Q1 = cv * q1
            else:
                # the resultant turns with the material (the centre's in-plane rotation) and grows
                kh = hourglass_coefficient * (lam + 2.0 * mu) * vol * bb / 16.0
                r00, r01, _, r10, r11, _, _, _, _ = cayley_matrix(0.0, 0.0, S[_SPIN * B + k], dt)
                Q0 = r00 * o0 + r01 * o1 + kh * dt * q0
                Q1 = r10 * o0 + r11 * o1 + kh * dt * q1
            S[_Q * B + k] = Q0
            S[(_Q + 1) * B + k] = Q1
            # trapezoidal, like the solver's work of all internal forces: (Q_n + Q_n+1)/2 . q
            S[_HG * B + k] = 0.5 * ((o0 + Q0) * q0 + (o1 + Q1) * q1)
            # f_a = S b_a + h_a Q (+ hoop N_a), S = V sigma - Q (h.x)^T, b_a = J^-T dN0_a: with
            # M = J^-1 S^T the force is M^T dN0_a, i.e. the transposed transform of (hoop, M/2, Q).
            t00 = vol * s0 - Q0 * hx0
            t01 = vol * s5 - Q0 * hx1
            t10 = vol * s5 - Q1 * hx0
            t11 = vol * s1 - Q1 * hx1
            hoop = 0.25 * vol * s2 / r if axisymmetric else 0.0
            (S[_FX * B + k], S[(_FX + 1) * B + k], S[(_FX + 2) * B + k], S[(_FX + 3) * B + k]) = unwalsh4(
                hoop, 0.5 * (i00 * t00 + i01 * t01), 0.5 * (i10 * t00 + i11 * t01), Q0)
            (S[_FY * B + k], S[(_FY + 1) * B + k], S[(_FY + 2) * B + k], S[(_FY + 3) * B + k]) = unwalsh4(
                0.0, 0.5 * (i00 * t10 + i01 * t11), 0.5 * (i10 * t10 + i11 * t11), Q1)
            S[_DT * B + k] = viscous_step(ls, wave_speed, ls, trd, q_quadratic, q_linear, beta)

    return _lane_function(response, "response", axisymmetric)


_RATES_AXISYMMETRIC, _RATES_PLANE = _rates_lanes(True), _rates_lanes(False)
_RESPONSE_AXISYMMETRIC, _RESPONSE_PLANE = _response_lanes(True), _response_lanes(False)


@njit(cache=True, fastmath=True, inline="always")
def _rates_phase(S, count, dt, kinematics, weight):
    """The kinematics lanes of the block's kinematics."""
    if kinematics == AXISYMMETRIC:
        _RATES_AXISYMMETRIC(S, count, dt)
    else:
        _RATES_PLANE(S, count, dt)


@njit(cache=True, fastmath=True, inline="always")
def _tensor6(S, row, B, k):
    """A stress or strain rate (11, 22, 33, 12 in rows ``row``..+3 of lane k) as the six components."""
    return S[row * B + k], S[(row + 1) * B + k], S[(row + 2) * B + k], 0.0, 0.0, S[(row + 3) * B + k]


@njit(cache=True, fastmath=True, inline="always")
def _store_stress(S, row, B, k, s):
    """The in-plane components and the hoop (out-of-plane) one of ``s`` into rows ``row``..+3 of lane k."""
    S[row * B + k], S[(row + 1) * B + k], S[(row + 2) * B + k], S[(row + 3) * B + k] = s[0], s[1], s[2], s[5]


@njit(cache=True, fastmath=True, inline="always")
def _spin3(S, row, B, k):
    """The in-plane spin W12 (row ``row`` of lane k) as (W23, W13, W12)."""
    return 0.0, 0.0, S[row * B + k]


@njit(cache=True, fastmath=True, inline="always")
def _radius(S, B, k, kinematics):
    """The radius of the cell's centre in axisymmetry (0 in plane strain)."""
    return S[_R * B + k] if kinematics == AXISYMMETRIC else 0.0


@njit(cache=True, fastmath=True, inline="always")
def _response_phase(S, count, dt, kinematics, thickness, weight, hourglass_form, hourglass_coefficient):
    """The response lanes of the block's kinematics."""
    if kinematics == AXISYMMETRIC:
        _RESPONSE_AXISYMMETRIC(S, count, dt, thickness, hourglass_form, hourglass_coefficient)
    else:
        _RESPONSE_PLANE(S, count, dt, thickness, hourglass_form, hourglass_coefficient)


# One-point quads (plane strain or axisymmetric) for ``blocks.lane_pass``: ``sigma`` is (cells, 1, 6),
# ``hourglass`` (cells, 2) the resultants of the last step, updated in place (the stiffness form accumulates
# them; both forms need them for the trapezoidal work); ``hourglass_form`` 0 stiffness, 1 viscous, with the
# coefficient eps; the rule (``N``, ``dN``, ``wq``), ``cell_kind`` and ``mean_dilatation`` say nothing a
# one-point quad does not fix.
QUADS = LaneElement(name="quad", source=__file__, lanes=LANES, nodes=4, gdim=2, rows=ROWS,
                    x_row=_X, v_row=_U, s_row=_S, stress_components=(0, 1, 2, 5), o_row=_O,
                    hourglass_modes=2, constants_row=_LAM, sn_row=_SN, f_row=_FX, q_row=_Q,
                    totals_row=_DET, eps_row=_EPS, d_row=_D, spin_row=_SPIN, wp_row=_WP, rates=_rates_phase,
                    elastic=_elastic, j2=_j2_lanes, response=_response_phase, tensor6=_tensor6,
                    store_stress=_store_stress, spin3=_spin3, radius=_radius)
QUAD_KERNELS = lane_passes(QUADS)
