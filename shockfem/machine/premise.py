"""The white paper's premise tested: for the same pulse through the same fixture, is a velocity amplifier
a better machine than one gas gun firing the striker directly, or than its own flying target?

Three arrangements, each delivering the designed fixture's striker to the payload at rest:

* (a) **amplifier**: the designed machine (``design.design_machine``): a gun launches the first mass, the
  chain brings the striker to its speed;
* (b) **direct striker**: the lightest gun within the same limits (``launcher.design.lightest_launcher``)
  fires the same striker (the dashpot's housing and its oil, in a sabot where the bore is wider than the
  housing) at the same speed; the payload waits at the muzzle;
* (c) **flying target** as the white paper sizes it: a target of the white paper's mass ratio (30 lb for
  a 12 lb article), the fixture designed for it (``fixture.design_fixture``: the housing's wall may ask
  more), fired by the white paper's own gun (12 in bore, 2000 psi, 20 ft^3, ``launcher.gun.white_paper_gun``)
  with as long a barrel as the speed needs.

Each is laid out with its stops designed as absorbers (``layout.place``) and weighed the same way.

``premise_map`` then asks where each wins over pulse durations, peaks and payloads, cheaply: the striker
from the rigid collision law (``programmer.dashpot_design.striker_speed``) at the designed fixture's
striker ratio and its measured restitution; the amplifier's masses from the closed form (``amplifier.gain
.design``) at the designed amplifier's effective restitution; each gun by the lightest-launcher design (one
start) or, for (c), the white paper's gun with its barrel solved (``launcher.gun.barrel_length_for``).  The
direct gun there carries the striker in a massless sabot (its lower bound); the sabot its bore and
pressure would need (``sabot_mass``) is reported beside it, and a point the direct gun wins only without
it is marked so.  (c) counts only where its barrel is within the spec's barrel limit.  The
restitution the map's amplifier runs at is the caller's (the system study passes the designed
amplifier's effective e, the rigid chain at its pads' finite-element restitutions at the spec's point,
carried over to every point: a pad sized and run at another point would restitute otherwise).  A machine's
figure of merit there is its gun (barrel and tank) and its moving masses; the stops and frame, which the
full design adds, are left out.  Range: the fixture is designed (and its validity checked) only
at the spec's point; elsewhere its ratio and restitution are carried over, and the amplifier's pads and
stresses are not checked (only its gain).
"""
from __future__ import annotations

import dataclasses
import functools
import math
import types
from dataclasses import asdict, dataclass, field

import numpy as np

from ..amplifier.gain import design as gain_design
from ..launcher.design import LauncherDesign, weights
from ..launcher.gun import barrel_length_for, fire, white_paper_gun
from ..programmer.dashpot_design import DASHPOT, PulseSpec, striker_speed
from ..programmer.requirement import requirement
from ..scene.library import initial_yield_stress, property_si
from ..units import FT, G0, LB
from .design import Machine, gun_thrust
from .fixture import bore_radius, design_fixture
from .launcher import SIZING, Launcher, launcher_for, launcher_of
from .layout import Layout, place
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

    def as_dict(self) -> dict:
        return asdict(self)


def sabot_mass(bore: float, pressure: float, striker_diameter: float) -> float:
    """The sabot that carries a striker narrower than the bore [kg]: an aluminium (6061-T6) cone at 45
    degrees from the bore's rim to the striker's base, the gas pressing on its back.  A conical shell of
    half-angle alpha under the pressure p carries the hoop stress p rho / (t cos alpha) at radius rho
    (Roark, 7th ed., Table 13.3 case 4, membrane), so at the allowable its thickness grows with the radius,
    t = p rho / (S cos alpha), and its mass is rho_al 2 pi p (R^3 - r^3) / (3 S sin alpha cos alpha).  The
    meridional stress, the drive on the striker over the cone's section at its base, is lower for these
    strikers.  Zero when the striker fills the bore."""
    R, r = bore / 2, striker_diameter / 2
    if R <= r * (1 + 1e-9):
        return 0.0
    rho = property_si(SABOT_MATERIAL, "density", "density")
    S = initial_yield_stress(SABOT_MATERIAL) / SABOT_SAFETY
    alpha = math.pi / 4
    return rho * 2 * math.pi * pressure * (R ** 3 - r ** 3) / (3 * S * math.sin(alpha) * math.cos(alpha))


