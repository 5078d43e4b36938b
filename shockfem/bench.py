"""``shockfem bench``: element-cycles per second, and speed against error.

Speed: an elastic steel cylinder, axisymmetric (quads) and 3D (hexes), at three mesh sizes
with one-point elements (the default) and at one size with full integration, and on linear
tetrahedra (constant strain, one point) at two sizes, a fixed number
of steps of the whole time loop (single process).  Element-cycles per second
= elements x steps / wall time of the loop; the shares of the phases (internal force =
strain rate + material update + force assembly in one compiled pass; nodal update;
energy bookkeeping) come from the solver's phase timers.

Compile time: in a process of its own with an empty numba cache (``NUMBA_CACHE_DIR``), each case at its
smallest mesh for a few steps, in turn: the CPU time numba spends compiling the kernels the case calls
(``numba:compile`` events; a kernel another case compiled first counts there, so the rows add up to the
whole).

Speed against error: the bar-wave verification case (front speed and plateau stress
against 1D theory) at three mesh sizes, both integrations, with its wall time; and the
elastic-plastic copper Taylor bar (final length and radius against the converged benchmark)
at two refinements, with the share of the internal-force pass spent in the plastic return
(``ReturnShare``: the same pass timed at eight times of the run with the material as it is and
switched to elastic).
"""
from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys
import tempfile
import time

from mpi4py import MPI
from numba.core import event

from .geometry import build_mesh
from .model import build_model
from .scene import resolve
from .elements.kernels import element_pass
from .solver.explicit import ExplicitSolver, PhaseTimes
from .verify.scenes import rod_scene, steel_c0, STEEL

SPEED_CASES = {
    # name: (kinematics, element, integration, radius, length, element sizes [m])
    "axisymmetric-quad": ("axisymmetric", "quad", "reduced", 0.05, 1.0, (0.0045, 0.0022, 0.001)),
    "axisymmetric-quad-full": ("axisymmetric", "quad", "full", 0.05, 1.0, (0.0022,)),
    "3d-hex": ("3d", "hex", "reduced", 0.02, 0.3, (0.005, 0.0035, 0.0024)),
    "3d-hex-full": ("3d", "hex", "full", 0.02, 0.3, (0.0035,)),
    # linear tetrahedra (one point, constant strain: ``elements.linear_tets``)
    "3d-tet": ("3d", "tet", "full", 0.02, 0.3, (0.005, 0.0035)),
}
TAYLOR_QUICK_SIZE = 0.0004          # the Taylor bar's coarsest element size [m]: 8 across its 3.2 mm radius
QUICK_SIZES = {"axisymmetric-quad": (0.01,), "axisymmetric-quad-full": (0.01,), "3d-hex": (0.006,),
               "3d-hex-full": (0.006,), "3d-tet": (0.006,)}


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
    for case, (kin, element, integration, R, L, sizes) in SPEED_CASES.items():
        for h in (QUICK_SIZES[case] if quick else sizes):
            raw = rod_scene(f"bench_{case}_{h}", kin, element, radius=R, length=L, h=h, end_time=1.0,
                            integration=integration)
            r = time_steps(raw, 20 if quick else steps)
            r["case"] = case
            r["element"] = element
            r["integration"] = integration
            r["element_size_m"] = h
            results.append(r)
            echo(f"{case:24s} {r['elements']:9d} {r['steps']:6d} {r['wall_time_s']:8.2f} "
                 f"{r['element_cycles_per_s'] / 1e6:7.2f}  {r['share_internal_force']:6.0%} "
                 f"{r['share_update']:6.0%} {r['share_energy']:6.0%}")
    if not quick:
        results += speed_against_error(echo)
        results += compile_bench(echo)
    results += taylor_bar_bench((TAYLOR_QUICK_SIZE,) if quick else (TAYLOR_QUICK_SIZE, 0.0002), echo)
    results += contact_bench(quick, echo)
    return results


