"""The hand-written decks of studies/lsdyna import to the scenes of their TOML forms, field for field, and
their meshes are the TOML scenes' own (the runs' agreement is ``shockfem verify lsdyna_decks``)."""
import pathlib

import numpy as np
import pytest

from shockfem.geometry.meshing import draw_body
from shockfem.importers import import_model
from shockfem.scene import load_scene
from shockfem.verify.lsdyna_cases import DECKS

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
    """Node for node and cell for cell: the committed mesh include is the TOML scene's gmsh mesh."""
    done = import_model(str(STUDIES / f"{name}.k"), str(tmp_path / f"{name}.toml"), DECKS[name]["units"])
    deck, toml = load_scene(done.scene), load_scene(str(STUDIES / f"{name}.toml"))
    for i in range(len(toml.bodies)):
        a, b = draw_body(deck, i), draw_body(toml, i)
        position = lambda m: np.searchsorted(m.node_tags, m.cells)        # cells by node order
        assert np.all(np.diff(a.node_tags) > 0) and np.all(np.diff(b.node_tags) > 0)
        assert np.array_equal(position(a), position(b))
        assert np.allclose(a.coords, b.coords, rtol=0.0, atol=1e-15)     # 1 ulp of a 0.1 m coordinate: 1.4e-17
