"""The velocity amplifier that brings the striker (the fixture's housing) to its speed, on pads of real
materials whose restitutions its own finite-element runs measure.

The masses are the closed form's (``amplifier.gain.design``: geometric ratios, the striker last) at an
effective restitution e.  For each interface (the two bodies at their sizes, closing at the rigid
chain's first-pass speed) every pad material of the library (``pad_materials``) is sized within its
limits (``pads.size_pad``); the pad chosen is the one with the highest restitution estimate among those
that keep every limit, or, when none does, the elastomer that breaks its limits least (a crushed metal
disc or bare steel returns too little of the energy for any gain: at e = 0.3, five masses give 2.9 at
most), carried with its broken limits.  Each chosen interface then runs in finite elements
(``pads.RunCache.measure_within_limits``, cached: an elastomer resized on its run until the run's
own peak stress is within its working stress), which gives its restitution (a run past ``pads.MAX_WORK`` is not made: its
pad, many times past its slenderness, keeps its material's estimate, ``Stage.measured`` False); the rigid
chain of those restitutions, every collision
followed (``amplifier.rigid.run_chain``), gives the gain, the gain the effective e (the one e with
which the rigid chain of these masses gains as much), and the masses are designed again at that e
until it settles (E_TOL) or the gain cannot be had with the masses given.

The first mass is a cylinder L = D until the launcher is known; ``check_with_first_mass`` measures the
first interface again with the first mass as the slug that fits the launcher's bore.  Each interface's
checks are ``Limit``s, gathered in ``Amplifier.limits`` (the FE run's peak von Mises stress in the
steel bodies among them).  Range of validity: the rigid chain leaves the pads' own mass out (each pad's
``mass over the struck body's`` limit keeps it small) and the bodies' lateral motion and friction on
their guides; the runs' restitutions are those of the spec's ``pad_resolution`` (smoke meshes unless
it says otherwise, ``pads.RESOLUTIONS``).
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import asdict, dataclass, field, replace

from scipy.optimize import brentq

from ..amplifier import rigid
from ..amplifier.gain import cylinder_size, design
from ..programmer.housing import HOUSING_STEELS
from ..scene.library import initial_yield_stress, property_si
from .fixture import Fixture
from .limits import Limit, broken
from .pad_materials import PAD_MATERIALS
from .pads import (PAD_MASS_SHARE, Interface, Measured, PadDesign, Resizing, RunCache, estimated_restitution,
                   pad_contact_stress, size_pad, solid_pads)
from .spec import MachineSpec

ASPECT = 1.0                # the intermediate masses' length over diameter
STRUCTURAL_DAMPING = 0.02
# the effective restitution settles when an iteration moves it by less than this: the coarse runs'
# restitutions move by some 0.005 when the geometry moves by a rounding (``pads.FIGURES``)
E_TOL, MAX_ITERATIONS = 5e-3, 6
# the masses are solved, at the measured restitutions, within this of the iterations' last e
SOLVE_SPAN = 0.1
# a stage's struck body moves about this share of v tau before its pad lets go (the amplifier study's
# sequenced gaps)
SEQUENCED = 0.6
MIN_GAP = 1e-3


@dataclass
class Stage:
    pair: str
    closing_speed: float        # rigid chain at the effective restitution [m/s]
    pad_material: str           # ``pad_materials.PAD_MATERIALS``
    pad_kind: str
    pad_stiffness: float        # its secant, peak force over travel (rigid bodies) [N/m]
    pad_travel: float           # [m]
    pad_thickness: float        # free [m]
    pad_diameter: float         # free [m] (0: no pad)
    pad_mass: float             # [kg]
    pad_energy: float           # M* dv^2 / 2 [J]
    contact_duration: float     # estimated [s]
    load_section: float         # the smaller of the two bodies' faces [m^2]
    face_stress: float          # the pad's peak force (rigid bodies) over it [Pa]
    interface_stress: float     # the FE run's peak contact force over it [Pa]
    restitution: float          # the FE run's
    run: str                    # its directory
    run_wall_time_s: float
    measured: bool = True       # its restitution from its run (False: the material's estimate, ``note``)
    note: str = ""
    limits: list = field(default_factory=list)          # of Limit
    alternatives: list = field(default_factory=list)    # every material sized here: material, worst ratio
    resizing: dict = field(default_factory=dict)        # ``pads.Resizing``: its sizes and runs


@dataclass
class Amplifier:
    architecture: str
    masses: list[float]                   # [kg], the striker last
    bodies: list[dict]                    # name, shape, diameter, length (the striker: the housing)
    launch_speed: float                   # [m/s]
    target_speed: float                   # the striker's [m/s]
    restitution: float                    # the effective e the masses are designed at
    iterations: list[dict]                # e assumed -> measured e per interface -> gain -> effective e
    gain: float                           # rigid chain at the measured restitutions
    striker_speed: float                  # [m/s]
    gaps: list[float]                     # before each pad [m]
    stages: list[Stage]
    peak_stress_over_yield: dict          # FE runs: each steel body's peak von Mises over yield
    yield_stress: float                   # [Pa]
    wall_time_s: float                    # the pad runs' (cache hits cost nothing)
    feasible: bool = True
    reason: str = ""
    runs: list[str] = field(default_factory=list)   # the pad runs' directories
    limits: list = field(default_factory=list)      # every stage's Limit
    cache: dict = field(default_factory=dict)       # the run cache's folder, hits and misses
    # why the masses themselves failed (no chain of them makes the gain), apart from the checks ``reason``
    # adds on the chain designed (its speed, its pads' limits)
    design_reason: str = ""
    # the first check's findings (``pad_bound``): an interface where no pad material holds its limits
    pad_bounds: list = field(default_factory=list)

    @property
    def restitutions(self) -> list[float]:
        return [st.restitution for st in self.stages]

    def as_dict(self) -> dict:
        out = asdict(self)
        out["limits"] = [lim.as_dict() for lim in self.limits]
        for st, raw in zip(self.stages, out["stages"]):
            raw["limits"] = [lim.as_dict() for lim in st.limits]
        out["restitutions"] = self.restitutions
        return out


def _bodies(masses, fixture: Fixture, rho: float, first_diameter: float | None) -> list[dict]:
    """The chain's bodies: cylinders (the first of ``first_diameter`` if given), the striker the housing."""
    out = []
    for k, m in enumerate(masses[:-1]):
        if k == 0 and first_diameter:
            d = first_diameter
            size = {"diameter": d, "length": m / (rho * math.pi * d * d / 4)}
        else:
            size = cylinder_size(m, rho, ASPECT)
        out.append({"name": f"m{k + 1}", "shape": "cylinder", **size})
    out.append({"name": "striker", "shape": "carrier", "diameter": 2 * fixture.housing_outer_radius,
                "length": fixture.housing_length, "bore": 2 * fixture.bore_radius, "bore_depth": fixture.bore_depth})
    return out


