"""The white paper's premise tested: for the same pulse through the same fixture, is a velocity amplifier
a better machine than one gas gun firing the striker directly, or than its own flying target?

Three arrangements, each delivering the designed fixture's striker to the payload at rest:

* (a) **amplifier**: the designed machine (``design.design_machine``): a gun launches the first mass, the
  chain brings the striker to its speed;
* (b) **direct striker**: the lightest gun within the same limits (``launcher.design.lightest_launcher``)
  fires the same striker (the dashpot's housing and its oil, in a sabot where the bore is wider than the
  housing) at the same speed; the payload waits at the muzzle, so the gun's gas still pushes the striker
  (its base in the bore) through the pulse's start, in the fixture's column run with it (``striker_push``,
  ``pushed_pulse``), and its sabot at its stop (``sabot_stop``: the gun's shot continued past its travel,
  ``launcher.ported_push``), its barrel as laid
  out (unvented) or, the same gun, with its last striker length ported (``vented``), or that ported gun with
  the sabot kept on the striker through the pulse and stopped with it (``kept``: no sabot stop, the sabot's
  mass on the striker in the column run, the muzzle's jet on it past the muzzle);
* (c) **flying target** as the white paper sizes it: a target of the white paper's mass ratio (30 lb for
  a 12 lb article), the fixture designed for it (``fixture.design_fixture``: the housing's wall may ask
  more), fired by the white paper's own gun (12 in bore, 2000 psi, 20 ft^3, ``launcher.gun.white_paper_gun``)
  with as long a barrel as the speed needs.

Each is laid out with its stops designed as absorbers (``layout.place``) and weighed the same way.  (b0),
(b) with a massless sabot, is the direct gun's lower bound and never a machine.  (d), the closed-breech gas drive
(no striker, no amplifier, no dashpot: the gas pressure makes the pulse), is ``gas_drive``'s.  ``verdict`` says, from the
arrangements' numbers, which holds within the limits; when neither does, by how much and what would
change it for the direct gun (``direct_remedies``: the barrel in air and in helium); and what the closed
form (``closed_form``, ``boundary``) says: the restitution above which any chain needs less gun than the
direct one, against the chain's and the best pad's.  The rows are at the designed fixture's striker speed;
``direct_at_speed`` and ``amplifier_at_speed`` give the guns again at the speed the band's centre asks.

``premise_map`` then asks where each wins over pulse durations, peaks and payloads, cheaply: the striker
scaled from the designed one by what its housing's mass scales with (``StrikerLaw``: the bore squared
times the bore's depth), its speed from the rigid collision law (``programmer.dashpot_design
.striker_speed``) at the fixture's measured restitution for the velocity change at the band's centre
(``PulseSpec.band_velocity_change``: the pulse the band accepts, not the specified shape's own area; the
study runs the map again at the two ends of the band's range); the amplifier as the launched chain at its launch
speed and mass count of least gun (``boundary.best_chain``, by the simple-wave and the infinitely
chambered gun, the lower Q kept), its masses by the closed form (``amplifier.gain.design``), designed only
where it needs less gun than the direct one in its sabot (elsewhere the direct gun, where it is feasible
and lightest, wins the point, its note 'nothing to amplify'), and feasible only where its pads can be, by
the closed form (``pads_hold``: its fastest interface's pad of the library's best solid within the share
of the struck body a pad may weigh, the pads' first check); each gun by the lightest-launcher design (one
start) or, for (c), the white paper's gun with its barrel solved (``launcher.gun.barrel_length_for``).  The
direct gun there fires the striker in its sabot (``_with_sabot`` at the bare striker's gun's bore, or the
striker's diameter: one bore where (b) scans five), the bare striker's gun (b0, the lower bound) beside it.  (c) counts only
where its barrel is within the spec's barrel limit.  The restitution the map's amplifier runs at is the
caller's (the system study passes the designed amplifier's effective e, carried over to every point: a pad
sized and run at another point would restitute otherwise).  A machine's figure of merit there is its gun
(barrel and tank) and its moving masses; the stops and frame, which the full design adds, are left out.
Range: the fixture is designed (and its validity checked) only at the spec's point; elsewhere its striker
is the law's and its restitution carried over (``premise_map``'s ``fixed_ratio`` runs the designed ratio
at every point instead, the verdict's sensitivity to the law), the flying target's dashpot is not
designed, the amplifier's pads checked only by that closed form at its fastest interface and its stresses
not at all, and the gas's push on the direct gun's striker after the muzzle not run.
"""
from __future__ import annotations

import copy
import dataclasses
import functools
import math
import multiprocessing
import types
from concurrent.futures import ProcessPoolExecutor
from dataclasses import asdict, dataclass, field

import numpy as np

from ..amplifier.gain import chain_efficiency, design as gain_design
from ..launcher.gas import GASES
from ..metrics.shapes import TOLERANCE
from ..launcher.design import LauncherDesign, weights
from ..launcher.gun import barrel_length_for, fire, white_paper_gun
from ..launcher.simple_wave import muzzle_speed, travel
from ..programmer.column_dashpot import StrikerPush
from ..programmer.dashpot_design import DASHPOT, DESIGN_MARGIN, PulseSpec, striker_speed
from ..programmer.requirement import requirement
from ..scene.library import initial_yield_stress, property_si
from ..units import FT, G0, IN, LB, PSI
from .design import Machine, design_machine, gun_thrust
from .fixture import DESIGN_EVALUATIONS, article_length, bore_radius, design_fixture, pulse_with_push
from .boundary import (MAX_MASSES, Chain, best_chain, best_pad_restitution, break_even,
                       break_even_speed, sound_speed)
from .launcher import SIZING, Launcher, launcher_for, launcher_of, muzzle_state, ported_push
from .layout import GAP_TO_PAYLOAD, RING_CLEARANCE, Layout, place, ring_area
from .pad_materials import PAD_MATERIALS
from .pads import PAD_MASS_SHARE
from .limits import Limit, broken, by_cause, cause
from .stops import pushed_stop
from .spec import MachineSpec

# the white paper's flying target: 30 lb for a 12 lb article (section 1.2), as a ratio to the article
WHITE_PAPER_TARGET = 30.0 / 12.0
SABOT_PASSES = 6
SABOT_BORES = 5
SABOT_MATERIAL, SABOT_SAFETY = "aluminium_6061_t6", 1.5


@dataclass
class Arrangement:
    name: str
    launched_mass: float          # what the gun fires [kg]
    launch_speed: float           # [m/s]
    launch_energy: float          # its kinetic energy at the muzzle [J]
    striker_mass: float           # [kg]
    striker_speed: float          # [m/s]
    bore: float                   # [m]
    barrel: float                 # travel [m]
    reservoir_pressure: float     # [Pa]
    reservoir_volume: float       # [m^3]
    stored: float                 # the tank's gas, p V / (gamma - 1) [J]
    gun_mass: float               # barrel and tank [kg]
    machine_mass: float           # every part on the axis and the frame [kg]
    machine_length: float         # [m]
    gun_feasible: bool            # the gun reaches the speed (within the limits, where it has them)
    notes: list[str] = field(default_factory=list)
    # every limit of the whole design holds (only (a), the designed machine, has them all checked)
    feasible: bool = True
    required_energy: float = math.nan   # the launched mass at the speed it was designed for [J]
    tank_mass: float = math.nan   # the gun's tank, the vessel that stores the gas [kg]
    # the limits checked on this arrangement beyond its gun ((a): the whole machine's; (b): its sabot's stop)
    limits: list = field(default_factory=list)
    # what its fixture, the same dashpot for every arrangement, breaks (the band, its broken limits)
    fixture_problems: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        d = asdict(self)
        d["limits"] = [lim.as_dict() for lim in self.limits]
        return d


@dataclass(frozen=True)
class SabotCone:
    """A sabot's cone sized at every radius (``sabot_cone``)."""
    mass: float                   # [kg]
    acceleration: float           # the shot's, striker and sabot [m/s^2]
    radius: np.ndarray            # from the striker's base ring out to the bore's rim [m]
    thickness: np.ndarray         # [m]
    hoop: np.ndarray              # the membrane stresses there [Pa] (meridional: compression negative)
    meridional: np.ndarray


def sabot_cone(bore: float, pressure: float, striker_diameter: float, striker_mass: float,
               samples: int = 400) -> SabotCone | None:
    """The sabot that carries a striker of ``striker_mass`` [kg] narrower than the bore: an aluminium
    (6061-T6) cone at half-angle alpha = 45 degrees from the bore's rim to the striker's base ring, the gas
    pressing on its back and on the striker's base.  As a membrane (Roark, 7th ed., Table 13.3 case 4) it
    carries at radius rho the hoop stress p rho / (t cos alpha) and the meridional stress
    -N(rho) / (2 pi rho t cos alpha), N(rho) the axial load through that section: the pressure's resultant
    outside it less the inertia of the cone outside it, p pi (R^2 - rho^2) - m(rho..R) a, which at the
    striker is the striker's inertia less its base's own pressure force, M_s a - p pi r^2 (compression).
    The thickness is the least at which von Mises (sqrt(s_h^2 - s_h s_m + s_m^2)) is the allowable S, the
    cone's mass integrated from the rim inward (dm = rho_al 2 pi rho t d rho / sin alpha), the acceleration
    a = p pi R^2 / (M_s + m) solved with the sabot's own mass.  Range: a membrane; the junctions' bending
    and the ring's bearing on the striker's floor are not checked.  None when the striker fills the bore."""
    R, r = bore / 2, striker_diameter / 2
    if R <= r * (1 + 1e-9):
        return None
    rho_al = property_si(SABOT_MATERIAL, "density", "density")
    S = initial_yield_stress(SABOT_MATERIAL) / SABOT_SAFETY
    alpha = math.pi / 4
    radius = np.linspace(R, r, samples)
    hoop_load = pressure * radius / math.cos(alpha)          # s_h t [N/m]
    mass, acceleration = 0.0, pressure * math.pi * R * R / striker_mass
    for _ in range(SABOT_PASSES * 10):
        t, m = np.empty(samples), np.zeros(samples)
        for i, rho in enumerate(radius):
            if i:
                # the cone outside rho: the trapezoidal rule in the radius, each ring at its own thickness
                m[i] = m[i - 1] + rho_al * math.pi * (radius[i - 1] - rho) * (
                    radius[i - 1] * t[i - 1] + rho * _ring_thickness(hoop_load[i], pressure, R, rho, m[i - 1],
                                                                     acceleration, alpha, S)) / math.sin(alpha)
            t[i] = _ring_thickness(hoop_load[i], pressure, R, rho, m[i], acceleration, alpha, S)
        new = m[-1]
        acceleration = pressure * math.pi * R * R / (striker_mass + new)
        if abs(new - mass) <= 1e-9 * (striker_mass + new):
            break
        mass = new
    N = pressure * math.pi * (R * R - radius ** 2) - m * acceleration
    return SabotCone(new, acceleration, radius[::-1], t[::-1], (hoop_load / t)[::-1],
                     (-N / (2 * math.pi * radius * t * math.cos(alpha)))[::-1])


def _ring_thickness(hoop_load: float, pressure: float, R: float, rho: float, outside: float, acceleration: float,
                    alpha: float, S: float) -> float:
    """The cone's least thickness at radius rho [m]: von Mises at S of the hoop stress hoop_load / t and the
    meridional -n / t, n = (p pi (R^2 - rho^2) - outside a) / (2 pi rho cos alpha) (``sabot_cone``)."""
    n = (pressure * math.pi * (R * R - rho * rho) - outside * acceleration) / (2 * math.pi * rho * math.cos(alpha))
    return math.sqrt(hoop_load ** 2 + hoop_load * n + n * n) / S


def sabot_mass(bore: float, pressure: float, striker_diameter: float, striker_mass: float) -> float:
    """The sabot's mass [kg] (``sabot_cone``); zero when the striker fills the bore."""
    cone = sabot_cone(bore, pressure, striker_diameter, striker_mass)
    return cone.mass if cone else 0.0


def striker_body(fixture) -> dict:
    return {"name": "striker", "shape": "carrier", "diameter": 2 * fixture.housing_outer_radius,
            "length": fixture.housing_length, "bore": 2 * fixture.bore_radius, "bore_depth": fixture.bore_depth}


