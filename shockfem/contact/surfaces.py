"""Contact surfaces: the boundary facets of a body or of one of its named regions, on every rank.

A facet is given by its nodes, ordered so that its normal points out of the body: in 2D the
segment (p0, p1) has the outward normal (t_y, -t_x) / |t|, t = p1 - p0; in 3D the facet
(p0, p1, ..., p_last) has the normal (p1 - p0) x (p_last - p0), quadrilaterals going around.
The order is fixed once on the reference mesh; kernels recompute normals every step.

Under MPI each rank finds the facets of its own part of the mesh and all ranks then share
them (global node numbers) once, so every rank knows the whole surface's facets; the positions of
its nodes are exchanged each step only where contact needs them (``halo.SurfaceHalo``: a rank's
slaves' near facets).  Springs, liquid cavities and the penetrated target, whose surfaces are
small, gather their nodes whole on every rank each step (``NodeExchange.gather``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import basix
import numpy as np
from dolfinx import mesh as dmesh
from mpi4py import MPI
from numba import njit

from ..geometry import region_facets
from ..model import Model
from ..model.kinematics import BASIX_CELLS
from ..materials.layout import P_LAMBDA, P_MU
from . import kernels

TWO_PI = 2.0 * math.pi
# tensor-ordered hexahedron (vertex k at (k & 1, k >> 1 & 1, k >> 2 & 1)) as six tetrahedra
# around its diagonal 0-7
_HEX_TETS = np.array([[0, 1, 3, 7], [0, 1, 5, 7], [0, 2, 3, 7], [0, 2, 6, 7], [0, 4, 5, 7], [0, 4, 6, 7]])


@dataclass
class Surface:
    name: str                   # "body" or "body.region"
    body: int                   # body index in the scene
    facets: np.ndarray          # (facets, nodes per facet) global node numbers, outward order
    area: np.ndarray            # (facets,) reference area [m^2] (2D: length x 2 pi r, or x thickness)
    size: np.ndarray            # (facets,) longest edge [m]
    bulk: np.ndarray            # (facets,) bulk modulus of the cell behind the facet [Pa]
    volume: np.ndarray          # (facets,) reference volume of that cell [m^3]


def _weight(model: Model, r: np.ndarray) -> np.ndarray:
    """The out-of-plane measure of 2D entities: 2 pi r (axisymmetric) or the thickness."""
    return TWO_PI * r if model.axisymmetric else np.full_like(r, model.thickness)


def cell_volumes(model: Model, cells: np.ndarray) -> np.ndarray:
    """Reference volumes of cells (2D: area x 2 pi r at the centroid of the nodes, or x thickness)."""
    p = model.X0[model.dofmap[cells]]
    nn = p.shape[1]
    if model.gdim == 2:
        if nn == 4:
            p = p[:, [0, 1, 3, 2]]                   # tensor order -> around
        x, y = p[..., 0], p[..., 1]
        area = 0.5 * np.abs(np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1))
        return area * _weight(model, x.mean(axis=1))
    tets = p[:, _HEX_TETS] if nn == 8 else p[:, None, :, :]
    e = tets[:, :, 1:] - tets[:, :, :1]
    return np.abs(np.linalg.det(e)).sum(axis=1) / 6.0


def area_vectors(model: Model, x: np.ndarray, facets: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """Area vectors of ``facets`` (facets, nodes: rows of ``x``, in outward order) on the positions ``x``:
    along the outward normal, as long as the facet's area (2D: its length times 2 pi r at its middle in
    axisymmetry, or the thickness), into ``out`` if given.  Compiled (``_area_vectors``): the liquid
    cavity and the penetrated target take them every step, where numpy's calls on a few facets cost
    tens of microseconds."""
    if out is None:
        out = np.empty((len(facets), model.gdim))
    _area_vectors(x, facets, model.axisymmetric, model.thickness, out)
    return out


@njit(cache=True)
def _area_vectors(x, facets, axisymmetric, thickness, out):
    """``area_vectors``' loop: a segment's (t_y, -t_x) w with t = p1 - p0 and w = 2 pi r at its middle or
    the thickness; a triangle's (p1 - p0) x (p2 - p0) / 2; a quadrilateral's (p2 - p0) x (p3 - p1) / 2."""
    for i in range(facets.shape[0]):
        a = facets[i, 0]
        if x.shape[1] == 2:
            b = facets[i, 1]
            w = TWO_PI * ((x[a, 0] + x[b, 0]) / 2.0) if axisymmetric else thickness
            out[i, 0] = (x[b, 1] - x[a, 1]) * w
            out[i, 1] = -(x[b, 0] - x[a, 0]) * w
            continue
        if facets.shape[1] == 3:
            b, c, d = facets[i, 1], a, facets[i, 2]            # (p1 - p0) x (p2 - p0)
        else:
            b, c, d = facets[i, 2], facets[i, 1], facets[i, 3]   # (p2 - p0) x (p3 - p1)
        u0, u1, u2 = x[b, 0] - x[a, 0], x[b, 1] - x[a, 1], x[b, 2] - x[a, 2]
        v0, v1, v2 = x[d, 0] - x[c, 0], x[d, 1] - x[c, 1], x[d, 2] - x[c, 2]
        out[i, 0] = 0.5 * (u1 * v2 - u2 * v1)
        out[i, 1] = 0.5 * (u2 * v0 - u0 * v2)
        out[i, 2] = 0.5 * (u0 * v1 - u1 * v0)


@njit(cache=True)
def trapezoidal_work(f, f_old, v, dt):
    """The work of nodal forces over a step, dt/2 (f_old + f) . v (v at the step's middle), for the loads
    whose forces the solver adds as they are (a liquid cavity, the penetrated target); ``f_old`` becomes
    ``f``."""
    power = 0.0
    for a in range(f.shape[0]):
        for j in range(f.shape[1]):
            power += (f_old[a, j] + f[a, j]) * v[a, j]
            f_old[a, j] = f[a, j]
    return 0.5 * dt * power


def _facet_geometry(model: Model, facets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Reference area and longest edge of facets given by local node numbers."""
    p = model.X0[facets]
    area = np.linalg.norm(area_vectors(model, model.X0, facets), axis=1)
    if model.gdim == 2:
        return area, np.linalg.norm(p[:, 1] - p[:, 0], axis=1)
    return area, np.linalg.norm(np.roll(p, -1, axis=1) - p, axis=2).max(axis=1)


def _boundary_facets(model: Model, spec: str) -> tuple[int, np.ndarray]:
    """Body index and the local facets of a "body" (its whole exterior) or a "body.region"."""
    body_name, _, region = spec.partition(".")
    names = model.body_names
    body = names.index(body_name)
    if region:
        return body, region_facets(model.meshed, spec)
    topology = model.meshed.mesh.topology
    tdim = topology.dim
    topology.create_connectivity(tdim - 1, tdim)
    facets = dmesh.exterior_facet_indices(topology)
    f_to_c = topology.connectivity(tdim - 1, tdim)
    first_cell = np.array([f_to_c.links(f)[0] for f in facets], dtype=np.int64)
    return body, facets[model.cell_body[first_cell] == body] if len(facets) else facets


def _outward_facets(model: Model, facets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Local node numbers of each facet in outward order, and the cell behind each."""
    topology = model.meshed.mesh.topology
    tdim = topology.dim
    topology.create_connectivity(tdim - 1, tdim)
    topology.create_connectivity(tdim, tdim - 1)
    f_to_c = topology.connectivity(tdim - 1, tdim)
    c_to_f = topology.connectivity(tdim, tdim - 1)
    ref_facets = basix.topology(BASIX_CELLS[topology.cell_name()])[tdim - 1]
    X = model.X0
    out, cells = [], []
    for f in facets:
        c = f_to_c.links(f)[0]
        local = int(np.flatnonzero(c_to_f.links(c) == f)[0])
        nodes = model.dofmap[c, ref_facets[local]].astype(np.int64)
        if len(nodes) == 4:
            nodes = nodes[[0, 1, 3, 2]]              # tensor order -> around
        p = X[nodes]
        if tdim == 2:
            t = p[1] - p[0]
            normal = np.array([t[1], -t[0]])
        else:
            normal = np.cross(p[1] - p[0], p[-1] - p[0])
        if np.dot(X[model.dofmap[c]].mean(axis=0) - p[0], normal) > 0:
            nodes = nodes[::-1]
        out.append(nodes)
        cells.append(c)
    width = len(ref_facets[0])
    return np.array(out, dtype=np.int64).reshape(-1, width), np.array(cells, dtype=np.int64)


# Reference positions rounded to a picometre.  dolfinx computes a node's coordinates from one of its cells,
# so they differ by ~1e-17 m from one partition to another; an order built from the rounded ones (which
# contact needs: ``build_surface``, ``pairs._reference_order``) is the same on any number of ranks.
REFERENCE_QUANTUM = 1e-12    # [m]


def reference_key(X: np.ndarray) -> np.ndarray:
    """Positions (..., gdim) as whole numbers of ``REFERENCE_QUANTUM`` (exact in a double up to 9 km)."""
    return np.round(X / REFERENCE_QUANTUM)


def _start_at_least(facets: np.ndarray, keys: np.ndarray) -> np.ndarray:
    """Each facet's nodes (local numbers, outward order) turned to start at its node of least reference
    position (x, then y, then z): the order a partition does not change (the cell's own vertex order
    does).  Turning keeps the outward order; a segment (2D) is left as it is (its order is its normal)."""
    nf = facets.shape[1]
    if nf < 3 or not len(facets):
        return facets
    k = keys[facets]                                    # (facets, nf, gdim)
    least = np.ones(k.shape[:2], dtype=bool)
    for d in range(k.shape[2]):
        column = np.where(least, k[..., d], np.inf)
        least &= column == column.min(axis=1, keepdims=True)
    first = np.argmax(least, axis=1)
    turn = (first[:, None] + np.arange(nf)[None, :]) % nf
    return np.take_along_axis(facets, turn, axis=1)


def _allgather(comm, a: np.ndarray) -> np.ndarray:
    if comm.size == 1:
        return a
    return np.concatenate(comm.allgather(a))


def build_surface(model: Model, spec: str) -> Surface:
    """The facets of ``spec`` ("body" or "body.region") from all ranks, in global node numbers, ordered
    by their centres in the reference configuration (x first), each starting at its node of least
    reference position: orders no partition changes (``reference_key``).

    Collective.  A facet seen by two ranks (a ghost facet) is kept once.
    """
    body, facets = _boundary_facets(model, spec)
    local, cells = _outward_facets(model, facets)
    keys = reference_key(model.X0)
    local = _start_at_least(local, keys)
    area, size = _facet_geometry(model, local)
    p = model.params[model.cell_material[cells]]
    bulk = p[:, P_LAMBDA] + 2.0 * p[:, P_MU] / 3.0
    volume = cell_volumes(model, cells)
    imap = model.V.dofmap.index_map
    to_global = imap.local_to_global(np.arange(imap.size_local + imap.num_ghosts, dtype=np.int32))
    glob = to_global[local].reshape(local.shape).astype(np.int64)
    centre = keys[local].sum(axis=1) if len(local) else np.zeros((0, model.gdim))     # nf x the centre, exact
    comm = model.comm
    glob = _allgather(comm, glob).reshape(-1, local.shape[1])
    area, size, bulk, volume = (_allgather(comm, a) for a in (area, size, bulk, volume))
    centre = _allgather(comm, centre).reshape(-1, model.gdim)
    _, first = np.unique(np.sort(glob, axis=1), axis=0, return_index=True)
    # in the order of their reference centres, which no partition changes: a contact pass's arithmetic
    # (which facet takes a node on an edge two facets share, in which order sums run) is then the same
    # on any number of ranks
    keep = first[np.lexsort(centre[first].T[::-1])]
    return Surface(spec, body, np.ascontiguousarray(glob[keep]), area[keep], size[keep], bulk[keep],
                   volume[keep])


class NodeExchange:
    """Copies between a rank's local node arrays and a compact array of chosen global nodes that
    every rank holds in full (the nodes of the contact surfaces, or of discrete springs), in the order of
    ``global_nodes`` (global node numbers, each once)."""

    def __init__(self, model: Model, global_nodes: np.ndarray):
        self.comm = model.comm
        self.size = len(global_nodes)
        imap = model.V.dofmap.index_map
        owned_global = imap.local_to_global(np.arange(imap.size_local, dtype=np.int32)).astype(np.int64)
        mine = np.isin(owned_global, global_nodes)
        self.local = np.flatnonzero(mine)                               # owned local nodes
        by_number = np.argsort(global_nodes)
        # their places in the compact array
        self.slot = by_number[np.searchsorted(global_nodes, owned_global[mine], sorter=by_number)]
        if self.comm.size > 1:
            self.counts = np.array(self.comm.allgather(len(self.local)))
            self.order = np.concatenate(self.comm.allgather(self.slot))
            if len(self.order) != self.size:
                raise RuntimeError("contact surface nodes are not owned exactly once over the ranks")

    def gather(self, values: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        """(local nodes, k) -> (compact nodes, k): every rank gets every value (into ``out`` if given).
        Collective."""
        k = values.shape[1]
        if out is None:
            out = np.empty((self.size, k))
        if self.comm.size == 1:
            kernels.gather_local(values, self.local, self.slot, out)
            return out
        mine = np.ascontiguousarray(values[self.local])
        received = np.empty((self.size, k))
        self.comm.Allgatherv(mine, [received, self.counts * k, None, MPI.DOUBLE])
        out[self.order] = received
        return out

    def gather_own(self, values: np.ndarray, out: np.ndarray):
        """(local nodes, k) -> this rank's own nodes of the compact array ``out`` (the others untouched)."""
        kernels.gather_local(values, self.local, self.slot, out)

    def owners(self) -> np.ndarray:
        """The rank owning each compact node."""
        owner = np.zeros(self.size, dtype=np.int64)
        if self.comm.size > 1:
            owner[self.order] = np.repeat(np.arange(self.comm.size), self.counts)
        return owner

    def add_to(self, compact: np.ndarray, local: np.ndarray):
        """Add compact values into the owned local nodes of this rank."""
        kernels.add_local(compact, self.slot, self.local, local)
