"""Structured meshes of the plain shapes, drawn with gmsh's built-in kernel, one function per shape
(every other part, and these with local refinement, comes from its outline in ``parts.catalog``,
drawn by ``outline.py``).

Each function adds one body to the current gmsh model and returns
``(entities, regions)``: the tags of its top-dimensional entities and, for every named
region of the body (``bottom``, ``top``, ``side``...), the tags of its boundary entities.
Axisymmetric and plane bodies live in the (x, y) = (r, z) plane; 3D bodies have their
axis along z.  Structured (transfinite) meshes are used where the shape allows, so
quads and hexes come out by default.
"""
from __future__ import annotations

import math

import gmsh


def _divisions(length: float, h: float, minimum: int = 1) -> int:
    return max(minimum, int(math.ceil(length / h - 1e-9)))


def _structured_rectangle(x0, y0, w, h_, size, quads, z0=0.0):
    geo = gmsh.model.geo
    p = [geo.addPoint(x0, y0, z0), geo.addPoint(x0 + w, y0, z0),
         geo.addPoint(x0 + w, y0 + h_, z0), geo.addPoint(x0, y0 + h_, z0)]
    lines = [geo.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]   # bottom, right, top, left
    loop = geo.addCurveLoop(lines)
    surf = geo.addPlaneSurface([loop])
    nx, ny = _divisions(w, size), _divisions(h_, size)
    for line, n in zip(lines, (nx, ny, nx, ny)):
        geo.mesh.setTransfiniteCurve(line, n + 1)
    geo.mesh.setTransfiniteSurface(surf)
    if quads:
        geo.mesh.setRecombine(2, surf)
    return surf, lines


def cylinder_2d(dims, position, size, quads):
    """Axisymmetric cylinder: the rectangle 0 <= r <= R, z0 <= z <= z0 + L."""
    R, L = dims["radius"], dims["length"]
    surf, (bottom, side, top, axis) = _structured_rectangle(0.0, position[1], R, L, size, quads)
    return [surf], {"bottom": [bottom], "top": [top], "side": [side], "axis": [axis]}


def box_2d(dims, position, size, quads):
    """Plane rectangle with its lower-left corner at ``position``."""
    surf, (bottom, right, top, left) = _structured_rectangle(position[0], position[1], dims["size_x"],
                                                             dims["size_y"], size, quads)
    return [surf], {"bottom": [bottom], "top": [top], "left": [left], "right": [right]}


def _extrude(surfaces, height, size, hexes):
    """Extrude surfaces along z in structured layers; returns (volumes, tops, sides per surface)."""
    n = _divisions(height, size)
    volumes, tops, laterals = [], [], []
    for s in surfaces:
        out = gmsh.model.geo.extrude([(2, s)], 0, 0, height, numElements=[n], recombine=hexes)
        # out: [top surface, volume, lateral surfaces in the order of the boundary curves]
        tops.append(out[0][1])
        volumes.append(out[1][1])
        laterals.append([e[1] for e in out[2:]])
    return volumes, tops, laterals


def cylinder_3d(dims, position, size, hexes):
    """Solid cylinder, axis z, bottom face centred at ``position``: an O-grid ("butterfly")
    cross-section extruded in layers, so hexahedra are regular across the section."""
    geo = gmsh.model.geo
    R, L = dims["radius"], dims["length"]
    x0, y0, z0 = position
    a = 0.5 * R   # corners of the core square at half the radius
    c = geo.addPoint(x0, y0, z0)
    angles = [math.pi / 4 + k * math.pi / 2 for k in range(4)]
    inner = [geo.addPoint(x0 + a * math.cos(t), y0 + a * math.sin(t), z0) for t in angles]
    outer = [geo.addPoint(x0 + R * math.cos(t), y0 + R * math.sin(t), z0) for t in angles]
    n_c = _divisions(math.pi * R / 2, size, minimum=2)
    n_r = _divisions(R - a, size)
    sq = [geo.addLine(inner[k], inner[(k + 1) % 4]) for k in range(4)]
    arcs = [geo.addCircleArc(outer[k], c, outer[(k + 1) % 4]) for k in range(4)]
    spokes = [geo.addLine(inner[k], outer[k]) for k in range(4)]
    for line in sq + arcs:
        geo.mesh.setTransfiniteCurve(line, n_c + 1)
    for line in spokes:
        geo.mesh.setTransfiniteCurve(line, n_r + 1)
    surfaces = [geo.addPlaneSurface([geo.addCurveLoop(sq)])]
    for k in range(4):
        loop = geo.addCurveLoop([sq[k], spokes[(k + 1) % 4], -arcs[k], -spokes[k]])
        surfaces.append(geo.addPlaneSurface([loop]))
    for s in surfaces:
        geo.mesh.setTransfiniteSurface(s)
        if hexes:
            geo.mesh.setRecombine(2, s)
    volumes, tops, laterals = _extrude(surfaces, L, size, hexes)
    # Lateral surface of sector k from its boundary curve -arcs[k] (third curve of its loop).
    side = [laterals[k + 1][2] for k in range(4)]
    return volumes, {"bottom": surfaces, "top": tops, "side": side}