def _layout(spec: MachineSpec, launcher: Launcher, fixture, pulse: dict | None = None, kept: float = 0.0,
            jet: float = 0.0) -> Layout:
    """The one-body machine: the gun fires the striker (its slug), the payload at the muzzle.  ``pulse``: the
    fixture's run with the gas's push on the striker (``pushed_pulse``), whose speeds after it and travels over
    it the striker's stop and the payload's catcher take (else the fixture's own); ``kept``: a sabot kept on
    the striker [kg], stopped with it, the body then as wide as the bore, and ``jet`` the muzzle's jet on it
    past the muzzle [N] (``striker_push``), which its stop carries."""
    rho = property_si(spec.material, "density", "density")
    S = initial_yield_stress(spec.material) / spec.safety_factor
    body = striker_body(fixture)
    if pulse is not None:
        fixture = copy.copy(fixture)
        fixture.striker_mass += kept
        for k in ("after_speed_striker", "after_speed_payload", "striker_travel", "payload_travel"):
            setattr(fixture, k, pulse[k])
    if kept:
        body["diameter"] = launcher.design.gun.bore
    amp = types.SimpleNamespace(bodies=[body], masses=[fixture.striker_mass], stages=[], gaps=[])
    return place(launcher, amp, fixture, rho, S, spec.catch, spec.material, [], spec.oil_pressure,
                 gun_thrust(launcher), muzzle_state(launcher.design.gun).push, jet)


def _arrangement(name: str, launcher: Launcher, fixture, layout: Layout, feasible: bool, notes: list[str],
                 extra: float = 0.0) -> Arrangement:
    """An arrangement's row; ``extra``: mass it carries beyond its layout's parts (a sabot) [kg]."""
    g = launcher.design.gun
    return Arrangement(name, launcher.projectile_mass, launcher.design.muzzle_velocity, launcher.launch_energy,
                       fixture.striker_mass, fixture.striker_speed, g.bore, g.length, g.reservoir_pressure,
                       g.reservoir_volume, launcher.stored_energy, launcher.design.weight,
                       sum(i.mass for i in layout.items) + extra if layout else math.nan,
                       layout.overall_length if layout else math.nan, feasible, notes,
                       required_energy=0.5 * launcher.projectile_mass * launcher.design.required_velocity ** 2,
                       tank_mass=launcher.design.tank_weight)


def amplifier_arrangement(m: Machine) -> Arrangement:
    """(a): the designed machine (its pads' restitutions measured, ``machine.amplifier``), with the gun's gas
    on its first mass while that mass strikes the second (``first_mass_push``) as a limit."""
    a = m.amplifier
    notes = [f"{len(a.masses)} masses, effective e {a.restitution:.4f} (the rigid chain at its pads' "
             "restitutions: " + ", ".join(f"{e:.3f}" for e in a.restitutions) + ")"]
    push = first_mass_push(m)
    if push is not None:
        notes.append(_first_push_words(push))
    if not m.feasible:
        notes.append(f"the machine is NOT FEASIBLE: {len(m.problems)} problems, the first: {m.problems[0]}")
    out = _arrangement("(a) amplifier", m.launcher, m.fixture, m.layout, m.launcher.design.feasible, notes)
    out.limits = list(m.limits) + ([push["limit"]] if push is not None else [])
    out.feasible = m.feasible and (push is None or push["limit"].holds)
    out.fixture_problems = fixture_problems(m)
    return out


def first_mass_push(m: Machine) -> dict | None:
    """The gun's gas on the amplifier's first mass while it strikes the second, None where the gun does not
    reach its launch speed (its push there is not the design's) or the chain is not launched from the gun.
    The first mass's front reaches the muzzle at the end of the gun's travel and the first pad waits
    ``gaps[0]`` past it (``layout.place``), so where the mass is longer than that gap its base is still in the
    bore when the contact starts: the gun's shot continued past its travel over the mass's length
    (``launcher.ported_push``, the barrel as laid out, unvented) gives the base pressure on the bore from
    the contact's start for the stage's estimated contact duration, or until the base leaves the muzzle.
    The two masses move together through the contact, so its impulse J adds J / (m1 + m2) to the second
    (Newton's restitution: the impulse leaves the masses' relative speeds alone), and the chain ahead, linear
    in that speed, carries it to the striker times V_s / v2 (the rigid chain's own speeds at the measured
    restitutions): the speed added to the striker, held against the band's tolerance (``gas_speed_limit``).
    Left out: the base pressure's rise as the mass slows in the contact (the push is the free shot's, a
    little low), the push after the contact (the first mass, pushed on, may strike the second again: not
    followed) and the muzzle's blast once the base is out."""
    a, L = m.amplifier, m.launcher
    if a.architecture != "launched-chain" or not a.stages or not L.design.feasible:
        return None
    g, stage = L.design.gun, a.stages[0]
    slug, gap = a.bodies[0]["length"], a.gaps[0]
    m1, m2 = a.masses[0], a.masses[1]
    v1 = L.design.muzzle_velocity
    v2 = (1 + a.restitutions[0]) * m1 * v1 / (m1 + m2)
    dv = m.spec.pulse.band_velocity_change()
    if gap >= slug:
        added, t0, t1, impulse = 0.0, 0.0, 0.0, 0.0
        basis = (f"the first mass's base out of the bore before it meets the pad ({slug:.3g} m long, the pad "
                 f"{gap:.3g} m past the muzzle): the muzzle's blast left out")
    else:
        r = ported_push(g, slug, 0.0, 1e-6, False)
        t0 = r.time_at(gap)
        t1 = min(r.at_muzzle, t0 + stage.contact_duration)
        impulse = r.impulse(g.area, t0, t1)
        added = impulse / (m1 + m2) * a.striker_speed / v2
        basis = (f"the gun's base pressure past the end of its travel on the bore, for {(t1 - t0) * 1e3:.3g} ms of "
                 f"the {stage.pair} contact, shared by the two masses and carried to the striker by the chain")
    return {"pair": stage.pair, "impulse": impulse, "time_in_bore": t1 - t0,
            "contact_duration": stage.contact_duration, "force": impulse / (t1 - t0) if t1 > t0 else 0.0,
            "speed_added": added, "velocity_change": dv, "limit": gas_speed_limit(added, dv, basis)}


def _first_push_words(push: dict) -> str:
    if push["time_in_bore"] <= 0:
        return f"the first mass's base leaves the bore before its {push['pair']} contact (no push in it)"
    lim = push["limit"]
    return (f"the gun's gas (the barrel as laid out, unvented, launcher.ported_push) pushes the first mass for "
            f"{push['time_in_bore'] * 1e3:.3g} ms of its {push['contact_duration'] * 1e3:.3g} ms {push['pair']} "
            f"contact, its base still in the bore, with {push['force'] / 1e6:.3g} MN on the mean: it adds "
            f"{push['speed_added']:.3g} m/s to the striker, {lim.ratio:.3g} of the band's tolerance "
            f"({lim.limit:.3g} m/s), which the chain's rigid law leaves out")


def best_chain_arrangement(m: Machine, out_dir: str, starts: int = 3) -> Arrangement:
    """(a*): the amplifier at its best, the machine designed again (``design.design_machine``, the same
    fixture, its files in ``out_dir``) for the closed form's best chain (``boundary.best_chain``: the launch
    speed and mass count of least gun) at the design's effective e and the fixture's striker speed; its own
    pads then set its own effective e."""
    e = m.amplifier.restitution
    c = best_chain(e, m.fixture.striker_speed, m.spec.gas)
    star = design_machine(dataclasses.replace(m.spec, masses=c.masses, launch_speed=c.launch_speed), out_dir,
                          starts=starts, fixture=m.fixture)
    out = amplifier_arrangement(star)
    out.name = "(a*) amplifier, the best chain"
    out.notes.insert(0, f"the closed form's best chain at e {e:.4f}: {c.masses} masses launched at "
                        f"{c.launch_speed:.4g} m/s (Q {c.gun_ratio:.3g} against the bare striker)")
    return out


def fixture_problems(m: Machine) -> list[str]:
    """What the designed fixture breaks, in words: its pulse outside the band, and each broken limit of the
    fixture's (``limits.cause``).  Every arrangement carries the same dashpot, so these are common to all."""
    out = ([] if m.fixture.band_passed else
           [f"its column's pulse is outside the band (worst excess {m.fixture.worst_excess:.3g} of the peak)"])
    return out + [f"{lim.component}: {lim.quantity} {lim.ratio:.3g} times its limit" for lim in broken(m.limits)
                  if cause(lim) == "the fixture"]


def _with_sabot(spec: MachineSpec, striker: float, speed: float, diameter: float, bore: float, starts: int,
                report_binding: bool) -> tuple[Launcher, float]:
    """The lightest gun of bore ``bore`` firing the striker in its sabot, designed again with the sabot of
    its bore and pressure until the sabot settles.  The first pass carries the sabot the spec's largest
    pressure asks at this bore (``sabot_mass`` grows with the pressure, and the lightest gun usually runs
    at the pressure limit): where the gun's pressure is that limit the sabot has settled at once."""
    s = dataclasses.replace(spec, max_bore=bore)
    sabot = sabot_mass(bore, spec.max_pressure, diameter, striker)
    for _ in range(SABOT_PASSES):
        L = launcher_for(s, striker + sabot, speed, starts, min_bore=bore, report_binding=report_binding)
        g = L.design.gun
        new = sabot_mass(g.bore, g.reservoir_pressure, diameter, striker)
        if abs(new - sabot) <= 1e-3 * (striker + sabot):
            break
        sabot = new
    return L, sabot


@functools.lru_cache(maxsize=16)
def bare_launcher(spec: MachineSpec, striker: float, speed: float, starts: int, report_binding: bool) -> Launcher:
    """The lightest gun within the spec's limits firing the striker alone (a massless sabot): the direct
    gun's lower bound and the start of its sabot's bore scan, designed once for both."""
    return launcher_for(spec, striker, speed, starts, report_binding=report_binding)


def direct_launcher(spec: MachineSpec, striker: float, speed: float, diameter: float | None, starts: int = 3,
                    report_binding: bool = True, bores: int = SABOT_BORES, lightest_short: list | None = None
                    ) -> tuple[Launcher, float]:
    """The lightest gun within the spec's limits firing a striker of ``striker`` [kg] and ``diameter`` at
    ``speed`` in the sabot its bore needs: the gun's optimiser does not see that the sabot grows with the
    bore (as p R^3), so the bore is scanned (``bores`` bores from half the bare striker's gun's bore, or the
    striker's diameter, to 1.25 times it, each gun designed with its sabot), the lightest feasible gun and
    sabot kept; when no bore's gun reaches the speed, the one that comes closest (the highest muzzle speed),
    not the lightest of those that fall short (that one, as (launcher, sabot), is put in ``lightest_short``
    when given, for a reader to see both).  ``diameter`` None: a massless sabot (the lower bound), one design
    (``bare_launcher``, shared with the scan's start).  Returns the launcher and the sabot's mass."""
    bare = bare_launcher(spec, striker, speed, starts, report_binding)
    if diameter is None:
        return bare, 0.0
    # the sabot favours a narrower bore than the bare striker's gun; scan from half of that bore up
    lo = max(diameter, 0.5 * bare.design.gun.bore)
    hi = max(lo, min(spec.max_bore, 1.25 * bare.design.gun.bore))
    best = light = None
    for bore in np.geomspace(lo, hi, bores):
        L, sabot = _with_sabot(spec, striker, speed, diameter, float(bore), starts, False)
        d = L.design
        key = (False, d.weight + sabot) if d.feasible else (True, -d.muzzle_velocity / d.required_velocity)
        if best is None or key < best[0]:
            best = (key, L, sabot)
        if not d.feasible and (light is None or d.weight + sabot < light[0]):
            light = (d.weight + sabot, L, sabot)
    if lightest_short is not None and not best[1].design.feasible and light[1] is not best[1]:
        lightest_short[:] = [light[1], light[2]]
    return best[1], best[2]


@functools.lru_cache(maxsize=8)
def _direct_design(spec: MachineSpec, striker: float, speed: float, diameter: float | None, starts: int,
                   bores: int) -> tuple:
    """``direct_launcher``'s gun and sabot, and its lightest gun that falls short (or ()), designed once for
    both of (b)'s barrels (unvented and vented: the same gun)."""
    short = []
    L, sabot = direct_launcher(spec, striker, speed, diameter, starts, bores=bores, lightest_short=short)
    return L, sabot, tuple(short)


