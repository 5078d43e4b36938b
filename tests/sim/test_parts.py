"""The catalogue of parts, through the scene files of studies/gallery: each part's meshed mass
against its closed-form volume (within 0.5%), every named region present, the axisymmetric and
3D versions of a part in agreement, local refinement where asked, and bad dimensions refused
with the field named."""
import glob
import os

import pytest

from shockfem.geometry import build_mesh, region_facets
from shockfem.parts.catalog import PARTS
from shockfem.geometry.quality import mesh_quality
from shockfem.model import build_model
from shockfem.scene import SceneError, read_toml, resolve

GALLERY = sorted(glob.glob(os.path.join(os.path.dirname(__file__), "..", "..", "studies", "gallery", "*.toml")))


def _load(path, kinematics="axisymmetric", element=None, coarsen=1.0):
    raw = read_toml(path)
    if kinematics == "3d":
        raw["scene"]["kinematics"] = "3d"
        raw["scene"]["element"] = element
        for b in raw["bodies"]:
            if isinstance(b.get("position"), list):
                b["position"] = [0, 0, b["position"][1]]
        planes = [c.get("wall", {}) for c in raw.get("contact", [])] + [raw.get("penetration", {}).get("face", {})]
        for plane in planes:                        # (r, z) -> (0, 0, z)
            for key in ("point", "normal"):
                if key in plane:
                    plane[key] = [0, 0, plane[key][1]]
    for b in raw["bodies"]:
        b["element_size"] = f"{coarsen} * {b['element_size']}"
        if coarsen != 1.0:
            b.pop("refine", None)
    return resolve(raw, os.path.dirname(path))


def _masses(scene):
    meshed = build_mesh(scene, log=lambda *a: None)
    model = build_model(scene, meshed)
    out = {}
    for i, b in enumerate(scene.bodies):
        expected = scene.material_of(b).rho * PARTS[b.shape].volume(b.dims, scene.gdim)
        empty = [r for r in PARTS[b.shape].regions(b.dims, scene.gdim)
                 if len(region_facets(meshed, f"{b.name}.{r}")) == 0]
        out[b.name] = (model.body_mass[i], expected, empty)
    return out, meshed


def test_gallery_has_every_part():
    shapes = {b["shape"] for path in GALLERY for b in read_toml(path)["bodies"]}
    assert shapes == set(PARTS)


def _native_3d(path) -> bool:
    """A gallery scene written for 3D (an oriented body): no axisymmetric version to compare with."""
    return read_toml(path)["scene"].get("kinematics") == "3d"


@pytest.mark.parametrize("path", GALLERY, ids=lambda p: os.path.basename(p)[:-5])
def test_part_mass_regions_and_3d_agreement(path):
    if _native_3d(path):
        masses, _ = _masses(resolve(read_toml(path), os.path.dirname(path)))
        for name, (mass, expected, empty) in masses.items():
            assert mass == pytest.approx(expected, rel=5e-3) and not empty, name
        return
    axi, _ = _masses(_load(path))
    solid, _ = _masses(_load(path, "3d", "tet"))      # the gallery's sizes are the parts' default sizes
    for name, (mass, expected, empty) in axi.items():
        assert mass == pytest.approx(expected, rel=5e-3), name
        assert not empty, f"{name}: empty regions {empty}"
        mass3, expected3, empty3 = solid[name]
        assert mass3 == pytest.approx(expected3, rel=5e-3), name
        assert not empty3, f"{name}: empty regions in 3D {empty3}"
        # same part both ways: the masses differ only by the 3D-only features (slots, orifice)
        assert mass3 / mass == pytest.approx(expected3 / expected, rel=5e-3)


def test_hexahedra_from_split_tetrahedra():
    """A crowned striker in 3D hexahedra: mass within 0.5%, every cell usable."""
    scene = _load([p for p in GALLERY if p.endswith("cylinder.toml")][0], "3d", "hex", coarsen=2.0)
    masses, meshed = _masses(scene)
    mass, expected, empty = masses["striker"]
    assert mass == pytest.approx(expected, rel=5e-3) and not empty
    assert mesh_quality(scene, meshed)[0].min_jacobian > 0.0


def test_refinement_near_a_face():
    """The striker's crowned face is refined to 0.5 mm (element size 2 mm): the smallest element
    is there, and about the refined size."""
    scene = _load([p for p in GALLERY if p.endswith("cylinder.toml")][0])
    meshed = build_mesh(scene, log=lambda *a: None)
    q = mesh_quality(scene, meshed)[0]
    assert q.smallest_at[1] < 0.006                     # within the 6 mm refinement distance
    assert 0.2e-3 < q.smallest_length < 0.6e-3


