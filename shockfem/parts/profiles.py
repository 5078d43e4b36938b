"""Parts of revolution as (r, z) profiles (pure geometry; ``geometry/outline.py`` draws them with gmsh).

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