def direct_arrangement(spec: MachineSpec, fixture, starts: int = 3, with_sabot: bool = True,
                       bores: int = SABOT_BORES, vented: bool = False, kept: bool = False) -> Arrangement:
    """(b): the same striker fired directly by the lightest gun within the same limits, in its sabot;
    ``with_sabot`` False: in a massless sabot (the direct gun's lower bound, (b0)); ``vented``: the barrel's
    last striker length ported (``launcher.ported_push``), else as laid out, unvented: the gas's push on the
    striker during the pulse (``striker_push``) and on the sabot at its stop (``sabot_stop``) follow from it;
    ``kept``: the sabot not stripped at the muzzle but kept on the striker through the pulse and stopped with
    it by the striker's stop (no stop of its own; its mass rides on the striker in the fixture's column run,
    and, filling the bore, it takes the muzzle's jet past the muzzle there and at the striker's stop:
    ``striker_push``'s ``jet``)."""
    diameter = 2 * fixture.housing_outer_radius if with_sabot else None
    L, sabot, short = _direct_design(spec, fixture.striker_mass, fixture.striker_speed, diameter, starts, bores)
    kept = kept and sabot > 0
    push = striker_push(spec, L, fixture, sabot, vented, diameter, kept)
    pulse = pushed_pulse(spec, fixture, push)
    layout = _layout(spec, L, fixture, pulse, sabot if kept else 0.0, push["jet"])
    stop = sabot_stop(spec, L, sabot, diameter, vented, fixture) if sabot and not kept else None
    notes = [_kept_words(sabot, pulse, layout, vented) if kept else
             f"sabot {sabot:.3g} kg (aluminium cone; counted in the machine), stopped at the muzzle at "
             f"{stop.speed:.4g} m/s (the muzzle's {L.design.muzzle_velocity:.4g} and the gas's push after it) by a "
             f"{stop.kind} ({stop.absorber_mass:.3g} kg, {stop.stroke:.3g} m of stroke at {stop.force / 1e6:.3g} MN, "
             f"holding {stop.hold / 1e6:.3g} MN at rest; counted in the machine's mass, not laid on its axis) "
             f"against the gas's {stop.push / 1e6:.3g} MN push on it there ({_barrel_words(vented)})"
             if stop else
             ("no sabot: the striker fills the bore" if with_sabot else "the sabot's mass left out (a lower bound)")]
    # its own stops' limits (the striker's, with a kept sabot on it, and the payload's catcher), the sabot's
    limits = [lim for st in layout.stops for lim in st.limits] + (stop.limits if stop else []) + [pulse["limit"]]
    notes.append(_push_words(push, pulse, fixture))
    notes += [f"breaks its limit: {lim.describe()}" for lim in broken(limits)]
    if not L.design.feasible:
        notes.append(L.design.note)
    if short:
        notes.append(_short_words(L, sabot, *short))
    name = ("(b) direct striker" if with_sabot else "(b0) direct striker, massless sabot") + (
        ", vented" if vented else "") + (", its sabot kept" if kept else "")
    out = _arrangement(name, L, fixture, layout, L.design.feasible, notes,
                       sabot + (stop.absorber_mass if stop else 0.0))
    out.limits = limits
    out.feasible = L.design.feasible and not broken(limits)
    return out


def _kept_words(sabot: float, pulse: dict, layout: Layout, vented: bool) -> str:
    """A sabot kept on the striker (``direct_arrangement``'s ``kept``), in words."""
    stop = next(s for s in layout.stops if s.body == "striker")
    jet = (f", against the muzzle's jet on it, {stop.push / 1e6:.3g} MN held over the stroke" if stop.push else "")
    return (f"sabot {sabot:.3g} kg (aluminium cone; counted in the machine) kept on the striker through the pulse "
            f"({_barrel_words(vented)}) and stopped with it by the striker's {stop.kind} ({stop.stroke:.3g} m of "
            f"stroke, {stop.force / 1e6:.3g} MN at most, from {pulse['after_speed_striker']:.4g} m/s{jet}): no sabot "
            f"stop of its own, the gas's push a stripped sabot takes at the muzzle moved onto the striker's stop as "
            f"the muzzle's jet; the cone at that stop carries its own inertia at a deceleration of at most the shot's "
            f"peak acceleration (the stop's force at most the gun's thrust), its junction with the striker and the "
            f"ring's bearing not checked")


def _barrel_words(vented: bool) -> str:
    return ("the barrel's last striker length ported, launcher.ported_push" if vented else
            "the barrel as laid out, unvented, launcher.ported_push with its ports shut")


def _push_words(push: dict, pulse: dict, fixture) -> str:
    """The gun's gas on the striker during the pulse (``striker_push``) and the pulse with it
    (``pushed_pulse``), in words."""
    lim = pulse["limit"]

    def said(peak, duration, dv, passed, excess):
        return (f"{peak / G0:,.0f} g for {duration * 1e3:.3g} ms, {dv:.4g} m/s, "
                + ("in the band" if passed else f"outside the band (worst excess {excess:.3g} of the peak)"))
    return (f"the gun's gas ({_barrel_words(push['vented'])}; the tank at {push['reservoir_pressure'] / 1e6:.3g} MPa "
            f"at the end of the travel) pushes the striker and its sabot on the bore for the first "
            f"{push['time_in_bore'] * 1e3:.3g} ms of the pulse, its base still in the bore, with {push['force'] / 1e6:.3g} "
            f"MN on the mean (the base pressure {push['pressure'] / 1e6:.3g} to {push['end_pressure'] / 1e6:.3g} MPa; "
            f"{push['force'] / push['pulse_force']:.3g} times the pulse's force on the payload), its impulse worth "
            f"{push['speed_added']:.3g} m/s to the striker and its sabot"
            + (f", then the muzzle's jet on the kept sabot, {push['jet'] / 1e6:.3g} MN held (an estimate) over the "
               f"record's last {push['jet_time'] * 1e3:.3g} ms, worth {push['jet_speed_added']:.3g} m/s more"
               if push.get("jet_time") else "")
            + "; the fixture's column run with it: "
            f"{said(pulse['peak'], pulse['duration'], pulse['velocity_change'], pulse['band_passed'], pulse['worst_excess'])} "
            f"(its energy balance closes to {pulse['energy_residual']:.2g} of the energy in), "
            f"against its own {said(fixture.peak, fixture.duration, fixture.velocity_change, fixture.band_passed, fixture.worst_excess)}: "
            f"the push adds {lim.value:.3g} of the peak to the band's worst excess, "
            + ("within" if lim.holds else f"{lim.ratio:.3g} times")
            + f" the fixture designer's margin ({lim.limit:.3g}), which its design leaves out")


def _short_words(closest: Launcher, sabot: float, light: Launcher, light_sabot: float) -> str:
    """The bore scan's closest gun beside its lightest, when no bore's gun reaches the speed."""
    def gun(L, s):
        d, g = L.design, L.design.gun
        return (f"{g.bore / IN:.3g} in x {g.length / FT:.3g} ft at {g.reservoir_pressure / PSI:,.0f} psi, "
                f"{(d.weight + s) / 1e3:.3g} t with its {s:.3g} kg sabot, {d.muzzle_velocity:.4g} m/s, "
                f"{d.required_velocity - d.muzzle_velocity:.3g} m/s short")
    return (f"no bore's gun reaches {closest.design.required_velocity:.4g} m/s: kept the closest ({gun(closest, sabot)}); "
            f"the lightest that falls short: {gun(light, light_sabot)}")


# how long the gas is followed with a sabot held at the muzzle (``launcher.ported_push``): past the stroke
# time of its stop (at constant deceleration 2 x / v: the 12 lb premise's 2-3 m at about 430 m/s take 9 to
# 14 ms), the largest barrel pressure over it held over the stroke
SABOT_HOLD = 0.03


def _ported(launcher: Launcher, fixture, diameter: float | None, vented: bool):
    """The gas behind the direct gun's striker past the end of its travel (``launcher.ported_push``): the
    striker fills the barrel's last ``housing_length``, its stripped sabot leaves its own section open."""
    hole = math.pi * diameter ** 2 / 4 if diameter else 0.0
    return ported_push(launcher.design.gun, fixture.housing_length, hole, SABOT_HOLD, vented)


def sabot_stop(spec: MachineSpec, launcher: Launcher, sabot: float, diameter: float, vented: bool = False,
               fixture=None):
    """The sabot's stop (``stops.pushed_stop``): the sabot leaves the muzzle at the striker's speed there (the
    gun's muzzle speed and what the gas adds after it, ``launcher.ported_push``) and is stripped by a ring that
    lets the striker pass (from its diameter to the bore's), its absorber at the force the sabot's inertia
    allows over its axial length (the 45 degree cone's, R - r), at most the gun's thrust, against the gas's
    push on the sabot's face outside the striker's base: the largest barrel pressure while it is held at the
    muzzle (``SABOT_HOLD``; the tank feeding the barrel through the open valve, the barrel venting through the
    stripped sabot's hole and, ``vented``, the ported last striker length) on pi (D^2 - d^2) / 4, held over the
    stroke.  ``fixture`` None: the striker taken as long as the barrel's slug (the launcher's own) is not
    known, so the push is the end of the travel's base pressure (``launcher.muzzle_state``)."""
    g = launcher.design.gun
    rho = property_si(SABOT_MATERIAL, "density", "density")
    S = initial_yield_stress(SABOT_MATERIAL) / SABOT_SAFETY
    ring = ring_area(g.bore, diameter + RING_CLEARANCE)
    if fixture is None:
        speed, p = launcher.design.muzzle_velocity, muzzle_state(g).base_pressure
        why = "the gun's gas at the end of its travel on the sabot's face outside the striker (launcher.muzzle_state)"
    else:
        r = _ported(launcher, fixture, diameter, vented)
        speed, p = r.muzzle_speed, r.held_pressure
        why = (f"the gun's gas on the sabot's face outside the striker while it is held at the muzzle, the largest "
               f"barrel pressure over {SABOT_HOLD * 1e3:.3g} ms ({_barrel_words(vented)})")
    return pushed_stop("sabot", sabot, speed, (g.bore - diameter) / 2, rho, S, ring, spec.oil_pressure,
                       p * ring_area(g.bore, diameter), why, max_force=gun_thrust(launcher))


# the share of the velocity change a speed the fixture's column run leaves out may add to the striker: the
# band's tolerance on the velocity change (``metrics.shapes.TOLERANCE``)
STRIKER_PUSH_SHARE = TOLERANCE["velocity_change"]


def gas_speed_limit(speed_added: float, velocity_change: float, basis: str) -> Limit:
    """The gas's push on a striker during the pulse as a model-range limit: the speed it adds, F t / (M +
    m_sabot), at most the band's tolerance on the velocity change (``STRIKER_PUSH_SHARE`` times
    ``velocity_change``).  The striker is many times the payload, so a force on it changes the payload's
    pulse through the striker's speed, not force for force."""
    return Limit("launcher's gas on the striker during the pulse", "the speed the gas adds to the striker",
                 speed_added, STRIKER_PUSH_SHARE * velocity_change, "m/s", basis,
                 "the fixture's column run's range: a speed it leaves out, at most the band's tolerance on the "
                 "velocity change (metrics.shapes.TOLERANCE) times the band's centre")


