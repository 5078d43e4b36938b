"""An LS-DYNA keyword deck in, a shockfem scene out: the phases of the import, each in its own module.

    read the cards (cards.py) -> what the keywords say (deck_model.py) -> bodies and their meshes
    (scene_out.py) -> materials (materials_out.py) -> controls (controls_out.py) -> regions, velocities,
    constraints, motions, contacts, walls (conditions_out.py)
"""
from __future__ import annotations

import os

from . import conditions_out, controls_out
from .cards import DeckError, read_deck
from .deck_model import WOULD_HAVE, read_model
from .scene_out import SceneOut, DeckMapper
from .unit_sets import UnitSet


def deck_to_scene(path: str, units: UnitSet) -> SceneOut:
    """The scene of the deck ``path`` in the unit set ``units``; raises ``DeckError`` listing every problem
    (each naming its file, line, keyword and card)."""
    title, keywords = read_deck(path)
    model = read_model(title, keywords)
    name = os.path.splitext(os.path.basename(path))[0]
    mapper = DeckMapper(model, units, name)
    mapper.source = os.path.basename(path)
    mapper.geometry()
    end = controls_out.controls(mapper)
    regions = conditions_out.Regions(mapper)
    if mapper.meshes:
        conditions_out.velocities(mapper)
        conditions_out.constraints(mapper, regions)
        conditions_out.rigid_constraints(mapper)
        conditions_out.motions(mapper, regions, end)
        conditions_out.contacts(mapper, regions)
        conditions_out.walls(mapper, regions)
    elif not model.elements:
        mapper.problems.append(f"{os.path.basename(path)}: no *ELEMENT_SOLID: nothing to import")
    if mapper.problems:
        raise DeckError(mapper.problems)
    unmapped = {k: (n, WOULD_HAVE.get(k, "not read by shockfem")) for k, n in sorted(model.unmapped.items())}
    if title:
        mapper.notes.insert(0, f"title: {title}")
    return SceneOut(mapper.scene, mapper.meshes, mapper.notes, unmapped, mapper.origins, mapper.source)
