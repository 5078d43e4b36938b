"""The velocity amplifier that brings the striker (the fixture's housing) to its speed, with the
restitution its own 1D model gives, not an assumed one.

The masses are the closed form's (``amplifier.gain.design``: geometric ratios, the striker last) at a
restitution e.  Every struck face carries a pad that holds the face stress at the allowable (yield / safety factor)
(``amplifier.interfaces.pad_for_force`` on the rigid chain's closing speeds, as the amplifier study
sizes them, section 6), the gaps let each stage end before the next begins.  The padded chain then
runs in the ``1d`` fidelity (``amplifier.bars``: elastic bars, waves, the pads as springs, 2%
structural damping), its gain gives the effective restitution (the one e with which the rigid chain of
these masses gains as much), and the masses are designed again at that e, until it settles.  The first
mass is a cylinder L = D until the launcher is known; ``check_with_first_mass`` runs the chain again
with the first mass as the slug that fits the launcher's bore.
"""
from __future__ import annotations

import math
import os
from dataclasses import asdict, dataclass, field

from ..amplifier import rigid
from ..amplifier.chain import run_chain_scene
from ..amplifier.gain import cylinder_size, design
from ..amplifier.interfaces import pad_for_force, reduced_mass
from ..scene.library import initial_yield_stress, property_si
from .fixture import Fixture
from .spec import MachineSpec

PAD_DAMPING = 0.02          # the pads' damping ratio (rigid bodies on them: restitution 0.94)
PAD_SPACE = 1.5             # a pad's free thickness over its travel
ASPECT = 1.0                # the intermediate masses' length over diameter
STRUCTURAL_DAMPING = 0.02
E_TOL, MAX_ITERATIONS = 1e-3, 6
# a stage's struck body moves about this share of v tau before its pad lets go (the amplifier study's
# sequenced gaps)
SEQUENCED = 0.6
MIN_GAP = 1e-3


@dataclass
class Stage:
    pair: str
    closing_speed: float        # rigid chain at the pads' restitution [m/s]
    pad_stiffness: float        # [N/m]
    pad_travel: float           # [m]
    pad_thickness: float        # [m]
    pad_energy: float           # [J]
    contact_duration: float     # [s]
    pad_diameter: float         # the smaller face's [m]
    load_section: float         # the smaller of the two bodies' load-carrying sections [m^2]
    face_stress: float          # the pad's peak force over it [Pa]
    interface_stress_1d: float  # the 1D run's peak interface force over the smaller face [Pa]


@dataclass
class Amplifier:
    architecture: str
    masses: list[float]                   # [kg], the striker last
    bodies: list[dict]                    # name, shape, diameter, length (the striker: the housing)
    launch_speed: float                   # [m/s]
    target_speed: float                   # the striker's [m/s]
    restitution: float                    # the effective e the masses are designed at
    iterations: list[dict]                # e assumed -> 1D gain -> effective e
    gain_1d: float
    striker_speed_1d: float               # [m/s]
    gaps: list[float]                     # before each pad [m]
    stages: list[Stage]
    peak_stress_over_yield: dict          # 1D, per body and interface
    yield_stress: float                   # [Pa]
    wall_time_s: float
    feasible: bool = True
    reason: str = ""
    runs: list[str] = field(default_factory=list)   # run directories of the 1D runs

    def as_dict(self) -> dict:
        return asdict(self)


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


def _pads(masses, bodies, launch: float, allowable: float, architecture: str) -> list:
    """The stiffest pad on each struck face that holds it at the ``allowable`` stress (rigid closing
    speeds at the pads' own restitution)."""
    dvs = rigid.first_closing_speeds(masses, launch, rigid.pad_restitution(PAD_DAMPING), architecture)
    return [(dv, pad_for_force(dv, reduced_mass(masses[k], masses[k + 1]),
                               allowable * min(load_section(bodies[k]), load_section(bodies[k + 1]))))
            for k, dv in enumerate(dvs)]


def _chain_raw(spec: MachineSpec, bodies, fixture: Fixture, stiffness: list[float], thickness: list[float],
               gaps: list[float]) -> dict:
    """The padded chain as a chain scene (``amplifier.chain``), fidelity 1d: its pads' stiffness and
    thickness and the gaps before them, one per interface."""
    rho = property_si(spec.material, "density", "density")
    steel = fixture.housing_steel_mass / rho
    scene_bodies = []
    for b in bodies[:-1]:
        scene_bodies.append({"name": b["name"], "material": "steel", "shape": "cylinder", "radius": b["diameter"] / 2,
                             "length": b["length"], "element_size": b["diameter"] / 4})
    h = bodies[-1]
    scene_bodies.append({"name": "striker", "material": "housing", "shape": "carrier", "radius": h["diameter"] / 2,
                         "length": h["length"], "seat_radius": h["bore"] / 2, "seat_depth": h["bore_depth"],
                         "element_size": h["diameter"] / 4})
    return {"chain": {"name": "amplifier", "architecture": spec.architecture, "launch_speed": spec.launch_speed,
                      "fidelity": "1d", "gap": gaps if spec.architecture == "launched-chain" else gaps[0],
                      "restitution": 0.9, "damping": STRUCTURAL_DAMPING,
                      "pad_stiffness": stiffness, "pad_thickness": thickness, "pad_damping": PAD_DAMPING},
            # the striker's oil rides in its bore: its mass smeared into the housing's steel
            "materials": {"steel": {"library": spec.material},
                          "housing": {"library": spec.material, "density": fixture.striker_mass / steel}},
            "bodies": scene_bodies}