def striker_push(spec: MachineSpec, launcher: Launcher, fixture, sabot: float = 0.0, vented: bool = False,
                 diameter: float | None = None, kept: bool = False) -> dict:
    """The gun's gas on a striker it fires directly while the pulse runs.  The payload waits ``GAP_TO_PAYLOAD``
    past the muzzle (``layout.place``) and the striker's front reaches the muzzle at the end of the gun's
    travel, so its base (and its sabot, there) is in the bore for the first (L_s - gap) / V_s of the pulse,
    pushed on the whole bore by the base pressure past the end of the travel (``launcher.ported_push``: the
    barrel as laid out, unvented, or ``vented``, its last striker length ported): the force history from
    first contact and the sabot it carries until its base leaves the muzzle, or, ``kept``, through the whole
    pulse (``push``, a
    ``programmer.column_dashpot.StrikerPush`` for the fixture's column run, ``pushed_pulse``), its mean, and
    the speed its impulse adds to the striker and its sabot, F t / (M + m_sabot).  The base pressure is the
    free shot's (the striker slowed by the dashpot, or sped by the push, moves the base pressure little: the
    striker is many times the payload).  After the base clears the muzzle the jet through the stripped
    sabot's ring (or the open muzzle) pushes the base on, less (left out).  A sabot ``kept`` on the striker
    fills the bore: the muzzle's jet then pushes it on, taken as the base pressure on the bore as the base
    leaves the muzzle (``jet``), held to the record's end (its fall as the barrel empties through the
    muzzle, and the share of the jet a body moving off intercepts, not modelled: an estimate, not a
    bound)."""
    g = launcher.design.gun
    r = _ported(launcher, fixture, diameter, vented)
    t0 = r.time_at(GAP_TO_PAYLOAD)
    t1 = min(r.at_muzzle, t0 + spec.pulse.duration)
    impulse = r.impulse(g.area, t0, t1)
    inside = (r.time > t0) & (r.time < t1)
    times = np.concatenate([[t0], r.time[inside], [t1]])
    force = g.area * np.interp(times, r.time, r.base_pressure)
    k0, k1 = (int(np.searchsorted(r.time, t)) for t in (t0, t1))
    # the base pressure as the base leaves (the sample at the muzzle itself is the held face's)
    jet = g.area * float(r.base_pressure[r.time < r.at_muzzle][-1]) if kept else 0.0
    jet_time = max(spec.pulse.record_end() - (t1 - t0), 0.0) if kept and t1 >= r.at_muzzle else 0.0
    if jet_time > 0:
        times, force = np.append(times, t1 + jet_time), np.append(force, jet)
    return {"vented": vented, "kept": kept, "pressure": float(np.interp(t0, r.time, r.base_pressure)),
            "end_pressure": float(r.base_pressure[max(k1 - 1, k0)]), "reservoir_pressure": float(r.reservoir_pressure[0]),
            "force": impulse / (t1 - t0), "impulse": impulse, "time_in_bore": t1 - t0,
            "speed_added": impulse / (fixture.striker_mass + sabot), "velocity_change": spec.pulse.band_velocity_change(),
            "pulse_force": fixture.payload_mass * spec.pulse.peak, "jet": jet, "jet_time": jet_time,
            "jet_speed_added": jet * jet_time / (fixture.striker_mass + sabot),
            "push": StrikerPush(times - t0, force, sabot, math.inf if kept else t1 - t0)}


def pushed_pulse(spec: MachineSpec, fixture, push: dict) -> dict:
    """The fixture's pulse with the gas's push on the striker (``striker_push``) in its column run
    (``fixture.pulse_with_push``), beside the fixture's own, and the limit it is held to
    (``pushed_pulse_limit``)."""
    pushed = pulse_with_push(spec, fixture, push["push"])
    added = pushed["worst_excess"] - fixture.worst_excess
    carried = "through the pulse" if push["kept"] else "that long"
    basis = (f"the fixture's column run with the gun's base pressure on the bore for {push['time_in_bore'] * 1e3:.3g} "
             f"ms of the pulse and the sabot carried {carried} ({_barrel_words(push['vented'])}): the band's worst "
             f"excess {pushed['worst_excess']:.3g} of the peak against the fixture's own {fixture.worst_excess:.3g}")
    return {**pushed, "limit": pushed_pulse_limit(added, basis)}


def pushed_pulse_limit(excess_added: float, basis: str) -> Limit:
    """The gas's push on a striker during the pulse as a model-range limit: the band's worst excess the push
    adds to the fixture's pulse (its column run with the push, against its own), at most the design margin
    the fixture's designer keeps inside the band for what its model leaves out
    (``programmer.dashpot_design.DESIGN_MARGIN``).  The fixture is designed without the push: past the margin
    it no longer stands for a pushed striker (a fixture designed with the push would be)."""
    return Limit("launcher's gas on the striker during the pulse", "the band's worst excess the push adds",
                 excess_added, DESIGN_MARGIN, "of the peak", basis,
                 "the fixture designer's range: its design margin inside the band "
                 "(programmer.dashpot_design.DESIGN_MARGIN), for what its model leaves out")


def direct_at_speed(spec: MachineSpec, fixture, speed: float, starts: int = 3, bores: int = SABOT_BORES) -> dict:
    """(b) and (b0) designed again for the striker at ``speed`` [m/s] (the band's centre): the lightest lumped
    gun within the limits firing it in its sabot (``direct_launcher``: the closest where none reaches it), in
    air and in helium, and bare ((b0)); the launch energy asked, the muzzle speed each reaches and, where the
    air gun falls short, the travel that gun (its bore, pressure and tank) needs to reach the speed
    (``launcher.gun.barrel_length_for``)."""
    d, M = 2 * fixture.housing_outer_radius, fixture.striker_mass
    out = {"speed": speed}
    for label, s, diameter in (("air", spec, d), ("helium", dataclasses.replace(spec, gas="helium"), d),
                               ("bare", spec, None)):
        L, sabot, _ = _direct_design(s, M, speed, diameter, starts, bores)
        g = L.design.gun
        out[label] = {"feasible": bool(L.design.feasible), "muzzle_velocity": L.design.muzzle_velocity,
                      "sabot": sabot, "launch_energy": 0.5 * (M + sabot) * speed ** 2, "bore": g.bore,
                      "travel": g.length, "pressure": g.reservoir_pressure, "tank": g.reservoir_volume,
                      "gun_mass": L.design.weight,
                      "travel_to_reach": g.length if L.design.feasible else barrel_length_for(g, speed)}
    return out



def amplifier_at_speed(spec: MachineSpec, x: Arrangement, speed: float, starts: int = 3) -> dict:
    """An amplifier arrangement ((a), (a*)) for the striker at ``speed`` [m/s] (the band's centre): the same
    chain, whose rigid gain is fixed, so its launch speed scales as the striker's and its launch energy as
    the square; its gun designed again (``launcher_for``) only where the answer is not already known (a gun
    short at a lower speed is short at a higher one, a gun that reaches a higher speed reaches a lower)."""
    ratio = speed / x.striker_speed
    required = math.sqrt(2 * x.required_energy / x.launched_mass) if x.launched_mass > 0 else math.nan
    out = {"speed": speed, "launch_speed": required * ratio, "launch_energy": x.required_energy * ratio ** 2}
    if (not x.gun_feasible and ratio >= 1) or (x.gun_feasible and ratio <= 1):
        out.update(gun_reaches=x.gun_feasible, how="as at the fixture's speed (a gun short at a lower speed is "
                   "short at a higher one)" if not x.gun_feasible else "as at the fixture's higher speed")
    else:
        L = launcher_for(spec, x.launched_mass, out["launch_speed"], starts, report_binding=False)
        out.update(gun_reaches=bool(L.design.feasible), how="its gun designed again at that launch speed",
                   muzzle_velocity=L.design.muzzle_velocity, gun_mass=L.design.weight)
    return out


def white_paper_launcher(spec: MachineSpec, launched: float, speed: float) -> tuple[Launcher, bool]:
    """The white paper's gun (12 in, 2000 psi, 20 ft^3, its valve) with the barrel ``speed`` needs."""
    g = white_paper_gun(launched, spec.gas)
    length = barrel_length_for(g, speed)
    ok = math.isfinite(length)
    if not ok:
        nan = math.nan
        g = dataclasses.replace(g, length=math.inf)
        d = LauncherDesign(g, nan, nan, nan, nan, speed, nan, nan, False,
                           note="the white paper's gun never reaches the speed, however long its barrel")
        return Launcher(d, {}, launched, nan, g.reservoir_pressure * g.reservoir_volume / (g.gas_model().gamma - 1),
                        nan), False
    g = dataclasses.replace(g, length=length)
    shot = fire(g, samples=2)
    wb, wt = weights(g, SIZING)
    d = LauncherDesign(g, wb + wt, wb, wt, shot.muzzle_velocity, speed, shot.peak_acceleration, shot.efficiency, ok)
    return launcher_of(d, launched), ok


def flying_target_arrangement(spec: MachineSpec, fixture, echo=None, evaluations: int = DESIGN_EVALUATIONS
                              ) -> tuple[Arrangement, object]:
    """(c): the white paper's flying target (its mass ratio to the article), the fixture designed for it
    (its search ``evaluations`` runs at most), fired by the white paper's gun with as long a barrel as it
    needs."""
    ratio = WHITE_PAPER_TARGET * spec.article_mass / fixture.payload_mass
    try:
        target = design_fixture(dataclasses.replace(spec, striker_ratio=ratio), echo, evaluations)
    except ValueError as err:
        # the dashpot's own models refuse the target (its liquid outweighs it): no flying target to fire
        return _no_target(spec, fixture, ratio, str(err)), types.SimpleNamespace(striker_ratio=ratio)
    L, ok = white_paper_launcher(spec, target.striker_mass, target.striker_speed)
    layout = _layout(spec, L, target) if ok else None
    notes = [f"asked {ratio:.3g} times the payload ({WHITE_PAPER_TARGET * spec.article_mass / LB:.3g} lb); the "
             f"fixture designer's target is {target.striker_ratio:.3g} times"
             + (" (its housing's wall sets it)" if target.housing_binds else "")]
    if not ok:
        notes.append("the white paper's gun never reaches the speed, however long its barrel")
    return _arrangement("(c) flying target, the white paper's gun", L, target, layout, ok, notes), target


def _no_target(spec: MachineSpec, fixture, ratio: float, why: str) -> Arrangement:
    """(c) when the fixture designer finds no dashpot for the white paper's target."""
    nan = math.nan
    M = ratio * fixture.payload_mass
    return Arrangement("(c) flying target, the white paper's gun", M, nan, nan, M, nan, nan, nan, nan, nan, nan,
                       nan, nan, nan, False, [f"asked {ratio:.3g} times the payload "
                                              f"({WHITE_PAPER_TARGET * spec.article_mass / LB:.3g} lb); the fixture "
                                              f"designer finds no dashpot for it: {why}"])


def _times(x: float, y: float) -> str:
    """How ``x`` compares with ``y`` in words: 'N times' or 'N times less than'."""
    if not (math.isfinite(x) and math.isfinite(y)) or x <= 0 or y <= 0:
        return "not comparable with"
    return f"{x / y:.3g} times" if x >= y else f"{y / x:.3g} times less than"


# Q within this of 1 is parity, where the verdict rests on the interfaces, not on Q: Q is a ratio of ideal
# guns, and the two ideal laws' best Q at the 12 lb design's point differ by 4% (1.47 simple-wave, 1.53
# chambered at 412.0 m/s and e 0.632: `boundary.best_chain`), more at faster strikers (the map's table gives
# both); 10% is a margin chosen above that 4%, not a measured bound on a real gun
PARITY = 1.1


def specified_striker_speed(m: Machine, dv: float | None = None) -> float:
    """The striker speed [m/s] the specification asks of the designed fixture's striker: the rigid collision
    law (``dashpot_design.striker_speed``) for the velocity change ``dv`` [m/s] (None: the band's centre,
    ``PulseSpec.band_velocity_change``: the pulse the band accepts, not the specified shape's own area, a
    rectangle's A T) at the fixture's payload, striker and measured restitution (the map's law at the spec's
    point)."""
    f = m.fixture
    dv = m.spec.pulse.band_velocity_change() if dv is None else dv
    return striker_speed(f.payload_mass, f.striker_mass, dv, max(f.restitution, 0.0))


