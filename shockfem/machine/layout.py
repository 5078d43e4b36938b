"""Where everything sits along the machine's axis, and what stops, guides and carries the moving bodies.

The machine is horizontal, on one axis x: the tank behind the breech, the barrel, the amplifier's
masses with their pads and gaps, the striker (the dashpot's housing), the payload (piston and article)
a gap beyond its mouth, then the arrest: every moving body is stopped by a ring stop on the axis whose
bore lets the smaller bodies ahead of it pass (masses shrink along the chain), the payload last by its
catcher.

* Each body's stop is an absorber (``stops.py``: a hydraulic buffer or a crushable, the shortest within
  its limits) at the force its inertia allows (a body stopped at one end at deceleration a carries
  rho L a at the stop, at most the allowable S); the payload's catcher at the spec's deceleration (half
  the test pulse's peak by default: the arrest must not be the harsher shock).  Each absorber takes its
  own length on the axis, after the previous one.  The gun's slug (the first body) leaves its travel with
  its front at the muzzle and the barrel full of gas behind it: where its base is still in the bore when
  it meets its stop, the stop is designed against that gas's push (``stops.pushed_stop``; the push the
  gun's base pressure at the end of its travel on the bore, ``launcher.muzzle_state``, held over the
  stroke: it falls as the barrel vents and rises toward the tank's pressure where the stopped body closes
  the bore with the valve open).
* Guides: two rails under every body, sliding shoes under it (its weight their load): catalogue
  rolling carriages run at most ``ROLLING_CARRIAGE_SPEED`` (item Industrietechnik, PS 4 bearing carriages:
  v max 5 m/s), far below the bodies' speeds, so the shoes slide (wear strips on hardened rails).
* Frame: two side members as ties that carry the largest stop force, or the gun's recoil at firing if that
  is larger, at the allowable stress (``frame_force``; their bending and the foundation are left out).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

from ..programmer.dashpot_design import DASHPOT, OIL
from ..programmer.housing import HOUSING_STEELS
from .stops import Stop, design_stop, pushed_stop

ROLLING_CARRIAGE_SPEED = 5.0       # [m/s], item PS 4 bearing carriages (catalogue)
GUIDES_PER_BODY = 2               # rails under a body, one sliding shoe on each
RAIL_SIZE = (0.06, 0.020)         # a rail's square section: this share of the body's diameter, at least [m]
GAP_TO_PAYLOAD = 0.05              # between the striker's mouth and the piston at rest [m]
RING_CLEARANCE = 0.01              # a stop ring's bore over the body that passes through it [m]
RING_OUTER = 1.3                  # a stop ring's (and the collar it meets) outer diameter over the body's
                                  # (or over the ring's bore, where the next body is the wider)
STOP_MARGIN = 0.05                 # free run past the next body's far end before a stop engages [m]


@dataclass
class Item:
    """One component on the axis: x0 its rear end, length along x, outer (and inner) diameter [m]."""
    name: str
    kind: str                  # tank, barrel, mass, pad, housing, oil, piston, article, stop, rail, frame
    x0: float
    length: float
    diameter: float
    inner: float = 0.0
    mass: float = 0.0          # [kg]
    material: str = ""
    note: str = ""


@dataclass
class Layout:
    items: list[Item]
    stops: list[Stop]
    overall_length: float      # [m]
    overall_width: float       # [m]
    frame_section: float       # each side member [m^2]
    frame_mass: float          # [kg]
    fastest_guided_speed: float
    notes: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        return asdict(self)


def rail_section(diameter: float) -> float:
    """The side of a body's rails' square section [m] (drawn, not designed)."""
    return max(RAIL_SIZE[0] * diameter, RAIL_SIZE[1])


def rail_geometry(diameter: float) -> tuple[float, tuple[float, float], float]:
    """A body's two rails (drawn, not designed): their square section's side h, their left faces' x and
    their bottom's y [m] (the body's axis at x = y = 0), a shoe h / 2 thick between rail and body."""
    h = rail_section(diameter)
    return h, (-0.35 * diameter - h / 2, 0.35 * diameter - h / 2), -diameter / 2 - 1.5 * h


def shoe_length(diameter: float, length: float) -> float:
    """A shoe's length along its rail [m]: a quarter of the body's diameter, at least two rail sections,
    at most the body's length."""
    h = rail_section(diameter)
    return min(length, max(2 * h, 0.25 * diameter))


def ring_area(outer: float, inner: float) -> float:
    """The face a stop ring meets [m^2]: the body's (``outer`` its diameter) less the bore ``inner`` that
    lets the next body pass."""
    return math.pi * (outer * outer - inner * inner) / 4


def tank_length(volume: float, diameter: float, head_thickness: float) -> float:
    """A tank's overall length [m]: its ``volume`` as a cylinder of inside ``diameter`` between hemispherical
    heads, then the heads."""
    L_cyl = max(volume - math.pi * diameter ** 3 / 6, 0.0) / (math.pi * diameter * diameter / 4)
    return L_cyl + diameter + 2 * head_thickness


