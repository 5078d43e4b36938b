"""The white paper's sizing claims set beside the design, at the white paper's assumptions and at the
design's measured restitution.

The claims (``compact-shock-tester-white-paper.md``): section 1.2, a 12 lb article (the chain's last mass)
and four more masses give a rigid-body velocity change of 1600 ft/s at restitution 0.9, the first mass
launched at 300-350 ft/s, the intermediate masses under 800 lb (under 4 ft^3 of steel), launched by a
12 in x 6 ft gun at 2000 psi; a 30 lb flying target at 1600 ft/s would need a gun about 90 ft long at the
same pressure; task 3, Eq. 2, a gain of five with four or five masses at e = 0.9.

Each is computed by the project's models: the masses by the closed form (``amplifier.gain.design``), the
gains by Eq. 2 (``amplifier.gain.stack_gain``, the stack on an anvil it describes) and the launched chain's
(``chain_gain``), the guns by the lumped gun (``launcher.gun.fire``) and the barrel a speed needs
(``barrel_length_for``).  The white paper gives its gun's bore, barrel and pressure only: the 20 ft^3 tank
and the 8 in valve opening in 2 ms are this project's assumptions (``white_paper_gun``), so the lumped
gun's speeds depend on them.  Beside them, three tank-free guns at its bore, barrel and pressure: the
simple-wave gun (a straight infinite chamber of the bore's section, ``launcher.simple_wave``: the
constant-area gun, no bound), the infinitely chambered gun (a chamber of unlimited size and section: the
most any real chamber gives) and the constant-pressure bound (an infinite reservoir right behind the base,
massless gas: p A L = m v^2 / 2).  Both of the white paper's guns are given by all three, its amplifier's
(the barrel its first mass needs at the launch speed) and its flying target's, so that neither is read by
a model that flatters it.  Its "800 lb" counts the intermediate masses only; the masses it adds to the
article include its first mass too, so they are tabled as well.

Its last collision (``last_interface``).  In the white paper the article is the chain's last mass, so the
contact of the last intermediate mass with the article is itself the test's pulse: at its e = 0.9 a nearly
elastic contact (a spring between two masses: a half-sine of the article's acceleration), not a dashpot's
plateau, and it closes at the fastest speed of its chain.  Its pad is sized by the pads' own sizing
(``machine.pads.size_pad``, each solid material at its estimated restitution, ``pads.estimated_restitution``;
the bodies steel cylinders of ``machine.amplifier.ASPECT``, the article of the spec's diameter), so the
white paper's arrangement is checked against the same limits as the design's interfaces, whatever striker the
design carries.
"""
from __future__ import annotations

import math

from ..amplifier.gain import chain_gain, collide, cylinder_size, design, stack_gain
from ..launcher.gun import barrel_length_for, fire, white_paper_gun
from ..launcher.simple_wave import muzzle_speed, travel
from ..programmer.requirement import requirement
from ..scene.library import property_si
from ..units import FT, G0, LB
from .amplifier import ASPECT, interfaces, share_speed
from .pads import PAD_MASS_SHARE, estimated_restitution, size_pad, solid_pads

CLAIM = {"article": 12 * LB, "masses": 5, "velocity_change": 1600 * FT, "launch": (300 * FT, 350 * FT),
         "intermediate": 800 * LB, "volume": 4 * FT ** 3, "e": 0.9, "gain": 5.0, "target": 30 * LB,
         "target_speed": 1600 * FT, "target_gun": 90 * FT}


def tank_free_speeds(mass: float) -> dict:
    """The white paper's bore, barrel and pressure firing ``mass`` [kg] without the assumed tank and valve:
    the simple-wave gun's and the constant-pressure bound's muzzle speeds [m/s]."""
    g = white_paper_gun(mass)
    gas = g.gas_model()
    c0 = gas.sound_speed(g.reservoir_pressure, g.reservoir_temperature)
    return {"simple_wave": muzzle_speed(g.length, mass, g.reservoir_pressure, g.area, c0, gas.gamma),
            "chambered": muzzle_speed(g.length, mass, g.reservoir_pressure, g.area, c0, gas.gamma, chambered=True),
            "constant_pressure": math.sqrt(2 * g.reservoir_pressure * g.area * g.length / mass)}