def striker_body(fixture) -> dict:
    return {"name": "striker", "shape": "carrier", "diameter": 2 * fixture.housing_outer_radius,
            "length": fixture.housing_length, "bore": 2 * fixture.bore_radius, "bore_depth": fixture.bore_depth}


def _layout(spec: MachineSpec, launcher: Launcher, fixture) -> Layout:
    """The one-body machine: the gun fires the striker (its slug), the payload at the muzzle."""
    rho = property_si(spec.material, "density", "density")
    S = initial_yield_stress(spec.material) / spec.safety_factor
    body = striker_body(fixture)
    amp = types.SimpleNamespace(bodies=[body], masses=[fixture.striker_mass], stages=[], gaps=[])
    return place(launcher, amp, fixture, rho, S, spec.catch, spec.material, [], spec.oil_pressure,
                 gun_thrust(launcher))


def _arrangement(name: str, launcher: Launcher, fixture, layout: Layout, feasible: bool, notes: list[str],
                 extra: float = 0.0) -> Arrangement:
    """An arrangement's row; ``extra``: mass it carries beyond its layout's parts (a sabot) [kg]."""
    g = launcher.design.gun
    return Arrangement(name, launcher.projectile_mass, launcher.design.muzzle_velocity, launcher.launch_energy,
                       fixture.striker_mass, fixture.striker_speed, g.bore, g.length, g.reservoir_pressure,
                       g.reservoir_volume, launcher.stored_energy, launcher.design.weight,
                       sum(i.mass for i in layout.items) + extra if layout else math.nan,
                       layout.overall_length if layout else math.nan, feasible, notes,
                       required_energy=0.5 * launcher.projectile_mass * launcher.design.required_velocity ** 2)


def amplifier_arrangement(m: Machine) -> Arrangement:
    """(a): the designed machine (its pads' restitutions measured, ``machine.amplifier``)."""
    a = m.amplifier
    notes = [f"{len(a.masses)} masses, effective e {a.restitution:.4f} (the rigid chain at its pads' "
             "restitutions: " + ", ".join(f"{e:.3f}" for e in a.restitutions) + ")"]
    if not m.feasible:
        notes.append(f"the machine is NOT FEASIBLE: {len(m.problems)} problems, the first: {m.problems[0]}")
    out = _arrangement("(a) amplifier", m.launcher, m.fixture, m.layout, m.launcher.design.feasible, notes)
    out.feasible = m.feasible
    return out


def _with_sabot(spec: MachineSpec, striker: float, speed: float, diameter: float, bore: float, starts: int,
                report_binding: bool) -> tuple[Launcher, float]:
    """The lightest gun of bore ``bore`` firing the striker in its sabot, designed again with the sabot of
    its bore and pressure until the sabot settles.  The first pass carries the sabot the spec's largest
    pressure asks at this bore (``sabot_mass`` grows with the pressure, and the lightest gun usually runs
    at the pressure limit): where the gun's pressure is that limit the sabot has settled at once."""
    s = dataclasses.replace(spec, max_bore=bore)
    sabot = sabot_mass(bore, spec.max_pressure, diameter)
    for _ in range(SABOT_PASSES):
        L = launcher_for(s, striker + sabot, speed, starts, min_bore=bore, report_binding=report_binding)
        g = L.design.gun
        new = sabot_mass(g.bore, g.reservoir_pressure, diameter)
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
                    report_binding: bool = True, bores: int = SABOT_BORES) -> tuple[Launcher, float]:
    """The lightest gun within the spec's limits firing a striker of ``striker`` [kg] and ``diameter`` at
    ``speed`` in the sabot its bore needs: the gun's optimiser does not see that the sabot grows with the
    bore (as p R^3), so the bore is scanned (``bores`` bores from half the bare striker's gun's bore, or the
    striker's diameter, to 1.25 times it, each gun designed with its sabot), the lightest gun and sabot kept.
    ``diameter`` None: a massless sabot (the lower bound), one design (``bare_launcher``, shared with the
    scan's start).  Returns the launcher and the sabot's mass."""
    bare = bare_launcher(spec, striker, speed, starts, report_binding)
    if diameter is None:
        return bare, 0.0
    # the sabot favours a narrower bore than the bare striker's gun; scan from half of that bore up
    lo = max(diameter, 0.5 * bare.design.gun.bore)
    hi = max(lo, min(spec.max_bore, 1.25 * bare.design.gun.bore))
    best = None
    for bore in np.geomspace(lo, hi, bores):
        L, sabot = _with_sabot(spec, striker, speed, diameter, float(bore), starts, False)
        key = (not L.design.feasible, L.design.weight + sabot)
        if best is None or key < best[0]:
            best = (key, L, sabot)
    return best[1], best[2]


