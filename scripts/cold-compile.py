"""Cold-compile time of the first axisymmetric plastic run (one-point quads): a coarse Taylor bar."""
import time, sys
t0 = time.perf_counter()
from mpi4py import MPI
from shockfem.verify.plasticity_cases import taylor_scene
from shockfem.verify.scenes import solve
import shockfem
print("shockfem from", shockfem.__file__)
solver, wall = solve(taylor_scene(0.0008, end_time=2e-6))
print(f"first plastic run: {time.perf_counter() - t0:.1f} s (solve wall {wall:.1f} s, {solver.step} steps)")