def box_3d(dims, position, size, hexes):
    """Box with its minimum corner at ``position``, extruded along z in layers."""
    x0, y0, z0 = position
    surf, _ = _structured_rectangle(x0, y0, dims["size_x"], dims["size_y"], size, hexes, z0)
    volumes, tops, laterals = _extrude([surf], dims["size_z"], size, hexes)
    front, right, back, left = laterals[0]     # from the curves bottom(y=y0), right, top(y=y1), left
    return volumes, {"bottom": [surf], "top": tops, "front": [front], "right": [right],
                     "back": [back], "left": [left]}


def sphere_2d(dims, position, size, quads):
    """Axisymmetric sphere: the half disc r >= 0 of radius R with its bottom pole at the body's
    position (the catalogue's definition: centre at z0 = z + R), meshed with unstructured quads graded
    from ``pole_element_size`` at the two poles (where spheres strike) to ``size`` at the equator."""
    geo = gmsh.model.geo
    R = dims["radius"]
    z0 = position[1] + R
    h_pole = dims.get("pole_element_size", size) or size
    south = geo.addPoint(0.0, z0 - R, 0.0, h_pole)
    north = geo.addPoint(0.0, z0 + R, 0.0, h_pole)
    centre = geo.addPoint(0.0, z0, 0.0, size)
    equator = geo.addPoint(R, z0, 0.0, size)
    lower = geo.addCircleArc(south, centre, equator)
    upper = geo.addCircleArc(equator, centre, north)
    axis_top = geo.addLine(north, centre)
    axis_bottom = geo.addLine(centre, south)
    surf = geo.addPlaneSurface([geo.addCurveLoop([lower, upper, axis_top, axis_bottom])])
    if quads:
        geo.mesh.setRecombine(2, surf)
        gmsh.option.setNumber("Mesh.Algorithm", 8)            # frontal-Delaunay for quads
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 2)
    # regions must not overlap (a facet carries one tag): the whole surface is the body itself
    return [surf], {"bottom": [lower], "top": [upper], "axis": [axis_top, axis_bottom]}


BUILDERS = {("cylinder", 2): cylinder_2d, ("box", 2): box_2d, ("sphere", 2): sphere_2d,
            ("cylinder", 3): cylinder_3d, ("box", 3): box_3d}
SHAPED_ENDS = ("bottom_chamfer", "top_chamfer", "bottom_crown", "top_crown")


def structured_builder(body, gdim: int):
    """(builder, dims) of the structured mesh for a plain shape (flat-ended cylinder, plate, box,
    axisymmetric sphere) with no local refinement, or None: the part is then drawn from its
    outline (``parts.catalog``, ``outline.py``), unstructured."""
    d = body.dims
    if body.shape == "box":
        return BUILDERS[("box", gdim)], d
    if body.refine:
        return None
    if body.shape == "cylinder" and not any(d.get(k) for k in SHAPED_ENDS):
        return BUILDERS[("cylinder", gdim)], d
    if body.shape == "plate":
        return BUILDERS[("cylinder", gdim)], {"radius": d["radius"], "length": d["thickness"]}
    if body.shape == "sphere" and gdim == 2:
        return BUILDERS[("sphere", 2)], d
    return None
