"""Write an imported model: the scene TOML (tomli-w), each body's mesh beside it, and the import report."""
from __future__ import annotations

import os
from dataclasses import dataclass

import tomli_w

from .mesh_out import write_msh
from .scene_out import SceneOut

NAMES = {"hex": ("hexahedron", "hexahedra"), "tet": ("tetrahedron", "tetrahedra")}


@dataclass(frozen=True)
class Imported:
    """What an import wrote: the scene, the meshes' folder, the report and its text."""
    scene: str
    mesh_dir: str
    report: str
    text: str


def write_import(out: SceneOut, scene_path: str, source: str, units: str) -> Imported:
    """Write ``scene_path``, its meshes in ``<scene>_meshes/`` and ``<scene>.import.txt``."""
    base = os.path.splitext(scene_path)[0]
    mesh_dir = base + "_meshes"
    os.makedirs(mesh_dir, exist_ok=True)
    scene_dir = os.path.dirname(os.path.abspath(scene_path))
    for body in out.scene["bodies"]:
        path = os.path.join(mesh_dir, f"{body['name']}.msh")
        body["regions"] = write_msh(out.meshes[body["name"]], path, f"{body['name']}, material {body['material']}")
        body["file"] = os.path.relpath(path, scene_dir)
    header = (f"# Imported by `shockfem import` from {os.path.basename(source)} ({units}); the bodies' meshes are "
              f"in {os.path.basename(mesh_dir)}/ (metres).\n# What the import changed or left out: "
              f"{os.path.basename(base)}.import.txt\n")
    with open(scene_path, "w") as fh:
        fh.write(header + tomli_w.dumps(out.scene))
    text = report_text(out, source, units, scene_path)
    report = base + ".import.txt"
    with open(report, "w") as fh:
        fh.write(text)
    return Imported(scene_path, mesh_dir, report, text)


def report_text(out: SceneOut, source: str, units: str, scene_path: str) -> str:
    """The import report: what was made, what the mapping changed, and each keyword not mapped with its
    count and what it would have done."""
    lines = [f"{os.path.basename(source)} -> {os.path.basename(scene_path)} ({units})",
             f"{len(out.meshes)} bod{'y' if len(out.meshes) == 1 else 'ies'}: " + ", ".join(f"{name} ({len(m.cells)} {NAMES[m.element][len(m.cells) != 1]}, "
                                                       f"regions {', '.join(m.regions) or 'none'})"
                                                       for name, m in out.meshes.items()),
             "", "What differs from the deck:"]
    lines += [f"  - {n}" for n in out.notes] or ["  (nothing)"]
    lines += ["", "Keywords not mapped (keyword, count, what it would have done):"]
    lines += [f"  *{k:<36s} {n:>4d}  {what}" for k, (n, what) in out.unmapped.items()] or ["  (none)"]
    return "\n".join(lines) + "\n"
