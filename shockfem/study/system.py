"""The system study (the white paper's task 5): ``shockfem study system``.

Sections of ``report.md``:

1. What the system model does and the choices it starts from.
2. The machine for each payload (10, 50 and 100 lb, and the fixture study's 12 lb) under the identical
   pulse: every component, its loads against its allowables, the STEP assembly and the drawing.
3. Scalability: what changes with the payload (the exponents of each parameter), which limits bind, and
   for a payload no machine of the starting architecture meets, the architectures tried (more masses,
   faster launches) and what each needs.
4. The coupled check: the 12 lb machine end to end at the fidelity that answers it: the gun fires the
   first mass into the padded chain in one 1D run (``amplifier.chain`` with its ``[launcher]``), and the
   striker, at the speed that run gives it, meets the payload in the fixture's axisymmetric
   finite-element run (elastic-plastic article, the oil as the cavity's lumped liquid); the article's
   pulse against the specification and against the system model.  Sequential coupling is exact here
   because the striker has left the chain before it meets the payload (checked: no chain mass catches it
   while the pulse lasts).

5. Every joule of a shot (``machine.energy``), for every payload; the stops as absorbers.
6. The verdicts, each on its machine's limits.
7. The chain's effective restitution with no, stiffness-proportional and band structural damping.
8. The premise: the amplifier against one gun firing the striker directly and the white paper's flying
   target, for the same pulse through the same fixture (``machine.premise``).
9. Where each wins over pulse durations, peaks and payloads: the map.
10. The white paper's sizing claims beside the design (``machine.white_paper``).

Sizes: ``smoke`` (tests: the 10 lb machine only, its coupled check on a coarse mesh, two alternative
architectures, the fixtures' searches at 40 runs instead of 120), ``default``.
"""
from __future__ import annotations

import dataclasses
import math
import os
import time

from ..amplifier.chain import run_chain_scene
from ..machine.amplifier import chain_scene
from ..machine.design import design_machine, models
from ..machine.fixture import DESIGN_EVALUATIONS
from ..machine.launcher import SIZING
from ..machine.layout import ROLLING_CARRIAGE_SPEED
from ..machine.output import write_machine
from ..machine.spec import MachineSpec, read_spec
from ..output.figures import pyplot
from ..units import FT, G0, IN, LB, PSI
from .cases import run_case
from .fixture.common import band_of
from .fixture.dashpot import dashpot_scene
from .fixture.runs import fe_pulse
from .report import Report
from . import system_premise as sections

SIZES = {
    "smoke": {"payloads": (10,), "coupled": 10, "h_article": 0.006, "h_pad": 0.03, "alternatives": ((6, 325),),
              "starts": 1, "sabot_bores": 3, "fixture_evaluations": 40,
              "map": {"durations": (0.2, 5.0), "peaks": (2000, 20000), "payloads": (10,)}},
    "default": {"payloads": (10, 12, 50, 100), "coupled": 12, "h_article": 0.003, "h_pad": 0.012,
                "alternatives": ((6, 325), (7, 325), (5, 450), (6, 450), (7, 450), (7, 600)), "starts": 3,
                "fixture_evaluations": DESIGN_EVALUATIONS,
                "sabot_bores": 5, "map_workers": 2,
                "map": {"durations": (0.2, 1.0, 5.0), "peaks": (2000, 10000, 20000), "payloads": (10, 30, 100)}},
}
# the machines' end: the fixture's record (the pulse and the band's window after it) in the coupled run
END_MARGIN = 1.3