def load_section(body: dict) -> float:
    """The section that carries a face's force [m^2]: a cylinder's face, the housing's wall (its bore is
    open on the struck side's far end, so the floor's force runs down the wall)."""
    return math.pi * (body["diameter"] ** 2 - body.get("bore", 0.0) ** 2) / 4


def _face_diameter(body: dict) -> float:
    """The diameter of the solid face a pad bears on: a cylinder's; the housing's wall as a disc of the
    same section (its floor closes the bore on the struck side)."""
    return math.sqrt(4 * load_section(body) / math.pi)


def interfaces(spec: MachineSpec, masses, bodies, e: float) -> list[Interface]:
    """The chain's interfaces at the rigid chain's first-pass closing speeds at restitution ``e``."""
    dvs = rigid.first_closing_speeds(masses, spec.launch_speed, e, spec.architecture)
    allowable = initial_yield_stress(spec.material) / spec.safety_factor
    return [Interface(f"{bodies[k]['name']}_{bodies[k + 1]['name']}", masses[k], _face_diameter(bodies[k]),
                      bodies[k]["length"], masses[k + 1], _face_diameter(bodies[k + 1]), bodies[k + 1]["length"],
                      dv, spec.material, allowable) for k, dv in enumerate(dvs)]


def choose_pad(iface: Interface, materials=tuple(PAD_MATERIALS)) -> tuple[PadDesign, list[dict]]:
    """The pad for ``iface`` (module docstring) and every material's sized pad as (material, worst limit
    ratio, estimated restitution)."""
    sized = [(size_pad(iface, m, estimated_restitution(m, iface)), estimated_restitution(m, iface)) for m in materials]
    table = [{"material": p.material, "worst": p.worst, "estimated_restitution": e,
              "broken": [f"{lim.quantity} {lim.ratio:.3g}x" for lim in broken(list(p.limits))]} for p, e in sized]
    holding = [(p, e) for p, e in sized if p.feasible]
    if holding:
        return max(holding, key=lambda pe: pe[1])[0], table
    elastomers = [(p, e) for p, e in sized if p.kind == "elastomer"] or sized
    return min(elastomers, key=lambda pe: pe[0].worst)[0], table


