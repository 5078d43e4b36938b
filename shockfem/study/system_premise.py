"""The system study's sections on a shot's energy, the verdict's limits, the structural damping, the
premise (amplifier, direct striker, flying target, gas drive, and the map of where each wins) and the white paper
side by side (``study/system.py`` runs them after the machines are designed)."""
from __future__ import annotations

import copy
import math
import os

from ..amplifier import rigid
from ..amplifier.chain import run_chain_scene
from ..machine import drive_end as E
from ..machine import gas_drive as D
from ..machine import premise as P
from ..machine.amplifier import chain_scene
from ..machine.gas_spring_chain import gas_spring_chain
from ..machine.limits import broken, by_cause, counted, verdict_line
from ..machine.stops import OIL_SOUND_SPEED
from ..programmer.dashpot_design import OIL
from ..machine.white_paper import CLAIM, claims
from ..units import FT, G0, IN, LB, PSI
from .report import Report


def energy(rep: Report, machines: dict, lb: int):
    """Every joule of a shot, for every payload, the table in full for ``lb``."""
    rep.heading("5. Every joule of a shot")
    rows = []
    for n, m in machines.items():
        e, t = m.energy, m.totals
        by = {g: sum(r.energy for r in e.rows if r.part and r.group == g) for g in ("gun", "interface", "stop",
                                                                                   "fixture", "payload")}
        rows.append([n, e.stored / 1e6, e.gas_work / 1e6, m.launcher.launch_energy / 1e6, by["gun"] / 1e6,
                     by["interface"] / 1e6, by["stop"] / 1e6, by["fixture"] / 1e6, by["payload"] / 1e6,
                     e.payload / e.stored, e.closure, e.models_closure])
    rep.table("energy_totals", ["payload [lb]", "gas stored [MJ]", "gas work [MJ]", "launched [MJ]",
                                "gun's losses [MJ]", "interfaces [MJ]", "to the stops [MJ]", "fixture's oil [MJ]",
                                "payload [MJ]", "payload / stored [-]", "closure [-]",
                                "closure, the gun's shortfall out [-]"], rows,
              ["{}"] + ["{:.4g}"] * 8 + ["{:.2%}", "{:+.3%}", "{:+.3%}"])
    for n, x in machines.items():
        if abs(x.energy.closure) > 5e-3:
            short = x.launcher.design.muzzle_velocity < x.spec.launch_speed * (1 - 1e-3)
            rep.text(f"The {n} lb table does not close ({x.energy.closure:+.1%}): "
                     + (f"its gun fires the first mass at {x.launcher.design.muzzle_velocity:.4g} m/s, the chain was "
                        f"launched at {x.spec.launch_speed:.4g} (the gun falls short: section 6); with that shortfall "
                        f"({x.energy.shortfall / 1e6:.4g} MJ) taken out the parts close on the gas work to "
                        f"{x.energy.models_closure:+.3%}." if short else
                        "the models disagree on the speeds they hand each other: " + "; ".join(x.energy.notes[1:]) + "."))
    m = machines[lb]
    e = m.energy
    rep.text(f"The {lb} lb machine's shot, row by row (`{lb}lb/machine.md` has it too). Each row comes from the "
             "model that owns it (the gun's own accounts, the designed chain's collisions at its pads' restitutions, "
             "the fixture's column run), so the "
             "parts close on the gas work only if the models agree: "
             f"{e.closure:+.3%} here (`shockfem verify machine_energy` holds it within 0.5%).")
    rep.table("energy", ["where the energy is", "energy [MJ]", "of the gas work", "a part of it"],
              [[r.name, r.energy / 1e6, r.energy / e.gas_work, "yes" if r.part else "-"] for r in e.rows]
              + [["the parts' sum", e.parts / 1e6, e.parts / e.gas_work, ""]], ["{}", "{:.4f}", "{:.2%}", "{}"])
    rep.text("; ".join(e.notes) + ".")
    rep.figure(f"{lb}lb/energy.png", f"The {lb} lb machine's shot: the stored gas, and the gas work split into "
               "its parts")
    stops = m.layout.stops
    rep.table("stops", ["body", "mass [kg]", "speed [m/s]", "energy [MJ]", "absorber", "stroke [m]", "peak force [MN]",
                        "own length [m]", "own mass [kg]", "used a shot [kg]", "allowed force"],
              [[s.body, s.mass, s.speed, s.energy / 1e6, s.kind, s.stroke, s.force / 1e6, s.length, s.absorber_mass,
                s.consumed, s.limit] for s in stops],
              ["{}", "{:,.4g}", "{:.1f}", "{:.3g}", "{}", "{:.3g}", "{:.3g}", "{:.3g}", "{:,.0f}", "{:,.1f}", "{}"])
    rep.text(f"The stops take {m.totals['energy_to_stops'] / 1e6:.3g} MJ a shot, "
             f"{m.totals['energy_to_stops'] / e.gas_work:.0%} of the gas work; their absorbers add "
             f"{m.totals['stops_length']:.3g} m of length and {m.totals['stops_mass']:,.0f} kg to the machine, and "
             f"{m.totals['consumed_per_shot']:,.0f} kg (honeycomb, water) is used up every shot. Each absorber is the "
             "shortest of a hydraulic buffer, an aluminium honeycomb and a water brake that holds its limits "
             "(`machine/stops.py`).")


def limits(rep: Report, machines: dict):
    """The verdict of every machine, on its limits."""
    rep.heading("6. The verdict: every part within its limits")
    rows = []
    for n, m in machines.items():
        worst = max(m.limits, key=lambda lim: lim.ratio)
        rows.append([n, len(counted(m.limits)), len(m.limits) - len(counted(m.limits)), len(broken(m.limits)),
                     len(by_cause(m.limits)), f"{worst.component}: {worst.quantity}", worst.ratio,
                     "FEASIBLE" if m.feasible else "NOT FEASIBLE"])
    rep.table("verdicts", ["payload [lb]", "limits checked", "set by the design (not counted)", "broken",
                           "causes", "the highest ratio", "ratio", "verdict"], rows,
              ["{}", "{}", "{}", "{}", "{}", "{}", "{:.3f}", "{}"])
    rep.text("A machine is FEASIBLE only when every limit holds (every stress against its own material's allowable, "
             "each absorber's limits, the dashpot oil's heating a shot, the largest single part against the road's "
             "envelope: 13.6 m, 2.55 m, 24 t, Council Directive 96/53/EC on a standard semi-trailer, the frame, rails "
             "and tank sectioned) and every part's model found a design. `<N>lb/machine.md` lists every limit with its basis and source.")
    for n, m in machines.items():
        if not m.feasible:
            rep.text(f"**{n} lb, NOT FEASIBLE**: {verdict_line(m.limits)}. Each: " + "; ".join(m.problems) + ".")


def not_runnable(m) -> str:
    """Why the designed chain is not run in 1D ('' when it is): its gun falls short of the launch speed, or
    its pads break their limits (a pad many times past its slenderness, or heavier than its struck body, is
    outside the 1D pads' model, a massless spring-dashpot; its run would also follow the bodies across gaps
    of tens of metres)."""
    words = []
    L = m.launcher.design
    if not L.feasible:
        words.append(f"its gun fires the first mass at {L.muzzle_velocity:.4g} m/s, not the {m.spec.launch_speed:.4g} "
                     "the chain was designed for")
    pads = broken(m.amplifier.limits)
    if pads:
        words.append(f"{len(pads)} of its pads' limits are broken (the worst: {pads[0].component}, "
                     f"{pads[0].quantity} {pads[0].ratio:.3g} times its limit)")
    return "; ".join(words)


def damping(rep: Report, m, out_dir: str):
    """The designed chain in 1D with no structural damping, stiffness-proportional and band damping: how
    much of the effective restitution is the damping model."""
    rep.heading("7. The designed chain in 1D: waves and the damping model")
    why = not_runnable(m)
    if why:
        rep.text(f"Not run: the {round(m.spec.article_mass / LB)} lb machine is NOT FEASIBLE and its chain is not one "
                 f"the 1D model can run: {why}.")
        rep.value("damping_run", False)
        return
    rep.value("damping_run", True)
    base = chain_scene(m.spec, m.amplifier, m.fixture)
    rows = []
    for label, kind, ratio in (("none", "band", 0.0), ("stiffness-proportional 2% at the first mode", "stiffness", 0.02),
                               ("band 2% over the first modes (the design's)", "band", 0.02)):
        raw = copy.deepcopy(base)
        raw["chain"]["damping_type"], raw["chain"]["damping"] = kind, ratio
        r = run_chain_scene(raw, os.path.join(out_dir, "damping", kind + f"_{ratio:g}"), "1d", progress=False,
                            echo=lambda *a: None)
        e = rigid.effective_restitution(m.amplifier.masses, m.spec.launch_speed, r["gain"], m.spec.architecture)
        rows.append([label, r["gain"], r["test_article_speed"], e])
    rep.table("damping", ["structural damping", "1D gain", "striker speed [m/s]", "effective e"], rows,
              ["{}", "{:.4f}", "{:.2f}", "{:.4f}"])
    spread = max(r[3] for r in rows) - min(r[3] for r in rows)
    rep.text(f"The designed chain run in 1D (`amplifier.bars`: elastic bars, each pad a spring of its secant "
             f"stiffness and one dashpot damping ratio for all, set to the design's effective e "
             f"{m.amplifier.restitution:.4f}) three ways: the effective restitution moves by {spread:.4f} between "
             f"them, so the structural damping model is {'not ' if spread < 0.01 else ''}what sets the chain's "
             "losses. This is a check with physics the design's rigid chain leaves out (the bars' waves through "
             "the whole chain at once) and without some it has (each pad's own law and its measured restitution: "
             "the 1D pads share one damping ratio).")


