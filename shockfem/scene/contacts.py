"""The [[contacts]] and [[springs]] entries: which surfaces meet, rigid walls and cylinders, penalty
and friction, and discrete springs between bodies."""
from __future__ import annotations

from .checker import Checker
from .specs import Contact, RigidSurface, Spring


PENALTIES = ("segment", "soft")
# how a contact holds its surfaces apart: penalty springs, or (a rigid wall only) a kinematic constraint that
# puts every node that would cross the wall on it (LS-DYNA's *RIGIDWALL_PLANAR), for impacts too fast for a
# penalty to catch
METHODS = ("penalty", "constraint")
# the keys of a penalty contact, which a constraint wall does not use
PENALTY_KEYS = ("penalty", "penalty_scale", "damping", "friction", "friction_dynamic", "friction_decay",
                "interference")
CYLINDER_SIDES = ("outside", "inside")


def surface_spec(ck: Checker, c: dict, key: str, path: str, body_regions: dict) -> str | None:
    """A "body" or "body.region" reference, checked against the scene's bodies."""
    spec = c.get(key)
    if not isinstance(spec, str):
        ck.fail(f"{path}.{key}", "missing ('body' or 'body.region')")
        return None
    bname, _, rname = spec.partition(".")
    if bname not in body_regions:
        ck.fail(f"{path}.{key}", f"unknown body {bname!r} (bodies: {', '.join(body_regions)})")
    elif rname and rname not in body_regions[bname]:
        ck.fail(f"{path}.{key}", f"body {bname!r} has regions {', '.join(body_regions[bname])}, got {rname!r}")
    return spec


def unit_vector(ck: Checker, d: dict, key: str, path: str, gdim: int, default) -> tuple:
    v = ck.vector(d, key, path, "dimensionless", gdim, default)
    norm = sum(x * x for x in v) ** 0.5
    if norm == 0:
        ck.fail(f"{path}.{key}", "must not be zero")
        return tuple(default)
    return tuple(x / norm for x in v)


def _rigid_surface(ck: Checker, c: dict, path: str, kin: str) -> RigidSurface:
    """``wall = {point, normal, velocity}`` or ``cylinder = {point, axis, radius, side, velocity}``."""
    gdim = 3 if kin == "3d" else 2
    zero = [0.0] * gdim
    if "wall" in c:
        p = f"{path}.wall"
        w = ck.table(c, "wall", p)
        ck.unknown(w, ("point", "normal", "velocity"), p)
        point = ck.vector(w, "point", p, "length", gdim, zero)
        normal = unit_vector(ck, w, "normal", p, gdim, zero[:-1] + [1.0])
        vel = ck.vector(w, "velocity", p, "velocity", gdim, zero)
        return RigidSurface("plane", point, normal, vel)
    p = f"{path}.cylinder"
    cyl = ck.table(c, "cylinder", p)
    allowed = ("point", "radius", "side", "velocity") + (("axis",) if gdim == 3 else ())
    ck.unknown(cyl, allowed, p)
    point = ck.vector(cyl, "point", p, "length", gdim, zero)
    radius = ck.quantity(cyl, "radius", p, "length", positive=True)
    side = ck.choice(cyl, "side", p, CYLINDER_SIDES, default="outside")
    vel = ck.vector(cyl, "velocity", p, "velocity", gdim, zero)
    if kin == "3d":
        axis = unit_vector(ck, cyl, "axis", p, 3, [0.0, 0.0, 1.0])
    elif kin == "axisymmetric":
        axis = (0.0, 1.0)                 # coaxial with the bodies
        if point[0] != 0.0 or vel[0] != 0.0:
            ck.fail(p, "an axisymmetric cylinder is coaxial with the bodies: point and velocity need r = 0")
    else:
        axis = (0.0, 0.0)                 # plane strain: the circle about point
    return RigidSurface("cylinder", point, axis, vel, radius, side == "inside")


