"""The scene: what a user describes, resolved to SI and checked before anything runs.

A scene file is TOML (documented with a worked example in ``docs/scenes.md``).  ``resolve``
turns the raw dictionary into the frozen dataclasses of ``specs.py``, collecting *every* problem
with its path (``bodies[1].radius: must be > 0, got -3 mm``, ``checker.py``) instead of stopping
at the first one.  This module reads the scene, its bodies, boundaries, damping and outputs; the
materials, contacts and springs, and the shock table have their own readers (``materials.py``,
``contacts.py``, ``shock.py``).  Nothing here imports dolfinx: a scene can be checked on any machine.
"""
from __future__ import annotations

import dataclasses
from typing import Any

from ..parts.catalog import CAD_FILES, MESH_FILES, PARTS
from .checker import Checker, SceneError
from .cavities import read_cavities
from .penetration import read_penetration
from .contacts import read_contacts, read_springs
from .materials import read_material
from .orientation import read_orientation, turned
from .shock import read_shock
from .specs import (BC_TYPES, BOX_REGIONS, DAMPING_TYPES, ELEMENTS, FIELDS, HOURGLASS_FORMS, INTEGRATIONS,
                    KINEMATICS, SHAPES, Body, Boundary, Damping, Material, Outputs, Scene, SectionCuts)


class _AnyRegion(tuple):
    """The regions of a body whose dimensions were refused: every name is taken as one of them."""

    def __contains__(self, name) -> bool:
        return True


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


def _damping(ck, raw: dict, path: str, kinds, default_kind: str) -> Damping:
    """A ``{ratio, frequency, type}`` damping table."""
    d = ck.table(raw, "damping", path)
    ck.unknown(d, ("ratio", "frequency", "type"), path)
    ratio = ck.quantity(d, "ratio", path, "dimensionless", nonnegative=True, upper=1.0)
    freq = ck.quantity(d, "frequency", path, "frequency", positive=True)
    kind = ck.choice(d, "type", path, kinds, default=default_kind)
    return Damping(ratio, freq, kind)


def _body_damping(ck, b: dict, path: str) -> Damping:
    """``bodies[i].damping``: the body's own stiffness-proportional damping, as LS-DYNA's
    *DAMPING_PART_STIFFNESS: a fraction of critical at the body's own frequency (its first mode,
    say), so that small stiff bodies are not damped at a large body's low frequency (stiffness
    damping grows with frequency).  Mass-proportional damping stays scene-wide."""
    return _damping(ck, b, f"{path}.damping", ("stiffness",), "stiffness")


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


