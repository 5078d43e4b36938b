"""The designed machine as a STEP assembly: named solids built with gmsh's OpenCASCADE kernel.

Why gmsh's OpenCASCADE: it is already the project's geometry kernel (every part is drawn and meshed with
it), so the CAD solids of the catalogue's parts (the article's ogive) are the very outlines the solver
meshes, and no second CAD stack (CadQuery or build123d, each a few hundred MB of OCP wheels pinned to
their own numpy) has to be installed.  Its STEP writer does not carry entity names (gmsh 4.15), so each
solid's PRODUCT is named in the written file (``_name_products``), in the order the solids were written;
gmsh reads them back as labels (``Shapes/<assembly>/<k>/<name>``), which the checks use.

Conventions: the solids are built in metres with gmsh's ``Geometry.OCCTargetUnit`` set to "M", so the
file is written in millimetres (it says so: SI_UNIT(.MILLI.,.METRE.)) and read back in metres whatever unit
an earlier import left OpenCASCADE in (it keeps one for the whole process); the machine's axis is z (the
tank at z = 0, the catcher last), y up, x across.  Pressure parts are hollow (their steel only), the
striker's housing is its steel with the oil a solid of its own, the article the catalogue's ogive standing
on its base, each pad of its material's density.  Rails, shoes and stop rings are drawn to show the
arrangement: their sections are not designed (their loads are, in ``machine.json``), so they carry no
designed mass.
"""
from __future__ import annotations

import contextlib
import math
import os
import re
import sys

import gmsh

from ..geometry.outline import draw
from ..launcher.vessel import MATERIALS as VESSEL_MATERIALS
from ..parts.catalog import PARTS, solid_ogive
from ..programmer.dashpot_design import OIL
from ..programmer.housing import HOUSING_STEELS
from ..scene.library import property_si
from .layout import rail_geometry, shoe_length
from .pad_materials import pad_material
from .spec import REFERENCE_ARTICLE



def _cylinder(z0, length, radius, x=0.0, y=0.0):
    return gmsh.model.occ.addCylinder(x, y, z0, 0, 0, length, radius)


def _tube(z0, length, outer, inner):
    o, i = _cylinder(z0, length, outer), _cylinder(z0, length, inner)
    out, _ = gmsh.model.occ.cut([(3, o)], [(3, i)])
    return [t for d, t in out if d == 3]


def _box(x0, y0, z0, dx, dy, dz):
    return gmsh.model.occ.addBox(x0, y0, z0, dx, dy, dz)


def _capsule(z0, length_cyl, r_cyl, r_head):
    """A cylinder of radius r_cyl and length length_cyl from z0 + r_head, with spheres of r_head at its
    ends (hemispherical heads)."""
    occ = gmsh.model.occ
    c = _cylinder(z0 + r_head, length_cyl, r_cyl)
    s1 = occ.addSphere(0, 0, (z0 + r_head), r_head)
    s2 = occ.addSphere(0, 0, (z0 + r_head + length_cyl), r_head)
    out, _ = occ.fuse([(3, c)], [(3, s1), (3, s2)])
    return out


def tank_solid(item, sizing) -> list[int]:
    """The tank (an ``Item``) as its steel: a capsule of the ASME shell and head thicknesses, hollow."""
    t = sizing["tank"]
    R = t["diameter"] / 2
    head = R + t["head_thickness"]
    L_cyl = item.length - 2 * head
    outer = _capsule(item.x0, L_cyl, R + t["shell_thickness"], head)
    inner = _capsule(item.x0 + (head - R), L_cyl, R, R)
    out, _ = gmsh.model.occ.cut(outer, inner)
    return [t for d, t in out if d == 3]


def article_solid(item) -> list[int]:
    """The catalogue's ogive, drawn nose down at its base's place, then turned end over end."""
    R = item.diameter / 2
    dims = solid_ogive(R, REFERENCE_ARTICLE["crh"], REFERENCE_ARTICLE["meplat_over_radius"] * R, item.length)
    volumes, _ = draw(PARTS["projectile"], dims, 3, (0.0, 0.0, item.x0))
    gmsh.model.occ.rotate([(3, v) for v in volumes], 0, 0, (item.x0 + item.length / 2), 1, 0, 0, math.pi)
    return volumes


def housing_solid(item, floor: float) -> list[int]:
    """The striker's housing (an ``Item``): a tube of its bore closed by a floor of thickness ``floor``."""
    steel = _tube(item.x0 + floor, item.length - floor, item.diameter / 2, item.inner / 2)
    fused, _ = gmsh.model.occ.fuse([(3, t) for t in steel], [(3, _cylinder(item.x0, floor, item.diameter / 2))])
    return [t for d, t in fused if d == 3]


