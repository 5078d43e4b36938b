"""The [penetration] table: a concrete target that the projectile's nose enters (``target/``).

    [penetration]
    nose = "penetrator.nose"                           # the wetted surface
    face = { point = [0, 0], normal = [0, 1] }         # the target's face, normal out of the target
    compressive_strength = "35 MPa"                    # f'c
    density = "2300 kg/m^3"
    strength_factor = 9.0                              # S; default Forrestal's fit of f'c
    crater_depth = "54 mm"                             # default two calibres (Forrestal's 4a)
    carries = ["payload"]                              # bodies riding in the projectile
    friction = 0.4                                     # the spin-down torque mu F a / 2 (3D)
    tunnel = true                                      # a rigid tunnel behind the nose
    tunnel_radius = "13.45 mm"                         # default the nose body's radius

The tunnel becomes a contact of its own (``penetration.tunnel``): the nose body's surface inside a rigid
cylinder that begins at the face and runs along the projectile's initial velocity (axisymmetric: along
the axis), so that the penetrated length cannot move sideways (tail slap).
"""
from __future__ import annotations

from .checker import Checker
from .contacts import surface_spec, unit_vector
from .specs import Body, Contact, Penetration, RigidSurface

FIELDS = ("nose", "face", "compressive_strength", "density", "strength_factor", "crater_depth", "carries",
          "friction", "tunnel", "tunnel_radius", "tunnel_penalty_scale")
TUNNEL_NAME = "penetration.tunnel"


def read_penetration(ck: Checker, raw: dict, body_regions: dict, bodies: list[Body],
                     kin: str) -> tuple[Penetration | None, Contact | None]:
    """The target and its tunnel contact, or (None, None) without a [penetration] table."""
    if "penetration" not in raw:
        return None, None
    path = "penetration"
    p = ck.table(raw, "penetration", path)
    ck.unknown(p, FIELDS, path)
    gdim = 3 if kin == "3d" else 2
    if kin == "plane-strain":
        ck.fail(path, "a penetrating nose needs kinematics = 'axisymmetric' (no yaw) or '3d'")
    nose = surface_spec(ck, p, "nose", path, body_regions) or ""
    body_name = nose.partition(".")[0]
    body = next((b for b in bodies if b.name == body_name), None)
    fp = f"{path}.face"
    face = ck.table(p, "face", fp)
    ck.unknown(face, ("point", "normal"), fp)
    zero = [0.0] * gdim
    point = ck.vector(face, "point", fp, "length", gdim, zero)
    normal = unit_vector(ck, face, "normal", fp, gdim, zero[:-1] + [1.0])
    if kin == "axisymmetric" and (point[0] != 0.0 or normal[0] != 0.0):
        ck.fail(fp, "an axisymmetric target's face is square to the axis: point and normal need r = 0")
    fc = ck.quantity(p, "compressive_strength", path, "pressure", positive=True)
    rho = ck.quantity(p, "density", path, "density", positive=True)
    S = ck.quantity(p, "strength_factor", path, "dimensionless", default=0.0, positive="strength_factor" in p)
    crater = ck.quantity(p, "crater_depth", path, "length", default=-1.0, nonnegative="crater_depth" in p)
    carries = p.get("carries", [])
    if not isinstance(carries, list) or any(not isinstance(c, str) or c not in body_regions or c == body_name
                                            for c in carries):
        ck.fail(f"{path}.carries", f"must list other bodies that ride in the projectile (bodies: "
                                   f"{', '.join(body_regions)}), got {carries!r}")
        carries = []
    mu = ck.quantity(p, "friction", path, "dimensionless", default=0.0, nonnegative=True)
    tunnel = p.get("tunnel", True)
    if not isinstance(tunnel, bool):
        ck.fail(f"{path}.tunnel", f"must be true or false, got {tunnel!r}")
        tunnel = False
    contact = None
    if tunnel:
        default = body.dims.get("radius") if body is not None else None
        radius = ck.quantity(p, "tunnel_radius", path, "length", default=default, positive=True)
        if radius is None:
            radius = 1.0      # the problem is recorded: the body has no radius to take
        scale = ck.quantity(p, "tunnel_penalty_scale", path, "dimensionless", default=0.1, positive=True)
        axis = _tunnel_axis(body, normal, kin)
        contact = Contact(TUNNEL_NAME, body_name, None, RigidSurface("tunnel", point, axis, tuple(zero), radius, True),
                          "segment", scale, 0.1)
    elif "tunnel_radius" in p or "tunnel_penalty_scale" in p:
        ck.fail(path, "tunnel_radius and tunnel_penalty_scale belong to a tunnel: remove them or set tunnel = true")
    spec = Penetration(nose, point, normal, fc, rho, S, crater, tuple(carries), mu, TUNNEL_NAME if tunnel else "")
    return spec, contact


def _tunnel_axis(body: Body | None, normal: tuple, kin: str) -> tuple:
    """Into the target: along the projectile's initial velocity (its path), square to the face if it has
    none; axisymmetric: the axis itself."""
    inward = tuple(0.0 - n for n in normal)
    if body is None or kin == "axisymmetric":
        return inward
    speed = sum(v * v for v in body.velocity) ** 0.5
    return tuple(v / speed for v in body.velocity) if speed > 0 else inward
