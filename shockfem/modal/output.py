"""Mode shapes to XDMF (one step per mode, in ParaView step through them and *Warp By Vector*)
and frequencies, labels, energy shares and what the body's damping makes of each mode
(``modal/damping.py``) to JSON."""
from __future__ import annotations

import json
import os

from dolfinx import fem, io

from .. import compat
from ..scene.damping import describe_damping
from .damping import mode_damping
from .labels import firsts


def write_modes(out_dir: str, modes, labels: list[dict]) -> dict:
    """Write ``modes.xdmf`` (+ .h5) and ``modes.json`` into ``out_dir``; returns the JSON data."""
    mesh = modes.space.mesh
    comm = mesh.comm
    if comm.rank == 0:
        os.makedirs(out_dir, exist_ok=True)
    comm.barrier()
    P1 = compat.vector_space(mesh, 1)
    shape = fem.Function(P1, name="mode_shape")
    with io.XDMFFile(comm, os.path.join(out_dir, "modes.xdmf"), "w") as xdmf:
        xdmf.write_mesh(mesh)
        for k, f in enumerate(modes.shapes, start=1):
            shape.interpolate(f)       # XDMF in dolfinx 0.5 writes fields of the mesh's degree
            xdmf.write_function(shape, float(k))
    data = {
        "body": modes.body, "kinematics": modes.kinematics, "element_degree": modes.degree,
        "mass": modes.mass, "boundary": "constrained" if modes.conditions else "free-free",
        "conditions": modes.conditions, "dofs": modes.dofs, "rigid_modes": modes.rigid,
        "wall_time_s": modes.wall_time_s,
        "damping": describe_damping(modes.damping) if modes.damping is not None else "none",
        "modes": [{"mode": k, "frequency_hz": float(f), **damped, **lab}
                  for k, (f, damped, lab) in enumerate(zip(modes.frequencies, mode_damping(modes.frequencies,
                                                                                        modes.damping), labels),
                                                       start=1)],
        "first": firsts(labels, modes.frequencies),
        "xdmf": "modes.xdmf: one step per mode (step k = mode k), field mode_shape scaled to max |u| = 1",
    }
    if comm.rank == 0:
        with open(os.path.join(out_dir, "modes.json"), "w") as fh:
            json.dump(data, fh, indent=2)
    return data
