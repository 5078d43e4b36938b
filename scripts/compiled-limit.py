"""The compiled limit of the elastic axisymmetric one-point quad step on this machine, against shockfem's.

How near the compiled limit is shockfem's whole step?  This is that limit, measured: the bench's
elastic steel cylinder (``bench.SPEED_CASES["axisymmetric-quad"]``), its whole step written by hand as
one scalar loop over the cells and one fused loop over the nodes, with nothing a product needs besides:
one material, no bodies' energy rows, no inverted-cell or critical-cell report, no MPI, the axis held
by a 0/1 factor.  The formulas are shockfem's own (the elements' inline helpers: Walsh transforms, the
2x2 inverse, the objective elastic update, bulk viscosity, the stable step), so the two compute the same
numbers (checked first, on one pass from the solver's state), and what the timings compare is the
code's shape: lanes and scratch rows, separate nodal passes, bookkeeping and Python between them.

Both run on the same mesh in turn, round after round (this machine runs in two speed modes that last
tens of calls: compare rounds paired, docs/performance.md), and the script prints ns a cell and the
ratio of each round.  Not a test, not part of the package.
The repetition of the element's arithmetic is the measurement: a change to the element's formulas
must be made here too, and the agreement printed first says whether it was.

    .venv/bin/python scripts/compiled-limit.py [element size, m: 0.001] [rounds: 40] [steps a round: 20]
"""
import math
import sys
import time

import numpy as np
from mpi4py import MPI
from numba import njit

from shockfem.elements.one_point import inverse_2x2, step_length, unwalsh4, walsh4
from shockfem.geometry import build_mesh
from shockfem.materials.layout import P_BETA, P_LAMBDA, P_MU, P_Q_LINEAR, P_Q_QUADRATIC, P_RHO, P_WAVE_SPEED
from shockfem.materials.objective import cayley_matrix
from shockfem.materials.update import elastic_update_stress
from shockfem.materials.viscosity import bulk_viscosity, viscous_step, viscous_stress_of
from shockfem.model import build_model
from shockfem.scene import resolve
from shockfem.solver.explicit import ExplicitSolver
from shockfem.verify.scenes import rod_scene


