"""This tree against another checkout, in one process: a ``shockfem bench`` speed case (or the Taylor bar)
built by each, their loops interleaved round by round.

    python scripts/bench-ab.py OTHER_CHECKOUT axisymmetric-quad 0.001 --steps 200 --rounds 15
    python scripts/bench-ab.py OTHER_CHECKOUT taylor_bar 0.0002 --rounds 5
    python scripts/bench-ab.py OTHER_CHECKOUT axisymmetric-quad-full 0.0022 --pass-only --rounds 200

The machine changes pace for tens of calls at a time, so two processes run in turn compare two paces as
often as two codes.  Here the other checkout's package is copied under another name (``shockfem_other``,
without its numba caches: a cached kernel's symbols carry the package's name, and two packages' kernels of
one name in a process could link to each other) into a temporary folder, both are imported, and every
round times each mode once, in an order that rotates.  The first run compiles the copy's kernels.

Modes: ``this`` (this tree's bench loop, ``bench.time_steps``' steps), ``other``, and ``other+peak``: the
other checkout's loop with its ``output.peak_stress.PeakStress.update`` after every step, where that
checkout takes the peak von Mises stress in a separate pass (its run path calls it so; in this tree the
element pass keeps it).  ``--pass-only`` times the element pass alone (``ExplicitSolver._internal_force``),
call by call, and the separate peak pass.  Before timing, both trees step the same state for a few steps
and the script says whether their stresses and forces are equal to the bit.  One JSON line per round (M
element-cycles/s per mode, or ns a cell per call), then the medians of the ratios.
"""
from __future__ import annotations

import argparse
import importlib
import json
import os
import shutil
import statistics
import sys
import tempfile
import time

import numpy as np

OTHER = "shockfem_other"


def copy_package(checkout: str, into: str) -> None:
    """``checkout``'s package as ``OTHER`` under ``into``, without numba's cache files (a copy already there,
    with the caches it compiled, is used as it is)."""
    if not os.path.isdir(os.path.join(into, OTHER)):
        shutil.copytree(os.path.join(checkout, "shockfem"), os.path.join(into, OTHER),
                        ignore=shutil.ignore_patterns("*.nbi", "*.nbc"))
    sys.path.insert(0, into)


def module(package: str, name: str):
    return importlib.import_module(f"{package}.{name}")


def has_separate_peak(package: str) -> bool:
    """Whether ``package``'s run path takes the peak stress in a pass of its own after the step."""
    return hasattr(module(package, "output.peak_stress"), "largest_von_mises2")


def speed_solver(package: str, case: str, h: float):
    """The bench's speed case at element size ``h`` [m], built by ``package``, as ``bench.time_steps`` builds it."""
    from mpi4py import MPI
    kin, element, integration, radius, length, _ = module(package, "bench").SPEED_CASES[case]
    raw = module(package, "verify.scenes").rod_scene(f"bench_{case}_{h}", kin, element, radius=radius,
                                                     length=length, h=h, end_time=1.0, integration=integration)
    scene = module(package, "scene").resolve(raw)
    mesh = module(package, "geometry").build_mesh(scene, MPI.COMM_WORLD, log=lambda m: None)
    model = module(package, "model").build_model(scene, mesh)
    return module(package, "solver.explicit").ExplicitSolver(model, initial_velocity=lambda x: 1e-3 * x / x.max())


def stepped_alike(case: str, h: float):
    """Both trees' solvers of the case after the same four steps (the first loads the kernels), and whether
    their stresses and forces are equal to the bit."""
    this, other = speed_solver("shockfem", case, h), speed_solver(OTHER, case, h)
    for _ in range(4):
        for s in (this, other):
            s.advance(s.stable_step())
    return this, other, bool(np.array_equal(this.sigma, other.sigma) and np.array_equal(this.f_int, other.f_int))


def stepper(solver, peaks, steps: int):
    """A timed loop of ``steps`` steps, with the separate peak pass after each if ``peaks``."""
    def run():
        t0 = time.perf_counter()
        for _ in range(steps):
            solver.advance(solver.stable_step())
            if peaks is not None:
                peaks.update(solver.t)
        return time.perf_counter() - t0
    return run


def speed_modes(case: str, h: float, steps: int):
    """Each mode's timed loop, the element count, and whether the two trees' steps are equal to the bit."""
    this, other, same = stepped_alike(case, h)
    peaks = module(OTHER, "output.peak_stress").PeakStress(other) if has_separate_peak(OTHER) else None
    modes = {"this": stepper(this, None, steps), "other": stepper(other, None, steps)}
    if peaks is not None:
        modes["other+peak"] = stepper(other, peaks, steps)
    return modes, this.model.num_cells_global, same


