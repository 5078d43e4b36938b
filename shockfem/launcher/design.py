"""The lightest gas gun that gives a payload a required muzzle velocity.

Design variables: bore, barrel length, reservoir pressure and reservoir volume.  Everything
else (gas, valve as a fraction of the bore, opening time, losses, materials, tank proportions)
comes from a template ``Gun`` and ``Sizing`` options, so the design uses the same lumped model
and the same ASME rules as a single shot.

Weight = barrel + tank (``vessel.py``, at the reservoir pressure).  With thin walls a tank's
weight goes as p V, as does the energy it stores, so pressure alone buys little: what the
optimiser trades is how much of the stored energy reaches the payload (expansion ratio, valve
flow, gas inertia) against the barrel's weight.

The problem is solved by SLSQP on the logarithms of the four variables, with the muzzle
velocity (and optionally the payload's peak acceleration) as inequality constraints evaluated
by ``fire``; finite-difference steps are far above the integrator's tolerance.  Several
starts are tried and the lightest feasible design kept.  A variable within 0.1% of a limit is
reported as binding, with the weight saved by relaxing that limit by 10%.
"""
from __future__ import annotations

import dataclasses
import math
import time
import warnings
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from scipy.optimize import minimize

from .gun import Gun, barrel_length_for, fire
from .vessel import barrel_weight, tank_diameter_for, tank_weight

VARIABLES = ("bore", "length", "reservoir_pressure", "reservoir_volume")
# relative tolerance on the muzzle-velocity constraint of the returned design
VELOCITY_TOL = 1e-4
# finite-difference step in the log of each variable (the shot is integrated to rtol 1e-9)
FD_STEP = 1e-4
RELAX = 1.10
# relative change of the weight at which SLSQP stops
FTOL = 1e-6


@dataclass(frozen=True)
class Sizing:
    """How the pressure parts are built (``output.sizing`` takes the same fields)."""
    barrel_material: str = "SA-106-B"
    tank_material: str = "SA-516-70"
    joint_efficiency: float = 1.0
    tank_aspect: float = 3.0          # tank overall length / diameter (hemispherical heads)
    tank_diameter: float | None = None  # fixed inside diameter; None: from the volume and aspect

    def tank_diameter_of(self, volume: float) -> float:
        return self.tank_diameter or tank_diameter_for(volume, self.tank_aspect)


@dataclass(frozen=True)
class Limits:
    """Bounds of the design variables [SI]; ``min_bore`` is the payload's diameter if it must fit."""
    max_length: float
    max_bore: float
    max_pressure: float
    min_bore: float = 0.0254
    min_length: float = 0.1
    min_pressure: float = 0.5e6
    min_volume: float = 1e-4
    max_volume: float = 100.0
    max_acceleration: float | None = None   # of the payload [m/s^2]

    def bounds(self) -> list[tuple[float, float]]:
        return [(self.min_bore, self.max_bore), (self.min_length, self.max_length),
                (self.min_pressure, self.max_pressure), (self.min_volume, self.max_volume)]

    def check(self) -> list[str]:
        problems = []
        for name, (lo, hi) in zip(VARIABLES, self.bounds()):
            if not 0 < lo <= hi:
                problems.append(f"{name}: the limits must satisfy 0 < min <= max, got {lo:.4g} .. {hi:.4g}")
        return problems


@dataclass
class LauncherDesign:
    gun: Gun
    weight: float                 # barrel + tank [kg]
    barrel_weight: float
    tank_weight: float
    muzzle_velocity: float
    required_velocity: float
    peak_acceleration: float
    efficiency: float
    feasible: bool
    binding: list[dict] = field(default_factory=list)   # {"limit", "value", "weight_saved_by_10%"}
    evaluations: int = 0
    wall_time_s: float = 0.0
    note: str = ""

    def summary(self) -> dict:
        d = dataclasses.asdict(self)
        d["gun"] = dataclasses.asdict(self.gun)
        return d


class ShotFigures(NamedTuple):
    """What the design reads of a shot (``gun.Shot``'s fields of the same names)."""
    muzzle_velocity: float        # [m/s]
    peak_acceleration: float      # [m/s^2]
    efficiency: float             # [-]


def weights(gun: Gun, sizing: Sizing) -> tuple[float, float]:
    """(barrel, tank) weight [kg] of a gun by the ASME rules at its reservoir pressure."""
    P = gun.reservoir_pressure
    _, wb = barrel_weight(P, gun.bore, gun.length, sizing.barrel_material, sizing.joint_efficiency)
    _, _, wt = tank_weight(P, gun.reservoir_volume, sizing.tank_diameter_of(gun.reservoir_volume),
                           sizing.tank_material, sizing.joint_efficiency)
    return wb, wt


