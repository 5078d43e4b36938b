"""Field output of a run: ``fields.xdmf`` at the field cadence and ``final_shape.xdmf`` at the end.

``fields.xdmf`` (+ ``fields.h5``, ``output/xdmf.py``): one time series of whole grids on the reference
mesh, each frame carrying the cell's ``body`` number and every field the scene asks for
(``outputs.fields``): ``displacement`` [m] and ``velocity`` [m/s] at the nodes (3 components, so
ParaView's *Warp By Vector* with ``displacement`` shows the deformed shape), and cell values
(``cell_fields.py``): ``von_mises`` and ``pressure`` [Pa], ``plastic_strain`` [-],
``plastic_strain_rate`` [1/s], the ``stress_*`` components [Pa] and the logarithmic ``strain_*``
components [-].  *Threshold* on ``body`` selects a body; the file names them.

``final_shape.xdmf``: one frame whose geometry is the deformed mesh at the run's end, with every
cell field, for measuring a deformed part directly (a Taylor bar's length and
footprint).

Under MPI the ranks' owned nodes and cells are gathered to the last rank (``writer``), which writes the
files: the same mesh and values as one process writes, its cells and nodes numbered in the ranks' order.
The last rank, not rank 0: rank 0 streams the history and writes the run directory's other files, and
every rank waits for the slowest at the step's reductions, so the two outputs' work goes to two ranks.
"""
from __future__ import annotations

import os

import numpy as np
from dolfinx import io

from .. import compat
from ..solver.explicit import ExplicitSolver
from . import cell_fields
from .xdmf import Field, Mesh, TimeSeries, three_coordinates, xdmf_cells

NODE_FIELDS = {"displacement": "m", "velocity": "m/s"}


def writer(comm) -> int:
    """The rank that gathers and writes the field files (the module's docstring says why the last)."""
    return comm.size - 1


class _Gathered:
    """The model's owned nodes and cells of every rank, in rank order, on the ``writer`` rank (None elsewhere)."""

    def __init__(self, model):
        self.comm = model.comm
        mesh = model.meshed.mesh
        self.num_nodes = model.num_owned
        self.num_cells = mesh.topology.index_map(mesh.topology.dim).size_local
        cells = model.dofmap[:self.num_cells]
        if self.comm.size > 1:
            cells = compat.global_node_numbers(model.V)[cells]
        self.cell_type = mesh.topology.cell_name()
        self.cells = self._stack(xdmf_cells(cells, self.cell_type))
        self.body = self._stack(model.cell_body[:self.num_cells] + 1)

    def _stack(self, local: np.ndarray):
        if self.comm.size == 1:
            return local
        root = writer(self.comm)
        parts = self.comm.gather(np.ascontiguousarray(local), root=root)
        return np.concatenate(parts) if self.comm.rank == root else None

    def nodes(self, values: np.ndarray):
        return self._stack(values[:self.num_nodes])

    def cell_values(self, values: np.ndarray):
        return self._stack(values[:self.num_cells])

    def mesh(self, points: np.ndarray, body_names) -> Mesh | None:
        """The mesh on the writer rank with ``points`` (this rank's nodes, gdim coordinates); None elsewhere."""
        gathered = self.nodes(points)
        if gathered is None:
            return None
        return Mesh(three_coordinates(gathered), self.cells, self.cell_type, self.body, tuple(body_names))


def _fields(solver: ExplicitSolver, names) -> list[Field]:
    nodal = [Field(n, "Node", 3, u) for n, u in NODE_FIELDS.items() if n in names]
    cells = [Field(n, "Cell", 1, u) for n, u in cell_fields.units(solver, names).items()]
    return nodal + cells


def _values(solver: ExplicitSolver, gathered: _Gathered, names) -> dict:
    """Every requested field's values, gathered (collective; a dict on the writer rank, empty elsewhere)."""
    out = {}
    if "displacement" in names:
        out["displacement"] = gathered.nodes(solver.x - solver.model.X0)
    if "velocity" in names:
        out["velocity"] = gathered.nodes(solver.motion()[0])     # at t (the solver holds v_{n+1/2})
    for name, v in cell_fields.cell_fields(solver, names, gathered.num_cells).items():
        out[name] = gathered.cell_values(v)
    return out if solver.comm.rank == writer(solver.comm) else {}


class FieldWriter:
    """``fields.xdmf`` of a run: a frame at each call of ``write``."""

    def __init__(self, path: str, solver: ExplicitSolver, fields, resume_after: float | None = None):
        """A new ``path`` with the mesh and its bodies; or, with ``resume_after`` (a resumed run), the
        existing file cut back to its frames up to that time, to be appended to."""
        self.solver, self.names = solver, tuple(fields)
        self.gathered = _Gathered(solver.model)
        mesh = self.gathered.mesh(solver.model.X0, solver.model.body_names)
        self.series = (TimeSeries(path, mesh, _fields(solver, self.names), resume_after)
                       if solver.comm.rank == writer(solver.comm) else None)
        self.last = resume_after        # the time of the last frame written

    def write(self, t: float):
        """One frame (collective).  A frame at the time of the last one is already there (a run stopped
        right after a frame)."""
        if t == self.last:
            return
        self.last = t
        values = _values(self.solver, self.gathered, self.names)
        if self.series is not None:
            self.series.append(t, values)

    def flush(self):
        """The XDMF file listing every frame written (it is rewritten only now and then as they come)."""
        if self.series is not None:
            self.series.flush()

    close = flush


def write_final_shape(path: str, solver: ExplicitSolver):
    """The deformed mesh at the solver's time with every cell field, to ``path`` (collective).  No
    displacement: the geometry is already the deformed one (a warp by it would deform it twice)."""
    names = tuple(cell_fields.SCALARS) + tuple(cell_fields.TENSORS)
    gathered = _Gathered(solver.model)
    mesh = gathered.mesh(solver.x, solver.model.body_names)
    values = _values(solver, gathered, names)
    if mesh is not None:
        series = TimeSeries(path, mesh, _fields(solver, names))
        series.append(solver.t, values)
        series.close()


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