def run_study(size: str = "default", out_dir: str = "results/system", echo=print,
              pad_resolution: str | None = None) -> str:
    """The study at ``size``; ``pad_resolution`` (``pads.RESOLUTIONS``) the pads' runs' meshes (default the
    spec's), "estimate" for none (the tests' quickest study: ``tests/sim/test_pad_runs.py`` runs the pads)."""
    t0 = time.perf_counter()
    cfg = SIZES[size]
    rep = Report(out_dir, "System integration and scalability study (white paper task 5)")
    base = read_spec({"article": "12 lb"})
    if pad_resolution:
        base = dataclasses.replace(base, pad_resolution=pad_resolution)
    rep.text(f"`shockfem study system --size {size}`" + (f" with the pads at '{pad_resolution}'" if pad_resolution
                                                          else "") + "; every number below was computed by this run. The system "
             "model is `shockfem design-machine` (`docs/machine.md`): each payload's machine is in "
             "`<N>lb/` (machine.json, machine.md, machine.step, drawing.svg/pdf/png).")
    echo("1/8 the system model and its choices")
    choices(rep, base)
    echo("2/8 the machines for each payload")
    machines = by_payload(rep, base, cfg, out_dir, echo)
    echo("3/8 scalability")
    scalability(rep, machines, cfg, out_dir, echo)
    echo("4/8 the coupled check, end to end")
    m = machines[cfg["coupled"]]
    coupled(rep, m, cfg, out_dir, echo)
    echo("5/8 the energy of a shot, the verdicts")
    sections.energy(rep, machines, cfg["coupled"])
    sections.limits(rep, machines)
    echo("6/8 the chain against the damping model")
    sections.damping(rep, m, out_dir)
    echo("7/8 the premise: the amplifier, a direct striker, a flying target, and the map")
    *_, target = sections.premise(rep, m, cfg, echo)
    sections.premise_map(rep, m, target, cfg, out_dir, echo)
    echo("8/8 the white paper side by side")
    sections.white_paper(rep, m)
    return rep.finish(t0, echo)


def choices(rep: Report, s: MachineSpec):
    rep.heading("1. The system model and its choices")
    rep.text(f"Every machine is designed for the identical pulse: a {s.pulse.shape} of {s.pulse.peak / G0:,.0f} g "
             f"for {s.pulse.duration * 1e3:g} ms (the fixture study's reading of the specification: the only "
             "shape that gives the white paper's 1650 ft/s of velocity change, `docs/fixture.md` section 1). "
             f"Choices: a {s.architecture} of {s.masses} masses launched at {s.launch_speed / FT:.0f} ft/s, "
             f"{s.material} ({s.safety_factor:g} on yield for every allowable), the striker at least "
             f"{s.striker_ratio:g} times the payload, the dashpot designed on its liquid column (its bore a design "
             "variable), "
             f"the launcher within {s.max_barrel_length / FT:.0f} ft, {s.max_bore / IN:.0f} in and "
             f"{s.max_pressure / PSI:,.0f} psi ({s.gas}; the launcher study's 'customary equipment dimensions and "
             "industry standard pressures'), the payload caught at half the pulse's peak. The article of each "
             "payload is the fixture study's 60 mm ogive scaled geometrically to its mass.")
    rep.text("The models, in the order the data flows:")
    for line in models(s):
        rep.text(f"- {line}")


def by_payload(rep: Report, base: MachineSpec, cfg, out_dir: str, echo) -> dict:
    rep.heading("2. The machine for each payload")
    machines = {}
    for lb in cfg["payloads"]:
        spec = base.with_article(lb * LB)
        where = os.path.join(out_dir, f"{lb}lb")
        m = design_machine(spec, where, echo=echo, starts=cfg["starts"], evaluations=cfg["fixture_evaluations"])
        write_machine(m, where)
        machines[lb] = m
    rows = [_row(lb, m) for lb, m in machines.items()]
    rep.table("machines", MACHINE_HEADER, rows, MACHINE_FORMATS)
    rep.text("Stress / allowable: the largest over every component (`<N>lb/machine.md` lists them all, with "
             "their bases). Striker: the dashpot's housing with its oil, the amplifier's last mass. Effective e: "
             "the one restitution with which the rigid chain of these masses gains what the rigid chain of the "
             "pads' own restitutions gains, each measured by its interface's finite-element run (or its "
             f"material's estimate where not run; the pads' meshes: '{base.pad_resolution}'); the chain's "
             "striker speed is that chain's (with the first mass as the launcher's slug where its gun reaches the launch "
             "speed).")
    for lb, m in machines.items():
        rep.text(f"**{lb} lb**: " + "; ".join(m.binding) + ("." if m.feasible else
                                                             ". NOT FEASIBLE: " + "; ".join(m.problems) + "."))
        rep.figure(f"{lb}lb/drawing.png", f"The {lb} lb machine: side elevation, plan, end view, isometric, "
                   f"dimensions [mm] and parts list (`{lb}lb/drawing.svg`, `.pdf`; the assembly `{lb}lb/machine.step`)")
    return machines


MACHINE_HEADER = ["payload [lb]", "bore [mm]", "payload with piston [kg]", "striker [kg]", "striker speed [m/s]",
                  "peak oil pressure [MPa]", "column peak [g]", "band", "first mass [kg]", "effective e",
                  "chain's striker speed [m/s]", "gun bore [in]", "gun travel [ft]", "reservoir [psi]",
                  "reservoir [m^3]", "gas [kg]", "launcher [kg]", "length [m]", "width [m]", "machine [kg]",
                  "stress / allowable", "feasible", "designed in [s]"]
