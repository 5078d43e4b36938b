"""The stops as absorbers: what takes each moving body's energy at the end of a shot, its stroke, force,
own length and mass, and the limits it must hold.

Every body leaves the shot with the kinetic energy E = m v^2 / 2 of its last speed (the amplifier's
masses after their stages, the striker after the pulse, the payload).  Two kinds of absorber are sized
for each, and the shortest whose limits all hold is kept (if none holds, the one least over its limits,
with its broken limits in the machine's verdict):

* **hydraulic buffer**: a piston driving oil through metering orifices at a constant force F (the force
  the stopped body's inertia or the catcher's deceleration allows, or less where the buffer's bore at its
  pressure would not fit the stop ring).  Stroke x = E / F.  The oil swept by the piston keeps the
  energy, so it warms by p / (rho c_p) whatever the size: the cylinder runs at the pressure at which that
  is the allowed rise (132 MPa for 80 K), or the dashpot's design pressure if lower; bore area F / p, the
  wall by ASME VIII-2 4.3.3 at the allowable (``programmer.housing.wall_ratio``: P = S ln Y), length 2.2 x
  (cylinder and rod retracted).
  Limits: the pressure a sudden impact raises in the oil, Joukowsky rho c v (Wylie and Streeter, Fluid
  Transients in Systems, ch. 1), at most p; the piston's Mach number in the oil v / c at most 0.1 (the
  lumped orifice law's range, ``programmer.dashpot_validity``); the oil's temperature rise a shot when
  the swept oil keeps the energy, E / (rho A x c_p) = p / (rho c_p), within ``OIL_TEMPERATURE_RISE``: one
  shot's rise from the ambient to the lower of the oil's flash point less a margin and its seals' service
  temperature (the constants' comment gives the sources; the seals bind, 80 K).
* **crushable**: an aluminium honeycomb block (``HONEYCOMB`` grades) crushed through; its force at
  speed v is the steady-shock crush stress A (sigma_c + rho0 v^2 / eps_D) (Reid and Peng, Int. J.
  Impact Eng. 19 (1997) 531: a cellular solid crushed at v carries the shock's momentum flux), so the
  body decelerates as m v dv/dx = -A (sigma_c + k v^2), k = rho0 / eps_D, and the stroke is
  x = m ln(1 + k v0^2 / sigma_c) / (2 A k).  The block is x / eps_D long (it crushes to eps_D of its
  length); it is consumed each shot (its mass a shot reported).  Area: the stop ring's (the body's face
  less the bore that lets the next body pass), smaller where the peak A (sigma_c + k v0^2) would pass
  the allowed force.  Limits: the peak force within the allowed force (by construction); the crush
  speed at most ``CRUSH_SPEED_LIMIT`` times the speed above which the shock term doubles the static
  crush stress, beyond which the model is extrapolated.

* **water brake, then a buffer**: a scoop on the body turns the water of a trough between the rails
  back on itself (the brakes of rocket-sled tracks): a jet turned by 180 degrees pushes 2 rho_w A_s v^2
  (momentum flux on a vane; White, Fluid Mechanics, ch. 3), so at the allowed force F at the first
  speed v0 the scoop is A_s = F / (2 rho_w v0^2), the body slows as e^(-x / l), l = m / (2 rho_w A_s),
  and reaches the speed a hydraulic buffer accepts (its Joukowsky limit) after x = l ln(v0 / v_b); the
  buffer takes the rest.  The water it throws out is refilled each shot.  Limit: the scoop's face carries
  the stagnation pressure 2 rho_w v0^2, at most the allowable.

A body pushed on while it is stopped (the gas drive's piston, its gas behind it; a gun's slug or a sabot
stopped at the muzzle, the barrel's gas behind it): the absorber must take the body's energy and the push's
work over its stroke, F s = m v^2 / 2 + F_p s, so only a force above the push stops it (a buffer's stroke
m v^2 / (2 (F - F_p)); a honeycomb's with sigma_c less the push over its area), and at rest it holds the push
(a honeycomb below its crush stress, a buffer's rod bottomed on its cylinder's end).  The water brake's force
falls with the speed, so it is left out there.  ``pushed_stop`` puts the push against the absorber's least
force (``Stop.hold``: a buffer's force, a block's static crush) among the stop's limits; where no absorber's
force exceeds it the body never stops, and that limit is broken.

The stop's face: the ring the absorber presses on, from the bore that lets the next body pass out to
a collar 1.3 times the body's diameter (the stop ring as drawn).

The allowed force: a body stopped at one end at deceleration a carries rho L a at the stop (a bar
pushed from one end), at most the allowable S; the payload's catcher is the spec's deceleration; and no
stop asks more of the frame than the gun's own thrust on its projectile, which the frame carries anyway
(``max_force``: the frame is sized once).  A
brake on the rails (friction or water) is not sized.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

from ..programmer.dashpot_design import OIL
from ..units import G0
from ..programmer.housing import wall_ratio
from .fixture import OIL_HEAT_CAPACITY
from .limits import Limit
from .pad_materials import AMBIENT

# the oil's speed of sound sqrt(K / rho) [m/s]
OIL_SOUND_SPEED = math.sqrt(OIL["bulk_modulus"] / OIL["density"])
# the lumped orifice law's range: piston speed over the oil's sound speed (``programmer.dashpot_validity``)
BUFFER_MACH = 0.1
WATER_DENSITY = 1000.0       # [kg/m^3]
# The oil's temperature rise a shot (the buffers' and the dashpot's): one shot heats the oil it throttles,
# which must stay below its flash point with a margin (the jet's shear layer runs hotter than the mean) and
# within its seals' service temperature; the lower of the two, less the ambient, is the rise.  Flash point:
# 200 C, the low end of mineral hydraulic oils' Cleveland open cup flash points (ISO 2592 / ASTM D92: 200 to
# 240 C for mineral base oils, an ISO VG 32 oil typically 220 C; data-sheet values, check), less 50 K;
# seals: nitrile (NBR) in mineral oil to 100 C (Parker O-Ring Handbook ORD 5700, nitrile compounds; check).
# The seals bind: 80 K from the 20 C ambient.
OIL_FLASH_POINT, FLASH_MARGIN, SEAL_TEMPERATURE = 200.0, 50.0, 100.0     # [C], [K], [C]
OIL_TEMPERATURE_RISE = min(OIL_FLASH_POINT - FLASH_MARGIN, SEAL_TEMPERATURE) - AMBIENT
OIL_TEMPERATURE_SOURCE = (f"a shot's rise from {AMBIENT:g} C to the lower of the oil's flash point less "
                          f"{FLASH_MARGIN:g} K ({OIL_FLASH_POINT:g} C, ISO 2592 Cleveland open cup, mineral "
                          f"hydraulic oil; check) and its nitrile seals' {SEAL_TEMPERATURE:g} C (Parker ORD 5700; check)")
BUFFER_LENGTH = 2.2           # a buffer's length over its stroke (the cylinder and its rod retracted)
# aluminium honeycomb (5052 alloy): density [kg/m^3], stabilised crush strength [Pa]; densification strain.
# Hexcel, "HexWeb Honeycomb Attributes and Properties" (TSB 120), 5052 hexagonal grades 3.1 to 12 pcf (check)
HONEYCOMB = {"3.1 pcf": (50.0, 0.90e6), "4.5 pcf": (72.0, 1.79e6), "6.1 pcf": (98.0, 3.10e6),
             "8.1 pcf": (130.0, 5.17e6), "12 pcf": (192.0, 9.65e6)}
HONEYCOMB_SOURCE = "Hexcel TSB 120, 5052 honeycomb (check)"
DENSIFICATION = 0.70          # the share of a honeycomb block's length it crushes through (Hexcel TSB 120)
# the steady-shock crush model is used up to this many times the speed sqrt(sigma_c / k) at which the shock
# term equals the static crush stress (Reid and Peng compare it with tests to about 3 times)
CRUSH_SPEED_LIMIT = 3.0


@dataclass
class Stop:
    body: str
    mass: float                # [kg]
    speed: float               # when it reaches its stop [m/s]
    deceleration: float        # peak [m/s^2]
    stroke: float              # [m]
    force: float               # peak [N]
    energy: float              # what it absorbs, m v^2 / 2 [J]
    stress: float              # rho L a: the stopped body's inertia at the stop, at the peak [Pa]
    limit: str                 # what set the allowed force
    kind: str = ""             # "hydraulic buffer" or "crushable (<grade> honeycomb)"
    length: float = 0.0        # the absorber's own length on the axis [m]
    absorber_mass: float = 0.0  # its own mass (steel, oil, the block) [kg]
    consumed: float = 0.0      # mass used up each shot [kg]
    detail: str = ""
    limits: list = field(default_factory=list)   # ``Limit``s of the absorber
    hold: float = math.nan     # the least force with which it stops the body: a buffer's, a block's static crush [N]
    push: float = 0.0          # a steady force on the body while it is stopped (``pushed_stop``) [N]

    def as_dict(self) -> dict:
        d = asdict(self)
        d["limits"] = [lim.as_dict() for lim in self.limits]
        return d

    @property
    def short(self) -> str:
        """The absorber in a parts list's few words."""
        return ("Al honeycomb" if self.kind.startswith("crushable") else
                "water brake + buffer" if self.kind.startswith("water") else "oil buffer")