def chain_run(spec: MachineSpec, masses, bodies, e: list[float]) -> rigid.ChainResult:
    """The rigid chain of ``masses`` with restitution e[k] at interface k, every collision followed
    (``rigid.designed_chain``: a stack falls on an anvil of the chain's mean restitution)."""
    return rigid.designed_chain(masses, spec.launch_speed, e, [b["length"] for b in bodies], MIN_GAP,
                                spec.architecture)


def _chain_gain(spec: MachineSpec, masses, bodies, e: list[float]) -> float:
    """The gain of ``chain_run``: the striker's final speed over the launch speed."""
    return abs(chain_run(spec, masses, bodies, e).final[-1]) / spec.launch_speed


def _gaps(spec: MachineSpec, masses, e: float, stages: list[Stage]) -> list[float]:
    """Launched chain: body k + 1 moves about SEQUENCED v tau while pad k is loaded; the gap after it lets
    that stage end before the next begins."""
    if spec.architecture != "launched-chain":
        return [MIN_GAP] * len(stages)
    speeds = rigid.launched_chain(masses, spec.launch_speed, e).first_pass
    return [MIN_GAP] + [max(MIN_GAP, SEQUENCED * speeds[k + 1] * stages[k].contact_duration)
                        for k in range(len(stages) - 1)]


def _stage(iface: Interface, pad: PadDesign, m: Measured, table: list[dict], allowable: float,
           resizing: Resizing) -> Stage:
    measured = [Limit(f"body {'striker' if body == 'a' else 'struck'} of {iface.name}", "stress (FE, von Mises)",
                      over * initial_yield_stress(iface.steel), allowable, "Pa",
                      "the interface's finite-element run: the body's peak von Mises stress",
                      f"{iface.steel}: yield / safety factor") for body, over in m.peak_stress_over_yield.items()]
    mat = PAD_MATERIALS[pad.material]
    if m.ran and mat.kind == "gas spring":
        # the sleeve is sized at the isentrope's peak; the column's shocks raise it at the closed end
        measured.append(Limit(f"pad {iface.name}", "sleeve pressure (gas column run)", m.peak_interface_stress,
                              pad.peak_force / iface.face_area, "Pa", "the gas column's run: its peak at the closed end",
                              "the sleeve's design pressure, p1 = gas_spring.PEAK_SHARE of the allowable"))
    if m.ran and pad.diameter > 0 and mat.working_stress > 0:
        # the pad's own stress in its run (the final size's: ``pads.RunCache.measure_within_limits``)
        measured.append(Limit(f"pad {iface.name}", "stress (FE contact)", pad_contact_stress(iface, pad, m),
                              mat.working_stress, "Pa", "the interface's finite-element run: the peak contact force "
                              "over the pad's free face", f"{mat.name}: working stress ({mat.source})"))
    k = pad.peak_force / pad.travel if pad.travel else 0.0
    return Stage(iface.name, iface.speed, pad.material, pad.kind, k, pad.travel, pad.thickness, pad.diameter,
                 pad.mass, pad.energy, pad.contact_time, iface.face_area, pad.peak_force / iface.face_area,
                 m.peak_interface_stress, m.restitution, m.run, m.wall_time_s, m.ran,
                 "; ".join(w for w in (m.note, resizing.verdict) if w), list(pad.limits) + measured, table,
                 resizing.as_dict())


