"""Verification of the whole machine's geometry and closed forms (``shockfem design-machine``).

``machine_geometry``: the solids of the STEP assembly against the closed forms the design weighs them by,
for the 12 lb machine's sizes.  OpenCASCADE integrates each solid's volume from its faces; the design
computes it by formula, so the two are independent:

* the launcher's tank: a cylinder with hemispherical heads, its steel pi ((R + t)^2 - R^2) L_cyl +
  4/3 pi ((R + t_h)^3 - R^3) at the ASME thicknesses (``launcher.vessel.tank_weight`` over the density);
* the striker's housing: pi ((R^2 - r^2) L_bore + R^2 t_floor);
* the article: the catalogue's ogive, its nose pi * integral of r(z)^2 (``parts.catalog``), turned end
  over end in the assembly.

And the housing's two closed forms at their sizing: Lame's hoop stress at the bore of the wall
``housing_wall`` gives is the allowable, and the clamped plate's edge stress of ``floor_thickness``'s
floor is the allowable (each against its textbook expression written out here).
"""
from __future__ import annotations

import math
import time

import gmsh

from ..launcher.vessel import MATERIALS, tank_diameter_for, tank_weight
from ..machine.cad import article_solid, empty_gmsh, housing_solid, tank_solid
from ..machine.fixture import floor_thickness, housing_wall
from ..machine.layout import Item
from ..parts.catalog import PARTS, solid_ogive, solid_ogive_length
from ..scene.library import property_si
from .checks import check

# the 12 lb machine's sizes (``shockfem design-machine --article "12 lb"``, rounded): the tank at 12.2 MPa
# holding 3.91 m^3, the housing's 79 mm bore in a 97 mm wall 1.47 m deep on a 15 mm floor, the 60 mm ogive
TANK = {"pressure": 12.2e6, "volume": 3.91, "aspect": 3.0, "material": "SA-516-70"}
HOUSING = {"bore_radius": 0.0395, "outer_radius": 0.0485, "depth": 1.47, "floor": 0.015}
ARTICLE = {"radius": 0.030, "mass": 5.443, "crh": 3.0, "meplat_over_radius": 0.2}
# OpenCASCADE's volume integration of these solids agrees with the closed forms to about 1e-10 (measured);
# 1e-6 would still catch a wrong head, a missing floor or a nose drawn at the wrong radius (each >1e-3)
VOLUME_TOL = 1e-6
PRESSURE, ALLOWABLE = 126e6, 460e6       # the 12 lb housing's peak oil pressure and its allowable


def machine_geometry(size: str, workdir: str) -> list[dict]:
    """The STEP assembly's solids against the design's closed-form volumes; the housing's Lame wall and
    clamped floor at their allowable."""
    t0 = time.perf_counter()
    out = []
    with empty_gmsh():
        gmsh.model.add("machine_geometry")
        # the tank
        D = tank_diameter_for(TANK["volume"], TANK["aspect"])
        shell, head, weight = tank_weight(TANK["pressure"], TANK["volume"], D, TANK["material"])
        R = D / 2
        L_cyl = (TANK["volume"] - 4 / 3 * math.pi * R ** 3) / (math.pi * R * R)
        sizing = {"tank": {"diameter": D, "shell_thickness": shell.thickness, "head_thickness": head}}
        tank = Item("tank", "tank", 0.0, L_cyl + 2 * (R + head), D + 2 * shell.thickness, D)
        v = sum(gmsh.model.occ.getMass(3, t) for t in tank_solid(tank, sizing))
        out.append(check("tank steel volume [m^3] (capsule, ASME walls)",
                         weight / MATERIALS[TANK["material"]]["density"], v, VOLUME_TOL, 0.0, 0))
        # the housing
        h = HOUSING
        housing = Item("striker", "housing", 10.0, h["floor"] + h["depth"], 2 * h["outer_radius"],
                       2 * h["bore_radius"])
        v = sum(gmsh.model.occ.getMass(3, t) for t in housing_solid(housing, h["floor"]))
        ref = math.pi * ((h["outer_radius"] ** 2 - h["bore_radius"] ** 2) * h["depth"]
                         + h["outer_radius"] ** 2 * h["floor"])
        out.append(check("housing steel volume [m^3] (wall and floor)", ref, v, VOLUME_TOL, 0.0, 0))
        # the article
        a = ARTICLE
        rho = property_si("steel_4340", "density", "density")
        meplat = a["meplat_over_radius"] * a["radius"]
        L = solid_ogive_length(a["mass"], rho, a["radius"], a["crh"], meplat)
        art = Item("article", "article", 20.0, L, 2 * a["radius"])
        v = sum(gmsh.model.occ.getMass(3, t) for t in article_solid(art))
        ref = PARTS["projectile"].volume(solid_ogive(a["radius"], a["crh"], meplat, L), 3)
        out.append(check("article volume [m^3] (ogive, turned end over end)", ref, v, VOLUME_TOL, 0.0, 0))
    wall = time.perf_counter() - t0
    for c in out:
        c["wall_time_s"] = wall / 3
    # the housing's closed forms at their sizing, against the textbook expressions
    r, p, S = h["bore_radius"], PRESSURE, ALLOWABLE
    Rw = housing_wall(p, r, S)
    out.append(check("Lame hoop stress at the bore of the sized wall [Pa]", S, p * (Rw ** 2 + r ** 2) / (Rw ** 2 - r ** 2),
                     1e-12, 0.0, 0))
    t = floor_thickness(p, r, S)
    out.append(check("clamped floor's edge stress 3 p r^2 / (4 t^2) [Pa] (Roark 11.2 case 10b)", S,
                     3 * p * r * r / (4 * t * t), 1e-12, 0.0, 0))
    return out
