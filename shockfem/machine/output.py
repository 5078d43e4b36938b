"""A designed machine's directory: ``machine.json`` (every number, SI, units named in ``units``),
``machine.md`` (its tables with units in the headers) and the lines the command prints."""
from __future__ import annotations

import json
import math
import os

from ..output.rundir import write_json_atomic
from ..units import FT, G0, IN, LB, PSI
from .cad import read_step, write_step
from .design import Machine
from .drawing import draw_sheet
from .energy import energy_figure
from .limits import broken, verdict_line

UNITS = {"mass": "kg", "length": "m", "speed": "m/s", "stress": "Pa", "pressure": "Pa", "energy": "J",
         "acceleration": "m/s^2", "force": "N", "stiffness": "N/m", "time": "s", "temperature rise": "K"}


def summary_lines(m: Machine) -> list[str]:
    s, f, a, L, t = m.spec, m.fixture, m.amplifier, m.launcher, m.totals
    g = L.design.gun
    lines = [
        f"machine for a {s.article_mass:.4g} kg ({s.article_mass / LB:.4g} lb) article, {s.pulse.shape} "
        f"{s.pulse.peak / G0:,.0f} g for {s.pulse.duration * 1e3:g} ms: {'FEASIBLE' if m.feasible else 'NOT FEASIBLE'}",
        f"  fixture: dashpot, bore {2 * f.bore_radius * 1e3:.0f} mm, payload {f.payload_mass:.3g} kg; striker "
        f"{f.striker_mass:.4g} kg at {f.striker_speed:.4g} m/s ({f.striker_speed / FT:.0f} ft/s); column pulse "
        f"{f.peak / G0:,.0f} g, {f.duration * 1e3:.2f} ms, {f.velocity_change:.1f} m/s, band "
        f"{'pass' if f.band_passed else 'FAIL'}, {f.verdict}; oil {f.peak_pressure / 1e6:.0f} MPa, +{f.oil_heating:.0f} K a shot",
        f"  striker: {f.striker_ratio:.4g} times the payload ({'the wall sets it' if f.housing_binds else 'the wall does not set it'}"
        f"; {f.redesigns} redesigns, {_fixed_point(f)}); housing outer radius {f.housing_outer_radius * 1e3:.1f} mm, the wall rule's "
        f"{f.housing_wall_radius * 1e3:.1f} mm (b / a {f.housing_wall_radius / f.bore_radius:.3g}), the striker's "
        f"mass's {f.housing_mass_radius * 1e3:.1f} mm; the column designer's striker {f.design_striker_mass:.4g} kg",
        f"  amplifier: {len(a.masses)} masses " + ", ".join(f"{x:.4g}" for x in a.masses) + " kg; pads "
        + ", ".join(f"{st.pad_material} (e {st.restitution:.3f}{'' if st.measured else ', estimate'})"
                    for st in a.stages) + (" (finite elements); " if any(st.measured for st in a.stages) else
                                           " (no pad run: each its material's estimate); ")
        + f"effective e {a.restitution:.4f}; the rigid chain of them gives the striker {a.striker_speed:.4g} m/s",
        f"  launcher: bore {g.bore / IN:.3g} in, barrel {g.length / FT:.3g} ft, {g.reservoir_volume:.3g} m^3 at "
        f"{g.reservoir_pressure / PSI:,.0f} psi ({g.gas}, {L.gas_mass:.4g} kg); barrel and tank {L.design.weight:,.0f} kg",
        f"  machine: {t['overall_length']:.3g} m long, {t['overall_width']:.3g} m wide, {t['machine_mass']:,.0f} kg; "
        f"the article gets {t['article_over_stored']:.2%} of the gas's stored energy",
    ]
    e = m.energy
    lines.append(f"  energy a shot: {e.stored / 1e6:.4g} MJ of gas stored, {e.gas_work / 1e6:.4g} MJ of gas work, "
                 f"{L.launch_energy / 1e6:.4g} MJ launched, {t['energy_to_stops'] / 1e6:.4g} MJ to the stops, "
                 f"{e.payload / 1e6:.3g} MJ to the payload (the parts close on the gas work to {e.closure:+.2%}"
                 + (f"; the gun falls {e.shortfall / 1e6:.4g} MJ short of the chain's launch, and with that out to "
                    f"{e.models_closure:+.2%})" if abs(e.closure - e.models_closure) > 1e-3 else ")"))
    lines.append("  stops: " + "; ".join(f"{st.body} {st.kind} {st.stroke:.3g} m stroke, {st.length:.3g} m long, "
                                         f"{st.force / 1e6:.3g} MN" for st in m.layout.stops))
    lines += [f"  binds: {b}" for b in m.binding]
    # each pad's run, resizing and range of validity (``pads.Resizing.verdict``)
    lines += [f"  pad {st.pair}: {st.note}" for st in a.stages if st.note]
    lines += [f"  PROBLEM: {p}" for p in m.problems]
    lines.append(f"  {verdict_line(m.limits)}")
    return lines