def pad_bound(iface: Interface) -> str:
    """The first check of an interface, closed forms only: "" when some material's pad keeps every limit
    there, else why none does.  A pad that holds M* dv^2 / 2 at its material's working energy per volume w
    weighs rho dv^2 / (2 w) m_a / (m_a + m_b) times the struck body whatever the bodies' size, so its mass
    share goes as dv^2 and stays within ``PAD_MASS_SHARE`` only below a speed (``share_speed``); bare
    steel faces stay at the allowable only below dv S / stress (the 1D impedance stress goes as dv)."""
    sized = {m: size_pad(iface, m, estimated_restitution(m, iface)) for m in PAD_MATERIALS}
    if any(p.feasible for p in sized.values()):
        return ""
    words = []
    padded = [(p.mass / iface.struck_mass, m) for m, p in sized.items() if p.mass > 0]
    if padded:
        share, m = min(padded)
        words.append(f"the lightest pad ({m}) weighs {share:.3g} times the struck body (at most "
                     f"{PAD_MASS_SHARE:g}: below {share_speed(iface, m):.4g} m/s)")
    bare = sized.get("none")
    if bare is not None:
        face = next((lim for lim in bare.limits if lim.component.startswith("face")), None)
        if face is not None and face.ratio > 1:
            words.append(f"bare steel faces reach {face.ratio:.3g} times the allowable (within it below "
                         f"{iface.speed / face.ratio:.3g} m/s)")
    return f"{iface.name} closing at {iface.speed:.4g} m/s: no pad material holds its limits: " + "; ".join(words)


def share_speed(iface: Interface, material: str) -> float:
    """The closing speed [m/s] at which the pad of ``material`` sized on ``iface`` weighs ``PAD_MASS_SHARE``
    of the struck body (about dv sqrt(limit / share): an elastomer's share goes as dv^2 at its fixed
    working point, a crushed disc's nearly so), root-found on the sizing itself."""
    def over(v):
        return size_pad(replace(iface, speed=v), material).mass / iface.struck_mass - PAD_MASS_SHARE
    if over(iface.speed) <= 0:
        return iface.speed
    return float(brentq(over, 1e-6 * iface.speed, iface.speed, xtol=1e-9, rtol=1e-10))


def _measure(spec, masses, bodies, e: float, cache: RunCache, resolution: str, echo,
             bounds: list[str] | None = None, materials=tuple(PAD_MATERIALS)) -> list[Stage]:
    """Each interface's pad chosen among ``materials`` and measured; where the first check (``pad_bound``) finds that no
    material holds its limits at some interface, no pad is run at all (each keeps its material's estimate,
    the square root of its rebound resilience) and ``bounds`` gets the reasons."""
    allowable = initial_yield_stress(spec.material) / spec.safety_factor
    stages = []
    faces = interfaces(spec, masses, bodies, e)
    why = [w for w in (pad_bound(i) for i in faces) if w]
    if bounds is not None:
        bounds[:] = why
    if why:
        resolution = "estimate"
    for iface in faces:
        pad, table = choose_pad(iface, materials)
        m, pad, resizing = cache.measure_within_limits(iface, pad.material, resolution)
        stages.append(_stage(iface.rounded(), pad, m, table, allowable, resizing))
        if echo:
            echo(f"    {iface.name}: {pad.material} at {iface.speed:.4g} m/s -> e = {m.restitution:.4f} "
                 + (f"({'cached' if m.cached else 'run'}, {m.elements} cells, {m.steps} steps, "
                    f"{m.wall_time_s:.3g} s)" if m.ran else f"({m.note})")
                 + (f"; {resizing.verdict}" if resizing.verdict else ""))
    return stages


