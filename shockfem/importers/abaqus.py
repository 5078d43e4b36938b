"""An Abaqus ``.inp`` mesh through meshio: its solids as bodies (one per element set when the sets share the
solids out, else one), its node sets as regions; the materials, end time and conditions are the scene's
to give (an ``.inp``'s steps and materials are not read).
"""
from __future__ import annotations

import os

import numpy as np

from .cards import DeckError
from .conditions_out import Regions
from .mesh_out import BodyMesh, signed_volumes, turn_inside_out
from .scene_out import SceneOut
from .unit_sets import UnitSet

# meshio's cell types of the solids a scene takes, and how many of their nodes are the corners
SOLIDS = {"hexahedron": ("hex", 8), "tetra": ("tet", 4), "tetra10": ("tet", 4)}


class _Holder:
    """What ``Regions`` reads of an import in progress: the bodies' meshes, each node's bodies, problems."""

    def __init__(self):
        self.meshes: dict[str, BodyMesh] = {}
        self.node_body: dict[int, set] = {}
        self.problems: list[str] = []


def inp_to_scene(path: str, units: UnitSet) -> SceneOut:
    """The scene of the Abaqus input file ``path`` (coordinates in ``units``' length)."""
    import meshio
    name = os.path.basename(path)
    try:
        mesh = meshio.read(path, file_format="abaqus")
    except Exception as e:                    # meshio raises its ReadError and plain errors alike
        raise DeckError([f"{name}: meshio cannot read it ({e})"]) from None
    blocks = [(k, b) for k, b in enumerate(mesh.cells) if b.type in SOLIDS]
    others = sorted({b.type for b in mesh.cells if b.type not in SOLIDS and b.type not in ("line", "vertex")})
    kinds = {SOLIDS[b.type][0] for _, b in blocks}
    if not blocks:
        raise DeckError([f"{name}: no solid elements (C3D8, C3D4, C3D10) among {others or 'none'}"])
    if len(kinds) > 1 or others:
        raise DeckError([f"{name}: elements {sorted({b.type for _, b in blocks}) + others}: a scene holds one "
                         "solid element type (all hexahedra or all tetrahedra)"])
    element = kinds.pop()
    X = np.asarray(mesh.points, dtype=float) * units.si(1.0, "length")
    if X.shape[1] != 3:
        raise DeckError([f"{name}: {X.shape[1]}D points; a 3D solid mesh is needed"])
    cells = np.vstack([b.data[:, :SOLIDS[b.type][1]] for _, b in blocks])
    groups = _element_sets(mesh, blocks, len(cells))
    holder = _Holder()
    scene = {"scene": {"name": os.path.splitext(name)[0], "kinematics": "3d", "element": element},
             "materials": {}, "bodies": []}
    notes = [f"{len(groups)} bodies from {'its element sets' if len(groups) > 1 else 'all its solids'}; give "
             "each material's fields, scene.end_time and the conditions in the scene"]
    node_ids = np.arange(1, len(X) + 1)
    for body, rows in groups.items():
        conn = cells[rows]
        used = np.unique(conn)
        local = np.searchsorted(used, conn)
        flip = signed_volumes(X[used], local, element) < 0
        local = turn_inside_out(local, element, flip) if flip.any() else local
        holder.meshes[body] = BodyMesh(element, node_ids[used], X[used], local)
        for n in node_ids[used]:
            holder.node_body.setdefault(int(n), set()).add(body)
        scene["materials"][body] = {}
        scene["bodies"].append({"name": body, "material": body, "shape": "mesh", "file": "", "regions": {}})
    regions = Regions(holder)
    for set_name, ids in mesh.point_sets.items():
        label = _name(set_name)
        regions.from_nodes(np.asarray(ids) + 1, label, lambda msg, s=set_name: f"{name}: *NSET {s}: {msg}")
    if holder.problems:
        raise DeckError(holder.problems)
    return SceneOut(scene, holder.meshes, notes, {})


def _name(text: str) -> str:
    out = "".join(c if c.isalnum() else "_" for c in text).strip("_").lower()
    return out if out and out[0].isalpha() else f"set_{out}"


def _element_sets(mesh, blocks, count: int) -> dict[str, np.ndarray]:
    """Body name -> rows of the stacked solids: the element sets when they share the solids out, each solid
    in one, else one body of all."""
    offsets = np.cumsum([0] + [len(b.data) for _, b in blocks])
    sets = {}
    for set_name, per_block in mesh.cell_sets.items():
        rows = np.concatenate([offsets[j] + np.asarray(per_block[k], dtype=np.int64)
                               for j, (k, _) in enumerate(blocks) if len(per_block[k])] or [np.zeros(0, int)])
        if len(rows):
            sets[_name(set_name)] = np.unique(rows)
    if sets:
        every = np.concatenate(list(sets.values()))
        if len(every) == count and len(np.unique(every)) == count:
            return sets
    return {"solid": np.arange(count)}
