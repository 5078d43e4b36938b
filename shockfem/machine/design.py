"""The whole machine from the article and the pulse: fixture -> amplifier -> launcher -> layout, then
the operating loads and stresses on every component against its allowable, the totals, and what binds.

The order is the data flow: the pulse and the article fix the fixture (the dashpot and the striker's
mass and speed), the striker fixes the amplifier (its masses at the restitution its 1D model gives),
the first mass fixes the launcher, and the launcher's bore reshapes the first mass, with which the
chain is run once more in 1D to check the striker's speed.  Each step names its model in ``models``.
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import asdict, dataclass, field

from ..amplifier import rigid
from ..scene.library import initial_yield_stress, property_si
from ..units import G0, format_si
from .amplifier import Amplifier, check_with_first_mass, design_amplifier
from .fixture import Fixture, design_fixture
from .launcher import Launcher, design_launcher
from .layout import GUIDES_PER_BODY, Layout, place, rail_section, shoe_length
from .spec import REFERENCE_ARTICLE, MachineSpec


@dataclass
class Load:
    component: str
    load: str                   # what loads it, in words with its value
    stress: float               # [Pa]
    allowable: float            # [Pa]
    basis: str                  # the formula or model
    sized: bool = False         # the design set this stress to the allowable (its ratio is 1 by construction)

    @property
    def ratio(self) -> float:
        return self.stress / self.allowable


@dataclass
class Machine:
    spec: MachineSpec
    fixture: Fixture
    amplifier: Amplifier
    launcher: Launcher
    layout: Layout
    loads: list[Load]
    totals: dict
    binding: list[str]
    models: list[str]
    wall_time_s: float
    feasible: bool
    problems: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        spec = asdict(self.spec)
        return {"spec": spec, "fixture": self.fixture.as_dict(), "amplifier": self.amplifier.as_dict(),
                "launcher": self.launcher.as_dict(), "layout": self.layout.as_dict(),
                "loads": [{**asdict(ld), "ratio": ld.ratio} for ld in self.loads], "totals": self.totals,
                "binding": self.binding, "models": self.models, "wall_time_s": self.wall_time_s,
                "feasible": self.feasible, "problems": self.problems}


def final_speeds(spec: MachineSpec, amp: Amplifier) -> list[float]:
    """Each mass's speed once the rigid chain at the effective restitution has no gap closing."""
    chain = (rigid.launched_chain if spec.architecture == "launched-chain" else rigid.stack_on_anvil)
    return [abs(v) for v in chain(amp.masses, spec.launch_speed, amp.restitution).final]


def design_machine(spec: MachineSpec, out_dir: str, echo=None, starts: int = 3, fixture: Fixture | None = None
                   ) -> Machine:
    """The machine for ``spec``; ``fixture``: one designed already for the same article and pulse (the
    amplifier's and the launcher's choices do not change it), to try other architectures without it."""
    t0 = time.perf_counter()
    say = echo or (lambda *a: None)
    say(f"machine for {spec.article_mass:.4g} kg: the fixture (dashpot iterated on its lumped model)")
    fixture = fixture or design_fixture(spec, echo)
    say("  the amplifier (1D chain, effective restitution)")
    amp = design_amplifier(spec, fixture, os.path.join(out_dir, "amplifier_1d"), echo)
    say("  the launcher (lightest gun within the limits)")
    launcher = design_launcher(spec, amp.masses, starts)
    if amp.masses:
        say("  the chain again with the first mass as the launcher's slug")
        amp = check_with_first_mass(spec, fixture, amp, launcher.design.gun.bore,
                                    os.path.join(out_dir, "amplifier_1d"))
    rho = property_si(spec.material, "density", "density")
    Y = initial_yield_stress(spec.material)
    S = Y / spec.safety_factor
    layout = place(launcher, amp, fixture, rho, S, spec.catch, spec.material, final_speeds(spec, amp))
    loads = operating_loads(spec, fixture, amp, launcher, layout, S)
    totals = _totals(fixture, amp, launcher, layout)
    binding, problems = _binding(spec, fixture, amp, launcher, layout, loads)
    return Machine(spec, fixture, amp, launcher, layout, loads, totals, binding, models(spec),
                   time.perf_counter() - t0, not problems, problems)


