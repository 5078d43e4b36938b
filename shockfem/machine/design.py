"""The whole machine from the article and the pulse: fixture -> amplifier -> launcher -> layout, then
the operating loads and stresses on every component against its allowable, every part's limits, the
energy of a shot, the totals, and what binds.

The verdict rests on ``limits`` (``machine.limits.Limit``): every stress against its part's own
allowable, the stops' absorbers' limits, the oil's heating, the largest part against what a road can
carry, and the amplifier's own (its pads', when it has them).  FEASIBLE only when all hold and every
part's model found a design; otherwise each broken limit is listed with its ratio.

The order is the data flow: the pulse and the article fix the fixture (the dashpot and the striker's
mass and speed), the striker fixes the amplifier (its masses at the effective restitution of its pads, each pad of a
real material and its restitution measured by the interface's finite-element run, the rigid chain
followed through every collision: ``machine.amplifier``), the first mass fixes the launcher, and the
launcher's bore reshapes the first mass, whose interface is measured again.  Each step names its model in ``models``.
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import asdict, dataclass, field

from ..scene.library import LIBRARY, initial_yield_stress, property_si
from ..units import G0, format_si
from .amplifier import Amplifier, chain_run, check_with_first_mass, design_amplifier
from .energy import EnergyTable, chain_record, energy_table
from .fixture import DESIGN_EVALUATIONS, Fixture, design_fixture
from ..launcher.vessel import max_pressure
from ..programmer.fixed_point import STRIKER_TOLERANCE
from .launcher import SIZING as LAUNCHER_SIZING, Launcher, design_launcher, muzzle_state
from .layout import GUIDES_PER_BODY, Layout, frame_force, place, rail_section, shoe_length
from .limits import Limit, broken, model_range
from .spec import REFERENCE_ARTICLE, MachineSpec
from .stops import OIL_TEMPERATURE_RISE, OIL_TEMPERATURE_SOURCE

# the largest single part a road carries without a special permit: Council Directive 96/53/EC (2.55 m wide,
# 40 t gross), on a standard semi-trailer's 13.6 m deck with about 24 t of payload; the frame and the rails
# are sectioned and joined on site, and the tank's volume may be a bank of vessels piped together (the same
# steel for the same p V), so none of them is a single part
TRANSPORT = {"length": 13.6, "width": 2.55, "mass": 24e3}
TRANSPORT_SOURCE = ("Council Directive 96/53/EC (2.55 m wide, 40 t gross); the 13.6 m deck and about 24 t of "
                    "payload derived from a standard semi-trailer, not set by the Directive")
SECTIONED = ("frame", "rail", "tank")
# the launcher and the slug's chain are designed in turn until the gun fires the chain's first mass (to
# this share of it)
SLUG_PASSES, SLUG_TOL = 4, 1e-9


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
    limits: list[Limit]
    energy: EnergyTable
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
                "loads": [{**asdict(ld), "ratio": ld.ratio} for ld in self.loads],
                "limits": [lim.as_dict() for lim in self.limits], "broken": [lim.as_dict() for lim in broken(self.limits)],
                "energy": self.energy.as_dict(), "totals": self.totals,
                "binding": self.binding, "models": self.models, "wall_time_s": self.wall_time_s,
                "feasible": self.feasible, "problems": self.problems}


def record_of(spec: MachineSpec, amp: Amplifier):
    """The chain's energies and final speeds (``energy.chain_record``) from the amplifier as designed: the
    rigid chain at each interface's own restitution (measured by its pad's run, or its material's estimate
    where the run was not made), every collision followed."""
    result = chain_run(spec, amp.masses, amp.bodies, amp.restitutions)
    words = ", ".join(f"{st.pair} {st.restitution:.4f} ({'measured' if st.measured else 'estimate'})"
                      for st in amp.stages)
    return chain_record(amp.masses, [b["name"] for b in amp.bodies], spec.launch_speed, spec.architecture, result,
                        f"the rigid chain at the pads' restitutions: {words}")


def design_machine(spec: MachineSpec, out_dir: str, echo=None, starts: int = 3, fixture: Fixture | None = None,
                   evaluations: int = DESIGN_EVALUATIONS) -> Machine:
    """The machine for ``spec``; ``fixture``: one designed already for the same article and pulse (the
    amplifier's and the launcher's choices do not change it), to try other architectures without it;
    else designed with its column search at ``evaluations`` runs at most (``fixture.design_fixture``)."""
    t0 = time.perf_counter()
    say = echo or (lambda *a: None)
    say(f"machine for {spec.article_mass:.4g} kg: the fixture (dashpot iterated on its liquid column)")
    fixture = fixture or design_fixture(spec, echo, evaluations)
    say(f"  the amplifier (pads of real materials, restitutions from their finite-element runs at "
        f"'{spec.pad_resolution}', the rigid chain through every collision)")
    amp = design_amplifier(spec, fixture, os.path.join(out_dir, "amplifier"), echo)
    say("  the launcher (lightest gun within the limits)")
    launcher = design_launcher(spec, amp.masses, starts)
    for _ in range(SLUG_PASSES):
        # a gun that cannot fire the first mass has no slug to shape it to: the chain stays as designed
        if not amp.masses or not launcher.design.feasible:
            break
        say("  the chain again with the first mass as the launcher's slug")
        amp = check_with_first_mass(spec, fixture, amp, launcher.design.gun.bore,
                                    os.path.join(out_dir, "amplifier"))
        if not amp.masses or abs(amp.masses[0] / launcher.projectile_mass - 1) <= SLUG_TOL:
            break
        # the slug's chain asks another first mass: the gun is designed again for it
        say("  the launcher again for the slug's first mass")
        launcher = design_launcher(spec, amp.masses, starts)
    rho = property_si(spec.material, "density", "density")
    Y = initial_yield_stress(spec.material)
    S = Y / spec.safety_factor
    record = record_of(spec, amp) if amp.masses else None
    speeds = [record.final_speeds[b["name"]] for b in amp.bodies] if record else []
    layout = place(launcher, amp, fixture, rho, S, spec.catch, spec.material, speeds, spec.oil_pressure,
                   gun_thrust(launcher), muzzle_state(launcher.design.gun).push)
    loads = operating_loads(spec, fixture, amp, launcher, layout, S)
    limits = part_limits(spec, fixture, amp, layout, loads) + stored_gas_limits(launcher)
    energy = energy_table(launcher, amp, fixture, layout.stops, record)
    totals = _totals(fixture, amp, launcher, layout, energy)
    binding, problems = _binding(spec, fixture, amp, launcher, layout, limits)
    return Machine(spec, fixture, amp, launcher, layout, loads, limits, energy, totals, binding, models(spec),
                   time.perf_counter() - t0, not problems, problems)


def gun_thrust(launcher: Launcher) -> float:
    """The gun's peak force on its projectile [N]: its mass times its peak acceleration (the frame carries it
    back to the breech; no stop need ask more)."""
    return launcher.projectile_mass * launcher.design.peak_acceleration


def _allowable_source(load: Load, spec: MachineSpec) -> str:
    """Where a load's allowable comes from."""
    if load.component.startswith("launcher"):
        return "ASME VIII-1 allowable of the vessel's steel"
    if load.component.startswith("striker housing"):
        return "ASME BPVC VIII-2 design stress of the housing steel (`programmer.housing`)"
    name = REFERENCE_ARTICLE["library"] if load.component == "article base" else spec.material
    return f"{name} yield / {spec.safety_factor:g} ({LIBRARY[name]['source'].split(';')[0]})"


