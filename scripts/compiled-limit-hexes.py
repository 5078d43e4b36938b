"""The compiled limit of the elastic one-point hex pass on this machine, against shockfem's.

``compiled-limit.py``'s measurement for the 3D hexes: the bench's elastic steel cylinder
(``bench.SPEED_CASES["3d-hex"]``), the hex lanes' formulas (``elements/one_point_hexes.py``: Walsh
transforms, 3x3 inverses, the objective elastic update, four hourglass modes, bulk viscosity, the stable
step) written by hand one cell at a time, with one material and no bodies' energy rows, inverted-cell
or critical-cell reports.  One pass of each from the solver's state must agree to round-off (printed);
then both run in turn, round after round, and the ratio is taken round by round.  The cell pass only:
the nodal passes are the quads' (``compiled-limit.py``).  Not a test, not part of the package.
The repetition of the element's arithmetic is the measurement: a change to the element's formulas
must be made here too, and the agreement printed first says whether it was.

    .venv/bin/python scripts/compiled-limit-hexes.py [element size, m: 0.0024] [rounds: 30] [calls a round: 5]
"""
import math
import sys
import time

import numpy as np
from mpi4py import MPI
from numba import njit

from shockfem.elements.one_point import walsh8, unwalsh4, step_length
from shockfem.materials.algebra import inverse_3x3
from shockfem.materials.objective import cayley_matrix
from shockfem.materials.update import elastic_update_stress
from shockfem.materials.viscosity import bulk_viscosity, viscous_step, viscous_stress_of
from shockfem.materials.layout import P_BETA, P_LAMBDA, P_MU, P_Q_LINEAR, P_Q_QUADRATIC, P_RHO, P_WAVE_SPEED
from shockfem.elements.one_point_hexes import HEX_KERNELS
from shockfem.verify.scenes import rod_scene
from shockfem.scene import resolve
from shockfem.geometry import build_mesh
from shockfem.model import build_model
from shockfem.solver.explicit import ExplicitSolver


@njit(fastmath=True, inline="always")
def hourglass_mode(hx, hv, o, e, rot, coef, dt, form):
    q0 = hv[0] - e[0] * hx[0] - e[1] * hx[1] - e[2] * hx[2]
    q1 = hv[1] - e[3] * hx[0] - e[4] * hx[1] - e[5] * hx[2]
    q2 = hv[2] - e[6] * hx[0] - e[7] * hx[1] - e[8] * hx[2]
    if form == 1:
        Q0, Q1, Q2 = coef * q0, coef * q1, coef * q2
    else:
        Q0 = rot[0] * o[0] + rot[1] * o[1] + rot[2] * o[2] + coef * dt * q0
        Q1 = rot[3] * o[0] + rot[4] * o[1] + rot[5] * o[2] + coef * dt * q1
        Q2 = rot[6] * o[0] + rot[7] * o[1] + rot[8] * o[2] + coef * dt * q2
    return Q0, Q1, Q2, 0.5 * ((o[0] + Q0) * q0 + (o[1] + Q1) * q1 + (o[2] + Q2) * q2)


@njit(fastmath=True, inline="always")
def add_forces(f, nd, k, lo, hi):
    """One component's forces on the cell's eight nodes ``nd``, four of the lower layer and four of the upper."""
    f[nd[0], k] += lo[0]
    f[nd[1], k] += lo[1]
    f[nd[2], k] += lo[2]
    f[nd[3], k] += lo[3]
    f[nd[4], k] += hi[0]
    f[nd[5], k] += hi[1]
    f[nd[6], k] += hi[2]
    f[nd[7], k] += hi[3]


@njit(fastmath=True, inline="always")
def component_forces(ta, tb, tc, inv, qa, qb, qc, qd):
    m0 = 0.25 * (inv[0] * ta + inv[1] * tb + inv[2] * tc)
    m1 = 0.25 * (inv[3] * ta + inv[4] * tb + inv[5] * tc)
    m2 = 0.25 * (inv[6] * ta + inv[7] * tb + inv[8] * tc)
    lo = unwalsh4(-m2, m0 - qc, m1 - qb, qa - qd)
    hi = unwalsh4(m2, m0 + qc, m1 + qb, qa + qd)
    return lo, hi