ARRANGEMENT_HEADER = ["arrangement", "launched [kg]", "launch speed [m/s]", "launch energy [MJ]", "striker [kg]",
                      "striker speed [m/s]", "bore [in]", "barrel [ft]", "reservoir [psi]", "reservoir [m^3]",
                      "gas stored, p0 V0 / (gamma - 1) from vacuum [MJ]", "its TNT equivalent [t]", "tank [kg]",
                      "gun [kg]", "machine [kg]", "length [m]", "gun reaches it", "notes"]
ARRANGEMENT_FORMATS = ["{}", "{:,.4g}", "{:.1f}", "{:.4g}", "{:.4g}", "{:.1f}", "{:.3g}", "{:.3g}", "{:,.0f}",
                       "{:.3g}", "{:.4g}", "{:.3g}", "{:,.0f}", "{:,.0f}", "{:,.0f}", "{:.3g}", "{}", "{}"]
# the energy of a tonne of TNT by definition (4.184 GJ): the stored gas as a siting hazard's yardstick
TNT_TONNE = 4.184e9


def _arrangement_row(x) -> list:
    return [x.name, x.launched_mass, x.launch_speed, x.launch_energy / 1e6, x.striker_mass, x.striker_speed,
            x.bore / IN, x.barrel / FT, x.reservoir_pressure / PSI, x.reservoir_volume, x.stored / 1e6,
            x.stored / TNT_TONNE, x.tank_mass, x.gun_mass,
            x.machine_mass, x.machine_length, "yes" if x.gun_feasible else "NO", "; ".join(x.notes)]


def premise(rep: Report, m, cfg, echo, answer_at_top: bool = False) -> tuple:
    """The three arrangements for the same pulse through the same fixture, and the verdict; the answer boxed
    (``answer_box``) after it, or at the report's top with ``answer_at_top`` (the premise's own study)."""
    lb = round(m.spec.article_mass / LB)
    rep.heading(f"8. The premise: the amplifier against a direct striker and a flying target ({lb} lb)")
    echo("  (b) the striker fired directly")
    a = P.amplifier_arrangement(m)
    stars = []
    if cfg.get("best_chain"):
        echo("  (a*) the amplifier at its best chain")
        stars = [P.best_chain_arrangement(m, rep.path("best_chain"), cfg["starts"])]
    sabot_starts = cfg.get("sabot_starts", cfg["starts"])
    b = P.direct_arrangement(m.spec, m.fixture, sabot_starts, bores=cfg["sabot_bores"])
    bv = P.direct_arrangement(m.spec, m.fixture, sabot_starts, bores=cfg["sabot_bores"], vented=True)
    bk = P.direct_arrangement(m.spec, m.fixture, sabot_starts, bores=cfg["sabot_bores"], vented=True, kept=True)
    b0 = P.direct_arrangement(m.spec, m.fixture, cfg["starts"], with_sabot=False)
    echo("  (c) the white paper's flying target")
    c, target = P.flying_target_arrangement(m.spec, m.fixture, evaluations=cfg["fixture_evaluations"])
    echo("  (d) the closed-breech gas drive")
    drives = D.gas_drives(m.spec, m.fixture)
    d_rows = [D.arrangement(x) for x in drives]
    header = ARRANGEMENT_HEADER[:-2] + [f"gun reaches it (at the fixture's {m.fixture.striker_speed:.4g} m/s"
                                        + ("" if m.fixture.band_passed else ", a pulse that fails the band") + ")",
                                        "notes"]
    rep.table("arrangements", header, [_arrangement_row(x) for x in (a, *stars, b, bv, bk, b0, c, *d_rows)],
              ARRANGEMENT_FORMATS)
    s = m.spec
    rep.text("(a) to (c) deliver the striker the fixture designer chose to the payload at rest, the same "
             "pulse through the same dashpot; each is laid out with its stops designed as absorbers and weighed the "
             f"same way (`machine/premise.py`). (b) is the lightest gun within the same limits "
             f"({s.max_barrel_length / FT:.3g} ft, {s.max_bore / IN:.3g} in, {s.max_pressure / PSI:,.0f} "
             "psi) with the striker in an aluminium sabot (its mass grows with the bore, so the bore is scanned); "
             "its barrel as laid out, unvented, and (b, vented) the same gun with its last striker length ported "
             "into the atmosphere (`launcher.ported_push`: the valve stays open on the tank, as in the gun model), "
             "and (b, its sabot kept) that ported gun with the sabot kept on the striker through the pulse and "
             "stopped with it by the striker's stop (no sabot stop; its mass on the striker in the fixture's column "
             "run, and the muzzle's jet on it, filling the bore, past the muzzle); "
             "(b0) the same with a massless sabot, the direct gun's lower bound; (c) the white paper's flying "
             f"target (its 30 lb for a 12 lb article in proportion: {P.WHITE_PAPER_TARGET * s.article_mass / LB:.3g} "
             "lb here, the fixture designed for it) fired by the white paper's own gun "
             "(12 in, 2,000 psi, 20 ft^3) with as long a barrel as it needs; (d) the closed-breech gas drive "
             "(`machine/gas_drive.py`, the HYGE-type actuator: the gas drives piston, carriage and article itself, "
             "no striker and no dashpot; its 'launched' column is the moving mass, its 'barrel' the stroke) in air "
             f"and in helium at the spec's {s.max_pressure / PSI:,.0f} psi, its pulse by the infinitely chambered "
             "gun's base pressure with the valve's onset ramp, its thrust ended by vent ports and the piston's "
             "arrest (the carriage and article separating and caught at the spec's catch deceleration after the "
             "band's window; the model leaves out the valve's dynamics beyond that ramp, gas friction and heat loss, the seal, the piston's elastic waves).")
    gas_drive_table(rep, drives)
    f = m.fixture
    closed = P.closed_form(m, sabot=b.launched_mass - b.striker_mass)
    remedies = P.direct_remedies(m.spec, f.striker_mass, f.striker_speed, 2 * f.housing_outer_radius)
    # the premise at the speed the specification asks (the band's centre, the map's law at the spec's point)
    # and across the band's range, its direct machine the striker in the sabot the limits' bore and pressure need
    band = P.band_verdicts(m)
    centre = band["rows"]["the band's centre"]
    remedies_spec, closed_spec = centre["remedies"], centre["closed"]
    boundary_table(rep, closed)
    band_table(rep, m, band)
    springs = gas_spring_section(rep, m, b.launched_mass - b.striker_mass)
    echo("  (b), (b0) and the amplifiers' guns again at the band's centre")
    speed = centre["striker_speed"]
    guns = {"direct": P.direct_at_speed(m.spec, f, speed, sabot_starts, cfg["sabot_bores"]),
            "amplifiers": {x.name: P.amplifier_at_speed(m.spec, x, speed, cfg["starts"]) for x in (a, *stars)}}
    centre_table(rep, guns)
    words = (P.verdict(a, b, c, b0, closed, remedies, (closed_spec, remedies_spec, f.band_passed))[:-1] + "; "
             + D.verdict_words(drives, a, b) + ".")
    rep.text("**Verdict.** " + words[0].upper() + words[1:])
    for x in (a, b, b0, c):
        rep.value(f"launch_energy_{x.name.split(')')[0].strip('(')}", x.launch_energy)
    rep.value("premise_closed_form", closed)
    rep.value("direct_remedies", remedies)
    rep.value("gas_drives", [{"gas": x.gas, "feasible": x.feasible, "in_band": x.in_band,
                              "worst_excess": x.band.worst_excess if x.band else None,
                              "machine_mass": x.machine_mass, "machine_length": x.machine_length,
                              "moving_mass": x.moving.total if x.moving else None,
                              "bore": x.gun.bore if x.gun else None, "stored": y.stored,
                              "broken": [lim.describe() for lim in broken(x.limits)]}
                             for x, y in zip(drives, d_rows)])
    rep.value("premise_closed_form_at_spec", closed_spec)
    rep.value("direct_remedies_at_spec", remedies_spec)
    rep.value("at_the_band_centre", guns)
    rep.value("direct", b.as_dict())
    rep.value("direct_vented", bv.as_dict())
    rep.value("direct_kept", bk.as_dict())
    box = answer_box(m, (a, b, b0, c), list(zip(d_rows, drives)), band, closed_spec, stars, springs, bv, guns, bk)
    rep.lead(box) if answer_at_top else rep.text(box)
    return a, b, b0, c, target