def direct_arrangement(spec: MachineSpec, fixture, starts: int = 3, with_sabot: bool = True,
                       bores: int = SABOT_BORES) -> Arrangement:
    """(b): the same striker fired directly by the lightest gun within the same limits, in its sabot;
    ``with_sabot`` False: in a massless sabot (the direct gun's lower bound, (b0))."""
    diameter = 2 * fixture.housing_outer_radius if with_sabot else None
    L, sabot = direct_launcher(spec, fixture.striker_mass, fixture.striker_speed, diameter, starts, bores=bores)
    layout = _layout(spec, L, fixture)
    notes = [f"sabot {sabot:.3g} kg (aluminium cone; counted in the machine, its own stop not designed)" if sabot else
             ("no sabot: the striker fills the bore" if with_sabot else "the sabot's mass left out (a lower bound)")]
    if not L.design.feasible:
        notes.append(L.design.note)
    name = "(b) direct striker" if with_sabot else "(b0) direct striker, massless sabot"
    return _arrangement(name, L, fixture, layout, L.design.feasible, notes, sabot)


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


def flying_target_arrangement(spec: MachineSpec, fixture, echo=None) -> tuple[Arrangement, object]:
    """(c): the white paper's flying target (its mass ratio to the article), the fixture designed for it,
    fired by the white paper's gun with as long a barrel as it needs."""
    ratio = WHITE_PAPER_TARGET * spec.article_mass / fixture.payload_mass
    try:
        target = design_fixture(dataclasses.replace(spec, striker_ratio=ratio), echo)
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


def b0_words(a: Arrangement, bound: Arrangement | None) -> str:
    if bound is None:
        return "not designed"
    return f"{bound.launch_energy / 1e6:.3g} MJ ((a) needs {_times(a.required_energy, bound.launch_energy)} that)"


def verdict(a: Arrangement, b: Arrangement, c: Arrangement, bound: Arrangement | None = None) -> str:
    """What the three arrangements say about the premise, from their numbers (``bound``: (b) with a
    massless sabot, the direct gun's lower bound)."""
    a_ok = a.gun_feasible and a.feasible
    launches = (f"launches {a.launch_energy / 1e6:.3g} MJ" if a.gun_feasible else
                f"must launch {a.required_energy / 1e6:.4g} MJ (its gun, every limit reached, launches only "
                f"{a.launch_energy / 1e6:.3g} MJ)")
    words = [f"to give the striker {0.5 * a.striker_mass * a.striker_speed ** 2 / 1e6:.3g} MJ the amplifier (a) "
             f"{launches} from {a.stored / 1e6:.3g} MJ of stored gas; "
             f"the direct gun (b) {'launches' if b.gun_feasible else 'must launch'} {b.required_energy / 1e6:.3g} MJ "
             f"(striker and sabot) from {b.stored / 1e6:.3g} MJ, so (a) needs "
             f"{_times(a.required_energy, b.required_energy)} (b)'s energy; "
             f"(b0), the striker alone, {b0_words(a, bound)}"]
    if not a_ok:
        words.append(f"the amplifier (a) is not a feasible machine ({a.launched_mass / 1e3:,.4g} t first mass; "
                     f"{a.notes[-1]})")
    for x in [b] + ([bound] if bound else []):
        if not x.gun_feasible:
            words.append(f"{x.name}: no gun within the limits fires it at its speed")
            continue
        if not a_ok:
            words.append(f"{x.name}'s gun is within the limits ({x.machine_mass / 1e3:.3g} t, "
                         f"{x.machine_length:.3g} m long): the direct gun is the better machine, amplification does "
                         "not pay")
            continue
        better = x.machine_mass <= a.machine_mass and x.machine_length <= a.machine_length
        worse = x.machine_mass >= a.machine_mass and x.machine_length >= a.machine_length
        words.append(f"{x.name} weighs {x.machine_mass / 1e3:.3g} t and is {x.machine_length:.3g} m long against "
                     f"(a)'s {a.machine_mass / 1e3:.3g} t and {a.machine_length:.3g} m: "
                     + ("the direct gun is the better machine, amplification does not pay" if better else
                        "amplification pays" if worse else "neither is better on both mass and length"))
    if not math.isfinite(c.striker_speed):
        words.append(f"the white paper's flying target (c) has no fixture: {c.notes[-1]}")
        return "; ".join(words) + "."
    words.append(f"the white paper's own gun (c) needs a {c.barrel / FT:.3g} ft barrel for the target the fixture "
                 f"designer gives it ({c.striker_mass:.3g} kg at {c.striker_speed:.0f} m/s)" if c.gun_feasible else
                 f"the white paper's own gun (c) never reaches its target's speed ({c.striker_mass:.3g} kg at "
                 f"{c.striker_speed:.0f} m/s), however long its barrel")
    return "; ".join(words) + "."