def chain_scene(spec: MachineSpec, amp: Amplifier, fixture: Fixture) -> dict:
    """The designed chain as a chain scene (``amplifier.chain``, fidelity 1d), its pads and gaps as designed."""
    return _chain_raw(spec, amp.bodies, fixture, [st.pad_stiffness for st in amp.stages],
                      [st.pad_thickness for st in amp.stages], amp.gaps)


def _run(spec, masses, bodies, fixture, out_dir, label):
    allowable = initial_yield_stress(spec.material) / spec.safety_factor
    pads = _pads(masses, bodies, spec.launch_speed, allowable, spec.architecture)
    if spec.architecture == "launched-chain":
        # body k + 1 moves about SEQUENCED v tau while pad k is loaded: the gap after it lets that stage
        # end before the next begins
        speeds = rigid.launched_chain(masses, spec.launch_speed, rigid.pad_restitution(PAD_DAMPING)).first_pass
        gaps = [MIN_GAP] + [max(MIN_GAP, SEQUENCED * speeds[k + 1] * pads[k][1].duration)
                            for k in range(len(pads) - 1)]
    else:
        gaps = [MIN_GAP] * len(pads)
    where = os.path.join(out_dir, label)
    raw = _chain_raw(spec, bodies, fixture, [p.stiffness for _, p in pads], [PAD_SPACE * p.travel for _, p in pads],
                     gaps)
    result = run_chain_scene(raw, where, "1d", progress=False, echo=lambda *a: None)
    return pads, gaps, result, where


def design_amplifier(spec: MachineSpec, fixture: Fixture, out_dir: str, echo=None) -> Amplifier:
    rho = property_si(spec.material, "density", "density")
    Y = initial_yield_stress(spec.material)
    V, M = fixture.striker_speed, fixture.striker_mass
    e = rigid.pad_restitution(PAD_DAMPING)
    iterations, runs, wall = [], [], 0.0
    for it in range(MAX_ITERATIONS):
        d = design(spec.architecture, M, V, spec.launch_speed, e, spec.masses)
        if not d.feasible:
            return Amplifier(spec.architecture, [], [], spec.launch_speed, V, e, iterations, math.nan, math.nan,
                             math.nan, [], {}, Y, wall, False, d.reason, runs)
        bodies = _bodies(d.masses, fixture, rho, None)
        pads, gaps, result, where = _run(spec, d.masses, bodies, fixture, out_dir, f"iteration_{it + 1}")
        runs.append(where)
        wall += result["wall_time_s"]
        e_eff = rigid.effective_restitution(d.masses, spec.launch_speed, result["gain"], spec.architecture)
        iterations.append({"assumed": e, "gain_1d": result["gain"], "effective": e_eff,
                           "striker_speed_1d": result["test_article_speed"], "first_mass": d.masses[0]})
        if echo:
            echo(f"  amplifier: e = {e:.4f} -> 1D gain {result['gain']:.4f} -> effective e {e_eff:.4f}")
        if not math.isfinite(e_eff):
            return Amplifier(spec.architecture, d.masses, bodies, spec.launch_speed, V, e, iterations,
                             result["gain"], result["test_article_speed"], gaps, [], {}, Y, wall, False,
                             f"no restitution in (0, 1] gives the rigid chain the 1D gain {result['gain']:.4g}", runs)
        if abs(e_eff - e) < E_TOL:
            break
        e = e_eff
    return _amplifier(spec, d.masses, bodies, pads, gaps, result, e, iterations, V, Y, wall, runs)


def _amplifier(spec, masses, bodies, pads, gaps, result, e, iterations, V, Y, wall, runs) -> Amplifier:
    stress = result["peak_stress"]
    names = [b["name"] for b in bodies]
    stages = []
    for k, (dv, p) in enumerate(pads):
        key = f"{names[k]}_{names[k + 1]}"
        area = min(load_section(bodies[k]), load_section(bodies[k + 1]))
        pad_diameter = min(bodies[k]["diameter"], bodies[k + 1]["diameter"])
        stages.append(Stage(key, dv, p.stiffness, p.travel, PAD_SPACE * p.travel, p.energy, p.duration, pad_diameter, area,
                            p.stiffness * p.travel / area, float(stress.get(key, math.nan))))
    feasible = abs(result["test_article_speed"] / V - 1) < 0.02
    return Amplifier(spec.architecture, list(masses), bodies, spec.launch_speed, V, e, iterations, result["gain"],
                     result["test_article_speed"], gaps, stages, dict(result["stress_over_yield"]), Y, wall, feasible,
                     "" if feasible else f"the 1D chain brings the striker to {result['test_article_speed']:.4g} m/s, "
                                         f"not {V:.4g}", runs)


def check_with_first_mass(spec: MachineSpec, fixture: Fixture, amp: Amplifier, bore: float, out_dir: str) -> Amplifier:
    """The designed chain run again in 1D with its first mass the slug of the launcher's bore."""
    rho = property_si(spec.material, "density", "density")
    bodies = _bodies(amp.masses, fixture, rho, bore)
    pads, gaps, result, where = _run(spec, amp.masses, bodies, fixture, out_dir, "with_launcher_slug")
    return _amplifier(spec, amp.masses, bodies, pads, gaps, result, amp.restitution, amp.iterations, amp.target_speed,
                      amp.yield_stress, result["wall_time_s"], amp.runs + [where])