def band_table(rep: Report, m, band: dict):
    """The premise at the velocity changes the band accepts (``premise.band_verdicts``)."""
    rows = []
    for label, x in band["rows"].items():
        r, k = x["remedies"], x["closed"]
        best, w, face = k["best"] or {}, k["with_sabot"]["best"] or {}, k["interface"] or {}
        rows.append([label, x["velocity_change"], x["striker_speed"], r["air"]["chambered_speed"],
                     r["bare"]["air"]["chambered_speed"], r["helium"]["chambered_speed"],
                     "yes" if x["air_fires_sabot"] else "no", "yes" if x["air_fires_bare"] else "no",
                     best.get("gun_ratio", float("nan")), w.get("gun_ratio", float("nan")),
                     face.get("closing_speed", float("nan")), face.get("pad_over_struck", float("nan")),
                     x["amplification"] or "-"])
    rep.table("premise_band", ["velocity change", "dv [m/s]", "striker speed [m/s]",
                               "chambered air gun at every limit, striker in its sabot [m/s]",
                               "the same, bare striker [m/s]", "chambered helium gun, in its sabot [m/s]",
                               "an air gun within the limits fires it in its sabot", "... bare",
                               "Q, bare striker [-]", "Q, in its sabot [-]", "fastest interface [m/s]",
                               "pad that held it over struck body [-]", "amplification"], rows,
              ["{}", "{:.1f}", "{:.1f}", "{:.4g}", "{:.4g}", "{:.4g}", "{}", "{}", "{:.3g}", "{:.3g}", "{:.0f}",
               "{:.3g}", "{}"])
    lo, hi = m.spec.pulse.band_velocity_range()
    names = {"air_fires_sabot": "whether an air gun within the limits fires the striker in its sabot",
             "air_fires_bare": "whether it fires the bare striker ((b0), the lower bound)",
             "amplification": "whether amplification pays"}
    flips = band["flips"]
    rep.text(f"The speed the specification asks is the one for the velocity change of the pulse the band accepts: "
             f"the band's centre, the checked shape's ideal ({m.spec.pulse.checked_shape}, "
             f"{m.spec.pulse.band_velocity_change():.4g} m/s; `PulseSpec.band_velocity_change`), not the specified "
             f"{m.spec.pulse.shape}'s own area ({rows[-1][1]:.4g} m/s, the last row, outside the band's range); the "
             f"band accepts {lo:.4g} to {hi:.4g} m/s. Across that range "
             + ("no verdict flips" if not flips else "these flip between its two ends: " + "; ".join(names[k] for k in flips))
             + " (the table: each row the rigid collision law's striker speed at the fixture's restitution, the "
             "ideal guns of `direct_remedies` and the closed form of `closed_form` at it).")
    rep.value("premise_band", {label: {k: v for k, v in x.items() if k not in ("remedies", "closed")}
                               for label, x in band["rows"].items()} | {"flips": flips})


def centre_table(rep: Report, guns: dict):
    """The guns again at the band's centre (``premise.direct_at_speed``, ``premise.amplifier_at_speed``)."""
    d, rows = guns["direct"], []
    for label, key in (("(b) direct striker, air", "air"), ("(b) direct striker, helium", "helium"),
                       ("(b0) bare striker, air", "bare")):
        x = d[key]
        rows.append([label, x["launch_energy"] / 1e6, x["muzzle_velocity"], "yes" if x["feasible"] else "NO",
                     x["bore"] / IN, x["travel"] / FT, x["pressure"] / PSI, x["tank"], (x["gun_mass"] + x["sabot"]) / 1e3,
                     x["travel_to_reach"] / FT, "the lightest gun within the limits designed again (its bore scanned "
                     "with its sabot)" if key != "bare" else "the lightest gun within the limits designed again"])
    for name, x in guns["amplifiers"].items():
        rows.append([name, x["launch_energy"] / 1e6, x.get("muzzle_velocity", math.nan),
                     "yes" if x["gun_reaches"] else "NO", math.nan, math.nan, math.nan, math.nan,
                     x.get("gun_mass", math.nan) / 1e3, math.nan,
                     f"the same chain, its first mass at {x['launch_speed']:.4g} m/s: {x['how']}"])
    rep.table("premise_at_centre", [f"at the band's centre ({d['speed']:.4g} m/s)", "launch energy asked [MJ]",
                                    "muzzle speed reached [m/s]", "reaches it", "bore [in]", "travel [ft]",
                                    "reservoir [psi]", "tank [m^3]", "gun and sabot [t]",
                                    "travel the air gun needs, its other variables kept (lumped gun) [ft]", "how"],
              rows, ["{}", "{:.4g}", "{:.4g}", "{}", "{:.3g}", "{:.3g}", "{:,.0f}", "{:.3g}", "{:.4g}", "{:.3g}", "{}"])
    rep.text("The arrangements' table above is at the designed fixture's striker speed; the band's centre asks "
             "more. This table designs (b)'s and (b0)'s guns again for it (`premise.direct_at_speed`; the lumped "
             "gun of `launcher.gun.fire`, its valve the full bore) and scales the amplifiers' chains (their rigid "
             "gain fixed, so the launch energy goes as the speed squared), their guns designed again where the "
             "answer is not already known (`premise.amplifier_at_speed`).")


def _worst(x) -> tuple[float, str]:
    """What keeps an arrangement from being a machine most, as (the ratio, its words): the gun's shortfall in
    launch energy, else its worst broken limit beyond the fixture's (common to (a) to (c))."""
    if not x.gun_feasible:
        if x.launch_energy > 0 and math.isfinite(x.launch_energy) and math.isfinite(x.required_energy):
            r = x.required_energy / x.launch_energy
            return r, f"its gun at every limit is {r:.3g} times short of the launch energy"
        return math.inf, "its gun never reaches the speed"
    worst = [lim for lim in broken(x.limits) if not lim.component.startswith(("dashpot", "striker housing",
                                                                             "piston", "article"))]
    if not worst:
        return 1.0, "nothing of its own broken"
    w = worst[0]                            # broken(): the worst first
    return w.ratio, f"{w.component}: {w.quantity}, {w.ratio:.3g} times its limit"


def _headline(m, amplifiers: list, b, bv, bk, closed_spec: dict, guns: dict, machine, least: float) -> str:
    """The premise's answer in two sentences: whether amplification makes the tester feasible and by how much
    each amplifier misses, with the fixture every arrangement shares (Q at the band's centre beside it, and
    what decides when Q is at parity); then the direct gun it would replace, with its margins at the band's
    centre and its least speed (``least`` [m/s])."""
    s = m.spec
    lb = round(s.article_mass / LB)
    amplified = [x.name for x in amplifiers if machine(x) == "FEASIBLE"]
    first = (f"Velocity amplification does {'' if amplified else 'not '}make a compact non-pyrotechnic tester "
             f"feasible for the {lb} lb spec ({s.pulse.peak / G0:,.0f} g x {s.pulse.duration * 1e3:.3g} ms, within "
             f"{s.max_barrel_length / FT:.3g} ft, {s.max_bore / IN:.3g} in, {s.max_pressure / PSI:,.0f} psi): "
             + ("FEASIBLE: " + ", ".join(amplified) if amplified else
                "; ".join(f"{x.name.split(' ')[0]} {_worst(x)[1]}" for x in amplifiers)))
    f = m.fixture
    if amplifiers[0].fixture_problems:
        first += (f"; and every arrangement with a striker carries the designed fixture, which sets it at "
                  f"{f.striker_ratio:.3g} times the payload ({s.striker_ratio:.3g} asked) and breaks its own limits "
                  f"({len(amplifiers[0].fixture_problems)}, the first: {amplifiers[0].fixture_problems[0]}), so "
                  "none is FEASIBLE until it is: the comparison holds it equal")
    w, face = (closed_spec.get("with_sabot") or {}).get("best"), closed_spec.get("interface") or {}
    if w:
        q = w["gun_ratio"]
        first += (f"; at the band's centre the closed form's best chain needs Q = {q:.3g} of the direct gun's "
                  f"p0 A L" + (f", within {P.PARITY - 1:.0%} of parity (Q is a ratio of ideal guns), so the "
                               f"interfaces decide: its fastest closes at "
                               f"{face['closing_speed']:.0f} m/s, where the library's best solid returns its energy "
                               f"only up to {face['elastic_limit_speed']:.0f} m/s" if q <= P.PARITY and face else
                               ", more gun than the direct machine"))
    built = [x for x in amplifiers if x.gun_feasible and math.isfinite(x.gun_mass)]
    if built and b.gun_feasible:
        x = min(built, key=lambda y: y.gun_mass)
        first += (f" (the designed guns, tanks included: {x.name.split(' ')[0]}'s {x.gun_mass / 1e3:.4g} t against "
                  f"(b)'s {b.gun_mass / 1e3:.4g} t at the fixture's speed, {x.gun_mass / b.gun_mass:.3g} times)")
    air, he, V = guns["direct"]["air"], guns["direct"]["helium"], guns["direct"]["speed"]
    gun = (f"its air gun within the limits reaches it ({air['launch_energy'] / 1e6:.4g} MJ)" if air["feasible"] else
           f"its air gun at every limit reaches {air['muzzle_velocity']:.4g} m/s, "
           f"{100 * (1 - air['muzzle_velocity'] / V):.1f}% short (a {air['travel_to_reach'] / FT:.3g} ft travel would "
           f"reach it" + (", or helium within the limits" if he["feasible"] else "") + "; the band's least "
           f"velocity change asks {least:.4g} m/s, which it " + ("reaches" if air["muzzle_velocity"] >= least
                                                                 else "does not reach either") + ")")
    stops = []
    for x, how in ((b, "as laid out"), (bv, "with its last striker length ported (the valve left open on the "
                                            "tank, as the gun model has it)"),
                   (bk, "ported with its sabot kept on the striker")):
        r, words = _worst(x)
        stops.append(f"{how}, {words if r > 1 else 'nothing of its own is broken'}")
    second = (f"The direct gun it would replace, (b), is {machine(b)}"
              + f": at the band's centre ({V:.4g} m/s, {air['launch_energy'] / 1e6:.4g} MJ) {gun}; "
              + "; ".join(stops) + ".")
    return first + ". " + second


