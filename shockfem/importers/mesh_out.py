"""A body's imported mesh, its boundary facets and named regions, written as the gmsh ``.msh`` a scene's mesh
body reads (``docs/scenes.md``, "Regions of each shape": cells of the scene's element type, regions as
physical groups of boundary facets, coordinates in metres).
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field

import numpy as np

# the faces of a cell, as local node indices, each ordered so that its normal points out of a positively
# oriented cell (gmsh's and LS-DYNA's node numbering of the hexahedron and the tetrahedron agree)
FACES = {
    "hex": np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]),
    "tet": np.array([[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]),
}
GMSH_CELL = {"hex": 5, "tet": 4}          # gmsh element types of the cells ...
GMSH_FACET = {"hex": 3, "tet": 2}         # ... and of their facets (quadrangle, triangle)


@dataclass
class BodyMesh:
    """One part's mesh: node ids (the deck's), coordinates [m], cells as indices into them, the boundary
    facets as indices, and named regions as rows of ``facets``."""
    element: str
    node_ids: np.ndarray
    coords: np.ndarray
    cells: np.ndarray
    facets: np.ndarray = None
    regions: dict = field(default_factory=dict)

    def __post_init__(self):
        if self.facets is None:
            self.facets = boundary_facets(self.cells, self.element)

    def region_nodes(self, name: str) -> np.ndarray:
        """The deck ids of the nodes of region ``name``'s facets."""
        return np.unique(self.node_ids[self.facets[self.regions[name]]])

    def facets_within(self, node_ids) -> np.ndarray:
        """The boundary facets all of whose nodes are among ``node_ids`` (deck ids)."""
        inside = np.isin(self.node_ids, np.asarray(list(node_ids), dtype=np.int64))
        return np.flatnonzero(inside[self.facets].all(axis=1))

    def facets_matching(self, segments) -> tuple[np.ndarray, list]:
        """The boundary facets on the segments (deck ids): a facet whose nodes are all among one segment's
        (a quadrilateral segment holds the two triangles of a cut hexahedron's face); the segments that
        hold none."""
        index = {int(n): k for k, n in enumerate(self.node_ids)}
        width = self.facets.shape[1]
        keys = {frozenset(f.tolist()): k for k, f in enumerate(self.facets)}
        found, missed = [], []
        for seg in segments:
            local = [index.get(int(n), -1) for n in dict.fromkeys(seg)]
            hits = [keys[frozenset(c)] for c in itertools.combinations(local, width) if frozenset(c) in keys]
            (found.extend(hits) if hits else missed.append(seg))
        return np.array(sorted(set(found)), dtype=np.int64), missed


def boundary_facets(cells: np.ndarray, element: str) -> np.ndarray:
    """The faces of ``cells`` that belong to one cell only, outward ordered, shape (facets, nodes)."""
    faces = cells[:, FACES[element]].reshape(-1, FACES[element].shape[1])
    key = np.sort(faces, axis=1)
    _, first, counts = np.unique(key, axis=0, return_index=True, return_counts=True)
    return faces[np.sort(first[counts == 1])]


def split_into_tets(nodes: list, order) -> list[tuple]:
    """Tetrahedra filling a hexahedron, or a degenerate one (a wedge, N5 = N6 and N7 = N8), around a new node
    at its centre (-1 here): each face, its repeated nodes dropped, is cut into triangles by the diagonal
    through its lowest node (``order`` ranks the nodes), so that two cells sharing a face cut it the same
    way and the tetrahedra meet face to face (the rule of Dompierre et al., "How to subdivide pyramids,
    prisms and hexahedra into tetrahedra", 1999, with a centre node instead of their tables)."""
    tets = []
    for face in FACES["hex"]:
        ring = list(dict.fromkeys(nodes[k] for k in face))
        if len(ring) == 4:
            low = min(range(4), key=lambda k: order[ring[k]])
            q = ring[low:] + ring[:low]
            tets += [(q[0], q[1], q[2], -1), (q[0], q[2], q[3], -1)]
        elif len(ring) == 3:
            tets.append((ring[0], ring[1], ring[2], -1))
    return tets


def signed_volumes(coords: np.ndarray, cells: np.ndarray, element: str) -> np.ndarray:
    """Six times the volume of the corner tetrahedron at node 0 (hex: nodes 0, 1, 3, 4), whose sign is the
    cell's orientation."""
    a, b, c, d = (coords[cells[:, k]] for k in ((0, 1, 3, 4) if element == "hex" else (0, 1, 2, 3)))
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)


def turn_inside_out(cells: np.ndarray, element: str, flip: np.ndarray) -> np.ndarray:
    """Cells with ``flip`` renumbered to the other orientation (hex: top and bottom faces swapped; tet: two
    nodes swapped)."""
    out = cells.copy()
    order = [4, 5, 6, 7, 0, 1, 2, 3] if element == "hex" else [0, 2, 1, 3]
    out[flip] = cells[flip][:, order]
    return out


def write_msh(mesh: BodyMesh, path: str, label: str):
    """Write the body's mesh (nodes in the deck's order; its cells the physical group ``label``, e.g.
    "part 1 bar, material 1") with one physical group per region, tagged 1, 2, ...; returns region name ->
    tag."""
    import gmsh
    if not gmsh.isInitialized():
        gmsh.initialize(interruptible=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add(f"import-{path}")
    try:
        volume = gmsh.model.addDiscreteEntity(3)
        tags = np.arange(1, len(mesh.node_ids) + 1)
        gmsh.model.mesh.addNodes(3, volume, tags, mesh.coords.ravel())
        gmsh.model.mesh.addElementsByType(volume, GMSH_CELL[mesh.element], np.arange(1, len(mesh.cells) + 1),
                                          (mesh.cells + 1).ravel())
        gmsh.model.addPhysicalGroup(3, [volume], 1)
        gmsh.model.setPhysicalName(3, 1, label)
        next_element = len(mesh.cells) + 1
        region_tags = {}
        for k, (name, rows) in enumerate(mesh.regions.items(), start=1):
            surface = gmsh.model.addDiscreteEntity(2)
            facets = mesh.facets[rows]
            gmsh.model.mesh.addElementsByType(surface, GMSH_FACET[mesh.element],
                                              np.arange(next_element, next_element + len(facets)),
                                              (facets + 1).ravel())
            next_element += len(facets)
            gmsh.model.addPhysicalGroup(2, [surface], k)
            gmsh.model.setPhysicalName(2, k, name)
            region_tags[name] = k
        # binary: the coordinates to the last bit (gmsh's text format keeps 16 digits, not always enough)
        gmsh.option.setNumber("Mesh.Binary", 1)
        gmsh.write(path)
    finally:
        gmsh.option.setNumber("Mesh.Binary", 0)
        gmsh.model.remove()
    return region_tags
