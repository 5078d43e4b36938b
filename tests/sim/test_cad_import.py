"""A body from a STEP file: gmsh's OCC kernel reads it (millimetres to metres), meshes it at the
body's element size, and names the faces the scene lists by their CAD tags."""
import math

import gmsh
import numpy as np
import pytest

from shockfem.errors import ModelError
from shockfem.geometry import build_mesh, region_facets
from shockfem.model import build_model
from shockfem.scene import SceneError, resolve

RADIUS_MM, LENGTH_MM = 10.0, 50.0


@pytest.fixture(scope="module")
def step_file(tmp_path_factory):
    """A cylinder written by gmsh in millimetres (STEP's default unit); gmsh tags its faces
    1 (side), 2 (top), 3 (bottom)."""
    path = str(tmp_path_factory.mktemp("cad") / "rod.step")
    initialized = gmsh.isInitialized()
    if not initialized:
        gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("cad_rod")
    gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, LENGTH_MM, RADIUS_MM)
    gmsh.model.occ.synchronize()
    gmsh.write(path)
    gmsh.model.remove()
    if not initialized:
        gmsh.finalize()
    return path


def _scene(step, **body):
    return {"scene": {"name": "cad", "kinematics": "3d", "element": "tet", "end_time": "1 us"},
            "materials": {"steel": {"density": "7850 kg/m^3", "youngs_modulus": "210 GPa", "poisson_ratio": 0.3}},
            "bodies": [{"name": "rod", "material": "steel", "shape": "mesh", "file": step,
                        "element_size": "3 mm", "position": [0, 0, 0.01],
                        "regions": {"bottom": 3, "top": [2]}, **body}]}


def test_step_body_has_its_mass_and_named_faces(step_file, tmp_path):
    scene = resolve(_scene(step_file))
    meshed = build_mesh(scene, cache_dir=str(tmp_path))
    model = build_model(scene, meshed)
    exact = 7850 * math.pi * (RADIUS_MM * 1e-3) ** 2 * LENGTH_MM * 1e-3
    # straight-sided tetrahedra on a 10 mm radius at 3 mm (24 around by curvature): within 1%
    assert model.body_mass[0] == pytest.approx(exact, rel=0.01)
    mesh = meshed.mesh
    mesh.topology.create_connectivity(2, 0)
    f2v = mesh.topology.connectivity(2, 0)
    for region, z in (("rod.bottom", 0.01), ("rod.top", 0.06)):
        facets = region_facets(meshed, region)
        assert len(facets) > 10
        nodes = np.unique(np.concatenate([f2v.links(f) for f in facets]))
        assert np.allclose(mesh.geometry.x[nodes, 2], z, atol=1e-9)


def test_step_body_errors_name_the_field(step_file, tmp_path):
    raw = _scene(step_file)
    del raw["bodies"][0]["element_size"]
    raw["bodies"][0]["regions"] = {"bottom": "3"}
    with pytest.raises(SceneError) as e:
        resolve(raw)
    text = "\n".join(e.value.problems)
    assert "bodies[0].element_size: missing: a CAD file is meshed here" in text
    assert "bodies[0].regions: must map region names to the CAD file's face tags" in text
    raw = _scene(step_file)
    raw["scene"]["kinematics"] = "axisymmetric"
    raw["scene"]["element"] = "quad"
    raw["bodies"][0]["position"] = [0, 0.01]
    with pytest.raises(SceneError, match=r"bodies\[0\].file: a CAD \(.step\) body needs kinematics = '3d'"):
        resolve(raw)
    scene = resolve(_scene(step_file, regions={"bottom": 7}))
    with pytest.raises(ModelError, match=r"has no face \[7\] \(region 'bottom'\); it has \[1, 2, 3\]"):
        build_mesh(scene, cache_dir=str(tmp_path))