class ReturnShare:
    """A probe for ``verify.scenes.solve``: the share of the internal-force pass spent in the plastic
    return, sampled over the run.

    At ``samples`` evenly spaced times the pass is timed on the solver's state as it is and with every
    material row switched to elastic in the kernel an elastic model runs (its copy without law calls),
    the fastest of ``repeats`` calls each, interleaved so that a change of the machine's pace falls on
    both.  Every call starts from the same state and everything the pass writes is put back after, so
    the run goes on to the bit as without the probe.  The share is the sum of the differences over the sum of the
    plastic passes; ``yielding`` is the mean fraction of cells whose plastic strain grew in the sampled
    passes (the final state alone, nearly at rest, has about 1% yielding and says little)."""

    def __init__(self, end_time: float, samples: int = 8, repeats: int = 11):
        self.due = [end_time * (k + 0.5) / samples for k in range(samples)]
        self.repeats = repeats
        self.plastic_s = self.elastic_s = self.wall_s = 0.0
        self.yielding: list[float] = []

    def __call__(self, solver):
        if not self.due or solver.t < self.due[0]:
            return
        self.due.pop(0)
        t0 = time.perf_counter()
        self._sample(solver)
        self.wall_s += time.perf_counter() - t0

    @property
    def share(self) -> float:
        return max(0.0, (self.plastic_s - self.elastic_s) / self.plastic_s) if self.plastic_s else float("nan")

    def _sample(self, solver):
        from .materials import layout
        m = solver.model
        arrays = [solver.sigma, solver.plastic_state, solver.hourglass, solver.f_int, solver.body_energy,
                  solver.peak]
        saved = [a.copy() for a in arrays]
        scalars = (solver.dt_stable, solver.critical_cell)
        params = m.params.copy()
        elastic = params.copy()
        elastic[:, layout.P_LAW] = layout.ELASTIC
        # the elastic reference is what an elastic model runs: the kernels' copy without law calls
        kernels = {"plastic": solver._element_pass, "elastic": element_pass(m.cell_kind, m.one_point, True)}
        eps_before = solver.plastic_state[:, :, layout.S_EPS].max(axis=1)
        best = {"plastic": float("inf"), "elastic": float("inf")}
        for _ in range(self.repeats):
            for mode, rows in (("plastic", params), ("elastic", elastic)):
                m.params[:] = rows
                solver._element_pass = kernels[mode]
                for a, s in zip(arrays, saved):
                    a[:] = s
                t0 = time.perf_counter()
                solver._internal_force(solver.dt)
                best[mode] = min(best[mode], time.perf_counter() - t0)
                if mode == "plastic":
                    grew = solver.plastic_state[:, :, layout.S_EPS].max(axis=1) > eps_before
        self.yielding.append(float(grew.mean()))
        m.params[:] = params
        solver._element_pass = kernels["plastic"]
        for a, s in zip(arrays, saved):
            a[:] = s
        solver.dt_stable, solver.critical_cell = scalars
        self.plastic_s += best["plastic"]
        self.elastic_s += best["elastic"]


def taylor_bar_bench(sizes, echo=print) -> list[dict]:
    """Copper Taylor bar: final length and radius errors against wall time and element-cycles/s."""
    from .verify.plasticity_cases import TAYLOR, taylor_measures, taylor_scene
    from .verify.scenes import solve
    echo("speed against error: copper Taylor bar (axisymmetric, one-point quads, 80 us, impact face held on the wall)")
    echo(f"{'size[mm]':>8s} {'elements':>9s} {'steps':>7s} {'wall[s]':>8s} {'Mcyc/s':>7s} {'length err':>10s} "
         f"{'radius err':>10s} {'eps_max':>7s} {'E err':>8s} {'return share':>12s} {'yielding':>8s}")
    out = []
    for h in sizes:
        share = ReturnShare(TAYLOR["end_time"])
        solver, wall = solve(taylor_scene(h), probe=share)
        wall -= share.wall_s             # the probe's passes are not the run's
        r = taylor_measures(solver)
        n = solver.model.num_cells_global
        row = {"case": "taylor_bar", "kinematics": "axisymmetric", "element_size_m": h, "elements": n, "steps": solver.step, "wall_time_s": wall,
               "element_cycles_per_s": n * solver.step / wall,
               "length_error": r["length"] / TAYLOR["final_length"] - 1,
               "radius_error": r["radius"] / TAYLOR["final_radius"] - 1,
               "max_plastic_strain": r["max_plastic_strain"], "balance_error": solver.energy.balance_error,
               "share_internal_force": solver.times.internal_force / wall,
               "share_plastic_return_of_internal_force": share.share,
               "yielding_fraction_sampled": sum(share.yielding) / len(share.yielding)}
        out.append(row)
        echo(f"{h * 1e3:8.2f} {n:9d} {solver.step:7d} {wall:8.2f} {row['element_cycles_per_s'] / 1e6:7.2f} "
             f"{row['length_error']:+10.2%} {row['radius_error']:+10.2%} {r['max_plastic_strain']:7.3g} "
             f"{row['balance_error']:8.1e} {row['share_plastic_return_of_internal_force']:12.0%} "
             f"{row['yielding_fraction_sampled']:8.0%}")
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