# --- the map -------------------------------------------------------------------------------------------

@dataclass
class MapPoint:
    duration: float               # [s]
    peak: float                   # [m/s^2]
    article: float                # [kg]
    payload: float                # with its piston [kg]
    velocity_change: float        # [m/s]
    striker_mass: float
    striker_speed: float
    amplifier: dict               # launch energy, first mass, gun mass, machine mass, feasible, note
    direct: dict
    flying: dict
    winner: str

    def as_dict(self) -> dict:
        return asdict(self)


def _gun_entry(L: Launcher, moving: float, feasible: bool, note: str = "") -> dict:
    g = L.design.gun
    return {"launch_energy": L.launch_energy, "launched": L.projectile_mass, "bore": g.bore, "barrel": g.length,
            "pressure": g.reservoir_pressure, "stored": L.stored_energy, "gun_mass": L.design.weight,
            "machine_mass": L.design.weight + moving, "feasible": bool(feasible), "note": note}


def map_point(spec: MachineSpec, duration: float, peak: float, article: float, ratio: float, ratio_c: float,
              fixture_e: float, amp_e: float, wall: float) -> MapPoint:
    """One point of the map: the three arrangements by closed forms and the lightest-launcher design;
    ``ratio`` and ``ratio_c`` the strikers of (b) and (c) over the payload, ``fixture_e`` the fixture's
    restitution, ``amp_e`` the amplifier's, ``wall`` the housing's outer over its bore radius."""
    s = dataclasses.replace(spec, article_mass=article, pulse=PulseSpec(spec.pulse.shape, peak, duration))
    rho = property_si(s.material, "density", "density")
    r = bore_radius(s, rho)
    payload = article + rho * math.pi * r * r * DASHPOT["piston_thickness"]
    dv = requirement(s.pulse.shape, peak, duration, payload).velocity_change
    M = ratio * payload
    V = striker_speed(payload, M, dv, fixture_e)
    diameter = 2 * r * wall
    Lb, _ = direct_launcher(s, M, V, None, starts=1, report_binding=False)
    gb = Lb.design.gun
    sabot = sabot_mass(gb.bore, gb.reservoir_pressure, diameter)
    direct = _gun_entry(Lb, M, Lb.design.feasible, f"massless sabot; its sabot would weigh {sabot:.3g} kg")
    direct["sabot_estimate"] = sabot
    d = gain_design(s.architecture, M, V, s.launch_speed, amp_e, s.masses)
    if d.feasible and V > s.launch_speed and d.masses:
        La = launcher_for(s, d.masses[0] if s.architecture == "launched-chain" else sum(d.masses), s.launch_speed,
                          starts=1, report_binding=False)
        amp = _gun_entry(La, sum(d.masses), La.design.feasible, f"first mass {d.masses[0]:,.0f} kg")
    else:
        amp = {"launch_energy": math.nan, "launched": math.nan, "bore": math.nan, "barrel": math.nan,
               "pressure": math.nan, "stored": math.nan, "gun_mass": math.nan, "machine_mass": math.nan,
               "feasible": False, "note": d.reason or f"the striker's {V:.3g} m/s is below the launch speed: "
                                                      "nothing to amplify"}
    Mc = ratio_c * payload
    Vc = striker_speed(payload, Mc, dv, fixture_e)
    Lc, ok = white_paper_launcher(s, Mc, Vc)
    flying = _gun_entry(Lc, Mc, ok and Lc.design.gun.length <= s.max_barrel_length,
                        f"barrel {Lc.design.gun.length / FT:.3g} ft" if ok else "never reaches the speed")
    options = {"amplifier": amp, "direct": direct, "flying target": flying}
    feasible = {k: v for k, v in options.items() if v["feasible"]}
    winner = min(feasible, key=lambda k: feasible[k]["machine_mass"]) if feasible else "none"
    if winner == "direct" and amp["feasible"] and direct["machine_mass"] + sabot > amp["machine_mass"]:
        winner = "direct, if its sabot is light"
    return MapPoint(duration, peak, article, payload, dv, M, V, amp, direct, flying, winner)