@njit(fastmath=True, error_model="numpy")
def hex_pass(dofmap, sign, x, v, dt, sigma, hg, f, consts, form, eps):
    lam, mu, beta, rho, wave_speed, q_quadratic, q_linear = consts
    hdt = 0.5 * dt
    dt_min = 1e300
    work_sum = 0.0
    hg_sum = 0.0
    for cell in range(dofmap.shape[0]):
        c = np.uint32(cell)
        nd = (np.uint32(dofmap[c, 0]), np.uint32(dofmap[c, 1]), np.uint32(dofmap[c, 2]), np.uint32(dofmap[c, 3]),
              np.uint32(dofmap[c, 4]), np.uint32(dofmap[c, 5]), np.uint32(dofmap[c, 6]), np.uint32(dofmap[c, 7]))
        tx = walsh8(x[nd[0], 0], x[nd[1], 0], x[nd[2], 0], x[nd[3], 0], x[nd[4], 0], x[nd[5], 0], x[nd[6], 0], x[nd[7], 0])
        ty = walsh8(x[nd[0], 1], x[nd[1], 1], x[nd[2], 1], x[nd[3], 1], x[nd[4], 1], x[nd[5], 1], x[nd[6], 1], x[nd[7], 1])
        tz = walsh8(x[nd[0], 2], x[nd[1], 2], x[nd[2], 2], x[nd[3], 2], x[nd[4], 2], x[nd[5], 2], x[nd[6], 2], x[nd[7], 2])
        ux = walsh8(v[nd[0], 0], v[nd[1], 0], v[nd[2], 0], v[nd[3], 0], v[nd[4], 0], v[nd[5], 0], v[nd[6], 0], v[nd[7], 0])
        uy = walsh8(v[nd[0], 1], v[nd[1], 1], v[nd[2], 1], v[nd[3], 1], v[nd[4], 1], v[nd[5], 1], v[nd[6], 1], v[nd[7], 1])
        uz = walsh8(v[nd[0], 2], v[nd[1], 2], v[nd[2], 2], v[nd[3], 2], v[nd[4], 2], v[nd[5], 2], v[nd[6], 2], v[nd[7], 2])
        j00, j01, j02 = 0.25 * tx[1], 0.25 * tx[2], 0.25 * tx[4]
        j10, j11, j12 = 0.25 * ty[1], 0.25 * ty[2], 0.25 * ty[4]
        j20, j21, j22 = 0.25 * tz[1], 0.25 * tz[2], 0.25 * tz[4]
        v00, v01, v02 = 0.25 * ux[1], 0.25 * ux[2], 0.25 * ux[4]
        v10, v11, v12 = 0.25 * uy[1], 0.25 * uy[2], 0.25 * uy[4]
        v20, v21, v22 = 0.25 * uz[1], 0.25 * uz[2], 0.25 * uz[4]
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
        d = (l00, l11, l22, 0.5 * (l12 + l21), 0.5 * (l02 + l20), 0.5 * (l01 + l10))
        spin = (0.5 * (l12 - l21), 0.5 * (l02 - l20), 0.5 * (l01 - l10))
        a = (sigma[c, 0, 0], sigma[c, 0, 1], sigma[c, 0, 2], sigma[c, 0, 3], sigma[c, 0, 4], sigma[c, 0, 5])
        s_np1 = elastic_update_stress(a, d, spin, dt, lam, mu)
        (det, i00, i01, i02, i10, i11, i12, i20, i21, i22) = inverse_3x3(j00, j01, j02, j10, j11, j12, j20, j21, j22)
        vol = det * sign[c]
        work_sum += 0.5 * dt * vol * (
            (a[0] + s_np1[0]) * d[0] + (a[1] + s_np1[1]) * d[1] + (a[2] + s_np1[2]) * d[2]
            + 2.0 * ((a[3] + s_np1[3]) * d[3] + (a[4] + s_np1[4]) * d[4] + (a[5] + s_np1[5]) * d[5]))
        e = (v00 * i00 + v01 * i10 + v02 * i20, v00 * i01 + v01 * i11 + v02 * i21, v00 * i02 + v01 * i12 + v02 * i22,
             v10 * i00 + v11 * i10 + v12 * i20, v10 * i01 + v11 * i11 + v12 * i21, v10 * i02 + v11 * i12 + v12 * i22,
             v20 * i00 + v21 * i10 + v22 * i20, v20 * i01 + v21 * i11 + v22 * i21, v20 * i02 + v21 * i12 + v22 * i22)
        bb = 0.5 * (i00 * i00 + i01 * i01 + i02 * i02 + i10 * i10 + i11 * i11 + i12 * i12
                    + i20 * i20 + i21 * i21 + i22 * i22)
        ls = step_length(8.0, bb)
        trd = d[0] + d[1] + d[2]
        pq = bulk_viscosity(rho, wave_speed, math.sqrt(3.0) * ls, trd, q_quadratic, q_linear)
        (s0, s1, s2, s3, s4, s5), pd, pv = viscous_stress_of(s_np1, d, pq, lam, mu, beta)
        rot = cayley_matrix(spin[0], spin[1], spin[2], dt)
        if form == 1:
            coef = eps * rho * wave_speed * vol * math.sqrt(bb) / 8.0
        else:
            coef = eps * (lam + 2.0 * mu) * vol * bb / 64.0
        hxa, hxb, hxc, hxd = (tx[3], ty[3], tz[3]), (tx[6], ty[6], tz[6]), (tx[5], ty[5], tz[5]), (tx[7], ty[7], tz[7])
        qa0, qa1, qa2, ha = hourglass_mode(hxa, (ux[3], uy[3], uz[3]), (hg[c, 0], hg[c, 1], hg[c, 2]), e, rot, coef, dt, form)
        qb0, qb1, qb2, hb = hourglass_mode(hxb, (ux[6], uy[6], uz[6]), (hg[c, 3], hg[c, 4], hg[c, 5]), e, rot, coef, dt, form)
        qc0, qc1, qc2, hc = hourglass_mode(hxc, (ux[5], uy[5], uz[5]), (hg[c, 6], hg[c, 7], hg[c, 8]), e, rot, coef, dt, form)
        qd0, qd1, qd2, hd = hourglass_mode(hxd, (ux[7], uy[7], uz[7]), (hg[c, 9], hg[c, 10], hg[c, 11]), e, rot, coef, dt, form)
        hg_sum += ha + hb + hc + hd
        t00 = vol * s0 - qa0 * hxa[0] - qb0 * hxb[0] - qc0 * hxc[0] - qd0 * hxd[0]
        t01 = vol * s5 - qa0 * hxa[1] - qb0 * hxb[1] - qc0 * hxc[1] - qd0 * hxd[1]
        t02 = vol * s4 - qa0 * hxa[2] - qb0 * hxb[2] - qc0 * hxc[2] - qd0 * hxd[2]
        t10 = vol * s5 - qa1 * hxa[0] - qb1 * hxb[0] - qc1 * hxc[0] - qd1 * hxd[0]
        t11 = vol * s1 - qa1 * hxa[1] - qb1 * hxb[1] - qc1 * hxc[1] - qd1 * hxd[1]
        t12 = vol * s3 - qa1 * hxa[2] - qb1 * hxb[2] - qc1 * hxc[2] - qd1 * hxd[2]
        t20 = vol * s4 - qa2 * hxa[0] - qb2 * hxb[0] - qc2 * hxc[0] - qd2 * hxd[0]
        t21 = vol * s3 - qa2 * hxa[1] - qb2 * hxb[1] - qc2 * hxc[1] - qd2 * hxd[1]
        t22 = vol * s2 - qa2 * hxa[2] - qb2 * hxb[2] - qc2 * hxc[2] - qd2 * hxd[2]
        inv = (i00, i01, i02, i10, i11, i12, i20, i21, i22)
        lo, hi = component_forces(t00, t01, t02, inv, qa0, qb0, qc0, qd0)
        add_forces(f, nd, 0, lo, hi)
        lo, hi = component_forces(t10, t11, t12, inv, qa1, qb1, qc1, qd1)
        add_forces(f, nd, 1, lo, hi)
        lo, hi = component_forces(t20, t21, t22, inv, qa2, qb2, qc2, qd2)
        add_forces(f, nd, 2, lo, hi)
        for i in range(6):
            sigma[c, 0, i] = s_np1[i]
        hg[c, 0], hg[c, 1], hg[c, 2] = qa0, qa1, qa2
        hg[c, 3], hg[c, 4], hg[c, 5] = qb0, qb1, qb2
        hg[c, 6], hg[c, 7], hg[c, 8] = qc0, qc1, qc2
        hg[c, 9], hg[c, 10], hg[c, 11] = qd0, qd1, qd2
        dt_min = min(dt_min, viscous_step(ls, wave_speed, math.sqrt(3.0) * ls, trd, q_quadratic, q_linear, beta))
    return dt_min, work_sum, hg_sum