@njit(fastmath=True, error_model="numpy")
def cell_pass(dofmap, sign, x, v, dt, sigma, hourglass, f, constants, eps):
    """Every cell's stress update and nodal forces (the stiffness hourglass form), one cell at a time;
    returns the stable step and the stresses' and hourglass work."""
    lam, mu, beta, rho, wave_speed, q_quadratic, q_linear = constants
    hdt = 0.5 * dt
    dt_min = 1e300
    work = 0.0
    hourglass_work = 0.0
    for cell in range(dofmap.shape[0]):
        c = np.uint32(cell)
        n0, n1, n2, n3 = np.uint32(dofmap[c, 0]), np.uint32(dofmap[c, 1]), np.uint32(dofmap[c, 2]), np.uint32(dofmap[c, 3])
        sx, j00, j01, hx0 = walsh4(x[n0, 0], x[n1, 0], x[n2, 0], x[n3, 0])
        _, j10, j11, hx1 = walsh4(x[n0, 1], x[n1, 1], x[n2, 1], x[n3, 1])
        su, v00, v01, hv0 = walsh4(v[n0, 0], v[n1, 0], v[n2, 0], v[n3, 0])
        _, v10, v11, hv1 = walsh4(v[n0, 1], v[n1, 1], v[n2, 1], v[n3, 1])
        j00, j01, j10, j11 = 0.5 * j00, 0.5 * j01, 0.5 * j10, 0.5 * j11
        v00, v01, v10, v11 = 0.5 * v00, 0.5 * v01, 0.5 * v10, 0.5 * v11
        r = 0.25 * sx
        vr = 0.25 * su
        _, i00, i01, i10, i11 = inverse_2x2(j00 - hdt * v00, j01 - hdt * v01, j10 - hdt * v10, j11 - hdt * v11)
        l00 = v00 * i00 + v01 * i10
        l01 = v00 * i01 + v01 * i11
        l10 = v10 * i00 + v11 * i10
        l11 = v10 * i01 + v11 * i11
        d = (l00, l11, vr / (r - hdt * vr), 0.0, 0.0, 0.5 * (l01 + l10))
        spin = 0.5 * (l01 - l10)
        a0, a1, a2, a5 = sigma[c, 0, 0], sigma[c, 0, 1], sigma[c, 0, 2], sigma[c, 0, 5]
        s_np1 = elastic_update_stress((a0, a1, a2, 0.0, 0.0, a5), d, (0.0, 0.0, spin), dt, lam, mu)
        det, i00, i01, i10, i11 = inverse_2x2(j00, j01, j10, j11)
        vol = det * sign[c] * 2.0 * math.pi * r
        work += 0.5 * dt * vol * ((a0 + s_np1[0]) * d[0] + (a1 + s_np1[1]) * d[1]
                                  + (a2 + s_np1[2]) * d[2] + 2.0 * (a5 + s_np1[5]) * d[5])
        e00 = v00 * i00 + v01 * i10
        e01 = v00 * i01 + v01 * i11
        e10 = v10 * i00 + v11 * i10
        e11 = v10 * i01 + v11 * i11
        q0 = hv0 - e00 * hx0 - e01 * hx1
        q1 = hv1 - e10 * hx0 - e11 * hx1
        bb = i00 * i00 + i01 * i01 + i10 * i10 + i11 * i11
        ls = step_length(4.0, bb)
        trd = d[0] + d[1] + d[2]
        pq = bulk_viscosity(rho, wave_speed, ls, trd, q_quadratic, q_linear)
        (s0, s1, s2, _, _, s5), _, _ = viscous_stress_of(s_np1, d, pq, lam, mu, beta)
        kh = eps * (lam + 2.0 * mu) * vol * bb / 16.0
        r00, r01, _, r10, r11, _, _, _, _ = cayley_matrix(0.0, 0.0, spin, dt)
        o0, o1 = hourglass[c, 0], hourglass[c, 1]
        Q0 = r00 * o0 + r01 * o1 + kh * dt * q0
        Q1 = r10 * o0 + r11 * o1 + kh * dt * q1
        hourglass_work += 0.5 * dt * ((o0 + Q0) * q0 + (o1 + Q1) * q1)
        t00 = vol * s0 - Q0 * hx0
        t01 = vol * s5 - Q0 * hx1
        t10 = vol * s5 - Q1 * hx0
        t11 = vol * s1 - Q1 * hx1
        hoop = 0.25 * vol * s2 / r
        fx0, fx1, fx2, fx3 = unwalsh4(hoop, 0.5 * (i00 * t00 + i01 * t01), 0.5 * (i10 * t00 + i11 * t01), Q0)
        fy0, fy1, fy2, fy3 = unwalsh4(0.0, 0.5 * (i00 * t10 + i01 * t11), 0.5 * (i10 * t10 + i11 * t11), Q1)
        f[n0, 0] += fx0
        f[n1, 0] += fx1
        f[n2, 0] += fx2
        f[n3, 0] += fx3
        f[n0, 1] += fy0
        f[n1, 1] += fy1
        f[n2, 1] += fy2
        f[n3, 1] += fy3
        sigma[c, 0, 0], sigma[c, 0, 1], sigma[c, 0, 2], sigma[c, 0, 5] = s_np1[0], s_np1[1], s_np1[2], s_np1[5]
        hourglass[c, 0], hourglass[c, 1] = Q0, Q1
        dt_min = min(dt_min, viscous_step(ls, wave_speed, ls, trd, q_quadratic, q_linear, beta))
    return dt_min, work, hourglass_work


@njit(fastmath=True)
def node_pass(x, v, f, inv_mass, mass, free, dt):
    """a = -f / m, the next half-step velocity (the axis held by ``free``), the next position, f cleared;
    returns the kinetic energy and the internal forces' work."""
    kinetic = 0.0
    work = 0.0
    for i in range(x.shape[0]):
        for k in range(2):
            vk = (v[i, k] - dt * f[i, k] * inv_mass[i]) * free[i, k]
            work -= f[i, k] * vk
            v[i, k] = vk
            x[i, k] += dt * vk
            f[i, k] = 0.0
            kinetic += 0.5 * mass[i] * vk * vk
    return kinetic, work


def timed(run, k: int, *arrays) -> float:
    """Seconds for ``run`` called k times; ``arrays`` put back after, so that every round starts alike."""
    saved = [a.copy() for a in arrays]
    t0 = time.perf_counter()
    for _ in range(k):
        run()
    seconds = time.perf_counter() - t0
    for a, b in zip(arrays, saved):
        a[...] = b
    return seconds