def _with(template: Gun, valve_ratio: float | None, x) -> Gun:
    bore, length, p, vol = (float(v) for v in x)
    valve = None if valve_ratio is None else math.pi * (valve_ratio * bore) ** 2 / 4
    return dataclasses.replace(template, bore=bore, length=length, reservoir_pressure=p, reservoir_volume=vol,
                               valve_area=valve)


def valve_ratio_of(gun: Gun) -> float | None:
    """The template's valve diameter over its bore (kept as the bore changes); None: no valve."""
    return None if gun.valve_area is None else math.sqrt(4 * gun.valve_area / math.pi) / gun.bore


def lightest_launcher(template: Gun, velocity: float, limits: Limits, sizing: Sizing = Sizing(),
                      starts: int = 3, report_binding: bool = True) -> LauncherDesign:
    """The lightest gun like ``template`` firing its projectile at ``velocity`` within ``limits``."""
    t0 = time.perf_counter()
    problems = limits.check()
    if problems:
        raise ValueError("; ".join(problems))
    ratio = valve_ratio_of(template)
    lo = np.log([b[0] for b in limits.bounds()])
    hi = np.log([b[1] for b in limits.bounds()])
    # a shot's two numbers the constraints read, by its design variables (SLSQP asks the same point for the
    # objective and each constraint, and its finite differences again): the shot itself, with its sampled
    # history, is not kept, so the cache holds about 100 bytes a point, not the 9 kB of a shot
    cache: dict = {}

    def shot(z):
        key = tuple(np.round(z, 12))
        if key not in cache:
            s = fire(_with(template, ratio, np.exp(z)), rtol=1e-9, samples=120)
            cache[key] = ShotFigures(s.muzzle_velocity, s.peak_acceleration, s.efficiency)
        return cache[key]

    def weight(z):
        try:
            return sum(weights(_with(template, ratio, np.exp(z)), sizing))
        except ValueError:          # above what a wall of this material can hold at all
            return 1e12

    constraints = [{"type": "ineq", "fun": lambda z: shot(z).muzzle_velocity / velocity - 1}]
    if limits.max_acceleration:
        constraints.append({"type": "ineq", "fun": lambda z: 1 - shot(z).peak_acceleration / limits.max_acceleration})

    # the most a gun within the limits can do: every variable at its largest (the muzzle velocity
    # grows with each of them); if that falls short, no design is feasible and SLSQP need not look
    corner = shot(hi)
    if corner.muzzle_velocity < velocity * (1 - VELOCITY_TOL):
        gun = _with(template, ratio, np.exp(hi))
        wb, wt = weights(gun, sizing)
        return LauncherDesign(gun, wb + wt, wb, wt, corner.muzzle_velocity, velocity, corner.peak_acceleration,
                              corner.efficiency, False, _binding(hi, lo, hi, limits), len(cache),
                              time.perf_counter() - t0,
                              f"no gun within the limits reaches {velocity:.4g} m/s: every variable at its "
                              f"largest gives {corner.muzzle_velocity:.4g} m/s")
    best = None
    for z0 in _starts(template, velocity, lo, hi, starts):
        with warnings.catch_warnings():     # SLSQP's line search may step outside; scipy clips it
            warnings.filterwarnings("ignore", "Values in x were outside bounds")
            # SLSQP's ftol is absolute: the weight is scaled by the start's, so it is relative
            scale = weight(z0)
            r = minimize(lambda z: weight(z) / scale, z0, method="SLSQP", bounds=list(zip(lo, hi)),
                         constraints=constraints, options={"maxiter": 100, "ftol": FTOL, "eps": FD_STEP})
        s = shot(r.x)
        ok = s.muzzle_velocity >= velocity * (1 - VELOCITY_TOL) and (
            not limits.max_acceleration or s.peak_acceleration <= limits.max_acceleration * (1 + VELOCITY_TOL))
        cand = (not ok, weight(r.x), r.x)
        if best is None or cand[:2] < best[:2]:
            best = cand
    infeasible, _, z = best
    gun = _with(template, ratio, np.exp(z))
    s = fire(gun)
    wb, wt = weights(gun, sizing)
    note = "" if not infeasible else (
        f"the optimiser found no design reaching {velocity:.4g} m/s (the best reaches {s.muzzle_velocity:.4g} m/s) "
        f"though every variable at its largest does; the acceleration limit may be what binds")
    design = LauncherDesign(gun, wb + wt, wb, wt, s.muzzle_velocity, velocity, s.peak_acceleration, s.efficiency,
                            not infeasible, [], len(cache), 0.0, note)
    design.binding = _binding(z, lo, hi, limits)
    if report_binding and not infeasible:
        for b in design.binding:
            relaxed = _relaxed(limits, b["limit"])
            if relaxed is None:
                continue
            other = lightest_launcher(gun, velocity, relaxed, sizing, starts=1, report_binding=False)
            b["weight_saved_by_relaxing_10%"] = design.weight - other.weight if other.feasible else math.nan
            design.evaluations += other.evaluations
    design.evaluations += len(cache)
    design.wall_time_s = time.perf_counter() - t0
    return design


