"""``shockfem bench``: element-cycles per second, and speed against error.

Speed: an elastic steel cylinder, axisymmetric (quads) and 3D (hexes), at three mesh sizes
with one-point elements (the default) and at one size with full integration, a fixed number
of steps of the whole time loop (single process).  Element-cycles per second
= elements x steps / wall time of the loop; the shares of the phases (internal force =
strain rate + material update + force assembly in one compiled pass; nodal update;
energy bookkeeping) come from the solver's phase timers.

Speed against error: the bar-wave verification case (front speed and plateau stress
against 1D theory) at three mesh sizes, both integrations, with its wall time; and the
elastic-plastic copper Taylor bar (final length and radius against the converged benchmark)
at two refinements, with the share of the internal-force pass spent in the plastic return
(the same pass timed on the bar's final state with the material switched to elastic).
"""
from __future__ import annotations

import itertools
import time

from mpi4py import MPI

from .geometry import build_mesh
from .model import build_model
from .scene import resolve
from .solver.explicit import ExplicitSolver, PhaseTimes
from .verify.scenes import rod_scene, steel_c0, STEEL

SPEED_CASES = {
    # name: (kinematics, integration, radius, length, element sizes [m])
    "axisymmetric-quad": ("axisymmetric", "reduced", 0.05, 1.0, (0.0045, 0.0022, 0.001)),
    "axisymmetric-quad-full": ("axisymmetric", "full", 0.05, 1.0, (0.0022,)),
    "3d-hex": ("3d", "reduced", 0.02, 0.3, (0.005, 0.0035, 0.0024)),
    "3d-hex-full": ("3d", "full", 0.02, 0.3, (0.0035,)),
}
QUICK_SIZES = {"axisymmetric-quad": (0.01,), "axisymmetric-quad-full": (0.01,), "3d-hex": (0.006,),
               "3d-hex-full": (0.006,)}


def time_steps(raw: dict, steps: int) -> dict:
    scene = resolve(raw)
    model = build_model(scene, build_mesh(scene, MPI.COMM_WORLD, log=lambda m: None))
    solver = ExplicitSolver(model, initial_velocity=lambda x: 1e-3 * x / x.max())
    solver.advance(solver.stable_step())          # one untimed step: numba/JIT loading, first touch of arrays
    solver.times = PhaseTimes()
    t0 = time.perf_counter()
    for _ in range(steps):
        solver.advance(solver.stable_step())
    wall = time.perf_counter() - t0
    n = model.num_cells_global
    pt = solver.times
    return {"kinematics": scene.kinematics, "elements": n, "steps": steps, "wall_time_s": wall,
            "element_cycles_per_s": n * steps / wall,
            "share_internal_force": pt.internal_force / wall, "share_update": pt.update / wall,
            "share_energy": pt.energy / wall,
            "share_python_overhead": max(0.0, 1 - pt.total / wall)}


def run_bench(quick: bool = False, steps: int = 200, echo=print) -> list[dict]:
    results = []
    echo(f"{'case':24s} {'elements':>9s} {'steps':>6s} {'wall[s]':>8s} {'Mcyc/s':>7s}  "
         f"{'force':>6s} {'update':>6s} {'energy':>6s}")
    for case, (kin, integration, R, L, sizes) in SPEED_CASES.items():
        for h in (QUICK_SIZES[case] if quick else sizes):
            raw = rod_scene(f"bench_{case}_{h}", kin, radius=R, length=L, h=h, end_time=1.0,
                            integration=integration)
            r = time_steps(raw, 20 if quick else steps)
            r["case"] = case
            r["integration"] = integration
            r["element_size_m"] = h
            results.append(r)
            echo(f"{case:24s} {r['elements']:9d} {r['steps']:6d} {r['wall_time_s']:8.2f} "
                 f"{r['element_cycles_per_s'] / 1e6:7.2f}  {r['share_internal_force']:6.0%} "
                 f"{r['share_update']:6.0%} {r['share_energy']:6.0%}")
    if not quick:
        results += speed_against_error(echo)
    results += taylor_bar_bench((0.0004,) if quick else (0.0004, 0.0002), echo)
    results += contact_bench(quick, echo)
    return results


def _material_update_share(solver, repeats: int = 20) -> float:
    """Share of the internal-force pass taken by the plastic return: the pass on the solver's
    state timed with its materials as they are and switched to elastic (state restored after)."""
    from .materials import layout
    m = solver.model
    saved = (solver.sigma.copy(), solver.plastic_state.copy(),
             None if solver.hourglass is None else solver.hourglass.copy(), solver.f_int.copy())
    params = m.params.copy()
    times = []
    for model_code in (None, layout.ELASTIC):
        if model_code is not None:
            m.params[:, layout.P_LAW] = model_code
        t0 = time.perf_counter()
        for _ in range(repeats):
            solver._internal_force(solver.dt)
        times.append(time.perf_counter() - t0)
    m.params[:] = params
    solver.sigma[:], solver.plastic_state[:] = saved[0], saved[1]
    if saved[2] is not None:
        solver.hourglass[:] = saved[2]
    solver.f_int[:] = saved[3]
    return max(0.0, (times[0] - times[1]) / times[0])