def solids(machine) -> list[tuple[str, int, float, str]]:
    """Build every component in the current gmsh model: (name, volume tag, density [kg/m^3] or 0 where
    the design gives it no mass, the layout's component it belongs to)."""
    lay, fixture, launcher = machine.layout, machine.fixture, machine.launcher
    rho = property_si(machine.spec.material, "density", "density")
    out: list[tuple[str, int, float, str]] = []
    for it in lay.items:
        def add(name, tags, density):
            for k, t in enumerate(tags):
                out.append((name if len(tags) == 1 else f"{name}_{k + 1}", t, density, it.name))

        if it.kind == "tank":
            add(it.name, tank_solid(it, launcher.sizing), _density(launcher.sizing["tank"]["material"]))
        elif it.kind == "barrel":
            add(it.name, _tube(it.x0, it.length, it.diameter / 2, it.inner / 2),
                _density(launcher.sizing["barrel"]["material"]))
        elif it.kind == "mass":
            add(it.name, [_cylinder(it.x0, it.length, it.diameter / 2)], rho)
        elif it.kind == "housing":
            add(it.name, housing_solid(it, fixture.floor_thickness), HOUSING_STEELS[fixture.housing_steel].density)
        elif it.kind == "pin":
            add(it.name, [_cylinder(it.x0, it.length, it.diameter / 2)], HOUSING_STEELS[fixture.housing_steel].density)
        elif it.kind == "oil":
            add(it.name, [_cylinder(it.x0, it.length, it.diameter / 2)], OIL["density"])
        elif it.kind == "piston":
            add(it.name, [_cylinder(it.x0, it.length, it.diameter / 2)], rho)
        elif it.kind == "article":
            add(it.name, article_solid(it), property_si(REFERENCE_ARTICLE["library"], "density", "density"))
        elif it.kind == "pad":
            add(it.name, [_cylinder(it.x0, it.length, it.diameter / 2)], pad_material(it.material).density)
        elif it.kind == "stop":
            add(it.name, _tube(it.x0, it.length, it.diameter / 2, it.inner / 2) if it.inner
                else [_cylinder(it.x0, it.length, it.diameter / 2)], 0.0)
        elif it.kind == "rail":
            h, xs, y = rail_geometry(it.diameter)
            for side, x in zip(("left", "right"), xs):
                add(f"{it.name}_{side}", [_box(x, y, it.x0, h, h, it.length)], 0.0)
                add(f"shoe_{it.name.removeprefix('rails_')}_{side}",
                    [_box(x - h / 2, y + h, it.x0, 2 * h, h / 2, shoe_length(it.diameter, it.length))], 0.0)
        elif it.kind == "frame":
            a = math.sqrt(lay.frame_section)
            W = lay.overall_width
            for side, x in (("left", -W / 2 - a), ("right", W / 2)):
                add(f"frame_{side}", [_box(x, -W / 2 - a, it.x0, a, a, it.length)], rho)
    gmsh.model.occ.synchronize()
    return out


def _density(vessel_material: str) -> float:
    return VESSEL_MATERIALS[vessel_material]["density"]


def write_step(machine, path: str, name: str) -> list[dict]:
    """Build the machine and write it as a STEP assembly of named solids; returns each solid's name, the
    component it belongs to, volume [m^3], density and mass [kg] (0 where the design gives none)."""
    with empty_gmsh():
        gmsh.model.add(name)
        parts = solids(machine)
        rows = []
        for solid, tag, density, part in parts:
            volume = gmsh.model.occ.getMass(3, tag)
            rows.append({"name": solid, "part": part, "volume": volume, "density": density, "mass": density * volume})
        order = {tag: solid for solid, tag, _, _ in parts}
        written = [order[t] for _, t in gmsh.model.getEntities(3)]
        with _quiet_stdout():           # OpenCASCADE's STEP writer prints its statistics on fd 1
            gmsh.write(path)
    _name_products(path, name, written)
    return rows


@contextlib.contextmanager
def _quiet_stdout():
    sys.stdout.flush()
    saved = os.dup(1)
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
        try:
            yield
        finally:
            os.dup2(saved, 1)
            os.close(saved)


def _name_products(path: str, assembly: str, names: list[str]):
    """Name the assembly's PRODUCT and each solid's (``<prefix> 1.k`` in the order written)."""
    text = open(path).read()
    products = re.findall(r"PRODUCT\('([^']*)'", text)
    top = products[0]
    mapping = {top: assembly}
    for k, n in enumerate(names, start=1):
        mapping[f"{top}.{k}"] = n
    text = re.sub(r"'(" + re.escape(top) + r"(?:\.\d+)?)'", lambda m: f"'{mapping.get(m.group(1), m.group(1))}'",
                  text)
    with open(path, "w") as fh:
        fh.write(text)


def read_step(path: str) -> list[dict]:
    """A STEP file's solids as gmsh reads them back: label (the last part of gmsh's label path) and volume [m^3]."""
    with empty_gmsh():
        gmsh.model.occ.importShapes(path)
        gmsh.model.occ.synchronize()
        return [{"name": gmsh.model.getEntityName(3, t).split("/")[-1],
                 "volume": gmsh.model.occ.getMass(3, t)} for _, t in gmsh.model.getEntities(3)]


@contextlib.contextmanager
def empty_gmsh():
    """gmsh with no model in it, for as long as the block runs; initialised as the mesher does it (once a
    process, left initialised for the next user), so a machine's solids never mix with a mesh's."""
    if not gmsh.isInitialized():
        gmsh.initialize(interruptible=False)
    gmsh.option.setNumber("General.Terminal", 0)
    unit = gmsh.option.getString("Geometry.OCCTargetUnit")
    gmsh.option.setString("Geometry.OCCTargetUnit", "M")
    gmsh.clear()
    try:
        yield
    finally:
        gmsh.clear()
        gmsh.option.setString("Geometry.OCCTargetUnit", unit)