def premise_map(spec: MachineSpec, fixture, amp_e: float, ratio_c: float, durations, peaks, payloads, echo=None
                ) -> list[MapPoint]:
    """The map over ``durations`` [s], ``peaks`` [m/s^2] and ``payloads`` (article masses) [kg]."""
    out = []
    for a in payloads:
        for T in durations:
            for A in peaks:
                p = map_point(spec, T, A, a, fixture.striker_ratio, ratio_c, max(fixture.restitution, 0.0), amp_e,
                              fixture.housing_outer_radius / fixture.bore_radius)
                out.append(p)
                if echo:
                    echo(f"    {a / LB:.0f} lb, {T * 1e3:.2g} ms, {A / G0:,.0f} g: dv {p.velocity_change:.0f} m/s, "
                         f"winner {p.winner}")
    return out


def boundary(points: list[MapPoint]) -> dict:
    """Where amplification pays on the map: the points it wins and the smallest velocity change among them,
    against the largest velocity change the direct gun still wins."""
    amp = [p for p in points if p.winner == "amplifier"]
    direct = [p for p in points if p.winner == "direct"]
    return {"amplifier_wins": len(amp), "direct_wins": len(direct),
            "flying_wins": sum(p.winner == "flying target" for p in points),
            "direct_if_light_sabot": sum(p.winner == "direct, if its sabot is light" for p in points),
            "none": sum(p.winner == "none" for p in points), "points": len(points),
            "smallest_dv_amplifier_wins": min((p.velocity_change for p in amp), default=math.nan),
            "largest_dv_direct_wins": max((p.velocity_change for p in direct), default=math.nan)}


def map_figure(points: list[MapPoint], path: str):
    """One panel per payload: the winner at each (duration, peak), and the direct machine's mass over the
    amplifier's written at each point."""
    from ..output.figures import pyplot, save
    plt = pyplot()
    payloads = sorted({p.article for p in points})
    fig, axes = plt.subplots(1, len(payloads), figsize=(4.2 * len(payloads), 4.0), squeeze=False)
    marks = {"amplifier": ("o", "#d95f02"), "direct": ("s", "#1b9e77"), "direct, if its sabot is light": ("D", "#a6d854"),
             "flying target": ("^", "#7570b3"), "none": ("x", "#444444")}
    for ax, a in zip(axes[0], payloads):
        for p in (q for q in points if q.article == a):
            m, c = marks[p.winner]
            ax.scatter(p.duration * 1e3, p.peak / G0, marker=m, color=c, s=70)
            ratio = p.amplifier["machine_mass"] / p.direct["machine_mass"] if p.direct["feasible"] else math.nan
            ax.annotate(f"{p.velocity_change:.0f} m/s" + (f"\na/b {ratio:.2g}" if math.isfinite(ratio) else ""),
                        (p.duration * 1e3, p.peak / G0), fontsize=6, xytext=(4, 4), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ds, ps = [q.duration * 1e3 for q in points], [q.peak / G0 for q in points]
        ax.set_xlim(min(ds) / 1.6, max(ds) * 2.2)
        ax.set_ylim(min(ps) / 1.4, max(ps) * 1.6)
        ax.set_xlabel("pulse duration [ms]")
        ax.set_ylabel("peak [g]")
        ax.set_title(f"{a / LB:.0f} lb article", fontsize=9)
        ax.grid(alpha=0.3, which="both")
    handles = [axes[0][0].scatter([], [], marker=m, color=c, label=f"{k} wins") for k, (m, c) in marks.items()]
    fig.legend(handles=handles, fontsize=7, loc="lower center", ncol=len(marks))
    fig.suptitle("The lightest machine (gun and moving masses) that gives the pulse\n"
                 "a/b: the amplifier's mass over the direct gun's (massless sabot)", fontsize=9)
    fig.subplots_adjust(bottom=0.27, top=0.82)
    save(fig, path)
    return path
