"""Field output to XDMF/HDF5 (opens in ParaView and pyvista).

The mesh is written once in its reference configuration with a ``body`` cell tag;
displacement and velocity are P1 fields (use ParaView's *Warp By Vector* with
``displacement`` for the deformed shape), von Mises stress and pressure are cell
averages (DG0).  Select one body with a *Threshold* on ``body``.
"""
from __future__ import annotations

import numpy as np
from dolfinx import fem, io

from ..solver.explicit import ExplicitSolver


def von_mises(sigma: np.ndarray) -> np.ndarray:
    """sqrt(3/2 s:s) of stresses stored as [..., 6] = [11, 22, 33, 23, 13, 12] [Pa]."""
    p = sigma[..., :3].mean(axis=-1)
    s = sigma[..., :3] - p[..., None]
    return np.sqrt(1.5 * ((s ** 2).sum(axis=-1) + 2.0 * (sigma[..., 3:] ** 2).sum(axis=-1)))


def pressure(sigma: np.ndarray) -> np.ndarray:
    """-tr(sigma)/3 [Pa], positive in compression."""
    return -sigma[..., :3].mean(axis=-1)


class FieldWriter:
    def __init__(self, path: str, solver: ExplicitSolver, fields):
        m = solver.model
        self.solver = solver
        self.fields = tuple(fields)
        mesh = m.meshed.mesh
        self.file = io.XDMFFile(mesh.comm, path, "w")
        self.file.write_mesh(mesh)
        m.meshed.cell_tags.name = "body"
        self.file.write_meshtags(m.meshed.cell_tags)
        DG0 = fem.FunctionSpace(mesh, ("DG", 0))
        self.vm = fem.Function(DG0, name="von_mises")
        self.p = fem.Function(DG0, name="pressure")
        self.vel = fem.Function(m.V, name="velocity")
        self.num_cells = mesh.topology.index_map(mesh.topology.dim).size_local

    def write(self, t: float):
        s = self.solver
        if "displacement" in self.fields:
            s.u_fn.x.scatter_forward()
            self.file.write_function(s.u_fn, t)
        if "velocity" in self.fields:
            # velocity at t_n (the solver holds v_{n-1/2}, v_{n+1/2} is ahead by half a step)
            self.vel.x.array[:] = (s.v + 0.5 * s.dt * s.a).reshape(-1)
            self.vel.x.scatter_forward()
            self.file.write_function(self.vel, t)
        n = self.num_cells
        cell_sigma = s.sigma[:n].mean(axis=1)
        if "von_mises" in self.fields:
            self.vm.x.array[:n] = von_mises(cell_sigma)
            self.vm.x.scatter_forward()
            self.file.write_function(self.vm, t)
        if "pressure" in self.fields:
            self.p.x.array[:n] = pressure(cell_sigma)
            self.p.x.scatter_forward()
            self.file.write_function(self.p, t)

    def close(self):
        self.file.close()