def closed_form(m: Machine, sabot: float = 0.0, speed: float | None = None) -> dict:
    """The premise's closed form (``boundary``) at the design's striker, at ``speed`` [m/s] (None: the
    designed fixture's): what the design's chain keeps of its launch energy (at its effective e, and at
    e = 1), the least gun any chain needs at that e, the break-even restitutions (the best chain, and the
    spec's launch speed and mass count; air, helium, an air amplifier against a helium direct gun), the same
    against the direct gun that launches the striker and its ``sabot`` [kg] (``with_sabot``: the direct
    machine the premise admits), the best chain's fastest interface against the solids' elastic limit
    (``chain_interface_bound``) and the best restitution a pad of the library is sized with."""
    s, e = m.spec, m.amplifier.restitution
    V = m.fixture.striker_speed if speed is None else speed
    G = V / s.launch_speed
    pad, e_pad = best_pad_restitution()
    ok = math.isfinite(e) and e > 0
    load = (m.fixture.striker_mass + sabot) / m.fixture.striker_mass
    best = best_chain(e, V, s.gas) if ok else None
    return {"striker_speed": V, "restitution": e, "masses": s.masses, "launch_speed": s.launch_speed, "gain": G,
            "chain_efficiency": chain_efficiency(e, G, s.masses) if ok else math.nan,
            "chain_efficiency_elastic": chain_efficiency(1.0, G, s.masses),
            "best": best.as_dict() if ok else None,
            "break_even": {gas: break_even(V, gas) for gas in ("air", "helium")},
            "break_even_spec": {gas: break_even(V, gas, masses=s.masses, launch_speed=s.launch_speed)
                                for gas in ("air", "helium")},
            "break_even_air_against_helium": break_even(V, "air", "helium"),
            # both guns as the infinitely chambered gun (the bound the simple-wave gun is not)
            "break_even_chambered": {"air": break_even(V, "air", chambered=True)},
            "with_sabot": {"sabot": sabot, "direct_load": load,
                           "best": best_chain(e, V, s.gas, direct_load=load).as_dict() if ok else None,
                           "break_even": {"air": break_even(V, "air", direct_load=load),
                                          "chambered": break_even(V, "air", chambered=True, direct_load=load)}},
            "interface": chain_interface_bound(m, best) if ok else None,
            "best_pad": pad, "best_pad_restitution": e_pad, "scale_free": scale_free(m)}


def chain_interface_bound(m: Machine, chain: Chain) -> dict:
    """The best chain's fastest interface (its last, closing at V_s / g, g the stage gain G^(1/(n-1))) against
    the speed v* to which the library's best solid returns an interface's energy elastically
    (``elastic_limit_speeds``): a pad that held it would weigh (dv / v*)^2 m_a / (m_a + m_b) times the struck
    body, m_a / (m_a + m_b) = 1 / (1 + q) for the geometric chain's mass ratio q = (1 + e) / g - 1."""
    g = chain.gain ** (1 / (chain.masses - 1))
    closing = chain.striker_speed / g
    q = (1 + chain.restitution) / g - 1
    speeds = elastic_limit_speeds(m.spec)
    best = max(speeds, key=speeds.get)
    return {"closing_speed": closing, "mass_ratio": q, "best_solid": best, "elastic_limit_speed": speeds[best],
            "pad_over_struck": (closing / speeds[best]) ** 2 / (1 + q), "past_elastic_limit": closing > speeds[best]}


# the restitutions the pads' finite-element runs measured at the 12 lb chain's first interface (4,773 kg on
# 1,600 kg closing at 99 m/s: `python scripts/pad-interface.py --run OUT 4772.5 0.914 0.926 1599.6 0.638 0.638
# 99.06`, docs/machine.md's Pads): polyurethane's highest and lowest, and flat steel faces
MEASURED_RESTITUTIONS = {"polyurethane, the best run": 0.457, "polyurethane, the worst run": 0.374,
                         "flat steel faces": 0.29}


def elastic_limit_speeds(spec: MachineSpec) -> dict:
    """The closing speed v* = sigma / sqrt(rho E) [m/s] up to which a solid returns an interface's energy
    elastically at its working (or yield) stress sigma, for the spec's steel at its allowable and every pad
    material of the library: a pad that holds M* dv^2 / 2 at sigma stores sigma^2 / (2 E) per volume, so its
    mass over the struck body's is (dv / v*)^2 m_a / (m_a + m_b), whatever the bodies' size (the pads' first
    check, ``amplifier.pad_bound``, is this law for each material; v* is also the flat bar-on-bar impact's
    yield particle velocity)."""
    rho, E = property_si(spec.material, "density", "density"), property_si(spec.material, "youngs_modulus", "pressure")
    out = {spec.material: initial_yield_stress(spec.material) / spec.safety_factor / math.sqrt(rho * E)}
    for name, pm in PAD_MATERIALS.items():
        sigma = max(pm.working_stress, pm.yield_stress)
        if pm.density > 0 and pm.youngs_modulus > 0 and sigma > 0:
            out[name] = sigma / math.sqrt(pm.density * pm.youngs_modulus)
    return out


# a spring outside the library that stores more per mass than its solids: a unidirectional CFRP strap in
# tension (T700-class fibre in epoxy: tensile strength about 2 GPa, E 140 GPa, 1600 kg/m^3; typical data-sheet
# values, check), w = sigma^2 / (2 E) = 14 MJ/m^3
FIBRE_SPRING = {"name": "a CFRP strap in tension", "stress": 2.0e9, "modulus": 140e9, "density": 1600.0}


def fibre_spring_speed() -> float:
    """v* = sigma / sqrt(rho E) [m/s] of ``FIBRE_SPRING``."""
    f = FIBRE_SPRING
    return f["stress"] / math.sqrt(f["density"] * f["modulus"])


def scale_free(m: Machine) -> dict:
    """Why the amplifier fails whatever its size, for interfaces of the library's solids: a stage gains at
    most 1 + e <= 2, so the chain's last interface closes at V_s / g >= V_s / 2 (g the stage gain), above the
    speed v* to which the library's solids return the energy elastically (``elastic_limit_speeds``); how far
    above for the best spring outside the library (``FIBRE_SPRING``, a fibre strap in tension); and the first
    mass at the restitutions the pads' runs measured (``MEASURED_RESTITUTIONS``; None where no chain of the
    spec's masses gains enough).  Gas and liquid springs are not solids and fall outside the argument (the gas
    spring's chain: ``gas_spring_chain``)."""
    s, V = m.spec, m.fixture.striker_speed
    g = (V / s.launch_speed) ** (1 / (s.masses - 1))
    speeds = elastic_limit_speeds(s)
    best = max(speeds, key=speeds.get)
    first = {}
    for label, e in MEASURED_RESTITUTIONS.items():
        d = gain_design(s.architecture, m.fixture.striker_mass, V, s.launch_speed, e, s.masses)
        first[label] = {"restitution": e, "first_mass": d.masses[0] if d.feasible else None}
    return {"stage_gain": g, "last_closing_speed": V / g, "half_striker_speed": V / 2,
            "elastic_limit_speeds": speeds, "best_solid": best, "best_elastic_limit_speed": speeds[best],
            "fibre_spring_speed": fibre_spring_speed(), "first_closing_speed": s.launch_speed,
            "first_mass_at_measured": first}


def _scale_free_words(k: dict) -> str:
    firsts = "; ".join(f"{label} ({x['restitution']:.3g}): " + (f"{x['first_mass'] / 1e3:,.0f} t" if x["first_mass"]
                                                                 else "no chain of these masses gains enough")
                       for label, x in k["first_mass_at_measured"].items())
    fibre = k["fibre_spring_speed"]
    return (f"why the amplifier fails whatever its size, on the library's solids: a stage gains at most 1 + e <= 2, "
            f"so the chain's last interface closes at V_s / g = {k['last_closing_speed']:.0f} m/s (at least V_s / 2 "
            f"= {k['half_striker_speed']:.0f} m/s at any e and any number of masses), while the best solid of the "
            f"library ({k['best_solid']}) returns an interface's energy elastically only up to v* = sigma / "
            f"sqrt(rho E) = {k['best_elastic_limit_speed']:.0f} m/s, whatever the fixture, the striker's mass or "
            f"the number of masses: every interface of those solids is past its elastic limit, and the chain's e is "
            f"the estimate of a slow rebound test; {FIBRE_SPRING['name']} (2 GPa) would reach v* = {fibre:.0f} m/s, "
            f"{k['half_striker_speed'] / fibre:.2f} times below V_s / 2 and {k['last_closing_speed'] / fibre:.2f} "
            f"times below the last interface (within reach of the first, at {k['first_closing_speed']:.0f} m/s); gas "
            f"and liquid springs are not solids and fall outside this argument (the gas spring's chain is its own "
            f"table); at the restitutions the pads' runs measured the first mass would be: {firsts}")


def direct_remedies(spec: MachineSpec, striker: float, speed: float, diameter: float) -> dict:
    """What one gun at the spec's widest bore and highest pressure needs to fire the striker, in its sabot
    there, at ``speed``: the barrel, and the speed a barrel of the spec's limit gives, in air and in helium,
    by the simple-wave gun (a straight infinite chamber of the bore's section, ``launcher.simple_wave``), the
    infinitely chambered gun (the most any real chamber gives, ``chambered``) and the constant-pressure bound
    (an infinite reservoir right behind the base, massless gas: p A L = M V^2 / 2, the least barrel of all)."""
    p, A, L = spec.max_pressure, math.pi * spec.max_bore ** 2 / 4, spec.max_barrel_length
    M = striker + sabot_mass(spec.max_bore, p, diameter, striker)
    out = {"limits": {"barrel": L, "bore": spec.max_bore, "pressure": p}, "launched": M, "striker": striker,
           "constant_pressure_barrel": 0.5 * M * speed ** 2 / (p * A),
           "constant_pressure_speed": math.sqrt(2 * p * A * L / M)}
    out.update(_ideal_guns(M, speed, p, A, L))
    # the bare striker at the same limits (a massless sabot): what no sabot could beat
    out["bare"] = _ideal_guns(striker, speed, p, A, L)
    return out


def barrel_as_laid_out(spec: MachineSpec, fixture, x: Arrangement) -> dict:
    """The spec's barrel limit is read as the gun's travel (``launcher_for``'s ``max_length``); the barrel as
    laid out (``layout.place``) adds the slug it holds at rest, for a directly fired striker its housing's
    length.  Its length [m] and, with the whole barrel within the limit (the travel shortened by the
    striker), the speed the infinitely chambered gun (the ideal upper bound, ``launcher.simple_wave``) of
    ``x``'s bore and pressure in the spec's gas gives ``x``'s launched mass [m/s]."""
    g = GASES[spec.gas]
    travel_within = spec.max_barrel_length - fixture.housing_length
    return {"barrel": x.barrel + fixture.housing_length, "travel_within": travel_within,
            "chambered_speed_within": muzzle_speed(travel_within, x.launched_mass, x.reservoir_pressure,
                                                   math.pi * x.bore ** 2 / 4, sound_speed(spec.gas), g.gamma,
                                                   chambered=True)}


def _ideal_guns(M: float, speed: float, p: float, A: float, L: float) -> dict:
    """``direct_remedies``' ideal guns in air and helium for a launched mass ``M`` [kg]."""
    out = {}
    for gas in ("air", "helium"):
        g = GASES[gas]
        c0 = sound_speed(gas)
        top = 2 * c0 / (g.gamma - 1)
        out[gas] = {"barrel": travel(speed, M, p, A, c0, g.gamma) if speed < top else math.inf,
                    "speed": muzzle_speed(L, M, p, A, c0, g.gamma),
                    "chambered_barrel": travel(speed, M, p, A, c0, g.gamma, chambered=True),
                    "chambered_speed": muzzle_speed(L, M, p, A, c0, g.gamma, chambered=True)}
    return out


def _energies(a: Arrangement, b: Arrangement, bound: Arrangement | None) -> str:
    """The energy each arrangement launches for the striker's; (b0) as the lower bound it is."""
    launches = (f"launches {a.launch_energy / 1e6:.4g} MJ" if a.gun_feasible else
                f"must launch {a.required_energy / 1e6:.4g} MJ (its gun, every limit reached, launches only "
                f"{a.launch_energy / 1e6:.4g} MJ, {_times(a.required_energy, a.launch_energy)} short of it)")
    words = (f"to give the striker {0.5 * a.striker_mass * a.striker_speed ** 2 / 1e6:.4g} MJ the amplifier (a) "
             f"{launches} from {a.stored / 1e6:.4g} MJ of gas stored (p0 V0 / (gamma - 1), counted from vacuum); "
             f"the direct gun (b) {'launches' if b.gun_feasible else 'must launch'} {b.required_energy / 1e6:.4g} MJ "
             f"(the striker and its sabot) from {b.stored / 1e6:.4g} MJ stored, so (a) asks "
             f"{_times(a.required_energy, b.required_energy)} (b)'s launch energy")
    if bound is not None:
        words += (f"; (b0), the striker alone, {bound.required_energy / 1e6:.4g} MJ: a lower bound on any direct gun "
                  "(no sabot weighs nothing), not a machine")
    return words