def answer_box(m, abc: tuple, drives: list, band: dict, closed_spec: dict, stars: list = (),
               springs: dict | None = None, vented=None, guns: dict | None = None, kept=None) -> str:
    """The premise's answer, boxed, for the top of the report (``premise.answer``), from the arrangements'
    numbers (``stars``: the amplifier at its best chain, (a*), where designed; ``springs``: the chain with gas
    springs, ``gas_spring_chain``; ``vented``: (b) with its last striker length ported; ``kept``: that with its
    sabot kept on the striker; ``guns``: the guns at
    the band's centre, ``centre_table``): a two-sentence answer, each arrangement's verdict and what it
    breaks, its launch energy at the fixture's speed and at the band's centre, what every arrangement with the
    fixture breaks, and what would change it."""
    a, b, b0, c = abc
    bv, bk = vented or b, kept or vented or b
    fixture_ok = not a.fixture_problems

    def machine(x):
        return "FEASIBLE" if x.gun_feasible and x.feasible and fixture_ok else "NOT FEASIBLE"
    amplifiers = [a, *stars]
    rows = [(x, machine(x), P.limit_words(x)) for x in amplifiers] + [(b, machine(b), P.limit_words(b))]
    rows += [(x, machine(x), P.limit_words(x)) for x in (vented, kept) if x is not None]
    rows += [(b0, "a lower bound, not a machine" + (" (its gun within the limits)" if b0.gun_feasible else ""),
              P.limit_words(b0)), (c, machine(c), P.limit_words(c))]
    for x, d in drives:
        if d.moving is None:
            rows.append((x, "NOT FEASIBLE", [f"no design: {d.notes[0]}"]))
            continue
        why = P.limit_words(x)
        if d.band is not None and not d.in_band:
            why.insert(0, f"its pulse outside the band (worst excess {d.band.worst_excess:.3g} of the peak)")
        if d.recovery and not d.recovery["band"].passed:
            why.insert(0, f"its pulse outside the band at the face pressure's upper end (worst excess "
                          f"{d.recovery['band'].worst_excess:.3g} of the peak)")
        rows.append((x, "CANDIDATE" if d.feasible else "NOT FEASIBLE", why))
    f = m.fixture
    centre = band["rows"]["the band's centre"]
    centre_cells = _centre_cells(guns, (a, *stars), (b, bv, bk), b0, c, [x for x, _ in drives]) if guns else None
    least = band["rows"]["the band's least"]["striker_speed"]
    headline = (_headline(m, amplifiers, b, bv, bk, closed_spec, guns, machine, least) if guns else
                f"Velocity amplification does {'' if any(machine(x) == 'FEASIBLE' for x in amplifiers) else 'not '}"
                "make a compact non-pyrotechnic tester feasible.") + _nearest(rows, centre_cells, _gun_models(drives))
    common = [f"The rows' first energy is at the designed fixture's striker speed ({f.striker_speed:.4g} m/s"
              + ("" if f.band_passed else ", a pulse that fails the band")
              + f"), the second at the band's centre ({centre['striker_speed']:.4g} m/s, the speed the specification "
              "asks; section 8's band and centre tables). Every number here is this run's but the pads' measured "
              "restitutions quoted below (`scripts/pad-interface.py`'s runs, docs/machine.md's Pads)."]
    if b.gun_feasible or guns:
        laid = P.barrel_as_laid_out(m.spec, f, b)
        common.append(f"The spec's {m.spec.max_barrel_length / FT:.3g} ft is read as the gun's travel: (b)'s barrel "
                      f"as laid out holds the striker too, {laid['barrel'] / FT:.3g} ft; with the whole barrel within "
                      f"{m.spec.max_barrel_length / FT:.3g} ft (a {laid['travel_within'] / FT:.3g} ft travel) the "
                      f"infinitely chambered gun, the ideal upper bound, fires (b)'s {b.launched_mass:.4g} kg at "
                      f"{laid['chambered_speed_within']:.4g} m/s. (b)'s length leaves out its sabot's stop, which its "
                      "mass counts (not laid on the axis); with its sabot kept the striker's stop, longer, takes both.")
    if a.fixture_problems:
        common.append(f"(a) to (c) carry the same fixture, and it breaks its own limits: {'; '.join(a.fixture_problems)}.")
    return P.answer(rows, common, _changes(a, b, bv, bk, centre, closed_spec, springs, drives), headline,
                    centre_cells)


def _gun_models(drives: list) -> dict:
    """The gas drives' rows' gun model, by name, where it is not the lumped gun the other rows' guns are
    designed with: the infinitely chambered law, with the lumped gun's check of it."""
    return {x.name: "its drive by the infinitely chambered gun" + (
        f"; the lumped gun's check ends {abs(d.lumped['speed_error']):.2%} "
        f"{'slower' if d.lumped['speed_error'] < 0 else 'faster'}" if d.lumped else "") for x, d in drives}


def _nearest(rows: list, centre: dict | None, models: dict | None = None) -> str:
    """The lightest machine of the answer's ``rows`` whose gun reaches the band's centre (``centre``, where
    given; else the fixture's speed): what it weighs, its length, its launch energy and what keeps it from
    being a machine, in one sentence (empty where none reaches it); ``models``: a row's gun model, by name,
    where it is not the lumped gun (``_gun_models``)."""
    def reaches(x):
        energy, ok = (centre or {"cells": {}})["cells"].get(x.name, (math.nan, None))
        return x.gun_feasible if ok is None else ok
    machines = [r for r in rows if "lower bound" not in r[1] and math.isfinite(r[0].machine_mass) and reaches(r[0])]
    if not machines:
        return ""
    x, word, why = min(machines, key=lambda r: r[0].machine_mass)
    where = "the band's centre" if centre else "the fixture's speed"
    model = (models or {}).get(x.name)
    return (f" The lightest machine here whose gun reaches {where} is {x.name}"
            + (f" ({model})" if model else "") + f": {x.machine_mass / 1e3:.4g} t, "
            f"{x.machine_length:.3g} m long, {x.required_energy / 1e6:.4g} MJ of launch energy; "
            + ("FEASIBLE" if word == "FEASIBLE" else f"{word}: " + "; ".join(why)) + ".")


def _centre_cells(guns: dict, amplifiers: tuple, directs: tuple, b0, c, drives: list) -> dict:
    """Each row's launch energy at the band's centre and whether its gun reaches it, by name."""
    cells = {x.name: (guns["amplifiers"][x.name]["launch_energy"], guns["amplifiers"][x.name]["gun_reaches"])
             for x in amplifiers}
    air, bare = guns["direct"]["air"], guns["direct"]["bare"]
    cells.update({x.name: (air["launch_energy"], air["feasible"]) for x in directs})
    cells[b0.name] = (bare["launch_energy"], bare["feasible"])
    # the flying target's gun short at the fixture's (lower) speed is short at the centre's; the gas drives are
    # designed at the band's centre already
    cells[c.name] = (math.nan, c.gun_feasible if c.gun_feasible is False else None)
    cells.update({x.name: (x.required_energy, x.gun_feasible) for x in drives})
    return {"speed": guns["direct"]["speed"], "cells": cells}