def resolve(raw: dict, base_dir: str = ".") -> Scene:
    """Check a raw scene dictionary completely and return the resolved ``Scene``.

    Raises
    ------
    SceneError
        Listing every problem found, each with its path.
    """
    import os

    ck = Checker()
    ck.unknown(raw, ("scene", "materials", "bodies", "boundary", "contact", "spring", "cavity", "damping",
                     "outputs", "shock", "penetration"), "")
    s = ck.table(raw, "scene", "scene")
    ck.unknown(s, ("name", "kinematics", "element", "end_time", "safety_factor", "thickness",
                   "energy_error_limit", "integration", "hourglass", "hourglass_coefficient", "gravity",
                   "bulk_viscosity_quadratic", "bulk_viscosity_linear", "curve_elements", "checkpoint_interval",
                   "mass_scaling_step", "mass_scaling_limit"),
               "scene")
    name = s.get("name", "scene")
    if not isinstance(name, str) or not name.strip() or name.strip(".") == "" or any(c in name for c in "/\\"):
        # the name is the run directory's default (results/<name>): it must name one directory
        ck.fail("scene.name", f"must be a name for the run's directory (letters, digits, - and _; no slash), "
                              f"got {name!r}")
        name = "scene"
    kin = ck.choice(s, "kinematics", "scene", KINEMATICS)
    gdim = 3 if kin == "3d" else 2
    element = ck.choice(s, "element", "scene", ELEMENTS[kin], default=ELEMENTS[kin][0])
    end_time = ck.quantity(s, "end_time", "scene", "time", positive=True)
    sf = ck.quantity(s, "safety_factor", "scene", "dimensionless", default=0.9, positive=True)
    if sf > 1.0:
        ck.fail("scene.safety_factor", f"must be <= 1 (explicit stability), got {sf}")
    thickness = ck.quantity(s, "thickness", "scene", "length", default=1.0, positive=True)
    elimit = ck.quantity(s, "energy_error_limit", "scene", "dimensionless", default=0.05, positive=True)
    # simulated time between checkpoints (``output/checkpoint.py``); 0: only when a signal stops the run
    checkpoint = ck.quantity(s, "checkpoint_interval", "scene", "time", default=end_time / 10,
                             nonnegative=True)
    # mass scaling (``model/mass_scaling.py``): the smallest step the run takes (safety factor included),
    # and the largest share of a body's mass it may add before the run is refused
    ms_step = ck.quantity(s, "mass_scaling_step", "scene", "time", default=0.0, nonnegative=True)
    ms_limit = ck.quantity(s, "mass_scaling_limit", "scene", "dimensionless", default=0.05, positive=True)
    curve = s.get("curve_elements", 24)
    if not isinstance(curve, int) or isinstance(curve, bool) or not 6 <= curve <= 360:
        ck.fail("scene.curve_elements", f"must be a whole number of elements round a circle in [6, 360], got {curve!r}")
        curve = 24
    integration = ck.choice(s, "integration", "scene", INTEGRATIONS, default="reduced")
    hourglass = ck.choice(s, "hourglass", "scene", HOURGLASS_FORMS, default="stiffness")
    hg_coef = ck.quantity(s, "hourglass_coefficient", "scene", "dimensionless", default=0.05,
                          nonnegative=True, upper=1.0)
    gravity = ck.vector(s, "gravity", "scene", "acceleration", gdim, [0.0] * gdim)
    bulk_viscosity = (ck.quantity(s, "bulk_viscosity_quadratic", "scene", "dimensionless", default=1.5,
                                  nonnegative=True),
                      ck.quantity(s, "bulk_viscosity_linear", "scene", "dimensionless", default=0.06,
                                  nonnegative=True))
    if kin == "axisymmetric" and gravity[0] != 0.0:
        ck.fail("scene.gravity", "axisymmetric gravity acts along the axis: the r component must be 0")

    materials: dict[str, Material] = {}
    mats = ck.table(raw, "materials", "materials")
    for mname, m in mats.items():
        path = f"materials.{mname}"
        if not isinstance(m, dict):
            ck.fail(path, "must be a table")
            continue
        materials[mname] = read_material(ck, mname, m, path)

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
        bname = b.get("name")
        if not isinstance(bname, str) or not bname.isidentifier():
            ck.fail(f"{path}.name", f"needs a name made of letters, digits and _, got {bname!r}")
            bname = f"body{i}"
        if bname in names:
            ck.fail(f"{path}.name", f"duplicate body name {bname!r}")
        names.add(bname)
        shape = ck.choice(b, "shape", path, SHAPES)
        allowed = {"name", "material", "shape", "element_size", "position", "velocity", "spin", "orientation", "rigid",
                   "refine",
                   "damping"}
        dims: dict[str, float] = {}
        mesh_file = None
        regions: dict[str, int] = {}
        if shape in PARTS:
            accepted, sound[bname] = _part_dims(ck, PARTS[shape], b, path, kin, dims)
            allowed |= accepted
        if shape == "box":
            allowed |= {"size"}
            size = ck.vector(b, "size", path, "length", gdim, [1.0] * gdim)
            if "size" not in b:
                ck.fail(f"{path}.size", f"missing ({gdim} lengths)")
            for k, v in zip("xyz", size):
                if v <= 0:
                    ck.fail(f"{path}.size", f"every length must be > 0, got {b.get('size')}")
                    break
                dims[f"size_{k}"] = v
        elif shape == "mesh":
            allowed |= {"file", "regions"}
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
        rigid = b.get("rigid", False)
        if not isinstance(rigid, bool):
            ck.fail(f"{path}.rigid", f"must be true or false, got {rigid!r}")
            rigid = False
        own_damping = _body_damping(ck, b, path) if "damping" in b else None
        bodies.append(Body(bname, mat if isinstance(mat, str) and mat in materials else "", shape, dims, h, pos, vel, spin,
                           rigid, mesh_file, regions, refine, own_damping, orientation))

    bodies = _fit_clamp_rings(ck, raw, bodies, gdim)
    # a body whose dimensions were refused has no regions to check against: any region named on it is
    # taken, so that one bad dimension is one message, not one more per contact, load and refinement
    body_regions = {b.name: _regions_of(b, gdim) if sound.get(b.name, True) else _AnyRegion() for b in bodies}
    for i, b in enumerate(bodies):
        for j, (region, _, _) in enumerate(b.refine):
            if region not in body_regions[b.name]:
                ck.fail(f"bodies[{i}].refine[{j}].region", f"{b.name} has no region {region!r} "
                                                          f"(it has: {', '.join(body_regions[b.name])})")
    boundaries: list[Boundary] = []
    axes = "xyz"[:gdim] if kin != "axisymmetric" else "rz"
    for path, bc in ck.entries(raw, "boundary"):
        ck.unknown(bc, ("region", "type", "direction", "value", "history"), path)
        region = bc.get("region", "")
        bname, _, rname = str(region).partition(".")
        if bname not in body_regions:
            ck.fail(f"{path}.region", f"must be 'body.region' with a known body, got {region!r}")
        elif rname not in body_regions[bname]:
            ck.fail(f"{path}.region", f"body {bname!r} has regions {', '.join(body_regions[bname])}; "
                                      f"got {rname!r}")
        kind = ck.choice(bc, "type", path, BC_TYPES)
        comps: tuple[int, ...] = tuple(range(gdim))
        history: tuple = ((0.0, 0.0),)
        if kind in ("velocity", "force"):
            d = bc.get("direction", axes[-1])
            if not isinstance(d, str) or d not in tuple(axes):        # ("rz" and "" are in the string "rz")
                ck.fail(f"{path}.direction", f"must be one of {', '.join(axes)}, got {d!r}")
                d = axes[-1]
            comps = (axes.index(d),)
            dim = "velocity" if kind == "velocity" else "force"
            if "history" in bc:
                history = tuple(ck.pairs(bc, "history", path, ("time", "value"), ("time", dim))) or history
            else:
                history = ((0.0, ck.quantity(bc, "value", path, dim)),)
        boundaries.append(Boundary(region, kind, comps, history))

    contacts = read_contacts(ck, raw, body_regions, kin)
    springs = read_springs(ck, raw, body_regions, gdim)
    cavities = read_cavities(ck, raw, body_regions)
    penetration, tunnel = read_penetration(ck, raw, body_regions, bodies, kin)
    if tunnel is not None:
        contacts.append(tunnel)

    damping = _damping(ck, raw, "damping", DAMPING_TYPES, "rayleigh") if "damping" in raw else None

    o = ck.table(raw, "outputs", "outputs", required=False)
    ck.unknown(o, ("fields", "field_interval", "history_interval", "sections"), "outputs")
    fields = o.get("fields", list(FIELDS))
    if not isinstance(fields, list) or any(f not in FIELDS for f in fields):
        ck.fail("outputs.fields", f"must be a list drawn from {', '.join(FIELDS)}, got {fields!r}")
        fields = list(FIELDS)
    fi = ck.quantity(o, "field_interval", "outputs", "time", default=end_time / 10, positive=True)
    hi = ck.quantity(o, "history_interval", "outputs", "time", default=0.0, nonnegative=True)
    outputs = Outputs(tuple(fields), fi, hi, _section_cuts(ck, o, bodies))
    shock = read_shock(ck, raw, body_regions, kin, end_time)

    if ck.problems:
        raise SceneError(ck.problems)
    return Scene(name, kin, element, end_time, sf, thickness, elimit, integration, hourglass, hg_coef,
                 materials, tuple(bodies),
                 tuple(boundaries), tuple(contacts), damping, outputs, tuple(springs),
                 gravity if any(gravity) else (), bulk_viscosity, shock, tuple(cavities), penetration, curve,
                 checkpoint, ms_step, ms_limit)