def _scene_with(body):
    return {"scene": {"name": "bad", "kinematics": "axisymmetric", "end_time": "1 us"},
            "materials": {"steel": {"density": 7850, "youngs_modulus": "200 GPa", "poisson_ratio": 0.3}},
            "bodies": [dict({"name": "part", "material": "steel", "element_size": "1 mm"}, **body)]}


@pytest.mark.parametrize("body, field, words", [
    ({"shape": "tube", "outer_radius": "10 mm", "inner_radius": "12 mm", "length": "20 mm"},
     "bodies[0].inner_radius", "smaller than outer_radius"),
    ({"shape": "tube", "outer_radius": "-10 mm", "inner_radius": "2 mm", "length": "20 mm"},
     "bodies[0].outer_radius", "must be > 0"),
    ({"shape": "split_cone", "outer_radius": "20 mm", "length": "30 mm", "entry_radius": "22 mm",
      "exit_radius": "10 mm"}, "bodies[0].entry_radius", "smaller than outer_radius"),
    ({"shape": "projectile", "radius": "10 mm", "length": "100 mm", "crh": 0.3}, "bodies[0].crh", ">= 0.5"),
    ({"shape": "projectile", "radius": "10 mm", "length": "30 mm", "crh": 3}, "bodies[0].length", "nose"),
    ({"shape": "dashpot", "outer_radius": "20 mm", "length": "30 mm", "cavity_radius": "5 mm",
      "cavity_centre_radius": "17 mm"}, "bodies[0].cavity_centre_radius", "inside"),
    ({"shape": "cylinder", "radius": "10 mm", "length": "30 mm", "bottom_crown": "5 mm"},
     "bodies[0].bottom_crown", "at least the radius"),
    ({"shape": "stepped_cylinder", "radii": ["10 mm"], "lengths": ["5 mm", "6 mm"]}, "bodies[0].radii", "as many"),
    ({"shape": "carrier", "radius": "10 mm", "length": "30 mm", "seat_radius": "12 mm", "seat_depth": "5 mm"},
     "bodies[0].seat_radius", "narrower"),
])
def test_bad_dimensions_name_the_field(body, field, words):
    with pytest.raises(SceneError) as info:
        resolve(_scene_with(body))
    assert any(p.startswith(field + ":") and words in p for p in info.value.problems), info.value.problems


@pytest.mark.parametrize("ring, field, words", [
    ({"fits": "cone", "interference": "20 mm", "thickness": "10 mm", "length": "20 mm"},
     "bodies[1].interference", "smaller than the ring's thickness"),
    ({"fits": "cone", "interference": "0.05 mm", "thickness": "10 mm", "length": "50 mm"},
     "bodies[1].position", "does not fit along cone"),
    ({"fits": "nothing", "interference": "0.05 mm", "thickness": "10 mm", "length": "20 mm"},
     "bodies[1].fits", "must name the body"),
])
def test_clamp_ring_that_does_not_fit(ring, field, words):
    raw = _scene_with({"name": "cone", "shape": "split_cone", "outer_radius": "30 mm", "length": "40 mm",
                       "entry_radius": "15 mm", "exit_radius": "12 mm"})
    raw["bodies"].append(dict({"name": "ring", "material": "steel", "shape": "clamp_ring", "element_size": "1 mm"},
                              **ring))
    with pytest.raises(SceneError) as info:
        resolve(raw)
    assert any(p.startswith(field + ":") and words in p for p in info.value.problems), info.value.problems


def test_clamp_ring_bore_from_the_cone_and_the_interference():
    raw = _scene_with({"name": "cone", "shape": "split_cone", "outer_radius": "30 mm", "length": "40 mm",
                       "entry_radius": "15 mm", "exit_radius": "12 mm"})
    raw["bodies"].append({"name": "ring", "material": "steel", "shape": "clamp_ring", "element_size": "1 mm",
                          "fits": "cone", "interference": "0.05 mm", "thickness": "10 mm", "length": "20 mm",
                          "position": [0, "10 mm"]})
    ring = resolve(raw).bodies[1]
    assert ring.dims["inner_radius"] == pytest.approx(0.02995)


def test_run_log_states_the_approximations_of_each_part():
    """The axisymmetric split cone's slots are a hoop law, the ring starts overlapping by its
    interference, the projectile's nose is blunted: the 'models that run' block says so; the 3D cone
    has its slots."""
    from shockfem.model import describe
    path = next(p for p in GALLERY if p.endswith("split_cone.toml"))
    axi = describe(build_model(s := _load(path), build_mesh(s, log=lambda *a: None)), s)
    assert "approximation: slots in axisymmetry as a slotted-ring hoop law: the 4 segments carry no hoop" in axi
    assert "approximation: starts overlapping the body it fits by the interference 0.05 mm" in axi
    solid = describe(build_model(s := _load(path, "3d", "tet"), build_mesh(s, log=lambda *a: None)), s)
    assert "slotted-ring" not in solid
    path = next(p for p in GALLERY if p.endswith("projectile.toml"))
    text = describe(build_model(s := _load(path), build_mesh(s, log=lambda *a: None)), s)
    assert "approximation: ogive nose blunted by a flat tip (meplat) of radius" in text