def frame_section(force: float, allowable: float) -> float:
    """Each of the frame's two side members [m^2]: half ``force`` at the allowable."""
    return force / allowable / 2


def frame_force(stops: list[Stop], recoil: float) -> float:
    """The largest force the frame's side members carry [N]: the largest stop force, or the gun's recoil at
    firing (its thrust on the projectile, carried from the breech to the stops' end), whichever is larger."""
    return max(max(st.force for st in stops), recoil if math.isfinite(recoil) else 0.0)


def place(launcher, amp, fixture, rho: float, allowable: float, catch: float, material: str,
          final_speeds: list[float], pressure: float, max_force: float = math.inf, push: float = 0.0,
          jet: float = 0.0) -> Layout:
    """Every component's place on the axis, the stops, the guides and the frame.  ``final_speeds``: each
    amplifier mass's speed after the chain (the striker's is the fixture's after the pulse); ``pressure``:
    the dashpot's design pressure (the hydraulic buffers' at most); ``max_force``: the most a stop may ask of
    the frame; ``push``: the gun's gas on the bore at the end of its travel [N] (``launcher.muzzle_state``),
    which the gun's slug (the first body) carries at its stop where its base is still in the bore when it
    meets it (``stops.pushed_stop``); ``jet``: the muzzle's jet on the slug once its base has left the bore
    [N] (a lone slug that fills the bore, the premise's kept sabot; else left out), which its stop carries
    there instead.  The slug's front reaches the muzzle at the end of the gun's travel; a
    lone slug (the premise's direct striker) finds the payload waiting there, ``GAP_TO_PAYLOAD`` past the
    muzzle."""
    g, size = launcher.design.gun, launcher.sizing
    items: list[Item] = []
    tank = size["tank"]
    D_t = tank["diameter"]
    L_tank = tank_length(g.reservoir_volume, D_t, tank["head_thickness"])
    items.append(Item("tank", "tank", 0.0, L_tank, D_t + 2 * tank["shell_thickness"], D_t, tank["weight"],
                      tank["material"], f"{g.reservoir_volume:.3g} m^3 of {g.gas} at {g.reservoir_pressure / 1e6:.3g} MPa"))
    bodies = amp.bodies
    slug = bodies[0]
    x_breech = L_tank
    L_barrel = g.length + slug["length"]
    D_barrel = g.bore + 2 * size["barrel"]["thickness"]
    # the ASME wall over the travel and the slug the barrel also holds at rest
    barrel_mass = size["barrel"]["weight"] * L_barrel / g.length
    items.append(Item("barrel", "barrel", x_breech, L_barrel, D_barrel, g.bore, barrel_mass, size["barrel"]["material"],
                      f"{g.length:.3g} m of travel and the {slug['length']:.3g} m slug"))
    # the chain as it stands when the first mass leaves the muzzle: the others at rest ahead of it
    fronts = []
    for k, (b, m) in enumerate(zip(bodies, amp.masses)):
        if k == 0:
            rear = x_breech
        else:
            stage = amp.stages[k - 1]
            pad_rear = (x_breech + g.length + slug["length"] if k == 1 else fronts[-1]) + amp.gaps[k - 1]
            if stage.pad_thickness:         # a crowned or bare steel face has no pad of its own
                items.append(Item(f"pad_{stage.pair}", "pad", pad_rear, stage.pad_thickness,
                                  stage.pad_diameter, 0.0, stage.pad_mass, stage.pad_material,
                                  f"{stage.pad_stiffness / 1e6:.4g} MN/m, {stage.pad_travel * 1e3:.0f} mm travel"))
            rear = pad_rear + stage.pad_thickness
        if b["name"] == "striker":
            items.append(Item(b["name"], "housing", rear, b["length"], b["diameter"], b["bore"],
                              fixture.housing_steel_mass, fixture.housing_steel, f"bore {b['bore'] * 1e3:.0f} mm, floor "
                                                                    f"{fixture.floor_thickness * 1e3:.0f} mm"))
            items.append(Item("oil", "oil", rear + fixture.floor_thickness, fixture.column, b["bore"], 0.0,
                              fixture.liquid_mass, "oil", f"{OIL['density']:g} kg/m^3, carried by the striker"))
            if fixture.pin_mass > 0:
                # the metering pin stands on the floor through the column: drawn as the cylinder of its volume
                steel = HOUSING_STEELS[fixture.housing_steel].density
                d_pin = math.sqrt(4 * fixture.pin_mass / (math.pi * steel * fixture.column))
                items.append(Item("pin", "pin", rear + fixture.floor_thickness, fixture.column, d_pin, 0.0,
                                  fixture.pin_mass, fixture.housing_steel, "metering pin, carried by the striker"))
        else:
            items.append(Item(b["name"], "mass", rear, b["length"], b["diameter"], 0.0, m, material))
        fronts.append(rear + b["length"])
    muzzle = x_breech + L_barrel
    # the striker's mouth at first contact: at rest ahead of the chain, or a lone slug's front at the muzzle
    mouth = fronts[-1] if len(bodies) > 1 else muzzle
    piston_x = mouth + GAP_TO_PAYLOAD
    t_piston = DASHPOT["piston_thickness"]
    items.append(Item("piston", "piston", piston_x, t_piston, 2 * fixture.bore_radius, 0.0, fixture.piston_mass,
                      material, "the article stands on it; it enters the bore"))
    items.append(Item("article", "article", piston_x + t_piston, fixture.article_length, fixture.article_diameter,
                      0.0, fixture.article_mass, "steel_4340", "the unit under test (the reference ogive, nose "
                                                               "forward)"))
    payload_front = piston_x + t_piston + fixture.article_length
    stops: list[Stop] = []
    stop_end: dict[str, float] = {}         # body -> where its stop's stroke ends

    def add_stop(s: Stop, name: str, x: float, outer: float, inner: float) -> float:
        """A stop's absorber on the axis from ``x`` over its own length; returns where it ends (its stroke
        and its length both end there: the body runs into it)."""
        items.append(Item(name, "stop", x, s.length, outer, inner, s.absorber_mass, s.short,
                          f"{s.kind}: {s.force / 1e6:.3g} MN peak over {s.stroke:.3g} m"))
        stops.append(s)
        stop_end[s.body] = x + s.length
        return stop_end[s.body]

    def slug_push(k: int, x: float) -> tuple[float, str]:
        """The gas's push on body ``k`` at its stop at ``x`` and where it comes from: the first body's, its
        base still in the bore, or the muzzle's jet on it past the muzzle."""
        if k != 0:
            return 0.0, ""
        if x - slug["length"] < muzzle:
            return push, "the gun's gas at the end of its travel on the bore (its base pressure, launcher.muzzle_state)"
        return jet, ("the muzzle's jet on the body that fills the bore: the base pressure on the bore as its base "
                     "leaves the muzzle, held (its fall as the barrel empties and the body moves off not modelled)")
    # each amplifier mass's ring just past the next body, after the previous ring's absorber
    ring_end = 0.0
    for k, b in enumerate(bodies[:-1]):
        inner = bodies[k + 1]["diameter"] + RING_CLEARANCE
        # the collar the stop meets reaches past the ring's bore even where the next body is the wider
        outer = RING_OUTER * max(b["diameter"], inner)
        x = max(fronts[k + 1] + STOP_MARGIN, ring_end)
        s = pushed_stop(b["name"], amp.masses[k], final_speeds[k], b["length"], rho, allowable,
                        ring_area(outer, inner), pressure, *slug_push(k, x), None, max_force)
        ring_end = add_stop(s, f"stop_{b['name']}", x, outer, inner)
    striker = bodies[-1]
    inner = 2 * fixture.bore_radius + RING_CLEARANCE
    x = max(mouth + fixture.striker_travel + STOP_MARGIN, ring_end)
    s = pushed_stop("striker", fixture.striker_mass, fixture.after_speed_striker, striker["length"], rho, allowable,
                    ring_area(RING_OUTER * striker["diameter"], inner), pressure, *slug_push(len(bodies) - 1, x),
                    None, max_force)
    ring_end = add_stop(s, "stop_striker", x, RING_OUTER * striker["diameter"], inner)
    c = design_stop("payload", fixture.payload_mass, fixture.after_speed_payload, fixture.article_length, rho,
                    allowable, ring_area(RING_OUTER * 2 * fixture.bore_radius, 0.0), pressure, catch, max_force)
    add_stop(c, "catcher", max(payload_front + fixture.payload_travel + STOP_MARGIN, ring_end),
             RING_OUTER * striker["diameter"], 0.0)
    length = max(i.x0 + i.length for i in items)
    width = max(i.diameter for i in items)
    # guides: rails under every moving body from where it rests to its stop's end (the piston: the payload's)
    for it in [i for i in items if i.kind in ("mass", "housing", "piston")]:
        body = "payload" if it.kind == "piston" else it.name
        items.append(Item(f"rails_{body}", "rail", it.x0, stop_end[body] - it.x0, it.diameter, 0.0, 0.0, material,
                          f"two rails, sliding shoes under {it.name}"))
    F = frame_force(stops, max_force)
    section = frame_section(F, allowable)
    frame_mass = 2 * rho * section * length
    items.append(Item("frame", "frame", 0.0, length, width, 0.0, frame_mass, material,
                      f"two side members of {section * 1e4:.3g} cm^2 each: the largest of the stop forces and the "
                      "gun's recoil at the allowable"))
    fastest = max([launcher.design.muzzle_velocity, fixture.striker_speed, fixture.after_speed_payload])
    notes = [f"the guided bodies reach {fastest:.4g} m/s, {fastest / ROLLING_CARRIAGE_SPEED:.0f} times the "
             f"{ROLLING_CARRIAGE_SPEED:g} m/s of catalogue rolling carriages: the shoes slide on the rails"]
    return Layout(items, stops, length, width, section, frame_mass, fastest, notes)
