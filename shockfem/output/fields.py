"""Field output to XDMF/HDF5 (opens in ParaView and pyvista).

``fields.xdmf``: the mesh is written once in its reference configuration with a ``body`` cell
tag; displacement and velocity are P1 fields (use ParaView's *Warp By Vector* with
``displacement`` for the deformed shape); von Mises stress, pressure, equivalent plastic
strain and plastic strain rate are cell averages (DG0).  Select one body with a *Threshold*
on ``body``.

``final_shape.xdmf``: the mesh in its final, deformed configuration with the same cell fields,
for measuring a deformed part directly (a Taylor bar's length and footprint).
"""
from __future__ import annotations

import os
from xml.etree import ElementTree

import h5py
import numpy as np
from dolfinx import fem, io

from .. import compat
from ..materials.layout import S_EPS, S_RATE
from ..solver.explicit import ExplicitSolver

# the XDMF files say xi:include: written back under that prefix, not ElementTree's ns0
ElementTree.register_namespace("xi", "http://www.w3.org/2001/XInclude")

CELL_FIELDS = ("von_mises", "pressure", "plastic_strain", "plastic_strain_rate")


def von_mises(sigma: np.ndarray) -> np.ndarray:
    """sqrt(3/2 s:s) of stresses stored as [..., 6] = [11, 22, 33, 23, 13, 12] [Pa]."""
    p = sigma[..., :3].mean(axis=-1)
    s = sigma[..., :3] - p[..., None]
    return np.sqrt(1.5 * ((s ** 2).sum(axis=-1) + 2.0 * (sigma[..., 3:] ** 2).sum(axis=-1)))


def pressure(sigma: np.ndarray) -> np.ndarray:
    """-tr(sigma)/3 [Pa], positive in compression."""
    return -sigma[..., :3].mean(axis=-1)


def cell_values(solver: ExplicitSolver, name: str) -> np.ndarray:
    """A cell field (one of ``CELL_FIELDS``) averaged over each cell's points, (cells,)."""
    if name == "von_mises":
        return von_mises(solver.sigma.mean(axis=1))
    if name == "pressure":
        return pressure(solver.sigma.mean(axis=1))
    if not solver.model.plastic:
        return np.zeros(len(solver.sigma))
    column = S_EPS if name == "plastic_strain" else S_RATE
    return solver.plastic_state[:, :, column].mean(axis=1)


class _CellFields:
    """DG0 functions for the requested cell fields of a mesh, written to an XDMF file."""

    def __init__(self, solver: ExplicitSolver, names):
        mesh = solver.model.meshed.mesh
        DG0 = compat.cell_space(mesh)
        self.solver = solver
        self.functions = {n: fem.Function(DG0, name=n) for n in CELL_FIELDS if n in names}
        self.num_cells = mesh.topology.index_map(mesh.topology.dim).size_local

    def write(self, file: io.XDMFFile, t: float):
        n = self.num_cells
        for name, fn in self.functions.items():
            compat.set_cell_values(fn, cell_values(self.solver, name), n)
            file.write_function(fn, t)


class FieldWriter:
    def __init__(self, path: str, solver: ExplicitSolver, fields, resume_after: float | None = None):
        """A new ``path`` with the mesh and its body tags; or, with ``resume_after`` (a resumed run), the
        existing file cut back to its frames up to that time, to be appended to."""
        m = solver.model
        self.solver = solver
        self.fields = tuple(fields)
        mesh = m.meshed.mesh
        self.path, self.comm = path, mesh.comm
        if resume_after is None:
            with io.XDMFFile(mesh.comm, path, "w") as file:
                file.write_mesh(mesh)
                m.meshed.cell_tags.name = "body"
                file.write_meshtags(m.meshed.cell_tags)
        else:
            if self.comm.rank == 0:
                drop_frames_after(path, resume_after)
            self.comm.barrier()
        self.cells = _CellFields(solver, self.fields)
        self.vel = fem.Function(m.V, name="velocity")
        self.last = resume_after        # the time of the last frame written

    def write(self, t: float):
        """One frame, the file opened to append it and closed again (1-2 ms): the HDF5 file is whole
        between frames, so a run killed at any moment leaves it readable to its last complete frame.  A
        frame at the time of the last one is already there (a run stopped right after a frame)."""
        if t == self.last:
            return
        self.last = t
        s = self.solver
        with io.XDMFFile(self.comm, self.path, "a") as file:
            if "displacement" in self.fields:
                s.u_fn.x.scatter_forward()
                file.write_function(s.u_fn, t)
            if "velocity" in self.fields:
                # velocity at t_n (the solver holds v_{n-1/2}, v_{n+1/2} is ahead by half a step)
                self.vel.x.array[:] = (s.v + 0.5 * s.dt * s.a).reshape(-1)
                self.vel.x.scatter_forward()
                file.write_function(self.vel, t)
            self.cells.write(file, t)

    def close(self):
        """Nothing stays open between frames."""


def drop_frames_after(path: str, t: float):
    """Cut the XDMF file ``path`` (as ``FieldWriter`` writes it) back to its frames at times up to ``t``:
    the later frames of a run resumed from a checkpoint at ``t`` are written again.  Their grids leave
    the XML and their datasets the HDF5 file (a frame written again at the same time would collide)."""
    tree = ElementTree.parse(path)
    domain = tree.getroot().find("Domain")
    dropped = []
    for series in domain.findall("Grid[@CollectionType='Temporal']"):
        for grid in series.findall("Grid"):
            if float(grid.find("Time").get("Value")) > t:
                dropped += [item.text.strip().split(":", 1)[1] for item in grid.iter("DataItem")]
                series.remove(grid)
    if not dropped:
        return
    with h5py.File(os.path.splitext(path)[0] + ".h5", "a") as h5:
        for name in dropped:
            if name in h5:
                del h5[name]
    partial = path + ".partial"
    tree.write(partial, xml_declaration=True, encoding="utf-8")
    os.replace(partial, path)


def write_final_shape(path: str, solver: ExplicitSolver):
    """The deformed mesh at the solver's time with all cell fields, to ``path`` (XDMF)."""
    m = solver.model
    mesh = m.meshed.mesh
    x = mesh.geometry.x
    reference = x.copy()
    nodes_per_cell = m.dofmap.shape[1]
    # P1 dofs and geometry nodes list a cell's vertices in the same (reference) order
    geometry = mesh.geometry.dofmap.array.reshape(-1, nodes_per_cell)[:len(m.dofmap)]
    x[geometry, :m.gdim] = solver.x[m.dofmap]
    try:
        with io.XDMFFile(mesh.comm, path, "w") as f:
            f.write_mesh(mesh)
            f.write_meshtags(m.meshed.cell_tags)
            _CellFields(solver, CELL_FIELDS).write(f, solver.t)
    finally:
        x[:] = reference


def write_mesh(meshed, path: str):
    """The scene's mesh with its body (cell) and region (facet) tags, to ``path`` (XDMF)."""
    mesh = meshed.mesh
    if mesh.comm.rank == 0:
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    mesh.comm.barrier()
    mesh.topology.create_connectivity(mesh.topology.dim - 1, mesh.topology.dim)
    meshed.cell_tags.name = "body"
    meshed.facet_tags.name = "region"
    with io.XDMFFile(mesh.comm, path, "w") as f:
        f.write_mesh(mesh)
        f.write_meshtags(meshed.cell_tags)
        f.write_meshtags(meshed.facet_tags)