def _feasibility(a: Arrangement, b: Arrangement, bound: Arrangement | None, remedies: dict | None) -> list[str]:
    a_ok, b_ok = a.gun_feasible and a.feasible, b.gun_feasible and b.feasible
    if a_ok and b_ok:
        better = b.machine_mass <= a.machine_mass and b.machine_length <= a.machine_length
        worse = b.machine_mass >= a.machine_mass and b.machine_length >= a.machine_length
        return [f"(b) weighs {b.machine_mass / 1e3:.3g} t and is {b.machine_length:.3g} m long against (a)'s "
                f"{a.machine_mass / 1e3:.3g} t and {a.machine_length:.3g} m: "
                + ("the direct gun is the better machine, amplification does not pay" if better else
                   "amplification pays" if worse else "neither is better on both mass and length")]
    if b_ok:
        return [f"the amplifier (a) is not a feasible machine ({a.notes[-1]}); the direct gun (b), the striker in its "
                f"sabot, is within the limits ({b.launch_speed:.4g} m/s from a {b.bore / IN:.3g} in x "
                f"{b.barrel / FT:.3g} ft gun at {b.reservoir_pressure / PSI:,.0f} psi; {b.machine_mass / 1e3:.3g} t, "
                f"{b.machine_length:.3g} m long): amplification does not pay"]
    if a_ok:
        return [f"the direct gun (b) has no gun within the limits and the amplifier (a) is feasible "
                f"({a.machine_mass / 1e3:.3g} t, {a.machine_length:.3g} m long): amplification pays"]
    lim = (remedies or {}).get("limits")
    within = (f" ({lim['barrel'] / FT:.3g} ft, {lim['bore'] / IN:.3g} in, {lim['pressure'] / PSI:,.0f} psi)"
              if lim else "")
    direct = (f"the direct gun (b) fires the striker at its {b.striker_speed:.4g} m/s but breaks its own limits ("
              + "; ".join(limit_words(b)) + ")" if b.gun_feasible else
              f"the direct gun (b) reaches {b.launch_speed:.4g} of the {b.striker_speed:.4g} m/s asked "
              f"({b.launch_energy / 1e6:.4g} of {b.required_energy / 1e6:.4g} MJ)")
    words = [f"NEITHER arrangement is feasible within the limits{within}: the amplifier (a) misses its launch energy "
             f"{_times(a.required_energy, a.launch_energy)} ({a.notes[-1]}); " + direct]
    if bound is not None:
        words.append(f"only the lower bound (b0)'s gun is within them ({bound.machine_mass / 1e3:.3g} t, "
                     f"{bound.machine_length:.3g} m long" + (", its other limits broken: " + "; ".join(
                         limit_words(bound)) if broken(bound.limits) else "") + ")" if bound.gun_feasible else
                     "not even the lower bound (b0)'s gun is within them")
    if remedies:
        air, he = remedies["air"], remedies["helium"]
        words.append(f"what would change it for (b), the striker in its sabot ({remedies['launched']:.4g} kg) at the "
                     f"widest bore and highest pressure: a barrel of at least {air['barrel'] / FT:.3g} ft in air "
                     f"(the simple-wave gun; {remedies['constant_pressure_barrel'] / FT:.3g} ft at the "
                     f"constant-pressure bound), or {he['barrel'] / FT:.3g} ft in helium; at the barrel limit the "
                     f"simple-wave gun gives {air['speed']:.4g} m/s in air and {he['speed']:.4g} m/s in helium, the "
                     f"infinitely chambered gun {air['chambered_speed']:.4g} m/s in air")
    return words


def _e_words(x: float) -> str:
    return f"{x:.3f}" if math.isfinite(x) else "never (not even at e = 1)"


def _closed_form_words(k: dict) -> str:
    be, spec = k["break_even"], k["break_even_spec"]
    air_he = k["break_even_air_against_helium"]
    return (f"the closed form (`machine.boundary`): the design's {k['masses']} masses at its effective e "
            f"{k['restitution']:.4f} keep {k['chain_efficiency']:.3g} of the launch energy "
            f"({k['chain_efficiency_elastic']:.3g} even at e = 1), so the amplifier always launches more than the "
            f"striker's energy and only the gun's higher efficiency at a lower speed can pay it back: for a striker "
            f"at {k['striker_speed']:.4g} m/s the amplifier needs less gun (p0 A L) than a direct gun firing the bare "
            f"striker only above e = {_e_words(be['air'])} in air and {_e_words(be['helium'])} in helium (the best "
            f"launch speed and mass count; at the spec's {k['launch_speed']:.4g} m/s and {k['masses']} masses "
            f"{_e_words(spec['air'])} and {_e_words(spec['helium'])}), and an air amplifier against a helium direct "
            f"gun {'pays only above ' + _e_words(air_he) if math.isfinite(air_he) else 'never pays'} (up to "
            f"{MAX_MASSES} masses); with both guns the infinitely chambered gun (a tank wider than the bore) the "
            f"air break-even is e = {_e_words(k['break_even_chambered']['air'])}; "
            f"the best pad material of the library is sized at e = {k['best_pad_restitution']:.3f} "
            f"({k['best_pad']}, its rebound on rigid masses), the design's chain runs at {k['restitution']:.3f}; "
            + _sabot_words(k))


def amplification(k: dict) -> str:
    """Whether amplification pays, from ``closed_form`` ``k``: 'does not pay' where the best chain needs more
    than ``PARITY`` times the gun of the direct machine the premise admits (the striker in its sabot), else
    as its fastest interface says ('does not pay' past the library's best solid's elastic limit, else 'may
    pay'); '' where there is no chain to compare."""
    best, w, face = k["best"], k["with_sabot"], k["interface"]
    if not best or not w["best"]:
        return ""
    if w["best"]["gun_ratio"] > PARITY or face["past_elastic_limit"]:
        return "does not pay"
    return "may pay"


def at_velocity_change(m: Machine, dv: float) -> dict:
    """The premise at the striker speed a velocity change ``dv`` [m/s] asks (``specified_striker_speed``): the
    direct gun's ideal guns at every limit (``direct_remedies``, the striker in the sabot they need), the closed
    form against that direct machine (``closed_form``), whether the infinitely chambered or simple-wave air gun
    within the limits fires the striker in its sabot and bare, and whether amplification pays there."""
    f = m.fixture
    V = specified_striker_speed(m, dv)
    remedies = direct_remedies(m.spec, f.striker_mass, V, 2 * f.housing_outer_radius)
    closed = closed_form(m, sabot=remedies["launched"] - f.striker_mass, speed=V)
    air, bare = remedies["air"], remedies["bare"]["air"]
    return {"velocity_change": dv, "striker_speed": V, "remedies": remedies, "closed": closed,
            "air_fires_sabot": bool(max(air["chambered_speed"], air["speed"]) >= V),
            "air_fires_bare": bool(max(bare["chambered_speed"], bare["speed"]) >= V),
            "amplification": amplification(closed)}


def band_verdicts(m: Machine) -> dict:
    """The premise across the velocity changes the band accepts (``PulseSpec.band_velocity_range``): at its
    least, its centre (the speed the specification asks, ``specified_striker_speed``) and its largest, and
    at the specified shape's own area (a rectangle's A T, outside the band's range where the checked shape
    has ramps) for comparison; ``flips``: the verdicts that differ between the band's two ends."""
    pulse = m.spec.pulse
    lo, hi = pulse.band_velocity_range()
    rows = {"the band's least": at_velocity_change(m, lo),
            "the band's centre": at_velocity_change(m, pulse.band_velocity_change()),
            "the band's largest": at_velocity_change(m, hi),
            f"the specified {pulse.shape}'s own area": at_velocity_change(
                m, requirement(pulse.shape, pulse.peak, pulse.duration, m.fixture.payload_mass).velocity_change)}
    ends = (rows["the band's least"], rows["the band's largest"])
    flips = [k for k in ("air_fires_sabot", "air_fires_bare", "amplification") if ends[0][k] != ends[1][k]]
    return {"rows": rows, "flips": flips}


def _tank_words(a: Arrangement, b: Arrangement) -> str:
    """What Q (p0 A L, the barrel's) leaves out: each gun's tank (``launcher.vessel``'s ASME shell)."""
    return (f"Q is the barrels' p0 A L and leaves out the tanks that feed them: with its tank the amplifier's gun "
            f"weighs {a.gun_mass / 1e3:.4g} t (the tank {a.tank_mass / 1e3:.4g} t) and the direct gun's "
            f"{b.gun_mass / 1e3:.4g} t (the tank {b.tank_mass / 1e3:.4g} t), {_times(a.gun_mass, b.gun_mass)} it")


def _sabot_words(k: dict) -> str:
    """Q against the direct machine the premise admits (the striker in its sabot), and what the verdict
    rests on: Q where it is clearly above parity, else the best chain's fastest interface."""
    best, w, face = k["best"], k["with_sabot"], k["interface"]
    if not best or not w["best"]:
        return "no chain to compare"
    q_bare, q = best["gun_ratio"], w["best"]["gun_ratio"]
    words = (f"the best chain ({best['masses']} masses launched at {best['launch_speed']:.4g} m/s) needs Q = "
             f"{q_bare:.3g} times the gun of a direct gun firing the bare striker, and Q = {q:.3g} times that of the "
             f"direct machine the premise admits, which fires the striker in its {w['sabot']:.4g} kg sabot (the "
             f"chain's masses fill the bore and need none; break-even e {_e_words(w['break_even']['air'])} "
             f"simple-wave, {_e_words(w['break_even']['chambered'])} chambered)")
    verdict = "amplification " + amplification(k)
    if q > PARITY:
        return words + ": " + verdict
    return (words + f"; so Q alone does not decide it, the interfaces do: the best chain's fastest interface "
            f"closes at {face['closing_speed']:.0f} m/s, where the library's best solid ({face['best_solid']}) "
            f"returns an interface's energy elastically only up to v* = {face['elastic_limit_speed']:.0f} m/s; a "
            f"pad that held it would weigh {face['pad_over_struck']:.3g} times the struck body (the pads' runs "
            f"restitute {min(MEASURED_RESTITUTIONS.values()):.2f}-{max(MEASURED_RESTITUTIONS.values()):.2f} at "
            f"99 m/s): {verdict}")


def _specified_words(k: dict, remedies: dict, band_passed: bool, fixture_speed: float) -> str:
    """The premise at the striker speed the specification asks (``specified_striker_speed``)."""
    air, he = remedies["air"], remedies["helium"]
    bare = remedies.get("bare", {}).get("air", {})
    fits = max(air["chambered_speed"], air["speed"]) >= k["striker_speed"]
    bare_fits = bool(bare) and max(bare["chambered_speed"], bare["speed"]) >= k["striker_speed"]
    words = (f"the comparison above is at the designed fixture's {fixture_speed:.4g} m/s"
             + (", a pulse that fails the band" if not band_passed else "")
             + f"; at the speed the specification asks ({k['striker_speed']:.4g} m/s, the rigid collision law for "
             f"the velocity change at the band's centre at this striker) the ideal infinitely chambered air gun at every limit "
             f"gives the striker in its {remedies['launched'] - remedies['striker']:.4g} kg sabot "
             f"{air['chambered_speed']:.4g} m/s" + (f" and the bare striker {bare['chambered_speed']:.4g} m/s"
                                                    if bare else "")
             + (": an air gun within the limits could fire it" if fits else
                ": no air gun within the limits fires it in its sabot"
                + (" (the bare striker, the lower bound (b0), it would)" if bare_fits else "")
                + f"; in helium the infinitely chambered gun gives "
                f"{he['chambered_speed']:.4g} m/s (the simple-wave gun {he['speed']:.4g}), "
                + ("enough" if he["chambered_speed"] >= k["striker_speed"] else "short of it too")
                + f", and in air a barrel of {air['chambered_barrel'] / FT:.3g} ft (chambered) would fire it"))
    return words + "; there " + _sabot_words(k)


