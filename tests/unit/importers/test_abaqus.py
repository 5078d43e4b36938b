"""Abaqus .inp meshes through meshio: element sets as bodies, node sets as regions, lengths in the unit set."""
import pathlib

import numpy as np
import pytest

from shockfem.importers import import_model
from shockfem.importers.abaqus import inp_to_scene
from shockfem.importers.unit_sets import unit_set
from shockfem.scene import SceneError

INP = pathlib.Path(__file__).parent / "decks" / "two_bricks.inp"
# a deck's number times pint's factors (powers of ten, exact in decimal): round-off only; a wrong unit
# or factor is off by 10^3 or more
EXACT = 1e-12



def test_element_sets_become_bodies_and_node_sets_regions():
    out = inp_to_scene(str(INP), unit_set("mm-ms-kg-kN"))
    assert [b["name"] for b in out.scene["bodies"]] == ["lower", "upper"]
    lower, upper = out.meshes["lower"], out.meshes["upper"]
    assert lower.element == "hex" and len(lower.cells) == 1 and len(upper.cells) == 1
    # the bricks are 1 mm cubes: the lower one spans z 0..1 mm, in metres
    assert lower.coords[:, 2].min() == 0.0 and lower.coords[:, 2].max() == pytest.approx(1e-3, rel=EXACT)
    # BASE (nodes 1-4) is the lower brick's bottom face, TOP (9-12) the upper brick's top face
    assert list(lower.regions) == ["base"] and list(upper.regions) == ["top"]
    assert np.allclose(upper.coords[upper.facets[upper.regions["top"]]][..., 2], 2e-3, rtol=EXACT)


def test_materials_are_left_to_the_scene(tmp_path):
    done = import_model(str(INP), str(tmp_path / "bricks.toml"), "m-s-kg-N")
    text = (tmp_path / "bricks.toml").read_text()
    assert "[materials.lower]" in text and "give each material's fields" in done.text


def test_units_are_required(tmp_path):
    with pytest.raises(SceneError, match="--units"):
        import_model(str(INP), str(tmp_path / "bricks.toml"), None)