def allowed_force(mass: float, length: float, rho: float, allowable: float, deceleration: float | None = None,
                  max_force: float = math.inf) -> tuple[float, str]:
    """The largest force a stop may put on a body [N] and why: its inertia's limit S / (rho L) as a
    deceleration, or ``deceleration`` (the catcher's) if given; at most ``max_force``."""
    if deceleration:
        F, why = mass * deceleration, f"the catcher's deceleration ({deceleration / G0:,.0f} g)"
    else:
        a = allowable / (rho * length)
        F, why = mass * a, f"its inertia: rho L a = allowable ({a / G0:,.0f} g)"
    if F > max_force:
        return max_force, f"the gun's thrust, which the frame carries ({max_force / 1e6:.3g} MN)"
    return F, why


def buffer_pressure(design_pressure: float) -> float:
    """A buffer's working pressure [Pa]: the one at which its swept oil warms by the allowed rise, p = dT rho
    c_p, at most ``design_pressure``."""
    return min(design_pressure, OIL_TEMPERATURE_RISE * OIL["density"] * OIL_HEAT_CAPACITY)


def hydraulic_buffer(body: str, mass: float, speed: float, force: float, ring_area: float, pressure: float,
                     rho_steel: float, allowable: float, push: float = 0.0) -> dict | None:
    """A constant-force hydraulic buffer taking ``mass`` at ``speed`` at ``force`` at most, its bore within
    ``ring_area``, its cylinder at ``pressure``, against a steady ``push`` [N] on the body (module docstring);
    its size and limits, None where its force cannot exceed the push."""
    area = min(force / pressure, ring_area)
    force = area * pressure
    if force <= push:
        return None
    stroke = 0.5 * mass * speed * speed / (force - push)
    energy = force * stroke                      # the body's and the push's work over the stroke
    r = math.sqrt(area / math.pi)
    R = r * wall_ratio(pressure, allowable)
    length = BUFFER_LENGTH * stroke
    steel = rho_steel * math.pi * (R * R - r * r) * length + rho_steel * area * stroke   # cylinder and rod
    oil = OIL["density"] * area * stroke
    heating = energy / (oil * OIL_HEAT_CAPACITY)
    joukowsky = OIL["density"] * OIL_SOUND_SPEED * speed
    # a buffer behind a water brake meets the body at its Joukowsky speed, and the working pressure is the
    # one of the allowed heating: those two are at their limits by design
    limits = [
        Limit(f"stop of {body} (hydraulic buffer)", "impact pressure rho c v", joukowsky, pressure, "Pa",
              "Joukowsky: a piston started suddenly on the oil", "the cylinder's working pressure (buffer_pressure)",
              sized=joukowsky >= pressure * (1 - 1e-9)),
        Limit(f"stop of {body} (hydraulic buffer)", "piston Mach number in the oil", speed / OIL_SOUND_SPEED,
              BUFFER_MACH, "-", "v / sqrt(K / rho)", "the lumped orifice law's range (programmer.dashpot_validity)"),
        Limit(f"stop of {body} (hydraulic buffer)", "oil temperature rise a shot", heating, OIL_TEMPERATURE_RISE, "K",
              "E / (rho A x c_p): the swept oil keeps the energy", OIL_TEMPERATURE_SOURCE,
              sized=heating >= OIL_TEMPERATURE_RISE * (1 - 1e-9)),
    ]
    return {"kind": "hydraulic buffer", "stroke": stroke, "force": force, "hold": force, "length": length,
            "absorber_mass": steel + oil, "consumed": 0.0, "limits": limits,
            "detail": f"bore {2e3 * r:.0f} mm at {pressure / 1e6:.0f} MPa, wall {1e3 * (R - r):.0f} mm, oil {oil:.3g} kg"}