def operating_loads(spec, fixture: Fixture, amp: Amplifier, launcher: Launcher, layout: Layout, S: float) -> list[Load]:
    """Every component's worst operating stress against its allowable."""
    out = []
    size = launcher.sizing
    P = size["design_pressure"]
    for part in ("barrel", "tank"):
        w = size[part]
        out.append(Load(f"launcher {part}", f"reservoir pressure {P / 1e6:.3g} MPa", w["hoop_stress"],
                        w["hoop_stress"] * (1 + w["margin"]),
                        f"Lame hoop stress at the bore; ASME VIII-1 {w['rule']} wall, {w['material']} allowable "
                        "(set by the design)", sized=True))
    g = launcher.design.gun
    base = launcher.projectile_mass * launcher.design.peak_acceleration / g.area
    out.append(Load("first mass in the barrel", f"peak launch acceleration {launcher.design.peak_acceleration / G0:,.0f} g",
                    base, S, "its inertia over the bore's area (the base pressure that drives it)"))
    for st in amp.stages:
        out.append(Load(f"pad {st.pair}", f"closing at {st.closing_speed:.1f} m/s", st.face_stress, S,
                        "rigid bodies on the pad: peak force dv sqrt(k M*) over the smaller load section "
                        "(set by the design)", sized=True))
        out.append(Load(f"interface {st.pair} (1D)", "the 1D chain's peak pad force", st.interface_stress_1d, S,
                        "1D run: the low-passed interface force over the smaller bar section"))
    for body, over in amp.peak_stress_over_yield.items():
        if "_" not in body:
            out.append(Load(f"{body} (1D)", "the chain's waves", over * amp.yield_stress, S,
                            "1D run: the largest axial stress in the bar"))
    f = fixture
    out.append(Load("striker housing wall", f"oil at {f.peak_pressure / 1e6:.0f} MPa", f.wall_hoop_stress, S,
                    "Lame hoop stress at the bore" + (" (the wall set the striker's mass)" if f.housing_binds else ""),
                    sized=f.housing_binds))
    out.append(Load("striker housing floor", f"oil at {f.peak_pressure / 1e6:.0f} MPa", f.floor_stress, S,
                    "clamped plate, 3 p r^2 / (4 t^2) at the edge (Roark 11.2 case 10b; set by the design)", sized=True))
    out.append(Load("piston", f"oil at {f.peak_pressure / 1e6:.0f} MPa", f.peak_pressure, S,
                    "the oil's pressure on its face, carried in compression"))
    a_Y = initial_yield_stress(REFERENCE_ARTICLE["library"])
    out.append(Load("article base", f"{f.peak / G0:,.0f} g", f.article_mass * f.peak / (math.pi * f.article_diameter ** 2 / 4),
                    a_Y / spec.safety_factor, "its mass times the pulse's peak over its base (the piston's face); "
                                              "4340's allowable"))
    for st in layout.stops:
        out.append(Load(f"stop of {st.body}", f"{st.mass:.4g} kg at {st.speed:.1f} m/s: {st.force / 1e6:.3g} MN over "
                                             f"{st.stroke:.3g} m", st.stress, S,
                        f"rho L a in the stopped body; deceleration: {st.limit}", sized="inertia" in st.limit))
    # the guides: each moving body's weight on its sliding shoes, as bearing pressure on the rails
    for it in layout.items:
        if it.kind in ("mass", "housing", "piston"):
            mass = it.mass + (fixture.liquid_mass if it.kind == "housing" else 0.0) + (
                fixture.article_mass if it.kind == "piston" else 0.0)
            area = rail_section(it.diameter) * shoe_length(it.diameter, it.length)
            out.append(Load(f"guide shoes of {it.name}", f"its weight {mass * G0 / 1e3:.3g} kN on {GUIDES_PER_BODY} shoes",
                            mass * G0 / (GUIDES_PER_BODY * area), S,
                            "bearing pressure on the rail (shoe and rail as drawn; a polymer wear strip's own limit "
                            "is lower and not modelled)"))
    out.append(Load("frame side members", f"the largest stop force {max(s.force for s in layout.stops) / 1e6:.3g} MN",
                    max(s.force for s in layout.stops) / (2 * layout.frame_section), S,
                    "two ties at the allowable (set by the design; bending and buckling left out)", sized=True))
    return out