def _changes(a, b, bv, bk, centre: dict, closed_spec: dict, springs: dict | None, drives: list) -> list[str]:
    """What would change the premise's answer, from the run's numbers."""
    change = []
    k = closed_spec
    face, w = k.get("interface") or {}, k["with_sabot"]
    if face:
        change.append(f"for (a), interfaces that return their energy at {face['closing_speed']:.0f} m/s (the best "
                      f"chain's fastest at the band's centre; the library's best solid does so only to "
                      f"{face['elastic_limit_speed']:.0f} m/s, a pad {face['pad_over_struck']:.3g} times its struck "
                      f"body) that keep a restitution above {w['break_even']['chambered']:.3f} (the chambered "
                      f"break-even against (b)): the chain's {k['restitution']:.3f} is its pads' estimate, and their "
                      f"runs at 99 m/s restitute {min(P.MEASURED_RESTITUTIONS.values()):.2f} to "
                      f"{max(P.MEASURED_RESTITUTIONS.values()):.2f}")
    best = (springs or {}).get("best_chain") or {}
    if best.get("feasible") and best.get("guns"):
        q_sw, q_ch = best["guns"]["simple_wave"]["Q"], best["guns"]["chambered"]["Q"]
        shares = [i["mass_share"] for i in best.get("interfaces", [])]
        change.append(f"for (a), gas springs at every interface: their best chain needs {q_sw:.3g} (simple-wave) "
                      f"and {q_ch:.3g} (chambered) of (b)'s gun"
                      + (f", with sleeves {min(shares):.3g} to {max(shares):.3g} times their struck bodies, which "
                         "the chain's masses leave out" if shares else "")
                      + (", and springs that break their limits (section 8's gas-spring table)"
                         if any(i["broken"] for i in best.get("interfaces", [])) else ""))
    change += _sabot_changes(b, bv, bk)
    variants = [("as laid out", b)] + ([("with its sabot kept", bk)] if bk is not b else [])
    pushed = [(how, lim) for how, x in variants for lim in broken(x.limits)
              if lim.component.startswith("launcher's gas on the striker")]
    if pushed:
        change.append("for (b), a fixture designed with the gas's push on the striker ("
                      + "; ".join(f"{how} it adds {lim.value:.3g} of the peak to the pulse's worst excess"
                                  for how, lim in pushed)
                      + f", past the fixture designer's {pushed[0][1].limit:.3g} margin), or the gas off the striker "
                      "before the pulse (the payload a striker length past the muzzle; the muzzle's jet on the "
                      "striker's base, which the model leaves out, would still push it there)")
    if not centre["air_fires_sabot"]:
        r = centre["remedies"]
        change.append(f"at the band's centre, a gun past the limits for (b): an air barrel of "
                      f"{r['air']['chambered_barrel'] / FT:.3g} ft (the ideal chambered gun; the lumped gun's in the "
                      f"centre table) or helium ({r['helium']['chambered_speed']:.4g} m/s at every limit, chambered)")
    if a.fixture_problems:
        change.append("and for (a) to (c) a fixture within its own limits")
    for x, d in drives:
        if d.moving is not None and not d.feasible:
            change.append(f"for (d) in {d.gas}, " + D._what_would_bring_it_in(d))
    return change


def _sabot_changes(b, bv, bk) -> list[str]:
    """For (b), the sabot's stop against the gas's push, as laid out and ported, and the sabot kept on the
    striker instead."""
    def stop(x):
        return ([lim for lim in broken(x.limits) if lim.component.startswith("stop of sabot")],
                next((lim for lim in x.limits if lim.component == "stop of sabot"), None))
    (shut, push), (open_, push_v) = stop(b), stop(bv)
    if not shut or push is None:
        return []
    words = (f"for (b), a sabot stop within its limits against the gas's {push.value / 1e6:.3g} MN push (the one "
             f"designed breaks {len(shut)}, the worst {shut[0].quantity}, {shut[0].ratio:.3g} times)")
    if bv is not b and push_v is not None:
        words += (f"; porting the barrel's last striker length cuts the push to {push_v.value / 1e6:.3g} MN (the "
                  "open valve keeps refilling the barrel from the tank)"
                  + (f", and its stop still breaks {len(open_)} (the worst {open_[0].quantity} "
                     f"{open_[0].ratio:.3g} times)" if open_ else ", and its stop holds"))
    impact = next((lim for lim in (open_ or shut) if lim.quantity == "impact pressure rho c v"), None)
    if impact is not None:
        v_max = impact.limit / (OIL["density"] * OIL_SOUND_SPEED)
        words += (f": the sabot's speed decides that, not the push (an oil buffer's impact pressure rho c v reaches "
                  f"its cylinder's {impact.limit / 1e6:.3g} MPa above {v_max:.0f} m/s, pushed or not), so the stop "
                  "needs an absorber that takes the muzzle's speed and whose static force exceeds the push (a "
                  "crushable with a push below its crush force: a valve that shuts after the shot, not modelled "
                  "here), or no sabot stop")
    if bk is not bv:
        own = [lim for lim in broken(bk.limits) if not lim.component.startswith("launcher's gas on the striker")]
        pulse = next(lim for lim in bk.limits if lim.component.startswith("launcher's gas on the striker"))
        words += ("; kept on the striker through the pulse and stopped with it by the striker's stop (the ported "
                  "gun), the sabot needs no stop of its own, "
                  + (f"the striker's stop breaks {len(own)} (the worst its {own[0].quantity} "
                     f"{own[0].ratio:.3g} times)" if own else "its stops hold their limits")
                  + f", and the push in the bore and the muzzle's jet on the kept sabot, its mass on the striker, add "
                  f"{pulse.value:.3g} of the peak to the band's worst excess, " + ("within" if pulse.holds else f"{pulse.ratio:.3g} times")
                  + f" the fixture designer's {pulse.limit:.3g} margin")
    return [words]


def gas_drive_table(rep: Report, drives: list):
    """(d)'s pulse and parts, gas by gas."""
    rows = []
    for x in drives:
        p, mv, lu = x.pulse, x.moving, x.lumped
        rows.append([x.gas, x.sound_speed, p.specific_force / G0 if p else float("nan"), p.peak / G0 if p else
                     float("nan"), x.band.worst_excess if x.band else float("nan"),
                     "yes" if x.in_band else "NO",
                     x.recovery["band"].worst_excess if x.recovery else float("nan"),
                     x.arrest.short if x.arrest else "-",
                     "no" if x.arrest and broken(x.arrest.limits) else ("yes" if x.arrest else "-"),
                     mv.material if mv else "none", mv.piston_mass if mv else
                     float("nan"), x.stop.kind if x.stop else "-", x.stop.stroke if x.stop else float("nan"),
                     f"{lu['speed_error']:+.2%}" if lu else "-", ("yes" if lu["band"].passed else "NO") if lu else "-",
                     "CANDIDATE (stated valve)" if x.feasible else "NOT FEASIBLE"])
    rep.table("gas_drive", ["gas", "c0 [m/s]", "k = p0 A / m [g]", "peak [g]", "band at the lower end: worst excess [of peak]",
                            "in the band at the lower end", "face's upper end: worst excess [of peak]", "piston's arrest",
                            "arrest within its limits", "piston", "piston [kg]", "catch", "catch stroke [m]",
                            "lumped gun: end speed error [-]", "lumped gun: in the band", "verdict"], rows,
              ["{}", "{:.0f}", "{:,.0f}", "{:,.0f}", "{:.3g}", "{}", "{:.3g}", "{}", "{}", "{}", "{:.3g}", "{}",
               "{:.3g}", "{}", "{}", "{}"])
    rep.text("(d)'s pulse and parts (`machine/gas_drive.py`): k = p0 A / m is the one specific force that gives the "
             "trapezoid's velocity change over its duration; the peak is where the valve's ramp ends (the chambered "
             "base pressure falls after it); the band is the fixture study's (`metrics.shapes`), checked at both "
             "ends of the face pressure's bracket after the ports open (the holes' discharge coefficient "
             f"{min(E.DISCHARGE_RANGE):g} to {max(E.DISCHARGE_RANGE):g}, the port gas keeping the column's speed or "
             "leaving radially: `machine.drive_end.bracket`); the piston's arrest takes the piston against the gas's "
             "push p0 A and holds it (`machine.stops`, a pushed body), a limit of the design; the piston the "
             "lightest of " + ", ".join(D.PISTON_MATERIALS) + " (a flat disc, Roark's simply supported plate under "
             f"the carriage's central load); the catch at the spec's catch deceleration; the lumped gun "
             "(`launcher.gun.fire`: the finite tank, the valve's flow, Lagrange gas, the air ahead) fires the same "
             "cylinder and tank, a check of the chambered law's tank fall and gas inertia only (it shares the "
             "valve's opening and the ported fall). `shockfem verify gas_drive` checks the drive against the "
             "chambered closed form and the constant-force limit, and the ported end against its closed forms.")


def boundary_table(rep: Report, k: dict):
    """The closed form's break-even restitutions at the design's striker speed, beside the restitutions the
    chain has."""
    be, spec = k["break_even"], k["break_even_spec"]
    best = k["best"] or {}
    rows = [["the best launch speed and mass count (2 to 10), both guns in air", be["air"]],
            ["the best launch speed and mass count, both guns in helium", be["helium"]],
            ["the best launch speed and mass count, an air amplifier against a helium direct gun",
             k["break_even_air_against_helium"]],
            [f"the spec's {k['launch_speed']:.4g} m/s and {k['masses']} masses, air", spec["air"]],
            [f"the spec's {k['launch_speed']:.4g} m/s and {k['masses']} masses, helium", spec["helium"]],
            [f"the best launch speed and mass count, air, against the direct gun firing the striker in its "
             f"{k['with_sabot']['sabot']:.4g} kg sabot", k["with_sabot"]["break_even"]["air"]],
            ["the same, both guns the infinitely chambered gun", k["with_sabot"]["break_even"]["chambered"]],
            [f"the best pad material of the library ({k['best_pad']}, sized at its rebound's sqrt(R))",
             k["best_pad_restitution"]],
            ["the design's chain (its effective e)", k["restitution"]]]
    rep.table("premise_boundary", ["restitution", "e [-] (nan: never, not even at e = 1)"], rows, ["{}", "{:.4f}"])
    rep.text(f"The premise's boundary in closed form (`machine/boundary.py`, `shockfem verify premise_boundary` "
             "checks both of its closed forms against the event-driven rigid chain and the lumped simple-wave gun): "
             "a launched chain of n geometric masses that gains G at restitution e keeps G^2 m_n / m_1 = "
             "[g (1 + e - g)]^(n-1) of its launch energy, g = G^(1/(n-1)); the simple-wave gun turns "
             "u^2 / (2 I(u)) of p0 A L into kinetic energy at its muzzle speed u (Seigel 1965), whatever the mass, "
             "bore and pressure. So the amplifier's gun (p0 A L, the barrel's steel and the gas it draws) over the "
             f"direct gun's is Q = eta(V_s) / (chi eta(V_s / G)). At the design's striker speed "
             f"{k['striker_speed']:.4g} m/s and its e {k['restitution']:.4f}, the best chain ({best.get('masses')} "
             f"masses launched at {best.get('launch_speed', float('nan')):.4g} m/s) has Q = "
             f"{best.get('gun_ratio', float('nan')):.3g}; the design's {k['masses']} masses at "
             f"{k['launch_speed']:.4g} m/s keep {k['chain_efficiency']:.3g} of the launch energy "
             f"({k['chain_efficiency_elastic']:.3g} at e = 1).")


