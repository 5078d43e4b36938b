"""The ``[[bodies]]`` tables: each body's shape (a catalogued part, a box, or a mesh or CAD file), its
element size and refinements, material, placement, motion and own damping; then the clamp rings fitted
to the bodies they grip, and every body's regions, which the other tables name."""
from __future__ import annotations

import dataclasses
import os

from ..parts.catalog import CAD_FILES, MESH_FILES, PARTS
from .checker import Checker
from .damping import read_body_damping
from .orientation import read_orientation, turned
from .specs import BOX_REGIONS, SHAPES, Body, Material

# a body's own fields; a part adds its dimensions, a box its size, a mesh its file and regions
BODY_FIELDS = {"name", "material", "shape", "element_size", "position", "velocity", "spin", "orientation", "rigid",
               "refine", "damping"}


class _AnyRegion(tuple):
    """The regions of a body whose dimensions were refused: every name is taken as one of them."""

    def __contains__(self, name) -> bool:
        return True


def read_bodies(ck: Checker, raw: dict, kin: str, materials: dict[str, Material],
                base_dir: str) -> tuple[list[Body], dict]:
    """Every ``[[bodies]]`` entry, the clamp rings fitted, and each body's regions by name (``_AnyRegion``
    for a body whose dimensions were refused: one bad dimension is one message, not one more per contact,
    load and refinement that names a region of it)."""
    gdim = 3 if kin == "3d" else 2
    bodies: list[Body] = []
    raw_bodies = raw.get("bodies", [])
    if not isinstance(raw_bodies, list) or not raw_bodies:
        ck.fail("bodies", "needs at least one [[bodies]] entry")
        raw_bodies = []
    names = set()
    sound: dict[str, bool] = {}     # parts whose dimensions passed their checks
    for i, b in enumerate(raw_bodies):
        path = f"bodies[{i}]"
        if not isinstance(b, dict):
            ck.fail(path, "must be a table")
            continue
        bodies.append(_read_body(ck, b, path, i, kin, materials, base_dir, names, sound))
    bodies = _fit_clamp_rings(ck, raw, bodies, gdim)
    body_regions = {b.name: _regions_of(b, gdim) if sound.get(b.name, True) else _AnyRegion() for b in bodies}
    for i, b in enumerate(bodies):
        for j, (region, _, _) in enumerate(b.refine):
            if region not in body_regions[b.name]:
                ck.fail(f"bodies[{i}].refine[{j}].region", f"{b.name} has no region {region!r} "
                                                          f"(it has: {', '.join(body_regions[b.name])})")
    return bodies, body_regions


def _read_body(ck: Checker, b: dict, path: str, i: int, kin: str, materials: dict, base_dir: str, names: set,
               sound: dict) -> Body:
    """One ``[[bodies]]`` entry."""
    gdim = 3 if kin == "3d" else 2
    bname = b.get("name")
    if not isinstance(bname, str) or not bname.isidentifier():
        ck.fail(f"{path}.name", f"needs a name made of letters, digits and _, got {bname!r}")
        bname = f"body{i}"
    if bname in names:
        ck.fail(f"{path}.name", f"duplicate body name {bname!r}")
    names.add(bname)
    shape = ck.choice(b, "shape", path, SHAPES)
    allowed = set(BODY_FIELDS)
    dims: dict[str, float] = {}
    mesh_file = None
    regions: dict = {}
    if shape in PARTS:
        accepted, sound[bname] = _part_dims(ck, PARTS[shape], b, path, kin, dims)
        allowed |= accepted
    if shape == "box":
        allowed |= {"size"}
        _box_size(ck, b, path, gdim, dims)
    elif shape == "mesh":
        allowed |= {"file", "regions"}
        mesh_file, regions = _mesh_file(ck, b, path, kin, base_dir)
    ck.unknown(b, allowed, path)
    mat = b.get("material")
    if not isinstance(mat, str) or mat not in materials:
        ck.fail(f"{path}.material", f"unknown material {mat!r} (defined: {', '.join(materials) or 'none'})")
    h = ck.quantity(b, "element_size", path, "length", positive=True,
                    default=None if shape != "mesh" else 0.0)
    if shape == "cylinder" and h > 0 and h > dims.get("radius", h):
        ck.fail(f"{path}.element_size", "must not exceed the radius (at least one element across)")
    refine = _refinements(ck, b, path, h)
    if refine and shape in ("box", "mesh"):
        ck.fail(f"{path}.refine", f"local refinement is drawn on the catalogued parts, not on a {shape}")
    position, velocity, spin, orientation = _placement(ck, b, path, kin)
    rigid = b.get("rigid", False)
    if not isinstance(rigid, bool):
        ck.fail(f"{path}.rigid", f"must be true or false, got {rigid!r}")
        rigid = False
    own_damping = read_body_damping(ck, b, path) if "damping" in b else None
    return Body(name=bname, material=mat if isinstance(mat, str) and mat in materials else "", shape=shape,
                dims=dims, element_size=h, position=position, velocity=velocity, spin=spin, rigid=rigid,
                mesh_file=mesh_file, regions=regions, refine=refine, damping=own_damping, orientation=orientation)


