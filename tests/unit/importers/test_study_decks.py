"""The hand-written decks of studies/lsdyna import to the scenes of their TOML forms, field for field, and
their meshes are the TOML scenes' own (the runs' agreement is ``shockfem verify lsdyna_decks``)."""
import pathlib

import numpy as np
import pytest

from shockfem.importers import import_model
from shockfem.scene import load_scene, read_toml
from shockfem.verify.lsdyna_cases import DECKS, scene_mesh

STUDIES = pathlib.Path(__file__).parents[3] / "studies" / "lsdyna"
# the deck's numbers are the TOML's in another unit set: the SI values agree to the round-off of pint's
# conversion factors (powers of ten, a few ulp)
ROUND_OFF = 1e-14


def _close(a, b):
    return np.allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=ROUND_OFF, atol=0.0)


@pytest.mark.parametrize("name", list(DECKS))
def test_deck_imports_to_its_toml_scene(name, tmp_path):
    done = import_model(str(STUDIES / f"{name}.k"), str(tmp_path / f"{name}.toml"), DECKS[name]["units"])
    deck, toml = load_scene(done.scene), load_scene(str(STUDIES / f"{name}.toml"))
    for field in ("kinematics", "element", "integration", "hourglass", "hourglass_coefficient", "safety_factor",
                  "bulk_viscosity", "mass_scaling_step"):
        assert getattr(deck, field) == getattr(toml, field), field
    assert _close(deck.end_time, toml.end_time)
    assert _close([deck.outputs.field_interval, deck.outputs.history_interval],
                  [toml.outputs.field_interval, toml.outputs.history_interval])
    for a, b in zip(deck.materials.values(), toml.materials.values()):
        assert _close([a.rho, a.E, a.nu], [b.rho, b.E, b.nu])
        assert (a.plasticity is None) == (b.plasticity is None)
        if a.plasticity:
            assert _close(a.plasticity.curve, b.plasticity.curve)
            pa, pb = a.plasticity, b.plasticity
            assert _close([pa.kinematic_modulus, pa.rate_D, pa.rate_q], [pb.kinematic_modulus, pb.rate_D, pb.rate_q])
            assert pa.rate_form == pb.rate_form
    assert [b.name for b in deck.bodies] == [b.name for b in toml.bodies]
    for a, b in zip(deck.bodies, toml.bodies):
        assert _close(a.velocity, b.velocity) and a.rigid == b.rigid
    for a, b in zip(deck.contacts, toml.contacts):
        keep = ("penalty", "penalty_scale", "damping", "friction", "method")
        assert {k: getattr(a, k) for k in keep} == {k: getattr(b, k) for k in keep}
    # the symmetry face (Taylor) becomes a zero axial velocity: the same constraint on the same nodes
    assert [(bc.kind, bc.components) for bc in deck.boundaries] == [
        ("velocity", (2,)) if bc.kind == "symmetry" else (bc.kind, bc.components) for bc in toml.boundaries]


@pytest.mark.parametrize("name", list(DECKS))
def test_deck_mesh_is_the_toml_mesh(name, tmp_path):
    """Node for node and cell for cell: the committed mesh include is the mesh the TOML scene runs on."""
    done = import_model(str(STUDIES / f"{name}.k"), str(tmp_path / f"{name}.toml"), DECKS[name]["units"])
    deck = read_toml(done.scene)
    for body in deck["bodies"]:
        body["file"] = str(tmp_path / body["file"])
    for a, b in zip(scene_mesh(deck, str(tmp_path)), scene_mesh(read_toml(str(STUDIES / f"{name}.toml")),
                                                                str(tmp_path))):
        assert np.array_equal(a["node_tags"], b["node_tags"]) and np.array_equal(a["cells"], b["cells"])
        # the include's numbers in the deck's length unit, read back: at most an ulp or two of 0.1 m
        assert np.allclose(a["coords"], b["coords"], rtol=0.0, atol=1e-16)