def backing_plate(p: float, r: float, S: float) -> float:
    """The thickness [m] of a circular plate of radius ``r`` clamped at its rim whose edge stress under the
    uniform pressure ``p`` is ``S``: 3 p r^2 / (4 t^2) = S (Roark, Formulas for Stress and Strain, 7th ed.,
    Table 11.2 case 10b)."""
    return r * math.sqrt(3 * p / (4 * S))


def crushable(body: str, mass: float, speed: float, force: float, ring_area: float, grade: str, rho_steel: float,
              allowable: float, push: float = 0.0) -> dict | None:
    """An aluminium honeycomb block of ``grade`` crushed by ``mass`` at ``speed``, its peak force at most
    ``force``, its section at most ``ring_area``, against a steady ``push`` [N] on the body (module docstring);
    its size and limits, None where its static crush force cannot exceed the push (the body never stops)."""
    rho0, sigma_c = HONEYCOMB[grade]
    k = rho0 / DENSIFICATION
    peak_stress = sigma_c + k * speed * speed
    area = min(ring_area, force / peak_stress)
    net = sigma_c - push / area                  # the static crush stress the push leaves to stop the body
    if net <= 0:
        return None
    stroke = mass * math.log(1 + k * speed * speed / net) / (2 * area * k)
    block = stroke / DENSIFICATION
    consumed = rho0 * area * block
    # a steel backing plate carrying the peak crush stress, clamped at its rim (``backing_plate``)
    plate = backing_plate(peak_stress, math.sqrt(area / math.pi), allowable)
    speed_limit = CRUSH_SPEED_LIMIT * math.sqrt(sigma_c / k)
    limits = [
        Limit(f"stop of {body} (crushable)", "crush speed", speed, speed_limit, "m/s",
              "the steady-shock crush model's range", f"Reid and Peng 1997; {HONEYCOMB_SOURCE}"),
    ]
    return {"kind": f"crushable ({grade} aluminium honeycomb)", "stroke": stroke, "force": area * peak_stress,
            "hold": area * sigma_c,
            "length": block + plate, "absorber_mass": consumed + rho_steel * area * plate, "consumed": consumed,
            "limits": limits,
            "detail": f"{area * 1e4:.3g} cm^2 x {block:.3g} m, crush {sigma_c / 1e6:.3g} MPa static, "
                      f"{peak_stress / 1e6:.3g} MPa at impact; {consumed:.3g} kg used a shot"}