def part_limits(spec: MachineSpec, fixture: Fixture, amp: Amplifier, layout: Layout, loads: list[Load]
                ) -> list[Limit]:
    """Every part's limits: each load's stress against its allowable, the stops' absorbers', the fixture's
    (its column run inside its laws' ranges, its housing), the oil's heating a shot, the largest single part
    against the road's envelope, and the amplifier's own."""
    out = [Limit(ld.component, "stress", ld.stress, ld.allowable, "Pa", f"{ld.basis} ({ld.load})",
                 _allowable_source(ld, spec), ld.sized) for ld in loads]
    for st in layout.stops:
        out += st.limits
    out += list(fixture.limits)
    out.append(Limit("dashpot oil", "temperature rise a shot", fixture.oil_heating, OIL_TEMPERATURE_RISE, "K",
                     "the energy the orifice throttles kept by the oil", OIL_TEMPERATURE_SOURCE))
    parts = [i for i in layout.items if i.kind not in SECTIONED]
    longest = max(parts, key=lambda i: i.length)
    widest = max(parts, key=lambda i: i.diameter)
    heaviest = max(parts, key=lambda i: i.mass)
    out += [Limit(f"{longest.name} (the longest part)", "length for transport", longest.length, TRANSPORT["length"],
                  "m", "its length on the axis", TRANSPORT_SOURCE),
            Limit(f"{widest.name} (the widest part)", "width for transport", widest.diameter, TRANSPORT["width"], "m",
                  "its outer diameter", TRANSPORT_SOURCE),
            Limit(f"{heaviest.name} (the heaviest part)", "mass for transport", heaviest.mass, TRANSPORT["mass"], "kg",
                  "its mass", TRANSPORT_SOURCE)]
    # the amplifier's own limits (its pads', when the amplifier carries them)
    out += list(getattr(amp, "limits", []))
    return out


