"""Verification of the preload stage (``solver/preload.py``): a shrink fit settled, then left alone.

The steel ring of ``split_cone_cases.shrink_fit`` (radial interference 0.02 mm on a solid shaft of its
length) comes on over 200 us in a ``[scene.preload]`` stage; the event that follows has nothing moving.
Settled, the fit must hold Lame's pressure (3%, the shrink fit's own acceptance) and stay still: the
kinetic energy through the event below 1e-6 of the stored energy (9e-8 measured at coarse size; the same
fit brought on by the interference option alone still rings at 7e-6 after its ramp), the energy
balance closed through stage and event (1%, the verification's bound).
"""
from __future__ import annotations

import time

import numpy as np

from .checks import check, element_count
from .scenes import STEEL
from .split_cone_cases import SHRINK, _shrink_fit_scene, lame_shrink_fit


def preload_stage(size, workdir):
    """A shrink fit settled in a preload stage, then left alone for 200 us: Lame's pressure, at rest."""
    from ..geometry import build_mesh
    from ..model import build_model
    from ..scene import resolve
    from ..solver.explicit import ExplicitSolver
    from ..solver.preload import settle
    raw = _shrink_fit_scene(size)
    raw["scene"]["end_time"] = SHRINK["ramp"]
    raw["scene"]["preload"] = {}
    scene = resolve(raw)
    solver = ExplicitSolver(build_model(scene, build_mesh(scene, cache_dir=workdir, log=lambda m: None)))
    t0 = time.perf_counter()
    report = settle(solver, scene.preload, log=lambda m: None)
    pair = solver.contacts[0]
    pressure, kinetic = [], []
    for s in solver.steps(scene.end_time):
        pressure.append(pair._pressure()["mean_pressure"])
        kinetic.append(s.energy.kinetic)
    wall = time.perf_counter() - t0
    E, nu = STEEL["youngs_modulus"], STEEL["poisson_ratio"]
    exact = lame_shrink_fit(SHRINK["interference"], 0.0, SHRINK["shaft_radius"], SHRINK["ring_outer"], E, nu, E, nu)
    p = np.array(pressure)
    n = element_count(solver)
    stored = solver.energy.internal
    return [
        check("preload.settled [-, abs]", 1.0, float(report["settled"]), 0.0, wall, n, absolute=True),
        check("preload.mean_pressure [Pa]", exact, float(p.mean()), 0.03, wall, n),
        check("preload.pressure_swing [-, abs]", 0.0, float((p.max() - p.min()) / exact), 0.01, wall, n,
              absolute=True),
        check("preload.kinetic_share [-, abs]", 0.0, max(kinetic) / stored, 1e-6, wall, n, absolute=True),
        check("preload.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n, absolute=True),
    ]
