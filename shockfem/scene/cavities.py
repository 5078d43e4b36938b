"""The [[cavity]] entries: a liquid-filled cavity of the fluid dashpot, discharging through a fixed
orifice or one whose area follows the stroke (a metering pin), by one of two models:

    model = "control_volume"   the liquid at one pressure between its walls (the default; ``fluid/cavity.py``)
    model = "column"           a compressible column along the bore between exactly two walls, the floor
                               first, then the piston face the orifice passes through
                               (``fluid/column_source.py``); ``cells`` finite volumes (200), ``section``
                               the liquid's section against the distance from the floor (a pin)

and one of two orifice laws (``orifice.law``, either model):

    law = "sharp_edged"        Idelchik's thin sharp-edged orifice with the velocity of approach and the
                               jet's reaction on the piston (the default: the law that holds across the
                               area ratios a metering pin passes through, up to ISO 5167-2's plates)
    law = "fixed_cd"           a fixed discharge coefficient ``discharge``, no velocity of approach, no jet
                               reaction (the textbook law; its range: (Cd a / A)^2 below 5%)
"""
from __future__ import annotations

from .checker import Checker
from .contacts import surface_spec
from .specs import CAVITY_MODELS, ORIFICE_LAWS, Cavity

FIELDS = ("name", "walls", "volume", "liquid", "orifice", "initial_pressure", "model", "cells", "section")
LIQUID_FIELDS = ("density", "bulk_modulus", "tait_exponent", "vapour_pressure", "heat_capacity")
ORIFICE_FIELDS = ("area", "area_curve", "piston_area", "discharge", "law")
# a column's cells: fewer than 10 resolve no wave; more than 100000 would be slower than the bodies
CELLS = (10, 100000)


def read_cavities(ck: Checker, raw: dict, body_regions: dict) -> list[Cavity]:
    out = []
    for i, (path, c) in enumerate(ck.entries(raw, "cavity")):
        ck.unknown(c, FIELDS, path)
        model = ck.choice(c, "model", path, CAVITY_MODELS, default="control_volume")
        column = model == "column"
        specs = _walls(ck, c, path, body_regions, column)
        # no volume: the walls close the cavity and give it (fluid/cavity.py); a column's is its walls'
        volume = ck.quantity(c, "volume", path, "volume", default=0.0, positive="volume" in c)
        rho, K, n, pv, cp = _liquid(ck, c, path)
        law, cd, curve, piston = _orifice(ck, c, path, column)
        p0 = ck.quantity(c, "initial_pressure", path, "pressure", default=0.0, nonnegative=True)
        cells, section = _column_fields(ck, c, path, column)
        out.append(Cavity(str(c.get("name", f"cavity{i}")), tuple(s for s in specs if s), volume, rho, K, n, cd,
                          tuple(curve) or ((0.0, 1.0),), piston, p0, model=model, law=law, cells=cells,
                          vapour_pressure=pv, heat_capacity=cp, section=tuple(section)))
    return out


def _walls(ck: Checker, c: dict, path: str, body_regions: dict, column: bool) -> list:
    walls = c.get("walls")
    if isinstance(walls, str):
        walls = [walls]
    if not isinstance(walls, list) or not walls:
        ck.fail(f"{path}.walls", "must name the surfaces that bound the liquid, e.g. ['piston.bottom']")
        walls = []
    elif column and len(walls) != 2:
        ck.fail(f"{path}.walls", f"a column names exactly two walls, the floor first, then the piston face the "
                                 f"orifice passes through, e.g. ['housing.seat_floor', 'piston.bottom']; got "
                                 f"{len(walls)}")
    return [surface_spec(ck, {"walls": w}, "walls", path, body_regions) for w in walls]


def _liquid(ck: Checker, c: dict, path: str) -> tuple:
    liquid = ck.table(c, "liquid", f"{path}.liquid")
    lp = f"{path}.liquid"
    ck.unknown(liquid, LIQUID_FIELDS, lp)
    rho = ck.quantity(liquid, "density", lp, "density", positive=True)
    K = ck.quantity(liquid, "bulk_modulus", lp, "pressure", positive=True)
    n = ck.quantity(liquid, "tait_exponent", lp, "dimensionless", default=1.0, positive=True)
    # a mineral oil's vapour pressure is ~0 absolute: -0.1 MPa gauge under an atmosphere (fluid/column.py)
    pv = ck.quantity(liquid, "vapour_pressure", lp, "pressure", default=-1.0e5)
    if pv > 0.0:
        ck.fail(f"{lp}.vapour_pressure", f"a gauge pressure at or below 0 (about -0.1 MPa under an atmosphere), "
                                         f"got {liquid['vapour_pressure']!r}")
    cp = ck.quantity(liquid, "heat_capacity", lp, "specific_heat", default=1900.0, positive=True)
    return rho, K, n, pv, cp


def _orifice(ck: Checker, c: dict, path: str, column: bool) -> tuple:
    o = ck.table(c, "orifice", f"{path}.orifice")
    op = f"{path}.orifice"
    ck.unknown(o, ORIFICE_FIELDS, op)
    law = ck.choice(o, "law", op, ORIFICE_LAWS, default="sharp_edged")
    cd = 0.0
    if law == "fixed_cd":
        cd = ck.quantity(o, "discharge", op, "dimensionless", positive=True, upper=1.0)
    elif "discharge" in o:
        ck.fail(f"{op}.discharge", "a fixed discharge coefficient is the fixed_cd law's: add law = \"fixed_cd\", "
                                   "or remove discharge for the sharp-edged law (the default)")
    piston = 0.0
    if ("area" in o) == ("area_curve" in o):
        ck.fail(op, "give area (a fixed orifice) or area_curve (area against stroke, a metering pin)")
        curve = [(0.0, 1.0)]
    elif "area" in o:
        curve = [(0.0, ck.quantity(o, "area", op, "area", nonnegative=True))]     # 0: sealed
    else:
        curve = ck.pairs(o, "area_curve", op, ("stroke", "area"), ("length", "area"))
        if any(a < 0 for _, a in curve):
            ck.fail(f"{op}.area_curve", "areas must be >= 0")
    # a control volume's metering pin needs it (stroke = displaced volume / piston_area); else it is the
    # passage the sharp-edged law's approach velocity is taken in (default: the orifice wall's own area)
    needed = "area_curve" in o and not column
    if needed or "piston_area" in o:
        piston = ck.quantity(o, "piston_area", op, "area", positive=True)
    return law, cd, curve, piston


def _column_fields(ck: Checker, c: dict, path: str, column: bool) -> tuple[int, list]:
    cells, section = 200, []
    for key in ("cells", "section"):
        if key in c and not column:
            ck.fail(f"{path}.{key}", "only a column has it: set model = \"column\" or remove it")
    if not column:
        return cells, section
    low, high = CELLS
    v = c.get("cells", cells)
    if isinstance(v, bool) or not isinstance(v, int) or not low <= v <= high:
        ck.fail(f"{path}.cells", f"must be a whole number of finite volumes in [{low}, {high}], got {v!r}")
    else:
        cells = v
    if "section" in c:
        section = ck.pairs(c, "section", path, ("distance", "area"), ("length", "area"))
        if any(x < 0 for x, _ in section):
            ck.fail(f"{path}.section", "distances from the floor must be >= 0")
        if any(a <= 0 for _, a in section):
            ck.fail(f"{path}.section", "the liquid's sections must be > 0")
    return cells, section