def stored_gas_limits(launcher: Launcher) -> list[Limit]:
    """The vessel that stores the gun's gas: its pressure within the range of the ASME VIII-1 rule its heads
    are sized by (UG-32(f), P <= 0.665 S E: ``launcher.vessel.max_pressure``; the shell's rules reach
    further); its walls and mass are ``launcher.vessel``'s (the loads' launcher tank).  The gas's stored
    energy is reported (the premise's table gives its TNT equivalent); no code sets a limit on it."""
    material = LAUNCHER_SIZING.tank_material
    return [Limit("launcher tank", "reservoir pressure within the head rule's range",
                  launcher.design.gun.reservoir_pressure, max_pressure(material, LAUNCHER_SIZING.joint_efficiency),
                  "Pa", f"the reservoir's pressure; {material} hemispherical heads", "ASME VIII-1 UG-32(f)'s range: "
                  "P <= 0.665 S E")]


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
    # (the pad's sized peak force on the steel face is its stage's ``face`` limit, ``pads.size_pad``, against
    # the same allowable: not counted a second time here; nor is it set to the allowable by the design)
    for st in amp.stages:
        if st.measured:
            out.append(Load(f"interface {st.pair} (FE)", "the pad run's peak contact force", st.interface_stress, S,
                            "the interface's finite-element run: peak contact force over the smaller load section"))
    # (each body's peak von Mises stress in its pad runs is its stage's limit, ``Amplifier.limits``: not
    # counted a second time here)
    f = fixture
    basis = f"{f.housing_steel}'s ASME VIII-2 design stress"
    out.append(Load("striker housing wall", f"oil at {f.peak_pressure / 1e6:.0f} MPa (the column's peak)", f.wall_stress,
                    f.allowable, "ASME VIII-2 4.3.3 at the peak times its dynamic factor: S P / (S ln Y) at the "
                    "wall's ratio Y; " + basis + (" (the wall set the striker's mass)" if f.housing_binds else ""),
                    sized=f.housing_binds and f.wall_stress <= f.allowable * (1 + 1e-9)))
    out.append(Load("striker housing floor", "the column's floor pressure", f.floor_stress, f.allowable,
                    "ASME VIII-2 4.6 integral flat head at the peak times its dynamic factor (set by the design); "
                    + basis, sized=True))
    out.append(Load("piston", f"oil at {f.peak_pressure / 1e6:.0f} MPa", f.peak_pressure, S,
                    "the oil's pressure on its face, carried in compression"))
    a_Y = initial_yield_stress(REFERENCE_ARTICLE["library"])
    out.append(Load("article base", f"{f.peak / G0:,.0f} g", f.article_mass * f.peak / (math.pi * f.article_diameter ** 2 / 4),
                    a_Y / spec.safety_factor, "its mass times the pulse's peak over its base (the piston's face); "
                                              "4340's allowable"))
    for st in layout.stops:
        out.append(Load(f"stop of {st.body}", f"{st.mass:.4g} kg at {st.speed:.1f} m/s: {st.force / 1e6:.3g} MN peak "
                                             f"over {st.stroke:.3g} m ({st.kind})", st.stress, S,
                        f"rho L a in the stopped body at the peak; allowed force: {st.limit}",
                        sized=st.stress >= S * (1 - 1e-6)))
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
    out.append(frame_load(launcher, layout, S))
    return out


def frame_load(launcher: Launcher, layout: Layout, S: float) -> Load:
    """The frame's side members under the larger of the largest stop force and the gun's recoil at firing
    (``layout.frame_force``), two ties."""
    stops, recoil = max(s.force for s in layout.stops), gun_thrust(launcher)
    F = frame_force(layout.stops, recoil)
    return Load("frame side members", f"the largest stop force {stops / 1e6:.3g} MN, the gun's recoil "
                                      f"{recoil / 1e6:.3g} MN", F / (2 * layout.frame_section), S,
                "two ties at the allowable under the larger (set by the design; bending and buckling left out)",
                sized=True)


def _totals(fixture, amp, launcher, layout, energy: EnergyTable) -> dict:
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
        "gas_work": energy.gas_work, "energy_closure": energy.closure,
        "stops_mass": sum(s.absorber_mass for s in layout.stops),
        "stops_length": sum(s.length for s in layout.stops),
        "consumed_per_shot": sum(s.consumed for s in layout.stops),
    }