MACHINE_FORMATS = ["{}", "{:.0f}", "{:.3g}", "{:.4g}", "{:.1f}", "{:.0f}", "{:,.0f}", "{}", "{:,.0f}", "{:.4f}",
                   "{:.1f}", "{:.3g}", "{:.3g}", "{:,.0f}", "{:.3g}", "{:,.0f}", "{:,.0f}", "{:.3g}", "{:.3g}",
                   "{:,.0f}", "{:.2f}", "{}", "{:.0f}"]


def _row(lb, m) -> list:
    f, a, L, t = m.fixture, m.amplifier, m.launcher, m.totals
    g = L.design.gun
    return [lb, 2e3 * f.bore_radius, f.payload_mass, f.striker_mass, f.striker_speed, f.peak_pressure / 1e6,
            f.peak / G0, "pass" if f.band_passed else "FAIL", a.masses[0] if a.masses else math.nan, a.restitution,
            a.striker_speed, g.bore / IN, g.length / FT, g.reservoir_pressure / PSI, g.reservoir_volume,
            L.gas_mass, L.design.weight, t["overall_length"], t["overall_width"], t["machine_mass"],
            max(ld.ratio for ld in m.loads), "yes" if m.feasible else "NO", m.wall_time_s]


# (name, value of a machine, whether it depends on the launcher: meaningless for a machine whose gun is
# only the corner of its limits)
SCALED = (("payload", lambda m: m.fixture.payload_mass, False), ("striker", lambda m: m.fixture.striker_mass, False),
          ("first mass", lambda m: m.amplifier.masses[0], False),
          ("launch energy needed", lambda m: 0.5 * m.amplifier.masses[0] * m.spec.launch_speed ** 2, False),
          ("peak oil pressure", lambda m: m.fixture.peak_pressure, False),
          ("gas mass", lambda m: m.launcher.gas_mass, True), ("machine mass", lambda m: m.totals["machine_mass"], True),
          ("overall length", lambda m: m.totals["overall_length"], True))


def scalability(rep: Report, machines: dict, cfg, out_dir: str, echo):
    rep.heading("3. Scalability")
    payloads = sorted(machines)
    lo = payloads[0]
    feasible = [lb for lb in payloads if machines[lb].feasible]
    rows = []
    for name, get, needs_gun in SCALED:
        ends = [lb for lb in (feasible if needs_gun else payloads) if lb > lo]
        if not ends or (needs_gun and lo not in feasible):
            continue
        hi = ends[-1]
        a, b = get(machines[lo]), get(machines[hi])
        rows.append([name, lo, a, hi, b, b / a, math.log(b / a) / math.log(hi / lo)])
    if rows:
        rep.table("scaling", ["quantity", "from [lb]", "value", "to [lb]", "value", "ratio",
                              "exponent (d ln X / d ln payload)"], rows,
                  ["{}", "{}", "{:.4g}", "{}", "{:.4g}", "{:.3g}", "{:.2f}"])
        faster = [f"{r[0]} ({r[6]:.2f})" for r in rows if r[6] > 1.05]
        slower = [f"{r[0]} ({r[6]:.2f})" for r in rows if r[6] < 0.95]
        rep.text("Values in SI (kg, J, Pa, m). The quantities that depend on the launcher are compared between "
                 "feasible machines only (an infeasible machine's gun is the corner of its limits). An exponent of 1 "
                 "is a quantity proportional to the payload. Faster than the payload: "
                 f"{', '.join(faster) or 'none'}; slower: {', '.join(slower) or 'none'}.")
        _scaling_figure(rep, machines)
    infeasible = [lb for lb in payloads if lb not in feasible]
    tried = infeasible or payloads[-1:]          # with none infeasible, what the alternatives do to the largest
    alt_rows = alternatives(rep, machines, tried, cfg, out_dir, echo)
    rep.text("**Verdict.** " + verdict(machines, alt_rows))