def verdict(a: Arrangement, b: Arrangement, c: Arrangement, bound: Arrangement | None = None,
            closed: dict | None = None, remedies: dict | None = None, at_spec: tuple | None = None) -> str:
    """What the arrangements say about the premise, from their numbers (``bound``: (b) with a massless
    sabot, the direct gun's lower bound, never a machine; ``closed``: ``closed_form``; ``remedies``:
    ``direct_remedies``; ``at_spec``: (``closed_form``, ``direct_remedies``, the fixture's band passed) at
    the striker speed the specification asks)."""
    words = [_energies(a, b, bound)] + _feasibility(a, b, bound, remedies)
    if closed and closed.get("scale_free"):
        words.append(_scale_free_words(closed["scale_free"]))
    if a.fixture_problems:
        words.append("every arrangement (a) to (c) carries the same fixture (its metering pin the closed form's "
                     "quasi-steady one, not cut on the column: `fixture.PIN_ITERATIONS`), and it is not within its "
                     "own limits (" + "; ".join(a.fixture_problems) + "): none of them is a feasible machine until "
                     "the fixture "
                     "is, and the comparison above is of the guns and moving masses that fixture asks")
    if closed:
        words.append(_closed_form_words(closed))
        words.append(_tank_words(a, b))
    if at_spec:
        words.append(_specified_words(*at_spec, a.striker_speed))
    if not math.isfinite(c.striker_speed):
        words.append(f"the white paper's flying target (c) has no fixture: {c.notes[-1]}")
        return "; ".join(words) + "."
    words.append(f"the white paper's own gun (c) needs a {c.barrel / FT:.3g} ft barrel for the target the fixture "
                 f"designer gives it ({c.striker_mass:.3g} kg at {c.striker_speed:.0f} m/s)" if c.gun_feasible else
                 f"the white paper's own gun (c) never reaches its target's speed ({c.striker_mass:.3g} kg at "
                 f"{c.striker_speed:.0f} m/s), however long its barrel")
    return "; ".join(words) + "."


def limit_words(x: Arrangement) -> list[str]:
    """What keeps arrangement ``x`` from being a machine, in words: its gun's shortfall, then its broken limits
    by cause (``limits.by_cause``: how many, and each cause's worst with its ratio), the fixture's left to
    ``fixture_problems`` (common to (a) to (c))."""
    out = []
    if not x.gun_feasible:
        short = x.launch_energy > 0 and math.isfinite(x.launch_energy) and math.isfinite(x.required_energy)
        out.append(f"its gun at every limit launches {x.launch_energy / 1e6:.4g} of the {x.required_energy / 1e6:.4g} "
                   f"MJ asked ({_times(x.required_energy, x.launch_energy)} short)" if short else
                   "its gun never reaches the speed, however long its barrel")
    out += [f"{c}: {n} broken, the worst {w.component}, {w.quantity}, {w.ratio:.3g} times its limit"
            for c, n, w in by_cause(x.limits) if c != "the fixture"]
    return out


def answer(rows: list[tuple], common: list[str], change: list[str], headline: str, centre: dict | None = None) -> str:
    """The premise's answer as a boxed paragraph (a Markdown block quote) for the top of a report: ``headline``,
    then per arrangement (``rows``: (arrangement, verdict, what it breaks)) its verdict, what it breaks and by
    how much, its launch energy, its machine's mass and length side by side (``centre``: {"speed", "cells":
    name -> (launch energy, gun reaches it or None)} adds each row's launch energy at the band's centre and
    whether its gun reaches it there), then ``common`` (what every arrangement with the fixture breaks) and
    ``change`` (what would change the answer)."""
    def number(x, scale, fmt):
        return format(x / scale, fmt) if math.isfinite(x) else "-"

    def at_centre(x):
        if not centre:
            return ""
        energy, reaches = centre["cells"].get(x.name, (math.nan, None))
        return (f" {number(energy, 1e6, '.4g')} | "
                f"{'-' if reaches is None else 'yes' if reaches else 'NO'} |")
    head = ("> | arrangement | verdict | what it breaks, by how much | launch energy asked [MJ] | machine [t] | "
            "length [m] |")
    rule = "> |---|---|---|---|---|---|"
    if centre:
        head += (f" at the band's centre ({centre['speed']:.4g} m/s): launch energy asked [MJ] | a gun within the "
                 "limits reaches it |")
        rule += "---|---|"
    lines = [f"> **The answer.** {headline}", ">", head, rule]
    for x, word, why in rows:
        lines.append(f"> | {x.name} | {word} | {'; '.join(why) or 'nothing'} | {number(x.required_energy, 1e6, '.4g')} | "
                     f"{number(x.machine_mass, 1e3, '.4g')} | {number(x.machine_length, 1.0, '.3g')} |{at_centre(x)}")
    lines += [">", "> " + " ".join(common + [("What would change it: " + "; ".join(change) + ".") if change else ""])]
    return "\n".join(lines)


# --- the map -------------------------------------------------------------------------------------------

# what a point can come to: the lightest feasible arrangement, or none
WINNERS = ("amplifier", "direct", "flying target", "none")
# the gun laws of the map's closed form (``boundary``): the simple-wave (constant-area) gun, and the
# infinitely chambered gun, the bound on any gun of the gas
LAWS = {"simple-wave": False, "chambered": True}


@dataclass
class MapPoint:
    duration: float               # [s]
    peak: float                   # [m/s^2]
    article: float                # [kg]
    payload: float                # with its piston [kg]
    velocity_change: float        # [m/s]
    striker_mass: float
    striker_speed: float
    chain: dict                   # the closed form's best chain, simple-wave guns (``boundary.best_chain``)
    eligible: bool                # a chain needs less gun than the direct one in its sabot (Q / direct_load < 1 by
                                  # either law): designed
    amplifier: dict               # launch energy, first mass, gun mass, machine mass, feasible, note
    direct: dict                  # the striker in its sabot, (b)
    flying: dict
    winner: str                   # WINNERS
    chain_chambered: dict = field(default_factory=dict)   # the same with both guns the infinitely chambered one
    striker_ratio: float = math.nan     # the striker over the payload at this point (``StrikerLaw``)
    note: str = ""                # why the amplifier was not designed, where it was not
    direct_load: float = 1.0      # (M + m_sabot) / M: the direct gun with the sabot its bore would need
    gun_ratio_sabot: float = math.nan   # the kept law's Q against that direct gun (Q / direct_load)
    interface: dict = field(default_factory=dict)   # the kept chain's fastest interface (``chain_interface_bound``)
    bare: dict = field(default_factory=dict)        # the striker alone, (b0): the direct gun's lower bound

    def as_dict(self) -> dict:
        return asdict(self)


def _gun_entry(L: Launcher, moving: float, feasible: bool, note: str = "") -> dict:
    g = L.design.gun
    return {"launch_energy": L.launch_energy, "launched": L.projectile_mass, "bore": g.bore, "barrel": g.length,
            "pressure": g.reservoir_pressure, "stored": L.stored_energy, "gun_mass": L.design.weight,
            "machine_mass": L.design.weight + moving, "feasible": bool(feasible), "note": note}


def _no_gun(note: str) -> dict:
    nan = math.nan
    return {"launch_energy": nan, "launched": nan, "bore": nan, "barrel": nan, "pressure": nan, "stored": nan,
            "gun_mass": nan, "machine_mass": nan, "feasible": False, "note": note}


def _amplifier_entry(s: MachineSpec, M: float, V: float, chain: Chain) -> dict:
    """The amplifier at the closed form's best launch speed and mass count: its masses by the closed form
    (the launched chain), its gun by the lightest-launcher design."""
    d = gain_design("launched-chain", M, V, chain.launch_speed, chain.restitution, chain.masses)
    if not d.feasible:
        return _no_gun(d.reason)
    L = launcher_for(s, d.masses[0], chain.launch_speed, starts=1, report_binding=False)
    return _gun_entry(L, sum(d.masses), L.design.feasible,
                      f"{chain.masses} masses launched at {chain.launch_speed:.0f} m/s, first mass {d.masses[0]:,.0f} kg")


def _winner(amp: dict, direct: dict, flying: dict) -> str:
    """The lightest feasible arrangement (WINNERS); an amplifier not designed (no chain needs less gun than
    the direct one) is not feasible, so the direct gun wins there wherever it is feasible and lightest."""
    options = {"amplifier": amp, "direct": direct, "flying target": flying}
    feasible = {k: v for k, v in options.items() if v["feasible"]}
    if not feasible:
        return "none"
    return min(feasible, key=lambda k: feasible[k]["machine_mass"])


def pads_hold(interface: dict) -> bool:
    """The map's amplifier's pads, by the closed form: its fastest interface's pad of the library's best solid
    (``chain_interface_bound``) within the share of the struck body a pad may weigh (``pads.PAD_MASS_SHARE``,
    the pads' first check, ``amplifier.pad_bound``)."""
    return interface["pad_over_struck"] <= PAD_MASS_SHARE


def pads_hold_below(spec: MachineSpec, e: float) -> float:
    """The striker speed [m/s] above which no chain at restitution ``e`` passes ``pads_hold``, whatever its
    gain and number of masses: its last interface closes at V_s / g, its mass ratio 1 + q = (1 + e) / g, so
    the pad over the struck body is (V_s / v*)^2 / (g (1 + e)), least at the largest stage gain g = 1 + e;
    within the share below v* (1 + e) sqrt(PAD_MASS_SHARE), v* the library's best solid's
    (``elastic_limit_speeds``)."""
    return (1 + e) * max(elastic_limit_speeds(spec).values()) * math.sqrt(PAD_MASS_SHARE)


def _pad_words(interface: dict) -> str:
    return (f"no pad: its fastest interface closes at {interface['closing_speed']:.0f} m/s, where a pad of the "
            f"library's best solid ({interface['best_solid']}, elastic to {interface['elastic_limit_speed']:.0f} m/s) "
            f"that held it would weigh {interface['pad_over_struck']:.3g} times the struck body (at most "
            f"{PAD_MASS_SHARE:g})")


@dataclass(frozen=True)
class StrikerLaw:
    """The fixture's striker at a map point, scaled from the designed one by what its housing's mass scales
    with: the housing over the whole bore (``fixture.striker_housing``, which sets the designed striker where
    ``housing_binds``) weighs rho pi ((R^2 - r^2) depth + R^2 t), so at the design's wall ratio R / r and
    floor over bore it goes as r^2 depth: r the bore the design oil pressure asks (``fixture.bore_radius``),
    depth the liquid column, which goes with the relative stroke (as dv T for one pulse shape), plus the
    piston and headroom and the article (``fixture.article_length``).  Never lighter than the striker asked
    (the spec's striker ratio, or the white paper's target).  Range: the design's wall ratio, floor, column
    over stroke and oil pressure carried over; exact at the design's point only (the designed striker)."""
    striker_mass: float           # the designed striker (or target) [kg]
    bore: float                   # the design oil pressure's bore at the design's point [m]
    column: float                 # the designed liquid column [m]
    rest: float                   # the bore's depth less the column and the article [m]
    article: float                # the designed fixture's article length [m]
    stroke_scale: float           # the design's velocity change times its duration [m]

    @classmethod
    def of(cls, spec: MachineSpec, fixture, striker_mass: float) -> "StrikerLaw":
        rho = property_si(spec.material, "density", "density")
        return cls(striker_mass, bore_radius(spec, rho), fixture.column,
                   fixture.bore_depth - fixture.column - fixture.article_length, fixture.article_length,
                   fixture.velocity_change * fixture.duration)

    def striker(self, s: MachineSpec, r: float, dv: float, least: float) -> float:
        """The striker [kg] at the point of spec ``s``, bore ``r`` [m] and velocity change ``dv`` [m/s], at
        least ``least`` [kg]."""
        column = self.column * dv * s.pulse.duration / self.stroke_scale
        depth = (column + self.rest + article_length(s)) / (self.column + self.rest + self.article)
        return max(least, self.striker_mass * (r / self.bore) ** 2 * depth)


def striker_laws(spec: MachineSpec, fixture, target) -> tuple[StrikerLaw, StrikerLaw]:
    """The striker's law (``StrikerLaw``) and the flying target's (its designed target in the striker's
    place; where the designer found none, the target ratio asked times the payload)."""
    t_mass = getattr(target, "striker_mass", target.striker_ratio * fixture.payload_mass)
    return StrikerLaw.of(spec, fixture, fixture.striker_mass), StrikerLaw.of(spec, fixture, t_mass)


def _chains(amp_e: float, V: float, gas: str) -> dict:
    """The best chain by each gun law (``LAWS``)."""
    return {law: best_chain(amp_e, V, gas, chambered=chambered) for law, chambered in LAWS.items()}