def _chain_row(label: str, c: dict) -> list:
    if not c.get("feasible", True) or c.get("guns") is None:
        return [label, c.get("restitution"), None, None, None, None, None, None, None, None, None, None,
                c.get("reason", "")]
    sw, ch = c["guns"]["simple_wave"], c["guns"]["chambered"]
    sleeves = sum(i["sleeve_mass"] for i in c.get("interfaces", []))
    return [label, c["restitution"], c.get("masses"), c.get("launch_speed"), c["first_mass"], sleeves,
            0.5 * c["first_mass"] * c.get("launch_speed", 0.0) ** 2 / 1e6, sw["amplifier"] / 1e6, sw["Q"],
            sw["Q_bare"], ch["amplifier"] / 1e6, ch["Q"], ch["Q_bare"]]


def gas_spring_section(rep: Report, m, sabot: float):
    """What the design's chain gains with a gas spring at every interface (``machine.gas_spring_chain``), Q
    against the direct gun firing the striker in its ``sabot`` [kg] and bare."""
    k = gas_spring_chain(m, CLAIM["e"], sabot)
    sc, best, wp = k["spec_chain"], k.get("best_chain", {}), k["at_white_paper_e"]
    wp_row = {**wp, "masses": m.spec.masses, "launch_speed": m.spec.launch_speed, "feasible": True}
    rows = [_chain_row("the design's masses and launch speed, a gas spring at every interface", sc),
            _chain_row("the best chain (its launch speed and masses at the settled e), gas springs", best),
            _chain_row("the chambered gun's best chain at the settled e, settled again, gas springs",
                       k.get("best_chain_chambered", {})),
            _chain_row(f"the design's masses and launch speed at the white paper's e {CLAIM['e']:g}", wp_row)]
    rep.table("gas_spring_chain", ["chain", "e [-]", "masses", "launch [m/s]", "first mass [kg]",
                                   "gas springs' sleeves [kg]", "launch energy [MJ]", "gun p0 A L, simple-wave [MJ]",
                                   "Q simple-wave, against (b) [-]", "Q simple-wave, the bare striker [-]",
                                   "gun p0 A L, chambered [MJ]", "Q chambered, against (b) [-]",
                                   "Q chambered, the bare striker [-]"], rows,
              ["{}", "{:.4f}", "{}", "{:.4g}", "{:,.0f}", "{:,.0f}", "{:.4g}", "{:.4g}", "{:.3g}", "{:.3g}", "{:.4g}",
               "{:.3g}", "{:.3g}"])
    direct = (sc.get("guns") or wp["guns"])
    iface = [[i["name"], i["closing_speed"], i["restitution"], i["closed_form_restitution"], i["bore"] * 1e3,
              i["column"], i["peak_pressure"] / 1e6, i["run_peak_pressure"] / 1e6, i["sleeve_mass"], i["mass_share"],
              "; ".join(i["broken"]) or "all hold"] for i in sc.get("interfaces", [])]
    rep.table("gas_spring_interfaces", ["interface", "closing [m/s]", "e, its gas column's run [-]",
                                        "e, closed form (an upper bound) [-]", "bore [mm]", "gas column [m]",
                                        "sleeve's design pressure [MPa]", "peak in the run [MPa]", "sleeve [kg]",
                                        "sleeve over struck body [-]", "broken limits"],
              iface, ["{}", "{:.4g}", "{:.4f}", "{:.4f}", "{:.0f}", "{:.3g}", "{:.3g}", "{:.3g}", "{:,.0f}", "{:.3g}",
                      "{}"])
    rep.value("gas_spring_chain", k)
    rep.text(_gas_spring_words(k, direct, rows))
    return k


def _gas_spring_words(k: dict, direct: dict, rows: list) -> str:
    sc = k["spec_chain"]
    shares = [i["mass_share"] for i in sc.get("interfaces", [])]
    held = all(not i["broken"] for i in sc.get("interfaces", []))
    words = (f"A gas spring (`machine/gas_spring.py`: nitrogen, its peak temperature 50 K below the seal oil's "
             f"auto-ignition, its restitution from its gas column's run, the shocks and their reverberations "
             f"resolved, with the heat and seal friction) "
             f"is the one interface not bound by a solid's v*. The direct gun fires the striker's "
             f"{k['striker_energy'] / 1e6:.4g} MJ in its {k['sabot']:.4g} kg sabot ((b), the direct machine the "
             f"premise admits: its gun {k['direct_load']:.4g} times the bare striker's, as the closed form's) from "
             f"p0 A L = {direct['simple_wave']['direct'] / 1e6:.4g} MJ (simple-wave) or "
             f"{direct['chambered']['direct'] / 1e6:.4g} MJ (chambered); the bare striker from "
             f"{direct['simple_wave']['direct_bare'] / 1e6:.4g} and {direct['chambered']['direct_bare'] / 1e6:.4g} MJ. "
             "Each Q below is against (b), the bare striker's beside it (the table).")
    if sc["feasible"]:
        words += (f" With gas springs the design's chain settles at e {sc['restitution']:.4f}, its first mass "
                  f"{sc['first_mass']:,.0f} kg launching {rows[0][6]:.4g} MJ from a gun of {rows[0][7]:.4g} MJ "
                  f"(Q {rows[0][8]:.3g}) or {rows[0][10]:.4g} MJ chambered (Q {rows[0][11]:.3g}); its sleeves weigh "
                  f"{min(shares):.3g} to {max(shares):.3g} times their struck bodies, and its springs "
                  + ("hold every limit." if held else "do not hold their limits (the table above)."))
    best = k.get("best_chain") or {}
    if best.get("feasible"):
        words += (f" The best chain at that e, settled again with its own springs, is {best['masses']} masses launched "
                  f"at {best['launch_speed']:.4g} m/s at e {best['restitution']:.4f}: its first mass "
                  f"{best['first_mass']:,.0f} kg launches {rows[1][6]:.4g} MJ from a gun of {rows[1][7]:.4g} MJ "
                  f"(Q {rows[1][8]:.3g}) or {rows[1][10]:.4g} MJ chambered (Q {rows[1][11]:.3g}), with "
                  f"{rows[1][5]:,.0f} kg of sleeves the chain's masses leave out.")
    ch = k.get("best_chain_chambered") or {}
    if ch.get("feasible"):
        words += (f" The chambered gun's own best chain, settled: {ch['masses']} masses launched at "
                  f"{ch['launch_speed']:.4g} m/s at e {ch['restitution']:.4f}, {rows[2][10]:.4g} MJ of chambered gun "
                  f"(Q {rows[2][11]:.3g}).")
    wp = k["at_white_paper_e"]
    if wp["guns"]:
        words += (f" At the white paper's e {wp['restitution']:g} the design's chain launches {rows[3][6]:.4g} MJ "
                  f"(its first mass {wp['first_mass']:,.0f} kg) from a gun of {rows[3][7]:.4g} MJ against the direct "
                  f"gun's {direct['simple_wave']['direct'] / 1e6:.4g} MJ (simple-wave; Q {rows[3][8]:.3g}).")
    return words


def _map_rows(points) -> list:
    rows = []
    for p in points:
        c, ch = p.chain, p.chain_chambered
        rows.append([p.article / LB, p.duration * 1e3, p.peak / G0, p.velocity_change, p.striker_ratio,
                     p.striker_speed, c["masses"], c["launch_speed"], c["gun_ratio"], ch["gun_ratio"],
                     "yes" if p.eligible else "no", p.amplifier["launch_energy"] / 1e6, p.amplifier["machine_mass"],
                     p.bare["launch_energy"] / 1e6, p.bare["machine_mass"], p.direct["launch_energy"] / 1e6,
                     p.direct["machine_mass"], p.direct["sabot"], "yes" if p.direct["feasible"] else "NO", p.direct_load, p.gun_ratio_sabot, p.interface.get("closing_speed", float("nan")),
                     p.interface.get("pad_over_struck", float("nan")),
                     p.flying["barrel"] / FT, p.flying["machine_mass"], p.winner, p.note or p.amplifier["note"]])
    return rows


MAP_HEADER = ["payload [lb]", "duration [ms]", "peak [g]", "velocity change [m/s]", "striker over payload [-]",
              "striker speed [m/s]", "best chain: masses", "best chain: launch [m/s]",
              "Q simple-wave, the bare striker [-]", "Q chambered, the bare striker [-]", "amplifier designed", "(a) launch [MJ]", "(a) gun and masses [kg]", "(b0) launch [MJ]",
              "(b0) gun and striker [kg]", "(b) launch [MJ]", "(b) gun, sabot and striker [kg]", "(b) its sabot [kg]",
              "(b) within the limits", "direct load (M + sabot) / M [-]",
              "Q against (b), the lower law's [-]", "best chain's fastest interface [m/s]",
              "pad that held it over struck body [-]", "(c) barrel [ft]", "(c) gun and target [kg]",
              "lightest", "note"]