def _box_size(ck: Checker, b: dict, path: str, gdim: int, dims: dict):
    """A box's ``size``, one positive length per axis, into ``dims`` as ``size_x``, ..."""
    size = ck.vector(b, "size", path, "length", gdim, [1.0] * gdim)
    if "size" not in b:
        ck.fail(f"{path}.size", f"missing ({gdim} lengths)")
    for k, v in zip("xyz", size):
        if v <= 0:
            ck.fail(f"{path}.size", f"every length must be > 0, got {b.get('size')}")
            break
        dims[f"size_{k}"] = v


def _mesh_file(ck: Checker, b: dict, path: str, kin: str, base_dir: str) -> tuple[str | None, dict]:
    """A mesh body's ``file`` (a gmsh .msh with physical groups, or a CAD file meshed here) and its
    ``regions``: (the file's path, region name -> tag or face tags)."""
    mesh_file, regions = None, {}
    f = b.get("file")
    if not isinstance(f, str) or not f.lower().endswith(MESH_FILES + CAD_FILES):
        ck.fail(f"{path}.file", "missing or not a mesh: the path of a gmsh .msh file with physical groups, "
                                "or of a .step / .stp CAD file (lengths in its own units)")
    else:
        mesh_file = f if os.path.isabs(f) else os.path.normpath(os.path.join(base_dir, f))
        if not os.path.exists(mesh_file):
            ck.fail(f"{path}.file", f"no such file {mesh_file}")
    cad = isinstance(f, str) and f.lower().endswith(CAD_FILES)
    reg = b.get("regions", {})
    if cad:
        # a CAD file has no physical groups: a region is one face tag or a list of them
        ok = isinstance(reg, dict) and all(
            isinstance(v, int) or (isinstance(v, list) and v and all(isinstance(x, int) for x in v))
            for v in reg.values())
        if not ok:
            ck.fail(f"{path}.regions", "must map region names to the CAD file's face tags (an integer or a "
                                       "list of integers, as gmsh numbers them on import)")
        else:
            regions = {k: tuple(v) if isinstance(v, list) else (v,) for k, v in reg.items()}
        if not b.get("element_size"):
            ck.fail(f"{path}.element_size", "missing: a CAD file is meshed here; give an element size")
        if kin != "3d":
            ck.fail(f"{path}.file", "a CAD (.step) body needs kinematics = '3d'; in 2D use a catalogued "
                                    "part or a .msh of the section")
    elif not isinstance(reg, dict) or not all(isinstance(v, int) for v in reg.values()):
        ck.fail(f"{path}.regions", "must map region names to gmsh physical group tags (integers)")
    else:
        regions = dict(reg)
    return mesh_file, regions


def _placement(ck: Checker, b: dict, path: str, kin: str) -> tuple:
    """A body's (position, velocity, spin, orientation); a single speed is along its own (turned) axis."""
    gdim = 3 if kin == "3d" else 2
    pos = ck.vector(b, "position", path, "length", gdim, [0.0] * gdim)
    vel = ck.vector(b, "velocity", path, "velocity", gdim, [0.0] * gdim)
    spin = ck.quantity(b, "spin", path, "angular_velocity", default=0.0)
    if spin and gdim != 3:
        ck.fail(f"{path}.spin", "an initial spin needs kinematics = '3d'")
    orientation = read_orientation(ck, b, path, gdim)
    if orientation is not None and not isinstance(b.get("velocity", []), list):
        # a single speed is along the body's own axis, turned with it
        vel = turned(orientation, list(vel) + [0.0] * (3 - gdim))[:gdim]
    if kin == "axisymmetric":
        if pos[0] != 0.0:
            ck.fail(f"{path}.position", "axisymmetric bodies sit on the axis: the r component must be 0")
        if vel[0] != 0.0:
            ck.fail(f"{path}.velocity", "axisymmetric bodies move along the axis: the r component must be 0")
    return pos, vel, spin, orientation