def tank_free_barrels(mass: float, speed: float) -> dict:
    """The barrels [m] the white paper's bore and pressure need for ``mass`` at ``speed`` without the assumed
    tank and valve: the simple-wave gun's and the constant-pressure bound's."""
    g = white_paper_gun(mass)
    gas = g.gas_model()
    c0 = gas.sound_speed(g.reservoir_pressure, g.reservoir_temperature)
    return {"simple_wave": travel(speed, mass, g.reservoir_pressure, g.area, c0, gas.gamma),
            "chambered": travel(speed, mass, g.reservoir_pressure, g.area, c0, gas.gamma, chambered=True),
            "constant_pressure": 0.5 * mass * speed ** 2 / (g.reservoir_pressure * g.area)}


def _chain(last: float, speed: float, launch: float, e: float, n: int, rho: float) -> dict:
    d = design("launched-chain", last, speed, launch, e, n)
    if not d.feasible:
        return {k: math.nan for k in ("first", "intermediate", "added", "volume", "added_volume", "eq2_gain",
                                      "chain_gain", "R", "wp_gun_muzzle", "simple_wave", "chambered",
                                      "constant_pressure")}
    mid = sum(d.masses[1:-1])
    R = d.masses[-1] / d.masses[0]
    return {"masses": d.masses, "first": d.masses[0], "intermediate": mid, "volume": mid / rho,
            "added": mid + d.masses[0], "added_volume": (mid + d.masses[0]) / rho,
            "eq2_gain": stack_gain(e, R, n), "chain_gain": chain_gain(e, R, n), "R": R,
            "wp_gun_muzzle": fire(white_paper_gun(d.masses[0]), samples=2).muzzle_velocity,
            **tank_free_speeds(d.masses[0])}


def last_interface(m) -> dict:
    """The white paper's own last collision (module docstring) for the spec of design ``m``: its chain at its
    assumptions (the 12 lb article last, e = 0.9, the spec's launch speed and masses), the last closing speed
    [m/s], the article's velocity change and its half-sine's peak over the spec's duration [m/s^2], and the
    lightest solid pad there against ``PAD_MASS_SHARE`` with its estimated restitution; {} when the white
    paper's chain has no design."""
    rho = property_si(m.spec.material, "density", "density")
    d = design("launched-chain", CLAIM["article"], CLAIM["velocity_change"], m.spec.launch_speed, CLAIM["e"],
               m.spec.masses)
    if not d.feasible:
        return {}
    article_area = math.pi * m.spec.diameter ** 2 / 4
    bodies = [{"name": f"m{k + 1}", **cylinder_size(mass, rho, ASPECT)} for k, mass in enumerate(d.masses[:-1])]
    bodies.append({"name": "article", "diameter": m.spec.diameter, "length": d.masses[-1] / (rho * article_area)})
    last = interfaces(m.spec, d.masses, bodies, CLAIM["e"])[-1]
    pads = {name: size_pad(last, name, estimated_restitution(name, last)) for name in solid_pads()}
    share, lightest = min((p.mass / last.struck_mass, name) for name, p in pads.items() if p.mass > 0)
    dv = collide(last.striker_mass, last.speed, last.struck_mass, 0.0, CLAIM["e"])[1]
    per_peak = requirement("half-sine", 1.0, m.spec.pulse.duration, last.struck_mass).velocity_change
    return {"interface": last.name, "striking_mass": last.striker_mass, "closing_speed": last.speed,
            "velocity_change": dv, "half_sine_peak": dv / per_peak, "lightest_pad": lightest,
            "pad_over_struck": share, "share_speed": share_speed(last, lightest),
            "pad_restitution": estimated_restitution(lightest, last)}


