"""Parts of revolution as (r, z) profiles, drawn with gmsh's OpenCASCADE kernel.

Most of a shock machine turns on a lathe: striker, amplifier cylinders, split cone, clamp
ring, dashpot, projectile.  Each such part is a closed outline in the (r, z) half plane
(``Profile``: lines and circular arcs, each naming the region it bounds) with optional
holes (internal cavities).  The same profile gives

* the axisymmetric body: the outline's plane surface, x = r, y = z;
* the 3D body: the outline revolved a full turn about z (x = r, y = 0 before the turn).
  Its faces are named by the profile segment they come from (a point of each face, taken
  back to (r, z), lies on exactly one segment); faces that lie on none (cuts a part makes
  afterwards, such as the split cone's slots) take the part's ``cut_region`` name.

Profiles are built with z = 0 at the part's bottom; ``position`` moves the whole part.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Line:
    start: tuple[float, float]          # (r, z)
    end: tuple[float, float]
    region: str


@dataclass(frozen=True)
class Arc:
    """A circular arc shorter than a half turn from ``start`` to ``end`` about ``centre``."""
    start: tuple[float, float]
    end: tuple[float, float]
    centre: tuple[float, float]
    region: str


@dataclass
class Profile:
    outline: list                       # closed chain of Line/Arc, end of each = start of the next
    holes: list[list] = field(default_factory=list)
    cut_region: str = "cut"

    def segments(self):
        yield from self.outline
        for hole in self.holes:
            yield from hole

    def regions(self) -> list[str]:
        seen = []
        for seg in self.segments():
            if seg.region and seg.region not in seen:
                seen.append(seg.region)
        return seen


def distance_to_segment(seg, r: float, z: float) -> float:
    """Distance from (r, z) to a profile segment."""
    p = np.array([r, z])
    a, b = np.array(seg.start), np.array(seg.end)
    if isinstance(seg, Line):
        ab = b - a
        t = np.clip(np.dot(p - a, ab) / np.dot(ab, ab), 0.0, 1.0)
        return float(np.linalg.norm(p - (a + t * ab)))
    c = np.array(seg.centre)
    radius = np.linalg.norm(a - c)
    # within the arc's angle (the chord separates the arc from the centre side for arcs under
    # a half turn): distance to the circle; otherwise to the nearer end
    chord_side = np.cross(b - a, p - a) * np.cross(b - a, c - a) <= 0.0
    if chord_side or np.linalg.norm(p - c) < 1e-300:
        return float(abs(np.linalg.norm(p - c) - radius))
    return float(min(np.linalg.norm(p - a), np.linalg.norm(p - b)))


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
    import gmsh
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
    import gmsh
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
    import gmsh
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