def _fixed_point(f) -> str:
    """The striker's fixed point with its housing, as the column designer's record gives it: the design
    kept and, where it did not converge, so."""
    fp = f.design["column_design"]["striker_fixed_point"]
    trials = " -> ".join(f"{t['ratio']:.4g} (asks {t['needed']:.4g})" for t in fp["trials"])
    kept = fp["kept"].removeprefix("not converged: ")
    return f"{'converged' if fp['converged'] else 'NOT CONVERGED'}: {kept}; trials {trials}"


def _table(header: list[str], rows: list[list]) -> str:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def markdown(m: Machine) -> str:
    s, f, a, t = m.spec, m.fixture, m.amplifier, m.totals
    g = m.launcher.design.gun
    parts = [f"# Machine for a {s.article_mass / LB:.4g} lb article ({s.pulse.shape}, {s.pulse.peak / G0:,.0f} g, "
             f"{s.pulse.duration * 1e3:g} ms)", "", "\n".join(summary_lines(m)[1:]), "", "## Models", ""]
    parts += [f"- {x}" for x in m.models]
    parts += ["", "## Components on the axis", "",
              _table(["component", "kind", "from x [m]", "length [m]", "diameter [m]", "bore [m]", "mass [kg]",
                      "material", "note"],
                     [[i.name, i.kind, f"{i.x0:.3f}", f"{i.length:.3f}", f"{i.diameter:.3f}",
                       f"{i.inner:.3f}" if i.inner else "-", f"{i.mass:,.1f}" if i.mass else "-", i.material, i.note]
                      for i in m.layout.items])]
    parts += ["", "## Operating loads and stresses", "",
              _table(["component", "load", "stress [MPa]", "allowable [MPa]", "stress / allowable", "basis"],
                     [[ld.component, ld.load, f"{ld.stress / 1e6:.1f}", f"{ld.allowable / 1e6:.1f}", f"{ld.ratio:.2f}",
                       ld.basis] for ld in m.loads])]
    parts += ["", "## Amplifier stages (pads)", "",
              _table(["stage", "closing speed [m/s]", "gap before the pad [m]", "pad", "diameter [mm]",
                      "thickness [mm]", "mass [kg]", "travel [mm]", "energy [kJ]", "restitution (FE) [-]",
                      "FE interface stress [MPa]", "FE run [s]", "broken limits"],
                     [[st.pair, f"{st.closing_speed:.1f}", f"{gap:.3f}", st.pad_material,
                       f"{st.pad_diameter * 1e3:.0f}",
                       f"{st.pad_thickness * 1e3:.0f}", f"{st.pad_mass:,.1f}", f"{st.pad_travel * 1e3:.0f}",
                       f"{st.pad_energy / 1e3:,.0f}",
                       f"{st.restitution:.3f}" + ("" if st.measured else " (estimate: not run)"),
                       f"{st.interface_stress / 1e6:.0f}" if st.measured else "-",
                       f"{st.run_wall_time_s:.3g}" if st.measured else "-",
                       "; ".join(f"{lim.quantity} {lim.ratio:.3g}x" for lim in st.limits if not lim.holds) or "none"]
                      for st, gap in zip(a.stages, a.gaps)])]
    parts += [""] + [f"- {st.pair}: {st.note}" for st in a.stages if st.note]
    parts += ["", "Pad limits (each stage):", "",
              _table(["part", "quantity", "value", "limit", "unit", "ratio", "basis", "source"],
                     [[lim.component, lim.quantity, f"{lim.value:.4g}", f"{lim.limit:.4g}", lim.unit,
                       f"{lim.ratio:.3g}",
                       lim.basis, lim.source] for lim in a.limits])]
    parts += ["", "The other pad materials at each stage (worst limit ratio; sized, not run):", "",
              _table(["stage"] + [alt["material"] for alt in (a.stages[0].alternatives if a.stages else [])],
                     [[st.pair] + [f"{alt['worst']:.3g}" for alt in st.alternatives] for st in a.stages])]
    parts += ["", "Effective restitution, iterated (pads measured in finite elements):", "",
              _table(["assumed e", "measured e per interface", "gain", "effective e", "striker speed [m/s]",
                      "first mass [kg]"],
                     [[f"{it['assumed']:.4f}", ", ".join(f"{x:.3f}" for x in it["measured"]), f"{it['gain']:.4f}",
                       f"{it['effective']:.4f}", f"{it['striker_speed']:.2f}", f"{it['first_mass']:,.1f}"]
                      for it in a.iterations])]
    parts += ["", "## Stops (absorbers)", "",
              _table(["body", "mass [kg]", "speed [m/s]", "absorber", "peak deceleration [g]", "stroke [m]",
                      "peak force [MN]", "energy [kJ]", "own length [m]", "own mass [kg]", "used a shot [kg]",
                      "allowed force", "detail"],
                     [[st.body, f"{st.mass:,.4g}", f"{st.speed:.1f}", st.kind, f"{st.deceleration / G0:,.0f}",
                       f"{st.stroke:.3f}", f"{st.force / 1e6:.3g}", f"{st.energy / 1e3:,.0f}", f"{st.length:.3f}",
                       f"{st.absorber_mass:,.1f}", f"{st.consumed:,.1f}", st.limit, st.detail] for st in m.layout.stops])]
    parts += ["", "## Energy of a shot", "", energy_markdown(m), "", "![energy](energy.png)"]
    parts += ["", "## Limits (the verdict rests on these)", "", limits_markdown(m.limits)]
    parts += ["", "## Totals", "", _table(["quantity", "value"], [[k, f"{v:.6g}"] for k, v in t.items()]),
              "", "(SI: kg, m, m^2, J, Pa, K.)", "",
              f"Launcher: {g.bore / IN:.4g} in bore, {g.length / FT:.4g} ft of travel, {g.reservoir_volume:.4g} m^3 at "
              f"{g.reservoir_pressure / PSI:,.0f} psi; fixture column pulse {f.peak / G0:,.0f} g ({f.verdict}).",
              f"Designed in {m.wall_time_s:.1f} s."]
    return "\n".join(parts) + "\n"