def taylor_bar_bench(sizes, echo=print) -> list[dict]:
    """Copper Taylor bar: final length and radius errors against wall time and element-cycles/s."""
    from .verify.plasticity_cases import TAYLOR, taylor_measures, taylor_scene
    from .verify.scenes import solve
    echo("speed against error: copper Taylor bar (axisymmetric, one-point quads, 80 us, impact face held on the wall)")
    echo(f"{'size[mm]':>8s} {'elements':>9s} {'steps':>7s} {'wall[s]':>8s} {'Mcyc/s':>7s} {'length err':>10s} "
         f"{'radius err':>10s} {'eps_max':>7s} {'E err':>8s} {'return share':>12s}")
    out = []
    for h in sizes:
        solver, wall = solve(taylor_scene(h))
        r = taylor_measures(solver)
        n = solver.model.num_cells_global
        row = {"case": "taylor_bar", "kinematics": "axisymmetric", "element_size_m": h, "elements": n, "steps": solver.step, "wall_time_s": wall,
               "element_cycles_per_s": n * solver.step / wall,
               "length_error": r["length"] / TAYLOR["final_length"] - 1,
               "radius_error": r["radius"] / TAYLOR["final_radius"] - 1,
               "max_plastic_strain": r["max_plastic_strain"], "balance_error": solver.energy.balance_error,
               "share_internal_force": solver.times.internal_force / wall,
               "share_plastic_return_of_internal_force": _material_update_share(solver)}
        out.append(row)
        echo(f"{h * 1e3:8.2f} {n:9d} {solver.step:7d} {wall:8.2f} {row['element_cycles_per_s'] / 1e6:7.2f} "
             f"{row['length_error']:+10.2%} {row['radius_error']:+10.2%} {r['max_plastic_strain']:7.3g} "
             f"{row['balance_error']:8.1e} {row['share_plastic_return_of_internal_force']:12.0%}")
    return out


def speed_against_error(echo=print) -> list[dict]:
    """Bar wave at three sizes: errors of front speed and plateau stress against wall time."""
    from .verify.foundation_cases import bar_step
    out = []
    echo("speed against error: bar wave (axisymmetric, R = 2 mm, L = 0.4 m, v = 1 m/s)")
    echo(f"{'integration':11s} {'size':8s} {'elements':>9s} {'wall[s]':>8s} {'front err':>10s} {'stress err':>10s}")
    c0, rho = steel_c0(), STEEL["density"]
    for integration, size in itertools.product(("reduced", "full"), ("coarse", "default", "fine")):
        solver, wall, plateau, speed = bar_step("axisymmetric", size, integration=integration)
        r = {"case": "bar_wave_accuracy", "integration": integration, "size": size, "kinematics": "axisymmetric",
             "elements": solver.model.num_cells_global, "steps": solver.step, "wall_time_s": wall,
             "element_cycles_per_s": solver.model.num_cells_global * solver.step / wall,
             "front_speed_error": abs(speed / c0 - 1), "stress_error": abs(plateau / (-rho * c0) - 1)}
        out.append(r)
        echo(f"{integration:11s} {size:8s} {r['elements']:9d} {wall:8.2f} {r['front_speed_error']:10.2e} "
             f"{r['stress_error']:10.2e}")
    return out


CONTACT_SIZES = {"axisymmetric": (0.0025, 0.00125, 0.000625), "3d": (0.005, 0.0035, 0.0025)}
QUICK_CONTACT_SIZES = {"axisymmetric": (0.0025,), "3d": (0.005,)}


def contact_bench(quick: bool = False, echo=print) -> list[dict]:
    """The two-rod contact case at three sizes, axisymmetric and 3D: wall time of the time loop, element-cycles
    per second, the phases' shares, and the error of the target's final speed against its converged value."""
    from .verify.contact_cases import TWO_RODS, two_rods_scene
    from .verify.scenes import solve
    c = TWO_RODS
    echo(f"speed against error: two steel rods R {c['radius'] * 1e3:g} mm, L {c['length'] * 1e3:g} mm, "
         f"{c['speed']:g} m/s, {c['end_time'] * 1e6:g} us; error of the target's speed against "
         f"{c['converged_speed']} m/s")
    echo(f"{'kinematics':12s} {'size[mm]':>8s} {'elements':>9s} {'steps':>6s} {'wall[s]':>8s} {'Mcyc/s':>7s}  "
         f"{'force':>6s} {'contact':>7s} {'update':>6s} {'energy':>6s} {'speed':>8s} {'error':>7s}")
    out = []
    for kinematics, sizes in (QUICK_CONTACT_SIZES if quick else CONTACT_SIZES).items():
        for h in sizes:
            solver, wall = solve(two_rods_scene(h, kinematics))
            v, _ = solver.body_means()
            n, t = solver.model.num_cells_global, solver.times
            speed = abs(float(v[1, -1]))
            row = {"case": "two_rods_contact", "kinematics": kinematics, "element_size_m": h, "elements": n,
                   "steps": solver.step, "wall_time_s": wall, "element_cycles_per_s": n * solver.step / wall,
                   "share_internal_force": t.internal_force / wall, "share_contact": t.contact / wall,
                   "share_update": t.update / wall, "share_energy": t.energy / wall,
                   "target_speed_m_s": speed, "speed_error": speed / c["converged_speed"] - 1,
                   "balance_error": solver.energy.balance_error}
            out.append(row)
            echo(f"{kinematics:12s} {h * 1e3:8.3g} {n:9d} {solver.step:6d} {wall:8.2f} "
                 f"{row['element_cycles_per_s'] / 1e6:7.2f}  {row['share_internal_force']:6.0%} "
                 f"{row['share_contact']:7.0%} {row['share_update']:6.0%} {row['share_energy']:6.0%} "
                 f"{speed:8.4f} {row['speed_error']:+7.2%}")
    return out