def design_amplifier(spec: MachineSpec, fixture: Fixture, out_dir: str, echo=None, resolution: str | None = None,
                     cache_dir: str | None = None, first_diameter: float | None = None, start: float | None = None,
                     iterations: list | None = None) -> Amplifier:
    """The amplifier for the fixture's striker (module docstring); the pad runs in ``cache_dir`` (default
    ``out_dir/pad_runs``) at ``resolution`` (``pads.RESOLUTIONS``; default the spec's ``pad_resolution``);
    the first mass a cylinder of ``first_diameter`` if given (the launcher's slug), the effective e
    iterated from ``start`` (default the best pad material's estimate), ``iterations`` the record so far."""
    resolution = resolution or spec.pad_resolution
    rho = property_si(spec.material, "density", "density")
    Y = initial_yield_stress(spec.material)
    V, M = fixture.striker_speed, fixture.striker_mass
    cache = RunCache(cache_dir or os.path.join(out_dir, "pad_runs"))
    # a gas spring's estimate depends on its interface: the start is the solid pads' best
    e = start or max(estimated_restitution(m) for m in solid_pads())
    iterations, last, t0, bounds = list(iterations or []), None, time.perf_counter(), []
    for it in range(MAX_ITERATIONS):
        d = design(spec.architecture, M, V, spec.launch_speed, e, spec.masses)
        if not d.feasible:
            reason = d.reason + (" (the measured restitutions)" if iterations else "")
            return _infeasible(spec, last, e, iterations, V, Y, cache, reason, t0)
        bodies = _bodies(d.masses, fixture, rho, first_diameter)
        stages = _measure(spec, d.masses, bodies, e, cache, resolution, echo, bounds)
        gain = _chain_gain(spec, d.masses, bodies, [st.restitution for st in stages])
        e_eff = rigid.effective_restitution(d.masses, spec.launch_speed, gain, spec.architecture)
        iterations.append({"assumed": e, "measured": [st.restitution for st in stages], "gain": gain,
                           "effective": e_eff, "striker_speed": gain * spec.launch_speed, "first_mass": d.masses[0],
                           "pads": [st.pad_material for st in stages]})
        last = (d.masses, bodies, stages, gain)
        if echo:
            echo(f"  amplifier: e = {e:.4f} -> measured " + ", ".join(f"{st.restitution:.3f}" for st in stages)
                 + f" -> gain {gain:.4f} -> effective e {e_eff:.4f}")
        if not math.isfinite(e_eff):
            return _infeasible(spec, last, e, iterations, V, Y, cache,
                               f"no restitution in (0, 1] gives the rigid chain the gain {gain:.4g}", t0)
        if abs(e_eff - e) < E_TOL:
            break
        e = e_eff
    e, last = _to_speed(spec, fixture, rho, first_diameter, e, last)
    out = _amplifier(spec, last, e, iterations, V, Y, cache, t0,
                     "; ".join(bounds) + (": no pad was run, each interface at its material's estimate" if bounds else ""))
    out.pad_bounds = bounds
    return out


def _to_speed(spec: MachineSpec, fixture: Fixture, rho: float, first_diameter: float | None, e: float, last):
    """The masses designed at the e (near the iterations' last) at which the rigid chain at the stages'
    restitutions, as measured, brings the striker to the fixture's speed exactly: the restitutions used
    for the chain are the ones its energy and its speed are counted with (the stages were measured at
    masses within E_TOL of e's).  ``last`` unchanged where no e near it does."""
    masses, bodies, stages, gain = last
    restitutions = [st.restitution for st in stages]
    target = fixture.striker_speed / spec.launch_speed

    def chain_at(x):
        d = design(spec.architecture, fixture.striker_mass, fixture.striker_speed, spec.launch_speed, x, spec.masses)
        if not d.feasible or len(d.masses) != len(masses):
            return None
        b = _bodies(d.masses, fixture, rho, first_diameter)
        return d.masses, b, _chain_gain(spec, d.masses, b, restitutions)

    def miss(x):
        out = chain_at(x)
        return math.nan if out is None else out[2] - target
    lo, hi = max(e - SOLVE_SPAN, 1e-3), min(e + SOLVE_SPAN, 0.999)
    f_lo, f_hi = miss(lo), miss(hi)
    if not (math.isfinite(f_lo) and math.isfinite(f_hi)) or f_lo * f_hi > 0:
        return e, last
    x = brentq(miss, lo, hi, xtol=1e-12, rtol=1e-12)
    m, b, g = chain_at(x)
    return x, (m, b, stages, g)


