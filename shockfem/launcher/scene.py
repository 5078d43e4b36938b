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
    gas_inertia = "lagrange"         # none | lagrange | simple-wave
    barrel_material = "SA-106-B"     # ASME sizing of the barrel and the tank
    tank_material = "SA-516-70"
    tank_diameter = "24 in"
    joint_efficiency = 1.0
"""
from __future__ import annotations

import math

from ..scene import SceneError
from ..units import UnitError, to_si
from .gas import GASES
from .gun import AIR_AHEAD, GAS_INERTIA, Gun
from .vessel import MATERIALS

QUANTITIES = {   # field: (dimension, default or None for required, must be > 0)
    "projectile_mass": ("mass", None, True), "bore": ("length", None, True), "length": ("length", None, True),
    "reservoir_pressure": ("pressure", None, True), "reservoir_volume": ("length**3", None, True),
    "reservoir_temperature": ("temperature", 293.15, True), "valve_diameter": ("length", 0.0, False),
    "discharge_coefficient": ("dimensionless", 0.8, True), "opening_time": ("time", 0.0, False),
    "dead_volume": ("length**3", -1.0, False), "ambient_pressure": ("pressure", 101325.0, True),
    "ambient_temperature": ("temperature", 293.15, True), "bore_friction": ("force", 0.0, False),
    "seal_drag": ("dimensionless", 0.0, False), "tank_diameter": ("length", 0.0, False),
    "joint_efficiency": ("dimensionless", 1.0, True),
}
CHOICES = {"gas": tuple(GASES), "air_ahead": AIR_AHEAD, "gas_inertia": GAS_INERTIA,
           "barrel_material": tuple(MATERIALS), "tank_material": tuple(MATERIALS)}
DEFAULTS = {"gas": "air", "air_ahead": "atmosphere", "gas_inertia": "lagrange", "barrel_material": "SA-106-B",
            "tank_material": "SA-516-70"}


def _si(value, dimension: str) -> float:
    from ..units import registry
    if dimension in ("length**3", "temperature"):
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value)
        q = registry().Quantity(str(value))
        unit = {"length**3": "m**3", "temperature": "K"}[dimension]
        try:
            return float(q.to(unit).magnitude)
        except Exception:
            raise UnitError(f"expected a {'volume' if dimension == 'length**3' else 'temperature'} "
                            f"(like '{'20 ft**3' if dimension == 'length**3' else '293 K'}'), got {value!r}") from None
    return to_si(value, dimension)


def resolve_launcher(raw: dict) -> tuple[str, Gun, dict]:
    """(name, gun, sizing options) from a raw scene with a [launcher] table; every problem listed."""
    problems = []
    d = raw.get("launcher")
    if not isinstance(d, dict):
        raise SceneError(["launcher: missing table [launcher]"])
    allowed = set(QUANTITIES) | set(CHOICES) | {"name", "real_gas"}
    for k in d:
        if k not in allowed:
            problems.append(f"launcher.{k}: unknown field (allowed: {', '.join(sorted(allowed))})")
    v = {}
    for k, (dim, default, positive) in QUANTITIES.items():
        if k not in d:
            if default is None:
                problems.append(f"launcher.{k}: missing")
            v[k] = default if default is not None else 1.0
            continue
        try:
            v[k] = _si(d[k], dim)
        except Exception as e:          # pint raises several kinds for an unreadable value
            problems.append(f"launcher.{k}: {e}")
            v[k] = 1.0
            continue
        if positive and not v[k] > 0:
            problems.append(f"launcher.{k}: must be > 0, got {d[k]}")
        if not positive and v[k] < 0:
            problems.append(f"launcher.{k}: must be >= 0, got {d[k]}")
    c = {}
    for k, choices in CHOICES.items():
        c[k] = d.get(k, DEFAULTS[k])
        if c[k] not in choices:
            problems.append(f"launcher.{k}: must be one of {', '.join(choices)}; got {c[k]!r}")
            c[k] = DEFAULTS[k]
    if v["valve_diameter"] and v["bore"] > 0 and v["valve_diameter"] > 2 * v["bore"]:
        problems.append("launcher.valve_diameter: larger than twice the bore; is it the tank's?")
    if problems:
        raise SceneError(problems)
    valve = math.pi * v["valve_diameter"] ** 2 / 4 if v["valve_diameter"] else None
    gun = Gun(v["reservoir_volume"], v["reservoir_pressure"], v["bore"], v["length"], v["projectile_mass"],
              v["reservoir_temperature"], c["gas"], bool(d.get("real_gas", False)), valve,
              v["discharge_coefficient"], v["opening_time"], None if v["dead_volume"] < 0 else v["dead_volume"],
              c["air_ahead"], v["ambient_pressure"], v["ambient_temperature"], v["bore_friction"], v["seal_drag"],
              c["gas_inertia"])
    sizing = {"barrel_material": c["barrel_material"], "tank_material": c["tank_material"],
              "tank_diameter": v["tank_diameter"] or (v["reservoir_volume"] * 4 / math.pi) ** (1 / 3) / 1.5,
              "joint_efficiency": v["joint_efficiency"]}
    return str(d.get("name", "launcher")), gun, sizing