def water_brake(body: str, mass: float, speed: float, force: float, ring_area: float, pressure: float,
                rho_steel: float, allowable: float) -> dict:
    """A water brake down to the speed a hydraulic buffer accepts, then the buffer; its size and limits."""
    v_b = pressure / (OIL["density"] * OIL_SOUND_SPEED)          # the buffer's Joukowsky limit
    v_b = min(v_b, BUFFER_MACH * OIL_SOUND_SPEED, speed)
    scoop = force / (2 * WATER_DENSITY * speed * speed)
    decay = mass / (2 * WATER_DENSITY * scoop)
    trough = decay * math.log(speed / v_b)
    buffer = hydraulic_buffer(body, mass, v_b, force, ring_area, pressure, rho_steel, allowable)
    stagnation = 2 * WATER_DENSITY * speed * speed
    limits = [Limit(f"stop of {body} (water brake)", "scoop face pressure 2 rho v^2", stagnation, allowable, "Pa",
                    "a jet turned by 180 degrees (White, Fluid Mechanics, ch. 3)", "the scoop steel's allowable")]
    limits += buffer["limits"]
    water = WATER_DENSITY * scoop * trough
    return {"kind": "water brake, then a hydraulic buffer", "stroke": trough + buffer["stroke"], "force": force,
            "hold": buffer["hold"],
            "length": trough + buffer["length"], "absorber_mass": buffer["absorber_mass"], "consumed": water,
            "limits": limits,
            "detail": f"scoop {scoop * 1e4:.3g} cm^2, trough {trough:.3g} m to {v_b:.0f} m/s, {water:.3g} kg of water "
                      f"a shot; then {buffer['detail']}"}


