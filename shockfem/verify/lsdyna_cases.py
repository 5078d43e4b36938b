"""LS-DYNA decks against their TOML scenes: the Taylor bar and the two-rod impact of ``studies/lsdyna/``,
imported, run the same as the scenes they were written from (the same mesh, the same numbers in another
unit set), to round-off.

The decks' keywords are written by hand; their meshes (``*NODE``, ``*ELEMENT_SOLID`` and the sets of the
loaded faces) are the TOML scene's own gmsh mesh written as an ``*INCLUDE`` (``write_mesh_include``), at
the case's element size.
"""
from __future__ import annotations

import os
import shutil

import numpy as np

from ..geometry.meshing import draw_body
from ..importers import import_model
from ..scene import read_toml, resolve
from .checks import SIZES, check, element_count
from .contact_cases import TWO_RODS, two_rods_scene
from .plasticity_cases import taylor_measures, taylor_scene
from .scenes import solve

STUDIES = os.path.join(os.path.dirname(__file__), "..", "..", "studies", "lsdyna")

# the decks, their unit sets, the length of one deck unit [m], the sets their meshes carry and the sizes
DECKS = {
    "taylor_bar": {"units": "mm-ms-kg-kN", "length": 1e-3, "sets": {"bar.bottom": ("node", 1)},
                   "scene": lambda h: taylor_scene(h, kinematics="3d"), "h": 0.0008},
    "two_rods": {"units": "mm-s-tonne-N", "length": 1e-3,
                 "sets": {"striker.bottom": ("segment", 1), "target.top": ("segment", 2)},
                 "scene": lambda h: two_rods_scene(h, kinematics="3d"), "h": 0.00625},
}


def write_mesh_include(raw: dict, path: str, length: float, sets: dict):
    """The bodies of the raw scene as ``*NODE`` / ``*ELEMENT_SOLID`` (body i is part i + 1, nodes in gmsh's
    order, coordinates in deck units of ``length`` metres, free format so no digit is lost) and the sets
    ``{"body.region": ("node" | "segment", sid)}`` of the regions' facets."""
    scene = resolve(raw)
    lines = ["*KEYWORD", "$ the mesh of a shockfem scene, written by shockfem.verify.lsdyna_cases"]
    offset = 0
    set_lines = []
    for i, body in enumerate(scene.bodies):
        bm = draw_body(scene, i)
        ids = {int(t): offset + k + 1 for k, t in enumerate(bm.node_tags)}
        lines.append("*NODE")
        lines += [f"{ids[int(t)]},{x / length!r},{y / length!r},{z / length!r}"
                  for t, (x, y, z) in zip(bm.node_tags, bm.coords)]
        lines.append("*ELEMENT_SOLID")
        for k, cell in enumerate(bm.cells):
            eid = offset + k + 1
            lines += [f"{eid},{i + 1}", ",".join(str(ids[int(n)]) for n in cell)]
        for key, (kind, sid) in sets.items():
            name, region = key.split(".")
            if name != body.name:
                continue
            facets = bm.regions[region]
            if kind == "node":
                nodes = [ids[int(n)] for n in dict.fromkeys(facets.ravel().tolist())]
                set_lines += ["*SET_NODE_LIST", f"{sid}"] + [",".join(map(str, nodes[j:j + 8]))
                                                              for j in range(0, len(nodes), 8)]
            else:
                set_lines += ["*SET_SEGMENT", f"{sid}"] + [",".join(str(ids[int(n)]) for n in f) for f in facets]
        offset += len(bm.node_tags)
    with open(path, "w") as fh:
        fh.write("\n".join(lines + set_lines + ["*END", ""]))


def deck_and_scene(name: str, h: float, workdir: str) -> tuple[dict, dict]:
    """The raw TOML scene of ``name`` at element size ``h`` and the raw scene imported from its deck (the
    deck of ``studies/lsdyna/`` with its mesh include written at ``h`` in ``workdir``)."""
    spec = DECKS[name]
    raw = spec["scene"](h)
    os.makedirs(workdir, exist_ok=True)
    deck = os.path.join(workdir, f"{name}.k")
    shutil.copy(os.path.join(STUDIES, f"{name}.k"), deck)
    write_mesh_include(raw, os.path.join(workdir, f"{name}_mesh.k"), spec["length"], spec["sets"])
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
    """The Taylor bar (3D one-point hexahedra, mm-ms-kg-kN) and the two-rod impact (3D, mm-s-tonne-N)
    written as LS-DYNA decks give what their TOML scenes give: final length and radius, plastic strain and
    energies; the rods' mean velocities and contact energy, to round-off."""
    out = []
    for name, measure in (("taylor_bar", _taylor), ("two_rods", _rods)):
        h = DECKS[name]["h"] * SIZES[size]
        raw, raw_deck = deck_and_scene(name, h, os.path.join(workdir, "lsdyna", name))
        scene_solver, _ = solve(raw, cache_dir=workdir)
        deck_solver, wall = solve(raw_deck, cache_dir=workdir)
        out += _agreement(name, measure(scene_solver), measure(deck_solver), ROUND_OFF, wall,
                          element_count(deck_solver))
    return out


def _taylor(solver) -> dict:
    return {**taylor_measures(solver), **_energies(solver)}


def _rods(solver) -> dict:
    v, _ = solver.body_means()
    e = solver.energy
    return {"striker_velocity": float(v[0, -1]), "target_velocity": float(v[1, -1]),
            "contact_energy": e.contact, **_energies(solver)}