def test_slotted_cone_outside_one_point_quads_is_a_clear_error(tmp_path):
    """The slotted-ring hoop law lives in the one-point quad kernel: triangles (or full
    integration) stop with the body named and what to change."""
    from shockfem.errors import ModelError
    raw = _scene_with({"name": "cone", "shape": "split_cone", "outer_radius": "30 mm", "length": "40 mm",
                       "entry_radius": "15 mm", "exit_radius": "12 mm", "element_size": "4 mm"})
    raw["scene"]["element"] = "tri"
    scene = resolve(raw)
    with pytest.raises(ModelError, match=r"body 'cone': the slotted split cone's hoop model .* element = \"quad\""):
        build_model(scene, build_mesh(scene, log=lambda *a: None, cache_dir=str(tmp_path)))


def test_projectile_quads_mesh_where_full_quad_recombination_refused(tmp_path):
    """The projectile's quads at twice the gallery's element size: gmsh's full-quad recombination refused
    the odd segment count of its small flat tip ("1D mesh cannot be divided by 2"); with every odd curve
    given a segment more the part meshes, its mass within 0.5%."""
    path = next(p for p in GALLERY if p.endswith("projectile.toml"))
    masses, _ = _masses(_load(path, coarsen=2.0))
    for name, (mass, expected, empty) in masses.items():
        assert mass == pytest.approx(expected, rel=5e-3) and not empty, name


def test_a_mesh_gmsh_cannot_make_is_a_clear_error(tmp_path, monkeypatch):
    """Whatever gmsh refuses, the run stops naming the body, the element type and size and what to
    change, not with gmsh's traceback (gmsh made to refuse every mesh here)."""
    import gmsh
    from shockfem.errors import ModelError

    def refuse(*args, **kwargs):
        raise Exception("no mesh today")
    monkeypatch.setattr(gmsh.model.mesh, "generate", refuse)
    path = next(p for p in GALLERY if p.endswith("projectile.toml"))
    with pytest.raises(ModelError, match=r"body penetrator: gmsh cannot mesh it with quad elements of 3 mm "
                                         r"\(no mesh today\); try a smaller element_size"):
        build_mesh(_load(path), log=lambda *a: None, cache_dir=str(tmp_path))


def test_payload_is_carried_in_the_projectile_cavity(tmp_path):
    """studies/gallery/projectile_payload.toml: the penetrator strikes a rigid plate nose first at
    50 m/s with a payload in its cavity.  The plate's impulse is the momentum both bodies lose, and
    the cavity's impulse on the payload is the momentum the payload loses (each to round-off: the impulse
    is integrated as the central-difference update applies the force, measured 5.6e-16 and 3.3e-16; it
    was up to 0.5% off when it took dt f_n+1); the payload stays in the cavity."""
    import json
    from shockfem.runner import run_scene
    path = next(p for p in GALLERY if p.endswith("projectile_payload.toml"))
    run_scene(_load(path), str(tmp_path / "run"), progress=False, quiet=True)
    s = json.loads((tmp_path / "run" / "summary.json").read_text())
    m = {k: b["mass"] for k, b in s["bodies"].items()}
    lost = {k: m[k] * (s["bodies"][k]["velocity_final"][1] + 50.0) for k in m}
    plate = s["contacts"]["nose_on_plate"]["impulse_on_a"][1]
    cavity = s["contacts"]["payload_in_cavity"]["impulse_on_a"][1]
    assert sum(lost.values()) == pytest.approx(plate, rel=1e-12)
    assert cavity == pytest.approx(lost["payload"], rel=1e-12) and cavity > 0.1 * m["payload"] * 50.0
    assert s["contacts"]["payload_in_cavity"]["max_penetration"] < 1e-4
    assert abs(s["energy"]["balance_error"]) < 1e-3