def verdict(machines: dict, rows: list) -> str:
    """The scalability verdict, from the machines and the alternatives' rows."""
    payloads = sorted(machines)
    ok = [lb for lb in payloads if machines[lb].feasible]
    out = []
    if ok:
        out.append(f"The starting architecture gives a machine within every limit for {', '.join(f'{lb} lb' for lb in ok)}")
    for lb in payloads:
        m = machines[lb]
        if m.feasible:
            continue
        limits = sorted({b.split(" at its limit ")[1].split(" ")[0] for b in m.binding if b.startswith("launcher")})
        alt = [r for r in rows if r[0] == lb and r[12] == "yes"]
        if m.launcher.design.feasible:
            words = f"at {lb} lb it does not: " + "; ".join(m.problems)
        else:
            words = (f"at {lb} lb it does not: the launcher reaches only {m.launcher.design.muzzle_velocity:.1f} of "
                     f"the {m.spec.launch_speed:.1f} m/s with {', '.join(limits)} all at their limits")
        if alt:
            best = min(alt, key=lambda r: r[10])
            words += (f"; the architecture has to change: {best[1]} masses launched at {best[2]} ft/s make it "
                      f"feasible ({best[3]:,.0f} kg first mass, {best[10]:,.0f} kg, {best[9]:.3g} m)")
        else:
            words += "; none of the architectures tried is feasible: the limits themselves have to move"
        out.append(words)
    bound = [lb for lb in ok if machines[lb].fixture.housing_binds]
    if bound:
        out.append(f"the striker's housing (its wall at the oil's pressure) sets the striker's mass above the asked ratio "
                   f"for {', '.join(f'{lb} lb' for lb in bound)}")
    # yield: the stresses no sizing set to the allowable, the highest over every feasible machine
    computed = [(ld.ratio, ld.component, lb) for lb in ok for ld in machines[lb].loads if not ld.sized]
    if computed:
        r, component, lb = max(computed)
        out.append(f"every pad, wall and the frame is sized to its allowable, every stop to the force its body's inertia "
                   f"or the gun's thrust allows; of the stresses no sizing set, the "
                   f"highest is the {component} at {r:.2f} of its allowable ({lb} lb)")
    # commercial parts: the guides
    fastest = max(machines[lb].layout.fastest_guided_speed for lb in payloads)
    out.append(f"at every payload the guided bodies reach {fastest:.0f} m/s, {fastest / ROLLING_CARRIAGE_SPEED:.0f} times "
               f"what catalogue rolling carriages allow ({ROLLING_CARRIAGE_SPEED:g} m/s): the guides are sliding shoes, "
               "not commercial linear bearings")
    return "; ".join(out) + "."


def _scaling_figure(rep: Report, machines: dict):
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    lbs = sorted(machines)
    for name, get, _ in SCALED[1:5]:
        vals = [get(machines[lb]) for lb in lbs]
        axes[0].loglog(lbs, [v / vals[0] for v in vals], "o-", label=name)
    axes[0].loglog(lbs, [lb / lbs[0] for lb in lbs], "k:", label="proportional to the payload")
    axes[0].set_xlabel("payload [lb]")
    axes[0].set_ylabel(f"over its value at {lbs[0]} lb [-]")
    axes[0].legend(fontsize=7)
    axes[1].plot(lbs, [machines[lb].totals["overall_length"] for lb in lbs], "o-", label="overall length [m]")
    axes[1].plot(lbs, [machines[lb].launcher.design.gun.reservoir_pressure / 1e6 for lb in lbs], "s-",
                 label="reservoir [MPa]")
    axes[1].set_xlabel("payload [lb]")
    axes[1].legend(fontsize=7)
    for ax in axes:
        ax.grid(alpha=0.3)
    rep.figure("scaling.png", "How the machine grows with the payload (the same pulse)", fig)