MAP_FORMATS = ["{:.0f}", "{:.2g}", "{:,.0f}", "{:.0f}", "{:.3g}", "{:.0f}", "{}", "{:.0f}", "{:.3g}", "{:.3g}", "{}",
               "{:.3g}", "{:,.0f}", "{:.3g}", "{:,.0f}", "{:.3g}", "{:,.0f}", "{:,.0f}", "{}", "{:.4g}", "{:.3g}", "{:.0f}",
               "{:.3g}", "{:.3g}",
               "{:,.0f}", "{}", "{}"]


def _map_lines(points, e: float, gas: str, at) -> dict:
    """The closed form's boundary lines: the velocity change above which Q < 1, by each gun law."""
    _, e_pad = P.best_pad_restitution()
    lines = {}
    for label, x in ((f"Q = 1, bare striker, at the design's e {e:.3f}", e),
                     (f"at the best pad's e {e_pad:.3f}", e_pad), ("at the white paper's e 0.9", CLAIM["e"]),
                     ("at e = 1", 1.0)):
        lines[label + ", simple-wave"] = P.boundary_velocity_change(points, x, gas, at=at)
        lines[label + ", chambered"] = P.boundary_velocity_change(points, x, gas, chambered=True, at=at)
    return lines


def premise_map(rep: Report, m, target, cfg, out_dir: str, echo):
    """Where each arrangement wins over durations, peaks and payloads (the striker scaled to each point), and
    the counts again at the designed striker ratio at every point (the verdict's sensitivity to that law)."""
    rep.heading("9. Where each arrangement wins")
    grid = cfg["map"]
    echo(f"  the map: {len(grid['durations']) * len(grid['peaks']) * len(grid['payloads'])} points")
    e = m.amplifier.restitution
    axes = ([d * 1e-3 for d in grid["durations"]], [p * G0 for p in grid["peaks"]], [w * LB for w in grid["payloads"]])
    # the points' guns are designed independently: the default sizes share them among the machine's cores
    workers = cfg.get("map_workers", 1)
    points = P.premise_map(m.spec, m.fixture, e, target, *axes, echo=echo, workers=workers)
    rep.table("map", MAP_HEADER, _map_rows(points), MAP_FORMATS)
    at = min(points, key=lambda p: abs(p.article - m.spec.article_mass) + abs(p.duration - m.spec.pulse.duration)
             * 1e3 + abs(p.peak - m.spec.pulse.peak) / G0 * 1e-3)
    lines = _map_lines(points, e, m.spec.gas, at)
    P.map_figure(points, rep.path("premise_map.png"), lines)
    rep.figure("premise_map.png", "Where each arrangement gives the lightest feasible machine (gun and moving "
               "masses), each point's velocity change and Q against the direct gun in its sabot (simple-wave / "
               "chambered guns); the lines: the velocity change above which the best chain needs less gun than the "
               "direct gun firing the bare striker (the sabot's load changes from point to point), at four "
               "restitutions by each gun law, at the striker speed per velocity change of the point nearest the "
               "design's")
    bd = P.boundary(points)
    bd["lines"] = lines
    bd["pads_hold_below"] = P.pads_hold_below(m.spec, e)
    echo("  the map again at the designed striker ratio at every point")
    fixed = P.boundary(P.premise_map(m.spec, m.fixture, e, target, *axes, fixed_ratio=True, workers=workers))
    bd["fixed_ratio"] = fixed
    if cfg.get("band_ends", True):
        echo("  the map again at the two ends of the band's range of velocity change")
        ends = {k: P.premise_map(m.spec, m.fixture, e, target, *axes, band_end=k, workers=workers) for k in (-1, 1)}
        bd["band_ends"] = _band_end_flips(rep, points, ends)
    rep.value("map_boundary", bd)
    extra = [["the amplifier designed (the lower Q against (b) < 1)", "eligible"],
             ["Q < 1 with simple-wave guns", "eligible_simple_wave"], ["Q < 1 with chambered guns", "eligible_chambered"],
             ["Q < 1 against the bare striker's gun (b0), the lower law's", "eligible_bare"],
             ["the amplifier designed, its pads past the closed form's bound", "pads_fail"],
             ["direct wins with nothing to amplify (no chain needs less gun)", "direct_wins_nothing_to_amplify"]]
    rows = ([[k, v, fixed["counts"][k]] for k, v in bd["counts"].items()] + [[w, bd[k], fixed[k]] for w, k in extra]
            + [[f"{name} within the limits", bd["within"][k], fixed["within"][k]] for k, name in
               (("amplifier", "the amplifier"), ("direct", "the direct gun, the striker in its sabot (b)"),
                ("bare", "the direct gun's lower bound (b0, a massless sabot)"), ("flying", "the flying target"))]
            + [["all", bd["points"], fixed["points"]]])
    rep.table("map_counts", ["outcome", "points (the striker scaled to each point)",
                             f"points (the designed ratio, {m.fixture.striker_ratio:.3g}, at every point)"], rows,
              ["{}", "{}", "{}"])
    rep.text(_map_reading(bd, e))
    rep.text(_map_models(m, e, target, bd))
    _restitution_effect(rep, m, target)
    return points


def _band_end_flips(rep: Report, points, ends: dict) -> dict:
    """The map's points whose lightest feasible machine differs between the band's two ends of velocity change
    (``premise_map``'s ``band_end``), tabled with the centre's."""
    lo, hi = ends[-1], ends[1]
    rows = [[p.article / LB, p.duration * 1e3, p.peak / G0, a.velocity_change, a.winner, p.velocity_change, p.winner,
             b.velocity_change, b.winner] for p, a, b in zip(points, lo, hi) if a.winner != b.winner]
    counts = {k: P.boundary(v)["counts"] for k, v in (("least", lo), ("largest", hi))}
    if rows:
        rep.table("map_band_ends", ["payload [lb]", "duration [ms]", "peak [g]", "the band's least dv [m/s]",
                                    "lightest there", "its centre [m/s]", "lightest there", "its largest [m/s]",
                                    "lightest there"], rows,
                  ["{:.0f}", "{:.2g}", "{:,.0f}", "{:.0f}", "{}", "{:.0f}", "{}", "{:.0f}", "{}"])
    rep.text(f"The map at the two ends of the band's range of velocity change (each point's dv its centre's less "
             f"and plus the band's tolerance, {lo[0].velocity_change / points[0].velocity_change:.2f} and "
             f"{hi[0].velocity_change / points[0].velocity_change:.2f} times it): {len(rows)} of the {len(points)} points change their lightest feasible machine between the "
             "two ends" + (" (the table)" if rows else "") + "; the counts at the least: "
             + ", ".join(f"{k} {v}" for k, v in counts["least"].items()) + "; at the largest: "
             + ", ".join(f"{k} {v}" for k, v in counts["largest"].items()) + ".")
    return {"flips": len(rows), "counts": counts}


def _map_models(m, e: float, target, bd: dict) -> str:
    lo, hi = bd["striker_ratios"]
    return ("The map's models (closed forms and lumped models per point, no finite elements): the striker is the "
            f"designed one ({m.fixture.striker_ratio:.3g} times the payload) scaled to each point as its housing's mass "
            "scales (`premise.StrikerLaw`: the bore squared times its depth, the column with the relative stroke; at "
            f"least the spec's {m.spec.striker_ratio:g} times the payload), {lo:.3g} to {hi:.3g} times the payload on "
            f"this map, at the fixture's measured restitution ({max(m.fixture.restitution, 0.0):.3f}) by the rigid "
            f"collision law; the amplifier is the launched chain at one restitution for every point, the design's "
            f"effective e ({e:.4f}: the rigid chain at its pads' restitutions "
            + ", ".join(f"{x:.3f}" for x in m.amplifier.restitutions) + f", {_pads_source(m)}), its launch speed and "
            "mass count (2 to 10) at each point those that need the least gun (`boundary.best_chain`, closed form) by "
            "the simple-wave gun and by the infinitely chambered gun (the bound on any gun), the lower Q kept, its "
            "masses by the closed form, its gun by the lightest-launcher design (one start), designed only where "
            "that Q against the direct gun in its sabot is below 1: elsewhere no chain needs less gun, and the "
            "direct gun, where it is feasible and the lightest, wins the point (its note says 'nothing to amplify'); "
            "where designed it is feasible only if its fastest interface's pad of the library's best solid weighs "
            f"at most {P.PAD_MASS_SHARE:g} of the struck body (`premise.pads_hold`, the pads' first check). The "
            "figure gives both Qs against that gun and both laws' lines against the bare striker's. The direct gun fires the "
            "striker in its sabot at the bare striker's gun's bore (or the striker's diameter, where wider; one "
            "start, one bore where the premise's (b) scans its bore, so its sabot may be heavier than the scan's, "
            "which favours the amplifier's Q); the bare striker's gun (b0, the lower bound) is beside it. The map leaves the models' "
            "checked range everywhere but the design's point: the dashpot is designed and its validity checked only "
            "there (the striker's law carries its wall ratio, floor and column over stroke), the amplifier's pads "
            "are not sized or run at the other points (their restitution is carried over; only the closed form's "
            "bound above), its stresses and stops are not checked, nor the gun's gas on the "
            "striker and its sabot after the muzzle (section 8); the flying target is the "
            "fixture designer's target scaled by the same law, its dashpot not designed at the map's points"
            + ("" if hasattr(target, "striker_mass") else " (at the design's point the designer finds none for it: "
               "its oil outweighs it; the oil's mass over the payload grows with the stroke, so at shorter, lower "
               "pulses one may exist)") + ". A point where no arrangement reaches the speed within the limits is "
            "'none'.")


