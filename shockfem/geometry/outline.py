"""Draw the catalogue's parts with gmsh's OpenCASCADE kernel: their (r, z) outlines
(``parts.profiles``) as plane surfaces (axisymmetric) or revolved solids (3D), then the 3D-only cuts
(the split cone's slots, the dashpot's orifice), with every boundary face named by its region.
"""
from __future__ import annotations

import math

import gmsh
import numpy as np

from ..parts.catalog import Part
from ..parts.profiles import Line, Profile, distance_to_segment


def _add_loop(occ, chain, gdim, points, origin):
    """Add a chain of segments to the OCC model; returns (curve loop tag, [(curve, region)])."""
    def xyz(rz):
        return ((origin[0] + rz[0], origin[1] + rz[1], 0.0) if gdim == 2
                else (origin[0] + rz[0], origin[1], origin[2] + rz[1]))

    def point(rz):
        key = (round(rz[0], 15), round(rz[1], 15))
        if key not in points:
            points[key] = occ.addPoint(*xyz(rz))
        return points[key]

    curves = []
    for seg in chain:
        if isinstance(seg, Line):
            tag = occ.addLine(point(seg.start), point(seg.end))
        else:
            centre = occ.addPoint(*xyz(seg.centre))
            tag = occ.addCircleArc(point(seg.start), centre, point(seg.end))
        curves.append((tag, seg.region))
    return occ.addCurveLoop([t for t, _ in curves]), curves


def draw_profile(profile: Profile, gdim: int, origin=(0.0, 0.0, 0.0)):
    """Add the profile's surface (gdim 2) or its solid of revolution (gdim 3) to the current gmsh
    model, its bottom centre at ``origin`` ((0, z0, 0) in 2D; drawn in place, as OCC cannot
    always move a solid of revolution after the fact).  Returns (entities, {region: [boundary
    entity tags]}) after synchronising; for gdim 3 the regions are found by ``classify_faces``
    (so cuts made later must call it again)."""
    occ = gmsh.model.occ
    points: dict = {}
    outer, curves = _add_loop(occ, profile.outline, gdim, points, origin)
    loops = [outer]
    for hole in profile.holes:
        loop, hole_curves = _add_loop(occ, hole, gdim, points, origin)
        loops.append(loop)
        curves += hole_curves
    surface = occ.addPlaneSurface(loops)
    if gdim == 2:
        occ.synchronize()
        regions: dict[str, list[int]] = {}
        for tag, region in curves:
            if region:
                regions.setdefault(region, []).append(tag)
        return [surface], regions
    out = occ.revolve([(2, surface)], origin[0], origin[1], origin[2], 0.0, 0.0, 1.0, 2.0 * math.pi)
    occ.synchronize()
    volumes = [t for d, t in out if d == 3]
    return volumes, classify_faces(profile, volumes, origin)


def _point_on_face(face: int, origin) -> tuple[float, float]:
    """(r, z) of a point inside a face: the first point of a parametric grid that gmsh finds on the
    face (the middle of the parameter box of a planar annulus is its hole)."""
    lo, hi = (np.asarray(b) for b in gmsh.model.getParametrizationBounds(2, face))
    for fu in (0.5, 0.37, 0.63, 0.21, 0.79, 0.1, 0.9):
        for fv in (0.5, 0.37, 0.63, 0.21, 0.79, 0.1, 0.9):
            uv = lo + np.array([fu, fv]) * (hi - lo)
            if gmsh.model.isInside(2, face, uv, parametric=True):
                x = gmsh.model.getValue(2, face, uv)
                return math.hypot(x[0] - origin[0], x[1] - origin[1]), x[2] - origin[2]
    raise RuntimeError(f"no point found on face {face} to name it")


def classify_faces(profile: Profile, volumes: list[int], origin=(0.0, 0.0, 0.0),
                   tolerance: float | None = None) -> dict[str, list[int]]:
    """Name the boundary faces of a solid of revolution by the profile segment each lies on."""
    segments = [s for s in profile.segments() if s.region and s.region != "axis"]     # the axis makes no face
    scale = max(max(abs(c) for s in profile.segments() for c in s.start + s.end), 1e-12)
    tol = tolerance or 1e-6 * scale
    regions: dict[str, list[int]] = {}
    for _, face in gmsh.model.getBoundary([(3, v) for v in volumes], oriented=False, combined=True):
        r, z = _point_on_face(face, origin)
        d = [distance_to_segment(s, r, z) for s in segments]
        k = int(np.argmin(d)) if d else -1
        name = segments[k].region if k >= 0 and d[k] < tol else profile.cut_region
        regions.setdefault(name, []).append(face)
    return regions


# ------------------------------------------------------------- 3D-only cuts

def _split_cone_slots(d, volumes, origin):
    """Cut ``segments`` axial slots of ``slot_width`` through the wall, the whole length."""
    occ = gmsh.model.occ
    n, w = int(d["segments"]), d["slot_width"]
    if n < 2:
        return volumes
    Ro, L = d["outer_radius"], d["length"]
    tools = []
    for k in range(n):
        box = occ.addBox(origin[0], origin[1] - 0.5 * w, origin[2] - 0.1 * L, 1.5 * Ro, w, 1.2 * L)
        occ.rotate([(3, box)], *origin, 0, 0, 1, 2 * math.pi * k / n)
        tools.append((3, box))
    out, _ = occ.cut([(3, v) for v in volumes], tools)
    occ.synchronize()
    return [t for dim, t in out if dim == 3]


def _dashpot_orifice(d, volumes, origin):
    """Drill the orifice: a round hole at r = cavity_centre_radius from the top face into the cavity."""
    occ = gmsh.model.occ
    ro = d["orifice_radius"]
    if not ro:
        return volumes
    L = d["length"]
    zc = d["cavity_height"] or 0.5 * L
    hole = occ.addCylinder(origin[0] + d["cavity_centre_radius"], origin[1], origin[2] + zc, 0.0, 0.0, 1.1 * L - zc, ro)
    out, _ = occ.cut([(3, v) for v in volumes], [(3, hole)])
    occ.synchronize()
    return [t for dim, t in out if dim == 3]


CUTS_3D = {"slots": _split_cone_slots, "orifice": _dashpot_orifice}


def draw(part: Part, dims: dict, gdim: int, origin=(0.0, 0.0, 0.0)):
    """Draw the part in the current gmsh model, its bottom centre at ``origin``:
    (entities, {region: boundary tags})."""
    profile = part.profile(dims)
    profile.cut_region = part.cut_region
    entities, regions = draw_profile(profile, gdim, origin)
    if gdim == 3 and part.cut_3d is not None:
        entities = CUTS_3D[part.cut_3d](dims, entities, origin)
        regions = classify_faces(profile, entities, origin)
    return entities, regions