def pass_modes(case: str, h: float):
    """The element pass alone on each side, and the other side's separate peak pass."""
    this, other, same = stepped_alike(case, h)

    def timed(f):
        def run():
            t0 = time.perf_counter()
            f()
            return time.perf_counter() - t0
        return run

    modes = {"this": timed(lambda: this._internal_force(this.dt)),
             "other": timed(lambda: other._internal_force(other.dt))}
    if has_separate_peak(OTHER):
        peaks = module(OTHER, "output.peak_stress").PeakStress(other)
        modes["peak pass"] = timed(lambda: peaks.update(other.t))
    return modes, this.model.num_cells_global, same


def taylor_modes(h: float):
    """The Taylor bar's whole run on each side (``verify.scenes.solve``; the other side's with the separate
    peak pass as a probe as well)."""
    def run_of(package, with_peak):
        scene = module(package, "verify.plasticity_cases").taylor_scene
        solve = module(package, "verify.scenes").solve
        peak_stress = module(package, "output.peak_stress").PeakStress

        def run():
            held = {}

            def probe(solver):
                if "peaks" in held:
                    held["peaks"].update(solver.t)
                else:
                    held["peaks"] = peak_stress(solver)
            solver, wall = solve(scene(h), probe=probe if with_peak else None)
            run.cycles = solver.model.num_cells_global * solver.step
            run.solver = solver
            return wall
        return run

    modes = {"this": run_of("shockfem", False), "other": run_of(OTHER, False)}
    if has_separate_peak(OTHER):
        modes["other+peak"] = run_of(OTHER, True)
    modes["this"](), modes["other"]()           # untimed: kernels loaded, first touch
    a, b = modes["this"].solver, modes["other"].solver
    same = bool(np.array_equal(a.sigma, b.sigma) and np.array_equal(a.x, b.x))
    return modes, a.model.num_cells_global, same


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("other", help="the other checkout (a folder holding shockfem/)")
    parser.add_argument("case", help="a key of bench.SPEED_CASES, or taylor_bar")
    parser.add_argument("size", type=float, help="element size [m]")
    parser.add_argument("--steps", type=int, default=200, help="steps a timed loop (speed cases)")
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--pass-only", action="store_true", help="time the element pass alone, call by call")
    parser.add_argument("--copy-dir", help="keep the copy and its compiled kernels here, for the next call "
                                           "(default: a temporary folder)")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as temporary:
        copy_package(os.path.abspath(args.other), args.copy_dir or temporary)
        if args.case == "taylor_bar":
            modes, n, same = taylor_modes(args.size)
        elif args.pass_only:
            modes, n, same = pass_modes(args.case, args.size)
        else:
            modes, n, same = speed_modes(args.case, args.size, args.steps)
        print(json.dumps({"case": args.case, "size": args.size, "elements": n, "equal_to_the_bit": same}))
        names = list(modes)
        rounds = []
        for r in range(args.rounds):
            figures = {}
            for name in names[r % len(names):] + names[:r % len(names)]:
                wall = modes[name]()
                if args.pass_only:
                    figures[name] = wall / n * 1e9                       # ns a cell
                else:
                    cycles = getattr(modes[name], "cycles", n * args.steps)
                    figures[name] = cycles / wall / 1e6                  # M element-cycles/s
            rounds.append(figures)
            print(json.dumps({"round": r, **figures}), flush=True)
    unit = "ns a cell" if args.pass_only else "M element-cycles/s"
    print(f"medians over {len(rounds)} rounds ({unit}): "
          + ", ".join(f"{k} {statistics.median(f[k] for f in rounds):.3g}" for k in names))
    # speed of this tree over the other's, round by round (> 1: this one is faster)
    speed = {k: [f["this"] / f[k] for f in rounds] for k in names[1:] if k != "peak pass"}
    if args.pass_only:
        speed = {"other": [f["other"] / f["this"] for f in rounds]}
        if "peak pass" in modes:
            speed["other + peak pass"] = [(f["other"] + f["peak pass"]) / f["this"] for f in rounds]
    for k, ratios in speed.items():
        print(f"speed, this / {k}: median {statistics.median(ratios):.3f} ({min(ratios):.3f}-{max(ratios):.3f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