def _part_dims(ck, part, b: dict, path: str, kin: str, dims: dict) -> tuple[set[str], bool]:
    """Read a catalogued part's dimensions into ``dims`` and check them together; returns the
    fields the part accepts and whether the dimensions are sound (so its regions can be drawn)."""
    read = len(ck.problems)
    for p in part.params:
        if p.kind == "lengths":
            raw = b.get(p.name)
            if not isinstance(raw, list) or not raw:
                ck.fail(f"{path}.{p.name}", f"missing (a list of lengths: {p.doc})")
                dims[p.name] = [1.0]
                continue
            values = []
            for j, item in enumerate(raw):
                values.append(ck.quantity({"v": item}, "v", "", "length", positive=True))
                if ck.problems and ck.problems[-1].startswith(".v:"):
                    ck.problems[-1] = f"{path}.{p.name}[{j}]" + ck.problems[-1][2:]
            dims[p.name] = values
        else:
            dims[p.name] = ck.quantity(b, p.name, path, "length" if p.kind == "length" else "dimensionless",
                                       default=p.default, positive=p.minimum == "positive",
                                       nonnegative=p.minimum == "nonnegative")
            if p.kind == "count" and (dims[p.name] != int(dims[p.name]) or dims[p.name] < 1):
                ck.fail(f"{path}.{p.name}", f"must be a whole number >= 1, got {b.get(p.name)!r}")
    shaped = any(dims.get(k) for k in ("bottom_chamfer", "top_chamfer", "bottom_crown", "top_crown"))
    if kin == "plane-strain" and (part.name != "cylinder" or shaped):
        ck.fail(f"{path}.shape", f"a {part.name} is a part of revolution: use kinematics 'axisymmetric' or '3d' "
                                 "(or shape = 'box' / 'mesh' in plane strain)")
    before = len(ck.problems)
    # a clamp ring is checked against the body it fits; dimensions already refused are not checked
    # together (their geometry would be nonsense: a negative radius under a square root)
    if part.name != "clamp_ring" and before == read:
        for fieldname, message in part.check(dims):
            ck.fail(f"{path}.{fieldname}", message)
    accepted = {p.name for p in part.params}
    if part.name == "clamp_ring":
        accepted.add("fits")
    return accepted, len(ck.problems) == read


def _refinements(ck, b: dict, path: str, h: float) -> tuple:
    """``refine = [{region, size, distance}]``: a finer element size near named faces, growing
    linearly to the body's element size over ``distance`` (default 5 element sizes)."""
    out = []
    fields = ("region", "size", "distance")
    for rp, r in ck.entries(b, "refine", f"{path}.refine", fields):
        ck.unknown(r, fields, rp)
        region = r.get("region")
        if not isinstance(region, str):
            ck.fail(f"{rp}.region", "missing (the name of one of the body's regions)")
        size = ck.quantity(r, "size", rp, "length", positive=True)
        if h and size >= h:
            ck.fail(f"{rp}.size", f"must be smaller than the body's element_size {h:g} m to refine, got {size:g} m")
        distance = ck.quantity(r, "distance", rp, "length", default=5 * size, positive=True)
        out.append((region if isinstance(region, str) else "", size, distance))
    return tuple(out)


def _fit_clamp_rings(ck, raw: dict, bodies: list, gdim: int) -> list:
    """Give each clamp ring its bore from the body it fits: that body's outer radius less the
    interference; the ring must be thicker than the interference and lie along that body."""
    out = []
    by_name = {b.name: b for b in bodies}
    for i, b in enumerate(bodies):
        if b.shape != "clamp_ring":
            out.append(b)
            continue
        path = f"bodies[{i}]"
        fits = raw["bodies"][i].get("fits")
        target = by_name.get(fits) if isinstance(fits, str) else None
        outer = None if target is None else target.dims.get("outer_radius", target.dims.get("radius"))
        dims = dict(b.dims)
        if target is None or outer is None or target.shape not in PARTS:
            ck.fail(f"{path}.fits", f"must name the body the ring is shrunk onto (a part of revolution), got {fits!r}")
            dims["inner_radius"] = 1.0
        else:
            dims["inner_radius"] = outer - dims["interference"]
            if dims["interference"] >= dims["thickness"]:
                ck.fail(f"{path}.interference", f"the interference ({dims['interference']:g} m) must be smaller "
                                                 f"than the ring's thickness ({dims['thickness']:g} m)")
            if dims["interference"] >= outer:
                ck.fail(f"{path}.interference", f"the ring does not fit: an interference of "
                                                 f"{dims['interference']:g} m on a radius of {outer:g} m")
            z0, z1 = b.position[-1], b.position[-1] + dims["length"]
            t0 = target.position[-1]
            t1 = t0 + target.dims.get("length", 0.0)
            if z0 < t0 - 1e-12 or z1 > t1 + 1e-12:
                ck.fail(f"{path}.position", f"the ring (z from {z0:g} to {z1:g} m) does not fit along {fits} "
                                            f"(z from {t0:g} to {t1:g} m)")
        out.append(dataclasses.replace(b, dims=dims))
    return out


def _regions_of(body, gdim: int) -> tuple[str, ...]:
    if body.shape == "mesh":
        return tuple(body.regions)
    if body.shape == "box":
        return BOX_REGIONS[gdim]
    return PARTS[body.shape].regions(body.dims, gdim)