def main():
    h = float(sys.argv[1]) if len(sys.argv) > 1 else 0.001
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 40
    steps = int(sys.argv[3]) if len(sys.argv) > 3 else 20
    scene = resolve(rod_scene("compiled_limit", "axisymmetric", "quad", radius=0.05, length=1.0, h=h, end_time=1.0,
                              integration="reduced"))
    model = build_model(scene, build_mesh(scene, MPI.COMM_WORLD, log=lambda m: None))
    solver = ExplicitSolver(model, initial_velocity=lambda x: 1e-3 * x / x.max())
    solver.advance(solver.stable_step())
    m = model
    assert np.array_equal(m.kernel_cells, np.arange(len(m.kernel_cells))) and (m.cell_material == m.cell_material[0]).all()
    p = m.params[m.cell_material[0]]
    constants = (p[P_LAMBDA], p[P_MU], p[P_BETA], p[P_RHO], p[P_WAVE_SPEED], p[P_Q_QUADRATIC], p[P_Q_LINEAR])
    eps = m.hourglass_coefficient
    assert m.hourglass_form == 0 and m.alpha == 0.0
    dofmap, sign = np.ascontiguousarray(m.dofmap), m.cell_sign.astype(float)
    x, v, f = solver.x.copy(), solver.v.copy(), np.zeros_like(solver.x)
    sigma, hourglass = solver.sigma.copy(), solver.hourglass.copy()
    mass = np.ascontiguousarray(m.mass)
    inv_mass = 1.0 / mass
    free = np.ones_like(x)
    free[np.abs(x[:, 0]) < 1e-12, 0] = 0.0
    dt = solver.stable_step()
    n = m.num_cells_global

    # the same numbers: one cell pass of each from the solver's state
    own = (sigma.copy(), hourglass.copy(), np.zeros_like(x))
    limit_dt, _, _ = cell_pass(dofmap, sign, solver.x, solver.v, dt, *own, constants, eps)
    product_state = (solver.sigma, solver.hourglass, solver.f_int, solver.body_energy)
    saved = [a.copy() for a in product_state]
    solver._internal_force(dt)
    force_gap = np.abs(own[2] - solver.f_int).max() / np.abs(solver.f_int).max()
    stress_gap = np.abs(own[0] - solver.sigma).max() / np.abs(solver.sigma).max()
    print(f"{n} cells, {x.shape[0]} nodes; one pass from the same state: forces {force_gap:.1e}, stresses "
          f"{stress_gap:.1e} of the largest apart, stable steps {limit_dt:.6e} and {solver.dt_stable:.6e} s")
    for a, b in zip(product_state, saved):
        a[...] = b

    def limit_step():
        cell_pass(dofmap, sign, x, v, dt, sigma, hourglass, f, constants, eps)
        node_pass(x, v, f, inv_mass, mass, free, dt)

    def limit_cells():
        cell_pass(dofmap, sign, x, v, dt, sigma, hourglass, f, constants, eps)

    cases = {  # name: (what runs, what it changes)
        "hand-written step": (limit_step, ()),
        "shockfem step (ExplicitSolver.advance)": (lambda: solver.advance(dt), ()),
        "hand-written cell pass": (limit_cells, (sigma, hourglass, f)),
        "shockfem cell pass (_internal_force)": (lambda: solver._internal_force(dt), product_state),
    }
    for run, arrays in cases.values():
        timed(run, 2, *arrays)
    ns = {name: [] for name in cases}
    for _ in range(rounds):
        for name, (run, arrays) in cases.items():
            ns[name].append(timed(run, steps, *arrays) / steps / n * 1e9)
    print(f"{rounds} rounds of {steps} calls each, in turn; ns a cell, median (fastest round), and M element-cycles/s")
    for name, values in ns.items():
        values = np.array(values)
        print(f"  {name:40s} {np.median(values):6.1f} ({values.min():5.1f})  {1e3 / np.median(values):5.1f} M "
              f"({1e3 / values.min():5.1f})")
    names = list(ns)
    for product, limit in ((names[1], names[0]), (names[3], names[2])):
        ratio = np.array(ns[product]) / np.array(ns[limit])
        print(f"  {product.split(' (')[0]} / {limit}, paired by round: median {np.median(ratio):.3f} "
              f"(range {ratio.min():.3f}-{ratio.max():.3f})")


main()