def _starts(template: Gun, velocity: float, lo, hi, n: int):
    """Start points: the template itself (clipped), then mid-box points of growing pressure,
    each with a tank storing four times the payload's kinetic energy."""
    kinetic = 0.5 * template.projectile_mass * velocity ** 2
    x = np.log([template.bore, template.length, template.reservoir_pressure, template.reservoir_volume])
    yield np.clip(x, lo, hi)
    for k in range(1, n):
        z = (lo + hi) / 2
        z[2] = lo[2] + (hi[2] - lo[2]) * k / n
        p = math.exp(z[2])
        z[3] = math.log(4 * kinetic * (template.gas_model().gamma - 1) / p)
        yield np.clip(z, lo, hi)


def _binding(z, lo, hi, limits: Limits) -> list[dict]:
    names = {0: ("bore", "min_bore", "max_bore"), 1: ("length", "min_length", "max_length"),
             2: ("reservoir_pressure", "min_pressure", "max_pressure"),
             3: ("reservoir_volume", "min_volume", "max_volume")}
    out = []
    for i, (var, lo_name, hi_name) in names.items():
        if z[i] - lo[i] < 1e-3:
            out.append({"limit": lo_name, "variable": var, "value": math.exp(lo[i])})
        elif hi[i] - z[i] < 1e-3:
            out.append({"limit": hi_name, "variable": var, "value": math.exp(hi[i])})
    return out


def _relaxed(limits: Limits, name: str) -> Limits | None:
    value = getattr(limits, name)
    factor = 1 / RELAX if name.startswith("min_") else RELAX
    return dataclasses.replace(limits, **{name: value * factor})


def trade(template: Gun, velocity: float, limits: Limits, sizing: Sizing, variable: str,
          values) -> list[LauncherDesign]:
    """The lightest launcher with one variable held at each of ``values`` (the others free
    within ``limits``): a trade curve, e.g. weight against pressure, or length against bore."""
    index = VARIABLES.index(variable)
    lo_name, hi_name = {0: ("min_bore", "max_bore"), 1: ("min_length", "max_length"),
                        2: ("min_pressure", "max_pressure"), 3: ("min_volume", "max_volume")}[index]
    out = []
    for v in values:
        held = dataclasses.replace(limits, **{lo_name: v, hi_name: v})
        out.append(lightest_launcher(dataclasses.replace(template, **{variable: v}), velocity, held, sizing,
                                     report_binding=False))
    return out


def length_against_bore(gun: Gun, velocity: float, bores, sizing: Sizing) -> list[dict]:
    """For each bore: the barrel length ``gun`` needs to reach ``velocity`` with its own tank and
    pressure (valve scaled with the bore), and the length an infinite chamber of the bore's
    section at that pressure needs (the simple-wave gun: what a bigger tank tends to, short of
    a chamber wider than the bore), with the weights."""
    ratio = valve_ratio_of(gun)
    rows = []
    for bore in bores:
        g = _with(gun, ratio, (bore, gun.length, gun.reservoir_pressure, gun.reservoir_volume))
        length = barrel_length_for(g, velocity)
        bound = barrel_length_for(dataclasses.replace(g, gas_inertia="simple-wave"), velocity)
        weight = sum(weights(dataclasses.replace(g, length=length), sizing)) if math.isfinite(length) else math.nan
        rows.append({"bore": bore, "length": length, "simple_wave": bound, "weight": weight})
    return rows


def around(value: float, lo: float, hi: float, n: int, span: float = 3.0) -> np.ndarray:
    """``n`` values spaced geometrically from value / span to value * span, within [lo, hi]."""
    return np.geomspace(max(lo, value / span), min(hi, value * span), n)