def _totals(fixture, amp, launcher, layout) -> dict:
    items = layout.items
    mass = sum(i.mass for i in items)
    g = launcher.design.gun
    article_energy = 0.5 * fixture.article_mass * fixture.velocity_change ** 2
    return {
        "machine_mass": mass,
        "launcher_mass": launcher.design.weight, "amplifier_mass": sum(amp.masses[:-1]),
        "striker_mass": fixture.striker_mass, "payload_mass": fixture.payload_mass, "frame_mass": layout.frame_mass,
        "overall_length": layout.overall_length, "overall_width": layout.overall_width,
        "footprint": layout.overall_length * layout.overall_width,
        "gas_mass": launcher.gas_mass, "stored_energy": launcher.stored_energy,
        "launch_energy": launcher.launch_energy,
        "striker_energy": 0.5 * fixture.striker_mass * fixture.striker_speed ** 2,
        "article_energy": article_energy, "article_over_stored": article_energy / launcher.stored_energy,
        "reservoir_pressure": g.reservoir_pressure, "bore": g.bore, "barrel_travel": g.length,
        "oil_heating_per_shot": fixture.oil_heating,
        "energy_to_stops": sum(s.energy for s in layout.stops),
    }


def _binding(spec, fixture, amp, launcher, layout, loads) -> tuple[list[str], list[str]]:
    """What binds (limits reached, stresses at their allowable by design) and what fails (problems)."""
    binding, problems = [], []
    dimension = {"bore": "length", "length": "length", "reservoir_pressure": "pressure", "reservoir_volume": "volume"}
    for b in launcher.design.binding:
        binding.append(f"launcher: {b['variable'].replace('_', ' ')} at its limit {b['limit']} "
                       f"({format_si(b['value'], dimension[b['variable']])})")
    if not launcher.design.feasible:
        problems.append(f"launcher: {launcher.design.note}")
    if fixture.housing_binds:
        binding.append(f"fixture: the housing's wall (Lame at {fixture.peak_pressure / 1e6:.0f} MPa) sets the striker "
                       f"at {fixture.striker_ratio:.2f} times the payload, above the {spec.striker_ratio:g} asked")
    if not fixture.band_passed:
        problems.append("fixture: the lumped pulse is outside the specification's band")
    if not amp.feasible:
        problems.append(f"amplifier: {amp.reason}")
    for ld in loads:
        if ld.ratio > 1 + 1e-6:
            problems.append(f"{ld.component}: {ld.stress / 1e6:.4g} MPa over the allowable {ld.allowable / 1e6:.4g} MPa "
                            f"({ld.ratio:.2f})")
    longest = max((i for i in layout.items if i.kind not in ("frame", "rail")), key=lambda i: i.length)
    binding.append(f"length: the longest part is the {longest.name} ({longest.length:.3g} m of the "
                   f"{layout.overall_length:.3g} m)")
    binding += layout.notes
    return binding, problems


def models(spec: MachineSpec) -> list[str]:
    """Which model answered each part, and what it leaves out."""
    return [
        "fixture: the fluid dashpot's lumped model (two rigid masses, the lumped oil with the cavity's laws; "
        "`programmer.lumped_dashpot`), its metering pin iterated to the band; the bodies' elasticity and the oil's "
        "waves are left out (the fixture study's finite-element runs agree within 1%)",
        "housing: Lame thick cylinder and a clamped plate at the peak oil pressure",
        f"amplifier: the {spec.architecture} in 1D (`amplifier.bars`: elastic bars, pads as spring-dashpots, "
        "2% structural damping), its gain read as an effective restitution; lateral motion, friction on the guides "
        "and the pads' own mass left out",
        "launcher: the lumped gas gun (`launcher.gun`: valve, Lagrange gas inertia, air ahead) and ASME VIII-1 walls",
        "stops, guides and frame: closed forms (a bar stopped at one end, the weight on sliding shoes, ties); "
        "foundations, bolts and bending of the frame left out",
    ]
