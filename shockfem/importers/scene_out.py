"""An LS-DYNA deck's model as a shockfem scene: a body per part with its own mesh, materials with units,
initial and boundary conditions, contacts and controls.

Each mapping says what LS-DYNA does and what shockfem does instead where they differ; those notes go
into the import report.  A reference the deck does not resolve (an element's node, a part's material,
a set) is an error naming its keyword, card and line.
"""
from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from .cards import DeckError
from .deck_model import DeckModel
from .mesh_out import BodyMesh, signed_volumes, split_into_tets, turn_inside_out
from .unit_sets import UnitSet

# ELFORM -> (shockfem element, integration, what differs): LS-DYNA Keyword Manual, *SECTION_SOLID
ELFORMS = {
    1: ("hex", "reduced", "constant-stress hexahedron with hourglass control: shockfem's one-point hexahedron"),
    2: ("hex", "full", "selective reduced (2x2x2, constant pressure) hexahedron: shockfem's full integration "
                       "with mean dilatation, the same split of the volumetric part"),
    10: ("tet", "reduced", "one-point tetrahedron: shockfem's linear tetrahedron, the same element"),
    13: ("tet", "reduced", "one-point nodal-pressure tetrahedron: shockfem's linear tetrahedron has no nodal "
                           "pressure averaging, so it locks more in nearly incompressible (plastic) flow"),
    16: ("tet", "reduced", "10-node tetrahedron: its corner nodes as a linear tetrahedron (the mid-side nodes "
                           "are dropped: a stiffer, coarser element)"),
    17: ("tet", "reduced", "10-node composite tetrahedron: its corner nodes as a linear tetrahedron"),
}


@dataclass
class SceneOut:
    """The scene as a TOML dictionary, the meshes of its bodies, and what the mapping changed."""
    scene: dict
    meshes: dict                       # body name -> BodyMesh
    notes: list = field(default_factory=list)
    unmapped: Counter = field(default_factory=Counter)
    origins: dict = field(default_factory=dict)     # scene path -> the error of the deck card it came from
    source: str = ""                                # the deck's file name

    def locate(self, problem: str) -> str:
        """A scene check's problem ("path: message") said where in the deck the field came from, "file:line:
        *KEYWORD card N: path: message", by the longest path its ``origins`` hold (a table's, or an entry's);
        as it was, after the deck's name, where none does."""
        path = problem.split(": ", 1)[0]
        keys = [k for k in self.origins if path == k or path.startswith((k + ".", k + "["))]
        if keys:
            return self.origins[max(keys, key=len)](problem)
        return f"{self.source}: the scene it maps to: {problem}"


def body_name(part) -> str:
    """A part's title as a body name (letters, digits, _), else ``part<PID>``."""
    name = re.sub(r"\W+", "_", part.title).strip("_").lower()
    return name if name and name[0].isalpha() else f"part{part.pid}"


