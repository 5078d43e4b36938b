"""The per-step peak von Mises pass (``output/peak_stress.py``) against the step, at ``shockfem bench``'s
first two sizes of each case given: CPU time of the step and of the pass in the same loop (the peak rises
every step of the bench's growing stresses), and of the pass alone on the last step's stresses (no new
peak).  docs/performance.md gives the figures.

    python scripts/peak-stress-cost.py STEPS CASE...     (CASE: a key of bench.SPEED_CASES)
"""
import sys
import time

from mpi4py import MPI
from shockfem.bench import SPEED_CASES
from shockfem.geometry import build_mesh
from shockfem.model import build_model
from shockfem.scene import resolve
from shockfem.solver.explicit import ExplicitSolver
from shockfem.output.peak_stress import PeakStress
from shockfem.verify.scenes import rod_scene

steps = int(sys.argv[1])
for case in sys.argv[2:]:
    kin, element, integration, R, L, sizes = SPEED_CASES[case]
    for h in sizes[:2]:
        scene = resolve(rod_scene(f"bench_{case}_{h}", kin, element, radius=R, length=L, h=h, end_time=1.0,
                                  integration=integration))
        model = build_model(scene, build_mesh(scene, MPI.COMM_WORLD, log=lambda m: None))
        solver = ExplicitSolver(model, initial_velocity=lambda x: 1e-3 * x / x.max())
        peaks = PeakStress(solver)
        solver.advance(solver.stable_step())        # untimed: first touch of the arrays
        peaks.update(solver.t)
        step_cpu = pass_cpu = 0.0
        for _ in range(steps):
            c0 = time.process_time()
            solver.advance(solver.stable_step())
            c1 = time.process_time()
            peaks.update(solver.t)
            c2 = time.process_time()
            step_cpu += c1 - c0
            pass_cpu += c2 - c1
        # a tighter figure for the pass alone: many calls on the same stresses
        c0 = time.process_time()
        for _ in range(steps):
            peaks.update(solver.t)
        alone = (time.process_time() - c0) / steps
        print(f"{case:22s} h={h:<7g} cells={model.num_cells_global:7d} step {step_cpu / steps * 1e3:8.3f} ms  "
              f"pass {pass_cpu / steps * 1e3:7.4f} ms ({pass_cpu / step_cpu:6.2%})  pass alone {alone * 1e3:7.4f} ms "
              f"({alone / (step_cpu / steps):6.2%})", flush=True)