def energy_markdown(m: Machine) -> str:
    e = m.energy
    rows = [[r.name, f"{r.energy / 1e6:.4f}", f"{r.energy / e.gas_work:.2%}", "yes" if r.part else "-", r.note]
            for r in e.rows]
    rows.append(["the parts' sum", f"{e.parts / 1e6:.4f}", f"{e.parts / e.gas_work:.2%}", "",
                 f"closure {e.closure:+.3%}; the gun's shortfall {e.shortfall / 1e6:.4g} MJ out: {e.models_closure:+.3%}"])
    return _table(["where the energy is", "energy [MJ]", "of the gas work", "a part", "note"], rows) + "\n\n" + \
        "\n".join(f"- {n}" for n in e.notes)


def limits_markdown(limits) -> str:
    return _table(["component", "quantity", "value", "limit", "unit", "ratio", "holds", "set by the design", "basis",
                   "limit's source"],
                  [[lim.component, lim.quantity, f"{lim.value:.4g}", f"{lim.limit:.4g}", lim.unit, f"{lim.ratio:.3f}",
                    "yes" if lim.holds else "**NO**", "yes" if lim.sized else "-", lim.basis, lim.source]
                   for lim in limits])


def write_machine(m: Machine, out_dir: str) -> list[str]:
    """``machine.json``, ``machine.md``, the STEP assembly ``machine.step`` (re-read and checked against
    the design: ``cad`` in the JSON) and the drawing ``drawing.svg/.pdf/.png`` in ``out_dir``; returns the
    paths."""
    os.makedirs(out_dir, exist_ok=True)
    step = os.path.join(out_dir, "machine.step")
    name = f"shock_tester_{m.spec.article_mass / LB:.3g}lb".replace(".", "_")
    cad_check = check_step(m, write_step(m, step, name), read_step(step))
    sheet = draw_sheet(m, os.path.join(out_dir, "drawing"))
    figure = energy_figure(m.energy, os.path.join(out_dir, "energy.png"),
                           f"The {m.spec.article_mass / LB:.3g} lb machine's shot")
    data = m.as_dict()
    data["units"] = UNITS
    data["cad"] = cad_check
    path_json = os.path.join(out_dir, "machine.json")
    write_json_atomic(path_json, _finite(json.loads(json.dumps(data, default=_plain))))
    path_md = os.path.join(out_dir, "machine.md")
    with open(path_md, "w") as fh:
        fh.write(markdown(m))
    return [path_json, path_md, step, *sheet, figure]


def check_step(m: Machine, written: list[dict], read_back: list[dict]) -> dict:
    """The STEP file read back: every solid by its name at the volume it was built with, and the designed
    parts' masses (a part's solids summed at their density) against the design's."""
    back = {r["name"]: r["volume"] for r in read_back}
    volume_error = max(abs(back.get(r["name"], 0.0) / r["volume"] - 1) for r in written)
    by_part: dict[str, float] = {}
    for r in written:
        by_part[r["part"]] = by_part.get(r["part"], 0.0) + r["mass"]
    # the stops' absorbers are drawn as the rings they act through (like the rails), not at their mass
    designed = {i.name: i.mass for i in m.layout.items if i.mass and i.kind != "stop"}
    mass_error = {k: by_part.get(k, 0.0) / v - 1 for k, v in designed.items()}
    return {"solids": written, "names_read_back": sorted(back) == sorted(r["name"] for r in written),
            "max_volume_error": volume_error, "mass_error": mass_error,
            "max_mass_error": max(abs(e) for e in mass_error.values())}


def _finite(x):
    """Non-finite numbers as null (JSON has no NaN)."""
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, dict):
        return {k: _finite(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_finite(v) for v in x]
    return x


def _plain(x):
    if hasattr(x, "tolist"):
        return x.tolist()
    return str(x)
