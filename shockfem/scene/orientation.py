"""A body's orientation: the rotation that turns it, as drawn (its own axis along z), about its
``position``.  In 3D a scene gives it as ``orientation = {axis = [x, y, z], angle = "10 deg"}`` (a
turn by the angle about the axis, right-handed) or ``orientation = {direction = [x, y, z]}`` (the
body's own z axis along the direction, by the smallest turn).  In 2D (axisymmetric, plane strain)
the only turn that keeps a body on the scene's axis is end over end, ``{direction = [0, -1]}``: a
half turn about the radial axis, which takes (r, z) to (r, 2 z_p - z) (a projectile standing on its
base instead of its nose).  The rotation is a 3x3 matrix R, x = p + R (X - p).
"""
from __future__ import annotations

import math

import numpy as np

from .checker import Checker

FIELDS = ("axis", "angle", "direction")


def axis_angle(axis, angle: float) -> np.ndarray:
    """Rodrigues' rotation by ``angle`` [rad] about the unit vector along ``axis``."""
    k = np.asarray(axis, dtype=float)
    k = k / np.linalg.norm(k)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + math.sin(angle) * K + (1.0 - math.cos(angle)) * K @ K


def z_to(direction) -> np.ndarray:
    """The smallest rotation that takes the z axis to the unit vector along ``direction``."""
    d = np.asarray(direction, dtype=float)
    d = d / np.linalg.norm(d)
    axis = np.cross([0.0, 0.0, 1.0], d)
    s = np.linalg.norm(axis)
    if s < 1e-15:
        return np.eye(3) if d[2] > 0 else axis_angle([1.0, 0.0, 0.0], math.pi)
    return axis_angle(axis, math.atan2(s, d[2]))


def turned(orientation: tuple[float, ...] | None, vector) -> tuple[float, ...]:
    """R v for a body's ``orientation`` (9 numbers, row-major; None: v unchanged)."""
    if orientation is None:
        return tuple(float(c) for c in vector)
    return tuple(float(c) for c in np.reshape(orientation, (3, 3)) @ np.asarray(vector, dtype=float))


def read_orientation(ck: Checker, b: dict, path: str, gdim: int) -> tuple[float, ...] | None:
    """The body's rotation R as 9 numbers (row-major), or None when it keeps the drawn orientation."""
    if "orientation" not in b:
        return None
    at = f"{path}.orientation"
    o = b["orientation"]
    if gdim != 3:
        return _end_over_end(ck, o, at)
    if not isinstance(o, dict):
        ck.fail(at, "must be a table: {axis = [x, y, z], angle = \"10 deg\"} or {direction = [x, y, z]}")
        return None
    ck.unknown(o, FIELDS, at)
    if "direction" in o and ("axis" in o or "angle" in o):
        ck.fail(at, "give either direction, or axis with angle, not both")
        return None
    if "direction" in o:
        d = ck.vector(o, "direction", at, "dimensionless", 3, (0.0, 0.0, 1.0))
        if np.linalg.norm(d) == 0.0:
            ck.fail(f"{at}.direction", "must not be the zero vector")
            return None
        return tuple(z_to(d).ravel())
    axis = ck.vector(o, "axis", at, "dimensionless", 3, (0.0, 0.0, 0.0))
    angle = ck.quantity(o, "angle", at, "angle")
    if np.linalg.norm(axis) == 0.0:
        ck.fail(f"{at}.axis", "missing or the zero vector: give the axis to turn about, e.g. [1, 0, 0]")
        return None
    return tuple(axis_angle(axis, angle).ravel())


def _end_over_end(ck: Checker, o, at: str) -> tuple[float, ...] | None:
    """A 2D body's orientation: as drawn ({direction = [0, 1]}) or end over end ({direction = [0, -1]},
    the half turn about the radial axis); any other turn would take it off the scene's axis."""
    words = ("in 2D a body keeps its axis and can only be turned end over end: orientation = {direction = "
             "[0, -1]} (any other turn needs kinematics = '3d')")
    if not isinstance(o, dict) or set(o) != {"direction"}:
        ck.fail(at, words)
        return None
    d = ck.vector(o, "direction", at, "dimensionless", 2, (0.0, 1.0))
    if d[0] != 0.0 or d[1] == 0.0:
        ck.fail(f"{at}.direction", words + f", got {list(d)}")
        return None
    return None if d[1] > 0 else tuple(axis_angle([1.0, 0.0, 0.0], math.pi).ravel())
