"""The three programmer concepts of the white paper's task 2, sized for a ``Requirement`` from the
closed forms of ``fixtures.md``: a crushable pad, an orifice (fluid) dashpot and a split cone with
a clamp ring.  Each gives the sizes that meet the pulse or the limit that rules it out; these are
the starting points a fixture study refines with the finite-element model.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from .requirement import Requirement

CONSTANT_FORCE_SHAPES = ("rectangle", "trapezoid")
# below this Mach number of the piston in the liquid an incompressible orifice law is a fair start
INCOMPRESSIBLE_MACH = 0.1


@dataclass
class Concept:
    """A sized concept: ``sizes`` (label, value, unit) in SI, ``notes`` what a designer must know,
    ``feasible`` False with ``reason`` when a limit rules it out; ``gives`` the pulse shape it makes
    (a constant force: a rectangle of the specified peak and velocity change)."""
    name: str
    model: str
    gives: str = "rectangle"
    feasible: bool = True
    reason: str = ""
    sizes: list[tuple[str, float, str]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        return {"name": self.name, "model": self.model, "gives": self.gives, "feasible": self.feasible,
                "reason": self.reason,
                "sizes": {label: {"value": value, "unit": unit} for label, value, unit in self.sizes},
                "notes": self.notes}


def _circle_diameter(area: float) -> float:
    return math.sqrt(4.0 * area / math.pi)


def constant_force_stroke(req: Requirement) -> float:
    """The stroke of a constant force at the specified peak bringing the article to rest from the
    velocity change: dV^2 / (2 A)."""
    return req.velocity_change ** 2 / (2.0 * req.peak)


def crushable_pad(req: Requirement, plateau: float, densification: float, density: float) -> Concept:
    """A pad crushing at a constant ``plateau`` stress [Pa] up to the ``densification`` strain, of foam
    ``density`` [kg/m^3]: area F / sigma_p for the peak force, stroke dV^2 / (2 A) at that force, thickness
    stroke / densification (a foam crushes without lateral expansion: volumetric = axial strain)."""
    c = Concept("crushable pad", f"constant crush stress {plateau / 1e6:.4g} MPa up to {densification:g} strain "
                                 f"(MAT_063-like); pad inertia and elastic rise left out")
    area = req.force / plateau
    stroke = constant_force_stroke(req)
    thickness = stroke / densification
    c.sizes += [("area", area, "m^2"), ("diameter (one round pad)", _circle_diameter(area), "m"),
                ("stroke at the peak force", stroke, "m"), ("thickness", thickness, "m"),
                ("pad mass", density * area * thickness, "kg"),
                ("pulse duration at the peak force", req.velocity_change / req.peak, "s")]
    if req.shape not in CONSTANT_FORCE_SHAPES:
        c.notes.append(f"a constant crush stress gives a rectangle: at the {req.peak_g:.5g} g peak it delivers the "
                       f"{req.velocity_change:.4g} m/s in {req.velocity_change / req.peak * 1e3:.4g} ms, not "
                       f"{req.duration * 1e3:.4g} ms; a {req.shape} needs a crushed area that grows and shrinks with the "
                       f"stroke (a shaped pad: cone, pyramid) or a rising crush curve")
    if density * area * thickness > 0.1 * req.mass:
        c.notes.append("the pad weighs over a tenth of the article: its own inertia shapes the start of the pulse "
                       "(run the finite-element model)")
    return c


def least_throttling_pressure(speed: float, density: float, discharge: float) -> float:
    """The pressure a piston at ``speed`` makes with the orifice as large as the piston itself,
    rho V^2 / (2 Cd^2): no orifice throttles it to less (fixtures.md)."""
    return density * speed ** 2 / (2.0 * discharge ** 2)


def metering_pin_area(stroke: float, piston_area: float, force: float, mass: float, speed: float, density: float,
                      discharge: float) -> float:
    """The orifice area that holds a constant ``force`` on a ``mass`` met at ``speed``, at ``stroke`` [m]:
    (A^(3/2) / Cd) sqrt(rho / (2F)) sqrt(V^2 - 2 F x / m) (fixtures.md; incompressible, quasi-steady)."""
    return (piston_area ** 1.5 / discharge * math.sqrt(density / (2.0 * force))
            * math.sqrt(max(speed ** 2 - 2.0 * force * stroke / mass, 0.0)))


def orifice_dashpot(req: Requirement, fluid_density: float, discharge: float, bulk_modulus: float,
                    max_pressure: float, heat_capacity: float) -> Concept:
    """A piston pushing liquid through an orifice, sized at ``max_pressure`` [Pa] (the smallest piston):
    piston area A = F / p; orifice a = A^(3/2) V sqrt(rho / (2F)) / Cd for a force F at speed V
    (incompressible, quasi-steady); no throttling below p = rho V0^2 / (2 Cd^2), the drop with the orifice
    as large as the piston."""
    V0 = req.velocity_change
    c = Concept("orifice dashpot", f"incompressible quasi-steady orifice law, Cd = {discharge:g}, liquid "
                                   f"{fluid_density:g} kg/m^3; compressibility, friction and seal leakage left out")
    p_min = least_throttling_pressure(V0, fluid_density, discharge)
    sound = math.sqrt(bulk_modulus / fluid_density)
    mach = V0 / sound
    c.sizes += [("least pressure that can throttle", p_min, "Pa"), ("piston Mach number in the liquid", mach, "-"),
                ("water-hammer pressure rho c V0", fluid_density * sound * V0, "Pa")]
    if p_min > max_pressure:
        c.feasible = False
        c.reason = (f"no orifice can throttle {V0:.4g} m/s below {p_min / 1e6:.4g} MPa (rho V0^2 / (2 Cd^2)), above "
                    f"the {max_pressure / 1e6:.4g} MPa allowed")
        return c
    A = req.force / max_pressure
    F, m = req.force, req.mass
    stroke = constant_force_stroke(req)

    def pin_area(x):
        return metering_pin_area(x, A, F, m, V0, fluid_density, discharge)
    c.sizes += [("piston area", A, "m^2"), ("piston diameter", _circle_diameter(A), "m"),
                ("stroke (constant force)", stroke, "m")]
    for frac in (0.0, 0.25, 0.5, 0.75, 0.95):
        c.sizes.append((f"metering-pin orifice diameter at {frac:.0%} of the stroke",
                        _circle_diameter(pin_area(frac * stroke)), "m"))
    a0 = pin_area(0.0)
    # a fixed orifice of that size: m dv/dt = -k v^2, v(t) = V0 / (1 + A t / V0) (fixtures.md)
    v_after = V0 / (1.0 + req.peak * req.duration / V0)
    c.sizes += [("fixed orifice giving the peak at V0: diameter", _circle_diameter(a0), "m"),
                ("fixed orifice: speed left after the duration", v_after, "m/s")]
    swept = A * stroke
    c.sizes.append(("liquid heating if the swept volume takes the energy",
                    req.energy / (fluid_density * swept * heat_capacity), "K"))
    c.notes.append(f"a fixed orifice gives an initial-peak pulse: after {req.duration * 1e3:.4g} ms the article still "
                   f"moves at {v_after:.4g} m/s; a constant force (rectangle) needs the metering pin above")
    if req.shape not in CONSTANT_FORCE_SHAPES:
        c.notes.append(f"the metering pin above gives a rectangle; a {req.shape} needs the pin profile recomputed for "
                       f"that force history")
    if mach > INCOMPRESSIBLE_MACH:
        c.notes.append(f"the piston moves at Mach {mach:.2f} in the liquid: the water-hammer pressure "
                       f"{fluid_density * sound * V0 / 1e6:.4g} MPa exceeds quasi-steady orifice pressures, so the "
                       f"incompressible law is a first guess only; model the liquid's compressibility")
    return c


def split_cone(req: Requirement, half_angle: float, friction: float, yield_stress: float, modulus: float,
               elongation: float, ring_density: float) -> Concept:
    """A cone of half-angle alpha pushed into a clamp ring with Coulomb friction mu (phi = atan mu): axial to
    radial force tan(alpha + phi) loading, tan(alpha - phi) unloading; an axial travel z opens the ring by
    z tan(alpha).  An elastic ring opens at most sigma_y / E of its radius; a ring yielding in hoop tension
    carries a hoop force sigma_y A_r, a radial force 2 pi sigma_y A_r in all, up to its usable strain."""
    phi = math.atan(friction)
    c = Concept("split cone", f"rigid wedge, Coulomb friction mu = {friction:g}, clamp ring elastic-perfectly "
                              f"plastic in hoop tension; ring bending and the cone's own stiffness left out")
    if half_angle <= phi:
        c.feasible = False
        c.reason = (f"self-locking: the half-angle {math.degrees(half_angle):.3g} deg is at most the friction angle "
                    f"{math.degrees(phi):.3g} deg, so the cone does not push back while unloading")
        return c
    ratio_load = math.tan(half_angle + phi)
    restitution = math.sqrt(math.tan(half_angle - phi) / ratio_load)
    elastic_radius = req.stroke * math.tan(half_angle) * modulus / yield_stress
    radius = constant_force_stroke(req) * math.tan(half_angle) / elongation
    section = req.force / (2.0 * math.pi * yield_stress * ratio_load)
    c.sizes += [("axial / radial force, loading", ratio_load, "-"),
                ("axial / radial force, unloading", math.tan(half_angle - phi), "-"),
                ("restitution of an elastic ring", restitution, "-"),
                ("elastic ring radius for the stroke", elastic_radius, "m"),
                ("yielding ring radius for the constant-force stroke", radius, "m"),
                ("yielding ring section", section, "m^2"),
                ("yielding ring mass", ring_density * 2.0 * math.pi * radius * section, "kg")]
    c.notes.append(f"an elastic ring opens at most sigma_y / E = {yield_stress / modulus:.3g} of its radius: it would "
                   f"need a radius of {elastic_radius:.3g} m for the {req.stroke:.3g} m stroke, so the ring must "
                   f"yield (a plateau force, a rectangle-like pulse) or the cone work in stages")
    if req.shape not in CONSTANT_FORCE_SHAPES:
        c.notes.append(f"a yielding ring pushes back with a nearly constant force (a rectangle), not a {req.shape}")
    return c