def alternatives(rep: Report, machines: dict, payloads: list, cfg, out_dir: str, echo):
    """Other architectures for the payloads the starting one does not meet: more masses, faster launches
    (the fixture is the same: only the amplifier and the launcher are designed again)."""
    rows = []
    for lb in payloads:
        m0 = machines[lb]
        for n, launch_fts in cfg["alternatives"]:
            spec = dataclasses.replace(m0.spec, masses=n, launch_speed=launch_fts * FT)
            where = os.path.join(out_dir, f"{lb}lb_alternatives", f"{n}_masses_{launch_fts}fts")
            m = design_machine(spec, where, echo=None, starts=cfg["starts"], fixture=m0.fixture)
            g = m.launcher.design.gun
            rows.append([lb, n, launch_fts, m.amplifier.masses[0] if m.amplifier.masses else math.nan,
                         m.launcher.launch_energy / 1e6, g.bore / IN, g.length / FT, g.reservoir_pressure / PSI,
                         m.launcher.design.muzzle_velocity / FT, m.totals["overall_length"], m.totals["machine_mass"],
                         max(ld.ratio for ld in m.loads), "yes" if m.feasible else "NO",
                         "; ".join(m.problems)[:160] or ", ".join(b for b in m.binding if b.startswith("launcher"))])
    rep.table("alternatives", ["payload [lb]", "masses", "launch [ft/s]", "first mass [kg]", "launch energy [MJ]",
                               "gun bore [in]", "gun travel [ft]", "reservoir [psi]", "muzzle [ft/s]", "length [m]",
                               "machine [kg]", "stress / allowable", "feasible", "what binds or fails"], rows,
              ["{}", "{}", "{}", "{:,.0f}", "{:.4g}", "{:.3g}", "{:.3g}", "{:,.0f}", "{:.0f}", "{:.3g}", "{:,.0f}",
               "{:.2f}", "{}", "{}"])
    words = []
    for lb in payloads:
        ok = [r for r in rows if r[0] == lb and r[12] == "yes"]
        if ok:
            best = min(ok, key=lambda r: r[10])
            words.append(f"{lb} lb: the lightest machine tried is {best[1]} masses launched at {best[2]} ft/s "
                         f"({best[10]:,.0f} kg, {best[9]:.3g} m)")
        else:
            words.append(f"{lb} lb: none of the architectures tried is feasible within the limits")
    rep.text("Reading: " + "; ".join(words) + ". The fixture of each payload is unchanged (only the amplifier and "
             "the launcher depend on the number of masses and the launch speed).")
    return rows


def coupled(rep: Report, m, cfg, out_dir: str, echo):
    """The machine end to end: gun and chain in one 1D run, then the striker at that run's speed on the
    payload in the fixture's finite-element run."""
    lb = round(m.spec.article_mass / LB)
    rep.heading(f"4. The coupled check: the {lb} lb machine end to end")
    why = sections.not_runnable(m)
    rep.value("coupled_run", not why)
    if why:
        rep.text(f"Not run: the {lb} lb machine is NOT FEASIBLE and cannot be run end to end: {why}.")
        return
    f, a = m.fixture, m.amplifier
    g = m.launcher.design.gun
    raw = chain_scene(m.spec, a, f)
    raw["chain"].pop("launch_speed")
    raw["launcher"] = {"name": "gun", "bore": g.bore, "length": g.length, "reservoir_pressure": g.reservoir_pressure,
                       "reservoir_volume": g.reservoir_volume, "valve_diameter": math.sqrt(4 * g.valve_area / math.pi),
                       "opening_time": g.opening_time, "gas": g.gas, "tank_aspect": SIZING.tank_aspect}
    t0 = time.perf_counter()
    chain = run_chain_scene(raw, os.path.join(out_dir, "coupled", "gun_and_chain"), "1d", progress=False,
                            echo=lambda *x: None)
    chain_wall = time.perf_counter() - t0
    v_striker = chain["test_article_speed"]
    caught = _caught_while_pulse(chain, v_striker)
    d = dict(f.design, striker_speed=v_striker)
    article = {"library": "steel_4340", "radius": f.article_diameter / 2, "crh": 3.0,
               "meplat_radius": 0.2 * f.article_diameter / 2, "length": f.article_length}
    scene = dashpot_scene(d, m.spec.pulse.shape, {"h_article": cfg["h_article"], "h_pad": cfg["h_pad"]},
                          END_MARGIN * m.spec.pulse.duration, article)
    scene["scene"]["name"] = "coupled_fixture"
    echo(f"  the fixture in finite elements, the striker at {v_striker:.1f} m/s")
    fe, wall, status = run_case("fixture", scene, os.path.join(out_dir, "coupled"), echo)
    rows = [["system model (column fixture, rigid chain at effective e)", f.striker_speed, f.peak / G0,
             f.duration * 1e3, f.velocity_change, "pass" if f.band_passed else "FAIL", "-", f"{m.wall_time_s:.1f}"]]
    if fe is not None:
        t, acc = fe_pulse(fe)
        pulse, band = band_of(t, acc, m.spec.pulse.shape)
        rows.append(["end to end (gun and chain 1D, fixture finite elements)", v_striker, pulse.peak / G0,
                     pulse.duration * 1e3, pulse.velocity_change, "pass" if band.passed else "FAIL",
                     f"{fe.summary['energy']['balance_error']:.1e}", f"{chain_wall:.1f} + {wall:.1f}"])
    rep.table("coupled", ["model", "striker speed [m/s]", "article peak [g]", "duration [ms]",
                          "velocity change [m/s]", "band", "energy balance [-]", "wall [s]"], rows,
              ["{}", "{:.1f}", "{:,.0f}", "{:.2f}", "{:.1f}", "{}", "{}", "{}"])
    rep.value("coupled_striker_speed", v_striker)
    rep.value("coupled_launch_speed", chain["launch_speed"])
    rep.text(f"The gun (the launcher of section 2, `{raw['launcher']['name']}` in the chain scene's `[launcher]` "
             f"table) fires the {a.masses[0]:,.0f} kg first mass at {chain['launch_speed']:.2f} m/s (the design: "
             f"{m.spec.launch_speed:.2f}); the 1D padded chain brings the striker to {v_striker:.1f} m/s (the system "
             f"model's {f.striker_speed:.1f}, {v_striker / f.striker_speed - 1:+.2%}). "
             + ("While the pulse lasts no chain mass catches the striker (the 1D run's bodies behind it are slower)."
                if not caught else f"NOTE: {caught}."))
    if fe is not None:
        rep.text(f"In the fixture's finite-element run (axisymmetric, the article elastic-plastic 4340 on its "
                 f"{f.piston_mass:.2f} kg piston, the oil as the cavity's lumped liquid through the metering pin) the "
                 f"article feels {pulse.peak / G0:,.0f} g for {pulse.duration * 1e3:.2f} ms, {pulse.velocity_change:.1f} m/s: "
                 f"{'inside' if band.passed else 'OUTSIDE'} the specification's band; the system model said "
                 f"{f.peak / G0:,.0f} g, {f.duration * 1e3:.2f} ms, {f.velocity_change:.1f} m/s "
                 f"({pulse.peak / f.peak - 1:+.1%} on the peak). Run directory: `coupled/fixture/` (fields.xdmf, "
                 "final_shape.png).")
        rep.run_pictures("coupled/fixture", "The end-to-end run's fixture", "piston and article")
        _tracked_stress(rep, fe, scene)
        rep.value("coupled_band_passed", bool(band.passed))
        rep.value("coupled_peak_g", pulse.peak / G0)
        rep.value("coupled_velocity_change", pulse.velocity_change)