def map_point(spec: MachineSpec, duration: float, peak: float, article: float, strikers: tuple, fixture_e: float,
              amp_e: float, wall: float, band_end: int = 0) -> MapPoint:
    """One point of the map: the three arrangements by closed forms and the lightest-launcher design;
    ``strikers`` the striker's and the flying target's laws (``striker_laws``), ``fixture_e`` the fixture's
    restitution, ``amp_e`` the amplifier's, ``wall`` the housing's outer over its bore radius.  The velocity
    change is the band's centre (``PulseSpec.band_velocity_change``), or with ``band_end`` -1 or +1 the least or
    the largest the band accepts (``band_velocity_range``).  The amplifier's launch speed and mass count are
    the closed form's best (``boundary.best_chain``) by the gun law whose Q is lower, and it is designed only
    where that Q is below 1; the point also carries that chain's Q against the direct gun with the sabot its
    bore and pressure would need (``direct_load``, as ``closed_form``'s "with_sabot") and its fastest interface
    against the solids' elastic limit (``chain_interface_bound``)."""
    s = dataclasses.replace(spec, article_mass=article, pulse=PulseSpec(spec.pulse.shape, peak, duration))
    rho = property_si(s.material, "density", "density")
    r = bore_radius(s, rho)
    payload = article + rho * math.pi * r * r * DASHPOT["piston_thickness"]
    dv = {0: s.pulse.band_velocity_change(), -1: s.pulse.band_velocity_range()[0],
          1: s.pulse.band_velocity_range()[1]}[band_end]
    M = strikers[0].striker(s, r, dv, spec.striker_ratio * payload)
    V = striker_speed(payload, M, dv, fixture_e)
    Lb, _ = direct_launcher(s, M, V, None, starts=1, report_binding=False)
    bare = _gun_entry(Lb, M, Lb.design.feasible, "the striker alone (a massless sabot): the lower bound")
    # the striker in its sabot at the bare gun's bore (the premise's own (b) scans the bore; a point, one bore)
    L, sabot = _with_sabot(s, M, V, 2 * r * wall, max(Lb.design.gun.bore, 2 * r * wall), 1, False)
    direct = _gun_entry(L, M + sabot, L.design.feasible, f"in its {sabot:.3g} kg sabot")
    direct["sabot"] = sabot
    load = (M + sabot) / M
    chains = _chains(amp_e, V, s.gas)
    law = min(chains, key=lambda k: chains[k].gun_ratio)
    chain = chains[law]
    q = chain.gun_ratio / load
    eligible = q < 1
    note = "" if eligible else (f"nothing to amplify: the best chain ({chain.masses} masses launched at "
                                f"{chain.launch_speed:.0f} m/s) needs {q:.3g} times the gun of the direct one in its "
                                f"sabot (p0 A L, {law} guns, the lower Q of the two laws)")
    interface = chain_interface_bound(types.SimpleNamespace(spec=s), chain)
    amp = _amplifier_entry(s, M, V, chain) if eligible else _no_gun(note)
    if eligible and not pads_hold(interface):
        amp["feasible"] = False
        amp["note"] = (amp["note"] + "; " if amp["note"] else "") + _pad_words(interface)
    Mc = strikers[1].striker(s, r, dv, WHITE_PAPER_TARGET * article)
    Vc = striker_speed(payload, Mc, dv, fixture_e)
    Lc, ok = white_paper_launcher(s, Mc, Vc)
    flying = _gun_entry(Lc, Mc, ok and Lc.design.gun.length <= s.max_barrel_length,
                        f"barrel {Lc.design.gun.length / FT:.3g} ft" if ok else "never reaches the speed")
    return MapPoint(duration, peak, article, payload, dv, M, V, chains["simple-wave"].as_dict(), eligible, amp,
                    direct, flying, _winner(amp, direct, flying), chains["chambered"].as_dict(), M / payload, note,
                    load, q, interface, bare)


def premise_map(spec: MachineSpec, fixture, amp_e: float, target, durations, peaks, payloads, echo=None,
                fixed_ratio: bool = False, band_end: int = 0, workers: int = 1) -> list[MapPoint]:
    """The map over ``durations`` [s], ``peaks`` [m/s^2] and ``payloads`` (article masses) [kg]; the striker
    and the flying target scaled to each point (``StrikerLaw``), or, ``fixed_ratio``, at the designed
    fixture's ratios to the payload at every point (the sensitivity of the verdict to the law); each point at
    the band's centre, or at an end of its range (``map_point``'s ``band_end``).  ``workers`` > 1: the points
    shared among that many processes (each point's guns are designed from scratch, a point's cost is its
    guns' optimisers: seconds to a minute; the results are the same, in the same order)."""
    strikers = striker_laws(spec, fixture, target)
    jobs = [(spec, T, A, a, strikers if not fixed_ratio else _fixed(spec, fixture, target, a, T, A),
             max(fixture.restitution, 0.0), amp_e, fixture.housing_outer_radius / fixture.bore_radius, band_end)
            for a in payloads for T in durations for A in peaks]
    if workers > 1:
        with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn")) as pool:
            points = pool.map(_map_point_of, jobs)
            return [_echoed(p, echo) for p in points]
    return [_echoed(map_point(*job), echo) for job in jobs]


def _map_point_of(job: tuple) -> MapPoint:
    return map_point(*job)


def _echoed(p: MapPoint, echo) -> MapPoint:
    if echo:
        echo(f"    {p.article / LB:.0f} lb, {p.duration * 1e3:.2g} ms, {p.peak / G0:,.0f} g: dv {p.velocity_change:.0f} "
             f"m/s, striker {p.striker_ratio:.3g} x payload, Q against (b) {p.chain['gun_ratio'] / p.direct_load:.3g} "
             f"(simple-wave) {p.chain_chambered['gun_ratio'] / p.direct_load:.3g} (chambered), winner {p.winner}")
    return p


@dataclass(frozen=True)
class _Ratio:
    """A striker at a fixed ratio to the payload (``premise_map``'s ``fixed_ratio``)."""
    ratio: float
    payload: float

    def striker(self, s, r, dv, least) -> float:
        return self.ratio * self.payload


def _fixed(spec: MachineSpec, fixture, target, article: float, T: float, A: float) -> tuple:
    s = dataclasses.replace(spec, article_mass=article, pulse=PulseSpec(spec.pulse.shape, A, T))
    rho = property_si(s.material, "density", "density")
    r = bore_radius(s, rho)
    payload = article + rho * math.pi * r * r * DASHPOT["piston_thickness"]
    return _Ratio(fixture.striker_ratio, payload), _Ratio(target.striker_ratio, payload)


def boundary(points: list[MapPoint]) -> dict:
    """The map's counts: each outcome's points, the direct wins where no chain needs less gun (the amplifier
    not designed), the points where the amplifier was eligible (designed; by each gun law, and against the
    bare striker's gun instead), where it was designed but its pads cannot be (``pads_hold``), each
    arrangement's points within the limits, and the smallest velocity change the amplifier wins at against the largest the direct gun
    wins at."""
    amp = [p for p in points if p.winner == "amplifier"]
    direct = [p for p in points if p.winner == "direct"]
    counts = {w: sum(p.winner == w for p in points) for w in WINNERS}
    within = {k: sum(getattr(p, k)["feasible"] for p in points) for k in ("amplifier", "direct", "bare", "flying")}
    return {"counts": counts, "eligible": sum(p.eligible for p in points), "points": len(points), "within": within,
            "amplifier_wins": counts["amplifier"], "direct_wins": counts["direct"],
            "direct_wins_nothing_to_amplify": sum(not p.eligible for p in direct),
            "eligible_chambered": sum(p.chain_chambered["gun_ratio"] < p.direct_load for p in points),
            "eligible_simple_wave": sum(p.chain["gun_ratio"] < p.direct_load for p in points),
            "eligible_bare": sum(min(p.chain["gun_ratio"], p.chain_chambered["gun_ratio"]) < 1 for p in points),
            "pads_fail": sum(p.eligible and not pads_hold(p.interface) for p in points),
            "smallest_dv_eligible": min((p.velocity_change for p in points if p.eligible), default=math.nan),
            "striker_ratios": [min(p.striker_ratio for p in points), max(p.striker_ratio for p in points)],
            "smallest_dv_amplifier_wins": min((p.velocity_change for p in amp), default=math.nan),
            "largest_dv_direct_wins": max((p.velocity_change for p in direct), default=math.nan)}


def boundary_velocity_change(points: list[MapPoint], e: float, gas: str, chambered: bool = False,
                             at: MapPoint | None = None) -> float:
    """The velocity change [m/s] above which an amplifier of restitution ``e`` needs less gun than the direct
    gun firing the bare striker: the closed form's striker speed (``boundary.break_even_speed``) over the
    striker speed per velocity change at the point ``at`` (default the first; the striker's ratio, so this
    speed per velocity change, moves a little from point to point: a striker many times the payload closes at
    about dv / (1 + e)).  Against the striker in its sabot there is no one line: the sabot's load changes from
    point to point with its gun's bore and pressure (each point's Q against it is the map's)."""
    p = at or points[0]
    return break_even_speed(e, gas, chambered=chambered) * p.velocity_change / p.striker_speed


MARKS = {"amplifier": ("o", "#d95f02"), "direct": ("s", "#1b9e77"), "flying target": ("^", "#7570b3"), "none": ("x", "#444444")}


def map_figure(points: list[MapPoint], path: str, lines: dict | None = None):
    """One panel per payload: the outcome at each (duration, peak) with its velocity change and Q (the best
    chain's gun over the direct gun's), and ``lines`` {label: velocity change [m/s]} drawn as the
    peak-duration curve of that velocity change (the closed form's boundary)."""
    from ..output.figures import pyplot, save
    plt = pyplot()
    payloads = sorted({p.article for p in points})
    fig = plt.figure(figsize=(max(4.4 * len(payloads), 9.0), 5.6))
    grid = fig.add_gridspec(2, len(payloads), height_ratios=[5, 1.3])
    axes = [[fig.add_subplot(grid[0, k]) for k in range(len(payloads))]]
    key = fig.add_subplot(grid[1, :])
    key.axis("off")
    # the pulse's velocity change over peak x duration (one shape on the map)
    per = points[0].velocity_change / (points[0].peak * points[0].duration)
    ds, ps = [q.duration * 1e3 for q in points], [q.peak / G0 for q in points]
    styles = {False: iter(["-", "--", ":", "-."]), True: iter(["-", "--", ":", "-."])}
    for ax, a in zip(axes[0], payloads):
        for p in (q for q in points if q.article == a):
            m, c = MARKS[p.winner]
            ax.scatter(p.duration * 1e3, p.peak / G0, marker=m, color=c, s=70)
            ax.annotate(f"{p.velocity_change:.0f} m/s\nQ {p.chain['gun_ratio'] / p.direct_load:.2g} / "
                        f"{p.chain_chambered['gun_ratio'] / p.direct_load:.2g}"
                        + ("" if p.eligible else "\n(no chain)"), (p.duration * 1e3, p.peak / G0),
                        fontsize=6, xytext=(4, 4), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(min(ds) / 1.6, max(ds) * 2.2)
        ax.set_ylim(min(ps) / 1.4, max(ps) * 1.6)
        ax.set_xlabel("pulse duration [ms]")
        ax.set_ylabel("peak [g]")
        ax.set_title(f"{a / LB:.0f} lb article", fontsize=9)
        ax.grid(alpha=0.3, which="both")
    handles = [key.scatter([], [], marker=m, color=c, label=k) for k, (m, c) in MARKS.items()]
    T = np.geomspace(min(ds) / 1.6, max(ds) * 2.2, 50)
    for label, dv in (lines or {}).items():
        if not math.isfinite(dv):
            continue
        # a line's gun law by its colour (a label ending 'chambered': the chambered gun's), its e by its style
        chambered = label.endswith("chambered")
        style, colour = next(styles[chambered], "-"), "#7570b3" if chambered else "#d95f02"
        for ax in axes[0]:
            ax.plot(T, dv / (per * T * 1e-3) / G0, linestyle=style, color=colour, lw=1)
        handles.append(key.plot([], [], linestyle=style, color=colour, lw=1, label=f"{label}: {dv:.3g} m/s")[0])
    key.legend(handles=handles, fontsize=7, loc="center", ncol=4, frameon=False)
    fig.suptitle("The lightest feasible machine (gun and moving masses) that gives the pulse; Q: the best chain's gun\n"
                 "(p0 A L) over the direct gun's in its sabot, closed form, simple-wave / infinitely chambered guns; the "
                 "amplifier designed only where the lower Q < 1 ('no chain': a direct win with nothing to amplify)",
                 fontsize=9)
    save(fig, path)
    return path