def _pads_source(m) -> str:
    """Where the chain's restitutions come from: its pads' finite-element runs, or, for an interface whose
    pad was not run (the pads' first check, the run budget, the 'estimate' resolution), its material's
    estimate sqrt(R)."""
    ran = sum(st.measured for st in m.amplifier.stages)
    if not ran:
        return "each its material's estimate sqrt(R): no pad was run"
    rest = len(m.amplifier.stages) - ran
    return (f"from their '{m.spec.pad_resolution}' runs at the design's point"
            + (f", {rest} of them at their material's estimate sqrt(R)" if rest else ""))


def _restitution_effect(rep: Report, m, target):
    """The design's point of the map at the design's measured effective e and at the white paper's assumed
    e: what the measured pads do to the amplifier's side of the premise."""
    s, f = m.spec, m.fixture
    rows = []
    strikers = P.striker_laws(s, f, target)
    for label, e in ((f"the design's effective e ({_pads_source(m)})", m.amplifier.restitution),
                     ("the white paper's assumed e", CLAIM["e"])):
        p = P.map_point(s, s.pulse.duration, s.pulse.peak, s.article_mass, strikers, max(f.restitution, 0.0), e,
                        f.housing_outer_radius / f.bore_radius)
        rows.append([label, e, p.note or p.amplifier["note"], p.amplifier["launch_energy"] / 1e6, p.amplifier["machine_mass"],
                     "yes" if p.amplifier["feasible"] else "NO", p.direct["machine_mass"], p.winner])
    lb = round(s.article_mass / LB)
    rep.table("map_restitution", ["amplifier's e", "e [-]", "(a)", "(a) launch [MJ]", "(a) gun and masses [kg]",
                                  "(a) gun within limits", "(b) gun, sabot and striker [kg]", "lightest"], rows,
              ["{}", "{:.4f}", "{}", "{:.4g}", "{:,.0f}", "{}", "{:,.0f}", "{}"])
    rep.value("map_restitution", [{"e": r[1], "launch_energy": r[3] * 1e6, "machine_mass": r[4], "winner": r[7]}
                                  for r in rows])
    def amp(r):
        """The amplifier's gun and masses at a row, or why it has none."""
        if math.isfinite(r[4]):
            return f"{r[4]:,.0f} kg of gun and masses ({r[3]:.4g} MJ launched)"
        return f"no design ({r[2]})"
    rep.text(f"The {lb} lb point of the map at the design's effective e ({rows[0][1]:.4f}, {_pads_source(m)}) "
             f"and at the white paper's e = {CLAIM['e']:g}: the amplifier has {amp(rows[0])} at the design's e, and "
             f"{amp(rows[1])} at e = {CLAIM['e']:g}; the lightest arrangement there is "
             f"'{rows[0][7]}' at the design's e and '{rows[1][7]}' at e = {CLAIM['e']:g}.")


def _map_reading(bd: dict, e: float) -> str:
    n, f = bd["counts"], bd["fixed_ratio"]
    sw, ch = next(iter(bd["lines"].values())), list(bd["lines"].values())[1]

    def where(x):
        return f"above {x:.0f} m/s of velocity change" if x == x else "nowhere below the gas's escape speed"
    w = bd["within"]
    return (f"Of the {bd['points']} points the amplifier at e {e:.3f} needs less gun than the direct one in its sabot, "
            f"and so was designed, at {bd['eligible']} ({bd['eligible_simple_wave']} by the simple-wave gun, "
            f"{bd['eligible_chambered']} by the chambered gun; against the bare striker's gun, the lower bound, at "
            f"{bd['eligible_bare']}; the closed form against the bare striker near the design's point: {where(sw)} "
            f"simple-wave, {where(ch)} chambered), and at {bd['pads_fail']} of those its fastest interface asks a pad past the closed form's "
            f"bound. The lightest feasible machine: the amplifier at {n['amplifier']}, the direct gun (the striker in "
            f"its sabot, within the limits at {w['direct']}; its bare lower bound at {w['bare']}) at {n['direct']} "
            f"({bd['direct_wins_nothing_to_amplify']} of them where no chain needs less gun, so nothing to "
            f"amplify), the flying target at {n['flying target']}, and at {n['none']} no arrangement is "
            f"feasible within the limits. With the library's solids the pads' bound holds only for a striker below "
            f"{bd['pads_hold_below']:.0f} m/s ((1 + e) v* sqrt({P.PAD_MASS_SHARE:g}), whatever the chain: "
            f"`premise.pads_hold_below`), while the map's chains need less gun than the direct one only from "
            f"{bd['smallest_dv_eligible']:.0f} m/s of velocity change up: no point of any map of these pads can have a feasible amplifier, so that count is the "
            f"closed form's, as section 8's scale-free argument is, not the grid's. The direct gun is checked on "
            f"its gun alone at the map's points (its sabot's stop, the gas's push on its striker and its stops are "
            f"not, which at the spec's point break limits: section 8), so its wins are where its gun reaches the "
            f"speed, an upper bound on where a direct machine is feasible. At the designed striker ratio at every point instead: the amplifier at "
            f"{f['counts']['amplifier']}, the direct gun at {f['counts']['direct']}, the flying target at "
            f"{f['counts']['flying target']}, none at {f['counts']['none']} (the amplifier designed at "
            f"{f['eligible']}).")


def white_paper(rep: Report, m):
    """Section 1.2's sizing claims, task 4's gun, Eq. 2 and the 90 ft gun beside the design."""
    rep.heading("10. The white paper side by side")
    rows = claims(m)
    rep.table("white_paper", ["claim", "the white paper", "its assumptions, our models", "the design's striker at e = 0.9",
                              "the design", "note"],
              [[r["claim"], r["white_paper"], r["wp_assumptions"], r["design_at_0.9"], r["design"], r["note"]]
               for r in rows], ["{}", "{:.4g}", "{:.4g}", "{:.4g}", "{:.4g}", "{}"])
    mid, added, gun, wave, bound, target = (rows[0], rows[2], rows[6], rows[7], rows[8], rows[-1])
    own = next((r for r in rows if r["claim"].startswith("barrel the white paper's 12 in gun")), None)
    over = [CLAIM["target_gun"] / target[k] for k in ("wp_assumptions", "simple_wave", "chambered")]
    rep.text(f"At its own assumptions (the 12 lb article the last mass, e = 0.9) the white paper's amplifier holds: "
             f"{mid['wp_assumptions'] / LB:,.0f} lb of intermediate masses against its 800 lb; but that figure leaves "
             f"out its own first mass: the masses it adds to the article weigh {added['wp_assumptions'] / LB:,.0f} lb. "
             f"Its 12 in x 6 ft gun at 2000 psi fires that {rows[3]['wp_assumptions']:.0f} kg first mass at "
             f"{gun['wp_assumptions']:.1f} m/s with the 20 ft^3 tank and 8 in valve this project assumes (the white "
             f"paper gives neither), and at {bound['wp_assumptions']:.1f} m/s at most without any tank (the "
             f"constant-pressure bound; the simple-wave gun {wave['wp_assumptions']:.1f} m/s): short of the "
             f"{325 * FT:.1f} m/s it needs, whatever the tank. The design is not that machine: its last mass is the "
             f"striker that carries the dashpot ({m.fixture.striker_mass:.3g} kg), so its intermediate masses are "
             f"{mid['design'] / LB:,.0f} lb ({mid['design'] / mid['white_paper']:.3g} times the claim), and the white "
             f"paper's gun fires the design's first mass at {gun['design']:.3g} m/s. Its 90 ft gun for a 30 lb "
             f"target at 1600 ft/s: the lumped gun needs {target['wp_assumptions'] / FT:.3g} ft, the simple-wave gun "
             f"{target['simple_wave'] / FT:.3g} ft, the infinitely chambered gun {target['chambered'] / FT:.3g} ft "
             f"(the constant-pressure bound {target['constant_pressure'] / FT:.3g} ft), so the white paper overstates "
             f"the flying target's gun {min(over):.2g}-{max(over):.2g} times, which cuts against its own premise"
             + (f"; and it understates its amplifier's: its 6 ft barrel would need {own['simple_wave'] / FT:.3g} ft "
                f"(simple-wave), {own['chambered'] / FT:.3g} ft (chambered) or {own['constant_pressure'] / FT:.3g} "
                "ft (constant pressure) for its own first mass, so by the chambered gun its amplifier needs the "
                + ("longer" if own["chambered"] > target["chambered"] else "shorter") + " barrel of the two"
                if own else "") + ".")