def _section_cuts(ck: Checker, o: dict, bodies) -> tuple[SectionCuts, ...]:
    """``outputs.sections = [{body = "bar", count = 21}]``: stress along slender deformable bodies."""
    deformable = [b.name for b in bodies if not b.rigid]
    cuts = []
    for path, c in ck.entries(o, "sections", "outputs.sections", ("body", "count")):
        ck.unknown(c, ("body", "count"), path)
        body = c.get("body")
        if body not in deformable:
            ck.fail(f"{path}.body", f"must name a deformable body (a rigid one has no stress; deformable: "
                                    f"{', '.join(deformable) or 'none'}), got {body!r}")
        count = c.get("count", 21)
        if not isinstance(count, int) or isinstance(count, bool) or not 2 <= count <= 1000:
            ck.fail(f"{path}.count", f"must be a whole number of cuts in [2, 1000], got {count!r}")
            count = 21
        if any(cut.body == body for cut in cuts):
            ck.fail(f"{path}.body", f"{body!r} already has its sections: one entry per body")
        cuts.append(SectionCuts(str(body), count))
    return tuple(cuts)


def to_plain(scene: Scene) -> dict[str, Any]:
    """The resolved scene (SI units) as plain data for ``resolved_scene.json``."""
    d = dataclasses.asdict(scene)
    d["units"] = "SI (m, kg, s, N, Pa, J)"
    return d
