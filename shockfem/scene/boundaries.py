"""The ``[[boundary]]`` tables: fixed, symmetry, prescribed velocity and force conditions on named
regions of the bodies, constant or as a history of (time, value) pairs."""
from __future__ import annotations

from .checker import Checker
from .specs import BC_TYPES, Boundary

BOUNDARY_FIELDS = ("region", "type", "direction", "value", "history")


def read_boundaries(ck: Checker, raw: dict, body_regions: dict, kin: str) -> list[Boundary]:
    """Every ``[[boundary]]`` entry, its region checked against the bodies' regions."""
    gdim = 3 if kin == "3d" else 2
    axes = "xyz"[:gdim] if kin != "axisymmetric" else "rz"
    return [_read_boundary(ck, bc, path, body_regions, axes) for path, bc in ck.entries(raw, "boundary")]


def _read_boundary(ck: Checker, bc: dict, path: str, body_regions: dict, axes: str) -> Boundary:
    """One condition: its region, type, the component it acts on and its history."""
    ck.unknown(bc, BOUNDARY_FIELDS, path)
    region = bc.get("region", "")
    bname, _, rname = str(region).partition(".")
    if bname not in body_regions:
        ck.fail(f"{path}.region", f"must be 'body.region' with a known body, got {region!r}")
    elif rname not in body_regions[bname]:
        ck.fail(f"{path}.region", f"body {bname!r} has regions {', '.join(body_regions[bname])}; "
                                  f"got {rname!r}")
    kind = ck.choice(bc, "type", path, BC_TYPES)
    comps: tuple[int, ...] = tuple(range(len(axes)))
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
    return Boundary(region=region, kind=kind, components=comps, history=history)
