"""Mesh quality before a run: the worst-shaped element and the smallest one, per body.

* Scaled Jacobian: at each corner, the volume (area) spanned by the corner's edges over the
  product of their lengths, scaled so that the ideal cell (square, cube, equilateral triangle,
  regular tetrahedron) scores 1; a cell's value is its worst corner.  <= 0 is an inverted or
  folded cell (unusable), below ``POOR_JACOBIAN`` a badly distorted one.
* Aspect ratio: longest over shortest edge of the cell.
* Smallest element: the characteristic length the solver's stable step uses
  (``elements.cells.characteristic_length``), and the step it gives, l / c times the safety factor,
  as the solver takes it: a band-damped body's wave speed c is its relaxed moduli's (the material's
  moduli are its dynamic ones at the band's reference frequency) and the band terms shorten the whole
  mesh's step by the smallest ``BandTerms.step_factor`` of the scene (``solver/band.py``), so a body
  with no band of its own is shortened too when another body has one.

Vertex order is dolfinx's: quads 0-1-3-2 around, hexes the tensor grid i + 2 j + 4 k.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from mpi4py import MPI

from ..scene.damping import band_terms

POOR_JACOBIAN = 0.2
POOR_ASPECT = 20.0

# corners and their edge neighbours (counter-clockwise / right-handed in the ideal cell)
_CORNERS = {
    "triangle": [(0, (1, 2)), (1, (2, 0)), (2, (0, 1))],
    "quadrilateral": [(0, (1, 2)), (1, (3, 0)), (3, (2, 1)), (2, (0, 3))],
    "tetrahedron": [(0, (1, 2, 3)), (1, (2, 0, 3)), (2, (0, 1, 3)), (3, (0, 2, 1))],
    "hexahedron": [(v, (v ^ 1, v ^ 2, v ^ 4)) for v in range(8)],
}
_IDEAL = {"triangle": 2.0 / np.sqrt(3.0), "quadrilateral": 1.0, "tetrahedron": np.sqrt(2.0), "hexahedron": 1.0}
_EDGES = {
    "triangle": [(0, 1), (1, 2), (2, 0)],
    "quadrilateral": [(0, 1), (1, 3), (3, 2), (2, 0)],
    "tetrahedron": [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)],
    "hexahedron": [(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7), (0, 4), (1, 5), (2, 6), (3, 7)],
}


def scaled_jacobian(xc: np.ndarray, cell: str) -> np.ndarray:
    """Worst-corner scaled Jacobian of each cell; xc (cells, vertices, gdim)."""
    values = []
    for v, nbrs in _CORNERS[cell]:
        e = [xc[:, n] - xc[:, v] for n in nbrs]
        if len(e) == 2:
            det = e[0][:, 0] * e[1][:, 1] - e[0][:, 1] * e[1][:, 0]
        else:
            det = np.einsum("ij,ij->i", e[0], np.cross(e[1], e[2]))
            if cell == "hexahedron" and bin(v).count("1") % 2:
                det = -det          # flipping an odd number of axes reverses the handedness
        norms = np.prod([np.linalg.norm(x, axis=1) for x in e], axis=0)
        values.append(det / np.maximum(norms, 1e-300))
    corners = np.array(values) * _IDEAL[cell]
    # gmsh may number a cell either way round: orient each cell by the sum of its corners
    orientation = np.where(corners.sum(axis=0) < 0, -1.0, 1.0)
    return (corners * orientation).min(axis=0)


def aspect_ratio(xc: np.ndarray, cell: str) -> np.ndarray:
    lengths = np.array([np.linalg.norm(xc[:, a] - xc[:, b], axis=1) for a, b in _EDGES[cell]])
    return lengths.max(axis=0) / np.maximum(lengths.min(axis=0), 1e-300)


def characteristic_lengths(xc: np.ndarray, cell: str) -> np.ndarray:
    from ..elements.cells import characteristic_lengths as lengths
    kind = {"triangle": 0, "quadrilateral": 1, "tetrahedron": 2, "hexahedron": 3}[cell]
    padded = np.zeros(xc.shape[:2] + (3,))
    padded[:, :, :xc.shape[2]] = xc
    return lengths(padded, kind)


@dataclass
class BodyQuality:
    body: str
    cells: int
    min_jacobian: float
    min_jacobian_at: list[float]
    max_aspect: float
    max_aspect_at: list[float]
    smallest_length: float
    smallest_at: list[float]
    stable_step: float            # smallest length / wave speed x safety factor (x the band's factor) [s]

    def problems(self) -> tuple[list[str], list[str]]:
        """(unusable, poor) messages naming the place."""
        def at(p):
            return "(" + ", ".join(f"{c:.4g}" for c in p) + ") m"
        bad, poor = [], []
        if self.min_jacobian <= 0.0:
            bad.append(f"body '{self.body}': an inverted or folded element (scaled Jacobian {self.min_jacobian:.3g}) "
                       f"at {at(self.min_jacobian_at)}; fix the geometry or the mesh file there")
        elif self.min_jacobian < POOR_JACOBIAN:
            poor.append(f"body '{self.body}': a distorted element (scaled Jacobian {self.min_jacobian:.3g} < "
                        f"{POOR_JACOBIAN}) at {at(self.min_jacobian_at)}; expect a poor answer near it")
        if self.max_aspect > POOR_ASPECT:
            poor.append(f"body '{self.body}': an element {self.max_aspect:.3g} times longer than wide at "
                        f"{at(self.max_aspect_at)}; it sets a small time step for its size")
        return bad, poor


def _worst(values, centres, comm, op):
    """Global extreme of ``values`` and the centre of the cell that holds it."""
    local = (float(values.min() if op is MPI.MIN else values.max()) if len(values) else
             (np.inf if op is MPI.MIN else -np.inf))
    where = centres[int(values.argmin() if op is MPI.MIN else values.argmax())].tolist() if len(values) else None
    pairs = comm.allgather((local, where))
    best = min(pairs, key=lambda p: p[0]) if op is MPI.MIN else max(pairs, key=lambda p: p[0])
    return best


def mesh_quality(scene, meshed) -> list[BodyQuality]:
    """Quality of every body's cells (this rank's cells, reduced over the communicator)."""
    mesh = meshed.mesh
    comm = mesh.comm
    cell = mesh.topology.cell_name()
    gdim = mesh.geometry.dim
    n_local = mesh.topology.index_map(mesh.topology.dim).size_local
    dofmap = mesh.geometry.dofmap.array.reshape(-1, mesh.geometry.dofmap.offsets[1])[:n_local]
    xc = mesh.geometry.x[dofmap][:, :, :gdim]
    tags = np.zeros(n_local, dtype=np.int32)
    owned = meshed.cell_tags.indices < n_local
    tags[meshed.cell_tags.indices[owned]] = meshed.cell_tags.values[owned]
    dampings = [body.damping or scene.damping for body in scene.bodies]
    bands = [None if body.rigid else band_terms(d) for body, d in zip(scene.bodies, dampings)]
    band_factor = min([t.step_factor for t in bands if t is not None], default=1.0)
    out = []
    for i, body in enumerate(scene.bodies):
        sel = tags == i + 1
        x = xc[sel]
        centres = x.mean(axis=1) if len(x) else np.zeros((0, gdim))
        sj = scaled_jacobian(x, cell) if len(x) else np.zeros(0)
        ar = aspect_ratio(x, cell) if len(x) else np.zeros(0)
        le = characteristic_lengths(x, cell) if len(x) else np.zeros(0)
        jmin, jat = _worst(sj, centres, comm, MPI.MIN)
        amax, aat = _worst(ar, centres, comm, MPI.MAX)
        lmin, lat = _worst(le, centres, comm, MPI.MIN)
        c = scene.material_of(body).c_dilatational
        if bands[i] is not None:
            # the elastic law runs with E x relaxed_scale: the wave speed x its square root
            c *= math.sqrt(bands[i].relaxed_scale(dampings[i].reference_frequency))
        out.append(BodyQuality(body.name, comm.allreduce(int(sel.sum()), op=MPI.SUM), jmin, jat, amax, aat,
                               lmin, lat, lmin / c * scene.safety_factor * band_factor))
    return out


def check_mesh(scene, meshed, log=print) -> list[BodyQuality]:
    """Report the mesh quality; warn of poor elements, stop (ModelError) on unusable ones."""
    from ..errors import ModelError
    qualities = mesh_quality(scene, meshed)
    for line in report(qualities):
        log("mesh quality: " + line)
    bad = [m for q in qualities for m in q.problems()[0]]
    for q in qualities:
        for message in q.problems()[1]:
            log("warning: " + message)
    if bad:
        raise ModelError("unusable mesh: " + "; ".join(bad))
    return qualities


def report(qualities: list[BodyQuality]) -> list[str]:
    lines = [f"{'body':14s} {'cells':>8s} {'min scaled J':>12s} {'max aspect':>10s} {'smallest [m]':>12s} "
             f"{'dt [s]':>10s}"]
    for q in qualities:
        lines.append(f"{q.body:14s} {q.cells:8d} {q.min_jacobian:12.3f} {q.max_aspect:10.2f} "
                     f"{q.smallest_length:12.4g} {q.stable_step:10.3g}")
    return lines
