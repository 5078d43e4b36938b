"""A launcher scene: a TOML ``[launcher]`` table with units, checked completely.

    [launcher]
    name = "white_paper_gun"
    projectile_mass = "2082 lb"
    bore = "12 in"
    length = "6 ft"
    reservoir_pressure = "2000 psi"
    reservoir_volume = "20 ft^3"
    valve_diameter = "8 in"          # or no valve (the reservoir opens on the bore)
    discharge_coefficient = 0.8
    opening_time = "2 ms"
    gas = "air"                      # or nitrogen; real_gas = true for the Noble-Abel covolume
    air_ahead = "atmosphere"         # or evacuated
    bore_friction = "500 lbf"
    seal_drag = 0.01
    gas_inertia = "lagrange"         # none | lagrange | simple-wave | chambered
    barrel_material = "SA-106-B"     # ASME sizing of the barrel and the tank
    tank_material = "SA-516-70"
    tank_diameter = "24 in"          # or tank_aspect = 3 (overall length / diameter)
    joint_efficiency = 1.0

    [design]                         # optional: shockfem launcher --lightest finds the lightest gun
    muzzle_velocity = "325 ft/s"     # required of the projectile
    max_length = "6 ft"              # limits of the design variables (max_* required)
    max_bore = "12 in"
    max_pressure = "2000 psi"
    min_bore = "10 in"               # e.g. the payload's diameter (default 1 in)
    max_acceleration = "2000 gee"    # of the payload (default: none)

The scene's gun is the design's first start point; its valve keeps its diameter over bore.
"""
from __future__ import annotations

import math

from ..scene.checker import Checker, SceneError
from .design import Limits, Sizing
from .gas import GASES
from .gun import AIR_AHEAD, GAS_INERTIA, Gun
from .vessel import MATERIALS, max_pressure

QUANTITIES = {   # field: (dimension, default or None for required, must be > 0)
    "projectile_mass": ("mass", None, True), "bore": ("length", None, True), "length": ("length", None, True),
    "reservoir_pressure": ("pressure", None, True), "reservoir_volume": ("volume", None, True),
    "reservoir_temperature": ("temperature", 293.15, True), "valve_diameter": ("length", 0.0, False),
    "discharge_coefficient": ("dimensionless", 0.8, True), "opening_time": ("time", 0.0, False),
    "dead_volume": ("volume", -1.0, False), "ambient_pressure": ("pressure", 101325.0, True),
    "ambient_temperature": ("temperature", 293.15, True), "bore_friction": ("force", 0.0, False),
    "seal_drag": ("dimensionless", 0.0, False), "tank_diameter": ("length", 0.0, False),
    "tank_aspect": ("dimensionless", 3.0, True), "joint_efficiency": ("dimensionless", 1.0, True),
}
DESIGN_QUANTITIES = {
    "muzzle_velocity": ("velocity", None, True), "max_length": ("length", None, True),
    "max_bore": ("length", None, True), "max_pressure": ("pressure", None, True),
    "min_bore": ("length", Limits.min_bore, True), "min_length": ("length", Limits.min_length, True),
    "min_pressure": ("pressure", Limits.min_pressure, True), "min_volume": ("volume", Limits.min_volume, True),
    "max_volume": ("volume", Limits.max_volume, True), "max_acceleration": ("acceleration", 0.0, False),
}
CHOICES = {"gas": tuple(GASES), "air_ahead": AIR_AHEAD, "gas_inertia": GAS_INERTIA,
           "barrel_material": tuple(MATERIALS), "tank_material": tuple(MATERIALS)}
DEFAULTS = {"gas": "air", "air_ahead": "atmosphere", "gas_inertia": "lagrange", "barrel_material": "SA-106-B",
            "tank_material": "SA-516-70"}


def resolve_launcher(raw: dict, projectile_mass: float | None = None) -> tuple[str, Gun, Sizing]:
    """(name, gun, sizing) from a raw scene with a [launcher] table; every problem listed.
    ``projectile_mass`` [kg] is the mass a chain gives the gun: the table may then omit it."""
    ck = Checker()
    d = raw.get("launcher")
    if not isinstance(d, dict):
        raise SceneError(["launcher: missing table [launcher]"])
    ck.unknown(d, set(QUANTITIES) | set(CHOICES) | {"name", "real_gas"}, "launcher")
    v = ck.quantities(d, "launcher", QUANTITIES, optional=("projectile_mass",) if projectile_mass else ())
    if projectile_mass:
        if "projectile_mass" in d and abs(v["projectile_mass"] / projectile_mass - 1) > 1e-3:
            ck.fail("launcher.projectile_mass", f"the chain launches {projectile_mass:.6g} kg, got "
                                                f"{d['projectile_mass']}; remove it (the chain sets it)")
        v["projectile_mass"] = projectile_mass
    c = {k: ck.choice(d, k, "launcher", choices, DEFAULTS[k]) for k, choices in CHOICES.items()}
    if v["valve_diameter"] and v["bore"] > 0 and v["valve_diameter"] > 2 * v["bore"]:
        ck.fail("launcher.valve_diameter", f"larger than twice the bore (is it the tank's?), got {d['valve_diameter']}")
    ck.done()
    valve = math.pi * v["valve_diameter"] ** 2 / 4 if v["valve_diameter"] else None
    gun = Gun(v["reservoir_volume"], v["reservoir_pressure"], v["bore"], v["length"], v["projectile_mass"],
              v["reservoir_temperature"], c["gas"], bool(d.get("real_gas", False)), valve,
              v["discharge_coefficient"], v["opening_time"], None if v["dead_volume"] < 0 else v["dead_volume"],
              c["air_ahead"], v["ambient_pressure"], v["ambient_temperature"], v["bore_friction"], v["seal_drag"],
              c["gas_inertia"])
    sizing = Sizing(c["barrel_material"], c["tank_material"], v["joint_efficiency"], v["tank_aspect"],
                    v["tank_diameter"] or None)
    return str(d.get("name", "launcher")), gun, sizing


def resolve_design(raw: dict) -> tuple[float, Limits]:
    """(required muzzle velocity, limits) from a launcher scene's [design] table."""
    d = raw.get("design")
    if not isinstance(d, dict):
        raise SceneError(["design: missing table [design] (muzzle_velocity, max_length, max_bore, max_pressure)"])
    ck = Checker()
    ck.unknown(d, DESIGN_QUANTITIES, "design")
    v = ck.quantities(d, "design", DESIGN_QUANTITIES)
    limits = Limits(v["max_length"], v["max_bore"], v["max_pressure"], v["min_bore"], v["min_length"],
                    v["min_pressure"], v["min_volume"], v["max_volume"], v["max_acceleration"] or None)
    ck.problems += [f"design.{problem}" for problem in limits.check()]
    _, _, sizing = resolve_launcher(raw)
    for part in ("barrel", "tank"):
        material = getattr(sizing, f"{part}_material")
        ceiling = max_pressure(material, sizing.joint_efficiency)
        if limits.max_pressure > ceiling:
            ck.fail("design.max_pressure", f"above the {ceiling / 1e6:.4g} MPa an {material} {part} can hold by "
                                           f"ASME VIII-1 (S E, and 0.665 S E for its heads), got {d['max_pressure']}; "
                                           f"lower it or choose a stronger {part}_material")
    ck.done()
    return v["muzzle_velocity"], limits