class DeckMapper:
    """The mapping's state: the deck's model, the unit set, and the scene it fills."""

    def __init__(self, m: DeckModel, units: UnitSet, name: str):
        self.m, self.u, self.name = m, units, name
        self.problems = list(m.problems)
        self.notes: list[str] = []
        self.scene: dict = {"scene": {"name": name, "kinematics": "3d"}, "materials": {}, "bodies": []}
        self.meshes: dict[str, BodyMesh] = {}
        self.body_of_part: dict[int, str] = {}
        self.node_body: dict[int, set] = {}
        self.split_parts: set[int] = set()          # parts whose hexahedra were cut into tetrahedra
        # scene path ("scene.end_time", "materials.mat1", "boundary[2]") -> the error function of the deck
        # card it came from, so that the scene check's problems are said where the deck has them
        self.origins: dict = {}
        self.source = ""                            # the deck's file name

    def origin(self, path: str, keyword, card: int | None = 0):
        """Record that the scene's ``path`` came from ``keyword``'s card ``card`` (0-based)."""
        if keyword is not None:
            self.origins[path] = lambda message, kw=keyword, c=card: kw.error(c, message)

    def add(self, table: str, entry: dict, error) -> dict:
        """Append ``entry`` to the scene's list ``table`` ([[boundary]], [[contact]]), made from the deck card
        whose problems ``error(message)`` names."""
        rows = self.scene.setdefault(table, [])
        rows.append(entry)
        self.origins[f"{table}[{len(rows) - 1}]"] = error
        return entry

    # --- geometry -------------------------------------------------------------------------------------
    def geometry(self):
        m = self.m
        ids = np.array(m.node_ids, dtype=np.int64)
        unique, counts = np.unique(ids, return_counts=True)
        for nid in unique[counts > 1][:5]:
            where = np.flatnonzero(ids == nid)
            kw, card = m.node_cards[where[1]]
            first_kw, first_card = m.node_cards[where[0]]
            self.problems.append(kw.error(card, f"node {nid} is defined {len(where)} times (first at "
                                                f"{first_kw.cards[first_card].where()})"))
        index = {int(n): k for k, n in enumerate(ids)}
        X = np.array(m.coords, dtype=float).reshape(-1, 3) * self.u.si(1.0, "length")
        by_part: dict[int, list] = {}
        kinds = Counter()
        for eid, pid, nodes, kw, card, node_card in m.elements:
            missing = [n for n in nodes if n not in index]
            if missing:
                self.problems.append(kw.error(node_card, f"element {eid}: node {missing[0]} is not defined by "
                                                         "any *NODE"))
                continue
            if pid not in m.parts:
                self.problems.append(kw.error(card, f"element {eid}: part {pid} is not defined by any *PART"))
                continue
            kind, corners = _solid_kind(nodes)
            if kind is None:
                self.problems.append(kw.error(node_card, f"element {eid}: {len(set(nodes))} distinct nodes "
                                                    f"{list(nodes)} make no hexahedron or tetrahedron"))
                continue
            kinds[kind] += 1
            by_part.setdefault(pid, []).append((eid, [index[n] for n in corners], kw, card))
        element = "tet" if kinds.get("tet") or kinds.get("wedge") else "hex"
        if element == "tet" and (kinds.get("hex") or kinds.get("wedge")):
            ids, X = self._split(by_part, ids, X)
            self.notes.append(f"the deck's solids are {dict(kinds)}: a scene holds one element type, so every "
                              "hexahedron and wedge is cut into tetrahedra about a node at its centre (12 and 8 "
                              "of them): linear tetrahedra, stiffer than the hexahedra they replace")
        self.scene["scene"]["element"] = element
        self._sections(by_part, element)
        for pid, cells in sorted(by_part.items()):
            self._body(pid, cells, element, ids, X)
        for pid, part in m.parts.items():
            if pid not in by_part:
                self.notes.append(f"part {pid} ({part.title or 'untitled'}) has no solid elements: left out")

    def _split(self, by_part, ids, X):
        """Every cell of more than four nodes cut into tetrahedra (``split_into_tets``); returns the node
        ids and coordinates with the new centre nodes after the deck's."""
        ids, X = list(ids), list(X)
        next_id = max(ids) + 1
        for pid, cells in by_part.items():
            out = []
            for eid, corners, kw, card in cells:
                if len(corners) == 4:
                    out.append((eid, corners, kw, card))
                    continue
                centre = len(X)
                X.append(np.mean([X[k] for k in dict.fromkeys(corners)], axis=0))
                ids.append(next_id)
                next_id += 1
                out += [(eid, [centre if k < 0 else k for k in tet], kw, card)
                        for tet in split_into_tets(corners, ids)]
            by_part[pid] = out
            self.split_parts.add(pid)
        return np.array(ids, dtype=np.int64), np.array(X)

    def _sections(self, by_part, element):
        rules = set()
        for pid in by_part:
            part = self.m.parts[pid]
            if part.secid not in self.m.sections:
                self.problems.append(part.keyword.error(part.card, f"part {pid}: section {part.secid} is not "
                                                                   "defined by any *SECTION_SOLID"))
                continue
            elform, kw = self.m.sections[part.secid]
            if elform not in ELFORMS:
                self.problems.append(kw.error(0, f"ELFORM {elform} is not mapped (shockfem maps "
                                                 f"{', '.join(map(str, ELFORMS))})"))
                continue
            kind, rule, what = ELFORMS[elform]
            if kind != element and pid not in self.split_parts:
                self.problems.append(kw.error(0, f"ELFORM {elform} is a {kind} formulation; part {pid}'s "
                                                 f"elements are {element}s"))
                continue
            rules.add(rule)
            self.notes.append(f"part {pid}: ELFORM {elform}, {what}")
        if len(rules) > 1:
            self.notes.append("parts with one-point and fully integrated hexahedra: a scene has one rule, the "
                              "one-point hexahedron (ELFORM 1) is used for all")
        self.scene["scene"]["integration"] = "full" if rules == {"full"} and element == "hex" else "reduced"

    def _body(self, pid, cells, element, ids, X):
        part = self.m.parts[pid]
        name = body_name(part)
        if name in self.meshes:
            name = f"{name}_{pid}"
        conn = np.array([c[1] for c in cells], dtype=np.int64)
        used = np.unique(conn)                      # the deck's node order
        local = np.searchsorted(used, conn)
        coords = X[used]
        vol = signed_volumes(coords, local, element)
        flip = vol < 0
        if flip.any():
            local = turn_inside_out(local, element, flip)
            self.notes.append(f"part {pid}: {int(flip.sum())} elements numbered inside out (negative volume) "
                              "renumbered")
        self.meshes[name] = BodyMesh(element, ids[used], coords, local)
        self.body_of_part[pid] = name
        for n in ids[used]:
            self.node_body.setdefault(int(n), set()).add(name)
        self.origin(f"bodies[{len(self.scene['bodies'])}]", part.keyword, part.card)
        body = {"name": name, "material": self._material(part), "shape": "mesh", "file": "", "regions": {}}
        mat = self.m.materials.get(part.mid)
        if mat is not None and mat.kind == "rigid":
            body["rigid"] = True
        self.scene["bodies"].append(body)

    # --- materials ------------------------------------------------------------------------------------
    def _material(self, part) -> str:
        mat = self.m.materials.get(part.mid)
        if mat is None:
            self.problems.append(part.keyword.error(part.card, f"part {part.pid}: material {part.mid} is not "
                                                               "defined by any *MAT_ keyword"))
            return f"mat{part.mid}"
        name = f"mat{part.mid}"
        if mat.kind == "refused":
            self.problems.append(mat.keyword.error(None, f"part {part.pid} ({part.title or 'untitled'}) uses "
                                                         f"material {part.mid}, *{mat.keyword.name}, which is "
                                                         "not mapped"))
            return name
        if name not in self.scene["materials"]:
            from .materials_out import material_table
            try:
                table, notes = material_table(mat, self.m.curves, self.m.tables, self.u)
            except DeckError as e:
                self.problems += e.problems
                return name
            self.scene["materials"][name] = table
            self.origin(f"materials.{name}", mat.keyword, 0)
            self.notes += [f"material {part.mid}: {n}" for n in notes]
        return name


def _solid_kind(nodes: tuple) -> tuple[str | None, tuple]:
    """The element an LS-DYNA solid's node list describes: 8 distinct nodes a hexahedron; 4 distinct (a
    4-node tet, the degenerate hexahedron N1 N2 N3 N4 N4 N4 N4 N4, or a 10-node tet's corners) a
    tetrahedron; N5 = N6 and N7 = N8 the degenerate wedge."""
    n = len(nodes)
    if n == 8 and len(set(nodes)) == 8:
        return "hex", nodes
    if n == 4 and len(set(nodes)) == 4:
        return "tet", nodes
    if n == 10 and len(set(nodes)) == 10:
        return "tet", nodes[:4]
    if n == 8 and len(set(nodes[3:])) == 1 and len(set(nodes[:4])) == 4:
        return "tet", nodes[:4]
    if n == 8 and nodes[4] == nodes[5] and nodes[6] == nodes[7] and len(set(nodes)) == 6:
        return "wedge", nodes
    return None, nodes
