"""LS-DYNA decks against their TOML scenes: the Taylor bar, the two-rod impact and the driven rigid punch of
``studies/lsdyna/``, imported, run the same as the scenes they were written from (the same mesh, the same
numbers in another unit set), to round-off.

The decks' keywords are written by hand; their meshes (``*NODE``, ``*ELEMENT_SOLID`` and the sets of the
loaded faces) are the TOML scene's own gmsh mesh written as an ``*INCLUDE`` (``write_mesh_include``), at
the case's element size.
"""
from __future__ import annotations

import os
import shutil

import numpy as np

from ..geometry.meshing import build_mesh
from ..importers import import_model
from ..scene import read_toml, resolve
from .checks import SIZES, check, element_count
from .contact_cases import TWO_RODS, two_rods_scene
from .plasticity_cases import taylor_measures, taylor_scene
from .rigid_drive_cases import punch_deck_scene
from .scenes import solve

STUDIES = os.path.join(os.path.dirname(__file__), "..", "..", "studies", "lsdyna")

# the decks, their unit sets, the length of one deck unit [m], the sets their meshes carry and the sizes
DECKS = {
    "taylor_bar": {"units": "mm-ms-kg-kN", "length": 1e-3, "sets": {"bar.bottom": ("node", 1)},
                   "scene": lambda h: taylor_scene(h, kinematics="3d"), "h": 0.0008},
    "two_rods": {"units": "m-ms-kg-MN", "length": 1.0,
                 "sets": {"striker.bottom": ("segment", 1), "target.top": ("segment", 2)},
                 "scene": lambda h: two_rods_scene(h, kinematics="3d"), "h": 0.00625},
    "rigid_punch": {"units": "m-ms-kg-MN", "length": 1.0,
                    "sets": {"punch.bottom": ("segment", 1), "rod.top": ("segment", 2)},
                    "scene": punch_deck_scene, "h": 0.0025},
}


def scene_mesh(raw: dict, cache_dir: str) -> list[dict]:
    """The mesh a raw scene runs on (``build_mesh``'s file, from its cache when there), body by body:
    ``node_tags`` (the run's numbering), ``coords`` [m], ``cells`` (node tags), ``regions`` (name -> facets)."""
    import gmsh
    scene = resolve(raw)
    meshed = build_mesh(scene, cache_dir=cache_dir, log=lambda message: None)
    gmsh.open(meshed.source)
    try:
        tags, xyz, _ = gmsh.model.mesh.getNodes()
        coords = dict(zip(tags.tolist(), xyz.reshape(-1, 3)))
        bodies = []
        for i, body in enumerate(scene.bodies):
            cells = _elements(3, i + 1)
            node_tags = np.unique(cells)
            regions = {name.split(".", 1)[1]: _elements(2, rid) for name, rid in meshed.region_ids.items()
                       if name.split(".", 1)[0] == body.name}
            bodies.append({"name": body.name, "node_tags": node_tags, "cells": cells, "regions": regions,
                           "coords": np.array([coords[t] for t in node_tags.tolist()])})
        return bodies
    finally:
        gmsh.clear()


def _elements(dim: int, physical: int) -> np.ndarray:
    """The node tags of the elements of a physical group, one row an element."""
    import gmsh
    rows = []
    for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, physical):
        types, _, nodes = gmsh.model.mesh.getElements(dim, entity)
        for kind, n in zip(types, nodes):
            per = gmsh.model.mesh.getElementProperties(kind)[3]
            rows.append(np.asarray(n, dtype=np.int64).reshape(-1, per))
    return np.vstack(rows)


def write_mesh_include(raw: dict, path: str, length: float, sets: dict, cache_dir: str):
    """The mesh the raw scene runs on as ``*NODE`` / ``*ELEMENT_SOLID`` (body i is part i + 1, node ids the
    run's own, coordinates in deck units of ``length`` metres, free format so no digit is lost) and the
    sets ``{"body.region": ("node" | "segment", sid)}`` of the regions' facets."""
    lines = ["*KEYWORD", "$ the mesh of a shockfem scene, written by shockfem.verify.lsdyna_cases"]
    set_lines = []
    eid = 0
    for i, body in enumerate(scene_mesh(raw, cache_dir)):
        lines.append("*NODE")
        lines += [f"{t}," + ",".join(repr(_deck_value(c, length)) for c in xyz)
                  for t, xyz in zip(body["node_tags"].tolist(), body["coords"])]
        lines.append("*ELEMENT_SOLID")
        for cell in body["cells"]:
            eid += 1
            lines += [f"{eid},{i + 1}", ",".join(map(str, cell.tolist()))]
        for key, (kind, sid) in sets.items():
            name, region = key.split(".")
            if name != body["name"]:
                continue
            facets = body["regions"][region]
            if kind == "node":
                nodes = list(dict.fromkeys(facets.ravel().tolist()))
                set_lines += ["*SET_NODE_LIST", f"{sid}"] + [",".join(map(str, nodes[j:j + 8]))
                                                              for j in range(0, len(nodes), 8)]
            else:
                set_lines += ["*SET_SEGMENT", f"{sid}"] + [",".join(map(str, f)) for f in facets.tolist()]
    with open(path, "w") as fh:
        fh.write("\n".join(lines + set_lines + ["*END", ""]))


