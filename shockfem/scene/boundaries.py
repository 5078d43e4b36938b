"""The ``[[boundary]]`` tables: fixed, symmetry, prescribed velocity and force conditions on named
regions of the bodies, constant or as a history of (time, value) pairs; and the drive of a rigid body.

A rigid body's nodes move with it, so a condition that holds them cannot sit on a region of it: a
``velocity`` or ``fixed`` condition names the rigid body itself (``region = "punch"``) and prescribes
the velocity of its centre of mass along ``direction`` (the other directions, and a 3D body's turn, stay
free), or holds it still (``fixed``: every direction, and its turn in 3D).  LS-DYNA's
``*BOUNDARY_PRESCRIBED_MOTION_RIGID``."""
from __future__ import annotations

from .checker import Checker
from .specs import BC_TYPES, Boundary

BOUNDARY_FIELDS = ("region", "type", "direction", "value", "history")
# what a condition naming a whole rigid body may be (the others need a region of a deformable body)
RIGID_BODY_TYPES = ("velocity", "fixed")


def read_boundaries(ck: Checker, raw: dict, body_regions: dict, kin: str, rigid: frozenset = frozenset()
                    ) -> list[Boundary]:
    """Every ``[[boundary]]`` entry, its region checked against the bodies' regions; ``rigid``: the names
    of the rigid bodies (driven whole, never by a region)."""
    gdim = 3 if kin == "3d" else 2
    axes = "xyz"[:gdim] if kin != "axisymmetric" else "rz"
    return [_read_boundary(ck, bc, path, body_regions, axes, rigid) for path, bc in ck.entries(raw, "boundary")]


def _check_region(ck: Checker, region, kind: str, path: str, body_regions: dict, rigid: frozenset):
    """A deformable body's ``body.region``, or a rigid body's own name for a drive (module docstring)."""
    bname, dot, rname = str(region).partition(".")
    if bname not in body_regions:
        ck.fail(f"{path}.region", f"must be 'body.region' with a known body (or a rigid body's name, to drive "
                                  f"it), got {region!r}")
    elif bname in rigid and kind != "force":
        if dot:
            ck.fail(f"{path}.region", f"{bname!r} is a rigid body: its nodes move with it, so a {kind} condition "
                                      f"cannot hold a region of it; give region = {bname!r} to drive (velocity) "
                                      f"or hold (fixed) the whole body")
        elif kind not in RIGID_BODY_TYPES:
            ck.fail(f"{path}.type", f"a rigid body ({bname!r}) is driven with type = \"velocity\" or held with "
                                    f"\"fixed\", got {kind!r}")
    elif not dot and bname in rigid:
        ck.fail(f"{path}.region", f"a force acts on a region of the rigid body {bname!r}: give "
                                  f"'{bname}.<region>' (it has {', '.join(body_regions[bname])})")
    elif not dot:
        ck.fail(f"{path}.region", f"{bname!r} is a deformable body: give one of its regions, "
                                  f"'{bname}.<region>' (it has {', '.join(body_regions[bname])}); only a rigid "
                                  f"body is driven whole")
    elif rname not in body_regions[bname]:
        ck.fail(f"{path}.region", f"body {bname!r} has regions {', '.join(body_regions[bname])}; "
                                  f"got {rname!r}")


def _read_boundary(ck: Checker, bc: dict, path: str, body_regions: dict, axes: str, rigid: frozenset) -> Boundary:
    """One condition: its region, type, the component it acts on and its history."""
    ck.unknown(bc, BOUNDARY_FIELDS, path)
    region = bc.get("region", "")
    kind = ck.choice(bc, "type", path, BC_TYPES)
    _check_region(ck, region, kind, path, body_regions, rigid)
    comps: tuple[int, ...] = tuple(range(len(axes)))
    history: tuple = ((0.0, 0.0),)
    if kind in ("velocity", "force"):
        d = bc.get("direction", axes[-1])
        if not isinstance(d, str) or d not in tuple(axes):        # ("rz" and "" are in the string "rz")
            ck.fail(f"{path}.direction", f"must be one of {', '.join(axes)}, got {d!r}")
            d = axes[-1]
        elif d == "r" and str(region) in rigid:
            ck.fail(f"{path}.direction", "an axisymmetric rigid body moves along z only (its radial forces "
                                         "cancel): drive it along z")
        comps = (axes.index(d),)
        dim = "velocity" if kind == "velocity" else "force"
        if "history" in bc:
            history = tuple(ck.pairs(bc, "history", path, ("time", "value"), ("time", dim))) or history
        else:
            history = ((0.0, ck.quantity(bc, "value", path, dim)),)
    return Boundary(region=region, kind=kind, components=comps, history=history)