def claims(m) -> list[dict]:
    """The white paper's claims against the design ``m`` (a ``design.Machine``): rows of (claim, the white
    paper's figure, the project's models at the white paper's assumptions, at the design, at the design's
    restitution), SI."""
    rho = property_si(m.spec.material, "density", "density")
    launch = m.spec.launch_speed
    n = m.spec.masses
    e_d = m.amplifier.restitution
    wp = _chain(CLAIM["article"], CLAIM["velocity_change"], launch, CLAIM["e"], n, rho)
    striker, V = m.fixture.striker_mass, m.fixture.striker_speed
    at_09 = _chain(striker, V, launch, CLAIM["e"], n, rho)
    at_e = _chain(striker, V, launch, e_d, n, rho)
    rows = [
        {"claim": "intermediate masses (section 1.2) [kg]", "white_paper": CLAIM["intermediate"],
         "wp_assumptions": wp.get("intermediate"), "design_at_0.9": at_09.get("intermediate"),
         "design": at_e.get("intermediate"),
         "note": "the white paper's last mass is the 12 lb article; the design's is the striker (the dashpot's "
                 f"housing, {striker:.3g} kg at {V:.1f} m/s), {striker / CLAIM['article']:.3g} times heavier"},
        {"claim": "their volume of steel [m^3]", "white_paper": CLAIM["volume"], "wp_assumptions": wp.get("volume"),
         "design_at_0.9": at_09.get("volume"), "design": at_e.get("volume"), "note": f"at {rho:g} kg/m^3"},
        {"claim": "the masses added to the article, the first included [kg]", "white_paper": CLAIM["intermediate"],
         "wp_assumptions": wp.get("added"), "design_at_0.9": at_09.get("added"),
         "design": sum(m.amplifier.masses[:-1]),
         "note": "the white paper's 800 lb counts the intermediate masses only, not its own first mass; their "
                 f"steel: {wp.get('added_volume', math.nan) / FT ** 3:.3g} ft^3 at its assumptions"},
        {"claim": "first mass [kg]", "white_paper": math.nan, "wp_assumptions": wp.get("first"),
         "design_at_0.9": at_09.get("first"), "design": m.amplifier.masses[0],
         "note": f"launched at {launch / FT:.0f} ft/s (the white paper: 300-350)"},
        {"claim": "Eq. 2 gain (a stack on an anvil) at the chain's mass ratio [-]", "white_paper": CLAIM["gain"],
         "wp_assumptions": wp.get("eq2_gain"), "design_at_0.9": at_09.get("eq2_gain"), "design": at_e.get("eq2_gain"),
         "note": "(1 + e)^n / (1 + R^(1/(n-1)))^(n-1) - 1, R the smallest over the largest mass"},
        {"claim": "launched-chain gain at that ratio [-]", "white_paper": CLAIM["gain"],
         "wp_assumptions": wp.get("chain_gain"), "design_at_0.9": at_09.get("chain_gain"),
         "design": m.amplifier.gain,
         "note": "the design column: the rigid chain's gain at the pads' measured restitutions"},
        {"claim": "the white paper's 12 in x 6 ft gun at 2000 psi: first mass's muzzle speed [m/s]",
         "white_paper": 325 * FT, "wp_assumptions": wp.get("wp_gun_muzzle"), "design_at_0.9": at_09.get("wp_gun_muzzle"),
         "design": fire(white_paper_gun(m.amplifier.masses[0]), samples=2).muzzle_velocity,
         "note": "the lumped gun with this project's assumed 20 ft^3 tank and 8 in valve (the white paper gives "
                 f"neither); the design's own gun: {m.launcher.design.gun.bore / 0.0254:.3g} in x "
                 f"{m.launcher.design.gun.length / FT:.3g} ft at {m.launcher.design.gun.reservoir_pressure / 6894.76:,.0f} psi"},
        {"claim": "the same gun without a tank: the simple-wave gun [m/s]", "white_paper": 325 * FT,
         "wp_assumptions": wp.get("simple_wave"), "design_at_0.9": at_09.get("simple_wave"),
         "design": tank_free_speeds(m.amplifier.masses[0])["simple_wave"],
         "note": "a straight infinite chamber of the bore's section"},
        {"claim": "the same gun without a tank: the constant-pressure bound [m/s]", "white_paper": 325 * FT,
         "wp_assumptions": wp.get("constant_pressure"), "design_at_0.9": at_09.get("constant_pressure"),
         "design": tank_free_speeds(m.amplifier.masses[0])["constant_pressure"],
         "note": "p A L = m v^2 / 2: the most any gun of that bore, barrel and pressure gives"},
        {"claim": "the same gun without a tank: the infinitely chambered gun [m/s]", "white_paper": 325 * FT,
         "wp_assumptions": wp.get("chambered"), "design_at_0.9": at_09.get("chambered"),
         "design": tank_free_speeds(m.amplifier.masses[0])["chambered"],
         "note": "a chamber of unlimited size and section: the most any real chamber gives"},
    ]
    if math.isfinite(wp.get("first", math.nan)):
        own = tank_free_barrels(wp["first"], launch)
        rows.append({"claim": "barrel the white paper's 12 in gun at 2000 psi needs for its own first mass at the "
                              "launch speed, the infinitely chambered gun [m]", "white_paper": 6 * FT,
                     "wp_assumptions": own["chambered"], "design_at_0.9": math.nan, "design": math.nan, **own,
                     "note": f"its first mass {wp['first']:.4g} kg at {launch / FT:.0f} ft/s: the simple-wave gun "
                             f"needs {own['simple_wave'] / FT:.3g} ft, the chambered gun {own['chambered'] / FT:.3g} "
                             f"ft, the constant-pressure bound {own['constant_pressure'] / FT:.3g} ft, against its "
                             "6 ft"})
    last = last_interface(m)
    if last:
        rows.append({"claim": "its last collision, the last intermediate mass onto the article: closing speed [m/s]",
                     "white_paper": math.nan, "wp_assumptions": last["closing_speed"], "design_at_0.9": math.nan,
                     "design": math.nan,
                     "note": f"{last['striking_mass']:.3g} kg onto its {CLAIM['article'] / LB:.0f} lb article, the "
                             f"chain's last mass: this contact is the pulse, at e = {CLAIM['e']:g} a half-sine of "
                             f"{last['half_sine_peak'] / G0:,.0f} g over {m.spec.pulse.duration * 1e3:g} ms for its "
                             f"{last['velocity_change']:.0f} m/s, not a plateau; the lightest solid pad "
                             f"({last['lightest_pad']}, its restitution about {last['pad_restitution']:.2g} against the "
                             f"{CLAIM['e']:g} assumed) weighs {last['pad_over_struck']:.3g} times the article "
                             f"(at most {PAD_MASS_SHARE:g}: below {last['share_speed']:.3g} m/s)"})
    g = white_paper_gun(CLAIM["target"])
    lumped = barrel_length_for(g, CLAIM["target_speed"])
    free = tank_free_barrels(CLAIM["target"], CLAIM["target_speed"])
    rows.append({"claim": "barrel for a 30 lb flying target at 1600 ft/s, 12 in at 2000 psi [m]",
                 "white_paper": CLAIM["target_gun"], "wp_assumptions": lumped, "design_at_0.9": math.nan,
                 "design": math.nan, "simple_wave": free["simple_wave"], "constant_pressure": free["constant_pressure"],
                 "chambered": free["chambered"],
                 "note": f"the lumped gun with the assumed 20 ft^3 tank and valve; the simple-wave gun (no tank) needs "
                         f"{free['simple_wave'] / FT:.3g} ft, the infinitely chambered gun {free['chambered'] / FT:.3g} "
                         f"ft, the constant-pressure bound {free['constant_pressure'] / FT:.3g} ft"})
    return rows
