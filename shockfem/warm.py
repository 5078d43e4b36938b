"""numba's kernels compiled into their cache before a first run needs them: ``shockfem warm``.

numba compiles a kernel at its first call, for the types of that call, and keeps the machine code in
``__pycache__`` beside the kernel's source; a later process loads it in milliseconds.  A first run therefore
pays the compile of every kernel it calls (a minute or more for a plastic contact scene), and so does every
process that starts before any other has finished compiling them.  ``warm`` runs each scene of a family for
a few steps through ``runner.run_scene``, as ``shockfem run`` does (histories, fields, metrics), so every
kernel such a run calls is compiled once, with the types a run calls it with.  Runs after it start computing
at once: the Docker image runs it when it is built, and the test suite before its workers start.

The families cover what the scenes of ``studies/`` and the test suite use: one-point quads (elastic, J2,
foam, rubber), triangles, contact with friction, cavities, springs and the penetration target in
axisymmetry; hexes, tetrahedra, 3D contact and the contact pair's MPI halo in 3D.  The cache holds code for
the CPU that compiled it: on another CPU model numba compiles again.
"""
from __future__ import annotations

import os
import tempfile
import time

from .errors import ModelError

# a few steps of each scene: enough to call every kernel it has
STEPS_S = 2e-6
STUDIES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "studies")

# scene files of studies/, or verification scenes by name (``_scene``)
FAMILIES = {
    "axisymmetric": ("foundation/bar_impact.toml", "metrics/rod_pulse.toml", "gallery/dashpot.toml",
                     "gallery/foam_pad.toml", "gallery/rubber_pad.toml", "gallery/split_cone.toml",
                     "gallery/penetration.toml", "gallery/projectile_payload.toml", "gallery/shrink_fit.toml"),
    "3d": ("gallery/tilted_drop.toml", "taylor_3d", "two_rods_3d", "tet_rod"),
}


def _scene(name: str) -> dict:
    """The raw scene ``name``: a verification scene, a file of ``studies/``, or a scene file's path."""
    from .scene import read_toml
    from .verify.contact_cases import two_rods_scene
    from .verify.plasticity_cases import taylor_scene
    from .verify.scenes import rod_scene
    if name == "taylor_3d":
        return taylor_scene(0.0016, kinematics="3d", end_time=STEPS_S)
    if name == "two_rods_3d":
        return two_rods_scene(0.005, "3d")
    if name == "tet_rod":
        return rod_scene("tet_rod", "3d", element="tet", h=0.004, velocity=-5.0)
    path = name if os.path.isfile(name) else os.path.join(STUDIES, name)
    if not os.path.isfile(path):
        raise ModelError(f"warm: no scene file {name!r} (give a scene file, or run from a source checkout, whose "
                         f"studies/ the families {', '.join(FAMILIES)} use)")
    return read_toml(path)


def warm_halo_kernels():
    """The kernels only a contact pair under MPI calls (``contact/halo.py``), with the types it calls them
    with, so that two ranks do not compile them at once."""
    import numpy as np
    from .contact import kernels
    x, nodes = np.zeros((2, 3)), np.arange(2, dtype=np.int64)
    rows = np.zeros((2, 6))
    kernels.pack_rows(x, x, nodes, rows)
    kernels.unpack_rows(rows, nodes, x, x)
    kernels.records_by_rank(np.zeros((1, kernels.record_width(4))), np.zeros(2, dtype=np.int64), 4, 0, 2)


def warm(names, report=None) -> list[tuple[str, float]]:
    """Compile (or load) the kernels of each family or scene file in ``names``, each scene run for
    ``STEPS_S`` in a temporary directory; ``report(name, seconds)`` after each.  Returns (scene, CPU seconds
    of this process) per scene, in order."""
    from .runner import run_scene
    from .scene import resolve
    scenes = []
    for name in names:
        scenes += FAMILIES.get(name, (name,))
    done = []
    with tempfile.TemporaryDirectory() as out:
        if "3d" in names:
            t0 = time.process_time()
            warm_halo_kernels()
            done.append(("contact halo (MPI)", time.process_time() - t0))
            if report:
                report(*done[-1])
        for k, name in enumerate(scenes):
            t0 = time.process_time()
            raw = _scene(name)
            raw["scene"]["end_time"] = STEPS_S
            run_scene(resolve(raw), os.path.join(out, str(k)), progress=False, quiet=True)
            done.append((name, time.process_time() - t0))
            if report:
                report(*done[-1])
    return done