class CompileClock(event.Listener):
    """The process CPU time numba spends compiling, from its ``numba:compile`` events: the outermost compile
    of each kernel called from Python, which holds the compiles of the kernels it calls (``count``, every
    compile, nested ones too)."""

    def __init__(self):
        self.depth = 0
        self.start = 0.0
        self.seconds = 0.0
        self.count = 0

    def on_start(self, event):
        self.count += 1
        if self.depth == 0:
            self.start = time.process_time()
        self.depth += 1

    def on_end(self, event):
        self.depth -= 1
        if self.depth == 0:
            self.seconds += time.process_time() - self.start


def _compile_case_runs() -> dict:
    """What each compile row runs: a few steps of the case at its smallest size."""
    from .verify.contact_cases import two_rods_scene
    from .verify.plasticity_cases import taylor_scene
    from .verify.scenes import solve
    few_steps = 2e-6

    def speed_case(case):
        kin, element, integration, R, L, sizes = SPEED_CASES[case]
        raw = rod_scene(f"bench_{case}", kin, element, radius=R, length=L, h=QUICK_SIZES[case][0], end_time=1.0,
                        integration=integration)
        return lambda: time_steps(raw, 2)

    def contact(kinematics):
        raw = two_rods_scene(QUICK_CONTACT_SIZES[kinematics][0], kinematics)
        raw["scene"]["end_time"] = few_steps
        return lambda: solve(raw)

    runs = {case: speed_case(case) for case in SPEED_CASES}
    runs["taylor_bar"] = lambda: solve(taylor_scene(TAYLOR_QUICK_SIZE, end_time=few_steps))
    runs["two_rods_contact axisymmetric"] = contact("axisymmetric")
    runs["two_rods_contact 3d"] = contact("3d")
    return runs


def compile_cases():
    """Run every compile row's case in turn in this process and print its figures as one JSON line (what
    ``compile_bench`` runs with an empty cache)."""
    clock = CompileClock()
    rows = []
    with event.install_listener("numba:compile", clock):
        for case, run in _compile_case_runs().items():
            seconds, count, cpu = clock.seconds, clock.count, time.process_time()
            run()
            rows.append({"case": "compile", "compiled_case": case, "kernels_compiled": clock.count - count,
                         "compile_cpu_s": clock.seconds - seconds, "case_cpu_s": time.process_time() - cpu})
    print(json.dumps(rows))


def compile_bench(echo=print) -> list[dict]:
    """The compile time of the kernels each case uses, from nothing (module docstring)."""
    echo("compile time from an empty cache: each case's first steps in turn, in one process (CPU seconds)")
    echo(f"{'case':32s} {'kernels':>7s} {'compile[s]':>10s} {'case[s]':>8s}")
    with tempfile.TemporaryDirectory() as cache:
        p = subprocess.run([sys.executable, "-c", "from shockfem.bench import compile_cases; compile_cases()"],
                           env=dict(os.environ, NUMBA_CACHE_DIR=cache), capture_output=True, text=True)
    if p.returncode != 0:
        echo(f"compile time not measured: its process failed ({p.stderr.strip().splitlines()[-1:]})")
        return []
    rows = json.loads(p.stdout.strip().splitlines()[-1])
    for r in rows:
        echo(f"{r['compiled_case']:32s} {r['kernels_compiled']:7d} {r['compile_cpu_s']:10.1f} {r['case_cpu_s']:8.1f}")
    echo(f"{'all':32s} {sum(r['kernels_compiled'] for r in rows):7d} {sum(r['compile_cpu_s'] for r in rows):10.1f} "
         f"{sum(r['case_cpu_s'] for r in rows):8.1f}")
    return rows