h = float(sys.argv[1]) if len(sys.argv) > 1 else 0.0024
rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 30
calls = int(sys.argv[3]) if len(sys.argv) > 3 else 5
scene = resolve(rod_scene("hexlimit", "3d", "hex", radius=0.02, length=0.3, h=h, end_time=1.0, integration="reduced"))
m = build_model(scene, build_mesh(scene, MPI.COMM_WORLD, log=lambda m: None))
s = ExplicitSolver(m, initial_velocity=lambda x: 1e-2 * x / x.max())
for _ in range(10):
    s.advance(s.stable_step())
dt = s.stable_step()
n = m.num_cells_global
assert np.array_equal(m.kernel_cells, np.arange(n)) and (m.cell_material == m.cell_material[0]).all()
p = m.params[m.cell_material[0]]
consts = (p[P_LAMBDA], p[P_MU], p[P_BETA], p[P_RHO], p[P_WAVE_SPEED], p[P_Q_QUADRATIC], p[P_Q_LINEAR])
dofmap, sign = np.ascontiguousarray(m.dofmap), m.cell_sign.astype(float)
product = HEX_KERNELS[True]
sig, hg, f, be = s.sigma.copy(), s.hourglass.copy(), np.zeros_like(s.f_int), np.zeros_like(s.body_energy)
A = (m.kernel_cells, m.dofmap, m.cell_material, m.cell_sign, s.x, s.v, s.t, dt, m.N, m.dN, m.wq, m.kinematics,
     m.thickness, m.cell_kind, True, m.hourglass_form, m.hourglass_coefficient, m.params, m.curves,
     s.plastic_state, sig, hg, f, be, s.peak.copy())
