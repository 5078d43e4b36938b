"""The scene: what a user describes, resolved to SI and checked before anything runs.

A scene file is TOML (documented with a worked example in ``docs/scenes.md``).  ``resolve``
turns the raw dictionary into the frozen dataclasses of ``specs.py``, collecting *every* problem
with its path (``bodies[1].radius: must be > 0, got -3 mm``, ``checker.py``) instead of stopping
at the first one.  Each table has its own reader, called here in turn: ``[scene]`` (``settings.py``),
materials, bodies, boundaries, contacts and springs, cavities, the penetrated target, damping, outputs
and the shock table.  Nothing here imports dolfinx: a scene can be checked on any machine.
"""
from __future__ import annotations

import dataclasses
import os
from typing import Any

from .bodies import read_bodies
from .boundaries import read_boundaries
from .cavities import read_cavities
from .checker import Checker, SceneError
from .contacts import read_contacts, read_springs
from .damping import check_band_laws, read_scene_damping
from .materials import read_materials
from .outputs import read_outputs
from .penetration import read_penetration
from .preload import read_preload
from .settings import read_settings
from .shock import read_shock
from .specs import Scene

# the tables of a scene file
TABLES = ("scene", "materials", "bodies", "boundary", "contact", "spring", "cavity", "damping", "outputs", "shock",
          "penetration")


def resolve(raw: dict, base_dir: str = ".") -> Scene:
    """Check a raw scene dictionary completely and return the resolved ``Scene``: each table by its own
    reader, in the order a reader needs the tables before it (the bodies' regions for the contacts, loads
    and outputs; the end time for the outputs' and shock's defaults).

    Raises
    ------
    SceneError
        Listing every problem found, each with its path.
    """
    ck = Checker()
    ck.unknown(raw, TABLES, "")
    settings = read_settings(ck, raw)
    kin, end_time = settings["kinematics"], settings["end_time"]
    materials = read_materials(ck, raw)
    bodies, body_regions = read_bodies(ck, raw, kin, materials, base_dir)
    boundaries = read_boundaries(ck, raw, body_regions, kin, frozenset(b.name for b in bodies if b.rigid))
    contacts = read_contacts(ck, raw, body_regions, kin)
    springs = read_springs(ck, raw, body_regions, 3 if kin == "3d" else 2)
    cavities = read_cavities(ck, raw, body_regions)
    penetration, tunnel = read_penetration(ck, raw, body_regions, bodies, kin)
    if tunnel is not None:
        contacts.append(tunnel)     # the target's tunnel is a contact with the projectile's sides
    preload = read_preload(ck, raw, boundaries, contacts)
    damping = read_scene_damping(ck, raw)
    check_band_laws(ck, bodies, materials, damping)
    outputs = read_outputs(ck, raw, bodies, end_time)
    shock = read_shock(ck, raw, body_regions, kin, end_time)
    if ck.problems:
        raise SceneError(ck.problems)
    return Scene(**settings, materials=materials, bodies=tuple(bodies), boundaries=tuple(boundaries),
                 contacts=tuple(contacts), damping=damping, outputs=outputs, springs=tuple(springs), shock=shock,
                 cavities=tuple(cavities), penetration=penetration, folder=_folder(base_dir), preload=preload)


def _folder(base_dir: str) -> str:
    """The scene's folder, absolute; "" for a scene built in code (no file, ``base_dir`` left at ".")."""
    return "" if base_dir == "." else os.path.abspath(base_dir)


def to_plain(scene: Scene) -> dict[str, Any]:
    """The resolved scene (SI units) as plain data for ``resolved_scene.json``."""
    d = dataclasses.asdict(scene)
    d["units"] = "SI (m, kg, s, N, Pa, J)"
    return d