def read_contacts(ck: Checker, raw: dict, body_regions: dict, kin: str) -> list[Contact]:
    """[[contact]] entries: two surfaces (``a``, ``b``) or a surface and a rigid ``wall`` or ``cylinder``."""
    out = []
    for path, c in ck.entries(raw, "contact"):
        ck.unknown(c, ("name", "a", "b", "wall", "cylinder", "method", "penalty", "penalty_scale", "damping",
                       "friction", "friction_dynamic", "friction_decay", "interference"), path)
        a = surface_spec(ck, c, "a", path, body_regions)
        b = rigid = None
        if sum(k in c for k in ("b", "wall", "cylinder")) != 1:
            ck.fail(path, "give exactly one of b (a second surface), wall (a rigid plane) or cylinder "
                          "(a rigid cylinder)")
        elif "b" in c:
            b = surface_spec(ck, c, "b", path, body_regions)
            if a and b and a.partition(".")[0] == b.partition(".")[0]:
                ck.fail(f"{path}.b", "self-contact of a body is not supported; give two different bodies")
        else:
            rigid = _rigid_surface(ck, c, path, kin)
        penalty = ck.choice(c, "penalty", path, PENALTIES, default="segment")
        scale = ck.quantity(c, "penalty_scale", path, "dimensionless", default=0.1, positive=True)
        zeta = ck.quantity(c, "damping", path, "dimensionless", default=0.1, nonnegative=True, upper=1.0)
        mu_s = ck.quantity(c, "friction", path, "dimensionless", default=0.0, nonnegative=True)
        mu_d = ck.quantity(c, "friction_dynamic", path, "dimensionless", default=mu_s, nonnegative=True)
        if mu_d > mu_s:
            ck.fail(f"{path}.friction_dynamic", f"must not exceed the static coefficient friction = {mu_s:g}")
        decay = ck.quantity(c, "friction_decay", path, "slowness", default=0.0, nonnegative=True)
        interference = ck.quantity(c, "interference", path, "time", default=0.0, nonnegative=True)
        method = ck.choice(c, "method", path, METHODS, default="penalty")
        if method == "constraint":
            if "wall" not in c:
                ck.fail(f"{path}.method", 'a constraint holds nodes on a rigid wall (a plane) only: give wall = '
                                          '{point, normal}, or leave method at "penalty"')
            for key in PENALTY_KEYS:
                if key in c:
                    ck.fail(f"{path}.{key}", 'not used by method = "constraint" (a frictionless wall that puts '
                                             'each node crossing it on it): drop it, or leave method at "penalty"')
        name = c.get("name", f"{a}-{b or (rigid.kind if rigid else '?')}")
        out.append(Contact(str(name), a or "", b, rigid, penalty, scale, zeta, (mu_s, mu_d, decay), interference,
                           method))
    return out


def read_springs(ck: Checker, raw: dict, body_regions: dict, gdim: int) -> list[Spring]:
    """[[spring]] entries: a linear ``stiffness`` or a tabulated ``curve``, and a ``damping``."""
    out = []
    for i, (path, c) in enumerate(ck.entries(raw, "spring")):
        ck.unknown(c, ("name", "a", "b", "direction", "stiffness", "curve", "damping", "compression_only"), path)
        a = surface_spec(ck, c, "a", path, body_regions)
        b = surface_spec(ck, c, "b", path, body_regions)
        if a and b and a.partition(".")[0] == b.partition(".")[0]:
            ck.fail(f"{path}.b", "a spring joins two different bodies")
        direction = unit_vector(ck, c, "direction", path, gdim, [0.0] * (gdim - 1) + [1.0]) \
            if "direction" in c else None
        stiffness = ck.quantity(c, "stiffness", path, "stiffness", default=0.0, nonnegative=True)
        curve: list[tuple[float, float]] = []
        if "curve" in c:
            if "stiffness" in c:
                ck.fail(path, "give stiffness (linear) or curve (tabulated), not both")
            curve = ck.pairs(c, "curve", path, ("extension", "force"), ("length", "force"), minimum=2)
        damping = ck.quantity(c, "damping", path, "damping", default=0.0, nonnegative=True)
        if not stiffness and not curve and not damping:
            ck.fail(path, "needs a stiffness, a curve or a damping")
        only = c.get("compression_only", False)
        if not isinstance(only, bool):
            ck.fail(f"{path}.compression_only", f"must be true or false, got {only!r}")
            only = False
        name = str(c.get("name", f"spring{i}"))
        out.append(Spring(name, a or "", b or "", direction, stiffness, tuple(curve), damping, only))
    return out