@pytest.mark.parametrize("kinematics, refine", [("axisymmetric", False), ("axisymmetric", True), ("3d", False)])
def test_a_sphere_stands_on_its_bottom_pole(kinematics, refine):
    """One definition of a sphere's position, whichever mesher draws it (the structured axisymmetric
    builder, the outline with local refinement, the 3D revolved outline): the bottom pole at the
    body's position, the top pole 2 R above it (to the mesh's coordinates, which lie on the sphere)."""
    R, z = 0.01, 0.05
    body = {"name": "ball", "material": "steel", "shape": "sphere", "radius": R, "element_size": 0.002,
            "position": [0.0, z] if kinematics == "axisymmetric" else [0.0, 0.0, z]}
    if refine:
        body["refine"] = [{"region": "bottom", "size": 0.001}]
    raw = {"scene": {"kinematics": kinematics, "end_time": 1e-6}, "materials": {"steel": {"library": "mild_steel"}},
           "bodies": [body]}
    meshed = build_mesh(resolve(raw), log=lambda *a: None)
    zs = meshed.mesh.geometry.x[:, 1 if kinematics == "axisymmetric" else 2]
    assert zs.min() == pytest.approx(z, abs=1e-9) and zs.max() == pytest.approx(z + 2 * R, abs=1e-9)


def test_a_turned_body_is_meshed_turned():
    """studies/gallery/tilted_drop.toml: the cylinder turned 15 degrees about x about its position
    is the unturned mesh turned, node for node (round-off), and its axis of least inertia (the axis of
    a 60 mm long, 20 mm radius cylinder) is the turned z axis."""
    import numpy as np
    path = next(p for p in GALLERY if p.endswith("tilted_drop.toml"))
    raw = read_toml(path)
    plain = {**raw, "bodies": [{k: v for k, v in b.items() if k != "orientation"} for b in raw["bodies"]]}
    x, m = {}, None
    for key, r in (("turned", raw), ("plain", plain)):
        scene = resolve(r, os.path.dirname(path))
        model = build_model(scene, build_mesh(scene, log=lambda *a: None))
        x[key], m = model.X0, model.mass
    angle = np.radians(15.0)
    R = np.array([[1.0, 0.0, 0.0], [0.0, np.cos(angle), -np.sin(angle)], [0.0, np.sin(angle), np.cos(angle)]])
    p = np.array([0.0, 0.0, 5.3e-3])
    assert np.abs(x["turned"] - (p + (x["plain"] - p) @ R.T)).max() < 1e-15
    rel = x["turned"] - (m[:, None] * x["turned"]).sum(axis=0) / m.sum()
    inertia = (m[:, None, None] * (np.einsum("ij,ij->i", rel, rel)[:, None, None] * np.eye(3)
                                   - rel[:, :, None] * rel[:, None, :])).sum(axis=0)
    axis = np.linalg.eigh(inertia)[1][:, 0]                     # the smallest moment
    assert abs(axis @ R[:, 2]) == pytest.approx(1.0, abs=1e-9)


def test_a_2d_body_turned_end_over_end_lands_as_its_mirror_image():
    """Axisymmetric, orientation = {direction = [0, -1]}: a 4340 penetrator turned end over end about its
    position p is its drawn mesh mirrored, z -> 2 p_z - z, node for node (round-off), its single speed
    turned with it; falling base first at 5 m/s onto a rigid floor it rebounds as the drawn body does
    flying base first up onto a rigid ceiling, its mirror image (round-off)."""
    import numpy as np
    from shockfem.verify.scenes import solve
    p, L, gap = 0.201, 0.2, 1e-4

    def scene(flipped):
        body = {"name": "p", "material": "s", "shape": "projectile", "radius": 0.03, "length": L, "crh": 3.0,
                "meplat_radius": 0.003, "element_size": 0.006,
                "refine": [{"region": "nose", "size": 0.003, "distance": 0.024}],
                "position": [0.0, p], "velocity": "5 m/s"}
        if flipped:
            body["orientation"] = {"direction": [0, -1]}
            wall = {"point": [0.0, p - L - gap], "normal": [0.0, 1.0]}      # a floor under the base
        else:
            wall = {"point": [0.0, p + L + gap], "normal": [0.0, -1.0]}     # a ceiling over it
        return {"scene": {"name": "flip", "kinematics": "axisymmetric", "end_time": 1.6e-4},
                "materials": {"s": {"library": "steel_4340"}}, "bodies": [body],
                "contact": [{"name": "wall", "a": "p.base", "wall": wall, "penalty_scale": 1.0}],
                "outputs": {"field_interval": 1.6e-4, "history_interval": 1e-6}}
    x, v, pair = {}, {}, {}
    for flipped in (False, True):
        solver, _ = solve(scene(flipped))
        x[flipped], v[flipped], pair[flipped] = solver.model.X0, solver.body_means()[0][0], solver.contacts[0]
    mirrored = x[False] * np.array([1.0, -1.0]) + np.array([0.0, 2 * p])
    assert np.abs(x[True] - mirrored).max() < 1e-15
    assert v[True][1] == pytest.approx(-v[False][1], rel=1e-9) and v[False][1] < -4.0   # rebounded
    assert pair[True].intervals[0][0] == pytest.approx(pair[False].intervals[0][0], rel=1e-9)