def _binding(spec, fixture, amp, launcher, layout, limits: list[Limit]) -> tuple[list[str], list[str]]:
    """What binds (limits reached, stresses at their allowable by design) and what fails (problems: a
    model that found no design, and every broken limit with its ratio, the worst first)."""
    binding, problems = [], []
    dimension = {"bore": "length", "length": "length", "reservoir_pressure": "pressure", "reservoir_volume": "volume"}
    for b in launcher.design.binding:
        binding.append(f"launcher: {b['variable'].replace('_', ' ')} at its limit {b['limit']} "
                       f"({format_si(b['value'], dimension[b['variable']])})")
    if not launcher.design.feasible:
        problems.append(f"launcher: {launcher.design.note}")
    if fixture.housing_binds:
        binding.append(f"fixture: the housing (ASME VIII-2 at the column's {fixture.peak_pressure / 1e6:.0f} MPa peak, "
                       "over the whole bore) sets the striker "
                       f"at {fixture.striker_ratio:.2f} times the payload, above the {spec.striker_ratio:g} asked "
                       f"(wall outer radius {fixture.housing_wall_radius * 1e3:.1f} mm, b / a "
                       f"{fixture.housing_wall_radius / fixture.bore_radius:.3g})")
    fp = fixture.design["column_design"]["striker_fixed_point"]
    if fp["needed"] > fp["ratio"] * (1 + STRIKER_TOLERANCE):
        problems.append(f"fixture: the striker ({fp['ratio']:.4g} times the payload) does not carry its housing "
                        f"({fp['needed']:.4g}): its fixed point did not converge in {fp['redesigns']} redesigns")
    if not fixture.band_passed:
        problems.append(f"fixture: the column's pulse is outside the specification's band (worst excess "
                        f"{fixture.worst_excess:.3g} of the peak)")
    if not amp.feasible:
        problems.append(f"amplifier: {amp.reason}")
    for lim in broken(limits):
        problems.append(f"{lim.component}: {lim.quantity} {lim.value:.4g} {lim.unit} against {lim.limit:.4g} "
                        f"{lim.unit}, over by {100 * (lim.ratio - 1):.0f}% ({lim.source})"
                        + (": a model outside its range, a finer model must check the part" if model_range(lim) else ""))
    longest = max((i for i in layout.items if i.kind not in ("frame", "rail")), key=lambda i: i.length)
    binding.append(f"length: the longest part is the {longest.name} ({longest.length:.3g} m of the "
                   f"{layout.overall_length:.3g} m)")
    binding += layout.notes
    return binding, problems


def models(spec: MachineSpec) -> list[str]:
    """Which model answered each part, and what it leaves out."""
    return [
        "fixture: the fluid dashpot designed on the compressible liquid column (two rigid masses, the oil as a 1D "
        "column of finite volumes, Idelchik's sharp-edged orifice with the velocity of approach and the jet's "
        "reaction; `programmer.column_design`), its bore, column, pin and striker's speed iterated to the band; its "
        "vetoing validity checks (area ratio, the coefficient's velocity-change error, piston Mach number, parting, "
        "freezing) and its housing's (wall ratio within Y_max, the pin's stress, the floor's range) are machine "
        "limits; the bodies' elasticity, friction on the bore and liquid returning through the orifice are left out",
        "housing: ASME VIII-2 4.3.3's wall (P = S ln Y) and 4.6's integral flat head at the column's peak "
        "pressures times their dynamic factors (`programmer.housing`)",
        f"amplifier: the {spec.architecture}'s masses by the closed form (`amplifier.gain.design`) at an effective "
        "restitution; each interface's pad of a real material sized within its limits (`machine.pads`), its "
        "restitution measured by the interface's axisymmetric finite-element run (the two bodies at their sizes, "
        f"steel J2, the pad's own law; meshes '{spec.pad_resolution}', `pads.RESOLUTIONS`; a run past the budget, or "
        "the 'estimate' resolution, keeps its material's estimate, an upper bound), and the rigid chain of those "
        "restitutions followed through every collision for the gain, iterated until the effective e settles "
        "(`machine.amplifier`); the pads' own mass, waves running from one interface's run into the next, "
        "lateral motion and friction on the guides are left out",
        "launcher: the lumped gas gun (`launcher.gun`: valve, Lagrange gas inertia, air ahead) and ASME VIII-1 walls",
        "stops: absorbers by closed forms (`machine.stops`: a constant-force hydraulic buffer, or an aluminium "
        "honeycomb crushed at its steady-shock stress), each at the force the stopped body's inertia allows",
        "guides and frame: closed forms (the weight on sliding shoes, ties); foundations, bolts and bending of the "
        "frame left out",
        "energy: the gun's own accounts, the designed chain's collisions at its pads' restitutions, the "
        "fixture's column run (`machine.energy`)",
    ]