tot = product(*A)
sig2, hg2, f2 = s.sigma.copy(), s.hourglass.copy(), np.zeros_like(s.f_int)
t0 = time.perf_counter()
lim = hex_pass(dofmap, sign, s.x, s.v, dt, sig2, hg2, f2, consts, m.hourglass_form, m.hourglass_coefficient)
print(f"{n} hexes; hand-written compiled in {time.perf_counter() - t0:.0f} s; forces {np.abs(f2 - f).max() / np.abs(f).max():.1e}, "
      f"stresses {np.abs(sig2 - sig).max() / np.abs(sig).max():.1e}, resultants {np.abs(hg2 - hg).max() / np.abs(hg).max():.1e} "
      f"apart; stable steps {lim[0]:.6e} {tot[0]:.6e}")
res = {"shockfem (lanes)": [], "hand-written": []}
for r in range(rounds):
    order = list(res) if r % 2 == 0 else list(res)[::-1]
    for name in order:
        for mine, start in ((sig, s.sigma), (hg, s.hourglass), (sig2, s.sigma), (hg2, s.hourglass)):
            mine[...] = start
        t0 = time.perf_counter()
        for _ in range(calls):
            if name == "hand-written":
                hex_pass(dofmap, sign, s.x, s.v, dt, sig2, hg2, f2, consts, m.hourglass_form, m.hourglass_coefficient)
            else:
                product(*A)
        res[name].append((time.perf_counter() - t0) / calls / n * 1e9)
for name, vals in res.items():
    print(f"  {name:18s} {np.median(vals):6.1f} ns a cell ({np.min(vals):6.1f}): {1e3 / np.median(vals):.2f} M ({1e3 / np.min(vals):.2f})")
q = np.array(res["shockfem (lanes)"]) / np.array(res["hand-written"])
print(f"  shockfem / hand-written paired: median {np.median(q):.3f} (range {q.min():.3f}-{q.max():.3f})")