def _amplifier(spec, last, e, iterations, V, Y, cache: RunCache, t0, reason: str = "") -> Amplifier:
    masses, bodies, stages, gain = last
    speed = gain * spec.launch_speed
    limits = [lim for st in stages for lim in st.limits]
    peaks = {}
    for st in stages:
        a, b = st.pair.split("_", 1)
        for name, lim in zip((a, b), [lim for lim in st.limits if lim.quantity == "stress (FE, von Mises)"]):
            peaks[name] = max(peaks.get(name, 0.0), lim.value / Y)
    # every reason the chain fails: ``reason`` (the masses' own, kept as ``design_reason``) and this chain's checks
    words = [reason] if reason else []
    if abs(speed / V - 1) >= 0.02:
        words.append(f"the chain brings the striker to {speed:.4g} m/s, not {V:.4g}")
    if broken(limits):
        words.append("pads outside their limits: " + "; ".join(lim.describe() for lim in broken(limits)[:3]))
    design_reason, reason = reason, "; ".join(words)
    return Amplifier(spec.architecture, list(masses), bodies, spec.launch_speed, V, e, iterations, gain, speed,
                     _gaps(spec, masses, e, stages), stages, peaks, Y, sum(st.run_wall_time_s for st in stages),
                     not reason, reason, [st.run for st in stages], limits,
                     {"folder": cache.folder, "hits": cache.hits, "misses": cache.misses,
                      "wall_time_s": time.perf_counter() - t0}, design_reason)


def _infeasible(spec, last, e, iterations, V, Y, cache, reason, t0) -> Amplifier:
    """No chain of these masses makes the gain: the last one designed (if any) with the reason."""
    if last is None:
        return Amplifier(spec.architecture, [], [], spec.launch_speed, V, e, iterations, math.nan, math.nan, [], [],
                         {}, Y, 0.0, False, reason, [], [], {"folder": cache.folder, "hits": cache.hits,
                                                             "misses": cache.misses}, reason)
    return _amplifier(spec, last, e, iterations, V, Y, cache, t0, reason)


def check_with_first_mass(spec: MachineSpec, fixture: Fixture, amp: Amplifier, bore: float, out_dir: str,
                          resolution: str | None = None, cache_dir: str | None = None) -> Amplifier:
    """The chain designed again with its first mass the slug of the launcher's bore: its interfaces
    measured with that body, the effective e iterated from the design's, the masses solved to the
    fixture's speed at the restitutions measured."""
    if not amp.masses:
        return amp
    return design_amplifier(spec, fixture, out_dir, None, resolution,
                            cache_dir or amp.cache.get("folder") or os.path.join(out_dir, "pad_runs"), bore,
                            amp.restitution, amp.iterations)


def pad_damping(e: float) -> float:
    """The damping ratio of a spring-dashpot pad that never pulls whose rigid restitution is ``e``."""
    return float(brentq(lambda z: rigid.pad_restitution(z) - e, 0.0, 0.99, xtol=1e-12))


def chain_scene(spec: MachineSpec, amp: Amplifier, fixture: Fixture) -> dict:
    """The designed chain as a chain scene (``amplifier.chain``, fidelity 1d): each pad a spring of its
    secant stiffness and its free thickness, the gaps as designed, the pads damped to restitute the
    effective e (the chain scene's pads share one damping ratio)."""
    steel = fixture.housing_steel_mass / HOUSING_STEELS[fixture.housing_steel].density
    scene_bodies = []
    for b in amp.bodies[:-1]:
        scene_bodies.append({"name": b["name"], "material": "steel", "shape": "cylinder", "radius": b["diameter"] / 2,
                             "length": b["length"], "element_size": b["diameter"] / 4})
    h = amp.bodies[-1]
    scene_bodies.append({"name": "striker", "material": "housing", "shape": "carrier", "radius": h["diameter"] / 2,
                         "length": h["length"], "seat_radius": h["bore"] / 2, "seat_depth": h["bore_depth"],
                         "element_size": h["diameter"] / 4})
    # a bare or crowned face has no pad: a stiff spring across a millimetre stands for its contact
    stiffness = [st.pad_stiffness or 1e12 for st in amp.stages]
    thickness = [st.pad_thickness or 1e-3 for st in amp.stages]
    gaps = amp.gaps
    return {"chain": {"name": "amplifier", "architecture": spec.architecture, "launch_speed": spec.launch_speed,
                      "fidelity": "1d", "gap": gaps if spec.architecture == "launched-chain" else gaps[0],
                      "restitution": 0.9, "damping": STRUCTURAL_DAMPING,
                      "pad_stiffness": stiffness, "pad_thickness": thickness,
                      "pad_damping": pad_damping(min(max(amp.restitution, 0.05), 0.999))},
            # the striker's oil rides in its bore: its mass smeared into the housing's steel
            "materials": {"steel": {"library": spec.material},
                          "housing": {"library": spec.material, "density": fixture.striker_mass / steel}},
            "bodies": scene_bodies}