def _tracked_stress(rep: Report, fe, scene: dict):
    """Each body's peak von Mises stress of the coupled run, tracked every step (with when), against its
    material's yield: the stress verdict of the end-to-end check."""
    from ..scene.library import initial_yield_stress
    libraries = {name: mat.get("library") for name, mat in scene["materials"].items()}
    rows = []
    for body in scene["bodies"]:
        got = fe.summary["bodies"].get(body["name"], {})
        lib = libraries.get(body.get("material"))
        if "max_von_mises" not in got or not lib:
            continue
        Y = initial_yield_stress(lib) if "yield_stress" in _library(lib) or "hardening_curve" in _library(lib) else math.nan
        rows.append([body["name"], lib, got["max_von_mises"] / 1e6, got.get("max_von_mises_time", math.nan) * 1e3,
                     Y / 1e6, got["max_von_mises"] / Y])
    rep.table("coupled_stress", ["body", "material", "peak von Mises [MPa]", "at [ms]", "yield [MPa]", "over yield"],
              rows, ["{}", "{}", "{:.1f}", "{:.3f}", "{:.0f}", "{:.2f}"])
    over = [r for r in rows if r[5] > 1]
    rep.text("Peak von Mises stress tracked every step at every point (not at field frames): "
             + ("every body stays below its yield." if not over else
                "above yield: " + ", ".join(f"{r[0]} ({r[5]:.2f})" for r in over) + " (they yield locally; the "
                "article is elastic-plastic 4340 in the run)."))


def _library(name: str) -> dict:
    from ..scene.library import LIBRARY
    return LIBRARY[name]


def _caught_while_pulse(chain: dict, v_striker: float) -> str:
    """Which chain bodies leave their last stage at least as fast as the striker (they would catch it while
    it pushes the payload); '' when none does."""
    after = {}
    for st in chain["stages"]:
        after[st["striker"]] = abs(st["striker_after"])
    faster = [b for b, v in after.items() if v >= v_striker]
    return f"{', '.join(faster)} at least as fast as the striker after their stages" if faster else ""