def _deck_value(x: float, length: float) -> float:
    """The deck number that the import turns back into ``x`` [m] bit for bit (``x / length``, or a neighbour
    of it: the division and the import's multiplication each round), so that the deck's mesh is the scene's
    own to the last bit; surfaces that touch at the start (the two rods) then touch in both."""
    d = x / length
    for candidate in (d, np.nextafter(d, np.inf), np.nextafter(d, -np.inf)):
        if candidate * length == x:
            return float(candidate)
    return d


def deck_and_scene(name: str, h: float, workdir: str) -> tuple[dict, dict]:
    """The raw TOML scene of ``name`` at element size ``h`` and the raw scene imported from its deck (the
    deck of ``studies/lsdyna/`` with its mesh include written at ``h`` in ``workdir``)."""
    spec = DECKS[name]
    raw = spec["scene"](h)
    os.makedirs(workdir, exist_ok=True)
    deck = os.path.join(workdir, f"{name}.k")
    shutil.copy(os.path.join(STUDIES, f"{name}.k"), deck)
    write_mesh_include(raw, os.path.join(workdir, f"{name}_mesh.k"), spec["length"], spec["sets"], workdir)
    imported = import_model(deck, os.path.join(workdir, f"{name}_imported.toml"), spec["units"])
    raw_deck = read_toml(imported.scene)
    for body in raw_deck["bodies"]:
        body["file"] = os.path.join(workdir, body["file"])
    raw_deck["scene"]["name"] = f"{name}_imported"
    return raw, raw_deck


def _energies(solver) -> dict:
    e = solver.energy
    return {"kinetic": e.kinetic, "internal": e.internal, "plastic": e.plastic, "hourglass": e.hourglass}


def _agreement(prefix, a: dict, b: dict, tol: float, wall: float, n: int) -> list[dict]:
    """One check per measure: the imported deck's value against the TOML scene's, relative to it."""
    return [check(f"{prefix}.{k} [deck vs scene]", a[k], b[k], tol, wall, n) for k in a if a[k] != 0.0]


# Deck against scene, relative: the meshes are the same nodes and cells in the same order, the numbers
# the same values written in another unit set, so the runs differ by the round-off of the unit conversion
# (1 ulp on a coordinate or a modulus) carried through the run.  Measured: see docs/import.md.
ROUND_OFF = 1e-9


def lsdyna_decks(size, workdir):
    """The Taylor bar (3D one-point hexahedra, mm-ms-kg-kN), the two-rod impact (3D, m-ms-kg-MN) and the rigid
    punch (3D, m-ms-kg-MN, *BOUNDARY_PRESCRIBED_MOTION_RIGID along a *DEFINE_CURVE) written as LS-DYNA decks
    give what their TOML scenes give: final length and radius, plastic strain and energies; the rods' mean
    velocities and contact energy; the drive's force and work, to round-off."""
    out = []
    for name, measure in (("taylor_bar", _taylor), ("two_rods", _rods), ("rigid_punch", _punch)):
        h = DECKS[name]["h"] * SIZES[size]
        case_dir = os.path.join(workdir, "lsdyna", name)
        raw, raw_deck = deck_and_scene(name, h, case_dir)          # the scene's mesh cached there
        scene_solver, _ = solve(raw, cache_dir=case_dir)
        deck_solver, wall = solve(raw_deck, cache_dir=case_dir)
        out += _agreement(name, measure(scene_solver), measure(deck_solver), ROUND_OFF, wall,
                          element_count(deck_solver))
    return out


def _taylor(solver) -> dict:
    return {**taylor_measures(solver), **_energies(solver)}


def _punch(solver) -> dict:
    """The rigid punch: the drive's reaction and work, the punch's centre, the rod's mean velocity and the
    contact's energy."""
    v, _ = solver.body_means()
    e = solver.energy
    return {"drive_force": float(solver.reactions()[-1][2]), "drive_work": e.external,
            "punch_z": float(solver.rigid_states[0].center[2]), "rod_velocity": float(v[0, 2]),
            "contact_energy": e.contact, **_energies(solver)}


def _rods(solver) -> dict:
    v, _ = solver.body_means()
    e = solver.energy
    return {"striker_velocity": float(v[0, -1]), "target_velocity": float(v[1, -1]),
            "contact_energy": e.contact, **_energies(solver)}
