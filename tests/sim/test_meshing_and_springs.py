"""Bodies mesh apart even when they touch; bodies read from gmsh files; compression-only springs."""
import math

import numpy as np
import pytest

from shockfem.geometry import build_mesh
from shockfem.model import build_model
from shockfem.scene import resolve
from shockfem.verify import spring_cases
from shockfem.verify.scenes import STEEL, solve


def _model(raw, tmp_path):
    scene = resolve(raw, str(tmp_path))
    return build_model(scene, build_mesh(scene, cache_dir=str(tmp_path), log=lambda m: None))


@pytest.mark.parametrize("kinematics", ["axisymmetric", "3d"])
def test_touching_bodies_share_no_nodes(kinematics, tmp_path):
    gdim = 3 if kinematics == "3d" else 2
    rod = {"material": "steel", "shape": "cylinder", "radius": 0.002, "length": 0.01, "element_size": 0.001}
    raw = {"scene": {"name": "touching", "kinematics": kinematics, "end_time": 1e-6},
           "materials": {"steel": dict(STEEL)},
           "bodies": [dict(rod, name="lower", position=[0.0] * gdim),
                      dict(rod, name="upper", position=[0.0] * (gdim - 1) + [0.01])]}
    m = _model(raw, tmp_path)
    at_interface = np.abs(m.X0[:, -1] - 0.01) < 1e-12
    assert set(m.node_body[at_interface]) == {0, 1}
    # as many nodes on the interface from each body: two coincident copies, none shared
    assert (m.node_body[at_interface] == 0).sum() == (m.node_body[at_interface] == 1).sum()
    # 3D: the section is the 16-gon on the circle (four arcs of four hex edges each)
    area = math.pi * 0.002 ** 2 if gdim == 2 else 0.5 * 16 * 0.002 ** 2 * math.sin(2 * math.pi / 16)
    assert m.body_mass == pytest.approx([STEEL["density"] * area * 0.01] * 2, rel=1e-9)
    # the model hands the solver what it needs of the scene, not the scene
    assert not hasattr(m, "scene") and m.body_names == ["lower", "upper"]
    assert m.axisymmetric == (kinematics == "axisymmetric") and not m.plastic and not m.point_state


def test_body_from_a_gmsh_file(tmp_path):
    import gmsh
    gmsh.initialize(interruptible=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("plate")
    s = gmsh.model.occ.addRectangle(0, 0, 0, 0.02, 0.01)
    gmsh.model.occ.synchronize()
    bottom = [c for _, c in gmsh.model.getBoundary([(2, s)], oriented=False)
              if abs(gmsh.model.occ.getCenterOfMass(1, c)[1]) < 1e-12]
    gmsh.model.addPhysicalGroup(2, [s], 1)
    gmsh.model.addPhysicalGroup(1, bottom, 7)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.002)
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.recombine()
    path = str(tmp_path / "plate.msh")
    gmsh.write(path)
    gmsh.clear()
    raw = {"scene": {"name": "from_file", "kinematics": "plane-strain", "end_time": 1e-6, "thickness": 0.005},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "plate", "material": "steel", "shape": "mesh", "file": "plate.msh",
                       "regions": {"base": 7}, "position": [0.1, 0.2]}],
           "boundary": [{"region": "plate.base", "type": "fixed"}]}
    m = _model(raw, tmp_path)
    assert m.body_mass[0] == pytest.approx(STEEL["density"] * 0.02 * 0.01 * 0.005, rel=1e-12)
    assert m.X0.min(axis=0) == pytest.approx([0.1, 0.2]) and m.X0.max(axis=0) == pytest.approx([0.12, 0.21])
    fixed = m.constraints[-1].dofs // 2
    assert np.allclose(m.X0[fixed, 1], 0.2)


def test_compression_only_spring_never_pulls(tmp_path):
    """Bodies flying apart on a compression-only pad keep their speeds; a two-way spring slows them."""
    raw, _, _ = spring_cases._scene(0.01)
    raw["scene"]["end_time"] = 2e-4
    raw["spring"][0]["compression_only"] = True
    solver, _ = solve(raw, cache_dir=str(tmp_path))
    v, _ = solver.body_means()
    assert v[1, 1] == pytest.approx(1.0, abs=1e-12) and v[0, 1] == pytest.approx(0.0, abs=1e-12)
    raw["spring"][0]["compression_only"] = False
    solver, _ = solve(raw, cache_dir=str(tmp_path))
    v, _ = solver.body_means()
    assert v[1, 1] < 0.9
