"""The [[cavity]] entries: a liquid-filled cavity of the fluid dashpot, discharging through a fixed
orifice or one whose area follows the stroke (a metering pin)."""
from __future__ import annotations

from .checker import Checker
from .contacts import surface_spec
from .specs import Cavity

FIELDS = ("name", "walls", "volume", "liquid", "orifice", "initial_pressure")
LIQUID_FIELDS = ("density", "bulk_modulus", "tait_exponent")
ORIFICE_FIELDS = ("area", "area_curve", "piston_area", "discharge")


def read_cavities(ck: Checker, raw: dict, body_regions: dict) -> list[Cavity]:
    out = []
    for i, (path, c) in enumerate(ck.entries(raw, "cavity")):
        ck.unknown(c, FIELDS, path)
        walls = c.get("walls")
        if isinstance(walls, str):
            walls = [walls]
        if not isinstance(walls, list) or not walls:
            ck.fail(f"{path}.walls", "must name the surfaces that bound the liquid, e.g. ['piston.bottom']")
            walls = []
        specs = [surface_spec(ck, {"walls": w}, "walls", path, body_regions) for w in walls]
        # no volume: the walls close the cavity and give it (fluid/cavity.py)
        volume = ck.quantity(c, "volume", path, "volume", default=0.0, positive="volume" in c)
        liquid = ck.table(c, "liquid", f"{path}.liquid")
        lp = f"{path}.liquid"
        ck.unknown(liquid, LIQUID_FIELDS, lp)
        rho = ck.quantity(liquid, "density", lp, "density", positive=True)
        K = ck.quantity(liquid, "bulk_modulus", lp, "pressure", positive=True)
        n = ck.quantity(liquid, "tait_exponent", lp, "dimensionless", default=1.0, positive=True)
        o = ck.table(c, "orifice", f"{path}.orifice")
        op = f"{path}.orifice"
        ck.unknown(o, ORIFICE_FIELDS, op)
        cd = ck.quantity(o, "discharge", op, "dimensionless", default=0.7, positive=True, upper=1.0)
        piston = 0.0
        if ("area" in o) == ("area_curve" in o):
            ck.fail(op, "give area (a fixed orifice) or area_curve (area against stroke, a metering pin)")
            curve = [(0.0, 1.0)]
        elif "area" in o:
            curve = [(0.0, ck.quantity(o, "area", op, "area", nonnegative=True))]     # 0: sealed
            if "piston_area" in o:
                ck.fail(f"{op}.piston_area", "only a metering pin (area_curve) needs it; remove it")
        else:
            curve = ck.pairs(o, "area_curve", op, ("stroke", "area"), ("length", "area"))
            if any(a < 0 for _, a in curve):
                ck.fail(f"{op}.area_curve", "areas must be >= 0")
            piston = ck.quantity(o, "piston_area", op, "area", positive=True)
        p0 = ck.quantity(c, "initial_pressure", path, "pressure", default=0.0, nonnegative=True)
        out.append(Cavity(str(c.get("name", f"cavity{i}")), tuple(s for s in specs if s), volume, rho, K, n, cd,
                          tuple(curve) or ((0.0, 1.0),), piston, p0))
    return out