def design_stop(body: str, mass: float, speed: float, length: float, rho: float, allowable: float, ring_area: float,
                pressure: float, deceleration: float | None = None, max_force: float = math.inf,
                push: float = 0.0) -> Stop | None:
    """The stop of a body of ``length`` [m] at ``speed``: a hydraulic buffer or a crushable, the shortest
    whose limits hold (else the least over them); with a steady ``push`` [N] on the body (module docstring)
    only those whose force exceeds it, the water brake left out (its force falls with the speed), None where
    none does."""
    force, why = allowed_force(mass, length, rho, allowable, deceleration, max_force)
    options = [hydraulic_buffer(body, mass, speed, force, ring_area, buffer_pressure(pressure), rho, allowable, push)]
    options += [crushable(body, mass, speed, force, ring_area, g, rho, allowable, push) for g in HONEYCOMB]
    if speed > buffer_pressure(pressure) / (OIL["density"] * OIL_SOUND_SPEED) and push == 0:
        options.append(water_brake(body, mass, speed, force, ring_area, buffer_pressure(pressure), rho, allowable))
    options = [o for o in options if o is not None]
    if not options:
        return None

    def worst(o):
        return max(lim.ratio for lim in o["limits"])
    held = [o for o in options if worst(o) <= 1 + 1e-6]
    best = min(held, key=lambda o: o["length"]) if held else min(options, key=worst)
    a = best["force"] / mass
    return Stop(body, mass, speed, a, best["stroke"], best["force"], 0.5 * mass * speed * speed, rho * length * a, why,
                best["kind"], best["length"], best["absorber_mass"], best["consumed"], best["detail"], best["limits"],
                best["hold"], push)


def pushed_stop(body: str, mass: float, speed: float, length: float, rho: float, allowable: float, ring_area: float,
                pressure: float, push: float, why: str, deceleration: float | None = None,
                max_force: float = math.inf) -> Stop:
    """The stop of a body pushed on by ``push`` [N] while it is stopped (``why``: where the push comes from):
    ``design_stop`` with the push, and the push against the absorber's least force (``Stop.hold``) among its
    limits; where no absorber's force exceeds the push, the body never stops: the stop designed without it,
    that limit broken by the push over its force.  No push: ``design_stop``'s stop, no limit added."""
    args = (body, mass, speed, length, rho, allowable, ring_area, pressure, deceleration, max_force)
    if push <= 0:
        return design_stop(*args)
    s = design_stop(*args, push) or design_stop(*args)
    s.push = push
    s.limits = list(s.limits) + [
        Limit(f"stop of {body}", "the push on the body over its absorber's least force", push, s.hold, "N",
              f"{why}, held over the stroke: below the absorber's least force the body never stops",
              "a pushed body (machine.stops, module docstring)")]
    return s
