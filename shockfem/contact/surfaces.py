"""Contact surfaces: the boundary segments of a body or of one of its named regions.

A segment is a boundary facet of the mesh given by its nodes (local P1 numbers), ordered so
that its normal points out of the body: in 2D the segment (p0, p1) has the outward normal
(t_y, -t_x) / |t|, t = p1 - p0.  The order is fixed once on the reference mesh; kernels
recompute the normal from the current positions every step.
"""
from __future__ import annotations

from dataclasses import dataclass

import basix
import numpy as np
from dolfinx import mesh as dmesh

from ..model import Model
from ..model.kinematics import BASIX_CELLS


@dataclass
class Surface:
    name: str                   # "body" or "body.region"
    body: int                   # body index in the scene
    segments: np.ndarray        # (segments, nodes per facet) local node numbers, outward order
    cells: np.ndarray           # (segments,) the cell each segment bounds
    nodes: np.ndarray           # unique nodes of the segments

    @property
    def num_segments(self) -> int:
        return len(self.segments)


def _boundary_facets(model: Model, spec: str) -> tuple[int, np.ndarray]:
    """Body index and the facets of a "body" (its whole exterior) or a "body.region"."""
    body_name, _, region = spec.partition(".")
    names = [b.name for b in model.scene.bodies]
    body = names.index(body_name)
    meshed = model.meshed
    if region:
        tags = meshed.facet_tags
        return body, tags.indices[tags.values == meshed.region_ids[spec]]
    topology = meshed.mesh.topology
    tdim = topology.dim
    topology.create_connectivity(tdim - 1, tdim)
    facets = dmesh.exterior_facet_indices(topology)
    f_to_c = topology.connectivity(tdim - 1, tdim)
    first_cell = np.array([f_to_c.links(f)[0] for f in facets], dtype=np.int64)
    return body, facets[model.cell_body[first_cell] == body]


def build_surface(model: Model, spec: str) -> Surface:
    """The segments of ``spec`` ("body" or "body.region") with outward-ordered nodes."""
    body, facets = _boundary_facets(model, spec)
    topology = model.meshed.mesh.topology
    tdim = topology.dim
    topology.create_connectivity(tdim - 1, tdim)
    topology.create_connectivity(tdim, tdim - 1)
    f_to_c = topology.connectivity(tdim - 1, tdim)
    c_to_f = topology.connectivity(tdim, tdim - 1)
    ref_facets = basix.topology(BASIX_CELLS[topology.cell_name()])[tdim - 1]
    segments, cells = [], []
    X = model.X0
    for f in facets:
        c = f_to_c.links(f)[0]
        local = int(np.flatnonzero(c_to_f.links(c) == f)[0])
        nodes = model.dofmap[c, ref_facets[local]].astype(np.int64)
        if tdim == 2:
            p0, p1 = X[nodes[0]], X[nodes[1]]
            t = p1 - p0
            normal = np.array([t[1], -t[0]])
            if np.dot(X[model.dofmap[c]].mean(axis=0) - p0, normal) > 0:
                nodes = nodes[::-1]
        else:
            # quadrilateral facets in tensor order (0, 1, 2, 3) -> around (0, 1, 3, 2)
            if len(nodes) == 4:
                nodes = nodes[[0, 1, 3, 2]]
            p = X[nodes]
            normal = np.cross(p[1] - p[0], p[-1] - p[0])
            if np.dot(X[model.dofmap[c]].mean(axis=0) - p[0], normal) > 0:
                nodes = nodes[::-1]
        segments.append(nodes)
        cells.append(c)
    seg = np.array(segments, dtype=np.int64).reshape(-1, 2 if tdim == 2 else len(ref_facets[0]))
    return Surface(spec, body, np.ascontiguousarray(seg), np.array(cells, dtype=np.int64), np.unique(seg))
